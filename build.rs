//! Generates the GL enums and the entry-point table from the Khronos registry (`gl.xml` shipped by
//! the `khronos_api` crate), so nothing of the API surface is typed by hand.
//!
//! Outputs (in `OUT_DIR`):
//! - `enums.rs`: every GL 1.0-1.5 enum, the two extensions tilegl implements
//!   (EXT_texture_filter_anisotropic, EXT_texture_compression_s3tc), and the ARB/EXT aliases of
//!   core enums that legacy programs use; plus name <-> value lookup tables.
//! - `commands.rs`: the `Gl` trait (one method per GL 1.5 entry point and the two of
//!   EXT_compiled_vertex_array, each defaulting to "unsupported"), the `COMMANDS` metadata
//!   table with ARB/EXT alias names, and the `gl_forward!` macro that implements trait methods
//!   by forwarding to inherent methods behind the one guard that enforces what is legal between
//!   `glBegin` and `glEnd`, after the display-list recording prologue (`list_record_code`).
//! - `capi_exports.rs`: the `extern "C"` entry points with the C signatures of `GL/gl.h`.
//! - `foreign.rs`: `ForeignGl`, an implementation of `Gl` that calls C function pointers (the
//!   Mesa oracle).

use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::fmt::Write as _;
use std::path::PathBuf;

#[path = "build/c_tables.rs"]
mod c_tables;
#[path = "build/replay.rs"]
mod replay;
use c_tables::*;
use replay::*;

#[derive(Clone, Debug)]
struct Param {
    name: String,
    base: String,
    is_const: bool,
    depth: usize,
    len: Option<String>,
    group: Option<String>,
}

#[derive(Clone, Debug)]
struct Command {
    name: String,
    ret_base: String,
    ret_depth: usize,
    params: Vec<Param>,
    alias_of: Option<String>,
}

const VERSIONS: [&str; 6] = [
    "GL_VERSION_1_0",
    "GL_VERSION_1_1",
    "GL_VERSION_1_2",
    "GL_VERSION_1_3",
    "GL_VERSION_1_4",
    "GL_VERSION_1_5",
];
const EXTENSIONS: [&str; 2] = [
    "GL_EXT_texture_filter_anisotropic",
    "GL_EXT_texture_compression_s3tc",
];
/// Extra enums outside GL 1.5 that the shared captures use and tilegl implements (see docs/features.md).
const EXTRA_EXTENSIONS: [&str; 11] = [
    "GL_NV_texture_env_combine4",
    // The unsuffixed framebuffer-object enums (GL_FRAMEBUFFER, GL_MAX_SAMPLES, ...).
    "GL_ARB_framebuffer_object",
    "GL_ARB_texture_rectangle",
    "GL_ATI_texture_mirror_once",
    "GL_EXT_texture_mirror_clamp",
    "GL_EXT_blend_equation_separate",
    "GL_ARB_texture_swizzle",
    // Internal formats captures from newer drivers copy into (texture/format.rs).
    "GL_ARB_texture_rg",
    "GL_ARB_texture_float",
    "GL_ARB_depth_buffer_float",
    "GL_EXT_packed_depth_stencil",
];

/// Enums of later core versions that captures use, generated like the others: generic
/// compressed RED/RG (GL 3.0) and point sprites (ARB_point_sprite, GL 2.0's coordinate
/// origin).
const EXTRA_ENUMS: [&str; 19] = [
    "GL_COMPRESSED_RED",
    "GL_COMPRESSED_RG",
    "GL_POINT_SPRITE",
    "GL_COORD_REPLACE",
    "GL_POINT_SPRITE_COORD_ORIGIN",
    "GL_LOWER_LEFT",
    "GL_UPPER_LEFT",
    // ARB_pixel_buffer_object's targets under their GL 2.1 and EXT_pixel_buffer_object names.
    "GL_PIXEL_PACK_BUFFER",
    "GL_PIXEL_UNPACK_BUFFER",
    "GL_PIXEL_PACK_BUFFER_BINDING",
    "GL_PIXEL_UNPACK_BUFFER_BINDING",
    "GL_PIXEL_PACK_BUFFER_EXT",
    "GL_PIXEL_UNPACK_BUFFER_EXT",
    "GL_PIXEL_PACK_BUFFER_BINDING_EXT",
    "GL_PIXEL_UNPACK_BUFFER_BINDING_EXT",
    // The buffer state ARB_map_buffer_range's mappings set (GL 3.0 names, no suffix).
    "GL_BUFFER_ACCESS_FLAGS",
    "GL_BUFFER_MAP_LENGTH",
    "GL_BUFFER_MAP_OFFSET",
    // GL 2.0's glGetString name, which piglit's GL 1.x tests read unconditionally.
    "GL_SHADING_LANGUAGE_VERSION",
];

/// Extensions whose entry points (and enums) join the GL 1.5 ones: the `Gl` trait, the C
/// exports, `ForeignGl` and the replay dispatch get them like core commands (those that alias
/// a core command become its aliases, below). EXT_vertex_array's `gl*PointerEXT` take a `count` the core ones lack.
const COMMAND_EXTENSIONS: [&str; 10] = [
    "GL_EXT_compiled_vertex_array",
    "GL_EXT_blend_equation_separate",
    "GL_EXT_vertex_array",
    "GL_EXT_provoking_vertex",
    "GL_EXT_framebuffer_object",
    "GL_EXT_framebuffer_blit",
    "GL_ARB_map_buffer_range",
    // No entry points: its targets and binding queries.
    "GL_ARB_pixel_buffer_object",
    "GL_ARB_texture_storage",
    "GL_ARB_sampler_objects",
];

