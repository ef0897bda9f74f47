"""Timing: interleaved repeats, medians, paired ratios and spreads.

The machine is shared and noisy, so every figure is a median of repeats interleaved with its
baseline's, and a ratio is the median of per-repeat ratios (see README.md here).
"""

from __future__ import annotations

import gc
import statistics
import time
from collections.abc import Callable

#: A clock: seconds as a float.  ``time.perf_counter`` (wall) by default; the choices section
#: uses ``time.process_time`` (see ``CPU``).
Clock = Callable[[], float]
#: The CPU time of this process: for single-threaded, CPU-bound searches on a shared machine
#: with more runnable processes than CPUs, the wall clock also counts the waits for a CPU.
CPU: Clock = time.process_time


def timed(fn: Callable[[], object], clock: Clock = time.perf_counter) -> tuple[float, object]:
    gc.collect()
    t = clock()
    result = fn()
    return clock() - t, result


#: A timed sample lasts at least this long: a shorter call is repeated inside the sample.
MIN_SAMPLE = 0.05


def interleaved(fns: dict[str, Callable[[], object]], repeats: int,
                clock: Clock = time.perf_counter) -> dict[str, list[float]]:
    """Seconds per call of each function, ``repeats`` samples each, round-robin, so a slow
    patch of the machine hits every contender alike.  A call shorter than MIN_SAMPLE is
    repeated within its sample (the number fixed by a first, untimed-for-results call)."""
    number = {}
    for name, fn in fns.items():
        dt, result = timed(fn, clock)
        del result
        number[name] = max(1, min(200, round(MIN_SAMPLE / max(dt, 1e-6))))
    out: dict[str, list[float]] = {name: [] for name in fns}
    for _ in range(repeats):
        for name, fn in fns.items():
            n = number[name]
            if n == 1:
                dt, result = timed(fn, clock)
                del result
            else:
                gc.collect()
                t = clock()
                for _ in range(n):
                    fn()
                dt = (clock() - t) / n
            out[name].append(dt)
    return out


def med(xs: list[float]) -> float:
    return statistics.median(xs)


def paired(xs: list[float], base: list[float]) -> float:
    """The median of the per-repeat ratios: each repeat's pair ran back to back (interleaved),
    so a slow patch of the shared machine mostly cancels out."""
    return med([x / b for x, b in zip(xs, base, strict=True)])


def spread(xs: list[float]) -> float:
    """(max - min) / median: how noisy the repeats were."""
    return (max(xs) - min(xs)) / med(xs) if len(xs) > 1 and med(xs) > 0 else 0.0


def fmt_time(xs: list[float] | float) -> str:
    if isinstance(xs, float):
        xs = [xs]
    m = med(xs)
    text = f"{m * 1e3:.3g} ms" if m < 1 else f"{m:.3g} s"
    if len(xs) > 1:
        text += f" ±{spread(xs) * 100:.0f}%"
    return text


NOISE: list[tuple[str, float]] = []  # (what, spread) of every timed series, for the summary


def series(name: str, xs: list[float]) -> list[float]:
    if len(xs) > 1:
        NOISE.append((name, spread(xs)))
    return xs
