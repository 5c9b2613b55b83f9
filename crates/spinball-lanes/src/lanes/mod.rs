//! The lane types: the physics is written once, over [`Lanes`], and runs on
//! one `f64`, on SSE2, AVX2 or AVX-512 registers, or on several registers at
//! once.
//!
//! A kernel step is a long chain of dependent operations (two divisions and
//! two square roots deep). Running `N` independent trajectories in the lanes
//! of vector registers, and several registers side by side ([`Wide`]), lets
//! the CPU overlap those chains. Each implementation maps one operation to
//! one instruction (`vdivpd`, `vcmppd` + `vblendvpd`, ...) of its level, so
//! the generated code does not depend on the auto-vectoriser. The table
//! lookup ([`Lanes::lookup`]) is the exception: a permute or a gather on
//! AVX-512 and AVX2, an indexed load per lane on SSE2 and `f64`.
//!
//! **Same numbers everywhere.** Every operation is the IEEE operation the
//! scalar code performs on each lane (no fused multiply-add, no approximate
//! reciprocal or square root); comparisons use the predicates of Rust's `<`,
//! `<=`, `==`, `!=` (ordered, except `!=`); [`Lanes::max`] and
//! [`Lanes::clamp`] have the NaN behaviour of `f64::max` (for a non-NaN
//! second argument) and `f64::clamp`. So a lane computes what the scalar code
//! computes, bitwise (up to the sign of a zero out of `max`, which Rust
//! leaves unspecified), on every level.
//!
//! This file holds the traits; the constant tables lanes index live in
//! `palette`, and each family of lane types has its own file:
//! [`portable`] (`f64` and [`Wide`]), `sse2`, `avx2`, `avx512` (x86 only) and
//! `counted` (tests). [`PerIsa`] names the lane type a kernel runs with at
//! each instruction-set level, and a table's [`Footprint`] which of a
//! kernel's three sets of counts it runs with.
//!
//! **Safety.** The SSE2, AVX2 and AVX-512 types call intrinsics, which is
//! undefined behaviour on a CPU without the feature. Each type names the
//! proof of the feature it needs ([`Lanes::Needs`], one of the zero-sized
//! proofs of [`isa`](crate::isa), which only detection makes), and the
//! compiler checks that no value is made without it: the constructors
//! ([`Lanes::splat`], [`Lanes::load`], [`BitsOps::splat`]) take the proof,
//! every x86 lane, mask and bits value holds it (a zero-sized field private
//! to the type's module), and every other operation makes its result from
//! operands that hold one ([`Lanes::proof`] hands it on). So holding a lane
//! value proves the CPU runs its instructions, in kernels and tests alike.
//! The one function that runs kernels,
//! [`run_chunks`](crate::kernels::run_chunks), takes a proof `C` and
//! requires that it proves the lane type's needs ([`ProvenBy`]), which makes
//! the proof the lanes are built with.

use std::ops::{Add, Div, Mul, Neg, Sub};

#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
use crate::isa::{Avx2Cpu, Avx512Cpu};
use crate::isa::{Baseline, ProvenBy};

/// Most lanes any [`Lanes`] type has (bounds the stack buffers of the kernels).
pub(crate) const MAX_LANES: usize = 64;

/// Lane-wise boolean operations of a comparison result.
pub(crate) trait MaskOps: Copy + std::fmt::Debug {
    /// Both.
    fn and(self, o: Self) -> Self;
    /// Either.
    fn or(self, o: Self) -> Self;
    /// Negation.
    fn not(self) -> Self;
    /// Whether any lane is set.
    fn any(self) -> bool;
}

/// Lane-wise `u64` arithmetic (exponent bookkeeping).
pub(crate) trait BitsOps: Copy {
    /// Number of lanes.
    const W: usize;
    /// The proof the constructor takes, as [`Lanes::Needs`].
    type Needs: Copy;
    /// Every lane `x`; `cpu` proves this CPU runs the type's instructions.
    fn splat(cpu: Self::Needs, x: u64) -> Self;
    /// Wrapping addition.
    fn add(self, o: Self) -> Self;
    /// Wrapping subtraction.
    fn sub(self, o: Self) -> Self;
    /// Lane `i` (outside hot loops).
    fn lane(self, i: usize) -> u64;
}

