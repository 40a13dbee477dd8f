//! `Context`: all GL state as plain data, the entry points that set it, and the one place that
//! turns it into the immutable per-draw snapshot.

pub mod accum;
pub mod arrays;
pub mod attrib;
pub mod clear_read;
pub mod client_memory;
mod client_sizes;
pub mod color_buffers;
pub mod draw;
pub mod evaluators;
pub mod fbo;
mod flush;
pub mod fog;
mod fragment_key;
pub mod get;
pub mod immediate;
pub mod lighting;
pub mod lists;
pub mod matrices;
pub mod per_fragment;
mod pixel_queue;
pub mod pixel_rect;
pub mod queries;
pub mod rasterization;
pub mod select;
pub mod share;
pub mod snapshot;
pub mod tables;
pub mod texenv;
pub mod texgen;
mod textures;

use std::collections::HashMap;
use std::ffi::CString;
use std::sync::Arc;

use crate::common::values::{Capability, HintTarget, PixelStoreParam, StringName};
use crate::framebuffer::{Framebuffer, FramebufferConfig};
use crate::gl::convert;
use crate::gl::enums::*;
use crate::gl::error::ErrorFlag;
use crate::raster::scene::Scene;
use crate::vertex::immediate::ImmediateBatch;
use tables::*;

pub use snapshot::DrawState;

/// Options of a new context.
#[derive(Clone, Copy, Debug)]
pub struct ContextConfig {
    pub width: i32,
    pub height: i32,
    pub framebuffer: FramebufferConfig,
    /// Worker threads for tile shading; 0 means one per core.
    pub threads: usize,
}

impl Default for ContextConfig {
    fn default() -> Self {
        ContextConfig {
            width: 256,
            height: 256,
            framebuffer: FramebufferConfig::default(),
            threads: 0,
        }
    }
}

/// `GL_EXTENSIONS`: the extensions whose functionality is implemented and tested (most were
/// folded into OpenGL 1.2-1.5 and are listed for programs that look for the old names).
/// Each name ends with a space, the last too, as in Mesa's and other drivers' strings:
/// programs that print the names one per line by turning spaces into newlines (piglit's
/// glinfo) end their last line so.
pub const EXTENSIONS: &str = "GL_ARB_depth_texture GL_ARB_framebuffer_object GL_ARB_map_buffer_range \
GL_ARB_multisample GL_ARB_multitexture GL_ARB_pixel_buffer_object GL_ARB_point_parameters \
GL_ARB_point_sprite \
GL_ARB_provoking_vertex GL_ARB_sampler_objects \
GL_ARB_shadow GL_ARB_texture_border_clamp GL_ARB_texture_compression GL_ARB_texture_cube_map \
GL_ARB_texture_env_add GL_ARB_texture_env_combine GL_ARB_texture_env_crossbar \
GL_ARB_texture_env_dot3 GL_ARB_texture_float GL_ARB_texture_mirrored_repeat GL_ARB_texture_non_power_of_two \
GL_ARB_texture_rectangle GL_ARB_texture_storage GL_ARB_transpose_matrix GL_ARB_vertex_array_bgra GL_ARB_vertex_buffer_object GL_ARB_window_pos GL_EXT_bgra \
GL_EXT_blend_color GL_EXT_blend_equation_separate GL_EXT_blend_func_separate \
GL_EXT_blend_minmax GL_EXT_blend_subtract \
GL_EXT_compiled_vertex_array GL_EXT_draw_range_elements GL_EXT_fog_coord GL_EXT_framebuffer_blit \
GL_EXT_framebuffer_object \
GL_EXT_multi_draw_arrays GL_EXT_packed_depth_stencil GL_EXT_packed_pixels GL_EXT_pixel_buffer_object \
GL_EXT_provoking_vertex \
GL_EXT_rescale_normal GL_EXT_secondary_color GL_EXT_separate_specular_color GL_EXT_shadow_funcs \
GL_EXT_stencil_wrap GL_EXT_texture3D \
GL_EXT_texture_compression_s3tc GL_EXT_texture_edge_clamp GL_EXT_texture_env_add \
GL_EXT_texture_env_combine GL_EXT_texture_env_dot3 GL_EXT_texture_filter_anisotropic \
GL_EXT_texture_lod_bias GL_EXT_texture_mirror_clamp GL_EXT_texture_swizzle GL_EXT_vertex_array \
GL_EXT_vertex_array_bgra \
GL_ATI_texture_mirror_once GL_NV_texture_env_combine4 GL_SGIS_generate_mipmap \
GL_SGIS_texture_edge_clamp GL_SGIS_texture_lod ";

