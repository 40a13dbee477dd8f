//! Projective texturing: a slide projector shining a picture onto a scene.
//!
//! What it teaches (Segal et al. 1992, "Fast shadows and lighting effects using texture
//! mapping"; GL 1.5 sections 2.11.4 and 3.8):
//! - Eye-linear texgen with the identity planes (S = (1,0,0,0), T = (0,1,0,0), R, Q likewise),
//!   specified while the modelview holds the camera's viewing transform V, generates
//!   (s, t, r, q) = the vertex's *world* position: GL stores eye planes multiplied by the inverse
//!   of the modelview at `glTexGen` time, which cancels V.
//! - The texture matrix then holds the projector like a camera: bias and scale [-1, 1] to [0, 1]
//!   (`glTranslatef(0.5, 0.5, 0.5)`, `glScalef(0.5, 0.5, 0.5)`), the projector's frustum
//!   (`gluPerspective`) and its viewing transform (`gluLookAt`).
//! - Texture lookups divide by q: (s/q, t/q) is where the projector's ray through the point hits
//!   the slide, interpolated perspective-correctly per fragment.
//! - `GL_CLAMP_TO_BORDER` with a grey border colour makes everything outside the slide dim;
//!   `GL_MODULATE` multiplies the slide into the lit colour.
//!
//! Stage: the slide.
//!
//! Run: `cargo run --release -p tilegl-conformance --example projective_texture [OUT_DIR]`
//! (default `out/projective_texture/`). The scene `ex_projective_texture` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. The example writes `tilegl.png`, `mesa.png`, `diff.png` (the difference
//! x 8) and the intermediate stages (`stageNN-*-tilegl.png`, `stageNN-*-mesa.png`),
//! and prints the difference (PSNR, largest channel difference, share of pixels off by more
//! than 8), the time each side took, and how far Mesa's llvmpipe and softpipe drivers differ
//! on the same calls. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("projective_texture", &["ex_projective_texture"]);
}
