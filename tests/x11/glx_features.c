/* Window-system features for tests/x11.rs, run on tilegl's libGL.so.1 and on Mesa's: each
 * mode draws, swaps and writes the window as the X server shows it (XGetImage) to a PPM file,
 * which the test compares between the two; checks print "FAIL ..." lines.
 *
 *   glx_features share OUT.ppm    contexts sharing texture objects, display lists and buffer
 *                                 objects (glXCreateContext's shareList), and one that does not
 *   glx_features threads          two threads, each with its own current context of one share
 *                                 group, creating, using and deleting objects at the same time
 *   glx_features xfont OUT.ppm    text drawn with glXUseXFont's display lists
 *   glx_features resize OUT.ppm   a window resized between frames (glViewport and
 *                                 glXMakeCurrent pick up the new size)
 *   glx_features reopen          three times: open the display, show a frame, close it (the
 *                                 presentation state of a closed display is dropped)
 *   glx_features multisample OUT.ppm
 *                                 a 4x multisample visual (GLX_SAMPLE_BUFFERS/GLX_SAMPLES): edges,
 *                                 sample coverage, alpha-to-coverage/-one, GL_MULTISAMPLE off
 *   glx_features present OUT.ppm W H SWAPS
 *                                 a W x H frame, then SWAPS timed swaps (prints the mean)
 */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <GL/gl.h>
#include <GL/glx.h>

static int failures;
#define CHECK(cond, ...) do { if (!(cond)) { failures++; printf("FAIL %s:%d: ", __FILE__, __LINE__); printf(__VA_ARGS__); printf("\n"); fflush(stdout); } } while (0)

/* glBindBuffer and friends are GL 1.5: through glXGetProcAddress, as programs do. */
typedef void (*GenBuffers)(GLsizei, GLuint *);
typedef void (*BindBuffer)(GLenum, GLuint);
typedef void (*BufferData)(GLenum, ptrdiff_t, const void *, GLenum);
typedef void (*DeleteBuffers)(GLsizei, const GLuint *);
typedef GLboolean (*IsBuffer)(GLuint);
static GenBuffers gen_buffers;
static BindBuffer bind_buffer;
static BufferData buffer_data;
static DeleteBuffers delete_buffers;
static IsBuffer is_buffer;

static Display *dpy;

static void load_buffer_functions(void)
{
    gen_buffers = (GenBuffers)glXGetProcAddress((const GLubyte *)"glGenBuffers");
    bind_buffer = (BindBuffer)glXGetProcAddress((const GLubyte *)"glBindBuffer");
    buffer_data = (BufferData)glXGetProcAddress((const GLubyte *)"glBufferData");
    delete_buffers = (DeleteBuffers)glXGetProcAddress((const GLubyte *)"glDeleteBuffers");
    is_buffer = (IsBuffer)glXGetProcAddress((const GLubyte *)"glIsBuffer");
    if (!gen_buffers || !bind_buffer || !buffer_data || !delete_buffers || !is_buffer) {
        printf("FAIL: no buffer object functions\n");
        exit(1);
    }
}

static XVisualInfo *visual(void)
{
    int attrs[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8,
                   GLX_DEPTH_SIZE, 16, None};
    XVisualInfo *vi = glXChooseVisual(dpy, DefaultScreen(dpy), attrs);
    if (!vi) {
        printf("FAIL: no visual\n");
        exit(1);
    }
    return vi;
}

static Window make_window(XVisualInfo *vi, int w, int h, int x)
{
    XSetWindowAttributes a;
    memset(&a, 0, sizeof a);
    a.colormap = XCreateColormap(dpy, RootWindow(dpy, vi->screen), vi->visual, AllocNone);
    a.background_pixmap = None;
    a.border_pixel = 0;
    Window win = XCreateWindow(dpy, RootWindow(dpy, vi->screen), x, 0, w, h, 0, vi->depth,
                               InputOutput, vi->visual, CWColormap | CWBackPixmap | CWBorderPixel, &a);
    XMapWindow(dpy, win);
    XSync(dpy, False);
    return win;
}

