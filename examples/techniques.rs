//! The gallery's technique scenes: the texture environment modes side by side; planar,
//! cylindrical, spherical and box projector mappings; mipmaps, ripmaps and summed-area tables;
//! latitude-longitude and dual-paraboloid environment maps; environment-mapped bump mapping;
//! texture animation through the texture matrix; image warping; detail textures; billboards
//! and impostors; antialiased points and lines through textures; an air-brush; CSG with the
//! stencil buffer; Phong highlights through a texture; reflections with the stencil buffer and
//! a clip plane; a particle system.
//!
//! What each teaches and which GL state does it is in `TECHNIQUE_TEXTS` of
//! `conformance/src/scenes_techniques.rs`, and on the gallery page (`cargo run --release`
//! writes `out/index.html`).
//!
//! Run: `cargo run --release -p tilegl-conformance --example techniques [OUT_DIR]`
//! (default `out/techniques/`): each scene on tilegl and, where Mesa's OSMesa is installed, on
//! Mesa, written as `SCENE-tilegl.png`, `SCENE-mesa.png`, `SCENE-diff.png` and the stages, with
//! the difference and the times printed. `tests/differential_techniques.rs` checks the same
//! scenes against Mesa.

fn main() {
    let names: Vec<&str> = tilegl_conformance::scenes_techniques::TECHNIQUE_SCENES
        .iter()
        .map(|s| s.name)
        .collect();
    tilegl_conformance::example_support::run("techniques", &names);
}
