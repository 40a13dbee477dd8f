/*
 * ARB_pixel_buffer_object and ARB_map_buffer_range from a plain OSMesa program (<GL/gl.h>,
 * <GL/glext.h>, <GL/osmesa.h>), built unchanged against Mesa's libOSMesa or against tilegl:
 *
 *     cc osmesa_pbo.c -Ltarget/release -ltilegl -o osmesa_pbo
 *
 * On a 64 x 64 RGBA buffer, with pointers passed as offsets while a buffer is bound:
 *   - glTexImage2D unpacks a 4 x 4 RGBA image from offset 16 of a pixel unpack buffer holding
 *     the bytes 0, 1, 2, ...: glGetTexImage into client memory gives bytes 16 .. 79;
 *   - glMapBufferRange maps 64 bytes at 128 for writing with explicit flushes; the program
 *     writes 255 - i there through the pointer, flushes, unmaps, and glTexSubImage2D from
 *     offset 128 replaces the image: glGetTexImage gives 255, 254, ...; the mapping queries
 *     (GL_BUFFER_MAP_OFFSET 128, GL_BUFFER_MAP_LENGTH 64, GL_BUFFER_ACCESS_FLAGS) read back;
 *   - glDrawPixels from offset 16 draws that image at (8, 8): glReadPixels gives it back;
 *   - glReadPixels packs the window's lower-left 8 x 8 into offset 4 of a pixel pack buffer;
 *     mapped read-only, the bytes equal a glReadPixels of the same rectangle into client
 *     memory, and the 4 bytes before stay as they were (0x5a);
 *   - errors: glReadPixels past the end of the pack buffer and glTexSubImage2D from a mapped
 *     unpack buffer give GL_INVALID_OPERATION and change nothing.
 * Exit status 0 means every check passed.
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 64

static int failures = 0;

static void expect_int(const char *what, long got, long want) {
    int ok = got == want;
    printf("%-60s got 0x%lx want 0x%lx %s\n", what, got, want, ok ? "ok" : "MISMATCH");
    if (!ok)
        failures++;
}

static void expect_bytes(const char *what, const GLubyte *got, const GLubyte *want, int n) {
    int bad = 0;
    for (int i = 0; i < n; i++)
        if (got[i] != want[i]) {
            if (bad < 4)
                printf("  %s byte %d: got %d want %d\n", what, i, got[i], want[i]);
            bad++;
        }
    printf("%-60s %d of %d bytes differ %s\n", what, bad, n, bad ? "MISMATCH" : "ok");
    if (bad)
        failures++;
}

typedef void *(*MapBufferRangeFn)(GLenum, GLintptr, GLsizeiptr, GLbitfield);
typedef void (*FlushMappedBufferRangeFn)(GLenum, GLintptr, GLsizeiptr);

int main(void) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    GLubyte *buffer = malloc(W * H * 4);
    if (!ctx || !buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) {
        printf("no context\n");
        return 2;
    }
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    expect_int("GL_ARB_pixel_buffer_object listed",
               ext && strstr(ext, "GL_ARB_pixel_buffer_object ") != NULL, 1);
    expect_int("GL_ARB_map_buffer_range listed",
               ext && strstr(ext, "GL_ARB_map_buffer_range ") != NULL, 1);
    MapBufferRangeFn map_range = (MapBufferRangeFn)OSMesaGetProcAddress("glMapBufferRange");
    FlushMappedBufferRangeFn flush_range =
        (FlushMappedBufferRangeFn)OSMesaGetProcAddress("glFlushMappedBufferRange");
    expect_int("OSMesaGetProcAddress(glMapBufferRange) found", map_range != NULL, 1);
    expect_int("OSMesaGetProcAddress(glFlushMappedBufferRange) found", flush_range != NULL, 1);
    if (!map_range || !flush_range)
        return 1;

    GLubyte bytes[256], want[64], got[64 * 4];
    for (int i = 0; i < 256; i++)
        bytes[i] = (GLubyte)i;

    GLuint bufs[2];
    glGenBuffers(2, bufs);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, bufs[0]);
    glBufferData(GL_PIXEL_UNPACK_BUFFER, 256, bytes, GL_STATIC_DRAW);
    GLint v = -1;
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &v);
    expect_int("GL_PIXEL_UNPACK_BUFFER_BINDING", v, bufs[0]);

    /* glTexImage2D from offset 16. */
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, (void *)16);
    expect_int("glTexImage2D from the buffer: error", glGetError(), GL_NO_ERROR);
    memset(got, 0, sizeof got);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, got);
    expect_bytes("texture from offset 16", got, bytes + 16, 64);

    /* A range mapped for explicit flushes, written through the pointer. */
    GLubyte *p = map_range(GL_PIXEL_UNPACK_BUFFER, 128, 64,
                           GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT);
    expect_int("glMapBufferRange: pointer", p != NULL, 1);
    if (!p)
        return 1;
    glGetBufferParameteriv(GL_PIXEL_UNPACK_BUFFER, GL_BUFFER_MAP_OFFSET, &v);
    expect_int("GL_BUFFER_MAP_OFFSET", v, 128);
    glGetBufferParameteriv(GL_PIXEL_UNPACK_BUFFER, GL_BUFFER_MAP_LENGTH, &v);
    expect_int("GL_BUFFER_MAP_LENGTH", v, 64);
    glGetBufferParameteriv(GL_PIXEL_UNPACK_BUFFER, GL_BUFFER_ACCESS_FLAGS, &v);
    expect_int("GL_BUFFER_ACCESS_FLAGS", v,
               GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT);
    void *q = NULL;
    glGetBufferPointerv(GL_PIXEL_UNPACK_BUFFER, GL_BUFFER_MAP_POINTER, &q);
    expect_int("GL_BUFFER_MAP_POINTER is the range's start", q == (void *)p, 1);
    for (int i = 0; i < 64; i++) {
        p[i] = (GLubyte)(255 - i);
        want[i] = (GLubyte)(255 - i);
    }
    flush_range(GL_PIXEL_UNPACK_BUFFER, 0, 64);
    expect_int("glFlushMappedBufferRange: error", glGetError(), GL_NO_ERROR);
    /* Mapped: unpacking from the buffer is an error and changes nothing. */
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, (void *)128);
    expect_int("glTexSubImage2D from a mapped buffer", glGetError(), GL_INVALID_OPERATION);
    expect_int("glUnmapBuffer", glUnmapBuffer(GL_PIXEL_UNPACK_BUFFER), GL_TRUE);
    glGetBufferParameteriv(GL_PIXEL_UNPACK_BUFFER, GL_BUFFER_MAP_LENGTH, &v);
    expect_int("GL_BUFFER_MAP_LENGTH after glUnmapBuffer", v, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, got);
    expect_bytes("texture kept after the refused sub-image", got, bytes + 16, 64);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, (void *)128);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, got);
    expect_bytes("texture from the written range", got, want, 64);

    /* glDrawPixels from offset 16 at (8, 8). */
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glWindowPos2i(8, 8);
    glDrawPixels(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, (void *)16);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glReadPixels(8, 8, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, got);
    expect_bytes("glDrawPixels from offset 16", got, bytes + 16, 64);

    /* glReadPixels into offset 4 of a pack buffer. */
    GLubyte fill[300], client[8 * 8 * 4];
    memset(fill, 0x5a, sizeof fill);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, bufs[1]);
    glBufferData(GL_PIXEL_PACK_BUFFER, sizeof fill, fill, GL_STREAM_READ);
    glReadPixels(4, 4, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, (void *)4);
    expect_int("glReadPixels into the buffer: error", glGetError(), GL_NO_ERROR);
    glReadPixels(0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, (void *)100);
    expect_int("glReadPixels past the end", glGetError(), GL_INVALID_OPERATION);
    const GLubyte *m = glMapBuffer(GL_PIXEL_PACK_BUFFER, GL_READ_ONLY);
    expect_int("glMapBuffer: pointer", m != NULL, 1);
    if (!m)
        return 1;
    GLubyte packed[300];
    memcpy(packed, m, sizeof packed);
    glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glReadPixels(4, 4, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, client);
    expect_bytes("packed pixels equal client-memory ones", packed + 4, client, sizeof client);
    expect_bytes("bytes before the offset kept", packed, fill, 4);
    expect_bytes("bytes after the image kept", packed + 4 + sizeof client, fill,
                 (int)(sizeof packed - 4 - sizeof client));

    glDeleteBuffers(2, bufs);
    glDeleteTextures(1, &tex);
    OSMesaDestroyContext(ctx);
    free(buffer);
    return failures ? 1 : 0;
}
