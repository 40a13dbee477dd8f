//! GL enum constants generated from the Khronos registry (see `build.rs`).
#![allow(missing_docs)]

pub use super::types::*;

include!(concat!(env!("OUT_DIR"), "/enums.rs"));

/// The value of a GL enum given its name (`"GL_TEXTURE_2D"`), including ARB/EXT aliases.
pub fn enum_by_name(name: &str) -> Option<GLenum> {
    ENUMS_BY_NAME
        .binary_search_by(|(n, _)| (*n).cmp(name))
        .ok()
        .map(|i| ENUMS_BY_NAME[i].1)
}

/// A name for a GL enum value, preferring the unsuffixed core name. Values shared by several
/// enums (0, 1, ...) give the first core name in alphabetical order.
pub fn enum_name(value: GLenum) -> Option<&'static str> {
    let mut best: Option<&'static str> = None;
    for (n, v) in ENUMS_BY_NAME {
        if *v == value {
            let suffixed = n.ends_with("_ARB") || n.ends_with("_EXT");
            match best {
                None => best = Some(n),
                Some(b) if (b.ends_with("_ARB") || b.ends_with("_EXT")) && !suffixed => {
                    best = Some(n)
                }
                _ => {}
            }
        }
    }
    best
}
