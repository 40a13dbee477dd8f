/*
 * Vertex arrays, buffer objects and display lists through the C ABI: a plain OSMesa program
 * (only <GL/gl.h> and <GL/osmesa.h>; GL 1.5 entry points through OSMesaGetProcAddress), so it
 * builds unchanged against Mesa's libOSMesa or against tilegl.
 *
 * On a 32 x 32 RGBA buffer cleared to black, with identity matrices (pixel (x, y) has its
 * centre at ndc ((x + 0.5) / 16 - 1, (y + 0.5) / 16 - 1)), it fills four quadrants, each by
 * another route, with flat colours, so the expected pixels follow from the geometry alone:
 *   - lower left, red: client-memory arrays (float positions, unsigned-byte colours),
 *     glDrawArrays of two triangles;
 *   - lower right, green: a buffer object written through glMapBuffer, indices from an
 *     element array buffer (unsigned short), glDrawElements;
 *   - upper left, blue: glMultiDrawArrays of two one-triangle draws from client memory;
 *   - upper right, white: a display list (colour + glRectf) called through glCallLists with a
 *     list base, after a glDrawArrays compiled into another list.
 * It also checks glGetPointerv and glGetError. Exit status 0 means every check passed.
 */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 32
#define H 32

static int failures = 0;

static void expect_pixel(const GLubyte *buf, const char *what, int x, int y, GLubyte r, GLubyte g,
                         GLubyte b) {
    const GLubyte *p = buf + 4 * (y * W + x);
    int ok = p[0] == r && p[1] == g && p[2] == b && p[3] == 255;
    printf("%-34s (%2d,%2d): got %3d %3d %3d %3d, want %3d %3d %3d 255  %s\n", what, x, y, p[0],
           p[1], p[2], p[3], r, g, b, ok ? "ok" : "MISMATCH");
    if (!ok)
        failures++;
}

static void expect_no_error(const char *after) {
    GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
        printf("glGetError() = 0x%04x after %s\n", e, after);
        failures++;
    }
}

typedef void (*GenBuffers)(GLsizei, GLuint *);
typedef void (*BindBuffer)(GLenum, GLuint);
typedef void (*BufferData)(GLenum, ptrdiff_t, const void *, GLenum);
typedef void *(*MapBuffer)(GLenum, GLenum);
typedef GLboolean (*UnmapBuffer)(GLenum);
typedef void (*MultiDrawArrays)(GLenum, const GLint *, const GLsizei *, GLsizei);

static void *proc(const char *name) {
    void *p = (void *)OSMesaGetProcAddress(name);
    if (!p) {
        printf("OSMesaGetProcAddress(%s) = NULL\n", name);
        exit(2);
    }
    return p;
}

int main(void) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    GLubyte *buffer = malloc(W * H * 4);
    if (!ctx || !buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) {
        printf("context set-up failed\n");
        return 2;
    }
    GenBuffers genBuffers = (GenBuffers)proc("glGenBuffers");
    BindBuffer bindBuffer = (BindBuffer)proc("glBindBuffer");
    BufferData bufferData = (BufferData)proc("glBufferData");
    MapBuffer mapBuffer = (MapBuffer)proc("glMapBuffer");
    UnmapBuffer unmapBuffer = (UnmapBuffer)proc("glUnmapBuffer");
    MultiDrawArrays multiDrawArrays = (MultiDrawArrays)proc("glMultiDrawArrays");

    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_FLAT);

    /* Lower left: client memory. */
    static const GLfloat ll[] = {-1, -1, 0, -1, 0, 0, -1, -1, 0, 0, -1, 0};
    static const GLubyte red[] = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255,
                                  255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
    glVertexPointer(2, GL_FLOAT, 0, ll);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, red);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    void *ptr = NULL;
    glGetPointerv(GL_VERTEX_ARRAY_POINTER, &ptr);
    if (ptr != (const void *)ll) {
        printf("glGetPointerv(GL_VERTEX_ARRAY_POINTER) = %p, want %p\n", ptr, (const void *)ll);
        failures++;
    }
    expect_no_error("client arrays");

    /* Lower right: buffer objects, the vertex buffer written through glMapBuffer. */
    GLuint bufs[2];
    genBuffers(2, bufs);
    bindBuffer(GL_ARRAY_BUFFER, bufs[0]);
    bufferData(GL_ARRAY_BUFFER, 8 * sizeof(GLfloat), NULL, GL_STATIC_DRAW);
    GLfloat *mapped = mapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
    if (!mapped) {
        printf("glMapBuffer returned NULL\n");
        return 1;
    }
    const GLfloat lr[] = {0, -1, 1, -1, 1, 0, 0, 0};
    memcpy(mapped, lr, sizeof lr);
    if (unmapBuffer(GL_ARRAY_BUFFER) != GL_TRUE) {
        printf("glUnmapBuffer did not return GL_TRUE\n");
        failures++;
    }
    glVertexPointer(2, GL_FLOAT, 0, (const void *)0);
    bindBuffer(GL_ARRAY_BUFFER, 0);
    glDisableClientState(GL_COLOR_ARRAY);
    glColor3ub(0, 255, 0);
    const GLushort idx[] = {7, 7, 0, 1, 2, 0, 2, 3};
    bindBuffer(GL_ELEMENT_ARRAY_BUFFER, bufs[1]);
    bufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, (const void *)(2 * sizeof(GLushort)));
    bindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    expect_no_error("buffer objects");

    /* Upper left: glMultiDrawArrays, client memory again. */
    static const GLfloat ul[] = {-1, 0, 0, 0, 0, 1, 9, 9, -1, 0, 0, 1, -1, 1};
    glVertexPointer(2, GL_FLOAT, 0, ul);
    glColor3ub(0, 0, 255);
    const GLint first[] = {0, 4};
    const GLsizei count[] = {3, 3};
    multiDrawArrays(GL_TRIANGLES, first, count, 2);
    expect_no_error("glMultiDrawArrays");

    /* Upper right: display lists. List base + 1 draws the quadrant; list base holds a
     * glDrawArrays of the lower-left vertices in green, compiled but never called. */
    GLuint base = glGenLists(2);
    glVertexPointer(2, GL_FLOAT, 0, ll);
    glNewList(base, GL_COMPILE);
    glColor3ub(0, 255, 0);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glEndList();
    glNewList(base + 1, GL_COMPILE);
    glColor3ub(255, 255, 255);
    glRectf(0, 0, 1, 1);
    glEndList();
    glListBase(base);
    const GLubyte names[] = {1};
    glCallLists(1, GL_UNSIGNED_BYTE, names);
    GLint v = -1;
    glGetIntegerv(GL_LIST_BASE, &v);
    if (v != (GLint)base) {
        printf("GL_LIST_BASE = %d, want %u\n", v, base);
        failures++;
    }
    if (!glIsList(base) || !glIsList(base + 1)) {
        printf("glIsList false for a defined list\n");
        failures++;
    }
    expect_no_error("display lists");
    glFinish();

    expect_pixel(buffer, "client arrays (red)", 8, 8, 255, 0, 0);
    expect_pixel(buffer, "mapped buffer, element buffer", 24, 8, 0, 255, 0);
    expect_pixel(buffer, "glMultiDrawArrays (blue)", 8, 24, 0, 0, 255);
    expect_pixel(buffer, "display list (white)", 24, 24, 255, 255, 255);

    OSMesaDestroyContext(ctx);
    free(buffer);
    if (failures)
        printf("%d check(s) failed\n", failures);
    return failures ? 1 : 0;
}
