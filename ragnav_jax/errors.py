"""User-facing errors: the CLI prints their message and exits with code 2, never a traceback."""

from __future__ import annotations


class UserError(Exception):
    """An error caused by the user's input (file, config, command line); exit code 2."""

    exit_code = 2


class ConfigError(UserError):
    """A config file or a dotted override is invalid; the message names the key."""


class SceneError(UserError):
    """A scene file is invalid; the message names the file and the JSON path of the problem."""

    def __init__(self, source: str, path: str, problem: str):
        self.source, self.path, self.problem = source, path, problem
        super().__init__(f"{source}: {path}: {problem}")


def printable(text: str, keep_newlines: bool = False) -> str:
    """`text` safe to print to a terminal: control characters (ANSI escape sequences among them) become
    visible escapes (\\x1b, \\n, ...), so user text echoed back can neither style nor move the cursor, and
    a one-line message stays one line. `keep_newlines` keeps line breaks of multi-line output."""
    keep = "\n" if keep_newlines else ""
    return "".join(c if c.isprintable() or c in keep else repr(c)[1:-1] for c in str(text))


def os_error_message(e: OSError) -> str:
    """One line for an OSError that reached the CLI: the path, then the system's reason and a hint."""
    import errno

    path = e.filename if e.filename is not None else ""
    reason = e.strerror or e.__class__.__name__
    hint = {
        errno.EEXIST: " (a file stands where a folder is needed: choose another --out)",
        errno.ENOTDIR: " (a file stands where a folder is expected)",
        errno.ENOSPC: " (free some space and run again)",
    }.get(e.errno, "")
    return f"{path}: {reason}{hint}" if path else f"{reason}{hint}"
