"""Builds the optional compiled search core, ``tui_search/engine/search/_core*.c`` (the rest of the
package's metadata is in pyproject.toml).

The extension is optional: where it does not build (no C compiler) ``pip install`` warns and
the app runs its Python search loops (:mod:`tui_search.engine.search.loops.compiled` says which core
runs).  The build embeds the source's fingerprint (the CRC-32 and total size of its four
files, as :func:`tui_search.engine.search.loops.compiled.source_hash` takes it), so an editable
install whose C source changed since is seen as stale.  Floats must sum as Python's do: no
contraction into fused multiply-adds (``-ffp-contract=off``; ``/fp:strict`` under MSVC).
"""

from __future__ import annotations

import zlib
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ENGINE = Path(__file__).parent / "tui_search" / "engine" / "search"
#: The C source, in the order hashed; the header last (it is no compiled source).
SOURCES = ("_core.c", "_core_loops.c", "_core_position.c", "_core.h")


class BuildExt(build_ext):
    """The compiler's flags for exact floats, chosen once the compiler is known."""

    def build_extensions(self) -> None:
        msvc = self.compiler.compiler_type == "msvc"
        for ext in self.extensions:
            ext.extra_compile_args = ["/O2", "/fp:strict"] if msvc else ["-O2",
                                                                         "-ffp-contract=off"]
        super().build_extensions()


source = b"".join((ENGINE / name).read_bytes() for name in SOURCES)
digest = f"crc32:{zlib.crc32(source):08x}:{len(source)}"
setup(
    ext_modules=[Extension("tui_search.engine.search._core",
                           [f"tui_search/engine/search/{name}" for name in SOURCES[:-1]],
                           depends=[f"tui_search/engine/search/{SOURCES[-1]}"], optional=True,
                           define_macros=[("CORE_SOURCE_HASH", f'"{digest}"')])],
    cmdclass={"build_ext": BuildExt},
)