/// The pixel commands of ARB_pixel_buffer_object (its issues 16 and 17) among tilegl's entry
/// points: (command, pointer parameter, whether it packs into `GL_PIXEL_PACK_BUFFER` rather
/// than unpacking from `GL_PIXEL_UNPACK_BUFFER`). While a buffer is bound to that target, the
/// pointer is an offset into it: the `Gl` trait has a `<method>_pbo` variant taking the offset
/// as `usize`, which the C exports call instead when a buffer is bound (and `ForeignGl`
/// implements by passing the offset as the pointer).
const PBO_COMMANDS: &[(&str, &str, bool)] = &[
    ("glBitmap", "bitmap", false),
    ("glCompressedTexImage1D", "data", false),
    ("glCompressedTexImage2D", "data", false),
    ("glCompressedTexImage3D", "data", false),
    ("glCompressedTexSubImage1D", "data", false),
    ("glCompressedTexSubImage2D", "data", false),
    ("glCompressedTexSubImage3D", "data", false),
    ("glDrawPixels", "pixels", false),
    ("glPixelMapfv", "values", false),
    ("glPixelMapuiv", "values", false),
    ("glPixelMapusv", "values", false),
    ("glPolygonStipple", "mask", false),
    ("glTexImage1D", "pixels", false),
    ("glTexImage2D", "pixels", false),
    ("glTexImage3D", "pixels", false),
    ("glTexSubImage1D", "pixels", false),
    ("glTexSubImage2D", "pixels", false),
    ("glTexSubImage3D", "pixels", false),
    ("glGetCompressedTexImage", "img", true),
    ("glGetPixelMapfv", "values", true),
    ("glGetPixelMapuiv", "values", true),
    ("glGetPixelMapusv", "values", true),
    ("glGetPolygonStipple", "mask", true),
    ("glGetTexImage", "pixels", true),
    ("glReadPixels", "pixels", true),
];

/// The `PBO_COMMANDS` entry of a command: its pointer parameter and whether it packs.
fn pbo_command(name: &str) -> Option<(&'static str, bool)> {
    PBO_COMMANDS
        .iter()
        .find(|(c, _, _)| *c == name)
        .map(|&(_, p, pack)| (p, pack))
}

/// ARB_framebuffer_object's commands that are not aliases of EXT_framebuffer_object's or
/// EXT_framebuffer_blit's (the spec's "Dependencies on EXT_framebuffer_object": the bind
/// commands differ, as they refuse names not made by `glGen*`) and its two new ones; the
/// other unsuffixed names are aliases of the EXT commands (below).
const ARB_FBO_COMMANDS: [&str; 4] = [
    "glBindFramebuffer",
    "glBindRenderbuffer",
    "glRenderbufferStorageMultisample",
    "glFramebufferTextureLayer",
];

const KEYWORDS: [&str; 12] = [
    "type", "ref", "in", "box", "fn", "mod", "use", "impl", "loop", "move", "match", "where",
];

fn parse_typed(node: roxmltree::Node) -> (String, String, bool, usize) {
    // Returns (name, base type, const, pointer depth).
    let mut name = String::new();
    let mut base = String::new();
    let mut text = String::new();
    for child in node.children() {
        if child.is_text() {
            text.push_str(child.text().unwrap_or(""));
        } else if child.has_tag_name("ptype") {
            base = child.text().unwrap_or("").to_string();
            text.push_str(" T ");
        } else if child.has_tag_name("name") {
            name = child.text().unwrap_or("").to_string();
        }
    }
    if base.is_empty() {
        base = if text.contains("void") {
            "void".into()
        } else {
            text.trim().to_string()
        };
    }
    if base == "GLvoid" {
        base = "void".into();
    }
    let depth = text.matches('*').count();
    let first_star = text.find('*').unwrap_or(text.len());
    let is_const = text[..first_star].contains("const");
    (name, base, is_const, depth)
}

fn snake(gl_name: &str) -> String {
    let s = gl_name.strip_prefix("gl").unwrap_or(gl_name);
    let chars: Vec<char> = s.chars().collect();
    let mut out = String::new();
    for (i, &c) in chars.iter().enumerate() {
        if i > 0 {
            let prev = chars[i - 1];
            if c.is_ascii_uppercase() && prev.is_ascii_lowercase() {
                out.push('_');
            }
            if c.is_ascii_digit() && prev.is_ascii_alphabetic() {
                out.push('_');
            }
        }
        out.push(c.to_ascii_lowercase());
    }
    out
}

fn ident(name: &str) -> String {
    let mut out = String::new();
    let chars: Vec<char> = name.chars().collect();
    for (i, &c) in chars.iter().enumerate() {
        if i > 0 && c.is_ascii_uppercase() && chars[i - 1].is_ascii_lowercase() {
            out.push('_');
        }
        out.push(c.to_ascii_lowercase());
    }
    if KEYWORDS.contains(&out.as_str()) {
        out.push('_');
    }
    out
}

fn scalar(base: &str) -> &'static str {
    match base {
        "GLenum" => "GLenum",
        "GLboolean" => "GLboolean",
        "GLbitfield" => "GLbitfield",
        "GLbyte" => "GLbyte",
        "GLshort" => "GLshort",
        "GLint" => "GLint",
        "GLsizei" => "GLsizei",
        "GLubyte" => "GLubyte",
        "GLushort" => "GLushort",
        "GLuint" => "GLuint",
        "GLfloat" => "GLfloat",
        "GLclampf" => "GLclampf",
        "GLdouble" => "GLdouble",
        "GLclampd" => "GLclampd",
        "GLintptr" => "GLintptr",
        "GLsizeiptr" => "GLsizeiptr",
        "void" => "u8",
        other => panic!("unknown GL type {other}"),
    }
}

fn literal_len(p: &Param) -> Option<usize> {
    p.len.as_deref().and_then(|l| l.parse::<usize>().ok())
}