/// A GL context: the state machine, its framebuffer and the deferred scene of binned work.
pub struct Context {
    pub(crate) error: ErrorFlag,
    pub(crate) transform: TransformState,
    pub(crate) raster: RasterState,
    pub(crate) fragment_ops: FragmentOpsState,
    pub(crate) clear_values: ClearValues,
    pub(crate) current: CurrentValues,
    pub(crate) hints: Hints,
    pub(crate) pack: PixelStore,
    pub(crate) unpack: PixelStore,
    /// The `glBegin`/`glEnd` batch being recorded, if inside one.
    pub(crate) immediate: Option<ImmediateBatch>,
    /// An emptied vertex buffer kept for the next `glBegin`.
    pub(crate) spare_vertices: Vec<crate::vertex::immediate::ImmVertex>,
    /// Clip-space vertices of the current draw, kept to reuse the allocation.
    pub(crate) clip_buffer: Vec<crate::primitive::clip::ClipVertex>,
    /// Assembled primitives of the current draw, kept like `clip_buffer`.
    pub(crate) primitive_buffer: Vec<crate::primitive::assemble::Primitive>,
    /// Window positions of the current draw's vertices (`None`: outside a clip plane), kept
    /// like `clip_buffer`.
    pub(crate) window_buffer: Vec<Option<crate::primitive::viewport::WindowVertex>>,
    /// The active texture unit (`glActiveTexture`), which selects the texture matrix stack.
    pub(crate) active_texture: usize,
    /// The client active texture unit (`glClientActiveTexture`, for texture-coordinate arrays).
    pub(crate) client_active_texture: usize,
    pub(crate) fog: fog::FogState,
    /// The current raster position (`glRasterPos`, `glWindowPos`).
    pub(crate) raster_pos: pixel_rect::RasterPos,
    /// Pixel transfer modes, maps and zoom.
    pub(crate) pixel_transfer: pixel_rect::PixelTransfer,
    /// Per-unit texture coordinate generation.
    pub(crate) tex_gen: [texgen::TexGenUnit; tables::limits::MAX_TEXTURE_UNITS],
    /// Per-unit texture environments.
    pub(crate) tex_env: [texenv::TexEnv; tables::limits::MAX_TEXTURE_UNITS],
    pub(crate) lighting: lighting::LightingState,
    /// Lighting inputs derived from the state, rebuilt after a change.
    pub(crate) light_setup: Option<std::sync::Arc<crate::vertex::lighting::LightSetup>>,
    /// Texture objects, bindings and per-unit enables.
    pub(crate) textures: crate::texture::TextureState,
    pub(crate) framebuffer: Framebuffer,
    /// Framebuffer and renderbuffer objects (EXT_framebuffer_object).
    pub(crate) fbo: fbo::FboState,
    /// `glDrawBuffer` / `glReadBuffer` settings.
    pub(crate) buffers: color_buffers::BufferSelection,
    pub(crate) scene: Scene,
    /// The snapshot for the next draw; `None` after any state change that affects drawing.
    pub(crate) draw_state: Option<Arc<DrawState>>,
    pub(crate) pool: Option<rayon::ThreadPool>,
    /// Threads that shade tiles (the pool's, or rayon's global pool's): background shading
    /// needs at least two.
    pub(crate) shading_threads: usize,
    /// The tiles and the scenes queued on them while workers shade in the background, if
    /// any.
    pub(crate) in_flight: Option<crate::raster::schedule::InFlight>,
    /// Background scenes shaded everywhere, for reuse, and how many are still in flight.
    pub(crate) recycle: Arc<crate::raster::schedule::Recycle>,
    /// A reset scene to record into after the next background hand-off.
    pub(crate) spare_scene: Option<Scene>,
    /// Strings handed out through the C ABI (`glGetString`), kept alive with the context.
    strings: HashMap<String, CString>,
    /// Set by `glFlush`/`glFinish`: the front end should show the finished picture.
    present_requested: bool,
    /// Set by `glViewport`: a window-system front end checks the drawable's size there (as
    /// Mesa's xlib driver does), so a resized window gets buffers of its new size.
    pub(crate) drawable_check_requested: bool,
    /// Forces the general fragment path (used by the fast-path twin tests).
    pub(crate) force_general_path: bool,
    /// Vertex arrays, buffer objects and the client attribute stack.
    pub(crate) client: arrays::ClientState,
    /// Display lists.
    pub(crate) lists: lists::ListState,
    /// The server attribute stack (`glPushAttrib`).
    pub(crate) attrib_stack: Vec<Box<attrib::AttribEntry>>,
    /// Multisample enables and sample coverage.
    pub(crate) multisample: attrib::MultisampleState,
    /// The sample passes of a multisample framebuffer's draws (`state::draw`), for the
    /// snapshot they were made from.
    pub(crate) sample_passes: Option<draw::SamplePasses>,
    /// Occlusion query objects and the active query.
    pub(crate) queries: queries::QueryState,
    /// Render mode, name stack, selection and feedback buffers.
    pub(crate) select: select::SelectState,
    /// Evaluator maps, enables and grids.
    pub(crate) eval: evaluators::EvalState,
    /// How `glEvalMesh2(GL_FILL)` connects the grid (not GL state).
    pub(crate) mesh_fill: evaluators::MeshFill,
    /// The client memory `ClientPtr`s name (none until the C ABI, or a Rust caller that
    /// promises the GL client-memory contract, attaches it).
    pub(crate) client_memory: &'static dyn client_memory::ClientMemory,
    /// How `GL_POINT_SMOOTH` points are drawn (not GL state).
    pub(crate) smooth_points: crate::raster::controls::SmoothPoints,
}

