//! Teaching examples of texturing: mipmapping, wrap modes, light maps, gloss maps, sphere
//! and cube maps (also rendered each frame), emboss and DOT3 bump mapping.

use super::*;

// ---------------------------------------------------------------------------------------------
// Mipmapping.

/// A black-and-white checkerboard, 4 texels a square, with a thin red line every 16 texels.
pub(super) fn fine_checker(size: usize) -> Vec<u8> {
    paint(size, size, 3, |u, v| {
        let (x, y) = ((u * size as f32) as usize, (v * size as f32) as usize);
        if x % 16 == 0 || y % 16 == 0 {
            [0.9, 0.1, 0.1, 1.0]
        } else if (x / 4 + y / 4) % 2 == 0 {
            [0.95, 0.95, 0.95, 1.0]
        } else {
            [0.05, 0.05, 0.1, 1.0]
        }
    })
}

pub(super) fn receding_plane(gl: &mut dyn Gl) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 60.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.color_3f(1.0, 1.0, 1.0);
    gl.begin(GL_QUADS);
    for (s, t, x, z) in [
        (0.0, 0.0, -3.0, -1.3),
        (3.0, 0.0, 3.0, -1.3),
        (3.0, 30.0, 3.0, -41.3),
        (0.0, 30.0, -3.0, -41.3),
    ] {
        gl.tex_coord_2f(s, t);
        gl.vertex_3f(x, -1.0, z);
    }
    gl.end();
}

/// Four filters on the same receding plane (2x2 viewports): NEAREST, LINEAR,
/// NEAREST_MIPMAP_NEAREST, LINEAR_MIPMAP_LINEAR.
pub(super) fn ex_mipmap_filters(gl: &mut dyn Gl) {
    clear_to(gl, [0.3, 0.4, 0.6]);
    let px = fine_checker(64);
    tex2d(gl, 64, 64, GL_RGB, &px);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    snap_texture(gl, "texture_level0", GL_TEXTURE_2D, 0, [64, 64, 1]);
    snap_texture(gl, "texture_level2", GL_TEXTURE_2D, 2, [16, 16, 1]);
    let filters = [
        (GL_NEAREST, GL_NEAREST),
        (GL_LINEAR, GL_LINEAR),
        (GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST),
        (GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR),
    ];
    for (i, (min, mag)) in filters.into_iter().enumerate() {
        example_support::viewport(gl, (i % 2) as i32 * 128, (1 - i / 2) as i32 * 128, 128, 128);
        sampling(gl, GL_TEXTURE_2D, min, mag, GL_REPEAT);
        receding_plane(gl);
    }
}

/// Magnification and anisotropy (2x2 viewports): an 8x8 texture stretched over a close quad
/// under NEAREST (top left) and LINEAR (top right); the receding plane under
/// LINEAR_MIPMAP_LINEAR (bottom left) and the same with 16x anisotropic filtering
/// (EXT_texture_filter_anisotropic, bottom right).
pub(super) fn ex_magnify_anisotropic(gl: &mut dyn Gl) {
    clear_to(gl, [0.3, 0.4, 0.6]);
    let small = paint(8, 8, 3, |u, v| {
        let (x, y) = ((u * 8.0) as i32, (v * 8.0) as i32);
        let k = ((x + y) % 2) as f32;
        [
            0.2 + 0.7 * k,
            0.3 + 0.08 * x as f32,
            0.9 - 0.1 * y as f32,
            1.0,
        ]
    });
    tex2d(gl, 8, 8, GL_RGB, &small);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    for (i, filter) in [GL_NEAREST, GL_LINEAR].into_iter().enumerate() {
        example_support::viewport(gl, i as i32 * 128, 128, 128, 128);
        sampling(gl, GL_TEXTURE_2D, filter, filter, GL_REPEAT);
        gl.matrix_mode(GL_PROJECTION);
        gl.load_identity();
        gl.ortho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.load_identity();
        gl.begin(GL_QUADS);
        // Slightly off the texel grid, so that both filters show their character.
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            gl.tex_coord_2f(0.03 + u * 0.97, 0.05 + v * 0.93);
            gl.vertex_2f(u, v);
        }
        gl.end();
    }
    for (i, aniso) in [1.0f32, 16.0].into_iter().enumerate() {
        example_support::viewport(gl, i as i32 * 128, 0, 128, 128);
        receding_checker(gl, aniso);
    }
}

