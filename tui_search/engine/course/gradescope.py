"""Gradescope's ``results.json``: a class report's maps or a student's checked ``search.py``
as the grades Gradescope's autograder uploads (``--gradescope OUT.json``).

The format, from Gradescope's published autograder specification: an object with the whole
submission's ``score`` and ``output``, and ``tests``, each with its ``name``, ``score``,
``max_score``, ``output`` and ``visibility`` (``visible``, ``hidden``, ``after_due_date`` or
``after_published``).  ``tests/data/gradescope_results.schema.json`` is the schema the tests
hold it to.
"""

from __future__ import annotations

__all__ = ["VISIBILITIES", "graded_test", "results", "scored_test"]

VISIBILITIES = ("visible", "hidden", "after_due_date", "after_published")


def graded_test(name: str, passed: bool, output: str, max_score: float = 1.0,
                visibility: str = "visible") -> dict[str, object]:
    """One test: full marks when ``passed``, else none."""
    if visibility not in VISIBILITIES:
        raise ValueError(f"visibility {visibility!r}: use {', '.join(VISIBILITIES)}")
    return {"name": name, "score": max_score if passed else 0.0, "max_score": max_score,
            "status": "passed" if passed else "failed", "output": output,
            "visibility": visibility}


def scored_test(name: str, score: float, max_score: float, output: str,
                visibility: str = "visible") -> dict[str, object]:
    """One test worth ``max_score``, of which ``score`` was earned (a quiz's right answers of
    those asked)."""
    test = graded_test(name, score >= max_score, output, max_score, visibility)
    test["score"] = float(score)
    return test


def results(output: str, tests: list[dict[str, object]]) -> dict[str, object]:
    """The whole ``results.json``: its score the tests' sum."""
    total = 0.0
    for test in tests:
        score = test["score"]
        assert isinstance(score, float)
        total += score
    return {"score": total, "output": output, "visibility": "visible",
            "stdout_visibility": "hidden", "tests": tests}
