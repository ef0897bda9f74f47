"""The course: exercises, their ``solved`` conditions, and lessons.

* :mod:`~tui_search.engine.course.exercise_file`: a teacher's exercise file;
* :mod:`~tui_search.engine.course.condition`: the ``solved`` condition's small language;
* :mod:`~tui_search.engine.course.grading`: an exercise graded on a map;
* :mod:`~tui_search.engine.course.lesson`: a lesson's sections.
"""