/// `N` independent `f64`s and the operations the physics needs.
pub(crate) trait Lanes:
    Copy
    + Send
    + Sync
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + Add<f64, Output = Self>
    + Sub<f64, Output = Self>
    + Mul<f64, Output = Self>
    + Div<f64, Output = Self>
{
    /// Number of lanes.
    const N: usize;
    /// A comparison result.
    type Mask: MaskOps;
    /// `u64` lanes.
    type Bits: BitsOps<Needs = Self::Needs>;
    /// The proof (a zero-sized type of [`isa`](crate::isa)) that the CPU can
    /// run this type's instructions: [`Baseline`] for
    /// `f64` and SSE2, [`Avx2Cpu`] and [`Avx512Cpu`] for the x86 vector
    /// types. The constructors take it, so a value of the type exists only
    /// where the proof did; kernels run only with a proof `C` such that
    /// `Needs: `[`ProvenBy`]`<C>`.
    type Needs: Copy;

    /// The proof this value was made with (zero-sized: free).
    fn proof(self) -> Self::Needs;
    /// Every lane `x`.
    fn splat(cpu: Self::Needs, x: f64) -> Self;
    /// Lanes from the first `N` elements of `s`.
    fn load(cpu: Self::Needs, s: &[f64]) -> Self;
    /// Lanes into the first `N` elements of `s`.
    fn store(self, s: &mut [f64]);
    /// Correctly rounded square root.
    fn sqrt(self) -> Self;
    /// Absolute value.
    fn abs(self) -> Self;
    /// `self` where `self > o`, else `o`, as `maxpd`: `f64::max` for `o`
    /// not NaN (a NaN `self` gives `o`), and `o` for two zeros of either
    /// sign, so `x.max(0.0)` is `+0.0` for `x = -0.0` on every instruction set.
    fn max(self, o: Self) -> Self;
    /// `self < o`.
    fn lt(self, o: Self) -> Self::Mask;
    /// `self <= o`.
    fn le(self, o: Self) -> Self::Mask;
    /// `self > o`.
    fn gt(self, o: Self) -> Self::Mask;
    /// `self >= o`.
    fn ge(self, o: Self) -> Self::Mask;
    /// `self == o`.
    fn eq(self, o: Self) -> Self::Mask;
    /// `self != o` (true for NaN).
    fn ne(self, o: Self) -> Self::Mask;
    /// `a` where `m`, `b` elsewhere.
    fn select(m: Self::Mask, a: Self, b: Self) -> Self;
    /// The biased exponent field, `bits >> 52` (for `self >= 0`).
    fn exponent(self) -> Self::Bits;
    /// `self` with its exponent replaced by 1.0's: the mantissa in `[1, 2)`
    /// (for `self > 0` and normal).
    fn mantissa(self) -> Self;
    /// The `f64` whose bits are `e << 52`: `2^(e − 1023)` for `e` in `1..2047`.
    fn pow2(e: Self::Bits) -> Self;
    /// The comparison `P` (one of [`cmp`]) lane by lane, the negated ones
    /// in one instruction where the level has it (x86: a compare with the
    /// inverse, unordered predicate).
    #[inline(always)]
    fn compare<const P: i32>(self, o: Self) -> Self::Mask {
        match P {
            cmp::EQ => self.eq(o),
            cmp::LT => self.lt(o),
            cmp::LE => self.le(o),
            cmp::NLT => self.lt(o).not(),
            cmp::NLE => self.le(o).not(),
            cmp::GE => self.ge(o),
            cmp::GT => self.gt(o),
            _ => unreachable!("not a comparison of `cmp`"),
        }
    }
    /// `within.and(self.compare::<P>(o))`: the lanes of `within` where the
    /// comparison holds. (AVX-512's masked compare would fuse the two, but
    /// `_mm512_mask_cmp_pd_mask` makes LLVM 22 fail, "Cannot emit physreg
    /// copy instruction", in some builds of the kernels (an open X86 backend
    /// regression, llvm/llvm-project#179100), so no level overrides this.)
    #[inline(always)]
    fn test<const P: i32>(self, o: Self, within: Self::Mask) -> Self::Mask {
        within.and(self.compare::<P>(o))
    }
    /// `p`'s entry at each lane's index: lane `i` of the result is
    /// [`p.get(index.lane(i))`](Palette::get) (a wall's constant fetched by
    /// the wall's id, so that a cast keeps only the id of the nearest wall
    /// and not its constants). AVX-512 permutes a palette of 8 or 16
    /// entries within registers; the other levels gather.
    fn lookup(p: &Palette, index: Self) -> Self;
    /// The eight constants of each lane's record in `r`: entry `c` of the
    /// result is bitwise [`lookup`](Self::lookup)`(r.column(c), index)`
    /// (a wall's landing constants fetched together by its id). AVX2 and
    /// SSE2 load each lane's row and transpose; AVX-512 permutes each
    /// column.
    #[inline(always)]
    fn fetch(r: &Records, index: Self) -> [Self; 8] {
        [
            Self::lookup(r.column(0), index),
            Self::lookup(r.column(1), index),
            Self::lookup(r.column(2), index),
            Self::lookup(r.column(3), index),
            Self::lookup(r.column(4), index),
            Self::lookup(r.column(5), index),
            Self::lookup(r.column(6), index),
            Self::lookup(r.column(7), index),
        ]
    }

    /// Lanes that are neither NaN nor infinite.
    #[inline(always)]
    fn is_finite(self) -> Self::Mask {
        self.abs().lt(Self::splat(self.proof(), f64::INFINITY))
    }
    /// `f64::clamp`: NaN passes through.
    #[inline(always)]
    fn clamp(self, lo: f64, hi: f64) -> Self {
        let cpu = self.proof();
        let x = Self::select(self.lt(Self::splat(cpu, lo)), Self::splat(cpu, lo), self);
        Self::select(x.gt(Self::splat(cpu, hi)), Self::splat(cpu, hi), x)
    }
    /// Lane `i` (outside hot loops).
    #[inline(always)]
    fn lane(self, i: usize) -> f64 {
        let mut buf = [0.0; MAX_LANES];
        self.store(&mut buf);
        buf[i]
    }
}