/// The receding checkerboard plane of the mipmapping scenes, trilinear with maximum
/// anisotropy `aniso`, drawn into the current viewport (the anisotropic panel of
/// `ex_magnify_anisotropic`; also rendered supersampled by the test that checks it).
pub fn receding_checker(gl: &mut dyn Gl, aniso: f32) {
    let px = fine_checker(64);
    tex2d(gl, 64, 64, GL_RGB, &px);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    sampling(
        gl,
        GL_TEXTURE_2D,
        GL_LINEAR_MIPMAP_LINEAR,
        GL_LINEAR,
        GL_REPEAT,
    );
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, aniso);
    receding_plane(gl);
}

/// Each mipmap level a different solid colour: the picture shows which level (and, with
/// LINEAR_MIPMAP_LINEAR, which blend of two levels) every pixel samples.
pub(super) fn ex_mipmap_levels(gl: &mut dyn Gl) {
    clear_to(gl, [0.3, 0.4, 0.6]);
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_2D, name[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    const LEVEL_COLOURS: [[f32; 3]; 7] = [
        [1.0, 0.2, 0.2],
        [1.0, 0.6, 0.1],
        [1.0, 1.0, 0.2],
        [0.2, 0.9, 0.2],
        [0.2, 0.8, 1.0],
        [0.3, 0.3, 1.0],
        [0.8, 0.3, 1.0],
    ];
    for (level, c) in LEVEL_COLOURS.iter().enumerate() {
        let s = 64usize >> level;
        let px = paint(s, s, 3, |u, v| {
            // A faint checker on top of the level colour so each level still shows texels.
            let k = if ((u * 8.0) as i32 + (v * 8.0) as i32) % 2 == 0 {
                1.0
            } else {
                0.8
            };
            [c[0] * k, c[1] * k, c[2] * k, 1.0]
        });
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            level as i32,
            GL_RGB as i32,
            s as i32,
            s as i32,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            Some(&px),
        );
    }
    sampling(
        gl,
        GL_TEXTURE_2D,
        GL_LINEAR_MIPMAP_LINEAR,
        GL_LINEAR,
        GL_REPEAT,
    );
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    receding_plane(gl);
}

// ---------------------------------------------------------------------------------------------
// Wrap modes.

/// The same quad with texture coordinates -0.75..1.75 under REPEAT, CLAMP, CLAMP_TO_EDGE,
/// CLAMP_TO_BORDER and MIRRORED_REPEAT (left to right); a 4x4 texture with a green border
/// colour and LINEAR filtering, which is where CLAMP and CLAMP_TO_EDGE differ.
pub(super) fn ex_wrap_modes(gl: &mut dyn Gl) {
    clear_to(gl, [0.15, 0.15, 0.2]);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 320.0, 0.0, 64.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    let px = paint(4, 4, 4, |u, v| {
        let (x, y) = ((u * 4.0) as usize, (v * 4.0) as usize);
        match (x, y) {
            (0, _) | (_, 0) => [1.0, 0.85, 0.2, 1.0],
            _ if (x + y) % 2 == 0 => [0.9, 0.2, 0.3, 1.0],
            _ => [0.2, 0.3, 0.9, 1.0],
        }
    });
    tex2d(gl, 4, 4, GL_RGBA, &px);
    gl.tex_parameterfv(
        GL_TEXTURE_2D,
        GL_TEXTURE_BORDER_COLOR,
        &[0.1, 0.7, 0.2, 1.0],
    );
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    let modes = [
        GL_REPEAT,
        GL_CLAMP,
        GL_CLAMP_TO_EDGE,
        GL_CLAMP_TO_BORDER,
        GL_MIRRORED_REPEAT,
    ];
    for (i, mode) in modes.into_iter().enumerate() {
        sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, mode);
        let x0 = 64.0 * i as f32 + 4.0;
        gl.begin(GL_QUADS);
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            gl.tex_coord_2f(-0.75 + 2.5 * u, -0.75 + 2.5 * v);
            gl.vertex_2f(x0 + 56.0 * u, 4.0 + 56.0 * v);
        }
        gl.end();
    }
}

