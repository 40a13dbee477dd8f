//! Splits a vertex sequence of one of the ten primitive modes into points, lines and
//! triangles, with the provoking vertex of each for flat shading (OpenGL 1.5 table 2.9).

use crate::common::values::PrimitiveMode;

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

/// Assembles `count` vertices of `mode`. Incomplete trailing primitives are ignored (section
/// 2.6.1). Triangles keep the winding of the primitive they come from.
pub fn assemble(mode: PrimitiveMode, count: usize) -> Vec<Primitive> {
    let mut out = Vec::new();
    assemble_into(mode, count, &mut out);
    out
}

/// [`assemble`] into `out` (cleared first), reusing its allocation: large batches would
/// otherwise fault in fresh pages on every draw.
pub fn assemble_into(mode: PrimitiveMode, count: usize, out: &mut Vec<Primitive>) {
    use Primitive::*;
    use PrimitiveMode::*;
    let n = count;
    out.clear();
    match mode {
        Points => out.extend((0..n).map(Point)),
        Lines => {
            for i in (0..n / 2 * 2).step_by(2) {
                out.push(Line {
                    v: [i, i + 1],
                    provoking: i + 1,
                });
            }
        }
        LineStrip | LineLoop => {
            if n >= 2 {
                for i in 0..n - 1 {
                    out.push(Line {
                        v: [i, i + 1],
                        provoking: i + 1,
                    });
                }
                if mode == LineLoop {
                    // The closing segment takes the colour of the first vertex.
                    out.push(Line {
                        v: [n - 1, 0],
                        provoking: 0,
                    });
                }
            }
        }
        Triangles => {
            for i in (0..n / 3 * 3).step_by(3) {
                out.push(Triangle {
                    v: [i, i + 1, i + 2],
                    provoking: i + 2,
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
                    provoking: i + 2,
                    edges: [true; 3],
                });
            }
        }
        TriangleFan => {
            for i in 1..n.saturating_sub(1) {
                out.push(Triangle {
                    v: [0, i, i + 1],
                    provoking: i + 1,
                    edges: [true; 3],
                });
            }
        }
        Quads => {
            for q in (0..n / 4 * 4).step_by(4) {
                out.push(Triangle {
                    v: [q, q + 1, q + 2],
                    provoking: q + 3,
                    edges: [true, true, false],
                });
                out.push(Triangle {
                    v: [q, q + 2, q + 3],
                    provoking: q + 3,
                    edges: [false, true, true],
                });
            }
        }
        QuadStrip => {
            let mut i = 0;
            while i + 3 < n {
                // Quad i is (2i, 2i+1, 2i+3, 2i+2); its last vertex provokes.
                out.push(Triangle {
                    v: [i, i + 1, i + 3],
                    provoking: i + 3,
                    edges: [true, true, false],
                });
                out.push(Triangle {
                    v: [i, i + 3, i + 2],
                    provoking: i + 3,
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
    fn counts_follow_the_spec() {
        use PrimitiveMode::*;
        let tri = |m, n| {
            assemble(m, n)
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
        assert_eq!(assemble(LineLoop, 3).len(), 3);
        assert_eq!(assemble(LineStrip, 1).len(), 0);
        assert_eq!(assemble(Lines, 5).len(), 2);
    }

    #[test]
    fn provoking_vertices() {
        use PrimitiveMode::*;
        assert_eq!(
            assemble(QuadStrip, 4)[0],
            Primitive::Triangle {
                v: [0, 1, 3],
                provoking: 3,
                edges: [true, true, false]
            }
        );
        assert_eq!(
            assemble(LineLoop, 3)[2],
            Primitive::Line {
                v: [2, 0],
                provoking: 0
            }
        );
        assert!(assemble(Polygon, 5)
            .iter()
            .all(|p| matches!(p, Primitive::Triangle { provoking: 0, .. })));
    }

    #[test]
    fn every_polygon_edge_appears_once_and_no_diagonal() {
        use std::collections::BTreeSet;
        use PrimitiveMode::*;
        // The boundary edges of the triangles are exactly the polygon's edges, each once.
        let boundary = |m, n| {
            let mut edges = Vec::new();
            for p in assemble(m, n) {
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
