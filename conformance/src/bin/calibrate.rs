//! `cargo run --release -p tilegl-conformance --bin calibrate`: measures how far Mesa llvmpipe
//! and softpipe differ on every differential scene (the driver of this process against the
//! other one, rendered in a child process), and how far tilegl is from each, as a Markdown table
//! for `conformance/TOLERANCE.md`. `--filter PREFIX` (repeatable) limits it to the scenes whose
//! names start with PREFIX; `--dump DIR` also writes the pictures.

use tilegl_conformance::compare::{self, diff, Diff};
use tilegl_conformance::mesa;
use tilegl_conformance::scenes::SCENES;

fn cells(d: &Diff, b2: &Diff, b24: &Diff) -> String {
    format!(
        "{} | {:.3} | {:.2} | {:.3} | {:.3} | {:.3}",
        d.max,
        d.mean,
        d.psnr,
        b2.bad_share * 100.0,
        d.bad_share * 100.0,
        b24.bad_share * 100.0
    )
}

fn main() {
    if compare::serve_child_request(&SCENES) {
        return;
    }
    if let Err(e) = mesa::mesa_available() {
        eprintln!("calibrate: {e}");
        std::process::exit(1);
    }
    // `--dump DIR`: also write the three pictures of every scene as PPM files.
    let args: Vec<String> = std::env::args().collect();
    let dump = args
        .iter()
        .position(|a| a == "--dump")
        .and_then(|i| args.get(i + 1))
        .map(std::path::PathBuf::from);
    // `--filter PREFIX`: only the scenes whose name starts with PREFIX (repeatable).
    let filters: Vec<&str> = args
        .iter()
        .enumerate()
        .filter(|(_, a)| *a == "--filter")
        .filter_map(|(i, _)| args.get(i + 1).map(String::as_str))
        .collect();
    let mut here = String::new();
    let mut other = String::new();
    let mut worst_bad8: f64 = 0.0;
    let mut worst_bad24: f64 = 0.0;
    let mut worst_max = 0u8;
    let mut rows = Vec::new();
    for scene in SCENES
        .iter()
        .filter(|s| filters.is_empty() || filters.iter().any(|f| s.name.starts_with(f)))
    {
        let (m, info) = match compare::render_mesa(scene) {
            Ok(x) => x,
            Err(e) => {
                eprintln!("{}: {e}", scene.name);
                std::process::exit(1);
            }
        };
        here = info.to_string();
        let other_driver = if info.driver() == "softpipe" {
            "llvmpipe"
        } else {
            "softpipe"
        };
        let (o, renderer) = match compare::render_scene_with_driver(other_driver, scene, &[]) {
            Ok(x) => x,
            Err(e) => {
                eprintln!("{}: {e}", scene.name);
                std::process::exit(1);
            }
        };
        other = renderer;
        let t = compare::render_tilegl(scene);
        if let Some(dir) = &dump {
            let _ = std::fs::create_dir_all(dir);
            let n = scene.name;
            let _ = m
                .image
                .write_ppm(&dir.join(format!("{n}-{}.ppm", info.driver())));
            let _ = o.write_ppm(&dir.join(format!("{n}-{other_driver}.ppm")));
            let _ = t.image.write_ppm(&dir.join(format!("{n}-tilegl.ppm")));
        }
        let dd = |a, b| (diff(a, b, 8), diff(a, b, 2), diff(a, b, 24));
        let (m8, m2, m24) = dd(&m.image, &o);
        let (t8, t2, t24) = dd(&t.image, &m.image);
        let (u8_, u2, u24) = dd(&t.image, &o);
        worst_bad8 = worst_bad8.max(m8.bad_share);
        worst_bad24 = worst_bad24.max(m24.bad_share);
        worst_max = worst_max.max(m8.max);
        rows.push(format!(
            "| {} | {} | {} | {} |",
            scene.name,
            cells(&m8, &m2, &m24),
            cells(&t8, &t2, &t24),
            cells(&u8_, &u2, &u24)
        ));
    }
    println!("In-process Mesa: {here}; child: {other}");
    println!();
    println!(
        "Columns per pair: max | mean | PSNR dB | bad% >2 | bad% >8 | bad% >24. Pairs: \
         Mesa(this process) vs Mesa(other driver) | tilegl vs Mesa(this process) | tilegl vs \
         Mesa(other driver)."
    );
    println!();
    let h = "max | mean | PSNR | bad>2 | bad>8 | bad>24";
    println!("| scene | {h} | {h} | {h} |");
    println!("|---|{}", "---:|".repeat(18));
    for r in rows {
        println!("{r}");
    }
    println!();
    println!(
        "driver vs driver worst: max {worst_max}, bad% >8 {:.3}, bad% >24 {:.3}",
        worst_bad8 * 100.0,
        worst_bad24 * 100.0
    );
}
