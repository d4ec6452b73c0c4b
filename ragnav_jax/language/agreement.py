"""Parse agreement: how often the parser reads back exactly what the episode generator wrote.

    report = parse_agreement(pairs)          # pairs: [GeneratedEpisode]; report["rate"] in [0, 1]

Compared per instruction: the order type, the number of subgoals and, per subgoal, the target (head,
phrase, attribute words, relations with their nested anchors), the room, the location hint, the
sensor constraints (reading, comparator, value, unit) and the dependencies. The free `text` span is
not compared.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable, Sequence

from ragnav_jax.language.types import ParseError, Subgoal, Target, TaskChain


def _target_key(t: Target) -> tuple:
    words = tuple(sorted(" ".join(t.attributes).split()))
    return (t.head, t.phrase, words, tuple((r.type, _target_key(r.anchor)) for r in t.relations))


def _close(a: float | None, b: float | None) -> bool:
    if a is None or b is None:
        return a is b
    return abs(a - b) <= 1e-6 * max(1.0, abs(a), abs(b))


def subgoal_differences(p: Subgoal, t: Subgoal) -> list[str]:
    out = []
    if _target_key(p.target) != _target_key(t.target):
        out.append(f"target {p.target.to_dict()} != {t.target.to_dict()}")
    if (p.room or None) != (t.room or None):
        out.append(f"room {p.room!r} != {t.room!r}")
    if (p.location is None) != (t.location is None) or (
        p.location is not None and not (_close(p.location.x, t.location.x) and _close(p.location.y, t.location.y))
    ):
        out.append(f"location {p.location} != {t.location}")
    ps = [(c.reading, c.comparator, c.unit) for c in p.sensors]
    ts = [(c.reading, c.comparator, c.unit) for c in t.sensors]
    if ps != ts or not all(_close(a.value, b.value) for a, b in zip(p.sensors, t.sensors)):
        out.append(f"sensors {[c.to_dict() for c in p.sensors]} != {[c.to_dict() for c in t.sensors]}")
    if p.time != t.time:
        out.append(f"time {p.time} != {t.time}")
    return out


def chain_differences(parsed: TaskChain, truth: TaskChain) -> list[str]:
    """Human-readable differences between a parsed chain and the ground truth ([] when they agree)."""
    out = []
    if parsed.order != truth.order:
        out.append(f"order {parsed.order} != {truth.order}")
    if len(parsed.subgoals) != len(truth.subgoals):
        out.append(f"{len(parsed.subgoals)} subgoals != {len(truth.subgoals)}")
        return out
    for i, (p, t) in enumerate(zip(parsed.subgoals, truth.subgoals)):
        out += [f"subgoal {i}: {d}" for d in subgoal_differences(p, t)]
    if set(parsed.dependencies) != set(truth.dependencies):
        out.append("dependencies differ")
    return out


def parse_agreement(pairs: Sequence, parse: Callable[[str], TaskChain] | None = None, keep: int = 50) -> dict:
    """Agreement of `parse` (default: the rule parser) with the generator's ground truth.

    pairs: GeneratedEpisode-like objects with .episode (id, instruction, modality) and .truth.
    Returns {"instructions", "agree", "rate", "parse_errors", "by_modality": {m: rate}, "failures": [...]}.
    """
    if parse is None:
        from ragnav_jax.language.parser import parse_instruction as parse
    n, ok, errors = 0, 0, 0
    per_mod, per_mod_ok = Counter(), Counter()
    failures = []
    for p in pairs:
        n += 1
        m = p.episode.modality
        per_mod[m] += 1
        try:
            diffs = chain_differences(parse(p.episode.instruction), p.truth)
        except ParseError as e:
            errors += 1
            diffs = [f"ParseError: {e}"]
        if diffs:
            if len(failures) < keep:
                failures.append({"id": p.episode.id, "instruction": p.episode.instruction, "differences": diffs})
        else:
            ok += 1
            per_mod_ok[m] += 1
    return {
        "instructions": n,
        "agree": ok,
        "rate": ok / n if n else 1.0,
        "parse_errors": errors,
        "by_modality": {m: per_mod_ok[m] / per_mod[m] for m in per_mod},
        "failures": failures,
    }
