"""argparse `type=` converters for numeric command-line options: every subcommand range-checks with these.

A value out of range is an argparse error (exit 2, one line naming the option), raised before any work.
"""

from __future__ import annotations

import argparse
import math


def _number(cast, text: str) -> int | float:
    try:
        v = cast(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected {'an integer' if cast is int else 'a number'}, got {text!r}") from None
    if not math.isfinite(v):
        raise argparse.ArgumentTypeError(f"expected a finite number, got {text!r}")
    return v


def _ranged(cast, ok, why: str):
    """A converter to `cast` that accepts values with ok(v) true and says `why` otherwise."""

    def convert(text: str):
        v = _number(cast, text)
        if not ok(v):
            raise argparse.ArgumentTypeError(f"must be {why}, got {text}")
        return v

    convert.__name__ = "integer" if cast is int else "number"  # argparse's word for the value in its messages
    return convert


def int_at_least(low: int):
    """Integers >= low."""
    return _ranged(int, lambda v: v >= low, f">= {low}")


positive_int = int_at_least(1)
nonneg_int = int_at_least(0)
positive_float = _ranged(float, lambda v: v > 0, "> 0")
unit_float = _ranged(float, lambda v: 0 <= v <= 1, "in [0, 1]")
