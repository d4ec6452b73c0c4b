"""Atomic output files: a file is either its old content or its whole new content, never a truncated one.

    with atomic_open(path, "wb") as f:  np.savez_compressed(f, ...)
    write_text(path, text); write_json(path, obj); write_jsonl(path, rows)

Data goes to a temporary file in the destination's folder (same file system), is flushed to disk, then
`os.replace`d onto the name, so a kill, a full disk or a read-only folder never leaves a half-written
output. On an OSError the temporary file is removed and the error is re-raised naming the destination;
the CLI prints it as one line (exit 2).
"""

from __future__ import annotations

import contextlib
import json
import os
import secrets
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import IO, Any

TMP_SUFFIX = ".tmp"


def named(e: OSError, path: str | Path, tmp: str | Path | None = None) -> OSError:
    """`e` naming `path` where it names no file (a failed write() or fsync()) or only the temporary one."""
    if e.filename is None or (tmp is not None and str(e.filename) == str(tmp)):
        e.filename, e.filename2 = str(path), None
    return e


@contextlib.contextmanager
def atomic_path(path: str | Path) -> Iterator[Path]:
    """A temporary file name beside `path` (with its suffix, for writers that pick a format by it, such as an
    animation encoder); on a clean exit the file written there replaces `path`. Creates missing parent
    folders. Nothing is left behind when the body raises."""
    path = Path(path)
    tmp = path.with_name(f".{path.stem}.{secrets.token_hex(4)}{TMP_SUFFIX}{path.suffix}")
    try:
        path.parent.mkdir(parents=True, exist_ok=True)  # an error here names the folder it could not make
        yield tmp
        os.replace(tmp, path)
    except BaseException as e:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        if isinstance(e, OSError):
            raise named(e, path, tmp) from None
        raise


@contextlib.contextmanager
def atomic_open(path: str | Path, mode: str = "w") -> Iterator[IO[Any]]:
    """Opens a temporary file beside `path` for writing ('w' text in UTF-8, or 'wb'), flushed to disk and
    renamed onto `path` on a clean exit (`atomic_path`)."""
    if mode not in ("w", "wb"):
        raise ValueError(f"atomic_open: mode must be 'w' or 'wb', got {mode!r}")
    with atomic_path(path) as tmp:
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)  # 0o666 & ~umask, as open() would
        with open(fd, mode, **({} if "b" in mode else {"encoding": "utf-8"})) as f:
            yield f
            f.flush()
            os.fsync(f.fileno())


def write_text(path: str | Path, text: str) -> Path:
    """Writes `text` to `path` atomically; returns the path."""
    with atomic_open(path, "w") as f:
        f.write(text)
    return Path(path)


def write_bytes(path: str | Path, data: bytes) -> Path:
    """Writes `data` to `path` atomically; returns the path."""
    with atomic_open(path, "wb") as f:
        f.write(data)
    return Path(path)


def write_json(path: str | Path, obj: Any) -> Path:
    """`obj` as indented JSON (the project's summary.json layout) with a final newline, atomically."""
    return write_text(path, json.dumps(obj, indent=1) + "\n")


def write_jsonl(path: str | Path, rows: Iterable[Any]) -> Path:
    """One JSON document per line, atomically (the file appears only once every row is written)."""
    with atomic_open(path, "w") as f:
        for r in rows:
            f.write(json.dumps(r) + "\n")
    return Path(path)


def save_figure(fig, path: str | Path, **kwargs) -> Path:
    """`fig.savefig` to `path` atomically, the format taken from the suffix (.png, .pdf, .svg)."""
    path = Path(path)
    with atomic_open(path, "wb") as f:
        fig.savefig(f, format=path.suffix.lstrip(".").lower() or None, **kwargs)
    return path
