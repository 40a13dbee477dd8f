//! A streaming reader of apitrace binary traces (`.trace`) as written by apitrace 11.x.
//!
//! The format is described in `shared/reference/apitrace-format.md`. Layers:
//! 1. the container: apitrace's snappy chunks (`at` magic, `u32` length + one raw snappy block
//!    each) or gzip;
//! 2. one continuous decompressed byte stream ([`ByteStream`]), read through a small window so
//!    memory stays bounded whatever the trace's size;
//! 3. events (call ENTER / LEAVE) holding typed [`Value`]s, with function, enum, bitmask, struct
//!    and backtrace-frame signatures defined inline on first use.
//!
//! Calls are handed out when their LEAVE is read (as apitrace does); calls still waiting at the
//! end of the file come last, marked incomplete. Every malformed input gives a [`TraceError`]
//! naming the offset in the decompressed stream (and the file offset of the chunk it came
//! from); nothing panics, and no allocation is larger than the input read so far justifies.

use std::cell::Cell;
use std::collections::HashMap;
use std::fmt;
use std::io::{self, Read};
use std::path::Path;
use std::rc::Rc;
use std::sync::Arc;

/// An error while reading a trace, with where it happened.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TraceError {
    /// Offset in the decompressed stream (the numbering `apitrace` and the format note use).
    pub offset: u64,
    /// File offset of the compressed chunk holding `offset` (equal to `offset` for
    /// uncompressed input).
    pub file_offset: u64,
    /// What went wrong.
    pub message: String,
}

impl fmt::Display for TraceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "trace error at stream offset {} (chunk at file offset {}): {}",
            self.offset, self.file_offset, self.message
        )
    }
}

impl std::error::Error for TraceError {}

/// A function signature: the name and the argument names.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FunctionSig {
    /// Function name, e.g. `glTexImage2D`.
    pub name: String,
    /// Argument names in order.
    pub arg_names: Vec<String>,
}

/// An enum signature: every name/value pair of one C enum type.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct EnumSig {
    /// Name/value pairs in signature order.
    pub values: Vec<(String, i64)>,
}

impl EnumSig {
    /// The first name with this value, as `apitrace dump` prints it.
    pub fn name_of(&self, v: i64) -> Option<&str> {
        self.values
            .iter()
            .find(|(_, x)| *x == v)
            .map(|(n, _)| n.as_str())
    }
}

/// A bitmask signature: flag names and values.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct BitmaskSig {
    /// Flag name/value pairs in signature order.
    pub flags: Vec<(String, u64)>,
}

/// A struct signature: the struct's name and member names.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StructSig {
    /// Struct name (may be empty).
    pub name: String,
    /// Member names (may be empty for anonymous members).
    pub members: Vec<String>,
}

/// One decoded value.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// A null pointer (also a buffer offset of 0).
    Null,
    /// C++ `bool`.
    Bool(bool),
    /// A negative integer.
    SInt(i64),
    /// A non-negative integer.
    UInt(u64),
    /// `float`.
    Float(f32),
    /// `double`.
    Double(f64),
    /// A C string (bytes, no NUL).
    String(Vec<u8>),
    /// A copy of client memory the call read (pixels, arrays, buffer data).
    Blob(Arc<[u8]>),
    /// An enum value with its signature.
    Enum(Arc<EnumSig>, i64),
    /// A bitmask value with its signature.
    Bitmask(Arc<BitmaskSig>, u64),
    /// An array of values.
    Array(Vec<Value>),
    /// A struct value.
    Struct(Arc<StructSig>, Vec<Value>),
    /// An opaque pointer or handle (an address at trace time, or a buffer offset).
    Opaque(u64),
    /// Two views of one value: (human, machine).
    Repr(Box<Value>, Box<Value>),
    /// A wide string (code points).
    WString(Vec<u32>),
}

impl Value {
    /// The value as a signed integer, if it is numeric (floats are truncated toward zero).
    pub fn as_i64(&self) -> Option<i64> {
        match self {
            Value::Null => Some(0),
            Value::Bool(b) => Some(*b as i64),
            Value::SInt(v) => Some(*v),
            Value::UInt(v) => Some(*v as i64),
            Value::Float(f) => Some(float_to_i64(*f as f64)),
            Value::Double(f) => Some(float_to_i64(*f)),
            Value::Enum(_, v) => Some(*v),
            Value::Bitmask(_, v) => Some(*v as i64),
            Value::Opaque(v) => Some(*v as i64),
            Value::Repr(_, m) => m.as_i64(),
            Value::Array(a) if a.len() == 1 => a[0].as_i64(),
            _ => None,
        }
    }

