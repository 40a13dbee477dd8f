//! Teaching examples of effects: antialiased text from a texture atlas, billboard trees and
//! decals, fog over terrain, a planar reflection, DXT compression, an HSV colour lookup.

use super::*;

// ---------------------------------------------------------------------------------------------
// Anti-aliased text.

/// Stroke glyphs on a 4 x 6 grid.
pub(super) const GLYPHS: &[(char, &[[f32; 4]])] = &[
    ('A', &[[0., 0., 2., 6.], [2., 6., 4., 0.], [1., 3., 3., 3.]]),
    (
        'E',
        &[
            [4., 6., 0., 6.],
            [0., 6., 0., 0.],
            [0., 0., 4., 0.],
            [0., 3., 3., 3.],
        ],
    ),
    (
        'G',
        &[
            [4., 5., 3., 6.],
            [3., 6., 1., 6.],
            [1., 6., 0., 5.],
            [0., 5., 0., 1.],
            [0., 1., 1., 0.],
            [1., 0., 3., 0.],
            [3., 0., 4., 1.],
            [4., 1., 4., 3.],
            [4., 3., 2., 3.],
        ],
    ),
    ('H', &[[0., 0., 0., 6.], [4., 0., 4., 6.], [0., 3., 4., 3.]]),
    ('I', &[[2., 0., 2., 6.], [1., 6., 3., 6.], [1., 0., 3., 0.]]),
    ('L', &[[0., 6., 0., 0.], [0., 0., 4., 0.]]),
    ('N', &[[0., 0., 0., 6.], [0., 6., 4., 0.], [4., 0., 4., 6.]]),
    (
        'O',
        &[
            [1., 6., 3., 6.],
            [3., 6., 4., 5.],
            [4., 5., 4., 1.],
            [4., 1., 3., 0.],
            [3., 0., 1., 0.],
            [1., 0., 0., 1.],
            [0., 1., 0., 5.],
            [0., 5., 1., 6.],
        ],
    ),
    (
        'P',
        &[
            [0., 0., 0., 6.],
            [0., 6., 3., 6.],
            [3., 6., 4., 5.],
            [4., 5., 4., 4.],
            [4., 4., 3., 3.],
            [3., 3., 0., 3.],
        ],
    ),
    ('T', &[[0., 6., 4., 6.], [2., 6., 2., 0.]]),
    ('X', &[[0., 0., 4., 6.], [0., 6., 4., 0.]]),
];

pub(super) const CELL: usize = 32;
pub(super) const ATLAS_W: usize = 8 * CELL;
pub(super) const ATLAS_H: usize = 2 * CELL;

