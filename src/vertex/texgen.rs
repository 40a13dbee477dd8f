//! Texture coordinate generation (section 2.11.4), per vertex, before the texture matrix.

use glam::{Vec3, Vec4};

use crate::api::convert::TexGenMode;

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
    if let [Some(gs), Some(gt), None, None] = gen {
        if gs.mode == TexGenMode::SphereMap && gt.mode == TexGenMode::SphereMap {
            let (r, m) = sphere_of(reflect());
            out[0] = sphere_coord(r.x, m);
            out[1] = sphere_coord(r.y, m);
            return Vec4::from_array(out);
        }
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
