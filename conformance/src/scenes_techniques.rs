//! More teaching scenes for the gallery: the fixed-function texturing techniques the first
//! examples did not cover (Haeberli & Segal 1993; McReynolds & Blythe, "Advanced Graphics
//! Programming Using OpenGL"; Akenine-Möller et al., "Real-Time Rendering"). Each is a
//! differential scene (checked against Mesa by `tests/differential_techniques.rs`), each has a
//! text in [`TECHNIQUE_TEXTS`] saying what it teaches and which GL state does it, and the
//! multitexture ones ask [`unit_on`] before enabling a unit, so the gallery can show the output
//! of each unit of the cascade on its own.

use crate::compare::Scene;
use crate::example_support::{self, snap_color, snap_stencil, snap_texture, unit_on};
use crate::prng::XorShift;
use crate::scenes_examples::{
    camera, clear_to, cross, cuboid, dot, floor_quad, grid, lamp, material, norm, paint, sampling,
    sub, tex2d, torus, V3,
};
use crate::tolerance::{Tolerance, DIFFERENTIAL};
use tilegl::enums::*;
use tilegl::Gl;

use std::f32::consts::{PI, TAU};

const fn sc(name: &'static str, draw: fn(&mut dyn Gl), w: i32, h: i32, tol: Tolerance) -> Scene {
    Scene {
        name,
        width: w,
        height: h,
        draw,
        tolerance: tol,
    }
}

/// The technique scenes, in gallery order.
pub const TECHNIQUE_SCENES: &[Scene] = &[
    sc("ex_texenv_modes", ex_texenv_modes, 288, 192, DIFFERENTIAL),
    sc(
        "ex_projector_mappings",
        ex_projector_mappings,
        256,
        256,
        DIFFERENTIAL,
    ),
    sc(
        "ex_prefilter_mip_rip_sat",
        ex_prefilter_mip_rip_sat,
        384,
        128,
        DIFFERENTIAL,
    ),
    sc(
        "ex_env_latlong_paraboloid",
        ex_env_latlong_paraboloid,
        256,
        128,
        DIFFERENTIAL,
    ),
    sc(
        "ex_texture_matrix_animation",
        ex_texture_matrix_animation,
        256,
        64,
        DIFFERENTIAL,
    ),
    sc("ex_image_warp", ex_image_warp, 384, 128, DIFFERENTIAL),
    sc(
        "ex_detail_texture",
        ex_detail_texture,
        128,
        128,
        DIFFERENTIAL,
    ),
    sc(
        "ex_billboards_impostors",
        ex_billboards_impostors,
        256,
        128,
        DIFFERENTIAL,
    ),
    sc(
        "ex_antialiased_points_lines",
        ex_antialiased_points_lines,
        256,
        128,
        DIFFERENTIAL,
    ),
    sc("ex_airbrush", ex_airbrush, 256, 128, DIFFERENTIAL),
    sc("ex_csg_stencil", ex_csg_stencil, 256, 128, DIFFERENTIAL),
    sc(
        "ex_phong_highlight_texture",
        ex_phong_highlight_texture,
        256,
        128,
        DIFFERENTIAL,
    ),
    sc(
        "ex_reflection_clip_plane",
        ex_reflection_clip_plane,
        256,
        128,
        DIFFERENTIAL,
    ),
    sc("ex_particles", ex_particles, 128, 128, DIFFERENTIAL),
    sc("ex_env_bump", ex_env_bump, 256, 128, DIFFERENTIAL),
];

