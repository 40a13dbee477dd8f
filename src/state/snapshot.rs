//! Builds the immutable `DrawState`: everything one draw needs, frozen at the draw, so that
//! deferred tile shading never sees a later state change. This is the one owner of "what a
//! draw needs".

use std::sync::Arc;

use glam::{DVec4, Mat4};

use super::Context;
use crate::common::limits::MAX_TEXTURE_UNITS;
use crate::common::rect::Rect;
use crate::common::values::{Face, PolygonMode, ProvokingVertex, ShadeModel, Winding};
use crate::common::values::{TexEnvMode, TexGenMode};
use crate::fragment::cache::{select_covered, select_pair, select_span};
pub use crate::fragment::fog::{fog_exp, FogDraw, EXP2_TAYLOR};
use crate::fragment::key::{FastTexture, FragmentKey, Uniforms};
use crate::texture::format::BaseFormat;
use crate::texture::sample::LevelPlan;
use crate::vertex::lighting::NormalTransform;
use crate::vertex::texgen::GenCoord;

pub use crate::common::attr::{self, COLOR_ATTRS, MAX_ATTRS};

pub use crate::fragment::draw::{FragmentDraw, TextureUnitDraw};
pub use crate::primitive::viewport::ViewportDraw;
pub use crate::raster::controls::{PolygonOffsetDraw, RasterDraw};
pub use crate::raster::draw::TileDraw;
pub use crate::vertex::transform::{TexCoordDraw, VertexDraw};

/// The frozen state of one draw: each stage's part, defined by the stage that reads it, and
/// what the draw driver (`state::draw`) decides with itself.
#[derive(Clone, Debug)]
pub struct DrawState {
    pub vertex: VertexDraw,
    pub viewport: ViewportDraw,
    /// Setup, binning and tile shading (with the fragment stage's part); the scene keeps it
    /// for the draw's commands.
    pub tile: Arc<TileDraw>,
    /// The viewport rectangle intersected with the framebuffer: nothing outside is drawn.
    pub viewport_rect: Rect,
    pub cull: Option<Face>,
    pub front_face: Winding,
    /// Which vertex provokes under flat shading (EXT_provoking_vertex).
    pub provoking: ProvokingVertex,
    /// Attributes carried through clipping (includes the back colours with two-sided lighting).
    pub clip_attr_count: usize,
}

impl Context {
    /// The window's pixels.
    pub(crate) fn window_rect(&self) -> Rect {
        Rect {
            x0: 0,
            y0: 0,
            x1: self.framebuffer.width,
            y1: self.framebuffer.height,
        }
    }

    /// The window's pixels cut by the scissor box when the scissor test is on: what draws,
    /// clears, pixel rectangles and `glAccum` may touch (the viewport limits only draws).
    pub(crate) fn scissored_window(&self) -> Rect {
        let ops = &self.fragment_ops;
        if ops.scissor_enabled {
            self.window_rect().intersect(&ops.scissor.rect())
        } else {
            self.window_rect()
        }
    }

