//! Attribute planes: the linear functions of window position the fragment stage evaluates
//! (`raster::setup` builds them from a primitive's vertices).

/// A linear function of window position: `a*x + b*y + c`, evaluated at pixel centres.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Plane {
    pub a: f64,
    pub b: f64,
    pub c: f64,
}

impl Plane {
    /// A constant.
    pub fn constant(v: f64) -> Plane {
        Plane {
            a: 0.0,
            b: 0.0,
            c: v,
        }
    }

    #[inline(always)]
    pub fn at(&self, x: f64, y: f64) -> f64 {
        self.a * x + self.b * y + self.c
    }
}
