/* The compiled search core's loops (see _core.c): a queue or a stack (graph or tree search,
 * either visit rule), iterative deepening, and a priority queue, each a port of the Python
 * loops of tui_search/engine/search/loops, writing the same record. */
#include "_core.h"

/* Room in the scratch buffers for the next ROOM steps (each a root and a successor per move
 * at most); a loop takes one step's room before each step. */
#define ROOM 4096
static int make_room(Search *s) {
    Py_ssize_t events = ROOM * (Py_ssize_t)(s->nmoves + 1) * sizeof(int);
    if (reserve(&s->node, events) < 0 || (s->loop == IDDFS && reserve(&s->depth, events) < 0)
        || reserve(&s->end, ROOM * sizeof(int)) < 0 || reserve(&s->exp, ROOM * sizeof(int)) < 0
        || reserve(&s->disc, ROOM * sizeof(int)) < 0 || reserve(&s->gs, ROOM * sizeof(double)) < 0)
        return -1;
    s->room = ROOM;
    return 0;
}
#define TAKE_ROOM() do { if (!s->room && make_room(s) < 0) return -3; s->room--; } while (0)

static inline int cell_of(Search *s, Py_ssize_t e) {
    return e < s->base_n ? s->base[e] : AT(s->node, int, e - s->base_n);
}

static int on_path(Search *s, int cell, int e) {  /* tree search: is cell on e's own path? */
    while (e >= 0) {
        if (cell_of(s, e) == cell) return 1;
        e = AT(s->parent, int, e);
    }
    return 0;
}

static inline int refused(Search *s, int i, int n) {  /* the corner rule refuses move i */
    return s->side_a[i] && s->walls[n + s->side_a[i]] + s->walls[n + s->side_b[i]] >= s->refused;
}

static double priority(Search *s, double g, int m) {
    if (!s->use_h) return g;
    int y = m / s->stride, x = m % s->stride;
    int dx = abs(x - s->gx), dy = abs(y - s->gy);
    double h;
    switch (s->heuristic) {
    case H_OCTILE: h = dx >= dy ? (double)dx + s->extra * (double)dy
                                : (double)dy + s->extra * (double)dx; break;
    case H_EUCLIDEAN: h = sqrt((double)dx * dx + (double)dy * dy); break;  /* = math.hypot */
    case H_MANHATTAN: h = (double)(dx + dy); break;
    case H_CHEBYSHEV: h = (double)(dx > dy ? dx : dy); break;
    default: h = 0.0;
    }
    if (s->scale != 1.0) h = s->scale * h;  /* terrain: times the lowest cell cost */
    if (!s->use_g) return h;
    if (s->weight != 1.0) h = s->weight * h;  /* weighted A*: g + W*h, rounded as Python's */
    return g + h;
}

/* -- the priority queue: a binary heap ordered by (priority, event), as heapq's tuples -- */
static inline int before(const Entry *a, const Entry *b) {
    return a->f < b->f || (a->f == b->f && a->e < b->e);
}

static int heap_push(Search *s, Entry x) {
    if (reserve(&s->stack, sizeof(Entry)) < 0) return -1;
    Entry *h = (Entry *)s->stack.a;
    Py_ssize_t i = s->stack.n / (Py_ssize_t)sizeof(Entry);
    s->stack.n += sizeof(Entry);
    while (i > 0 && before(&x, &h[(i - 1) / 2])) { h[i] = h[(i - 1) / 2]; i = (i - 1) / 2; }
    h[i] = x;
    return 0;
}

static Entry heap_pop(Search *s) {
    Entry *h = (Entry *)s->stack.a, top = h[0];
    Py_ssize_t n = s->stack.n / (Py_ssize_t)sizeof(Entry) - 1, i = 0;
    s->stack.n -= sizeof(Entry);
    Entry last = h[n];
    for (;;) {
        Py_ssize_t c = 2 * i + 1;
        if (c >= n) break;
        if (c + 1 < n && before(&h[c + 1], &h[c])) c++;
        if (!before(&h[c], &last)) break;
        h[i] = h[c]; i = c;
    }
    if (n > 0) h[i] = last;
    return top;
}

