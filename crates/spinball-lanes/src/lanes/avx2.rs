//! Four `f64` lanes in an AVX2 register: x86-64 since Haswell and Zen 1.
//!
//! The intrinsics are only sound on a CPU with AVX2, which is known at run
//! time only. [`Avx2`]'s `Lanes::Needs` is the proof [`Avx2Cpu`]: the
//! kernels run with it only given an `Avx2Cpu` (or an `Avx512Cpu`), made by
//! detecting the features, and only inside the entry points compiled with
//! AVX2 (or AVX-512) enabled.

#[cfg(target_arch = "x86")]
use std::arch::x86::*;
#[cfg(target_arch = "x86_64")]
use std::arch::x86_64::*;

use super::{BitsOps, EXP_SHIFT, Lanes, MANTISSA, MaskOps, ONE_BITS, Palette, Records};
use crate::isa::Avx2Cpu;

/// Four lanes in an AVX2 register.
///
/// # Invariant
/// Code that makes or uses an `Avx2` (or its [`Avx2Mask`], [`Avx2Bits`])
/// runs only on a CPU with AVX2. The kernels run on lanes only through
/// `kernels::run_chunks`, which takes a proof `C` with `Needs:
/// ProvenBy<C>` (checked by the compiler; here `Needs` is [`Avx2Cpu`], made
/// only by detection), and nothing else in the crate makes these values.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx2(__m256d);
/// A mask of [`Avx2`] lanes (all ones or all zeros per lane).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx2Mask(__m256d);
/// `u64` lanes of [`Avx2`].
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx2Bits(__m256i);

ops!(Avx2, avx2_splat, |a, b|
    // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
    // AVX2 was detected (the type's invariant).
    add: Avx2(unsafe { _mm256_add_pd(a.0, b.0) }),
    // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
    // AVX2 was detected (the type's invariant).
    sub: Avx2(unsafe { _mm256_sub_pd(a.0, b.0) }),
    // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
    // AVX2 was detected (the type's invariant).
    mul: Avx2(unsafe { _mm256_mul_pd(a.0, b.0) }),
    // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
    // AVX2 was detected (the type's invariant).
    div: Avx2(unsafe { _mm256_div_pd(a.0, b.0) }),
    // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
    // AVX2 was detected (the type's invariant).
    neg: Avx2(unsafe { _mm256_xor_pd(a.0, _mm256_set1_pd(-0.0)) }));

#[inline(always)]
fn avx2_splat(x: f64) -> Avx2 {
    // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
    // AVX2 was detected (the type's invariant).
    Avx2(unsafe { _mm256_set1_pd(x) })
}

