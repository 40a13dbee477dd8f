//! Element counts of C pointer parameters whose length the registry gives as
//! `COMPSIZE(...)`: the number of elements GL reads or writes, computed from the other
//! arguments and the context's state. Pixel commands take their sizes from
//! `state/client_sizes.rs`, whose layouts the commands themselves check against. Every
//! `COMPSIZE` parameter of an exported entry point has a case here; the audit in
//! `tests/capi_lengths.rs` fails for any that would get 0 on a valid call.

use crate::api::enums::*;
use crate::state::Context;

/// Element count of parameter `param` of `command` given the COMPSIZE arguments `args`.
pub fn size(ctx: &Context, command: &str, param: &str, args: &[i64]) -> usize {
    let _ = param;
    let arg = |i: usize| args.get(i).copied().unwrap_or(0);
    match command {
        "glGetBooleanv" | "glGetIntegerv" | "glGetFloatv" | "glGetDoublev" => {
            ctx.query_count(arg(0) as u32)
        }
        "glReadPixels" => {
            ctx.read_pixels_len(arg(0) as u32, arg(1) as u32, arg(2) as i32, arg(3) as i32)
        }
        "glTexImage1D" | "glTexSubImage1D" => {
            ctx.tex_image_len(1, arg(0) as u32, arg(1) as u32, [arg(2) as i32, 1, 1])
        }
        "glTexImage2D" | "glTexSubImage2D" => ctx.tex_image_len(
            2,
            arg(0) as u32,
            arg(1) as u32,
            [arg(2) as i32, arg(3) as i32, 1],
        ),
        "glTexImage3D" | "glTexSubImage3D" => ctx.tex_image_len(
            3,
            arg(0) as u32,
            arg(1) as u32,
            [arg(2) as i32, arg(3) as i32, arg(4) as i32],
        ),
        "glDrawPixels" => {
            ctx.draw_pixels_len(arg(0) as u32, arg(1) as u32, arg(2) as i32, arg(3) as i32)
        }
        "glBitmap" => ctx.bitmap_len(arg(0) as i32, arg(1) as i32),
        "glGetTexImage" => {
            ctx.get_tex_image_len(arg(0) as u32, arg(1) as i32, arg(2) as u32, arg(3) as u32)
        }
        "glGetCompressedTexImage" => ctx.get_compressed_tex_image_len(arg(0) as u32, arg(1) as i32),
        "glGetPixelMapfv" | "glGetPixelMapuiv" | "glGetPixelMapusv" => {
            ctx.pixel_map_len(arg(0) as u32)
        }
        "glPolygonStipple" | "glGetPolygonStipple" => 128,
        "glMap1f" | "glMap1d" => crate::state::evaluators::map1_len(arg(0) as u32, arg(1), arg(2)),
        "glMap2f" | "glMap2d" => {
            crate::state::evaluators::map2_len(arg(0) as u32, arg(1), arg(2), arg(3), arg(4))
        }
        "glGetMapfv" | "glGetMapdv" | "glGetMapiv" => ctx.get_map_len(arg(0) as u32, arg(1) as u32),
        "glCallLists" => {
            let n = arg(0).clamp(0, i32::MAX as i64) as usize;
            n * match arg(1) as u32 {
                GL_BYTE | GL_UNSIGNED_BYTE | GL_2_BYTES | GL_3_BYTES | GL_4_BYTES => {
                    match arg(1) as u32 {
                        GL_2_BYTES => 2,
                        GL_3_BYTES => 3,
                        GL_4_BYTES => 4,
                        _ => 1,
                    }
                }
                GL_SHORT | GL_UNSIGNED_SHORT => 2,
                GL_INT | GL_UNSIGNED_INT | GL_FLOAT => 4,
                _ => 0,
            }
        }
        // `count` of the multi-draw calls: one count per draw.
        "glMultiDrawArrays" | "glMultiDrawElements" => arg(0).clamp(0, i32::MAX as i64) as usize,
        _ if args.len() == 1 => pname_count(arg(0) as u32),
        _ => 0,
    }
}

/// Values taken or returned for a `pname` of the `gl*v` state calls.
pub fn pname_count(pname: u32) -> usize {
    match pname {
        GL_AMBIENT
        | GL_DIFFUSE
        | GL_SPECULAR
        | GL_EMISSION
        | GL_AMBIENT_AND_DIFFUSE
        | GL_POSITION
        | GL_FOG_COLOR
        | GL_TEXTURE_ENV_COLOR
        | GL_TEXTURE_BORDER_COLOR
        | GL_TEXTURE_SWIZZLE_RGBA
        | GL_EYE_PLANE
        | GL_OBJECT_PLANE
        | GL_LIGHT_MODEL_AMBIENT => 4,
        GL_SPOT_DIRECTION | GL_COLOR_INDEXES | GL_POINT_DISTANCE_ATTENUATION => 3,
        _ => 1,
    }
}
