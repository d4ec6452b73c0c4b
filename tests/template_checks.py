"""Checks shared by the tests of template sets M to AA: each takes the set's own functions and its own words
(relation words, comparator readers, order cues), so the readers stay independent of the templates they check."""

from __future__ import annotations

import re

import numpy as np
import pytest
from test_phrasings_dev8 import _all_targets, _has, read_numbers

from ragnav_jax.language.types import Location, Subgoal, Target

_NUMBER = r"-?\d+(?:\.\d+)?"


def check_goal(text: str, sg: Subgoal, rel_words: dict, room: str) -> None:
    """Every head, attribute, relation (one of rel_words[type]) and the room (`room` formatted with it) is written."""
    plain = text.replace("-", " ")  # "switched-on" before a noun
    assert text.startswith("the ") and not text.endswith("-")
    for t in _all_targets(sg.target):
        assert _has(text, t.head), (t.head, text)
        for a in t.attributes:
            assert _has(text, a) or _has(plain, a), (a, text)
        for r in t.relations:
            assert any(_has(text, w) or (w.endswith("/") and f" {w} " in text) for w in rel_words[r.type]), (r.type, text)
    if sg.room:
        assert _has(text, room.format(sg.room)), text


def check_goal_layout(text: str, sg: Subgoal, rel_words: dict, endings: tuple[str, ...] = (",", ";", "—")) -> None:
    """check_goal, and the layout every set after P keeps: no dangling separator or doubled space or comma, the
    goal's own head before its anchors' (or among them), the room before any relation, brackets balanced (an
    anchor's own relations stay with it)."""
    check_goal(text, sg, rel_words, "{}")
    assert not text.endswith(endings) and "  " not in text and ",," not in text, text
    low = text.lower()
    assert low.find(sg.target.head) <= min((low.find(r.anchor.head) for r in sg.target.relations), default=10**6) or \
        any(sg.target.head in t.head for r in sg.target.relations for t in _all_targets(r.anchor))
    if sg.room and sg.target.relations:
        first_anchor = min(low.rfind(r.anchor.phrase) for r in sg.target.relations)
        assert low.find(sg.room) < first_anchor, text
    assert text.count("(") == text.count(")"), text


def check_sensor(rendered: tuple, c, comparator, low: str, unit_c: str, unit_pct: str = r"%|percent",
                 numbers=None, reading=None) -> None:
    """The phrase names the constraint it says it wrote: the reading (read by `reading`, when given), the number
    (read by `numbers`; default `read_numbers`), the comparator (read by `comparator`), the unit (regexes `unit_c`,
    `unit_pct`); a superlative names no number and says low (regex `low`) exactly when it is a minimum."""
    prefix, tail, written = rendered
    text = (prefix + " " + tail).strip()
    assert bool(prefix) != bool(tail) and (written.reading, written.comparator) == (c.reading, c.comparator)
    if reading is not None:
        assert reading(text) == c.reading, text
    if c.is_superlative:
        assert written.value is None and (numbers or read_numbers)(text) == [], text
        assert bool(re.search(low, text)) == (c.comparator == "min"), text
        return
    assert written.value == pytest.approx(c.value, abs=0.006)
    got = numbers(text) if numbers is not None else read_numbers(text.replace("°C", " C"))
    assert got == [pytest.approx(written.value)], text
    assert comparator(text) == c.comparator, text
    unit = "c" if re.search(unit_c, text.lower()) else "%" if re.search(unit_pct, text) else ""
    assert unit == written.unit, text


def check_sensor_goal(render_sensor, render_goal, c, sg: Subgoal, seed: int, numbers) -> None:
    """A goal rendered with a sensor phrase keeps its head, room and phrase: a superlative adjective stands before
    the noun phrase (its states hyphenated with it), a tail after the head (and after the room for a superlative,
    which is read inside it); the only number in the text is the constraint's (read by `numbers`)."""
    rng = np.random.default_rng(seed)
    prefix, tail, _ = render_sensor(rng, c)
    sg = Subgoal(0, Target(sg.target.phrase, sg.target.head, sg.target.attributes), room=sg.room)
    text = render_goal(rng, sg, prefix=prefix, tail=tail)
    assert _has(text, sg.target.head), text
    if sg.room:
        assert _has(text, sg.room), text
    if prefix:  # a superlative adjective stands before the noun phrase, the attributes with it
        states = [a for a in sg.target.attributes if a not in sg.target.phrase.split()]
        starts = (f"the {prefix} {sg.target.phrase}", f"the {prefix} {' '.join(s.replace(' ', '-') for s in states)} "
                  f"{sg.target.phrase}")
        assert text.startswith(starts), text
    else:
        assert tail in text and text.index(sg.target.head) < text.index(tail), text
        if sg.room and c.is_superlative:  # a superlative is read inside the room: the room comes first
            assert text.index(sg.room) < text.index(tail), text
    assert numbers(text) == ([] if c.is_superlative else [pytest.approx(c.value, abs=0.006)]), text


