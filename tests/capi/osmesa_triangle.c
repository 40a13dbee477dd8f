/*
 * A plain OSMesa program: it uses only <GL/gl.h> and <GL/osmesa.h>, so it builds unchanged
 * against Mesa's libOSMesa or against tilegl:
 *
 *     cc osmesa_triangle.c -Ltarget/release -ltilegl -o osmesa_triangle
 *     LD_LIBRARY_PATH=target/release ./osmesa_triangle
 *
 * It renders, with identity matrices on a 64 x 64 RGBA buffer cleared to blue:
 *   - a green triangle at z = -0.5 (window depth 0.25) covering the lower-left half,
 *       (-0.9,-0.9) (0.9,-0.9) (-0.9,0.9), i.e. x > -0.9, y > -0.9, x + y < 0;
 *   - then a red triangle at z = +0.5 (window depth 0.75, farther) covering the lower-right
 *       half, (-0.9,-0.9) (0.9,-0.9) (0.9,0.9), i.e. x < 0.9, y > -0.9, y < x;
 * with GL_DEPTH_TEST and the default GL_LESS. The expected colours follow from the geometry
 * alone: pixel centres deep inside exactly one triangle have its (flat) colour, where both
 * overlap the nearer green one wins although red was drawn last, and pixels outside both keep
 * the clear colour. Window x = (ndc x + 1) * 32, so pixel (x, y) has its centre at
 * ndc ((x + 0.5) / 32 - 1, (y + 0.5) / 32 - 1).
 *
 * The pixels are checked in the caller's buffer (OSMesa's rows are bottom-up: row 0 is
 * window y = 0) and through glReadPixels. Exit status 0 means every check passed.
 */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 64

static int failures = 0;

struct probe {
    const char *what;
    int x, y;
    GLubyte rgba[4];
};

static const GLubyte BLUE[4] = {0, 0, 255, 255};
static const GLubyte GREEN[4] = {0, 255, 0, 255};
static const GLubyte RED[4] = {255, 0, 0, 255};

static void check(const char *source, const struct probe *p, const GLubyte *got) {
    int ok = memcmp(got, p->rgba, 4) == 0;
    printf("%-12s %-44s (%2d,%2d): got %3d %3d %3d %3d, want %3d %3d %3d %3d  %s\n", source,
           p->what, p->x, p->y, got[0], got[1], got[2], got[3], p->rgba[0], p->rgba[1],
           p->rgba[2], p->rgba[3], ok ? "ok" : "MISMATCH");
    if (!ok)
        failures++;
}

int main(void) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!ctx) {
        printf("OSMesaCreateContextExt failed\n");
        return 2;
    }
    GLubyte *buffer = malloc(W * H * 4);
    if (!buffer) {
        printf("out of memory\n");
        return 2;
    }
    memset(buffer, 0x55, W * H * 4);
    if (!OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) {
        printf("OSMesaMakeCurrent failed\n");
        return 2;
    }
    const GLubyte *renderer = glGetString(GL_RENDERER);
    const GLubyte *version = glGetString(GL_VERSION);
    printf("GL_RENDERER %s, GL_VERSION %s\n", renderer ? (const char *)renderer : "(null)",
           version ? (const char *)version : "(null)");
    if (!renderer || !version)
        failures++;

    GLint viewport[4] = {-1, -1, -1, -1};
    glGetIntegerv(GL_VIEWPORT, viewport);
    if (viewport[0] != 0 || viewport[1] != 0 || viewport[2] != W || viewport[3] != H) {
        printf("viewport after OSMesaMakeCurrent is %d %d %d %d, want 0 0 %d %d\n", viewport[0],
               viewport[1], viewport[2], viewport[3], W, H);
        failures++;
    }

    glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    glClearDepth(1.0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* The nearer triangle first ... */
    glBegin(GL_TRIANGLES);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex3f(-0.9f, -0.9f, -0.5f);
    glVertex3f(0.9f, -0.9f, -0.5f);
    glVertex3f(-0.9f, 0.9f, -0.5f);
    glEnd();
    /* ... then the farther one, which the depth test must reject where they overlap. */
    glBegin(GL_TRIANGLES);
    glColor3ub(255, 0, 0);
    glVertex3f(-0.9f, -0.9f, 0.5f);
    glVertex3f(0.9f, -0.9f, 0.5f);
    glVertex3f(0.9f, 0.9f, 0.5f);
    glEnd();
    glFinish();

    GLenum error = glGetError();
    if (error != GL_NO_ERROR) {
        printf("glGetError() = 0x%04x after drawing\n", error);
        failures++;
    }

    const struct probe probes[] = {
        {"overlap: nearer green wins over later red", 32, 8, {0}},
        {"green only", 8, 32, {0}},
        {"red only", 56, 32, {0}},
        {"outside both (top centre)", 32, 60, {0}},
        {"outside both (bottom-left corner)", 0, 0, {0}},
        {"outside both (top-right corner)", 63, 63, {0}},
    };
    const GLubyte *want[] = {GREEN, GREEN, RED, BLUE, BLUE, BLUE};
    struct probe p[sizeof probes / sizeof probes[0]];
    int n = (int)(sizeof probes / sizeof probes[0]);
    for (int i = 0; i < n; i++) {
        p[i] = probes[i];
        memcpy(p[i].rgba, want[i], 4);
    }

    /* 1. Directly in the caller's buffer, bottom-up rows. */
    for (int i = 0; i < n; i++)
        check("buffer", &p[i], buffer + (p[i].y * W + p[i].x) * 4);

    /* 2. Through glReadPixels, one pixel at a time. */
    for (int i = 0; i < n; i++) {
        GLubyte px[4] = {1, 2, 3, 4};
        glReadPixels(p[i].x, p[i].y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        check("glReadPixels", &p[i], px);
    }

    /* 3. The whole framebuffer through glReadPixels equals the caller's buffer. */
    GLubyte *all = malloc(W * H * 4);
    if (!all) {
        printf("out of memory\n");
        return 2;
    }
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, all);
    if (memcmp(all, buffer, W * H * 4) != 0) {
        printf("full glReadPixels differs from the OSMesa buffer\n");
        failures++;
    } else {
        printf("full glReadPixels equals the OSMesa buffer\n");
    }

    /* 4. OSMesaGetColorBuffer describes the caller's buffer. */
    GLint w = 0, h = 0, format = 0;
    void *described = NULL;
    if (!OSMesaGetColorBuffer(ctx, &w, &h, &format, &described) || w != W || h != H ||
        format != OSMESA_RGBA || described != buffer) {
        printf("OSMesaGetColorBuffer: %d x %d, format 0x%x, buffer %p (want %p)\n", w, h, format,
               described, (void *)buffer);
        failures++;
    }

    error = glGetError();
    if (error != GL_NO_ERROR) {
        printf("glGetError() = 0x%04x at the end\n", error);
        failures++;
    }

    OSMesaDestroyContext(ctx);
    free(all);
    free(buffer);
    printf("%d failure(s)\n", failures);
    return failures == 0 ? 0 : 1;
}
