//! Benchmarks at 1024x768 on tilegl (1 and 2 threads) and Mesa (llvmpipe and softpipe, the
//! driver that is not the one of this process through a child process), with ms/frame, the
//! ratio to tilegl and the image error between the implementations. Workloads
//! (`--workload NAME`, default `all`):
//! - `triangles`: 100k random small smooth-shaded, depth-tested triangles per frame;
//! - `sprites`: 20k alpha-blended, alpha-tested textured sprites with depth writes off;
//! - `fog`: a lit height-field terrain under exp2 fog in perspective (~130k triangles);
//! - `overdraw`: eight full-screen trilinear-textured, modulated quads per frame;
//! - `horizon`: a trilinear, repeating ground plane receding to the horizon;
//! - `ladder`: the horizon under each texture quality setting (nearest, bilinear, trilinear,
//!   anisotropic 2x-16x), each with its time and its error against a 16x-supersampled
//!   reference rendered by tilegl, as a table and a PNG chart of error against time;
//! - `lightmap`: a corridor of walls, a trilinear base texture on unit 0 and a light map on
//!   unit 1 through `GL_COMBINE` (`MODULATE` of `PREVIOUS` and `TEXTURE`, `RGB_SCALE` 2);
//! - `spheremap`: a tessellated, lit torus, then the same torus again with a sphere-mapped
//!   environment (`GL_SPHERE_MAP` texgen) added (`glBlendFunc(GL_ONE, GL_ONE)`, depth `LEQUAL`);
//! - `tunnel` / `tunnel-nofog`: a perspective tunnel whose walls are trilinear-mipmapped,
//!   `MODULATE`d by a smooth vertex colour, depth-tested, under `EXP2` fog (or without fog);
//! - `objects` / `objects-nofog`: a grid of lit, trilinear-textured (`MODULATE`) tori drawn
//!   from one display list under `LINEAR` fog (or without fog);
//! - `toggles` (not in `all`): the state-toggle matrix: the `tunnel-nofog` scene, then the same
//!   scene with one fixed-function feature turned on, on tilegl and llvmpipe: each toggle's
//!   added cost on both;
//! - `lighting` (not in `all`): the cost of lighting against the triangle count: a sphere of
//!   constant size on screen tessellated into 2k ... 128k triangles, drawn lit (two lights,
//!   specular, one positional and attenuated) and unlit; the difference is the lighting cost,
//!   with a least-squares line through it to show that it grows linearly.
//!
//! Shared by `cargo run --release -p tilegl-conformance --bin bench` and
//! `cargo bench -p tilegl-conformance --bench triangles`.

use std::time::{Duration, Instant};

use tilegl::enums::*;
use tilegl::{Context, ContextConfig, FramebufferConfig, Gl};

use crate::bench_scenes::{self, LitVertex, Pixels, Segment};
use crate::c_route::CAbiContext;
use crate::compare::{diff, Image};
use crate::machine::cross_core_round_trip_ns;
use crate::mesa::{self, MesaContext, Oracle, OracleInfo};
use crate::prng::XorShift;

mod draw;
mod run;
pub use draw::*;
pub use run::*;

/// Benchmark parameters.
#[derive(Clone, Debug)]
pub struct BenchConfig {
    pub workload: Workload,
    /// Run only the quality ladder (`--workload ladder`).
    pub ladder_only: bool,
    /// Texture quality for the textured workloads: an index into [`LADDER`].
    pub quality: usize,
    pub width: i32,
    pub height: i32,
    pub triangles: usize,
    /// Timed frames per implementation, at least (the median is reported); one untimed
    /// warm-up frame comes first.
    pub frames: usize,
    /// Keep adding timed frames until an implementation has been timed this long (within the
    /// budget): the machine's slow spells last up to about a second, and a fast
    /// implementation's few frames would otherwise fall inside one while a slow one's span
    /// it, which skews their ratio either way.
    pub min_time: Duration,
    /// Stop adding timed frames once an implementation has used this much time (at least one
    /// timed frame always runs).
    pub budget: Duration,
    pub seed: u64,
    /// Empty: time tilegl through its C exports with its default threads (one per core);
    /// `--threads N`: through the Rust API with N threads (for profiling without the C layer).
    pub tilegl_threads: Vec<usize>,
    /// The `tunnel` workloads with one feature of [`TOGGLES`] turned on (`--toggle N`).
    pub toggle: Option<usize>,
    /// Run the state-toggle matrix (`--workload toggles`).
    pub toggles_only: bool,
    /// `--tiny-viewport`: the same calls with a 1x1 viewport set after the set-up, so the
    /// frames clear, process vertices, bin, hand off, finish and present as before but shade
    /// almost nothing (a diagnostic of the cost that does not depend on the pixels drawn).
    pub tiny_viewport: bool,
}

