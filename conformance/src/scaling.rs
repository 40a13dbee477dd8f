//! `bench --scaling`: how the time per frame grows with the work, on tilegl and on Mesa
//! llvmpipe. Two series: pixels (a full-window trilinear-textured quad drawn 4 times, at
//! window sizes from 128x128 to 1024x1024) and triangles (N small lit triangles in one
//! window, N from 10k to 160k). Each is fitted with a least-squares line; the report gives the
//! slope, the intercept and R^2, and a chart per series (`target/bench/scaling-*.png`).

use std::path::Path;
use std::time::{Duration, Instant};

use plotters::prelude::*;
use tilegl::enums::*;
use tilegl::Gl;

use crate::mesa::{MesaContext, Oracle};
use crate::quality::{register_font, texture, tilegl_context};

/// A least-squares line y = slope * x + intercept and its coefficient of determination.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fit {
    pub slope: f64,
    pub intercept: f64,
    pub r2: f64,
}

/// Fits `points` (x, y) with a line; `None` for fewer than two distinct x.
pub fn fit(points: &[(f64, f64)]) -> Option<Fit> {
    let n = points.len() as f64;
    let (sx, sy) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x, b + y));
    let (mx, my) = (sx / n, sy / n);
    let sxx: f64 = points.iter().map(|&(x, _)| (x - mx) * (x - mx)).sum();
    let sxy: f64 = points.iter().map(|&(x, y)| (x - mx) * (y - my)).sum();
    let syy: f64 = points.iter().map(|&(_, y)| (y - my) * (y - my)).sum();
    if points.len() < 2 || sxx == 0.0 {
        return None;
    }
    let slope = sxy / sxx;
    let intercept = my - slope * mx;
    let r2 = if syy == 0.0 {
        1.0
    } else {
        (sxy * sxy) / (sxx * syy)
    };
    Some(Fit {
        slope,
        intercept,
        r2,
    })
}

/// One series: what x counts, and the measured points per implementation.
pub struct Series {
    pub title: &'static str,
    pub x_desc: &'static str,
    pub tilegl: Vec<(f64, f64)>,
    pub llvmpipe: Vec<(f64, f64)>,
}

fn median_ms(gl: &mut dyn Gl, frame: &mut dyn FnMut(&mut dyn Gl), min_time: Duration) -> f64 {
    frame(gl);
    gl.finish();
    let mut t = Vec::new();
    let start = Instant::now();
    while t.len() < 3 || (start.elapsed() < min_time && t.len() < 100) {
        let s = Instant::now();
        frame(gl);
        gl.finish();
        t.push(s.elapsed().as_secs_f64() * 1000.0);
    }
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}

fn quads(gl: &mut dyn Gl) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for i in 0..4 {
        let z = -0.5 + 0.1 * i as f32;
        gl.begin(GL_QUADS);
        gl.tex_coord_2f(0.0, 0.0);
        gl.vertex_3f(-1.0, -1.0, z);
        gl.tex_coord_2f(3.0, 0.0);
        gl.vertex_3f(1.0, -1.0, z);
        gl.tex_coord_2f(3.0, 3.0);
        gl.vertex_3f(1.0, 1.0, z);
        gl.tex_coord_2f(0.0, 3.0);
        gl.vertex_3f(-1.0, 1.0, z);
        gl.end();
    }
}

fn triangles(gl: &mut dyn Gl, n: usize) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    let side = (n as f64).sqrt().ceil() as usize;
    let step = 2.0 / side as f32;
    gl.begin(GL_TRIANGLES);
    for i in 0..n {
        let (x, y) = (
            -1.0 + step * (i % side) as f32,
            -1.0 + step * (i / side) as f32,
        );
        gl.normal_3f(0.0, 0.2, 1.0);
        gl.vertex_3f(x, y, 0.0);
        gl.normal_3f(0.2, 0.0, 1.0);
        gl.vertex_3f(x + step, y, 0.0);
        gl.normal_3f(0.0, 0.0, 1.0);
        gl.vertex_3f(x, y + step, 0.0);
    }
    gl.end();
}

fn setup_quads(gl: &mut dyn Gl) {
    texture(gl, 256, GL_RGBA8, false);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_DEPTH_TEST);
}

fn setup_lit(gl: &mut dyn Gl) {
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_DEPTH_TEST);
}