/// The comparisons of [`Lanes::compare`] and [`Lanes::test`], numbered as
/// x86's `_CMP_*` predicates: the ordered ones false for NaN, as Rust's
/// `==`, `<`, `<=`, `>=`, `>`; the negations `!(a < b)`, `!(a <= b)` true
/// for NaN.
pub(crate) mod cmp {
    /// `a == b`.
    pub const EQ: i32 = 0x00;
    /// `a < b`.
    pub const LT: i32 = 0x11;
    /// `a <= b`.
    pub const LE: i32 = 0x12;
    /// `!(a < b)`.
    pub const NLT: i32 = 0x15;
    /// `!(a <= b)`.
    pub const NLE: i32 = 0x16;
    /// `a >= b`.
    pub const GE: i32 = 0x1D;
    /// `a > b`.
    pub const GT: i32 = 0x1E;
}

const EXP_SHIFT: u32 = 52;
const MANTISSA: u64 = 0x000f_ffff_ffff_ffff;
const ONE_BITS: u64 = 0x3ff0_0000_0000_0000;

/// The operations of an x86 lane type that have the same shape on every
/// level, from the level's intrinsics: the operators, the `u64` lanes
/// ([`BitsOps`]) and the [`Lanes`] methods that map to one intrinsic each
/// (`splat`, `load`, `store`, `sqrt`, `max`, the exponent bit operations).
/// What differs between the levels (negation, `abs`, the comparisons, blends,
/// gathers and permutes) each file writes after `own`, inside the generated
/// `impl Lanes`.
///
/// Every lane, mask and bits value is a register and the proof `$cpu` that
/// this CPU runs the level (field `.1`, zero-sized): the constructors
/// (`Lanes::splat`, `Lanes::load`, `BitsOps::splat`) take the proof, and every
/// other operation makes its result from values that hold one. So a value
/// exists only after the level was detected, which is what each `unsafe`
/// intrinsic call below rests on, and the compiler checks it.
///
/// One intrinsic per operation, no loop, everything `#[inline(always)]`:
/// the kernels inline it into the `#[target_feature]` entry points.
#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
macro_rules! simd_lanes {
    (@binop $t:ident, $tr:ident, $f:ident, $intr:ident) => {
        impl ::std::ops::$tr for $t {
            type Output = $t;
            #[inline(always)]
            fn $f(self, o: $t) -> $t {
                // SAFETY: `self.1` proves this CPU has the level's features.
                $t(unsafe { $intr(self.0, o.0) }, self.1)
            }
        }
        impl ::std::ops::$tr<f64> for $t {
            type Output = $t;
            #[inline(always)]
            fn $f(self, o: f64) -> $t {
                ::std::ops::$tr::$f(self, <$t as $crate::lanes::Lanes>::splat(self.1, o))
            }
        }
    };
    (
        $t:ident, mask $m:ident, bits $b:ident, needs $cpu:ty, lanes $n:literal;
        pd { set1: $set1:ident, loadu: $loadu:ident, storeu: $storeu:ident,
             add: $add:ident, sub: $sub:ident, mul: $mul:ident, div: $div:ident,
             sqrt: $sqrt:ident, max: $max:ident }
        epi64 { set1: $iset1:ident, storeu: $istoreu:ident, add: $iadd:ident, sub: $isub:ident,
                and: $iand:ident, or: $ior:ident, srli: $srli:ident, slli: $slli:ident,
                shift: $shift:expr }
        cast { to_bits: $to_bits:ident, to_pd: $to_pd:ident }
        own { $($own:tt)* }
    ) => {
        simd_lanes!(@binop $t, Add, add, $add);
        simd_lanes!(@binop $t, Sub, sub, $sub);
        simd_lanes!(@binop $t, Mul, mul, $mul);
        simd_lanes!(@binop $t, Div, div, $div);

        impl $crate::lanes::BitsOps for $b {
            const W: usize = $n;
            type Needs = $cpu;
            #[inline(always)]
            fn splat(cpu: $cpu, x: u64) -> Self {
                // SAFETY: `cpu` proves this CPU has the level's features.
                $b(unsafe { $iset1(x as i64) }, cpu)
            }
            #[inline(always)]
            fn add(self, o: Self) -> Self {
                // SAFETY: `self.1` proves this CPU has the level's features.
                $b(unsafe { $iadd(self.0, o.0) }, self.1)
            }
            #[inline(always)]
            fn sub(self, o: Self) -> Self {
                // SAFETY: `self.1` proves this CPU has the level's features.
                $b(unsafe { $isub(self.0, o.0) }, self.1)
            }
            fn lane(self, i: usize) -> u64 {
                let mut buf = [0u64; $n];
                // SAFETY: `self.1` proves this CPU has the level's features;
                // `buf` is `$n` `u64`s, one register, so the unaligned store
                // writes only to it.
                unsafe { $istoreu(buf.as_mut_ptr().cast(), self.0) };
                buf[i]
            }
        }

        impl $crate::lanes::Lanes for $t {
            const N: usize = $n;
            type Mask = $m;
            type Bits = $b;
            type Needs = $cpu;
            #[inline(always)]
            fn proof(self) -> $cpu {
                self.1
            }
            #[inline(always)]
            fn splat(cpu: $cpu, x: f64) -> Self {
                // SAFETY: `cpu` proves this CPU has the level's features.
                $t(unsafe { $set1(x) }, cpu)
            }
            #[inline(always)]
            fn load(cpu: $cpu, s: &[f64]) -> Self {
                let s = &s[..$n];
                // SAFETY: `cpu` proves this CPU has the level's features;
                // `s` was cut to `$n` elements, one register, so the
                // unaligned load reads only from it.
                $t(unsafe { $loadu(s.as_ptr()) }, cpu)
            }
            #[inline(always)]
            fn store(self, s: &mut [f64]) {
                let s = &mut s[..$n];
                // SAFETY: `self.1` proves this CPU has the level's features;
                // `s` was cut to `$n` elements, one register, so the
                // unaligned store writes only to it.
                unsafe { $storeu(s.as_mut_ptr(), self.0) }
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                // SAFETY: `self.1` proves this CPU has the level's features.
                $t(unsafe { $sqrt(self.0) }, self.1)
            }
            #[inline(always)]
            fn max(self, o: Self) -> Self {
                // SAFETY: `self.1` proves this CPU has the level's features.
                $t(unsafe { $max(self.0, o.0) }, self.1)
            }
            #[inline(always)]
            fn exponent(self) -> $b {
                // SAFETY: `self.1` proves this CPU has the level's features.
                $b(unsafe { $srli::<{ $shift }>($to_bits(self.0)) }, self.1)
            }
            #[inline(always)]
            fn mantissa(self) -> Self {
                // SAFETY: `self.1` proves this CPU has the level's features.
                let m = unsafe {
                    $to_pd($ior(
                        $iand($to_bits(self.0), $iset1($crate::lanes::MANTISSA as i64)),
                        $iset1($crate::lanes::ONE_BITS as i64),
                    ))
                };
                $t(m, self.1)
            }
            #[inline(always)]
            fn pow2(e: $b) -> Self {
                // SAFETY: `e.1` proves this CPU has the level's features.
                $t(unsafe { $to_pd($slli::<{ $shift }>(e.0)) }, e.1)
            }
            $($own)*
        }
    };
}

