/* EGL behaviour checks for tests/x11.rs, run on tilegl's libEGL.so.1 and on Mesa's (which
 * checks the expectations): displays, initialisation, client extensions, configurations, an
 * OpenGL context on a window surface, swaps shown in the window, surface queries, the current
 * state and the error codes of bad calls. Exits 0 when every check holds. */
#include <stdio.h>
#include <string.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <EGL/egl.h>
#include <GL/gl.h>

static int failures;
#define CHECK(cond, ...) do { if (!(cond)) { failures++; printf("FAIL %s:%d: ", __FILE__, __LINE__); printf(__VA_ARGS__); printf("\n"); } } while (0)

int main(void)
{
    Display *x = XOpenDisplay(NULL);
    if (!x) {
        printf("FAIL: no display\n");
        return 1;
    }
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    CHECK(client && strstr(client, "EGL_EXT_platform_x11"), "client extensions: %s", client ? client : "(null)");

    EGLDisplay bogus = (EGLDisplay)&failures;
    CHECK(!eglInitialize(bogus, NULL, NULL) && eglGetError() == EGL_BAD_DISPLAY, "bad display");
    CHECK(eglGetError() == EGL_SUCCESS, "eglGetError resets");

    EGLDisplay d = eglGetDisplay((EGLNativeDisplayType)x);
    CHECK(d != EGL_NO_DISPLAY, "eglGetDisplay");
    CHECK(eglGetDisplay((EGLNativeDisplayType)x) == d, "same display twice");
    EGLint n = 0;
    CHECK(!eglChooseConfig(d, NULL, NULL, 0, &n) && eglGetError() == EGL_NOT_INITIALIZED,
          "eglChooseConfig before eglInitialize");
    EGLint major = 0, minor = 0;
    CHECK(eglInitialize(d, &major, &minor) && major == 1 && minor >= 4, "EGL %d.%d", major, minor);
    CHECK(eglQueryString(d, EGL_VENDOR) != NULL, "vendor");
    const char *apis = eglQueryString(d, EGL_CLIENT_APIS);
    CHECK(apis && strstr(apis, "OpenGL"), "client APIs: %s", apis ? apis : "(null)");

    EGLint attrs[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                      EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_DEPTH_SIZE, 16, EGL_NONE};
    EGLConfig configs[64];
    CHECK(eglChooseConfig(d, attrs, configs, 64, &n) && n > 0, "eglChooseConfig: %d", n);
    if (n <= 0)
        return 1;
    for (int i = 0; i < n; i++) {
        EGLint depth = -1, red = -1, type = 0;
        eglGetConfigAttrib(d, configs[i], EGL_DEPTH_SIZE, &depth);
        eglGetConfigAttrib(d, configs[i], EGL_RED_SIZE, &red);
        eglGetConfigAttrib(d, configs[i], EGL_RENDERABLE_TYPE, &type);
        CHECK(depth >= 16 && red >= 8 && (type & EGL_OPENGL_BIT), "config %d: depth %d red %d type %x", i, depth, red, type);
    }
    EGLint value;
    CHECK(!eglGetConfigAttrib(d, configs[0], 0x7777, &value) && eglGetError() == EGL_BAD_ATTRIBUTE, "bad attribute");
    EGLint visual_id = 0;
    eglGetConfigAttrib(d, configs[0], EGL_NATIVE_VISUAL_ID, &visual_id);
    XVisualInfo tmpl;
    memset(&tmpl, 0, sizeof tmpl);
    tmpl.visualid = visual_id;
    int nv = 0;
    XVisualInfo *vi = XGetVisualInfo(x, VisualIDMask, &tmpl, &nv);
    CHECK(vi && nv > 0, "visual %x of the config", visual_id);
    if (!vi)
        return 1;

    XSetWindowAttributes a;
    memset(&a, 0, sizeof a);
    a.colormap = XCreateColormap(x, RootWindow(x, vi->screen), vi->visual, AllocNone);
    Window win = XCreateWindow(x, RootWindow(x, vi->screen), 0, 0, 40, 30, 0, vi->depth, InputOutput,
                               vi->visual, CWColormap | CWBorderPixel, &a);
    XMapWindow(x, win);
    XSync(x, False);

    CHECK(eglBindAPI(EGL_OPENGL_API), "eglBindAPI(EGL_OPENGL_API)");
    CHECK(eglQueryAPI() == EGL_OPENGL_API, "eglQueryAPI");
    EGLSurface s = eglCreateWindowSurface(d, configs[0], (EGLNativeWindowType)win, NULL);
    CHECK(s != EGL_NO_SURFACE, "eglCreateWindowSurface: %x", eglGetError());
    EGLint ctx_attrs[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_MINOR_VERSION, 3, EGL_NONE};
    EGLContext c = eglCreateContext(d, configs[0], EGL_NO_CONTEXT, ctx_attrs);
    CHECK(c != EGL_NO_CONTEXT, "eglCreateContext 1.3: %x", eglGetError());
    CHECK(!eglMakeCurrent(d, s, s, (EGLContext)&failures) && eglGetError() == EGL_BAD_CONTEXT, "bad context");
    CHECK(eglMakeCurrent(d, s, s, c), "eglMakeCurrent");
    CHECK(eglGetCurrentContext() == c && eglGetCurrentSurface(EGL_DRAW) == s && eglGetCurrentDisplay() == d,
          "current state");
    EGLint w = 0, h = 0;
    eglQuerySurface(d, s, EGL_WIDTH, &w);
    eglQuerySurface(d, s, EGL_HEIGHT, &h);
    CHECK(w == 40 && h == 30, "surface %dx%d", w, h);
    CHECK(glGetString(GL_VERSION) != NULL, "glGetString through EGL");
    CHECK(eglGetProcAddress("glActiveTexture") != NULL, "eglGetProcAddress(glActiveTexture)");

    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    CHECK(eglSwapBuffers(d, s), "eglSwapBuffers");
    XSync(x, False);
    XImage *img = XGetImage(x, win, 20, 15, 1, 1, AllPlanes, ZPixmap);
    unsigned long p = img ? XGetPixel(img, 0, 0) & 0xffffff : 0xdeadbeef;
    CHECK(p == 0x00ff00, "window after eglSwapBuffers: %06lx", p);
    if (img)
        XDestroyImage(img);

    /* share_context: a context sharing with c sees c's texture and list, one without does
     * not; a share context that is no context is EGL_BAD_CONTEXT. */
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glEndList();
    EGLContext shared = eglCreateContext(d, configs[0], c, ctx_attrs);
    EGLContext alone = eglCreateContext(d, configs[0], EGL_NO_CONTEXT, ctx_attrs);
    CHECK(shared != EGL_NO_CONTEXT && alone != EGL_NO_CONTEXT, "sharing contexts: %x", eglGetError());
    CHECK(eglCreateContext(d, configs[0], (EGLContext)&failures, ctx_attrs) == EGL_NO_CONTEXT &&
              eglGetError() == EGL_BAD_CONTEXT, "bad share context");
    CHECK(eglMakeCurrent(d, s, s, shared), "make the sharing context current");
    CHECK(glIsTexture(tex) && glIsList(list), "shared: texture %d list %d", glIsTexture(tex), glIsList(list));
    CHECK(eglMakeCurrent(d, s, s, alone), "make the unshared context current");
    CHECK(!glIsTexture(tex) && !glIsList(list), "unshared: texture %d list %d", glIsTexture(tex), glIsList(list));
    CHECK(eglMakeCurrent(d, s, s, c), "c again");
    CHECK(eglDestroyContext(d, shared) && eglDestroyContext(d, alone), "destroy the sharing contexts");

    CHECK(eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT), "release");
    CHECK(eglGetCurrentContext() == EGL_NO_CONTEXT, "nothing current");
    CHECK(!eglSwapBuffers(d, (EGLSurface)&failures) && eglGetError() == EGL_BAD_SURFACE, "bad surface");
    CHECK(eglDestroyContext(d, c), "eglDestroyContext");
    CHECK(eglDestroySurface(d, s), "eglDestroySurface");
    CHECK(eglTerminate(d), "eglTerminate");
    XFree(vi);
    XCloseDisplay(x);
    if (failures)
        printf("%d failures\n", failures);
    else
        printf("all EGL checks passed\n");
    return failures != 0;
}
