//! The eight-lane filter (`tilegl::texture::simd::filter8` and `filter8_mix`: texel pairs read
//! as 64-bit elements, the 2x2 footprint's lerps in 16-bit lanes, two levels mixed before the
//! bytes are packed) against the scalar sampler (`BoundTexture::sample`, the general route:
//! `fixed::filter_image` and `fixed::lerp4` per pixel), bit for bit, over random texture
//! sizes (powers of two and not, 1 to 64 texels a side), every one-byte base format the
//! filter takes, `REPEAT` and `CLAMP_TO_EDGE` per axis, NEAREST and LINEAR, single levels and
//! mixes of two, and random coordinates (texel centres and edges, wrapped several times,
//! negative, near the 32-bit index limit).

use tilegl::enums::*;
use tilegl::texture::sample::LevelPlan;
use tilegl::texture::simd::{filter8, filter8_mix, Level8};
use tilegl::{Context, Gl};

fn xorshift(seed: &mut u64) -> u64 {
    *seed ^= *seed << 13;
    *seed ^= *seed >> 7;
    *seed ^= *seed << 17;
    *seed
}

/// A coordinate on an axis of `size` texels: texel centres and edges (where the weight is 0
/// or the index steps), fractions of them, a few periods either side, the first texels
/// (whose pair reads start near the level's first byte), and huge values.
fn coord(seed: &mut u64, size: i32) -> f32 {
    let r = xorshift(seed);
    let n = size as f32;
    let k = ((r >> 8) % (8 * size as u64 + 1)) as f32 - 4.0 * n;
    let unit = (r >> 16) as u32 as f32 / u32::MAX as f32;
    match r % 64 {
        0 => (unit - 0.5) * 1e7,
        1 => (unit - 0.5) * 1e4,
        2..=13 => (k + 0.5) / n,
        14..=25 => k / n,
        26..=37 => (k + ((r >> 40) % 256) as f32 / 256.0) / n,
        38..=45 => ((r >> 20) % 3) as f32 / (2.0 * n) + ((r >> 30) % 2) as f32 * 1e-7,
        _ => unit * 6.0 - 3.0,
    }
}

