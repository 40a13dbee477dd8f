//! GLenum conversions of vertex arrays, buffer objects and display lists (part of `convert`).

use crate::common::values::*;

use crate::gl::enums::*;
use crate::gl::types::GLenum;

pub fn client_array(e: GLenum) -> Option<ClientArray> {
    use ClientArray::*;
    Some(match e {
        GL_VERTEX_ARRAY => Vertex,
        GL_NORMAL_ARRAY => Normal,
        GL_COLOR_ARRAY => Color,
        GL_SECONDARY_COLOR_ARRAY => SecondaryColor,
        GL_FOG_COORD_ARRAY => FogCoord,
        GL_TEXTURE_COORD_ARRAY => TexCoord,
        GL_EDGE_FLAG_ARRAY => EdgeFlag,
        GL_INDEX_ARRAY => Index,
        _ => return None,
    })
}

impl ArrayType {
    pub fn to_gl(self) -> GLenum {
        use ArrayType::*;
        match self {
            Byte => GL_BYTE,
            UnsignedByte => GL_UNSIGNED_BYTE,
            Short => GL_SHORT,
            UnsignedShort => GL_UNSIGNED_SHORT,
            Int => GL_INT,
            UnsignedInt => GL_UNSIGNED_INT,
            Float => GL_FLOAT,
            Double => GL_DOUBLE,
        }
    }
}

pub fn array_type(e: GLenum) -> Option<ArrayType> {
    use ArrayType::*;
    Some(match e {
        GL_BYTE => Byte,
        GL_UNSIGNED_BYTE => UnsignedByte,
        GL_SHORT => Short,
        GL_UNSIGNED_SHORT => UnsignedShort,
        GL_INT => Int,
        GL_UNSIGNED_INT => UnsignedInt,
        GL_FLOAT => Float,
        GL_DOUBLE => Double,
        _ => return None,
    })
}

pub fn index_type(e: GLenum) -> Option<IndexType> {
    Some(match e {
        GL_UNSIGNED_BYTE => IndexType::UnsignedByte,
        GL_UNSIGNED_SHORT => IndexType::UnsignedShort,
        GL_UNSIGNED_INT => IndexType::UnsignedInt,
        _ => return None,
    })
}

pub fn interleaved_format(e: GLenum) -> Option<InterleavedFormat> {
    use InterleavedFormat::*;
    Some(match e {
        GL_V2F => V2f,
        GL_V3F => V3f,
        GL_C4UB_V2F => C4ubV2f,
        GL_C4UB_V3F => C4ubV3f,
        GL_C3F_V3F => C3fV3f,
        GL_N3F_V3F => N3fV3f,
        GL_C4F_N3F_V3F => C4fN3fV3f,
        GL_T2F_V3F => T2fV3f,
        GL_T4F_V4F => T4fV4f,
        GL_T2F_C4UB_V3F => T2fC4ubV3f,
        GL_T2F_C3F_V3F => T2fC3fV3f,
        GL_T2F_N3F_V3F => T2fN3fV3f,
        GL_T2F_C4F_N3F_V3F => T2fC4fN3fV3f,
        GL_T4F_C4F_N3F_V4F => T4fC4fN3fV4f,
        _ => return None,
    })
}

pub fn buffer_target(e: GLenum) -> Option<BufferTarget> {
    Some(match e {
        GL_ARRAY_BUFFER => BufferTarget::Array,
        GL_ELEMENT_ARRAY_BUFFER => BufferTarget::ElementArray,
        GL_PIXEL_PACK_BUFFER => BufferTarget::PixelPack,
        GL_PIXEL_UNPACK_BUFFER => BufferTarget::PixelUnpack,
        _ => return None,
    })
}

/// `glBufferData` usage hints: accepted, kept for `GL_BUFFER_USAGE`, otherwise no effect.
pub fn buffer_usage(e: GLenum) -> Option<GLenum> {
    matches!(
        e,
        GL_STREAM_DRAW
            | GL_STREAM_READ
            | GL_STREAM_COPY
            | GL_STATIC_DRAW
            | GL_STATIC_READ
            | GL_STATIC_COPY
            | GL_DYNAMIC_DRAW
            | GL_DYNAMIC_READ
            | GL_DYNAMIC_COPY
    )
    .then_some(e)
}