// ---------------------------------------------------------------------------------------------
// Light maps.

/// A light map: three coloured pools of light on a dim ambient level.
pub(super) fn light_map(size: usize) -> Vec<u8> {
    paint(size, size, 3, |u, v| {
        let spots = [
            (0.3, 0.3, [1.0, 0.8, 0.5]),
            (0.72, 0.6, [0.5, 0.7, 1.0]),
            (0.35, 0.8, [0.8, 1.0, 0.6]),
        ];
        let mut c = [0.18f32; 3];
        for (x, y, col) in spots {
            let d2 = (u - x) * (u - x) + (v - y) * (v - y);
            let k = (-d2 / 0.02).exp();
            for i in 0..3 {
                c[i] += col[i] * k;
            }
        }
        [c[0], c[1], c[2], 1.0]
    })
}

pub(super) fn lightmap_camera(gl: &mut dyn Gl) {
    clear_to(gl, [0.05, 0.05, 0.08]);
    camera(gl, 50.0, 1.0, [0.0, 2.4, 2.2], [0.0, 0.0, -0.8]);
    gl.enable(GL_DEPTH_TEST);
}

pub(super) const LM_X: [f32; 2] = [-2.0, 2.0];
pub(super) const LM_Z: [f32; 2] = [-3.5, 1.0];

/// Light map by multitexture: unit 0 the bricks (repeated 4x), unit 1 the light map (once over
/// the floor), both MODULATE: colour = bricks x light.
pub(super) fn ex_lightmap_multitexture(gl: &mut dyn Gl) {
    lightmap_camera(gl);
    let b = bricks(64);
    tex2d(gl, 64, 64, GL_RGB, &b);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    snap_texture(gl, "base_texture", GL_TEXTURE_2D, 0, [64, 64, 1]);
    gl.active_texture(GL_TEXTURE1);
    let l = light_map(32);
    tex2d(gl, 32, 32, GL_RGB, &l);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    if unit_on(1) {
        gl.enable(GL_TEXTURE_2D);
    }
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    snap_texture(gl, "light_map", GL_TEXTURE_2D, 0, [32, 32, 1]);
    gl.active_texture(GL_TEXTURE0);
    gl.color_3f(1.0, 1.0, 1.0);
    floor_quad(
        gl,
        LM_X,
        LM_Z,
        &[(GL_TEXTURE0, 4.0, 4.0), (GL_TEXTURE1, 1.0, 1.0)],
    );
}

/// The same picture in two passes on one unit: the bricks, then the light map multiplied into
/// the framebuffer with glBlendFunc(GL_DST_COLOR, GL_ZERO) (dst = src x dst) on the same
/// geometry (depth test GL_LEQUAL: the second pass's fragments have the same depths).
pub(super) fn ex_lightmap_multipass(gl: &mut dyn Gl) {
    lightmap_camera(gl);
    let b = bricks(64);
    let bricks_tex = tex2d(gl, 64, 64, GL_RGB, &b);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    let l = light_map(32);
    let light_tex = tex2d(gl, 32, 32, GL_RGB, &l);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.bind_texture(GL_TEXTURE_2D, bricks_tex);
    floor_quad(gl, LM_X, LM_Z, &[(GL_TEXTURE0, 4.0, 4.0)]);
    snap_color(gl, "pass1_bricks", 128, 128);
    gl.bind_texture(GL_TEXTURE_2D, light_tex);
    gl.depth_func(GL_LEQUAL);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_DST_COLOR, GL_ZERO);
    floor_quad(gl, LM_X, LM_Z, &[(GL_TEXTURE0, 1.0, 1.0)]);
}

// ---------------------------------------------------------------------------------------------
// Gloss map.

/// Tiles: polished metal (gloss 1) and rough stone (gloss 0.08).
pub(super) fn metal_tile(u: f32, v: f32) -> bool {
    ((u * 4.0) as i32 + (v * 4.0) as i32) % 2 == 0
}

pub(super) fn gloss_plane(gl: &mut dyn Gl) {
    grid(gl, 24, &|gl, u, v| {
        gl.normal_3f(0.0, 0.0, 1.0);
        gl.tex_coord_2f(u, v);
        gl.vertex_3f(-1.5 + 3.0 * u, -1.5 + 3.0 * v, 0.0);
    });
}

