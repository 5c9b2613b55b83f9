//! Four `f64` lanes in an AVX2 register: x86-64 since Haswell and Zen 1.
//!
//! The intrinsics are only sound on a CPU with AVX2, which is known at run
//! time only. [`Avx2`]'s `Lanes::Needs` is the proof [`Avx2Cpu`], made by
//! detecting the features: every value holds one, so the compiler checks
//! that none is made without it. The operations of the same shape on every
//! level come from the `simd_lanes!` macro of the parent module; the
//! gather and the transposing fetch are AVX2's own.

#[cfg(target_arch = "x86")]
use std::arch::x86::*;
#[cfg(target_arch = "x86_64")]
use std::arch::x86_64::*;

use super::{EXP_SHIFT, Palette, Records};
use crate::isa::Avx2Cpu;

/// Four lanes in an AVX2 register, and the proof that this CPU has AVX2.
///
/// # Invariant
/// Code that makes or uses an `Avx2` (or its [`Avx2Mask`], [`Avx2Bits`])
/// runs only on a CPU with AVX2. Every value holds an [`Avx2Cpu`] (field
/// `.1`, zero-sized, private to this module), which only detection makes:
/// the constructors (`Lanes::splat`, `Lanes::load`, `BitsOps::splat`) take
/// one, and every other operation hands on its operands'. The compiler
/// checks this; the `unsafe` blocks below rest on it.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct Avx2(__m256d, Avx2Cpu);
/// A mask of [`Avx2`] lanes (all ones or all zeros per lane).
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct Avx2Mask(__m256d, Avx2Cpu);
/// `u64` lanes of [`Avx2`].
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct Avx2Bits(__m256i, Avx2Cpu);

impl std::ops::Neg for Avx2 {
    type Output = Avx2;
    #[inline(always)]
    fn neg(self) -> Avx2 {
        // SAFETY: `self.1` proves this CPU has AVX2.
        Avx2(
            unsafe { _mm256_xor_pd(self.0, _mm256_set1_pd(-0.0)) },
            self.1,
        )
    }
}

vector_mask!(Avx2Mask;
    and: _mm256_and_pd,
    or: _mm256_or_pd,
    xor: _mm256_xor_pd,
    ones: _mm256_castsi256_pd(_mm256_set1_epi64x(-1)),
    movemask: _mm256_movemask_pd);

