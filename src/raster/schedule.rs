//! Flush points: shade every tile in parallel, each replaying its bin in submission order. The
//! result does not depend on the number of threads or the order tiles are picked.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::Receiver;
use std::sync::{Arc, Mutex};

use rayon::prelude::*;

use super::coarse::CoarseDepth;
use super::scene::{ClearCommand, Command, Scene};
use super::setup::Plane;
use super::tri::{raster_triangle, AttrScratch};
use crate::fragment::span::{Interpolants, PrimitiveShared, UnitLevels};
use crate::framebuffer::{ColorBuffer, DrawTarget, Tile};
use crate::state::Context;

/// Recorded commands after which a draw hands the scene to the shading workers and goes on
/// recording the next one (see `Context::flush_in_background`).
pub const BACKGROUND_COMMANDS: usize = 1 << 12;

/// Recorded commands after which a draw hands the scene over early, when no worker has tiles
/// left to claim (at the start of a frame, or when the workers have caught up with the caller).
pub const EARLY_BACKGROUND_COMMANDS: usize = 1 << 9;

/// A scene being shaded in the background while the caller's thread records the next one
/// (see `Context::flush_in_background`): it owns the framebuffer's tiles until the caller
/// joins it.
pub(crate) struct InFlight {
    shared: Arc<Background>,
    /// One message from each background worker once it has stopped claiming tiles and let go
    /// of `shared`.
    stopped: Receiver<()>,
    workers: usize,
}

/// The scene and tiles shared by the background workers and, when it joins, the caller.
struct Background {
    scene: Scene,
    tiles: Vec<Mutex<Tile>>,
    /// Indices of the tiles with work, the busiest first (each worker then finishes with
    /// small tiles instead of waiting on another's last large one).
    order: Vec<usize>,
    /// The next entry of `order` to claim.
    next: AtomicUsize,
}

impl Background {
    fn new(scene: Scene, tiles: Vec<Tile>) -> Background {
        let mut order: Vec<usize> = (0..tiles.len())
            .filter(|&t| scene.bins.get(t).is_some_and(|b| !b.is_empty()))
            .collect();
        order.sort_by_key(|&t| std::cmp::Reverse(scene.bins[t].len()));
        Background {
            scene,
            tiles: tiles.into_iter().map(Mutex::new).collect(),
            order,
            next: AtomicUsize::new(0),
        }
    }

    /// Claims and shades tiles until none is left unclaimed. A panic while shading leaves
    /// that tile's lock poisoned; its pixels are then as far as they got.
    fn shade_claimed(&self) {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| loop {
            let i = self.next.fetch_add(1, Ordering::Relaxed);
            let Some(&t) = self.order.get(i) else {
                return;
            };
            let mut tile = self.tiles[t].lock().unwrap_or_else(|p| p.into_inner());
            shade_tile(&self.scene, &self.scene.bins[t], &mut tile);
        }));
    }
}

impl Context {
    /// Finishes the scene in the background (if any), shading the tiles nobody has claimed
    /// yet on this thread, and puts the tiles back.
    pub(crate) fn join_background(&mut self) {
        let Some(flight) = self.in_flight.take() else {
            return;
        };
        flight.shared.shade_claimed();
        // Every worker has stopped claiming once it reports; tiles it was shading are done.
        for _ in 0..flight.workers {
            if flight.stopped.recv().is_err() {
                break;
            }
        }
        match Arc::try_unwrap(flight.shared) {
            Ok(done) => {
                self.framebuffer.tiles = done
                    .tiles
                    .into_iter()
                    .map(|t| t.into_inner().unwrap_or_else(|p| p.into_inner()))
                    .collect();
                let mut scene = done.scene;
                scene.reset();
                self.spare_scene = Some(scene);
            }
            // A worker never stops without reporting (it catches panics and lets go of the
            // scene first); should one ever, the pixels are lost but the framebuffer stays
            // usable.
            Err(_) => {
                let (w, h, config) = (
                    self.framebuffer.width,
                    self.framebuffer.height,
                    self.framebuffer.config,
                );
                self.framebuffer = crate::framebuffer::Framebuffer::new(w, h, config);
                self.apply_buffer_selection();
            }
        }
    }

