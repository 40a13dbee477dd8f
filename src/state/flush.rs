//! The hand-off of recorded work to tile shading: at flush points (`glFlush`, `glFinish`,
//! reads of the framebuffer) the scene is shaded in place, and a growing scene is handed to
//! background workers while the caller records the next (`raster::schedule` shades).

use std::sync::atomic::Ordering;
use std::sync::Arc;

use super::Context;
use crate::framebuffer::{ColorBuffer, DrawTarget, Tile};
use crate::raster::scene::Scene;
use crate::raster::schedule::{
    lock, shade_all, shade_here, Background, InFlight, TileVisit, BACKGROUND_COMMANDS,
    EARLY_BACKGROUND_COMMANDS, MAX_SCENES_IN_FLIGHT,
};

impl Context {
    /// Finishes background shading (if any), shading queued tiles on this thread too, and
    /// puts the tiles back into the framebuffer.
    pub(crate) fn join_background(&mut self) {
        let Some(flight) = self.in_flight.take() else {
            return;
        };
        let shared = flight.shared;
        loop {
            shared.shade_ready();
            if self.recycle.in_flight.load(Ordering::Acquire) == 0 {
                break;
            }
            // A worker is on a tile: woken when it is done (or soon anyway).
            std::thread::park_timeout(std::time::Duration::from_micros(200));
        }
        // Every scene is shaded; a worker may still be leaving a tile, so take each under
        // its lock. Workers that start later find nothing ready and touch no tile.
        self.framebuffer.tiles = shared.take_tiles();
        if self.spare_scene.is_none() {
            self.spare_scene = lock(&self.recycle.scenes).pop();
        }
    }

    /// When the scene has grown past [`BACKGROUND_COMMANDS`] and several workers shade, hands
    /// it to the workers and starts a new one, so that the caller's thread (vertex
    /// processing, clipping, binning) and the tile shading overlap; at the next hand-off the
    /// caller first shades the tiles nobody has taken yet instead of leaving them waiting
    /// (measured: spheremap 2T 13.0-14.6 -> 12.1-12.3 ms, sprites 3 % faster, the other
    /// workloads unchanged; keeping one worker out while the caller records was 5 % slower on
    /// `triangles`), but never waits for a tile another thread is shading. Each tile replays
    /// its scenes in order, so pictures do not change. A single worker (`threads` = 1) keeps
    /// flushing synchronously, so "one thread" means one.
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

    /// Whether no tile is waiting for a background worker (or there is no background work).
    fn workers_waiting(&self) -> bool {
        self.in_flight
            .as_ref()
            .is_none_or(|f| f.shared.nothing_ready())
    }

    /// [`Context::flush_in_background`] past its threshold (with at least two shading
    /// threads).
    #[inline(never)]
    fn hand_off_scene(&mut self) {
        let workers = self.shading_threads;
        let DrawTarget::One(buffer) = self.framebuffer.draw else {
            return;
        };
        if self.in_flight.as_ref().is_some_and(|f| f.buffer != buffer) {
            self.join_background();
        }
        let shared = match &self.in_flight {
            Some(f) => {
                // Tiles nobody has taken yet: shaded here rather than left waiting.
                f.shared.shade_ready();
                Arc::clone(&f.shared)
            }
            None => {
                self.framebuffer.make_resident(buffer);
                let tiles = std::mem::take(&mut self.framebuffer.tiles);
                let shared = Arc::new(Background::new(tiles, Arc::clone(&self.recycle)));
                self.in_flight = Some(InFlight {
                    shared: Arc::clone(&shared),
                    buffer,
                });
                shared
            }
        };
        // Bounded memory: past the cap, shade (or wait for) tiles until a scene is done.
        while self.recycle.in_flight.load(Ordering::Acquire) >= MAX_SCENES_IN_FLIGHT {
            shared.shade_ready();
            if self.recycle.in_flight.load(Ordering::Acquire) >= MAX_SCENES_IN_FLIGHT {
                std::thread::park_timeout(std::time::Duration::from_micros(200));
            }
        }
        let mut next = match self
            .spare_scene
            .take()
            .or_else(|| lock(&self.recycle.scenes).pop())
        {
            Some(s) => s,
            None => Scene::new(&self.framebuffer),
        };
        // A multisample draw hands off in the middle of one sample's pass.
        next.set_sample_plane(self.scene.sample_plane());
        let scene = std::mem::replace(&mut self.scene, next);
        shared.enqueue(scene);
        for _ in 0..workers {
            let shared = Arc::clone(&shared);
            let job = move || shared.shade_ready();
            match &self.pool {
                Some(p) => p.spawn(job),
                None => rayon::spawn(job),
            }
        }
    }

