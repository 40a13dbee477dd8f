/*
 * OSMesaCreateContextExt's sharelist: a context created with another as its sharelist sees
 * the other's texture objects and display lists (names and contents); a context created
 * without one sees none of them. Builds unchanged against Mesa's libOSMesa or tilegl.
 *
 * Context A makes a 2x2 texture (red, green / blue, white, NEAREST) and a display list that
 * draws the textured square over the whole 16 x 16 buffer; context B (sharelist A) calls the
 * list, so each quarter of its buffer shows one texel: the colours follow from the texture
 * alone. B then deletes the texture; A no longer has it. Exit status 0 means every check passed.
 */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <string.h>

#define N 16

static int failures = 0;
#define CHECK(cond, ...) do { if (!(cond)) { failures++; printf("FAIL %s:%d: ", __FILE__, __LINE__); printf(__VA_ARGS__); printf("\n"); } } while (0)

static GLubyte buf_a[N * N * 4], buf_b[N * N * 4], buf_c[N * N * 4];

static void pixel_is(const GLubyte *buf, int x, int y, const GLubyte *want, const char *what)
{
    const GLubyte *p = buf + (y * N + x) * 4;
    CHECK(memcmp(p, want, 3) == 0, "%s at (%d,%d): %d %d %d, wanted %d %d %d", what, x, y, p[0],
          p[1], p[2], want[0], want[1], want[2]);
}

int main(void)
{
    OSMesaContext a = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    OSMesaContext b = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, a);
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    CHECK(a && b && c, "contexts %p %p %p", (void *)a, (void *)b, (void *)c);
    if (!a || !b || !c)
        return 1;

    CHECK(OSMesaMakeCurrent(a, buf_a, GL_UNSIGNED_BYTE, N, N), "make a current");
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    static const GLubyte texels[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBindTexture(GL_TEXTURE_2D, tex);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(-1, -1);
    glTexCoord2f(1, 0); glVertex2f(1, -1);
    glTexCoord2f(1, 1); glVertex2f(1, 1);
    glTexCoord2f(0, 1); glVertex2f(-1, 1);
    glEnd();
    glEndList();
    glFinish();

    CHECK(OSMesaMakeCurrent(c, buf_c, GL_UNSIGNED_BYTE, N, N), "make c current");
    CHECK(!glIsTexture(tex) && !glIsList(list), "the unshared context sees texture %d list %d",
          glIsTexture(tex), glIsList(list));

    CHECK(OSMesaMakeCurrent(b, buf_b, GL_UNSIGNED_BYTE, N, N), "make b current");
    CHECK(glIsTexture(tex) && glIsList(list), "the sharing context sees texture %d list %d",
          glIsTexture(tex), glIsList(list));
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glCallList(list);
    glFinish();
    static const GLubyte red[] = {255, 0, 0}, green[] = {0, 255, 0}, blue[] = {0, 0, 255},
                         white[] = {255, 255, 255};
    pixel_is(buf_b, 4, 4, red, "texel (0,0)");
    pixel_is(buf_b, 12, 4, green, "texel (1,0)");
    pixel_is(buf_b, 4, 12, blue, "texel (0,1)");
    pixel_is(buf_b, 12, 12, white, "texel (1,1)");
    CHECK(glGetError() == GL_NO_ERROR, "errors in b");
    glDeleteTextures(1, &tex);
    glDeleteLists(list, 1);

    CHECK(OSMesaMakeCurrent(a, buf_a, GL_UNSIGNED_BYTE, N, N), "make a current again");
    CHECK(!glIsTexture(tex) && !glIsList(list), "a still sees texture %d list %d after b deleted them",
          glIsTexture(tex), glIsList(list));
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(c);
    OSMesaDestroyContext(b);
    OSMesaDestroyContext(a);
    if (failures)
        printf("%d failures\n", failures);
    return failures != 0;
}
