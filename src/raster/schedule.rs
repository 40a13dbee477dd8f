//! Tile shading at flush points and in the background: tiles are shaded in parallel, each
//! replaying its commands in submission order (its bin, and in the background its queued
//! scenes oldest first), so the result does not depend on the number of threads or on the
//! order tiles are picked.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

use rayon::prelude::*;

use super::coarse::CoarseDepth;
use super::line_tile::LineShading;
use super::prefetch;
use super::scene::{ClearCommand, Command, Scene};
use super::setup::Plane;
use super::tri::{raster_triangle, AttrScratch};
use crate::common::rect::Rect;
use crate::fragment::span::{Interpolants, PrimitiveShared, UnitLevels};
use crate::framebuffer::{ColorBuffer, Tile};

/// Recorded commands after which a draw hands the scene to the shading workers and goes on
/// recording the next one (see `state::flush`).
pub const BACKGROUND_COMMANDS: usize = 1 << 12;

/// Recorded commands after which a draw hands the scene over early, when no worker has tiles
/// left to claim (at the start of a frame, or when the workers have caught up with the caller).
pub const EARLY_BACKGROUND_COMMANDS: usize = 1 << 9;

/// Scenes cap: past this many handed-off scenes not yet shaded everywhere, the caller's
/// thread shades queued tiles (or waits for one) before recording more; each scene is about
/// a megabyte, and a worker stalled on one tile (a descheduled thread) holds back only that
/// tile's later scenes until then.
pub(crate) const MAX_SCENES_IN_FLIGHT: usize = 6;

/// Background shading (see `state::flush`): the framebuffer's tiles, each
/// with the handed-off scenes still to be shaded in it, in order. A tile is shaded by one
/// thread at a time, its scenes one after the other, so every tile sees its commands in
/// submission order; different tiles (and a tile's later scenes) go on while another tile is
/// in progress, so no thread waits for another's tile except at a flush point.
pub(crate) struct InFlight {
    pub(crate) shared: Arc<Background>,
    /// The colour buffer the tiles hold.
    pub(crate) buffer: ColorBuffer,
}

/// What the background workers and the caller share while tiles are away from the
/// framebuffer.
pub(crate) struct Background {
    tiles: Vec<TileSlot>,
    /// Tiles with queued scenes and nobody shading them (each at most once).
    ready: Mutex<std::collections::VecDeque<usize>>,
    recycle: Arc<Recycle>,
    /// The caller's thread: woken whenever a tile's queue is done (it may wait for one).
    caller: std::thread::Thread,
}

struct TileSlot {
    pixels: Mutex<Tile>,
    /// Handed-off scenes with commands for this tile, oldest first.
    queue: Mutex<std::collections::VecDeque<Arc<SceneJob>>>,
    /// In `ready`, or being shaded (by whoever cleared it from `ready`).
    scheduled: std::sync::atomic::AtomicBool,
    /// The token of the thread that shaded the tile last (`thread_token`): a thread takes
    /// the ready tiles it shaded before first, whose pixels are still in its core's cache.
    /// (When the VM's two cores are far apart, each line of a tile that moved between them
    /// waits about 400 ns: spheremap 2T 1-2 % faster there, the same otherwise.)
    last: AtomicUsize,
}

/// A number for the current thread, distinct from every other thread's.
fn thread_token() -> usize {
    static NEXT: AtomicUsize = AtomicUsize::new(1);
    thread_local!(static TOKEN: usize = NEXT.fetch_add(1, Ordering::Relaxed));
    TOKEN.with(|t| *t)
}

/// Scenes that were shaded everywhere, reset for reuse, and the count of those in flight.
#[derive(Default)]
pub(crate) struct Recycle {
    pub(crate) scenes: Mutex<Vec<Scene>>,
    pub(crate) in_flight: AtomicUsize,
}

impl Recycle {
    /// Forgets the spare scenes (their bins no longer match a resized framebuffer).
    pub(crate) fn clear(&self) {
        lock(&self.scenes).clear();
    }
}

/// A handed-off scene; its last holder (the last tile to shade it) resets it and puts it back
/// for the caller to record into again.
struct SceneJob {
    scene: Option<Scene>,
    recycle: Arc<Recycle>,
}