/// The mask operations of a level whose comparisons give a vector register
/// (all ones or all zeros per lane: SSE2 and AVX2), from its intrinsics.
#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
macro_rules! vector_mask {
    ($m:ident; and: $and:ident, or: $or:ident, xor: $xor:ident, ones: $ones:expr, movemask: $movemask:ident) => {
        impl $crate::lanes::MaskOps for $m {
            #[inline(always)]
            fn and(self, o: Self) -> Self {
                // SAFETY: `self.1` proves this CPU has the level's features.
                $m(unsafe { $and(self.0, o.0) }, self.1)
            }
            #[inline(always)]
            fn or(self, o: Self) -> Self {
                // SAFETY: `self.1` proves this CPU has the level's features.
                $m(unsafe { $or(self.0, o.0) }, self.1)
            }
            #[inline(always)]
            fn not(self) -> Self {
                // SAFETY: `self.1` proves this CPU has the level's features.
                $m(unsafe { $xor(self.0, $ones) }, self.1)
            }
            #[inline(always)]
            fn any(self) -> bool {
                // SAFETY: `self.1` proves this CPU has the level's features.
                unsafe { $movemask(self.0) != 0 }
            }
        }
    };
}

/// The comparisons of a level with one compare intrinsic taking the
/// predicate as a constant (AVX2's `vcmppd`, AVX-512's into a mask
/// register): the six of [`Lanes`] and [`Lanes::compare`] (whose negated
/// predicates `NLT`, `NLE` are then one instruction too). Expands to methods
/// of an `impl Lanes`.
#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
macro_rules! predicate_compares {
    ($m:ident, $cmp:ident) => {
        predicate_compares!(@one $m, $cmp, lt = _CMP_LT_OQ, le = _CMP_LE_OQ, gt = _CMP_GT_OQ,
            ge = _CMP_GE_OQ, eq = _CMP_EQ_OQ, ne = _CMP_NEQ_UQ);
        #[inline(always)]
        fn compare<const P: i32>(self, o: Self) -> $m {
            // SAFETY: `self.1` proves this CPU has the level's features. `P`
            // is one of `cmp`'s predicates, all valid.
            $m(unsafe { $cmp::<P>(self.0, o.0) }, self.1)
        }
    };
    (@one $m:ident, $cmp:ident, $($f:ident = $p:ident),*) => {$(
        #[inline(always)]
        fn $f(self, o: Self) -> $m {
            // SAFETY: `self.1` proves this CPU has the level's features.
            $m(unsafe { $cmp::<$p>(self.0, o.0) }, self.1)
        }
    )*};
}

