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

mod drawing;
mod mapping;
use drawing::*;
use mapping::*;

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
