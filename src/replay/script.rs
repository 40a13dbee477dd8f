//! Call scripts: a text form of a call stream that a person can read and write, and that
//! `tilegl dump` writes from an apitrace capture.
//!
//! One statement per call, ended by `;`, in C call syntax:
//!
//! ```text
//! // comments run to the end of the line
//! window(64, 64);                                   // a 64x64 double-buffered window
//! glClearColor(0.0f, 0.0f, 0.25f, 1.0f);
//! glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
//! glGenTextures(1, {1});                            // output arrays: the traced names
//! glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker(8, 8, 2));
//! glBegin(GL_TRIANGLES); glColor3f(1.0f, 0.0f, 0.0f); glVertex2f(-1, -1); ... glEnd();
//! swap();                                           // end of frame 0
//! ```
//!
//! - **Call numbers**: statements are numbered from 0 in order, like apitrace's calls. A
//!   statement may start with an explicit number (`1744 glXSwapBuffers(...);`, as `tilegl
//!   dump` writes them, so `--calls N` names the same call in a capture and in its dump); the
//!   next unnumbered statement gets the following number. Numbers must increase.
//! - `fake` before the name marks a call the tracer made up (apitrace's `// fake`): a fake
//!   `glViewport` gives the window size.
//! - **Values**: integers (decimal, `0x` hex, negative), floats (`1.5`, `1e-3`; an `f` suffix
//!   makes a 32-bit float, written exactly), GL enum names (`GL_LINEAR`) and `|` between them
//!   for masks, `NULL`, `true`/`false`, strings `"..."` (escapes `\\`, `\"`, `\n`, `\t`,
//!   `\xHH`), arrays `{a, b, ...}`, pointers `ptr(0x...)` (buffer offsets, traced addresses).
//! - **Data** (pixels, vertex arrays, buffer contents): `hex("00ff...")`, `file("path")` (raw
//!   bytes; paths are relative to the script), `png("path.png")` (RGBA8, rows bottom-up as GL
//!   expects them) and the generator `checker(W, H, CELL)` (RGBA8 black and white squares of
//!   CELL pixels, white first).
//! - A return value follows `=` after the call (`glGenLists(1) = 1;`): the replay needs the
//!   traced one for display-list names and mapped buffers.
//! - `window(W, H);` stands for "a window of W x H pixels" (a fake `glViewport(0, 0, W, H)`):
//!   a script that never makes a context current gets one at its first GL call.
//!   `swap();` ends a frame (as `glXSwapBuffers`).
//!
//! Errors name the line and column.

use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::api::enums::enum_by_name;

use super::player::CallSource;
use super::trace::{Call, FunctionSig, Value};

/// Largest data a script generator or file may produce (bytes).
const MAX_DATA: usize = 1 << 28;

/// Reads a call script.
pub struct ScriptReader {
    text: Vec<u8>,
    pos: usize,
    line: usize,
    line_start: usize,
    next_no: u64,
    base: PathBuf,
    sigs: HashMap<String, Arc<FunctionSig>>,
    failed: bool,
}

impl ScriptReader {
    /// A script from text; `base` is the folder relative paths start from.
    pub fn new(text: impl Into<Vec<u8>>, base: &Path) -> ScriptReader {
        ScriptReader {
            text: text.into(),
            pos: 0,
            line: 1,
            line_start: 0,
            next_no: 0,
            base: base.to_path_buf(),
            sigs: HashMap::new(),
            failed: false,
        }
    }

    /// Opens a script file.
    pub fn open(path: &Path) -> Result<ScriptReader, String> {
        let text =
            std::fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        let base = path.parent().unwrap_or(Path::new(".")).to_path_buf();
        Ok(ScriptReader::new(text, &base))
    }

    fn err(&self, msg: impl Into<String>) -> String {
        format!(
            "line {}, column {}: {}",
            self.line,
            self.pos - self.line_start + 1,
            msg.into()
        )
    }

    fn peek(&self) -> Option<u8> {
        self.text.get(self.pos).copied()
    }

    fn bump(&mut self) -> Option<u8> {
        let c = self.peek()?;
        self.pos += 1;
        if c == b'\n' {
            self.line += 1;
            self.line_start = self.pos;
        }
        Some(c)
    }

