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

use super::{EXP_SHIFT, Palette, Records};
use crate::isa::Baseline;

/// Two lanes in an SSE2 register, and the proof that the target has SSE2.
///
/// The proof, [`Baseline`], is free to make (every CPU that runs this
/// binary has SSE2); the type holds it as the AVX types hold theirs, so that
/// all three come from one macro.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct Sse2(__m128d, Baseline);
/// A mask of [`Sse2`] lanes (all ones or all zeros per lane).
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct Sse2Mask(__m128d, Baseline);
/// `u64` lanes of [`Sse2`].
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct Sse2Bits(__m128i, Baseline);

impl std::ops::Neg for Sse2 {
    type Output = Sse2;
    #[inline(always)]
    fn neg(self) -> Sse2 {
        // SAFETY: `self.1` proves this CPU has SSE2 (the target's).
        Sse2(unsafe { _mm_xor_pd(self.0, _mm_set1_pd(-0.0)) }, self.1)
    }
}

vector_mask!(Sse2Mask;
    and: _mm_and_pd,
    or: _mm_or_pd,
    xor: _mm_xor_pd,
    ones: _mm_castsi128_pd(_mm_set1_epi64x(-1)),
    movemask: _mm_movemask_pd);

simd_lanes! {
    Sse2, mask Sse2Mask, bits Sse2Bits, needs Baseline, lanes 2;
    pd { set1: _mm_set1_pd, loadu: _mm_loadu_pd, storeu: _mm_storeu_pd,
         add: _mm_add_pd, sub: _mm_sub_pd, mul: _mm_mul_pd, div: _mm_div_pd,
         sqrt: _mm_sqrt_pd, max: _mm_max_pd }
    epi64 { set1: _mm_set1_epi64x, storeu: _mm_storeu_si128, add: _mm_add_epi64,
            sub: _mm_sub_epi64, and: _mm_and_si128, or: _mm_or_si128,
            srli: _mm_srli_epi64, slli: _mm_slli_epi64, shift: EXP_SHIFT as i32 }
    cast { to_bits: _mm_castpd_si128, to_pd: _mm_castsi128_pd }
    own {
        #[inline(always)]
        fn abs(self) -> Self {
            // SAFETY: `self.1` proves this CPU has SSE2 (the target's).
            Sse2(unsafe { _mm_andnot_pd(_mm_set1_pd(-0.0), self.0) }, self.1)
        }
        #[inline(always)]
        fn lt(self, o: Self) -> Sse2Mask {
            // SAFETY: `self.1` proves this CPU has SSE2 (the target's).
            Sse2Mask(unsafe { _mm_cmplt_pd(self.0, o.0) }, self.1)
        }
        #[inline(always)]
        fn le(self, o: Self) -> Sse2Mask {
            // SAFETY: `self.1` proves this CPU has SSE2 (the target's).
            Sse2Mask(unsafe { _mm_cmple_pd(self.0, o.0) }, self.1)
        }
        #[inline(always)]
        fn gt(self, o: Self) -> Sse2Mask {
            // SAFETY: `self.1` proves this CPU has SSE2 (the target's).
            Sse2Mask(unsafe { _mm_cmpgt_pd(self.0, o.0) }, self.1)
        }
        #[inline(always)]
        fn ge(self, o: Self) -> Sse2Mask {
            // SAFETY: `self.1` proves this CPU has SSE2 (the target's).
            Sse2Mask(unsafe { _mm_cmpge_pd(self.0, o.0) }, self.1)
        }
        #[inline(always)]
        fn eq(self, o: Self) -> Sse2Mask {
            // SAFETY: `self.1` proves this CPU has SSE2 (the target's).
            Sse2Mask(unsafe { _mm_cmpeq_pd(self.0, o.0) }, self.1)
        }
        #[inline(always)]
        fn ne(self, o: Self) -> Sse2Mask {
            // SAFETY: `self.1` proves this CPU has SSE2 (the target's).
            Sse2Mask(unsafe { _mm_cmpneq_pd(self.0, o.0) }, self.1)
        }
        #[inline(always)]
        fn select(m: Sse2Mask, a: Self, b: Self) -> Self {
            // SAFETY: `a.1` proves this CPU has SSE2 (the target's).
            Sse2(unsafe { _mm_or_pd(_mm_and_pd(m.0, a.0), _mm_andnot_pd(m.0, b.0)) }, a.1)
        }
        #[inline(always)]
        fn compare<const P: i32>(self, o: Self) -> Sse2Mask {
            // `cmpnlt`/`cmpnle` are true for NaN, as `!(a < b)`, `!(a <= b)`.
            match P {
                // SAFETY: `self.1` proves this CPU has SSE2 (the target's).
                super::cmp::NLT => Sse2Mask(unsafe { _mm_cmpnlt_pd(self.0, o.0) }, self.1),
                // SAFETY: as above.
                super::cmp::NLE => Sse2Mask(unsafe { _mm_cmpnle_pd(self.0, o.0) }, self.1),
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
            Self::load(index.1, &[p.get(i[0]), p.get(i[1])])
        }
        #[inline(always)]
        fn fetch(r: &Records, index: Self) -> [Self; 8] {
            let mut i = [0.0; 2];
            index.store(&mut i);
            let (a, b) = (r.row(i[0]), r.row(i[1]));
            // Columns `2j` and `2j + 1` from the two rows' entries `2j, 2j + 1`.
            let pair = |j: usize| -> (Sse2, Sse2) {
                let (x, y) = (Self::load(index.1, &a[2 * j..]), Self::load(index.1, &b[2 * j..]));
                // SAFETY: `index.1` proves this CPU has SSE2 (the target's).
                unsafe {
                    (
                        Sse2(_mm_unpacklo_pd(x.0, y.0), index.1),
                        Sse2(_mm_unpackhi_pd(x.0, y.0), index.1),
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
}