pub(super) fn seg_dist(p: [f32; 2], s: &[f32; 4]) -> f32 {
    let (ax, ay, bx, by) = (s[0], s[1], s[2], s[3]);
    let (dx, dy) = (bx - ax, by - ay);
    let t = (((p[0] - ax) * dx + (p[1] - ay) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
    ((p[0] - ax - t * dx).powi(2) + (p[1] - ay - t * dy).powi(2)).sqrt()
}

/// The font texture: each glyph's strokes rasterised with 4x4 supersampling into the alpha of a
/// 32x32 cell (coverage = alpha: the texture is the anti-aliased glyph).
pub(super) fn font_atlas() -> Vec<u8> {
    let mut a = vec![0u8; ATLAS_W * ATLAS_H];
    for (g, (_, strokes)) in GLYPHS.iter().enumerate() {
        let (cx, cy) = ((g % 8) * CELL, (g / 8) * CELL);
        for y in 0..CELL {
            for x in 0..CELL {
                let mut hits = 0;
                for sy in 0..4 {
                    for sx in 0..4 {
                        let px = x as f32 + (sx as f32 + 0.5) / 4.0;
                        let py = y as f32 + (sy as f32 + 0.5) / 4.0;
                        // Grid unit: 5 texels across, 4.3 up; 6-texel left and 3-texel bottom margins.
                        let p = [(px - 6.0) / 5.0, (py - 3.0) / 4.3];
                        let d = strokes
                            .iter()
                            .map(|s| seg_dist(p, s))
                            .fold(f32::MAX, f32::min);
                        if d * 4.6 < 1.9 {
                            hits += 1;
                        }
                    }
                }
                a[(cy + y) * ATLAS_W + cx + x] = (hits * 255 / 16) as u8;
            }
        }
    }
    a
}

/// Draws `text` with glyph cells `size` units high from (x, y), one textured quad per glyph.
pub(super) fn draw_text(gl: &mut dyn Gl, text: &str, x: f32, y: f32, size: f32) {
    gl.begin(GL_QUADS);
    let mut pen = x;
    for ch in text.chars() {
        if let Some(g) = GLYPHS.iter().position(|(c, _)| *c == ch) {
            let s0 = ((g % 8) * CELL) as f32 / ATLAS_W as f32;
            let t0 = ((g / 8) * CELL) as f32 / ATLAS_H as f32;
            let (ds, dt) = (CELL as f32 / ATLAS_W as f32, CELL as f32 / ATLAS_H as f32);
            for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
                gl.tex_coord_2f(s0 + u * ds, t0 + v * dt);
                gl.vertex_2f(pen + u * size, y + v * size);
            }
        }
        pen += size * 0.78;
    }
    gl.end();
}

/// Anti-aliased text as texture-mapped quads (Haeberli & Segal): the glyphs' coverage is in
/// an ALPHA texture; GL_MODULATE takes the colour from glColor and the alpha from the texture,
/// and glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) blends the edges. Filtering (with
/// mipmaps for the small sizes) keeps the text smooth at any size, angle and perspective.
pub(super) fn ex_text(gl: &mut dyn Gl) {
    clear_to(gl, [0.12, 0.16, 0.3]);
    let atlas = font_atlas();
    tex2d(gl, ATLAS_W as i32, ATLAS_H as i32, GL_ALPHA, &atlas);
    sampling(
        gl,
        GL_TEXTURE_2D,
        GL_LINEAR_MIPMAP_LINEAR,
        GL_LINEAR,
        GL_CLAMP_TO_EDGE,
    );
    snap_texture(
        gl,
        "font_texture",
        GL_TEXTURE_2D,
        0,
        [ATLAS_W as i32, ATLAS_H as i32, 1],
    );
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 256.0, 0.0, 128.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.color_3f(1.0, 0.95, 0.6);
    draw_text(gl, "TILEGL", 6.3, 82.4, 40.0);
    gl.color_3f(0.7, 0.9, 1.0);
    draw_text(gl, "ALPHA TEXT", 8.2, 60.3, 20.0);
    gl.color_3f(1.0, 1.0, 1.0);
    draw_text(gl, "OPENGL ALPHA TEXT", 8.6, 48.2, 10.0);
    gl.push_matrix();
    gl.translatef(150.0, 10.0, 0.0);
    gl.rotatef(25.0, 0.0, 0.0, 1.0);
    gl.color_3f(1.0, 0.6, 0.5);
    draw_text(gl, "OPENGL", 0.3, 0.2, 16.0);
    gl.pop_matrix();
    // Text on a plane receding in perspective.
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-1.0, 1.0, -0.5, 0.5, 1.0, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(-1.3, -0.45, -1.4);
    gl.rotatef(-70.0, 1.0, 0.0, 0.0);
    gl.scalef(0.02, 0.02, 0.02);
    gl.color_3f(0.6, 1.0, 0.6);
    draw_text(gl, "TEXT TEXT TEXT", 0.0, 0.0, 16.0);
}

// ---------------------------------------------------------------------------------------------
// Cut-outs and decals.

/// A tree: a trunk and a leafy crown with holes; alpha 0 elsewhere.
pub(super) fn tree_texture(size: usize) -> Vec<u8> {
    let mut rng = XorShift::new(7);
    let noise: Vec<f32> = (0..size * size).map(|_| rng.next_f32()).collect();
    let mut p = Vec::with_capacity(size * size * 4);
    for y in 0..size {
        for x in 0..size {
            let (u, v) = (
                (x as f32 + 0.5) / size as f32,
                (y as f32 + 0.5) / size as f32,
            );
            let n = noise[(y / 2) * size + x / 2];
            let crown = ((u - 0.5) / 0.42).powi(2) + ((v - 0.62) / 0.36).powi(2);
            let c = if crown < 1.0 && n > 0.25 {
                [(40.0 + 60.0 * n) as u8, (110.0 + 90.0 * n) as u8, 40, 255]
            } else if (u - 0.5).abs() < 0.06 && v < 0.4 {
                [100, 70, 40, 255]
            } else {
                [0, 0, 0, 0]
            };
            p.extend_from_slice(&c);
        }
    }
    p
}

/// Cut-out "cross trees": two perpendicular quads with an RGBA tree texture; the alpha test
/// (glAlphaFunc(GL_GREATER, 0.5)) discards the transparent texels, so the depth buffer sees only
/// the leaves and trunk and the quads need no sorting.
pub(super) fn ex_cross_tree(gl: &mut dyn Gl) {
    clear_to(gl, [0.6, 0.75, 0.95]);
    camera(gl, 50.0, 1.0, [0.4, 1.3, 3.6], [0.0, 0.7, 0.0]);
    gl.enable(GL_DEPTH_TEST);
    gl.color_3f(0.35, 0.55, 0.25);
    floor_quad(gl, [-3.0, 3.0], [-4.0, 2.0], &[]);
    let px = tree_texture(64);
    tex2d(gl, 64, 64, GL_RGBA, &px);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "tree_texture", GL_TEXTURE_2D, 0, [64, 64, 1]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_ALPHA_TEST);
    gl.alpha_func(GL_GREATER, 0.5);
    for (x, z, h, a) in [
        (-0.8, -0.6, 1.8, 10.0),
        (0.9, -1.4, 2.2, 35.0),
        (0.1, 0.6, 1.4, 70.0),
    ] {
        gl.push_matrix();
        gl.translatef(x, 0.0, z);
        gl.rotatef(a, 0.0, 1.0, 0.0);
        gl.begin(GL_QUADS);
        for plane in 0..2 {
            for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
                gl.tex_coord_2f(u, v);
                let w = (u - 0.5) * h;
                if plane == 0 {
                    gl.vertex_3f(w, v * h, 0.0);
                } else {
                    gl.vertex_3f(0.0, v * h, w);
                }
            }
        }
        gl.end();
        gl.pop_matrix();
    }
}

