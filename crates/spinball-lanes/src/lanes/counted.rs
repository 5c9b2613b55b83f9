//! A one-lane [`Lanes`] type that counts the operations a kernel performs
//! (the "operation count" floor of `docs/PERFORMANCE.md`).
//!
//! It exists for a test (`kernels::tests::operation_counts_per_step`): run a
//! kernel on [`Counted`] and read how many additions, divisions, square
//! roots, ... one collision step costs, the least any instruction set can
//! execute.

use std::cell::Cell;
use std::ops::{Add, Div, Mul, Neg, Sub};

use super::{Lanes, MaskOps, Palette};
use crate::isa::Baseline;

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
    /// select (blend) and table lookup (permute)
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
    type Needs = Baseline;
    fn proof(self) -> Baseline {
        Baseline
    }
    fn splat(_: Baseline, x: f64) -> Self {
        Counted(x)
    }
    fn load(_: Baseline, s: &[f64]) -> Self {
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
        Counted(if self.0 > o.0 { self.0 } else { o.0 })
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
    fn compare<const P: i32>(self, o: Self) -> CMask {
        tick(Op::Cmp);
        CMask(f64::compare::<P>(self.0, o.0))
    }
    fn lookup(p: &Palette, index: Self) -> Self {
        tick(Op::Select);
        Counted(p.get(index.0))
    }
}
