//! The lane types: the physics is written once, over [`Lanes`], and runs on
//! one `f64`, on SSE2, AVX2 or AVX-512 registers, or on several registers at
//! once.
//!
//! A kernel step is a long chain of dependent operations (two divisions and
//! two square roots deep). Running `N` independent trajectories in the lanes
//! of vector registers, and several registers side by side ([`Wide`]), lets
//! the CPU overlap those chains. Each implementation maps one operation to
//! one instruction (`vdivpd`, `vcmppd` + `vblendvpd`, ...) of its level, so
//! the generated code does not depend on the auto-vectoriser.
//!
//! **Same numbers everywhere.** Every operation is the IEEE operation the
//! scalar code performs on each lane (no fused multiply-add, no approximate
//! reciprocal or square root); comparisons use the predicates of Rust's `<`,
//! `<=`, `==`, `!=` (ordered, except `!=`); [`Lanes::max`] and
//! [`Lanes::clamp`] have the NaN behaviour of `f64::max` (for a non-NaN
//! second argument) and `f64::clamp`. So a lane computes what the scalar code
//! computes, bitwise (up to the sign of a zero out of `max`, which Rust
//! leaves unspecified), on every level.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// Most lanes any [`Lanes`] type has (bounds the stack buffers of the kernels).
pub(crate) const MAX_LANES: usize = 64;

/// Lane-wise boolean operations of a comparison result.
pub(crate) trait MaskOps: Copy {
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
    /// Every lane `x`.
    fn splat(x: u64) -> Self;
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
    type Bits: BitsOps;

    /// Every lane `x`.
    fn splat(x: f64) -> Self;
    /// Lanes from the first `N` elements of `s`.
    fn load(s: &[f64]) -> Self;
    /// Lanes into the first `N` elements of `s`.
    fn store(self, s: &mut [f64]);
    /// Correctly rounded square root.
    fn sqrt(self) -> Self;
    /// Absolute value.
    fn abs(self) -> Self;
    /// `f64::max` (for `o` not NaN: a NaN `self` gives `o`).
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

    /// Lanes that are neither NaN nor infinite.
    #[inline(always)]
    fn is_finite(self) -> Self::Mask {
        self.abs().lt(Self::splat(f64::INFINITY))
    }
    /// `f64::clamp`: NaN passes through.
    #[inline(always)]
    fn clamp(self, lo: f64, hi: f64) -> Self {
        let x = Self::select(self.lt(Self::splat(lo)), Self::splat(lo), self);
        Self::select(x.gt(Self::splat(hi)), Self::splat(hi), x)
    }
    /// Lane `i` (outside hot loops).
    #[inline(always)]
    fn lane(self, i: usize) -> f64 {
        let mut buf = [0.0; MAX_LANES];
        self.store(&mut buf);
        buf[i]
    }
}

const EXP_SHIFT: u32 = 52;
const MANTISSA: u64 = 0x000f_ffff_ffff_ffff;
const ONE_BITS: u64 = 0x3ff0_0000_0000_0000;

/// Operators of a lane type from its binary-operation closure.
macro_rules! ops {
    ($t:ty, $splat:path, |$a:ident, $b:ident| add: $add:expr, sub: $sub:expr, mul: $mul:expr, div: $div:expr, neg: $neg:expr) => {
        impl Add for $t {
            type Output = $t;
            #[inline(always)]
            fn add(self, o: $t) -> $t {
                let ($a, $b) = (self, o);
                $add
            }
        }
        impl Sub for $t {
            type Output = $t;
            #[inline(always)]
            fn sub(self, o: $t) -> $t {
                let ($a, $b) = (self, o);
                $sub
            }
        }
        impl Mul for $t {
            type Output = $t;
            #[inline(always)]
            fn mul(self, o: $t) -> $t {
                let ($a, $b) = (self, o);
                $mul
            }
        }
        impl Div for $t {
            type Output = $t;
            #[inline(always)]
            fn div(self, o: $t) -> $t {
                let ($a, $b) = (self, o);
                $div
            }
        }
        impl Neg for $t {
            type Output = $t;
            #[inline(always)]
            fn neg(self) -> $t {
                let $a = self;
                $neg
            }
        }
        impl Add<f64> for $t {
            type Output = $t;
            #[inline(always)]
            fn add(self, o: f64) -> $t {
                self + $splat(o)
            }
        }
        impl Sub<f64> for $t {
            type Output = $t;
            #[inline(always)]
            fn sub(self, o: f64) -> $t {
                self - $splat(o)
            }
        }
        impl Mul<f64> for $t {
            type Output = $t;
            #[inline(always)]
            fn mul(self, o: f64) -> $t {
                self * $splat(o)
            }
        }
        impl Div<f64> for $t {
            type Output = $t;
            #[inline(always)]
            fn div(self, o: f64) -> $t {
                self / $splat(o)
            }
        }
    };
}