/// A decal with a clamped transparent border (Haeberli & Segal): unit 1 holds an RGBA target
/// in GL_DECAL mode (colour = previous x (1 - At) + texture x At) with CLAMP_TO_BORDER and a
/// border colour of alpha 0, so outside the decal's square the wall shows through. The texture
/// matrix places, scales and rotates the decal on the wall.
pub(super) fn ex_decal(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.1]);
    camera(gl, 45.0, 1.0, [0.8, 0.3, 3.0], [0.0, 0.0, 0.0]);
    gl.enable(GL_DEPTH_TEST);
    let b = bricks(64);
    tex2d(gl, 64, 64, GL_RGB, &b);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.active_texture(GL_TEXTURE1);
    let d = paint(32, 32, 4, |u, v| {
        let r = ((u - 0.5).powi(2) + (v - 0.5).powi(2)).sqrt() * 2.0;
        let ring = ((r * 4.0) as i32) % 2 == 0;
        let a = ((1.0 - r) * 12.0).clamp(0.0, 1.0);
        if ring {
            [0.95, 0.15, 0.1, a]
        } else {
            [1.0, 1.0, 0.95, a]
        }
    });
    tex2d(gl, 32, 32, GL_RGBA, &d);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_BORDER);
    gl.tex_parameterfv(
        GL_TEXTURE_2D,
        GL_TEXTURE_BORDER_COLOR,
        &[0.0, 0.0, 0.0, 0.0],
    );
    snap_texture(gl, "decal_texture", GL_TEXTURE_2D, 0, [32, 32, 1]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL as i32);
    if unit_on(1) {
        gl.enable(GL_TEXTURE_2D);
    }
    gl.matrix_mode(GL_TEXTURE);
    gl.translatef(0.5, 0.5, 0.0);
    gl.rotatef(20.0, 0.0, 0.0, 1.0);
    gl.scalef(2.4, 3.0, 1.0);
    gl.translatef(-0.62, -0.45, 0.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.active_texture(GL_TEXTURE0);
    gl.color_3f(0.95, 0.95, 0.9);
    gl.begin(GL_QUADS);
    for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
        gl.multi_tex_coord_2f(GL_TEXTURE0, 3.0 * u, 2.4 * v);
        gl.multi_tex_coord_2f(GL_TEXTURE1, u, v);
        gl.vertex_3f(-1.5 + 3.0 * u, -1.2 + 2.4 * v, 0.0);
    }
    gl.end();
}

