//! The built-in scenes: small pictures, each showing one part of the fixed-function pipeline.
//!
//! Every scene is a plain function over `&mut dyn Gl`, so the same code draws on tilegl and on
//! any other GL 1.5 implementation behind the trait (the conformance crate's Mesa context).
//! A scene sets all the state it relies on except the framebuffer size, which it is given.
//!
//! `src/bin/tilegl/main.rs` renders them all (`cargo run --release`); the example
//! `examples/smooth_depth.rs` includes this file and renders one of them.

use tilegl::enums::*;
use tilegl::Gl;

/// A built-in scene: a name (also the PNG's file stem), what it shows, its size and how to
/// draw it.
pub struct Scene {
    pub name: &'static str,
    pub about: &'static str,
    pub width: i32,
    pub height: i32,
    /// Draws the whole picture into a framebuffer of `width` x `height`.
    pub draw: fn(gl: &mut dyn Gl, width: i32, height: i32),
}

/// All built-in scenes, in gallery order.
pub const SCENES: &[Scene] = &[
    Scene {
        name: "smooth_depth",
        about: "smooth-shaded colour cube and two interpenetrating triangles, glFrustum perspective, depth test",
        width: 320,
        height: 240,
        draw: smooth_depth,
    },
    Scene {
        name: "primitives",
        about: "the ten primitive modes, one per viewport cell (scissored clears as backgrounds)",
        width: 384,
        height: 288,
        draw: primitives,
    },
    Scene {
        name: "clipping",
        about: "near-plane clipping of a floor that reaches behind the eye; a cube's corner cut off by a user clip plane",
        width: 384,
        height: 192,
        draw: clipping,
    },
    Scene {
        name: "flat_smooth",
        about: "the same triangle strip and fan with GL_FLAT (left, last vertex provokes) and GL_SMOOTH (right)",
        width: 384,
        height: 192,
        draw: flat_smooth,
    },
    Scene {
        name: "culling",
        about: "a colour cube with back faces culled (left) and front faces culled (right)",
        width: 384,
        height: 192,
        draw: culling,
    },
    Scene {
        name: "textured_fog",
        about: "a lit, sphere-mapped torus over a trilinear-mipmapped floor fading into exp2 fog",
        width: 320,
        height: 240,
        draw: textured_fog,
    },
    Scene {
        name: "raster_modes",
        about: "wide and smooth points and lines, stipples, polygon outlines, glBitmap text and glDrawPixels with zoom",
        width: 320,
        height: 240,
        draw: raster_modes,
    },
];

/// Looks a scene up by name.
pub fn find(name: &str) -> Option<&'static Scene> {
    SCENES.iter().find(|s| s.name == name)
}

/// Distinct, saturated vertex colours used by several scenes. Every component times 255 is a
/// whole number, so a flat-shaded pixel has an exactly predictable 8-bit value.
const PALETTE: [[f32; 3]; 8] = [
    [1.0, 0.2, 0.2],
    [1.0, 0.8, 0.0],
    [0.2, 0.8, 0.2],
    [0.0, 0.8, 1.0],
    [0.2, 0.4, 1.0],
    [0.8, 0.2, 1.0],
    [1.0, 1.0, 1.0],
    [1.0, 0.6, 0.0],
];

fn palette(i: usize) -> [f32; 3] {
    PALETTE[i % PALETTE.len()]
}

/// The six faces of the cube [-1, 1]^3, each wound counter-clockwise seen from outside (so
/// `glFrontFace(GL_CCW)` makes the outside the front).
const CUBE_FACES: [[[f32; 3]; 4]; 6] = [
    // +X
    [[1., -1., -1.], [1., 1., -1.], [1., 1., 1.], [1., -1., 1.]],
    // -X
    [
        [-1., -1., -1.],
        [-1., -1., 1.],
        [-1., 1., 1.],
        [-1., 1., -1.],
    ],
    // +Y
    [[-1., 1., -1.], [-1., 1., 1.], [1., 1., 1.], [1., 1., -1.]],
    // -Y
    [
        [-1., -1., -1.],
        [1., -1., -1.],
        [1., -1., 1.],
        [-1., -1., 1.],
    ],
    // +Z
    [[-1., -1., 1.], [1., -1., 1.], [1., 1., 1.], [-1., 1., 1.]],
    // -Z
    [
        [-1., -1., -1.],
        [-1., 1., -1.],
        [1., 1., -1.],
        [1., -1., -1.],
    ],
];