/// Gloss map in two passes: pass 1 the diffuse-lit base texture; pass 2 only the specular term
/// of the lighting (material ambient and diffuse black), modulated by the gloss map and added
/// with glBlendFunc(GL_ONE, GL_ONE): highlights appear only on the shiny tiles.
pub(super) fn ex_gloss_map(gl: &mut dyn Gl) {
    clear_to(gl, [0.08, 0.08, 0.1]);
    camera(gl, 45.0, 1.0, [0.0, -2.6, 2.8], [0.0, 0.0, 0.0]);
    gl.enable(GL_DEPTH_TEST);
    lamp(gl, [0.3, 0.2, 1.0, 1.0]);
    gl.light_modeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    let base = paint(64, 64, 3, |u, v| {
        if metal_tile(u, v) {
            [0.55, 0.6, 0.7, 1.0]
        } else {
            let n = ((u * 97.0).sin() * (v * 113.0).sin()).abs();
            [0.55 + 0.2 * n, 0.4 + 0.1 * n, 0.25, 1.0]
        }
    });
    let gloss = paint(64, 64, 1, |u, v| {
        let g = if metal_tile(u, v) { 1.0 } else { 0.08 };
        [g, g, g, 1.0]
    });
    let base_tex = tex2d(gl, 64, 64, GL_RGB, &base);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    let gloss_tex = tex2d(gl, 64, 64, GL_LUMINANCE, &gloss);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    snap_texture(gl, "gloss_map", GL_TEXTURE_2D, 0, [64, 64, 1]);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    // Pass 1: ambient + diffuse, no specular.
    gl.bind_texture(GL_TEXTURE_2D, base_tex);
    material(gl, [1.0, 1.0, 1.0, 1.0], 0.0, 1.0);
    gloss_plane(gl);
    snap_color(gl, "pass1_diffuse", 128, 128);
    // Pass 2: specular only, times the gloss map, added.
    gl.bind_texture(GL_TEXTURE_2D, gloss_tex);
    gl.light_modelfv(GL_LIGHT_MODEL_AMBIENT, &[0.0, 0.0, 0.0, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_AMBIENT, &[0.0, 0.0, 0.0, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.0, 0.0, 0.0, 1.0]);
    gl.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, &[1.0, 1.0, 0.9, 1.0]);
    gl.materialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0);
    gl.depth_func(GL_LEQUAL);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_ONE, GL_ONE);
    gloss_plane(gl);
}

// ---------------------------------------------------------------------------------------------
// Environment maps.

/// The environment seen in direction `d`: a sky gradient with a sun above the horizon, a
/// checkered ground below, and a red marker on +x and a blue one on -z to show orientation.
pub(super) fn environment(d: V3) -> [f32; 4] {
    let d = norm(d);
    if dot(d, norm([1.0, 0.15, 0.0])) > 0.985 {
        return [0.9, 0.1, 0.1, 1.0];
    }
    if dot(d, norm([0.0, 0.15, -1.0])) > 0.985 {
        return [0.1, 0.2, 0.95, 1.0];
    }
    if d[1] >= 0.0 {
        if dot(d, norm([-0.5, 0.6, -0.6])) > 0.97 {
            return [1.0, 0.95, 0.7, 1.0];
        }
        let k = d[1].sqrt();
        [0.85 - 0.6 * k, 0.9 - 0.45 * k, 1.0 - 0.1 * k, 1.0]
    } else {
        let (x, z) = (d[0] / -d[1], d[2] / -d[1]);
        let c = if (x.floor() as i32 + z.floor() as i32) % 2 == 0 {
            [0.45, 0.3, 0.2]
        } else {
            [0.75, 0.6, 0.4]
        };
        let f = (-d[1] * 4.0).min(1.0);
        [
            c[0] * f + 0.85 * (1.0 - f),
            c[1] * f + 0.9 * (1.0 - f),
            c[2] * f + 1.0 * (1.0 - f),
            1.0,
        ]
    }
}

