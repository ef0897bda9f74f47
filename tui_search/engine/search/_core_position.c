/* The compiled core's part of reading a record: the bulk loops of a position's rebuild (a long
 * jump; tui_search/engine/run/rebuild.py holds their Python twins) and the walk up an event's
 * parents (EventTree.ancestors in tui_search/engine/run/queries.py); tests/engine holds each equal
 * to its Python twin, array for array.  They take the record's arrays and a position's
 * per-cell counters as int arrays (any buffer of C ints); events are given as an int array or
 * a range.  Every index is checked: a bad one raises IndexError, nothing is written out of
 * bounds. */
#include "_core.h"

typedef struct { Py_buffer view; int *a; Py_ssize_t n; } Ints;

static int ints(PyObject *obj, Ints *out, int writable) {
    if (PyObject_GetBuffer(obj, &out->view, PyBUF_FORMAT | (writable ? PyBUF_WRITABLE : 0)) < 0)
        return -1;
    if (out->view.itemsize != sizeof(int) || !out->view.format
        || (strcmp(out->view.format, "i") && strcmp(out->view.format, "@i"))) {
        PyBuffer_Release(&out->view);
        PyErr_SetString(PyExc_TypeError, "an array of C ints ('i') expected");
        return -1;
    }
    out->a = out->view.buf;
    out->n = out->view.len / (Py_ssize_t)sizeof(int);
    return 0;
}

/* Events given as a range (step 1) or an int array: [lo, hi) of a range, or the array. */
typedef struct { Ints arr; int is_range; Py_ssize_t lo, hi; } Events;

static int events(PyObject *obj, Events *out) {
    out->is_range = PyRange_Check(obj);
    if (!out->is_range) {
        if (ints(obj, &out->arr, 0) < 0) return -1;
        out->lo = 0; out->hi = out->arr.n;
        return 0;
    }
    PyObject *start = PyObject_GetAttrString(obj, "start"), *stop = PyObject_GetAttrString(obj, "stop"),
             *step = PyObject_GetAttrString(obj, "step");
    int ok = start && stop && step;
    if (ok) {
        out->lo = PyLong_AsSsize_t(start); out->hi = PyLong_AsSsize_t(stop);
        ok = !PyErr_Occurred() && PyLong_AsLong(step) == 1;
        if (ok && out->hi < out->lo) out->hi = out->lo;
    }
    Py_XDECREF(start); Py_XDECREF(stop); Py_XDECREF(step);
    if (!ok && !PyErr_Occurred()) PyErr_SetString(PyExc_ValueError, "a range of step 1 expected");
    return ok ? 0 : -1;
}

static inline Py_ssize_t event_at(const Events *e, Py_ssize_t i) {
    return e->is_range ? i : e->arr.a[i];
}

static void release(Events *e) { if (!e->is_range) PyBuffer_Release(&e->arr.view); }

static PyObject *bad_index(void) {
    PyErr_SetString(PyExc_IndexError, "an event or a cell out of range");
    return NULL;
}

/* count_generated(gen_node, lo, hi, n_gen, latest): for each event g in lo .. hi - 1, in
 * order, its cell's n_gen += 1 and latest = g. */
static PyObject *count_generated(PyObject *module, PyObject *args) {
    (void)module;
    PyObject *o_node, *o_gen, *o_last;
    Py_ssize_t lo, hi;
    if (!PyArg_ParseTuple(args, "OnnOO", &o_node, &lo, &hi, &o_gen, &o_last)) return NULL;
    Ints node, gen, last;
    if (ints(o_node, &node, 0) < 0) return NULL;
    if (ints(o_gen, &gen, 1) < 0) { PyBuffer_Release(&node.view); return NULL; }
    if (ints(o_last, &last, 1) < 0) {
        PyBuffer_Release(&node.view); PyBuffer_Release(&gen.view); return NULL;
    }
    int ok = 0 <= lo && lo <= hi && hi <= node.n && hi <= INT_MAX;
    for (Py_ssize_t g = lo; ok && g < hi; g++) {
        int p = node.a[g];
        if (p < 0 || p >= gen.n || p >= last.n) { ok = 0; break; }
        gen.a[p]++;
        last.a[p] = (int)g;
    }
    PyBuffer_Release(&node.view); PyBuffer_Release(&gen.view); PyBuffer_Release(&last.view);
    if (!ok) return bad_index();
    Py_RETURN_NONE;
}

/* count_expanded(gen_node, events, n_exp): for each event g of events (an int array or a
 * range), its cell's n_exp += 1. */
static PyObject *count_expanded(PyObject *module, PyObject *args) {
    (void)module;
    PyObject *o_node, *o_events, *o_exp;
    if (!PyArg_ParseTuple(args, "OOO", &o_node, &o_events, &o_exp)) return NULL;
    Ints node, exp;
    Events ev;
    if (ints(o_node, &node, 0) < 0) return NULL;
    if (events(o_events, &ev) < 0) { PyBuffer_Release(&node.view); return NULL; }
    if (ints(o_exp, &exp, 1) < 0) { PyBuffer_Release(&node.view); release(&ev); return NULL; }
    int ok = 1;
    for (Py_ssize_t i = ev.lo; i < ev.hi; i++) {
        Py_ssize_t g = event_at(&ev, i);
        int p;
        if (g < 0 || g >= node.n || (p = node.a[g]) < 0 || p >= exp.n) { ok = 0; break; }
        exp.a[p]++;
    }
    PyBuffer_Release(&node.view); PyBuffer_Release(&exp.view); release(&ev);
    if (!ok) return bad_index();
    Py_RETURN_NONE;
}

