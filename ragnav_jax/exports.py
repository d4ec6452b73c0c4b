"""Lazy re-exports: a subpackage names its public API in `__init__` without importing its modules.

    __getattr__, __dir__, __all__ = lazy_exports(__name__, {"parse_instruction": "parser", ...})

`from ragnav_jax.language import parse_instruction` then imports `ragnav_jax.language.parser` on first
use, so `import ragnav_jax.language.commands` (the CLI's start) stays as light as before.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable


def lazy_exports(package: str, names: dict[str, str]) -> tuple[Callable[[str], object], Callable[[], list[str]], list[str]]:
    """(__getattr__, __dir__, __all__) for `package`: each name in `names` is taken from the submodule it maps to."""

    def __getattr__(name: str) -> object:
        if name not in names:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        return getattr(importlib.import_module(f"{package}.{names[name]}"), name)

    def __dir__() -> list[str]:
        return sorted(names)

    return __getattr__, __dir__, sorted(names)