/// The "colour cube": each corner's colour is its position mapped from [-1, 1] to [0, 1], so
/// smooth shading blends the eight corner colours across the faces.
fn colour_cube(gl: &mut dyn Gl) {
    gl.begin(GL_QUADS);
    for face in &CUBE_FACES {
        for v in face {
            gl.color_3f(0.5 * (v[0] + 1.0), 0.5 * (v[1] + 1.0), 0.5 * (v[2] + 1.0));
            gl.vertex_3f(v[0], v[1], v[2]);
        }
    }
    gl.end();
}

/// A symmetric perspective projection with the given vertical half-angle tangent, like
/// `gluPerspective` but written with `glFrustum`.
fn perspective(gl: &mut dyn Gl, aspect: f64, tan_half_fovy: f64, near: f64, far: f64) {
    let top = near * tan_half_fovy;
    let right = top * aspect;
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(-right, right, -top, top, near, far);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

/// Resets the state the scenes share: full viewport, no scissor, default depth range,
/// smooth shading, depth test on, no culling, no clip planes.
fn reset(gl: &mut dyn Gl, width: i32, height: i32) {
    gl.viewport(0, 0, width, height);
    gl.depth_range(0.0, 1.0);
    gl.disable(GL_SCISSOR_TEST);
    gl.disable(GL_CULL_FACE);
    gl.disable(GL_CLIP_PLANE0);
    gl.shade_model(GL_SMOOTH);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_LESS);
    gl.depth_mask(GL_TRUE as GLboolean);
    gl.color_mask(1, 1, 1, 1);
    gl.clear_depth(1.0);
}

