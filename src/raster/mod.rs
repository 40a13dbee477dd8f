//! The tile-based rasterizer: setup turns window-space primitives into edge functions and
//! attribute planes, binning records them per screen tile, and at a flush point the tiles are
//! shaded in parallel, each replaying its commands in submission order.

pub mod coarse;
pub mod controls;
pub mod draw;
pub mod line;
mod line_tile;
pub mod point;
pub mod prefetch;
pub mod scene;
pub mod schedule;
pub mod setup;
pub mod tri;
