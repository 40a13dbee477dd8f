//! Writes seed inputs for the fuzz targets into `fuzz/seeds/TARGET/` (`fuzz/run --seed`
//! merges them into the committed corpora): prefixes of the repository's captures, cut after
//! a call (`trace_reader`, `replay`), the same calls as scripts (`call_script`), and call
//! sequences for `c_calls` (a triangle, client arrays, a texture, a display list, selection).

use std::io::Cursor;
use std::path::{Path, PathBuf};

use tilegl::capi::exports::FUZZ_CALLS;
use tilegl::enums::*;
use tilegl::replay::script::write_call;
use tilegl::replay::trace::TraceReader;

/// The captures the seeds come from (small ones, of varied features).
const CAPTURES: &[&str] = &[
    "glxheads",
    "piglit-dlist-color-material",
    "piglit-gl-1.0-edgeflag",
    "piglit-gl-1.1-xor",
    "piglit-gl-1.2-rescale-normal",
    "piglit-polygon-mode",
    "piglit-two-sided-lighting",
    "xss-sierpinski3d",
    "shared/piglit-gl-1.0-rendermode-feedback",
    "shared/piglit-select",
    "shared/piglit-cubemap",
    "shared/piglit-linestipple",
    "shared/piglit-fog-modes",
    "shared/piglit-mipmap-setup",
];

/// Decompressed prefixes of a capture, cut after the first call that ends past each limit.
fn prefixes(stream: &[u8], limits: &[u64]) -> Vec<Vec<u8>> {
    let file = tilegl_fuzz::capture_bytes(stream);
    let mut r = TraceReader::new(Box::new(Cursor::new(file))).expect("a capture");
    let mut out = Vec::new();
    let mut next = 0;
    while next < limits.len() {
        match r.next_call() {
            Ok(Some(_)) if r.offset() >= limits[next] => {
                out.push(stream[..r.offset() as usize].to_vec());
                next += 1;
            }
            Ok(Some(_)) => {}
            _ => {
                out.push(stream.to_vec());
                break;
            }
        }
    }
    out.dedup();
    out
}

/// A call script of the calls in a decompressed stream (blobs inline).
fn script(stream: &[u8]) -> String {
    let mut r =
        TraceReader::new(Box::new(Cursor::new(tilegl_fuzz::capture_bytes(stream)))).unwrap();
    let mut text = String::new();
    while let Ok(Some(call)) = r.next_call() {
        let mut inline = |b: &[u8]| -> Result<String, String> {
            Ok(format!(
                "hex(\"{}\")",
                b.iter().map(|x| format!("{x:02x}")).collect::<String>()
            ))
        };
        write_call(&mut text, &call, &mut inline).unwrap();
    }
    text
}

/// Encodes `c_calls` inputs in the argument distributions of `fuzz/src/c_calls.rs`.
struct Calls(Vec<u8>);

impl Calls {
    fn new(width: u8, height: u8, config: u8) -> Calls {
        Calls(vec![width - 1, height - 1, config, 1, 2, 3, 4])
    }
    fn call(&mut self, name: &str) -> &mut Self {
        let i = FUZZ_CALLS.iter().position(|(n, _)| *n == name).unwrap() as u16;
        self.0.extend(i.to_le_bytes());
        self
    }
    fn e(&mut self, name: &str) -> &mut Self {
        let i = ENUMS_BY_NAME.iter().position(|(n, _)| *n == name).unwrap() as u16;
        self.0.push(0);
        self.0.extend(i.to_le_bytes());
        self
    }
    fn bits(&mut self, v: u32) -> &mut Self {
        self.0.push(0);
        self.0.extend(v.to_le_bytes());
        self
    }
    fn int(&mut self, v: i64) -> &mut Self {
        match v {
            -2..=253 => self.0.extend([0, (v + 2) as u8]),
            _ => {
                self.0.push(230);
                self.0.extend((v as i32).to_le_bytes());
            }
        }
        self
    }
    fn f(&mut self, v: f64) -> &mut Self {
        self.0.push(128);
        self.0.extend((((v * 64.0) as i16) as u16).to_le_bytes());
        self
    }
    /// Memory of floats: a non-null marker, the values, a fill seed.
    fn floats(&mut self, vs: &[f64]) -> &mut Self {
        self.0.push(0);
        for &v in vs {
            self.f(v);
        }
        self.0.push(7);
        self
    }
    /// A retained address (its choice bytes).
    fn at(&mut self, choice: u16) -> &mut Self {
        self.0.extend(choice.to_le_bytes());
        self
    }
}

