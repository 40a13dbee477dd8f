//! `cargo run -p tilegl-conformance --bin scene_diff -- NAME...`: renders differential scenes
//! on tilegl and Mesa, prints the comparison and a map of the differing pixels (`.` equal,
//! digits: the largest channel difference / 26), and writes both pictures as PPM files into
//! `target/scene_diff/` for a closer look.

use tilegl_conformance::compare;
use tilegl_conformance::scenes::{find, SCENES};

fn main() {
    if compare::serve_child_request(&SCENES) {
        return;
    }
    let names: Vec<String> = std::env::args().skip(1).collect();
    if names.is_empty() {
        eprintln!("usage: scene_diff NAME...");
        std::process::exit(2);
    }
    for name in names {
        let Some(scene) = find(&name) else {
            eprintln!("no scene {name}");
            std::process::exit(2);
        };
        let c = match compare::compare_scene(scene, scene.tolerance) {
            Ok(c) => c,
            Err(e) => {
                eprintln!("{name}: {e}");
                std::process::exit(1);
            }
        };
        println!("{}", c.summary());
        // The first differing pixel, all four channels.
        'find: for y in 0..scene.height {
            for x in 0..scene.width {
                let (a, b) = (c.tilegl.image.pixel(x, y), c.mesa.image.pixel(x, y));
                if a != b {
                    println!("first difference at ({x}, {y}): tilegl {a:?}, mesa {b:?}");
                    break 'find;
                }
            }
        }
        for y in (0..scene.height).rev() {
            let row: String = (0..scene.width)
                .map(|x| {
                    let (a, b) = (c.tilegl.image.pixel(x, y), c.mesa.image.pixel(x, y));
                    let d = (0..4).map(|k| a[k].abs_diff(b[k])).max().unwrap_or(0);
                    match d {
                        0 => '.',
                        d => char::from_digit((d as u32 / 26).min(9), 10).unwrap_or('9'),
                    }
                })
                .collect();
            println!("{row}");
        }
        if let Err(e) = c.dump(std::path::Path::new("target/scene_diff")) {
            eprintln!("cannot write pictures: {e}");
        }
    }
}