/// Measures both series on tilegl (default threads) and, when `with_mesa`, llvmpipe.
pub fn measure(min_time: Duration, with_mesa: bool) -> Vec<Series> {
    let sizes = [128, 256, 384, 512, 768, 1024];
    let counts = [10_000usize, 20_000, 40_000, 80_000, 160_000];
    let mut pixels = Series {
        title: "Time against pixels (4 full-window trilinear quads)",
        x_desc: "pixels per frame (millions)",
        tilegl: Vec::new(),
        llvmpipe: Vec::new(),
    };
    for &s in &sizes {
        let x = 4.0 * (s * s) as f64 / 1e6;
        let mut t = tilegl_context(s, 0);
        setup_quads(&mut t);
        pixels
            .tilegl
            .push((x, median_ms(&mut t, &mut |g| quads(g), min_time)));
        if with_mesa {
            if let Ok(mut m) = MesaContext::create(s, s) {
                setup_quads(&mut *m);
                pixels
                    .llvmpipe
                    .push((x, median_ms(&mut *m, &mut |g| quads(g), min_time)));
            }
        }
    }
    let mut tris = Series {
        title: "Time against triangles (small lit triangles, 512x512)",
        x_desc: "triangles per frame (thousands)",
        tilegl: Vec::new(),
        llvmpipe: Vec::new(),
    };
    for &n in &counts {
        let x = n as f64 / 1000.0;
        let mut t = tilegl_context(512, 0);
        setup_lit(&mut t);
        tris.tilegl
            .push((x, median_ms(&mut t, &mut |g| triangles(g, n), min_time)));
        if with_mesa {
            if let Ok(mut m) = MesaContext::create(512, 512) {
                setup_lit(&mut *m);
                tris.llvmpipe
                    .push((x, median_ms(&mut *m, &mut |g| triangles(g, n), min_time)));
            }
        }
    }
    vec![pixels, tris]
}

/// Draws `s` (points and fitted lines of both implementations) into `path` (900x560 PNG).
pub fn chart(s: &Series, path: &Path) -> Result<(), String> {
    register_font()?;
    let e = |e: &dyn std::fmt::Display| e.to_string();
    let all = s.tilegl.iter().chain(&s.llvmpipe);
    let max_x = all.clone().map(|p| p.0).fold(0.0, f64::max) * 1.1;
    let max_y = all.map(|p| p.1).fold(0.1, f64::max) * 1.3;
    let root = BitMapBackend::new(path, (900, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    let mut c = ChartBuilder::on(&root)
        .caption(s.title, ("sans-serif", 22))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(64)
        .build_cartesian_2d(0.0..max_x, 0.0..max_y)
        .map_err(|x| e(&x))?;
    c.configure_mesh()
        .x_desc(s.x_desc)
        .y_desc("time per frame (ms, median)")
        .axis_desc_style(("sans-serif", 16))
        .draw()
        .map_err(|x| e(&x))?;
    for (points, colour, name) in [
        (&s.tilegl, BLUE, "tilegl"),
        (&s.llvmpipe, RED, "Mesa llvmpipe"),
    ] {
        if points.is_empty() {
            continue;
        }
        let label = match fit(points) {
            Some(f) => format!("{name}: {:.3} ms per unit, R² {:.3}", f.slope, f.r2),
            None => name.to_string(),
        };
        c.draw_series(points.iter().map(|&p| Circle::new(p, 5, colour.filled())))
            .map_err(|x| e(&x))?
            .label(label)
            .legend(move |(x, y)| Circle::new((x + 10, y), 5, colour.filled()));
        if let Some(f) = fit(points) {
            c.draw_series(LineSeries::new(
                [0.0, max_x].map(|x| (x, f.intercept + f.slope * x)),
                colour.stroke_width(1),
            ))
            .map_err(|x| e(&x))?;
        }
    }
    c.configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .label_font(("sans-serif", 15))
        .draw()
        .map_err(|x| e(&x))?;
    root.present().map_err(|x| e(&x))
}

/// `bench --scaling`: measures, prints the points and fits, writes the charts into `dir`.
pub fn run(dir: &Path, with_mesa: bool) -> i32 {
    let series = measure(Duration::from_millis(300), with_mesa);
    if let Err(e) = std::fs::create_dir_all(dir) {
        eprintln!("{}: {e}", dir.display());
        return 2;
    }
    for (i, s) in series.iter().enumerate() {
        println!("== {}", s.title);
        for (name, pts) in [("tilegl", &s.tilegl), ("llvmpipe", &s.llvmpipe)] {
            let list: Vec<String> = pts
                .iter()
                .map(|p| format!("{:.2}: {:.2} ms", p.0, p.1))
                .collect();
            println!("{name:<9} {}", list.join(", "));
            if let Some(f) = fit(pts) {
                println!(
                    "{name:<9} fit: {:.3} ms per unit + {:.2} ms, R^2 {:.3}",
                    f.slope, f.intercept, f.r2
                );
            }
        }
        let path = dir.join(if i == 0 {
            "scaling-pixels.png"
        } else {
            "scaling-triangles.png"
        });
        match chart(s, &path) {
            Ok(()) => println!("chart: {}", path.display()),
            Err(e) => {
                eprintln!("chart not written: {e}");
                return 2;
            }
        }
    }
    0
}