/* -- the loops: each runs at most `chunk` steps and returns PAUSED, NO_GOAL or the goal's
 *    event; -3 on an error (memory) -- */
#define END_STEP() PUT(s->end, int, (int)count)

/* A FIFO queue (the events in the order generated) or a LIFO stack of (event, cell): graph
 * search under either visit rule, or tree search (only the node's own path is skipped).  The
 * hot loop of the app: what it reads is in locals (a store to `closed` could alias any field)
 * and it writes the record through cursors. */
#define LOAD() (node = (int *)(s->node.a + s->node.n), end = (int *)(s->end.a + s->end.n), \
                exp = (int *)(s->exp.a + s->exp.n), disc = (int *)(s->disc.a + s->disc.n), \
                events = (const int *)s->node.a)
#define SAVE() (s->node.n = (char *)node - s->node.a, s->end.n = (char *)end - s->end.a, \
                s->exp.n = (char *)exp - s->exp.a, s->disc.n = (char *)disc - s->disc.a)
long core_run_queue(Search *s, Py_ssize_t chunk) {
    Py_ssize_t count = s->count, head = s->head, step = s->steps, stop = s->steps + chunk;
    Py_ssize_t room = s->room, base_n = s->base_n;
    unsigned char *const closed = s->closed;
    const unsigned char *const walls = s->walls;
    const int *const base = s->base;
    const int lifo = s->lifo, tree = s->tree, expand = s->visit_expand, nm = s->nmoves;
    const int on_push = s->goal_on_push, on_pop = s->goal_on_pop, limit = s->refused;
    int off[8], sa[8], sb[8], *node, *end, *exp, *disc;
    const int *events;
    memcpy(off, s->off, sizeof off); memcpy(sa, s->side_a, sizeof sa);
    memcpy(sb, s->side_b, sizeof sb);
    LOAD();
    long result = PAUSED;
    while (step < stop) {
        int e, n;
        if (!room) {
            SAVE();
            if (make_room(s) < 0) return -3;
            LOAD();
            room = s->room;
        }
        room--;
        if (lifo) {
            if (!s->stack.n) break;
            s->stack.n -= 2 * sizeof(int);
            const int *top = (const int *)(s->stack.a + s->stack.n);
            e = top[0]; n = top[1];
            *exp++ = e;
        } else {
            if (head >= count) break;
            e = (int)head++;
            n = e < base_n ? base[e] : events[e - base_n];
        }
        step++;
        if (expand) {
            if (closed[n]) { *disc++ = (int)step; *end++ = (int)count; continue; }
            closed[n] = 1;
        }
        if (n == on_pop) { result = e; *end++ = (int)count; goto out; }
        if (lifo && reserve(&s->stack, nm * 2 * sizeof(int)) < 0) return -3;
        if (tree && reserve(&s->parent, nm * sizeof(int)) < 0) return -3;
        for (int i = 0; i < nm; i++) {
            int m = n + off[i];
            if (closed[m] || (sa[i] && walls[n + sa[i]] + walls[n + sb[i]] >= limit)) continue;
            if (tree) {
                if (on_path(s, m, e)) continue;
                PUT(s->parent, int, e);
            } else if (!expand) {
                closed[m] = 1;
            }
            if (lifo) {
                int *top = (int *)(s->stack.a + s->stack.n);
                top[0] = (int)count; top[1] = m;
                s->stack.n += 2 * sizeof(int);
            }
            *node++ = m;
            count++;
            if (m == on_push) { result = count - 1; *end++ = (int)count; goto out; }
        }
        *end++ = (int)count;
    }
    if (lifo ? !s->stack.n : head >= count) result = NO_GOAL;
out:
    SAVE();
    s->count = count; s->head = head; s->steps = step; s->room = room;
    return result;
}

/* Iterative deepening: depth-limited DFS with limits 0, 1, 2, ...; a cell is generated again
 * in an iteration only when reached at a smaller depth (graph search), or when not on the
 * node's own path (tree search).  The stack holds (event, cell, depth). */
