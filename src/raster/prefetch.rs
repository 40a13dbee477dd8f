//! Cache-line prefetches for the scene's hand-over between cores. The thread that records a
//! scene and the threads that shade it run on different cores; each line crosses between
//! them, and on the development VM a cache line's round trip between its two virtual CPUs
//! takes 45-120 ns in some phases and about 400 ns in others (when the host places them far
//! apart; `tilegl-conformance`'s `machine` module measures it). Asking for the lines early lets that wait overlap with work.

/// Asks for `lines` cache lines from `item`'s address to be read into the nearest cache.
#[inline(always)]
pub fn read<T>(item: &T, lines: usize) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        let p = item as *const T as *const i8;
        for line in 0..lines {
            // SAFETY: a prefetch is only a hint: it never faults or changes memory, whatever
            // the address.
            unsafe { _mm_prefetch::<_MM_HINT_T0>(p.wrapping_add(64 * line)) }
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (item, lines);
}

/// How far ahead of the recording thread's stores into a scene array its lines are asked
/// for, in bytes: a few triangles' worth of planes, enough to cover a slow round trip.
pub const WRITE_AHEAD: usize = 512;

/// Asks for the cache lines of the `bytes` bytes from `ahead` bytes past the end of `items`
/// (where the next pushes onto its vector go) with write ownership (x86 `PREFETCHW`), so
/// that the stores there do not wait. A recycled scene's lines were last read by a shading
/// thread on another core, and the first store to each waits until that core has given it
/// up: with these prefetches ahead of the recording thread's stores, spheremap 2T went from
/// 12.7 to 11.0 ms in the VM's slow phases (within 1 % in its fast ones).
#[inline(always)]
pub fn write_past<T>(items: &[T], ahead: usize, bytes: usize) {
    #[cfg(target_arch = "x86_64")]
    if prefetchw_available() {
        let next = (items.as_ptr() as *const u8)
            .wrapping_add(std::mem::size_of_val(items))
            .wrapping_add(ahead);
        for line in 0..bytes.div_ceil(64) {
            // SAFETY: the processor has the instruction (checked above); a prefetch never
            // faults or changes memory, whatever the address.
            unsafe { prefetchw(next.wrapping_add(64 * line)) }
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (items, ahead, bytes);
}

/// `PREFETCHW` of the line at `p`.
///
/// # Safety
/// The processor must have the instruction (`prefetchw_available`). Any address is allowed:
/// a prefetch never faults or changes memory.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn prefetchw(p: *const u8) {
    // SAFETY: the caller checked that the instruction exists; a prefetch never faults or
    // changes memory, whatever the address.
    unsafe {
        std::arch::asm!(
            "prefetchw [{}]",
            in(reg) p,
            options(nostack, preserves_flags, readonly)
        );
    }
}

/// Whether the processor has `PREFETCHW` (CPUID 0x8000_0001, ECX bit 8; `std`'s feature
/// detection does not name it), asked once.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn prefetchw_available() -> bool {
    use std::sync::atomic::{AtomicU8, Ordering};
    static KNOWN: AtomicU8 = AtomicU8::new(0);
    match KNOWN.load(Ordering::Relaxed) {
        1 => false,
        2 => true,
        _ => {
            let has = detect_prefetchw();
            KNOWN.store(if has { 2 } else { 1 }, Ordering::Relaxed);
            has
        }
    }
}

#[cfg(target_arch = "x86_64")]
#[cold]
fn detect_prefetchw() -> bool {
    use std::arch::x86_64::__cpuid;
    __cpuid(0x8000_0000).eax >= 0x8000_0001 && __cpuid(0x8000_0001).ecx & (1 << 8) != 0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Prefetches are hints: lines that must never be read (far past a vector's end, in the
    /// last page of the address space) are asked for without a fault.
    #[test]
    fn prefetching_past_the_end_is_harmless() {
        let v = vec![1u32; 10];
        read(&v[9], 64);
        for ahead in [0, 4096, usize::MAX / 2, usize::MAX - 64] {
            write_past(&v, ahead, 256);
            write_past(&v[..0], ahead, 64);
        }
        write_past(&[0u8; 0], 0, 64);
        assert_eq!(v, vec![1u32; 10]);
    }

    /// The CPUID test agrees with the kernel's name for the feature (`3dnowprefetch` in
    /// /proc/cpuinfo), where the kernel lists flags.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn prefetchw_detection_matches_the_kernel() {
        let Ok(info) = std::fs::read_to_string("/proc/cpuinfo") else {
            return;
        };
        let Some(flags) = info.lines().find(|l| l.starts_with("flags")) else {
            return;
        };
        let listed = flags.split_whitespace().any(|f| f == "3dnowprefetch");
        assert_eq!(detect_prefetchw(), listed, "{flags}");
    }
}