    /// When the scene has grown past [`BACKGROUND_COMMANDS`] and several workers shade, hands
    /// it to the workers and starts a new one, so that the caller's thread (vertex
    /// processing, clipping, binning) and the tile shading overlap; at the next hand-off or
    /// flush the caller shades the tiles nobody has claimed yet instead of waiting idle
    /// (measured: spheremap 2T 13.0-14.6 -> 12.1-12.3 ms, sprites 3 % faster, the other
    /// workloads unchanged; keeping one worker out while the caller records was 5 % slower on
    /// `triangles`). Scenes still execute one after the other and each tile replays its bins
    /// in order, so pictures do not change. A single worker (`threads` = 1) keeps flushing
    /// synchronously, so "one thread" means one.
    #[inline]
    pub(crate) fn flush_in_background(&mut self) {
        // Checked for every primitive: the hand-off itself is rare and stays out of line.
        if self.shading_threads < 2 {
            return;
        }
        let n = self.scene.commands.len();
        if n >= BACKGROUND_COMMANDS
            || (n >= EARLY_BACKGROUND_COMMANDS
                && n.is_multiple_of(EARLY_BACKGROUND_COMMANDS)
                && self.workers_waiting())
        {
            self.hand_off_scene();
        }
    }

    /// Whether the background workers have no tile left to claim (or there is no background
    /// scene).
    fn workers_waiting(&self) -> bool {
        self.in_flight
            .as_ref()
            .is_none_or(|f| f.shared.next.load(Ordering::Relaxed) >= f.shared.order.len())
    }

    /// [`Context::flush_in_background`] past its threshold (with at least two shading
    /// threads).
    #[inline(never)]
    fn hand_off_scene(&mut self) {
        let workers = self.shading_threads;
        let DrawTarget::One(buffer) = self.framebuffer.draw else {
            return;
        };
        self.join_background();
        self.framebuffer.make_resident(buffer);
        let tiles = std::mem::take(&mut self.framebuffer.tiles);
        let next = match self.spare_scene.take() {
            Some(s) => s,
            None => Scene::new(&self.framebuffer),
        };
        let scene = std::mem::replace(&mut self.scene, next);
        let shared = Arc::new(Background::new(scene, tiles));
        let (report, stopped) = std::sync::mpsc::channel();
        let background = workers;
        for _ in 0..background {
            let (shared, report) = (Arc::clone(&shared), report.clone());
            let job = move || {
                shared.shade_claimed();
                drop(shared);
                let _ = report.send(());
            };
            match &self.pool {
                Some(p) => p.spawn(job),
                None => rayon::spawn(job),
            }
        }
        self.in_flight = Some(InFlight {
            shared,
            stopped,
            workers: background,
        });
    }

    /// Executes all recorded work. Called at every flush point (`glFinish`, `glFlush`,
    /// `glReadPixels`, framebuffer access, scene memory cap).
    pub(crate) fn flush_scene(&mut self) {
        self.join_background();
        if self.scene.is_empty() {
            return;
        }
        let fb = &mut self.framebuffer;
        let scene = &self.scene;
        let pool = &self.pool;
        let shade = |tiles: &mut [Tile]| match pool {
            Some(pool) => pool.install(|| shade_all(scene, tiles)),
            None => shade_all(scene, tiles),
        };
        match fb.draw {
            DrawTarget::One(buffer) => {
                fb.make_resident(buffer);
                shade(&mut fb.tiles);
            }
            DrawTarget::None => {
                // Depth and stencil are still written; the colour is put back afterwards.
                let saved: Vec<Vec<[u8; 4]>> = fb.tiles.iter().map(|t| t.color.clone()).collect();
                shade(&mut fb.tiles);
                for (tile, color) in fb.tiles.iter_mut().zip(saved) {
                    tile.color = color;
                }
            }
            DrawTarget::Both => {
                // Each colour buffer gets the same fragments and blends with its own content.
                // Depth and stencil results do not depend on the colour buffer, so the second
                // pass starts from the same depth/stencil as the first and ends identically.
                let saved: Vec<(Vec<u32>, Vec<u8>)> = fb
                    .tiles
                    .iter()
                    .map(|t| (t.depth.clone(), t.stencil.clone()))
                    .collect();
                fb.make_resident(ColorBuffer::Back);
                shade(&mut fb.tiles);
                for (tile, (depth, stencil)) in fb.tiles.iter_mut().zip(saved) {
                    tile.depth = depth;
                    tile.stencil = stencil;
                }
                // Occlusion queries count the fragments once, not once per buffer.
                let counted: Vec<u64> = fb.tiles.iter().map(|t| t.samples_passed).collect();
                fb.make_resident(ColorBuffer::Front);
                shade(&mut fb.tiles);
                for (tile, n) in fb.tiles.iter_mut().zip(counted) {
                    tile.samples_passed = n;
                }
                fb.make_resident(ColorBuffer::Back);
            }
        }
        self.scene.reset();
    }
}