impl Drop for SceneJob {
    fn drop(&mut self) {
        if let Some(mut scene) = self.scene.take() {
            scene.reset();
            lock(&self.recycle.scenes).push(scene);
        }
        self.recycle.in_flight.fetch_sub(1, Ordering::AcqRel);
    }
}

pub(crate) fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    // A panic while shading is caught where it happens; its tile keeps the pixels as far as
    // they got.
    m.lock().unwrap_or_else(|p| p.into_inner())
}

impl Background {
    pub(crate) fn new(tiles: Vec<Tile>, recycle: Arc<Recycle>) -> Background {
        Background {
            tiles: tiles
                .into_iter()
                .map(|t| TileSlot {
                    pixels: Mutex::new(t),
                    queue: Mutex::new(Default::default()),
                    scheduled: Default::default(),
                    last: Default::default(),
                })
                .collect(),
            ready: Mutex::new(Default::default()),
            recycle,
            caller: std::thread::current(),
        }
    }

    /// Queues `scene` on the tiles it has commands for, the busiest first.
    pub(crate) fn enqueue(&self, scene: Scene) {
        let mut order: Vec<usize> = (0..self.tiles.len())
            .filter(|&t| scene.bins.get(t).is_some_and(|b| !b.is_empty()))
            .collect();
        order.sort_by_key(|&t| std::cmp::Reverse(scene.bins[t].len()));
        self.recycle.in_flight.fetch_add(1, Ordering::AcqRel);
        let job = Arc::new(SceneJob {
            scene: Some(scene),
            recycle: Arc::clone(&self.recycle),
        });
        let mut newly_ready = Vec::with_capacity(order.len());
        for t in order {
            let slot = &self.tiles[t];
            lock(&slot.queue).push_back(Arc::clone(&job));
            if !slot.scheduled.swap(true, Ordering::SeqCst) {
                newly_ready.push(t);
            }
        }
        lock(&self.ready).extend(newly_ready);
    }

    /// Shades queued tiles until none is ready.
    pub(crate) fn shade_ready(&self) {
        let me = thread_token();
        // `take_ready` releases the lock before the tile is shaded.
        while let Some(t) = self.take_ready(me) {
            self.shade_queue(t);
        }
    }

    /// Takes a ready tile for the thread with token `me`: one it shaded last if any is ready,
    /// else the one ready longest.
    fn take_ready(&self, me: usize) -> Option<usize> {
        let mut ready = lock(&self.ready);
        let own = ready
            .iter()
            .position(|&t| self.tiles[t].last.load(Ordering::Relaxed) == me);
        match own {
            Some(i) => ready.remove(i),
            None => ready.pop_front(),
        }
    }

    /// Shades tile `t`'s queued scenes in order (the caller took `t` from `ready`).
    fn shade_queue(&self, t: usize) {
        let slot = &self.tiles[t];
        let mut pixels = lock(&slot.pixels);
        slot.last.store(thread_token(), Ordering::Relaxed);
        loop {
            let next = lock(&slot.queue).pop_front();
            if let Some(job) = next {
                if let Some(scene) = &job.scene {
                    let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                        shade_tile(scene, &scene.bins[t], &mut pixels)
                    }));
                }
                continue;
            }
            slot.scheduled.store(false, Ordering::SeqCst);
            // A hand-off may have queued a scene after the pop above and seen the tile still
            // scheduled: take it back unless that hand-off has made it ready again.
            if lock(&slot.queue).is_empty() || slot.scheduled.swap(true, Ordering::SeqCst) {
                break;
            }
        }
        drop(pixels);
        self.caller.unpark();
    }

    /// Takes every tile's pixels (each under its lock: a worker may still be leaving it).
    pub(crate) fn take_tiles(&self) -> Vec<Tile> {
        self.tiles
            .iter()
            .map(|slot| std::mem::take(&mut *lock(&slot.pixels)))
            .collect()
    }

    /// Whether no tile waits for a thread.
    pub(crate) fn nothing_ready(&self) -> bool {
        lock(&self.ready).is_empty()
    }
}