// ---------------------------------------------------------------------------------------------
// Fog.

pub(super) const FOG: [f32; 4] = [0.7, 0.75, 0.82, 1.0];

pub(super) fn fog_panels(gl: &mut dyn Gl, fogged: bool) {
    for (i, mode) in [GL_LINEAR, GL_EXP, GL_EXP2].into_iter().enumerate() {
        example_support::viewport(gl, 128 * i as i32, 0, 128, 128);
        camera(gl, 50.0, 1.0, [0.0, 1.6, 1.8], [0.0, 0.0, -3.0]);
        if fogged {
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, mode as i32);
            gl.fogfv(GL_FOG_COLOR, &FOG);
            gl.fogf(GL_FOG_START, 1.5);
            gl.fogf(GL_FOG_END, 9.0);
            gl.fogf(GL_FOG_DENSITY, if mode == GL_EXP { 0.3 } else { 0.22 });
        }
        terrain(gl, 32, -10.0);
    }
}

/// Fog over a terrain: GL_LINEAR ((end - z) / (end - start)), GL_EXP (e^(-density z)) and
/// GL_EXP2 (e^(-(density z)^2)) side by side; the fragment colour is blended towards the fog
/// colour by that factor of the eye distance. The clear colour is the fog colour.
pub(super) fn ex_fog_terrain(gl: &mut dyn Gl) {
    clear_to(gl, [FOG[0], FOG[1], FOG[2]]);
    gl.enable(GL_DEPTH_TEST);
    fog_panels(gl, false);
    snap_color(gl, "without_fog", 384, 128);
    example_support::viewport(gl, 0, 0, 384, 128);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    fog_panels(gl, true);
}

// ---------------------------------------------------------------------------------------------
// Planar reflection with the stencil buffer.

pub(super) fn mirror_floor(gl: &mut dyn Gl) {
    gl.begin(GL_QUADS);
    for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
        gl.tex_coord_2f(4.0 * u, 4.0 * v);
        gl.vertex_3f(-1.5 + 3.0 * u, 0.0, 1.5 - 3.0 * v);
    }
    gl.end();
}

pub(super) fn reflected_object(gl: &mut dyn Gl) {
    material(gl, [0.9, 0.4, 0.2, 1.0], 0.6, 30.0);
    gl.push_matrix();
    gl.translatef(0.0, 0.75, 0.0);
    gl.rotatef(50.0, 1.0, 0.0, 0.0);
    gl.rotatef(20.0, 0.0, 0.0, 1.0);
    torus(gl, 0.5, 0.2, 32, 14);
    gl.pop_matrix();
}

