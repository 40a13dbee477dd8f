//! Object to clip coordinates, and the per-vertex attributes the draw needs.

use glam::{DVec4, Mat4};

use super::immediate::ImmVertex;
use super::lighting::NormalTransform;
use super::texgen;
use super::texgen::GenCoord;
use crate::common::attr;
use crate::primitive::clip::ClipVertex;

/// The vertex stage's part of a draw's frozen state (built by `state::snapshot`).
#[derive(Clone, Debug)]
pub struct VertexDraw {
    /// Projection x modelview.
    pub mvp: Mat4,
    pub modelview: Mat4,
    /// Normals to eye space (texture generation needs them).
    pub normal_transform: NormalTransform,
    pub normalize: bool,
    /// Two-sided lighting: the back colours travel with the vertex.
    pub two_sided: bool,
    /// The eye position is needed: user clip planes, point attenuation, fog from the eye
    /// distance or texture coordinate generation.
    pub needs_eye: bool,
    /// Texture units in use, in unit order: their coordinates' generation and matrix.
    pub units: Vec<TexCoordDraw>,
    /// Fog on: whether the fog coordinate is the vertex's (`true`) or the eye distance.
    pub fog_from_vertex: Option<bool>,
}

/// How one texture unit in use gets its coordinates.
#[derive(Clone, Debug)]
pub struct TexCoordDraw {
    pub unit: usize,
    /// The unit's texture matrix.
    pub matrix: Mat4,
    /// Texture coordinate generation for s, t, r, q (`None`: the current coordinate).
    pub texgen: [Option<GenCoord>; 4],
}

/// Inverse of `m`, or the identity when `m` is singular or not finite (Mesa does the same;
/// the specification leaves it undefined).
pub(crate) fn inverse_or_identity(m: Mat4) -> Mat4 {
    let det = m.determinant();
    if det == 0.0 || !det.is_finite() {
        return Mat4::IDENTITY;
    }
    let inv = m.inverse();
    if inv.is_finite() {
        inv
    } else {
        Mat4::IDENTITY
    }
}

/// Transforms one vertex. Colours are clamped to [0, 1] here (section 2.14.7; with lighting
/// off the current colour is used as is, then clamped).
pub fn to_clip(ds: &VertexDraw, v: &ImmVertex) -> ClipVertex {
    let mut out = ClipVertex::ZERO;
    to_clip_into(ds, v, &mut out);
    out
}

/// [`to_clip`] written over `out` in place: a batch's vertices go straight into the draw's
/// reused buffer instead of being built and then copied (a clip vertex is 264 bytes).
#[inline]
pub fn to_clip_into(ds: &VertexDraw, v: &ImmVertex, out: &mut ClipVertex) {
    to_clip_except(ds, v, out, false);
}

/// [`to_clip_into`] for a batch (`out[i]` from `verts[i]`): units whose generation is the
/// sphere map (`texgen::is_sphere_map`) get it eight vertices at a time
/// (`texgen::sphere_map8`, the same values). The same clip vertices as one by one.
pub fn to_clip_batch(ds: &VertexDraw, verts: &[ImmVertex], out: &mut [ClipVertex]) {
    let deferred = crate::common::cpu::available()
        && ds.units.iter().any(|u| texgen::is_sphere_map(&u.texgen));
    if !deferred {
        for (c, v) in out.iter_mut().zip(verts) {
            to_clip_into(ds, v, c);
        }
        return;
    }
    for (vs, cs) in verts.chunks(8).zip(out.chunks_mut(8)) {
        for (c, v) in cs.iter_mut().zip(vs) {
            to_clip_except(ds, v, c, true);
        }
        for u in ds.units.iter().filter(|u| texgen::is_sphere_map(&u.texgen)) {
            let mut eye = [[0f32; 8]; 4];
            let mut normal = [[0f32; 8]; 3];
            let normals: Vec3x8 = std::array::from_fn(|lane| {
                vs.get(lane)
                    .map(|v| ds.normal_transform.apply(v.normal, ds.normalize))
            });
            for (lane, c) in cs.iter().enumerate() {
                let e = c.eye.as_vec4().to_array();
                for k in 0..4 {
                    eye[k][lane] = e[k];
                }
                if let Some(n) = normals[lane] {
                    for k in 0..3 {
                        normal[k][lane] = n[k];
                    }
                }
            }
            let st = texgen::sphere_map8(&eye, &normal);
            for (lane, (c, v)) in cs.iter_mut().zip(vs).enumerate() {
                let mut tc = v.texcoords[u.unit];
                match st {
                    Some(st) => (tc.x, tc.y) = (st[0][lane], st[1][lane]),
                    None => {
                        let n = normals[lane].unwrap_or_default();
                        tc = texgen::generate(&u.texgen, tc, v.position, c.eye.as_vec4(), n);
                    }
                }
                let tc = u.matrix * tc;
                c.attrs[attr::TEX + 4 * u.unit..attr::TEX + 4 * u.unit + 4]
                    .copy_from_slice(&tc.to_array());
            }
        }
    }
}

/// Eye normals of up to eight vertices.
type Vec3x8 = [Option<glam::Vec3>; 8];