/// For each technique scene: a title, what it teaches, and the GL state that does it.
pub const TECHNIQUE_TEXTS: &[(&str, &str, &str, &str)] = &[
    (
        "ex_texenv_modes",
        "Texture environment modes side by side",
        "The same RGBA texture (stripes, an opaque disc in a 30 % alpha surround) over the same \
         smooth-shaded quad (colour and alpha vary across it) and a checker backdrop, blended \
         with the fragment alpha. REPLACE takes the texel; MODULATE multiplies it with the \
         primary colour; DECAL lays the texel's colour over the primary colour by its alpha and \
         keeps the primary alpha; BLEND mixes the primary colour with the environment colour by \
         the texel's colour; ADD adds the colours and multiplies the alphas; COMBINE here \
         interpolates between the texel and a constant colour by the primary colour.",
        "glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE | GL_MODULATE | GL_DECAL | \
         GL_BLEND | GL_ADD | GL_COMBINE); GL_TEXTURE_ENV_COLOR; GL_COMBINE_RGB = GL_INTERPOLATE \
         with GL_SOURCE0..2_RGB = GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR; glBlendFunc(GL_SRC_ALPHA, \
         GL_ONE_MINUS_SRC_ALPHA).",
    ),
    (
        "ex_projector_mappings",
        "Planar, cylindrical, spherical and box projector mappings",
        "Four ways to give an object texture coordinates from its shape, each on the same lit \
         sphere with the same grid texture. Planar (top left): s and t are linear functions of \
         the object position, the texture is pushed through the object along z and stretches \
         where the surface turns away. Cylindrical (top right): s is the angle around the y \
         axis, t the height. Spherical (bottom left): s the angle around the axis, t the \
         latitude angle; the texture pinches at the poles. Box (bottom right): each triangle \
         takes a planar projection along the axis its normal points most along, six planar \
         projectors with seams between them.",
        "Planar: glTexGeni(GL_S/GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR) with \
         GL_OBJECT_PLANE (0.5, 0, 0, 0.5) and (0, 0.5, 0, 0.5). The others: glTexCoord2f per \
         vertex, computed from the position (cylindrical, spherical) or from the triangle's \
         normal (box). GL_REPEAT wrap, GL_MODULATE with GL_LIGHTING.",
    ),
    (
        "ex_prefilter_mip_rip_sat",
        "Mipmaps, ripmaps and summed-area tables",
        "A texture of fine horizontal stripes and thin vertical lines drawn squeezed 2.7x, 5.3x \
         and 10.7x vertically but not horizontally. Mipmaps (left) filter the same amount in \
         both directions (the level follows the larger squeeze), so the vertical lines blur. \
         Ripmaps (middle, built on the CPU: every combination of halving in x and in y) keep \
         x sharp and average y; the nearest power-of-two reduction is sampled. A summed-area \
         table (right, built on the CPU) gives the average over any rectangle with four \
         look-ups; each texel holds the box of exactly the height its pixel covers. GL samples \
         all three.",
        "Left: GL_GENERATE_MIPMAP and GL_LINEAR_MIPMAP_LINEAR. Middle and right: textures \
         uploaded with glTexImage2D, GL_LINEAR minification without mipmaps. Pixel-space \
         glOrtho.",
    ),
    (
        "ex_env_latlong_paraboloid",
        "Latitude-longitude and dual-paraboloid environment maps",
        "A mirror sphere reflecting one environment stored two ways. Left: a \
         latitude-longitude map; the reflection vector is turned into azimuth and elevation \
         per vertex on the CPU (a map GL cannot index by itself) and the seam where the \
         azimuth wraps is fixed per triangle. Right: a dual-paraboloid map, two textures each \
         holding one hemisphere of directions; GL computes the reflection vector and the \
         texture matrix projects it onto the paraboloid (s = rx / (1 + rz)), so it works per \
         vertex without CPU help; the back half is drawn first and the front half over it \
         where its alpha (1 inside the paraboloid's disc) passes the alpha test.",
        "Left: glTexCoord2f from atan2 / asin, GL_REPEAT in s. Right: glTexGeni(GL_S/T/R, \
         GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP), glMatrixMode(GL_TEXTURE) with a projective \
         matrix (q = 1 + rz, or 1 - rz for the back map), glAlphaFunc(GL_GREATER, 0.5), \
         glDepthFunc(GL_LEQUAL) for the second pass.",
    ),
    (
        "ex_texture_matrix_animation",
        "Texture animation through the texture matrix",
        "Four frames of flowing water: the geometry and the texture never change, only the \
         texture matrices. Unit 0 scrolls and turns a caustics pattern; unit 1 scrolls the \
         same texture, scaled, the other way and adds it. Animating texture coordinates costs \
         one matrix per frame instead of new coordinates per vertex.",
        "glMatrixMode(GL_TEXTURE) with glTranslatef / glRotatef / glScalef per unit \
         (glActiveTexture selects which unit's matrix); GL_REPEAT; unit 1 GL_ADD.",
    ),
    (
        "ex_image_warp",
        "Image warping",
        "An image (left) warped by a mesh: in the middle the vertex positions of a 16x16 grid \
         are moved (a swirl) and the texture coordinates stay regular, so the image follows the \
         mesh (a forward warp); on the right the positions stay regular and the texture \
         coordinates are moved (an inverse warp, the texture is looked up where the pixel comes \
         from). Between vertices the warp is piecewise linear.",
        "GL_TRIANGLE_STRIP grid, glTexCoord2f per vertex, GL_LINEAR, GL_CLAMP_TO_EDGE, \
         GL_REPLACE.",
    ),
    (
        "ex_detail_texture",
        "Detail textures",
        "A low-resolution terrain colour texture is blurry when magnified near the viewer. A \
         second texture of small grey noise around 0.5, repeated 16 times, adds high-frequency \
         detail: ADD_SIGNED adds it as a signed offset (texel - 0.5), so the average colour \
         stays the base colour.",
        "Unit 0: the base texture, GL_MODULATE. Unit 1: GL_COMBINE, GL_COMBINE_RGB = \
         GL_ADD_SIGNED, sources GL_PREVIOUS and GL_TEXTURE; two texture coordinate sets \
         (glMultiTexCoord2f) repeating 1x and 16x.",
    ),
    (
        "ex_billboards_impostors",
        "Billboards and impostors",
        "Trees are flat textured quads turned to face the camera about the vertical axis \
         (billboards); their transparent texels are cut away by the alpha test, so the depth \
         buffer sorts them with no blending order. The tori are impostors: one torus was \
         rendered once into a corner of the framebuffer, copied into a texture, and every \
         torus after that is a billboard showing that picture.",
        "glRotatef per billboard (the camera's azimuth), glAlphaFunc(GL_GREATER, 0.5) with \
         GL_ALPHA_TEST, glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, ...) from a framebuffer \
         cleared to alpha 0.",
    ),
    (
        "ex_antialiased_points_lines",
        "Antialiased points and lines through textures and alpha",
        "Left: plain wide points and lines, their edges stair-stepped. Right: the same points \
         as quads with a disc texture whose alpha falls off smoothly at the rim, and the lines \
         as thin quads with a texture whose alpha falls off across their width, blended over \
         the background: the texture does the coverage computation.",
        "Left: glPointSize(5), glLineWidth(3). Right: GL_QUADS with an RGBA texture, \
         GL_MODULATE, glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA), GL_LINEAR.",
    ),
    (
        "ex_airbrush",
        "Air-brush: painting with a texture",
        "A soft brush (a texture whose alpha is a Gaussian) stamped along three strokes with \
         blending builds up paint in the framebuffer (left). The finished canvas is then copied \
         into a texture and hung on a tilted sheet (right): painting into a texture.",
        "GL_QUADS stamps with GL_MODULATE and a translucent glColor4f, glBlendFunc(GL_SRC_ALPHA, \
         GL_ONE_MINUS_SRC_ALPHA); glCopyTexImage2D of the canvas.",
    ),
    (
        "ex_csg_stencil",
        "CSG with the stencil buffer",
        "A cube minus a sphere (left) and a cube intersected with a sphere (right), with no \
         geometry computed on the CPU. For each candidate surface (say the cube's front faces) \
         its depth is laid down, then the other solid's front faces increment and its back \
         faces decrement the stencil where they are nearer: a count of 1 means the surface is \
         inside the other solid. Only the surface's fragments with the right count are coloured. \
         Difference: the sphere's back faces inside the cube, then the cube's front faces \
         outside the sphere. Intersection: each solid's front faces inside the other.",
        "glStencilOp(GL_KEEP, GL_KEEP, GL_INCR / GL_DECR), glStencilFunc(GL_EQUAL / \
         GL_NOTEQUAL, 0, 0xff), glCullFace(GL_FRONT / GL_BACK) to pick faces, glColorMask and \
         glDepthMask for the depth-only passes, glDepthFunc(GL_LEQUAL) for the colour pass, \
         GL_LIGHT_MODEL_TWO_SIDE for the inner faces.",
    ),
    (
        "ex_phong_highlight_texture",
        "Phong highlights through texture",
        "The same coarse sphere. Left: the specular highlight from per-vertex lighting, \
         interpolated between vertices (Gouraud) so it is blotchy and follows the mesh. Right: \
         lighting without specular, and the highlight from a sphere-map texture holding \
         (R . L)^40 for every reflection direction; GL computes the reflection per vertex but \
         the texture lookup is per pixel, so the highlight is round and smooth.",
        "Left: GL_SPECULAR material, GL_SHININESS 40. Right: unit 0 a base texture \
         (GL_MODULATE), unit 1 the highlight with glTexGeni(GL_S/T, GL_TEXTURE_GEN_MODE, \
         GL_SPHERE_MAP) and GL_ADD.",
    ),
    (
        "ex_reflection_clip_plane",
        "Reflections with the stencil buffer and a clip plane",
        "A torus and a ball standing in water, reflected by drawing them mirrored (scale y by \
         -1) only where the water's stencil is set. Left: without a clip plane the submerged \
         parts, mirrored, poke up out of the water. Right: a user clip plane at the water \
         level removes everything below it before mirroring, so only what is above the water \
         is reflected.",
        "glStencilFunc(GL_EQUAL, 1, 0xff) after marking the water with GL_REPLACE; glScalef(1, \
         -1, 1) and glFrontFace(GL_CW) for the mirrored pass; glClipPlane(GL_CLIP_PLANE0, \
         (0, 1, 0, 0)) with GL_CLIP_PLANE0 enabled; the water blended over with \
         glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA).",
    ),
    (
        "ex_particles",
        "Particle systems",
        "A fountain of 300 particles, each a camera-facing quad with a soft disc texture, \
         positioned by a ballistic simulation (on the CPU) and coloured by age from yellow to \
         red, fading out. Additive blending makes the order in which they are drawn irrelevant, \
         so no sorting is needed, and depth writes are off so they do not hide each other.",
        "glBlendFunc(GL_SRC_ALPHA, GL_ONE), glDepthMask(GL_FALSE), GL_MODULATE with glColor4f \
         per particle, quads in eye space (identity modelview) so they face the camera.",
    ),
    (
        "ex_env_bump",
        "Environment-mapped bump mapping",
        "A metal plate reflecting a sphere map of the environment: flat (left) it is a mirror; \
         with its normals tilted by the gradient of a bump map of ripples (right) the reflected \
         picture is displaced, which is what environment-mapped bump mapping does: the bump map \
         offsets the environment lookup. GL 1.5 has no dependent texture read (the per-pixel \
         offset of DirectX 6 style EMBM), so here the offset is applied per vertex: the \
         perturbed normal of each vertex of a 64x64 mesh, about two pixels apart, goes to GL, \
         which computes the sphere-map coordinates from it.",
        "glNormal3f per vertex from the bump map's gradient (N - k dh/du T - k dh/dv B), \
         glTexGeni(GL_S/T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP), GL_REPLACE, a sphere-map \
         texture built from the environment's directions.",
    ),
];

// ---------------------------------------------------------------------------------------------
// Helpers.

/// Viewport and scissor on one panel.
fn panel(gl: &mut dyn Gl, x: i32, y: i32, w: i32, h: i32) {
    example_support::viewport(gl, x, y, w, h);
    example_support::scissor(gl, x, y, w, h);
    gl.enable(GL_SCISSOR_TEST);
}

/// Projection `glOrtho(0, w, 0, h, -1, 1)`, identity modelview.
fn ortho(gl: &mut dyn Gl, w: f64, h: f64) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, w, 0.0, h, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

/// A textured axis-aligned quad (texture coordinates 0..1), current colour.
fn rect(gl: &mut dyn Gl, x0: f32, y0: f32, x1: f32, y1: f32) {
    gl.begin(GL_QUADS);
    for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
        gl.tex_coord_2f(u, v);
        gl.vertex_2f(x0 + u * (x1 - x0), y0 + v * (y1 - y0));
    }
    gl.end();
}