    /// Skips white space and comments.
    fn skip(&mut self) {
        loop {
            match self.peek() {
                Some(c) if c.is_ascii_whitespace() => {
                    self.bump();
                }
                Some(b'/') if self.text.get(self.pos + 1) == Some(&b'/') => {
                    while let Some(c) = self.peek() {
                        if c == b'\n' {
                            break;
                        }
                        self.bump();
                    }
                }
                _ => return,
            }
        }
    }

    fn expect(&mut self, c: u8) -> Result<(), String> {
        self.skip();
        if self.peek() == Some(c) {
            self.bump();
            Ok(())
        } else {
            Err(self.err(format!(
                "expected `{}`, found {}",
                c as char,
                self.peek()
                    .map_or("the end".to_string(), |x| format!("`{}`", x as char))
            )))
        }
    }

    fn ident(&mut self) -> Option<String> {
        self.skip();
        let start = self.pos;
        while let Some(c) = self.peek() {
            if c.is_ascii_alphanumeric() || c == b'_' {
                self.bump();
            } else {
                break;
            }
        }
        (self.pos > start && !self.text[start].is_ascii_digit())
            .then(|| String::from_utf8_lossy(&self.text[start..self.pos]).into_owned())
            .or_else(|| {
                self.pos = start;
                None
            })
    }

    fn number(&mut self) -> Result<Value, String> {
        self.skip();
        let start = self.pos;
        let neg = self.peek() == Some(b'-');
        if neg {
            self.bump();
        }
        if self.text[self.pos..].starts_with(b"inf") {
            self.pos += 3;
            return Ok(Value::Double(if neg {
                f64::NEG_INFINITY
            } else {
                f64::INFINITY
            }));
        }
        if self.text[self.pos..].starts_with(b"0x") || self.text[self.pos..].starts_with(b"0X") {
            self.pos += 2;
            let s = self.pos;
            while self.peek().is_some_and(|c| c.is_ascii_hexdigit()) {
                self.bump();
            }
            let digits = std::str::from_utf8(&self.text[s..self.pos]).unwrap_or("");
            let v = u64::from_str_radix(digits, 16).map_err(|_| self.err("bad hex number"))?;
            if !neg {
                return Ok(Value::UInt(v));
            }
            // -0x8000000000000000 is i64::MIN; anything larger has no i64 value.
            return i64::try_from(-(v as i128))
                .map(Value::SInt)
                .map_err(|_| self.err("hex number out of range"));
        }
        let mut float = false;
        while let Some(c) = self.peek() {
            match c {
                b'0'..=b'9' => {}
                b'.' | b'e' | b'E' => float = true,
                b'+' | b'-' if matches!(self.text[self.pos - 1], b'e' | b'E') => {}
                _ => break,
            }
            self.bump();
        }
        let s = String::from_utf8_lossy(&self.text[start..self.pos]).into_owned();
        let s = s.as_str();
        if self.peek() == Some(b'f') {
            self.bump();
            return s
                .parse::<f32>()
                .map(Value::Float)
                .map_err(|_| self.err(format!("bad number `{s}`")));
        }
        if float {
            return s
                .parse::<f64>()
                .map(Value::Double)
                .map_err(|_| self.err(format!("bad number `{s}`")));
        }
        if neg {
            s.parse::<i64>()
                .map(|v| {
                    if v < 0 {
                        Value::SInt(v)
                    } else {
                        Value::UInt(v as u64)
                    }
                })
                .map_err(|_| self.err(format!("bad number `{s}`")))
        } else {
            s.parse::<u64>()
                .map(Value::UInt)
                .map_err(|_| self.err(format!("bad number `{s}`")))
        }
    }

