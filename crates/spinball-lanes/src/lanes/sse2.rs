//! Two `f64` lanes in an SSE2 register: the baseline of x86-64.
//!
//! Compiled only where SSE2 is part of the target (every x86-64 target, and
//! 32-bit x86 targets such as i686 that enable it); a 32-bit target without
//! SSE2 (i586) runs the portable lanes at the baseline instead. Because the
//! whole binary already assumes SSE2 there, the intrinsics need no run-time
//! detection: every CPU that runs the binary has them.

#[cfg(target_arch = "x86")]
use std::arch::x86::*;
#[cfg(target_arch = "x86_64")]
use std::arch::x86_64::*;

use super::{BitsOps, EXP_SHIFT, Lanes, MANTISSA, MaskOps, ONE_BITS, Palette, Records};
use crate::isa::Baseline;

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
    // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
    // cfg), so every CPU that runs this binary has it.
    add: Sse2(unsafe { _mm_add_pd(a.0, b.0) }),
    // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
    // cfg), so every CPU that runs this binary has it.
    sub: Sse2(unsafe { _mm_sub_pd(a.0, b.0) }),
    // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
    // cfg), so every CPU that runs this binary has it.
    mul: Sse2(unsafe { _mm_mul_pd(a.0, b.0) }),
    // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
    // cfg), so every CPU that runs this binary has it.
    div: Sse2(unsafe { _mm_div_pd(a.0, b.0) }),
    // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
    // cfg), so every CPU that runs this binary has it.
    neg: Sse2(unsafe { _mm_xor_pd(a.0, _mm_set1_pd(-0.0)) }));

#[inline(always)]
fn sse2_splat(x: f64) -> Sse2 {
    // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
    // cfg), so every CPU that runs this binary has it.
    Sse2(unsafe { _mm_set1_pd(x) })
}

