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

/// Lighting with `n` lights: light 0 as in [`light_toggle`], the others alternately
/// positional (attenuated) and directional, each in its own colour.
fn lights_toggle(gl: &mut dyn Gl, n: usize) {
    light_toggle(gl);
    for i in 1..n {
        let light = GL_LIGHT0 + i as GLenum;
        let a = i as f32 * 0.8;
        let w = if i % 2 == 1 { 1.0 } else { 0.0 };
        gl.enable(light);
        gl.lightfv(light, GL_POSITION, &[a.cos(), a.sin(), -4.0 * w, w]);
        let c = [
            0.3 + 0.1 * (i % 3) as f32,
            0.25,
            0.35 - 0.04 * i as f32,
            1.0,
        ];
        gl.lightfv(light, GL_DIFFUSE, &c);
        gl.lightfv(light, GL_SPECULAR, &c);
        if w == 1.0 {
            gl.lightf(light, GL_LINEAR_ATTENUATION, 0.15);
        }
    }
}

/// Texture coordinates generated on s and t of unit 0 in `mode` (planes for the linear modes:
/// about one repeat per two units, as the tunnel's own coordinates).
fn texgen_toggle(gl: &mut dyn Gl, mode: GLenum) {
    for (c, cap, plane) in [
        (GL_S, GL_TEXTURE_GEN_S, [0.5f32, 0.0, 0.5, 0.0]),
        (GL_T, GL_TEXTURE_GEN_T, [0.0, 0.5, 0.5, 0.0]),
    ] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, mode as i32);
        gl.tex_genfv(c, GL_OBJECT_PLANE, &plane);
        gl.tex_genfv(c, GL_EYE_PLANE, &plane);
        gl.enable(cap);
    }
}

/// `units` texture units in all: the units after 0 each with the bench texture (trilinear),
/// `MODULATE`, and their own constant coordinate.
fn units_toggle(gl: &mut dyn Gl, units: usize) {
    for u in 1..units {
        gl.active_texture(GL_TEXTURE0 + u as GLenum);
        bench_texture_setup(gl, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 1.0);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    }
    gl.active_texture(GL_TEXTURE0);
}

/// Unit 0 through `GL_COMBINE` with `func` on RGB: the texture, the vertex colour and a
/// constant colour as its arguments.
fn combine_toggle(gl: &mut dyn Gl, func: GLenum) {
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, func as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PRIMARY_COLOR as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_CONSTANT as i32);
    gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.6, 0.5, 0.4, 0.5]);
}

/// Fog of `mode` with the `tunnel` workload's parameters.
fn fog_toggle(gl: &mut dyn Gl, mode: GLenum) {
    gl.enable(GL_FOG);
    gl.fogi(GL_FOG_MODE, mode as i32);
    gl.fogf(GL_FOG_DENSITY, 0.07);
    gl.fogf(GL_FOG_START, 1.0);
    gl.fogf(GL_FOG_END, 30.0);
    gl.fogfv(GL_FOG_COLOR, &[0.25, 0.22, 0.2, 1.0]);
}

/// Lighting with one directional light and a specular material (the tunnel's normals point
/// inwards).
fn light_toggle(gl: &mut dyn Gl) {
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.3, 0.8, 1.0, 0.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.8, 0.8, 0.8, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 16.0);
}

/// A torus about the y axis as triangle strips with normals and texture coordinates (s four
/// times around the ring, t twice around the tube).
fn textured_torus(gl: &mut dyn Gl, rings: usize, sides: usize, big: f32, small: f32) {
    use std::f32::consts::TAU;
    for i in 0..rings {
        gl.begin(GL_TRIANGLE_STRIP);
        for j in 0..=sides {
            let b = TAU * j as f32 / sides as f32;
            for ii in [i + 1, i] {
                let a = TAU * ii as f32 / rings as f32;
                let n = [a.cos() * b.cos(), b.sin(), a.sin() * b.cos()];
                gl.normal_3fv(&n);
                gl.tex_coord_2f(
                    4.0 * ii as f32 / rings as f32,
                    2.0 * j as f32 / sides as f32,
                );
                gl.vertex_3f(
                    a.cos() * (big + small * b.cos()),
                    small * b.sin(),
                    a.sin() * (big + small * b.cos()),
                );
            }
        }
        gl.end();
    }
}

/// The tunnel's tube (radius 1.5 about the z axis, from z = 0.5 to 47.5 units deep), as quad
/// strips with inward normals, texture coordinates (s twice around, t one repeat per two
/// units) and a smooth colour that darkens with the angle (its alpha varies too).
fn tunnel(gl: &mut dyn Gl, sides: usize, segments: usize) {
    use std::f32::consts::TAU;
    let r = 1.5f32;
    for i in 0..segments {
        let (z0, z1) = (0.5 - i as f32, 0.5 - (i + 1) as f32);
        gl.begin(GL_QUAD_STRIP);
        for j in 0..=sides {
            let a = TAU * j as f32 / sides as f32;
            let (c, s) = (a.cos(), a.sin());
            let shade = 0.75 + 0.25 * s;
            // Alpha from 0.1 to 1 around the tube, for the alpha test and blending toggles.
            gl.color_4f(shade, shade * 0.95, shade * 0.9, 0.55 + 0.45 * c);
            gl.normal_3f(-c, -s, 0.0);
            for z in [z0, z1] {
                gl.tex_coord_2f(2.0 * j as f32 / sides as f32, -z * 0.5);
                gl.vertex_3f(r * c, r * s, z);
            }
        }
        gl.end();
    }
}

/// A 64x64 luminance light map: a bright pool of light with a soft falloff and a dimmer
/// second lamp, on a dark ambient floor.
fn light_map_texture() -> Vec<u8> {
    let mut p = Vec::with_capacity(64 * 64);
    for y in 0..64 {
        for x in 0..64 {
            let (u, v) = ((x as f32 + 0.5) / 64.0, (y as f32 + 0.5) / 64.0);
            let d1 = (u - 0.35).powi(2) + (v - 0.6).powi(2);
            let d2 = (u - 0.75).powi(2) + (v - 0.3).powi(2);
            let l = 0.15 + 0.85 * (-d1 * 18.0).exp() + 0.5 * (-d2 * 40.0).exp();
            p.push((l.min(1.0) * 255.0) as u8);
        }
    }
    p
}

/// A 128x128 RGB environment for the sphere map: sky above, ground below, a sun.
fn environment_texture() -> Vec<u8> {
    let mut p = Vec::with_capacity(128 * 128 * 3);
    for y in 0..128 {
        for x in 0..128 {
            let (u, v) = ((x as f32 + 0.5) / 64.0 - 1.0, (y as f32 + 0.5) / 64.0 - 1.0);
            let sun = (-((u - 0.3).powi(2) + (v - 0.4).powi(2)) * 30.0).exp();
            let c = if v > 0.0 {
                [0.3 + 0.4 * v, 0.45 + 0.4 * v, 0.9]
            } else {
                [0.35 - 0.2 * v, 0.3, 0.2]
            };
            p.extend(c.map(|c| ((c + sun).min(1.0) * 160.0) as u8));
        }
    }
    p
}

/// A torus about the y axis (`big` and `small` radii) as triangle strips with normals.
pub(crate) fn torus(gl: &mut dyn Gl, rings: usize, sides: usize, big: f32, small: f32) {
    use std::f32::consts::TAU;
    for i in 0..rings {
        gl.begin(GL_TRIANGLE_STRIP);
        for j in 0..=sides {
            let b = TAU * j as f32 / sides as f32;
            for ii in [i + 1, i] {
                let a = TAU * ii as f32 / rings as f32;
                let n = [a.cos() * b.cos(), b.sin(), a.sin() * b.cos()];
                gl.normal_3fv(&n);
                gl.vertex_3f(
                    a.cos() * (big + small * b.cos()),
                    small * b.sin(),
                    a.sin() * (big + small * b.cos()),
                );
            }
        }
        gl.end();
    }
}

/// A unit sphere as triangle strips with normals (2 x stacks x slices triangles).
fn bench_sphere(gl: &mut dyn Gl, stacks: usize, slices: usize) {
    use std::f32::consts::{PI, TAU};
    for i in 0..stacks {
        let (t0, t1) = (
            PI * i as f32 / stacks as f32,
            PI * (i + 1) as f32 / stacks as f32,
        );
        gl.begin(GL_TRIANGLE_STRIP);
        for j in 0..=slices {
            let p = TAU * j as f32 / slices as f32;
            for t in [t1, t0] {
                let n = [t.sin() * p.cos(), t.cos(), t.sin() * p.sin()];
                gl.normal_3fv(&n);
                gl.vertex_3fv(&n);
            }
        }
        gl.end();
    }
}

/// A 256x256 RGBA test texture: a checkerboard of colour ramps with fine lines (it aliases
/// visibly when under-filtered).
pub fn bench_texture() -> Vec<u8> {
    let mut p = Vec::with_capacity(256 * 256 * 4);
    for y in 0..256u32 {
        for x in 0..256u32 {
            let check = ((x / 32) + (y / 32)) % 2 == 0;
            let line = x % 16 == 0 || y % 16 == 0;
            let (r, g, b) = if line {
                (20, 20, 20)
            } else if check {
                (230, (x % 32 * 6) as u8, 60)
            } else {
                (40, 120 + (y % 32 * 4) as u8, 220)
            };
            p.extend_from_slice(&[r, g, b, 255]);
        }
    }
    p
}

