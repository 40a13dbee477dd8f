//! The sticky GL error flag (OpenGL 1.5 section 2.5): the first error recorded is kept until
//! `glGetError` reads it; later errors are dropped.

use super::enums::GL_NO_ERROR;
use super::types::GLenum;

/// The error flag of one context.
#[derive(Clone, Copy, Debug, Default)]
pub struct ErrorFlag {
    first: Option<GLenum>,
}

impl ErrorFlag {
    /// Records `error` unless an earlier error is still unread.
    pub fn record(&mut self, error: GLenum) {
        if self.first.is_none() {
            self.first = Some(error);
        }
    }

    /// Returns the recorded error (or `GL_NO_ERROR`) and clears the flag.
    pub fn take(&mut self) -> GLenum {
        self.first.take().unwrap_or(GL_NO_ERROR)
    }

    /// The recorded error, without clearing it.
    pub fn peek(&self) -> GLenum {
        self.first.unwrap_or(GL_NO_ERROR)
    }
}