    /// The snapshot for the next draw, rebuilt only after a state change.
    pub(crate) fn snapshot(&mut self) -> Arc<DrawState> {
        if let Some(ds) = &self.draw_state {
            return ds.clone();
        }
        let t = &self.transform;
        let modelview = *t.modelview.last().unwrap_or(&Mat4::IDENTITY);
        let projection = *t.projection.last().unwrap_or(&Mat4::IDENTITY);
        let clip_planes = (0..t.clip_planes.len())
            .filter(|&i| t.clip_plane_enabled[i])
            .map(|i| t.clip_planes[i])
            .collect();
        let vp = t.viewport;
        let [n, f] = t.depth_range;
        let viewport_rect = self.window_rect().intersect(&vp.rect());
        let draw_rect = self.scissored_window().intersect(&vp.rect());
        let ops = &self.fragment_ops;
        let cfg = self.framebuffer.config;
        let lit = &self.lighting;
        // Colour sum (section 3.9): with lighting, under separate specular; else GL_COLOR_SUM.
        let color_sum = if lit.enabled {
            lit.separate_specular
        } else {
            lit.color_sum
        };
        let two_sided = lit.enabled && lit.two_side;
        let units: Vec<TextureUnitDraw> = (0..MAX_TEXTURE_UNITS)
            .filter_map(|u| {
                let texture = self.textures.bound_for_unit(u)?;
                Some(TextureUnitDraw {
                    unit: u,
                    base: texture.base_format(),
                    lod: texture.lod_select(self.tex_env[u].lod_bias),
                    fixed_plan: match texture.plan_without_lambda() {
                        Some(LevelPlan::One { level, linear }) => Some((level, linear)),
                        _ => None,
                    },
                    texture,
                    env: self.tex_env[u],
                })
            })
            .collect();
        let coord_units: Vec<TexCoordDraw> = units
            .iter()
            .map(|d| {
                let u = d.unit;
                TexCoordDraw {
                    unit: u,
                    matrix: *self.transform.texture[u].last().unwrap_or(&Mat4::IDENTITY),
                    texgen: std::array::from_fn(|c| {
                        let g = &self.tex_gen[u][c];
                        g.enabled.then(|| GenCoord {
                            mode: g.mode,
                            plane: DVec4::from_array(if g.mode == TexGenMode::ObjectLinear {
                                g.object_plane
                            } else {
                                g.eye_plane
                            })
                            .as_vec4(),
                        })
                    }),
                }
            })
            .collect();
        let fs = &self.fog;
        let fog = fs.enabled.then_some(FogDraw {
            mode: fs.mode,
            density: fs.density,
            start: fs.start,
            end: fs.end,
            color: [fs.color[0], fs.color[1], fs.color[2]],
            coord_from_vertex: fs.coord_from_vertex,
        });
        // A prefix of the layout: the secondary colour comes after the fog coordinate, so the
        // colour sum needs both whether or not fog is on.
        let attr_count = match units.last() {
            Some(last) => attr::TEX + 4 * (last.unit + 1),
            None if color_sum => attr::COLOR1 + 4,
            None if fog.is_some() => attr::FOG + 1,
            None => COLOR_ATTRS,
        };
        let mut key =
            FragmentKey::from_state(ops, cfg.depth_bits > 0, cfg.stencil_bits > 0, color_sum);
        // A framebuffer object's image without some components never gets them written.
        key.color_mask = self.color_write_mask();
        key.texturing = !units.is_empty();
        key.fast_texture = match units.as_slice() {
            [u] if matches!(u.env.mode, TexEnvMode::Replace | TexEnvMode::Modulate)
                && u.texture.fast_2d() =>
            {
                match u.base {
                    BaseFormat::Rgb => Some(FastTexture::Rgb),
                    BaseFormat::Rgba => Some(FastTexture::Rgba),
                    _ => None,
                }
            }
            _ => None,
        };
        key.simd_units = !units.is_empty() && units.iter().all(|u| u.texture.simd_2d());
        key.fog = fog.map(|f| f.mode);
        key.byte_env =
            crate::common::cpu::available() && crate::fragment::bytenv::applies(&key, &units);
        key.count_samples = self.queries.active.is_some();
        // Multisample fragment operations apply with a multisample buffer and GL_MULTISAMPLE
        // on (section 4.1.3); each sample pass sets its threshold (`state::draw`).
        let ms = self.multisample;
        let multisampling = self.framebuffer.samples > 1 && ms.multisample;
        key.alpha_to_coverage = multisampling && ms.alpha_to_coverage;
        key.alpha_to_one = multisampling && ms.alpha_to_one;
        let uniforms = Uniforms::from_state(ops, cfg.stencil_bits);
        let raster = self.raster_draw();
        let clip_planes: Vec<DVec4> = clip_planes;
        let needs_eye = !clip_planes.is_empty()
            || raster.point_attenuation.is_some()
            || fog.is_some_and(|f| !f.coord_from_vertex)
            || coord_units
                .iter()
                .any(|u| u.texgen.iter().any(|g| g.is_some()));
        let ds = Arc::new(DrawState {
            vertex: VertexDraw {
                mvp: projection * modelview,
                modelview,
                normal_transform: NormalTransform::new(
                    modelview,
                    self.transform.normalize,
                    self.transform.rescale_normal,
                ),
                normalize: self.transform.normalize,
                two_sided,
                needs_eye,
                units: coord_units,
                fog_from_vertex: fog.map(|f| f.coord_from_vertex),
            },
            viewport: ViewportDraw {
                clip_planes,
                viewport_scale: [vp.width as f64 / 2.0, vp.height as f64 / 2.0, (f - n) / 2.0],
                viewport_offset: [
                    vp.x as f64 + vp.width as f64 / 2.0,
                    vp.y as f64 + vp.height as f64 / 2.0,
                    (n + f) / 2.0,
                ],
                // Outlines and vertices of polygons in line and point mode (wide lines and
                // points near the viewport's edges) are drawn from the polygon clipped to the
                // view volume.
                guard: if self.raster.polygon_mode == [PolygonMode::Fill; 2] {
                    crate::primitive::clip::guard_factors(
                        [vp.width as f64 / 2.0, vp.height as f64 / 2.0],
                        [
                            vp.x as f64 + vp.width as f64 / 2.0,
                            vp.y as f64 + vp.height as f64 / 2.0,
                        ],
                    )
                } else {
                    crate::primitive::clip::EXACT
                },
            },
            tile: Arc::new(TileDraw {
                draw_rect,
                flat: self.raster.shade_model == ShadeModel::Flat,
                attr_count,
                live_attrs: live_attrs(&units, fog.is_some(), color_sum, attr_count),
                coarse_depth: !self.force_general_path && crate::raster::coarse::applies(&key),
                fast_lines: !self.force_general_path,
                raster,
                fragment: FragmentDraw {
                    cascade: (!units.is_empty())
                        .then(|| {
                            crate::fragment::cascade::Program::new(
                                &units
                                    .iter()
                                    .map(|u| (u.env, u.base, u.unit))
                                    .collect::<Vec<_>>(),
                            )
                        })
                        .flatten(),
                    units,
                    fog,
                    depth_max: self.framebuffer.depth_max(),
                    key,
                    uniforms,
                    span: select_span(&key, self.force_general_path),
                    span_pair: select_pair(&key, self.force_general_path),
                    span_covered: select_covered(&key, self.force_general_path),
                },
            }),
            viewport_rect,
            cull: self.raster.cull_enabled.then_some(self.raster.cull_face),
            front_face: self.raster.front_face,
            provoking: self.raster.provoking_vertex,
            clip_attr_count: if two_sided { attr::COUNT } else { attr_count },
        });
        self.draw_state = Some(ds.clone());
        ds
    }
}