/// Texture quality settings of the ladder: (name, min filter, mag filter, max anisotropy).
pub const LADDER: [(&str, GLenum, GLenum, f32); 7] = [
    ("nearest", GL_NEAREST, GL_NEAREST, 1.0),
    ("bilinear", GL_LINEAR, GL_LINEAR, 1.0),
    ("trilinear", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 1.0),
    ("aniso 2x", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 2.0),
    ("aniso 4x", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 4.0),
    ("aniso 8x", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 8.0),
    ("aniso 16x", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, 16.0),
];

/// Creates and binds the bench texture with the given filtering.
pub fn bench_texture_setup(gl: &mut dyn Gl, min: GLenum, mag: GLenum, aniso: f32) {
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_2D, name[0]);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        256,
        256,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&bench_texture()),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT as i32);
    if aniso > 1.0 {
        gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, aniso);
    }
    gl.enable(GL_TEXTURE_2D);
}

/// A 64x64 RGBA sprite texture: a soft disc (alpha falls to 0 at the rim) with rings.
fn sprite_texture() -> Vec<u8> {
    let mut p = Vec::with_capacity(64 * 64 * 4);
    for y in 0..64 {
        for x in 0..64 {
            let (dx, dy) = (x as f32 - 31.5, y as f32 - 31.5);
            let r = (dx * dx + dy * dy).sqrt() / 32.0;
            let a = (1.0 - r).clamp(0.0, 1.0);
            let ring = 0.75 + 0.25 * (r * 20.0).cos();
            let v = (255.0 * ring) as u8;
            p.extend_from_slice(&[v, v, 255, (255.0 * a) as u8]);
        }
    }
    p
}

/// One vertex: window-space position (pixels, z in [-1, 1]) and colour.
#[derive(Clone, Copy, Debug)]
pub struct BenchVertex {
    pub pos: [f32; 3],
    pub color: [f32; 3],
}

/// The fixed-seed random triangles: each within a ~16-pixel box anywhere on the screen, with
/// a random depth slope and three random vertex colours.
pub fn triangles(cfg: &BenchConfig) -> Vec<BenchVertex> {
    let mut rng = XorShift::new(cfg.seed);
    let mut out = Vec::with_capacity(cfg.triangles * 3);
    for _ in 0..cfg.triangles {
        let cx = rng.range(-8.0, cfg.width as f32 + 8.0);
        let cy = rng.range(-8.0, cfg.height as f32 + 8.0);
        let cz = rng.range(-0.95, 0.95);
        for _ in 0..3 {
            out.push(BenchVertex {
                pos: [
                    cx + rng.range(-9.0, 9.0),
                    cy + rng.range(-9.0, 9.0),
                    (cz + rng.range(-0.04, 0.04)).clamp(-1.0, 1.0),
                ],
                color: [rng.next_f32(), rng.next_f32(), rng.next_f32()],
            });
        }
    }
    out
}

/// The state set once per context.
pub fn setup(gl: &mut dyn Gl, cfg: &BenchConfig) {
    gl.viewport(0, 0, cfg.width, cfg.height);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_LESS);
    gl.shade_model(GL_SMOOTH);
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.clear_depth(1.0);
    match cfg.workload {
        Workload::Triangles
        | Workload::Sprites
        | Workload::LitTriangles
        | Workload::Lines
        | Workload::Text
        | Workload::Uploads => {
            gl.matrix_mode(GL_PROJECTION);
            gl.ortho(0.0, cfg.width as f64, 0.0, cfg.height as f64, -1.0, 1.0);
            gl.matrix_mode(GL_MODELVIEW);
        }
        Workload::Fog
        | Workload::Horizon
        | Workload::Lightmap
        | Workload::Spheremap
        | Workload::Tunnel
        | Workload::TunnelNoFog
        | Workload::Objects
        | Workload::ObjectsNoFog
        | Workload::Combine4
        | Workload::Cubemap
        | Workload::Shadow
        | Workload::Accum
        | Workload::Lighting => {
            gl.matrix_mode(GL_PROJECTION);
            let aspect = cfg.width as f64 / cfg.height as f64;
            let far = if matches!(cfg.workload, Workload::Horizon | Workload::Accum) {
                2000.0
            } else {
                40.0
            };
            gl.frustum(-0.1 * aspect, 0.1 * aspect, -0.1, 0.1, 0.2, far);
            gl.matrix_mode(GL_MODELVIEW);
        }
        Workload::Overdraw => {
            gl.matrix_mode(GL_PROJECTION);
            gl.ortho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
            gl.matrix_mode(GL_MODELVIEW);
        }
    }
    if matches!(
        cfg.workload,
        Workload::Overdraw | Workload::Horizon | Workload::Accum
    ) {
        let (_, min, mag, aniso) = LADDER[cfg.quality.min(LADDER.len() - 1)];
        bench_texture_setup(gl, min, mag, aniso);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
        // The overdraw layers are depth-tested (each nearer than the last, so all are drawn).
        if cfg.workload != Workload::Overdraw {
            gl.disable(GL_DEPTH_TEST);
        }
        gl.clear_color(0.55, 0.7, 0.9, 1.0);
    }
    match cfg.workload {
        Workload::LitTriangles => bench_scenes::setup_lit_triangles(gl, cfg.width, cfg.height),
        Workload::Combine4 => bench_scenes::setup_combine4(
            gl,
            &bench_texture(),
            &light_map_texture(),
            &environment_texture(),
        ),
        Workload::Cubemap => bench_scenes::setup_cubemap(gl),
        Workload::Lines => bench_scenes::setup_lines(gl, cfg.width, cfg.height),
        Workload::Shadow => bench_scenes::setup_shadow(gl),
        Workload::Text => bench_scenes::setup_text(gl, cfg.width, cfg.height),
        Workload::Uploads => {
            if let WorkData::Uploads(px, _, _) = work_data(cfg) {
                bench_scenes::setup_uploads(gl, cfg.width, cfg.height, &px);
            }
        }
        _ => {}
    }
    if cfg.workload == Workload::Sprites {
        let mut name = [0u32];
        gl.gen_textures(1, &mut name);
        gl.bind_texture(GL_TEXTURE_2D, name[0]);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
        gl.tex_parameteri(
            GL_TEXTURE_2D,
            GL_TEXTURE_MIN_FILTER,
            GL_LINEAR_MIPMAP_LINEAR as i32,
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA8 as i32,
            64,
            64,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&sprite_texture()),
        );
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
        gl.enable(GL_TEXTURE_2D);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        gl.enable(GL_ALPHA_TEST);
        gl.alpha_func(GL_GREATER, 0.05);
        gl.depth_mask(0);
        gl.clear_color(0.1, 0.1, 0.15, 1.0);
    }
    if cfg.workload == Workload::Lightmap {
        let (_, min, mag, aniso) = LADDER[cfg.quality.min(LADDER.len() - 1)];
        gl.active_texture(GL_TEXTURE0);
        bench_texture_setup(gl, min, mag, aniso);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
        gl.active_texture(GL_TEXTURE1);
        let mut name = [0u32];
        gl.gen_textures(1, &mut name);
        gl.bind_texture(GL_TEXTURE_2D, name[0]);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_LUMINANCE as i32,
            64,
            64,
            0,
            GL_LUMINANCE,
            GL_UNSIGNED_BYTE,
            Some(&light_map_texture()),
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE as i32);
        gl.enable(GL_TEXTURE_2D);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_MODULATE as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_PREVIOUS as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_TEXTURE as i32);
        gl.tex_envf(GL_TEXTURE_ENV, GL_RGB_SCALE, 2.0);
        gl.active_texture(GL_TEXTURE0);
        gl.clear_color(0.0, 0.0, 0.0, 1.0);
    }
    if cfg.workload == Workload::Spheremap {
        let mut name = [0u32];
        gl.gen_textures(1, &mut name);
        gl.bind_texture(GL_TEXTURE_2D, name[0]);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGB as i32,
            128,
            128,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            Some(&environment_texture()),
        );
        gl.tex_parameteri(
            GL_TEXTURE_2D,
            GL_TEXTURE_MIN_FILTER,
            GL_LINEAR_MIPMAP_LINEAR as i32,
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
        gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
        gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
        gl.depth_func(GL_LEQUAL);
        gl.blend_func(GL_ONE, GL_ONE);
        gl.materialfv(GL_FRONT, GL_DIFFUSE, &[0.6, 0.25, 0.15, 1.0]);
        gl.materialfv(GL_FRONT, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
        gl.materialf(GL_FRONT, GL_SHININESS, 32.0);
        gl.enable(GL_LIGHT0);
        gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.4, 1.0, 0.8, 0.0]);
        gl.clear_color(0.1, 0.1, 0.12, 1.0);
    }
    if cfg.workload == Workload::Lighting {
        gl.materialfv(GL_FRONT, GL_DIFFUSE, &[0.7, 0.6, 0.4, 1.0]);
        gl.materialfv(GL_FRONT, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
        gl.materialf(GL_FRONT, GL_SHININESS, 24.0);
        gl.enable(GL_LIGHT0);
        gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.4, 1.0, 0.8, 0.0]);
        gl.enable(GL_LIGHT1);
        gl.lightfv(GL_LIGHT1, GL_POSITION, &[-1.0, 0.5, -2.0, 1.0]);
        gl.lightfv(GL_LIGHT1, GL_DIFFUSE, &[0.3, 0.4, 0.9, 1.0]);
        gl.lightfv(GL_LIGHT1, GL_SPECULAR, &[0.3, 0.4, 0.9, 1.0]);
        gl.lightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2);
        gl.clear_color(0.1, 0.1, 0.12, 1.0);
    }
    if matches!(cfg.workload, Workload::Tunnel | Workload::TunnelNoFog) {
        let (_, min, mag, aniso) = LADDER[cfg.quality.min(LADDER.len() - 1)];
        bench_texture_setup(gl, min, mag, aniso);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
        gl.clear_color(0.25, 0.22, 0.2, 1.0);
        if cfg.workload == Workload::Tunnel {
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_EXP2 as i32);
            gl.fogf(GL_FOG_DENSITY, 0.07);
            gl.fogfv(GL_FOG_COLOR, &[0.25, 0.22, 0.2, 1.0]);
        }
        if let Some(t) = cfg.toggle {
            (TOGGLES[t.min(TOGGLES.len() - 1)].1)(gl);
        }
    }
    if matches!(cfg.workload, Workload::Objects | Workload::ObjectsNoFog) {
        let (_, min, mag, aniso) = LADDER[cfg.quality.min(LADDER.len() - 1)];
        bench_texture_setup(gl, min, mag, aniso);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
        gl.enable(GL_LIGHTING);
        gl.enable(GL_LIGHT0);
        gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.3, 1.0, 0.6, 0.0]);
        gl.materialfv(GL_FRONT, GL_AMBIENT, &[0.3, 0.3, 0.3, 1.0]);
        gl.materialfv(GL_FRONT, GL_DIFFUSE, &[0.9, 0.85, 0.8, 1.0]);
        gl.materialfv(GL_FRONT, GL_SPECULAR, &[0.4, 0.4, 0.4, 1.0]);
        gl.materialf(GL_FRONT, GL_SHININESS, 20.0);
        gl.enable(GL_CULL_FACE);
        gl.clear_color(0.5, 0.55, 0.6, 1.0);
        if cfg.workload == Workload::Objects {
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_LINEAR as i32);
            gl.fogf(GL_FOG_START, 3.0);
            gl.fogf(GL_FOG_END, 16.0);
            gl.fogfv(GL_FOG_COLOR, &[0.5, 0.55, 0.6, 1.0]);
        }
        let list = gl.gen_lists(1);
        gl.new_list(list, GL_COMPILE);
        textured_torus(gl, 48, 24, 0.8, 0.35);
        gl.end_list();
    }
    if cfg.workload == Workload::Fog {
        gl.enable(GL_LIGHTING);
        gl.enable(GL_LIGHT0);
        gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.3, 1.0, 0.5, 0.0]);
        gl.enable(GL_COLOR_MATERIAL);
        gl.enable(GL_NORMALIZE);
        gl.enable(GL_FOG);
        gl.fogi(GL_FOG_MODE, GL_EXP2 as i32);
        gl.fogf(GL_FOG_DENSITY, 0.09);
        gl.fogfv(GL_FOG_COLOR, &[0.6, 0.65, 0.75, 1.0]);
        gl.clear_color(0.6, 0.65, 0.75, 1.0);
    }
}