impl Default for BenchConfig {
    fn default() -> Self {
        BenchConfig {
            workload: Workload::Triangles,
            ladder_only: false,
            quality: 2,
            width: 1024,
            height: 768,
            triangles: 100_000,
            frames: 5,
            min_time: Duration::from_millis(1500),
            budget: Duration::from_secs(15),
            seed: 0x5EED_1234_ABCD_0001,
            tilegl_threads: Vec::new(),
            toggle: None,
            toggles_only: false,
            tiny_viewport: false,
        }
    }
}

/// What a benchmark frame draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Workload {
    Triangles,
    Sprites,
    Fog,
    Overdraw,
    Horizon,
    Lightmap,
    Spheremap,
    Tunnel,
    TunnelNoFog,
    Objects,
    ObjectsNoFog,
    LitTriangles,
    Combine4,
    Cubemap,
    Lines,
    Shadow,
    Text,
    Uploads,
    Accum,
    /// The lit sphere of the `lighting` measurement (not in [`Workload::ALL`]).
    Lighting,
}

impl Workload {
    pub const ALL: [Workload; 19] = [
        Workload::Triangles,
        Workload::Sprites,
        Workload::Fog,
        Workload::Overdraw,
        Workload::Horizon,
        Workload::Lightmap,
        Workload::Spheremap,
        Workload::Tunnel,
        Workload::TunnelNoFog,
        Workload::Objects,
        Workload::ObjectsNoFog,
        Workload::LitTriangles,
        Workload::Combine4,
        Workload::Cubemap,
        Workload::Lines,
        Workload::Shadow,
        Workload::Text,
        Workload::Uploads,
        Workload::Accum,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Workload::Triangles => "triangles",
            Workload::Sprites => "sprites",
            Workload::Fog => "fog",
            Workload::Overdraw => "overdraw",
            Workload::Horizon => "horizon",
            Workload::Lightmap => "lightmap",
            Workload::Spheremap => "spheremap",
            Workload::Tunnel => "tunnel",
            Workload::TunnelNoFog => "tunnel-nofog",
            Workload::Objects => "objects",
            Workload::ObjectsNoFog => "objects-nofog",
            Workload::LitTriangles => "lit-triangles",
            Workload::Combine4 => "combine4",
            Workload::Cubemap => "cubemap",
            Workload::Lines => "lines",
            Workload::Shadow => "shadow",
            Workload::Text => "text",
            Workload::Uploads => "uploads",
            Workload::Accum => "accum",
            Workload::Lighting => "lighting",
        }
    }

    pub fn parse(s: &str) -> Option<Workload> {
        Workload::ALL.into_iter().find(|w| w.name() == s)
    }
}

/// Sprites per frame of the `sprites` workload.
pub const SPRITES: usize = 20_000;
/// Height-field cells per side of the `fog` workload.
pub const TERRAIN_CELLS: usize = 256;

/// One sprite: centre (pixels), z in [-1, 1], half size, colour with alpha.
#[derive(Clone, Copy, Debug)]
pub struct Sprite {
    pub centre: [f32; 2],
    pub z: f32,
    pub half: f32,
    pub color: [f32; 4],
}

