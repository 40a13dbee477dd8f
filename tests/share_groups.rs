//! Share groups through the Rust API (`Context::share_group`, `join_share_group`): contexts of
//! one group see the same texture objects, display lists and buffer objects, names and
//! contents; a context outside sees none; the defaults of name 0, bindings and the list being
//! compiled stay per context; two threads using one group at once never get the same name and
//! always draw their own objects. (`tests/x11.rs` checks the same through GLX against Mesa.)

mod common;

use common::{pixel, window_ortho};
use tilegl::enums::*;
use tilegl::{Context, Gl};

/// A 1x1 RGB texture of `rgb` bound to `GL_TEXTURE_2D` under a new name.
fn solid_texture(gl: &mut Context, rgb: [u8; 3]) -> u32 {
    let mut t = [0u32];
    gl.gen_textures(1, &mut t);
    gl.bind_texture(GL_TEXTURE_2D, t[0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGB as i32,
        1,
        1,
        0,
        GL_RGB,
        GL_UNSIGNED_BYTE,
        Some(&rgb),
    );
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    t[0]
}

/// Draws a textured square over the whole window with `tex` (REPLACE) and returns the centre.
fn draw_with(gl: &mut Context, tex: u32) -> [u8; 4] {
    window_ortho(gl);
    let (w, h) = gl.size();
    gl.bind_texture(GL_TEXTURE_2D, tex);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.begin(GL_QUADS);
    for (x, y) in [(0, 0), (w, 0), (w, h), (0, h)] {
        gl.tex_coord_2f(0.5, 0.5);
        gl.vertex_2f(x as f32, y as f32);
    }
    gl.end();
    gl.disable(GL_TEXTURE_2D);
    pixel(gl, w / 2, h / 2)
}

#[test]
fn a_group_shares_textures_lists_and_buffers() {
    let mut a = Context::new(8, 8);
    let mut b = Context::new(8, 8);
    let mut c = Context::new(8, 8);
    b.join_share_group(&a.share_group());
    let tex = solid_texture(&mut a, [10, 200, 30]);
    let list = a.gen_lists(1);
    a.new_list(list, GL_COMPILE);
    a.clear_color(0.0, 0.0, 1.0, 1.0);
    a.end_list();
    let mut vbo = [0u32];
    a.gen_buffers(1, &mut vbo);
    a.bind_buffer(GL_ARRAY_BUFFER, vbo[0]);
    a.buffer_data(GL_ARRAY_BUFFER, 4, Some(&[1, 2, 3, 4]), GL_STATIC_DRAW);

    // b sees all three, with their contents.
    assert!(b.is_texture(tex) != 0 && b.is_list(list) != 0 && b.is_buffer(vbo[0]) != 0);
    assert_eq!(draw_with(&mut b, tex), [10, 200, 30, 255]);
    b.call_list(list);
    b.clear(GL_COLOR_BUFFER_BIT);
    assert_eq!(pixel(&mut b, 1, 1), [0, 0, 255, 255]);
    b.bind_buffer(GL_ARRAY_BUFFER, vbo[0]);
    let mut got = [0u8; 4];
    b.get_buffer_sub_data(GL_ARRAY_BUFFER, 0, 4, &mut got);
    assert_eq!(got, [1, 2, 3, 4]);
    // The binding is b's own: a's array buffer binding stays as a set it.
    b.bind_buffer(GL_ARRAY_BUFFER, 0);
    let mut bound = [0i32];
    a.get_integerv(GL_ARRAY_BUFFER_BINDING, &mut bound);
    assert_eq!(bound[0], vbo[0] as i32);

    // c, outside the group, sees none of them.
    assert!(c.is_texture(tex) == 0 && c.is_list(list) == 0 && c.is_buffer(vbo[0]) == 0);

    // A change in b is seen by a once a binds the texture again.
    b.bind_texture(GL_TEXTURE_2D, tex);
    b.tex_sub_image_2d(
        GL_TEXTURE_2D,
        0,
        0,
        0,
        1,
        1,
        GL_RGB,
        GL_UNSIGNED_BYTE,
        Some(&[250, 5, 6]),
    );
    assert_eq!(draw_with(&mut a, tex), [250, 5, 6, 255]);

    // Deleting in a deletes for b.
    a.delete_textures(1, &[tex]);
    a.delete_lists(list, 1);
    a.delete_buffers(1, &vbo);
    assert!(b.is_texture(tex) == 0 && b.is_list(list) == 0 && b.is_buffer(vbo[0]) == 0);
    assert_eq!(a.get_error(), GL_NO_ERROR);
    assert_eq!(b.get_error(), GL_NO_ERROR);
}

#[test]
fn default_textures_and_list_compilation_stay_per_context() {
    let mut a = Context::new(4, 4);
    let mut b = Context::new(4, 4);
    b.join_share_group(&a.share_group());
    // Name 0 is each context's own default texture.
    a.bind_texture(GL_TEXTURE_2D, 0);
    a.tex_image_2d(
        GL_TEXTURE_2D,
        0,
        GL_RGB as i32,
        1,
        1,
        0,
        GL_RGB,
        GL_UNSIGNED_BYTE,
        Some(&[9, 9, 9, 0]),
    );
    let mut w = [0i32];
    b.get_tex_level_parameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &mut w);
    assert_eq!(w[0], 0, "b's default texture has no image");
    a.get_tex_level_parameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &mut w);
    assert_eq!(w[0], 1);
    // A list being compiled in a is not compiling in b, and appears for both at glEndList.
    a.new_list(5, GL_COMPILE);
    let mut index = [0i32];
    b.get_integerv(GL_LIST_INDEX, &mut index);
    assert_eq!(index[0], 0);
    a.end_list();
    assert!(b.is_list(5) != 0);
}

