/* Solves outlines with libspiro and times each solve: the comparison of lac's splines with
 * point types against Spiro (tools/spiro/compare.py builds and runs it on demand).
 *
 * Input (stdin), one outline a line: "n closed x0 y0 t0 x1 y1 t1 ..." with t a Spiro point
 * type character ('c' G2, 'v' corner, '[' and ']' the line-curve points, 'a' an anchor,
 * followed by its 'h' handle). Output, one line an outline: "ok nanoseconds count", then
 * with the argument "--curves K" for outline K its Bézier pieces, one a line "x0 y0 x1 y1 x2
 * y2 x3 y3" (a line as a cubic with its thirds as controls).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <bezctx.h>
#include <spiroentrypoints.h>

#define MAX_CURVES 4096

typedef struct {
    bezctx base;
    double x, y;
    int count, finite;
    double curves[MAX_CURVES][8];
} collector;

static void add(collector *c, double x1, double y1, double x2, double y2, double x3, double y3) {
    if (!(isfinite(x1) && isfinite(y1) && isfinite(x2) && isfinite(y2) && isfinite(x3) && isfinite(y3)))
        c->finite = 0;
    if (c->count < MAX_CURVES) {
        double *q = c->curves[c->count++];
        q[0] = c->x; q[1] = c->y; q[2] = x1; q[3] = y1; q[4] = x2; q[5] = y2; q[6] = x3; q[7] = y3;
    }
    c->x = x3;
    c->y = y3;
}

static void moveto(bezctx *bc, double x, double y, int is_open) {
    collector *c = (collector *)bc;
    (void)is_open;
    c->x = x;
    c->y = y;
}

static void lineto(bezctx *bc, double x, double y) {
    collector *c = (collector *)bc;
    add(c, c->x + (x - c->x) / 3, c->y + (y - c->y) / 3, c->x + 2 * (x - c->x) / 3,
        c->y + 2 * (y - c->y) / 3, x, y);
}

static void quadto(bezctx *bc, double x1, double y1, double x2, double y2) {
    collector *c = (collector *)bc;
    add(c, c->x + 2 * (x1 - c->x) / 3, c->y + 2 * (y1 - c->y) / 3, x2 + 2 * (x1 - x2) / 3,
        y2 + 2 * (y1 - y2) / 3, x2, y2);
}

static void curveto(bezctx *bc, double x1, double y1, double x2, double y2, double x3, double y3) {
    add((collector *)bc, x1, y1, x2, y2, x3, y3);
}

static void mark_knot(bezctx *bc, int knot) {
    (void)bc;
    (void)knot;
}

int main(int argc, char **argv) {
    int show = -1, index = 0;
    if (argc == 3 && strcmp(argv[1], "--curves") == 0) show = atoi(argv[2]);
    static collector c;
    spiro_cp cps[256];
    int n, closed;
    while (scanf("%d %d", &n, &closed) == 2) {
        if (n > 256) return 2;
        for (int i = 0; i < n; i++) {
            char t[4];
            if (scanf("%lf %lf %3s", &cps[i].x, &cps[i].y, t) != 3) return 2;
            cps[i].ty = t[0];
        }
        memset(&c, 0, sizeof c);
        c.base.moveto = moveto;
        c.base.lineto = lineto;
        c.base.quadto = quadto;
        c.base.curveto = curveto;
        c.base.mark_knot = mark_knot;
        c.finite = 1;
        struct timespec t0, t1;
        clock_gettime(CLOCK_MONOTONIC, &t0);
        int ok = SpiroCPsToBezier0(cps, n, closed, &c.base);
        clock_gettime(CLOCK_MONOTONIC, &t1);
        long ns = (t1.tv_sec - t0.tv_sec) * 1000000000L + (t1.tv_nsec - t0.tv_nsec);
        printf("%d %ld %d\n", ok && c.finite && c.count > 0, ns, c.count);
        if (index == show)
            for (int k = 0; k < c.count; k++) {
                double *q = c.curves[k];
                printf("%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", q[0], q[1], q[2], q[3],
                       q[4], q[5], q[6], q[7]);
            }
        index++;
    }
    return 0;
}
