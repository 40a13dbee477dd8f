/*
 * EXT_framebuffer_object from a plain OSMesa program (<GL/gl.h>, <GL/glext.h>,
 * <GL/osmesa.h>), built unchanged against Mesa's libOSMesa or against tilegl:
 *
 *     cc osmesa_fbo.c -Ltarget/release -ltilegl -o osmesa_fbo
 *
 * On a 64 x 64 RGBA buffer:
 *   - a 32 x 16 GL_RGBA8 texture is attached to a framebuffer object with a 24-bit depth
 *     renderbuffer; the object is cleared to red with depth 1, then, in window coordinates
 *     (glOrtho over the object's size), a green quad at depth 0.25 covers x < 16 and a blue
 *     quad at depth 0.75 covers y < 8: where they overlap the nearer green one wins;
 *   - glGetTexImage then gives: green for x < 16, blue for x >= 16 and y < 8, red elsewhere;
 *   - the texture drawn 1:1 into the window (GL_REPLACE, GL_NEAREST) gives the same picture
 *     at the window's lower left, the clear colour (black) beside it;
 *   - a framebuffer object without attachments is incomplete
 *     (GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_EXT) and glClear of it is
 *     GL_INVALID_FRAMEBUFFER_OPERATION_EXT;
 *   - OSMesaGetProcAddress finds the entry points.
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
#define TW 32
#define TH 16

static int failures = 0;

static void expect_int(const char *what, long got, long want) {
    int ok = got == want;
    printf("%-60s got 0x%lx want 0x%lx %s\n", what, got, want, ok ? "ok" : "MISMATCH");
    if (!ok)
        failures++;
}

static const GLubyte RED[4] = {255, 0, 0, 255};
static const GLubyte GREEN[4] = {0, 255, 0, 255};
static const GLubyte BLUE[4] = {0, 0, 255, 255};
static const GLubyte BLACK[4] = {0, 0, 0, 0};

/* The picture rendered into the texture, from the geometry above. */
static const GLubyte *rendered(int x, int y) {
    if (x < 16)
        return GREEN;
    if (y < 8)
        return BLUE;
    return RED;
}

static void check_pixels(const char *what, const GLubyte *px, int stride, int w, int h,
                         const GLubyte *(*want)(int, int)) {
    int bad = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const GLubyte *p = px + (y * stride + x) * 4;
            const GLubyte *e = want(x, y);
            if (memcmp(p, e, 4) != 0) {
                if (bad < 4)
                    printf("  %s (%d,%d): got %d %d %d %d want %d %d %d %d\n", what, x, y, p[0],
                           p[1], p[2], p[3], e[0], e[1], e[2], e[3]);
                bad++;
            }
        }
    printf("%-60s %d of %d pixels differ %s\n", what, bad, w * h, bad ? "MISMATCH" : "ok");
    if (bad)
        failures++;
}

static const GLubyte *window_picture(int x, int y) {
    return (x < TW && y < TH) ? rendered(x, y) : BLACK;
}

static void quad(float x0, float y0, float x1, float y1, float z) {
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex3f(x0, y0, z);
    glTexCoord2f(1, 0);
    glVertex3f(x1, y0, z);
    glTexCoord2f(1, 1);
    glVertex3f(x1, y1, z);
    glTexCoord2f(0, 1);
    glVertex3f(x0, y1, z);
    glEnd();
}

static void pixel_space(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

int main(void) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    GLubyte *buffer = malloc(W * H * 4);
    if (!ctx || !buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) {
        printf("no context\n");
        return 2;
    }
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    expect_int("GL_EXT_framebuffer_object listed", ext && strstr(ext, "GL_EXT_framebuffer_object ") != NULL, 1);
    expect_int("OSMesaGetProcAddress(glBindFramebufferEXT) found",
               OSMesaGetProcAddress("glBindFramebufferEXT") != NULL, 1);
    expect_int("OSMesaGetProcAddress(glGenerateMipmapEXT) found",
               OSMesaGetProcAddress("glGenerateMipmapEXT") != NULL, 1);

    GLuint tex, fb, rb;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glGenRenderbuffersEXT(1, &rb);
    glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, rb);
    glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, TW, TH);
    glGenFramebuffersEXT(1, &fb);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, tex, 0);
    glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT, rb);
    expect_int("status with texture and depth renderbuffer",
               glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT), GL_FRAMEBUFFER_COMPLETE_EXT);
    GLint v = -1;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING_EXT, &v);
    expect_int("GL_FRAMEBUFFER_BINDING_EXT", v, fb);

    pixel_space(TW, TH);
    glClearColor(1, 0, 0, 1);
    glClearDepth(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glColor3f(0, 1, 0);
    quad(0, 0, 16, TH, 0.5f); /* depth 0.25 */
    glColor3f(0, 0, 1);
    quad(0, 0, TW, 8, -0.5f); /* depth 0.75 */
    glDisable(GL_DEPTH_TEST);
    GLubyte *read = malloc(TW * TH * 4);
    glReadPixels(0, 0, TW, TH, GL_RGBA, GL_UNSIGNED_BYTE, read);
    check_pixels("glReadPixels of the framebuffer object", read, TW, TW, TH, rendered);
    expect_int("glGetError after drawing", glGetError(), GL_NO_ERROR);

    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, read);
    check_pixels("glGetTexImage of the rendered texture", read, TW, TW, TH, rendered);

    pixel_space(W, H);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    quad(0, 0, TW, TH, 0);
    glDisable(GL_TEXTURE_2D);
    glFinish();
    check_pixels("the window after drawing the texture", buffer, W, W, H, window_picture);

    GLuint empty;
    glGenFramebuffersEXT(1, &empty);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, empty);
    expect_int("status without attachments", glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT),
               GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_EXT);
    glClear(GL_COLOR_BUFFER_BIT);
    expect_int("glClear of an incomplete framebuffer", glGetError(),
               GL_INVALID_FRAMEBUFFER_OPERATION_EXT);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    glDeleteFramebuffersEXT(1, &empty);
    glDeleteFramebuffersEXT(1, &fb);
    glDeleteRenderbuffersEXT(1, &rb);
    glDeleteTextures(1, &tex);
    expect_int("glIsFramebufferEXT after deleting", glIsFramebufferEXT(fb), GL_FALSE);
    expect_int("glGetError at the end", glGetError(), GL_NO_ERROR);

    free(read);
    free(buffer);
    OSMesaDestroyContext(ctx);
    printf("%d failures\n", failures);
    return failures ? 1 : 0;
}
