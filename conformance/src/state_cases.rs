//! State and error cases: a script of GL calls that records its own answers (queries,
//! `glGetError` results, read-back values) in order, run on three routes: Mesa, tilegl through
//! the Rust API and tilegl through its C ABI ([`crate::c_route`]). The C ABI's answers must be
//! exactly the Rust API's (printed alike, so NaN and -0.0 count too); tilegl's must agree with
//! Mesa's under the case's own rule, with the known-failure rule applied.

use std::fmt::Debug;

use tilegl::{Context, Gl};

use crate::c_route::CAbiContext;
use crate::known_failures::check_outcome;
use crate::mesa::{self, MesaContext, Oracle};

/// The framebuffer size every state case runs with.
pub const SIZE: i32 = 64;

/// Runs `script` on Mesa, on tilegl's Rust API and on tilegl's C ABI (64x64, the default
/// buffers of [`Context::new`]); asserts the two tilegl routes answer identically and checks
/// each of tilegl's answers against Mesa's with `agree`.
pub fn run<T: Debug>(name: &str, script: fn(&mut dyn Gl, &mut Vec<T>), agree: fn(&T, &T) -> bool) {
    if !mesa::require_mesa(name) {
        return;
    }
    let mut mesa = MesaContext::create(SIZE, SIZE).expect("mesa context");
    let mut m = Vec::new();
    script(&mut *mesa, &mut m);
    let mut t = Vec::new();
    script(&mut Context::new(SIZE, SIZE), &mut t);
    let mut c = Vec::new();
    let mut c_abi = CAbiContext::create(SIZE, SIZE, 0).expect("a context through the C ABI");
    script(&mut *c_abi, &mut c);
    drop(c_abi);

    let show = |a: &[T]| a.iter().map(|x| format!("{x:?}")).collect::<Vec<_>>();
    let (ts, cs) = (show(&t), show(&c));
    if ts != cs {
        let first = ts.iter().zip(&cs).position(|(a, b)| a != b);
        panic!(
            "{name}: answers through the C ABI differ from the Rust API's ({} vs {} answers); first \
             difference: {:?}",
            cs.len(),
            ts.len(),
            first.map(|i| (&ts[i], &cs[i]))
        );
    }

    let mut report = format!("{name} [{}]:", mesa.info());
    let mut ok = m.len() == t.len();
    if !ok {
        report.push_str(&format!(
            "\n  answer counts differ: tilegl {} mesa {}\n  tilegl {:#?}\n  mesa {:#?}",
            t.len(),
            m.len(),
            t,
            m
        ));
    }
    for (a, b) in t.iter().zip(&m) {
        if !agree(a, b) {
            ok = false;
            report.push_str(&format!("\n  tilegl {a:?}\n  mesa   {b:?}"));
        }
    }
    if ok {
        report.push_str(&format!(" {} answers agree", t.len()));
    }
    check_outcome(name, ok, &report);
}