impl BufferAccess {
    pub fn to_gl(self) -> GLenum {
        match self {
            BufferAccess::ReadOnly => GL_READ_ONLY,
            BufferAccess::WriteOnly => GL_WRITE_ONLY,
            BufferAccess::ReadWrite => GL_READ_WRITE,
        }
    }
}

pub fn buffer_access(e: GLenum) -> Option<BufferAccess> {
    Some(match e {
        GL_READ_ONLY => BufferAccess::ReadOnly,
        GL_WRITE_ONLY => BufferAccess::WriteOnly,
        GL_READ_WRITE => BufferAccess::ReadWrite,
        _ => return None,
    })
}

pub fn buffer_param(e: GLenum) -> Option<BufferParam> {
    Some(match e {
        GL_BUFFER_SIZE => BufferParam::Size,
        GL_BUFFER_USAGE => BufferParam::Usage,
        GL_BUFFER_ACCESS => BufferParam::Access,
        GL_BUFFER_MAPPED => BufferParam::Mapped,
        GL_BUFFER_ACCESS_FLAGS => BufferParam::AccessFlags,
        GL_BUFFER_MAP_OFFSET => BufferParam::MapOffset,
        GL_BUFFER_MAP_LENGTH => BufferParam::MapLength,
        _ => return None,
    })
}

/// `glGetPointerv` names (the array pointers; selection and feedback buffers belong to their
/// own modules).
pub fn pointer_name(e: GLenum) -> Option<ClientArray> {
    use ClientArray::*;
    Some(match e {
        GL_VERTEX_ARRAY_POINTER => Vertex,
        GL_NORMAL_ARRAY_POINTER => Normal,
        GL_COLOR_ARRAY_POINTER => Color,
        GL_SECONDARY_COLOR_ARRAY_POINTER => SecondaryColor,
        GL_FOG_COORD_ARRAY_POINTER => FogCoord,
        GL_TEXTURE_COORD_ARRAY_POINTER => TexCoord,
        GL_EDGE_FLAG_ARRAY_POINTER => EdgeFlag,
        GL_INDEX_ARRAY_POINTER => Index,
        _ => return None,
    })
}

