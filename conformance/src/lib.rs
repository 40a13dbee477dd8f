//! The tilegl conformance crate: the Mesa oracle ([`mesa`]), scene comparison ([`compare`]),
//! the differential tolerance ([`tolerance`]), the shared differential scenes ([`scenes`]), the
//! known-failures list ([`known_failures`]) and the triangle benchmark ([`bench`]).

pub mod bench;
pub mod compare;
pub mod known_failures;
pub mod mesa;
pub mod prng;
pub mod scenes;
pub mod tolerance;

pub use compare::{Diff, Image, Scene};
pub use mesa::{MesaContext, Oracle, OracleError, OracleInfo};