    /// The value as a float, if it is numeric.
    pub fn as_f64(&self) -> Option<f64> {
        match self {
            Value::Float(f) => Some(*f as f64),
            Value::Double(f) => Some(*f),
            Value::UInt(v) => Some(*v as f64),
            Value::Bitmask(_, v) => Some(*v as f64),
            Value::Opaque(v) => Some(*v as f64),
            Value::Repr(_, m) => m.as_f64(),
            Value::Array(a) if a.len() == 1 => a[0].as_f64(),
            other => other.as_i64().map(|v| v as f64),
        }
    }

    /// The number of elements for arrays and bytes for blobs and strings; 1 for scalars, 0 for
    /// null.
    pub fn len(&self) -> usize {
        match self {
            Value::Null => 0,
            Value::Array(a) => a.len(),
            Value::Blob(b) => b.len(),
            Value::String(s) => s.len(),
            Value::WString(s) => s.len(),
            _ => 1,
        }
    }

    /// True for null and empty arrays, blobs and strings.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

fn float_to_i64(f: f64) -> i64 {
    if f.is_nan() {
        0
    } else {
        f as i64 // saturating in Rust
    }
}

/// One call: a completed ENTER/LEAVE pair (or an incomplete ENTER at the end of the file).
#[derive(Debug, Clone)]
pub struct Call {
    /// Call number (the Nth ENTER event, from 0).
    pub no: u64,
    /// Thread index.
    pub thread: u64,
    /// The function.
    pub sig: Arc<FunctionSig>,
    /// Arguments by index; `None` where no value was recorded.
    pub args: Vec<Option<Value>>,
    /// The return value, if recorded.
    pub ret: Option<Value>,
    /// Call flags; bit 0 = fake (made up by the tracer).
    pub flags: u64,
    /// The call never returned (its LEAVE is missing).
    pub incomplete: bool,
}

impl Call {
    /// The function's name.
    pub fn name(&self) -> &str {
        &self.sig.name
    }

    /// Whether the tracer made the call up to record state (`// fake` in `apitrace dump`).
    pub fn is_fake(&self) -> bool {
        self.flags & 1 != 0
    }

    /// Argument `i`, if recorded.
    pub fn arg(&self, i: usize) -> Option<&Value> {
        self.args.get(i).and_then(|a| a.as_ref())
    }

    /// The argument called `name`, if recorded.
    pub fn arg_named(&self, name: &str) -> Option<&Value> {
        let i = self.sig.arg_names.iter().position(|n| n == name)?;
        self.arg(i)
    }
}

// ------------------------------------------------------------------------------------------
// Container layer

/// Largest compressed chunk accepted (apitrace writes at most ~1 MiB of data per chunk).
const MAX_CHUNK: u64 = 1 << 28;

/// Largest blob or string one value may hold: 1 GiB, the largest texture image tilegl (and
/// Mesa llvmpipe) accepts ([`crate::texture::image::MAX_IMAGE_BYTES`]). A capture claiming
/// more is refused with an error naming the size and the offset, before anything is
/// allocated or read for it (a highly compressible blob would otherwise be decompressed into
/// gigabytes of memory).
pub const MAX_BLOB: u64 = crate::texture::image::MAX_IMAGE_BYTES as u64;

/// Largest number of elements of one array value (each element takes at least one byte of
/// the stream and a few dozen bytes of memory once read).
pub const MAX_ARRAY: u64 = 1 << 24;

enum Container {
    /// apitrace snappy chunks.
    Snappy {
        inner: Box<dyn Read>,
        file_pos: u64,
        compressed: Vec<u8>,
        done: bool,
    },
    /// gzip (apitrace repack -z, early tracers), with the count of compressed bytes read.
    Gzip(Box<dyn Read>, Rc<Cell<u64>>),
}

/// Counts bytes read (for file offsets in error messages).
struct CountingReader<R> {
    inner: R,
    count: Rc<Cell<u64>>,
}

impl<R: Read> Read for CountingReader<R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = self.inner.read(buf)?;
        self.count.set(self.count.get() + n as u64);
        Ok(n)
    }
}

