/* The compiled search core: every recorded loop of tui_search.engine.search.loops in C.
 *
 * A Search appends to the same Record arrays the Python loops write (gen_node, step_end,
 * step_exp, step_g, discarded, gen_depth and the iteration lists), a chunk of steps per
 * advance(): the chunk's new entries go to scratch buffers and into the arrays in one
 * frombytes each.  This file is the Python type; _core_loops.c the loops, _core.h what they
 * share, _core_position.c the bulk loops of a position's rebuild (a long jump).  The reference loop (tui_search/engine/search/reference.py) is the specification;
 * tests/engine holds this core equal to it, array for array.  Three loops serve every
 * algorithm and choice: a queue or a stack (graph or tree search, either visit rule), iterative
 * deepening, and a priority queue.  Floats are summed in Python's order; the build turns off
 * contraction (-ffp-contract=off), so g and priorities are Python's bit for bit.
 */
#include "_core.h"

#ifndef CORE_SOURCE_HASH
#define CORE_SOURCE_HASH "unknown"
#endif

/* -- the Python type -- */
static int append_bytes(PyObject *arr, Buf *b) {  /* the chunk's entries into the record */
    if (!b->n || arr == Py_None) { b->n = 0; return 0; }
    PyObject *view = PyMemoryView_FromMemory(b->a, b->n, PyBUF_READ);
    if (!view) return -1;
    PyObject *r = PyObject_CallMethod(arr, "frombytes", "O", view);
    Py_DECREF(view);
    b->n = 0;
    if (!r) return -1;
    Py_DECREF(r);
    return 0;
}

/* Steps run between two appends to the record: the scratch buffers stay this small (a few
 * hundred kB, in cache), so a long run's memory is touched once, in the record's own arrays,
 * not first in a scratch buffer as large as the run and then again in the copy (that
 * doubled the page faults: benchmarks/README.md, "core"). */
#define SLICE 65536

static long run_slice(Search *s, Py_ssize_t chunk) {  /* PAUSED, NO_GOAL, the goal's event, -3 */
    Py_buffer view;
    if (PyObject_GetBuffer(s->r_node, &view, PyBUF_SIMPLE) < 0) return -3;
    s->base = view.buf; s->base_n = view.len / (Py_ssize_t)sizeof(int);
    long r;
    if (s->loop != IDDFS && !s->started) {  /* the start alone, when it is the goal */
        s->started = 1;
        if (s->start == s->goal_on_push) { r = 0; goto recorded; }
    }
    if (s->loop == IDDFS) r = core_run_iddfs(s, chunk);
    else if (s->loop == BEST) r = core_run_best(s, chunk);
    else r = core_run_queue(s, chunk);
recorded:
    PyBuffer_Release(&view);
    s->base = NULL; s->base_n = 0;
    if (r == -3) return -3;
    if (PyErr_Occurred() || append_bytes(s->r_node, &s->node) || append_bytes(s->r_end, &s->end)
        || append_bytes(s->r_exp, &s->exp) || append_bytes(s->r_g, &s->gs)
        || append_bytes(s->r_disc, &s->disc) || append_bytes(s->r_depth, &s->depth))
        return -3;
    return r;
}

static PyObject *Search_advance(Search *s, PyObject *arg) {
    Py_ssize_t chunk = PyLong_AsSsize_t(arg);
    if (chunk < 1) { if (!PyErr_Occurred()) PyErr_SetString(PyExc_ValueError, "chunk < 1"); return NULL; }
    long r = PAUSED;
    for (Py_ssize_t stop = s->steps + chunk; r == PAUSED && s->steps < stop;) {
        Py_ssize_t left = stop - s->steps, before = s->steps;
        r = run_slice(s, left < SLICE ? left : SLICE);
        if (r == PAUSED && s->steps == before) break;  /* paused between passes: as called */
    }
    if (r == -3) return NULL;
    if (r != PAUSED) {  /* done: what only a paused search needs goes */
        PyMem_RawFree(s->stack.a); s->stack = (Buf){0};
        PyMem_RawFree(s->parent.a); s->parent = (Buf){0};
    }
    return PyLong_FromLong(r);
}

static void Search_dealloc(Search *s) {
    Buf *bufs[] = {&s->node, &s->end, &s->exp, &s->gs, &s->disc, &s->depth, &s->stack, &s->parent};
    for (size_t i = 0; i < sizeof bufs / sizeof *bufs; i++) PyMem_RawFree(bufs[i]->a);
    PyMem_RawFree(s->closed); PyMem_RawFree(s->best);
    PyMem_RawFree(s->best_depth); PyMem_RawFree(s->stamp);
    if (s->walls_view.obj) PyBuffer_Release(&s->walls_view);
    if (s->terrain_view.obj) PyBuffer_Release(&s->terrain_view);
    PyObject *refs[] = {s->r_node, s->r_end, s->r_exp, s->r_g, s->r_disc, s->r_depth,
                        s->it_first, s->it_root, s->it_limit};
    for (size_t i = 0; i < sizeof refs / sizeof *refs; i++) Py_XDECREF(refs[i]);
    Py_TYPE(s)->tp_free((PyObject *)s);
}