/// Planar reflection (McReynolds & Blythe; Kilgard): the mirror's pixels are marked in the
/// stencil buffer; the object is drawn mirrored (glScalef(1, -1, 1), which flips the winding, so
/// glFrontFace(GL_CW)) only where the stencil is 1; the floor is blended over it; then the
/// object is drawn normally. The light is re-specified under the mirrored modelview.
pub(super) fn ex_planar_reflection(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.15]);
    camera(gl, 45.0, 1.0, [0.0, 1.7, 3.4], [0.0, 0.3, 0.0]);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_CULL_FACE);
    let light = [1.0, 2.5, 1.5, 1.0];
    // 1. The mirror into the stencil buffer only.
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_ALWAYS, 1, 0xff);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
    gl.color_mask(0, 0, 0, 0);
    gl.depth_mask(0);
    mirror_floor(gl);
    gl.color_mask(1, 1, 1, 1);
    gl.depth_mask(1);
    snap_stencil(gl, "stencil_mirror", 128, 128);
    // 2. The reflection, where the stencil is 1.
    gl.stencil_func(GL_EQUAL, 1, 0xff);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
    gl.push_matrix();
    gl.scalef(1.0, -1.0, 1.0);
    lamp(gl, light);
    gl.front_face(GL_CW);
    reflected_object(gl);
    gl.front_face(GL_CCW);
    gl.pop_matrix();
    gl.disable(GL_STENCIL_TEST);
    snap_color(gl, "reflection", 128, 128);
    // 3. The floor, translucent, over the reflection.
    gl.lightfv(GL_LIGHT0, GL_POSITION, &light);
    gl.disable(GL_LIGHTING);
    let checker = paint(8, 8, 3, |u, v| {
        if ((u * 8.0) as i32 + (v * 8.0) as i32) % 2 == 0 {
            [0.8, 0.8, 0.85, 1.0]
        } else {
            [0.3, 0.35, 0.5, 1.0]
        }
    });
    tex2d(gl, 8, 8, GL_RGB, &checker);
    sampling(gl, GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.color_4f(1.0, 1.0, 1.0, 0.7);
    mirror_floor(gl);
    gl.disable(GL_BLEND);
    gl.disable(GL_TEXTURE_2D);
    snap_color(gl, "floor_blended", 128, 128);
    // 4. The object itself.
    gl.enable(GL_LIGHTING);
    reflected_object(gl);
}

// ---------------------------------------------------------------------------------------------
// S3TC (DXT) compression.

/// A 64x64 RGBA picture with smooth gradients, hard edges and a soft alpha disc: what block
/// compression keeps (gradients within a block) and loses (several colours in one block).
pub(super) fn dxt_source() -> Vec<u8> {
    paint(64, 64, 4, |u, v| {
        let ring = (((u - 0.5).powi(2) + (v - 0.5).powi(2)).sqrt() * 9.0).floor() as i32;
        let stripe = ((u * 8.0).floor() as i32 + (v * 3.0).floor() as i32) % 3;
        let base = [u, 0.3 + 0.5 * v, 1.0 - u * v, 1.0];
        let mut c = match (ring % 2, stripe) {
            (0, 0) => [0.95, 0.9, 0.2, 1.0],
            (0, _) => base,
            _ => [base[2], base[0], base[1], 1.0],
        };
        let d = ((u - 0.5).powi(2) + (v - 0.5).powi(2)).sqrt();
        c[3] = (1.2 - 2.0 * d).clamp(0.0, 1.0);
        c
    })
}

/// RGB565 of a colour, and back.
pub(super) fn to_565(c: [u8; 3]) -> u16 {
    ((c[0] as u16 >> 3) << 11) | ((c[1] as u16 >> 2) << 5) | (c[2] as u16 >> 3)
}

pub(super) fn from_565(v: u16) -> [i32; 3] {
    let (r, g, b) = ((v >> 11) & 31, (v >> 5) & 63, v & 31);
    [
        (r as i32 * 255 + 15) / 31,
        (g as i32 * 255 + 31) / 63,
        (b as i32 * 255 + 15) / 31,
    ]
}

