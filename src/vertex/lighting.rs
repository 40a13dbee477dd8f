//! The GL 1.x lighting equations (section 2.14.1), evaluated per vertex in eye space.

use glam::{Mat3, Mat4, Vec3, Vec4};

use crate::common::values::{Face, MaterialParam};
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

/// The lighting inputs of `N` vertices, one lane each: object position, normal, and the
/// current colour (read only where `GL_COLOR_MATERIAL` tracks it).
#[derive(Clone, Copy, Debug)]
pub struct VertexLanes<const N: usize> {
    pub position: [[f32; N]; 4],
    pub normal: [[f32; N]; 3],
    pub color: [[f32; N]; 4],
}

/// Lit colours of `N` vertices: `[primary, secondary][channel][lane]` per face.
#[derive(Clone, Copy, Debug)]
pub struct LitLanes<const N: usize> {
    pub front: [[[f32; N]; 4]; 2],
    pub back: [[[f32; N]; 4]; 2],
}

fn clamp_lanes<const N: usize>(v: [[f32; N]; 4]) -> [[f32; N]; 4] {
    // max/min with NaN yield the non-NaN operand, so NaN becomes 0.
    v.map(|row| row.map(|x| x.max(0.0).min(1.0)))
}

/// `Vec3::normalize_or_zero` per lane: n / |n|, or zero where 1 / |n| is not a positive
/// finite number.
fn normalize_lanes<const N: usize>(n: &mut [[f32; N]; 3]) {
    for j in 0..N {
        let length = ((n[0][j] * n[0][j]) + (n[1][j] * n[1][j]) + (n[2][j] * n[2][j])).sqrt();
        let rcp = 1.0 / length;
        let ok = rcp.is_finite() && rcp > 0.0;
        for row in n.iter_mut() {
            row[j] = if ok { row[j] * rcp } else { 0.0 };
        }
    }
}

