/*
 * ARB_sampler_objects from a plain OSMesa program (<GL/gl.h>, <GL/glext.h>,
 * <GL/osmesa.h>), built unchanged against Mesa's libOSMesa or against tilegl, in the manner
 * of piglit's tex-miplevel-selection:
 *
 *     cc osmesa_samplers.c -Ltarget/release -ltilegl -o osmesa_samplers
 *
 * On a 64 x 64 RGBA buffer:
 *   - a 16 x 16 GL_RGBA8 texture with 5 levels from glTexStorage2D has each level cleared
 *     through a framebuffer object to its own colour (red, green, blue, yellow, cyan);
 *   - the texture's own filter is GL_NEAREST; a sampler object bound to unit 0 with
 *     GL_NEAREST_MIPMAP_NEAREST and GL_TEXTURE_MIN_LOD = GL_TEXTURE_MAX_LOD = k makes a 4 x 4
 *     quad (texture coordinates 0..1, so λ = 2 before clamping) show level k, for k = 0..4;
 *     GL_TEXTURE_LOD_BIAS -2 with the LODs unclamped shows level 0, and the texture's
 *     GL_TEXTURE_BASE_LEVEL 3 (image state, the texture's) level 3 with the bias 0;
 *   - the texture's own GL_TEXTURE_MIN_FILTER still reads GL_NEAREST; with the sampler
 *     unbound (and again after binding it and deleting it) the quad shows level 0;
 *   - GL_SAMPLER_BINDING, glIsSampler, the errors of glBindSampler and glSamplerParameteri,
 *     and glGetString(GL_SHADING_LANGUAGE_VERSION) parsing as "major.minor";
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
#define TS 16
#define LEVELS 5

static int failures = 0;

static void expect_int(const char *what, long got, long want) {
    int ok = got == want;
    printf("%-60s got 0x%lx want 0x%lx %s\n", what, got, want, ok ? "ok" : "MISMATCH");
    if (!ok)
        failures++;
}

static const GLubyte COLOURS[LEVELS][4] = {
    {255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 0, 255}, {0, 255, 255, 255},
};

static void pixel_space(int w, int h) {
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* A 4 x 4 quad at the window's origin with texture coordinates 0..1 (16 texels over 4
 * pixels: λ = 2), then its centre pixel compared with level `level`'s colour. */