    /// Finishes pending rendering and runs `f` on every tile of the colour buffer the tiles
    /// then hold (the front buffer of a single-buffered framebuffer), on the shading threads
    /// when there are several. The C ABI copies a finished picture into a caller's buffer this
    /// way: each tile's rows straight to their place, by the thread that shaded the tile last,
    /// right after it (while the tile is in that core's cache), instead of the whole image
    /// gathered into rows on the caller's thread after the flush.
    pub(crate) fn for_each_tile(&mut self, f: &(dyn Fn(&Tile) + Sync)) {
        use rayon::prelude::*;
        self.join_background();
        let fb = &self.framebuffer;
        if matches!(fb.draw, DrawTarget::One(_))
            && !self.scene.is_empty()
            && self.scene.bins.len() == fb.tiles.len()
        {
            self.shade_scene(Some(f));
            return;
        }
        self.flush_scene();
        let tiles = &self.framebuffer.tiles;
        if self.shading_threads < 2 {
            tiles.iter().for_each(f);
            return;
        }
        // One task per tile row of the framebuffer: enough to share between the threads,
        // few enough that the hand-out costs nothing next to the copies.
        let per_row = self.framebuffer.tiles_x.max(1);
        let run = || {
            tiles
                .par_chunks(per_row)
                .for_each(|row| row.iter().for_each(f))
        };
        match &self.pool {
            Some(pool) => pool.install(run),
            None => run(),
        }
    }

    /// Executes all recorded work. Called at every flush point (`glFinish`, `glFlush`,
    /// `glReadPixels`, framebuffer access, scene memory cap).
    pub(crate) fn flush_scene(&mut self) {
        self.join_background();
        if self.scene.is_empty() {
            return;
        }
        self.shade_scene(None);
    }

    /// Shades the recorded scene (background work joined) and resets it; with one colour
    /// buffer drawn, `visit` runs on each tile right after its shading (see
    /// [`Context::for_each_tile`]), else on every tile after all shading.
    fn shade_scene(&mut self, visit: TileVisit) {
        let fb = &mut self.framebuffer;
        let scene = &self.scene;
        let pool = &self.pool;
        // One shading thread: this one. Handing the scene to the pool's thread would move it
        // (and the tiles) to whichever core that thread runs on, which costs a tenth of the
        // frame when the cores are far apart (see `shade_here`).
        let one_thread = self.shading_threads < 2;
        let shade = |tiles: &mut [Tile], visit: TileVisit| match pool {
            _ if one_thread => shade_here(scene, tiles, visit),
            Some(pool) => pool.install(|| shade_all(scene, tiles, visit)),
            None => shade_all(scene, tiles, visit),
        };
        match fb.draw {
            DrawTarget::One(buffer) => {
                fb.make_resident(buffer);
                shade(&mut fb.tiles, visit);
            }
            DrawTarget::None => {
                // Depth and stencil are still written; the colour is put back afterwards.
                let saved: Vec<Vec<[u8; 4]>> = fb.tiles.iter().map(|t| t.color.clone()).collect();
                shade(&mut fb.tiles, None);
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
                shade(&mut fb.tiles, None);
                for (tile, (depth, stencil)) in fb.tiles.iter_mut().zip(saved) {
                    tile.depth = depth;
                    tile.stencil = stencil;
                }
                // Occlusion queries count the fragments once, not once per buffer.
                let counted: Vec<u64> = fb.tiles.iter().map(|t| t.samples_passed).collect();
                fb.make_resident(ColorBuffer::Front);
                shade(&mut fb.tiles, None);
                for (tile, n) in fb.tiles.iter_mut().zip(counted) {
                    tile.samples_passed = n;
                }
                fb.make_resident(ColorBuffer::Back);
            }
        }
        if let (Some(f), false) = (visit, matches!(fb.draw, DrawTarget::One(_))) {
            fb.tiles.iter().for_each(f);
        }
        self.scene.reset();
    }
}