impl MaskOps for Avx2Mask {
    #[inline(always)]
    fn and(self, o: Self) -> Self {
        // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant).
        Avx2Mask(unsafe { _mm256_and_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn or(self, o: Self) -> Self {
        // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant).
        Avx2Mask(unsafe { _mm256_or_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn not(self) -> Self {
        // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant).
        Avx2Mask(unsafe { _mm256_xor_pd(self.0, _mm256_castsi256_pd(_mm256_set1_epi64x(-1))) })
    }
    #[inline(always)]
    fn any(self) -> bool {
        // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant).
        unsafe { _mm256_movemask_pd(self.0) != 0 }
    }
}

impl BitsOps for Avx2Bits {
    const W: usize = 4;
    #[inline(always)]
    fn splat(x: u64) -> Self {
        // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant).
        Avx2Bits(unsafe { _mm256_set1_epi64x(x as i64) })
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant).
        Avx2Bits(unsafe { _mm256_add_epi64(self.0, o.0) })
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant).
        Avx2Bits(unsafe { _mm256_sub_epi64(self.0, o.0) })
    }
    fn lane(self, i: usize) -> u64 {
        let mut buf = [0u64; 4];
        // SAFETY: AVX (the type's invariant); `buf` is 4 `u64`s, 32 bytes, so the
        // unaligned store writes only to it.
        unsafe { _mm256_storeu_si256(buf.as_mut_ptr().cast(), self.0) };
        buf[i]
    }
}

macro_rules! avx_cmp {
    ($($f:ident = $p:ident),*) => {$(
        #[inline(always)]
        fn $f(self, o: Self) -> Avx2Mask {
            // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
            // AVX2 was detected (the type's invariant).
            Avx2Mask(unsafe { _mm256_cmp_pd::<$p>(self.0, o.0) })
        }
    )*};
}

impl Lanes for Avx2 {
    const N: usize = 4;
    type Mask = Avx2Mask;
    type Bits = Avx2Bits;
    type Needs = Avx2Cpu;
    #[inline(always)]
    fn splat(x: f64) -> Self {
        avx2_splat(x)
    }
    #[inline(always)]
    fn load(s: &[f64]) -> Self {
        let s = &s[..4];
        // SAFETY: AVX (the type's invariant); `s` was cut to 4 elements, so the
        // unaligned 32-byte load reads only from it.
        Avx2(unsafe { _mm256_loadu_pd(s.as_ptr()) })
    }
    #[inline(always)]
    fn store(self, s: &mut [f64]) {
        let s = &mut s[..4];
        // SAFETY: AVX (the type's invariant); `s` was cut to 4 elements, so the
        // unaligned 32-byte store writes only to it.
        unsafe { _mm256_storeu_pd(s.as_mut_ptr(), self.0) }
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant).
        Avx2(unsafe { _mm256_sqrt_pd(self.0) })
    }
    #[inline(always)]
    fn abs(self) -> Self {
        // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant).
        Avx2(unsafe { _mm256_andnot_pd(_mm256_set1_pd(-0.0), self.0) })
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant).
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
        // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant).
        Avx2(unsafe { _mm256_blendv_pd(b.0, a.0, m.0) })
    }
    #[inline(always)]
    fn exponent(self) -> Avx2Bits {
        // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant).
        Avx2Bits(unsafe { _mm256_srli_epi64::<{ EXP_SHIFT as i32 }>(_mm256_castpd_si256(self.0)) })
    }
    #[inline(always)]
    fn mantissa(self) -> Self {
        // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant).
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
        // SAFETY: an AVX/AVX2 intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant).
        Avx2(unsafe { _mm256_castsi256_pd(_mm256_slli_epi64::<{ EXP_SHIFT as i32 }>(e.0)) })
    }
    #[inline(always)]
    fn compare<const P: i32>(self, o: Self) -> Avx2Mask {
        // SAFETY: an AVX intrinsic; code with `Avx2` lanes runs only where
        // AVX2 was detected (the type's invariant). `P` is one of `cmp`'s
        // predicates, all valid.
        Avx2Mask(unsafe { _mm256_cmp_pd::<P>(self.0, o.0) })
    }
    #[inline(always)]
    fn lookup(p: &Palette, index: Self) -> Self {
        let t = p.entries();
        // SAFETY: AVX2 intrinsics (and SSE4.1's `_mm_min_epu32`, which AVX2
        // implies); code with `Avx2` lanes runs only where AVX2 was detected
        // (the type's invariant). The gather reads `t[k]` for each lane's
        // index `k`, clamped to `t.len() - 1` (a NaN or out-of-range lane
        // converts to `i32::MIN`, which is `2^31` unsigned, and clamps too),
        // so every read is inside `t`.
        Avx2(unsafe {
            let k = _mm256_cvttpd_epi32(index.0);
            let k = _mm_min_epu32(k, _mm_set1_epi32(t.len() as i32 - 1));
            _mm256_i32gather_pd::<8>(t.as_ptr(), k)
        })
    }
    #[inline(always)]
    fn fetch(r: &Records, index: Self) -> [Self; 8] {
        let rows = r.rows();
        // Each lane's index, clamped as `lookup` clamps it (the rows are as
        // many as a column's entries).
        // SAFETY: AVX2 and SSE4.1 intrinsics (AVX2 implies SSE4.1); code
        // with `Avx2` lanes runs only where AVX2 was detected (the type's
        // invariant).
        let k = unsafe {
            let k = _mm256_cvttpd_epi32(index.0);
            _mm_min_epu32(k, _mm_set1_epi32(rows.len() as i32 - 1))
        };
        let lane = |i: i32| -> &[f64; 8] {
            // SAFETY: SSE4.1 intrinsics, as above (`rows[k]` is then
            // bounds-checked).
            let k = unsafe {
                match i {
                    0 => _mm_extract_epi32::<0>(k),
                    1 => _mm_extract_epi32::<1>(k),
                    2 => _mm_extract_epi32::<2>(k),
                    _ => _mm_extract_epi32::<3>(k),
                }
            };
            &rows[k as u32 as usize]
        };
        let (a, b, c, d) = (lane(0), lane(1), lane(2), lane(3));
        // Columns `2j` and `2j + 1`: lanes 0 and 2 of the pair in one
        // register, lanes 1 and 3 in another, interleaved.
        let pair = |j: usize| -> (Avx2, Avx2) {
            // SAFETY: AVX intrinsics (the type's invariant); each 16-byte
            // load reads entries `2j, 2j + 1` (`j < 4`) of a row of 8.
            unsafe {
                let two = |row: &[f64; 8]| _mm_loadu_pd(row[2 * j..2 * j + 2].as_ptr());
                let ac = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(two(a)), two(c));
                let bd = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(two(b)), two(d));
                (
                    Avx2(_mm256_unpacklo_pd(ac, bd)),
                    Avx2(_mm256_unpackhi_pd(ac, bd)),
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