static void expect_level(const char *what, int level) {
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2f(0, 0);
    glTexCoord2f(1, 0);
    glVertex2f(4, 0);
    glTexCoord2f(1, 1);
    glVertex2f(4, 4);
    glTexCoord2f(0, 1);
    glVertex2f(0, 4);
    glEnd();
    GLubyte p[4];
    glReadPixels(2, 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    int got = -1;
    for (int l = 0; l < LEVELS; l++)
        if (memcmp(p, COLOURS[l], 4) == 0)
            got = l;
    char label[128];
    snprintf(label, sizeof label, "level sampled: %s", what);
    expect_int(label, got, level);
}

int main(void) {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    GLubyte *buffer = malloc(W * H * 4);
    if (!ctx || !buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, H)) {
        printf("no context\n");
        return 2;
    }
    const char *ext = (const char *)glGetString(GL_EXTENSIONS);
    expect_int("GL_ARB_sampler_objects listed", ext && strstr(ext, "GL_ARB_sampler_objects ") != NULL, 1);
    const char *names[] = {"glGenSamplers", "glBindSampler", "glSamplerParameteri",
                           "glGetSamplerParameterIuiv", "glDeleteSamplers"};
    for (int i = 0; i < 5; i++) {
        char label[96];
        snprintf(label, sizeof label, "OSMesaGetProcAddress(%s) found", names[i]);
        expect_int(label, OSMesaGetProcAddress(names[i]) != NULL, 1);
    }
    const char *glsl = (const char *)glGetString(GL_SHADING_LANGUAGE_VERSION);
    int major = -1, minor = -1;
    expect_int("GL_SHADING_LANGUAGE_VERSION parses as major.minor",
               glsl != NULL && sscanf(glsl, "%d.%d", &major, &minor) == 2, 1);

    GLuint tex, fb;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexStorage2D(GL_TEXTURE_2D, LEVELS, GL_RGBA8, TS, TS);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenFramebuffersEXT(1, &fb);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
    for (int l = 0; l < LEVELS; l++) {
        glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, tex, l);
        glClearColor(COLOURS[l][0] / 255.0f, COLOURS[l][1] / 255.0f, COLOURS[l][2] / 255.0f, 1);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    glDeleteFramebuffersEXT(1, &fb);
    expect_int("glGetError after clearing the levels", glGetError(), GL_NO_ERROR);

    pixel_space(W, H);
    glClearColor(0, 0, 0, 0);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    expect_level("the texture's own GL_NEAREST", 0);

    GLuint s[2];
    glGenSamplers(2, s);
    expect_int("glIsSampler of a generated name", glIsSampler(s[0]), GL_TRUE);
    expect_int("glIsSampler(0)", glIsSampler(0), GL_FALSE);
    glBindSampler(0, s[0]);
    GLint v = -1;
    glGetIntegerv(GL_SAMPLER_BINDING, &v);
    expect_int("GL_SAMPLER_BINDING", v, (long)s[0]);
    glSamplerParameteri(s[0], GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glSamplerParameteri(s[0], GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    expect_level("sampler NEAREST_MIPMAP_NEAREST", 2);
    for (int k = 0; k < LEVELS; k++) {
        char what[64];
        snprintf(what, sizeof what, "sampler MIN_LOD = MAX_LOD = %d", k);
        glSamplerParameterf(s[0], GL_TEXTURE_MIN_LOD, (float)k);
        glSamplerParameterf(s[0], GL_TEXTURE_MAX_LOD, (float)k);
        expect_level(what, k);
    }
    glSamplerParameterf(s[0], GL_TEXTURE_MIN_LOD, -1000);
    glSamplerParameterf(s[0], GL_TEXTURE_MAX_LOD, 1000);
    glSamplerParameterf(s[0], GL_TEXTURE_LOD_BIAS, -2);
    expect_level("sampler LOD bias -2", 0);
    glSamplerParameterf(s[0], GL_TEXTURE_LOD_BIAS, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 3);
    expect_level("texture base level 3", 3);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    v = -1;
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v);
    expect_int("the texture's own GL_TEXTURE_MIN_FILTER", v, GL_NEAREST);
    glBindSampler(0, 0);
    expect_level("sampler unbound", 0);
    glBindSampler(0, s[0]);
    expect_level("sampler bound again", 2);

    glBindSampler(0, s[1] + 100);
    expect_int("glBindSampler of an unused name", glGetError(), GL_INVALID_OPERATION);
    glBindSampler(100000, s[0]);
    expect_int("glBindSampler of unit 100000", glGetError(), GL_INVALID_VALUE);
    glSamplerParameteri(s[1] + 100, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    expect_int("glSamplerParameteri of an unused name", glGetError(), GL_INVALID_OPERATION);
    glSamplerParameteri(s[1], GL_TEXTURE_BASE_LEVEL, 1);
    expect_int("glSamplerParameteri(GL_TEXTURE_BASE_LEVEL)", glGetError(), GL_INVALID_ENUM);
    GLuint u = 0;
    glGetSamplerParameterIuiv(s[0], GL_TEXTURE_MIN_FILTER, &u);
    expect_int("glGetSamplerParameterIuiv(GL_TEXTURE_MIN_FILTER)", u, GL_NEAREST_MIPMAP_NEAREST);

    glDeleteSamplers(2, s);
    v = -1;
    glGetIntegerv(GL_SAMPLER_BINDING, &v);
    expect_int("GL_SAMPLER_BINDING after deleting the sampler", v, 0);
    expect_level("sampler deleted", 0);
    expect_int("glGetError at the end", glGetError(), GL_NO_ERROR);

    glDeleteTextures(1, &tex);
    free(buffer);
    OSMesaDestroyContext(ctx);
    printf("%d failures\n", failures);
    return failures ? 1 : 0;
}