/// A point on the unit sphere: `u` the longitude fraction, `v` the latitude fraction (0 at the
/// south pole).
fn sphere_point(u: f32, v: f32) -> V3 {
    let (phi, theta) = (TAU * u, PI * (v - 0.5));
    [
        theta.cos() * phi.sin(),
        theta.sin(),
        theta.cos() * phi.cos(),
    ]
}

/// The triangles of a unit sphere (counter-clockwise from outside), each as three (u, v,
/// position) corners.
fn sphere_triangles(nu: usize, nv: usize) -> Vec<[(f32, f32, V3); 3]> {
    let mut tris = Vec::new();
    let c = |i: usize, j: usize| {
        let (u, v) = (i as f32 / nu as f32, j as f32 / nv as f32);
        (u, v, sphere_point(u, v))
    };
    for j in 0..nv {
        for i in 0..nu {
            let (a, b, cc, d) = (c(i, j), c(i + 1, j), c(i + 1, j + 1), c(i, j + 1));
            if j > 0 {
                tris.push([a, b, cc]);
            }
            if j + 1 < nv {
                tris.push([a, cc, d]);
            }
        }
    }
    tris
}

/// A sphere of radius `r` at `c`, with normals, as triangles; `tc` gives each corner's texture
/// coordinates from (triangle, corner index) (None: no texture coordinates).
type Tri = [(f32, f32, V3); 3];
/// Texture coordinates of a triangle's corner.
type Coords<'a> = &'a dyn Fn(&Tri, usize) -> [f32; 2];
fn sphere(gl: &mut dyn Gl, c: V3, r: f32, n: (usize, usize), tc: Option<Coords>) {
    gl.begin(GL_TRIANGLES);
    for t in sphere_triangles(n.0, n.1) {
        for (k, &(_, _, p)) in t.iter().enumerate() {
            if let Some(f) = tc {
                let st = f(&t, k);
                gl.tex_coord_2f(st[0], st[1]);
            }
            gl.normal_3f(p[0], p[1], p[2]);
            gl.vertex_3f(c[0] + r * p[0], c[1] + r * p[1], c[2] + r * p[2]);
        }
    }
    gl.end();
}

/// A soft disc: white, alpha falling from 1 at the centre to 0 at the rim (smoothstep).
fn soft_disc(size: usize, hard: f32) -> Vec<u8> {
    paint(size, size, 4, |u, v| {
        let r = (((u - 0.5).powi(2) + (v - 0.5).powi(2)).sqrt() * 2.0).min(1.0);
        let x = ((1.0 - r) / (1.0 - hard)).clamp(0.0, 1.0);
        [1.0, 1.0, 1.0, x * x * (3.0 - 2.0 * x)]
    })
}

fn gaussian_brush(size: usize) -> Vec<u8> {
    paint(size, size, 4, |u, v| {
        let r2 = (u - 0.5).powi(2) + (v - 0.5).powi(2);
        let a = (-r2 / (2.0 * 0.16f32.powi(2))).exp();
        [1.0, 1.0, 1.0, if r2 > 0.25 { 0.0 } else { a }]
    })
}

fn combine(gl: &mut dyn Gl, rgb: GLenum, sources: &[GLenum]) {
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, rgb as i32);
    let names = [GL_SOURCE0_RGB, GL_SOURCE1_RGB, GL_SOURCE2_RGB];
    let ops = [GL_OPERAND0_RGB, GL_OPERAND1_RGB, GL_OPERAND2_RGB];
    for (i, &s) in sources.iter().enumerate() {
        gl.tex_envi(GL_TEXTURE_ENV, names[i], s as i32);
        gl.tex_envi(GL_TEXTURE_ENV, ops[i], GL_SRC_COLOR as i32);
    }
}

// ---------------------------------------------------------------------------------------------
// Texture environment modes.

fn ex_texenv_modes(gl: &mut dyn Gl) {
    clear_to(gl, [0.12, 0.12, 0.16]);
    let tex = paint(32, 32, 4, |u, v| {
        let d = ((u - 0.5).powi(2) + (v - 0.5).powi(2)).sqrt();
        let a = if d < 0.33 { 1.0 } else { 0.3 };
        if (u * 4.0) as i32 % 2 == 0 {
            [0.95, 0.8 + 0.15 * v, 0.2, a]
        } else {
            [0.15, 0.3 + 0.4 * v, 0.85, a]
        }
    });
    tex2d(gl, 32, 32, GL_RGBA, &tex);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "texture", GL_TEXTURE_2D, 0, [32, 32, 1]);
    gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.95, 0.6, 0.1, 1.0]);
    let modes = [
        GL_REPLACE,
        GL_MODULATE,
        GL_DECAL,
        GL_BLEND,
        GL_ADD,
        GL_COMBINE,
    ];
    for (i, &mode) in modes.iter().enumerate() {
        panel(gl, (i as i32 % 3) * 96, (1 - i as i32 / 3) * 96, 96, 96);
        ortho(gl, 1.0, 1.0);
        // The checker backdrop.
        gl.disable(GL_TEXTURE_2D);
        gl.disable(GL_BLEND);
        gl.begin(GL_QUADS);
        for j in 0..6 {
            for k in 0..6 {
                let g = if (j + k) % 2 == 0 { 0.75 } else { 0.35 };
                gl.color_3f(g, g, g);
                let (x, y) = (k as f32 / 6.0, j as f32 / 6.0);
                gl.vertex_2f(x, y);
                gl.vertex_2f(x + 1.0 / 6.0, y);
                gl.vertex_2f(x + 1.0 / 6.0, y + 1.0 / 6.0);
                gl.vertex_2f(x, y + 1.0 / 6.0);
            }
        }
        gl.end();
        gl.enable(GL_TEXTURE_2D);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        if mode == GL_COMBINE {
            combine(
                gl,
                GL_INTERPOLATE,
                &[GL_TEXTURE, GL_CONSTANT, GL_PRIMARY_COLOR],
            );
            gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_MODULATE as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_TEXTURE as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_PRIMARY_COLOR as i32);
        } else {
            gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, mode as i32);
        }
        // Colours and alpha affine in position (any split of the quad gives the same picture).
        let col = |x: f32, y: f32| [0.2 + 0.7 * x, 0.9 - 0.6 * y, 0.3 + 0.5 * y, 0.45 + 0.5 * x];
        gl.begin(GL_QUADS);
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            let (x, y) = (0.08 + 0.84 * u, 0.08 + 0.84 * v);
            let c = col(x, y);
            gl.color_4f(c[0], c[1], c[2], c[3]);
            gl.tex_coord_2f(u, v);
            gl.vertex_2f(x, y);
        }
        gl.end();
    }
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Projector mappings.

fn grid_texture() -> Vec<u8> {
    paint(64, 64, 3, |u, v| {
        let (x, y) = ((u * 64.0) as i32, (v * 64.0) as i32);
        if x % 8 == 0 || y % 8 == 0 {
            return [0.95, 0.95, 0.95, 1.0];
        }
        match (u < 0.5, v < 0.5) {
            (true, true) => [0.85, 0.2, 0.15, 1.0],
            (false, true) => [0.2, 0.65, 0.25, 1.0],
            (true, false) => [0.2, 0.35, 0.85, 1.0],
            (false, false) => [0.9, 0.75, 0.15, 1.0],
        }
    })
}

