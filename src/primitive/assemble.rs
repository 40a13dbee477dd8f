//! Splits a vertex sequence of one of the ten primitive modes into points, lines and
//! triangles, with the provoking vertex of each for flat shading (OpenGL 1.5 table 2.9, and
//! EXT_provoking_vertex's first-vertex column).

use crate::common::values::PrimitiveMode;
pub use crate::common::values::ProvokingVertex as Provoking;

/// One assembled primitive: vertex indices and the provoking vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Primitive {
    Point(usize),
    Line {
        v: [usize; 2],
        provoking: usize,
    },
    /// `edges[k]`: the edge from `v[k]` to `v[(k + 1) % 3]` is an edge of the polygon the
    /// triangle comes from (not a diagonal added by splitting a quad or polygon).
    Triangle {
        v: [usize; 3],
        provoking: usize,
        edges: [bool; 3],
    },
}

/// Whether the vertex edge flags apply to `mode` (section 2.6.2: independent triangles, quads
/// and polygons; strips and fans draw every edge).
pub fn uses_edge_flags(mode: PrimitiveMode) -> bool {
    matches!(
        mode,
        PrimitiveMode::Triangles | PrimitiveMode::Quads | PrimitiveMode::Polygon
    )
}

/// Whether quads and quad strips follow the first-vertex convention
/// (`GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION_EXT`, implementation-dependent). False, as
/// Mesa's llvmpipe answers: quads always take their last vertex's colours.
pub const QUADS_FOLLOW_PROVOKING_VERTEX: bool = false;

/// Assembles `count` vertices of `mode`. Incomplete trailing primitives are ignored (section
/// 2.6.1). Triangles keep the winding of the primitive they come from.
pub fn assemble(mode: PrimitiveMode, count: usize, convention: Provoking) -> Vec<Primitive> {
    let mut out = Vec::new();
    assemble_into(mode, count, convention, &mut out);
    out
}

/// Re-splits the triangles [`assemble`] made of `GL_QUADS` along the other diagonal, from
/// vertex 1 to vertex 3: (0, 1, 3) and (1, 2, 3). Section 2.6.1 leaves the split
/// open; it decides the coverage of a non-convex quad and the shading of a smooth quad whose
/// attributes are not affine. Mesa splits at 0-2 when it draws a batch directly and at 1-3 when
/// the batch goes through its clipping pipeline (some vertex outside the view volume or a
/// clip plane), which the caller decides.
pub fn split_quads_through_1_3(prims: &mut [Primitive]) {
    for p in prims.iter_mut() {
        if let Primitive::Triangle { v, edges, .. } = p {
            // Both triangles of quad (q, q+1, q+2, q+3) start at q.
            let q = v[0];
            *v = if v[1] == q + 1 {
                *edges = [true, false, true];
                [q, q + 1, q + 3]
            } else {
                *edges = [true, true, false];
                [q + 1, q + 2, q + 3]
            };
        }
    }
}

