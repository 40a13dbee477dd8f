//! The dependency direction of `src/`, checked from the source: each top-level module may use
//! only modules below it in the pipeline order of `docs/design.md`
//!
//! `capi`, `replay` -> `api` -> `state` -> `gl` -> `vertex` -> `primitive` -> `raster`
//! -> `fragment` -> `texture` -> `framebuffer` -> `compare` -> `common`.
//!
//! `api` is the entry-point surface (the `Gl` trait and `Context`'s implementation of it);
//! `state` is the GL state machine, the only owner of `Context`; `gl` is the vocabulary the two
//! speak (C types, GL enums, their conversion to typed values, the error flag), ranked below
//! `state` and above the stages so that no stage sees a GL enum. Each stage defines the part of
//! the per-draw snapshot it reads (`vertex::VertexDraw`, `primitive::ViewportDraw`,
//! `raster::TileDraw`, `fragment::FragmentDraw`) and `state::snapshot` composes them.
//! `texture` sits below `fragment` (the fragment stage samples textures; texturing knows no
//! fragment type) and above `framebuffer` (the stages write tiles; the tiles know neither), so
//! "texture beside fragment" is one rank lower in this strict order. `common` is the leaf every
//! module may use: CPU features, limits, fixed-point conversions, rectangles, the vertex
//! attribute layout and the typed values of GL state; it uses no other module. The two entry
//! layers, `capi` (the C ABI) and `replay` (the trace player), share rank 0 and may use each
//! other, but not both ways (no cycle).
//!
//! Every `crate::MODULE` path in non-test code counts, grouped ones (`crate::{a::X, b::Y}`)
//! included; test code (a file's text from `#[cfg(test)]` on) may use any module.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// Pipeline rank of each top-level module; an edge must go from a lower rank to a higher one.
const RANKS: &[(&str, u32)] = &[
    ("capi", 0),
    ("replay", 0),
    ("api", 1),
    ("state", 2),
    ("gl", 3),
    ("vertex", 4),
    ("primitive", 5),
    ("raster", 6),
    ("fragment", 7),
    ("texture", 8),
    ("framebuffer", 9),
    ("compare", 10),
    ("common", 11),
];

/// The top-level modules each top-level module names (`crate::X`), from its files' non-test
/// code (a file's text before `#[cfg(test)]`).
fn edges() -> BTreeMap<String, BTreeSet<String>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut out: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut stack = vec![src.clone()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                if path.file_name().is_some_and(|n| n != "bin") {
                    stack.push(path);
                }
                continue;
            }
            if path.extension().is_none_or(|e| e != "rs") {
                continue;
            }
            let rel = path.strip_prefix(&src).unwrap();
            let first = rel
                .components()
                .next()
                .unwrap()
                .as_os_str()
                .to_string_lossy();
            let module = first.trim_end_matches(".rs").to_string();
            if module == "lib" {
                continue;
            }
            let text = std::fs::read_to_string(&path).unwrap();
            let code = text.split("#[cfg(test)]").next().unwrap_or("");
            for (i, _) in code.match_indices("crate::") {
                let rest = &code[i + 7..];
                // `crate::{a::X, b::{Y, Z}}`: the first name of each top-level element.
                let names: Vec<&str> = match rest.strip_prefix('{') {
                    Some(group) => {
                        let mut depth = 0;
                        let end = group
                            .find(|c| {
                                match c {
                                    '{' => depth += 1,
                                    '}' if depth == 0 => return true,
                                    '}' => depth -= 1,
                                    _ => {}
                                }
                                false
                            })
                            .unwrap_or(group.len());
                        let mut depth = 0;
                        group[..end]
                            .split(|c| {
                                match c {
                                    '{' => depth += 1,
                                    '}' => depth -= 1,
                                    ',' if depth == 0 => return true,
                                    _ => {}
                                }
                                false
                            })
                            .collect()
                    }
                    None => vec![rest],
                };
                for n in names {
                    let name: String = n
                        .trim_start()
                        .chars()
                        .take_while(|c| c.is_ascii_lowercase() || *c == '_')
                        .collect();
                    if !name.is_empty() && name != module {
                        out.entry(module.clone()).or_default().insert(name);
                    }
                }
            }
        }
    }
    out
}

#[test]
fn modules_only_use_modules_below_them() {
    let rank: BTreeMap<&str, u32> = RANKS.iter().copied().collect();
    let mut upward = BTreeSet::new();
    for (from, tos) in edges() {
        let Some(&rf) = rank.get(from.as_str()) else {
            panic!("top-level module `{from}` has no rank in RANKS");
        };
        for to in tos {
            let Some(&rt) = rank.get(to.as_str()) else {
                continue; // not a module (a macro path, a crate-level item)
            };
            if rt <= rf && !(rf == 0 && rt == 0) {
                upward.insert((from.clone(), to));
            }
        }
    }
    assert!(
        upward.is_empty(),
        "upward dependencies (a lower stage using a higher one): {upward:?}"
    );
}

/// No cycle at all, the rank-0 pair included: a depth-first search finds no back edge.
#[test]
fn no_import_cycle_between_top_level_modules() {
    let edges = edges();
    fn visit<'a>(
        m: &'a str,
        edges: &'a BTreeMap<String, BTreeSet<String>>,
        path: &mut Vec<&'a str>,
        done: &mut BTreeSet<&'a str>,
    ) {
        if done.contains(m) {
            return;
        }
        if let Some(i) = path.iter().position(|&p| p == m) {
            panic!("import cycle: {:?} -> {m}", &path[i..]);
        }
        path.push(m);
        for to in edges.get(m).into_iter().flatten() {
            visit(to, edges, path, done);
        }
        path.pop();
        done.insert(m);
    }
    let mut done = BTreeSet::new();
    for m in edges.keys() {
        visit(m, &edges, &mut Vec::new(), &mut done);
    }
    // The check sees the edges it must judge: the pipeline's first link is there.
    assert!(edges.get("api").is_some_and(|t| t.contains("state")));
}
