//! GLenum conversions of the texturing calls (part of `convert`).
