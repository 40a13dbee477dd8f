/* LD_PRELOAD shim for glretrace: create replay windows at screen size, so that Mesa's software
 * back buffer (sized at window creation, resized only at a swap) holds the whole picture of a
 * capture that never swaps. */
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
    w = 1024;
    h = 768;
    return real(d, parent, x, y, w, h, bw, depth, cls, vis, mask, attrs);
}