mod palette;
pub(crate) use palette::{Palette, Records};

mod portable;
pub(crate) use portable::Wide;

#[cfg(all(
    any(target_arch = "x86", target_arch = "x86_64"),
    target_feature = "sse2"
))]
mod sse2;
#[cfg(all(
    any(target_arch = "x86", target_arch = "x86_64"),
    target_feature = "sse2"
))]
pub(crate) use sse2::Sse2;

#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
mod avx2;
#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
pub(crate) use avx2::Avx2;

#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
mod avx512;
#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
pub(crate) use avx512::Avx512;

#[cfg(test)]
pub(crate) mod counted;

/// The lane type a kernel runs with at each instruction-set level.
///
/// The results do not depend on it: it only sets how many trajectories share
/// the registers, which is a matter of each kernel's register pressure.
pub(crate) trait PerIsa {
    /// At [`Isa::Avx512`](crate::Isa::Avx512).
    #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
    type Avx512: Lanes<Needs: ProvenBy<Avx512Cpu>>;
    /// At [`Isa::Avx2`](crate::Isa::Avx2).
    #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
    type Avx2: Lanes<Needs: ProvenBy<Avx2Cpu>>;
    /// At [`Isa::Baseline`](crate::Isa::Baseline).
    type Baseline: Lanes<Needs: ProvenBy<Baseline>>;
}