/// Shades the scene's tiles on the calling thread, one after the other: with one shading
/// thread, the thread that recorded the scene shades it, so the scene is read from the cache
/// it was written to. (Through a one-thread pool, the scene went to the pool's thread: on the
/// development VM, whose two virtual CPUs are at times placed far apart, with a cache line's
/// round trip between them at 400 ns instead of 100, that made spheremap 1T 21.6 ms instead of
/// 18.7; the same time otherwise.)
pub(crate) fn shade_here(scene: &Scene, tiles: &mut [Tile], visit: TileVisit) {
    for (tile, bin) in tiles.iter_mut().zip(&scene.bins) {
        if !bin.is_empty() {
            shade_tile(scene, bin, tile);
        }
        if let Some(f) = visit {
            f(tile);
        }
    }
}

/// What runs on each tile right after the scene's commands for it (or at once when it has
/// none), on the thread that shaded it, while its pixels are in that core's cache: the copy
/// of a finished picture into a C caller's buffer (`Context::for_each_tile`).
pub(crate) type TileVisit<'a> = Option<&'a (dyn Fn(&Tile) + Sync)>;

pub(crate) fn shade_all(scene: &Scene, tiles: &mut [Tile], visit: TileVisit) {
    // The busiest tiles first, each its own task: the workers finish the scene together
    // instead of one waiting for the other's last large tile (scenes are shaded one after
    // the other, so that wait is paid at every background hand-off). Tiles with nothing to
    // shade come last, when they are visited.
    let mut work: Vec<(&mut Tile, &Vec<u32>)> = tiles
        .iter_mut()
        .zip(&scene.bins)
        .filter(|(_, bin)| visit.is_some() || !bin.is_empty())
        .collect();
    work.sort_unstable_by_key(|(_, bin)| std::cmp::Reverse(bin.len()));
    work.into_par_iter()
        .with_max_len(1)
        .for_each(|(tile, bin)| {
            if !bin.is_empty() {
                shade_tile(scene, bin, tile);
            }
            if let Some(f) = visit {
                f(tile);
            }
        });
}

fn shade_tile(scene: &Scene, bin: &[u32], tile: &mut Tile) {
    // The texture levels of the last command's draw state (consecutive commands mostly share
    // one).
    let mut levels = UnitLevels::default();
    let mut levels_state = None;
    // A triangle's attribute planes spread over the full layout.
    let mut attrs = AttrScratch::default();
    let mut coarse = CoarseDepth::default();
    // The coverages of antialiased lines' pending runs (`LineShading`), made on first use.
    let mut coverage = Vec::new();
    // The first entries, which the loop's look-ahead never reaches.
    for k in 0..PREFETCH_COMMAND_AHEAD {
        prefetch_command(scene, bin, k);
    }
    for k in 0..PREFETCH_PLANES_AHEAD {
        prefetch_planes(scene, bin, k);
    }
    for (k, &ci) in bin.iter().enumerate() {
        prefetch_command(scene, bin, k + PREFETCH_COMMAND_AHEAD);
        prefetch_planes(scene, bin, k + PREFETCH_PLANES_AHEAD);
        let command = &scene.commands[ci as usize];
        let state = match command {
            Command::Clear(_) => None,
            Command::Triangle(t) => Some(t.state),
            Command::Rect(r) => Some(r.state),
            Command::Line(l) => Some(l.state),
        };
        if let Some(state) = state.filter(|&s| levels_state != Some(s)) {
            levels.prepare(&scene.states[state as usize].fragment);
            levels_state = Some(state);
        }
        match command {
            Command::Clear(c) => {
                clear_tile(c, tile);
                if c.depth.is_some() {
                    coarse.forget(tile, c.rect);
                }
            }
            Command::Triangle(t) => {
                let ds = &scene.states[t.state as usize];
                let at = t.planes as usize;
                let planes = &scene.planes[at..at + t.plane_count(ds)];
                if coarse.hides(tile, ds, &planes[0], t.bbox().intersect(&tile.rect())) {
                    continue;
                }
                raster_triangle(t, ds, planes, &levels, &mut attrs, tile);
                if ds.fragment.key.depth_write {
                    coarse.forget(tile, t.bbox());
                }
            }
            Command::Rect(r) => {
                let ds = &scene.states[r.state as usize];
                let attrs = &scene.planes[r.attrs as usize..r.attrs as usize + ds.attr_count];
                shade_rect(
                    ds,
                    tile,
                    &levels,
                    &mut coarse,
                    r.rect,
                    r.z,
                    attrs,
                    r.coverage,
                );
            }
            Command::Line(l) => {
                let line = &scene.lines[l.line as usize];
                let ds = &scene.states[l.state as usize];
                let (at, n) = (line.attrs as usize, line.n as usize);
                let ends = &scene.line_attrs[at..at + 2 * n];
                let mut shading = LineShading {
                    ds,
                    levels: &levels,
                    coarse: &mut coarse,
                    coverage: &mut coverage,
                };
                shading.line(line, ends, tile);
            }
        }
    }
}

