//! S3TC (DXT) block compression versus the original texture.
//!
//! What it teaches (EXT_texture_compression_s3tc):
//! - DXT stores each 4x4 block of texels in 8 bytes (DXT1) or 16 (DXT5): two RGB565 endpoint
//!   colours and a 2-bit index per texel choosing one of four colours on the line between
//!   them; DXT5 adds two 8-bit alpha endpoints and a 3-bit index per texel (eight alpha levels).
//!   4 or 8 bits per texel instead of 32, decoded by the sampler.
//! - Smooth gradients inside a block survive; blocks holding several unrelated colours get
//!   them replaced by points on one line (the artefacts in the middle panel). DXT1 has at most
//!   a 1-bit alpha (here opaque), DXT5 keeps the soft alpha disc (right panel).
//! - The blocks are built by the scene with a simple encoder (darkest and brightest texels as
//!   endpoints) and uploaded with `glCompressedTexImage2D`, so tilegl and Mesa decode the same
//!   bytes; how to encode is left to implementations (uploading uncompressed data with a
//!   compressed internal format makes the driver encode).
//!
//! Stages: the three textures as `glGetTexImage` returns them (decoded).
//!
//! Run: `cargo run --release -p tilegl-conformance --example dxt_compression [OUT_DIR]`
//! (default `out/dxt_compression/`). The scene `ex_dxt_compression` (in
//! `conformance/src/scenes_examples.rs`) is rendered on tilegl and, where Mesa's OSMesa is
//! installed, on Mesa. `tests/differential_examples.rs` checks the same scene against Mesa.

fn main() {
    tilegl_conformance::example_support::run("dxt_compression", &["ex_dxt_compression"]);
}
