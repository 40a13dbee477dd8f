//! Texture entry points (`glTexImage*`, `glTexParameter*`, `glBindTexture`, ...).

/// The texture entry points `impl Gl for Context` forwards (see `gl_forward_all!`).
macro_rules! texture_entry_points {
    () => {};
}
