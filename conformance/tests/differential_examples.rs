//! Differential tests of the teaching examples' scenes (`tilegl_conformance::scenes_examples`,
//! run by `examples/*.rs`), under each scene's tolerance.

use tilegl_conformance::scenes_examples::EXAMPLE_SCENES;

/// Every scene of the list against Mesa, one line per scene, all failures listed at the end
/// (`TILEGL_CASE=NAME` runs only the scenes whose names contain NAME).
#[test]
fn example_scenes_agree_with_mesa() {
    tilegl_conformance::run_differential_list("EXAMPLE_SCENES", EXAMPLE_SCENES);
}

/// Recording the stages, as the examples do, must not change the pictures: the `snap_*` calls
/// only read back (`glReadPixels`, `glGetTexImage`, `glGetTexLevelParameteriv`). Checked on
/// tilegl, and on Mesa where it is installed.
#[test]
fn recording_stages_changes_nothing() {
    use tilegl_conformance::{compare, example_support, mesa};
    let mesa_ok = mesa::mesa_available().is_ok();
    for scene in EXAMPLE_SCENES {
        let plain = compare::render_tilegl(scene);
        let (recorded, stages) = example_support::record(|| compare::render_tilegl(scene));
        assert_eq!(
            plain.image, recorded.image,
            "{}: picture changed",
            scene.name
        );
        assert_eq!(plain.error, recorded.error, "{}", scene.name);
        for s in &stages {
            let i = &s.image;
            assert_eq!(
                i.pixels.len(),
                (i.width * i.height * 4) as usize,
                "{}",
                s.name
            );
        }
        if mesa_ok {
            let (plain, _) = compare::render_mesa(scene).unwrap();
            let (recorded, mesa_stages) =
                example_support::record(|| compare::render_mesa(scene).unwrap());
            assert_eq!(
                plain.image, recorded.0.image,
                "{}: Mesa picture",
                scene.name
            );
            let names = |v: &[example_support::Stage]| -> Vec<String> {
                v.iter().map(|s| s.name.clone()).collect()
            };
            assert_eq!(names(&stages), names(&mesa_stages), "{}", scene.name);
        }
    }
}

#[test]
fn multipass_scenes_record_their_stages() {
    use tilegl_conformance::{compare, example_support, scenes};
    let stages = |name: &str| -> Vec<String> {
        let scene = scenes::find(name).unwrap();
        let (_, s) = example_support::record(|| compare::render_tilegl(scene));
        s.into_iter().map(|s| s.name).collect()
    };
    assert_eq!(
        stages("ex_emboss_bump"),
        ["height_map", "pass1_height", "pass2_embossed"]
    );
    assert_eq!(stages("ex_shadow_map"), ["light_view_depth", "shadow_map"]);
    assert_eq!(
        stages("ex_planar_reflection"),
        ["stencil_mirror", "reflection", "floor_blended"]
    );
    // Outside `record` nothing is kept.
    let scene = scenes::find("ex_emboss_bump").unwrap();
    let _ = compare::render_tilegl(scene);
    let (_, none) = example_support::record(|| ());
    assert!(none.is_empty());
}

/// The anisotropic panel of `ex_magnify_anisotropic`, checked against an independent route to
/// the ideal picture: the same plane rendered at 4x4 the resolution and box-filtered down
/// (each pixel the mean of 16 samples of its footprint). Anisotropic filtering must come closer
/// to it than trilinear filtering, which blurs the far plane.
#[test]
fn anisotropic_panel_is_closer_to_the_supersampled_plane_than_trilinear() {
    use tilegl::{Context, ContextConfig, Gl};
    use tilegl_conformance::compare::{diff, Image};
    use tilegl_conformance::scenes_examples::receding_checker;
    let render = |size: i32, aniso: f32| {
        let mut gl = Context::with_config(ContextConfig {
            width: size,
            height: size,
            ..ContextConfig::default()
        });
        gl.clear_color(0.3, 0.4, 0.6, 1.0);
        gl.clear(tilegl::enums::GL_COLOR_BUFFER_BIT);
        receding_checker(&mut gl, aniso);
        Image::read(&mut gl, size, size)
    };
    let big = render(512, 16.0);
    let mut reference = Image {
        width: 128,
        height: 128,
        pixels: vec![0; 128 * 128 * 4],
    };
    for y in 0..128usize {
        for x in 0..128usize {
            for c in 0..4 {
                let mut sum = 0u32;
                for dy in 0..4 {
                    for dx in 0..4 {
                        sum += big.pixels[((4 * y + dy) * 512 + 4 * x + dx) * 4 + c] as u32;
                    }
                }
                reference.pixels[(y * 128 + x) * 4 + c] = ((sum + 8) / 16) as u8;
            }
        }
    }
    let trilinear = diff(&render(128, 1.0), &reference, 24);
    let anisotropic = diff(&render(128, 16.0), &reference, 24);
    eprintln!(
        "against the supersampled plane: trilinear {:.2} dB, anisotropic 16x {:.2} dB",
        trilinear.psnr, anisotropic.psnr
    );
    assert!(
        anisotropic.psnr > trilinear.psnr + 3.0,
        "anisotropic {:.2} dB, trilinear {:.2} dB",
        anisotropic.psnr,
        trilinear.psnr
    );
}
