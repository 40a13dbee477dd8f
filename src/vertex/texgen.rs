//! Texture coordinate generation (section 2.11.4), per vertex, before the texture matrix.

use glam::{Vec3, Vec4};

use crate::common::values::TexGenMode;

/// Generation of one coordinate in a draw: the mode and the plane it uses (the object plane
/// for OBJECT_LINEAR, the eye plane for EYE_LINEAR).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GenCoord {
    pub mode: TexGenMode,
    pub plane: Vec4,
}

/// Replaces the enabled coordinates of `current` with generated ones. `eye` is the vertex in
/// eye coordinates and `eye_normal` its transformed normal.
pub fn generate(
    gen: &[Option<GenCoord>; 4],
    current: Vec4,
    object: Vec4,
    eye: Vec4,
    eye_normal: Vec3,
) -> Vec4 {
    let mut out = current.to_array();
    // The reflection vector r = u - 2 n (n . u), with u the unit vector from the eye to the
    // vertex (computed once, only when a mode needs it).
    let reflect = || {
        let e = if eye.w != 0.0 {
            eye.truncate() / eye.w
        } else {
            eye.truncate()
        };
        let u = e.normalize_or_zero();
        u - 2.0 * eye_normal * eye_normal.dot(u)
    };
    // The sphere map's r and m (shared by s and t).
    let sphere_of = |r: Vec3| {
        let m = 2.0 * (r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0)).sqrt();
        (r, m)
    };
    let sphere_coord = |c: f32, m: f32| if m > 0.0 { c / m + 0.5 } else { 0.5 };
    // The usual environment map (s and t by SPHERE_MAP, r and q as they are) without the
    // general loop's bookkeeping: the same arithmetic.
    if is_sphere_map(gen) {
        let (r, m) = sphere_of(reflect());
        out[0] = sphere_coord(r.x, m);
        out[1] = sphere_coord(r.y, m);
        return Vec4::from_array(out);
    }
    let mut reflection: Option<Vec3> = None;
    let mut r = || *reflection.get_or_insert_with(reflect);
    let mut sphere: Option<(Vec3, f32)> = None;
    for (i, g) in gen.iter().enumerate() {
        let Some(g) = g else { continue };
        out[i] = match g.mode {
            TexGenMode::ObjectLinear => g.plane.dot(object),
            TexGenMode::EyeLinear => g.plane.dot(eye),
            TexGenMode::SphereMap => {
                let (r, m) = *sphere.get_or_insert_with(|| sphere_of(r()));
                sphere_coord(if i == 0 { r.x } else { r.y }, m)
            }
            TexGenMode::ReflectionMap => r()[i],
            TexGenMode::NormalMap => eye_normal[i],
        };
    }
    Vec4::from_array(out)
}

/// Whether a unit's generation is the usual environment map (s and t by SPHERE_MAP, r and q as
/// they are): the case [`sphere_map8`] computes eight vertices at a time.
pub fn is_sphere_map(gen: &[Option<GenCoord>; 4]) -> bool {
    matches!(gen, [Some(s), Some(t), None, None]
        if s.mode == TexGenMode::SphereMap && t.mode == TexGenMode::SphereMap)
}

/// The sphere map's s and t of eight vertices (lanes) from their eye positions `eye` (x, y, z,
/// w) and eye normals `normal`: [`generate`]'s arithmetic, operation for operation in the same
/// order (IEEE division and square root are exact in every lane), so the same values. `None`
/// without AVX2. (The divisions and square roots of one vertex form a long dependency chain;
/// eight lanes at once instead of one vertex after another.)
pub fn sphere_map8(eye: &[[f32; 8]; 4], normal: &[[f32; 8]; 3]) -> Option<[[f32; 8]; 2]> {
    #[cfg(target_arch = "x86_64")]
    {
        if crate::common::cpu::available() {
            // SAFETY: AVX2 is present (checked just above).
            return Some(unsafe { x86::sphere_map8(eye, normal) });
        }
    }
    let _ = (eye, normal);
    None
}

#[cfg(target_arch = "x86_64")]
mod x86 {
    use std::arch::x86_64::*;