    fn string(&mut self) -> Result<Vec<u8>, String> {
        self.expect(b'"')?;
        let mut out = Vec::new();
        loop {
            match self.bump() {
                None => return Err(self.err("unterminated string")),
                Some(b'"') => return Ok(out),
                Some(b'\\') => match self.bump() {
                    Some(b'n') => out.push(b'\n'),
                    Some(b't') => out.push(b'\t'),
                    Some(b'x') => {
                        let h = self.text.get(self.pos..self.pos + 2).unwrap_or(b"");
                        let v = std::str::from_utf8(h)
                            .ok()
                            .and_then(|h| u8::from_str_radix(h, 16).ok())
                            .ok_or_else(|| self.err("bad \\x escape"))?;
                        self.pos += 2;
                        out.push(v);
                    }
                    Some(c) => out.push(c),
                    None => return Err(self.err("unterminated string")),
                },
                Some(c) => out.push(c),
            }
        }
    }

    fn int_arg(&mut self) -> Result<i64, String> {
        self.number()?
            .as_i64()
            .ok_or_else(|| self.err("expected an integer"))
    }

    fn data_function(&mut self, name: &str) -> Result<Value, String> {
        self.expect(b'(')?;
        let v = match name {
            "ptr" => match self.number()? {
                Value::UInt(v) => Value::Opaque(v),
                _ => return Err(self.err("ptr() takes an address")),
            },
            "hex" => {
                let s = self.string()?;
                let s: Vec<u8> = s.into_iter().filter(|c| !c.is_ascii_whitespace()).collect();
                if !s.len().is_multiple_of(2) {
                    return Err(self.err("hex() needs an even number of digits"));
                }
                let mut out = Vec::with_capacity(s.len() / 2);
                for pair in s.chunks(2) {
                    let h = std::str::from_utf8(pair).unwrap_or("");
                    out.push(u8::from_str_radix(h, 16).map_err(|_| self.err("bad hex digit"))?);
                }
                Value::Blob(out.into())
            }
            "file" => {
                let p = String::from_utf8_lossy(&self.string()?).into_owned();
                let path = self.base.join(&p);
                let bytes =
                    std::fs::read(&path).map_err(|e| self.err(format!("file(\"{p}\"): {e}")))?;
                Value::Blob(bytes.into())
            }
            "png" => {
                let p = String::from_utf8_lossy(&self.string()?).into_owned();
                let path = self.base.join(&p);
                let img = image::open(&path)
                    .map_err(|e| self.err(format!("png(\"{p}\"): {e}")))?
                    .to_rgba8();
                let row = img.width() as usize * 4;
                let raw = img.as_raw();
                let mut out = Vec::with_capacity(raw.len());
                for r in raw.chunks(row.max(1)).rev() {
                    out.extend_from_slice(r);
                }
                Value::Blob(out.into())
            }
            "checker" => {
                let w = self.int_arg()?;
                self.expect(b',')?;
                let h = self.int_arg()?;
                self.expect(b',')?;
                let cell = self.int_arg()?.max(1);
                // Checked: `inf` or a huge literal reads as i64::MAX, and w * h * 4 would overflow.
                let bytes = w
                    .checked_mul(h)
                    .and_then(|n| n.checked_mul(4))
                    .filter(|&n| w >= 0 && h >= 0 && n as u64 <= MAX_DATA as u64)
                    .ok_or_else(|| self.err("checker() size out of range"))?;
                let mut out = Vec::with_capacity(bytes as usize);
                for y in 0..h {
                    for x in 0..w {
                        let v = if (x / cell + y / cell) % 2 == 0 {
                            255
                        } else {
                            0
                        };
                        out.extend_from_slice(&[v, v, v, 255]);
                    }
                }
                Value::Blob(out.into())
            }
            _ => unreachable!(),
        };
        self.expect(b')')?;
        Ok(v)
    }

