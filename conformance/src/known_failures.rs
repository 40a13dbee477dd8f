//! Differential cases that fail because of a known tilegl bug. A listed case still runs and
//! prints its figures; it passes only while it keeps failing, so the list stays honest: a listed
//! case that starts passing fails with "remove it from KNOWN_FAILURES".

/// (case name, what goes wrong). Each entry is described in the conformance report.
pub const KNOWN_FAILURES: &[(&str, &str)] = &[
    // Empty: the line-endpoint cases (line_endpoints, lines, line_strip, flat_lines) were
    // fixed by the exact diamond-exit test in src/raster/line.rs.
];

/// The reason a case is listed, if it is.
pub fn known_failure(case: &str) -> Option<&'static str> {
    KNOWN_FAILURES
        .iter()
        .find(|(name, _)| *name == case)
        .map(|(_, why)| *why)
}

/// Applies the known-failure rule to one case outcome: `Err` (with the reason) when an unlisted
/// case fails or a listed case passes, `Ok` (with what to print) otherwise.
pub fn outcome(case: &str, passed: bool, details: &str) -> Result<String, String> {
    match (passed, known_failure(case)) {
        (true, None) => Ok(details.to_string()),
        (false, None) => Err(format!("{case} failed: {details}")),
        (false, Some(why)) => Ok(format!(
            "{details}\n{case}: KNOWN FAILURE (listed in KNOWN_FAILURES): {why}"
        )),
        (true, Some(why)) => Err(format!(
            "{case} is listed in KNOWN_FAILURES ({why}) but now passes: remove it from the list"
        )),
    }
}

/// Applies the known-failure rule to one case outcome. Panics (fails the test) when an unlisted
/// case fails or a listed case passes; prints the figures either way.
pub fn check_outcome(case: &str, passed: bool, details: &str) {
    println!("{details}");
    if let Err(e) = outcome(case, passed, details) {
        panic!("{e}");
    }
    if let Some(why) = known_failure(case).filter(|_| !passed) {
        println!("{case}: KNOWN FAILURE (listed in KNOWN_FAILURES): {why}");
    }
}
