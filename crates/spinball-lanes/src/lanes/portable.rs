//! The lane types without intrinsics: one plain `f64` lane, and [`Wide`],
//! several registers of any lane type side by side.
//!
//! `f64` is the reference every other type must match bitwise, the lane type
//! of the baseline where the target has no SSE2, and the base of the
//! operation-counting type of the tests. [`Wide`] turns one register into a
//! group: `K` independent dependency chains the CPU overlaps, at every level.
//! The one `unsafe` operation is `each!`'s reading of the group it has
//! just written, element by element.

use std::mem::MaybeUninit;
use std::ops::{Add, Div, Mul, Neg, Sub};

use super::{BitsOps, EXP_SHIFT, Lanes, MANTISSA, MaskOps, ONE_BITS, Palette, Records};
use crate::isa::Baseline;

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
    type Needs = Baseline;
    #[inline(always)]
    fn splat(_: Baseline, x: u64) -> u64 {
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
    type Needs = Baseline;
    #[inline(always)]
    fn proof(self) -> Baseline {
        Baseline
    }
    #[inline(always)]
    fn splat(_: Baseline, x: f64) -> f64 {
        x
    }
    #[inline(always)]
    fn load(_: Baseline, s: &[f64]) -> f64 {
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
        // `maxpd`'s rule (`f64::max` leaves the sign of a zero unspecified).
        if self > o { self } else { o }
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
    #[inline(always)]
    fn lookup(p: &Palette, index: f64) -> f64 {
        p.get(index)
    }
}

/// `K` registers of `L` side by side: `K · L::N` lanes whose dependency
/// chains the CPU overlaps.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Wide<L, const K: usize>(pub [L; K]);

/// The most registers a [`Wide`] group holds.
pub(crate) const MAX_GROUP: usize = 4;

/// Build `[T; K]` element by element (`K <= MAX_GROUP`), as straight-line
/// code: no loop, no closure, no call.
///
/// Every operation of a group goes through here, thousands per kernel, so
/// the shape matters for compile time as much as for speed: a loop (even
/// one LLVM unrolls in the end, such as the repeat of `[x; K]` or a `while`
/// over `0..K`) reaches the optimiser once per operation, and its loop
/// passes then run once per loop over a function that keeps growing
/// (docs/PERFORMANCE.md, "Build time"); `std::array::from_fn`'s helpers are
/// not always inlined into the `#[target_feature]` functions (a call per
/// operation, out of the vector context). Here the `if`s test a constant and
/// fold away before any loop pass runs.
macro_rules! each {
    ($k:expr, |$i:ident| $e:expr) => {{
        const { assert!($k >= 1 && $k <= MAX_GROUP) };
        let mut out = [const { MaybeUninit::uninit() }; $k];
        {
            let $i = 0;
            out[0].write($e);
        }
        if $k > 1 {
            let $i = 1;
            out[1].write($e);
        }
        if $k > 2 {
            let $i = 2;
            out[2].write($e);
        }
        if $k > 3 {
            let $i = 3;
            out[3].write($e);
        }
        // SAFETY: `out` has `$k <= MAX_GROUP` elements (asserted above at
        // compile time) and the blocks above wrote each of them.
        unsafe { assume_init(&out) }
    }};
}

/// The array `a`, every element of which is initialised.
///
/// # Safety
/// Every element of `a` must be initialised.
#[inline(always)]
unsafe fn assume_init<T, const K: usize>(a: &[MaybeUninit<T>; K]) -> [T; K] {
    // SAFETY: `MaybeUninit<T>` has `T`'s layout, so `[MaybeUninit<T>; K]`
    // has `[T; K]`'s; the caller promises every element is initialised, and
    // the read copies them out of a live, aligned array.
    unsafe { std::ptr::read(a.as_ptr().cast::<[T; K]>()) }
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
                let o = L::splat(self.0[0].proof(), o);
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
    type Needs = L::Needs;

    #[inline(always)]
    fn proof(self) -> L::Needs {
        self.0[0].proof()
    }
    #[inline(always)]
    fn splat(cpu: L::Needs, x: f64) -> Self {
        Wide([L::splat(cpu, x); K])
    }
    #[inline(always)]
    fn load(cpu: L::Needs, s: &[f64]) -> Self {
        Wide(each!(K, |i| L::load(cpu, &s[i * L::N..])))
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
    #[inline(always)]
    fn compare<const P: i32>(self, o: Self) -> Self::Mask {
        Wide(each!(K, |i| self.0[i].compare::<P>(o.0[i])))
    }
    #[inline(always)]
    fn lookup(p: &Palette, index: Self) -> Self {
        Wide(each!(K, |i| L::lookup(p, index.0[i])))
    }
    #[inline(always)]
    fn fetch(r: &Records, index: Self) -> [Self; 8] {
        let each = each!(K, |i| L::fetch(r, index.0[i]));
        [
            Wide(each!(K, |i| each[i][0])),
            Wide(each!(K, |i| each[i][1])),
            Wide(each!(K, |i| each[i][2])),
            Wide(each!(K, |i| each[i][3])),
            Wide(each!(K, |i| each[i][4])),
            Wide(each!(K, |i| each[i][5])),
            Wide(each!(K, |i| each[i][6])),
            Wide(each!(K, |i| each[i][7])),
        ]
    }
}

/// `u64` lanes of a [`Wide`] (lane `i` lives in register `i / L::N`).
impl<B: BitsOps, const K: usize> BitsOps for Wide<B, K> {
    type Needs = B::Needs;
    #[inline(always)]
    fn splat(cpu: B::Needs, x: u64) -> Self {
        Wide([B::splat(cpu, x); K])
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
