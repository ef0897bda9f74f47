"""Writing a file atomically, and saying in a few words why an OS call on a file failed.

Saving a map and saving the app's config file both replace the file this way, so a crash or a
full disk never leaves half a file; the file keeps its permissions, owner and group, a symlink
stays a link, and what a killed save left behind is cleaned up at the next one.  Writing in
place (for a file with hard links, which a rename would split) is here too.  Stdlib only.
"""

from __future__ import annotations

import os
import re
import stat
import time

__all__ = [
    "STALE_TEMP_SECONDS",
    "os_reason",
    "remove_stale_temps",
    "write_atomically",
    "write_in_place",
]


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


#: A temporary file of :func:`write_atomically` untouched for this long is left over from a
#: save that was killed (a live save writes, fsyncs and renames it within moments).
STALE_TEMP_SECONDS = 30.0


def _temp_pattern(base: str) -> re.Pattern[str]:
    """The names of this module's temporary files for a target named ``base``, exactly."""
    return re.compile(rf"\.{re.escape(base)}\.[0-9a-f]{{8}}\.tmp")


def remove_stale_temps(target: str, now: float | None = None) -> list[str]:
    """Remove the temporary files a killed :func:`write_atomically` of ``target`` left beside
    it: regular files named exactly ``.NAME.XXXXXXXX.tmp`` (8 hex digits) and older than
    :data:`STALE_TEMP_SECONDS`; nothing else.  Best effort; returns the names removed."""
    folder, base = os.path.split(os.path.abspath(target))
    pattern = _temp_pattern(base)
    limit = (time.time() if now is None else now) - STALE_TEMP_SECONDS
    removed: list[str] = []
    try:
        entries = list(os.scandir(folder))
    except OSError:
        return removed
    for entry in entries:
        if not pattern.fullmatch(entry.name):
            continue
        try:
            st = entry.stat(follow_symlinks=False)
            if stat.S_ISREG(st.st_mode) and st.st_mtime < limit:
                os.unlink(entry.path)
                removed.append(entry.name)
        except OSError:
            continue
    return removed


def write_atomically(target: str, data: bytes) -> None:
    """Replace ``target`` by ``data``: readers (and a crash) see the old file or the new one,
    never half of one.  A temporary file beside the target is written, fsynced and renamed
    over the target, keeping the target's permissions, and its owner and group where the
    process may set them.  A symlink is followed: its target is replaced and the link stays.
    Stale temporary files of an earlier, killed write are removed first
    (:func:`remove_stale_temps`).  On failure the temporary file is removed, the old file is
    untouched, and the OSError propagates."""
    target = os.path.realpath(target)
    folder = os.path.dirname(target)
    remove_stale_temps(target)
    try:
        old: os.stat_result | None = os.stat(target)
    except OSError:
        old = None
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
            if old is not None:
                _keep_owner_and_mode(handle.fileno(), old)
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


def write_in_place(target: str, data: bytes) -> None:
    """Overwrite the file ``target`` with ``data`` where it is (write, truncate, fsync), so
    that its hard links keep sharing it.  Not atomic: a crash may leave half a file."""
    fd = os.open(target, os.O_WRONLY)
    with os.fdopen(fd, "wb") as handle:
        handle.write(data)
        handle.truncate(len(data))
        handle.flush()
        os.fsync(handle.fileno())


def _keep_owner_and_mode(fd: int, old: os.stat_result) -> None:
    """Give the new file the old one's owner and group (or its group alone, or neither: as
    far as the process may), then its permissions (after: a chown may clear set-id bits)."""
    if hasattr(os, "fchown"):
        new = os.fstat(fd)
        for uid, gid in ((old.st_uid, old.st_gid), (-1, old.st_gid)):
            if (new.st_uid, new.st_gid) == (old.st_uid, old.st_gid):
                break
            try:
                os.fchown(fd, uid, gid)
                break
            except OSError:  # not allowed (PermissionError), or not on this filesystem
                continue
    if hasattr(os, "fchmod"):
        os.fchmod(fd, stat.S_IMODE(old.st_mode))


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
