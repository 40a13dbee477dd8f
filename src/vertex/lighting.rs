//! The GL 1.x lighting equations (section 2.14.1), evaluated per vertex in eye space.

use glam::{Mat3, Mat4, Vec3, Vec4};

use crate::state::lighting::{Light, LightingState, Material};

/// Object-space normals to eye space (section 2.11.3): the inverse transpose of the modelview's
/// upper 3x3, then `GL_NORMALIZE` or the `GL_RESCALE_NORMAL` factor.
#[derive(Clone, Copy, Debug)]
pub struct NormalTransform {
    pub matrix: Mat3,
    /// The rescale factor f = 1 / |third row of the inverse|, when rescaling applies.
    pub rescale: Option<f32>,
}

impl NormalTransform {
    pub fn new(modelview: Mat4, normalize: bool, rescale: bool) -> NormalTransform {
        let inv = crate::state::matrices::inverse_or_identity(modelview);
        let rescale = (rescale && !normalize).then(|| {
            let row = Vec3::new(inv.x_axis.z, inv.y_axis.z, inv.z_axis.z);
            let len = row.length();
            if len > 0.0 && len.is_finite() {
                1.0 / len
            } else {
                1.0
            }
        });
        NormalTransform {
            matrix: Mat3::from_mat4(inv).transpose(),
            rescale,
        }
    }

    pub fn apply(&self, normal: Vec3, normalize: bool) -> Vec3 {
        let n = self.matrix * normal;
        if normalize {
            n.normalize_or_zero()
        } else if let Some(f) = self.rescale {
            n * f
        } else {
            n
        }
    }
}

/// Lighting inputs that depend only on state outside `glBegin`/`glEnd` (derived once per state
/// change): the enabled lights and the normal transformation.
#[derive(Clone, Debug)]
pub struct LightSetup {
    modelview: Mat4,
    normal_matrix: Mat3,
    /// `GL_NORMALIZE`, or the `GL_RESCALE_NORMAL` factor.
    normalize: bool,
    rescale: Option<f32>,
    lights: Vec<PreparedLight>,
    model_ambient: Vec4,
    local_viewer: bool,
    two_side: bool,
    separate_specular: bool,
    /// Whether any term reads the vertex's eye position (a positional light or a local
    /// viewer); otherwise it is not computed.
    needs_eye_position: bool,
}

#[derive(Clone, Debug)]
struct PreparedLight {
    light: Light,
    spot_dir: Vec3,
    cos_cutoff: f32,
    /// For a directional light (w = 0): the unit direction to the light, the same at every
    /// vertex, and with an infinite viewer also the half vector.
    direction: Option<Vec3>,
    half_vector: Option<Vec3>,
}

/// Lit colours of one vertex: primary and secondary, for the front and the back face.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LitColors {
    pub front: [Vec4; 2],
    pub back: [Vec4; 2],
}

fn clamp01(v: Vec4) -> Vec4 {
    // max/min with NaN yield the non-NaN operand, so NaN becomes 0.
    Vec4::new(
        v.x.max(0.0).min(1.0),
        v.y.max(0.0).min(1.0),
        v.z.max(0.0).min(1.0),
        v.w.max(0.0).min(1.0),
    )
}

impl LightSetup {
    pub fn new(state: &LightingState, modelview: Mat4, normalize: bool, rescale: bool) -> Self {
        let NormalTransform {
            matrix: normal_matrix,
            rescale,
        } = NormalTransform::new(modelview, normalize, rescale);
        let lights = state
            .lights
            .iter()
            .filter(|l| l.enabled)
            .map(|l| {
                // Computed exactly as `face` would per vertex, so the values do not change.
                let direction =
                    (l.position.w == 0.0).then(|| l.position.truncate().normalize_or_zero());
                PreparedLight {
                    light: *l,
                    spot_dir: l.spot_direction.normalize_or_zero(),
                    cos_cutoff: l.spot_cutoff.to_radians().cos(),
                    direction,
                    half_vector: direction
                        .filter(|_| !state.local_viewer)
                        .map(|vp| (vp + Vec3::Z).normalize_or_zero()),
                }
            })
            .collect::<Vec<_>>();
        let needs_eye_position =
            state.local_viewer || lights.iter().any(|l: &PreparedLight| l.direction.is_none());
        LightSetup {
            modelview,
            normal_matrix,
            normalize,
            rescale,
            lights,
            model_ambient: state.model_ambient,
            local_viewer: state.local_viewer,
            two_side: state.two_side,
            separate_specular: state.separate_specular,
            needs_eye_position,
        }
    }

    /// Lights one vertex given its object position, normal and the current materials.
    pub fn light(&self, position: Vec4, normal: Vec3, materials: &[Material; 2]) -> LitColors {
        let v = if !self.needs_eye_position {
            Vec3::ZERO
        } else {
            let eye = self.modelview * position;
            if eye.w != 0.0 {
                eye.truncate() / eye.w
            } else {
                eye.truncate()
            }
        };
        let n = NormalTransform {
            matrix: self.normal_matrix,
            rescale: self.rescale,
        }
        .apply(normal, self.normalize);
        let front = self.face(v, n, &materials[0]);
        let back = if self.two_side {
            self.face(v, -n, &materials[1])
        } else {
            front
        };
        LitColors { front, back }
    }

    fn face(&self, v: Vec3, n: Vec3, m: &Material) -> [Vec4; 2] {
        let mut color = m.emission + m.ambient * self.model_ambient;
        let mut specular = Vec4::ZERO;
        for pl in &self.lights {
            let l = &pl.light;
            let (vp, attenuation) = if let Some(direction) = pl.direction {
                (direction, 1.0)
            } else {
                let d = l.position.truncate() / l.position.w - v;
                let dist = d.length();
                let [k0, k1, k2] = l.attenuation;
                let vp = if dist > 0.0 { d / dist } else { Vec3::ZERO };
                (vp, 1.0 / (k0 + k1 * dist + k2 * dist * dist))
            };
            let spot = if l.spot_cutoff == 180.0 {
                1.0
            } else {
                let s = (-vp).dot(pl.spot_dir);
                if s >= pl.cos_cutoff {
                    s.max(0.0).powf(l.spot_exponent)
                } else {
                    0.0
                }
            };
            let scale = attenuation * spot;
            if scale == 0.0 {
                continue;
            }
            let n_dot_vp = n.dot(vp).max(0.0);
            let mut term = m.ambient * l.ambient + m.diffuse * l.diffuse * n_dot_vp;
            let mut spec = Vec4::ZERO;
            let specular_product = m.specular * l.specular;
            // A zero specular product (the default material) adds zero whatever the power:
            // skip the half vector and the power.
            if n_dot_vp > 0.0 && specular_product.truncate() != Vec3::ZERO {
                let h = match pl.half_vector {
                    Some(h) => h,
                    None => {
                        let eye_dir = if self.local_viewer {
                            (-v).normalize_or_zero()
                        } else {
                            Vec3::Z
                        };
                        (vp + eye_dir).normalize_or_zero()
                    }
                };
                let n_dot_h = n.dot(h);
                if n_dot_h > 0.0 {
                    spec = specular_product * n_dot_h.powf(m.shininess);
                }
            }
            if self.separate_specular {
                specular += spec * scale;
            } else {
                term += spec;
            }
            color += term * scale;
        }
        // The alpha of the lit colour is the material's diffuse alpha.
        color.w = m.diffuse.w;
        specular.w = 0.0;
        [clamp01(color), clamp01(specular)]
    }
}