static PyObject *Search_new(PyTypeObject *type, PyObject *args, PyObject *kw) {
    (void)kw;
    Search *s = (Search *)type->tp_alloc(type, 0);
    if (!s) return NULL;
    PyObject *moves, *walls, *terrain;
    if (!PyArg_ParseTuple(args, "iiiiiiiiiiiidOO(OOOOOOOOO)iiiOddd", &s->loop, &s->lifo, &s->tree,
                          &s->visit_expand, &s->use_g, &s->use_h,
                          &s->heuristic, &s->close, &s->refused, &s->stride, &s->start,
                          &s->goal, &s->extra, &walls, &moves, &s->r_node, &s->r_end,
                          &s->r_exp, &s->r_g, &s->r_disc, &s->r_depth, &s->it_first,
                          &s->it_root, &s->it_limit, &s->goal_on_push, &s->goal_on_pop,
                          &s->nmoves, &terrain, &s->scale, &s->cheaper,
                          &s->weight)) {
        s->r_node = s->r_end = s->r_exp = s->r_g = s->r_disc = s->r_depth = NULL;
        s->it_first = s->it_root = s->it_limit = NULL;
        Py_DECREF(s); return NULL;
    }
    PyObject *refs[] = {s->r_node, s->r_end, s->r_exp, s->r_g, s->r_disc, s->r_depth,
                        s->it_first, s->it_root, s->it_limit};
    for (size_t i = 0; i < sizeof refs / sizeof *refs; i++) Py_INCREF(refs[i]);
    if (s->nmoves < 1 || s->nmoves > 8 || PyTuple_Size(moves) != s->nmoves) {
        PyErr_SetString(PyExc_ValueError, "one to eight moves");
        Py_DECREF(s); return NULL;
    }
    for (int i = 0; i < s->nmoves; i++)
        if (!PyArg_ParseTuple(PyTuple_GET_ITEM(moves, i), "iddii", &s->off[i], &s->cost[i],
                              &s->margin[i], &s->side_a[i], &s->side_b[i])) {
            Py_DECREF(s); return NULL;
        }
    if (PyObject_GetBuffer(walls, &s->walls_view, PyBUF_SIMPLE) < 0) { Py_DECREF(s); return NULL; }
    s->walls = s->walls_view.buf; s->ncells = s->walls_view.len;
    if (terrain != Py_None) {
        if (PyObject_GetBuffer(terrain, &s->terrain_view, PyBUF_SIMPLE) < 0) { Py_DECREF(s); return NULL; }
        if (s->terrain_view.len != s->ncells * (Py_ssize_t)sizeof(double)) {
            PyErr_SetString(PyExc_ValueError, "terrain: a double per cell");
            Py_DECREF(s); return NULL;
        }
        s->terrain = s->terrain_view.buf;
    }
    if (core_start(s) < 0) { Py_DECREF(s); return NULL; }
    return (PyObject *)s;
}

/* The peak table's scan (tui_search/engine/run/peak.py): max(ends[j] - j - c for lo <= j < hi). */
static PyObject *largest_size(PyObject *module, PyObject *args) {
    (void)module;
    PyObject *ends;
    Py_ssize_t lo, hi, c;
    if (!PyArg_ParseTuple(args, "Onnn", &ends, &lo, &hi, &c)) return NULL;
    Py_buffer view;
    if (PyObject_GetBuffer(ends, &view, PyBUF_FORMAT) < 0) return NULL;
    if (view.itemsize != sizeof(int) || lo < 0 || hi > view.len / (Py_ssize_t)sizeof(int) || lo >= hi) {
        PyBuffer_Release(&view);
        PyErr_SetString(PyExc_ValueError, "largest_size: an int array and 0 <= lo < hi <= len");
        return NULL;
    }
    const int *e = view.buf;
    Py_ssize_t best = e[lo] - lo - c;
    for (Py_ssize_t j = lo + 1; j < hi; j++)
        if (e[j] - j - c > best) best = e[j] - j - c;
    PyBuffer_Release(&view);
    return PyLong_FromSsize_t(best);
}

static PyMethodDef module_functions[] = {
    {"largest_size", largest_size, METH_VARARGS,
     "largest_size(ends, lo, hi, c): the largest ends[j] - j - c over lo <= j < hi"},
    {NULL}
};

static PyMethodDef Search_methods[] = {
    {"advance", (PyCFunction)Search_advance, METH_O,
     "advance(chunk): record up to chunk more steps; -2 paused, -1 done with no path, "
     "else done with the goal's event"},
    {NULL}
};

static PyTypeObject SearchType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "tui_search.engine.search._core.Search",
    .tp_basicsize = sizeof(Search),
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "One recorded search (built by tui_search.engine.search.loops.compiled).",
    .tp_new = Search_new,
    .tp_dealloc = (destructor)Search_dealloc,
    .tp_methods = Search_methods,
};

extern PyMethodDef core_position_functions[];  /* _core_position.c */

static struct PyModuleDef core_module = {
    PyModuleDef_HEAD_INIT, "_core", "The compiled search core (see _core.c).", -1,
    module_functions, NULL, NULL, NULL, NULL
};

PyMODINIT_FUNC PyInit__core(void) {
    if (PyType_Ready(&SearchType) < 0) return NULL;
    PyObject *m = PyModule_Create(&core_module);
    if (!m) return NULL;
    Py_INCREF(&SearchType);
    if (PyModule_AddFunctions(m, core_position_functions) < 0
        || PyModule_AddObject(m, "Search", (PyObject *)&SearchType) < 0
        || PyModule_AddStringConstant(m, "SOURCE_HASH", CORE_SOURCE_HASH) < 0) {
        Py_DECREF(m); return NULL;
    }
    return m;
}