pub(super) fn env_object(gl: &mut dyn Gl) {
    clear_to(gl, [0.2, 0.2, 0.25]);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    perspective(gl, 40.0, 1.0, 1.0, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.enable(GL_DEPTH_TEST);
    gl.translatef(0.0, 0.0, -4.0);
    gl.rotatef(55.0, 1.0, 0.0, 0.0);
    gl.rotatef(20.0, 0.0, 0.0, 1.0);
}

/// Sphere mapping: the texture is the environment as reflected in a mirror ball seen from far
/// away; GL_SPHERE_MAP texgen computes (s, t) from the eye-space reflection vector.
pub(super) fn ex_sphere_map(gl: &mut dyn Gl) {
    let px = paint(128, 128, 3, |s, t| {
        let (x, y) = (2.0 * s - 1.0, 2.0 * t - 1.0);
        let r2 = x * x + y * y;
        if r2 > 1.0 {
            return [0.0, 0.0, 0.0, 1.0];
        }
        let z = (1.0 - r2).sqrt();
        // The reflection of the view direction (0, 0, -1) about the normal (x, y, z).
        environment([2.0 * z * x, 2.0 * z * y, 2.0 * z * z - 1.0])
    });
    env_object(gl);
    tex2d(gl, 128, 128, GL_RGB, &px);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    snap_texture(gl, "sphere_map", GL_TEXTURE_2D, 0, [128, 128, 1]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    torus(gl, 1.0, 0.42, 40, 20);
}

/// Cube environment mapping: six faces of the environment; GL_REFLECTION_MAP texgen on s, t, r
/// gives the eye-space reflection vector, which selects the face and the texel.
pub(super) fn ex_cube_map(gl: &mut dyn Gl) {
    env_object(gl);
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_CUBE_MAP, name[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    const N: usize = 64;
    // Direction of texel (sc, tc) of each face (GL 1.5 table 3.19, inverted).
    let faces: [fn(f32, f32) -> V3; 6] = [
        |s, t| [1.0, -t, -s],
        |s, t| [-1.0, -t, s],
        |s, t| [s, 1.0, t],
        |s, t| [s, -1.0, -t],
        |s, t| [s, -t, 1.0],
        |s, t| [-s, -t, -1.0],
    ];
    for (i, dir) in faces.iter().enumerate() {
        let px = paint(N, N, 3, |u, v| {
            environment(dir(2.0 * u - 1.0, 2.0 * v - 1.0))
        });
        gl.tex_image_2d(
            GL_TEXTURE_CUBE_MAP_POSITIVE_X + i as GLenum,
            0,
            GL_RGB as i32,
            N as i32,
            N as i32,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            Some(&px),
        );
    }
    sampling(
        gl,
        GL_TEXTURE_CUBE_MAP,
        GL_LINEAR,
        GL_LINEAR,
        GL_CLAMP_TO_EDGE,
    );
    for (i, face) in ["px", "nx", "py", "ny", "pz", "nz"].iter().enumerate() {
        snap_texture(
            gl,
            &format!("face_{face}"),
            GL_TEXTURE_CUBE_MAP_POSITIVE_X + i as GLenum,
            0,
            [N as i32, N as i32, 1],
        );
    }
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_CUBE_MAP);
    for c in [GL_S, GL_T, GL_R] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP as i32);
    }
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    gl.enable(GL_TEXTURE_GEN_R);
    torus(gl, 1.0, 0.42, 40, 20);
}

/// The world of the dynamic cube map: a lit checkered floor and coloured boxes in a ring.
pub(super) fn dyn_world(gl: &mut dyn Gl, checker: u32) {
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.4, 1.0, 0.7, 0.0]);
    material(gl, [1.0, 1.0, 1.0, 1.0], 0.0, 1.0);
    gl.bind_texture(GL_TEXTURE_2D, checker);
    gl.enable(GL_TEXTURE_2D);
    grid(gl, 8, &|gl, u, v| {
        gl.normal_3f(0.0, 1.0, 0.0);
        gl.tex_coord_2f(6.0 * u, 6.0 * v);
        gl.vertex_3f(-4.0 + 8.0 * u, 0.0, 4.0 - 8.0 * v);
    });
    gl.disable(GL_TEXTURE_2D);
    // Boxes in a ring, leaving a gap towards the camera (+z).
    let colours = [
        [0.9, 0.2, 0.2],
        [0.9, 0.8, 0.2],
        [0.2, 0.8, 0.3],
        [0.2, 0.7, 0.9],
        [0.3, 0.3, 0.9],
        [0.8, 0.3, 0.8],
    ];
    for (k, c) in colours.iter().enumerate() {
        let a = (10.0 + 40.0 * k as f32).to_radians() + std::f32::consts::PI;
        material(gl, [c[0], c[1], c[2], 1.0], 0.0, 1.0);
        let h = 0.4 + 0.15 * k as f32;
        cuboid(gl, [2.07 * a.cos(), h, 2.07 * a.sin()], [0.3, h, 0.3]);
    }
    gl.disable(GL_LIGHTING);
}