/// Segment `k` of the `lightmap` corridor (4 wide, 3 high, 2 long): floor, ceiling and two
/// walls, each a quad.
pub(crate) fn corridor_walls(k: usize) -> [[[f32; 3]; 4]; 4] {
    let (z0, z1) = (-2.0 * k as f32, -2.0 * (k + 1) as f32);
    [
        [
            [-2.0, -1.5, z0],
            [2.0, -1.5, z0],
            [2.0, -1.5, z1],
            [-2.0, -1.5, z1],
        ],
        [
            [-2.0, 1.5, z1],
            [2.0, 1.5, z1],
            [2.0, 1.5, z0],
            [-2.0, 1.5, z0],
        ],
        [
            [-2.0, -1.5, z1],
            [-2.0, -1.5, z0],
            [-2.0, 1.5, z0],
            [-2.0, 1.5, z1],
        ],
        [
            [2.0, -1.5, z0],
            [2.0, -1.5, z1],
            [2.0, 1.5, z1],
            [2.0, 1.5, z0],
        ],
    ]
}

/// The `horizon` ground plane: 800 wide, from 0.3 to 1500 units deep, the texture repeating
/// every 4 units.
fn horizon_plane(gl: &mut dyn Gl) {
    gl.color_3f(1.0, 1.0, 1.0);
    gl.begin(GL_QUADS);
    let (w, near, far) = (400.0f32, -0.3f32, -1500.0f32);
    for (x, z) in [(-w, near), (w, near), (w, far), (-w, far)] {
        gl.tex_coord_2f(x / 4.0, z / 4.0);
        gl.vertex_3f(x, -1.0, z);
    }
    gl.end();
}