static int new_iteration(Search *s) {
    Py_ssize_t root = s->count;
    if (s->limit) {
        PyObject *a = PyLong_FromSsize_t(s->steps + 1), *b = PyLong_FromSsize_t(root),
                 *c = PyLong_FromLong(s->limit);
        int bad = !a || !b || !c || PyList_Append(s->it_first, a) || PyList_Append(s->it_root, b)
                  || PyList_Append(s->it_limit, c);
        Py_XDECREF(a); Py_XDECREF(b); Py_XDECREF(c);
        if (bad) return -1;
    } else {
        PyObject *zero = PyLong_FromLong(0);
        if (!zero || PyList_SetItem(s->it_limit, 0, zero)) return -1;  /* steals zero */
    }
    if (reserve(&s->node, sizeof(int)) < 0 || reserve(&s->depth, sizeof(int)) < 0
        || reserve(&s->stack, 3 * sizeof(int)) < 0 || reserve(&s->parent, sizeof(int)) < 0)
        return -1;
    PUT(s->node, int, s->start); PUT(s->depth, int, 0);
    if (s->tree) PUT(s->parent, int, -1);
    s->count++;
    s->iteration++;
    s->stamp[s->start] = s->iteration; s->best_depth[s->start] = 0;
    PUT(s->stack, int, (int)root); PUT(s->stack, int, s->start); PUT(s->stack, int, 0);
    s->cut_off = 0;
    return 0;
}

long core_run_iddfs(Search *s, Py_ssize_t chunk) {
    Py_ssize_t count = s->count, step = s->steps, stop = s->steps + chunk;
    long result = PAUSED;
    if (!s->started) {
        s->started = 1;
        if (new_iteration(s) < 0) return -3;
        count = s->count;
        if (s->start == s->goal_on_push) return (long)(count - 1);
    }
    while (step < stop) {
        TAKE_ROOM();
        if (!s->stack.n) {
            if (!s->cut_off) { result = NO_GOAL; break; }
            s->limit++;
            s->count = count; s->steps = step;
            if (new_iteration(s) < 0) return -3;
            count = s->count;
        }
        s->stack.n -= 3 * sizeof(int);
        int *top = (int *)(s->stack.a + s->stack.n), e = top[0], n = top[1], depth = top[2];
        if (n == s->goal_on_pop) { PUT(s->exp, int, e); step++; result = e; END_STEP(); goto out; }
        if (depth >= s->limit) {
            s->cut_off = 1;
        } else {
            int child = depth + 1;
            if (reserve(&s->stack, s->nmoves * 3 * sizeof(int)) < 0
                || reserve(&s->parent, s->nmoves * sizeof(int)) < 0) return -3;
            for (int i = 0; i < s->nmoves; i++) {
                int m = n + s->off[i];
                if (s->walls[m] || refused(s, i, n)) continue;
                if (s->tree) {
                    if (on_path(s, m, e)) continue;
                    PUT(s->parent, int, e);
                } else if (s->stamp[m] == s->iteration && s->best_depth[m] <= child) {
                    continue;
                } else {
                    s->stamp[m] = s->iteration; s->best_depth[m] = child;
                }
                PUT(s->stack, int, (int)count); PUT(s->stack, int, m); PUT(s->stack, int, child);
                PUT(s->node, int, m); PUT(s->depth, int, child);
                count++;
                if (m == s->goal_on_push) {
                    PUT(s->exp, int, e); step++; result = count - 1; END_STEP(); goto out;
                }
            }
        }
        PUT(s->exp, int, e); step++;
        END_STEP();
    }
    if (result == PAUSED && !s->stack.n && !s->cut_off) result = NO_GOAL;
out:
    s->count = count; s->steps = step;
    return result;
}

/* The priority queue's mark, beside `closed`'s 1 in the same byte: the cell's best g is set. */
#define SEEN 2

