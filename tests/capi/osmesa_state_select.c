/*
 * The attribute stack, an occlusion query, selection and feedback through the C ABI: a plain
 * OSMesa program (only <GL/gl.h> and <GL/osmesa.h>; the GL 1.5 query entry points through
 * OSMesaGetProcAddress), so it builds unchanged against Mesa's libOSMesa or against tilegl.
 *
 * On a 32 x 32 RGBA buffer with glOrtho(0, 32, 0, 32, -1, 1) (object x, y are window x, y and
 * window z = (1 - z) / 2), the expectations follow from the specification alone:
 *   - glPushAttrib/glPopAttrib bring back the line width, blending and the clear colour;
 *   - an occlusion query over a 10 x 6 rectangle counts 60 samples, 0 behind a nearer one;
 *   - selection: a triangle at z = 0.5 under names {1, 2} is one hit record with z range
 *     0.25 (2^32 - 1 times 0.25, rounded), written into the C array by glRenderMode;
 *   - feedback (GL_2D): a point and a pass-through token.
 * Exit status 0 means every check passed.
 */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

#define W 32
#define H 32

static int failures = 0;

static void check(int ok, const char *what) {
    printf("%-52s %s\n", what, ok ? "ok" : "MISMATCH");
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

typedef void (*GenQueries)(GLsizei, GLuint *);
typedef void (*BeginQuery)(GLenum, GLuint);
typedef void (*EndQuery)(GLenum);
typedef void (*GetQueryObjectuiv)(GLuint, GLenum, GLuint *);

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
    GenQueries genQueries = (GenQueries)proc("glGenQueries");
    BeginQuery beginQuery = (BeginQuery)proc("glBeginQuery");
    EndQuery endQuery = (EndQuery)proc("glEndQuery");
    GetQueryObjectuiv getQueryObjectuiv = (GetQueryObjectuiv)proc("glGetQueryObjectuiv");

    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);

    /* Attribute stack. */
    GLint depth = -1;
    glLineWidth(2.0f);
    glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    glPushAttrib(GL_LINE_BIT | GL_COLOR_BUFFER_BIT);
    glGetIntegerv(GL_ATTRIB_STACK_DEPTH, &depth);
    check(depth == 1, "GL_ATTRIB_STACK_DEPTH after a push is 1");
    glLineWidth(5.0f);
    glEnable(GL_BLEND);
    glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
    glPopAttrib();
    GLfloat width = 0, clear[4] = {0};
    glGetFloatv(GL_LINE_WIDTH, &width);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    check(width == 2.0f, "glPopAttrib restores the line width");
    check(!glIsEnabled(GL_BLEND), "glPopAttrib restores the blend enable");
    check(clear[0] == 0.0f && clear[2] == 1.0f, "glPopAttrib restores the clear colour");
    glPopAttrib();
    check(glGetError() == GL_STACK_UNDERFLOW, "a pop of the empty stack underflows");

    /* Occlusion query. */
    glEnable(GL_DEPTH_TEST);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    GLuint q[2], samples[2] = {99, 99};
    genQueries(2, q);
    beginQuery(GL_SAMPLES_PASSED, q[0]);
    glRectf(4.0f, 4.0f, 14.0f, 10.0f);
    endQuery(GL_SAMPLES_PASSED);
    glTranslatef(0.0f, 0.0f, -0.5f);
    beginQuery(GL_SAMPLES_PASSED, q[1]);
    glRectf(4.0f, 4.0f, 14.0f, 10.0f);
    endQuery(GL_SAMPLES_PASSED);
    glLoadIdentity();
    getQueryObjectuiv(q[0], GL_QUERY_RESULT, &samples[0]);
    getQueryObjectuiv(q[1], GL_QUERY_RESULT, &samples[1]);
    printf("samples passed: %u, %u\n", samples[0], samples[1]);
    check(samples[0] == 60, "a 10 x 6 rectangle passes 60 samples");
    check(samples[1] == 0, "behind a nearer rectangle it passes none");
    glDisable(GL_DEPTH_TEST);
    expect_no_error("the occlusion queries");

    /* Selection. */
    GLuint select[16] = {0};
    glSelectBuffer(16, select);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(1);
    glPushName(2);
    glBegin(GL_TRIANGLES);
    glVertex3f(2.0f, 2.0f, 0.5f);
    glVertex3f(12.0f, 2.0f, 0.5f);
    glVertex3f(2.0f, 12.0f, 0.5f);
    glEnd();
    GLint hits = glRenderMode(GL_RENDER);
    printf("hits %d: %u %u %u %u %u\n", hits, select[0], select[1], select[2], select[3],
           select[4]);
    const GLuint z = 1073741824u; /* 0.25 * (2^32 - 1), rounded */
    check(hits == 1, "one hit record");
    check(select[0] == 2 && select[3] == 1 && select[4] == 2, "the record holds names 1, 2");
    check(select[1] + 2 >= z && select[1] <= z + 2 && select[2] + 2 >= z && select[2] <= z + 2,
          "the record's z range is 0.25");
    expect_no_error("selection");

    /* Feedback. */
    GLfloat feedback[16] = {0};
    glFeedbackBuffer(16, GL_2D, feedback);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_POINTS);
    glVertex2f(3.5f, 7.5f);
    glEnd();
    glPassThrough(5.0f);
    GLint values = glRenderMode(GL_RENDER);
    printf("feedback %d: %g %g %g %g %g\n", values, feedback[0], feedback[1], feedback[2],
           feedback[3], feedback[4]);
    check(values == 5, "five feedback values");
    check(feedback[0] == (GLfloat)GL_POINT_TOKEN && feedback[1] == 3.5f && feedback[2] == 7.5f,
          "a point token and its window position");
    check(feedback[3] == (GLfloat)GL_PASS_THROUGH_TOKEN && feedback[4] == 5.0f,
          "a pass-through token and its value");
    expect_no_error("feedback");

    OSMesaDestroyContext(ctx);
    free(buffer);
    return failures == 0 ? 0 : 1;
}
