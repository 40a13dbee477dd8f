//! The replay front door: apitrace captures ([`trace`]) and call scripts ([`script`]) decoded
//! into [`trace::Call`]s and replayed on any [`crate::Gl`] implementation through one generated
//! dispatch ([`dispatch`]).

pub mod dispatch;
pub mod player;
pub mod reference;
pub mod script;
pub mod trace;