fn ex_projector_mappings(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.14]);
    let t = grid_texture();
    tex2d(gl, 64, 64, GL_RGB, &t);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_DEPTH_TEST);
    let cyl = |t: &Tri, k: usize| -> [f32; 2] {
        // The angle around the axis; the poles take their triangle's other corners' mean.
        let (u, _, p) = t[k];
        let s = if p[1].abs() > 0.9999 {
            let others: Vec<f32> = (0..3).filter(|&i| i != k).map(|i| t[i].0).collect();
            others.iter().sum::<f32>() / others.len() as f32
        } else {
            u
        };
        [s, 0.5 + 0.5 * p[1]]
    };
    let sph = |t: &Tri, k: usize| -> [f32; 2] { [cyl(t, k)[0], t[k].1] };
    let boxm = |t: &Tri, k: usize| -> [f32; 2] {
        let n = cross(sub(t[1].2, t[0].2), sub(t[2].2, t[0].2));
        let p = t[k].2;
        let (a, b) = if n[0].abs() >= n[1].abs() && n[0].abs() >= n[2].abs() {
            (p[2], p[1])
        } else if n[1].abs() >= n[2].abs() {
            (p[0], p[2])
        } else {
            (p[0], p[1])
        };
        [0.5 + 0.5 * a, 0.5 + 0.5 * b]
    };
    for i in 0..4 {
        panel(gl, (i % 2) * 128, (1 - i / 2) * 128, 128, 128);
        camera(gl, 34.0, 1.0, [1.2, 1.6, 3.6], [0.0, 0.0, 0.0]);
        lamp(gl, [0.5, 1.0, 1.0, 0.0]);
        material(gl, [1.0, 1.0, 1.0, 1.0], 0.0, 1.0);
        gl.color_3f(1.0, 1.0, 1.0);
        if i == 0 {
            for (c, plane) in [(GL_S, [0.5, 0.0, 0.0, 0.5]), (GL_T, [0.0, 0.5, 0.0, 0.5])] {
                gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR as i32);
                gl.tex_genfv(c, GL_OBJECT_PLANE, &plane);
            }
            gl.enable(GL_TEXTURE_GEN_S);
            gl.enable(GL_TEXTURE_GEN_T);
            sphere(gl, [0.0; 3], 1.0, (24, 12), None);
            gl.disable(GL_TEXTURE_GEN_S);
            gl.disable(GL_TEXTURE_GEN_T);
        } else {
            let f: Coords = match i {
                1 => &cyl,
                2 => &sph,
                _ => &boxm,
            };
            sphere(gl, [0.0; 3], 1.0, (24, 12), Some(f));
        }
    }
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Mipmaps, ripmaps, summed-area tables.

const PF: usize = 128;

fn stripes_texture() -> Vec<u8> {
    paint(PF, PF, 3, |u, v| {
        let (x, y) = ((u * PF as f32) as usize, (v * PF as f32) as usize);
        if x % 16 == 7 {
            return [0.05, 0.05, 0.05, 1.0];
        }
        let band = (y / 2) % 3;
        let c = [[0.95, 0.3, 0.2], [0.95, 0.95, 0.9], [0.2, 0.4, 0.9]][band];
        [c[0], c[1], c[2], 1.0]
    })
}

/// The rows of the prefilter scene: (bottom, height) in pixels.
const PF_ROWS: [(f32, f32); 3] = [(72.0, 48.0), (36.0, 24.0), (12.0, 12.0)];

fn ex_prefilter_mip_rip_sat(gl: &mut dyn Gl) {
    clear_to(gl, [0.12, 0.12, 0.16]);
    ortho(gl, 384.0, 128.0);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    let src = stripes_texture();
    // Mipmaps.
    tex2d(gl, PF as i32, PF as i32, GL_RGB, &src);
    sampling(
        gl,
        GL_TEXTURE_2D,
        GL_LINEAR_MIPMAP_LINEAR,
        GL_LINEAR,
        GL_CLAMP_TO_EDGE,
    );
    for (y, h) in PF_ROWS {
        rect(gl, 0.0, y, 128.0, y + h);
    }
    // Ripmaps: reductions by 2^j in y only (x needs none here).
    let mut rip = src.clone();
    let mut rows = PF;
    let mut levels = vec![(rows, rip.clone())];
    while rows > 1 {
        let next: Vec<u8> = (0..rows / 2)
            .flat_map(|y| {
                let rip = &rip;
                (0..PF * 3).map(move |i| {
                    let a = rip[2 * y * PF * 3 + i] as u32;
                    let b = rip[(2 * y + 1) * PF * 3 + i] as u32;
                    (a + b).div_ceil(2) as u8
                })
            })
            .collect();
        rows /= 2;
        rip = next;
        levels.push((rows, rip.clone()));
    }
    for (y, h) in PF_ROWS {
        let squeeze = PF as f32 / h;
        let j = (squeeze.log2().round() as usize).min(levels.len() - 1);
        let (r, px) = &levels[j];
        tex2d(gl, PF as i32, *r as i32, GL_RGB, px);
        sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
        rect(gl, 128.0, y, 256.0, y + h);
    }
    // Summed-area table: sat[(y, x)] = sum of the texels below and left, per channel.
    let w = PF + 1;
    let mut sat = vec![0u32; w * w * 3];
    for y in 0..PF {
        for x in 0..PF {
            for c in 0..3 {
                sat[((y + 1) * w + x + 1) * 3 + c] = src[(y * PF + x) * 3 + c] as u32
                    + sat[(y * w + x + 1) * 3 + c]
                    + sat[((y + 1) * w + x) * 3 + c]
                    - sat[(y * w + x) * 3 + c];
            }
        }
    }
    let area = |x0: usize, y0: usize, x1: usize, y1: usize, c: usize| -> f32 {
        let s = |x: usize, y: usize| sat[(y * w + x) * 3 + c] as i64;
        let sum = s(x1, y1) - s(x0, y1) - s(x1, y0) + s(x0, y0);
        sum as f32 / ((x1 - x0) * (y1 - y0)) as f32
    };
    for (y, h) in PF_ROWS {
        let squeeze = PF as f32 / h;
        let mut px = Vec::with_capacity(PF * PF * 3);
        for ty in 0..PF {
            let centre = ty as f32 + 0.5;
            let y0 = (centre - squeeze / 2.0).round().clamp(0.0, PF as f32 - 1.0) as usize;
            let y1 = ((centre + squeeze / 2.0).round() as usize).clamp(y0 + 1, PF);
            for tx in 0..PF {
                for c in 0..3 {
                    px.push(area(tx, y0, tx + 1, y1, c).round() as u8);
                }
            }
        }
        tex2d(gl, PF as i32, PF as i32, GL_RGB, &px);
        sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
        if h == PF_ROWS[1].1 {
            snap_texture(
                gl,
                "sat_filtered_5x",
                GL_TEXTURE_2D,
                0,
                [PF as i32, PF as i32, 1],
            );
        }
        rect(gl, 256.0, y, 384.0, y + h);
    }
}

// ---------------------------------------------------------------------------------------------
// Latitude-longitude and dual-paraboloid environment maps.

/// The environment, by direction (eye space: y up, +z towards the viewer).
fn environment(d: V3) -> [f32; 3] {
    let d = norm(d);
    let sun = norm([0.5, 0.6, -0.6]);
    if dot(d, sun) > 0.97 {
        return [1.0, 0.95, 0.7];
    }
    let az = d[0].atan2(d[2]);
    if d[1].abs() < 0.25 {
        let k = ((az / (PI / 4.0)).round() as i32).rem_euclid(8);
        if (az - k as f32 * PI / 4.0).abs() < 0.12 || (az + TAU - k as f32 * PI / 4.0).abs() < 0.12
        {
            let c = [
                [0.9, 0.2, 0.2],
                [0.2, 0.8, 0.3],
                [0.3, 0.4, 0.95],
                [0.95, 0.85, 0.2],
            ];
            return c[k as usize % 4];
        }
    }
    if d[1] >= 0.0 {
        let t = d[1];
        [0.55 - 0.4 * t, 0.75 - 0.45 * t, 1.0 - 0.3 * t]
    } else {
        let check = ((az * 4.0 / PI).floor() as i32 + ((-d[1]) * 6.0) as i32).rem_euclid(2);
        if check == 0 {
            [0.45, 0.33, 0.2]
        } else {
            [0.3, 0.22, 0.14]
        }
    }
}

