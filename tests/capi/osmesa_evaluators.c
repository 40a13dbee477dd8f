/*
 * Evaluators through the C ABI: a plain OSMesa program (only <GL/gl.h> and <GL/osmesa.h>), so
 * it builds unchanged against Mesa's libOSMesa or against tilegl. It checks that the arrays of
 * glMap1/glMap2 (read with their strides and orders) and glGetMap (written with the map's
 * size) cross the ABI whole, and draws with glEvalMesh2 and glEvalMesh1.
 *
 * On a 32 x 32 RGBA buffer cleared to black, with identity matrices:
 *   - a bilinear MAP2_VERTEX_3 patch over the left half (x in [-1, 0]), flat MAP2_COLOR_4 red
 *     (order 1), drawn with glEvalMesh2(GL_FILL) on a 4 x 4 grid: the left half is red;
 *   - a line MAP1_VERTEX_4 (w = 2, points padded to stride 6) from (0.2, 0.51875) to (0.8, 0.51875) in
 *     green with glEvalMesh1(GL_LINE): row 24 of the right half is green, row 8 black.
 * Exit status 0 means every check passed.
 */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

#define W 32
#define H 32

static int failures = 0;

static void expect_pixel(const GLubyte *buf, const char *what, int x, int y, GLubyte r, GLubyte g,
                         GLubyte b) {
    const GLubyte *p = buf + 4 * (y * W + x);
    int ok = p[0] == r && p[1] == g && p[2] == b && p[3] == 255;
    printf("%-30s (%2d,%2d): got %3d %3d %3d %3d, want %3d %3d %3d 255  %s\n", what, x, y, p[0],
           p[1], p[2], p[3], r, g, b, ok ? "ok" : "MISMATCH");
    if (!ok)
        failures++;
}

static void expect_error(const char *after, GLenum want) {
    GLenum e = glGetError();
    if (e != want) {
        printf("glGetError() = 0x%04x after %s, want 0x%04x\n", e, after, want);
        failures++;
    }
}

int main(void) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    GLubyte *buffer = calloc(W * H, 4);
    if (!ctx || !buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) {
        printf("could not create and bind the OSMesa context\n");
        return 2;
    }
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);

    /* 2 x 2 control points, u along x, v along y; ustride 8 (padding), vstride 3. */
    const GLfloat patch[] = {-1, -1, 0, 99, 99, -1, 1, 0, /* i = 0 */
                             0,  -1, 0, 99, 99, 0,  1, 0}; /* i = 1 */
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 8, 2, 0, 1, 5, 2, patch);
    expect_error("glMap2f", GL_NO_ERROR);
    GLfloat coeff[12];
    for (int i = 0; i < 12; i++)
        coeff[i] = -7;
    glGetMapfv(GL_MAP2_VERTEX_3, GL_COEFF, coeff);
    const GLfloat want_coeff[] = {-1, -1, 0, -1, 1, 0, 0, -1, 0, 0, 1, 0};
    for (int i = 0; i < 12; i++)
        if (coeff[i] != want_coeff[i]) {
            printf("glGetMapfv COEFF[%d] = %g, want %g\n", i, coeff[i], want_coeff[i]);
            failures++;
        }
    GLint order[2] = {-1, -1};
    glGetMapiv(GL_MAP2_VERTEX_3, GL_ORDER, order);
    if (order[0] != 2 || order[1] != 2) {
        printf("glGetMapiv ORDER = %d %d, want 2 2\n", order[0], order[1]);
        failures++;
    }
    GLdouble domain[4];
    glGetMapdv(GL_MAP2_VERTEX_3, GL_DOMAIN, domain);
    if (domain[0] != 0 || domain[1] != 1 || domain[2] != 0 || domain[3] != 1) {
        printf("glGetMapdv DOMAIN = %g %g %g %g\n", domain[0], domain[1], domain[2], domain[3]);
        failures++;
    }
    const GLdouble red[] = {1, 0, 0, 1};
    glMap2d(GL_MAP2_COLOR_4, 0, 1, 4, 1, 0, 1, 4, 1, red);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_MAP2_COLOR_4);
    glMapGrid2f(4, 0, 1, 4, 0, 1);
    glEvalMesh2(GL_FILL, 0, 4, 0, 4);
    expect_error("glEvalMesh2", GL_NO_ERROR);

    /* A homogeneous line, stride 6 with padding. */
    const GLfloat line[] = {0.4f, 1.0375f, 0, 2, 99, 99, 1.6f, 1.0375f, 0, 2};
    glMap1f(GL_MAP1_VERTEX_4, 0, 1, 6, 2, line);
    GLfloat lc[8];
    glGetMapfv(GL_MAP1_VERTEX_4, GL_COEFF, lc);
    if (lc[4] != 1.6f || lc[7] != 2) {
        printf("glGetMapfv MAP1 COEFF = %g ... %g, want 1.6 ... 2\n", lc[4], lc[7]);
        failures++;
    }
    glEnable(GL_MAP1_VERTEX_4);
    glColor3ub(0, 255, 0);
    glMapGrid1d(6, 0, 1);
    glEvalMesh1(GL_LINE, 0, 6);
    expect_error("glEvalMesh1", GL_NO_ERROR);

    /* Errors: a stride below the point size, and glMap inside glBegin/glEnd. */
    glMap1f(GL_MAP1_VERTEX_4, 0, 1, 3, 2, line);
    expect_error("glMap1f stride 3", GL_INVALID_VALUE);
    glBegin(GL_POINTS);
    glMap1f(GL_MAP1_VERTEX_4, 0, 1, 6, 2, line);
    glEnd();
    expect_error("glMap1f inside glBegin", GL_INVALID_OPERATION);
    GLint max_order = 0;
    glGetIntegerv(GL_MAX_EVAL_ORDER, &max_order);
    if (max_order < 8) {
        printf("GL_MAX_EVAL_ORDER = %d\n", max_order);
        failures++;
    }
    glFinish();

    expect_pixel(buffer, "patch (red)", 4, 4, 255, 0, 0);
    expect_pixel(buffer, "patch (red)", 12, 28, 255, 0, 0);
    expect_pixel(buffer, "right half below the line", 24, 8, 0, 0, 0);
    expect_pixel(buffer, "line (green)", 20, 24, 0, 255, 0);

    OSMesaDestroyContext(ctx);
    free(buffer);
    if (failures)
        printf("%d check(s) failed\n", failures);
    return failures ? 1 : 0;
}