/// Pointers that GL keeps after the call returns (client arrays, selection and feedback buffers,
/// index offsets into buffer objects): a safe slice cannot express them, so they travel as
/// addresses.
fn is_retained(cmd: &str, p: &Param) -> bool {
    p.depth >= 2
        || ((cmd.ends_with("Pointer") || cmd.ends_with("PointerEXT")) && p.name == "pointer")
        || cmd == "glInterleavedArrays"
        || cmd == "glSelectBuffer"
        || cmd == "glFeedbackBuffer"
        || ((cmd == "glDrawElements" || cmd == "glDrawRangeElements") && p.name == "indices")
}

fn trait_param_type(cmd: &str, p: &Param) -> String {
    if p.depth == 0 {
        return scalar(&p.base).to_string();
    }
    if is_retained(cmd, p) {
        return "ClientPtr".into();
    }
    let t = scalar(&p.base);
    match (p.is_const, p.base == "void", literal_len(p)) {
        (true, true, _) => "Option<&[u8]>".into(),
        (true, false, Some(n)) => format!("&[{t}; {n}]"),
        (true, false, None) => format!("&[{t}]"),
        (false, true, _) => "&mut [u8]".into(),
        (false, false, Some(n)) => format!("&mut [{t}; {n}]"),
        (false, false, None) => format!("&mut [{t}]"),
    }
}

/// The parameters of a command's pixel-buffer variant: the pointer parameter `pname` becomes
/// an offset (`usize`), the others keep their trait types.
fn pbo_params(c: &Command, pname: &str) -> Vec<String> {
    c.params
        .iter()
        .map(|p| {
            if p.name == pname {
                format!("{}: usize", ident(&p.name))
            } else {
                format!("{}: {}", ident(&p.name), trait_param_type(&c.name, p))
            }
        })
        .collect()
}

fn trait_ret_type(c: &Command) -> Option<String> {
    match (c.ret_base.as_str(), c.ret_depth) {
        ("void", 0) => None,
        ("GLubyte", 1) => Some("Option<String>".into()),
        ("void", 1) => Some("ClientPtr".into()),
        (b, 0) => Some(scalar(b).to_string()),
        other => panic!("unhandled return type {other:?} in {}", c.name),
    }
}

fn c_param_type(p: &Param) -> String {
    if p.depth == 0 {
        return scalar(&p.base).to_string();
    }
    if p.depth >= 2 {
        return "*const c_void".into();
    }
    let t = if p.base == "void" {
        "c_void"
    } else {
        scalar(&p.base)
    };
    if p.is_const {
        format!("*const {t}")
    } else {
        format!("*mut {t}")
    }
}

fn c_ret_type(c: &Command) -> Option<String> {
    match (c.ret_base.as_str(), c.ret_depth) {
        ("void", 0) => None,
        ("GLubyte", 1) => Some("*const GLubyte".into()),
        ("void", 1) => Some("*mut c_void".into()),
        (b, 0) => Some(scalar(b).to_string()),
        _ => unreachable!(),
    }
}

/// The vertex-array draws, which a display list holds as the vertices they fetch
/// (`state::arrays` records them, not the generated prologue).
const SELF_RECORDED_DRAWS: &[&str] = &[
    "glDrawArrays",
    "glDrawElements",
    "glDrawRangeElements",
    "glMultiDrawArrays",
    "glMultiDrawElements",
];

fn allowed_in_begin_end(name: &str) -> bool {
    // glIndexMask and glIndexPointer share glIndex's prefix but are not vertex commands.
    if name.contains("Pointer") || name == "glIndexMask" {
        return false;
    }
    let prefixes = [
        "glVertex",
        "glColor3",
        "glColor4",
        "glSecondaryColor3",
        "glIndex",
        "glNormal3",
        "glMaterial",
        "glTexCoord",
        "glMultiTexCoord",
        "glFogCoord",
        "glEdgeFlag",
        "glArrayElement",
        "glEvalCoord",
        "glEvalPoint",
        "glCallList",
        "glEnd",
    ];
    name == "glEnd" || prefixes.iter().any(|p| name.starts_with(p)) && name != "glEndList"
}

/// Commands that a display list never holds: section 5.4 of the 1.5 specification lists what
/// is executed immediately while a list is being compiled. Commands that return a value or
/// write through a pointer (`glGen*`, `glIs*`, `glGet*`, `glReadPixels`, `glRenderMode`, ...)
/// and those that retain client pointers (`gl*Pointer`, `glSelectBuffer`, ...) are excluded
/// by their signatures in `compiled_into_lists`. The vertex-array draw commands are compiled by
/// their own code (`state::arrays`), which dereferences the arrays at compile time.
const NOT_COMPILED_INTO_LISTS: &[&str] = &[
    "glNewList",
    "glEndList",
    "glDeleteLists",
    "glFeedbackBuffer",
    "glSelectBuffer",
    "glPixelStoref",
    "glPixelStorei",
    "glEnableClientState",
    "glDisableClientState",
    "glClientActiveTexture",
    "glPushClientAttrib",
    "glPopClientAttrib",
    "glDeleteTextures",
    "glDeleteQueries",
    "glDeleteBuffers",
    "glBindBuffer",
    "glBufferData",
    "glBufferSubData",
    "glFlush",
    "glFinish",
    "glArrayElement",
    "glDrawArrays",
    "glDrawElements",
    "glDrawRangeElements",
    "glMultiDrawArrays",
    "glMultiDrawElements",
    "glLockArraysEXT",
    "glUnlockArraysEXT",
    // EXT_framebuffer_object's additions to section 5.4: executed immediately.
    "glBindFramebufferEXT",
    "glDeleteFramebuffersEXT",
    "glBindRenderbufferEXT",
    "glDeleteRenderbuffersEXT",
    "glRenderbufferStorageEXT",
    "glFramebufferTexture1DEXT",
    "glFramebufferTexture2DEXT",
    "glFramebufferTexture3DEXT",
    "glFramebufferRenderbufferEXT",
    "glGenerateMipmapEXT",
    // Buffer object commands execute immediately (like glBufferSubData).
    "glFlushMappedBufferRange",
    // ARB_texture_storage: "add TexStorage* to the list of commands that cannot be used".
    "glTexStorage1D",
    "glTexStorage2D",
    "glTexStorage3D",
    // ARB_sampler_objects: "Sampler objects: GenSamplers and DeleteSamplers" join the
    // commands not usable in display lists (glGenSamplers is excluded by its signature);
    // glBindSampler and glSamplerParameter* are compiled.
    "glDeleteSamplers",
    // ARB_framebuffer_object's own commands, likewise.
    "glBindFramebuffer",
    "glBindRenderbuffer",
    "glRenderbufferStorageMultisample",
    "glFramebufferTextureLayer",
];