impl Context {
    /// A context with a `width` x `height` framebuffer and default buffers (RGBA8, 24-bit
    /// depth, 8-bit stencil). The viewport and scissor box start as the whole framebuffer.
    pub fn new(width: i32, height: i32) -> Context {
        Context::with_config(ContextConfig {
            width,
            height,
            ..ContextConfig::default()
        })
    }

    /// A context with explicit buffer configuration and thread count.
    pub fn with_config(config: ContextConfig) -> Context {
        let width = config.width.clamp(0, limits::MAX_VIEWPORT_DIM);
        let height = config.height.clamp(0, limits::MAX_VIEWPORT_DIM);
        let transform = TransformState {
            viewport: Viewport {
                x: 0,
                y: 0,
                width,
                height,
            },
            ..TransformState::default()
        };
        let fragment_ops = FragmentOpsState {
            scissor: transform.viewport,
            ..FragmentOpsState::default()
        };
        let pool = if config.threads > 0 {
            rayon::ThreadPoolBuilder::new()
                .num_threads(config.threads)
                .build()
                .ok()
        } else {
            None
        };
        let shading_threads = match &pool {
            Some(p) => p.current_num_threads(),
            None => rayon::current_num_threads(),
        };
        let framebuffer = Framebuffer::new(width, height, config.framebuffer);
        let scene = Scene::new(&framebuffer);
        Context {
            error: ErrorFlag::default(),
            transform,
            raster: RasterState::default(),
            fragment_ops,
            clear_values: ClearValues::default(),
            current: CurrentValues::default(),
            hints: Hints::default(),
            pack: PixelStore::default(),
            unpack: PixelStore::default(),
            immediate: None,
            spare_vertices: Vec::new(),
            clip_buffer: Vec::new(),
            primitive_buffer: Vec::new(),
            window_buffer: Vec::new(),
            active_texture: 0,
            client_active_texture: 0,
            tex_env: Default::default(),
            tex_gen: std::array::from_fn(|_| texgen::default_unit()),
            fog: Default::default(),
            raster_pos: Default::default(),
            pixel_transfer: Default::default(),
            textures: Default::default(),
            lighting: Default::default(),
            light_setup: None,
            buffers: color_buffers::BufferSelection::new(config.framebuffer.double_buffer),
            framebuffer,
            fbo: Default::default(),
            scene,
            in_flight: None,
            recycle: Default::default(),
            spare_scene: None,
            draw_state: None,
            pool,
            shading_threads,
            strings: HashMap::new(),
            present_requested: false,
            drawable_check_requested: false,
            force_general_path: false,
            client: Default::default(),
            client_memory: &client_memory::NoClientMemory,
            lists: Default::default(),
            attrib_stack: Vec::new(),
            multisample: Default::default(),
            sample_passes: None,
            queries: Default::default(),
            select: Default::default(),
            eval: Default::default(),
            mesh_fill: Default::default(),
            smooth_points: Default::default(),
        }
    }