fn ex_env_latlong_paraboloid(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.14]);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    let eye = [0.0, 0.0, 3.0];
    // Left: latitude-longitude, coordinates per vertex on the CPU.
    let ll = paint(128, 64, 3, |s, t| {
        let (az, el) = ((s - 0.5) * TAU, (t - 0.5) * PI);
        let c = environment([el.cos() * az.sin(), el.sin(), el.cos() * az.cos()]);
        [c[0], c[1], c[2], 1.0]
    });
    tex2d(gl, 128, 64, GL_RGB, &ll);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE as i32);
    snap_texture(gl, "latlong_map", GL_TEXTURE_2D, 0, [128, 64, 1]);
    panel(gl, 0, 0, 128, 128);
    camera(gl, 40.0, 1.0, eye, [0.0, 0.0, 0.0]);
    let reflect = |p: V3| -> V3 {
        let v = norm(sub(p, eye));
        let k = 2.0 * dot(p, v);
        [v[0] - k * p[0], v[1] - k * p[1], v[2] - k * p[2]]
    };
    let latlong = |t: &Tri, k: usize| -> [f32; 2] {
        let st: Vec<[f32; 2]> = t
            .iter()
            .map(|&(_, _, p)| {
                let r = reflect(p);
                [
                    0.5 + r[0].atan2(r[2]) / TAU,
                    0.5 + r[1].clamp(-1.0, 1.0).asin() / PI,
                ]
            })
            .collect();
        // The seam: a triangle spanning more than half the azimuths crosses it.
        let (lo, hi) = st
            .iter()
            .fold((f32::MAX, f32::MIN), |(a, b), v| (a.min(v[0]), b.max(v[0])));
        let mut s = st[k][0];
        if hi - lo > 0.5 && s < 0.5 {
            s += 1.0;
        }
        [s, st[k][1]]
    };
    sphere(gl, [0.0; 3], 1.0, (32, 16), Some(&latlong));
    // Right: dual paraboloid, reflection vector by GL.
    let para = |front: bool| -> Vec<u8> {
        paint(64, 64, 4, move |s, t| {
            let (x, y) = (2.0 * s - 1.0, 2.0 * t - 1.0);
            let r2 = x * x + y * y;
            let z = (1.0 - r2) / (1.0 + r2);
            let d = [
                2.0 * x / (1.0 + r2),
                2.0 * y / (1.0 + r2),
                if front { z } else { -z },
            ];
            let c = environment(d);
            [
                c[0],
                c[1],
                c[2],
                if !front || r2 <= 1.0 { 1.0 } else { 0.0 },
            ]
        })
    };
    let back = tex2d(gl, 64, 64, GL_RGBA, &para(false));
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "paraboloid_back", GL_TEXTURE_2D, 0, [64, 64, 1]);
    let front = tex2d(gl, 64, 64, GL_RGBA, &para(true));
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "paraboloid_front", GL_TEXTURE_2D, 0, [64, 64, 1]);
    panel(gl, 128, 0, 128, 128);
    for c in [GL_S, GL_T, GL_R] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP as i32);
    }
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    gl.enable(GL_TEXTURE_GEN_R);
    gl.tex_coord_4f(0.0, 0.0, 0.0, 1.0);
    gl.depth_func(GL_LEQUAL);
    for (tex, sign) in [(back, -1.0f32), (front, 1.0)] {
        // s = (rx / (1 + sign rz) + 1) / 2, t likewise: q = 1 + sign rz.
        gl.matrix_mode(GL_TEXTURE);
        gl.load_matrixf(&[
            0.5,
            0.0,
            0.0,
            0.0,
            0.0,
            0.5,
            0.0,
            0.0,
            0.5 * sign,
            0.5 * sign,
            0.0,
            sign,
            0.5,
            0.5,
            0.0,
            1.0,
        ]);
        gl.matrix_mode(GL_MODELVIEW);
        gl.bind_texture(GL_TEXTURE_2D, tex);
        if sign > 0.0 {
            gl.enable(GL_ALPHA_TEST);
            gl.alpha_func(GL_GREATER, 0.5);
        }
        sphere(gl, [0.0; 3], 1.0, (32, 16), None);
        if sign < 0.0 {
            snap_color(gl, "back_pass", 256, 128);
        }
    }
    gl.disable(GL_ALPHA_TEST);
    gl.matrix_mode(GL_TEXTURE);
    gl.load_identity();
    gl.matrix_mode(GL_MODELVIEW);
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Texture matrix animation.

fn caustics() -> Vec<u8> {
    paint(32, 32, 3, |u, v| {
        let a = (TAU * (u * 2.0 + 0.3 * (TAU * v).sin())).sin();
        let b = (TAU * (v * 2.0 + 0.3 * (TAU * u).cos())).sin();
        let w = (0.5 + 0.25 * (a + b)).clamp(0.0, 1.0);
        [0.1 + 0.3 * w * w, 0.25 + 0.45 * w * w, 0.45 + 0.4 * w, 1.0]
    })
}

fn ex_texture_matrix_animation(gl: &mut dyn Gl) {
    clear_to(gl, [0.0, 0.0, 0.0]);
    let c = caustics();
    tex2d(gl, 32, 32, GL_RGB, &c);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.active_texture(GL_TEXTURE1);
    tex2d(gl, 32, 32, GL_RGB, &c);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD as i32);
    if unit_on(1) {
        gl.enable(GL_TEXTURE_2D);
    }
    gl.active_texture(GL_TEXTURE0);
    for frame in 0..4 {
        let f = frame as f32;
        panel(gl, frame * 64, 0, 64, 64);
        ortho(gl, 1.0, 1.0);
        gl.matrix_mode(GL_TEXTURE);
        gl.active_texture(GL_TEXTURE0);
        gl.load_identity();
        gl.translatef(0.5 + 0.13 * f, 0.5 + 0.05 * f, 0.0);
        gl.rotatef(11.0 * f, 0.0, 0.0, 1.0);
        gl.translatef(-0.5, -0.5, 0.0);
        gl.active_texture(GL_TEXTURE1);
        gl.load_identity();
        gl.translatef(-0.07 * f, -0.17 * f, 0.0);
        gl.scalef(1.7, 1.7, 1.0);
        gl.active_texture(GL_TEXTURE0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.color_3f(1.0, 1.0, 1.0);
        gl.begin(GL_QUADS);
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            gl.multi_tex_coord_2f(GL_TEXTURE0, u * 1.5, v * 1.5);
            gl.multi_tex_coord_2f(GL_TEXTURE1, u, v);
            gl.vertex_2f(u, v);
        }
        gl.end();
    }
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Image warping.

fn picture() -> Vec<u8> {
    paint(64, 64, 3, |u, v| {
        let (x, y) = (u - 0.5, v - 0.5);
        let r = (x * x + y * y).sqrt();
        let check = ((u * 8.0) as i32 + (v * 8.0) as i32) % 2 == 0;
        let base = if check {
            [0.85, 0.85, 0.8]
        } else {
            [0.3, 0.45, 0.6]
        };
        if r < 0.22 {
            [0.95, 0.75, 0.2, 1.0]
        } else if (r - 0.3).abs() < 0.03 {
            [0.8, 0.15, 0.15, 1.0]
        } else {
            [base[0], base[1], base[2], 1.0]
        }
    })
}

/// The swirl: a point of the unit square turned about the centre by an angle falling off with
/// the distance.
fn swirl(u: f32, v: f32, amount: f32) -> (f32, f32) {
    let (x, y) = (u - 0.5, v - 0.5);
    let r = (x * x + y * y).sqrt();
    let a = amount * (1.0 - (r / 0.5).min(1.0)).powi(2);
    let (s, c) = a.sin_cos();
    (0.5 + c * x - s * y, 0.5 + s * x + c * y)
}