    fn value(&mut self) -> Result<Value, String> {
        self.skip();
        match self.peek() {
            Some(b'{') => {
                self.bump();
                let mut items = Vec::new();
                self.skip();
                if self.peek() == Some(b'}') {
                    self.bump();
                    return Ok(Value::Array(items));
                }
                loop {
                    items.push(self.value()?);
                    self.skip();
                    match self.bump() {
                        Some(b',') => continue,
                        Some(b'}') => return Ok(Value::Array(items)),
                        _ => return Err(self.err("expected `,` or `}` in an array")),
                    }
                }
            }
            Some(b'"') => Ok(Value::String(self.string()?)),
            Some(c) if c == b'-' || c.is_ascii_digit() => self.number(),
            Some(c) if c.is_ascii_alphabetic() || c == b'_' => {
                let id = self.ident().unwrap_or_default();
                match id.as_str() {
                    "NULL" => return Ok(Value::Null),
                    "true" => return Ok(Value::Bool(true)),
                    "false" => return Ok(Value::Bool(false)),
                    "nan" => return Ok(Value::Double(f64::NAN)),
                    "inf" => return Ok(Value::Double(f64::INFINITY)),
                    "ptr" | "hex" | "file" | "png" | "checker" => return self.data_function(&id),
                    _ => {}
                }
                // An enum, or several joined by `|`.
                let mut v = self.enum_value(&id)?;
                loop {
                    self.skip();
                    if self.peek() != Some(b'|') {
                        return Ok(Value::UInt(v));
                    }
                    self.bump();
                    self.skip();
                    v |= match self.ident() {
                        Some(id) => self.enum_value(&id)?,
                        None => self
                            .number()?
                            .as_i64()
                            .ok_or_else(|| self.err("expected a number"))?
                            as u64,
                    };
                }
            }
            _ => Err(self.err("expected a value")),
        }
    }

    fn enum_value(&self, id: &str) -> Result<u64, String> {
        enum_by_name(id)
            .map(|v| v as u64)
            .ok_or_else(|| self.err(format!("unknown name `{id}`")))
    }

    fn sig(&mut self, name: &str, nargs: usize) -> Arc<FunctionSig> {
        if let Some(s) = self.sigs.get(name) {
            if s.arg_names.len() >= nargs {
                return s.clone();
            }
        }
        let mut arg_names: Vec<String> = crate::api::command(name)
            .map(|c| c.params.iter().map(|p| p.name.to_string()).collect())
            .unwrap_or_default();
        while arg_names.len() < nargs {
            arg_names.push(format!("arg{}", arg_names.len()));
        }
        let s = Arc::new(FunctionSig {
            name: name.to_string(),
            arg_names,
        });
        self.sigs.insert(name.to_string(), s.clone());
        s
    }

    fn statement(&mut self) -> Result<Option<Call>, String> {
        self.skip();
        if self.peek().is_none() {
            return Ok(None);
        }
        let mut no = self.next_no;
        if self.peek().is_some_and(|c| c.is_ascii_digit()) {
            let n = self.int_arg()? as u64;
            if n < self.next_no {
                return Err(self.err(format!(
                    "call number {n} is not after the previous call ({})",
                    self.next_no.saturating_sub(1)
                )));
            }
            no = n;
        }
        let mut name = self.ident().ok_or_else(|| self.err("expected a call"))?;
        let mut flags = 0;
        if name == "fake" {
            flags = 1;
            name = self
                .ident()
                .ok_or_else(|| self.err("expected a call after `fake`"))?;
        }
        self.expect(b'(')?;
        let mut args = Vec::new();
        self.skip();
        if self.peek() == Some(b')') {
            self.bump();
        } else {
            loop {
                args.push(Some(self.value()?));
                self.skip();
                match self.bump() {
                    Some(b',') => continue,
                    Some(b')') => break,
                    _ => return Err(self.err("expected `,` or `)` after an argument")),
                }
            }
        }
        self.skip();
        let mut ret = None;
        if self.peek() == Some(b'=') {
            self.bump();
            ret = Some(self.value()?);
        }
        self.expect(b';')?;
        let (name, args, flags) = match name.as_str() {
            "window" => {
                if args.len() != 2 {
                    return Err(self.err("window(W, H) takes two numbers"));
                }
                let mut a = vec![Some(Value::UInt(0)), Some(Value::UInt(0))];
                a.extend(args);
                ("glViewport".to_string(), a, 1)
            }
            "swap" => ("glXSwapBuffers".to_string(), args, flags),
            _ => (name, args, flags),
        };
        let sig = self.sig(&name, args.len());
        self.next_no = no
            .checked_add(1)
            .ok_or_else(|| self.err("call number out of range"))?;
        Ok(Some(Call {
            no,
            thread: 0,
            sig,
            args,
            ret,
            flags,
            incomplete: false,
        }))
    }
}