/// Whether a display list being compiled records the command (instead of executing it).
fn compiled_into_lists(c: &Command) -> bool {
    if c.ret_base != "void"
        || c.ret_depth != 0
        || NOT_COMPILED_INTO_LISTS.contains(&c.name.as_str())
    {
        return false;
    }
    c.params
        .iter()
        .all(|p| p.depth == 0 || (p.is_const && !is_retained(&c.name, p)))
}

/// The start of a forwarding method for display-list compilation: while a list is being
/// compiled, the arguments are copied into a boxed closure that replays the call through the
/// `Gl` trait (so errors are raised when the list is executed, as section 5.4 asks); in
/// `GL_COMPILE` mode the call then returns without executing.
fn list_record_code(c: &Command) -> String {
    if !compiled_into_lists(c) {
        return String::new();
    }
    let mut owned = String::new();
    let mut args = Vec::new();
    for p in &c.params {
        let n = ident(&p.name);
        let ty = trait_param_type(&c.name, p);
        if p.depth == 0 {
            args.push(n);
        } else if ty == "Option<&[u8]>" {
            write!(owned, "let {n} = {n}.map(<[u8]>::to_vec); ").unwrap();
            args.push(format!("{n}.as_deref()"));
        } else if ty.starts_with("&[") && ty.contains(';') {
            write!(owned, "let {n} = *{n}; ").unwrap();
            args.push(format!("&{n}"));
        } else {
            write!(owned, "let {n} = {n}.to_vec(); ").unwrap();
            args.push(format!("&{n}"));
        }
    }
    format!(
        "if self.list_recording() {{ {owned}self.list_record(Box::new(move |ctx: &mut Self| {{ crate::api::Gl::{}(ctx, {}); }})); if self.list_compile_only() {{ return; }} }} ",
        snake(&c.name),
        args.join(", ")
    )
}