    #[target_feature(enable = "avx2")]
    pub fn sphere_map8(eye: &[[f32; 8]; 4], normal: &[[f32; 8]; 3]) -> [[f32; 8]; 2] {
        // SAFETY: every row holds eight f32; unaligned loads.
        let load = |row: &[f32; 8]| unsafe { _mm256_loadu_ps(row.as_ptr()) };
        let [ex, ey, ez, ew] = eye.each_ref().map(load);
        let [nx, ny, nz] = normal.each_ref().map(load);
        let zero = _mm256_setzero_ps();
        let (add, sub, mul, div) = (_mm256_add_ps, _mm256_sub_ps, _mm256_mul_ps, _mm256_div_ps);
        // e = eye.xyz / w where w != 0.
        let w_nonzero = _mm256_cmp_ps::<_CMP_NEQ_UQ>(ew, zero);
        let [ex, ey, ez] = [ex, ey, ez].map(|c| _mm256_blendv_ps(c, div(c, ew), w_nonzero));
        // u = e normalized (glam's normalize_or_zero: times 1 / length where that is finite
        // and positive, else 0).
        let dot = |a: [__m256; 3], b: [__m256; 3]| {
            add(add(mul(a[0], b[0]), mul(a[1], b[1])), mul(a[2], b[2]))
        };
        let rcp = div(
            _mm256_set1_ps(1.0),
            _mm256_sqrt_ps(dot([ex, ey, ez], [ex, ey, ez])),
        );
        let finite = _mm256_cmp_ps::<_CMP_LT_OQ>(
            _mm256_andnot_ps(_mm256_set1_ps(-0.0), rcp),
            _mm256_set1_ps(f32::INFINITY),
        );
        let usable = _mm256_and_ps(finite, _mm256_cmp_ps::<_CMP_GT_OQ>(rcp, zero));
        let u = [ex, ey, ez].map(|c| _mm256_and_ps(mul(c, rcp), usable));
        // r = u - (2 n) (n . u)
        let d = dot([nx, ny, nz], u);
        let two = _mm256_set1_ps(2.0);
        let n = [nx, ny, nz];
        let r: [__m256; 3] = std::array::from_fn(|k| sub(u[k], mul(mul(two, n[k]), d)));
        // m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2); each coordinate c / m + 1/2, or 1/2 where m
        // is not positive.
        let z1 = add(r[2], _mm256_set1_ps(1.0));
        let m = mul(
            two,
            _mm256_sqrt_ps(add(add(mul(r[0], r[0]), mul(r[1], r[1])), mul(z1, z1))),
        );
        let positive = _mm256_cmp_ps::<_CMP_GT_OQ>(m, zero);
        let half = _mm256_set1_ps(0.5);
        let coord = |c: __m256| _mm256_blendv_ps(half, add(div(c, m), half), positive);
        let mut out = [[0f32; 8]; 2];
        for (o, v) in out.iter_mut().zip([coord(r[0]), coord(r[1])]) {
            // SAFETY: `o` holds eight f32; unaligned store.
            unsafe { _mm256_storeu_ps(o.as_mut_ptr(), v) };
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sphere_map_of_a_normal_facing_the_viewer_is_the_centre() {
        let g = Some(GenCoord {
            mode: TexGenMode::SphereMap,
            plane: Vec4::ZERO,
        });
        let v = generate(
            &[g, g, None, None],
            Vec4::new(9.0, 9.0, 9.0, 1.0),
            Vec4::ZERO,
            Vec4::new(0.0, 0.0, -5.0, 1.0),
            Vec3::Z,
        );
        // u = (0,0,-1), r = u - 2n(n.u) = (0,0,1), m = 2*2 = 4: s = t = 0.5.
        assert_eq!(v, Vec4::new(0.5, 0.5, 9.0, 1.0));
    }

    /// `sphere_map8` gives `generate`'s values bit for bit: random and degenerate eye
    /// positions (w = 0, at the eye, huge, tiny) and normals (zero, unnormalised, NaN), and
    /// reflections straight back (m = 0).
    #[test]
    fn sphere_map8_matches_generate() {
        let g = Some(GenCoord {
            mode: TexGenMode::SphereMap,
            plane: Vec4::ZERO,
        });
        let gen = [g, g, None, None];
        assert!(is_sphere_map(&gen));
        let mut seed = 0x0DDB_1A5E_5BAD_5EEDu64;
        let mut next = || {
            let seed = crate::test_support::xorshift(&mut seed);
            let unit = (seed >> 40) as f32 / (1u64 << 24) as f32 - 0.5;
            match seed % 23 {
                0 => 0.0,
                1 => 1e30,
                2 => 1e-30,
                3 => f32::NAN,
                4 => 1.0,
                _ => unit * 4.0,
            }
        };
        let mut checked = 0;
        for _ in 0..20_000 {
            let mut eye = [[0f32; 8]; 4];
            let mut normal = [[0f32; 8]; 3];
            for lane in 0..8 {
                for row in eye.iter_mut() {
                    row[lane] = next();
                }
                for row in normal.iter_mut() {
                    row[lane] = next();
                }
                if lane == 7 {
                    // Looking down -z at a normal facing the viewer: r = (0, 0, 1)... and the
                    // mirror case r = (0, 0, -1), m = 0.
                    eye[0][lane] = 0.0;
                    eye[1][lane] = 0.0;
                    eye[2][lane] = 5.0;
                    eye[3][lane] = 1.0;
                    normal[0][lane] = 0.0;
                    normal[1][lane] = 0.0;
                    normal[2][lane] = 0.0;
                }
            }
            let Some(st) = sphere_map8(&eye, &normal) else {
                return;
            };
            for lane in 0..8 {
                let e = Vec4::new(eye[0][lane], eye[1][lane], eye[2][lane], eye[3][lane]);
                let n = Vec3::new(normal[0][lane], normal[1][lane], normal[2][lane]);
                let want = generate(&gen, Vec4::new(7.0, 8.0, 9.0, 1.0), Vec4::ZERO, e, n);
                for (k, got) in [st[0][lane], st[1][lane]].into_iter().enumerate() {
                    assert!(
                        got.to_bits() == want[k].to_bits() || (got.is_nan() && want[k].is_nan()),
                        "lane {lane} coordinate {k}: {got} != {} for {e} {n}",
                        want[k]
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked > 0);
    }

    #[test]
    fn linear_modes_are_plane_dot_products() {
        let og = Some(GenCoord {
            mode: TexGenMode::ObjectLinear,
            plane: Vec4::new(1.0, 2.0, 3.0, 4.0),
        });
        let eg = Some(GenCoord {
            mode: TexGenMode::EyeLinear,
            plane: Vec4::new(0.0, 0.0, -1.0, 0.0),
        });
        let v = generate(
            &[og, eg, None, None],
            Vec4::ZERO,
            Vec4::new(1.0, 1.0, 1.0, 1.0),
            Vec4::new(0.0, 0.0, -7.0, 1.0),
            Vec3::Z,
        );
        assert_eq!(v.x, 10.0);
        assert_eq!(v.y, 7.0);
    }
}