// ---------------------------------------------------------------- one lane

impl MaskOps for bool {
    #[inline(always)]
    fn and(self, o: bool) -> bool {
        self & o
    }
    #[inline(always)]
    fn or(self, o: bool) -> bool {
        self | o
    }
    #[inline(always)]
    fn not(self) -> bool {
        !self
    }
    #[inline(always)]
    fn any(self) -> bool {
        self
    }
}

impl BitsOps for u64 {
    const W: usize = 1;
    #[inline(always)]
    fn splat(x: u64) -> u64 {
        x
    }
    #[inline(always)]
    fn add(self, o: u64) -> u64 {
        self.wrapping_add(o)
    }
    #[inline(always)]
    fn sub(self, o: u64) -> u64 {
        self.wrapping_sub(o)
    }
    #[inline(always)]
    fn lane(self, _: usize) -> u64 {
        self
    }
}

/// One lane: plain `f64` (the portable fallback and the reference).
impl Lanes for f64 {
    const N: usize = 1;
    type Mask = bool;
    type Bits = u64;
    #[inline(always)]
    fn splat(x: f64) -> f64 {
        x
    }
    #[inline(always)]
    fn load(s: &[f64]) -> f64 {
        s[0]
    }
    #[inline(always)]
    fn store(self, s: &mut [f64]) {
        s[0] = self;
    }
    #[inline(always)]
    fn sqrt(self) -> f64 {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn abs(self) -> f64 {
        f64::abs(self)
    }
    #[inline(always)]
    fn max(self, o: f64) -> f64 {
        f64::max(self, o)
    }
    #[inline(always)]
    fn lt(self, o: f64) -> bool {
        self < o
    }
    #[inline(always)]
    fn le(self, o: f64) -> bool {
        self <= o
    }
    #[inline(always)]
    fn gt(self, o: f64) -> bool {
        self > o
    }
    #[inline(always)]
    fn ge(self, o: f64) -> bool {
        self >= o
    }
    #[inline(always)]
    fn eq(self, o: f64) -> bool {
        self == o
    }
    #[inline(always)]
    fn ne(self, o: f64) -> bool {
        self != o
    }
    #[inline(always)]
    fn select(m: bool, a: f64, b: f64) -> f64 {
        if m { a } else { b }
    }
    #[inline(always)]
    fn exponent(self) -> u64 {
        self.to_bits() >> EXP_SHIFT
    }
    #[inline(always)]
    fn mantissa(self) -> f64 {
        f64::from_bits((self.to_bits() & MANTISSA) | ONE_BITS)
    }
    #[inline(always)]
    fn pow2(e: u64) -> f64 {
        f64::from_bits(e << EXP_SHIFT)
    }
}

// ------------------------------------------------------------ several lanes

/// `K` registers of `L` side by side: `K · L::N` lanes whose dependency
/// chains the CPU overlaps.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Wide<L, const K: usize>(pub [L; K]);

/// Build `[T; K]` element by element (`T: Copy`). A plain loop rather than
/// `std::array::from_fn`, whose helpers are not always inlined into the
/// `#[target_feature]` functions (a call per operation, out of the vector
/// context).
macro_rules! each {
    ($k:expr, |$i:ident| $e:expr) => {{
        let mut out = [{
            let $i = 0;
            $e
        }; $k];
        let mut $i = 1;
        while $i < $k {
            out[$i] = $e;
            $i += 1;
        }
        out
    }};
}

impl<M: MaskOps, const K: usize> MaskOps for Wide<M, K> {
    #[inline(always)]
    fn and(self, o: Self) -> Self {
        Wide(each!(K, |i| self.0[i].and(o.0[i])))
    }
    #[inline(always)]
    fn or(self, o: Self) -> Self {
        Wide(each!(K, |i| self.0[i].or(o.0[i])))
    }
    #[inline(always)]
    fn not(self) -> Self {
        Wide(each!(K, |i| self.0[i].not()))
    }
    #[inline(always)]
    fn any(self) -> bool {
        self.0.iter().any(|m| m.any())
    }
}

macro_rules! wide_binop {
    ($tr:ident, $f:ident) => {
        impl<L: Lanes, const K: usize> $tr for Wide<L, K> {
            type Output = Self;
            #[inline(always)]
            fn $f(self, o: Self) -> Self {
                Wide(each!(K, |i| $tr::$f(self.0[i], o.0[i])))
            }
        }
        impl<L: Lanes, const K: usize> $tr<f64> for Wide<L, K> {
            type Output = Self;
            #[inline(always)]
            fn $f(self, o: f64) -> Self {
                let o = L::splat(o);
                Wide(each!(K, |i| $tr::$f(self.0[i], o)))
            }
        }
    };
}
wide_binop!(Add, add);
wide_binop!(Sub, sub);
wide_binop!(Mul, mul);
wide_binop!(Div, div);

impl<L: Lanes, const K: usize> Neg for Wide<L, K> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Wide(each!(K, |i| -self.0[i]))
    }
}