/// The expression giving a pointer parameter's element count in the C ABI.
fn c_len_expr(cmd: &Command, p: &Param) -> String {
    // The registry gives `first` of glMultiDrawArrays the length COMPSIZE(count), where count
    // is itself an array; its real length is drawcount.
    let len = if cmd.name == "glMultiDrawArrays" && p.name == "first" {
        "drawcount".to_string()
    } else {
        p.len.clone().unwrap_or_else(|| "COMPSIZE()".into())
    };
    if let Some(n) = literal_len(p) {
        return n.to_string();
    }
    if let Some(inner) = len
        .strip_prefix("COMPSIZE(")
        .and_then(|s| s.strip_suffix(')'))
    {
        let args: Vec<String> = inner
            .split(',')
            .filter(|a| !a.trim().is_empty())
            .map(|a| format!("{} as i64", ident(a.trim())))
            .collect();
        return format!(
            "crate::capi::compsize::size(ctx, \"{}\", \"{}\", &[{}])",
            cmd.name,
            p.name,
            args.join(", ")
        );
    }
    if let Some((a, b)) = len.split_once('*') {
        return format!("count_len({} as i64 * {})", ident(a.trim()), b.trim());
    }
    format!("count_len({} as i64)", ident(len.trim()))
}

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=build");
    link_window_system_libraries();
    let xml = std::str::from_utf8(khronos_api::GL_XML).expect("gl.xml is UTF-8");
    let doc = roxmltree::Document::parse(xml).expect("gl.xml parses");
    let root = doc.root_element();

    // All enum values (api="gl" or unqualified).
    let mut enum_values: HashMap<String, u64> = HashMap::new();
    for e in root.descendants().filter(|n| n.has_tag_name("enum")) {
        if e.parent().map(|p| p.has_tag_name("enums")) != Some(true) {
            continue;
        }
        if let Some(api) = e.attribute("api") {
            if api != "gl" {
                continue;
            }
        }
        let (Some(name), Some(value)) = (e.attribute("name"), e.attribute("value")) else {
            continue;
        };
        let v = if let Some(h) = value.strip_prefix("0x") {
            u64::from_str_radix(h.trim_end_matches(['u', 'l', 'L', 'U']), 16)
        } else {
            value
                .trim_end_matches(['u', 'l', 'L', 'U'])
                .parse::<i64>()
                .map(|v| v as u64)
        };
        if let Ok(v) = v {
            enum_values.entry(name.to_string()).or_insert(v);
        }
    }

    // Commands.
    let mut commands: HashMap<String, Command> = HashMap::new();
    for c in root.descendants().filter(|n| n.has_tag_name("command")) {
        let Some(proto) = c.children().find(|n| n.has_tag_name("proto")) else {
            continue;
        };
        let (name, ret_base, _, ret_depth) = parse_typed(proto);
        let params = c
            .children()
            .filter(|n| n.has_tag_name("param"))
            .map(|p| {
                let (pname, base, is_const, depth) = parse_typed(p);
                Param {
                    name: pname,
                    base,
                    is_const,
                    depth,
                    len: p.attribute("len").map(str::to_string),
                    group: p.attribute("group").map(str::to_string),
                }
            })
            .collect();
        let alias_of = c
            .children()
            .find(|n| n.has_tag_name("alias"))
            .and_then(|a| a.attribute("name"))
            .map(str::to_string);
        commands.insert(
            name.clone(),
            Command {
                name,
                ret_base,
                ret_depth,
                params,
                alias_of,
            },
        );
    }

    // Features 1.0-1.5 and the chosen extensions.
    let mut core_cmds: Vec<String> = Vec::new();
    let mut core_enums: BTreeSet<String> = BTreeSet::new();
    let mut ext_enums: BTreeSet<String> = BTreeSet::new();
    for f in root.children().filter(|n| n.has_tag_name("feature")) {
        if f.attribute("api") != Some("gl")
            || !VERSIONS.contains(&f.attribute("name").unwrap_or(""))
        {
            continue;
        }
        for r in f.children().filter(|n| n.has_tag_name("require")) {
            for item in r.children().filter(|n| n.is_element()) {
                let Some(n) = item.attribute("name") else {
                    continue;
                };
                if item.has_tag_name("command") && !core_cmds.iter().any(|c| c == n) {
                    core_cmds.push(n.to_string());
                } else if item.has_tag_name("enum") {
                    core_enums.insert(n.to_string());
                }
            }
        }
    }
    for x in root.descendants().filter(|n| n.has_tag_name("extension")) {
        let name = x.attribute("name").unwrap_or("");
        if COMMAND_EXTENSIONS.contains(&name) {
            for c in x.descendants().filter(|n| n.has_tag_name("command")) {
                if let Some(n) = c.attribute("name") {
                    let aliases_core = commands
                        .get(n)
                        .and_then(|c| c.alias_of.as_ref())
                        .is_some_and(|t| core_cmds.contains(t));
                    if !aliases_core && !core_cmds.iter().any(|c| c == n) {
                        core_cmds.push(n.to_string());
                    }
                }
            }
        } else if !EXTENSIONS.contains(&name) && !EXTRA_EXTENSIONS.contains(&name) {
            continue;
        }
        for e in x.descendants().filter(|n| n.has_tag_name("enum")) {
            if let Some(n) = e.attribute("name") {
                ext_enums.insert(n.to_string());
            }
        }
    }
    for n in ARB_FBO_COMMANDS {
        if !core_cmds.iter().any(|c| c == n) {
            core_cmds.push(n.to_string());
        }
    }
    // Single later-core enums captures use (generic compressed RED/RG of GL 3.0).
    for n in EXTRA_ENUMS {
        ext_enums.insert(n.to_string());
    }
    core_cmds.sort();

    // ARB/EXT aliases: enums whose unsuffixed name is core with the same value.
    let core_set: BTreeSet<&String> = core_enums.iter().collect();
    let mut alias_enums: BTreeSet<String> = BTreeSet::new();
    for (name, v) in &enum_values {
        for suffix in ["_ARB", "_EXT"] {
            if let Some(base) = name.strip_suffix(suffix) {
                if core_set.contains(&base.to_string()) && enum_values.get(base) == Some(v) {
                    alias_enums.insert(name.clone());
                }
            }
        }
    }
    // Command aliases.
    let core_cmd_set: BTreeSet<&String> = core_cmds.iter().collect();
    let mut cmd_aliases: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for c in commands.values() {
        if let Some(target) = &c.alias_of {
            if core_cmd_set.contains(target) && (c.name.ends_with("ARB") || c.name.ends_with("EXT"))
            {
                cmd_aliases
                    .entry(target.clone())
                    .or_default()
                    .push(c.name.clone());
            }
        }
    }
    // Extension entry points that later became core (glBlendEquationSeparateEXT, core in
    // GL 2.0): the core name is an alias of the extension one, for programs that call it.
    for c in commands.values() {
        if let Some(target) = &c.alias_of {
            if core_cmd_set.contains(&c.name) && !core_cmd_set.contains(target) {
                cmd_aliases
                    .entry(c.name.clone())
                    .or_default()
                    .push(target.clone());
            }
        }
    }
    for v in cmd_aliases.values_mut() {
        v.sort();
    }

    let out = PathBuf::from(std::env::var("OUT_DIR").expect("OUT_DIR"));

    // ---------------- enums.rs
    let mut all_enums: BTreeMap<String, (u64, u8)> = BTreeMap::new(); // name -> (value, rank)
    for n in &core_enums {
        if let Some(v) = enum_values.get(n) {
            all_enums.insert(n.clone(), (*v, 0));
        }
    }
    for n in &ext_enums {
        if let Some(v) = enum_values.get(n) {
            all_enums.entry(n.clone()).or_insert((*v, 1));
        }
    }
    for n in &alias_enums {
        if let Some(v) = enum_values.get(n) {
            all_enums.entry(n.clone()).or_insert((*v, 2));
        }
    }
    let mut s = String::new();
    writeln!(
        s,
        "// Generated by build.rs from the Khronos registry. Do not edit."
    )
    .unwrap();
    for (n, (v, _)) in &all_enums {
        if *v > u32::MAX as u64 {
            continue;
        }
        writeln!(s, "pub const {n}: GLenum = 0x{v:X};").unwrap();
    }
    writeln!(
        s,
        "/// Every generated enum name with its value, sorted by name."
    )
    .unwrap();
    writeln!(s, "pub static ENUMS_BY_NAME: &[(&str, GLenum)] = &[").unwrap();
    for (n, (v, _)) in &all_enums {
        if *v <= u32::MAX as u64 {
            writeln!(s, "    (\"{n}\", 0x{v:X}),").unwrap();
        }
    }
    writeln!(s, "];").unwrap();
    std::fs::write(out.join("enums.rs"), s).expect("write enums.rs");

    // ---------------- commands.rs (the C headers need `core` and `all_enums` too)
    let core: Vec<&Command> = core_cmds
        .iter()
        .map(|n| {
            commands
                .get(n)
                .unwrap_or_else(|| panic!("command {n} missing"))
        })
        .collect();
    let mut s = String::new();
    writeln!(
        s,
        "// Generated by build.rs from the Khronos registry. Do not edit."
    )
    .unwrap();
    writeln!(
        s,
        "/// One method per OpenGL 1.5 entry point, named after the GL function in snake case\n\
/// (`glTexImage2D` is `tex_image_2d`). Every method defaults to [`Gl::unsupported`], so an\n\
/// implementation states exactly which entry points it provides.\n\
///\n\
/// Pointer parameters are slices (fixed-size arrays where GL fixes the length); pointers that\n\
/// GL keeps after the call (client arrays, selection and feedback buffers) are [`ClientPtr`]s."
    )
    .unwrap();
    writeln!(s, "#[allow(clippy::too_many_arguments)]").unwrap();
    writeln!(s, "pub trait Gl {{").unwrap();
    writeln!(
        s,
        "    /// Called by every entry point the implementation does not provide; should record\n    /// `GL_INVALID_OPERATION`."
    )
    .unwrap();
    writeln!(s, "    fn unsupported(&mut self, name: &'static str);").unwrap();
    let mut forward_arms = String::new();
    for c in &core {
        let rname = snake(&c.name);
        let params: Vec<String> = c
            .params
            .iter()
            .map(|p| format!("{}: {}", ident(&p.name), trait_param_type(&c.name, p)))
            .collect();
        let ret = trait_ret_type(c)
            .map(|r| format!(" -> {r}"))
            .unwrap_or_default();
        let names: Vec<String> = c.params.iter().map(|p| ident(&p.name)).collect();
        writeln!(s, "    /// `{}`", c.name).unwrap();
        writeln!(
            s,
            "    fn {rname}(&mut self, {}){ret} {{",
            params.join(", ")
        )
        .unwrap();
        if !names.is_empty() {
            writeln!(s, "        let _ = ({},);", names.join(", ")).unwrap();
        }
        writeln!(s, "        self.unsupported(\"{}\");", c.name).unwrap();
        if ret.is_empty() {
            writeln!(s, "    }}").unwrap();
        } else {
            writeln!(s, "        Default::default()\n    }}").unwrap();
        }
        // Forwarding arm.
        let guard = if allowed_in_begin_end(&c.name) {
            String::new()
        } else if SELF_RECORDED_DRAWS.contains(&c.name.as_str()) {
            // These record themselves (after the guard): the error goes into the list too, so
            // that a list compiled with GL_COMPILE_AND_EXECUTE raises it again when called.
            "if self.reject_inside_begin_end_in_lists() { return Default::default(); } ".into()
        } else {
            "if self.reject_inside_begin_end() { return Default::default(); } ".into()
        };
        let record = list_record_code(c);
        writeln!(
            forward_arms,
            "    ({rname}) => {{ fn {rname}(&mut self, {}){ret} {{ {record}{guard}Self::{rname}(self, {}) }} }};",
            params.join(", "),
            names.join(", ")
        )
        .unwrap();
        if let Some((pname, pack)) = pbo_command(&c.name) {
            // The pixel-buffer variant: the pointer parameter becomes an offset.
            let pbo_params = pbo_params(c, pname);
            let target = if pack {
                "GL_PIXEL_PACK_BUFFER"
            } else {
                "GL_PIXEL_UNPACK_BUFFER"
            };
            writeln!(
                s,
                "    /// `{}` with a buffer bound to `{target}`: `{}` is an offset into it\n    /// (ARB_pixel_buffer_object).",
                c.name,
                ident(pname)
            )
            .unwrap();
            writeln!(
                s,
                "    fn {rname}_pbo(&mut self, {}) {{",
                pbo_params.join(", ")
            )
            .unwrap();
            writeln!(s, "        let _ = ({},);", names.join(", ")).unwrap();
            writeln!(s, "        self.unsupported(\"{}\");\n    }}", c.name).unwrap();
            // Packing commands (never compiled into display lists) forward as they are. An
            // unpacking one takes its data out of the buffer (the inherent `_pbo` method checks
            // the access and returns the data) and goes on as the call with that data in client
            // memory, so that a display list being compiled keeps the data (section 5.4 of
            // OpenGL 2.1: buffer data is dereferenced when the list is compiled).
            let body = if pack {
                format!("{guard}Self::{rname}_pbo(self, {})", names.join(", "))
            } else {
                let p = c
                    .params
                    .iter()
                    .find(|p| p.name == pname)
                    .expect("pbo parameter");
                let data = if trait_param_type(&c.name, p).starts_with("Option<") {
                    "Some(&data)"
                } else {
                    "&data"
                };
                let args: Vec<String> = c
                    .params
                    .iter()
                    .map(|p| {
                        if p.name == pname {
                            data.to_string()
                        } else {
                            ident(&p.name)
                        }
                    })
                    .collect();
                format!(
                    "if !self.list_recording() {{ {guard}}} if let Some(data) = Self::{rname}_pbo(self, {}) {{ crate::api::Gl::{rname}(self, {}) }}",
                    names.join(", "),
                    args.join(", ")
                )
            };
            writeln!(
                forward_arms,
                "    ({rname}_pbo) => {{ fn {rname}_pbo(&mut self, {}) {{ {body} }} }};",
                pbo_params.join(", ")
            )
            .unwrap();
        }
    }
    writeln!(s, "}}").unwrap();
    writeln!(
        s,
        "/// Implements `Gl` methods by forwarding to inherent methods of the same name, behind the\n\
/// one guard for calls that are illegal between `glBegin` and `glEnd`.\n\
#[doc(hidden)]\nmacro_rules! gl_forward_one {{\n{forward_arms}}}\n\
/// Implements a list of `Gl` methods by forwarding (see `gl_forward_one`).\n\
#[doc(hidden)]\nmacro_rules! gl_forward_all {{ ($($name:ident),* $(,)?) => {{ $( gl_forward_one!($name); )* }} }}"
    )
    .unwrap();

    // Metadata table.
    writeln!(
        s,
        "/// Metadata for every GL 1.5 entry point, sorted by name."
    )
    .unwrap();
    writeln!(s, "pub static COMMANDS: &[CommandInfo] = &[").unwrap();
    for c in &core {
        let aliases = cmd_aliases.get(&c.name).cloned().unwrap_or_default();
        let params: Vec<String> = c
            .params
            .iter()
            .map(|p| {
                let ctype = if p.depth == 0 {
                    p.base.clone()
                } else {
                    format!(
                        "{}{} {}",
                        if p.is_const { "const " } else { "" },
                        p.base,
                        "*".repeat(p.depth)
                    )
                };
                format!(
                    "ParamInfo {{ name: \"{}\", c_type: \"{}\", group: {:?}, len: {:?} }}",
                    p.name, ctype, p.group, p.len
                )
            })
            .collect();
        writeln!(
            s,
            "    CommandInfo {{ name: \"{}\", rust_name: \"{}\", params: &[{}], returns: \"{}{}\", aliases: &[{}], allowed_in_begin_end: {} }},",
            c.name,
            snake(&c.name),
            params.join(", "),
            c.ret_base,
            "*".repeat(c.ret_depth),
            aliases.iter().map(|a| format!("\"{a}\"")).collect::<Vec<_>>().join(", "),
            allowed_in_begin_end(&c.name)
        )
        .unwrap();
    }
    writeln!(s, "];").unwrap();
    std::fs::write(out.join("commands.rs"), s).expect("write commands.rs");

    // ---------------- capi_exports.rs and foreign.rs
    let mut ex = String::new();
    let mut fo = String::new();
    writeln!(
        ex,
        "// Generated by build.rs from the Khronos registry. Do not edit."
    )
    .unwrap();
    writeln!(
        fo,
        "// Generated by build.rs from the Khronos registry. Do not edit."
    )
    .unwrap();
    writeln!(fo, "impl Gl for ForeignGl {{").unwrap();
    writeln!(
        fo,
        "    fn unsupported(&mut self, name: &'static str) {{ self.missing.push(name); }}"
    )
    .unwrap();
    for (idx, c) in core.iter().enumerate() {
        let rname = snake(&c.name);
        let c_params: Vec<String> = c
            .params
            .iter()
            .map(|p| format!("{}: {}", ident(&p.name), c_param_type(p)))
            .collect();
        let c_types: Vec<String> = c.params.iter().map(c_param_type).collect();
        let c_ret = c_ret_type(c)
            .map(|r| format!(" -> {r}"))
            .unwrap_or_default();
        let has_ret = !c_ret.is_empty();
        let mut conv = String::new();
        let mut call_args = Vec::new();
        for p in &c.params {
            let n = ident(&p.name);
            if p.depth == 0 {
                call_args.push(n);
                continue;
            }
            if is_retained(&c.name, p) {
                call_args.push(format!("ClientPtr({n} as usize)"));
                continue;
            }
            let len = c_len_expr(c, p);
            let t = scalar(&p.base);
            let e = match (p.is_const, p.base == "void", literal_len(p)) {
                (true, true, _) => format!("let {n} = opt_slice({n} as *const u8, {len});"),
                (true, false, Some(k)) => {
                    format!("let Some({n}) = array_ref::<{t}, {k}>({n}) else {{ return Default::default(); }};")
                }
                (true, false, None) => format!("let {n} = slice({n}, {len});"),
                (false, true, _) => format!("let {n} = slice_mut({n} as *mut u8, {len});"),
                (false, false, Some(k)) => {
                    format!("let Some({n}) = array_mut::<{t}, {k}>({n}) else {{ return Default::default(); }};")
                }
                (false, false, None) => format!("let {n} = slice_mut({n}, {len});"),
            };
            conv.push_str("        ");
            conv.push_str(&e);
            conv.push('\n');
            call_args.push(n);
        }
        let ret_conv = match (c.ret_base.as_str(), c.ret_depth) {
            ("GLubyte", 1) => ".map_or(std::ptr::null(), |s| ctx.intern_string(&s))",
            ("void", 1) => ".0 as *mut c_void",
            _ => "",
        };
        writeln!(
            ex,
            "/// `{}`: forwards to [`Gl::{rname}`] on the current context.",
            c.name
        )
        .unwrap();
        writeln!(ex, "///\n/// # Safety\n/// Pointer arguments follow the C API's contract: each points to as many elements as GL reads or writes.").unwrap();
        writeln!(ex, "#[no_mangle]\n#[allow(clippy::too_many_arguments, clippy::missing_safety_doc, unused_variables)]").unwrap();
        writeln!(
            ex,
            "pub unsafe extern \"C\" fn {}({}){c_ret} {{",
            c.name,
            c_params.join(", ")
        )
        .unwrap();
        writeln!(ex, "    with_current(|ctx| {{").unwrap();
        if let Some((pname, pack)) = pbo_command(&c.name) {
            // ARB_pixel_buffer_object: with a buffer bound, the pointer is an offset into it.
            let args: Vec<String> = c
                .params
                .iter()
                .map(|p| {
                    let n = ident(&p.name);
                    if p.name == pname {
                        format!("{n} as usize")
                    } else {
                        n
                    }
                })
                .collect();
            writeln!(
                ex,
                "        if ctx.pixel_buffer_bound({pack}) {{ return Gl::{rname}_pbo(ctx, {}); }}",
                args.join(", ")
            )
            .unwrap();
        }
        ex.push_str(&conv);
        writeln!(
            ex,
            "        Gl::{rname}(ctx, {}){ret_conv}",
            call_args.join(", ")
        )
        .unwrap();
        writeln!(ex, "    }})").unwrap();
        writeln!(ex, "}}").unwrap();
        for a in cmd_aliases.get(&c.name).into_iter().flatten() {
            let names: Vec<String> = c.params.iter().map(|p| ident(&p.name)).collect();
            writeln!(
                ex,
                "/// `{a}`: the extension name of `{}`.\n///\n/// # Safety\n/// As for `{}`.",
                c.name, c.name
            )
            .unwrap();
            writeln!(
                ex,
                "#[no_mangle]\n#[allow(clippy::too_many_arguments, clippy::missing_safety_doc)]"
            )
            .unwrap();
            writeln!(
                ex,
                "pub unsafe extern \"C\" fn {a}({}){c_ret} {{ {}({}) }}",
                c_params.join(", "),
                c.name,
                names.join(", ")
            )
            .unwrap();
        }

        // Foreign forwarding.
        let t_params: Vec<String> = c
            .params
            .iter()
            .map(|p| format!("{}: {}", ident(&p.name), trait_param_type(&c.name, p)))
            .collect();
        let t_ret = trait_ret_type(c)
            .map(|r| format!(" -> {r}"))
            .unwrap_or_default();
        let f_args: Vec<String> = c
            .params
            .iter()
            .map(|p| {
                let n = ident(&p.name);
                if p.depth == 0 {
                    n
                } else if is_retained(&c.name, p) {
                    format!("{n}.0 as *const c_void as _")
                } else if p.is_const && p.base == "void" {
                    format!("{n}.map_or(std::ptr::null(), |s| s.as_ptr()) as *const c_void")
                } else if p.is_const {
                    format!("{n}.as_ptr()")
                } else if p.base == "void" {
                    format!("{n}.as_mut_ptr() as *mut c_void")
                } else {
                    format!("{n}.as_mut_ptr()")
                }
            })
            .collect();
        let f_ret_conv = match (c.ret_base.as_str(), c.ret_depth) {
            ("GLubyte", 1) => "; c_string(r)",
            ("void", 1) => "; ClientPtr(r as usize)",
            _ if has_ret => "; r",
            _ => ";",
        };
        writeln!(
            fo,
            "    fn {rname}(&mut self, {}){t_ret} {{",
            t_params.join(", ")
        )
        .unwrap();
        writeln!(fo, "        let fp = self.fns[{idx}];").unwrap();
        writeln!(
            fo,
            "        if fp.is_null() {{ self.unsupported(\"{}\"); return Default::default(); }}",
            c.name
        )
        .unwrap();
        writeln!(
            fo,
            "        // SAFETY: `fp` was looked up under this name, so it has the C signature of the\n        // registry; `ForeignGl::new`'s caller guarantees slices are as long as GL uses."
        )
        .unwrap();
        writeln!(
            fo,
            "        let fp: unsafe extern \"C\" fn({}){c_ret} = unsafe {{ std::mem::transmute(fp) }};",
            c_types.join(", ")
        )
        .unwrap();
        writeln!(
            fo,
            "        #[allow(unused_variables)] let r = unsafe {{ fp({}) }}{f_ret_conv}",
            f_args.join(", ")
        )
        .unwrap();
        writeln!(fo, "    }}").unwrap();
        if let Some((pname, _)) = pbo_command(&c.name) {
            let pbo_params = pbo_params(c, pname);
            let pbo_args: Vec<String> = c
                .params
                .iter()
                .zip(&f_args)
                .map(|(p, a)| {
                    if p.name == pname {
                        format!("{} as {}", ident(&p.name), c_param_type(p))
                    } else {
                        a.clone()
                    }
                })
                .collect();
            writeln!(
                fo,
                "    fn {rname}_pbo(&mut self, {}) {{",
                pbo_params.join(", ")
            )
            .unwrap();
            writeln!(fo, "        let fp = self.fns[{idx}];").unwrap();
            writeln!(
                fo,
                "        if fp.is_null() {{ self.unsupported(\"{}\"); return; }}",
                c.name
            )
            .unwrap();
            writeln!(
                fo,
                "        // SAFETY: as for `{rname}`; the offset travels as the pointer, as\n        // ARB_pixel_buffer_object has it while a pixel buffer is bound."
            )
            .unwrap();
            writeln!(
                fo,
                "        let fp: unsafe extern \"C\" fn({}){c_ret} = unsafe {{ std::mem::transmute(fp) }};",
                c_types.join(", ")
            )
            .unwrap();
            writeln!(
                fo,
                "        #[allow(unused_variables)] let r = unsafe {{ fp({}) }};",
                pbo_args.join(", ")
            )
            .unwrap();
            writeln!(fo, "    }}").unwrap();
        }
    }
    writeln!(fo, "}}").unwrap();
    capi_audit_tables(&mut ex, &core);
    capi_fuzz_table(&mut ex, &core);
    writeln!(ex, "/// The exported GL function of this name (core or ARB/EXT alias), for `OSMesaGetProcAddress`.").unwrap();
    writeln!(
        ex,
        "pub fn gl_proc_address(name: &str) -> *const c_void {{\n    match name {{"
    )
    .unwrap();
    for c in &core {
        writeln!(ex, "        \"{0}\" => {0} as *const c_void,", c.name).unwrap();
        for a in cmd_aliases.get(&c.name).into_iter().flatten() {
            writeln!(ex, "        \"{0}\" => {0} as *const c_void,", a).unwrap();
        }
    }
    writeln!(ex, "        _ => std::ptr::null(),\n    }}\n}}").unwrap();
    writeln!(
        fo,
        "/// Names looked up by `ForeignGl::new`, in `COMMANDS` order."
    )
    .unwrap();
    writeln!(fo, "pub const FOREIGN_NAMES: [&str; {}] = [", core.len()).unwrap();
    for c in &core {
        writeln!(fo, "    \"{}\",", c.name).unwrap();
    }
    writeln!(fo, "];").unwrap();
    std::fs::write(out.join("capi_exports.rs"), ex).expect("write capi_exports.rs");
    c_headers(&out, &core, &cmd_aliases, &all_enums);
    std::fs::write(out.join("foreign.rs"), fo).expect("write foreign.rs");

    // ---------------- replay_dispatch.rs
    std::fs::write(
        out.join("replay_dispatch.rs"),
        replay_dispatch(&core, &cmd_aliases),
    )
    .expect("write replay_dispatch.rs");
}
