//! Call scripts.