/// The material parameter `GL_COLOR_MATERIAL` tracks on face `face` (0 front, 1 back).
fn tracked(tracking: Option<(Face, MaterialParam)>, face: usize) -> Option<MaterialParam> {
    let (f, p) = tracking?;
    let on = match f {
        Face::Front => face == 0,
        Face::Back => face == 1,
        Face::FrontAndBack => true,
    };
    on.then_some(p)
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
        let lanes = VertexLanes::<1> {
            position: position.to_array().map(|c| [c]),
            normal: normal.to_array().map(|c| [c]),
            color: [[0.0]; 4],
        };
        let lit = self.light_lanes(&lanes, materials, None);
        let color = |c: &[[f32; 1]; 4]| Vec4::new(c[0][0], c[1][0], c[2][0], c[3][0]);
        LitColors {
            front: [color(&lit.front[0]), color(&lit.front[1])],
            back: [color(&lit.back[0]), color(&lit.back[1])],
        }
    }

    /// Lights `N` vertices at once (the lanes of each array), with the arithmetic of one
    /// vertex in every lane, so that a batch lit eight at a time gets the colours the vertices
    /// lit one by one would. `tracking`: `GL_COLOR_MATERIAL`'s faces and parameter, which
    /// then take each lane's `color` instead of `materials`.
    pub fn light_lanes<const N: usize>(
        &self,
        v: &VertexLanes<N>,
        materials: &[Material; 2],
        tracking: Option<(Face, MaterialParam)>,
    ) -> LitLanes<N> {
        let eye = if !self.needs_eye_position {
            [[0.0; N]; 3]
        } else {
            let m = self.modelview.to_cols_array_2d();
            let mut e = [[0.0; N]; 4];
            for (r, row) in e.iter_mut().enumerate() {
                for j in 0..N {
                    row[j] = m[0][r] * v.position[0][j]
                        + m[1][r] * v.position[1][j]
                        + m[2][r] * v.position[2][j]
                        + m[3][r] * v.position[3][j];
                }
            }
            let mut out = [[0.0; N]; 3];
            for j in 0..N {
                let w = if e[3][j] != 0.0 { e[3][j] } else { 1.0 };
                for c in 0..3 {
                    out[c][j] = e[c][j] / w;
                }
            }
            out
        };
        let m = self.normal_matrix.to_cols_array_2d();
        let mut n = [[0.0; N]; 3];
        for (r, row) in n.iter_mut().enumerate() {
            for j in 0..N {
                row[j] =
                    m[0][r] * v.normal[0][j] + m[1][r] * v.normal[1][j] + m[2][r] * v.normal[2][j];
            }
        }
        if self.normalize {
            normalize_lanes(&mut n);
        } else if let Some(f) = self.rescale {
            for row in n.iter_mut() {
                for x in row.iter_mut() {
                    *x *= f;
                }
            }
        }
        let front = self.face_lanes(&eye, &n, v, &materials[0], tracked(tracking, 0));
        let back = if self.two_side {
            let neg = n.map(|row| row.map(|x| -x));
            self.face_lanes(&eye, &neg, v, &materials[1], tracked(tracking, 1))
        } else {
            front
        };
        LitLanes { front, back }
    }

    fn face_lanes<const N: usize>(
        &self,
        eye: &[[f32; N]; 3],
        n: &[[f32; N]; 3],
        v: &VertexLanes<N>,
        m: &Material,
        tracked: Option<MaterialParam>,
    ) -> [[[f32; N]; 4]; 2] {
        // A material colour per lane: the lane's current colour where COLOR_MATERIAL tracks it.
        let param = |p: MaterialParam, value: Vec4| -> [[f32; N]; 4] {
            let follows = match tracked {
                Some(MaterialParam::AmbientAndDiffuse) => {
                    matches!(p, MaterialParam::Ambient | MaterialParam::Diffuse)
                }
                Some(t) => t == p,
                None => false,
            };
            if follows {
                v.color
            } else {
                value.to_array().map(|c| [c; N])
            }
        };
        let ambient = param(MaterialParam::Ambient, m.ambient);
        let diffuse = param(MaterialParam::Diffuse, m.diffuse);
        let specular_m = param(MaterialParam::Specular, m.specular);
        let emission = param(MaterialParam::Emission, m.emission);
        let mut color = [[0.0; N]; 4];
        for c in 0..4 {
            for j in 0..N {
                color[c][j] = emission[c][j] + ambient[c][j] * self.model_ambient[c];
            }
        }
        let mut specular = [[0.0; N]; 4];
        for pl in &self.lights {
            let l = &pl.light;
            // The direction to the light and the attenuation, per lane.
            let mut vp = [[0.0; N]; 3];
            let mut attenuation = [1.0; N];
            match pl.direction {
                Some(d) => {
                    for c in 0..3 {
                        vp[c] = [d[c]; N];
                    }
                }
                None => {
                    let lp = l.position.truncate() / l.position.w;
                    let [k0, k1, k2] = l.attenuation;
                    for j in 0..N {
                        let d = [lp.x - eye[0][j], lp.y - eye[1][j], lp.z - eye[2][j]];
                        let dist = ((d[0] * d[0]) + (d[1] * d[1]) + (d[2] * d[2])).sqrt();
                        for c in 0..3 {
                            vp[c][j] = if dist > 0.0 { d[c] / dist } else { 0.0 };
                        }
                        attenuation[j] = 1.0 / (k0 + k1 * dist + k2 * dist * dist);
                    }
                }
            }
            let mut scale = attenuation;
            if l.spot_cutoff != 180.0 {
                for j in 0..N {
                    let s = ((-vp[0][j]) * pl.spot_dir.x)
                        + ((-vp[1][j]) * pl.spot_dir.y)
                        + ((-vp[2][j]) * pl.spot_dir.z);
                    let spot = if s >= pl.cos_cutoff {
                        s.max(0.0).powf(l.spot_exponent)
                    } else {
                        0.0
                    };
                    scale[j] *= spot;
                }
            }
            let mut n_dot_vp = [0.0; N];
            for j in 0..N {
                n_dot_vp[j] =
                    ((n[0][j] * vp[0][j]) + (n[1][j] * vp[1][j]) + (n[2][j] * vp[2][j])).max(0.0);
            }
            let mut term = [[0.0; N]; 4];
            for c in 0..4 {
                for j in 0..N {
                    term[c][j] =
                        ambient[c][j] * l.ambient[c] + diffuse[c][j] * l.diffuse[c] * n_dot_vp[j];
                }
            }
            // The specular term: zero (skipped, with the half vector and the power) where the
            // specular product is zero, as for the default material.
            let mut spec = [[0.0; N]; 4];
            for j in 0..N {
                let product = [0, 1, 2, 3].map(|c| specular_m[c][j] * l.specular[c]);
                if !(n_dot_vp[j] > 0.0) || product[..3] == [0.0; 3] {
                    continue;
                }
                let h = match pl.half_vector {
                    Some(h) => h,
                    None => {
                        let vpj = Vec3::new(vp[0][j], vp[1][j], vp[2][j]);
                        let eye_dir = if self.local_viewer {
                            (-Vec3::new(eye[0][j], eye[1][j], eye[2][j])).normalize_or_zero()
                        } else {
                            Vec3::Z
                        };
                        (vpj + eye_dir).normalize_or_zero()
                    }
                };
                let n_dot_h = (n[0][j] * h.x) + (n[1][j] * h.y) + (n[2][j] * h.z);
                if n_dot_h > 0.0 {
                    let power = n_dot_h.powf(m.shininess);
                    for c in 0..4 {
                        spec[c][j] = product[c] * power;
                    }
                }
            }
            for c in 0..4 {
                for j in 0..N {
                    // A light whose attenuation and spot factor are zero adds nothing (not
                    // 0 * its term, which could be NaN).
                    if scale[j] == 0.0 {
                        continue;
                    }
                    if self.separate_specular {
                        specular[c][j] += spec[c][j] * scale[j];
                        color[c][j] += term[c][j] * scale[j];
                    } else {
                        color[c][j] += (term[c][j] + spec[c][j]) * scale[j];
                    }
                }
            }
        }
        // The alpha of the lit colour is the material's diffuse alpha.
        color[3] = diffuse[3];
        specular[3] = [0.0; N];
        [clamp_lanes(color), clamp_lanes(specular)]
    }
}