/* The window as the X server shows it, as a binary PPM. */
static void write_window(Window win, const char *path)
{
    XSync(dpy, False);
    XWindowAttributes wa;
    XGetWindowAttributes(dpy, win, &wa);
    XImage *img = XGetImage(dpy, win, 0, 0, wa.width, wa.height, AllPlanes, ZPixmap);
    if (!img) {
        printf("FAIL: XGetImage\n");
        failures++;
        return;
    }
    FILE *f = fopen(path, "wb");
    if (!f) {
        printf("FAIL: cannot write %s\n", path);
        failures++;
        return;
    }
    fprintf(f, "P6\n%d %d\n255\n", wa.width, wa.height);
    for (int y = 0; y < wa.height; y++)
        for (int x = 0; x < wa.width; x++) {
            unsigned long p = XGetPixel(img, x, y);
            unsigned char rgb[3] = {(p >> 16) & 0xff, (p >> 8) & 0xff, p & 0xff};
            fwrite(rgb, 1, 3, f);
        }
    fclose(f);
    XDestroyImage(img);
}

static void ortho(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* ----- share */

static int share(const char *out)
{
    XVisualInfo *vi = visual();
    Window win = make_window(vi, 96, 96, 0);
    GLXContext a = glXCreateContext(dpy, vi, NULL, True);
    GLXContext b = glXCreateContext(dpy, vi, a, True);
    GLXContext c = glXCreateContext(dpy, vi, b, True); /* the same group, through b */
    GLXContext d = glXCreateContext(dpy, vi, NULL, True);
    CHECK(a && b && c && d, "contexts %p %p %p %p", (void *)a, (void *)b, (void *)c, (void *)d);
    if (!(a && b && c && d))
        return 1;

    /* Context a makes a texture, a display list and a buffer object. */
    CHECK(glXMakeCurrent(dpy, win, a), "make a current");
    load_buffer_functions();
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
    glColor3f(1, 1, 0);
    glBegin(GL_TRIANGLES);
    glVertex2f(52, 52);
    glVertex2f(92, 52);
    glVertex2f(72, 92);
    glEnd();
    glEndList();
    GLuint vbo;
    gen_buffers(1, &vbo);
    bind_buffer(GL_ARRAY_BUFFER, vbo);
    static const GLfloat tri[] = {52, 4, 92, 4, 72, 44};
    buffer_data(GL_ARRAY_BUFFER, sizeof tri, tri, GL_STATIC_DRAW);
    bind_buffer(GL_ARRAY_BUFFER, 0);
    glFinish();
    CHECK(glGetError() == GL_NO_ERROR, "errors in a");

    /* d shares nothing: none of the names is an object there. */
    CHECK(glXMakeCurrent(dpy, win, d), "make d current");
    CHECK(!glIsTexture(tex) && !glIsList(list) && !is_buffer(vbo),
          "d sees a's objects: texture %d list %d buffer %d", glIsTexture(tex), glIsList(list),
          is_buffer(vbo));

    /* c (sharing through b) changes one texel of a's texture. */
    CHECK(glXMakeCurrent(dpy, win, c), "make c current");
    CHECK(glIsTexture(tex) && glIsList(list) && is_buffer(vbo),
          "c does not see a's objects: texture %d list %d buffer %d", glIsTexture(tex),
          glIsList(list), is_buffer(vbo));
    glBindTexture(GL_TEXTURE_2D, tex);
    static const GLubyte black[] = {0, 0, 0};
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, black);
    glFinish();

    /* b draws with all three. */
    CHECK(glXMakeCurrent(dpy, win, b), "make b current");
    CHECK(glIsTexture(tex) && glIsList(list) && is_buffer(vbo),
          "b does not see a's objects: texture %d list %d buffer %d", glIsTexture(tex),
          glIsList(list), is_buffer(vbo));
    ortho(96, 96);
    glClearColor(0.25, 0.25, 0.25, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindTexture(GL_TEXTURE_2D, tex);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(4, 4);
    glTexCoord2f(1, 0); glVertex2f(44, 4);
    glTexCoord2f(1, 1); glVertex2f(44, 92);
    glTexCoord2f(0, 1); glVertex2f(4, 92);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glCallList(list);
    bind_buffer(GL_ARRAY_BUFFER, vbo);
    glVertexPointer(2, GL_FLOAT, 0, (const void *)0);
    glEnableClientState(GL_VERTEX_ARRAY);
    glColor3f(1, 0, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisableClientState(GL_VERTEX_ARRAY);
    bind_buffer(GL_ARRAY_BUFFER, 0);
    CHECK(glGetError() == GL_NO_ERROR, "errors in b");
    glXSwapBuffers(dpy, win);
    write_window(win, out);

    /* Deleting in b deletes for the whole group; a context outside it could not share. */
    glDeleteTextures(1, &tex);
    glDeleteLists(list, 1);
    delete_buffers(1, &vbo);
    CHECK(glXMakeCurrent(dpy, win, a), "make a current again");
    CHECK(!glIsTexture(tex) && !glIsList(list) && !is_buffer(vbo),
          "a still sees deleted objects: texture %d list %d buffer %d", glIsTexture(tex),
          glIsList(list), is_buffer(vbo));
    glXMakeCurrent(dpy, None, NULL);
    glXDestroyContext(dpy, c);
    glXDestroyContext(dpy, b);
    glXDestroyContext(dpy, a);
    glXDestroyContext(dpy, d);
    return 0;
}

/* ----- threads */

struct worker { GLXContext ctx; Window win; int id; int bad; GLuint first_names[3]; };

static void *work(void *p)
{
    struct worker *w = p;
    if (!glXMakeCurrent(dpy, w->win, w->ctx)) {
        w->bad++;
        return NULL;
    }
    ortho(32, 32);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int i = 0; i < 150; i++) {
        /* A colour no other iteration of either thread uses. */
        GLubyte col[3] = {(GLubyte)(40 + i), (GLubyte)(w->id * 100 + 20), (GLubyte)(200 - i)};
        GLuint tex, vbo, list;
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        GLubyte texels[4 * 3];
        for (int k = 0; k < 4; k++)
            memcpy(texels + 3 * k, col, 3);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gen_buffers(1, &vbo);
        bind_buffer(GL_ARRAY_BUFFER, vbo);
        GLfloat quad[] = {0, 0, 0, 0, 1, 0, 32, 0, 1, 1, 32, 32, 0, 1, 0, 32};
        buffer_data(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
        list = glGenLists(1);
        glNewList(list, GL_COMPILE);
        glBindTexture(GL_TEXTURE_2D, tex);
        glEnable(GL_TEXTURE_2D);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
        glEndList();
        if (i == 0) {
            w->first_names[0] = tex;
            w->first_names[1] = vbo;
            w->first_names[2] = list;
        }
        glClear(GL_COLOR_BUFFER_BIT);
        glCallList(list);
        glTexCoordPointer(2, GL_FLOAT, 4 * sizeof(GLfloat), (const void *)0);
        glVertexPointer(2, GL_FLOAT, 4 * sizeof(GLfloat), (const void *)(2 * sizeof(GLfloat)));
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glDrawArrays(GL_QUADS, 0, 4);
        glDisableClientState(GL_VERTEX_ARRAY);
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        glDisable(GL_TEXTURE_2D);
        GLubyte got[4] = {0, 0, 0, 0};
        glReadPixels(16, 16, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, got);
        if (memcmp(got, col, 3) != 0 || glGetError() != GL_NO_ERROR) {
            if (w->bad < 5)
                printf("FAIL thread %d iteration %d: drew %d %d %d, wanted %d %d %d\n", w->id, i,
                       got[0], got[1], got[2], col[0], col[1], col[2]);
            w->bad++;
        }
        bind_buffer(GL_ARRAY_BUFFER, 0);
        glDeleteLists(list, 1);
        delete_buffers(1, &vbo);
        glDeleteTextures(1, &tex);
        if (i % 10 == 0)
            glXSwapBuffers(dpy, w->win);
    }
    glXMakeCurrent(dpy, None, NULL);
    return NULL;
}

static int threads(void)
{
    XVisualInfo *vi = visual();
    struct worker w[2];
    memset(w, 0, sizeof w);
    w[0].win = make_window(vi, 32, 32, 0);
    w[1].win = make_window(vi, 32, 32, 40);
    w[0].ctx = glXCreateContext(dpy, vi, NULL, True);
    w[1].ctx = glXCreateContext(dpy, vi, w[0].ctx, True);
    CHECK(w[0].ctx && w[1].ctx, "contexts");
    if (!w[0].ctx || !w[1].ctx)
        return 1;
    glXMakeCurrent(dpy, w[0].win, w[0].ctx);
    load_buffer_functions();
    glXMakeCurrent(dpy, None, NULL);
    pthread_t t[2];
    for (int i = 0; i < 2; i++) {
        w[i].id = i;
        pthread_create(&t[i], NULL, work, &w[i]);
    }
    for (int i = 0; i < 2; i++)
        pthread_join(t[i], NULL);
    for (int i = 0; i < 2; i++)
        CHECK(w[i].bad == 0, "thread %d: %d bad iterations", i, w[i].bad);
    /* Names come from one namespace: the threads' first objects have distinct names. */
    for (int k = 0; k < 3; k++)
        CHECK(w[0].first_names[k] != w[1].first_names[k], "both threads got name %u (kind %d)",
              w[0].first_names[k], k);
    glXDestroyContext(dpy, w[1].ctx);
    glXDestroyContext(dpy, w[0].ctx);
    return 0;
}

/* ----- xfont */

static int xfont(const char *out)
{
    XVisualInfo *vi = visual();
    Window win = make_window(vi, 320, 96, 0);
    GLXContext ctx = glXCreateContext(dpy, vi, NULL, True);
    CHECK(ctx && glXMakeCurrent(dpy, win, ctx), "context");
    /* The text font every server has, and the cursor font: glyphs of many sizes, bearings
     * that reach left of the origin and below the baseline. */
    XFontStruct *text = XLoadQueryFont(dpy, "fixed");
    XFontStruct *cursor = XLoadQueryFont(dpy, "cursor");
    CHECK(text && cursor, "fonts: fixed %p cursor %p", (void *)text, (void *)cursor);
    if (!text || !cursor)
        return 1;
    GLuint text_base = glGenLists(96);
    glXUseXFont(text->fid, 32, 96, text_base);
    GLuint cursor_base = glGenLists(154);
    glXUseXFont(cursor->fid, 0, 154, cursor_base);
    /* Mesa 22 records GL_OUT_OF_MEMORY for the space (a glyph without pixels): printed for
     * the test to check on tilegl, not a check here. */
    printf("glXUseXFont error 0x%x\n", glGetError());
    CHECK(glIsList(text_base + 'A' - 32) && glIsList(cursor_base + 153), "lists missing");
    ortho(320, 96);
    glClearColor(0, 0, 0.2, 1); /* exact in 8 bits: 51 */
    glClear(GL_COLOR_BUFFER_BIT);
    /* Raster positions in window coordinates (glWindowPos): exact, so glyph placement is all
     * that differs between implementations. */
    typedef void (*WindowPos2i)(GLint, GLint);
    WindowPos2i window_pos = (WindowPos2i)glXGetProcAddress((const GLubyte *)"glWindowPos2i");
    CHECK(window_pos != NULL, "no glWindowPos2i");
    if (!window_pos)
        return 1;
    /* The unpack state in effect when the lists run does not change the glyphs. */
    glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
    glColor3f(1, 1, 1);
    window_pos(4, 80);
    /* No spaces: Mesa 22 makes the space's list empty (see above), so it does not advance. */
    const char *s1 = "Hello,tilegl!gjpqy_|{}@";
    glListBase(text_base - 32);
    glCallLists((GLsizei)strlen(s1), GL_UNSIGNED_BYTE, s1);
    glColor3f(1, 1, 0);
    window_pos(3, 58);
    const char *s2 = "~`^AVWMi!#$%&*()[]<>?";
    glCallLists((GLsizei)strlen(s2), GL_UNSIGNED_BYTE, s2);
    GLint pos[4];
    glGetIntegerv(GL_CURRENT_RASTER_POSITION, pos);
    printf("raster position after the text: %d %d\n", pos[0], pos[1]);
    glColor3f(0, 1, 0.6); /* exact in 8 bits: 153 */
    window_pos(12, 24);
    GLubyte shapes[20];
    for (int i = 0; i < 20; i++)
        shapes[i] = (GLubyte)(2 * i + (i % 3 == 0)); /* shapes and some masks */
    glListBase(cursor_base);
    glCallLists(20, GL_UNSIGNED_BYTE, shapes);
    glGetIntegerv(GL_CURRENT_RASTER_POSITION, pos);
    printf("raster position after the cursor glyphs: %d %d\n", pos[0], pos[1]);
    /* The space: its list moves the raster position by the font's width for it. */
    int space_width = text->per_char ? text->per_char[' ' - text->min_char_or_byte2].width
                                     : text->max_bounds.width;
    window_pos(0, 0);
    glCallList(text_base);
    glGetIntegerv(GL_CURRENT_RASTER_POSITION, pos);
    printf("space: moved %d, font width %d\n", pos[0], space_width);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
    CHECK(glGetError() == GL_NO_ERROR, "errors drawing text");
    glXSwapBuffers(dpy, win);
    write_window(win, out);
    XFreeFont(dpy, text);
    XFreeFont(dpy, cursor);
    return 0;
}

/* ----- resize */

static void frame(int w, int h)
{
    glClearColor(0.1, 0.2, 0.3, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(-0.9, -0.9);
    glColor3f(0, 1, 0); glVertex2f(0.9, -0.9);
    glColor3f(0, 0, 1); glVertex2f(0, 0.9);
    glEnd();
    (void)w;
    (void)h;
}

static int resize(const char *out)
{
    XVisualInfo *vi = visual();
    Window win = make_window(vi, 100, 80, 0);
    GLXContext ctx = glXCreateContext(dpy, vi, NULL, True);
    CHECK(ctx && glXMakeCurrent(dpy, win, ctx), "context");
    frame(100, 80);
    glXSwapBuffers(dpy, win);
    /* Larger: the frame after glViewport fills the new size. */
    XResizeWindow(dpy, win, 160, 120);
    XSync(dpy, False);
    glViewport(0, 0, 160, 120);
    frame(160, 120);
    glXSwapBuffers(dpy, win);
    char path[4096];
    snprintf(path, sizeof path, "%s.1.ppm", out);
    write_window(win, path);
    /* Smaller, picked up by glXMakeCurrent (the viewport stays as it was set). */
    XResizeWindow(dpy, win, 120, 60);
    XSync(dpy, False);
    glXMakeCurrent(dpy, None, NULL);
    CHECK(glXMakeCurrent(dpy, win, ctx), "make current again");
    frame(120, 60);
    glXSwapBuffers(dpy, win);
    snprintf(path, sizeof path, "%s.2.ppm", out);
    write_window(win, path);
    return 0;
}

/* ----- multisample */

static void flat_triangle(float r, float g, float b, float x0, float y0, float x1, float y1,
                          float x2, float y2)
{
    glColor3f(r, g, b);
    glBegin(GL_TRIANGLES);
    glVertex2f(x0, y0);
    glVertex2f(x1, y1);
    glVertex2f(x2, y2);
    glEnd();
}

static void rect(float x0, float y0, float x1, float y1)
{
    glBegin(GL_QUADS);
    glVertex2f(x0, y0);
    glVertex2f(x1, y0);
    glVertex2f(x1, y1);
    glVertex2f(x0, y1);
    glEnd();
}

static int multisample(const char *out)
{
    int attrs[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8,
                   GLX_BLUE_SIZE, 8, GLX_DEPTH_SIZE, 16, GLX_SAMPLE_BUFFERS, 1,
                   GLX_SAMPLES, 4, None};
    XVisualInfo *vi = glXChooseVisual(dpy, DefaultScreen(dpy), attrs);
    CHECK(vi != NULL, "no 4x multisample visual");
    if (!vi)
        return 1;
    int buffers = -1, samples = -1;
    glXGetConfig(dpy, vi, GLX_SAMPLE_BUFFERS, &buffers);
    glXGetConfig(dpy, vi, GLX_SAMPLES, &samples);
    CHECK(buffers == 1 && samples == 4, "GLX_SAMPLE_BUFFERS %d GLX_SAMPLES %d", buffers, samples);
    const int w = 128, h = 96;
    Window win = make_window(vi, w, h, 0);
    GLXContext ctx = glXCreateContext(dpy, vi, NULL, True);
    CHECK(ctx && glXMakeCurrent(dpy, win, ctx), "context");
    GLint gl_buffers = -1, gl_samples = -1;
    glGetIntegerv(GL_SAMPLE_BUFFERS, &gl_buffers);
    glGetIntegerv(GL_SAMPLES, &gl_samples);
    CHECK(gl_buffers == 1 && gl_samples == 4, "GL_SAMPLE_BUFFERS %d GL_SAMPLES %d", gl_buffers,
          gl_samples);
    ortho(w, h);
    glClearColor(0.1f, 0.1f, 0.2f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    /* Edges at many slopes and sub-pixel offsets: the sample positions decide each pixel. */
    flat_triangle(1, 0.55f, 0, 2.3f, 1.7f, 60.9f, 9.1f, 14.2f, 46.45f);
    flat_triangle(0, 1, 0.55f, 62.1f, 3.3f, 63.7f, 45.2f, 20.6f, 40.1f);
    flat_triangle(0.35f, 0.6f, 1, 5.5f, 50.25f, 58.75f, 52.6f, 31.2f, 93.9f);
    /* Depth: a nearer triangle crossing a farther one. */
    glEnable(GL_DEPTH_TEST);
    glColor3f(1, 1, 1);
    glBegin(GL_TRIANGLES);
    glVertex3f(66.2f, 2.4f, 0.5f);
    glVertex3f(125.3f, 20.1f, -0.5f);
    glVertex3f(70.1f, 44.7f, 0.5f);
    glColor3f(1, 0, 1);
    glVertex3f(68.9f, 30.2f, -0.9f);
    glVertex3f(124.6f, 4.3f, 0.9f);
    glVertex3f(110.2f, 43.8f, -0.2f);
    glEnd();
    glDisable(GL_DEPTH_TEST);
    /* Sample coverage: 0.5 red, then its inverse green, 0.25 blue. */
    glEnable(GL_SAMPLE_COVERAGE);
    glSampleCoverage(0.5f, GL_FALSE);
    glColor3f(1, 0, 0);
    rect(66, 50, 94, 70);
    glSampleCoverage(0.5f, GL_TRUE);
    glColor3f(0, 1, 0);
    rect(66, 50, 94, 70);
    glSampleCoverage(0.25f, GL_FALSE);
    glColor3f(0, 0, 1);
    rect(96, 50, 126, 70);
    glDisable(GL_SAMPLE_COVERAGE);
    /* Alpha to coverage at four alphas, the last two with alpha to one. */
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    const float alphas[] = {0.1f, 0.4f, 0.6f, 0.9f};
    for (int i = 0; i < 4; i++) {
        if (i == 2)
            glEnable(GL_SAMPLE_ALPHA_TO_ONE);
        glColor4f(1, 1, 0, alphas[i]);
        rect(66 + 15 * i, 72, 79 + 15 * i, 82);
    }
    glDisable(GL_SAMPLE_ALPHA_TO_ONE);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    /* GL_MULTISAMPLE off: pixel-centre coverage, every sample the same. */
    glDisable(GL_MULTISAMPLE);
    flat_triangle(0.8f, 0.8f, 0.2f, 66.4f, 84.3f, 126.1f, 86.7f, 90.3f, 95.2f);
    glEnable(GL_MULTISAMPLE);
    glXSwapBuffers(dpy, win);
    write_window(win, out);
    return 0;
}

/* ----- present */

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

static int present(const char *out, int w, int h, int swaps)
{
    XVisualInfo *vi = visual();
    Window win = make_window(vi, w, h, 0);
    GLXContext ctx = glXCreateContext(dpy, vi, NULL, True);
    CHECK(ctx && glXMakeCurrent(dpy, win, ctx), "context");
    ortho(w, h);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    /* Every channel value in the rows: a gradient over the window and a few triangles. */
    glBegin(GL_QUADS);
    glColor3f(0, 0, 0); glVertex2i(0, 0);
    glColor3f(1, 0, 0.5); glVertex2i(w, 0);
    glColor3f(1, 1, 1); glVertex2i(w, h);
    glColor3f(0, 1, 0.5); glVertex2i(0, h);
    glEnd();
    glBegin(GL_TRIANGLES);
    glColor3f(0.2, 0.4, 1); glVertex2i(w / 8, h / 8); glVertex2i(w / 2, h / 8); glVertex2i(w / 4, h / 2);
    glEnd();
    glXSwapBuffers(dpy, win);
    write_window(win, out);
    /* Swaps of the same frame: the time is presenting it (the back buffer is redrawn by a
     * clear-free copy: nothing else changes). */
    double best = 1e9, total = 0;
    for (int i = 0; i < swaps; i++) {
        double t0 = now();
        glXSwapBuffers(dpy, win);
        XSync(dpy, False);
        double t = now() - t0;
        total += t;
        if (t < best)
            best = t;
    }
    if (swaps > 0)
        printf("swap %dx%d: mean %.3f ms, best %.3f ms over %d swaps\n", w, h, total / swaps * 1e3,
               best * 1e3, swaps);
    return 0;
}

/* ----- reopen */

static int reopen(void)
{
    XCloseDisplay(dpy);
    static const unsigned long colours[3] = {0xff0000, 0x00ff00, 0x0000ff};
    for (int i = 0; i < 3; i++) {
        dpy = XOpenDisplay(NULL);
        CHECK(dpy != NULL, "reopen %d", i);
        if (!dpy)
            return 1;
        XVisualInfo *vi = visual();
        Window win = make_window(vi, 64, 64, 0);
        GLXContext ctx = glXCreateContext(dpy, vi, NULL, True);
        CHECK(ctx && glXMakeCurrent(dpy, win, ctx), "context %d", i);
        glClearColor(i == 0, i == 1, i == 2, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glXSwapBuffers(dpy, win);
        XSync(dpy, False);
        XImage *img = XGetImage(dpy, win, 32, 32, 1, 1, AllPlanes, ZPixmap);
        unsigned long p = img ? XGetPixel(img, 0, 0) & 0xffffff : 0xdeadbeef;
        if (img)
            XDestroyImage(img);
        CHECK(p == colours[i], "frame %d shows %06lx, wanted %06lx", i, p, colours[i]);
        glXMakeCurrent(dpy, None, NULL);
        glXDestroyContext(dpy, ctx);
        XFree(vi);
        if (i < 2)
            XCloseDisplay(dpy);
    }
    return 0;
}

int main(int argc, char **argv)
{
    XInitThreads();
    dpy = XOpenDisplay(NULL);
    if (!dpy || argc < 2) {
        printf("FAIL: no display or no mode\n");
        return 1;
    }
    int r = 1;
    const char *mode = argv[1];
    if (!strcmp(mode, "share") && argc == 3)
        r = share(argv[2]);
    else if (!strcmp(mode, "threads"))
        r = threads();
    else if (!strcmp(mode, "xfont") && argc == 3)
        r = xfont(argv[2]);
    else if (!strcmp(mode, "resize") && argc == 3)
        r = resize(argv[2]);
    else if (!strcmp(mode, "multisample") && argc == 3)
        r = multisample(argv[2]);
    else if (!strcmp(mode, "reopen"))
        r = reopen();
    else if (!strcmp(mode, "present") && argc == 6)
        r = present(argv[2], atoi(argv[3]), atoi(argv[4]), atoi(argv[5]));
    else
        printf("FAIL: bad arguments\n");
    if (r == 0 && failures == 0)
        printf("all checks passed\n");
    else
        printf("%d failures\n", failures);
    XCloseDisplay(dpy);
    return r == 0 && failures == 0 ? 0 : 1;
}