macro_rules! wide_cmp {
    ($($f:ident),*) => {$(
        #[inline(always)]
        fn $f(self, o: Self) -> Self::Mask {
            Wide(each!(K, |i| self.0[i].$f(o.0[i])))
        }
    )*};
}

impl<L: Lanes, const K: usize> Lanes for Wide<L, K> {
    const N: usize = L::N * K;
    type Mask = Wide<L::Mask, K>;
    type Bits = Wide<L::Bits, K>;

    #[inline(always)]
    fn splat(x: f64) -> Self {
        Wide([L::splat(x); K])
    }
    #[inline(always)]
    fn load(s: &[f64]) -> Self {
        Wide(each!(K, |i| L::load(&s[i * L::N..])))
    }
    #[inline(always)]
    fn store(self, s: &mut [f64]) {
        for (i, x) in self.0.into_iter().enumerate() {
            x.store(&mut s[i * L::N..]);
        }
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        Wide(each!(K, |i| self.0[i].sqrt()))
    }
    #[inline(always)]
    fn abs(self) -> Self {
        Wide(each!(K, |i| self.0[i].abs()))
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        Wide(each!(K, |i| self.0[i].max(o.0[i])))
    }
    wide_cmp!(lt, le, gt, ge, eq, ne);
    #[inline(always)]
    fn select(m: Self::Mask, a: Self, b: Self) -> Self {
        Wide(each!(K, |i| L::select(m.0[i], a.0[i], b.0[i])))
    }
    #[inline(always)]
    fn exponent(self) -> Self::Bits {
        Wide(each!(K, |i| self.0[i].exponent()))
    }
    #[inline(always)]
    fn mantissa(self) -> Self {
        Wide(each!(K, |i| self.0[i].mantissa()))
    }
    #[inline(always)]
    fn pow2(e: Self::Bits) -> Self {
        Wide(each!(K, |i| L::pow2(e.0[i])))
    }
}

/// `u64` lanes of a [`Wide`] (lane `i` lives in register `i / L::N`).
impl<B: BitsOps, const K: usize> BitsOps for Wide<B, K> {
    #[inline(always)]
    fn splat(x: u64) -> Self {
        Wide([B::splat(x); K])
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Wide(each!(K, |i| self.0[i].add(o.0[i])))
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Wide(each!(K, |i| self.0[i].sub(o.0[i])))
    }
    const W: usize = B::W * K;
    fn lane(self, i: usize) -> u64 {
        self.0[i / B::W].lane(i % B::W)
    }
}

#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
pub(crate) use x86::{Avx2, Avx512, Sse2};

#[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
mod x86 {
    //! SSE2, AVX2 and AVX-512 registers.
    //!
    //! # Safety
    //! The intrinsics are `#[target_feature]` functions: calling one on a CPU
    //! without the feature is undefined behaviour. The types [`Avx2`] and
    //! [`Avx512`] are only ever used inside the kernel instantiations of
    //! `isa::on_avx2` / `isa::on_avx512`, which are compiled with those
    //! features and entered only after `is_x86_feature_detected!` confirmed
    //! them (see `isa::dispatch!`); [`Sse2`] needs only SSE2, which every
    //! x86-64 CPU has (it is part of the x86-64 baseline).