    /// Lets the context read and write the client memory its `ClientPtr`s name (client
    /// arrays, `glGetPointerv`, selection and feedback buffers) through `memory`; the C ABI
    /// attaches the process's memory to the contexts it creates (`capi::client_memory`).
    pub fn set_client_memory(&mut self, memory: &'static dyn client_memory::ClientMemory) {
        self.client_memory = memory;
    }

    /// Resizes the framebuffer (contents become undefined; tilegl clears them). Used by the C
    /// ABI when `OSMesaMakeCurrent` binds a buffer of another size. Flushes pending work first.
    pub fn resize(&mut self, width: i32, height: i32) {
        self.flush_scene();
        let width = width.clamp(0, limits::MAX_VIEWPORT_DIM);
        let height = height.clamp(0, limits::MAX_VIEWPORT_DIM);
        if self.fbo_bound() {
            // The window's buffers are parked while a framebuffer object is bound.
            let w = self.window_framebuffer_mut();
            if (w.width, w.height) != (width, height) {
                let (draw, read) = (w.draw, w.read);
                *w = Framebuffer::new(width, height, w.config);
                w.draw = draw;
                w.read = read;
                let b = match draw {
                    crate::framebuffer::DrawTarget::One(b) => b,
                    _ => w.read,
                };
                w.make_resident(b);
            }
            return;
        }
        if width == self.framebuffer.width && height == self.framebuffer.height {
            return;
        }
        self.framebuffer = Framebuffer::new(width, height, self.framebuffer.config);
        self.apply_buffer_selection();
        self.scene = Scene::new(&self.framebuffer);
        self.spare_scene = None;
        self.recycle.clear();
        self.draw_state = None;
    }

    /// Width and height of the framebuffer.
    pub fn size(&self) -> (i32, i32) {
        let fb = self.window_framebuffer();
        (fb.width, fb.height)
    }

    /// The window's framebuffer after finishing all pending rendering (while a framebuffer
    /// object is bound too).
    pub fn framebuffer(&mut self) -> &Framebuffer {
        self.flush_scene();
        self.window_framebuffer()
    }

    /// Mutable framebuffer access after finishing pending rendering (the C ABI adopts caller
    /// buffers through it).
    pub fn framebuffer_mut(&mut self) -> &mut Framebuffer {
        self.flush_scene();
        self.window_framebuffer_mut()
    }

    /// True once after each `glFlush`/`glFinish`: the caller (the C ABI) copies the finished
    /// picture to where the application expects it.
    pub fn take_present_request(&mut self) -> bool {
        std::mem::take(&mut self.present_requested)
    }

    /// True once after each `glViewport`: the caller (the C ABI) resizes the buffers to a
    /// window whose size changed.
    pub fn take_drawable_check_request(&mut self) -> bool {
        std::mem::take(&mut self.drawable_check_requested)
    }

    /// Makes every draw take the general fragment path instead of a specialised one (for
    /// testing that both agree).
    pub fn set_force_general_path(&mut self, on: bool) {
        self.force_general_path = on;
        self.draw_state = None;
    }

    /// Records a GL error (the first one sticks until `glGetError`).
    pub(crate) fn record_error(&mut self, error: GLenum) {
        self.error.record(error);
    }

    /// The guard for calls illegal between `glBegin` and `glEnd`: records
    /// `GL_INVALID_OPERATION` and returns true when inside.
    pub(crate) fn reject_inside_begin_end(&mut self) -> bool {
        if self.immediate.is_some() {
            self.record_error(GL_INVALID_OPERATION);
            true
        } else {
            false
        }
    }

    /// [`Context::reject_inside_begin_end`] for the commands that record themselves into
    /// display lists (the array draws): the error is recorded into the list being compiled
    /// too, and raised now unless the list is only compiled.
    pub(crate) fn reject_inside_begin_end_in_lists(&mut self) -> bool {
        if self.immediate.is_some() {
            self.list_aware_error(GL_INVALID_OPERATION);
            true
        } else {
            false
        }
    }

    /// Marks drawing state changed: the next draw builds a new snapshot.
    #[inline]
    pub(crate) fn invalidate(&mut self) {
        self.draw_state = None;
        self.light_setup = None;
    }

