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