fn ex_image_warp(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.14]);
    let p = picture();
    tex2d(gl, 64, 64, GL_RGB, &p);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    for k in 0..3 {
        panel(gl, k * 128, 0, 128, 128);
        gl.matrix_mode(GL_PROJECTION);
        gl.load_identity();
        gl.ortho(-0.05, 1.05, -0.05, 1.05, -1.0, 1.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.load_identity();
        grid(gl, 16, &|gl, u, v| {
            let (w, z) = swirl(u, v, 2.2);
            match k {
                0 => {
                    gl.tex_coord_2f(u, v);
                    gl.vertex_2f(u, v);
                }
                1 => {
                    gl.tex_coord_2f(u, v);
                    gl.vertex_2f(w, z);
                }
                _ => {
                    gl.tex_coord_2f(w, z);
                    gl.vertex_2f(u, v);
                }
            }
        });
    }
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Detail textures.

fn ex_detail_texture(gl: &mut dyn Gl) {
    clear_to(gl, [0.55, 0.7, 0.9]);
    camera(gl, 50.0, 1.0, [0.0, 0.9, 2.6], [0.0, 0.0, -1.0]);
    gl.enable(GL_DEPTH_TEST);
    let base = paint(16, 16, 3, |u, v| {
        let a = (TAU * u).sin() * (TAU * v).cos();
        [0.35 + 0.15 * a, 0.5 + 0.2 * (TAU * (u + v)).sin(), 0.2, 1.0]
    });
    tex2d(gl, 16, 16, GL_RGB, &base);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    snap_texture(gl, "base", GL_TEXTURE_2D, 0, [16, 16, 1]);
    gl.active_texture(GL_TEXTURE1);
    let mut rng = XorShift::new(25);
    let noise: Vec<u8> = (0..32 * 32)
        .flat_map(|_| {
            let g = (0.5 + rng.range(-0.22, 0.22)) * 255.0;
            [g as u8; 3]
        })
        .collect();
    tex2d(gl, 32, 32, GL_RGB, &noise);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    combine(gl, GL_ADD_SIGNED, &[GL_PREVIOUS, GL_TEXTURE]);
    snap_texture(gl, "detail", GL_TEXTURE_2D, 0, [32, 32, 1]);
    if unit_on(1) {
        gl.enable(GL_TEXTURE_2D);
    }
    gl.active_texture(GL_TEXTURE0);
    gl.color_3f(1.0, 1.0, 1.0);
    floor_quad(
        gl,
        [-4.0, 4.0],
        [-8.0, 2.5],
        &[(GL_TEXTURE0, 1.0, 1.0), (GL_TEXTURE1, 16.0, 16.0)],
    );
}

// ---------------------------------------------------------------------------------------------
// Billboards and impostors.

fn tree_texture() -> Vec<u8> {
    paint(32, 64, 4, |u, v| {
        let trunk = (u - 0.5).abs() < 0.07 && v < 0.3;
        let crown = v >= 0.2 && (u - 0.5).abs() < 0.45 * (1.0 - (v - 0.2) / 0.8);
        if trunk {
            [0.4, 0.25, 0.1, 1.0]
        } else if crown {
            let shade = if ((v * 10.0) as i32) % 2 == 0 {
                0.0
            } else {
                0.12
            };
            [0.1 + shade, 0.5 + shade, 0.15, 1.0]
        } else {
            [0.0, 0.0, 0.0, 0.0]
        }
    })
}

fn ex_billboards_impostors(gl: &mut dyn Gl) {
    // 1. The impostor: one lit torus rendered into a 64x64 corner, alpha 0 around it.
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.viewport(0, 0, 64, 64);
    camera(gl, 40.0, 1.0, [0.0, 1.2, 2.6], [0.0, 0.0, 0.0]);
    gl.enable(GL_DEPTH_TEST);
    lamp(gl, [0.4, 1.0, 0.8, 0.0]);
    material(gl, [0.9, 0.5, 0.2, 1.0], 0.5, 20.0);
    torus(gl, 0.75, 0.3, 24, 12);
    gl.disable(GL_LIGHTING);
    let mut t = [0u32];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 64, 64, 0);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "impostor", GL_TEXTURE_2D, 0, [64, 64, 1]);
    let impostor = t[0];
    let tree = tree_texture();
    let tree_tex = tex2d(gl, 32, 64, GL_RGBA, &tree);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    // 2. The scene.
    example_support::viewport(gl, 0, 0, 256, 128);
    clear_to(gl, [0.55, 0.72, 0.92]);
    let eye = [0.3, 1.6, 5.0];
    camera(gl, 40.0, 2.0, eye, [0.0, 0.4, 0.0]);
    gl.color_3f(0.35, 0.55, 0.25);
    gl.begin(GL_TRIANGLES);
    for (x, z) in [
        (-6.0, -6.0),
        (6.0, -6.0),
        (6.0, 4.0),
        (-6.0, -6.0),
        (6.0, 4.0),
        (-6.0, 4.0),
    ] {
        gl.vertex_3f(x, 0.0, z);
    }
    gl.end();
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_ALPHA_TEST);
    gl.alpha_func(GL_GREATER, 0.5);
    let billboard = |gl: &mut dyn Gl, p: V3, w: f32, h: f32| {
        gl.push_matrix();
        gl.translatef(p[0], p[1], p[2]);
        let yaw = (eye[0] - p[0]).atan2(eye[2] - p[2]).to_degrees();
        gl.rotatef(yaw, 0.0, 1.0, 0.0);
        gl.begin(GL_QUADS);
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            gl.tex_coord_2f(u, v);
            gl.vertex_3f((u - 0.5) * w, v * h, 0.0);
        }
        gl.end();
        gl.pop_matrix();
    };
    gl.bind_texture(GL_TEXTURE_2D, tree_tex);
    for (i, p) in [
        [-2.6, 0.0, -1.0],
        [-1.4, 0.0, 0.6],
        [-3.4, 0.0, -3.5],
        [-0.7, 0.0, -2.8],
        [-2.0, 0.0, 2.0],
    ]
    .into_iter()
    .enumerate()
    {
        billboard(gl, p, 0.8 + 0.1 * i as f32, 1.7 + 0.2 * i as f32);
    }
    gl.bind_texture(GL_TEXTURE_2D, impostor);
    for p in [
        [1.3, 0.0, 0.8],
        [2.6, 0.0, -1.2],
        [1.0, 0.0, -3.0],
        [3.4, 0.0, 1.6],
    ] {
        billboard(gl, p, 1.2, 1.2);
    }
    gl.disable(GL_ALPHA_TEST);
}

// ---------------------------------------------------------------------------------------------
// Antialiased points and lines through textures.

const AA_POINTS: [(f32, f32); 6] = [
    (20.3, 100.4),
    (43.7, 108.2),
    (70.2, 96.6),
    (95.4, 111.3),
    (30.6, 80.7),
    (84.1, 79.3),
];
const AA_LINES: [((f32, f32), (f32, f32)); 5] = [
    ((8.3, 10.4), (118.7, 30.2)),
    ((10.6, 60.3), (117.4, 18.7)),
    ((20.2, 8.6), (50.7, 66.1)),
    ((64.3, 5.2), (71.6, 68.4)),
    ((90.8, 12.3), (112.2, 64.7)),
];

fn ex_antialiased_points_lines(gl: &mut dyn Gl) {
    clear_to(gl, [0.08, 0.08, 0.12]);
    ortho(gl, 256.0, 128.0);
    let colour = |gl: &mut dyn Gl, i: usize, a: f32| {
        let c = [
            [1.0, 0.4, 0.3],
            [0.4, 1.0, 0.5],
            [0.4, 0.6, 1.0],
            [1.0, 0.9, 0.3],
        ][i % 4];
        gl.color_4f(c[0], c[1], c[2], a);
    };
    // Left: aliased.
    gl.point_size(5.0);
    gl.begin(GL_POINTS);
    for (i, &(x, y)) in AA_POINTS.iter().enumerate() {
        colour(gl, i, 1.0);
        gl.vertex_2f(x, y);
    }
    gl.end();
    gl.line_width(3.0);
    gl.begin(GL_LINES);
    for (i, &(a, b)) in AA_LINES.iter().enumerate() {
        colour(gl, i, 1.0);
        gl.vertex_2f(a.0, a.1);
        gl.vertex_2f(b.0, b.1);
    }
    gl.end();
    // Right: textured quads, coverage in the texture's alpha.
    let disc = soft_disc(16, 0.55);
    tex2d(gl, 16, 16, GL_RGBA, &disc);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "disc", GL_TEXTURE_2D, 0, [16, 16, 1]);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (i, &(x, y)) in AA_POINTS.iter().enumerate() {
        colour(gl, i, 1.0);
        rect(gl, 128.0 + x - 4.0, y - 4.0, 128.0 + x + 4.0, y + 4.0);
    }
    // A profile across the line: alpha 1 in the middle, falling to 0 at the edges.
    let profile = paint(4, 16, 4, |_, v| {
        let x = (1.0 - (2.0 * v - 1.0).abs() * 1.0).clamp(0.0, 1.0);
        [1.0, 1.0, 1.0, (x * 1.6).min(1.0)]
    });
    tex2d(gl, 4, 16, GL_RGBA, &profile);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    for (i, &(a, b)) in AA_LINES.iter().enumerate() {
        colour(gl, i, 1.0);
        let d = [b.0 - a.0, b.1 - a.1];
        let l = (d[0] * d[0] + d[1] * d[1]).sqrt();
        let n = [-d[1] / l * 2.5, d[0] / l * 2.5];
        gl.begin(GL_QUADS);
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            let s = 2.0 * v - 1.0;
            gl.tex_coord_2f(u, v);
            gl.vertex_2f(128.0 + a.0 + u * d[0] + s * n[0], a.1 + u * d[1] + s * n[1]);
        }
        gl.end();
    }
    gl.disable(GL_BLEND);
    gl.disable(GL_TEXTURE_2D);
}

