/* The compiled search core's shared types: the state of one search (Search), the scratch
 * buffers a chunk's record goes through (Buf), and what the loops of _core_loops.c give the
 * Python type of _core.c.  See _core.c. */
#ifndef TUI_SEARCH_CORE_H
#define TUI_SEARCH_CORE_H
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

enum { QUEUE = 0, IDDFS = 1, BEST = 2 };          /* the loop */
enum { H_OCTILE, H_EUCLIDEAN, H_MANHATTAN, H_CHEBYSHEV, H_ZERO };
#define PAUSED (-2)
#define NO_GOAL (-1)

typedef struct { char *a; Py_ssize_t n, cap; } Buf;   /* n and cap in bytes */
typedef struct { double f; int e, n; double g; } Entry;  /* a priority queue's entry */

static inline int reserve(Buf *b, Py_ssize_t more) {
    if (b->n + more <= b->cap) return 0;
    Py_ssize_t cap = b->cap ? b->cap : 4096;
    while (cap < b->n + more) cap *= 2;
    char *a = PyMem_RawRealloc(b->a, cap);
    if (!a) { PyErr_NoMemory(); return -1; }
    b->a = a; b->cap = cap;
    return 0;
}
#define PUT(b, T, v) (*(T *)((b).a + (b).n) = (v), (b).n += sizeof(T))  /* reserved before */
#define AT(b, T, i) (((T *)(b).a)[i])

typedef struct {
    PyObject_HEAD
    int loop, lifo, tree, visit_expand, use_g, use_h, heuristic, close, refused;
    int nmoves, off[8], side_a[8], side_b[8];
    double cost[8], margin[8], extra;
    int stride, start, goal, goal_on_push, goal_on_pop, gx, gy;
    Py_buffer walls_view;
    const unsigned char *walls;
    unsigned char *closed;
    Py_ssize_t ncells;
    /* the record: its arrays (step_exp, step_g, gen_depth may be None) and iteration lists */
    PyObject *r_node, *r_end, *r_exp, *r_g, *r_disc, *r_depth, *it_first, *it_root, *it_limit;
    Buf node, end, exp, gs, disc, depth;     /* a chunk's new entries */
    Buf stack, parent;                        /* the stack or heap; each event's parent */
    double *best;                             /* priority queue: each cell's lowest g */
    int *best_depth, *stamp;                  /* iterative deepening: per iteration */
    const int *base; Py_ssize_t base_n;       /* gen_node as recorded before this chunk */
    Py_ssize_t count, steps, head;
    Py_ssize_t room;                          /* steps the scratch buffers hold, reserved */
    int started, limit, cut_off, iteration;
    /* terrain: each padded cell's cost (NULL: all 1), the heuristic's factor (the lowest
     * cost) and how much cheaper a new g must be (CHEAPER_BY); weighted A*'s W (f = g + W*h;
     * 1: A*) */
    Py_buffer terrain_view;
    const double *terrain;
    double scale, cheaper, weight;
} Search;

/* _core_loops.c: a search's set-up before its first step, and its three loops; each loop
 * runs at most `chunk` steps and returns PAUSED, NO_GOAL or the goal's event (-3: an error,
 * with an exception set).  core_start returns 0, or -1 with an exception set. */
int core_start(Search *s);
long core_run_queue(Search *s, Py_ssize_t chunk);
long core_run_iddfs(Search *s, Py_ssize_t chunk);
long core_run_best(Search *s, Py_ssize_t chunk);

#endif