/* A priority queue of (priority, event, cell, g): graph search (an entry whose g is above its
 * cell's best is stale: a discarded step) or tree search.  A move costs its length times the
 * cost of the cell it enters (terrain; its length alone without). */
long core_run_best(Search *s, Py_ssize_t chunk) {
    Py_ssize_t count = s->count, step = s->steps, stop = s->steps + chunk;
    unsigned char *closed = s->closed;
    double *best = s->best;
    const double *terrain = s->terrain;
    long result = PAUSED;
    while (step < stop && s->stack.n) {
        TAKE_ROOM();
        Entry x = heap_pop(s);
        int e = x.e, n = x.n;
        double g = x.g;
        PUT(s->exp, int, e); PUT(s->gs, double, g);
        step++;
        if (!s->tree && g > best[n]) { END_STEP(); PUT(s->disc, int, (int)step); continue; }
        if (n == s->goal_on_pop) { result = e; END_STEP(); goto out; }
        if (!s->tree) closed[n] |= (unsigned char)s->close;
        if (s->tree && reserve(&s->parent, s->nmoves * sizeof(int)) < 0) return -3;
        for (int i = 0; i < s->nmoves; i++) {
            int m = n + s->off[i];
            if ((closed[m] & 1) || refused(s, i, n)) continue;
            double cost = terrain ? s->cost[i] * terrain[m] : s->cost[i];
            if (s->tree) {
                if (on_path(s, m, e)) continue;
                PUT(s->parent, int, e);
            } else if ((closed[m] & SEEN)
                       && (terrain ? g + cost + s->cheaper >= best[m] : g + s->margin[i] >= best[m])) {
                continue;
            }
            double ng = g + cost;
            if (!s->tree) { best[m] = ng; closed[m] |= SEEN; }
            Entry y = {priority(s, ng, m), (int)count, m, ng};
            if (heap_push(s, y) < 0) return -3;
            PUT(s->node, int, m);
            count++;
            if (m == s->goal_on_push) { result = count - 1; END_STEP(); goto out; }
        }
        END_STEP();
    }
    if (!s->stack.n) result = NO_GOAL;
out:
    s->count = count; s->steps = step;
    return result;
}

/* What a search holds before its first step: its closed cells, and the start on its frontier
 * (iterative deepening pushes a root an iteration). */
int core_start(Search *s) {
    s->gy = s->goal / s->stride; s->gx = s->goal % s->stride;
    s->closed = PyMem_RawMalloc(s->ncells);
    if (!s->closed) { PyErr_NoMemory(); return -1; }
    memcpy(s->closed, s->walls, s->ncells);
    if (s->loop == IDDFS) {
        s->best_depth = PyMem_RawMalloc(s->ncells * sizeof(int));
        s->stamp = PyMem_RawCalloc(s->ncells, sizeof(int));
        if (!s->best_depth || !s->stamp) { PyErr_NoMemory(); return -1; }
        return 0;
    }
    if (make_room(s) < 0) return -1;
    PUT(s->node, int, s->start);  /* the start, event 0: written by the first advance */
    s->count = 1;
    if (s->tree) {
        if (reserve(&s->parent, sizeof(int)) < 0) return -1;
        PUT(s->parent, int, -1);
    }
    if (s->loop == BEST) {
        /* not filled: a cell's best is read only once set (SEEN), so the pages of a big map
         * that the search never reaches are never touched (A* across open 1024x1024 reaches
         * a few thousand of its million cells) */
        s->best = PyMem_RawMalloc(s->ncells * sizeof(double));
        if (!s->best) { PyErr_NoMemory(); return -1; }
        s->best[s->start] = 0.0;
        s->closed[s->start] |= SEEN;
        Entry root = {priority(s, 0.0, s->start), 0, s->start, 0.0};
        return heap_push(s, root);
    }
    if (!s->visit_expand && !s->tree) s->closed[s->start] = 1;
    if (s->lifo) {
        if (reserve(&s->stack, 2 * sizeof(int)) < 0) return -1;
        PUT(s->stack, int, 0); PUT(s->stack, int, s->start);
    }
    return 0;
}
