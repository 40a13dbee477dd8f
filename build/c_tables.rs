//! Generated C-side tables and headers: the pointer-length audit and fuzz tables of the C
//! exports, and `include/GL/{gl,glext,osmesa}.h`.

use super::*;

/// The audit tables of the C ABI's pointer lengths (`tests/capi_lengths.rs`): every exported
/// entry point with a pointer that GL sizes at call time, with the registry's length, and for
/// those whose every pointer has a fixed length, a call with defaulted scalars.
pub(crate) fn capi_audit_tables(ex: &mut String, core: &[&Command]) {
    writeln!(ex, "/// Entry points with pointer parameters sized at call time: (name, parameter, registry length).").unwrap();
    writeln!(
        ex,
        "#[doc(hidden)]\npub const SIZED_POINTER_PARAMS: &[(&str, &str, &str)] = &["
    )
    .unwrap();
    for c in core {
        for p in c
            .params
            .iter()
            .filter(|p| p.depth > 0 && !is_retained(&c.name, p))
        {
            let len = p.len.clone().unwrap_or_default();
            writeln!(ex, "    (\"{}\", \"{}\", \"{}\"),", c.name, p.name, len).unwrap();
        }
    }
    writeln!(ex, "];").unwrap();
    writeln!(ex, "/// Calls of the entry points whose every pointer has a fixed length: (name, bytes each pointer spans, call with every pointer at the argument).").unwrap();
    writeln!(
        ex,
        "#[doc(hidden)]\npub type AuditCall = unsafe fn(*mut u8);\n#[doc(hidden)]\npub const FIXED_LENGTH_CALLS: &[(&str, usize, AuditCall)] = &["
    )
    .unwrap();
    for c in core {
        let ptrs: Vec<&Param> = c.params.iter().filter(|p| p.depth > 0).collect();
        if ptrs.is_empty()
            || ptrs
                .iter()
                .any(|p| is_retained(&c.name, p) || literal_len(p).is_none())
        {
            continue;
        }
        let bytes: Vec<String> = ptrs
            .iter()
            .map(|p| {
                format!(
                    "{} * std::mem::size_of::<{}>()",
                    literal_len(p).unwrap(),
                    scalar(&p.base)
                )
            })
            .collect();
        let args: Vec<String> = c
            .params
            .iter()
            .map(|p| {
                if p.depth > 0 {
                    format!("p as {}", c_param_type(p))
                } else if p.name == "target" && c.name.starts_with("glMultiTexCoord") {
                    "crate::api::enums::GL_TEXTURE0".into()
                } else if p.name == "plane" {
                    "crate::api::enums::GL_CLIP_PLANE0".into()
                } else {
                    format!("0 as {}", scalar(&p.base))
                }
            })
            .collect();
        writeln!(
            ex,
            "    (\"{0}\", {1}, |p| unsafe {{ {3}{0}({2}); }}),",
            c.name,
            bytes[0],
            args.join(", "),
            if c.ret_base == "void" && c.ret_depth == 0 {
                ""
            } else {
                "let _ = "
            }
        )
        .unwrap();
    }
    writeln!(ex, "];").unwrap();
}

