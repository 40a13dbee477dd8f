//! `cargo bench -p tilegl-conformance --bench triangles`: the triangle benchmark, tilegl
//! (1 and 2 threads) side by side with Mesa llvmpipe and softpipe (see
//! `tilegl_conformance::bench`).

fn main() {
    std::process::exit(tilegl_conformance::bench::run_cli());
}
