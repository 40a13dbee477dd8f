//! Typed values of the evaluators (section 5.1; part of `values`).

/// What a map produces (the part of a `GL_MAP1_*`/`GL_MAP2_*` target after the dimension).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EvalTarget {
    Vertex3,
    Vertex4,
    Index,
    Color4,
    Normal,
    TexCoord1,
    TexCoord2,
    TexCoord3,
    TexCoord4,
}

impl EvalTarget {
    /// Every target, in the order of [`EvalTarget::index`].
    pub const ALL: [EvalTarget; 9] = [
        EvalTarget::Vertex3,
        EvalTarget::Vertex4,
        EvalTarget::Index,
        EvalTarget::Color4,
        EvalTarget::Normal,
        EvalTarget::TexCoord1,
        EvalTarget::TexCoord2,
        EvalTarget::TexCoord3,
        EvalTarget::TexCoord4,
    ];

    /// Position in [`EvalTarget::ALL`] (the per-target state arrays).
    pub fn index(self) -> usize {
        self as usize
    }

    /// k of table 5.1: values per control point.
    pub fn components(self) -> usize {
        match self {
            EvalTarget::Index | EvalTarget::TexCoord1 => 1,
            EvalTarget::TexCoord2 => 2,
            EvalTarget::Vertex3 | EvalTarget::Normal | EvalTarget::TexCoord3 => 3,
            EvalTarget::Vertex4 | EvalTarget::Color4 | EvalTarget::TexCoord4 => 4,
        }
    }
}

/// A map of either dimension (`glGetMap*` targets).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AnyMap {
    Map1(EvalTarget),
    Map2(EvalTarget),
}

/// The `query` of `glGetMap*`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum GetMapQuery {
    Coeff,
    Order,
    Domain,
}

/// Modes of `glEvalMesh1` (`fill` false) and `glEvalMesh2` (`fill` true also takes `GL_FILL`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EvalMeshMode {
    Point,
    Line,
    Fill,
}

/// Evaluator state of `glGet*` (table 6.24 and the implementation limit).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EvalQuery {
    MaxEvalOrder,
    Map1GridDomain,
    Map1GridSegments,
    Map2GridDomain,
    Map2GridSegments,
}
