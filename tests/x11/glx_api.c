/* GLX behaviour checks for tests/x11.rs, run on tilegl's libGL.so.1 and on Mesa's (which
 * checks the expectations): configurations, windows, make-current and the current-state
 * queries, swaps shown in the window (read back from the X server), a window resize, two
 * contexts on two windows, a single-buffered window shown at glFlush, a context current on
 * another thread, proc addresses. Exits 0 when every check holds; prints each failure. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <GL/gl.h>
#include <GL/glx.h>

static int failures;
#define CHECK(cond, ...) do { if (!(cond)) { failures++; printf("FAIL %s:%d: ", __FILE__, __LINE__); printf(__VA_ARGS__); printf("\n"); } } while (0)

static int ignore_errors(Display *d, XErrorEvent *e) { (void)d; (void)e; return 0; }

static Display *dpy;

/* The window's pixel (x, y from the top left) as 0xRRGGBB. */
static unsigned long pixel(Window w, int x, int y)
{
    XSync(dpy, False);
    XImage *img = XGetImage(dpy, w, x, y, 1, 1, AllPlanes, ZPixmap);
    if (!img)
        return 0xdeadbeef;
    unsigned long p = XGetPixel(img, 0, 0);
    XDestroyImage(img);
    return p & 0xffffff;
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

static void clear_to(float r, float g, float b)
{
    glClearColor(r, g, b, 1);
    glClear(GL_COLOR_BUFFER_BIT);
}

struct thread_args { GLXContext ctx; Window win; int made_current; };

static void *other_thread(void *p)
{
    struct thread_args *a = p;
    a->made_current = glXMakeCurrent(dpy, a->win, a->ctx);
    if (a->made_current) {
        clear_to(1, 0, 1);
        glXSwapBuffers(dpy, a->win);
        glXMakeCurrent(dpy, None, NULL);
    }
    return NULL;
}

int main(void)
{
    XInitThreads();
    dpy = XOpenDisplay(NULL);
    if (!dpy) {
        printf("FAIL: no display\n");
        return 1;
    }
    XSetErrorHandler(ignore_errors);
    int screen = DefaultScreen(dpy);
    int major = 0, minor = 0;
    CHECK(glXQueryVersion(dpy, &major, &minor) && major == 1 && minor >= 3, "GLX %d.%d", major, minor);
    CHECK(glXQueryExtensionsString(dpy, screen) != NULL, "no extensions string");

    /* Configurations: every one returned satisfies the request; depth is sorted larger first. */
    int attrs[] = {GLX_DOUBLEBUFFER, True, GLX_RED_SIZE, 8, GLX_DEPTH_SIZE, 16, GLX_STENCIL_SIZE, 1,
                   GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, GLX_RENDER_TYPE, GLX_RGBA_BIT, None};
    int n = 0;
    GLXFBConfig *configs = glXChooseFBConfig(dpy, screen, attrs, &n);
    CHECK(configs && n > 0, "glXChooseFBConfig found %d", n);
    if (!configs || n == 0)
        return 1;
    for (int i = 0; i < n; i++) {
        int db, red, depth, stencil;
        glXGetFBConfigAttrib(dpy, configs[i], GLX_DOUBLEBUFFER, &db);
        glXGetFBConfigAttrib(dpy, configs[i], GLX_RED_SIZE, &red);
        glXGetFBConfigAttrib(dpy, configs[i], GLX_DEPTH_SIZE, &depth);
        glXGetFBConfigAttrib(dpy, configs[i], GLX_STENCIL_SIZE, &stencil);
        CHECK(db == True && red >= 8 && depth >= 16 && stencil >= 1,
              "config %d: double %d red %d depth %d stencil %d", i, db, red, depth, stencil);
    }
    int none_attrs[] = {GLX_STEREO, True, None};
    int n_stereo = -1;
    GLXFBConfig *stereo = glXChooseFBConfig(dpy, screen, none_attrs, &n_stereo);
    (void)stereo; /* Mesa may have some; only the count's sanity is checked */
    CHECK(n_stereo >= 0, "stereo count %d", n_stereo);

    GLXFBConfig cfg = configs[0];
    XVisualInfo *vi = glXGetVisualFromFBConfig(dpy, cfg);
    CHECK(vi != NULL, "no visual for the config");
    if (!vi)
        return 1;
    Window win = make_window(vi, 64, 48, 0);
    GLXContext ctx = glXCreateNewContext(dpy, cfg, GLX_RGBA_TYPE, NULL, True);
    CHECK(ctx != NULL, "glXCreateNewContext");
    CHECK(glXMakeContextCurrent(dpy, win, win, ctx), "glXMakeContextCurrent");
    CHECK(glXGetCurrentContext() == ctx, "current context");
    CHECK(glXGetCurrentDrawable() == win, "current drawable");
    CHECK(glXGetCurrentDisplay() == dpy, "current display");
    unsigned int qw = 0, qh = 0;
    glXQueryDrawable(dpy, win, GLX_WIDTH, &qw);
    glXQueryDrawable(dpy, win, GLX_HEIGHT, &qh);
    CHECK(qw == 64 && qh == 48, "glXQueryDrawable %ux%u", qw, qh);
    GLint vp[4];
    glGetIntegerv(GL_VIEWPORT, vp);
    CHECK(vp[2] == 64 && vp[3] == 48, "initial viewport %dx%d", vp[2], vp[3]);
    CHECK(glGetString(GL_RENDERER) != NULL, "glGetString");
    CHECK(glXIsDirect(dpy, ctx), "glXIsDirect");

    /* A swap shows the back buffer. */
    clear_to(1, 0, 0);
    glXSwapBuffers(dpy, win);
    CHECK(pixel(win, 10, 10) == 0xff0000, "after swap: %06lx", pixel(win, 10, 10));
    /* Drawing into the back buffer alone does not change the window. */
    clear_to(0, 1, 0);
    glFlush();
    CHECK(pixel(win, 10, 10) == 0xff0000, "back buffer shown before the swap: %06lx", pixel(win, 10, 10));
    glXSwapBuffers(dpy, win);
    CHECK(pixel(win, 10, 10) == 0x00ff00, "second swap: %06lx", pixel(win, 10, 10));

    /* A resize: after the next swap the buffers have the new size. */
    XResizeWindow(dpy, win, 100, 80);
    XSync(dpy, False);
    glXSwapBuffers(dpy, win);
    glViewport(0, 0, 100, 80);
    clear_to(0, 0, 1);
    glXSwapBuffers(dpy, win);
    CHECK(pixel(win, 95, 75) == 0x0000ff, "after resize, far corner %06lx", pixel(win, 95, 75));

    /* Two contexts on two windows. */
    Window win2 = make_window(vi, 32, 32, 200);
    GLXContext ctx2 = glXCreateNewContext(dpy, cfg, GLX_RGBA_TYPE, NULL, True);
    CHECK(glXMakeCurrent(dpy, win2, ctx2), "make ctx2 current");
    clear_to(1, 1, 0);
    glXSwapBuffers(dpy, win2);
    CHECK(glXMakeCurrent(dpy, win, ctx), "ctx back");
    clear_to(0, 1, 1);
    glXSwapBuffers(dpy, win);
    CHECK(pixel(win2, 5, 5) == 0xffff00, "window 2: %06lx", pixel(win2, 5, 5));
    CHECK(pixel(win, 5, 5) == 0x00ffff, "window 1: %06lx", pixel(win, 5, 5));

    /* A context current on this thread cannot be made current on another. */
    struct thread_args a = {ctx, win, -1};
    pthread_t t;
    pthread_create(&t, NULL, other_thread, &a);
    pthread_join(t, NULL);
    CHECK(a.made_current == False, "context current on two threads");
    /* Released here, the other thread can use it. */
    CHECK(glXMakeCurrent(dpy, None, NULL), "release");
    CHECK(glXGetCurrentContext() == NULL, "nothing current after release");
    a.made_current = -1;
    pthread_create(&t, NULL, other_thread, &a);
    pthread_join(t, NULL);
    CHECK(a.made_current == True, "other thread after release");
    CHECK(pixel(win, 5, 5) == 0xff00ff, "drawn by the other thread: %06lx", pixel(win, 5, 5));

    /* A single-buffered window shows what is drawn at glFlush. */
    int single[] = {GLX_DOUBLEBUFFER, False, GLX_RED_SIZE, 8, None};
    int ns = 0;
    GLXFBConfig *sc = glXChooseFBConfig(dpy, screen, single, &ns);
    CHECK(sc && ns > 0, "no single-buffered config");
    if (sc && ns > 0) {
        XVisualInfo *svi = glXGetVisualFromFBConfig(dpy, sc[0]);
        Window sw = make_window(svi, 32, 32, 300);
        GLXContext sctx = glXCreateNewContext(dpy, sc[0], GLX_RGBA_TYPE, NULL, True);
        CHECK(glXMakeCurrent(dpy, sw, sctx), "single-buffered make current");
        GLboolean dbl = 1;
        glGetBooleanv(GL_DOUBLEBUFFER, &dbl);
        CHECK(!dbl, "GL_DOUBLEBUFFER on a single-buffered config");
        clear_to(1, 1, 1);
        glFlush();
        CHECK(pixel(sw, 5, 5) == 0xffffff, "single-buffered after glFlush: %06lx", pixel(sw, 5, 5));
        glXMakeCurrent(dpy, None, NULL);
        glXDestroyContext(dpy, sctx);
        XFree(svi);
        XFree(sc);
    }

    /* GLX 1.2 visuals: a double- and a single-buffered choice each keep their configuration. */
    int vdouble[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 1, None};
    int vsingle[] = {GLX_RGBA, GLX_DEPTH_SIZE, 1, None};
    XVisualInfo *dv = glXChooseVisual(dpy, screen, vdouble);
    XVisualInfo *sv = glXChooseVisual(dpy, screen, vsingle);
    CHECK(dv && sv, "glXChooseVisual");
    if (dv && sv) {
        int d1 = -1, d2 = -1, z = -1, rgba = -1;
        glXGetConfig(dpy, dv, GLX_DOUBLEBUFFER, &d1);
        glXGetConfig(dpy, sv, GLX_DOUBLEBUFFER, &d2);
        glXGetConfig(dpy, dv, GLX_DEPTH_SIZE, &z);
        glXGetConfig(dpy, dv, GLX_RGBA, &rgba);
        CHECK(d1 == 1 && d2 == 0, "GLX_DOUBLEBUFFER of the chosen visuals: %d %d", d1, d2);
        CHECK(z >= 1 && rgba == 1, "depth %d rgba %d", z, rgba);
        /* A GLX pixmap of the single-buffered visual: drawing lands in the X pixmap. */
        Pixmap pm = XCreatePixmap(dpy, RootWindow(dpy, screen), 16, 16, sv->depth);
        GLXPixmap gp = glXCreateGLXPixmap(dpy, sv, pm);
        GLXContext pctx = glXCreateContext(dpy, sv, NULL, True);
        CHECK(gp && pctx && glXMakeCurrent(dpy, gp, pctx), "GLX pixmap current");
        clear_to(0, 0, 1);
        glFinish();
        glXWaitGL();
        CHECK(pixel(pm, 3, 3) == 0x0000ff, "GLX pixmap: %06lx", pixel(pm, 3, 3));
        glXMakeCurrent(dpy, None, NULL);
        glXDestroyContext(dpy, pctx);
        glXDestroyGLXPixmap(dpy, gp);
        XFreePixmap(dpy, pm);
        XFree(dv);
        XFree(sv);
    }

    /* Proc addresses: core names, ARB aliases, GLX names; unknown names are not ours. */
    CHECK(glXGetProcAddressARB((const GLubyte *)"glActiveTextureARB") != NULL, "glActiveTextureARB");
    CHECK(glXGetProcAddress((const GLubyte *)"glBindBuffer") != NULL, "glBindBuffer");
    CHECK(glXGetProcAddress((const GLubyte *)"glXSwapBuffers") != NULL, "glXSwapBuffers");

    /* Destroying a current context defers the destruction; it stays usable until released. */
    CHECK(glXMakeCurrent(dpy, win2, ctx2), "ctx2 current again");
    glXDestroyContext(dpy, ctx2);
    clear_to(0, 0, 0);
    glXSwapBuffers(dpy, win2);
    CHECK(pixel(win2, 5, 5) == 0x000000, "destroyed-while-current context drew %06lx", pixel(win2, 5, 5));
    CHECK(glXMakeCurrent(dpy, None, NULL), "release ctx2");

    glXDestroyContext(dpy, ctx);
    XFree(vi);
    XFree(configs);
    XCloseDisplay(dpy);
    if (failures)
        printf("%d failures\n", failures);
    else
        printf("all GLX checks passed\n");
    return failures != 0;
}
