"""Names that become file names (scene names, name prefixes, episode ids) and paths that must stay in a folder.

A safe name is one path component: not empty, not '.' or '..', no '/' or '\\', no control characters, at most
MAX_NAME characters (room for a suffix within the usual 255-byte limit). Loaders check names with
`name_problem` where they read them, so a bad name is a one-line error naming the file or config key;
`inside` checks a finished output path as well.
"""

from __future__ import annotations

from pathlib import Path

from ragnav_jax.errors import UserError

MAX_NAME = 200


def name_problem(name: object) -> str | None:
    """Why `name` cannot be a file name (one short phrase), or None when it can."""
    if not isinstance(name, str) or not name:
        return "must be a non-empty string"
    if name in (".", ".."):
        return f"{name!r} is not a file name"
    if "/" in name or "\\" in name:
        return f"{name!r} holds a path separator (one file name only)"
    if any(ord(c) < 32 or ord(c) == 127 for c in name):
        return f"{name!r} holds control characters"
    if len(name) > MAX_NAME:
        return f"is {len(name)} characters long (at most {MAX_NAME})"
    return None


def inside(root: str | Path, path: str | Path) -> Path:
    """`path`, after checking that it resolves to a location inside folder `root`; else UserError."""
    root, path = Path(root).resolve(), Path(path)
    if not path.resolve().is_relative_to(root):
        raise UserError(f"{path}: output path outside its run folder {root}")
    return path