pub(super) const DYN_CENTRE: V3 = [0.0, 0.6, 0.0];
pub(super) const DYN_EYE: V3 = [0.3, 1.9, 3.3];

/// A dynamic cube map: the world is rendered six times from the reflecting object's centre
/// (90-degree frustum, one view per face) and each view copied into its face with
/// glCopyTexSubImage2D; the sphere then reflects it with GL_REFLECTION_MAP texgen, the texture
/// matrix turning the eye-space reflection vector back into world space.
pub(super) fn ex_cube_map_dynamic(gl: &mut dyn Gl) {
    clear_to(gl, [0.45, 0.6, 0.85]);
    gl.enable(GL_DEPTH_TEST);
    let checker_px = paint(32, 32, 3, |u, v| {
        if ((u * 8.0) as i32 + (v * 8.0) as i32) % 2 == 0 {
            [0.85, 0.85, 0.8, 1.0]
        } else {
            [0.35, 0.35, 0.4, 1.0]
        }
    });
    let checker = tex2d(gl, 32, 32, GL_RGB, &checker_px);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_CUBE_MAP, name[0]);
    const N: i32 = 64;
    for i in 0..6 {
        let face = GL_TEXTURE_CUBE_MAP_POSITIVE_X + i;
        gl.tex_image_2d(
            face,
            0,
            GL_RGB as i32,
            N,
            N,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            None,
        );
    }
    sampling(
        gl,
        GL_TEXTURE_CUBE_MAP,
        GL_LINEAR,
        GL_LINEAR,
        GL_CLAMP_TO_EDGE,
    );
    // The six views: looking along +x, -x, +y, -y, +z, -z with the "up" vectors that make
    // window coordinates match the faces' (s, t) orientation (GL 1.5 table 3.19).
    let views: [(V3, V3); 6] = [
        ([1.0, 0.0, 0.0], [0.0, -1.0, 0.0]),
        ([-1.0, 0.0, 0.0], [0.0, -1.0, 0.0]),
        ([0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
        ([0.0, -1.0, 0.0], [0.0, 0.0, -1.0]),
        ([0.0, 0.0, 1.0], [0.0, -1.0, 0.0]),
        ([0.0, 0.0, -1.0], [0.0, -1.0, 0.0]),
    ];
    gl.viewport(0, 0, N, N);
    for (i, (dir, up)) in views.into_iter().enumerate() {
        gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        gl.matrix_mode(GL_PROJECTION);
        gl.load_identity();
        perspective(gl, 90.0, 1.0, 0.1, 20.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.load_identity();
        let c = DYN_CENTRE;
        look_at(gl, c, [c[0] + dir[0], c[1] + dir[1], c[2] + dir[2]], up);
        dyn_world(gl, checker);
        let face = GL_TEXTURE_CUBE_MAP_POSITIVE_X + i as GLenum;
        gl.bind_texture(GL_TEXTURE_CUBE_MAP, name[0]);
        gl.copy_tex_sub_image_2d(face, 0, 0, 0, 0, 0, N, N);
    }
    for (i, face) in ["px", "nx", "py", "ny", "pz", "nz"].iter().enumerate() {
        snap_texture(
            gl,
            &format!("face_{face}"),
            GL_TEXTURE_CUBE_MAP_POSITIVE_X + i as GLenum,
            0,
            [N, N, 1],
        );
    }
    // The camera's view: the world, then the mirror sphere.
    example_support::viewport(gl, 0, 0, 128, 128);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    camera(gl, 50.0, 1.0, DYN_EYE, DYN_CENTRE);
    dyn_world(gl, checker);
    // Texture matrix: the inverse of the camera's rotation (its transpose).
    let f = norm(sub(DYN_CENTRE, DYN_EYE));
    let s = norm(cross(f, [0.0, 1.0, 0.0]));
    let u = cross(s, f);
    gl.matrix_mode(GL_TEXTURE);
    gl.load_matrixf(&[
        s[0], s[1], s[2], 0.0, u[0], u[1], u[2], 0.0, -f[0], -f[1], -f[2], 0.0, 0.0, 0.0, 0.0, 1.0,
    ]);
    gl.matrix_mode(GL_MODELVIEW);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_CUBE_MAP);
    for c in [GL_S, GL_T, GL_R] {
        gl.tex_geni(c, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP as i32);
    }
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    gl.enable(GL_TEXTURE_GEN_R);
    gl.enable(GL_NORMALIZE);
    gl.translatef(DYN_CENTRE[0], DYN_CENTRE[1], DYN_CENTRE[2]);
    gl.scalef(0.6, 0.6, 0.6);
    crate::scenes::sphere(gl, 24, 32);
}

// ---------------------------------------------------------------------------------------------
// Bump mapping.

pub(super) const BUMP_X: [f32; 2] = [-1.3, 1.3];
pub(super) const BUMP_Z: [f32; 2] = [-1.3, 1.3];

pub(super) fn bump_camera(gl: &mut dyn Gl) {
    clear_to(gl, [0.1, 0.1, 0.12]);
    camera(gl, 45.0, 1.0, [0.0, 2.6, 2.2], [0.0, 0.0, 0.0]);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_LEQUAL);
}

