"""Builds the optional compiled search core, ``tui_search/engine/_core.c`` (the rest of the
package's metadata is in pyproject.toml).

The extension is optional: where it does not build (no C compiler) ``pip install`` warns and
the app runs its Python search loops (:mod:`tui_search.engine.loops.compiled` says which core
runs).  The build embeds the source's SHA-256, so an editable install whose ``_core.c`` changed
since is seen as stale.  Floats must sum as Python's do: no contraction into fused
multiply-adds (``-ffp-contract=off``; ``/fp:strict`` under MSVC).
"""

from __future__ import annotations

import hashlib
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = "tui_search/engine/_core.c"


class BuildExt(build_ext):
    """The compiler's flags for exact floats, chosen once the compiler is known."""

    def build_extensions(self) -> None:
        msvc = self.compiler.compiler_type == "msvc"
        for ext in self.extensions:
            ext.extra_compile_args = ["/O2", "/fp:strict"] if msvc else ["-O2",
                                                                         "-ffp-contract=off"]
        super().build_extensions()


digest = hashlib.sha256((Path(__file__).parent / SOURCE).read_bytes()).hexdigest()
setup(
    ext_modules=[Extension("tui_search.engine._core", [SOURCE], optional=True,
                           define_macros=[("CORE_SOURCE_HASH", f'"{digest}"')])],
    cmdclass={"build_ext": BuildExt},
)