    #[cfg(target_arch = "x86")]
    use std::arch::x86::*;
    #[cfg(target_arch = "x86_64")]
    use std::arch::x86_64::*;
    use std::ops::{Add, Div, Mul, Neg, Sub};

    use super::{BitsOps, EXP_SHIFT, Lanes, MANTISSA, MaskOps, ONE_BITS};

    // SAFETY (for every `unsafe` block in this module): see the module docs.
    // Each block calls exactly one intrinsic of the type's level (or a load
    // or store through a pointer to a slice checked to hold N elements).

    /// Two lanes in an SSE2 register.
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct Sse2(__m128d);
    /// A mask of [`Sse2`] lanes (all ones or all zeros per lane).
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct Sse2Mask(__m128d);
    /// `u64` lanes of [`Sse2`].
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct Sse2Bits(__m128i);

    ops!(Sse2, sse2_splat, |a, b|
        add: Sse2(unsafe { _mm_add_pd(a.0, b.0) }),
        sub: Sse2(unsafe { _mm_sub_pd(a.0, b.0) }),
        mul: Sse2(unsafe { _mm_mul_pd(a.0, b.0) }),
        div: Sse2(unsafe { _mm_div_pd(a.0, b.0) }),
        neg: Sse2(unsafe { _mm_xor_pd(a.0, _mm_set1_pd(-0.0)) }));

    #[inline(always)]
    fn sse2_splat(x: f64) -> Sse2 {
        Sse2(unsafe { _mm_set1_pd(x) })
    }

    impl MaskOps for Sse2Mask {
        #[inline(always)]
        fn and(self, o: Self) -> Self {
            Sse2Mask(unsafe { _mm_and_pd(self.0, o.0) })
        }
        #[inline(always)]
        fn or(self, o: Self) -> Self {
            Sse2Mask(unsafe { _mm_or_pd(self.0, o.0) })
        }
        #[inline(always)]
        fn not(self) -> Self {
            Sse2Mask(unsafe { _mm_xor_pd(self.0, _mm_castsi128_pd(_mm_set1_epi64x(-1))) })
        }
        #[inline(always)]
        fn any(self) -> bool {
            unsafe { _mm_movemask_pd(self.0) != 0 }
        }
    }

    impl BitsOps for Sse2Bits {
        const W: usize = 2;
        #[inline(always)]
        fn splat(x: u64) -> Self {
            Sse2Bits(unsafe { _mm_set1_epi64x(x as i64) })
        }
        #[inline(always)]
        fn add(self, o: Self) -> Self {
            Sse2Bits(unsafe { _mm_add_epi64(self.0, o.0) })
        }
        #[inline(always)]
        fn sub(self, o: Self) -> Self {
            Sse2Bits(unsafe { _mm_sub_epi64(self.0, o.0) })
        }
        fn lane(self, i: usize) -> u64 {
            let mut buf = [0u64; 2];
            unsafe { _mm_storeu_si128(buf.as_mut_ptr().cast(), self.0) };
            buf[i]
        }
    }