/// The decompressed byte stream behind a bounded window.
pub struct ByteStream {
    container: Container,
    /// Decompressed bytes not consumed yet are `buf[pos..]`.
    buf: Vec<u8>,
    pos: usize,
    /// Stream offset of `buf[0]`.
    base: u64,
    /// File offset of the chunk that produced `buf` (best effort).
    chunk_file_offset: u64,
    eof: bool,
}

impl ByteStream {
    /// Opens a stream on a reader positioned at the start of a trace file.
    pub fn new(mut inner: Box<dyn Read>) -> Result<ByteStream, TraceError> {
        let mut magic = [0u8; 2];
        let n = read_full(&mut inner, &mut magic).map_err(|e| TraceError {
            offset: 0,
            file_offset: 0,
            message: format!("cannot read: {e}"),
        })?;
        let err = |m: &str| TraceError {
            offset: 0,
            file_offset: 0,
            message: m.to_string(),
        };
        if n < 2 {
            return Err(err("file too short to be a trace"));
        }
        let container = match magic {
            [b'a', b't'] => Container::Snappy {
                inner,
                file_pos: 2,
                compressed: Vec::new(),
                done: false,
            },
            [0x1f, 0x8b] => {
                let count = Rc::new(Cell::new(0));
                let chained = io::Cursor::new(magic.to_vec()).chain(inner);
                let dec = flate2::read::MultiGzDecoder::new(CountingReader {
                    inner: chained,
                    count: count.clone(),
                });
                Container::Gzip(Box::new(dec), count)
            }
            [0x28, 0xb5] => return Err(err("zstd-compressed traces are not supported")),
            _ => {
                return Err(err(
                    "not an apitrace snappy or gzip trace (brotli traces are not supported)",
                ))
            }
        };
        Ok(ByteStream {
            container,
            buf: Vec::new(),
            pos: 0,
            base: 0,
            chunk_file_offset: 0,
            eof: false,
        })
    }

    /// Offset in the decompressed stream of the next byte.
    pub fn offset(&self) -> u64 {
        self.base + self.pos as u64
    }

    fn error(&self, message: impl Into<String>) -> TraceError {
        self.error_at(self.offset(), message)
    }

    fn error_at(&self, offset: u64, message: impl Into<String>) -> TraceError {
        TraceError {
            offset,
            file_offset: self.chunk_file_offset,
            message: message.into(),
        }
    }

    /// Refills the window; returns false at the end of the data.
    fn refill(&mut self) -> Result<bool, TraceError> {
        if self.eof {
            return Ok(false);
        }
        // Drop consumed bytes.
        if self.pos > 0 {
            self.buf.drain(..self.pos);
            self.base += self.pos as u64;
            self.pos = 0;
        }
        let offset = self.offset();
        match &mut self.container {
            Container::Snappy {
                inner,
                file_pos,
                compressed,
                done,
            } => loop {
                if *done {
                    self.eof = true;
                    return Ok(false);
                }
                let mut len = [0u8; 4];
                let n = read_full(inner, &mut len).map_err(|e| TraceError {
                    offset,
                    file_offset: *file_pos,
                    message: format!("cannot read: {e}"),
                })?;
                if n < 4 {
                    *done = true;
                    continue;
                }
                let clen = u32::from_le_bytes(len) as u64;
                let chunk_start = *file_pos;
                *file_pos += 4;
                if clen == 0 {
                    *done = true;
                    continue;
                }
                if clen > MAX_CHUNK {
                    return Err(TraceError {
                        offset,
                        file_offset: chunk_start,
                        message: format!("snappy chunk length {clen} is implausibly large"),
                    });
                }
                compressed.clear();
                // `take` + `read_to_end` grows the buffer only as data really arrives.
                let got = inner
                    .by_ref()
                    .take(clen)
                    .read_to_end(compressed)
                    .map_err(|e| TraceError {
                        offset,
                        file_offset: chunk_start,
                        message: format!("cannot read: {e}"),
                    })? as u64;
                *file_pos += got;
                if got < clen {
                    *done = true;
                    return Err(TraceError {
                        offset,
                        file_offset: chunk_start,
                        message: format!(
                            "truncated file: snappy chunk of {clen} bytes has only {got}"
                        ),
                    });
                }
                let ulen = snap::raw::decompress_len(compressed).map_err(|e| TraceError {
                    offset,
                    file_offset: chunk_start,
                    message: format!("bad snappy chunk: {e}"),
                })?;
                // A snappy element of k input bytes yields at most ~22 k output bytes.
                if ulen as u64 > clen * 32 + 64 {
                    return Err(TraceError {
                        offset,
                        file_offset: chunk_start,
                        message: format!(
                            "snappy chunk claims {ulen} bytes from {clen} compressed bytes"
                        ),
                    });
                }
                let start = self.buf.len();
                self.buf.resize(start + ulen, 0);
                let res = snap::raw::Decoder::new().decompress(compressed, &mut self.buf[start..]);
                self.chunk_file_offset = chunk_start;
                match res {
                    Ok(n) => {
                        self.buf.truncate(start + n);
                        if n == 0 {
                            continue;
                        }
                        return Ok(true);
                    }
                    Err(e) => {
                        self.buf.truncate(start);
                        *done = true;
                        return Err(TraceError {
                            offset,
                            file_offset: chunk_start,
                            message: format!("bad snappy chunk: {e}"),
                        });
                    }
                }
            },
            Container::Gzip(dec, count) => {
                let start = self.buf.len();
                self.buf.resize(start + (1 << 16), 0);
                let res = dec.read(&mut self.buf[start..]);
                self.chunk_file_offset = count.get();
                match res {
                    Ok(0) => {
                        self.buf.truncate(start);
                        self.eof = true;
                        Ok(false)
                    }
                    Ok(n) => {
                        self.buf.truncate(start + n);
                        Ok(true)
                    }
                    Err(e) => {
                        self.buf.truncate(start);
                        self.eof = true;
                        Err(self.error_at(offset, format!("bad gzip data: {e}")))
                    }
                }
            }
        }
    }