pub(super) fn stone(size: usize) -> Vec<u8> {
    paint(size, size, 3, |u, v| {
        let n = (u * 31.0).sin() * (v * 23.0).cos() * 0.5 + 0.5;
        [0.75 + 0.1 * n, 0.7 + 0.08 * n, 0.6, 1.0]
    })
}

/// Emboss bump mapping (Real-Time Rendering; McReynolds & Blythe): the height map H drawn, the
/// same map drawn with texture coordinates shifted towards the light and subtracted
/// (glBlendEquation(GL_FUNC_REVERSE_SUBTRACT)), which leaves 0.5 + (H(p) - H(p + shift)) / 2,
/// an estimate of the slope along the light direction; then the base colour multiplied in with
/// glBlendFunc(GL_DST_COLOR, GL_SRC_COLOR) (2 x src x dst).
pub(super) fn ex_emboss_bump(gl: &mut dyn Gl) {
    bump_camera(gl);
    let h = paint(64, 64, 1, |u, v| {
        let b = bump_height(u, v);
        [b, b, b, 1.0]
    });
    let height_tex = tex2d(gl, 64, 64, GL_LUMINANCE, &h);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    snap_texture(gl, "height_map", GL_TEXTURE_2D, 0, [64, 64, 1]);
    let s = stone(64);
    let base_tex = tex2d(gl, 64, 64, GL_RGB, &s);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.enable(GL_TEXTURE_2D);
    // The light direction in the plane's tangent space: s along +x, t along -z.
    let light = norm([-0.7, 0.5, -0.5]);
    let shift = 2.0 / 64.0; // two texels of the height map
    let (ds, dt) = (light[0] * shift, -light[2] * shift);
    // Pass 1: 0.5 + H/2, by GL_COMBINE INTERPOLATE(texture, constant white, primary 0.5).
    gl.bind_texture(GL_TEXTURE_2D, height_tex);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_CONSTANT as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_PRIMARY_COLOR as i32);
    // The third operand defaults to GL_SRC_ALPHA (which is 1 here): use the colour.
    gl.tex_envi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_COLOR as i32);
    gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[1.0, 1.0, 1.0, 1.0]);
    gl.color_3f(0.5, 0.5, 0.5);
    floor_quad(gl, BUMP_X, BUMP_Z, &[(GL_TEXTURE0, 2.0, 2.0)]);
    snap_color(gl, "pass1_height", 128, 128);
    // Pass 2: subtract H(p + shift) / 2 (MODULATE by 0.5, reverse-subtract blending).
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_BLEND);
    gl.blend_equation(GL_FUNC_REVERSE_SUBTRACT);
    gl.blend_func(GL_ONE, GL_ONE);
    gl.matrix_mode(GL_TEXTURE);
    gl.translatef(ds, dt, 0.0);
    gl.matrix_mode(GL_MODELVIEW);
    floor_quad(gl, BUMP_X, BUMP_Z, &[(GL_TEXTURE0, 2.0, 2.0)]);
    snap_color(gl, "pass2_embossed", 128, 128);
    gl.matrix_mode(GL_TEXTURE);
    gl.load_identity();
    gl.matrix_mode(GL_MODELVIEW);
    // Pass 3: base colour x diffuse factor, times 2 x the embossed term.
    gl.bind_texture(GL_TEXTURE_2D, base_tex);
    gl.blend_equation(GL_FUNC_ADD);
    gl.blend_func(GL_DST_COLOR, GL_SRC_COLOR);
    let diffuse = light[1];
    gl.color_3f(diffuse, diffuse, diffuse);
    floor_quad(gl, BUMP_X, BUMP_Z, &[(GL_TEXTURE0, 1.0, 1.0)]);
}