    /// Keeps `s` alive with the context and returns a C string pointer to it.
    pub(crate) fn intern_string(&mut self, s: &str) -> *const GLubyte {
        let entry = self
            .strings
            .entry(s.to_string())
            .or_insert_with(|| CString::new(s.replace('\0', "")).unwrap_or_default());
        entry.as_ptr() as *const GLubyte
    }

    // ----- entry points: errors, strings, flush

    pub(crate) fn get_error(&mut self) -> GLenum {
        self.error.take()
    }

    pub(crate) fn get_string(&mut self, name: GLenum) -> Option<String> {
        let Some(name) = convert::string_name(name) else {
            self.record_error(GL_INVALID_ENUM);
            return None;
        };
        Some(
            match name {
                StringName::Vendor => "tilegl",
                StringName::Renderer => "tilegl tile-based software rasterizer",
                StringName::Version => "1.5 tilegl 0.1",
                // Only what works end to end (and is verified against Mesa) is listed.
                StringName::Extensions => EXTENSIONS,
                // No shading language: version 0.0. The name is OpenGL 2.0's, but programs
                // read it from any context, parsing "major.minor" (piglit's GL 1.x tests
                // tex-miplevel-selection and others call piglit_get_glsl_version, which
                // would dereference NULL); GLSL support is still told by GL_VERSION and
                // GL_ARB_shading_language_100, neither of which claims it.
                StringName::ShadingLanguageVersion => "0.0",
            }
            .to_string(),
        )
    }

    pub(crate) fn flush(&mut self) {
        self.flush_scene();
        self.present();
    }

    pub(crate) fn finish(&mut self) {
        self.flush_scene();
        self.present();
    }

    fn present(&mut self) {
        self.present_requested = true;
    }

    pub(crate) fn hint(&mut self, target: GLenum, mode: GLenum) {
        let (Some(target), Some(mode)) = (convert::hint_target(target), convert::hint_mode(mode))
        else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        let h = &mut self.hints;
        *match target {
            HintTarget::PerspectiveCorrection => &mut h.perspective_correction,
            HintTarget::PointSmooth => &mut h.point_smooth,
            HintTarget::LineSmooth => &mut h.line_smooth,
            HintTarget::PolygonSmooth => &mut h.polygon_smooth,
            HintTarget::Fog => &mut h.fog,
            HintTarget::GenerateMipmap => &mut h.generate_mipmap,
            HintTarget::TextureCompression => &mut h.texture_compression,
        } = mode;
    }

    // ----- enables