fn c_calls_seeds() -> Vec<Vec<u8>> {
    let mut seeds = Vec::new();
    // A smooth triangle with depth test.
    let mut c = Calls::new(32, 32, 4);
    c.call("glEnable").e("GL_DEPTH_TEST");
    c.call("glClearColor").f(0.1).f(0.2).f(0.3).f(1.0);
    c.call("glClear")
        .bits(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    c.call("glBegin").e("GL_TRIANGLES");
    for (x, y) in [(-1.0, -1.0), (1.0, -0.5), (0.0, 1.0)] {
        c.call("glColor3f").f(x).f(y).f(0.5);
        c.call("glVertex3f").f(x).f(y).f(0.25);
    }
    c.call("glEnd");
    c.call("glReadPixels")
        .int(0)
        .int(0)
        .int(4)
        .int(4)
        .e("GL_RGBA")
        .e("GL_UNSIGNED_BYTE");
    c.0.extend([0, 7]);
    seeds.push(c.0.clone());
    // Client arrays: glDrawArrays and glDrawElements.
    let mut c = Calls::new(48, 40, 0);
    c.call("glEnableClientState").e("GL_VERTEX_ARRAY");
    c.call("glEnableClientState").e("GL_COLOR_ARRAY");
    c.call("glVertexPointer").int(3).e("GL_FLOAT").int(0).at(8);
    c.call("glColorPointer")
        .int(4)
        .e("GL_UNSIGNED_BYTE")
        .int(0)
        .at(4096);
    c.call("glDrawArrays").e("GL_TRIANGLE_STRIP").int(0).int(12);
    c.call("glDrawElements")
        .e("GL_TRIANGLES")
        .int(30)
        .e("GL_UNSIGNED_SHORT")
        .at(0);
    c.call("glInterleavedArrays")
        .e("GL_C4F_N3F_V3F")
        .int(0)
        .at(64);
    c.call("glDrawArrays").e("GL_LINES").int(0).int(8);
    seeds.push(c.0.clone());
    // A texture, texgen and a textured quad.
    let mut c = Calls::new(64, 64, 16 | 4);
    c.call("glTexImage2D")
        .e("GL_TEXTURE_2D")
        .int(0)
        .e("GL_RGBA")
        .int(8)
        .int(8)
        .int(0);
    c.e("GL_RGBA").e("GL_UNSIGNED_BYTE").0.extend([0, 9]);
    c.call("glTexParameteri")
        .e("GL_TEXTURE_2D")
        .e("GL_TEXTURE_MIN_FILTER")
        .e("GL_NEAREST");
    c.call("glEnable").e("GL_TEXTURE_2D");
    c.call("glEnable").e("GL_TEXTURE_GEN_S");
    c.call("glBegin").e("GL_QUADS");
    for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        c.call("glTexCoord2f").f(x).f(y);
        c.call("glVertex2f").f(x).f(y);
    }
    c.call("glEnd");
    c.call("glCopyTexSubImage2D")
        .e("GL_TEXTURE_2D")
        .int(0)
        .int(0)
        .int(0)
        .int(0)
        .int(0);
    c.int(8).int(8);
    seeds.push(c.0.clone());
    // A display list with lighting, called twice.
    let mut c = Calls::new(16, 24, 1);
    c.call("glNewList").int(1).e("GL_COMPILE");
    c.call("glEnable").e("GL_LIGHTING");
    c.call("glEnable").e("GL_LIGHT0");
    c.call("glLightfv")
        .e("GL_LIGHT0")
        .e("GL_POSITION")
        .floats(&[0.0, 0.0, 1.0, 0.0]);
    c.call("glRectf").f(-0.5).f(-0.5).f(0.5).f(0.5);
    c.call("glEndList");
    c.call("glCallList").int(1);
    c.call("glTranslatef").f(0.25).f(0.0).f(0.0);
    c.call("glCallList").int(1);
    seeds.push(c.0.clone());
    // Selection and feedback.
    let mut c = Calls::new(20, 20, 0);
    c.call("glSelectBuffer").int(64).at(0);
    c.call("glRenderMode").e("GL_SELECT");
    c.call("glInitNames");
    c.call("glPushName").int(7);
    c.call("glRectf").f(-0.5).f(-0.5).f(0.5).f(0.5);
    c.call("glRenderMode").e("GL_RENDER");
    c.call("glFeedbackBuffer").int(64).e("GL_3D_COLOR").at(0);
    c.call("glRenderMode").e("GL_FEEDBACK");
    c.call("glBegin").e("GL_LINES");
    c.call("glVertex2f").f(-1.0).f(0.0);
    c.call("glVertex2f").f(1.0).f(0.5);
    c.call("glEnd");
    c.call("glRenderMode").e("GL_RENDER");
    seeds.push(c.0.clone());
    // Buffer objects as array sources.
    let mut c = Calls::new(32, 16, 2);
    c.call("glGenBuffers").int(1).0.extend([0, 0, 7]);
    c.call("glBindBuffer").e("GL_ARRAY_BUFFER").int(1);
    c.call("glBufferData")
        .e("GL_ARRAY_BUFFER")
        .int(96)
        .0
        .extend([0, 7]);
    c.e("GL_STATIC_DRAW");
    c.call("glEnableClientState").e("GL_VERTEX_ARRAY");
    c.call("glVertexPointer").int(2).e("GL_FLOAT").int(8).at(0);
    c.call("glDrawArrays").e("GL_POINTS").int(0).int(12);
    seeds.push(c.0.clone());
    // Stencil, blending, accumulation and pixel rectangles.
    let mut c = Calls::new(24, 24, 16 | 32 | 8);
    c.call("glEnable").e("GL_STENCIL_TEST");
    c.call("glStencilFunc").e("GL_ALWAYS").int(1).bits(0xff);
    c.call("glStencilOp")
        .e("GL_KEEP")
        .e("GL_KEEP")
        .e("GL_REPLACE");
    c.call("glEnable").e("GL_BLEND");
    c.call("glBlendFunc")
        .e("GL_SRC_ALPHA")
        .e("GL_ONE_MINUS_SRC_ALPHA");
    c.call("glRectf").f(-0.5).f(-0.5).f(0.5).f(0.5);
    c.call("glAccum").e("GL_LOAD").f(0.5);
    c.call("glAccum").e("GL_RETURN").f(2.0);
    c.call("glRasterPos2f").f(-0.5).f(-0.5);
    c.call("glDrawPixels")
        .int(4)
        .int(4)
        .e("GL_RGBA")
        .e("GL_FLOAT")
        .0
        .extend([0, 7]);
    c.call("glCopyPixels")
        .int(0)
        .int(0)
        .int(8)
        .int(8)
        .e("GL_COLOR");
    c.call("glBitmap")
        .int(8)
        .int(8)
        .f(0.0)
        .f(0.0)
        .f(1.0)
        .f(1.0)
        .0
        .extend([0, 7]);
    seeds.push(c.0.clone());
    // Evaluators.
    let mut c = Calls::new(32, 32, 4);
    c.call("glMap1f")
        .e("GL_MAP1_VERTEX_3")
        .f(0.0)
        .f(1.0)
        .int(3)
        .int(4);
    c.floats(&[
        -1.0, -1.0, 0.0, -0.5, 1.0, 0.0, 0.5, -1.0, 0.0, 1.0, 1.0, 0.0,
    ]);
    c.call("glEnable").e("GL_MAP1_VERTEX_3");
    c.call("glMapGrid1f").int(20).f(0.0).f(1.0);
    c.call("glEvalMesh1").e("GL_LINE").int(0).int(20);
    seeds.push(c.0.clone());
    // Plain pseudo-random inputs.
    let mut s = 0x2545_f491_4f6c_dd1d_u64;
    for len in [64, 256, 1024, 4096] {
        let mut v = Vec::with_capacity(len);
        for _ in 0..len {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            v.push(s as u8);
        }
        seeds.push(v);
    }
    seeds
}