/// One frame: clear, the workload in immediate mode, glFinish.
pub fn frame(gl: &mut dyn Gl, data: &WorkData) {
    let sprites = matches!(data, WorkData::Sprites(_));
    if sprites {
        // glClear honours the depth mask: clear with writes on, draw with them off.
        gl.depth_mask(1);
    }
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if sprites {
        gl.depth_mask(0);
    }
    match data {
        WorkData::Triangles(verts) => {
            gl.begin(GL_TRIANGLES);
            for v in verts {
                gl.color_3fv(&v.color);
                gl.vertex_3fv(&v.pos);
            }
            gl.end();
        }
        WorkData::Sprites(sprites) => {
            gl.begin(GL_QUADS);
            for s in sprites {
                let [x, y] = s.centre;
                let h = s.half;
                gl.color_4fv(&s.color);
                gl.tex_coord_2f(0.0, 0.0);
                gl.vertex_3f(x - h, y - h, s.z);
                gl.tex_coord_2f(1.0, 0.0);
                gl.vertex_3f(x + h, y - h, s.z);
                gl.tex_coord_2f(1.0, 1.0);
                gl.vertex_3f(x + h, y + h, s.z);
                gl.tex_coord_2f(0.0, 1.0);
                gl.vertex_3f(x - h, y + h, s.z);
            }
            gl.end();
        }
        WorkData::Terrain(h) => {
            let n = TERRAIN_CELLS + 1;
            let step = 24.0 / TERRAIN_CELLS as f32;
            gl.load_identity();
            gl.rotatef(18.0, 1.0, 0.0, 0.0);
            gl.translatef(-12.0, -1.6, -26.0);
            let at = |i: usize, j: usize| h[j * n + i];
            let normal = |i: usize, j: usize| {
                let dx = at((i + 1).min(n - 1), j) - at(i.saturating_sub(1), j);
                let dz = at(i, (j + 1).min(n - 1)) - at(i, j.saturating_sub(1));
                [-dx, 2.0 * step, -dz]
            };
            for j in 0..TERRAIN_CELLS {
                gl.begin(GL_TRIANGLE_STRIP);
                for i in 0..n {
                    for jj in [j + 1, j] {
                        let y = at(i, jj);
                        gl.color_3f(0.35 + 0.3 * y, 0.55 + 0.2 * y, 0.3);
                        gl.normal_3fv(&normal(i, jj));
                        gl.vertex_3f(i as f32 * step, y, jj as f32 * step);
                    }
                }
                gl.end();
            }
        }
        WorkData::Overdraw(layers) => {
            gl.begin(GL_QUADS);
            for k in 0..*layers {
                // Each layer a different scale and rotation: minification from 1x to 8x.
                let scale = 1.0 + k as f32;
                let a = 0.2 * k as f32;
                let (c, s) = (a.cos() * scale, a.sin() * scale);
                gl.color_4f(1.0, 1.0 - 0.05 * k as f32, 0.8 + 0.02 * k as f32, 1.0);
                // Back to front: each layer nearer than the last passes the depth test.
                let z = -0.9 + 0.2 * k as f32;
                for (x, y) in [(-1.0f32, -1.0f32), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                    gl.tex_coord_2f(c * x - s * y, s * x + c * y);
                    gl.vertex_3f(x, y, z);
                }
            }
            gl.end();
        }
        WorkData::Horizon => {
            gl.load_identity();
            gl.rotatef(6.0, 1.0, 0.0, 0.0);
            horizon_plane(gl);
        }
        WorkData::Accum(passes) => {
            // Motion blur: the horizon turning a little between passes, averaged.
            for p in 0..*passes {
                if p > 0 {
                    gl.clear(GL_COLOR_BUFFER_BIT);
                }
                gl.load_identity();
                gl.rotatef(6.0, 1.0, 0.0, 0.0);
                gl.rotatef(1.5 * p as f32, 0.0, 1.0, 0.0);
                horizon_plane(gl);
                let op = if p == 0 { GL_LOAD } else { GL_ACCUM };
                gl.accum(op, 1.0 / *passes as f32);
            }
            gl.accum(GL_RETURN, 1.0);
        }
        WorkData::LitTriangles(verts) => bench_scenes::frame_lit_triangles(gl, verts),
        WorkData::Combine4(segments) => bench_scenes::frame_combine4(gl, *segments),
        WorkData::Cubemap(rings, sides) => bench_scenes::frame_cubemap(gl, *rings, *sides),
        WorkData::Lines(segs) => bench_scenes::frame_lines(gl, segs),
        WorkData::Shadow => bench_scenes::frame_shadow(gl),
        WorkData::Text(px, height) => bench_scenes::frame_text(gl, px, *height),
        WorkData::Uploads(px, width, height) => {
            bench_scenes::frame_uploads(gl, px, *width, *height)
        }
        WorkData::Lightmap(segments) => {
            gl.load_identity();
            gl.translatef(0.0, 0.0, -0.5);
            gl.color_3f(1.0, 1.0, 1.0);
            // A corridor 4 wide, 3 high, `segments` x 2 long: floor, ceiling and two walls,
            // each segment its own quad with its own light-map square.
            gl.begin(GL_QUADS);
            for k in 0..*segments {
                let walls = corridor_walls(k);
                for w in walls {
                    for (c, v) in w.iter().enumerate() {
                        let (u, t) = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)][c];
                        gl.multi_tex_coord_2f(GL_TEXTURE0, u * 2.0, t * 1.5);
                        gl.multi_tex_coord_2f(GL_TEXTURE1, u, t);
                        gl.vertex_3fv(v);
                    }
                }
            }
            gl.end();
        }
        WorkData::Spheremap(rings, sides) => {
            gl.load_identity();
            gl.translatef(0.0, 0.0, -4.0);
            gl.rotatef(35.0, 1.0, 0.0, 0.0);
            gl.rotatef(20.0, 0.0, 0.0, 1.0);
            // Pass 1: lit.
            gl.enable(GL_LIGHTING);
            torus(gl, *rings, *sides, 1.2, 0.5);
            // Pass 2: the environment, added.
            gl.disable(GL_LIGHTING);
            gl.enable(GL_TEXTURE_2D);
            gl.enable(GL_TEXTURE_GEN_S);
            gl.enable(GL_TEXTURE_GEN_T);
            gl.enable(GL_BLEND);
            gl.depth_mask(0);
            torus(gl, *rings, *sides, 1.2, 0.5);
            gl.depth_mask(1);
            gl.disable(GL_BLEND);
            gl.disable(GL_TEXTURE_GEN_S);
            gl.disable(GL_TEXTURE_GEN_T);
            gl.disable(GL_TEXTURE_2D);
        }
        WorkData::Sphere(stacks, slices, lit) => {
            gl.load_identity();
            gl.translatef(0.0, 0.0, -4.0);
            if *lit {
                gl.enable(GL_LIGHTING);
            } else {
                gl.disable(GL_LIGHTING);
                gl.color_3f(0.7, 0.6, 0.4);
            }
            bench_sphere(gl, *stacks, *slices);
        }
        WorkData::Tunnel(sides, segments) => {
            gl.load_identity();
            // Looking a little off the axis, so the far end is not centred.
            gl.rotatef(4.0, 0.0, 1.0, 0.0);
            gl.rotatef(3.0, 1.0, 0.0, 0.0);
            tunnel(gl, *sides, *segments);
        }
        WorkData::Objects(cols, rows) => {
            // Rows recede: the nearest at 4 units, the farthest at 13 (fog 3..16).
            for r in 0..*rows {
                for c in 0..*cols {
                    gl.load_identity();
                    let z = -4.0 - 3.0 * r as f32;
                    let x = (c as f32 - (*cols as f32 - 1.0) / 2.0) * (0.55 * -z);
                    let y = (r as f32 - (*rows as f32 - 1.0) / 2.0) * 0.5 * -z * 0.45;
                    gl.translatef(x, y, z);
                    gl.rotatef(25.0 + 17.0 * c as f32, 1.0, 0.0, 0.0);
                    gl.rotatef(11.0 * r as f32, 0.0, 0.0, 1.0);
                    gl.call_list(OBJECT_LIST);
                }
            }
        }
    }
    gl.finish();
}

/// Timings and final picture of one implementation.
#[derive(Clone, Debug)]
pub struct BenchResult {
    pub name: String,
    /// Milliseconds of each timed frame.
    pub frame_ms: Vec<f64>,
    pub image: Image,
    pub error: GLenum,
}

impl BenchResult {
    /// Median ms/frame.
    pub fn median_ms(&self) -> f64 {
        let mut v = self.frame_ms.clone();
        v.sort_by(f64::total_cmp);
        if v.is_empty() {
            return f64::NAN;
        }
        let n = v.len();
        if n % 2 == 1 {
            v[n / 2]
        } else {
            (v[n / 2 - 1] + v[n / 2]) / 2.0
        }
    }
}

/// Runs the warm-up and timed frames on `gl`.
pub fn run_frames(name: &str, gl: &mut dyn Gl, cfg: &BenchConfig, data: &WorkData) -> BenchResult {
    setup(gl, cfg);
    frame(gl, data);
    let mut frame_ms = Vec::new();
    let start = Instant::now();
    while frame_ms.len() < cfg.frames.max(1) || start.elapsed() < cfg.min_time {
        let t = Instant::now();
        frame(gl, data);
        frame_ms.push(t.elapsed().as_secs_f64() * 1000.0);
        if start.elapsed() > cfg.budget {
            break;
        }
    }
    let error = gl.get_error();
    let image = Image::read(gl, cfg.width, cfg.height);
    BenchResult {
        name: name.to_string(),
        frame_ms,
        image,
        error,
    }
}

/// tilegl with `threads` worker threads.
pub fn run_tilegl(cfg: &BenchConfig, data: &WorkData, threads: usize) -> BenchResult {
    let mut ctx = crate::client_context(ContextConfig {
        width: cfg.width,
        height: cfg.height,
        threads,
        framebuffer: FramebufferConfig {
            accum_bits: 16,
            ..FramebufferConfig::default()
        },
    });
    run_frames(&format!("tilegl {threads}T"), &mut ctx, cfg, data)
}

/// Mesa in this process (its driver is fixed by `GALLIUM_DRIVER` at the first context).
pub fn run_mesa(cfg: &BenchConfig, data: &WorkData) -> Result<(BenchResult, OracleInfo), String> {
    let mut mesa = MesaContext::create(cfg.width, cfg.height).map_err(|e| e.to_string())?;
    let info = mesa.info().clone();
    let mut r = run_frames("mesa", &mut *mesa, cfg, data);
    r.name = format!("mesa {}", info.driver());
    Ok((r, info))
}

const CHILD_ARG: &str = "--mesa-child";

fn encode_result(r: &BenchResult) -> Vec<u8> {
    let header = format!(
        "{}\n{}\n{}\n",
        r.name,
        r.error,
        r.frame_ms
            .iter()
            .map(|m| m.to_string())
            .collect::<Vec<_>>()
            .join(",")
    );
    let mut out = header.into_bytes();
    out.extend_from_slice(&r.image.to_bytes());
    out
}

fn decode_result(b: &[u8]) -> Option<BenchResult> {
    let mut lines = Vec::new();
    let mut rest = b;
    for _ in 0..3 {
        let nl = rest.iter().position(|&c| c == b'\n')?;
        lines.push(String::from_utf8_lossy(&rest[..nl]).into_owned());
        rest = &rest[nl + 1..];
    }
    Some(BenchResult {
        name: lines[0].clone(),
        error: lines[1].parse().ok()?,
        frame_ms: lines[2].split(',').filter_map(|s| s.parse().ok()).collect(),
        image: Image::from_bytes(rest)?,
    })
}

/// Mesa with another Gallium driver, in a child run of the current executable.
pub fn run_mesa_subprocess(
    driver: &str,
    cfg: &BenchConfig,
    extra_args: &[&str],
) -> Result<BenchResult, String> {
    let out =
        std::env::temp_dir().join(format!("tilegl-bench-{}-{driver}.raw", std::process::id()));
    let out_s = out.to_string_lossy().into_owned();
    let frames = cfg.frames.to_string();
    let tris = cfg.triangles.to_string();
    let budget = cfg.budget.as_secs_f64().to_string();
    let min_time = cfg.min_time.as_secs_f64().to_string();
    let mut args: Vec<&str> = extra_args.to_vec();
    let quality = cfg.quality.to_string();
    let toggle = cfg.toggle.map(|t| t.to_string());
    if let Some(t) = &toggle {
        args.extend_from_slice(&["--toggle", t]);
    }
    args.extend_from_slice(&[
        "--quality",
        &quality,
        "--workload",
        cfg.workload.name(),
        CHILD_ARG,
        &out_s,
        "--frames",
        &frames,
        "--triangles",
        &tris,
        "--budget",
        &budget,
        "--min-time",
        &min_time,
    ]);
    mesa::run_self_with_driver(driver, &args, &[]).map_err(|e| e.to_string())?;
    let bytes = std::fs::read(&out).map_err(|e| e.to_string())?;
    let _ = std::fs::remove_file(&out);
    decode_result(&bytes).ok_or_else(|| "bad result from bench child".to_string())
}

