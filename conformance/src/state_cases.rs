//! State and error cases: a script of GL calls that records its own answers (queries,
//! `glGetError` results, read-back values) in order, run on three routes: Mesa, tilegl through
//! the Rust API and tilegl through its C ABI ([`crate::c_route`]). The C ABI's answers must be
//! exactly the Rust API's (printed alike, so NaN and -0.0 count too); tilegl's must agree with
//! Mesa's under the case's own rule, with the known-failure rule applied.
//!
//! The cases are declared once, in the lists of the submodules ([`STATE_CASE_LISTS`]); the
//! tests (`conformance/tests/differential*.rs`) and the conformance report both run them from
//! there.

use std::fmt::Debug;
use std::time::Instant;

use tilegl::Gl;

use crate::c_route::CAbiContext;
use crate::known_failures;
use crate::mesa::{self, MesaContext, Oracle};

pub mod arb_fbo;
pub mod arrays;
pub mod attrib;
pub mod basic;
pub mod eval;
pub mod fbo;
pub mod fbo_blit;
pub mod pbo;
pub mod piglit;
pub mod samplers;
pub mod tex_storage;

/// The framebuffer size every state case runs with.
pub const SIZE: i32 = 64;

/// One recorded answer: what was asked and the value it got.
pub trait Recorded: Debug {
    fn label(&self) -> String;
    fn value(&self) -> String;
}

impl<T: Debug> Recorded for (String, T) {
    fn label(&self) -> String {
        self.0.clone()
    }
    fn value(&self) -> String {
        format!("{:?}", self.1)
    }
}

/// A state or error case, declared once in its list.
#[derive(Clone, Copy, Debug)]
pub struct StateCase {
    pub name: &'static str,
    /// What the specification says the answers are (the expected result).
    pub expect: &'static str,
    /// The source file the script is in (its calls are shown in the report).
    pub source: &'static str,
    /// Runs the script on the three routes.
    pub run: fn(&'static str) -> StateOutcome,
}

impl StateCase {
    /// The script's source text: the function called like the case.
    pub fn calls(&self) -> String {
        function_source(self.source, self.name).unwrap_or_default()
    }

    /// Runs the case and applies the C ABI and known-failure rules: `Ok` with the figures,
    /// `Err` with why it failed (a panic inside counts as a failure of this case only).
    pub fn check(&self) -> Result<String, String> {
        let name = self.name;
        std::panic::catch_unwind(|| (self.run)(name))
            .map_err(|_| format!("{name} panicked"))
            .and_then(|o| o.check(name))
    }
}

/// Every list of state and error cases with its feature area, in report order.
pub const STATE_CASE_LISTS: &[(&str, &[StateCase])] = &[
    ("state cases: queries, matrices, errors", basic::CASES),
    (
        "state cases: attributes, queries, selection, feedback",
        attrib::CASES,
    ),
    ("state cases: arrays, buffers, lists", arrays::CASES),
    ("state cases: evaluators", eval::CASES),
    ("state cases: piglit scripts", piglit::CASES),
    ("state cases: framebuffer objects", fbo::CASES),
    ("state cases: framebuffer blits", fbo_blit::CASES),
    ("state cases: ARB_texture_storage", tex_storage::CASES),
    (
        "state cases: pixel buffer objects, buffer ranges",
        pbo::CASES,
    ),
    ("state cases: ARB_framebuffer_object", arb_fbo::CASES),
    ("state cases: ARB_sampler_objects", samplers::CASES),
];

/// Every state and error case.
pub fn all() -> impl Iterator<Item = &'static StateCase> {
    STATE_CASE_LISTS.iter().flat_map(|(_, l)| l.iter())
}

/// The text of `fn NAME(` up to its closing brace at the same indentation.
fn function_source(source: &str, name: &str) -> Option<String> {
    let key = format!("fn {name}(");
    let at = source.find(&key)?;
    let line_start = source[..at].rfind('\n').map_or(0, |i| i + 1);
    let indent: String = source[line_start..]
        .chars()
        .take_while(|c| *c == ' ')
        .collect();
    let close = format!("\n{indent}}}");
    let end = source[at..].find(&close)? + at + close.len();
    let body: Vec<&str> = source[line_start..end]
        .lines()
        .map(|l| l.strip_prefix(indent.as_str()).unwrap_or(l))
        .collect();
    Some(body.join("\n"))
}

/// One answer on the three routes.
#[derive(Clone, Debug)]
pub struct AnswerRow {
    pub label: String,
    pub rust: Option<String>,
    pub c: Option<String>,
    pub mesa: Option<String>,
    /// tilegl (Rust) agrees with Mesa under the case's rule.
    pub agrees: bool,
}

/// What one state case came to.
#[derive(Clone, Debug)]
pub struct StateOutcome {
    /// Mesa's renderer, or why Mesa did not run.
    pub mesa: Result<String, String>,
    pub answers: Vec<AnswerRow>,
    /// The C ABI gave exactly the Rust API's answers.
    pub c_matches_rust: bool,
    /// Every answer agrees with Mesa's and the counts are equal.
    pub agrees_with_mesa: bool,
    /// Milliseconds: Rust API, C ABI, Mesa.
    pub times: [Option<f64>; 3],
    /// The figures as printed.
    pub summary: String,
}

