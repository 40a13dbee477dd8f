/* LD_PRELOAD helper for tests/x11.rs: after swap number $SWAPSHOT_FRAME (from 0) of an
 * unmodified GLX program, reads the window back from the X server with XGetImage (what the
 * user sees, whichever libGL drew it), writes it to $SWAPSHOT_OUT as a binary PPM (P6) and
 * exits with status 0. The same helper runs over Mesa's libGL and over tilegl's. */
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

void glXSwapBuffers(Display *dpy, unsigned long drawable)
{
    static swap_fn real;
    static int count;
    if (!real)
        real = (swap_fn)dlsym(RTLD_NEXT, "glXSwapBuffers");
    if (!real) {
        fprintf(stderr, "swapshot: no glXSwapBuffers behind the preload\n");
        exit(3);
    }
    real(dpy, drawable);
    const char *frame = getenv("SWAPSHOT_FRAME");
    const char *out = getenv("SWAPSHOT_OUT");
    if (!frame || !out || count++ != atoi(frame))
        return;
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