/// [`Wide`] groups of `AVX512` AVX-512 registers, `AVX2` AVX2 registers,
/// `SSE2` SSE2 registers and (where the baseline has no SSE2) `PORTABLE`
/// `f64`s.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Groups<
    const AVX512: usize,
    const AVX2: usize,
    const SSE2: usize,
    const PORTABLE: usize,
>;

impl<const AVX512: usize, const AVX2: usize, const SSE2: usize, const PORTABLE: usize> PerIsa
    for Groups<AVX512, AVX2, SSE2, PORTABLE>
{
    #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
    type Avx512 = Wide<Avx512, AVX512>;
    #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
    type Avx2 = Wide<Avx2, AVX2>;
    #[cfg(all(
        any(target_arch = "x86", target_arch = "x86_64"),
        target_feature = "sse2"
    ))]
    type Baseline = Wide<Sse2, SSE2>;
    #[cfg(not(all(
        any(target_arch = "x86", target_arch = "x86_64"),
        target_feature = "sse2"
    )))]
    type Baseline = Wide<f64, PORTABLE>;
}

/// How many registers a table's cast keeps live, as far as the choice of
/// register groups goes: a kernel names its groups for a [`LeanCast`]
/// (the built-in tables' closed-form casts), for a [`BulkyCast`] (a
/// table built from segments, whose cast carries the nearest candidate so
/// far through a loop over its walls) and for an [`ArcCast`] (such a table
/// with arcs), and the table picks one
/// ([`Geom::Footprint`](crate::geom::Geom::Footprint)).
///
/// Like the group counts themselves, the choice never changes a result.
pub(crate) trait Footprint {
    /// `Lean`, `Bulky` or `Arcs`, whichever this footprint is.
    type Pick<Lean: PerIsa, Bulky: PerIsa, Arcs: PerIsa>: PerIsa;
}

/// The footprint of a closed-form cast (circle, rectangle, stadium, Sinai).
#[derive(Debug, Clone, Copy)]
pub(crate) enum LeanCast {}

/// The footprint of a cast that loops over walls (tables built from
/// segments): in the 16 registers of AVX2 and SSE2 it leaves room for
/// fewer groups.
#[derive(Debug, Clone, Copy)]
pub(crate) enum BulkyCast {}

/// The footprint of a cast that loops over flat walls and arcs (tables
/// built from segments with arcs): each arc's square root adds live values
/// to the loop's.
#[derive(Debug, Clone, Copy)]
pub(crate) enum ArcCast {}

impl Footprint for LeanCast {
    type Pick<Lean: PerIsa, Bulky: PerIsa, Arcs: PerIsa> = Lean;
}

impl Footprint for BulkyCast {
    type Pick<Lean: PerIsa, Bulky: PerIsa, Arcs: PerIsa> = Bulky;
}

