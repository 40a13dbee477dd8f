//! `bench --scaling`'s pieces that do not depend on timing: the least-squares fit against
//! lines and data computed in the test, and the chart written from given points.

use std::path::Path;

use tilegl_conformance::quality::FONT;
use tilegl_conformance::scaling::{chart, fit, Series};

#[test]
fn the_fit_recovers_lines_and_measures_their_spread() {
    let exact: Vec<(f64, f64)> = (0..6).map(|i| (i as f64, 2.5 * i as f64 + 4.0)).collect();
    let f = fit(&exact).unwrap();
    assert!((f.slope - 2.5).abs() < 1e-12 && (f.intercept - 4.0).abs() < 1e-12);
    assert!((f.r2 - 1.0).abs() < 1e-12);
    // y = x with alternating +-1 noise over x = 0..9: slope and R^2 computed by hand.
    let noisy: Vec<(f64, f64)> = (0..10)
        .map(|i| (i as f64, i as f64 + if i % 2 == 0 { 1.0 } else { -1.0 }))
        .collect();
    let f = fit(&noisy).unwrap();
    // sxx = 82.5, sxy = 82.5 - 5 = 77.5 (the noise's covariance with x is -5), syy = 82.5 - 10 + 10 = 82.5
    assert!((f.slope - 77.5 / 82.5).abs() < 1e-12, "{f:?}");
    assert!((f.r2 - 77.5 * 77.5 / (82.5 * 82.5)).abs() < 1e-12, "{f:?}");
    assert!(fit(&[(1.0, 2.0)]).is_none());
    assert!(fit(&[(1.0, 2.0), (1.0, 3.0)]).is_none());
}

#[test]
fn the_chart_is_drawn_from_the_points() {
    if !Path::new(FONT).is_file() {
        assert!(
            std::env::var("CI").map_or(true, |v| v != "true"),
            "CI=true and the chart font {FONT} is missing"
        );
        return;
    }
    let s = Series {
        title: "test series",
        x_desc: "units",
        tilegl: vec![(1.0, 2.0), (2.0, 3.9), (4.0, 8.1)],
        llvmpipe: vec![(1.0, 3.0), (2.0, 5.0), (4.0, 9.0)],
    };
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("scaling-test.png");
    chart(&s, &path).unwrap();
    let img = image::open(&path).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (900, 560));
    let blue = img.pixels().filter(|p| p.0 == [0, 0, 255]).count();
    let red = img.pixels().filter(|p| p.0 == [255, 0, 0]).count();
    assert!(
        blue > 50 && red > 50,
        "blue {blue}, red {red}: both series drawn"
    );
}