/// Parses the options into `cfg`; returns the child-output path (child mode) and whether
/// every workload was asked for.
fn parse_args(args: &[String], cfg: &mut BenchConfig) -> (Option<String>, bool) {
    let mut child_out = None;
    let mut all = true;
    let mut i = 0;
    while i < args.len() {
        let next = args.get(i + 1);
        match (args[i].as_str(), next) {
            (CHILD_ARG, Some(p)) => {
                child_out = Some(p.clone());
                i += 1;
            }
            ("--workload", Some(v)) if v == "lighting" => {
                cfg.workload = Workload::Lighting;
                all = false;
                i += 1;
            }
            ("--workload", Some(v)) if v == "toggles" => {
                cfg.toggles_only = true;
                all = false;
                i += 1;
            }
            ("--toggle", Some(v)) => {
                cfg.toggle = v.parse().ok();
                i += 1;
            }
            ("--workload", Some(v)) if v == "ladder" => {
                cfg.ladder_only = true;
                all = false;
                i += 1;
            }
            ("--workload", Some(v)) => {
                match Workload::parse(v) {
                    Some(w) => {
                        cfg.workload = w;
                        all = false;
                    }
                    None => all = v == "all",
                }
                i += 1;
            }
            ("--quality", Some(v)) => {
                cfg.quality = v.parse().unwrap_or(cfg.quality);
                i += 1;
            }
            ("--frames", Some(v)) => {
                cfg.frames = v.parse().unwrap_or(cfg.frames);
                i += 1;
            }
            ("--threads", Some(v)) => {
                if let Ok(t) = v.parse::<usize>() {
                    cfg.tilegl_threads = vec![t.max(1)];
                }
                i += 1;
            }
            ("--triangles", Some(v)) => {
                cfg.triangles = v.parse().unwrap_or(cfg.triangles);
                i += 1;
            }
            ("--budget", Some(v)) => {
                if let Ok(s) = v.parse::<f64>() {
                    cfg.budget = Duration::from_secs_f64(s.max(0.0));
                }
                i += 1;
            }
            ("--min-time", Some(v)) => {
                if let Ok(s) = v.parse::<f64>() {
                    cfg.min_time = Duration::from_secs_f64(s.clamp(0.0, 3600.0));
                }
                i += 1;
            }
            _ => {}
        }
        i += 1;
    }
    (child_out, all)
}

/// What `--help` prints.
pub const USAGE: &str = "bench [--workload NAME|all|toggles|ladder|lighting] [--no-ladder] \
[--frames N] [--min-time SECONDS] [--budget SECONDS] [--threads N] [--toggle K] [--quality K] \
[--no-mesa] [--no-xcore] [--scaling]

Times each workload at 1024x768 on tilegl (through its C exports; --threads N: through the \
Rust API with N threads) and Mesa (llvmpipe with LP_NUM_THREADS=2 in this process, softpipe in \
a child), tilegl and llvmpipe in alternating rounds, and prints a ratio table with each \
workload's picture error beside its times. Workloads: triangles sprites fog overdraw horizon \
lightmap spheremap tunnel tunnel-nofog objects objects-nofog lit-triangles combine4 cubemap \
lines shadow text uploads accum; toggles: the state-toggle matrix; ladder: texture quality \
against time; lighting: lighting cost against triangle count; --scaling: time against pixels \
and triangles.";

/// The benchmark's command line ([`USAGE`]). Prints one table per workload, then the ratio
/// table, and returns the process exit code.
pub fn run_cli() -> i32 {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.iter().any(|a| a == "--help" || a == "-h") {
        println!("{USAGE}");
        return 0;
    }
    if args.iter().any(|a| a == "--scaling") {
        let with_mesa =
            !args.iter().any(|a| a == "--no-mesa") && crate::mesa::mesa_available().is_ok();
        return crate::scaling::run(std::path::Path::new("target/bench"), with_mesa);
    }
    if std::env::var_os("LP_NUM_THREADS").is_none() {
        // llvmpipe with two rendering threads (the reference), set before Mesa's
        // first context reads it.
        std::env::set_var("LP_NUM_THREADS", "2");
    }
    let mut cfg = BenchConfig::default();
    let (child_out, all) = parse_args(&args, &mut cfg);
    if let Some(out) = child_out {
        // Child mode: Mesa with the driver the parent selected.
        let data = work_data(&cfg);
        return match run_mesa(&cfg, &data) {
            Ok((r, _)) => match std::fs::write(&out, encode_result(&r)) {
                Ok(()) => 0,
                Err(e) => {
                    eprintln!("bench child: {e}");
                    3
                }
            },
            Err(e) => {
                eprintln!("bench child: {e}");
                2
            }
        };
    }
    if cfg.toggles_only {
        run_toggles(&cfg);
        return 0;
    }
    let workloads: Vec<Workload> = if all {
        Workload::ALL.to_vec()
    } else if cfg.ladder_only {
        Vec::new()
    } else {
        vec![cfg.workload]
    };
    if cfg.workload == Workload::Lighting && !all {
        run_lighting_scaling(&cfg);
        return 0;
    }
    let mut rows = Vec::new();
    for w in workloads {
        cfg.workload = w;
        rows.extend(run_workload(&cfg, &args));
    }
    if !rows.is_empty() {
        println!();
        println!(
            "== ratio table ({}x{}; vs: the Mesa driver's ms over tilegl's, above 1 tilegl is \
             faster; error: tilegl's picture against the driver's)",
            cfg.width, cfg.height
        );
        print!("{}", ratio_table(&rows));
    }
    if (all && !args.iter().any(|a| a == "--no-ladder")) || cfg.ladder_only {
        run_ladder(&cfg);
    }
    0
}

/// Lighting cost against triangle count: the `lighting` sphere at 2k ... 128k triangles, lit
/// and unlit, on tilegl (1 thread, so the vertex stage is not hidden by parallel
/// rasterization) and on Mesa in this process; the lit-minus-unlit time per frame is the
/// lighting cost, fitted by least squares to a + b N (with R^2).
pub fn run_lighting_scaling(cfg: &BenchConfig) {
    println!();
    println!(
        "== lighting: a sphere of constant screen size at {}x{}, two lights (one positional, \
         attenuated), specular; median ms/frame lit and unlit",
        cfg.width, cfg.height
    );
    println!(
        "{:>10} {:>12} {:>12} {:>12} {:>12} {:>12}",
        "triangles", "tilegl lit", "unlit", "light cost", "ns/triangle", "llvmpipe cost"
    );
    let mut c = cfg.clone();
    c.workload = Workload::Lighting;
    // Lighting at glEnd costs a few ns a vertex: the difference of two medians needs many
    // frames to stand out of the machine's noise.
    c.frames = c.frames.max(25);
    // Its own alternation (below) guards against slow spells.
    c.min_time = Duration::ZERO;
    let mut points = Vec::new();
    for k in [1usize, 2, 4, 8, 16, 32, 64] {
        let (stacks, slices) = (32, 32 * k);
        let n = 2 * stacks * slices;
        // Lit and unlit alternately, three times, keeping each one's fastest median: the
        // machine's slow spells then cannot land on one side only.
        let (mut lit, mut unlit) = (f64::INFINITY, f64::INFINITY);
        for _ in 0..3 {
            let l = run_tilegl(&c, &WorkData::Sphere(stacks, slices, true), 1).median_ms();
            let u = run_tilegl(&c, &WorkData::Sphere(stacks, slices, false), 1).median_ms();
            lit = lit.min(l);
            unlit = unlit.min(u);
        }
        let mesa = match (
            run_mesa(&c, &WorkData::Sphere(stacks, slices, true)),
            run_mesa(&c, &WorkData::Sphere(stacks, slices, false)),
        ) {
            (Ok((l, _)), Ok((u, _))) => format!("{:.2}", l.median_ms() - u.median_ms()),
            _ => "-".to_string(),
        };
        let cost = lit - unlit;
        println!(
            "{:>10} {:>12.2} {:>12.2} {:>12.2} {:>12.1} {:>12}",
            n,
            lit,
            unlit,
            cost,
            cost * 1e6 / n as f64,
            mesa
        );
        points.push((n as f64, cost));
    }
    let m = points.len() as f64;
    let (sx, sy) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x, b + y));
    let (mx, my) = (sx / m, sy / m);
    let sxx: f64 = points.iter().map(|&(x, _)| (x - mx).powi(2)).sum();
    let sxy: f64 = points.iter().map(|&(x, y)| (x - mx) * (y - my)).sum();
    let syy: f64 = points.iter().map(|&(_, y)| (y - my).powi(2)).sum();
    let b = sxy / sxx;
    let a = my - b * mx;
    let r2 = if syy > 0.0 {
        sxy * sxy / (sxx * syy)
    } else {
        1.0
    };
    println!(
        "tilegl lighting cost = {a:.3} ms + {:.1} ns x triangles (R^2 = {r2:.4})",
        b * 1e6
    );
}