/// [`to_clip_into`], leaving the texture coordinates of sphere-mapped units (0) to the caller
/// when `defer_sphere_map`.
#[inline(always)]
fn to_clip_except(ds: &VertexDraw, v: &ImmVertex, out: &mut ClipVertex, defer_sphere_map: bool) {
    let pos = (ds.mvp * v.position).as_dvec4();
    let eye = if !ds.needs_eye {
        DVec4::ZERO
    } else {
        (ds.modelview * v.position).as_dvec4()
    };
    let attrs = &mut out.attrs;
    attrs.fill(0.0);
    let clamp = |c: f32| c.max(0.0).min(1.0); // NaN becomes 0
    let colors = [v.color, v.secondary_color];
    for (k, c) in colors.iter().enumerate() {
        for (i, x) in c.to_array().into_iter().enumerate() {
            attrs[attr::color(4 * k + i)] = clamp(x);
        }
    }
    if ds.two_sided {
        for (k, c) in v.back_colors.iter().enumerate() {
            for (i, x) in c.to_array().into_iter().enumerate() {
                attrs[attr::BACK + 4 * k + i] = clamp(x);
            }
        }
    }
    for u in &ds.units {
        if defer_sphere_map && texgen::is_sphere_map(&u.texgen) {
            continue;
        }
        let mut tc = v.texcoords[u.unit];
        if u.texgen.iter().any(|g| g.is_some()) {
            let n = ds.normal_transform.apply(v.normal, ds.normalize);
            tc = texgen::generate(&u.texgen, tc, v.position, eye.as_vec4(), n);
        }
        let tc = u.matrix * tc;
        attrs[attr::TEX + 4 * u.unit..attr::TEX + 4 * u.unit + 4].copy_from_slice(&tc.to_array());
    }
    if let Some(from_vertex) = ds.fog_from_vertex {
        // Section 3.10: the fog coordinate, or the eye distance approximated by |z_eye|.
        attrs[attr::FOG] = if from_vertex {
            v.fog_coord
        } else {
            (eye.z as f32).abs()
        };
    }
    out.pos = pos;
    out.eye = eye;
    out.edge = v.edge_flag;
}

#[cfg(test)]
mod tests {
    use glam::{Vec3, Vec4};

    use super::*;
    use crate::api::enums::*;
    use crate::state::Context;

    /// The batch path (sphere-mapped units eight vertices at a time) gives every clip vertex
    /// bit for bit as one by one: two sphere-mapped units, one under a texture matrix, beside
    /// an object-linear one, for batch lengths around multiples of eight.
    #[test]
    fn batches_transform_as_vertices_one_by_one() {
        let mut gl = Context::new(16, 16);
        gl.matrix_mode(GL_MODELVIEW);
        gl.translatef(0.1, -0.2, -3.0);
        gl.rotatef(30.0, 1.0, 0.5, 0.0);
        gl.enable(GL_NORMALIZE);
        let texel = [200u8, 100, 50, 255];
        for unit in 0..3 {
            gl.active_texture(GL_TEXTURE0 + unit);
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                0,
                GL_RGBA as i32,
                1,
                1,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                Some(&texel),
            );
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
            gl.enable(GL_TEXTURE_2D);
            gl.enable(GL_TEXTURE_GEN_S);
            gl.enable(GL_TEXTURE_GEN_T);
            let mode = if unit == 2 {
                GL_OBJECT_LINEAR
            } else {
                GL_SPHERE_MAP
            };
            gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, mode as i32);
            gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, mode as i32);
        }
        gl.active_texture(GL_TEXTURE1);
        gl.matrix_mode(GL_TEXTURE);
        gl.rotatef(40.0, 0.0, 0.0, 1.0);
        gl.scalef(2.0, 0.5, 1.0);
        let ds = gl.snapshot();
        assert_eq!(ds.vertex.units.len(), 3);
        let mut seed = 0x5EED_1234_ABCD_0001u64;
        let mut next = || {
            let seed = crate::test_support::xorshift(&mut seed);
            (seed >> 40) as f32 / (1u64 << 24) as f32 * 4.0 - 2.0
        };
        for n in [1, 7, 8, 9, 16, 23] {
            let verts: Vec<ImmVertex> = (0..n)
                .map(|_| {
                    let position = Vec4::new(next(), next(), next(), 1.0);
                    let texcoords = std::array::from_fn(|_| Vec4::new(next(), next(), next(), 1.0));
                    ImmVertex {
                        position,
                        color: Vec4::new(next(), next(), next(), 1.0),
                        secondary_color: Vec4::ZERO,
                        back_colors: [Vec4::ONE; 2],
                        normal: Vec3::new(next(), next(), next()),
                        texcoords,
                        fog_coord: 0.0,
                        edge_flag: true,
                    }
                })
                .collect();
            let mut batch = vec![ClipVertex::ZERO; n];
            to_clip_batch(&ds.vertex, &verts, &mut batch);
            for (i, (b, v)) in batch.iter().zip(&verts).enumerate() {
                let one = to_clip(&ds.vertex, v);
                assert_eq!(b.pos, one.pos, "batch of {n}, vertex {i}");
                let bits = |c: &ClipVertex| c.attrs.map(f32::to_bits);
                assert_eq!(bits(b), bits(&one), "batch of {n}, vertex {i}");
            }
        }
    }
}
