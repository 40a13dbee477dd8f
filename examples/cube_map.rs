//! Cube environment mapping: the same environment as six square faces, indexed by the reflection
//! vector.
//!
//! What it teaches (GL 1.3 cube maps; GL 1.5 section 3.8.6; Real-Time Rendering):
//! - `GL_TEXTURE_CUBE_MAP` holds six 2D images, one per face of a cube around the viewer
//!   (`GL_TEXTURE_CUBE_MAP_POSITIVE_X` ...). A 3D direction (s, t, r) selects the face of its
//!   largest component and a texel on it (table 3.19).
//! - `glTexGeni(GL_S/GL_T/GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP)` sets (s, t, r) to the
//!   eye-space reflection vector, so the surface mirrors the environment; unlike a sphere map,
//!   a cube map is valid from every viewing direction and samples the environment evenly.
//! - `ex_cube_map`: the faces are generated from the same environment function as
//!   `sphere_map`, so the two examples can be compared.
//! - `ex_cube_map_dynamic`: the faces are *rendered*: six views of the world from the mirror
//!   sphere's centre, each with a 90-degree `gluPerspective` and the look/up vectors that match
//!   the face's (s, t) axes, copied from the colour buffer with `glCopyTexSubImage2D` into
//!   `GL_TEXTURE_CUBE_MAP_POSITIVE_X + i` (allocated first with `glTexImage2D(..., NULL)`). The
//!   reflection vector is in eye space; the texture matrix holds the inverse of the camera's
//!   rotation so it indexes the world-aligned faces. `GL_NORMALIZE` keeps the scaled sphere's
//!   normals unit length. (The cube map treats the environment as infinitely far: the boxes near
//!   the sphere reflect with a small parallax error.)
//!
//! Stages: the six faces (`px`, `nx`, `py`, `ny`, `pz`, `nz`) of each scene.
//!
//! Run: `cargo run --release -p tilegl-conformance --example cube_map [OUT_DIR]`
//! (default `out/cube_map/`). The scenes `ex_cube_map`, `ex_cube_map_dynamic` (in
//! `conformance/src/scenes_examples.rs`) are rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! each prefixed with the scene's name,
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scenes against Mesa.

fn main() {
    tilegl_conformance::example_support::run("cube_map", &["ex_cube_map", "ex_cube_map_dynamic"]);
}
