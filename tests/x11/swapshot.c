/* LD_PRELOAD helper for tests/x11.rs: after swap number $SWAPSHOT_FRAME (from 0) of an
 * unmodified GLX or EGL program, reads the window back from the X server with XGetImage (what
 * the user sees, whichever libGL drew it), writes it to $SWAPSHOT_OUT as a binary PPM (P6) and
 * exits with status 0. The same helper runs over Mesa's libraries and over tilegl's. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

typedef void (*swap_fn)(Display *, unsigned long);

static int channel(unsigned long pixel, unsigned long mask)
{
    int shift = 0, bits = 0;
    if (!mask)
        return 0;
    while (!(mask & 1)) { mask >>= 1; shift++; }
    while (mask & 1) { mask >>= 1; bits++; }
    unsigned long v = (pixel >> shift) & ((1ul << bits) - 1);
    return bits >= 8 ? (int)(v >> (bits - 8)) : (int)(v * 255 / ((1ul << bits) - 1));
}

/* Writes window `drawable` of `dpy` to $SWAPSHOT_OUT and exits. */
static void shoot(Display *dpy, unsigned long drawable)
{
    const char *out = getenv("SWAPSHOT_OUT");
    XSync(dpy, False);
    XWindowAttributes wa;
    if (!XGetWindowAttributes(dpy, drawable, &wa)) {
        fprintf(stderr, "swapshot: XGetWindowAttributes failed\n");
        exit(4);
    }
    XImage *img = XGetImage(dpy, drawable, 0, 0, wa.width, wa.height, AllPlanes, ZPixmap);
    if (!img) {
        fprintf(stderr, "swapshot: XGetImage failed\n");
        exit(5);
    }
    FILE *f = fopen(out, "wb");
    if (!f) {
        perror(out);
        exit(6);
    }
    fprintf(f, "P6\n%d %d\n255\n", wa.width, wa.height);
    for (int y = 0; y < wa.height; y++)
        for (int x = 0; x < wa.width; x++) {
            unsigned long p = XGetPixel(img, x, y);
            fputc(channel(p, img->red_mask), f);
            fputc(channel(p, img->green_mask), f);
            fputc(channel(p, img->blue_mask), f);
        }
    fclose(f);
    XDestroyImage(img);
    exit(0);
}

/* Whether this swap is the one to shoot (counts every swap). */
static int due(void)
{
    static int count;
    const char *frame = getenv("SWAPSHOT_FRAME");
    return frame && getenv("SWAPSHOT_OUT") && count++ == atoi(frame);
}

void glXSwapBuffers(Display *dpy, unsigned long drawable)
{
    static swap_fn real;
    if (!real)
        real = (swap_fn)dlsym(RTLD_NEXT, "glXSwapBuffers");
    if (!real) {
        fprintf(stderr, "swapshot: no glXSwapBuffers behind the preload\n");
        exit(3);
    }
    real(dpy, drawable);
    if (due())
        shoot(dpy, drawable);
}

/* EGL: the window of the last window surface made, shot from a connection of our own. */
static unsigned long egl_window;

typedef void *(*surface_fn)(void *, void *, void *, const void *);
void *eglCreatePlatformWindowSurface(void *dpy, void *config, void *native, const void *attribs)
{
    surface_fn real = (surface_fn)dlsym(RTLD_NEXT, "eglCreatePlatformWindowSurface");
    if (native)
        egl_window = *(unsigned long *)native;
    return real ? real(dpy, config, native, attribs) : NULL;
}

typedef void *(*wsurface_fn)(void *, void *, unsigned long, const void *);
void *eglCreateWindowSurface(void *dpy, void *config, unsigned long win, const void *attribs)
{
    wsurface_fn real = (wsurface_fn)dlsym(RTLD_NEXT, "eglCreateWindowSurface");
    egl_window = win;
    return real ? real(dpy, config, win, attribs) : NULL;
}

typedef unsigned (*eswap_fn)(void *, void *);
unsigned eglSwapBuffers(void *dpy, void *surface)
{
    eswap_fn real = (eswap_fn)dlsym(RTLD_NEXT, "eglSwapBuffers");
    if (!real) {
        fprintf(stderr, "swapshot: no eglSwapBuffers behind the preload\n");
        exit(3);
    }
    unsigned r = real(dpy, surface);
    if (due() && egl_window) {
        Display *own = XOpenDisplay(NULL);
        if (!own) {
            fprintf(stderr, "swapshot: XOpenDisplay failed\n");
            exit(7);
        }
        shoot(own, egl_window);
    }
    return r;
}