/// The light position of the DOT3 scene.
pub(super) const DOT3_LIGHT: V3 = [0.5, 0.6, -0.3];

/// DOT3 bump mapping: a normal map (tangent-space normals packed as 0.5 + n/2) on unit 0,
/// combined with the light vector carried in the primary colour by GL_COMBINE DOT3_RGB
/// (4 x ((r0-0.5)(r1-0.5) + ...) = N.L); unit 1 modulates the base texture.
pub(super) fn ex_dot3_bump(gl: &mut dyn Gl) {
    bump_camera(gl);
    let nm = paint(64, 64, 3, |u, v| {
        let e = 1.0 / 64.0;
        let k = 0.12; // height scale in texture units
        let dhdu = (bump_height(u + e, v) - bump_height(u - e, v)) / (2.0 * e) * k / 4.0;
        let dhdv = (bump_height(u, v + e) - bump_height(u, v - e)) / (2.0 * e) * k / 4.0;
        let n = norm([-dhdu, -dhdv, 1.0]);
        [0.5 + 0.5 * n[0], 0.5 + 0.5 * n[1], 0.5 + 0.5 * n[2], 1.0]
    });
    tex2d(gl, 64, 64, GL_RGB, &nm);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    snap_texture(gl, "normal_map", GL_TEXTURE_2D, 0, [64, 64, 1]);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGB as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PRIMARY_COLOR as i32);
    gl.active_texture(GL_TEXTURE1);
    let s = stone(64);
    tex2d(gl, 64, 64, GL_RGB, &s);
    sampling(gl, GL_TEXTURE_2D, GL_LINEAR, GL_LINEAR, GL_REPEAT);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.active_texture(GL_TEXTURE0);
    let plane = |gl: &mut dyn Gl| {
        grid(gl, 16, &|gl, u, v| {
            let p = [
                BUMP_X[0] + u * (BUMP_X[1] - BUMP_X[0]),
                0.0,
                BUMP_Z[1] + v * (BUMP_Z[0] - BUMP_Z[1]),
            ];
            // The light vector in tangent space (T = +x, B = -z, N = +y), packed in the colour.
            let l = norm(sub(DOT3_LIGHT, p));
            let lt = [l[0], -l[2], l[1]];
            gl.color_3f(0.5 + 0.5 * lt[0], 0.5 + 0.5 * lt[1], 0.5 + 0.5 * lt[2]);
            gl.multi_tex_coord_2f(GL_TEXTURE0, 2.0 * u, 2.0 * v);
            gl.multi_tex_coord_2f(GL_TEXTURE1, u, v);
            gl.vertex_3f(p[0], p[1], p[2]);
        });
    };
    // Stage: the DOT3 term alone (unit 1 off), then the full picture over it.
    plane(gl);
    snap_color(gl, "dot3_only", 128, 128);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.active_texture(GL_TEXTURE1);
    gl.enable(GL_TEXTURE_2D);
    gl.active_texture(GL_TEXTURE0);
    plane(gl);
}