    impl Lanes for Sse2 {
        const N: usize = 2;
        type Mask = Sse2Mask;
        type Bits = Sse2Bits;
        #[inline(always)]
        fn splat(x: f64) -> Self {
            sse2_splat(x)
        }
        #[inline(always)]
        fn load(s: &[f64]) -> Self {
            let s = &s[..2];
            Sse2(unsafe { _mm_loadu_pd(s.as_ptr()) })
        }
        #[inline(always)]
        fn store(self, s: &mut [f64]) {
            let s = &mut s[..2];
            unsafe { _mm_storeu_pd(s.as_mut_ptr(), self.0) }
        }
        #[inline(always)]
        fn sqrt(self) -> Self {
            Sse2(unsafe { _mm_sqrt_pd(self.0) })
        }
        #[inline(always)]
        fn abs(self) -> Self {
            Sse2(unsafe { _mm_andnot_pd(_mm_set1_pd(-0.0), self.0) })
        }
        #[inline(always)]
        fn max(self, o: Self) -> Self {
            Sse2(unsafe { _mm_max_pd(self.0, o.0) })
        }
        #[inline(always)]
        fn lt(self, o: Self) -> Sse2Mask {
            Sse2Mask(unsafe { _mm_cmplt_pd(self.0, o.0) })
        }
        #[inline(always)]
        fn le(self, o: Self) -> Sse2Mask {
            Sse2Mask(unsafe { _mm_cmple_pd(self.0, o.0) })
        }
        #[inline(always)]
        fn gt(self, o: Self) -> Sse2Mask {
            Sse2Mask(unsafe { _mm_cmpgt_pd(self.0, o.0) })
        }
        #[inline(always)]
        fn ge(self, o: Self) -> Sse2Mask {
            Sse2Mask(unsafe { _mm_cmpge_pd(self.0, o.0) })
        }
        #[inline(always)]
        fn eq(self, o: Self) -> Sse2Mask {
            Sse2Mask(unsafe { _mm_cmpeq_pd(self.0, o.0) })
        }
        #[inline(always)]
        fn ne(self, o: Self) -> Sse2Mask {
            Sse2Mask(unsafe { _mm_cmpneq_pd(self.0, o.0) })
        }
        #[inline(always)]
        fn select(m: Sse2Mask, a: Self, b: Self) -> Self {
            Sse2(unsafe { _mm_or_pd(_mm_and_pd(m.0, a.0), _mm_andnot_pd(m.0, b.0)) })
        }
        #[inline(always)]
        fn exponent(self) -> Sse2Bits {
            Sse2Bits(unsafe { _mm_srli_epi64::<{ EXP_SHIFT as i32 }>(_mm_castpd_si128(self.0)) })
        }
        #[inline(always)]
        fn mantissa(self) -> Self {
            Sse2(unsafe {
                _mm_castsi128_pd(_mm_or_si128(
                    _mm_and_si128(_mm_castpd_si128(self.0), _mm_set1_epi64x(MANTISSA as i64)),
                    _mm_set1_epi64x(ONE_BITS as i64),
                ))
            })
        }
        #[inline(always)]
        fn pow2(e: Sse2Bits) -> Self {
            Sse2(unsafe { _mm_castsi128_pd(_mm_slli_epi64::<{ EXP_SHIFT as i32 }>(e.0)) })
        }
    }

    /// Four lanes in an AVX2 register.
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct Avx2(__m256d);
    /// A mask of [`Avx2`] lanes (all ones or all zeros per lane).
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct Avx2Mask(__m256d);
    /// `u64` lanes of [`Avx2`].
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct Avx2Bits(__m256i);

    ops!(Avx2, avx2_splat, |a, b|
        add: Avx2(unsafe { _mm256_add_pd(a.0, b.0) }),
        sub: Avx2(unsafe { _mm256_sub_pd(a.0, b.0) }),
        mul: Avx2(unsafe { _mm256_mul_pd(a.0, b.0) }),
        div: Avx2(unsafe { _mm256_div_pd(a.0, b.0) }),
        neg: Avx2(unsafe { _mm256_xor_pd(a.0, _mm256_set1_pd(-0.0)) }));

    #[inline(always)]
    fn avx2_splat(x: f64) -> Avx2 {
        Avx2(unsafe { _mm256_set1_pd(x) })
    }

    impl MaskOps for Avx2Mask {
        #[inline(always)]
        fn and(self, o: Self) -> Self {
            Avx2Mask(unsafe { _mm256_and_pd(self.0, o.0) })
        }
        #[inline(always)]
        fn or(self, o: Self) -> Self {
            Avx2Mask(unsafe { _mm256_or_pd(self.0, o.0) })
        }
        #[inline(always)]
        fn not(self) -> Self {
            Avx2Mask(unsafe { _mm256_xor_pd(self.0, _mm256_castsi256_pd(_mm256_set1_epi64x(-1))) })
        }
        #[inline(always)]
        fn any(self) -> bool {
            unsafe { _mm256_movemask_pd(self.0) != 0 }
        }
    }

    impl BitsOps for Avx2Bits {
        const W: usize = 4;
        #[inline(always)]
        fn splat(x: u64) -> Self {
            Avx2Bits(unsafe { _mm256_set1_epi64x(x as i64) })
        }
        #[inline(always)]
        fn add(self, o: Self) -> Self {
            Avx2Bits(unsafe { _mm256_add_epi64(self.0, o.0) })
        }
        #[inline(always)]
        fn sub(self, o: Self) -> Self {
            Avx2Bits(unsafe { _mm256_sub_epi64(self.0, o.0) })
        }
        fn lane(self, i: usize) -> u64 {
            let mut buf = [0u64; 4];
            unsafe { _mm256_storeu_si256(buf.as_mut_ptr().cast(), self.0) };
            buf[i]
        }
    }