// ---------------------------------------------------------------------------------------------
// Air-brush.

fn ex_airbrush(gl: &mut dyn Gl) {
    clear_to(gl, [0.93, 0.91, 0.85]);
    ortho(gl, 256.0, 128.0);
    let brush = gaussian_brush(32);
    tex2d(gl, 32, 32, GL_RGBA, &brush);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "brush", GL_TEXTURE_2D, 0, [32, 32, 1]);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    type Path<'a> = &'a dyn Fn(f32) -> (f32, f32);
    let strokes: [([f32; 3], Path); 3] = [
        ([0.85, 0.2, 0.15], &|t| {
            (12.3 + 104.0 * t, 90.2 + 18.0 * (t * 7.0).sin())
        }),
        ([0.15, 0.35, 0.8], &|t| {
            (64.1 + 40.0 * (t * TAU).cos(), 60.3 + 34.0 * (t * TAU).sin())
        }),
        ([0.2, 0.6, 0.2], &|t| {
            (14.2 + 100.0 * t, 18.4 + 60.0 * t * t)
        }),
    ];
    for (c, path) in strokes {
        gl.color_4f(c[0], c[1], c[2], 0.6);
        for k in 0..36 {
            let (x, y) = path(k as f32 / 35.0);
            rect(gl, x - 8.0, y - 8.0, x + 8.0, y + 8.0);
        }
    }
    gl.disable(GL_BLEND);
    snap_color(gl, "canvas", 256, 128);
    // The canvas as a texture, on a tilted sheet.
    let mut t = [0u32];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 128, 128, 0);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    panel(gl, 128, 0, 128, 128);
    gl.clear_color(0.2, 0.22, 0.28, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    camera(gl, 40.0, 1.0, [0.0, 0.0, 3.0], [0.0, 0.0, 0.0]);
    gl.rotatef(-35.0, 0.0, 1.0, 0.0);
    gl.rotatef(-20.0, 1.0, 0.0, 0.0);
    gl.begin(GL_QUADS);
    for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
        gl.tex_coord_2f(u, v);
        gl.vertex_3f(2.0 * u - 1.0, 2.0 * v - 1.0, 0.0);
    }
    gl.end();
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// CSG with the stencil buffer.

type Solid<'a> = &'a dyn Fn(&mut dyn Gl);

/// Colours the faces of `a` not culled by `cull` where they are inside (`inside`) or outside
/// the convex solid `b`: `a`'s depth, then `b`'s front faces +1 and back faces -1 where nearer,
/// then `a`'s colour where the count is right.
fn csg_pass(gl: &mut dyn Gl, a: Solid, b: Solid, cull: GLenum, inside: bool, snap: Option<&str>) {
    gl.clear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.enable(GL_CULL_FACE);
    gl.enable(GL_DEPTH_TEST);
    gl.color_mask(0, 0, 0, 0);
    gl.depth_mask(1);
    gl.depth_func(GL_LESS);
    gl.disable(GL_STENCIL_TEST);
    gl.cull_face(cull);
    a(gl);
    gl.depth_mask(0);
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_ALWAYS, 0, 0xff);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_INCR);
    gl.cull_face(GL_BACK);
    b(gl);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_DECR);
    gl.cull_face(GL_FRONT);
    b(gl);
    if let Some(name) = snap {
        snap_stencil(gl, name, 256, 128);
    }
    gl.color_mask(1, 1, 1, 1);
    gl.depth_mask(1);
    gl.depth_func(GL_LEQUAL);
    gl.stencil_func(if inside { GL_NOTEQUAL } else { GL_EQUAL }, 0, 0xff);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
    gl.cull_face(cull);
    a(gl);
    gl.disable(GL_STENCIL_TEST);
}