/// A simple DXT colour block (EXT_texture_compression_s3tc): the two endpoints are the
/// block's darkest and brightest texels, each texel takes the nearest of the four palette
/// colours (c0 > c1: the 1/3 and 2/3 blends). The same bytes go to every implementation, so
/// the pictures compare the decoders, not the encoders (which the extension leaves open).
pub(super) fn dxt_color_block(texels: &[[u8; 4]; 16]) -> [u8; 8] {
    let luma = |c: &[u8; 4]| c[0] as u32 * 3 + c[1] as u32 * 6 + c[2] as u32;
    let lo = texels
        .iter()
        .min_by_key(|c| luma(c))
        .copied()
        .unwrap_or([0; 4]);
    let hi = texels
        .iter()
        .max_by_key(|c| luma(c))
        .copied()
        .unwrap_or([0; 4]);
    let (mut c0, mut c1) = (to_565([hi[0], hi[1], hi[2]]), to_565([lo[0], lo[1], lo[2]]));
    if c0 < c1 {
        std::mem::swap(&mut c0, &mut c1);
    }
    if c0 == c1 {
        // Four-colour mode needs c0 > c1; with one colour every index 0 is exact.
        c1 = c0.saturating_sub(1);
    }
    let (p0, p1) = (from_565(c0), from_565(c1));
    let palette = [
        p0,
        p1,
        [0, 1, 2].map(|k| (2 * p0[k] + p1[k]) / 3),
        [0, 1, 2].map(|k| (p0[k] + 2 * p1[k]) / 3),
    ];
    let mut bits = 0u32;
    for (i, t) in texels.iter().enumerate() {
        let dist = |p: &[i32; 3]| (0..3).map(|k| (p[k] - t[k] as i32).pow(2)).sum::<i32>();
        let best = (0..4).min_by_key(|&j| dist(&palette[j])).unwrap_or(0) as u32;
        bits |= best << (2 * i);
    }
    let mut out = [0u8; 8];
    out[..2].copy_from_slice(&c0.to_le_bytes());
    out[2..4].copy_from_slice(&c1.to_le_bytes());
    out[4..].copy_from_slice(&bits.to_le_bytes());
    out
}

/// A DXT5 alpha block: endpoints max and min alpha (a0 > a1: six interpolated steps), each
/// texel the nearest of the eight.
pub(super) fn dxt5_alpha_block(texels: &[[u8; 4]; 16]) -> [u8; 8] {
    let a0 = texels.iter().map(|t| t[3]).max().unwrap_or(0);
    let a1 = texels.iter().map(|t| t[3]).min().unwrap_or(0);
    let (a0, a1) = if a0 == a1 {
        (a0.max(1), a0.max(1) - 1)
    } else {
        (a0, a1)
    };
    let level = |j: u64| -> i32 {
        let (a0, a1) = (a0 as i32, a1 as i32);
        match j {
            0 => a0,
            1 => a1,
            j => ((8 - j as i32) * a0 + (j as i32 - 1) * a1) / 7,
        }
    };
    let mut bits = 0u64;
    for (i, t) in texels.iter().enumerate() {
        let best = (0..8u64)
            .min_by_key(|&j| (level(j) - t[3] as i32).abs())
            .unwrap_or(0);
        bits |= best << (3 * i);
    }
    let mut out = [0u8; 8];
    out[0] = a0;
    out[1] = a1;
    out[2..].copy_from_slice(&bits.to_le_bytes()[..6]);
    out
}

/// The blocks of a 64x64 RGBA picture: DXT1 (8 bytes a block) or DXT5 (16).
pub(super) fn dxt_blocks(px: &[u8], dxt5: bool) -> Vec<u8> {
    let mut out = Vec::new();
    for by in 0..16 {
        for bx in 0..16 {
            let mut texels = [[0u8; 4]; 16];
            for (i, t) in texels.iter_mut().enumerate() {
                let (x, y) = (bx * 4 + i % 4, by * 4 + i / 4);
                let k = (y * 64 + x) * 4;
                t.copy_from_slice(&px[k..k + 4]);
            }
            if dxt5 {
                out.extend_from_slice(&dxt5_alpha_block(&texels));
            }
            out.extend_from_slice(&dxt_color_block(&texels));
        }
    }
    out
}