/// A hand-written script with every kind of value and statement.
const SCRIPT: &str = "// every kind of statement\n\
window(16, 16);\n\
glClearColor(0.0f, 0.0f, 0.25f, 1.0f);\n\
glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);\n\
glGenTextures(1, {1});\n\
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker(8, 8, 2));\n\
glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, hex(\"ff00ff80\"));\n\
glGenLists(1) = 1;\n\
glLightfv(GL_LIGHT0, GL_POSITION, {0, 0.5, -1e-3, 0x10});\n\
glColor4ub(255, 0, 128, 0xff);\n\
glBegin(GL_TRIANGLES); glVertex2f(-1, -1); glVertex2f(1, -1); glVertex2f(0, 1); glEnd();\n\
20 fake glViewport(0, 0, 16, 16);\n\
glCallLists(2, GL_UNSIGNED_BYTE, \"\\x01\\n\\t\\\\\\\"\");\n\
glVertexPointer(3, GL_FLOAT, 0, ptr(0x1000));\n\
glFogf(GL_FOG_DENSITY, nan); glFogf(GL_FOG_START, -inf);\n\
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, file(\"a.bin\"));\n\
glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, png(\"a.png\"));\n\
glEnable(true); glDisable(NULL);\n\
swap();\n";

fn write(dir: &Path, name: String, data: &[u8]) {
    std::fs::create_dir_all(dir).unwrap();
    std::fs::write(dir.join(name), data).unwrap();
}

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let traces = root.join("../conformance/traces");
    let seeds = root.join("seeds");
    let _ = std::fs::remove_dir_all(&seeds);
    for name in CAPTURES {
        let file = std::fs::read(traces.join(format!("{name}.trace")))
            .unwrap_or_else(|e| panic!("{name}.trace: {e}"));
        let stream = tilegl_fuzz::decompressed_stream(&file).expect("a snappy capture");
        let base = name.trim_start_matches("shared/");
        // Inputs over 48 KiB slow the fuzzer down more than they teach it.
        for (i, p) in prefixes(&stream, &[1 << 10, 4 << 10, 16 << 10])
            .iter()
            .filter(|p| p.len() <= 48 << 10)
            .enumerate()
        {
            write(&seeds.join("trace_reader"), format!("{base}-{i}"), p);
            write(&seeds.join("replay"), format!("{base}-{i}"), p);
            if i < 2 {
                write(
                    &seeds.join("call_script"),
                    format!("{base}-{i}.gl"),
                    script(p).as_bytes(),
                );
            }
        }
        // One whole capture file as it is (the snappy container itself).
        if file.len() < 64 << 10 {
            write(&seeds.join("trace_reader"), format!("{base}-file"), &file);
        }
    }
    write(
        &seeds.join("call_script"),
        "every-kind.gl".into(),
        SCRIPT.as_bytes(),
    );
    for (i, s) in c_calls_seeds().iter().enumerate() {
        write(&seeds.join("c_calls"), format!("seed-{i}"), s);
    }
    println!("seeds written to {}", seeds.display());
}