def check_coordinates(hint_text, render_goal, render_instruction, x: float, y: float, seed: int, as_read=lambda t: t) -> None:
    """The hint, and the whole one-goal instruction (as_read undoes the set's own shorthand), hold x then y."""
    xs, ys = (f"{v:.1f}" for v in (x + 0.0, y + 0.0))
    rng = np.random.default_rng(seed)
    hint = hint_text(rng, xs, ys)
    assert [float(v) for v in re.findall(_NUMBER, hint)] == [float(xs), float(ys)], hint
    goal = render_goal(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(x, y)), hint=hint)
    text = as_read(render_instruction(rng, [goal], "strict"))
    assert [float(v) for v in re.findall(_NUMBER, text)] == [float(xs), float(ys)], text


def check_order(render_goal, render_instruction, sgs, seed: int, strict: bool, strict_cues: str, free_cues: str) -> None:
    """A free instruction says so and says no strict cue; a strict one says no free cue; heads come in visiting order."""
    rng = np.random.default_rng(seed)
    res = [render_goal(rng, sg) for sg in sgs]
    low = render_instruction(rng, res, "strict" if strict else "free").lower()
    assert not re.search(free_cues, low) if strict else re.search(free_cues, low), low
    if not strict:
        assert not re.search(strict_cues, low), low
    at = 0
    for sg in sgs:
        at = low.find(sg.target.head, at)
        assert at >= 0, (sg.target.head, low)


_ONES = {w: i for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine",
                                     "ten", "eleven", "twelve", "thirteen", "fourteen", "fifteen", "sixteen",
                                     "seventeen", "eighteen", "nineteen"))}
_TENS = {"twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "seventy": 70, "eighty": 80, "ninety": 90}


def spoken_numbers(toks: list[str]) -> list[float]:
    """Every number among a text's tokens (digit runs and lower-case words): '-18', '.6', 'minus eighteen',
    'three hundred and five'. Each set's test normalises its own formats into such tokens first."""
    out: list[float] = []
    neg, cur = False, None
    for tok in toks + ["."]:
        parts = tok.split("-")
        if tok == "minus":
            neg = True
        elif all(p in _ONES or p in _TENS for p in parts):
            cur = (cur or 0) + sum(_ONES.get(p, 0) + _TENS.get(p, 0) for p in parts)
        elif tok == "hundred" and cur is not None:
            cur *= 100
        elif tok == "and" and cur is not None and cur % 100 == 0:
            pass
        else:
            if cur is not None:
                out.append(-cur if neg else float(cur))
                neg, cur = False, None
            if re.fullmatch(r"-?\d*\.?\d+", tok):
                out.append(-float(tok) if neg else float(tok))
                neg = False
    return out


def target_truth(t: Target) -> dict:
    """A target as the held-out sets' readers read it back: head, attributes before it, states, relations."""
    pre = t.phrase[: len(t.phrase) - len(t.head)].split()
    return {"head": t.head, "attrs": [a for a in t.attributes if a in pre],
            "states": sorted(a for a in t.attributes if a not in pre),
            "relations": [(r.type, target_truth(r.anchor)) for r in t.relations]}


def reading_norm(got: dict) -> dict:
    """A reading with its states sorted (their order in the sentence is free)."""
    return {"head": got["head"], "attrs": got["attrs"], "states": sorted(got["states"]),
            "relations": [(k, reading_norm(a)) for k, a in got["relations"]]}


def depths(text: str) -> list[int]:
    """Per character of text, how many brackets are open there (a bracket's own characters count inside it)."""
    out, d = [], 0
    for ch in text:
        if ch == "(":
            d += 1
        out.append(d)
        if ch == ")":
            d -= 1
    return out


def word_number(w: str) -> float:
    """A number written as one word: digits ("14") or a spoken number ("fourteen")."""
    if re.fullmatch(r"\d+", w):
        return float(w)
    k = spoken_numbers([w])
    assert len(k) == 1, w
    return k[0]


def tidy_commas(s: str) -> str:
    """Text with runs of spaces closed up, commas that lost their words merged and none left at the end."""
    s = " ".join(s.split())
    for a, b in ((" ,", ","), (",,", ","), (", ,", ",")):
        s = s.replace(a, b)
    return s.strip().rstrip(",").strip()