/// The table of structured calls for the fuzzer (`fuzz/`, target `c_calls`): for every
/// exported entry point, a call whose scalars come from a [`FuzzArgs`] source and whose
/// pointers point to memory the source hands out, as long as the C ABI itself computes for
/// those scalars and the current state (the same length expressions as the exports), so every
/// call keeps the C contract. Pointers GL keeps (client arrays, selection and feedback
/// buffers) are the source's to place.
pub(crate) fn capi_fuzz_table(ex: &mut String, core: &[&Command]) {
    ex.push_str(
        "/// Where the fuzzer's structured calls (`FUZZ_CALLS`) take their arguments from.\n\
#[doc(hidden)]\n\
pub trait FuzzArgs {\n\
    /// A value for the integer parameter `param` (of GL type `ty`) of `cmd`.\n\
    fn int(&mut self, cmd: &'static str, param: &'static str, ty: &'static str) -> i64;\n\
    /// A value for the floating-point parameter `param` of `cmd`.\n\
    fn float(&mut self, cmd: &'static str, param: &'static str) -> f64;\n\
    /// `bytes` bytes of memory, aligned for any GL type, for the pointer parameter `param`\n\
    /// (elements of GL type `ty`, `void` for data of any type; null is allowed), valid until\n\
    /// the call returns; `None` skips the call.\n\
    fn memory(&mut self, cmd: &'static str, param: &'static str, ty: &'static str, bytes: usize) -> Option<*mut u8>;\n\
    /// An address for a pointer parameter GL keeps after the call (client arrays, indices,\n\
    /// selection and feedback buffers, `glGetPointerv`'s result).\n\
    fn retained(&mut self, cmd: &'static str, param: &'static str) -> *mut u8;\n\
}\n\
/// A structured call: draws its arguments from the source, then calls the export.\n\
#[doc(hidden)]\n\
pub type FuzzCall = unsafe fn(&mut dyn FuzzArgs);\n\
/// Every exported entry point (core names) with its structured call.\n\
#[doc(hidden)]\n\
#[allow(clippy::unnecessary_cast, clippy::let_unit_value, unused_parens, unused_variables)]\n\
pub const FUZZ_CALLS: &[(&str, FuzzCall)] = &[\n",
    );
    for c in core {
        let mut body = String::new();
        for p in c.params.iter().filter(|p| p.depth == 0) {
            let n = ident(&p.name);
            let t = scalar(&p.base);
            let v = if matches!(t, "GLfloat" | "GLclampf" | "GLdouble" | "GLclampd") {
                format!("a.float(\"{}\", \"{}\") as {t}", c.name, p.name)
            } else {
                format!("a.int(\"{}\", \"{}\", \"{t}\") as {t}", c.name, p.name)
            };
            writeln!(body, "        let {n} = {v};").unwrap();
        }
        for p in c.params.iter().filter(|p| p.depth > 0) {
            let n = ident(&p.name);
            if is_retained(&c.name, p) {
                writeln!(
                    body,
                    "        let {n} = a.retained(\"{}\", \"{}\") as {};",
                    c.name,
                    p.name,
                    c_param_type(p)
                )
                .unwrap();
                continue;
            }
            let elem = if p.base == "void" {
                "u8"
            } else {
                scalar(&p.base)
            };
            writeln!(
                body,
                "        let bytes = with_current(|ctx| {{ let _ = &ctx; ({}) as usize }}).saturating_mul(std::mem::size_of::<{elem}>());",
                c_len_expr(c, p)
            )
            .unwrap();
            writeln!(
                body,
                "        let Some({n}) = a.memory(\"{}\", \"{}\", \"{}\", bytes) else {{ return; }};\n        let {n} = {n} as {};",
                c.name,
                p.name,
                if p.base == "void" { "void" } else { scalar(&p.base) },
                c_param_type(p)
            )
            .unwrap();
        }
        let args: Vec<String> = c.params.iter().map(|p| ident(&p.name)).collect();
        writeln!(
            ex,
            "    (\"{0}\", |a| {{\n{1}        // SAFETY: every pointer spans what the C ABI reads or writes for these arguments.\n        let _ = unsafe {{ {0}({2}) }};\n    }}),",
            c.name,
            body,
            args.join(", ")
        )
        .unwrap();
    }
    writeln!(ex, "];").unwrap();
}

/// The C text of a parameter's type, as `GL/gl.h` writes it.
pub(crate) fn c_header_type(p: &Param) -> String {
    match (p.depth, p.is_const) {
        (0, _) => format!("{} ", p.base),
        (1, c) => format!("{}{} *", if c { "const " } else { "" }, p.base),
        (_, true) => format!("const {} *const*", p.base),
        (_, false) => format!("{} **", p.base),
    }
}

