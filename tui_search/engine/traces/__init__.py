"""Another program's search trace: read, checked against a search, diagnosed, replayed.

* :mod:`~tui_search.engine.traces.read`: reading a trace;
* :mod:`~tui_search.engine.traces.check`: a trace against one search, step by step;
* :mod:`~tui_search.engine.traces.meeting`: a trace against a bidirectional search, its
  stopping rule included; without ``-a``, a trace that looks bidirectional diagnosed with
  the bidirectional searches too;
* :mod:`~tui_search.engine.traces.differences`: where a trace parts from a search, and why;
* :mod:`~tui_search.engine.traces.causes`: the causes named, their codes, whom they speak of, and
  the difference that carries one;
* :mod:`~tui_search.engine.traces.ties`: a tie of the priority taken another way;
* :mod:`~tui_search.engine.traces.diagnose`: which searches a trace matches longest;
* :mod:`~tui_search.engine.traces.orders`: the move orders a trace allows (a bidirectional
  one's too);
* :mod:`~tui_search.engine.traces.posthoc`: Posthoc's trace format, read and written;
* :mod:`~tui_search.engine.traces.hand`: a search stepped by hand, each step checked;
* :mod:`~tui_search.engine.traces.as_run`: a trace as a run like any other;
* :mod:`~tui_search.engine.traces.replay`: a trace beside its search, for ``--replay``;
* :mod:`~tui_search.engine.traces.student_search`: a student's search.py's problem, its calls
  as a trace;
* :mod:`~tui_search.engine.traces.sandbox`: a student's search.py run in a fenced process;
* :mod:`~tui_search.engine.traces.sandbox_child`: the fenced process's side (a script);
* :mod:`~tui_search.engine.traces.course_util`: the ``util`` module a search.py imports there.
"""