impl Footprint for ArcCast {
    type Pick<Lean: PerIsa, Bulky: PerIsa, Arcs: PerIsa> = Arcs;
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `L::lookup` reads, bit for bit, the entry [`Palette::get`] reads, for
    /// palettes of 8, 16 and 24 entries and every index in every lane.
    fn lookup_reads_the_indexed_entry<L: Lanes>(cpu: L::Needs) {
        for walls in [1, 5, 8, 9, 13, 16, 17, 20] {
            // Distinct entries, a negative zero and a subnormal among them.
            let values: Vec<f64> = (0..walls)
                .map(|i| match i {
                    1 => -0.0,
                    2 => f64::MIN_POSITIVE / 3.0,
                    _ => (i as f64 + 0.25) * if i % 2 == 0 { 1.0 } else { -1e3 },
                })
                .collect();
            let p = Palette::new(values);
            let n = p.entries().len();
            for first in 0..n {
                // Lane j reads entry (first + 5 j) mod n: every entry in every
                // lane over the loop (5 is prime to every n).
                let index: Vec<f64> = (0..L::N).map(|j| ((first + 5 * j) % n) as f64).collect();
                let mut got = vec![0.0; L::N];
                L::lookup(&p, L::load(cpu, &index)).store(&mut got);
                for (j, g) in got.iter().enumerate() {
                    assert_eq!(
                        g.to_bits(),
                        p.get(index[j]).to_bits(),
                        "{walls} walls, lane {j}, index {}",
                        index[j]
                    );
                }
            }
        }
    }

    /// `L::fetch` reads, bit for bit, what `L::lookup` reads from each
    /// column, for every index in every lane (and a NaN index); `row` reads
    /// what `Palette::get` reads.
    fn fetch_reads_each_column<L: Lanes>(cpu: L::Needs) {
        for walls in [1, 5, 8, 9, 16, 17] {
            let rows: Vec<[f64; 8]> = (0..walls)
                .map(|i| {
                    std::array::from_fn(|c| {
                        (i * 8 + c) as f64 * if c % 2 == 0 { 1.5 } else { -0.25 }
                    })
                })
                .collect();
            let r = Records::new(rows);
            let n = r.rows().len();
            for first in 0..=n {
                // Lane j reads entry (first + 5 j) mod n, and a NaN at `n`.
                let index: Vec<f64> = (0..L::N)
                    .map(|j| {
                        if first == n && j == 0 {
                            f64::NAN
                        } else {
                            ((first + 5 * j) % n) as f64
                        }
                    })
                    .collect();
                for &i in &index {
                    for c in 0..8 {
                        assert_eq!(r.row(i)[c].to_bits(), r.column(c).get(i).to_bits());
                    }
                }
                let k = L::load(cpu, &index);
                let got = L::fetch(&r, k);
                for (c, g) in got.iter().enumerate() {
                    let (mut a, mut b) = (vec![0.0; L::N], vec![0.0; L::N]);
                    g.store(&mut a);
                    L::lookup(r.column(c), k).store(&mut b);
                    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
                    assert_eq!(
                        bits(&a),
                        bits(&b),
                        "{walls} walls, column {c}, indices {index:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn fetch_reads_each_column_on_every_level() {
        fetch_reads_each_column::<f64>(Baseline);
        fetch_reads_each_column::<<Groups<1, 1, 1, 1> as PerIsa>::Baseline>(Baseline);
        fetch_reads_each_column::<<Groups<2, 2, 2, 2> as PerIsa>::Baseline>(Baseline);
        #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
        {
            if let Some(cpu) = Avx2Cpu::detect() {
                fetch_reads_each_column::<Avx2>(cpu);
                fetch_reads_each_column::<Wide<Avx2, 2>>(cpu);
            }
            if let Some(cpu) = Avx512Cpu::detect() {
                fetch_reads_each_column::<Avx512>(cpu);
            }
        }
    }

    /// On every instruction-set level this CPU has: AVX-512 permutes
    /// palettes of 8 and 16 entries and gathers larger ones, AVX2 gathers,
    /// the baseline reads one lane at a time.
    #[test]
    fn lookup_reads_the_indexed_entry_on_every_level() {
        lookup_reads_the_indexed_entry::<<Groups<1, 1, 1, 1> as PerIsa>::Baseline>(Baseline);
        #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
        {
            if let Some(cpu) = Avx2Cpu::detect() {
                lookup_reads_the_indexed_entry::<Avx2>(cpu);
            }
            if let Some(cpu) = Avx512Cpu::detect() {
                lookup_reads_the_indexed_entry::<Avx512>(cpu);
            }
        }
    }
}
