//! The client attribute stack (`glPushClientAttrib`, `glPopClientAttrib`).

use super::*;

impl Context {
    pub(crate) fn push_client_attrib(&mut self, mask: GLbitfield) {
        if self.client.stack.len() >= MAX_CLIENT_ATTRIB_STACK_DEPTH {
            self.record_error(GL_STACK_OVERFLOW);
            return;
        }
        let (pixel, arrays) = convert::client_attrib_mask(mask);
        let entry = ClientAttribEntry {
            pixel_store: pixel.then_some((self.pack, self.unpack, self.client.pixel_buffers)),
            arrays: arrays.then(|| {
                (
                    Box::new(self.client.arrays.clone()),
                    self.client_active_texture,
                )
            }),
        };
        self.client.stack.push(entry);
    }

    pub(crate) fn pop_client_attrib(&mut self) {
        let Some(e) = self.client.stack.pop() else {
            self.record_error(GL_STACK_UNDERFLOW);
            return;
        };
        if let Some((pack, unpack, pixel_buffers)) = e.pixel_store {
            self.pack = pack;
            self.unpack = unpack;
            // A buffer deleted since the push is not bound again.
            let live = self.client.buffers.read();
            self.client.pixel_buffers = pixel_buffers.map(|b| {
                if matches!(live.objects.get(&b), Some(Some(_))) {
                    b
                } else {
                    0
                }
            });
        }
        if let Some((arrays, unit)) = e.arrays {
            self.client.arrays = *arrays;
            self.client_active_texture = unit;
        }
    }
}