    macro_rules! avx_cmp {
        ($($f:ident = $p:ident),*) => {$(
            #[inline(always)]
            fn $f(self, o: Self) -> Avx2Mask {
                Avx2Mask(unsafe { _mm256_cmp_pd::<$p>(self.0, o.0) })
            }
        )*};
    }

    impl Lanes for Avx2 {
        const N: usize = 4;
        type Mask = Avx2Mask;
        type Bits = Avx2Bits;
        #[inline(always)]
        fn splat(x: f64) -> Self {
            avx2_splat(x)
        }
        #[inline(always)]
        fn load(s: &[f64]) -> Self {
            let s = &s[..4];
            Avx2(unsafe { _mm256_loadu_pd(s.as_ptr()) })
        }
        #[inline(always)]
        fn store(self, s: &mut [f64]) {
            let s = &mut s[..4];
            unsafe { _mm256_storeu_pd(s.as_mut_ptr(), self.0) }
        }
        #[inline(always)]
        fn sqrt(self) -> Self {
            Avx2(unsafe { _mm256_sqrt_pd(self.0) })
        }
        #[inline(always)]
        fn abs(self) -> Self {
            Avx2(unsafe { _mm256_andnot_pd(_mm256_set1_pd(-0.0), self.0) })
        }
        #[inline(always)]
        fn max(self, o: Self) -> Self {
            Avx2(unsafe { _mm256_max_pd(self.0, o.0) })
        }
        avx_cmp!(
            lt = _CMP_LT_OQ,
            le = _CMP_LE_OQ,
            gt = _CMP_GT_OQ,
            ge = _CMP_GE_OQ,
            eq = _CMP_EQ_OQ,
            ne = _CMP_NEQ_UQ
        );
        #[inline(always)]
        fn select(m: Avx2Mask, a: Self, b: Self) -> Self {
            Avx2(unsafe { _mm256_blendv_pd(b.0, a.0, m.0) })
        }
        #[inline(always)]
        fn exponent(self) -> Avx2Bits {
            Avx2Bits(unsafe {
                _mm256_srli_epi64::<{ EXP_SHIFT as i32 }>(_mm256_castpd_si256(self.0))
            })
        }
        #[inline(always)]
        fn mantissa(self) -> Self {
            Avx2(unsafe {
                _mm256_castsi256_pd(_mm256_or_si256(
                    _mm256_and_si256(
                        _mm256_castpd_si256(self.0),
                        _mm256_set1_epi64x(MANTISSA as i64),
                    ),
                    _mm256_set1_epi64x(ONE_BITS as i64),
                ))
            })
        }
        #[inline(always)]
        fn pow2(e: Avx2Bits) -> Self {
            Avx2(unsafe { _mm256_castsi256_pd(_mm256_slli_epi64::<{ EXP_SHIFT as i32 }>(e.0)) })
        }
    }

    /// Eight lanes in an AVX-512 register.
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct Avx512(__m512d);
    /// `u64` lanes of [`Avx512`].
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct Avx512Bits(__m512i);
    /// A mask of [`Avx512`] lanes (one bit per lane, in a mask register).
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct Avx512Mask(__mmask8);

    ops!(Avx512, avx512_splat, |a, b|
    add: Avx512(unsafe { _mm512_add_pd(a.0, b.0) }),
    sub: Avx512(unsafe { _mm512_sub_pd(a.0, b.0) }),
    mul: Avx512(unsafe { _mm512_mul_pd(a.0, b.0) }),
    div: Avx512(unsafe { _mm512_div_pd(a.0, b.0) }),
    neg: Avx512(unsafe {
        _mm512_castsi512_pd(_mm512_xor_si512(
            _mm512_castpd_si512(a.0),
            _mm512_set1_epi64(i64::MIN),
        ))
    }));

    #[inline(always)]
    fn avx512_splat(x: f64) -> Avx512 {
        Avx512(unsafe { _mm512_set1_pd(x) })
    }

