//! Eight `f64` lanes in an AVX-512 register, with mask registers for the
//! comparisons: Zen 4/5 and Xeon since Skylake-SP.
//!
//! The intrinsics are only sound on a CPU with AVX-512, which is known at run
//! time only. [`Avx512`]'s `Lanes::Needs` is the proof [`Avx512Cpu`]: the
//! kernels run with it only given an `Avx512Cpu`, made by detecting the
//! features, and only inside the entry point compiled with AVX-512 enabled.

#[cfg(target_arch = "x86")]
use std::arch::x86::*;
#[cfg(target_arch = "x86_64")]
use std::arch::x86_64::*;

use super::{BitsOps, EXP_SHIFT, Lanes, MANTISSA, MaskOps, ONE_BITS, Palette};
use crate::isa::Avx512Cpu;

/// Eight lanes in an AVX-512 register.
///
/// # Invariant
/// Code that makes or uses an `Avx512` (or its [`Avx512Mask`],
/// [`Avx512Bits`]) runs only on a CPU with AVX-512 F, DQ, VL and BW. The
/// kernels run on lanes only through `kernels::run_chunks`, which takes a
/// proof `C` with `Needs: ProvenBy<C>` (checked by the compiler; here
/// `Needs` is [`Avx512Cpu`], made only by detection), and nothing else in
/// the crate makes these values.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx512(__m512d);
/// `u64` lanes of [`Avx512`].
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx512Bits(__m512i);
/// A mask of [`Avx512`] lanes (one bit per lane, in a mask register).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx512Mask(__mmask8);

ops!(Avx512, avx512_splat, |a, b|
// SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
// AVX-512 was detected (the type's invariant).
add: Avx512(unsafe { _mm512_add_pd(a.0, b.0) }),
// SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
// AVX-512 was detected (the type's invariant).
sub: Avx512(unsafe { _mm512_sub_pd(a.0, b.0) }),
// SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
// AVX-512 was detected (the type's invariant).
mul: Avx512(unsafe { _mm512_mul_pd(a.0, b.0) }),
// SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
// AVX-512 was detected (the type's invariant).
div: Avx512(unsafe { _mm512_div_pd(a.0, b.0) }),
// SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
// AVX-512 was detected (the type's invariant).
neg: Avx512(unsafe {
    _mm512_castsi512_pd(_mm512_xor_si512(
        _mm512_castpd_si512(a.0),
        _mm512_set1_epi64(i64::MIN),
    ))
}));

#[inline(always)]
fn avx512_splat(x: f64) -> Avx512 {
    // SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
    // AVX-512 was detected (the type's invariant).
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
        // SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
        // AVX-512 was detected (the type's invariant).
        Avx512Bits(unsafe { _mm512_set1_epi64(x as i64) })
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        // SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
        // AVX-512 was detected (the type's invariant).
        Avx512Bits(unsafe { _mm512_add_epi64(self.0, o.0) })
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        // SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
        // AVX-512 was detected (the type's invariant).
        Avx512Bits(unsafe { _mm512_sub_epi64(self.0, o.0) })
    }
    fn lane(self, i: usize) -> u64 {
        let mut buf = [0u64; 8];
        // SAFETY: AVX-512F (the type's invariant); `buf` is 8 `u64`s, 64 bytes, so the
        // unaligned store writes only to it.
        unsafe { _mm512_storeu_si512(buf.as_mut_ptr().cast(), self.0) };
        buf[i]
    }
}

macro_rules! avx512_cmp {
    ($($f:ident = $p:ident),*) => {$(
        #[inline(always)]
        fn $f(self, o: Self) -> Avx512Mask {
            // SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
            // AVX-512 was detected (the type's invariant).
            Avx512Mask(unsafe { _mm512_cmp_pd_mask::<$p>(self.0, o.0) })
        }
    )*};
}

impl Lanes for Avx512 {
    const N: usize = 8;
    type Mask = Avx512Mask;
    type Bits = Avx512Bits;
    type Needs = Avx512Cpu;
    #[inline(always)]
    fn splat(x: f64) -> Self {
        avx512_splat(x)
    }
    #[inline(always)]
    fn load(s: &[f64]) -> Self {
        let s = &s[..8];
        // SAFETY: AVX-512F (the type's invariant); `s` was cut to 8 elements, so the
        // unaligned 64-byte load reads only from it.
        Avx512(unsafe { _mm512_loadu_pd(s.as_ptr()) })
    }
    #[inline(always)]
    fn store(self, s: &mut [f64]) {
        let s = &mut s[..8];
        // SAFETY: AVX-512F (the type's invariant); `s` was cut to 8 elements, so the
        // unaligned 64-byte store writes only to it.
        unsafe { _mm512_storeu_pd(s.as_mut_ptr(), self.0) }
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        // SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
        // AVX-512 was detected (the type's invariant).
        Avx512(unsafe { _mm512_sqrt_pd(self.0) })
    }
    #[inline(always)]
    fn abs(self) -> Self {
        // SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
        // AVX-512 was detected (the type's invariant).
        Avx512(unsafe { _mm512_abs_pd(self.0) })
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        // SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
        // AVX-512 was detected (the type's invariant).
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
        // SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
        // AVX-512 was detected (the type's invariant).
        Avx512(unsafe { _mm512_mask_blend_pd(m.0, b.0, a.0) })
    }
    #[inline(always)]
    fn exponent(self) -> Avx512Bits {
        // SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
        // AVX-512 was detected (the type's invariant).
        Avx512Bits(unsafe { _mm512_srli_epi64::<EXP_SHIFT>(_mm512_castpd_si512(self.0)) })
    }
    #[inline(always)]
    fn mantissa(self) -> Self {
        // SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
        // AVX-512 was detected (the type's invariant).
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
        // SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
        // AVX-512 was detected (the type's invariant).
        Avx512(unsafe { _mm512_castsi512_pd(_mm512_slli_epi64::<EXP_SHIFT>(e.0)) })
    }
    #[inline(always)]
    fn compare<const P: i32>(self, o: Self) -> Avx512Mask {
        // SAFETY: an AVX-512F intrinsic; code with `Avx512` lanes runs only where
        // AVX-512 was detected (the type's invariant). `P` is one of `cmp`'s
        // predicates, all valid.
        Avx512Mask(unsafe { _mm512_cmp_pd_mask::<P>(self.0, o.0) })
    }
    #[inline(always)]
    fn lookup(p: &Palette, index: Self) -> Self {
        let t = p.entries();
        // SAFETY: AVX-512 F and DQ intrinsics; code with `Avx512` lanes runs
        // only where AVX-512 F, DQ, VL and BW were detected (the type's
        // invariant). The loads read `t[0..8]` and, for 16 entries,
        // `t[8..16]`, inside `t`; the permutes use only the low 3 or 4 bits
        // of each index. The gather reads `t[k]` for each lane's index `k`,
        // clamped to `t.len() - 1` (a NaN or out-of-range lane converts to
        // `2^63` unsigned, which clamps too), so every read is inside `t`.
        Avx512(unsafe {
            let k = _mm512_cvttpd_epi64(index.0);
            match t.len() {
                8 => _mm512_permutexvar_pd(k, _mm512_loadu_pd(t.as_ptr())),
                16 => _mm512_permutex2var_pd(
                    _mm512_loadu_pd(t.as_ptr()),
                    k,
                    _mm512_loadu_pd(t.as_ptr().add(8)),
                ),
                n => {
                    let k = _mm512_min_epu64(k, _mm512_set1_epi64(n as i64 - 1));
                    _mm512_i64gather_pd::<8>(k, t.as_ptr())
                }
            }
        })
    }
}