impl StateOutcome {
    /// The C ABI rule (must match exactly) and the known-failure rule.
    pub fn check(&self, name: &str) -> Result<String, String> {
        if let Err(e) = &self.mesa {
            return Err(format!("{name}: Mesa: {e}"));
        }
        if !self.c_matches_rust {
            return Err(self.summary.clone());
        }
        known_failures::outcome(name, self.agrees_with_mesa, &self.summary)
    }
}

fn timed<R>(f: impl FnOnce() -> R) -> (R, f64) {
    let t = Instant::now();
    let r = f();
    (r, t.elapsed().as_secs_f64() * 1000.0)
}

/// Runs `script` on Mesa, on tilegl's Rust API and on tilegl's C ABI (64x64, the default
/// buffers of [`tilegl::Context::new`]) and compares: the two tilegl routes must answer identically;
/// each of tilegl's answers is checked against Mesa's with `agree`.
pub fn run_routes<T: Recorded>(
    name: &str,
    script: fn(&mut dyn Gl, &mut Vec<T>),
    agree: fn(&T, &T) -> bool,
) -> StateOutcome {
    let (t, t_ms) = timed(|| {
        let mut t = Vec::new();
        script(
            &mut crate::client_context(tilegl::ContextConfig {
                width: SIZE,
                height: SIZE,
                ..Default::default()
            }),
            &mut t,
        );
        t
    });
    let (c, c_ms) = timed(|| {
        let mut c = Vec::new();
        let mut c_abi = CAbiContext::create(SIZE, SIZE, 0).expect("a context through the C ABI");
        script(&mut *c_abi, &mut c);
        c
    });
    let (m, m_ms) = timed(|| {
        mesa::mesa_available().map_err(|e| e.to_string())?;
        let mut mesa = MesaContext::create(SIZE, SIZE).map_err(|e| e.to_string())?;
        let mut m = Vec::new();
        script(&mut *mesa, &mut m);
        Ok::<_, String>((m, mesa.info().to_string()))
    });

    let show = |a: &[T]| a.iter().map(|x| format!("{x:?}")).collect::<Vec<_>>();
    let (ts, cs) = (show(&t), show(&c));
    let c_matches_rust = ts == cs;
    let mut summary = String::new();
    if !c_matches_rust {
        let first = ts.iter().zip(&cs).position(|(a, b)| a != b);
        summary = format!(
            "{name}: answers through the C ABI differ from the Rust API's ({} vs {} answers); \
             first difference: {:?}\n",
            cs.len(),
            ts.len(),
            first.map(|i| (&ts[i], &cs[i]))
        );
    }
    let (mesa_answers, info) = match &m {
        Ok((m, info)) => (Some(m), Ok(info.clone())),
        Err(e) => (None, Err(e.clone())),
    };
    let n = t
        .len()
        .max(c.len())
        .max(mesa_answers.map_or(0, |m| m.len()));
    let mut answers = Vec::with_capacity(n);
    for i in 0..n {
        let (a, b) = (t.get(i), mesa_answers.and_then(|m| m.get(i)));
        answers.push(AnswerRow {
            label: a.or(b).or(c.get(i)).map(|x| x.label()).unwrap_or_default(),
            rust: a.map(|x| x.value()),
            c: c.get(i).map(|x| x.value()),
            mesa: b.map(|x| x.value()),
            agrees: matches!((a, b), (Some(a), Some(b)) if agree(a, b)),
        });
    }
    let mut agrees_with_mesa = false;
    match (&m, &info) {
        (Ok((m, _)), Ok(info)) => {
            summary.push_str(&format!("{name} [{info}]:"));
            agrees_with_mesa = m.len() == t.len();
            if !agrees_with_mesa {
                summary.push_str(&format!(
                    "\n  answer counts differ: tilegl {} mesa {}\n  tilegl {:#?}\n  mesa {:#?}",
                    t.len(),
                    m.len(),
                    t,
                    m
                ));
            }
            for (a, b) in t.iter().zip(m) {
                if !agree(a, b) {
                    agrees_with_mesa = false;
                    summary.push_str(&format!("\n  tilegl {a:?}\n  mesa   {b:?}"));
                }
            }
            if agrees_with_mesa {
                summary.push_str(&format!(" {} answers agree", t.len()));
            }
        }
        _ => summary.push_str(&format!("{name}: Mesa did not run")),
    }
    StateOutcome {
        mesa: info,
        answers,
        c_matches_rust,
        agrees_with_mesa,
        times: [Some(t_ms), Some(c_ms), m.is_ok().then_some(m_ms)],
        summary,
    }
}

/// The test of a list of state cases: requires Mesa (a skip outside CI), then checks every
/// case, one line per case, all failures listed at the end.
pub fn run_list(what: &str, cases: &[StateCase]) {
    if !mesa::require_mesa(what) {
        return;
    }
    crate::run_case_list(what, cases, |c| c.name, StateCase::check);
}

/// Declares a module's `CASES`: `state_case_list!(source = include_str!("this_file.rs"), agree
/// = RULE; name: "what the specification says", ...)`, each name a script function of the
/// module.
macro_rules! state_case_list {
    (source = $source:expr, agree = $agree:expr; $($name:ident: $expect:expr),* $(,)?) => {
        /// This module's cases, in report order.
        pub const CASES: &[$crate::state_cases::StateCase] = &[$(
            $crate::state_cases::StateCase {
                name: stringify!($name),
                expect: $expect,
                source: $source,
                run: |name| $crate::state_cases::run_routes(name, $name, $agree),
            },
        )*];
    };
}
pub(crate) use state_case_list;
