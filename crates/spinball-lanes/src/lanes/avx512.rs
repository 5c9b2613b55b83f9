//! Eight `f64` lanes in an AVX-512 register, with mask registers for the
//! comparisons: Zen 4/5 and Xeon since Skylake-SP.
//!
//! The intrinsics are only sound on a CPU with AVX-512, which is known at run
//! time only. [`Avx512`]'s `Lanes::Needs` is the proof [`Avx512Cpu`], made
//! by detecting the features: every value holds one, so the compiler checks
//! that none is made without it. The operations of the same shape on every
//! level come from the `simd_lanes!` macro of the parent module; the mask
//! register logic and the permuting lookup are AVX-512's own.

#[cfg(target_arch = "x86")]
use std::arch::x86::*;
#[cfg(target_arch = "x86_64")]
use std::arch::x86_64::*;

use super::{EXP_SHIFT, MaskOps, Palette};
use crate::isa::Avx512Cpu;

/// Eight lanes in an AVX-512 register, and the proof that this CPU has
/// AVX-512.
///
/// # Invariant
/// Code that makes or uses an `Avx512` (or its [`Avx512Mask`],
/// [`Avx512Bits`]) runs only on a CPU with AVX-512 F, DQ, VL and BW. Every
/// value holds an [`Avx512Cpu`] (field `.1`, zero-sized, private to this
/// module), which only detection makes: the constructors (`Lanes::splat`,
/// `Lanes::load`, `BitsOps::splat`) take one, and every other operation
/// hands on its operands'. The compiler checks this; the `unsafe` blocks
/// below rest on it.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct Avx512(__m512d, Avx512Cpu);
/// `u64` lanes of [`Avx512`].
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct Avx512Bits(__m512i, Avx512Cpu);
/// A mask of [`Avx512`] lanes (one bit per lane, in a mask register).
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct Avx512Mask(__mmask8, Avx512Cpu);

impl std::ops::Neg for Avx512 {
    type Output = Avx512;
    #[inline(always)]
    fn neg(self) -> Avx512 {
        // SAFETY: `self.1` proves this CPU has AVX-512 F, DQ, VL and BW.
        Avx512(
            unsafe {
                _mm512_castsi512_pd(_mm512_xor_si512(
                    _mm512_castpd_si512(self.0),
                    _mm512_set1_epi64(i64::MIN),
                ))
            },
            self.1,
        )
    }
}

/// Mask-register logic: plain integer operations on the lane bits.
impl MaskOps for Avx512Mask {
    #[inline(always)]
    fn and(self, o: Self) -> Self {
        Avx512Mask(self.0 & o.0, self.1)
    }
    #[inline(always)]
    fn or(self, o: Self) -> Self {
        Avx512Mask(self.0 | o.0, self.1)
    }
    #[inline(always)]
    fn not(self) -> Self {
        Avx512Mask(!self.0, self.1)
    }
    #[inline(always)]
    fn any(self) -> bool {
        self.0 != 0
    }
}

simd_lanes! {
    Avx512, mask Avx512Mask, bits Avx512Bits, needs Avx512Cpu, lanes 8;
    pd { set1: _mm512_set1_pd, loadu: _mm512_loadu_pd, storeu: _mm512_storeu_pd,
         add: _mm512_add_pd, sub: _mm512_sub_pd, mul: _mm512_mul_pd, div: _mm512_div_pd,
         sqrt: _mm512_sqrt_pd, max: _mm512_max_pd }
    epi64 { set1: _mm512_set1_epi64, storeu: _mm512_storeu_si512, add: _mm512_add_epi64,
            sub: _mm512_sub_epi64, and: _mm512_and_si512, or: _mm512_or_si512,
            srli: _mm512_srli_epi64, slli: _mm512_slli_epi64, shift: EXP_SHIFT }
    cast { to_bits: _mm512_castpd_si512, to_pd: _mm512_castsi512_pd }
    own {
        #[inline(always)]
        fn abs(self) -> Self {
            // SAFETY: `self.1` proves this CPU has AVX-512 F, DQ, VL and BW.
            Avx512(unsafe { _mm512_abs_pd(self.0) }, self.1)
        }
        predicate_compares!(Avx512Mask, _mm512_cmp_pd_mask);
        #[inline(always)]
        fn select(m: Avx512Mask, a: Self, b: Self) -> Self {
            // Lanes with the mask bit set take the second operand.
            // SAFETY: `a.1` proves this CPU has AVX-512 F, DQ, VL and BW.
            Avx512(unsafe { _mm512_mask_blend_pd(m.0, b.0, a.0) }, a.1)
        }
        #[inline(always)]
        fn lookup(p: &Palette, index: Self) -> Self {
            let t = p.entries();
            // SAFETY: AVX-512 F and DQ intrinsics; `index.1` proves this CPU has
            // AVX-512 F, DQ, VL and BW. The loads read `t[0..8]` and, for 16 entries,
            // `t[8..16]`, inside `t`; the permutes use only the low 3 or 4 bits
            // of each index. The gather reads `t[k]` for each lane's index `k`,
            // clamped to `t.len() - 1` (a NaN or out-of-range lane converts to
            // `2^63` unsigned, which clamps too), so every read is inside `t`.
            Avx512(
                unsafe {
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
                },
                index.1,
            )
        }
    }
}