    impl MaskOps for Avx512Mask {
        #[inline(always)]
        fn and(self, o: Self) -> Self {
            Avx512Mask(self.0 & o.0)
        }
        #[inline(always)]
        fn or(self, o: Self) -> Self {
            Avx512Mask(self.0 | o.0)
        }
        #[inline(always)]
        fn not(self) -> Self {
            Avx512Mask(!self.0)
        }
        #[inline(always)]
        fn any(self) -> bool {
            self.0 != 0
        }
    }

    impl BitsOps for Avx512Bits {
        const W: usize = 8;
        #[inline(always)]
        fn splat(x: u64) -> Self {
            Avx512Bits(unsafe { _mm512_set1_epi64(x as i64) })
        }
        #[inline(always)]
        fn add(self, o: Self) -> Self {
            Avx512Bits(unsafe { _mm512_add_epi64(self.0, o.0) })
        }
        #[inline(always)]
        fn sub(self, o: Self) -> Self {
            Avx512Bits(unsafe { _mm512_sub_epi64(self.0, o.0) })
        }
        fn lane(self, i: usize) -> u64 {
            let mut buf = [0u64; 8];
            unsafe { _mm512_storeu_si512(buf.as_mut_ptr().cast(), self.0) };
            buf[i]
        }
    }

    macro_rules! avx512_cmp {
        ($($f:ident = $p:ident),*) => {$(
            #[inline(always)]
            fn $f(self, o: Self) -> Avx512Mask {
                Avx512Mask(unsafe { _mm512_cmp_pd_mask::<$p>(self.0, o.0) })
            }
        )*};
    }

    impl Lanes for Avx512 {
        const N: usize = 8;
        type Mask = Avx512Mask;
        type Bits = Avx512Bits;
        #[inline(always)]
        fn splat(x: f64) -> Self {
            avx512_splat(x)
        }
        #[inline(always)]
        fn load(s: &[f64]) -> Self {
            let s = &s[..8];
            Avx512(unsafe { _mm512_loadu_pd(s.as_ptr()) })
        }
        #[inline(always)]
        fn store(self, s: &mut [f64]) {
            let s = &mut s[..8];
            unsafe { _mm512_storeu_pd(s.as_mut_ptr(), self.0) }
        }
        #[inline(always)]
        fn sqrt(self) -> Self {
            Avx512(unsafe { _mm512_sqrt_pd(self.0) })
        }
        #[inline(always)]
        fn abs(self) -> Self {
            Avx512(unsafe { _mm512_abs_pd(self.0) })
        }
        #[inline(always)]
        fn max(self, o: Self) -> Self {
            Avx512(unsafe { _mm512_max_pd(self.0, o.0) })
        }
        avx512_cmp!(
            lt = _CMP_LT_OQ,
            le = _CMP_LE_OQ,
            gt = _CMP_GT_OQ,
            ge = _CMP_GE_OQ,
            eq = _CMP_EQ_OQ,
            ne = _CMP_NEQ_UQ
        );
        #[inline(always)]
        fn select(m: Avx512Mask, a: Self, b: Self) -> Self {
            // Lanes with the mask bit set take the second operand.
            Avx512(unsafe { _mm512_mask_blend_pd(m.0, b.0, a.0) })
        }
        #[inline(always)]
        fn exponent(self) -> Avx512Bits {
            Avx512Bits(unsafe { _mm512_srli_epi64::<EXP_SHIFT>(_mm512_castpd_si512(self.0)) })
        }
        #[inline(always)]
        fn mantissa(self) -> Self {
            Avx512(unsafe {
                _mm512_castsi512_pd(_mm512_or_si512(
                    _mm512_and_si512(
                        _mm512_castpd_si512(self.0),
                        _mm512_set1_epi64(MANTISSA as i64),
                    ),
                    _mm512_set1_epi64(ONE_BITS as i64),
                ))
            })
        }
        #[inline(always)]
        fn pow2(e: Avx512Bits) -> Self {
            Avx512(unsafe { _mm512_castsi512_pd(_mm512_slli_epi64::<EXP_SHIFT>(e.0)) })
        }
    }
}

/// A one-lane [`Lanes`] type that counts the operations a kernel performs
/// (the "operation count" floor of `docs/PERFORMANCE.md`).
#[cfg(test)]
pub(crate) mod counted {
    use std::cell::Cell;
    use std::ops::{Add, Div, Mul, Neg, Sub};

    use super::{Lanes, MaskOps};

