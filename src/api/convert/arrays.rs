//! GLenum conversions of vertex arrays, buffer objects and display lists (part of `convert`).

use crate::api::enums::*;
use crate::api::types::GLenum;

/// The client arrays of `glEnableClientState` (section 2.8). The texture-coordinate array is
/// the one of the client active texture unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ClientArray {
    Vertex,
    Normal,
    Color,
    SecondaryColor,
    FogCoord,
    TexCoord,
    EdgeFlag,
    /// Colour indices: state only in RGBA mode (sets the current index).
    Index,
}

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

/// Component types of vertex arrays (table 2.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ArrayType {
    Byte,
    UnsignedByte,
    Short,
    UnsignedShort,
    Int,
    UnsignedInt,
    Float,
    Double,
}

impl ArrayType {
    /// Every component type (what colour arrays accept).
    pub const ALL: [ArrayType; 8] = [
        ArrayType::Byte,
        ArrayType::UnsignedByte,
        ArrayType::Short,
        ArrayType::UnsignedShort,
        ArrayType::Int,
        ArrayType::UnsignedInt,
        ArrayType::Float,
        ArrayType::Double,
    ];

    /// Bytes per component.
    pub fn size(self) -> usize {
        use ArrayType::*;
        match self {
            Byte | UnsignedByte => 1,
            Short | UnsignedShort => 2,
            Int | UnsignedInt | Float => 4,
            Double => 8,
        }
    }

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

/// Index types of `glDrawElements` and friends.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum IndexType {
    UnsignedByte,
    UnsignedShort,
    UnsignedInt,
}

impl IndexType {
    pub fn size(self) -> usize {
        match self {
            IndexType::UnsignedByte => 1,
            IndexType::UnsignedShort => 2,
            IndexType::UnsignedInt => 4,
        }
    }
}

pub fn index_type(e: GLenum) -> Option<IndexType> {
    Some(match e {
        GL_UNSIGNED_BYTE => IndexType::UnsignedByte,
        GL_UNSIGNED_SHORT => IndexType::UnsignedShort,
        GL_UNSIGNED_INT => IndexType::UnsignedInt,
        _ => return None,
    })
}

/// Formats of `glInterleavedArrays` (table 2.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum InterleavedFormat {
    V2f,
    V3f,
    C4ubV2f,
    C4ubV3f,
    C3fV3f,
    N3fV3f,
    C4fN3fV3f,
    T2fV3f,
    T4fV4f,
    T2fC4ubV3f,
    T2fC3fV3f,
    T2fN3fV3f,
    T2fC4fN3fV3f,
    T4fC4fN3fV4f,
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

/// Buffer object binding targets (section 2.9).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BufferTarget {
    Array,
    ElementArray,
}

pub fn buffer_target(e: GLenum) -> Option<BufferTarget> {
    Some(match e {
        GL_ARRAY_BUFFER => BufferTarget::Array,
        GL_ELEMENT_ARRAY_BUFFER => BufferTarget::ElementArray,
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

/// `glMapBuffer` access modes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BufferAccess {
    ReadOnly,
    WriteOnly,
    ReadWrite,
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

/// `glGetBufferParameteriv` names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BufferParam {
    Size,
    Usage,
    Access,
    Mapped,
}

pub fn buffer_param(e: GLenum) -> Option<BufferParam> {
    Some(match e {
        GL_BUFFER_SIZE => BufferParam::Size,
        GL_BUFFER_USAGE => BufferParam::Usage,
        GL_BUFFER_ACCESS => BufferParam::Access,
        GL_BUFFER_MAPPED => BufferParam::Mapped,
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

/// What a vertex-array, buffer or display-list `glGet` asks (table 6.8, 6.9, 6.37).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ArrayQuery {
    Enabled(ClientArray),
    Size(ClientArray),
    Type(ClientArray),
    Stride(ClientArray),
    BufferBinding(ClientArray),
    ArrayBufferBinding,
    ElementArrayBufferBinding,
    MaxElementsVertices,
    MaxElementsIndices,
    ClientAttribStackDepth,
    MaxClientAttribStackDepth,
    ListBase,
    ListIndex,
    ListMode,
    MaxListNesting,
    /// EXT_compiled_vertex_array.
    LockFirst,
    LockCount,
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

/// The name types of `glCallLists`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ListNameType {
    Byte,
    UnsignedByte,
    Short,
    UnsignedShort,
    Int,
    UnsignedInt,
    Float,
    /// `GL_2_BYTES`, `GL_3_BYTES`, `GL_4_BYTES`: big-endian unsigned names of this many bytes.
    Bytes(usize),
}

impl ListNameType {
    /// Bytes per name.
    pub fn size(self) -> usize {
        use ListNameType::*;
        match self {
            Byte | UnsignedByte => 1,
            Short | UnsignedShort => 2,
            Int | UnsignedInt | Float => 4,
            Bytes(n) => n,
        }
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
