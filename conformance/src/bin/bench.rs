//! `cargo run --release -p tilegl-conformance --bin bench [-- --frames N --triangles N]`:
//! the triangle benchmark (see `tilegl_conformance::bench`).

fn main() {
    std::process::exit(tilegl_conformance::bench::run_cli());
}
