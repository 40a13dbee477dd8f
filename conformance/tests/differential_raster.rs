//! Differential tests of the rasterization controls (scenes in
//! `tilegl_conformance::scenes_raster`): point size and parameters, wide, stippled and
//! antialiased lines, polygon modes, edge flags, polygon offset and stipple.

use tilegl_conformance::scenes_raster::RASTER_SCENES;

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn raster_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("RASTER_SCENES", RASTER_SCENES);
}

/// Mesa 22 draws `GL_POINT_SMOOTH` points as discs without coverage: every pixel whose centre
/// lies within max(size / 2, 1) of the point takes the full colour (llvmpipe and softpipe
/// alike). With `SmoothPoints::Discs` (the replay player's default, so that captures recorded
/// on Mesa replay to Mesa's pictures) tilegl must give both drivers' pictures exactly, and the
/// discs must be those of the rule, computed here.
#[test]
fn smooth_point_discs_match_mesa_exactly() {
    use tilegl::{Context, ContextConfig, SmoothPoints};
    use tilegl_conformance::compare::{diff, render_scene_with_driver, run_scene};
    use tilegl_conformance::scenes;
    use tilegl_conformance::scenes_raster::SMOOTH_POINT_SIZES;

    let scene = scenes::find("smooth_point_sizes").expect("scene");
    if tilegl_conformance::compare::serve_child_request(&scenes::SCENES) {
        return;
    }
    let mut ctx = Context::with_config(ContextConfig {
        width: scene.width,
        height: scene.height,
        ..ContextConfig::default()
    });
    ctx.set_smooth_points(SmoothPoints::Discs);
    let ours = run_scene(&mut ctx, scene);
    assert_eq!(ours.error, 0, "glGetError");

    // The rule, point by point (cells are far enough apart), over the scene's clear colour.
    let bg = [0.1f32, 0.1, 0.15].map(|c| (c * 255.0).round() as u8);
    for (i, size) in SMOOTH_POINT_SIZES.iter().enumerate() {
        let (col, row) = ((i % 5) as f32, (i / 5) as f32);
        let cx = 6.4 + 12.8 * col + ((i as f32 * 0.37).fract() - 0.5);
        let cy = 6.4 + 12.8 * row + ((i as f32 * 0.61).fract() - 0.5);
        let r = (f64::from(*size) / 2.0).max(1.0);
        let (x0, y0) = ((12.8 * col) as i32, (12.8 * row) as i32);
        for y in y0..y0 + 12 {
            for x in x0..x0 + 12 {
                let (dx, dy) = (
                    f64::from(x) + 0.5 - f64::from(cx),
                    f64::from(y) + 0.5 - f64::from(cy),
                );
                let lit = ours.image.pixel(x, y)[..3] != bg;
                // Pixels exactly on the circle may go either way (single-precision centres).
                let d = (dx * dx + dy * dy).sqrt();
                if (d - r).abs() > 1e-4 {
                    assert_eq!(
                        lit,
                        d < r,
                        "size {size}: pixel ({x}, {y}) at {d:.4} from the centre, radius {r}"
                    );
                }
            }
        }
    }

    if !tilegl_conformance::mesa::require_mesa("smooth_point_discs_match_mesa_exactly") {
        return;
    }
    for driver in ["llvmpipe", "softpipe"] {
        let (mesa, renderer) = render_scene_with_driver(
            driver,
            scene,
            &[
                "smooth_point_discs_match_mesa_exactly",
                "--exact",
                "--nocapture",
            ],
        )
        .unwrap_or_else(|e| panic!("{driver}: {e}"));
        assert!(
            renderer.contains(driver),
            "asked for {driver}, the child ran {renderer}"
        );
        let lit = (0..64 * 64)
            .filter(|i| mesa.pixel(i % 64, i / 64)[..3] != bg)
            .count();
        assert!(lit > 300, "{driver} drew {lit} pixels");
        let d = diff(&ours.image, &mesa, 0);
        assert_eq!(d.bad_pixels, 0, "{driver}: {d}");
    }
}