impl CallSource for ScriptReader {
    fn next_call(&mut self) -> Result<Option<Call>, String> {
        if self.failed {
            return Ok(None);
        }
        self.statement().inspect_err(|_| self.failed = true)
    }
}

/// Whether `bytes` (the start of a file) look like an apitrace capture rather than a script.
pub fn looks_like_trace(bytes: &[u8]) -> bool {
    bytes.starts_with(b"at") || bytes.starts_with(&[0x1f, 0x8b])
}

// ------------------------------------------------------------------------------------------
// Writing scripts (`tilegl dump`)

/// Blobs up to this size are written inline as `hex("...")`, larger ones to files.
pub const INLINE_BLOB: usize = 64;

/// Writes one value in script syntax. `blob` stores a large blob and returns the value text
/// that refers to it (e.g. `file("blobs/...")`).
pub fn write_value(
    out: &mut String,
    v: &Value,
    blob: &mut dyn FnMut(&[u8]) -> Result<String, String>,
) -> Result<(), String> {
    match v {
        Value::Null => out.push_str("NULL"),
        Value::Bool(b) => out.push_str(if *b { "true" } else { "false" }),
        Value::SInt(i) => write!(out, "{i}").unwrap(),
        Value::UInt(u) => write!(out, "{u}").unwrap(),
        Value::Float(f) => {
            if f.is_finite() {
                write!(out, "{f:?}f").unwrap()
            } else {
                write_nonfinite(out, *f as f64)
            }
        }
        Value::Double(d) => {
            if d.is_finite() {
                write!(out, "{d:?}").unwrap()
            } else {
                write_nonfinite(out, *d)
            }
        }
        Value::String(s) => write_string(out, s),
        Value::WString(s) => {
            let s: String = s.iter().filter_map(|&c| char::from_u32(c)).collect();
            write_string(out, s.as_bytes())
        }
        Value::Blob(b) => {
            if b.len() <= INLINE_BLOB {
                out.push_str("hex(\"");
                for x in b.iter() {
                    write!(out, "{x:02x}").unwrap();
                }
                out.push_str("\")");
            } else {
                out.push_str(&blob(b)?);
            }
        }
        Value::Enum(sig, e) => {
            // The trace's name when it means the same in tilegl's enum table, else the number.
            match sig
                .name_of(*e)
                .filter(|n| enum_by_name(n).map(|x| x as i64) == Some(*e))
            {
                Some(n) => out.push_str(n),
                None => write!(out, "{e}").unwrap(),
            }
        }
        Value::Bitmask(sig, m) => {
            let mut rest = *m;
            let mut parts = Vec::new();
            for (n, f) in &sig.flags {
                if *f != 0 && rest & f == *f && enum_by_name(n).map(|x| x as u64) == Some(*f) {
                    parts.push(n.clone());
                    rest &= !f;
                }
            }
            if rest != 0 || parts.is_empty() {
                parts.push(format!("0x{rest:x}"));
            }
            out.push_str(&parts.join(" | "));
        }
        Value::Array(items) | Value::Struct(_, items) => {
            out.push('{');
            for (i, x) in items.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                write_value(out, x, blob)?;
            }
            out.push('}');
        }
        Value::Opaque(p) => write!(out, "ptr(0x{p:x})").unwrap(),
        Value::Repr(_, machine) => write_value(out, machine, blob)?,
    }
    Ok(())
}

fn write_nonfinite(out: &mut String, f: f64) {
    out.push_str(if f.is_nan() {
        "nan"
    } else if f > 0.0 {
        "inf"
    } else {
        "-inf"
    });
}

fn write_string(out: &mut String, s: &[u8]) {
    out.push('"');
    for &c in s {
        match c {
            b'"' => out.push_str("\\\""),
            b'\\' => out.push_str("\\\\"),
            b'\n' => out.push_str("\\n"),
            b'\t' => out.push_str("\\t"),
            0x20..=0x7e => out.push(c as char),
            _ => write!(out, "\\x{c:02x}").unwrap(),
        }
    }
    out.push('"');
}

