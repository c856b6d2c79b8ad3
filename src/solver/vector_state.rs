//! Clean vector registers after faer's dense matrix products.
//!
//! On x86-64, faer's matrix-multiply micro-kernels (the crate `private-gemm-x86`, hand-written
//! assembly) return with the upper halves of the AVX registers still in use: they end in `ret`
//! with no `vzeroupper`. Until some compiled AVX function clears them, every legacy-SSE
//! instruction pays the AVX/SSE transition penalty, and legacy SSE is all the scalar floating
//! point of a default x86-64 build: hycon's element and contact kernels, nalgebra, libm.
//! Measured on the development machine (AMD EPYC with AVX-512), reference Hertz scene, n = 32,
//! mu = 0.3: after the analysis' first Gram product of images the prescribed motion's element
//! forces took 0.035 s instead of 0.013 s, and the whole analysis 0.127 s instead of 0.104 s.
//!
//! Where hycon returns to its own scalar code straight from such a product, the product goes
//! through [`clean_after`]: the Gram products of images. The dense and sparse factorizations,
//! the triangular and sparse solves end in compiled AVX code, which clears the state (the
//! small system's unit tests check both); the products inside the substitutions within a reach
//! are followed by a triangular solve within a few scalar loops (cleaning there too changed no
//! timing of `bench contact`).

/// `f()`, then `vzeroupper` (on x86-64 CPUs with AVX; nothing elsewhere) before its result is
/// returned.
pub(crate) fn clean_after<T>(f: impl FnOnce() -> T) -> T {
    let out = f();
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx") {
        // SAFETY: the CPU has AVX, the one feature `zero_upper` is compiled for.
        unsafe { zero_upper() }
    }
    out
}

/// `vzeroupper`: zero bits 128 and up of the vector registers 0-15 (the state the transition
/// penalty follows).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
fn zero_upper() {
    std::arch::x86_64::_mm256_zeroupper();
}

/// Whether the upper halves of the AVX registers are in use (XINUSE bit 2, read with
/// `xgetbv(1)`); `None` where the CPU cannot tell.
#[cfg(all(test, target_arch = "x86_64"))]
pub(crate) fn upper_in_use() -> Option<bool> {
    use std::arch::is_x86_feature_detected;
    if !is_x86_feature_detected!("xsave") || !is_x86_feature_detected!("avx") {
        return None;
    }
    // (leaf 0xD is defined where XSAVE is)
    let has_xgetbv1 = std::arch::x86_64::__cpuid_count(0xd, 1).eax & 4 != 0;
    if !has_xgetbv1 {
        return None;
    }
    #[target_feature(enable = "xsave")]
    unsafe fn xinuse() -> u64 {
        // SAFETY: the caller checked that the CPU has XSAVE and xgetbv with ECX = 1.
        unsafe { std::arch::x86_64::_xgetbv(1) }
    }
    // SAFETY: the CPU has XSAVE and xgetbv with ECX = 1 (checked above).
    Some(unsafe { xinuse() } & 4 != 0)
}