    /// True if no byte is left.
    pub fn at_end(&mut self) -> Result<bool, TraceError> {
        if self.pos < self.buf.len() {
            return Ok(false);
        }
        Ok(!self.refill()?)
    }

    fn byte(&mut self) -> Result<u8, TraceError> {
        if self.pos >= self.buf.len() && !self.refill()? {
            return Err(self.error("unexpected end of data (truncated trace)"));
        }
        let b = self.buf[self.pos];
        self.pos += 1;
        Ok(b)
    }

    /// An unsigned LEB128 number (at most 64 bits).
    fn uint(&mut self) -> Result<u64, TraceError> {
        let start = self.offset();
        let mut v: u64 = 0;
        let mut shift = 0u32;
        loop {
            let b = self.byte()?;
            if shift >= 64 || (shift == 63 && (b & 0x7f) > 1) {
                return Err(self.error_at(start, "integer longer than 64 bits"));
            }
            v |= ((b & 0x7f) as u64) << shift;
            if b & 0x80 == 0 {
                return Ok(v);
            }
            shift += 7;
        }
    }

    fn array<const N: usize>(&mut self) -> Result<[u8; N], TraceError> {
        let mut a = [0u8; N];
        for x in &mut a {
            *x = self.byte()?;
        }
        Ok(a)
    }

    /// `n` bytes; the buffer grows only as bytes really arrive.
    fn bytes(&mut self, n: u64) -> Result<Vec<u8>, TraceError> {
        let start = self.offset();
        if n > MAX_BLOB {
            return Err(self.error_at(
                start,
                format!(
                    "a blob or string of {n} bytes is larger than a capture may hold in one \
                     value ({MAX_BLOB} bytes): refused"
                ),
            ));
        }
        let mut out = Vec::with_capacity((n as usize).min(1 << 16));
        let mut left = n;
        while left > 0 {
            if self.pos >= self.buf.len() && !self.refill()? {
                return Err(self.error_at(
                    start,
                    format!("length {n} runs past the end of the data (truncated trace)"),
                ));
            }
            let take = (self.buf.len() - self.pos).min(left.min(usize::MAX as u64) as usize);
            out.extend_from_slice(&self.buf[self.pos..self.pos + take]);
            self.pos += take;
            left -= take as u64;
        }
        Ok(out)
    }

    fn string(&mut self) -> Result<Vec<u8>, TraceError> {
        let n = self.uint()?;
        self.bytes(n)
    }
}