    /// Operation classes.
    #[derive(Clone, Copy, Debug)]
    pub enum Op {
        /// add, sub, neg
        Add,
        /// mul
        Mul,
        /// div
        Div,
        /// sqrt
        Sqrt,
        /// max, abs, compare
        Cmp,
        /// select (blend)
        Select,
        /// mask logic
        Mask,
        /// exponent/mantissa bit operations
        Bits,
    }

    thread_local! {
        static COUNTS: Cell<[u64; 8]> = const { Cell::new([0; 8]) };
    }

    fn tick(op: Op) {
        COUNTS.with(|c| {
            let mut v = c.get();
            v[op as usize] += 1;
            c.set(v);
        });
    }

    /// Counts so far, by [`Op`] index; resets them.
    pub fn take() -> [u64; 8] {
        COUNTS.with(|c| c.replace([0; 8]))
    }

    /// A counted `f64`.
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Counted(pub f64);
    /// A counted mask.
    #[derive(Clone, Copy, Debug)]
    pub struct CMask(bool);

    impl MaskOps for CMask {
        fn and(self, o: Self) -> Self {
            tick(Op::Mask);
            CMask(self.0 & o.0)
        }
        fn or(self, o: Self) -> Self {
            tick(Op::Mask);
            CMask(self.0 | o.0)
        }
        fn not(self) -> Self {
            tick(Op::Mask);
            CMask(!self.0)
        }
        fn any(self) -> bool {
            tick(Op::Mask);
            self.0
        }
    }

    macro_rules! op {
        ($tr:ident, $f:ident, $op:tt, $class:ident) => {
            impl $tr for Counted {
                type Output = Counted;
                fn $f(self, o: Counted) -> Counted {
                    tick(Op::$class);
                    Counted(self.0 $op o.0)
                }
            }
            impl $tr<f64> for Counted {
                type Output = Counted;
                fn $f(self, o: f64) -> Counted {
                    tick(Op::$class);
                    Counted(self.0 $op o)
                }
            }
        };
    }
    op!(Add, add, +, Add);
    op!(Sub, sub, -, Add);
    op!(Mul, mul, *, Mul);
    op!(Div, div, /, Div);
    impl Neg for Counted {
        type Output = Counted;
        fn neg(self) -> Counted {
            tick(Op::Add);
            Counted(-self.0)
        }
    }

    impl Lanes for Counted {
        const N: usize = 1;
        type Mask = CMask;
        type Bits = u64;
        fn splat(x: f64) -> Self {
            Counted(x)
        }
        fn load(s: &[f64]) -> Self {
            Counted(s[0])
        }
        fn store(self, s: &mut [f64]) {
            s[0] = self.0;
        }
        fn sqrt(self) -> Self {
            tick(Op::Sqrt);
            Counted(self.0.sqrt())
        }
        fn abs(self) -> Self {
            tick(Op::Cmp);
            Counted(self.0.abs())
        }
        fn max(self, o: Self) -> Self {
            tick(Op::Cmp);
            Counted(self.0.max(o.0))
        }
        fn lt(self, o: Self) -> CMask {
            tick(Op::Cmp);
            CMask(self.0 < o.0)
        }
        fn le(self, o: Self) -> CMask {
            tick(Op::Cmp);
            CMask(self.0 <= o.0)
        }
        fn gt(self, o: Self) -> CMask {
            tick(Op::Cmp);
            CMask(self.0 > o.0)
        }
        fn ge(self, o: Self) -> CMask {
            tick(Op::Cmp);
            CMask(self.0 >= o.0)
        }
        fn eq(self, o: Self) -> CMask {
            tick(Op::Cmp);
            CMask(self.0 == o.0)
        }
        fn ne(self, o: Self) -> CMask {
            tick(Op::Cmp);
            CMask(self.0 != o.0)
        }
        fn select(m: CMask, a: Self, b: Self) -> Self {
            tick(Op::Select);
            if m.0 { a } else { b }
        }
        fn exponent(self) -> u64 {
            tick(Op::Bits);
            self.0.exponent()
        }
        fn mantissa(self) -> Self {
            tick(Op::Bits);
            tick(Op::Bits);
            Counted(self.0.mantissa())
        }
        fn pow2(e: u64) -> Self {
            tick(Op::Bits);
            tick(Op::Bits);
            Counted(f64::pow2(e))
        }
    }
}