/// The data a workload draws, generated from the seed (a child process regenerates it).
#[derive(Clone, Debug)]
pub enum WorkData {
    Triangles(Vec<BenchVertex>),
    Sprites(Vec<Sprite>),
    /// Heights of a (cells + 1)^2 grid.
    Terrain(Vec<f32>),
    /// Full-screen quads (the count of layers).
    Overdraw(usize),
    /// The ground plane.
    Horizon,
    /// The light-mapped corridor: wall segments along its length.
    Lightmap(usize),
    /// The two-pass sphere-mapped torus: rings and sides.
    Spheremap(usize, usize),
    /// The lighting measurement's sphere: stacks, slices, lit.
    Sphere(usize, usize, bool),
    /// The tunnel: sides around, segments along.
    Tunnel(usize, usize),
    /// The display-list objects: columns and rows of the grid.
    Objects(usize, usize),
    /// Small lit triangles (`lit-triangles`).
    LitTriangles(Vec<LitVertex>),
    /// The four-unit corridor: wall segments along its length.
    Combine4(usize),
    /// The cube-mapped torus: rings and sides.
    Cubemap(usize, usize),
    /// Line segments.
    Lines(Vec<Segment>),
    /// The shadow-volume scene.
    Shadow,
    /// The glyphs and picture, and the window height.
    Text(Box<Pixels>, i32),
    /// The upload frames, and the window size.
    Uploads(Box<Pixels>, i32, i32),
    /// The horizon, jittered passes summed in the accumulation buffer.
    Accum(usize),
}

/// Sides around and segments along the `tunnel` workload's tube.
pub const TUNNEL: (usize, usize) = (32, 48);
/// Columns and rows of the `objects` workload's grid of tori.
pub const OBJECTS: (usize, usize) = (5, 4);
/// The display list holding one textured torus (`objects`; the first name of a fresh context).
const OBJECT_LIST: GLuint = 1;

/// Wall segments along the `lightmap` corridor.
pub const CORRIDOR_SEGMENTS: usize = 24;
/// Tessellation of the `spheremap` torus (rings x sides quads, two triangles each).
pub const TORUS: (usize, usize) = (192, 96);

/// Generates the workload's data.
pub fn work_data(cfg: &BenchConfig) -> WorkData {
    match cfg.workload {
        Workload::Triangles => WorkData::Triangles(triangles(cfg)),
        Workload::Sprites => {
            let mut rng = XorShift::new(cfg.seed ^ 0x5917);
            WorkData::Sprites(
                (0..SPRITES)
                    .map(|_| Sprite {
                        centre: [
                            rng.range(0.0, cfg.width as f32),
                            rng.range(0.0, cfg.height as f32),
                        ],
                        z: rng.range(-0.9, 0.9),
                        half: rng.range(4.0, 16.0),
                        color: [
                            rng.range(0.3, 1.0),
                            rng.range(0.3, 1.0),
                            rng.range(0.3, 1.0),
                            rng.range(0.4, 1.0),
                        ],
                    })
                    .collect(),
            )
        }
        Workload::Fog => {
            let n = TERRAIN_CELLS + 1;
            let mut h = Vec::with_capacity(n * n);
            for j in 0..n {
                for i in 0..n {
                    let (x, y) = (i as f32 / 16.0, j as f32 / 16.0);
                    h.push(
                        0.6 * (x * 0.9).sin() * (y * 0.7).cos()
                            + 0.25 * (x * 2.3 + y * 1.7).sin()
                            + 0.08 * (x * 7.1).cos() * (y * 5.3).sin(),
                    );
                }
            }
            WorkData::Terrain(h)
        }
        Workload::Overdraw => WorkData::Overdraw(8),
        Workload::Horizon => WorkData::Horizon,
        Workload::Lightmap => WorkData::Lightmap(CORRIDOR_SEGMENTS),
        Workload::Spheremap => WorkData::Spheremap(TORUS.0, TORUS.1),
        Workload::Lighting => WorkData::Sphere(32, 32, true),
        Workload::Tunnel | Workload::TunnelNoFog => WorkData::Tunnel(TUNNEL.0, TUNNEL.1),
        Workload::Objects | Workload::ObjectsNoFog => WorkData::Objects(OBJECTS.0, OBJECTS.1),
        Workload::LitTriangles => {
            WorkData::LitTriangles(bench_scenes::lit_triangles(cfg.width, cfg.height, cfg.seed))
        }
        Workload::Combine4 => WorkData::Combine4(CORRIDOR_SEGMENTS),
        Workload::Cubemap => WorkData::Cubemap(TORUS.0, TORUS.1),
        Workload::Lines => WorkData::Lines(bench_scenes::segments(cfg.width, cfg.height, cfg.seed)),
        Workload::Shadow => WorkData::Shadow,
        Workload::Text => WorkData::Text(Box::new(bench_scenes::pixels(cfg.seed)), cfg.height),
        Workload::Uploads => WorkData::Uploads(
            Box::new(bench_scenes::pixels(cfg.seed)),
            cfg.width,
            cfg.height,
        ),
        Workload::Accum => WorkData::Accum(bench_scenes::ACCUM_PASSES),
    }
}

