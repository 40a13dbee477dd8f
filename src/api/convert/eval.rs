//! GLenum conversions of the evaluators (section 5.1; part of `convert`).

use crate::api::enums::*;
use crate::api::types::GLenum;

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

/// `GL_MAP1_*` targets.
pub fn map1_target(e: GLenum) -> Option<EvalTarget> {
    Some(match e {
        GL_MAP1_VERTEX_3 => EvalTarget::Vertex3,
        GL_MAP1_VERTEX_4 => EvalTarget::Vertex4,
        GL_MAP1_INDEX => EvalTarget::Index,
        GL_MAP1_COLOR_4 => EvalTarget::Color4,
        GL_MAP1_NORMAL => EvalTarget::Normal,
        GL_MAP1_TEXTURE_COORD_1 => EvalTarget::TexCoord1,
        GL_MAP1_TEXTURE_COORD_2 => EvalTarget::TexCoord2,
        GL_MAP1_TEXTURE_COORD_3 => EvalTarget::TexCoord3,
        GL_MAP1_TEXTURE_COORD_4 => EvalTarget::TexCoord4,
        _ => return None,
    })
}

/// `GL_MAP2_*` targets.
pub fn map2_target(e: GLenum) -> Option<EvalTarget> {
    Some(match e {
        GL_MAP2_VERTEX_3 => EvalTarget::Vertex3,
        GL_MAP2_VERTEX_4 => EvalTarget::Vertex4,
        GL_MAP2_INDEX => EvalTarget::Index,
        GL_MAP2_COLOR_4 => EvalTarget::Color4,
        GL_MAP2_NORMAL => EvalTarget::Normal,
        GL_MAP2_TEXTURE_COORD_1 => EvalTarget::TexCoord1,
        GL_MAP2_TEXTURE_COORD_2 => EvalTarget::TexCoord2,
        GL_MAP2_TEXTURE_COORD_3 => EvalTarget::TexCoord3,
        GL_MAP2_TEXTURE_COORD_4 => EvalTarget::TexCoord4,
        _ => return None,
    })
}

/// A map of either dimension (`glGetMap*` targets).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AnyMap {
    Map1(EvalTarget),
    Map2(EvalTarget),
}

pub fn any_map_target(e: GLenum) -> Option<AnyMap> {
    map1_target(e)
        .map(AnyMap::Map1)
        .or_else(|| map2_target(e).map(AnyMap::Map2))
}

/// The `query` of `glGetMap*`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum GetMapQuery {
    Coeff,
    Order,
    Domain,
}

pub fn get_map_query(e: GLenum) -> Option<GetMapQuery> {
    Some(match e {
        GL_COEFF => GetMapQuery::Coeff,
        GL_ORDER => GetMapQuery::Order,
        GL_DOMAIN => GetMapQuery::Domain,
        _ => return None,
    })
}

/// Modes of `glEvalMesh1` (`fill` false) and `glEvalMesh2` (`fill` true also takes `GL_FILL`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EvalMeshMode {
    Point,
    Line,
    Fill,
}

pub fn eval_mesh_mode(e: GLenum, fill: bool) -> Option<EvalMeshMode> {
    Some(match e {
        GL_POINT => EvalMeshMode::Point,
        GL_LINE => EvalMeshMode::Line,
        GL_FILL if fill => EvalMeshMode::Fill,
        _ => return None,
    })
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

pub fn eval_query(e: GLenum) -> Option<EvalQuery> {
    Some(match e {
        GL_MAX_EVAL_ORDER => EvalQuery::MaxEvalOrder,
        GL_MAP1_GRID_DOMAIN => EvalQuery::Map1GridDomain,
        GL_MAP1_GRID_SEGMENTS => EvalQuery::Map1GridSegments,
        GL_MAP2_GRID_DOMAIN => EvalQuery::Map2GridDomain,
        GL_MAP2_GRID_SEGMENTS => EvalQuery::Map2GridSegments,
        _ => return None,
    })
}
