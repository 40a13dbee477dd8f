/* What real programs do with pixels, through the C API of OSMesa: mipmapped texture uploads
 * from several formats, types and unpack states, sub-image updates, glGetTexImage round trips
 * under several pack states, glDrawPixels (RGBA, luminance, depth, stencil), glBitmap text,
 * glReadPixels with pack state, pixel maps set and read back, compressed upload and read-back,
 * glCopyTexImage2D. Every result is printed as a named section of bytes ("name count" then
 * hex); tests/capi.rs runs this program on tilegl and on Mesa and compares the sections. */
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 64

static void dump(const char *name, const void *data, size_t n) {
    const unsigned char *b = data;
    printf("%s %zu\n", name, n);
    for (size_t i = 0; i < n; i++) printf("%02x%s", b[i], (i % 32 == 31 || i + 1 == n) ? "\n" : "");
}

static void dump_error(const char *after) {
    GLenum e = glGetError();
    char name[128];
    snprintf(name, sizeof name, "error-after-%s", after);
    dump(name, &e, sizeof e);
}

static unsigned char pattern(int i) { return (unsigned char)((i * 37 + 11) & 0xff); }

int main(void) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!ctx) { fprintf(stderr, "no context\n"); return 1; }
    static unsigned char fb[W * H * 4];
    if (!OSMesaMakeCurrent(ctx, fb, GL_UNSIGNED_BYTE, W, H)) { fprintf(stderr, "no current\n"); return 1; }

    unsigned char src[4096];
    for (int i = 0; i < (int)sizeof src; i++) src[i] = pattern(i);
    unsigned char out[8192];

    /* 1. A mipmapped RGB texture, 8x8 .. 1x1, from bytes with alignment 1. */
    GLuint tex[4];
    glGenTextures(4, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int level = 0, s = 8; s >= 1; level++, s /= 2)
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGB8, s, s, 0, GL_RGB, GL_UNSIGNED_BYTE, src + level * 7);
    dump_error("mip-upload");
    for (int level = 0, s = 8; s >= 1; level++, s /= 2) {
        char name[32];
        memset(out, 0, sizeof out);
        glGetTexImage(GL_TEXTURE_2D, level, GL_RGBA, GL_UNSIGNED_BYTE, out);
        snprintf(name, sizeof name, "mip-level-%d", level);
        dump(name, out, (size_t)s * s * 4);
    }

    /* 2. Packed and float types, row length and skips (alignment 8). */
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 7);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, src);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
    dump("rgba4444-rowlength-skips", out, 4 * 4 * 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB5, 4, 4, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, src);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_BYTE, out);
    dump("rgb565-rowlength-skips", out, 4 * 4 * 3);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, src);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
    dump("bgra8888rev-rowlength-skips", out, 4 * 4 * 4);
    {
        float f[7 * 6 * 2];
        for (int i = 0; i < 7 * 6 * 2; i++) f[i] = (float)((i * 13) % 17) / 16.0f;
        glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE8_ALPHA8, 4, 4, 0, GL_LUMINANCE_ALPHA, GL_FLOAT, f);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, out);
        dump("luminance-alpha-float", out, 4 * 4 * 2);
    }
    dump_error("packed-uploads");

    /* 3. Sub-image updates, then read back under an odd pack state (as shorts). */
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 3, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, src + 100);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 5, 5, 3, 3, GL_LUMINANCE, GL_UNSIGNED_BYTE, src + 300);
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glPixelStorei(GL_PACK_ROW_LENGTH, 10);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
    glPixelStorei(GL_PACK_SKIP_ROWS, 1);
    memset(out, 0xcd, sizeof out);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT, out);
    /* row 10 * 8 bytes = 80 (aligned); start 80 + 8; end 88 + 7 * 80 + 8 * 8 = 712 */
    dump("subimage-readback-ushort-packed", out, 712);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    dump_error("subimage");

    /* 4. A textured quad (nearest, REPLACE), read back with glReadPixels. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(0, 0);
    glTexCoord2f(1, 0); glVertex2f(32, 0);
    glTexCoord2f(1, 1); glVertex2f(32, 32);
    glTexCoord2f(0, 1); glVertex2f(0, 32);
    glEnd();
    glDisable(GL_TEXTURE_2D);

    /* 5. glDrawPixels: RGBA bytes, luminance floats with zoom, depth, stencil. */
    glRasterPos2i(34, 2);
    glDrawPixels(8, 6, GL_RGBA, GL_UNSIGNED_BYTE, src);
    glRasterPos2i(44, 2);
    {
        float lum[6 * 5];
        for (int i = 0; i < 6 * 5; i++) lum[i] = (float)i / 29.0f;
        glPixelZoom(2.0f, 1.5f);
        glDrawPixels(6, 5, GL_LUMINANCE, GL_FLOAT, lum);
        glPixelZoom(1.0f, 1.0f);
    }
    {
        unsigned short depth[8 * 8];
        unsigned char stencil[8 * 8];
        for (int i = 0; i < 64; i++) { depth[i] = (unsigned short)(i * 1000); stencil[i] = (unsigned char)(i * 3); }
        glRasterPos2i(34, 20);
        glDrawPixels(8, 8, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, depth);
        glDrawPixels(8, 8, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
        glReadPixels(34, 20, 8, 8, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, out);
        dump("drawpixels-depth-readback", out, 8 * 8 * 2);
        glReadPixels(34, 20, 8, 8, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, out);
        dump("drawpixels-stencil-readback", out, 8 * 8);
    }
    dump_error("drawpixels");

    /* 6. glBitmap text: three 8x12 glyphs, LSB first on the second. */
    {
        static const GLubyte glyph[12] = {0x00, 0x00, 0xc3, 0xc3, 0xc3, 0xff, 0xff, 0xc3, 0xc3, 0x66, 0x3c, 0x18};
        glColor3f(1.0f, 1.0f, 0.0f);
        glRasterPos2i(2, 40);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glBitmap(8, 12, 0, 0, 10, 0, glyph);
        glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
        glBitmap(8, 12, 0, 0, 10, 0, glyph);
        glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
        glBitmap(8, 12, 0, 0, 10, 0, glyph);
    }
    dump_error("bitmap");

    /* 7. Pixel maps, set and read back. */
    {
        GLfloat rmap[4] = {0.0f, 0.9f, 0.3f, 1.0f};
        GLushort gmap[2] = {65535, 1000};
        GLuint imap[4] = {3, 2, 1, 0};
        GLfloat rf[4];
        GLuint ru[4];
        GLushort rs[4];
        glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, rmap);
        glPixelMapusv(GL_PIXEL_MAP_G_TO_G, 2, gmap);
        glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 4, imap);
        glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, rf);
        dump("pixelmap-r-fv", rf, sizeof rf);
        glGetPixelMapuiv(GL_PIXEL_MAP_I_TO_I, ru);
        dump("pixelmap-i-uiv", ru, sizeof ru);
        glGetPixelMapusv(GL_PIXEL_MAP_G_TO_G, rs);
        dump("pixelmap-g-usv", rs, 2 * sizeof(GLushort));
        GLint size = 0;
        glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, &size);
        dump("pixelmap-r-size", &size, sizeof size);
    }
    dump_error("pixelmaps");

    /* 8. Compressed upload and read-back (DXT1, 8x8: four 8-byte blocks). */
    {
        GLint compressed = 0, size = 0;
        glBindTexture(GL_TEXTURE_2D, tex[2]);
        glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 8, 8, 0, 32, src + 40);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &compressed);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
        dump("compressed-flag", &compressed, sizeof compressed);
        dump("compressed-size", &size, sizeof size);
        glGetCompressedTexImage(GL_TEXTURE_2D, 0, out);
        dump("compressed-readback", out, 32);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
        dump("compressed-decoded", out, 8 * 8 * 4);
    }
    dump_error("compressed");

    /* 9. glCopyTexImage2D from the framebuffer, read back. */
    glBindTexture(GL_TEXTURE_2D, tex[3]);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 30, 0, 16, 16, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_BYTE, out);
    dump("copyteximage", out, 16 * 16 * 3);
    dump_error("copyteximage");

    /* 10. The whole picture, read with an odd pack state. */
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    {
        static unsigned char pic[W * H * 3 + 64];
        glReadPixels(0, 0, W, H, GL_RGB, GL_UNSIGNED_BYTE, pic);
        dump("picture", pic, W * H * 3);
    }
    dump_error("readpixels");

    OSMesaDestroyContext(ctx);
    return 0;
}
