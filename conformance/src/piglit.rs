//! piglit's OpenGL 1.x tests on Mesa and on tilegl, for the conformance report: the table of
//! the latest committed run (`docs/piglit.md`, written from the output of `tests/piglit/run.sh`),
//! or the two TSV files of a fresh run (`run.sh` prints `name<TAB>verdict` lines). piglit itself
//! is not run here: it needs an X server and takes about half an hour.

use std::path::{Path, PathBuf};

/// One piglit test's verdicts.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Row {
    pub test: String,
    pub mesa: String,
    pub tilegl: String,
    /// The first message tilegl's run printed, where the record has it.
    pub message: String,
}

/// A piglit run on both implementations.
#[derive(Clone, Debug)]
pub struct Run {
    /// Where the rows come from.
    pub source: String,
    /// When and on what the run was made (the record's "Machine:" paragraph).
    pub label: String,
    /// How to redo it (shell commands).
    pub redo: String,
    pub rows: Vec<Row>,
}

/// The committed record, `docs/piglit.md` of this source tree.
pub fn committed_record() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/piglit.md")
}

/// The rows of the first markdown table after the line `heading`, each row's cells trimmed;
/// the header and separator lines are left out.
fn table_after<'a>(md: &'a str, heading: &str) -> Vec<Vec<&'a str>> {
    // The heading on a line of its own (the text may mention it too).
    let Some(at) = md.find(&format!("\n{heading}\n")) else {
        return Vec::new();
    };
    md[at..]
        .lines()
        .skip_while(|l| !l.starts_with('|'))
        .take_while(|l| l.starts_with('|'))
        .skip(2)
        .map(|l| {
            l.trim()
                .trim_start_matches('|')
                .trim_end_matches('|')
                .split(" | ")
                .map(str::trim)
                .collect()
        })
        .collect()
}

/// Parses the record `docs/piglit.md`: the "All tests" table, the first messages of the tests
/// that pass on Mesa only, the "Machine:" paragraph and the commands that redo it.
pub fn parse_record(md: &str, source: &str) -> Result<Run, String> {
    let mut rows: Vec<Row> = table_after(md, "## All tests")
        .into_iter()
        .filter(|c| c.len() >= 3)
        .map(|c| Row {
            test: c[0].to_string(),
            mesa: c[1].to_string(),
            tilegl: c[2].to_string(),
            message: String::new(),
        })
        .collect();
    if rows.is_empty() {
        return Err(format!("{source}: no \"## All tests\" table"));
    }
    for c in table_after(md, "## Tests that pass on Mesa and not on tilegl") {
        if let (Some(test), Some(msg)) = (c.first(), c.get(3)) {
            if let Some(r) = rows.iter_mut().find(|r| r.test == *test) {
                r.message = msg.to_string();
            }
        }
    }
    let label = md
        .split("\n\n")
        .find(|p| p.starts_with("Machine:"))
        .map(|p| p.replace('\n', " "))
        .unwrap_or_default();
    let redo = md
        .split("```sh\n")
        .nth(1)
        .and_then(|s| s.split("```").next())
        .unwrap_or_default()
        .to_string();
    Ok(Run {
        source: source.to_string(),
        label,
        redo,
        rows,
    })
}

/// Reads the committed record.
pub fn read_committed() -> Result<Run, String> {
    let path = committed_record();
    let md = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    parse_record(&md, "docs/piglit.md")
}

/// Joins the outputs of `tests/piglit/run.sh` on Mesa and on tilegl (`name<TAB>verdict` lines)
/// by test name; a test missing from one side gets the verdict "-".
pub fn from_tsv(mesa: &Path, tilegl: &Path) -> Result<Run, String> {
    let read = |p: &Path| -> Result<Vec<(String, String)>, String> {
        let text = std::fs::read_to_string(p).map_err(|e| format!("{}: {e}", p.display()))?;
        Ok(text
            .lines()
            .filter_map(|l| l.split_once('\t'))
            .map(|(n, v)| (n.to_string(), v.trim().to_string()))
            .collect())
    };
    let (m, t) = (read(mesa)?, read(tilegl)?);
    let mut rows: Vec<Row> = m
        .iter()
        .map(|(name, v)| Row {
            test: name.clone(),
            mesa: v.clone(),
            tilegl: t
                .iter()
                .find(|(n, _)| n == name)
                .map_or("-".into(), |(_, v)| v.clone()),
            message: String::new(),
        })
        .collect();
    for (name, v) in &t {
        if !m.iter().any(|(n, _)| n == name) {
            rows.push(Row {
                test: name.clone(),
                mesa: "-".into(),
                tilegl: v.clone(),
                message: String::new(),
            });
        }
    }
    let modified = std::fs::metadata(tilegl)
        .and_then(|m| m.modified())
        .ok()
        .and_then(|t| t.duration_since(std::time::UNIX_EPOCH).ok())
        .map_or("unknown time".into(), |d| {
            format!("{} s after the Unix epoch", d.as_secs())
        });
    Ok(Run {
        source: format!("{} and {}", mesa.display(), tilegl.display()),
        label: format!("A run given on the command line (tilegl's file written at {modified})."),
        redo: "see docs/piglit.md".into(),
        rows,
    })
}

/// (Mesa verdict, tilegl verdict, number of tests), most common first.
pub fn summary(rows: &[Row]) -> Vec<(String, String, usize)> {
    let mut out: Vec<(String, String, usize)> = Vec::new();
    for r in rows {
        match out
            .iter_mut()
            .find(|(m, t, _)| *m == r.mesa && *t == r.tilegl)
        {
            Some(e) => e.2 += 1,
            None => out.push((r.mesa.clone(), r.tilegl.clone(), 1)),
        }
    }
    out.sort_by(|a, b| b.2.cmp(&a.2).then(a.0.cmp(&b.0)).then(a.1.cmp(&b.1)));
    out
}
