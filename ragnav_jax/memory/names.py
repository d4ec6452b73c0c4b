"""Names the memory learnt mean the same thing: aliases from the captions of each object's views.

The verifier (evaluation/verify.py) checks a goal's head noun against an object's names and aliases; retrieval
(retrieval/index.py) ranks a time-indexed query among the instances that go by the head noun.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence


def name_classes(recorded_names: dict[int, Sequence[str]], share: float = 0.15) -> tuple[dict, dict]:
    """Names that mean the same thing, learnt from the memory: (name -> frozenset of its aliases, object ->
    its frequent names). Names said at least twice and for at least `share` of one instance's views are
    aliases ('houseplant' and 'potted plant'). A name said rarely joins nothing, but where no object goes
    by it frequently it means what the objects it was said of go by ('cot', said once of a crib, means
    the cribs); a rare confusion with a name other objects go by ('chair' for an armchair once) means
    only itself."""
    parent: dict[str, str] = {}

    def find(x: str) -> str:
        while parent.setdefault(x, x) != x:
            x = parent[x]
        return x

    frequent = {}
    for i, ns in recorded_names.items():
        cnt = Counter(n.lower() for n in ns)
        frequent[i] = [x for x, k in cnt.items() if k >= 2 and k >= share * len(ns)] or list(cnt)
        for x in frequent[i]:
            parent[find(x)] = find(frequent[i][0])
    groups: dict[str, set[str]] = {}
    for x in list(parent):
        groups.setdefault(find(x), set()).add(x)
    out = {x: frozenset(groups[find(x)]) for x in parent}
    rare: dict[str, set[str]] = {}
    for i, ns in recorded_names.items():
        for x in {n.lower() for n in ns} - set(frequent[i]) - set(parent):
            rare.setdefault(x, {x}).update(out[frequent[i][0]])
    return {**out, **{x: frozenset(ys) for x, ys in rare.items()}}, frequent


def alias_sets(recorded_names: dict[int, Sequence[str]], classes: dict, frequent: dict) -> dict[int, tuple[str, ...]]:
    """Every name an object goes by: its recorded names and the aliases of its frequent ones (classes,
    frequent: `name_classes(recorded_names)`)."""
    return {i: tuple(sorted({n.lower() for n in ns} | {y for x in frequent[i] for y in classes[x]}))
            for i, ns in recorded_names.items()}