fn ex_csg_stencil(gl: &mut dyn Gl) {
    clear_to(gl, [0.12, 0.12, 0.16]);
    gl.light_modeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    let cube: Solid = &|gl| {
        material(gl, [0.85, 0.3, 0.2, 1.0], 0.0, 1.0);
        cuboid(gl, [0.0, 0.0, 0.0], [0.7, 0.7, 0.7]);
    };
    let ball: Solid = &|gl| {
        material(gl, [0.25, 0.45, 0.9, 1.0], 0.0, 1.0);
        sphere(gl, [0.45, 0.4, 0.5], 0.68, (24, 12), None);
    };
    for k in 0..2 {
        panel(gl, k * 128, 0, 128, 128);
        camera(gl, 38.0, 1.0, [1.8, 1.5, 3.0], [0.0, 0.0, 0.0]);
        lamp(gl, [0.3, 0.8, 1.0, 0.0]);
        if k == 0 {
            // Difference: the ball's back faces inside the cube, then the cube's front faces
            // outside the ball (they win wherever they are valid).
            csg_pass(gl, ball, cube, GL_FRONT, true, None);
            csg_pass(gl, cube, ball, GL_BACK, false, Some("count_cube_in_ball"));
        } else {
            csg_pass(gl, ball, cube, GL_BACK, true, None);
            csg_pass(gl, cube, ball, GL_BACK, true, None);
        }
    }
    gl.disable(GL_CULL_FACE);
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Phong highlights through a texture.

/// The highlight sphere map: (R . L)^shininess for the reflection direction each texel stands
/// for (GL 1.5 section 2.11.4: the texel at (s, t) holds the direction whose sphere-map
/// coordinates are (s, t)).
fn highlight_map(size: usize, light: V3, shininess: f32) -> Vec<u8> {
    let l = norm(light);
    paint(size, size, 3, |s, t| {
        let (x, y) = (2.0 * s - 1.0, 2.0 * t - 1.0);
        let r2 = x * x + y * y;
        if r2 > 1.0 {
            return [0.0, 0.0, 0.0, 1.0];
        }
        let z = (1.0 - r2).sqrt();
        let r = [2.0 * z * x, 2.0 * z * y, 2.0 * z * z - 1.0];
        let h = dot(r, l).max(0.0).powf(shininess);
        [h, h, h * 0.95, 1.0]
    })
}

fn ex_phong_highlight_texture(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.14]);
    gl.enable(GL_DEPTH_TEST);
    let light = [0.6, 0.7, 1.0];
    // The light is set with an identity modelview: its direction is in eye space.
    let setup = |gl: &mut dyn Gl, diffuse: [f32; 4], specular: f32| {
        gl.matrix_mode(GL_MODELVIEW);
        gl.load_identity();
        lamp(gl, [light[0], light[1], light[2], 0.0]);
        gl.lightfv(GL_LIGHT0, GL_SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
        material(gl, diffuse, specular, 40.0);
        gl.matrix_mode(GL_PROJECTION);
        gl.load_identity();
        gl.frustum(-0.4, 0.4, -0.4, 0.4, 1.0, 10.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.translatef(0.0, 0.0, -3.0);
        gl.rotatef(25.0, 1.0, 0.0, 0.0);
    };
    let coords = |t: &Tri, k: usize| [t[k].0 * 4.0, t[k].1 * 2.0];
    // Left: per-vertex specular.
    panel(gl, 0, 0, 128, 128);
    setup(gl, [0.6, 0.36, 0.22, 1.0], 1.0);
    sphere(gl, [0.0; 3], 1.0, (12, 8), Some(&coords));
    // Right: base texture on unit 0, highlight sphere map added on unit 1.
    panel(gl, 128, 0, 128, 128);
    setup(gl, [0.75, 0.75, 0.75, 1.0], 0.0);
    let base = paint(16, 16, 3, |u, v| {
        let k = ((u * 4.0) as i32 + (v * 4.0) as i32) % 2;
        if k == 0 {
            [0.9, 0.55, 0.3, 1.0]
        } else {
            [0.75, 0.35, 0.25, 1.0]
        }
    });
    tex2d(gl, 16, 16, GL_RGB, &base);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    if unit_on(0) {
        gl.enable(GL_TEXTURE_2D);
    }
    gl.active_texture(GL_TEXTURE1);
    let h = highlight_map(64, light, 40.0);
    tex2d(gl, 64, 64, GL_RGB, &h);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "highlight_sphere_map", GL_TEXTURE_2D, 0, [64, 64, 1]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD as i32);
    gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    if unit_on(1) {
        gl.enable(GL_TEXTURE_2D);
    }
    gl.active_texture(GL_TEXTURE0);
    sphere(gl, [0.0; 3], 1.0, (12, 8), Some(&coords));
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Reflections with the stencil buffer and a clip plane.

fn water_objects(gl: &mut dyn Gl) {
    material(gl, [0.9, 0.55, 0.2, 1.0], 0.4, 20.0);
    gl.push_matrix();
    gl.translatef(-0.3, 0.2, 0.0);
    gl.rotatef(70.0, 1.0, 0.0, 0.0);
    torus(gl, 0.6, 0.2, 24, 12);
    gl.pop_matrix();
    material(gl, [0.3, 0.7, 0.4, 1.0], 0.2, 10.0);
    sphere(gl, [0.95, 0.05, -0.3], 0.32, (16, 8), None);
}

fn water(gl: &mut dyn Gl) {
    gl.begin(GL_TRIANGLES);
    gl.normal_3f(0.0, 1.0, 0.0);
    for (x, z) in [
        (-2.0, -2.0),
        (-2.0, 2.0),
        (2.0, 2.0),
        (-2.0, -2.0),
        (2.0, 2.0),
        (2.0, -2.0),
    ] {
        gl.vertex_3f(x, 0.0, z);
    }
    gl.end();
}

fn ex_reflection_clip_plane(gl: &mut dyn Gl) {
    clear_to(gl, [0.55, 0.65, 0.8]);
    let light = [0.5, 1.0, 0.7, 0.0];
    for k in 0..2 {
        panel(gl, k * 128, 0, 128, 128);
        camera(gl, 40.0, 1.0, [0.0, 1.4, 3.4], [0.0, 0.0, 0.0]);
        gl.enable(GL_DEPTH_TEST);
        gl.enable(GL_CULL_FACE);
        // 1. Mark the water in the stencil buffer.
        gl.enable(GL_STENCIL_TEST);
        gl.stencil_func(GL_ALWAYS, 1, 0xff);
        gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
        gl.color_mask(0, 0, 0, 0);
        gl.depth_mask(0);
        water(gl);
        gl.color_mask(1, 1, 1, 1);
        gl.depth_mask(1);
        // 2. The mirrored objects where the water is, clipped at the water level.
        gl.stencil_func(GL_EQUAL, 1, 0xff);
        gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
        gl.push_matrix();
        gl.scalef(1.0, -1.0, 1.0);
        lamp(gl, light);
        if k == 1 {
            gl.clip_plane(GL_CLIP_PLANE0, &[0.0, 1.0, 0.0, 0.0]);
            gl.enable(GL_CLIP_PLANE0);
        }
        gl.front_face(GL_CW);
        water_objects(gl);
        gl.front_face(GL_CCW);
        gl.disable(GL_CLIP_PLANE0);
        gl.pop_matrix();
        gl.disable(GL_STENCIL_TEST);
        if k == 1 {
            snap_color(gl, "reflection_clipped", 256, 128);
        }
        // 3. The objects, then the water blended over (it hides their submerged parts).
        gl.lightfv(GL_LIGHT0, GL_POSITION, &light);
        water_objects(gl);
        gl.disable(GL_LIGHTING);
        gl.enable(GL_BLEND);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        gl.color_4f(0.15, 0.35, 0.55, 0.6);
        water(gl);
        gl.disable(GL_BLEND);
    }
    gl.disable(GL_CULL_FACE);
    gl.disable(GL_SCISSOR_TEST);
}

// ---------------------------------------------------------------------------------------------
// Particle systems.

fn ex_particles(gl: &mut dyn Gl) {
    clear_to(gl, [0.02, 0.02, 0.05]);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    let disc = soft_disc(16, 0.0);
    tex2d(gl, 16, 16, GL_RGBA, &disc);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_mask(0);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE);
    let mut rng = XorShift::new(7);
    let life = 1.6;
    let g = -2.0;
    gl.begin(GL_QUADS);
    for _ in 0..300 {
        let age = rng.range(0.0, life);
        let v = [
            rng.range(-0.35, 0.35),
            rng.range(1.9, 2.4),
            rng.range(-0.35, 0.35),
        ];
        let p = [
            v[0] * age,
            -0.9 + v[1] * age + 0.5 * g * age * age,
            -3.0 + v[2] * age,
        ];
        let f = age / life;
        gl.color_4f(1.0, 0.9 - 0.7 * f, 0.3 - 0.25 * f, 0.5 * (1.0 - f));
        let s = 0.05 + 0.05 * f;
        for (u, w) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            gl.tex_coord_2f(u, w);
            gl.vertex_3f(p[0] + (2.0 * u - 1.0) * s, p[1] + (2.0 * w - 1.0) * s, p[2]);
        }
    }
    gl.end();
    gl.depth_mask(1);
    gl.disable(GL_BLEND);
}

// ---------------------------------------------------------------------------------------------
// Environment-mapped bump mapping.

/// Ripples around two centres: the height and its gradient over the unit square.
fn ripples(u: f32, v: f32) -> (f32, f32, f32) {
    let mut h = (0.0, 0.0, 0.0);
    for (cu, cv, f) in [(0.3, 0.35, 26.0), (0.72, 0.7, 34.0)] {
        let (du, dv) = (u - cu, v - cv);
        let r = (du * du + dv * dv).sqrt().max(1e-4);
        let fall = (-r * 3.0).exp();
        h.0 += (f * r).sin() * fall;
        let d = (f * (f * r).cos() - 3.0 * (f * r).sin()) * fall;
        h.1 += d * du / r;
        h.2 += d * dv / r;
    }
    h
}

fn ex_env_bump(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.14]);
    gl.enable(GL_DEPTH_TEST);
    // The sphere map: texel (s, t) holds the environment in the direction it stands for.
    let map = paint(128, 128, 3, |s, t| {
        let (x, y) = (2.0 * s - 1.0, 2.0 * t - 1.0);
        let r2 = x * x + y * y;
        if r2 > 1.0 {
            return [0.0, 0.0, 0.0, 1.0];
        }
        let z = (1.0 - r2).sqrt();
        let c = environment([2.0 * z * x, 2.0 * z * y, 2.0 * z * z - 1.0]);
        [c[0], c[1], c[2], 1.0]
    });
    tex2d(gl, 128, 128, GL_RGB, &map);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "sphere_map", GL_TEXTURE_2D, 0, [128, 128, 1]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    for k in 0..2 {
        panel(gl, k * 128, 0, 128, 128);
        camera(gl, 40.0, 1.0, [0.0, 0.0, 2.9], [0.0, 0.0, 0.0]);
        gl.rotatef(-12.0, 1.0, 0.0, 0.0);
        gl.rotatef(18.0, 0.0, 1.0, 0.0);
        let bump = if k == 1 { 0.008 } else { 0.0 };
        // The plate: z = 0 over x, y in [-1, 1]; T = +x, B = +y, N = +z.
        grid(gl, 64, &|gl, u, v| {
            let (_, du, dv) = ripples(u, v);
            let n = norm([-bump * du, -bump * dv, 1.0]);
            gl.normal_3f(n[0], n[1], n[2]);
            gl.vertex_3f(2.0 * u - 1.0, 2.0 * v - 1.0, 0.0);
        });
    }
    gl.disable(GL_TEXTURE_GEN_S);
    gl.disable(GL_TEXTURE_GEN_T);
    gl.disable(GL_SCISSOR_TEST);
}