/// One case: a `w` x `h` texture of `format` with random bytes and a full mipmap chain,
/// wrapped by `wrap`, every level and every level pair filtered at random coordinates by the
/// eight-lane filter and by the sampler. Returns the groups compared.
fn check(seed: &mut u64, format: GLenum, w: i32, h: i32, wrap: [GLenum; 2]) -> usize {
    let comps = match format {
        GL_RGBA => 4,
        GL_RGB => 3,
        GL_LUMINANCE_ALPHA => 2,
        _ => 1,
    };
    let bytes: Vec<u8> = (0..w * h * comps)
        .map(|_| (xorshift(seed) >> 24) as u8)
        .collect();
    let mut gl = Context::new(8, 8);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        format as i32,
        w,
        h,
        0,
        if format == GL_INTENSITY {
            GL_LUMINANCE
        } else {
            format
        },
        GL_UNSIGNED_BYTE,
        Some(&bytes),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap[0] as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap[1] as i32);
    gl.enable(GL_TEXTURE_2D);
    let modes = |gl: &mut Context, min: GLenum, mag: GLenum| {
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag as i32);
        gl.bound_texture(0).expect("complete texture")
    };
    let mut groups = 0;
    for linear in [false, true] {
        let mag = if linear { GL_LINEAR } else { GL_NEAREST };
        let (one, two) = if linear {
            (GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_LINEAR)
        } else {
            (GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST_MIPMAP_LINEAR)
        };
        for mix in [false, true] {
            let tex = modes(&mut gl, if mix { two } else { one }, mag);
            let wrap_st = tex.wrap_st();
            let base = tex.base_format();
            let count = tex.level_count();
            let level8 = |l: usize| {
                let fast = tex.fast_level(l).expect("byte level");
                let lvl = Level8::new(&fast, wrap_st, base);
                let [lw, lh] = fast.size();
                let npot_repeat = |d: usize, n: i64| wrap[d] == GL_REPEAT && n & (n - 1) != 0;
                assert_eq!(lvl.is_none(), npot_repeat(0, lw) || npot_repeat(1, lh));
                lvl.map(|v| (v, [lw as i32, lh as i32]))
            };
            for l in 0..count - usize::from(mix) {
                let Some((l1, [lw, lh])) = level8(l) else {
                    continue;
                };
                let l2 = if mix { level8(l + 1) } else { None };
                if mix && l2.is_none() {
                    continue;
                }
                for _ in 0..24 {
                    let (mut s, mut t) = ([0f32; 8], [0f32; 8]);
                    for j in 0..8 {
                        s[j] = coord(seed, lw);
                        t[j] = coord(seed, lh);
                    }
                    // Level l alone: λ = l (level 0: magnification); a mix: λ = l + f, f per
                    // lane.
                    let mut lambda = [l as f32; 8];
                    let mut weight = [0f32; 8];
                    let mut magnified = false;
                    for j in 0..8 {
                        let f = match xorshift(seed) % 3 {
                            0 => ((xorshift(seed) % 255) + 1) as f32 / 256.0,
                            _ => (xorshift(seed) % 1000 + 1) as f32 / 1002.0,
                        };
                        if mix {
                            lambda[j] += f;
                        }
                        match tex.level_plan(lambda[j]) {
                            LevelPlan::Two {
                                levels,
                                linear: lin,
                                weight: w,
                            } if mix => {
                                assert_eq!((levels, lin), ([l, l + 1], linear));
                                weight[j] = w;
                            }
                            LevelPlan::One { level, linear: lin } if !mix => {
                                assert_eq!((level, lin), (l, linear));
                            }
                            // A mix at λ <= c is magnification: not this case.
                            _ => magnified = true,
                        }
                    }
                    if magnified {
                        continue;
                    }
                    let got = match &l2 {
                        Some((l2, _)) => filter8_mix([&l1, l2], linear, &s, &t, &weight),
                        None => filter8(&l1, linear, &s, &t),
                    };
                    let Some(got) = got else {
                        // Only for coordinates past the 32-bit index range.
                        let far = |v: f32, n: i32| (v * n as f32 * 256.0).abs() >= 1e9;
                        assert!(
                            (0..8).any(|j| far(s[j], lw) || far(t[j], lh)),
                            "refused {s:?} {t:?}"
                        );
                        continue;
                    };
                    groups += 1;
                    for j in 0..8 {
                        let want = tex.sample([s[j], t[j], 0.0], lambda[j]);
                        for c in 0..4 {
                            assert_eq!(
                                got[c][j].to_bits(),
                                want[c].to_bits(),
                                "format {format:#x} {w}x{h} wrap {wrap:x?} level {l} mix {mix} \
                                 linear {linear} lane {j} (s, t) = ({}, {}) λ {}: \
                                 got {:?} want {want:?}",
                                s[j],
                                t[j],
                                lambda[j],
                                [got[0][j], got[1][j], got[2][j], got[3][j]],
                            );
                        }
                    }
                }
            }
        }
    }
    groups
}

#[test]
fn eight_lane_filter_matches_the_sampler() {
    if !is_x86_feature_detected!("avx2") {
        return;
    }
    let formats = [
        GL_RGBA,
        GL_RGB,
        GL_LUMINANCE_ALPHA,
        GL_LUMINANCE,
        GL_INTENSITY,
        GL_ALPHA,
    ];
    let sizes = [1, 2, 3, 4, 5, 7, 8, 16, 17, 32, 64];
    let wraps = [GL_REPEAT, GL_CLAMP_TO_EDGE];
    let mut seed = 0x9E37_79B9_7F4A_7C15u64;
    let mut groups = 0;
    for case in 0..240 {
        let format = formats[case % formats.len()];
        let w = sizes[(xorshift(&mut seed) % sizes.len() as u64) as usize];
        let h = sizes[(xorshift(&mut seed) % sizes.len() as u64) as usize];
        let wrap = [
            wraps[(xorshift(&mut seed) % 2) as usize],
            wraps[(xorshift(&mut seed) % 2) as usize],
        ];
        groups += check(&mut seed, format, w, h, wrap);
    }
    // Most cases are filtered eight lanes at a time, not refused.
    assert!(groups > 10_000, "{groups} groups compared");
}
