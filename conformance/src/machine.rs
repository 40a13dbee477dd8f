//! The state of the machine when a benchmark runs: the time a cache line takes to go from one
//! core to another and back. On the shared VM tilegl was developed on, this flips between
//! about 100 ns and about 400 ns every minute or so (the host places the two virtual CPUs near
//! each other or far apart); in the slow phases every multi-threaded renderer (tilegl 2T,
//! llvmpipe) loses speed, since the scenes, tiles and locks its threads share cross between
//! the cores, while single-threaded softpipe does not. The benchmark prints it beside each
//! implementation's time, so that each ratio is read together with the phase it was measured
//! in.

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::time::Instant;

/// Round trips per measurement (a few milliseconds).
const TRIPS: u64 = 20_000;

/// The median of five measurements of a cache line's round trip between CPU 0 and CPU 1, in
/// nanoseconds: two threads, pinned one to each, pass a counter back and forth. `None` when
/// the machine has one CPU or the threads cannot be pinned (unpinned threads may share a CPU
/// and measure the scheduler instead).
pub fn cross_core_round_trip_ns() -> Option<f64> {
    if std::thread::available_parallelism().map_or(1, |n| n.get()) < 2 {
        return None;
    }
    let mut batches = Vec::new();
    for _ in 0..5 {
        batches.push(measure(0, 1)?);
    }
    batches.sort_by(f64::total_cmp);
    Some(batches[2])
}

/// One measurement between CPUs `here` (this thread) and `there` (a spawned one).
fn measure(here: usize, there: usize) -> Option<f64> {
    let ball = AtomicU64::new(0);
    // Set by a side that gives up (it could not be pinned); never cleared, so neither side
    // can wait for a counter the other will not advance.
    let abort = AtomicBool::new(false);
    std::thread::scope(|s| {
        let (ball, abort) = (&ball, &abort);
        let other = s.spawn(move || {
            if !pin_to_cpu(there) {
                abort.store(true, Ordering::Release);
                return false;
            }
            for k in 0..TRIPS {
                if !wait_for(ball, abort, 2 * k + 1) {
                    return false;
                }
                ball.store(2 * k + 2, Ordering::Release);
            }
            true
        });
        let saved = affinity();
        let mut ok = saved.is_some() && pin_to_cpu(here);
        if ok {
            // The first trip waits for the other thread to start: not timed.
            ball.store(1, Ordering::Release);
            ok = wait_for(ball, abort, 2);
        }
        let start = Instant::now();
        let mut k = 1;
        while ok && k < TRIPS {
            ball.store(2 * k + 1, Ordering::Release);
            ok = wait_for(ball, abort, 2 * k + 2);
            k += 1;
        }
        let elapsed = start.elapsed().as_secs_f64();
        if !ok {
            abort.store(true, Ordering::Release);
        }
        let other_ok = other.join().unwrap_or(false);
        if let Some(mask) = saved {
            set_affinity(&mask);
        }
        (ok && other_ok).then(|| elapsed * 1e9 / (TRIPS - 1) as f64)
    })
}

/// Spins until the counter is `value` (true) or a side gave up (false).
fn wait_for(ball: &AtomicU64, abort: &AtomicBool, value: u64) -> bool {
    loop {
        if ball.load(Ordering::Acquire) == value {
            return true;
        }
        if abort.load(Ordering::Acquire) {
            return false;
        }
        std::hint::spin_loop();
    }
}

/// Bytes of glibc's `cpu_set_t` (1024 CPUs).
const CPU_SET_BYTES: usize = 128;

/// glibc's `cpu_set_t`: one bit per CPU.
type CpuSet = [u64; CPU_SET_BYTES / 8];

extern "C" {
    /// glibc's `sched_setaffinity(2)` wrapper (pid 0: the calling thread).
    fn sched_setaffinity(pid: i32, cpusetsize: usize, mask: *const u64) -> i32;
    /// glibc's `sched_getaffinity(2)` wrapper (pid 0: the calling thread).
    fn sched_getaffinity(pid: i32, cpusetsize: usize, mask: *mut u64) -> i32;
}

/// The CPUs the calling thread may run on.
fn affinity() -> Option<CpuSet> {
    let mut mask: CpuSet = [0; CPU_SET_BYTES / 8];
    // SAFETY: `mask` is a writable buffer of `CPU_SET_BYTES` bytes that outlives the call,
    // and pid 0 names the calling thread.
    let ok = unsafe { sched_getaffinity(0, CPU_SET_BYTES, mask.as_mut_ptr()) } == 0;
    ok.then_some(mask)
}

/// Lets the calling thread run on the CPUs of `mask`; false when the system refuses.
fn set_affinity(mask: &CpuSet) -> bool {
    // SAFETY: `mask` is an initialized buffer of `CPU_SET_BYTES` bytes that outlives the
    // call, and pid 0 names the calling thread.
    unsafe { sched_setaffinity(0, CPU_SET_BYTES, mask.as_ptr()) == 0 }
}

/// Pins the calling thread to `cpu`; false when the system refuses.
fn pin_to_cpu(cpu: usize) -> bool {
    if cpu >= 8 * CPU_SET_BYTES {
        return false;
    }
    let mut mask: CpuSet = [0; CPU_SET_BYTES / 8];
    mask[cpu / 64] |= 1 << (cpu % 64);
    set_affinity(&mask)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The measurement returns a plausible round trip on a machine with two CPUs (between
    /// 10 ns, faster than any cache line can travel, and 100 µs, a time slice), and gives the
    /// calling thread back the CPUs it had.
    #[test]
    fn round_trip_is_plausible_and_restores_the_affinity() {
        if std::thread::available_parallelism().map_or(1, |n| n.get()) < 2 {
            return;
        }
        let before = affinity().expect("sched_getaffinity");
        let Some(ns) = cross_core_round_trip_ns() else {
            // A restricted cpuset: nothing to measure here.
            return;
        };
        assert!((10.0..100_000.0).contains(&ns), "{ns} ns");
        assert_eq!(affinity(), Some(before));
    }

    /// A side that cannot be pinned (a CPU the machine does not have) gives up without
    /// leaving the other waiting, on either side, and the affinity is restored.
    #[test]
    fn an_unpinnable_side_gives_up() {
        let before = affinity().expect("sched_getaffinity");
        assert_eq!(measure(0, 1023), None);
        assert_eq!(measure(1023, 0), None);
        assert_eq!(affinity(), Some(before));
    }
}