/// `GL/gl.h` (OpenGL 1.5: types, enums, prototypes) and `GL/glext.h` (the extension enums
/// tilegl knows, the ARB/EXT entry-point names it exports, and `PFN...PROC` types for every
/// exported function), generated from the registry so C programs need no other GL headers.
pub(crate) fn c_headers(
    out: &std::path::Path,
    core: &[&Command],
    cmd_aliases: &BTreeMap<String, Vec<String>>,
    enums: &BTreeMap<String, (u64, u8)>,
) {
    let proto = |c: &Command, name: &str| -> (String, String) {
        let ret = match c.ret_depth {
            0 => c.ret_base.clone(),
            _ => format!(
                "{} *",
                if c.ret_base == "GLubyte" {
                    "const GLubyte"
                } else {
                    c.ret_base.as_str()
                }
            ),
        };
        let params: Vec<String> = c
            .params
            .iter()
            .map(|p| format!("{}{}", c_header_type(p), p.name))
            .map(|s| s.replace("* ", "*"))
            .collect();
        let params = if params.is_empty() {
            "void".to_string()
        } else {
            params.join(", ")
        };
        let _ = name;
        (ret, params)
    };
    let mut h = String::new();
    h.push_str("/* Generated by tilegl's build.rs from the Khronos registry (OpenGL 1.5). Do not edit. */\n");
    h.push_str("#ifndef __gl_h_\n#define __gl_h_\n#define __GL_H__\n\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n");
    h.push_str("#ifndef APIENTRY\n#define APIENTRY\n#endif\n#ifndef APIENTRYP\n#define APIENTRYP APIENTRY *\n#endif\n#ifndef GLAPI\n#define GLAPI extern\n#endif\n#ifndef GLAPIENTRY\n#define GLAPIENTRY APIENTRY\n#endif\n\n");
    h.push_str("#include <stddef.h>\n\n");
    for (t, c) in [
        ("GLenum", "unsigned int"),
        ("GLboolean", "unsigned char"),
        ("GLbitfield", "unsigned int"),
        ("GLvoid", "void"),
        ("GLbyte", "signed char"),
        ("GLshort", "short"),
        ("GLint", "int"),
        ("GLubyte", "unsigned char"),
        ("GLushort", "unsigned short"),
        ("GLuint", "unsigned int"),
        ("GLsizei", "int"),
        ("GLfloat", "float"),
        ("GLclampf", "float"),
        ("GLdouble", "double"),
        ("GLclampd", "double"),
        ("GLintptr", "ptrdiff_t"),
        ("GLsizeiptr", "ptrdiff_t"),
    ] {
        writeln!(h, "typedef {c} {t};").unwrap();
    }
    h.push('\n');
    for v in [
        "GL_VERSION_1_1",
        "GL_VERSION_1_2",
        "GL_VERSION_1_3",
        "GL_VERSION_1_4",
        "GL_VERSION_1_5",
    ] {
        writeln!(h, "#define {v} 1").unwrap();
    }
    h.push_str("#define GL_VERSION_1_0 1\n\n");
    for (n, (v, rank)) in enums {
        if *rank == 0 && *v <= u32::MAX as u64 {
            writeln!(h, "#define {n} 0x{v:X}").unwrap();
        }
    }
    h.push('\n');
    for c in core {
        let (ret, params) = proto(c, &c.name);
        writeln!(h, "GLAPI {ret} GLAPIENTRY {}({params});", c.name).unwrap();
    }
    h.push_str("\n#ifdef __cplusplus\n}\n#endif\n\n#endif /* __gl_h_ */\n");

    let mut e = String::new();
    e.push_str("/* Generated by tilegl's build.rs from the Khronos registry. Do not edit. */\n");
    e.push_str("#ifndef __glext_h_\n#define __glext_h_ 1\n\n#include <GL/gl.h>\n\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n");
    for (n, (v, rank)) in enums {
        if *rank > 0 && *v <= u32::MAX as u64 {
            writeln!(e, "#ifndef {n}\n#define {n} 0x{v:X}\n#endif").unwrap();
        }
    }
    e.push('\n');
    for c in core {
        let (ret, params) = proto(c, &c.name);
        for name in std::iter::once(&c.name).chain(cmd_aliases.get(&c.name).into_iter().flatten()) {
            if name != &c.name {
                writeln!(e, "GLAPI {ret} GLAPIENTRY {name}({params});").unwrap();
            }
            writeln!(
                e,
                "typedef {ret} (APIENTRYP PFN{}PROC)({params});",
                name.to_uppercase()
            )
            .unwrap();
        }
    }
    e.push_str("\n#ifdef __cplusplus\n}\n#endif\n\n#endif /* __glext_h_ */\n");
    std::fs::write(out.join("gl.h"), h).expect("write gl.h");
    std::fs::write(out.join("glext.h"), e).expect("write glext.h");
}