simd_lanes! {
    Avx2, mask Avx2Mask, bits Avx2Bits, needs Avx2Cpu, lanes 4;
    pd { set1: _mm256_set1_pd, loadu: _mm256_loadu_pd, storeu: _mm256_storeu_pd,
         add: _mm256_add_pd, sub: _mm256_sub_pd, mul: _mm256_mul_pd, div: _mm256_div_pd,
         sqrt: _mm256_sqrt_pd, max: _mm256_max_pd }
    epi64 { set1: _mm256_set1_epi64x, storeu: _mm256_storeu_si256, add: _mm256_add_epi64,
            sub: _mm256_sub_epi64, and: _mm256_and_si256, or: _mm256_or_si256,
            srli: _mm256_srli_epi64, slli: _mm256_slli_epi64, shift: EXP_SHIFT as i32 }
    cast { to_bits: _mm256_castpd_si256, to_pd: _mm256_castsi256_pd }
    own {
        #[inline(always)]
        fn abs(self) -> Self {
            // SAFETY: `self.1` proves this CPU has AVX2.
            Avx2(unsafe { _mm256_andnot_pd(_mm256_set1_pd(-0.0), self.0) }, self.1)
        }
        predicate_compares!(Avx2Mask, _mm256_cmp_pd);
        #[inline(always)]
        fn select(m: Avx2Mask, a: Self, b: Self) -> Self {
            // SAFETY: `a.1` proves this CPU has AVX2.
            Avx2(unsafe { _mm256_blendv_pd(b.0, a.0, m.0) }, a.1)
        }
        #[inline(always)]
        fn lookup(p: &Palette, index: Self) -> Self {
            let t = p.entries();
            // SAFETY: AVX2 intrinsics (and SSE4.1's `_mm_min_epu32`, which AVX2
            // implies); `index.1` proves this CPU has AVX2. The gather reads `t[k]` for each lane's
            // index `k`, clamped to `t.len() - 1` (a NaN or out-of-range lane
            // converts to `i32::MIN`, which is `2^31` unsigned, and clamps too),
            // so every read is inside `t`.
            Avx2(
                unsafe {
                    let k = _mm256_cvttpd_epi32(index.0);
                    let k = _mm_min_epu32(k, _mm_set1_epi32(t.len() as i32 - 1));
                    _mm256_i32gather_pd::<8>(t.as_ptr(), k)
                },
                index.1,
            )
        }
        #[inline(always)]
        fn fetch(r: &Records, index: Self) -> [Self; 8] {
            let rows = r.rows();
            // Each lane's index, clamped as `lookup` clamps it (the rows are as
            // many as a column's entries).
            // SAFETY: AVX2 and SSE4.1 intrinsics (AVX2 implies SSE4.1);
            // `index.1` proves this CPU has AVX2.
            let k = unsafe {
                let k = _mm256_cvttpd_epi32(index.0);
                _mm_min_epu32(k, _mm_set1_epi32(rows.len() as i32 - 1))
            };
            // Helper functions rather than closures: a closure does not
            // take on the caller's target features and, in a large kernel,
            // may be left out of line, its intrinsics then called one by one.
            let (a, b, c, d) = (
                row::<0>(rows, k, index.1),
                row::<1>(rows, k, index.1),
                row::<2>(rows, k, index.1),
                row::<3>(rows, k, index.1),
            );
            let (c0, c1) = pair::<0>([a, b, c, d], index.1);
            let (c2, c3) = pair::<2>([a, b, c, d], index.1);
            let (c4, c5) = pair::<4>([a, b, c, d], index.1);
            let (c6, c7) = pair::<6>([a, b, c, d], index.1);
            [c0, c1, c2, c3, c4, c5, c6, c7]
        }
    }
}

/// Row `k[I]` of `rows` (`k` clamped to the rows); `cpu` proves AVX2.
#[inline(always)]
fn row<const I: i32>(rows: &[[f64; 8]], k: __m128i, _cpu: Avx2Cpu) -> &[f64; 8] {
    // SAFETY: an SSE4.1 intrinsic (AVX2 implies SSE4.1); `cpu` proves this
    // CPU has AVX2. `rows[k]` is then bounds-checked.
    let k = unsafe {
        match I {
            0 => _mm_extract_epi32::<0>(k),
            1 => _mm_extract_epi32::<1>(k),
            2 => _mm_extract_epi32::<2>(k),
            _ => _mm_extract_epi32::<3>(k),
        }
    };
    &rows[k as u32 as usize]
}

/// Columns `C` and `C + 1` of the four rows `[a, b, c, d]` (one per lane),
/// transposed: lanes 0 and 2 of the pair in one register, lanes 1 and 3 in
/// another, interleaved; `cpu` proves AVX2.
#[inline(always)]
fn pair<const C: usize>(rows: [&[f64; 8]; 4], cpu: Avx2Cpu) -> (Avx2, Avx2) {
    const { assert!(C < 7) };
    let [a, b, c, d] = rows;
    // SAFETY: AVX intrinsics (`cpu` proves AVX2); each 16-byte load reads
    // entries `C, C + 1` (`C < 7`) of a row of 8.
    unsafe {
        let ac = _mm256_insertf128_pd::<1>(
            _mm256_castpd128_pd256(_mm_loadu_pd(a[C..C + 2].as_ptr())),
            _mm_loadu_pd(c[C..C + 2].as_ptr()),
        );
        let bd = _mm256_insertf128_pd::<1>(
            _mm256_castpd128_pd256(_mm_loadu_pd(b[C..C + 2].as_ptr())),
            _mm_loadu_pd(d[C..C + 2].as_ptr()),
        );
        (
            Avx2(_mm256_unpacklo_pd(ac, bd), cpu),
            Avx2(_mm256_unpackhi_pd(ac, bd), cpu),
        )
    }
}