/// The largest tile side (`framebuffer::TILE_SIZES`).
pub(super) const MAX_SIDE: usize = 128;

/// Shades the pixels of `rect` (inside the draw rectangle) in `tile` with constant
/// attributes: a point, a column of a line, or one pixel of an antialiased point or line.
#[allow(clippy::too_many_arguments)]
#[inline]
pub(super) fn shade_rect(
    ds: &super::draw::TileDraw,
    tile: &mut Tile,
    levels: &UnitLevels,
    coarse: &mut CoarseDepth,
    rect: Rect,
    z: f64,
    attrs: &[Plane],
    coverage: f32,
) {
    let shared = PrimitiveShared::new(levels);
    let it = Interpolants {
        z: Plane::constant(z),
        inv_w: Plane::constant(1.0),
        attrs,
        perspective: false,
        constant_primary: false,
        coverage,
        shared: &shared,
    };
    if ds.fragment.key.depth_write {
        coarse.forget(tile, rect);
    }
    let t = tile.side();
    let (x0, x1) = (rect.x0.max(tile.x0), rect.x1.min(tile.x0 + t));
    let (y0, y1) = (rect.y0.max(tile.y0), rect.y1.min(tile.y0 + t));
    if x0 < x1 {
        for y in y0..y1 {
            (ds.fragment.span)(&ds.fragment, tile, y, x0, x1, &it);
        }
    }
}

/// Bin entries ahead of the one being shaded whose command, and (nearer) whose planes, are
/// prefetched: the front end wrote them long before (or on another core), and a tile's
/// commands are scattered over the scene, so each first touch would otherwise wait on memory.
const PREFETCH_COMMAND_AHEAD: usize = 8;
const PREFETCH_PLANES_AHEAD: usize = 4;

/// Prefetches the command of bin entry `k` (if there is one).
#[inline(always)]
fn prefetch_command(scene: &Scene, bin: &[u32], k: usize) {
    if let Some(c) = bin.get(k).and_then(|&c| scene.commands.get(c as usize)) {
        prefetch::read(c, 1);
    }
}

/// Prefetches the planes of bin entry `k` when it is a triangle: their first three cache
/// lines, the z and 1/w planes and most attributes'.
#[inline(always)]
fn prefetch_planes(scene: &Scene, bin: &[u32], k: usize) {
    if let Some(Command::Triangle(t)) = bin.get(k).and_then(|&c| scene.commands.get(c as usize)) {
        if let Some(p) = scene.planes.get(t.planes as usize) {
            prefetch::read(p, 3);
        }
    }
}