pub fn array_query(e: GLenum) -> Option<ArrayQuery> {
    use ArrayQuery::*;
    use ClientArray as A;
    if let Some(a) = client_array(e) {
        return Some(Enabled(a));
    }
    Some(match e {
        GL_VERTEX_ARRAY_SIZE => Size(A::Vertex),
        GL_COLOR_ARRAY_SIZE => Size(A::Color),
        GL_SECONDARY_COLOR_ARRAY_SIZE => Size(A::SecondaryColor),
        GL_TEXTURE_COORD_ARRAY_SIZE => Size(A::TexCoord),
        GL_VERTEX_ARRAY_TYPE => Type(A::Vertex),
        GL_NORMAL_ARRAY_TYPE => Type(A::Normal),
        GL_COLOR_ARRAY_TYPE => Type(A::Color),
        GL_SECONDARY_COLOR_ARRAY_TYPE => Type(A::SecondaryColor),
        GL_FOG_COORD_ARRAY_TYPE => Type(A::FogCoord),
        GL_TEXTURE_COORD_ARRAY_TYPE => Type(A::TexCoord),
        GL_INDEX_ARRAY_TYPE => Type(A::Index),
        GL_VERTEX_ARRAY_STRIDE => Stride(A::Vertex),
        GL_NORMAL_ARRAY_STRIDE => Stride(A::Normal),
        GL_COLOR_ARRAY_STRIDE => Stride(A::Color),
        GL_SECONDARY_COLOR_ARRAY_STRIDE => Stride(A::SecondaryColor),
        GL_FOG_COORD_ARRAY_STRIDE => Stride(A::FogCoord),
        GL_TEXTURE_COORD_ARRAY_STRIDE => Stride(A::TexCoord),
        GL_EDGE_FLAG_ARRAY_STRIDE => Stride(A::EdgeFlag),
        GL_INDEX_ARRAY_STRIDE => Stride(A::Index),
        GL_VERTEX_ARRAY_COUNT_EXT => Count(A::Vertex),
        GL_NORMAL_ARRAY_COUNT_EXT => Count(A::Normal),
        GL_COLOR_ARRAY_COUNT_EXT => Count(A::Color),
        GL_INDEX_ARRAY_COUNT_EXT => Count(A::Index),
        GL_TEXTURE_COORD_ARRAY_COUNT_EXT => Count(A::TexCoord),
        GL_EDGE_FLAG_ARRAY_COUNT_EXT => Count(A::EdgeFlag),
        GL_VERTEX_ARRAY_BUFFER_BINDING => BufferBinding(A::Vertex),
        GL_NORMAL_ARRAY_BUFFER_BINDING => BufferBinding(A::Normal),
        GL_COLOR_ARRAY_BUFFER_BINDING => BufferBinding(A::Color),
        GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING => BufferBinding(A::SecondaryColor),
        GL_FOG_COORD_ARRAY_BUFFER_BINDING => BufferBinding(A::FogCoord),
        GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING => BufferBinding(A::TexCoord),
        GL_EDGE_FLAG_ARRAY_BUFFER_BINDING => BufferBinding(A::EdgeFlag),
        GL_INDEX_ARRAY_BUFFER_BINDING => BufferBinding(A::Index),
        GL_ARRAY_BUFFER_BINDING => ArrayBufferBinding,
        GL_ELEMENT_ARRAY_BUFFER_BINDING => ElementArrayBufferBinding,
        GL_PIXEL_PACK_BUFFER_BINDING => PixelPackBufferBinding,
        GL_PIXEL_UNPACK_BUFFER_BINDING => PixelUnpackBufferBinding,
        GL_MAX_ELEMENTS_VERTICES => MaxElementsVertices,
        GL_MAX_ELEMENTS_INDICES => MaxElementsIndices,
        GL_CLIENT_ATTRIB_STACK_DEPTH => ClientAttribStackDepth,
        GL_MAX_CLIENT_ATTRIB_STACK_DEPTH => MaxClientAttribStackDepth,
        GL_LIST_BASE => ListBase,
        GL_LIST_INDEX => ListIndex,
        GL_LIST_MODE => ListMode,
        GL_MAX_LIST_NESTING => MaxListNesting,
        GL_ARRAY_ELEMENT_LOCK_FIRST_EXT => LockFirst,
        GL_ARRAY_ELEMENT_LOCK_COUNT_EXT => LockCount,
        _ => return None,
    })
}

/// `glNewList` modes: `Some(true)` for `GL_COMPILE_AND_EXECUTE`.
pub fn list_mode(e: GLenum) -> Option<bool> {
    match e {
        GL_COMPILE => Some(false),
        GL_COMPILE_AND_EXECUTE => Some(true),
        _ => None,
    }
}

pub fn list_name_type(e: GLenum) -> Option<ListNameType> {
    use ListNameType::*;
    Some(match e {
        GL_BYTE => Byte,
        GL_UNSIGNED_BYTE => UnsignedByte,
        GL_SHORT => Short,
        GL_UNSIGNED_SHORT => UnsignedShort,
        GL_INT => Int,
        GL_UNSIGNED_INT => UnsignedInt,
        GL_FLOAT => Float,
        GL_2_BYTES => Bytes(2),
        GL_3_BYTES => Bytes(3),
        GL_4_BYTES => Bytes(4),
        _ => return None,
    })
}

/// `glPushClientAttrib` groups: (pixel store, vertex array); other bits are ignored.
pub fn client_attrib_mask(mask: u32) -> (bool, bool) {
    (
        mask & GL_CLIENT_PIXEL_STORE_BIT != 0,
        mask & GL_CLIENT_VERTEX_ARRAY_BIT != 0,
    )
}