fn shade_all(scene: &Scene, tiles: &mut [Tile]) {
    // The busiest tiles first, each its own task: the workers finish the scene together
    // instead of one waiting for the other's last large tile (scenes are shaded one after
    // the other, so that wait is paid at every background hand-off).
    let mut work: Vec<(&mut Tile, &Vec<u32>)> = tiles
        .iter_mut()
        .zip(&scene.bins)
        .filter(|(_, bin)| !bin.is_empty())
        .collect();
    work.sort_unstable_by_key(|(_, bin)| std::cmp::Reverse(bin.len()));
    work.into_par_iter()
        .with_max_len(1)
        .for_each(|(tile, bin)| shade_tile(scene, bin, tile));
}

fn shade_tile(scene: &Scene, bin: &[u32], tile: &mut Tile) {
    // The texture levels of the last command's draw state (consecutive commands mostly share
    // one).
    let mut levels = UnitLevels::default();
    let mut levels_state = None;
    // A triangle's attribute planes spread over the full layout.
    let mut attrs = AttrScratch::default();
    let mut coarse = CoarseDepth::default();
    for (k, &ci) in bin.iter().enumerate() {
        prefetch_ahead(scene, bin, k);
        let command = &scene.commands[ci as usize];
        let state = match command {
            Command::Clear(_) => None,
            Command::Triangle(t) => Some(t.state),
            Command::Rect(r) => Some(r.state),
        };
        if let Some(state) = state.filter(|&s| levels_state != Some(s)) {
            levels.prepare(&scene.states[state as usize]);
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
                if ds.key.depth_write {
                    coarse.forget(tile, t.bbox());
                }
            }
            Command::Rect(r) => {
                let ds = &scene.states[r.state as usize];
                let attrs = &scene.planes[r.attrs as usize..r.attrs as usize + ds.attr_count];
                let shared = PrimitiveShared::new(&levels);
                let it = Interpolants {
                    z: Plane::constant(r.z),
                    inv_w: Plane::constant(1.0),
                    attrs,
                    perspective: false,
                    constant_primary: false,
                    coverage: r.coverage,
                    shared: &shared,
                };
                if ds.key.depth_write {
                    coarse.forget(tile, r.rect);
                }
                let t = crate::framebuffer::TILE as i32;
                let (x0, x1) = (r.rect.x0.max(tile.x0), r.rect.x1.min(tile.x0 + t));
                let (y0, y1) = (r.rect.y0.max(tile.y0), r.rect.y1.min(tile.y0 + t));
                if x0 < x1 {
                    for y in y0..y1 {
                        (ds.span)(ds, tile, y, x0, x1, &it);
                    }
                }
            }
        }
    }
}

/// Bin entries ahead of the one being shaded whose command, and (nearer) whose planes, are
/// prefetched: the front end wrote them long before (or on another core), and a tile's
/// commands are scattered over the scene, so each first touch would otherwise wait on memory.
const PREFETCH_COMMAND_AHEAD: usize = 8;
const PREFETCH_PLANES_AHEAD: usize = 4;

#[inline(always)]
fn prefetch_ahead(scene: &Scene, bin: &[u32], k: usize) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
        let prefetch = |p: *const u8| {
            // SAFETY: a prefetch is only a hint: it never faults or changes memory, whatever
            // the address.
            unsafe { _mm_prefetch::<_MM_HINT_T0>(p as *const i8) }
        };
        if let Some(c) = bin
            .get(k + PREFETCH_COMMAND_AHEAD)
            .and_then(|&c| scene.commands.get(c as usize))
        {
            prefetch(c as *const Command as *const u8);
        }
        if let Some(Command::Triangle(t)) = bin
            .get(k + PREFETCH_PLANES_AHEAD)
            .and_then(|&c| scene.commands.get(c as usize))
        {
            if let Some(p) = scene.planes.get(t.planes as usize) {
                let p = p as *const Plane as *const u8;
                // The first three cache lines: the z and 1/w planes and most attributes'.
                for line in 0..3 {
                    prefetch(p.wrapping_add(64 * line));
                }
            }
        }
    }
}

fn clear_tile(c: &ClearCommand, tile: &mut Tile) {
    let t = crate::framebuffer::TILE as i32;
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
