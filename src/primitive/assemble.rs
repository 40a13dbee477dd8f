//! Splits a vertex sequence of one of the ten primitive modes into points, lines and
//! triangles, with the provoking vertex of each for flat shading (OpenGL 1.5 table 2.9).

use crate::api::convert::PrimitiveMode;

/// One assembled primitive: vertex indices and the provoking vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Primitive {
    Point(usize),
    Line { v: [usize; 2], provoking: usize },
    Triangle { v: [usize; 3], provoking: usize },
}

/// Assembles `count` vertices of `mode`. Incomplete trailing primitives are ignored (section
/// 2.6.1). Triangles keep the winding of the primitive they come from.
pub fn assemble(mode: PrimitiveMode, count: usize) -> Vec<Primitive> {
    use Primitive::*;
    use PrimitiveMode::*;
    let n = count;
    let mut out = Vec::new();
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
                });
            }
        }
        TriangleFan => {
            for i in 1..n.saturating_sub(1) {
                out.push(Triangle {
                    v: [0, i, i + 1],
                    provoking: i + 1,
                });
            }
        }
        Quads => {
            for q in (0..n / 4 * 4).step_by(4) {
                out.push(Triangle {
                    v: [q, q + 1, q + 2],
                    provoking: q + 3,
                });
                out.push(Triangle {
                    v: [q, q + 2, q + 3],
                    provoking: q + 3,
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
                });
                out.push(Triangle {
                    v: [i, i + 3, i + 2],
                    provoking: i + 3,
                });
                i += 2;
            }
        }
        Polygon => {
            for i in 1..n.saturating_sub(1) {
                out.push(Triangle {
                    v: [0, i, i + 1],
                    provoking: 0,
                });
            }
        }
    }
    out
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
                provoking: 3
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
}
