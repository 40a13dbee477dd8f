//! The C types of `GL/gl.h`, so signatures read like the specification.
#![allow(missing_docs)]

pub type GLenum = u32;
pub type GLboolean = u8;
pub type GLbitfield = u32;
pub type GLbyte = i8;
pub type GLshort = i16;
pub type GLint = i32;
pub type GLsizei = i32;
pub type GLubyte = u8;
pub type GLushort = u16;
pub type GLuint = u32;
pub type GLfloat = f32;
pub type GLclampf = f32;
pub type GLdouble = f64;
pub type GLclampd = f64;
pub type GLintptr = isize;
pub type GLsizeiptr = isize;

/// A client memory address that GL keeps after the call returns (client arrays, selection and
/// feedback buffers, offsets into buffer objects). Safe Rust cannot hand such a pointer over, so
/// it travels as a number; only the C ABI turns it back into memory (`capi::client_memory`),
/// for the contexts it is attached to: those the C ABI and the replayer create, and a Rust
/// context whose owner calls `unsafe capi::client_memory::attach`, promising GL's client-array
/// contract (the memory stays valid while draws read it). A context without it reads client
/// arrays as empty and skips pointer and buffer writes. Rust code that wants no such promise
/// sources its arrays from buffer objects, where the value is an offset into context-owned
/// memory.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ClientPtr(pub usize);