/// A toggle of the state-toggle matrix: its name and what it turns on.
pub type Toggle = (&'static str, fn(&mut dyn Gl));

/// The state-toggle matrix's toggles: a name and the state it turns on over the
/// `tunnel-nofog` scene (textured, perspective, depth-tested; the first entry changes
/// nothing).
pub const TOGGLES: [Toggle; 43] = [
    ("base (tunnel-nofog)", |_| {}),
    ("fog LINEAR", |gl| fog_toggle(gl, GL_LINEAR)),
    ("fog EXP", |gl| fog_toggle(gl, GL_EXP)),
    ("fog EXP2", |gl| fog_toggle(gl, GL_EXP2)),
    ("fog EXP2, hint NICEST", |gl| {
        fog_toggle(gl, GL_EXP2);
        gl.hint(GL_FOG_HINT, GL_NICEST);
    }),
    ("fog EXP2, hint FASTEST", |gl| {
        fog_toggle(gl, GL_EXP2);
        gl.hint(GL_FOG_HINT, GL_FASTEST);
    }),
    ("alpha test GREATER 0.5", |gl| {
        gl.enable(GL_ALPHA_TEST);
        gl.alpha_func(GL_GREATER, 0.5);
    }),
    ("blend SRC_ALPHA, 1-SRC_ALPHA", |gl| {
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }),
    ("blend ONE, ONE", |gl| {
        gl.enable(GL_BLEND);
        gl.blend_func(GL_ONE, GL_ONE);
    }),
    ("blend DST_COLOR, ZERO", |gl| {
        gl.enable(GL_BLEND);
        gl.blend_func(GL_DST_COLOR, GL_ZERO);
    }),
    ("blend ONE, 1-SRC_ALPHA", |gl| {
        gl.enable(GL_BLEND);
        gl.blend_func(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    }),
    ("lighting, 1 light", light_toggle),
    ("lighting, 2 lights", |gl| lights_toggle(gl, 2)),
    ("lighting, 4 lights", |gl| lights_toggle(gl, 4)),
    ("lighting, 8 lights", |gl| lights_toggle(gl, 8)),
    ("lighting, separate specular", |gl| {
        light_toggle(gl);
        gl.light_modeli(
            GL_LIGHT_MODEL_COLOR_CONTROL,
            GL_SEPARATE_SPECULAR_COLOR as i32,
        );
    }),
    ("lighting, two-sided", |gl| {
        light_toggle(gl);
        gl.light_modeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
        gl.materialfv(GL_BACK, GL_DIFFUSE, &[0.5, 0.7, 0.9, 1.0]);
    }),
    ("lighting, colour material", |gl| {
        light_toggle(gl);
        gl.color_material(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
        gl.enable(GL_COLOR_MATERIAL);
    }),
    ("texgen OBJECT_LINEAR", |gl| {
        texgen_toggle(gl, GL_OBJECT_LINEAR)
    }),
    ("texgen EYE_LINEAR", |gl| texgen_toggle(gl, GL_EYE_LINEAR)),
    ("texgen SPHERE_MAP", |gl| texgen_toggle(gl, GL_SPHERE_MAP)),
    ("texgen REFLECTION_MAP", |gl| {
        texgen_toggle(gl, GL_REFLECTION_MAP)
    }),
    ("texgen NORMAL_MAP", |gl| texgen_toggle(gl, GL_NORMAL_MAP)),
    ("second unit (MODULATE)", |gl| units_toggle(gl, 2)),
    ("fourth unit (3 more, MODULATE)", |gl| units_toggle(gl, 4)),
    ("COMBINE REPLACE", |gl| combine_toggle(gl, GL_REPLACE)),
    ("COMBINE MODULATE", |gl| combine_toggle(gl, GL_MODULATE)),
    ("COMBINE ADD", |gl| combine_toggle(gl, GL_ADD)),
    ("COMBINE ADD_SIGNED", |gl| combine_toggle(gl, GL_ADD_SIGNED)),
    ("COMBINE INTERPOLATE", |gl| {
        combine_toggle(gl, GL_INTERPOLATE)
    }),
    ("COMBINE SUBTRACT", |gl| combine_toggle(gl, GL_SUBTRACT)),
    ("COMBINE DOT3_RGB", |gl| combine_toggle(gl, GL_DOT3_RGB)),
    ("stencil (ALWAYS, REPLACE)", |gl| {
        gl.enable(GL_STENCIL_TEST);
        gl.stencil_func(GL_ALWAYS, 1, 0xFF);
        gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
    }),
    ("polygon offset fill", |gl| {
        gl.enable(GL_POLYGON_OFFSET_FILL);
        gl.polygon_offset(1.0, 2.0);
    }),
    ("logic op XOR", |gl| {
        gl.enable(GL_COLOR_LOGIC_OP);
        gl.logic_op(GL_XOR);
    }),
    ("polygon stipple", |gl| {
        let pattern: Vec<u8> = (0..128)
            .map(|i| if (i / 4) % 2 == 0 { 0xAA } else { 0x55 })
            .collect();
        gl.polygon_stipple(&pattern);
        gl.enable(GL_POLYGON_STIPPLE);
    }),
    ("flat shading", |gl| gl.shade_model(GL_FLAT)),
    ("fog EXP2 + alpha test", |gl| {
        fog_toggle(gl, GL_EXP2);
        gl.enable(GL_ALPHA_TEST);
        gl.alpha_func(GL_GREATER, 0.5);
    }),
    ("fog EXP2 + blend SRC_ALPHA", |gl| {
        fog_toggle(gl, GL_EXP2);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }),
    ("alpha test + blend SRC_ALPHA", |gl| {
        gl.enable(GL_ALPHA_TEST);
        gl.alpha_func(GL_GREATER, 0.2);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }),
    ("lighting + fog LINEAR", |gl| {
        light_toggle(gl);
        fog_toggle(gl, GL_LINEAR);
    }),
    ("second unit + fog EXP2", |gl| {
        units_toggle(gl, 2);
        fog_toggle(gl, GL_EXP2);
    }),
    ("lighting + texgen SPHERE_MAP", |gl| {
        light_toggle(gl);
        texgen_toggle(gl, GL_SPHERE_MAP);
    }),
];

/// Toggles that leave the picture as it is: they change only the stencil values, or compute
/// the base scene's `MODULATE` through `GL_COMBINE`. (The polygon offset changes which of the
/// tunnel's far, nearly edge-on fragments win the depth test.)
pub const PICTURE_NEUTRAL_TOGGLES: [&str; 2] = ["stencil (ALWAYS, REPLACE)", "COMBINE MODULATE"];

#[cfg(test)]
mod tests {
    use super::phase_note;

    /// Only round trips more than twice apart mark a ratio; a missing measurement marks
    /// nothing.
    #[test]
    fn ratios_across_phases_are_marked() {
        assert_eq!(phase_note(Some(45.0), Some(44.0)), "");
        assert_eq!(phase_note(Some(45.0), Some(90.0)), "");
        assert_eq!(
            phase_note(Some(389.0), Some(45.0)),
            " (phases differ: xcore 389 vs 45 ns)"
        );
        assert!(phase_note(Some(44.0), Some(420.0)).contains("phases differ"));
        assert_eq!(phase_note(None, Some(420.0)), "");
    }
}