/// Writes one call as a numbered script statement (one line, with the newline).
pub fn write_call(
    out: &mut String,
    call: &Call,
    blob: &mut dyn FnMut(&[u8]) -> Result<String, String>,
) -> Result<(), String> {
    write!(out, "{} ", call.no).unwrap();
    if call.is_fake() {
        out.push_str("fake ");
    }
    out.push_str(call.name());
    out.push('(');
    for (i, a) in call.args.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        match a {
            Some(v) => write_value(out, v, blob)?,
            // An argument that was never recorded (an output of a call that did not return).
            None => out.push_str("NULL"),
        }
    }
    out.push(')');
    if let Some(r) = &call.ret {
        out.push_str(" = ");
        write_value(out, r, blob)?;
    }
    out.push_str(";\n");
    Ok(())
}

/// Writes a whole call stream as a script into `dir/NAME.gl`, large blobs into
/// `dir/NAME.blobs/`. Returns the script's path and the number of calls.
pub fn dump(
    source: &mut dyn CallSource,
    dir: &Path,
    name: &str,
    header: &str,
) -> Result<(PathBuf, u64), String> {
    use std::io::Write;
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let script = dir.join(format!("{name}.gl"));
    let blob_dir_name = format!("{name}.blobs");
    let blob_dir = dir.join(&blob_dir_name);
    let file = std::fs::File::create(&script)
        .map_err(|e| format!("cannot create {}: {e}", script.display()))?;
    let mut w = std::io::BufWriter::new(file);
    let write_err = |e: std::io::Error| format!("cannot write {}: {e}", script.display());
    for line in header.lines() {
        writeln!(w, "// {line}").map_err(write_err)?;
    }
    let mut n = 0u64;
    let mut blobs = 0u64;
    let mut line = String::new();
    loop {
        let call = match source.next_call() {
            Ok(Some(c)) => c,
            Ok(None) => break,
            Err(e) => {
                w.flush().map_err(write_err)?;
                return Err(format!("after {n} calls: {e}"));
            }
        };
        line.clear();
        let mut store = |b: &[u8]| -> Result<String, String> {
            if blobs == 0 {
                std::fs::create_dir_all(&blob_dir)
                    .map_err(|e| format!("cannot create {}: {e}", blob_dir.display()))?;
            }
            let f = format!("{:010}-{blobs}.bin", call.no);
            blobs += 1;
            std::fs::write(blob_dir.join(&f), b).map_err(|e| format!("cannot write {f}: {e}"))?;
            Ok(format!("file(\"{blob_dir_name}/{f}\")"))
        };
        write_call(&mut line, &call, &mut store)?;
        w.write_all(line.as_bytes()).map_err(write_err)?;
        n += 1;
    }
    w.flush().map_err(write_err)?;
    Ok((script, n))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::api::enums::*;

    fn calls(text: &str) -> Result<Vec<Call>, String> {
        let mut r = ScriptReader::new(text, Path::new("."));
        let mut v = Vec::new();
        while let Some(c) = CallSource::next_call(&mut r)? {
            v.push(c);
        }
        Ok(v)
    }

    #[test]
    fn statements_parse_into_calls() {
        let c = calls(
            "// a comment\n\
             window(32, 16);\n\
             glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT); // trailing\n\
             7 glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);\n\
             glLightfv(GL_LIGHT0, GL_POSITION, {1.5f, -2, 0x10, 1e-3});\n\
             fake glViewport(0, 0, 8, 8);\n\
             glGenLists(2) = 5;\n\
             glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker(2, 2, 1));\n\
             glBufferData(GL_ARRAY_BUFFER, 3, hex(\"0a0B ff\"), GL_STATIC_DRAW);\n\
             glVertexPointer(3, GL_FLOAT, 0, ptr(0xc)); glPushName(\"a\\\"b\\x41\");\n\
             swap();",
        )
        .unwrap();
        let names: Vec<&str> = c.iter().map(|c| c.name()).collect();
        assert_eq!(
            names,
            [
                "glViewport",
                "glClear",
                "glTexParameterf",
                "glLightfv",
                "glViewport",
                "glGenLists",
                "glTexImage2D",
                "glBufferData",
                "glVertexPointer",
                "glPushName",
                "glXSwapBuffers"
            ]
        );
        let nos: Vec<u64> = c.iter().map(|c| c.no).collect();
        assert_eq!(nos, [0, 1, 7, 8, 9, 10, 11, 12, 13, 14, 15]);
        assert!(c[0].is_fake() && c[4].is_fake() && !c[1].is_fake());
        assert_eq!(c[0].arg(3).unwrap().as_i64(), Some(16));
        assert_eq!(
            c[1].arg(0).unwrap().as_i64(),
            Some((GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT) as i64)
        );
        assert_eq!(c[2].arg(2).unwrap().as_f64(), Some(GL_LINEAR as f64));
        assert_eq!(
            c[3].arg(2),
            Some(&Value::Array(vec![
                Value::Float(1.5),
                Value::SInt(-2),
                Value::UInt(16),
                Value::Double(1e-3)
            ]))
        );
        assert_eq!(c[5].ret, Some(Value::UInt(5)));
        let Some(Value::Blob(b)) = c[6].arg(8) else {
            panic!()
        };
        assert_eq!(
            &b[..],
            &[255, 255, 255, 255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255, 255]
        );
        assert_eq!(c[7].arg(2), Some(&Value::Blob(vec![10, 11, 255].into())));
        assert_eq!(c[8].arg(3), Some(&Value::Opaque(12)));
        assert_eq!(c[9].arg(0), Some(&Value::String(b"a\"bA".to_vec())));
        assert_eq!(c[2].sig.arg_names[1], "pname");
    }

    #[test]
    fn errors_name_the_line_and_never_panic() {
        for (text, want) in [
            ("glClear(GL_NOT_A_NAME);", "line 1"),
            ("\n\nglClear(1", "line 3"),
            ("glClear(1) glEnd();", "expected `;`"),
            ("5 glEnd(); 3 glEnd();", "not after"),
            ("glVertex2f(1.0.0, 2);", "bad number"),
            ("glFoo(\"abc);", "unterminated"),
            ("glFoo(hex(\"abc\"));", "even"),
            ("glFoo(file(\"/nonexistent/x\"));", "file("),
            ("glFoo({1, 2);", "array"),
            ("window(1);", "window"),
            ("glFoo(checker(4, inf, 2));", "checker() size"),
            (
                "glFoo(checker(4611686018427387904, 4, 1));",
                "checker() size",
            ),
            ("glFoo(checker(-2, 4, 1));", "checker() size"),
            ("18446744073709551615 glEnd();", "call number out of range"),
            ("glFoo(-0x8000000000000001);", "out of range"),
        ] {
            let e = calls(text).unwrap_err();
            assert!(e.contains(want), "{text}: {e}");
        }
        // Arbitrary bytes: an error or calls, never a panic.
        let mut state = 0x1234_5678u32;
        for _ in 0..2000 {
            let mut t = Vec::new();
            for _ in 0..(state % 40) {
                state ^= state << 13;
                state ^= state >> 17;
                state ^= state << 5;
                t.push(b"gl(){},;\"x0-.|f/ \n1e_GLA"[state as usize % 24]);
            }
            let _ = calls(&String::from_utf8_lossy(&t));
        }
    }

    #[test]
    fn written_calls_read_back_the_same() {
        let text = "3 fake glViewport(0, 0, 300, 300);\n\
                    4 glClearColor(0.1f, 0.2f, 0.3f, 1.0f);\n\
                    5 glTranslated(0.1, -2.0, inf);\n\
                    6 glBufferData(GL_ARRAY_BUFFER, 2, hex(\"0102\"), GL_STATIC_DRAW);\n\
                    7 glGenTextures(1, {1});\n\
                    8 glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY) = ptr(0x55aa);\n\
                    9 glXSwapBuffers(ptr(0x1), 2097154);\n";
        let first = calls(text).unwrap();
        let mut out = String::new();
        for c in &first {
            write_call(&mut out, c, &mut |_| Err("no big blobs".into())).unwrap();
        }
        let second = calls(&out).unwrap();
        assert_eq!(first.len(), second.len());
        for (a, b) in first.iter().zip(&second) {
            assert_eq!((a.no, a.name(), a.flags), (b.no, b.name(), b.flags));
            assert_eq!(a.args, b.args, "{out}");
            assert_eq!(a.ret, b.ret);
        }
    }
}
