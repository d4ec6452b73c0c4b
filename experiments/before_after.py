"""Success of each method on episode sets run before and after a change, paired episode by episode.

    .venv/bin/python experiments/before_after.py "J (48)=runs/J-before,runs/J-after" "K (24)=runs/K-before,runs/K-after"

Each argument is NAME=BEFORE_RUN,AFTER_RUN (`ragnav eval --out` folders over the same episodes); each cell reads
"before -> after (episodes won / lost, exact two-sided sign test p)". Prints a markdown table.
"""

from __future__ import annotations

import argparse
import json
import sys
from math import comb
from pathlib import Path

METHODS = [("ragnav", "**RAGNav**"), ("etpnav", "ETPNav-style"), ("graphrag", "GraphRAG-style"),
           ("lightrag", "LightRAG-style"), ("naive_rag", "NaiveRAG-style"), ("remembr", "ReMEmbR-style"),
           ("oracle", "Oracle (reads no instruction)")]


class InputError(Exception):
    """A run folder or argument that cannot be read; the message names it."""


def successes(run: str, method: str) -> dict[str, bool] | None:
    """{episode id: success} of a method in an eval run folder (None where the run did not evaluate it)."""
    path = Path(run) / "eval" / method / "episodes.jsonl"
    if not Path(run).is_dir():
        raise InputError(f"{run}: no such run folder")
    if not path.is_file():
        return None
    out = {}
    for k, line in enumerate(path.read_text().splitlines(), 1):
        try:
            row = json.loads(line)
            out[row["episode"]] = bool(row["success"])
        except (json.JSONDecodeError, KeyError, TypeError):
            raise InputError(f"{path}:{k}: not an episode row with 'episode' and 'success'") from None
    return out


def sign_p(won: int, lost: int) -> float:
    """Exact two-sided sign test of won against lost pairs."""
    n, k = won + lost, min(won, lost)
    return 1.0 if n == 0 else min(1.0, 2 * sum(comb(n, i) for i in range(k + 1)) / 2**n)


def cell(before: dict[str, bool], after: dict[str, bool], where: str) -> str:
    if set(before) != set(after):
        raise InputError(f"{where}: the two runs hold different episodes")
    won = sum(after[e] and not before[e] for e in after)
    lost = sum(before[e] and not after[e] for e in after)
    sb, sa = sum(before.values()) / len(before), sum(after.values()) / len(after)
    return f"{sb:.3f} -> {sa:.3f} ({won} / {lost}, p {sign_p(won, lost):.2g})"


def table(sets: list[tuple[str, str, str]]) -> str:
    out = ["| method | " + " | ".join(n for n, _, _ in sets) + " |", "|---|" + "---|" * len(sets)]
    for m, label in METHODS:
        cells = []
        for name, b, a in sets:
            before, after = successes(b, m), successes(a, m)
            cells.append("-" if before is None or after is None or not before else cell(before, after, f"{name}, {m}"))
        if any(c != "-" for c in cells):
            out.append(f"| {label} | " + " | ".join(cells) + " |")
    return "\n".join(out)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("sets", nargs="+", metavar="NAME=BEFORE_RUN,AFTER_RUN")
    a = ap.parse_args(argv)
    try:
        sets = []
        for arg in a.sets:
            name, sep, runs = arg.partition("=")
            pair = runs.split(",")
            if not sep or len(pair) != 2 or not all(pair):
                raise InputError(f"{arg!r}: expected NAME=BEFORE_RUN,AFTER_RUN")
            sets.append((name, *pair))
        print(table(sets))
    except (InputError, OSError) as e:
        print(f"before_after: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
