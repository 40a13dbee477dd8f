//! Micro-benchmark of the paths that take the share-group locks (texture binds and draw
//! snapshots, display-list calls, buffer-object draws, and the name lookups alone) on one
//! unshared context: `cargo run --release --example object_paths`. docs/performance.md
//! records it before and after the namespaces moved behind locks.
use std::time::Instant;
use tilegl::enums::*;
use tilegl::{ClientPtr, Context, Gl};

fn main() {
    let mut gl = Context::new(64, 64);
    let mut tex = [0u32; 2];
    gl.gen_textures(2, &mut tex);
    let texels = vec![200u8; 4 * 4 * 4];
    for &t in &tex {
        gl.bind_texture(GL_TEXTURE_2D, t);
        gl.tex_image_2d(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as i32,
            4,
            4,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            Some(&texels),
        );
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    }
    gl.enable(GL_TEXTURE_2D);
    let list = gl.gen_lists(1);
    gl.new_list(list, GL_COMPILE);
    gl.begin(GL_TRIANGLES);
    gl.tex_coord_2f(0.0, 0.0);
    gl.vertex_2f(-0.5, -0.5);
    gl.vertex_2f(-0.4, -0.5);
    gl.vertex_2f(-0.5, -0.4);
    gl.end();
    gl.end_list();
    let mut vbo = [0u32; 1];
    gl.gen_buffers(1, &mut vbo);
    gl.bind_buffer(GL_ARRAY_BUFFER, vbo[0]);
    let v: [f32; 6] = [0.1, 0.1, 0.2, 0.1, 0.1, 0.2];
    let bytes: Vec<u8> = v.iter().flat_map(|f| f.to_ne_bytes()).collect();
    gl.buffer_data(
        GL_ARRAY_BUFFER,
        bytes.len() as isize,
        Some(&bytes),
        GL_STATIC_DRAW,
    );
    gl.vertex_pointer(2, GL_FLOAT, 0, ClientPtr(0));
    gl.enable_client_state(GL_VERTEX_ARRAY);
    let n = 200_000;
    let mut times = Vec::new();
    for _ in 0..7 {
        let t0 = Instant::now();
        for i in 0..n {
            gl.bind_texture(GL_TEXTURE_2D, tex[i & 1]);
            gl.call_list(list);
            gl.draw_arrays(GL_TRIANGLES, 0, 3);
        }
        gl.finish();
        times.push(t0.elapsed().as_secs_f64() * 1e9 / n as f64);
    }
    times.sort_by(|a, b| a.partial_cmp(b).unwrap());
    println!(
        "bind + call_list + draw_arrays: median {:.0} ns, min {:.0} ns per iteration",
        times[3], times[0]
    );
    // The namespace lookups alone: glIsTexture, glIsList, glIsBuffer and an empty list.
    let empty = gl.gen_lists(1);
    gl.new_list(empty, GL_COMPILE);
    gl.end_list();
    let n = 2_000_000;
    let mut times = Vec::new();
    let mut hits = 0u32;
    for _ in 0..7 {
        let t0 = Instant::now();
        for i in 0..n {
            hits += gl.is_texture(tex[i & 1]) as u32;
            hits += gl.is_list(list) as u32;
            hits += gl.is_buffer(vbo[0]) as u32;
            gl.call_list(empty);
        }
        times.push(t0.elapsed().as_secs_f64() * 1e9 / n as f64);
    }
    times.sort_by(|a, b| a.partial_cmp(b).unwrap());
    println!("is_texture + is_list + is_buffer + empty call_list: median {:.1} ns, min {:.1} ns ({hits})", times[3], times[0]);
}
