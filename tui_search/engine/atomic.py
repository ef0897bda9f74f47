"""Writing a file atomically, and saying in a few words why an OS call on a file failed.

Saving a map and saving the app's config file both replace the file this way, so a crash or a
full disk never leaves half a file.  Stdlib only.
"""

from __future__ import annotations

import os
import stat

__all__ = ["os_reason", "write_atomically"]


def os_reason(err: OSError) -> str:
    """A short lower-case reason for an OS error, without the path (the message names it)."""
    if isinstance(err, FileNotFoundError):
        return "no such file"
    if isinstance(err, PermissionError):
        return "permission denied"
    if isinstance(err, IsADirectoryError):
        return "is a directory"
    if isinstance(err, NotADirectoryError):
        return "a part of the path is not a directory"
    reason = err.strerror or str(err) or type(err).__name__
    return reason[:1].lower() + reason[1:]


def write_atomically(target: str, data: bytes) -> None:
    """Replace ``target`` by ``data``: readers (and a crash) see the old file or the new one,
    never half of one.  A temporary file beside the target is written, fsynced and renamed
    over the target (keeping the target's permissions).  On failure the temporary file is
    removed, the old file is untouched, and the OSError propagates."""
    folder = os.path.dirname(os.path.abspath(target))
    try:
        old_mode: int | None = stat.S_IMODE(os.stat(target).st_mode)
    except OSError:
        old_mode = None
    tmp = ""  # set once the temporary file exists, cleared once it has been renamed
    try:
        # os.open with 0o666 applies the umask like any new file (mkstemp would make it
        # private); O_EXCL so that another writer's temporary file is never reused.
        for _ in range(100):
            name = os.path.join(folder, f".{os.path.basename(target)}.{os.urandom(4).hex()}.tmp")
            try:
                fd = os.open(name, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
            except FileExistsError:
                continue
            tmp = name
            break
        else:  # pragma: no cover - 100 random clashes in a row
            raise FileExistsError("could not pick a temporary file name")
        with os.fdopen(fd, "wb") as handle:
            if old_mode is not None and hasattr(os, "fchmod"):
                os.fchmod(handle.fileno(), old_mode)
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(tmp, target)
        tmp = ""
    finally:
        if tmp:
            try:
                os.unlink(tmp)
            except OSError:
                pass
    _fsync_dir(folder)


def _fsync_dir(folder: str) -> None:
    """Make the rename itself durable; best effort (not every OS or filesystem allows it)."""
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)
