//! GLenum conversions of the evaluators (section 5.1; part of `convert`).

use crate::common::values::*;

use crate::gl::enums::*;
use crate::gl::types::GLenum;

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

pub fn any_map_target(e: GLenum) -> Option<AnyMap> {
    map1_target(e)
        .map(AnyMap::Map1)
        .or_else(|| map2_target(e).map(AnyMap::Map2))
}

pub fn get_map_query(e: GLenum) -> Option<GetMapQuery> {
    Some(match e {
        GL_COEFF => GetMapQuery::Coeff,
        GL_ORDER => GetMapQuery::Order,
        GL_DOMAIN => GetMapQuery::Domain,
        _ => return None,
    })
}

pub fn eval_mesh_mode(e: GLenum, fill: bool) -> Option<EvalMeshMode> {
    Some(match e {
        GL_POINT => EvalMeshMode::Point,
        GL_LINE => EvalMeshMode::Line,
        GL_FILL if fill => EvalMeshMode::Fill,
        _ => return None,
    })
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
