//! Typed values of vertex arrays, buffer objects and display lists (part of `values`).

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

/// Buffer object binding targets (section 2.9).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BufferTarget {
    Array,
    ElementArray,
    /// ARB_pixel_buffer_object: where pixel commands pack (write) to.
    PixelPack,
    /// ARB_pixel_buffer_object: where pixel commands unpack (read) from.
    PixelUnpack,
}

/// `glMapBuffer` access modes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BufferAccess {
    ReadOnly,
    WriteOnly,
    ReadWrite,
}

/// `glGetBufferParameteriv` names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BufferParam {
    Size,
    Usage,
    Access,
    Mapped,
    /// ARB_map_buffer_range's mapping state (`GL_BUFFER_ACCESS_FLAGS`, `GL_BUFFER_MAP_OFFSET`,
    /// `GL_BUFFER_MAP_LENGTH`).
    AccessFlags,
    MapOffset,
    MapLength,
}

/// What a vertex-array, buffer or display-list `glGet` asks (table 6.8, 6.9, 6.37).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ArrayQuery {
    Enabled(ClientArray),
    Size(ClientArray),
    Type(ClientArray),
    Stride(ClientArray),
    /// EXT_vertex_array's `GL_*_ARRAY_COUNT_EXT`.
    Count(ClientArray),
    BufferBinding(ClientArray),
    ArrayBufferBinding,
    ElementArrayBufferBinding,
    PixelPackBufferBinding,
    PixelUnpackBufferBinding,
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
