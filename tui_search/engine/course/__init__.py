"""The course: exercises, their ``solved`` conditions, lessons, and the class's records.

* :mod:`~tui_search.engine.course.presets`: a course's choices in one word (``cs188``);
* :mod:`~tui_search.engine.course.autograder_files`: the CS188 autograder's ``.test`` and
  ``.solution`` files, read;
* :mod:`~tui_search.engine.course.autograder_check`: a course test run in the course's words;
* :mod:`~tui_search.engine.course.gradescope`: grades as Gradescope's ``results.json``;
* :mod:`~tui_search.engine.course.exercise_file`: a teacher's exercise file;
* :mod:`~tui_search.engine.course.toml_places`: a key's line and column in its TOML text;
* :mod:`~tui_search.engine.course.graph_exercise`: an exercise on a graph: its rules and edits;
* :mod:`~tui_search.engine.course.condition`: the ``solved`` condition's small language;
* :mod:`~tui_search.engine.course.grading`: an exercise graded on a map;
* :mod:`~tui_search.engine.course.lesson`: a lesson's sections;
* :mod:`~tui_search.engine.course.records`: what each student did, written and read;
* :mod:`~tui_search.engine.course.class_table`: the records as a class's table.
"""