    fn set_capability(&mut self, cap: GLenum, on: bool) {
        let Some(cap) = convert::capability(cap) else {
            // The vertex arrays' names enable the arrays, as glEnable did in EXT_vertex_array
            // (before GL 1.1 moved them to glEnableClientState) and still does in Mesa's and
            // other drivers' compatibility contexts; programs (piglit's among them) rely on
            // it. glIsEnabled answers for them as GL 1.1 specifies.
            if convert::client_array(cap).is_some() {
                self.set_client_state(cap, on);
                return;
            }
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        match cap {
            Capability::DepthTest => self.fragment_ops.depth_test = on,
            Capability::CullFace => self.raster.cull_enabled = on,
            Capability::ScissorTest => self.fragment_ops.scissor_enabled = on,
            Capability::ClipPlane(i) => self.transform.clip_plane_enabled[i] = on,
            Capability::Dither => self.fragment_ops.dither = on,
            Capability::Normalize => self.transform.normalize = on,
            Capability::RescaleNormal => self.transform.rescale_normal = on,
            Capability::Texture(t) => self.textures.set_enabled(self.active_texture, t, on),
            Capability::AlphaTest => self.fragment_ops.alpha_test = on,
            Capability::StencilTest => self.fragment_ops.stencil_test = on,
            Capability::Blend => self.fragment_ops.blend = on,
            Capability::ColorLogicOp => self.fragment_ops.color_logic_op = on,
            Capability::IndexLogicOp => self.fragment_ops.index_logic_op = on,
            Capability::Lighting => self.lighting.enabled = on,
            Capability::Light(i) => self.lighting.lights[i].enabled = on,
            Capability::ColorMaterial => {
                self.lighting.color_material = on;
                // Enabling makes the current colour the tracked material at once.
                let c = self.current.color;
                self.lighting.track_color(c);
            }
            Capability::ColorSum => self.lighting.color_sum = on,
            Capability::TexGen(c) => self.tex_gen[self.active_texture][c].enabled = on,
            Capability::Fog => self.fog.enabled = on,
            Capability::PointSmooth => self.raster.point_smooth = on,
            Capability::PointSprite => self.raster.point_sprite = on,
            Capability::LineSmooth => self.raster.line_smooth = on,
            Capability::PolygonSmooth => self.raster.polygon_smooth = on,
            Capability::LineStipple => self.raster.line_stipple = on,
            Capability::PolygonStipple => self.raster.polygon_stipple = on,
            Capability::PolygonOffsetFill => self.raster.offset_enabled[0] = on,
            Capability::PolygonOffsetLine => self.raster.offset_enabled[1] = on,
            Capability::PolygonOffsetPoint => self.raster.offset_enabled[2] = on,
            Capability::Multisample(m) => *self.multisample.enable(m) = on,
            Capability::Map1(t) => self.eval.map1_enabled[t.index()] = on,
            Capability::Map2(t) => self.eval.map2_enabled[t.index()] = on,
            Capability::AutoNormal => self.eval.auto_normal = on,
        }
        self.invalidate();
    }

    pub(crate) fn enable(&mut self, cap: GLenum) {
        self.set_capability(cap, true);
    }

    pub(crate) fn disable(&mut self, cap: GLenum) {
        self.set_capability(cap, false);
    }

    pub(crate) fn is_enabled(&mut self, cap: GLenum) -> GLboolean {
        let Some(cap) = convert::capability(cap) else {
            if let Some(on) = self.client_array_enabled(cap) {
                return on as GLboolean;
            }
            self.record_error(GL_INVALID_ENUM);
            return GL_FALSE as GLboolean;
        };
        self.capability_enabled(cap) as GLboolean
    }

    pub(crate) fn capability_enabled(&self, cap: Capability) -> bool {
        match cap {
            Capability::DepthTest => self.fragment_ops.depth_test,
            Capability::CullFace => self.raster.cull_enabled,
            Capability::ScissorTest => self.fragment_ops.scissor_enabled,
            Capability::ClipPlane(i) => self.transform.clip_plane_enabled[i],
            Capability::Dither => self.fragment_ops.dither,
            Capability::Normalize => self.transform.normalize,
            Capability::RescaleNormal => self.transform.rescale_normal,
            Capability::Texture(t) => self.textures.is_enabled(self.active_texture, t),
            Capability::AlphaTest => self.fragment_ops.alpha_test,
            Capability::StencilTest => self.fragment_ops.stencil_test,
            Capability::Blend => self.fragment_ops.blend,
            Capability::ColorLogicOp => self.fragment_ops.color_logic_op,
            Capability::IndexLogicOp => self.fragment_ops.index_logic_op,
            Capability::Lighting => self.lighting.enabled,
            Capability::Light(i) => self.lighting.lights[i].enabled,
            Capability::ColorMaterial => self.lighting.color_material,
            Capability::ColorSum => self.lighting.color_sum,
            Capability::TexGen(c) => self.tex_gen[self.active_texture][c].enabled,
            Capability::Fog => self.fog.enabled,
            Capability::PointSmooth => self.raster.point_smooth,
            Capability::PointSprite => self.raster.point_sprite,
            Capability::LineSmooth => self.raster.line_smooth,
            Capability::PolygonSmooth => self.raster.polygon_smooth,
            Capability::LineStipple => self.raster.line_stipple,
            Capability::PolygonStipple => self.raster.polygon_stipple,
            Capability::PolygonOffsetFill => self.raster.offset_enabled[0],
            Capability::PolygonOffsetLine => self.raster.offset_enabled[1],
            Capability::PolygonOffsetPoint => self.raster.offset_enabled[2],
            Capability::Multisample(m) => self.multisample.enabled(m),
            Capability::Map1(t) => self.eval.map1_enabled[t.index()],
            Capability::Map2(t) => self.eval.map2_enabled[t.index()],
            Capability::AutoNormal => self.eval.auto_normal,
        }
    }

    // ----- rasterization state

    pub(crate) fn cull_face(&mut self, mode: GLenum) {
        let Some(face) = convert::face(mode) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.raster.cull_face = face;
        self.invalidate();
    }

    pub(crate) fn front_face(&mut self, mode: GLenum) {
        let Some(w) = convert::winding(mode) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.raster.front_face = w;
        self.invalidate();
    }

    pub(crate) fn shade_model(&mut self, mode: GLenum) {
        let Some(m) = convert::shade_model(mode) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.raster.shade_model = m;
        self.invalidate();
    }

    /// EXT_provoking_vertex.
    pub(crate) fn provoking_vertex_ext(&mut self, mode: GLenum) {
        let Some(m) = convert::provoking_vertex(mode) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.raster.provoking_vertex = m;
        self.invalidate();
    }

    // ----- per-fragment operations and framebuffer control

    pub(crate) fn depth_func(&mut self, func: GLenum) {
        let Some(f) = convert::compare_func(func) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        self.fragment_ops.depth_func = f;
        self.invalidate();
    }

    pub(crate) fn depth_mask(&mut self, flag: GLboolean) {
        self.fragment_ops.depth_mask = flag != 0;
        self.invalidate();
    }

    pub(crate) fn color_mask(&mut self, r: GLboolean, g: GLboolean, b: GLboolean, a: GLboolean) {
        self.fragment_ops.color_mask = [r != 0, g != 0, b != 0, a != 0];
        self.invalidate();
    }

    pub(crate) fn stencil_mask(&mut self, mask: GLuint) {
        self.fragment_ops.stencil_writemask = mask;
        self.invalidate();
    }

    pub(crate) fn scissor(&mut self, x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
        if width < 0 || height < 0 {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        self.fragment_ops.scissor = Viewport {
            x,
            y,
            width,
            height,
        };
        self.invalidate();
    }

    pub(crate) fn clear_color(&mut self, r: GLclampf, g: GLclampf, b: GLclampf, a: GLclampf) {
        self.clear_values.color = [r, g, b, a].map(|c| clamp01(c as f64) as f32);
    }

    pub(crate) fn clear_depth(&mut self, depth: GLclampd) {
        self.clear_values.depth = clamp01(depth);
    }

    pub(crate) fn clear_stencil(&mut self, s: GLint) {
        self.clear_values.stencil = s;
    }

    pub(crate) fn clear(&mut self, mask: GLbitfield) {
        let Some(mask) = convert::clear_mask(mask) else {
            self.record_error(GL_INVALID_VALUE);
            return;
        };
        if !self.framebuffer_ready() {
            return;
        }
        if self.select.mode != convert::RenderMode::Render {
            // Selection and feedback modes change no buffer (as in Mesa).
            return;
        }
        if mask.accum {
            self.clear_accum_buffer();
        }
        self.record_clear(mask);
    }

    pub(crate) fn pixel_storei(&mut self, pname: GLenum, param: GLint) {
        let Some(p) = convert::pixel_store_param(pname) else {
            self.record_error(GL_INVALID_ENUM);
            return;
        };
        use PixelStoreParam::*;
        let (pack, value_ok) = match p {
            Alignment { pack } => (pack, matches!(param, 1 | 2 | 4 | 8)),
            RowLength { pack }
            | SkipPixels { pack }
            | SkipRows { pack }
            | SkipImages { pack }
            | ImageHeight { pack } => (pack, param >= 0),
            SwapBytes { pack } | LsbFirst { pack } => (pack, true),
        };
        if !value_ok {
            self.record_error(GL_INVALID_VALUE);
            return;
        }
        let s = if pack {
            &mut self.pack
        } else {
            &mut self.unpack
        };
        match p {
            Alignment { .. } => s.alignment = param,
            RowLength { .. } => s.row_length = param,
            SkipPixels { .. } => s.skip_pixels = param,
            SkipRows { .. } => s.skip_rows = param,
            SkipImages { .. } => s.skip_images = param,
            ImageHeight { .. } => s.image_height = param,
            SwapBytes { .. } => s.swap_bytes = param != 0,
            LsbFirst { .. } => s.lsb_first = param != 0,
        }
    }

    pub(crate) fn pixel_storef(&mut self, pname: GLenum, param: GLfloat) {
        // Section 3.6.1: a float value is rounded to the nearest integer (booleans: non-zero).
        let v = if param.is_finite() {
            param.round().clamp(i32::MIN as f32, i32::MAX as f32) as i32
        } else {
            -1
        };
        self.pixel_storei(pname, v);
    }
}

/// Clamps to [0, 1]; NaN becomes 0.
pub(crate) fn clamp01(v: f64) -> f64 {
    if v >= 1.0 {
        1.0
    } else if v > 0.0 {
        v
    } else {
        0.0
    }
}
