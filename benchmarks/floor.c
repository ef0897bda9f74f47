/* The C floor of the core section (benchmarks/core.py) and of the terrain section's floor row
 * (benchmarks/terrain.py): the searches of the compiled core
 * with the least record that lets the app move to any step -- each event's cell, each step's
 * end, the event it expanded (a stack's or a priority queue's), its g and the discarded steps
 * (a priority queue's) -- in arrays that double, and no more.  Built by benchmarks/core.py
 * with the compiled core's flags and called through ctypes; returns the steps taken. */
#include <stdlib.h>
#include <string.h>

typedef struct { void *a; long n, cap; } Arr;
static void *grow(Arr *x, long size) {  /* room for one more item of `size` bytes */
    if (x->n == x->cap) { x->cap = x->cap ? 2 * x->cap : 1024; x->a = realloc(x->a, x->cap * size); }
    return (char *)x->a + x->n++ * size;
}
#define ADD(x, T, v) (*(T *)grow(&(x), sizeof(T)) = (v))

/* BFS (lifo 0) or DFS (lifo 1): graph search, visited and goal-tested when generated; a
 * diagonal refused when a side cell (sa, sb; 0 for a straight move or no corner rule) is a wall. */
long floor_queue(const unsigned char *walls, long ncells, int start, int goal, const int *off,
                 const int *sa, const int *sb, int nm, int lifo) {
    unsigned char *closed = malloc(ncells);
    memcpy(closed, walls, ncells);
    Arr node = {0}, end = {0}, exp = {0}, stack = {0};
    ADD(node, int, start); ADD(end, int, 1); closed[start] = 1;
    if (lifo) ADD(stack, int, 0);
    long head = 0, steps = 0;
    while (lifo ? stack.n : head < node.n) {
        int e = lifo ? ((int *)stack.a)[--stack.n] : (int)head++, n = ((int *)node.a)[e];
        if (lifo) ADD(exp, int, e);
        steps++;
        for (int i = 0; i < nm; i++) {
            int m = n + off[i];
            if (closed[m] || (sa[i] && (walls[n + sa[i]] | walls[n + sb[i]]))) continue;
            closed[m] = 1;
            if (lifo) ADD(stack, int, (int)node.n);
            ADD(node, int, m);
            if (m == goal) goto done;
        }
        ADD(end, int, (int)node.n);
    }
done:
    free(closed); free(node.a); free(end.a); free(exp.a); free(stack.a);
    return steps;
}

typedef struct { double f; int e, n; double g; } Entry;
static int before(const Entry *a, const Entry *b) { return a->f < b->f || (a->f == b->f && a->e < b->e); }

/* A* (octile, use_h 1) or UCS (use_h 0) with MovingAI's corner rule (sa, sb: the diagonals'
 * side cells, 0 for a straight move), the goal tested when taken off, stale entries skipped.
 * Terrain as the compiled core has it (NULL: every cell costs 1): a move costs its length
 * times the cost of the (padded) cell it enters, and the heuristic is times `scale`, the
 * map's lowest cell cost. */
long floor_best(const unsigned char *walls, long ncells, int stride, int start, int goal,
                const int *off, const int *sa, const int *sb, const double *cost, int nm,
                int use_h, double extra, const double *terrain, double scale) {
    unsigned char *closed = malloc(ncells);
    memcpy(closed, walls, ncells);
    double *best = malloc(ncells * sizeof(double));
    for (long i = 0; i < ncells; i++) best[i] = 1e300;
    Arr node = {0}, end = {0}, exp = {0}, gs = {0}, disc = {0}, heap = {0};
    ADD(node, int, start); ADD(end, int, 1); best[start] = 0.0;
    Entry first = {0.0, 0, start, 0.0};
    ADD(heap, Entry, first);
    long steps = 0;
    int gx = goal % stride, gy = goal / stride;
    while (heap.n) {
        Entry *h = heap.a, x = h[0], last = h[--heap.n];
        long i = 0;
        for (long c; (c = 2 * i + 1) < heap.n; i = c) {
            if (c + 1 < heap.n && before(&h[c + 1], &h[c])) c++;
            if (!before(&h[c], &last)) break;
            h[i] = h[c];
        }
        if (heap.n) h[i] = last;
        ADD(exp, int, x.e); ADD(gs, double, x.g);
        steps++;
        if (x.g > best[x.n]) { ADD(disc, int, (int)steps); ADD(end, int, (int)node.n); continue; }
        if (x.n == goal) break;
        closed[x.n] = 1;
        for (int k = 0; k < nm; k++) {
            int m = x.n + off[k];
            if (closed[m] || (sa[k] && (walls[x.n + sa[k]] | walls[x.n + sb[k]]))) continue;
            double c = terrain ? cost[k] * terrain[m] : cost[k];
            if (terrain ? x.g + c + 1e-9 >= best[m] : x.g + (cost[k] + 1e-9) >= best[m]) continue;
            double ng = x.g + c;
            best[m] = ng;
            double f = ng;
            if (use_h) {
                int dx = abs(m % stride - gx), dy = abs(m / stride - gy);
                double h = dx >= dy ? dx + extra * dy : dy + extra * dx;
                f = ng + (scale != 1.0 ? scale * h : h);
            }
            Entry y = {f, (int)node.n, m, ng};
            long j = heap.n;
            grow(&heap, sizeof(Entry)); h = heap.a;
            while (j > 0 && before(&y, &h[(j - 1) / 2])) { h[j] = h[(j - 1) / 2]; j = (j - 1) / 2; }
            h[j] = y;
            ADD(node, int, m);
        }
        ADD(end, int, (int)node.n);
    }
    free(closed); free(best); free(node.a); free(end.a); free(exp.a); free(gs.a); free(disc.a);
    free(heap.a);
    return steps;
}