/* clear_events(flags, events, root): flags[g - root] = 0 for each event g of events (an int
 * array or a range); flags is a bytearray. */
static PyObject *clear_events(PyObject *module, PyObject *args) {
    (void)module;
    PyObject *o_flags, *o_events;
    Py_ssize_t root;
    if (!PyArg_ParseTuple(args, "OOn", &o_flags, &o_events, &root)) return NULL;
    Py_buffer flags;
    Events ev;
    if (PyObject_GetBuffer(o_flags, &flags, PyBUF_WRITABLE) < 0) return NULL;
    if (events(o_events, &ev) < 0) { PyBuffer_Release(&flags); return NULL; }
    unsigned char *f = flags.buf;
    int ok = 1;
    for (Py_ssize_t i = ev.lo; i < ev.hi; i++) {
        Py_ssize_t at = event_at(&ev, i) - root;
        if (at < 0 || at >= flags.len) { ok = 0; break; }
        f[at] = 0;
    }
    PyBuffer_Release(&flags); release(&ev);
    if (!ok) return bad_index();
    Py_RETURN_NONE;
}

/* open_events(flags, root, lo, hi): the events g in lo .. hi - 1 whose flags[g - root] is not
 * 0, in order, as a list. */
static PyObject *open_events(PyObject *module, PyObject *args) {
    (void)module;
    PyObject *o_flags;
    Py_ssize_t root, lo, hi;
    if (!PyArg_ParseTuple(args, "Onnn", &o_flags, &root, &lo, &hi)) return NULL;
    Py_buffer flags;
    if (PyObject_GetBuffer(o_flags, &flags, PyBUF_SIMPLE) < 0) return NULL;
    if (hi < lo) hi = lo;
    if (lo - root < 0 || hi - root > flags.len) { PyBuffer_Release(&flags); return bad_index(); }
    const unsigned char *f = flags.buf;
    PyObject *out = PyList_New(0);
    for (Py_ssize_t g = lo; out && g < hi; g++) {
        if (!f[g - root]) continue;
        PyObject *event = PyLong_FromSsize_t(g);
        if (!event || PyList_Append(out, event) < 0) Py_CLEAR(out);
        Py_XDECREF(event);
    }
    PyBuffer_Release(&flags);
    return out;
}

/* ancestors(step_end, step_exp, root, g): the events from root down to g, each the parent of
 * the next: the event expanded (step_exp[k], or k - 1 where step_exp is None: a queue's) by
 * the step k that generated it, the first k with step_end[k] > g. */
static PyObject *ancestors(PyObject *module, PyObject *args) {
    (void)module;
    PyObject *o_end, *o_exp;
    Py_ssize_t root, g;
    if (!PyArg_ParseTuple(args, "OOnn", &o_end, &o_exp, &root, &g)) return NULL;
    PyObject *chain = PyList_New(0);
    if (!chain || g < 0) return chain;
    Ints end, exp = {0};
    if (ints(o_end, &end, 0) < 0) { Py_DECREF(chain); return NULL; }
    if (o_exp != Py_None && ints(o_exp, &exp, 0) < 0) {
        PyBuffer_Release(&end.view); Py_DECREF(chain); return NULL;
    }
    int ok = 1;
    for (;;) {
        PyObject *event = PyLong_FromSsize_t(g);
        if (!event || PyList_Append(chain, event) < 0) { Py_XDECREF(event); ok = -1; break; }
        Py_DECREF(event);
        if (g <= root) { ok = g == root; break; }
        Py_ssize_t lo = 0, hi = end.n;  /* the first k with end[k] > g */
        while (lo < hi) {
            Py_ssize_t mid = lo + (hi - lo) / 2;
            if (end.a[mid] > g) hi = mid; else lo = mid + 1;
        }
        if (lo >= end.n || lo < 1 || (o_exp != Py_None && lo >= exp.n)) { ok = 0; break; }
        g = o_exp == Py_None ? lo - 1 : exp.a[lo];
    }
    PyBuffer_Release(&end.view);
    if (o_exp != Py_None) PyBuffer_Release(&exp.view);
    if (ok == 1 && PyList_Reverse(chain) == 0) return chain;
    Py_DECREF(chain);
    return ok ? NULL : bad_index();
}

PyMethodDef core_position_functions[] = {
    {"count_generated", count_generated, METH_VARARGS,
     "count_generated(gen_node, lo, hi, n_gen, latest): each event's cell counted, in order"},
    {"count_expanded", count_expanded, METH_VARARGS,
     "count_expanded(gen_node, events, n_exp): each expanded event's cell counted"},
    {"clear_events", clear_events, METH_VARARGS,
     "clear_events(flags, events, root): flags[g - root] = 0 for each event g"},
    {"open_events", open_events, METH_VARARGS,
     "open_events(flags, root, lo, hi): the events g in lo .. hi - 1 with flags[g - root] set"},
    {"ancestors", ancestors, METH_VARARGS,
     "ancestors(step_end, step_exp, root, g): the events from root down to g"},
    {NULL}
};