#[test]
fn two_threads_share_one_group_without_collisions() {
    let first = Context::new(4, 4);
    let group = first.share_group();
    let handles: Vec<_> = (0..2u8)
        .map(|id| {
            let group = group.clone();
            std::thread::spawn(move || {
                let mut gl = Context::new(4, 4);
                gl.join_share_group(&group);
                let mut names = Vec::new();
                for i in 0..200u8 {
                    let rgb = [i, id * 100 + 20, 255 - i];
                    let tex = solid_texture(&mut gl, rgb);
                    let list = gl.gen_lists(1);
                    gl.new_list(list, GL_COMPILE);
                    gl.bind_texture(GL_TEXTURE_2D, tex);
                    gl.end_list();
                    let mut vbo = [0u32];
                    gl.gen_buffers(1, &mut vbo);
                    gl.bind_buffer(GL_ARRAY_BUFFER, vbo[0]);
                    gl.buffer_data(GL_ARRAY_BUFFER, 3, Some(&rgb), GL_STATIC_DRAW);
                    gl.bind_texture(GL_TEXTURE_2D, 0);
                    gl.call_list(list);
                    let mut bound = [0i32];
                    gl.get_integerv(GL_TEXTURE_BINDING_2D, &mut bound);
                    assert_eq!(bound[0], tex as i32, "the list binds this thread's texture");
                    let drawn = draw_with(&mut gl, tex);
                    assert_eq!(&drawn[..3], &rgb, "thread {id} iteration {i}");
                    let mut back = [0u8; 3];
                    gl.get_buffer_sub_data(GL_ARRAY_BUFFER, 0, 3, &mut back);
                    assert_eq!(back, rgb);
                    names.push((tex, list, vbo[0]));
                    // Half the objects are deleted while the other thread works.
                    if i % 2 == 0 {
                        gl.delete_textures(1, &[tex]);
                        gl.delete_lists(list, 1);
                        gl.delete_buffers(1, &vbo);
                    }
                }
                assert_eq!(gl.get_error(), GL_NO_ERROR);
                names
            })
        })
        .collect();
    let names: Vec<Vec<(u32, u32, u32)>> = handles.into_iter().map(|h| h.join().unwrap()).collect();
    // Objects both threads kept have distinct names of each kind.
    let kept = |v: &Vec<(u32, u32, u32)>| -> Vec<(u32, u32, u32)> {
        v.iter().skip(1).step_by(2).copied().collect()
    };
    let (k0, k1) = (kept(&names[0]), kept(&names[1]));
    for (a, b) in k0.iter().flat_map(|a| k1.iter().map(move |b| (a, b))) {
        assert!(
            a.0 != b.0 && a.1 != b.1 && a.2 != b.2,
            "{a:?} and {b:?} collide"
        );
    }
}
