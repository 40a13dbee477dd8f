/* LD_PRELOAD shim for glretrace: create replay windows at screen size, so that Mesa's software
 * back buffer (sized at window creation, resized only at a swap) holds the whole picture of a
 * capture that never swaps. The screen must hold the capture's window: a 1000 x 1000 piglit
 * window needs `Xvfb -screen 0 1024x1024x24` (on a 768-high screen the rows above 768 are not
 * owned by the context and stay black in the reference). */
#define _GNU_SOURCE
#include <X11/Xlib.h>
#include <dlfcn.h>

Window XCreateWindow(Display *d, Window parent, int x, int y, unsigned int w, unsigned int h,
                     unsigned int bw, int depth, unsigned int cls, Visual *vis,
                     unsigned long mask, XSetWindowAttributes *attrs) {
    static Window (*real)(Display *, Window, int, int, unsigned int, unsigned int, unsigned int,
                          int, unsigned int, Visual *, unsigned long, XSetWindowAttributes *);
    if (!real)
        real = dlsym(RTLD_NEXT, "XCreateWindow");
    w = DisplayWidth(d, DefaultScreen(d));
    h = DisplayHeight(d, DefaultScreen(d));
    return real(d, parent, x, y, w, h, bw, depth, cls, vis, mask, attrs);
}