/// The original texture, its DXT1 and its DXT5 compression, magnified side by side over a
/// checker (alpha blended) so the block artefacts and DXT5's smooth alpha show.
pub(super) fn ex_dxt_compression(gl: &mut dyn Gl) {
    clear_to(gl, [0.2, 0.2, 0.25]);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 384.0, 0.0, 128.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    // A checker behind, to show alpha.
    for j in 0..16 {
        for i in 0..48 {
            let g = if (i + j) % 2 == 0 { 0.35 } else { 0.5 };
            gl.color_3f(g, g, g);
            gl.rectf(
                i as f32 * 8.0,
                j as f32 * 8.0,
                i as f32 * 8.0 + 8.0,
                j as f32 * 8.0 + 8.0,
            );
        }
    }
    let px = dxt_source();
    let mut names = [0u32; 3];
    gl.gen_textures(3, &mut names);
    gl.bind_texture(GL_TEXTURE_2D, names[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        64,
        64,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&px),
    );
    let dxt1 = dxt_blocks(&px, false);
    gl.bind_texture(GL_TEXTURE_2D, names[1]);
    gl.compressed_tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
        64,
        64,
        0,
        dxt1.len() as i32,
        Some(&dxt1),
    );
    let dxt5 = dxt_blocks(&px, true);
    gl.bind_texture(GL_TEXTURE_2D, names[2]);
    gl.compressed_tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_COMPRESSED_RGBA_S3TC_DXT5_EXT,
        64,
        64,
        0,
        dxt5.len() as i32,
        Some(&dxt5),
    );
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    for (k, name) in names.into_iter().enumerate() {
        gl.bind_texture(GL_TEXTURE_2D, name);
        sampling(gl, GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE);
        snap_texture(
            gl,
            ["original", "dxt1", "dxt5"][k],
            GL_TEXTURE_2D,
            0,
            [64, 64, 1],
        );
        // Off-integer corners and scale: no pixel centre falls exactly on a texel edge
        // (NEAREST would then be a tie implementations break differently).
        let x0 = 128.0 * k as f32 + 4.37;
        gl.begin(GL_QUADS);
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            gl.tex_coord_2f(u, v);
            gl.vertex_2f(x0 + 117.3 * u, 4.41 + 117.3 * v);
        }
        gl.end();
    }
    gl.disable(GL_BLEND);
}

// ---------------------------------------------------------------------------------------------
// HSV colour interpolation through a 3D lookup texture.

/// HSV (each in 0..1, hue wrapping) to RGB.
pub(super) fn hsv_to_rgb(h: f32, s: f32, v: f32) -> [f32; 3] {
    let h6 = h.rem_euclid(1.0) * 6.0;
    let f = |n: f32| {
        let k = (n + h6) % 6.0;
        v - v * s * k.min(4.0 - k).clamp(0.0, 1.0)
    };
    [f(5.0), f(3.0), f(1.0)]
}