/// [`assemble`] into `out` (cleared first), reusing its allocation: large batches would
/// otherwise fault in fresh pages on every draw.
pub fn assemble_into(
    mode: PrimitiveMode,
    count: usize,
    convention: Provoking,
    out: &mut Vec<Primitive>,
) {
    use Primitive::*;
    use PrimitiveMode::*;
    let n = count;
    out.clear();
    // EXT_provoking_vertex's table: under the first-vertex convention a primitive's first
    // vertex (in the order the primitive lists them) provokes; a polygon's is its first
    // either way, and quads keep their last unless QUADS_FOLLOW_PROVOKING_VERTEX.
    let first = convention == Provoking::First;
    let first_quads = first && QUADS_FOLLOW_PROVOKING_VERTEX;
    match mode {
        Points => out.extend((0..n).map(Point)),
        Lines => {
            for i in (0..n / 2 * 2).step_by(2) {
                out.push(Line {
                    v: [i, i + 1],
                    provoking: if first { i } else { i + 1 },
                });
            }
        }
        LineStrip | LineLoop => {
            if n >= 2 {
                for i in 0..n - 1 {
                    out.push(Line {
                        v: [i, i + 1],
                        provoking: if first { i } else { i + 1 },
                    });
                }
                if mode == LineLoop {
                    // The closing segment takes the colour of the loop's first vertex (its
                    // own second), or of the last under the first-vertex convention.
                    out.push(Line {
                        v: [n - 1, 0],
                        provoking: if first { n - 1 } else { 0 },
                    });
                }
            }
        }
        Triangles => {
            for i in (0..n / 3 * 3).step_by(3) {
                out.push(Triangle {
                    v: [i, i + 1, i + 2],
                    provoking: if first { i } else { i + 2 },
                    edges: [true; 3],
                });
            }
        }
        TriangleStrip => {
            for i in 0..n.saturating_sub(2) {
                let v = if i % 2 == 0 {
                    [i, i + 1, i + 2]
                } else {
                    [i + 1, i, i + 2]
                };
                out.push(Triangle {
                    v,
                    provoking: if first { i } else { i + 2 },
                    edges: [true; 3],
                });
            }
        }
        TriangleFan => {
            for i in 1..n.saturating_sub(1) {
                out.push(Triangle {
                    v: [0, i, i + 1],
                    provoking: if first { i } else { i + 1 },
                    edges: [true; 3],
                });
            }
        }
        Quads => {
            for q in (0..n / 4 * 4).step_by(4) {
                let provoking = if first_quads { q } else { q + 3 };
                out.push(Triangle {
                    v: [q, q + 1, q + 2],
                    provoking,
                    edges: [true, true, false],
                });
                out.push(Triangle {
                    v: [q, q + 2, q + 3],
                    provoking,
                    edges: [false, true, true],
                });
            }
        }
        QuadStrip => {
            let mut i = 0;
            while i + 3 < n {
                // Quad i is (2i, 2i+1, 2i+3, 2i+2); its last vertex (or first) provokes.
                let provoking = if first_quads { i } else { i + 3 };
                out.push(Triangle {
                    v: [i, i + 1, i + 3],
                    provoking,
                    edges: [true, true, false],
                });
                out.push(Triangle {
                    v: [i, i + 3, i + 2],
                    provoking,
                    edges: [false, true, true],
                });
                i += 2;
            }
        }
        Polygon => {
            for i in 1..n.saturating_sub(1) {
                out.push(Triangle {
                    v: [0, i, i + 1],
                    provoking: 0,
                    edges: [i == 1, true, i + 2 == n],
                });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quads_split_through_1_3_keep_winding_provoking_vertex_and_boundary() {
        let mut prims = assemble(PrimitiveMode::Quads, 8, Provoking::Last);
        split_quads_through_1_3(&mut prims);
        let tri = |v, edges| Primitive::Triangle {
            v,
            provoking: v[2],
            edges,
        };
        assert_eq!(
            prims,
            vec![
                tri([0, 1, 3], [true, false, true]),
                tri([1, 2, 3], [true, true, false]),
                tri([4, 5, 7], [true, false, true]),
                tri([5, 6, 7], [true, true, false]),
            ]
        );
    }

    #[test]
    fn counts_follow_the_spec() {
        use PrimitiveMode::*;
        let tri = |m, n| {
            assemble(m, n, Provoking::Last)
                .iter()
                .filter(|p| matches!(p, Primitive::Triangle { .. }))
                .count()
        };
        assert_eq!(tri(Triangles, 7), 2);
        assert_eq!(tri(TriangleStrip, 5), 3);
        assert_eq!(tri(TriangleFan, 5), 3);
        assert_eq!(tri(Quads, 9), 4);
        assert_eq!(tri(QuadStrip, 7), 4);
        assert_eq!(tri(Polygon, 6), 4);
        assert_eq!(tri(Polygon, 2), 0);
        assert_eq!(assemble(LineLoop, 3, Provoking::Last).len(), 3);
        assert_eq!(assemble(LineStrip, 1, Provoking::Last).len(), 0);
        assert_eq!(assemble(Lines, 5, Provoking::Last).len(), 2);
    }

    #[test]
    fn provoking_vertices() {
        use PrimitiveMode::*;
        assert_eq!(
            assemble(QuadStrip, 4, Provoking::Last)[0],
            Primitive::Triangle {
                v: [0, 1, 3],
                provoking: 3,
                edges: [true, true, false]
            }
        );
        assert_eq!(
            assemble(LineLoop, 3, Provoking::Last)[2],
            Primitive::Line {
                v: [2, 0],
                provoking: 0
            }
        );
        assert!(assemble(Polygon, 5, Provoking::Last)
            .iter()
            .all(|p| matches!(p, Primitive::Triangle { provoking: 0, .. })));
    }

    /// EXT_provoking_vertex's table, 1-based as the extension writes it: primitive i of n
    /// (vertex count `count`) and its provoking vertex under each convention.
    fn spec_provoking(mode: PrimitiveMode, i: usize, n: usize, first: bool) -> usize {
        use PrimitiveMode::*;
        match (mode, first) {
            (Points, _) => i,
            (Lines, true) => 2 * i - 1,
            (Lines, false) => 2 * i,
            (LineLoop, true) | (LineStrip, true) => i,
            (LineLoop, false) if i == n => 1,
            (LineLoop, false) | (LineStrip, false) => i + 1,
            (Triangles, true) => 3 * i - 2,
            (Triangles, false) => 3 * i,
            (TriangleStrip, true) => i,
            (TriangleStrip, false) => i + 2,
            (TriangleFan, true) => i + 1,
            (TriangleFan, false) => i + 2,
            // QUADS_FOLLOW_PROVOKING_VERTEX is false: quads keep the last vertex.
            (Quads, _) => 4 * i,
            (QuadStrip, _) => 2 * i + 2,
            (Polygon, _) => 1,
        }
    }

    #[test]
    fn provoking_vertices_follow_the_extension_table_for_every_mode() {
        use PrimitiveMode::*;
        const { assert!(!QUADS_FOLLOW_PROVOKING_VERTEX) };
        let modes = [
            Points,
            Lines,
            LineStrip,
            LineLoop,
            Triangles,
            TriangleStrip,
            TriangleFan,
            Quads,
            QuadStrip,
            Polygon,
        ];
        for mode in modes {
            for count in 0..13 {
                for (convention, first) in [(Provoking::First, true), (Provoking::Last, false)] {
                    let prims = assemble(mode, count, convention);
                    // Quads and polygons give several triangles per primitive: number them by
                    // the primitive they come from.
                    let per_prim = match mode {
                        Quads | QuadStrip => 2,
                        Polygon => count.saturating_sub(2).max(1),
                        _ => 1,
                    };
                    let n = prims.len() / per_prim;
                    for (k, p) in prims.iter().enumerate() {
                        let i = k / per_prim + 1;
                        let got = match *p {
                            Primitive::Point(v) => v,
                            Primitive::Line { provoking, .. }
                            | Primitive::Triangle { provoking, .. } => provoking,
                        };
                        assert_eq!(
                            got + 1,
                            spec_provoking(mode, i, n, first),
                            "{mode:?} count {count} primitive {i} first {first}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn every_polygon_edge_appears_once_and_no_diagonal() {
        use std::collections::BTreeSet;
        use PrimitiveMode::*;
        // The boundary edges of the triangles are exactly the polygon's edges, each once.
        let boundary = |m, n| {
            let mut edges = Vec::new();
            for p in assemble(m, n, Provoking::Last) {
                if let Primitive::Triangle { v, edges: e, .. } = p {
                    for k in 0..3 {
                        if e[k] {
                            let (a, b) = (v[k], v[(k + 1) % 3]);
                            edges.push((a.min(b), a.max(b)));
                        }
                    }
                }
            }
            edges
        };
        let polygon: BTreeSet<_> = boundary(Polygon, 6).into_iter().collect();
        assert_eq!(boundary(Polygon, 6).len(), 6);
        assert_eq!(
            polygon,
            [(0, 1), (1, 2), (2, 3), (3, 4), (4, 5), (0, 5)]
                .into_iter()
                .collect()
        );
        let quads: BTreeSet<_> = boundary(Quads, 4).into_iter().collect();
        assert_eq!(
            quads,
            [(0, 1), (1, 2), (2, 3), (0, 3)].into_iter().collect()
        );
        // A quad strip's quad (0, 1, 3, 2) has edges 0-1, 1-3, 3-2, 2-0.
        let strip: BTreeSet<_> = boundary(QuadStrip, 4).into_iter().collect();
        assert_eq!(
            strip,
            [(0, 1), (1, 3), (2, 3), (0, 2)].into_iter().collect()
        );
        assert_eq!(boundary(Polygon, 3).len(), 3);
    }
}
