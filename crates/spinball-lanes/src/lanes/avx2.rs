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

use super::{BitsOps, EXP_SHIFT, Lanes, MANTISSA, MaskOps, ONE_BITS, Palette};
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
        match t.len() {
            8 => {
                // SAFETY: AVX2 intrinsics; code with `Avx2` lanes runs only
                // where AVX2 was detected (the type's invariant). The loads
                // read `t[0..8]`, inside `t` (its length was just matched).
                unsafe { Avx2(permute8(index.0, (load(t, 0), load(t, 4)))) }
            }
            16 => {
                // SAFETY: as above; the loads read `t[0..16]`, inside `t`.
                unsafe {
                    let low = permute8(index.0, (load(t, 0), load(t, 4)));
                    let high = permute8(index.0, (load(t, 8), load(t, 12)));
                    // Bit 3 of the index, as the sign of both of a lane's
                    // 32-bit halves, picks the upper eight.
                    Avx2(_mm256_blendv_pd(low, high, index_bit(index.0, 3)))
                }
            }
            n => {
                // SAFETY: AVX2 intrinsics (and SSE4.1's `_mm_min_epu32`,
                // which AVX2 implies); code with `Avx2` lanes runs only where
                // AVX2 was detected (the type's invariant). The gather reads
                // `t[k]` for each lane's index `k`, clamped to `n - 1` (a NaN
                // or out-of-range lane converts to `i32::MIN`, which is
                // `2^31` unsigned, and clamps too), so every read is inside
                // `t`.
                Avx2(unsafe {
                    let k = _mm256_cvttpd_epi32(index.0);
                    let k = _mm_min_epu32(k, _mm_set1_epi32(n as i32 - 1));
                    _mm256_i32gather_pd::<8>(t.as_ptr(), k)
                })
            }
        }
    }
}

/// Four entries `t[at..at + 4]` of a palette, as 32-bit words for
/// [`permute8`].
///
/// # Safety
/// AVX is available, and `at + 4 <= t.len()`.
#[inline(always)]
unsafe fn load(t: &[f64], at: usize) -> __m256 {
    debug_assert!(at + 4 <= t.len());
    // SAFETY: AVX (the caller's promise); the 32-byte unaligned load reads
    // `t[at..at + 4]`, inside `t` by the caller's promise.
    unsafe { _mm256_castpd_ps(_mm256_loadu_pd(t.as_ptr().add(at))) }
}

/// The entries of an 8-entry palette `(t[0..4], t[4..8])` at each lane's
/// index (an integer `0..8` as `f64`; any other index, NaN included, gives
/// some entry), by moving data within registers: AVX2 has no 64-bit
/// permute across the register by variable indices, so a lane's index `k`
/// becomes the pair of 32-bit word indices `2k, 2k + 1`, both halves of
/// the register are permuted by them, and bit 2 of `k` picks the half.
/// Exactly the entries a gather would read, without the gather (slow on
/// AMD Zen, where it issues a load per lane in microcode).
///
/// # Safety
/// AVX2 is available.
#[inline(always)]
unsafe fn permute8(index: __m256d, (low, high): (__m256, __m256)) -> __m256d {
    // SAFETY: AVX/AVX2 intrinsics (the caller's promise); no memory access.
    unsafe {
        let words = word_indices(index);
        let from_low = _mm256_permutevar8x32_ps(low, words);
        let from_high = _mm256_permutevar8x32_ps(high, words);
        _mm256_castps_pd(_mm256_blendv_ps(
            from_low,
            from_high,
            _mm256_castpd_ps(index_bit(index, 2)),
        ))
    }
}

/// Each lane's index `k` (an `f64`, truncated) as the 32-bit words `2k` and
/// `2k + 1` of its lane.
///
/// # Safety
/// AVX2 is available.
#[inline(always)]
unsafe fn word_indices(index: __m256d) -> __m256i {
    // SAFETY: AVX/AVX2 intrinsics (the caller's promise); no memory access.
    unsafe {
        let k = _mm256_cvtepu32_epi64(_mm256_cvttpd_epi32(index));
        let twice = _mm256_add_epi64(k, k);
        let pair = _mm256_or_si256(twice, _mm256_slli_epi64::<32>(twice));
        _mm256_add_epi32(pair, _mm256_setr_epi32(0, 1, 0, 1, 0, 1, 0, 1))
    }
}

/// The lanes whose index (an `f64`, truncated) has bit `b` set (`b < 31`),
/// as the sign of both of the lane's 32-bit halves: the bits `blendv_pd` and
/// `blendv_ps` read (the rest is not a mask).
///
/// # Safety
/// AVX2 is available.
#[inline(always)]
unsafe fn index_bit(index: __m256d, b: u32) -> __m256d {
    // SAFETY: AVX/AVX2 intrinsics (the caller's promise); no memory access.
    unsafe {
        let k = _mm256_cvtepu32_epi64(_mm256_cvttpd_epi32(index));
        let pair = _mm256_or_si256(k, _mm256_slli_epi64::<32>(k));
        // Bit b to the sign of each 32-bit word.
        _mm256_castsi256_pd(_mm256_sll_epi32(pair, _mm_cvtsi32_si128(31 - b as i32)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `lookup` reads, bit for bit, the entry `Palette::get` reads, for
    /// palettes that take each path (8 and 16 entries permuted, 24
    /// gathered) and every index in every lane.
    #[test]
    fn lookup_reads_the_indexed_entry() {
        if Avx2Cpu::detect().is_none() {
            eprintln!("no AVX2 on this CPU: nothing to test");
            return;
        }
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
                // lane over the loop, in mixed halves of the palette.
                let index: Vec<f64> = (0..4).map(|j| ((first + 5 * j) % n) as f64).collect();
                let mut got = [0.0; 4];
                Avx2::lookup(&p, Avx2::load(&index)).store(&mut got);
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
}