/// Gouraud shading interpolates RGB; here the rasterizer interpolates (hue, saturation, value)
/// as texture coordinates instead and a 24 x 8 x 8 3D texture turns them into RGB. HSV to RGB
/// is piecewise multilinear with hue breakpoints every 1/6, so with texel centres on hue
/// multiples of 1/24 (the texture matrix maps values onto texel centres) trilinear filtering
/// reproduces it exactly; `GL_REPEAT` on the hue axis makes hue wrap, so 1.08 -> 0.8 goes the
/// short way through red. Top: three pairs of bars, RGB-interpolated above HSV-interpolated;
/// bottom: a triangle with red, green and blue corners both ways.
pub(super) fn ex_hsv_lookup(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.12]);
    const H: usize = 24;
    const S: usize = 8;
    const V: usize = 8;
    let mut px = Vec::with_capacity(H * S * V * 3);
    for k in 0..V {
        for j in 0..S {
            for i in 0..H {
                let c = hsv_to_rgb(
                    i as f32 / H as f32,
                    j as f32 / (S - 1) as f32,
                    k as f32 / (V - 1) as f32,
                );
                px.extend(c.iter().map(|&x| to_u8(x)));
            }
        }
    }
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_3D, name[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_3d(
        GL_TEXTURE_3D,
        0,
        GL_RGB as i32,
        H as i32,
        S as i32,
        V as i32,
        0,
        GL_RGB,
        GL_UNSIGNED_BYTE,
        Some(&px),
    );
    sampling(gl, GL_TEXTURE_3D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    gl.tex_parameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_REPEAT as i32);
    snap_texture(
        gl,
        "hsv_lut",
        GL_TEXTURE_3D,
        0,
        [H as i32, S as i32, V as i32],
    );
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    // Values to texel centres: hue h -> h + 1/48 (texel i's centre is (i + 1/2) / 24),
    // saturation and value x -> (7 x + 1/2) / 8.
    gl.matrix_mode(GL_TEXTURE);
    gl.load_identity();
    gl.translatef(0.5 / H as f32, 0.5 / S as f32, 0.5 / V as f32);
    gl.scalef(1.0, (S - 1) as f32 / S as f32, (V - 1) as f32 / V as f32);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 128.0, 0.0, 128.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();

    // (hue, saturation, value) at the left and right ends of each pair of bars.
    let pairs: [([f32; 3], [f32; 3]); 3] = [
        ([1.0, 1.0, 1.0], [2.0 / 3.0, 1.0, 1.0]), // red -> blue through magenta
        ([1.0 / 6.0, 1.0, 1.0], [2.0 / 3.0, 1.0, 1.0]), // yellow -> blue through green
        ([1.08, 1.0, 1.0], [0.8, 0.4, 0.6]),      // orange -> dull violet through red
    ];
    let bar = |gl: &mut dyn Gl, y: f32, ends: ([f32; 3], [f32; 3]), hsv: bool| {
        gl.begin(GL_QUADS);
        for (x, dy, e) in [
            (4.0, 0.0, ends.0),
            (124.0, 0.0, ends.1),
            (124.0, 11.0, ends.1),
            (4.0, 11.0, ends.0),
        ] {
            if hsv {
                gl.tex_coord_3f(e[0], e[1], e[2]);
            } else {
                let c = hsv_to_rgb(e[0], e[1], e[2]);
                gl.color_3f(c[0], c[1], c[2]);
            }
            gl.vertex_2f(x, y + dy);
        }
        gl.end();
    };
    for (k, &ends) in pairs.iter().enumerate() {
        bar(gl, 114.0 - 28.0 * k as f32, ends, false);
    }
    let corners = [(4.3, 4.4), (59.7, 4.4), (32.2, 40.6)];
    let hues = [0.0, 1.0 / 3.0, 2.0 / 3.0];
    gl.begin(GL_TRIANGLES);
    for (&(x, y), &h) in corners.iter().zip(&hues) {
        let c = hsv_to_rgb(h, 1.0, 1.0);
        gl.color_3f(c[0], c[1], c[2]);
        gl.vertex_2f(x, y);
    }
    gl.end();
    snap_color(gl, "rgb_interpolation", 128, 128);
    gl.enable(GL_TEXTURE_3D);
    for (k, &ends) in pairs.iter().enumerate() {
        bar(gl, 101.0 - 28.0 * k as f32, ends, true);
    }
    gl.begin(GL_TRIANGLES);
    for (&(x, y), &h) in corners.iter().zip(&hues) {
        gl.tex_coord_3f(h, 1.0, 1.0);
        gl.vertex_2f(x + 64.0, y);
    }
    gl.end();
}