fn read_full<R: Read>(r: &mut R, buf: &mut [u8]) -> io::Result<usize> {
    let mut n = 0;
    while n < buf.len() {
        match r.read(&mut buf[n..]) {
            Ok(0) => break,
            Ok(k) => n += k,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
    }
    Ok(n)
}

// ------------------------------------------------------------------------------------------
// Event layer

/// Deepest nesting of arrays/structs/reprs accepted (deeper input is treated as corrupt rather
/// than risking the stack).
const MAX_DEPTH: u32 = 64;
/// Largest argument index accepted.
const MAX_ARG_INDEX: u64 = 4096;

/// Reads calls from a trace, one at a time.
pub struct TraceReader {
    stream: ByteStream,
    /// Stream format version (6 for apitrace 11).
    pub version: u64,
    /// Semantic version.
    pub semantic_version: u64,
    /// Header properties (`process.name`, ...).
    pub properties: Vec<(String, String)>,
    functions: HashMap<u64, Arc<FunctionSig>>,
    enums: HashMap<u64, Arc<EnumSig>>,
    bitmasks: HashMap<u64, Arc<BitmaskSig>>,
    structs: HashMap<u64, Arc<StructSig>>,
    frames: HashMap<u64, ()>,
    /// Calls entered but not left yet, in ENTER order.
    pending: Vec<Call>,
    next_call_no: u64,
    /// Incomplete calls being handed out at the end of the file.
    draining: bool,
    failed: bool,
}

impl TraceReader {
    /// Opens a trace file.
    pub fn open(path: &Path) -> Result<TraceReader, TraceError> {
        let file = std::fs::File::open(path).map_err(|e| TraceError {
            offset: 0,
            file_offset: 0,
            message: format!("cannot open {}: {e}", path.display()),
        })?;
        TraceReader::new(Box::new(io::BufReader::with_capacity(1 << 16, file)))
    }

    /// Reads a trace from any reader (positioned at the file's first byte).
    pub fn new(inner: Box<dyn Read>) -> Result<TraceReader, TraceError> {
        let mut stream = ByteStream::new(inner)?;
        let version = stream.uint()?;
        if version > 6 {
            return Err(stream.error_at(0, format!("unsupported trace version {version}")));
        }
        let mut semantic_version = version;
        let mut properties = Vec::new();
        if version >= 6 {
            semantic_version = stream.uint()?;
            loop {
                let name = stream.string()?;
                if name.is_empty() {
                    break;
                }
                let value = stream.string()?;
                properties.push((lossy(name), lossy(value)));
            }
        }
        Ok(TraceReader {
            stream,
            version,
            semantic_version,
            properties,
            functions: HashMap::new(),
            enums: HashMap::new(),
            bitmasks: HashMap::new(),
            structs: HashMap::new(),
            frames: HashMap::new(),
            pending: Vec::new(),
            next_call_no: 0,
            draining: false,
            failed: false,
        })
    }

    /// Offset in the decompressed stream of the next unread byte.
    pub fn offset(&self) -> u64 {
        self.stream.offset()
    }

    /// The next call (in LEAVE order, then the incomplete ones), `Ok(None)` at the end.
    /// After an error the reader stays at the end.
    pub fn next_call(&mut self) -> Result<Option<Call>, TraceError> {
        if self.failed {
            return Ok(None);
        }
        match self.next_inner() {
            Ok(c) => Ok(c),
            Err(e) => {
                self.failed = true;
                Err(e)
            }
        }
    }

    fn next_inner(&mut self) -> Result<Option<Call>, TraceError> {
        loop {
            if self.draining {
                if self.pending.is_empty() {
                    return Ok(None);
                }
                let mut c = self.pending.remove(0);
                c.incomplete = true;
                return Ok(Some(c));
            }
            if self.stream.at_end()? {
                self.draining = true;
                continue;
            }
            let start = self.stream.offset();
            match self.stream.byte()? {
                0x00 => {
                    let thread = if self.version >= 4 {
                        self.stream.uint()?
                    } else {
                        0
                    };
                    let sig = self.function_sig()?;
                    let mut call = Call {
                        no: self.next_call_no,
                        thread,
                        args: Vec::new(),
                        ret: None,
                        flags: 0,
                        incomplete: false,
                        sig,
                    };
                    self.next_call_no += 1;
                    self.details(&mut call, start)?;
                    self.pending.push(call);
                }
                0x01 => {
                    let no = self.stream.uint()?;
                    match self.pending.iter().rposition(|c| c.no == no) {
                        Some(i) => {
                            let mut call = self.pending.remove(i);
                            self.details(&mut call, start)?;
                            return Ok(Some(call));
                        }
                        None => {
                            // A LEAVE for a call that is not waiting: parse it to skip it.
                            let mut dummy = Call {
                                no,
                                thread: 0,
                                sig: Arc::new(FunctionSig {
                                    name: String::new(),
                                    arg_names: Vec::new(),
                                }),
                                args: Vec::new(),
                                ret: None,
                                flags: 0,
                                incomplete: false,
                            };
                            self.details(&mut dummy, start)?;
                        }
                    }
                }
                b => {
                    return Err(self
                        .stream
                        .error_at(start, format!("unknown event type 0x{b:02x}")))
                }
            }
        }
    }

    fn function_sig(&mut self) -> Result<Arc<FunctionSig>, TraceError> {
        let id = self.stream.uint()?;
        if let Some(s) = self.functions.get(&id) {
            return Ok(s.clone());
        }
        let name = lossy(self.stream.string()?);
        let n = self.stream.uint()?;
        let mut arg_names = Vec::new();
        for _ in 0..n {
            arg_names.push(lossy(self.stream.string()?));
        }
        let sig = Arc::new(FunctionSig { name, arg_names });
        self.functions.insert(id, sig.clone());
        Ok(sig)
    }

    fn details(&mut self, call: &mut Call, event_start: u64) -> Result<(), TraceError> {
        loop {
            let at = self.stream.offset();
            match self.stream.byte()? {
                0x00 => return Ok(()),
                0x01 => {
                    let index = self.stream.uint()?;
                    if index >= MAX_ARG_INDEX {
                        return Err(self
                            .stream
                            .error_at(at, format!("argument index {index} is too large")));
                    }
                    let v = self.value(0)?;
                    let index = index as usize;
                    let want = call.sig.arg_names.len().max(index + 1);
                    if call.args.len() < want {
                        call.args.resize(want, None);
                    }
                    call.args[index] = Some(v);
                }
                0x02 => call.ret = Some(self.value(0)?),
                0x03 => call.thread = self.stream.uint()?,
                0x04 => {
                    let n = self.stream.uint()?;
                    for _ in 0..n {
                        self.backtrace_frame()?;
                    }
                }
                0x05 => call.flags = self.stream.uint()?,
                b => {
                    return Err(self.stream.error_at(
                        at,
                        format!("unknown call detail 0x{b:02x} (event at offset {event_start})"),
                    ))
                }
            }
        }
    }

    fn backtrace_frame(&mut self) -> Result<(), TraceError> {
        let id = self.stream.uint()?;
        if self.frames.contains_key(&id) {
            return Ok(());
        }
        loop {
            let at = self.stream.offset();
            match self.stream.byte()? {
                0x00 => break,
                0x01..=0x03 => {
                    self.stream.string()?;
                }
                0x04 | 0x05 => {
                    self.stream.uint()?;
                }
                b => {
                    return Err(self
                        .stream
                        .error_at(at, format!("unknown backtrace frame detail 0x{b:02x}")))
                }
            }
        }
        self.frames.insert(id, ());
        Ok(())
    }

    fn tagged_sint(&mut self) -> Result<i64, TraceError> {
        let at = self.stream.offset();
        match self.stream.byte()? {
            0x03 => Ok((self.stream.uint()? as i64).wrapping_neg()),
            0x04 => Ok(self.stream.uint()? as i64),
            b => Err(self.stream.error_at(
                at,
                format!("expected a signed integer tag, found 0x{b:02x}"),
            )),
        }
    }

    fn value(&mut self, depth: u32) -> Result<Value, TraceError> {
        let at = self.stream.offset();
        if depth > MAX_DEPTH {
            return Err(self.stream.error_at(at, "values nested too deeply"));
        }
        let tag = self.stream.byte()?;
        Ok(match tag {
            0x00 => Value::Null,
            0x01 => Value::Bool(false),
            0x02 => Value::Bool(true),
            0x03 => Value::SInt((self.stream.uint()? as i64).wrapping_neg()),
            0x04 => Value::UInt(self.stream.uint()?),
            0x05 => Value::Float(f32::from_le_bytes(self.stream.array::<4>()?)),
            0x06 => Value::Double(f64::from_le_bytes(self.stream.array::<8>()?)),
            0x07 => Value::String(self.stream.string()?),
            0x08 => {
                let n = self.stream.uint()?;
                Value::Blob(self.stream.bytes(n)?.into())
            }
            0x09 => {
                let id = self.stream.uint()?;
                let sig = match self.enums.get(&id) {
                    Some(s) => s.clone(),
                    None => {
                        let mut sig = EnumSig::default();
                        if self.version >= 3 {
                            let n = self.stream.uint()?;
                            for _ in 0..n {
                                let name = lossy(self.stream.string()?);
                                let v = self.tagged_sint()?;
                                sig.values.push((name, v));
                            }
                        } else {
                            // Old form: one name and a full value; the value is the value.
                            let name = lossy(self.stream.string()?);
                            let v = self.value(depth + 1)?.as_i64().unwrap_or(0);
                            sig.values.push((name, v));
                            let sig = Arc::new(sig);
                            self.enums.insert(id, sig.clone());
                            return Ok(Value::Enum(sig, v));
                        }
                        let sig = Arc::new(sig);
                        self.enums.insert(id, sig.clone());
                        sig
                    }
                };
                if self.version < 3 {
                    let v = sig.values.first().map_or(0, |p| p.1);
                    return Ok(Value::Enum(sig, v));
                }
                let v = self.tagged_sint()?;
                Value::Enum(sig, v)
            }
            0x0a => {
                let id = self.stream.uint()?;
                let sig = match self.bitmasks.get(&id) {
                    Some(s) => s.clone(),
                    None => {
                        let mut sig = BitmaskSig::default();
                        let n = self.stream.uint()?;
                        for _ in 0..n {
                            let name = lossy(self.stream.string()?);
                            let v = self.stream.uint()?;
                            sig.flags.push((name, v));
                        }
                        let sig = Arc::new(sig);
                        self.bitmasks.insert(id, sig.clone());
                        sig
                    }
                };
                Value::Bitmask(sig, self.stream.uint()?)
            }
            0x0b => {
                let at = self.stream.offset();
                let n = self.stream.uint()?;
                if n > MAX_ARRAY {
                    return Err(self.stream.error_at(
                        at,
                        format!(
                            "an array of {n} elements is larger than a capture may hold in one \
                             value ({MAX_ARRAY}): refused"
                        ),
                    ));
                }
                let mut items = Vec::with_capacity((n as usize).min(1024));
                for _ in 0..n {
                    items.push(self.value(depth + 1)?);
                }
                Value::Array(items)
            }
            0x0c => {
                let id = self.stream.uint()?;
                let sig = match self.structs.get(&id) {
                    Some(s) => s.clone(),
                    None => {
                        let name = lossy(self.stream.string()?);
                        let n = self.stream.uint()?;
                        let mut members = Vec::new();
                        for _ in 0..n {
                            members.push(lossy(self.stream.string()?));
                        }
                        let sig = Arc::new(StructSig { name, members });
                        self.structs.insert(id, sig.clone());
                        sig
                    }
                };
                let mut members = Vec::with_capacity(sig.members.len().min(1024));
                for _ in 0..sig.members.len() {
                    members.push(self.value(depth + 1)?);
                }
                Value::Struct(sig, members)
            }
            0x0d => Value::Opaque(self.stream.uint()?),
            0x0e => {
                let human = self.value(depth + 1)?;
                let machine = self.value(depth + 1)?;
                Value::Repr(Box::new(human), Box::new(machine))
            }
            0x0f => {
                let n = self.stream.uint()?;
                let mut s = Vec::with_capacity((n as usize).min(1024));
                for _ in 0..n {
                    s.push(self.stream.uint()? as u32);
                }
                Value::WString(s)
            }
            b => {
                return Err(self
                    .stream
                    .error_at(at, format!("unknown value type 0x{b:02x}")))
            }
        })
    }
}

impl Iterator for TraceReader {
    type Item = Result<Call, TraceError>;

    fn next(&mut self) -> Option<Self::Item> {
        self.next_call().transpose()
    }
}

fn lossy(b: Vec<u8>) -> String {
    match String::from_utf8(b) {
        Ok(s) => s,
        Err(e) => String::from_utf8_lossy(e.as_bytes()).into_owned(),
    }
}