/// The attributes the fragment stage reads ([`TileDraw::live_attrs`]): the primary colour;
/// the fog coordinate under fog; the secondary colour with the colour sum; each unit's s, t
/// and q, and r where its texture reads it.
fn live_attrs(units: &[TextureUnitDraw], fog: bool, color_sum: bool, attr_count: usize) -> u64 {
    let bits = |range: std::ops::Range<usize>| range.fold(0u64, |m, i| m | 1 << i);
    let mut live = bits(attr::COLOR0..attr::COLOR0 + 4);
    if fog {
        live |= 1 << attr::FOG;
    }
    if color_sum {
        live |= bits(attr::COLOR1..attr::COLOR1 + 4);
    }
    for u in units {
        let s = attr::TEX + 4 * u.unit;
        live |= 1 << s | 1 << (s + 1) | 1 << (s + 3);
        if u.texture.reads_r() {
            live |= 1 << (s + 2);
        }
    }
    live & bits(0..attr_count)
}

impl Context {
    fn raster_draw(&self) -> RasterDraw {
        let r = &self.raster;
        let offset_on = r.offset_enabled.iter().any(|&e| e);
        RasterDraw {
            point_size: r.point_size,
            point_smooth: r.point_smooth,
            smooth_points: self.smooth_points,
            point_sprite: r
                .point_sprite
                .then_some((r.point_sprite_coord_replace, r.point_sprite_upper_left)),
            point_attenuation: (r.point_attenuation != [1.0, 0.0, 0.0])
                .then_some(r.point_attenuation),
            point_size_range: [r.point_size_min, r.point_size_max],
            line_width: r.line_width,
            line_smooth: r.line_smooth,
            line_stipple: r.line_stipple.then_some((
                r.line_stipple_factor.clamp(1, 256) as u32,
                r.line_stipple_pattern,
            )),
            polygon_mode: r.polygon_mode,
            offset: offset_on.then_some(PolygonOffsetDraw {
                factor: r.offset_factor as f64,
                units: r.offset_units as f64,
                enabled: r.offset_enabled,
            }),
            polygon_stipple: r.polygon_stipple.then_some(r.polygon_stipple_pattern),
            polygon_smooth: r.polygon_smooth,
        }
    }
}