fn clear_tile(c: &ClearCommand, tile: &mut Tile) {
    let t = tile.side();
    let x0 = c.rect.x0.max(tile.x0);
    let x1 = c.rect.x1.min(tile.x0 + t);
    let y0 = c.rect.y0.max(tile.y0);
    let y1 = c.rect.y1.min(tile.y0 + t);
    if x0 >= x1 || y0 >= y1 {
        return;
    }
    for y in y0..y1 {
        let row = tile.index(x0, y);
        let n = (x1 - x0) as usize;
        if let Some((rgba, mask)) = c.color {
            if mask == [true; 4] {
                tile.color[row..row + n].fill(rgba);
            } else {
                for px in &mut tile.color[row..row + n] {
                    for ch in 0..4 {
                        if mask[ch] {
                            px[ch] = rgba[ch];
                        }
                    }
                }
            }
        }
        if let Some(d) = c.depth {
            tile.depth[row..row + n].fill(d);
        }
        if let Some((s, m)) = c.stencil {
            for v in &mut tile.stencil[row..row + n] {
                *v = (*v & !m) | (s & m);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::rect::Rect;
    use crate::framebuffer::{Framebuffer, FramebufferConfig};

    /// A scene that clears the whole `fb` to `color`.
    fn clear_scene(fb: &Framebuffer, color: [u8; 4]) -> Scene {
        let mut scene = Scene::new(fb);
        let rect = Rect {
            x0: 0,
            y0: 0,
            x1: fb.width,
            y1: fb.height,
        };
        let clear = ClearCommand {
            rect,
            color: Some((color, [true; 4])),
            depth: None,
            stencil: None,
        };
        scene.bin(Command::Clear(clear), rect);
        scene
    }

    fn colour(c: u8) -> [u8; 4] {
        [c, 255 - c, c / 2, 255u8]
    }

    /// Scenes queued on a tile before anyone shades it are shaded oldest first (the last
    /// clear wins), each scene is recycled once every tile has shaded it, and the count of
    /// scenes in flight returns to zero.
    #[test]
    fn queued_scenes_are_shaded_in_order_and_recycled() {
        let fb = Framebuffer::new(192, 128, FramebufferConfig::default());
        let recycle = Arc::new(Recycle::default());
        let background = Background::new(fb.tiles.clone(), Arc::clone(&recycle));
        for c in [10, 120, 230] {
            background.enqueue(clear_scene(&fb, colour(c)));
        }
        assert_eq!(recycle.in_flight.load(Ordering::Acquire), 3);
        assert_eq!(lock(&background.ready).len(), fb.tiles.len());
        background.shade_ready();
        assert_eq!(recycle.in_flight.load(Ordering::Acquire), 0);
        assert_eq!(lock(&recycle.scenes).len(), 3);
        for slot in &background.tiles {
            assert!(lock(&slot.pixels).color.iter().all(|&p| p == colour(230)));
            assert!(!slot.scheduled.load(Ordering::Acquire));
        }
    }

    /// A thread takes the ready tiles it shaded last before the others, then the rest in the
    /// order they became ready.
    #[test]
    fn a_thread_takes_its_own_tiles_first() {
        let fb = Framebuffer::new(256, 64, FramebufferConfig::default());
        let background = Background::new(fb.tiles.clone(), Arc::new(Recycle::default()));
        let me = thread_token();
        background.tiles[2].last.store(me, Ordering::Relaxed);
        background.tiles[3].last.store(me + 1, Ordering::Relaxed);
        background.enqueue(clear_scene(&fb, colour(7)));
        // All four tiles have the same bin length: ready in tile order.
        assert_eq!(
            lock(&background.ready).iter().copied().collect::<Vec<_>>(),
            [0, 1, 2, 3]
        );
        let order: Vec<usize> = std::iter::from_fn(|| background.take_ready(me)).collect();
        assert_eq!(order, [2, 0, 1, 3]);
        assert_ne!(
            thread_token(),
            std::thread::spawn(thread_token).join().unwrap()
        );
    }

    /// Four threads shade while this one queues 300 scenes on the same tiles (the way the
    /// caller hands scenes off during shading): no scene is lost or shaded out of order (the
    /// last clear wins everywhere) and the work drains.
    #[test]
    fn concurrent_queueing_loses_no_scene() {
        let fb = Framebuffer::new(128, 128, FramebufferConfig::default());
        let recycle = Arc::new(Recycle::default());
        let background = Arc::new(Background::new(fb.tiles.clone(), Arc::clone(&recycle)));
        let stop = Arc::new(std::sync::atomic::AtomicBool::new(false));
        let workers: Vec<_> = (0..4)
            .map(|_| {
                let (background, stop) = (Arc::clone(&background), Arc::clone(&stop));
                std::thread::spawn(move || {
                    while !stop.load(Ordering::Acquire) {
                        background.shade_ready();
                        std::hint::spin_loop();
                    }
                })
            })
            .collect();
        for k in 0..20000u32 {
            background.enqueue(clear_scene(&fb, colour((k % 251) as u8)));
        }
        let deadline = std::time::Instant::now() + std::time::Duration::from_secs(20);
        while recycle.in_flight.load(Ordering::Acquire) != 0 {
            background.shade_ready();
            assert!(
                std::time::Instant::now() < deadline,
                "queued scenes never drained"
            );
            std::thread::yield_now();
        }
        stop.store(true, Ordering::Release);
        for w in workers {
            w.join().expect("a worker panicked");
        }
        for slot in &background.tiles {
            assert!(lock(&slot.pixels)
                .color
                .iter()
                .all(|&p| p == colour((19999 % 251) as u8)));
        }
    }
}
