//! Run-time CPU feature detection: whether the AVX2 kernels may run. Every stage that has an
//! AVX2 route (vertex texgen and transform, the viewport transform, coarse depth, texture
//! filtering, the eight-lane fragment paths) asks [`available`] and otherwise takes its scalar
//! twin.

/// The environment variable that switches the AVX2 paths off: with `TILEGL_NO_SIMD=1` (any
/// value but empty or `0`) [`available`] answers `false`, so every place that picks an AVX2
/// route at run time (texture filtering, the eight-pixel spans, texgen, the viewport
/// transform, coarse depth) takes its scalar twin, on any processor. Read once, at the first
/// question; the pictures are the same either way (`conformance/tests/determinism.rs`).
pub const NO_SIMD_ENV: &str = "TILEGL_NO_SIMD";

const UNKNOWN: u8 = 0;
const ON: u8 = 1;
const OFF: u8 = 2;

/// The answer of [`available`], once known.
static STATE: std::sync::atomic::AtomicU8 = std::sync::atomic::AtomicU8::new(UNKNOWN);

/// Whether the AVX2 paths (texture filtering and the others) may run: the processor has AVX2 and
/// [`NO_SIMD_ENV`] does not switch them off. One relaxed load after the first call, like the
/// standard library's own feature cache.
#[inline]
pub fn available() -> bool {
    match STATE.load(std::sync::atomic::Ordering::Relaxed) {
        ON => true,
        OFF => false,
        _ => detect(),
    }
}

#[cold]
fn detect() -> bool {
    let off = std::env::var_os(NO_SIMD_ENV).is_some_and(|v| !v.is_empty() && v != "0");
    #[cfg(target_arch = "x86_64")]
    let cpu = std::arch::is_x86_feature_detected!("avx2");
    #[cfg(not(target_arch = "x86_64"))]
    let cpu = false;
    let on = cpu && !off;
    STATE.store(
        if on { ON } else { OFF },
        std::sync::atomic::Ordering::Relaxed,
    );
    on
}