impl MaskOps for Sse2Mask {
    #[inline(always)]
    fn and(self, o: Self) -> Self {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2Mask(unsafe { _mm_and_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn or(self, o: Self) -> Self {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2Mask(unsafe { _mm_or_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn not(self) -> Self {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2Mask(unsafe { _mm_xor_pd(self.0, _mm_castsi128_pd(_mm_set1_epi64x(-1))) })
    }
    #[inline(always)]
    fn any(self) -> bool {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        unsafe { _mm_movemask_pd(self.0) != 0 }
    }
}

impl BitsOps for Sse2Bits {
    const W: usize = 2;
    #[inline(always)]
    fn splat(x: u64) -> Self {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2Bits(unsafe { _mm_set1_epi64x(x as i64) })
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2Bits(unsafe { _mm_add_epi64(self.0, o.0) })
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2Bits(unsafe { _mm_sub_epi64(self.0, o.0) })
    }
    fn lane(self, i: usize) -> u64 {
        let mut buf = [0u64; 2];
        // SAFETY: SSE2 (the target's); `buf` is 2 `u64`s, 16 bytes, so the
        // unaligned store writes only to it.
        unsafe { _mm_storeu_si128(buf.as_mut_ptr().cast(), self.0) };
        buf[i]
    }
}

impl Lanes for Sse2 {
    const N: usize = 2;
    type Mask = Sse2Mask;
    type Bits = Sse2Bits;
    type Needs = Baseline;
    #[inline(always)]
    fn splat(x: f64) -> Self {
        sse2_splat(x)
    }
    #[inline(always)]
    fn load(s: &[f64]) -> Self {
        let s = &s[..2];
        // SAFETY: SSE2 (the target's); `s` was cut to 2 elements, so the
        // unaligned 16-byte load reads only from it.
        Sse2(unsafe { _mm_loadu_pd(s.as_ptr()) })
    }
    #[inline(always)]
    fn store(self, s: &mut [f64]) {
        let s = &mut s[..2];
        // SAFETY: SSE2 (the target's); `s` was cut to 2 elements, so the
        // unaligned 16-byte store writes only to it.
        unsafe { _mm_storeu_pd(s.as_mut_ptr(), self.0) }
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2(unsafe { _mm_sqrt_pd(self.0) })
    }
    #[inline(always)]
    fn abs(self) -> Self {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2(unsafe { _mm_andnot_pd(_mm_set1_pd(-0.0), self.0) })
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2(unsafe { _mm_max_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn lt(self, o: Self) -> Sse2Mask {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2Mask(unsafe { _mm_cmplt_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn le(self, o: Self) -> Sse2Mask {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2Mask(unsafe { _mm_cmple_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn gt(self, o: Self) -> Sse2Mask {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2Mask(unsafe { _mm_cmpgt_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn ge(self, o: Self) -> Sse2Mask {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2Mask(unsafe { _mm_cmpge_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn eq(self, o: Self) -> Sse2Mask {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2Mask(unsafe { _mm_cmpeq_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn ne(self, o: Self) -> Sse2Mask {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2Mask(unsafe { _mm_cmpneq_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn select(m: Sse2Mask, a: Self, b: Self) -> Self {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2(unsafe { _mm_or_pd(_mm_and_pd(m.0, a.0), _mm_andnot_pd(m.0, b.0)) })
    }
    #[inline(always)]
    fn exponent(self) -> Sse2Bits {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2Bits(unsafe { _mm_srli_epi64::<{ EXP_SHIFT as i32 }>(_mm_castpd_si128(self.0)) })
    }
    #[inline(always)]
    fn mantissa(self) -> Self {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2(unsafe {
            _mm_castsi128_pd(_mm_or_si128(
                _mm_and_si128(_mm_castpd_si128(self.0), _mm_set1_epi64x(MANTISSA as i64)),
                _mm_set1_epi64x(ONE_BITS as i64),
            ))
        })
    }
    #[inline(always)]
    fn pow2(e: Sse2Bits) -> Self {
        // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the module's
        // cfg), so every CPU that runs this binary has it.
        Sse2(unsafe { _mm_castsi128_pd(_mm_slli_epi64::<{ EXP_SHIFT as i32 }>(e.0)) })
    }
    #[inline(always)]
    fn compare<const P: i32>(self, o: Self) -> Sse2Mask {
        // `cmpnlt`/`cmpnle` are true for NaN, as `!(a < b)`, `!(a <= b)`.
        match P {
            // SAFETY: an SSE2 intrinsic; SSE2 is part of the target (the
            // module's cfg), so every CPU that runs this binary has it.
            super::cmp::NLT => Sse2Mask(unsafe { _mm_cmpnlt_pd(self.0, o.0) }),
            // SAFETY: as above.
            super::cmp::NLE => Sse2Mask(unsafe { _mm_cmpnle_pd(self.0, o.0) }),
            super::cmp::EQ => self.eq(o),
            super::cmp::LT => self.lt(o),
            super::cmp::LE => self.le(o),
            super::cmp::GE => self.ge(o),
            super::cmp::GT => self.gt(o),
            _ => unreachable!("not a comparison of `cmp`"),
        }
    }
    #[inline(always)]
    fn lookup(p: &Palette, index: Self) -> Self {
        let mut i = [0.0; 2];
        index.store(&mut i);
        Self::load(&[p.get(i[0]), p.get(i[1])])
    }
    #[inline(always)]
    fn fetch(r: &Records, index: Self) -> [Self; 8] {
        let mut i = [0.0; 2];
        index.store(&mut i);
        let (a, b) = (r.row(i[0]), r.row(i[1]));
        // Columns `2j` and `2j + 1` from the two rows' entries `2j, 2j + 1`.
        let pair = |j: usize| -> (Sse2, Sse2) {
            let (x, y) = (Self::load(&a[2 * j..]), Self::load(&b[2 * j..]));
            // SAFETY: SSE2 intrinsics; SSE2 is part of the target (the
            // module's cfg), so every CPU that runs this binary has it.
            unsafe {
                (
                    Sse2(_mm_unpacklo_pd(x.0, y.0)),
                    Sse2(_mm_unpackhi_pd(x.0, y.0)),
                )
            }
        };
        let (c0, c1) = pair(0);
        let (c2, c3) = pair(1);
        let (c4, c5) = pair(2);
        let (c6, c7) = pair(3);
        [c0, c1, c2, c3, c4, c5, c6, c7]
    }
}