/// The state-toggle matrix: the `tunnel-nofog` scene with each of [`TOGGLES`] on tilegl
/// (through the C exports, or `--threads`) and Mesa in this process, in two alternating rounds
/// per toggle; the base scene is timed first and again last (its figure is the mean of the two).
/// Prints each toggle's added cost on both, tilegl's over Mesa's, whether that is within the
/// issue's 1.5x, and tilegl's picture error against Mesa's; then the same as a Markdown table.
pub fn run_toggles(cfg: &BenchConfig) {
    let mut c = cfg.clone();
    c.workload = Workload::TunnelNoFog;
    let data = work_data(&c);
    println!();
    println!(
        "== toggles: {} at {}x{}, each feature turned on alone or in a pair (medians over two \
         alternating rounds of at least {} frames and {:.1} s each)",
        describe(&c),
        c.width,
        c.height,
        c.frames.div_ceil(2),
        c.min_time.as_secs_f64() / 2.0
    );
    let (half, budget) = (c.min_time / 2, c.budget / 2);
    let frames = c.frames.div_ceil(2);
    let time = |c: &BenchConfig| -> Option<(BenchResult, Option<BenchResult>)> {
        let mut t = open_tilegl(c, &data).ok()?;
        let mut m = open_mesa(c, &data).ok().map(|(m, _)| m);
        t.round(&data, frames, half, budget);
        if let Some(m) = &mut m {
            m.round(&data, frames, half, budget);
            m.round(&data, frames, half, budget);
        }
        t.round(&data, frames, half, budget);
        Some((t.finish(c), m.map(|m| m.finish(c))))
    };
    let mut rows: Vec<(&str, f64, f64, Option<tilegl::compare::Diff>)> = Vec::new();
    for (k, (name, _)) in TOGGLES.iter().enumerate() {
        c.toggle = Some(k);
        let Some((t, m)) = time(&c) else {
            println!("tilegl: no context");
            return;
        };
        let mesa_ms = m.as_ref().map_or(f64::NAN, BenchResult::median_ms);
        let d = m.as_ref().map(|m| diff(&t.image, &m.image, 8));
        println!(
            "{:<34} tilegl {:>7.1} ms  mesa {:>7.1} ms{}{}",
            name,
            t.median_ms(),
            mesa_ms,
            d.as_ref().map_or(String::new(), |d| format!("  {d}")),
            if t.error != 0 {
                format!("  glError {:#x}", t.error)
            } else {
                String::new()
            }
        );
        rows.push((name, t.median_ms(), mesa_ms, d));
    }
    // The base again, after the toggles: the machine's drift over the run shows in the two.
    c.toggle = Some(0);
    let again = time(&c);
    let (t0, m0) = (rows[0].1, rows[0].2);
    let (bt, bm) = match &again {
        Some((t, m)) => {
            let m1 = m.as_ref().map_or(f64::NAN, BenchResult::median_ms);
            println!(
                "{:<34} tilegl {:>7.1} ms  mesa {:>7.1} ms (the base again)",
                TOGGLES[0].0,
                t.median_ms(),
                m1
            );
            ((t0 + t.median_ms()) / 2.0, (m0 + m1) / 2.0)
        }
        None => (t0, m0),
    };
    let tilegl = open_tilegl(&c, &data).map_or("tilegl".to_string(), |s| s.name);
    println!();
    println!(
        "| toggle | {tilegl} ms | added | llvmpipe ms | added | tilegl's added / llvmpipe's | \
         within 1.5x | error vs llvmpipe (>8, mean) |"
    );
    println!("| --- | ---: | ---: | ---: | ---: | ---: | --- | ---: |");
    for (k, (name, t, m, d)) in rows.iter().enumerate() {
        let (ta, ma) = (t - bt, m - bm);
        let ratio = if k == 0 {
            "-".to_string()
        } else if ma.abs() < 0.3 {
            format!("{ta:+.1} ms vs {ma:+.1} ms")
        } else {
            format!("{:.2}", ta / ma)
        };
        let within = if k == 0 {
            "-"
        } else if toggle_within(ta, ma, bt) {
            "yes"
        } else {
            "**no**"
        };
        println!(
            "| {name} | {t:.1} | {ta:+.1} | {m:.1} | {ma:+.1} | {ratio} | {within} | {} |",
            d.as_ref().map_or("-".to_string(), |d| format!(
                "{:.3} % / {:.3}",
                d.bad_share * 100.0,
                d.mean
            ))
        );
    }
    println!(
        "base: the mean of the first and last base runs; added: the toggle's time minus the \
         base's; within 1.5x: tilegl's added time is at most 1.5 times llvmpipe's, or within \
         the noise (5 % of tilegl's base time)"
    );
}

/// Whether a toggle adding `tilegl_added` ms to tilegl and `mesa_added` ms to Mesa is within
/// the bound (at most 1.5 times Mesa's added cost); differences under 5 % of tilegl's
/// base time `tilegl_base` are within the noise of the shared machine.
pub fn toggle_within(tilegl_added: f64, mesa_added: f64, tilegl_base: f64) -> bool {
    tilegl_added <= (1.5 * mesa_added).max(0.05 * tilegl_base)
}

/// " (phases differ: ...)" when two runs' cross-core round trips (`machine`) differ by more
/// than twice, else nothing: their ratio then mixes the machine's fast and slow phases.
fn phase_note(a: Option<f64>, b: Option<f64>) -> String {
    match (a, b) {
        (Some(a), Some(b)) if a.max(b) > 2.0 * a.min(b) => {
            format!(" (phases differ: xcore {a:.0} vs {b:.0} ns)")
        }
        _ => String::new(),
    }
}

/// Box-filters an image `f` times smaller in each direction.
fn downsample(img: &Image, f: i32) -> Image {
    let (w, h) = (img.width / f, img.height / f);
    let mut pixels = Vec::with_capacity((w * h * 4) as usize);
    for y in 0..h {
        for x in 0..w {
            let mut sum = [0u32; 4];
            for dy in 0..f {
                for dx in 0..f {
                    let p = img.pixel(x * f + dx, y * f + dy);
                    for k in 0..4 {
                        sum[k] += p[k] as u32;
                    }
                }
            }
            let n = (f * f) as u32;
            pixels.extend(sum.map(|v| ((v + n / 2) / n) as u8));
        }
    }
    Image {
        width: w,
        height: h,
        pixels,
    }
}

/// The quality ladder (error against run time): the horizon under every setting of
/// [`LADDER`] on tilegl (2 threads) and Mesa in this process, each with its median time and
/// its error against a 16x-supersampled (4x4) tilegl rendering with 16x anisotropic
/// filtering; a table and a PNG chart (`target/bench/ladder.png`).
pub fn run_ladder(cfg: &BenchConfig) {
    let mut c = cfg.clone();
    c.workload = Workload::Horizon;
    let data = work_data(&c);
    println!();
    println!(
        "== ladder: the horizon at {}x{} under each texture quality setting; error against a \
         4x4-supersampled tilegl reference (aniso 16x)",
        c.width, c.height
    );
    let reference = {
        let mut big = c.clone();
        big.width = c.width * 4;
        big.height = c.height * 4;
        big.quality = LADDER.len() - 1;
        big.frames = 1;
        big.min_time = Duration::ZERO;
        let r = run_tilegl(&big, &data, 0);
        downsample(&r.image, 4)
    };
    let mut rows = Vec::new();
    for (q, setting) in LADDER.iter().enumerate() {
        c.quality = q;
        let t = run_tilegl(&c, &data, 2);
        let m = run_mesa(&c, &data).ok().map(|(r, _)| r);
        rows.push((setting.0, t, m));
    }
    println!(
        "{:<10} {:>12} {:>14} {:>12} {:>14}",
        "setting", "tilegl ms", "tilegl err", "llvmpipe ms", "llvmpipe err"
    );
    let mut points = Vec::new();
    for (name, t, m) in &rows {
        let dt = diff(&t.image, &reference, 8);
        let (mm, me) = match m {
            Some(m) => {
                let dm = diff(&m.image, &reference, 8);
                (
                    format!("{:.1}", m.median_ms()),
                    format!("{:.2} dB", dm.psnr),
                )
            }
            None => ("-".to_string(), "-".to_string()),
        };
        println!(
            "{:<10} {:>12.1} {:>11.2} dB {:>12} {:>14}",
            name,
            t.median_ms(),
            dt.psnr,
            mm,
            me
        );
        points.push((t.median_ms(), dt.mean));
    }
    let path = std::path::Path::new("target/bench/ladder.png");
    match ladder_chart(&points, path) {
        Ok(()) => println!("chart (mean error against ms/frame): {}", path.display()),
        Err(e) => println!("chart not written: {e}"),
    }
}