/// Smooth shading and the depth buffer, seen through a perspective projection.
///
/// - `glFrustum` maps a truncated pyramid to the clip cube, so farther things look smaller;
///   colours (like every attribute) are interpolated perspective-correctly across each
///   triangle, so the blend on a receding face is not skewed.
/// - With `GL_SMOOTH`, each vertex's `glColor` is blended across the primitive: the cube's
///   eight corner colours flow into each other.
/// - With `GL_DEPTH_TEST` and `GL_LESS`, a fragment is kept only if it is nearer than what the
///   pixel already holds, independently of drawing order: the cube's hidden faces vanish, and
///   the two triangles (drawn far one last) cut through each other along a straight line
///   where their depths are equal.
pub fn smooth_depth(gl: &mut dyn Gl, width: i32, height: i32) {
    reset(gl, width, height);
    gl.clear_color(0.08, 0.08, 0.12, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    perspective(gl, width as f64 / height.max(1) as f64, 0.45, 1.0, 30.0);

    // The colour cube, turned to show three faces, on the left.
    gl.push_matrix();
    gl.translatef(-1.6, 0.0, -7.0);
    gl.rotatef(30.0, 1.0, 0.0, 0.0);
    gl.rotatef(-35.0, 0.0, 1.0, 0.0);
    colour_cube(gl);
    gl.pop_matrix();

    // Two triangles tilted in opposite directions about the vertical axis, on the right: each
    // is nearer on one side, so they intersect along a vertical line.
    gl.push_matrix();
    gl.translatef(1.7, 0.0, -7.0);
    for (angle, colours) in [
        (40.0f32, [[1.0, 0.9, 0.2], [1.0, 0.5, 0.0], [1.0, 0.1, 0.1]]),
        (-40.0, [[0.2, 0.6, 1.0], [0.1, 1.0, 0.6], [0.6, 0.2, 1.0]]),
    ] {
        gl.push_matrix();
        gl.rotatef(angle, 0.0, 1.0, 0.0);
        gl.begin(GL_TRIANGLES);
        let verts = [[-1.3f32, -1.2, 0.0], [1.3, -1.2, 0.0], [0.0, 1.4, 0.0]];
        for (c, v) in colours.iter().zip(verts) {
            gl.color_3f(c[0], c[1], c[2]);
            gl.vertex_3f(v[0], v[1], v[2]);
        }
        gl.end();
        gl.pop_matrix();
    }
    gl.pop_matrix();
}

/// Vertices (x, y in [-0.8, 0.8]) that make a readable picture for each primitive mode.
fn mode_vertices(mode: GLenum) -> Vec<[f32; 2]> {
    let circle = |n: usize, r: f32, start: f32, span: f32, cy: f32| -> Vec<[f32; 2]> {
        (0..n)
            .map(|i| {
                let a = start + span * i as f32 / n as f32;
                [r * a.cos(), cy + r * a.sin()]
            })
            .collect()
    };
    let tau = std::f32::consts::TAU;
    match mode {
        GL_POINTS => (0..25)
            .map(|i| [-0.8 + 0.4 * (i % 5) as f32, -0.8 + 0.4 * (i / 5) as f32])
            .collect(),
        GL_LINES => vec![
            [-0.8, -0.8],
            [0.8, -0.4],
            [-0.8, -0.2],
            [0.8, 0.2],
            [-0.8, 0.4],
            [0.8, 0.8],
        ],
        // Zig-zags: alternately low and high, left to right.
        GL_LINE_STRIP | GL_TRIANGLE_STRIP => (0..6)
            .map(|i| [-0.8 + 0.32 * i as f32, if i % 2 == 0 { -0.6 } else { 0.6 }])
            .collect(),
        GL_LINE_LOOP => circle(6, 0.8, 0.0, tau, 0.0),
        GL_TRIANGLES => vec![
            [-0.8, -0.8],
            [0.1, -0.8],
            [-0.35, 0.7],
            [0.0, 0.8],
            [0.35, -0.6],
            [0.8, 0.8],
        ],
        // A centre and an arc above it.
        GL_TRIANGLE_FAN => {
            // Seven arc points from 0.5 to pi - 0.5 radians (`circle` stops one step short
            // of start + span).
            let (n, start) = (7, 0.5f32);
            let span = (std::f32::consts::PI - 2.0 * start) * n as f32 / (n - 1) as f32;
            let mut v = vec![[0.0, -0.7]];
            v.extend(circle(n, 1.1, start, span, -0.7));
            v
        }
        GL_QUADS => vec![
            [-0.8, -0.8],
            [-0.1, -0.8],
            [-0.1, -0.1],
            [-0.8, -0.1],
            [0.1, 0.1],
            [0.8, 0.2],
            [0.7, 0.8],
            [0.0, 0.7],
        ],
        // Pairs: bottom then top, left to right.
        GL_QUAD_STRIP => (0..8)
            .map(|i| {
                let x = -0.8 + 0.533 * (i / 2) as f32;
                [x, if i % 2 == 0 { -0.6 } else { 0.6 }]
            })
            .collect(),
        _ => circle(5, 0.8, tau / 4.0, tau, -0.1),
    }
}

/// The ten primitive modes of `glBegin`, each in its own viewport cell of a 4 x 3 grid, with
/// one palette colour per vertex (smooth shading). Each cell's background is a scissored
/// `glClear`; lines and points are one pixel wide.
pub fn primitives(gl: &mut dyn Gl, width: i32, height: i32) {
    const MODES: [GLenum; 10] = [
        GL_POINTS,
        GL_LINES,
        GL_LINE_STRIP,
        GL_LINE_LOOP,
        GL_TRIANGLES,
        GL_TRIANGLE_STRIP,
        GL_TRIANGLE_FAN,
        GL_QUADS,
        GL_QUAD_STRIP,
        GL_POLYGON,
    ];
    reset(gl, width, height);
    gl.disable(GL_DEPTH_TEST);
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();

    let (cols, rows) = (4, 3);
    let (cw, ch) = (width / cols, height / rows);
    gl.enable(GL_SCISSOR_TEST);
    for (i, &mode) in MODES.iter().enumerate() {
        let (col, row) = (i as i32 % cols, i as i32 / cols);
        // Row 0 at the top of the picture; GL's window y grows upwards.
        let (x, y) = (col * cw, height - (row + 1) * ch);
        gl.scissor(x, y, cw, ch);
        let shade = if (col + row) % 2 == 0 { 0.16 } else { 0.10 };
        gl.clear_color(shade, shade, shade + 0.04, 1.0);
        gl.clear(GL_COLOR_BUFFER_BIT);
        gl.viewport(x, y, cw, ch);
        gl.begin(mode);
        for (j, v) in mode_vertices(mode).iter().enumerate() {
            let c = palette(j);
            gl.color_3f(c[0], c[1], c[2]);
            gl.vertex_2f(v[0], v[1]);
        }
        gl.end();
    }
    gl.disable(GL_SCISSOR_TEST);
}

/// Clipping in two panels.
///
/// Left: a checkered floor from 6 units behind the eye to 40 units in front of it, seen
/// through `glFrustum`. Vertices behind the eye have w < 0; only clipping against the near
/// plane in homogeneous coordinates, before the divide by w, draws the floor correctly.
///
/// Right: the colour cube with its white corner (1, 1, 1), the one nearest the eye, cut off by
/// the user clip plane -x - y - z + 1.5 >= 0 (in the cube's object space: `glClipPlane`
/// transforms the plane by the modelview matrix current when it is called). Through the
/// triangular hole one sees the inside of the three far faces.
pub fn clipping(gl: &mut dyn Gl, width: i32, height: i32) {
    reset(gl, width, height);
    gl.clear_color(0.05, 0.05, 0.08, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    let half = width / 2;

    // Left panel: the floor.
    gl.viewport(0, 0, half, height);
    perspective(gl, half as f64 / height.max(1) as f64, 0.6, 0.5, 60.0);
    gl.rotatef(12.0, 1.0, 0.0, 0.0);
    gl.translatef(0.0, -1.5, 0.0);
    gl.begin(GL_QUADS);
    let (step, x0, x1, z0, z1) = (2.0f32, -8i32, 8i32, -40i32, 6i32);
    for zi in (z0..z1).step_by(step as usize) {
        for xi in (x0..x1).step_by(step as usize) {
            let (x, z) = (xi as f32, zi as f32);
            let dark = ((xi - x0) / step as i32 + (zi - z0) / step as i32) % 2 == 0;
            // Near squares are warm, far squares cool; the dark checks are dimmer.
            let t = (z - z0 as f32) / (z1 - z0) as f32;
            let k = if dark { 0.45 } else { 1.0 };
            let corners = [[x, z + step], [x + step, z + step], [x + step, z], [x, z]];
            for [cx, cz] in corners {
                let tt = t + (cz - z) / (z1 - z0) as f32;
                gl.color_3f(k * tt, k * 0.35, k * (1.0 - tt));
                gl.vertex_3f(cx, 0.0, cz);
            }
        }
    }
    gl.end();

    // Right panel: the cube and the user clip plane.
    gl.viewport(half, 0, width - half, height);
    perspective(
        gl,
        (width - half) as f64 / height.max(1) as f64,
        0.45,
        1.0,
        20.0,
    );
    gl.translatef(0.0, 0.0, -5.5);
    gl.rotatef(25.0, 1.0, 0.0, 0.0);
    gl.rotatef(-30.0, 0.0, 1.0, 0.0);
    gl.clip_plane(GL_CLIP_PLANE0, &[-1.0, -1.0, -1.0, 1.5]);
    gl.enable(GL_CLIP_PLANE0);
    colour_cube(gl);
    gl.disable(GL_CLIP_PLANE0);
}

/// The same triangle strip (top) and fan (bottom) drawn with `GL_FLAT` on the left and
/// `GL_SMOOTH` on the right. Flat shading gives each triangle the colour of its provoking
/// vertex: for strips and fans (and independent triangles) that is the last vertex of the
/// triangle; for quads and polygons it would be the last and the first vertex respectively.
pub fn flat_smooth(gl: &mut dyn Gl, width: i32, height: i32) {
    reset(gl, width, height);
    gl.disable(GL_DEPTH_TEST);
    gl.clear_color(0.1, 0.1, 0.1, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    let half = width / 2;
    for (panel, model) in [(0, GL_FLAT), (1, GL_SMOOTH)] {
        gl.viewport(panel * half, 0, half, height);
        gl.shade_model(model);
        // Strip in the upper half.
        gl.begin(GL_TRIANGLE_STRIP);
        for i in 0..8 {
            let c = palette(i);
            gl.color_3f(c[0], c[1], c[2]);
            let x = -0.9 + 1.8 * (i / 2) as f32 / 3.0;
            gl.vertex_2f(x, if i % 2 == 0 { 0.1 } else { 0.9 });
        }
        gl.end();
        // Fan in the lower half.
        gl.begin(GL_TRIANGLE_FAN);
        gl.color_3f(1.0, 1.0, 1.0);
        gl.vertex_2f(0.0, -0.9);
        for i in 0..7 {
            let a = std::f32::consts::PI * i as f32 / 6.0;
            let c = palette(i);
            gl.color_3f(c[0], c[1], c[2]);
            gl.vertex_2f(0.9 * a.cos(), -0.9 + 0.8 * a.sin());
        }
        gl.end();
    }
    gl.shade_model(GL_SMOOTH);
}

/// Face culling: the colour cube with `glCullFace(GL_BACK)` on the left (the usual solid
/// look, without the depth test) and `glCullFace(GL_FRONT)` on the right (only the inside,
/// far faces remain). Which side is the front is decided by the winding in window
/// coordinates and `glFrontFace` (counter-clockwise by default).
pub fn culling(gl: &mut dyn Gl, width: i32, height: i32) {
    reset(gl, width, height);
    gl.disable(GL_DEPTH_TEST);
    gl.clear_color(0.08, 0.1, 0.08, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.enable(GL_CULL_FACE);
    gl.front_face(GL_CCW);
    let half = width / 2;
    for (panel, face) in [(0, GL_BACK), (1, GL_FRONT)] {
        gl.viewport(panel * half, 0, half, height);
        perspective(gl, half as f64 / height.max(1) as f64, 0.45, 1.0, 20.0);
        gl.translatef(0.0, 0.0, -5.5);
        gl.rotatef(30.0, 1.0, 0.0, 0.0);
        gl.rotatef(-35.0, 0.0, 1.0, 0.0);
        gl.cull_face(face);
        colour_cube(gl);
    }
    gl.disable(GL_CULL_FACE);
    gl.cull_face(GL_BACK);
}

/// A procedural checkerboard texture (RGBA8) with mipmaps generated by the driver.
fn checker_texture(gl: &mut dyn Gl, size: usize, a: [u8; 3], b: [u8; 3]) {
    let mut px = Vec::with_capacity(size * size * 4);
    for y in 0..size {
        for x in 0..size {
            let c = if (x / 8 + y / 8) % 2 == 0 { a } else { b };
            px.extend_from_slice(&[c[0], c[1], c[2], 255]);
        }
    }
    let mut name = [0u32];
    gl.gen_textures(1, &mut name);
    gl.bind_texture(GL_TEXTURE_2D, name[0]);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGBA8 as i32,
        size as i32,
        size as i32,
        0,
        GL_RGBA,
        GL_UNSIGNED_BYTE,
        Some(&px),
    );
    gl.tex_parameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR as i32,
    );
}

/// Texturing, lighting, texture coordinate generation and fog together.
///
/// - The floor is a trilinear-mipmapped checkerboard (`GL_LINEAR_MIPMAP_LINEAR`): far away
///   the squares blend to grey instead of shimmering.
/// - The torus is lit per vertex (`GL_LIGHT0`, `GL_COLOR_MATERIAL`) and textured with
///   `GL_SPHERE_MAP` coordinate generation, the classic fake chrome.
/// - Exp2 fog (`GL_FOG`) blends every fragment towards the sky colour with its eye distance.
pub fn textured_fog(gl: &mut dyn Gl, width: i32, height: i32) {
    reset(gl, width, height);
    let sky = [0.62, 0.7, 0.82, 1.0];
    gl.clear_color(sky[0], sky[1], sky[2], 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    perspective(gl, width as f64 / height as f64, 0.5, 0.3, 60.0);
    gl.enable(GL_FOG);
    gl.fogi(GL_FOG_MODE, GL_EXP2 as i32);
    gl.fogf(GL_FOG_DENSITY, 0.09);
    gl.fogfv(GL_FOG_COLOR, &sky);
    gl.enable(GL_TEXTURE_2D);
    checker_texture(gl, 64, [235, 230, 215], [70, 90, 120]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.begin(GL_QUADS);
    for (s, t, x, z) in [
        (0.0f32, 0.0f32, -20.0f32, 2.0f32),
        (10.0, 0.0, 20.0, 2.0),
        (10.0, 15.0, 20.0, -40.0),
        (0.0, 15.0, -20.0, -40.0),
    ] {
        gl.tex_coord_2f(s, t);
        gl.vertex_3f(x, -1.2, z);
    }
    gl.end();
    // The torus: lit, sphere-mapped.
    checker_texture(gl, 32, [255, 240, 160], [60, 40, 140]);
    gl.enable(GL_TEXTURE_GEN_S);
    gl.enable(GL_TEXTURE_GEN_T);
    gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.lightfv(GL_LIGHT0, GL_POSITION, &[0.4, 1.0, 0.6, 0.0]);
    gl.enable(GL_COLOR_MATERIAL);
    gl.enable(GL_NORMALIZE);
    gl.translatef(0.0, 0.2, -5.0);
    gl.rotatef(60.0, 1.0, 0.25, 0.0);
    gl.color_3f(0.9, 0.75, 0.6);
    let (big, small, nu, nv) = (1.1f32, 0.42f32, 48, 24);
    for i in 0..nu {
        gl.begin(GL_QUAD_STRIP);
        for j in 0..=nv {
            for di in [0, 1] {
                let u = (i + di) as f32 / nu as f32 * std::f32::consts::TAU;
                let v = j as f32 / nv as f32 * std::f32::consts::TAU;
                let (cu, su, cv, sv) = (u.cos(), u.sin(), v.cos(), v.sin());
                gl.normal_3f(cu * cv, su * cv, sv);
                gl.vertex_3f((big + small * cv) * cu, (big + small * cv) * su, small * sv);
            }
        }
        gl.end();
    }
    for cap in [
        GL_LIGHTING,
        GL_LIGHT0,
        GL_COLOR_MATERIAL,
        GL_NORMALIZE,
        GL_TEXTURE_GEN_S,
        GL_TEXTURE_GEN_T,
        GL_TEXTURE_2D,
        GL_FOG,
    ] {
        gl.disable(cap);
    }
}

/// The rasterization controls and pixel rectangles of GL 1.x.
///
/// - Points of growing `glPointSize`, aliased (squares) and with `GL_POINT_SMOOTH` (discs with
///   coverage in their alpha, blended).
/// - Lines of growing `glLineWidth`, a stippled strip (`glLineStipple`) and antialiased lines.
/// - A star polygon in `glPolygonMode(GL_LINE)` over a filled, `glPolygonStipple`d copy.
/// - `glBitmap` glyphs advancing the raster position, and a `glDrawPixels` image zoomed 3x.
pub fn raster_modes(gl: &mut dyn Gl, width: i32, height: i32) {
    reset(gl, width, height);
    gl.disable(GL_DEPTH_TEST);
    gl.clear_color(0.08, 0.08, 0.12, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    // Drawn in the coordinates of its own 320x240 window, whatever the window's size; point
    // sizes, line widths and the pixel zoom grow with it (stipples and bitmaps stay in pixels).
    gl.ortho(0.0, 320.0, 0.0, 240.0, -1.0, 1.0);
    let s = (width as f32 / 320.0).min(height as f32 / 240.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    // Points: aliased on the first row, smooth on the second.
    for (row, smooth) in [(0, false), (1, true)] {
        if smooth {
            gl.enable(GL_POINT_SMOOTH);
        }
        for k in 0..8 {
            let c = palette(k);
            gl.color_3f(c[0], c[1], c[2]);
            gl.point_size((1.0 + 2.0 * k as f32) * s);
            gl.begin(GL_POINTS);
            gl.vertex_2f(14.3 + 19.0 * k as f32, 222.4 - 24.0 * row as f32);
            gl.end();
        }
        gl.disable(GL_POINT_SMOOTH);
    }
    // Lines: widths, a stipple, smooth.
    for k in 0..5 {
        let c = palette(k + 2);
        gl.color_3f(c[0], c[1], c[2]);
        gl.line_width((1.0 + k as f32 * 1.5) * s);
        gl.begin(GL_LINES);
        gl.vertex_2f(8.3, 150.2 - 10.0 * k as f32);
        gl.vertex_2f(150.7, 162.6 - 10.0 * k as f32);
        gl.end();
    }
    gl.line_width(2.0 * s);
    gl.enable(GL_LINE_STIPPLE);
    gl.line_stipple(3, 0xAAF0);
    gl.color_3f(1.0, 1.0, 1.0);
    gl.begin(GL_LINE_STRIP);
    for k in 0..8 {
        gl.vertex_2f(
            10.4 + 20.0 * k as f32,
            92.3 + if k % 2 == 0 { 0.0 } else { 14.0 },
        );
    }
    gl.end();
    gl.disable(GL_LINE_STIPPLE);
    gl.enable(GL_LINE_SMOOTH);
    gl.line_width(1.5 * s);
    gl.begin(GL_LINES);
    for k in 0..6 {
        let a = 0.2 + k as f32 * 0.25;
        let c = palette(k);
        gl.color_3f(c[0], c[1], c[2]);
        gl.vertex_2f(80.0, 40.0);
        gl.vertex_2f(80.0 + 70.0 * a.cos(), 40.0 + 30.0 * a.sin());
    }
    gl.end();
    gl.disable(GL_LINE_SMOOTH);
    gl.line_width(1.0);
    // A star: stippled fill under a line-mode outline.
    let star: Vec<[f32; 2]> = (0..10)
        .map(|k| {
            let r = if k % 2 == 0 { 55.0 } else { 24.0 };
            let a = k as f32 * std::f32::consts::PI / 5.0 + 0.3;
            [245.0 + r * a.cos(), 170.0 + r * a.sin()]
        })
        .collect();
    let pattern: Vec<u8> = (0..128u32)
        .map(|k| if (k / 4 + k % 4) % 2 == 0 { 0xCC } else { 0x33 })
        .collect();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.polygon_stipple(&pattern);
    gl.enable(GL_POLYGON_STIPPLE);
    gl.color_3f(0.3, 0.6, 1.0);
    gl.begin(GL_TRIANGLE_FAN);
    gl.vertex_2f(245.0, 170.0);
    for p in star.iter().chain(star.first()) {
        gl.vertex_2f(p[0], p[1]);
    }
    gl.end();
    gl.disable(GL_POLYGON_STIPPLE);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
    gl.line_width(2.0 * s);
    gl.color_3f(1.0, 0.9, 0.3);
    gl.begin(GL_POLYGON);
    for p in &star {
        gl.vertex_2f(p[0], p[1]);
    }
    gl.end();
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_FILL);
    gl.line_width(1.0);
    // glBitmap: an 8x8 "glyph" per letter, the raster position advancing.
    gl.color_3f(0.9, 1.0, 0.9);
    gl.raster_pos_2i(180, 70);
    for k in 0..10u8 {
        let glyph: Vec<u8> = (0..8u8)
            .map(|r| (r.wrapping_mul(37) ^ k.wrapping_mul(91)) | 0x81)
            .collect();
        gl.bitmap(8, 8, 0.0, 0.0, 12.0, 0.0, &glyph);
    }
    // glDrawPixels of a small gradient, zoomed 3x.
    let img: Vec<u8> = (0..16 * 12)
        .flat_map(|k| [(k % 16 * 16) as u8, (k / 16 * 21) as u8, 180, 255])
        .collect();
    gl.pixel_zoom(3.0 * s, 3.0 * s);
    gl.raster_pos_2i(180, 8);
    gl.draw_pixels(16, 12, GL_RGBA, GL_UNSIGNED_BYTE, Some(&img));
    gl.pixel_zoom(1.0, 1.0);
    gl.disable(GL_BLEND);
}

#[cfg(test)]
mod tests {
    use super::*;
    use tilegl::Context;

    fn render(scene: &Scene) -> Context {
        let mut ctx = Context::new(scene.width, scene.height);
        (scene.draw)(&mut ctx, scene.width, scene.height);
        ctx.finish();
        ctx
    }

    fn pixel(ctx: &mut Context, x: i32, y: i32) -> [u8; 4] {
        let mut px = [0u8; 4];
        ctx.read_pixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &mut px);
        px
    }

    #[test]
    fn every_scene_draws_without_gl_errors_and_covers_pixels() {
        for scene in SCENES {
            let mut ctx = render(scene);
            assert_eq!(ctx.get_error(), GL_NO_ERROR, "scene {}", scene.name);
            let mut all = vec![0u8; (scene.width * scene.height * 4) as usize];
            ctx.read_pixels(
                0,
                0,
                scene.width,
                scene.height,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                &mut all,
            );
            let distinct: std::collections::HashSet<&[u8]> = all.chunks(4).collect();
            assert!(
                distinct.len() > 20,
                "scene {} has only {} colours",
                scene.name,
                distinct.len()
            );
        }
    }

    #[test]
    fn scene_names_are_unique() {
        for (i, a) in SCENES.iter().enumerate() {
            assert!(SCENES[i + 1..].iter().all(|b| b.name != a.name));
            assert!(find(a.name).is_some());
        }
    }

    #[test]
    fn cube_faces_are_counter_clockwise_from_outside() {
        for face in &CUBE_FACES {
            let [a, b, c, _] = face;
            let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
            let n = [
                u[1] * v[2] - u[2] * v[1],
                u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0],
            ];
            let centre: Vec<f32> = (0..3).map(|k| face.iter().map(|p| p[k]).sum()).collect();
            let outward: f32 = (0..3).map(|k| n[k] * centre[k]).sum();
            assert!(outward > 0.0, "face {face:?}");
        }
    }

    #[test]
    fn flat_shading_uses_the_last_vertex_of_each_strip_triangle() {
        let scene = find("flat_smooth").unwrap();
        let mut ctx = render(scene);
        // First strip triangle (vertices 0, 1, 2) of the left (flat) panel: its centroid.
        let half = scene.width / 2;
        let to_win = |x: f32, y: f32| {
            (
                ((x + 1.0) * 0.5 * half as f32) as i32,
                ((y + 1.0) * 0.5 * scene.height as f32) as i32,
            )
        };
        let (x, y) = to_win((-0.9 + -0.9 + -0.3) / 3.0, (0.1 + 0.9 + 0.1) / 3.0);
        let c = palette(2);
        let expect = [
            (c[0] * 255.0).round() as u8,
            (c[1] * 255.0).round() as u8,
            (c[2] * 255.0).round() as u8,
            255,
        ];
        assert_eq!(pixel(&mut ctx, x, y), expect);
    }

    #[test]
    fn clipping_scene_covers_what_it_should() {
        let scene = find("clipping").unwrap();
        let mut ctx = render(scene);
        let bg = pixel(&mut ctx, scene.width - 1, scene.height - 1);
        let centre = pixel(&mut ctx, scene.width * 3 / 4, scene.height / 2);
        assert_ne!(bg, centre, "the cube covers the right panel's centre");
        // The left panel's bottom row is floor right under the eye: covered, not background.
        let floor = pixel(&mut ctx, scene.width / 4, 0);
        assert_ne!(
            bg, floor,
            "the floor reaches the bottom edge (near-plane clipping)"
        );
    }
}