/// Draws the ladder as a chart with tilegl itself: mean absolute error (y) against ms/frame
/// (x), one coloured marker per setting in [`LADDER`] order (nearest red ... aniso 16x
/// violet), joined by a line.
fn ladder_chart(points: &[(f64, f64)], path: &std::path::Path) -> Result<(), String> {
    let (w, h) = (640, 400);
    let mut gl = Context::new(w, h);
    gl.clear_color(1.0, 1.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let max_x = points.iter().map(|p| p.0).fold(1e-9, f64::max) * 1.1;
    let max_y = points.iter().map(|p| p.1).fold(1e-9, f64::max) * 1.1;
    gl.matrix_mode(GL_PROJECTION);
    gl.ortho(-0.08, 1.02, -0.1, 1.05, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.color_3f(0.0, 0.0, 0.0);
    gl.line_width(2.0);
    gl.begin(GL_LINE_STRIP);
    gl.vertex_2f(0.0, 1.0);
    gl.vertex_2f(0.0, 0.0);
    gl.vertex_2f(1.0, 0.0);
    gl.end();
    gl.color_3f(0.6, 0.6, 0.6);
    gl.line_width(1.0);
    gl.begin(GL_LINE_STRIP);
    for &(x, y) in points {
        gl.vertex_2f((x / max_x) as f32, (y / max_y) as f32);
    }
    gl.end();
    gl.enable(GL_POINT_SMOOTH);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.point_size(12.0);
    gl.begin(GL_POINTS);
    for (k, &(x, y)) in points.iter().enumerate() {
        let hue = k as f32 / points.len().max(1) as f32;
        gl.color_3f(1.0 - hue, 0.3 + 0.4 * (hue * 3.0).sin().abs(), hue);
        gl.vertex_2f((x / max_x) as f32, (y / max_y) as f32);
    }
    gl.end();
    gl.finish();
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(|e| e.to_string())?;
    }
    tilegl::framebuffer::image::save_png(gl.framebuffer(), path).map_err(|e| e.to_string())
}

fn describe(cfg: &BenchConfig) -> String {
    match cfg.workload {
        Workload::Triangles => format!(
            "{} smooth-shaded depth-tested triangles/frame",
            cfg.triangles
        ),
        Workload::Sprites => format!(
            "{SPRITES} alpha-blended, alpha-tested, trilinear-textured sprites/frame, depth writes off"
        ),
        Workload::Fog => format!(
            "lit {TERRAIN_CELLS}x{TERRAIN_CELLS} height field ({} triangles) under exp2 fog",
            2 * TERRAIN_CELLS * TERRAIN_CELLS
        ),
        Workload::Overdraw => {
            "8 full-screen quads/frame (overdraw 8), trilinear, modulate".to_string()
        }
        Workload::Horizon => format!(
            "a ground plane receding to the horizon, repeat, {}",
            LADDER[cfg.quality.min(LADDER.len() - 1)].0
        ),
        Workload::Lightmap => format!(
            "a corridor of {} light-mapped wall quads, base texture {} on unit 0, light map \
             through GL_COMBINE MODULATE x2 on unit 1",
            4 * CORRIDOR_SEGMENTS,
            LADDER[cfg.quality.min(LADDER.len() - 1)].0
        ),
        Workload::Spheremap => format!(
            "a lit torus of {} triangles, then again sphere-mapped and added (2 passes)",
            2 * TORUS.0 * TORUS.1
        ),
        Workload::Lighting => "a lit sphere".to_string(),
        Workload::LitTriangles => format!(
            "{} small lit triangles/frame through glNormal3f/glVertex3f, one light, specular",
            bench_scenes::LIT_TRIANGLES
        ),
        Workload::Combine4 => format!(
            "the lightmap corridor through GL_COMBINE on 4 units (base trilinear x colour, light \
             map x2, signed detail trilinear, interpolated environment), {} quads",
            4 * CORRIDOR_SEGMENTS
        ),
        Workload::Cubemap => format!(
            "a lit torus of {} triangles reflecting a cube map (GL_REFLECTION_MAP on s, t, r)",
            2 * TORUS.0 * TORUS.1
        ),
        Workload::Lines => format!(
            "{} segments/frame: half smooth (width 2.5, blended), half wide (width 3)",
            bench_scenes::LINES
        ),
        Workload::Shadow => format!(
            "a lit floor and {} plates, their shadow volumes counted in the stencil buffer \
             (z-pass, two passes), a blended darkening quad",
            bench_scenes::PLATES.0 * bench_scenes::PLATES.1
        ),
        Workload::Text => format!(
            "4 glDrawPixels of 256x192 RGBA and {} glBitmap glyphs of 8x13/frame",
            bench_scenes::TEXT.0 * bench_scenes::TEXT.1
        ),
        Workload::Uploads => "4 glTexSubImage2D of 256x256 RGBA and 1 glTexImage2D of 512x512 \
                              RGB per frame, each drawn (bilinear)"
            .to_string(),
        Workload::Accum => format!(
            "the horizon drawn {} times with a turn, averaged with glAccum (LOAD, ACCUM, RETURN)",
            bench_scenes::ACCUM_PASSES
        ),
        Workload::Tunnel | Workload::TunnelNoFog => format!(
            "a perspective tunnel of {} quads, {} walls MODULATEd by a smooth colour, depth \
             test{}",
            TUNNEL.0 * TUNNEL.1,
            LADDER[cfg.quality.min(LADDER.len() - 1)].0,
            match cfg.toggle {
                Some(t) => format!(", {}", TOGGLES[t.min(TOGGLES.len() - 1)].0),
                None if cfg.workload == Workload::Tunnel => ", EXP2 fog".to_string(),
                None => ", no fog".to_string(),
            }
        ),
        Workload::Objects | Workload::ObjectsNoFog => format!(
            "{} lit, {} textured (MODULATE) tori of {} triangles from one display list, {}",
            OBJECTS.0 * OBJECTS.1,
            LADDER[cfg.quality.min(LADDER.len() - 1)].0,
            2 * 48 * 24,
            if cfg.workload == Workload::Objects {
                "LINEAR fog"
            } else {
                "no fog"
            }
        ),
    }
}

/// A context under test: tilegl through its C exports (`OSMesaCreateContextExt`, every call
/// through the function `OSMesaGetProcAddress` returns, as Mesa is driven), tilegl through
/// the Rust API with a thread count (`--threads N`, for profiling without the C layer), or Mesa
/// in this process.
pub enum Subject {
    CAbi(CAbiContext),
    Rust(Box<Context>),
    Mesa(MesaContext),
}

impl Subject {
    pub fn gl(&mut self) -> &mut dyn Gl {
        match self {
            Subject::CAbi(c) => &mut **c,
            Subject::Rust(c) => &mut **c,
            Subject::Mesa(m) => &mut **m,
        }
    }
}

/// A subject with its workload set up and one warm-up frame drawn, collecting frame times over
/// rounds that alternate with the other subjects' (a slow spell of the shared machine then
/// falls on both sides instead of one).
pub struct Session {
    pub name: String,
    subject: Subject,
    frame_ms: Vec<f64>,
    spent: Duration,
}

impl Session {
    pub fn open(name: String, mut subject: Subject, cfg: &BenchConfig, data: &WorkData) -> Self {
        setup(subject.gl(), cfg);
        frame(subject.gl(), data);
        Session {
            name,
            subject,
            frame_ms: Vec::new(),
            spent: Duration::ZERO,
        }
    }

    /// Times frames until this round has at least `frames` of them and `min_time`, stopping
    /// early once the session has spent `budget` (at least one frame per round).
    pub fn round(&mut self, data: &WorkData, frames: usize, min_time: Duration, budget: Duration) {
        let start = Instant::now();
        let mut n = 0;
        while n < frames.max(1) || start.elapsed() < min_time {
            let t = Instant::now();
            frame(self.subject.gl(), data);
            let dt = t.elapsed();
            self.frame_ms.push(dt.as_secs_f64() * 1000.0);
            self.spent += dt;
            n += 1;
            if self.spent > budget {
                break;
            }
        }
    }

    /// The GL error after the frames and the final picture.
    pub fn finish(mut self, cfg: &BenchConfig) -> BenchResult {
        let gl = self.subject.gl();
        let error = gl.get_error();
        let image = Image::read(gl, cfg.width, cfg.height);
        BenchResult {
            name: self.name,
            frame_ms: self.frame_ms,
            image,
            error,
        }
    }
}

/// tilegl as programs reach it (the C exports, default threads: one per core), or through the
/// Rust API with `cfg.tilegl_threads[0]` threads when `--threads` was given.
pub fn open_tilegl(cfg: &BenchConfig, data: &WorkData) -> Result<Session, String> {
    match cfg.tilegl_threads.first() {
        Some(&threads) => {
            let ctx = crate::client_context(ContextConfig {
                width: cfg.width,
                height: cfg.height,
                threads,
                framebuffer: FramebufferConfig {
                    accum_bits: 16,
                    ..FramebufferConfig::default()
                },
            });
            Ok(Session::open(
                format!("tilegl {threads}T rs"),
                Subject::Rust(Box::new(ctx)),
                cfg,
                data,
            ))
        }
        None => {
            let ctx = CAbiContext::create(cfg.width, cfg.height, 16)
                .ok_or("the C ABI refused the context")?;
            let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
            Ok(Session::open(
                format!("tilegl {threads}T"),
                Subject::CAbi(ctx),
                cfg,
                data,
            ))
        }
    }
}

/// Mesa in this process (llvmpipe unless `GALLIUM_DRIVER` says otherwise).
pub fn open_mesa(cfg: &BenchConfig, data: &WorkData) -> Result<(Session, OracleInfo), String> {
    let mesa = MesaContext::create(cfg.width, cfg.height).map_err(|e| e.to_string())?;
    let info = mesa.info().clone();
    let name = format!("mesa {}", info.driver());
    Ok((Session::open(name, Subject::Mesa(mesa), cfg, data), info))
}

/// One line of the ratio table.
#[derive(Clone, Debug)]
pub struct SummaryRow {
    pub workload: Workload,
    pub tilegl_name: String,
    pub tilegl_ms: f64,
    pub llvmpipe_ms: Option<f64>,
    pub softpipe_ms: Option<f64>,
    /// tilegl's picture against llvmpipe's and softpipe's.
    pub vs_llvmpipe: Option<tilegl::compare::Diff>,
    pub vs_softpipe: Option<tilegl::compare::Diff>,
    /// A GL error reported by any implementation after the frames.
    pub errors: Vec<String>,
}

/// Times one workload: tilegl and Mesa in this process in two alternating rounds (tilegl,
/// Mesa; then Mesa, tilegl), the other Mesa driver in a child process between them; prints
/// each implementation's figures and every pair's picture difference, and returns the row of
/// the ratio table.
fn run_workload(cfg: &BenchConfig, args: &[String]) -> Option<SummaryRow> {
    let data = work_data(cfg);
    println!();
    println!(
        "== {}: {} at {}x{}, median of at least {} frames and {:.1} s over two alternating \
         rounds (after 1 warm-up; at most {:.0} s), each ending in glFinish",
        cfg.workload.name(),
        describe(cfg),
        cfg.width,
        cfg.height,
        cfg.frames,
        cfg.min_time.as_secs_f64(),
        cfg.budget.as_secs_f64()
    );
    // The cross-core round trip just before each implementation's first round (`machine`);
    // not with `--no-xcore` (under valgrind its two spinning threads take minutes).
    let measure = !args.iter().any(|a| a == "--no-xcore");
    let cross_core_round_trip_ns = || measure.then(cross_core_round_trip_ns).flatten();
    let frames = cfg.frames.div_ceil(2);
    let (half, budget) = (cfg.min_time / 2, cfg.budget / 2);
    let mut tile = match open_tilegl(cfg, &data) {
        Ok(t) => t,
        Err(e) => {
            println!("tilegl: {e}");
            return None;
        }
    };
    let mut mesa = if args.iter().any(|a| a == "--no-mesa") {
        Err("--no-mesa".to_string())
    } else {
        open_mesa(cfg, &data)
    };
    let trip_tile = cross_core_round_trip_ns();
    tile.round(&data, frames, half, budget);
    let trip_mesa = cross_core_round_trip_ns();
    if let Ok((m, _)) = &mut mesa {
        m.round(&data, frames, half, budget);
    }
    // The other driver in a child between the rounds (softpipe takes about a second a frame:
    // three frames).
    let child = match &mesa {
        Ok((_, info)) => {
            let other = if info.driver() == "softpipe" {
                "llvmpipe"
            } else {
                "softpipe"
            };
            // cargo bench passes --bench; keep it so the child parses args the same way.
            let extra: Vec<&str> = args
                .iter()
                .filter(|a| a.as_str() == "--bench")
                .map(|s| s.as_str())
                .collect();
            let mut c = cfg.clone();
            c.frames = 3;
            c.min_time = half;
            let before = cross_core_round_trip_ns();
            Some((other, run_mesa_subprocess(other, &c, &extra), before))
        }
        Err(_) => None,
    };
    if let Ok((m, _)) = &mut mesa {
        m.round(&data, frames, half, budget);
    }
    tile.round(&data, frames, half, budget);

    let mut results = vec![tile.finish(cfg)];
    let mut round_trip = vec![trip_tile];
    match mesa {
        Ok((m, info)) => {
            println!("Mesa in this process: {info}");
            results.push(m.finish(cfg));
            round_trip.push(trip_mesa);
        }
        Err(e) => println!("Mesa: unavailable ({e}); tilegl figures only"),
    }
    if let Some((other, r, before)) = child {
        match r {
            Ok(r) => {
                results.push(r);
                round_trip.push(before);
            }
            Err(e) => println!("mesa {other}: unavailable ({e})"),
        }
    }

    let base = results[0].median_ms();
    println!(
        "{:<16} {:>10} {:>10} {:>8} {:>7}  timed frames: count, fastest, 90th percentile, \
         slowest (ms)",
        "implementation", "ms/frame", "vs tilegl", "glError", "xcore"
    );
    for (r, trip) in results.iter().zip(&round_trip) {
        let trip = trip.map_or("-".to_string(), |ns| format!("{ns:.0} ns"));
        let mut sorted = r.frame_ms.clone();
        sorted.sort_by(f64::total_cmp);
        let at = |q: f64| {
            sorted
                .get(((sorted.len() as f64 - 1.0) * q).round() as usize)
                .copied()
                .unwrap_or(f64::NAN)
        };
        println!(
            "{:<16} {:>10.1} {:>9.2}x {:>#8x} {:>7}  {} frames: {:.1}, {:.1}, {:.1}",
            r.name,
            r.median_ms(),
            r.median_ms() / base,
            r.error,
            trip,
            sorted.len(),
            at(0.0),
            at(0.9),
            at(1.0)
        );
    }
    println!(
        "xcore: a cache line's round trip between CPU 0 and CPU 1 just before the run \
         (machine::cross_core_round_trip_ns; the development VM has phases of ~100 and ~400 ns, \
         and multi-threaded renderers are slower in the second)"
    );
    // The issues' targets are speeds relative to Mesa's drivers: tilegl's speed against each
    // Mesa run's (above 1: tilegl is faster). A ratio of two runs timed in different phases of
    // the machine is marked.
    let t = &results[0];
    let speeds: Vec<String> = results
        .iter()
        .zip(&round_trip)
        .skip(1)
        .map(|(m, trip)| {
            let note = phase_note(round_trip[0], *trip);
            format!("{:.2}x {}{note}", m.median_ms() / t.median_ms(), m.name)
        })
        .collect();
    if !speeds.is_empty() {
        println!("speed of {}: {}", t.name, speeds.join(", "));
    }
    if let Some(dir) = std::env::var_os("TILEGL_BENCH_DUMP") {
        // Pictures for a closer look: DIR/WORKLOAD-IMPLEMENTATION.ppm.
        let dir = std::path::PathBuf::from(dir);
        let _ = std::fs::create_dir_all(&dir);
        for r in &results {
            let file = format!("{}-{}.ppm", cfg.workload.name(), r.name.replace(' ', "_"));
            if let Err(e) = r.image.write_ppm(&dir.join(file)) {
                println!("cannot write picture: {e}");
            }
        }
    }
    println!("image error (per pair; bad = pixels with a channel difference > 8):");
    for i in 0..results.len() {
        for j in i + 1..results.len() {
            let d = diff(&results[i].image, &results[j].image, 8);
            println!("  {:<14} vs {:<14} {}", results[i].name, results[j].name, d);
        }
    }
    let find = |driver: &str| results.iter().find(|r| r.name == format!("mesa {driver}"));
    let (llvmpipe, softpipe) = (find("llvmpipe"), find("softpipe"));
    Some(SummaryRow {
        workload: cfg.workload,
        tilegl_name: t.name.clone(),
        tilegl_ms: t.median_ms(),
        llvmpipe_ms: llvmpipe.map(BenchResult::median_ms),
        softpipe_ms: softpipe.map(BenchResult::median_ms),
        vs_llvmpipe: llvmpipe.map(|m| diff(&t.image, &m.image, 8)),
        vs_softpipe: softpipe.map(|m| diff(&t.image, &m.image, 8)),
        errors: results
            .iter()
            .filter(|r| r.error != 0)
            .map(|r| format!("{} {:#x}", r.name, r.error))
            .collect(),
    })
}

/// The ratio table of a run as Markdown: each workload's median ms on tilegl, llvmpipe and
/// softpipe, tilegl's speed against each (above 1: faster), and beside the times tilegl's
/// picture error against each (share of pixels with a channel off by more than 8, mean
/// channel difference).
pub fn ratio_table(rows: &[SummaryRow]) -> String {
    let ms = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.1}"));
    let speed = |t: f64, m: Option<f64>| m.map_or("-".to_string(), |m| format!("{:.2}x", m / t));
    let err = |d: &Option<tilegl::compare::Diff>| {
        d.as_ref().map_or("-".to_string(), |d| {
            format!("{:.3} % / {:.3}", d.bad_share * 100.0, d.mean)
        })
    };
    let tilegl = rows.first().map_or("tilegl", |r| r.tilegl_name.as_str());
    let mut out = format!(
        "| workload | {tilegl} ms | llvmpipe ms | softpipe ms | vs llvmpipe | vs softpipe | \
         error vs llvmpipe (>8, mean) | error vs softpipe (>8, mean) |\n\
         | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n"
    );
    for r in rows {
        out += &format!(
            "| `{}` | {:.1} | {} | {} | {} | {} | {} | {} |{}\n",
            r.workload.name(),
            r.tilegl_ms,
            ms(r.llvmpipe_ms),
            ms(r.softpipe_ms),
            speed(r.tilegl_ms, r.llvmpipe_ms),
            speed(r.tilegl_ms, r.softpipe_ms),
            err(&r.vs_llvmpipe),
            err(&r.vs_softpipe),
            if r.errors.is_empty() {
                String::new()
            } else {
                format!(" GL errors: {}", r.errors.join(", "))
            }
        );
    }
    out
}

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
