"""Phrasings of set N: goal, sensor, coordinate and instruction templates for the `unseen_dev11` split.

Held out for round 13, developed against in round 14; moved to this development split when set O (then
`phrasings_heldout.py`, now `phrasings_dev12.py`) took its place as `unseen`. Written in round 13, before any run of
it, after that round's parser changes were made on hand-written probes in the registers of set M (now
`unseen_dev10`); measured fresh with the round-13 parser (closed loop from a frozen copy of that commit), then
parser round 14 was written on hand-written probes in its registers. Same four functions, arguments and meanings
as the other template sets. The style is requests from the staff and residents of a care home:

- a nurse's handover note: abbreviations ("pls chk", "nr" for near, "w/" for with, "rm"), "+" between goals
  that may come in any order, "then" between ordered ones;
- a resident's polite, hedged request: "I wonder if you might pop along to ...", "if it's no trouble",
  "whichever order suits you best";
- an activities coordinator's plan: "First: ... Second: ... Last: ...", "Any order: ...";
- a carer writing in a second language: "go at", "near of", "after go to", "the order is not important".

Goals: attributes before the noun or after it ("the sofa, grey one"); states before the noun or after it ("that is
on", "which is left open"); the room as "in the X", "in X rm", "in X"; relations in other words ("nr", "w/",
"near of", "close of", "on the top of", "just beside"). Readings: "more than 20 degree", "approx 21C", "bigger
than 0.5", "higher than 60%", "lower than", "not more than", "minimum", "around"; superlatives as "the warmest",
"with the max temp", "with the highest humidity". Coordinates: "x 3.5, y 2", "(3.5 ; 2)", "pos. 3.5/2", "at point
3.5,2", "x:3.5 y:2"; always x then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.phrasings import number_words
from ragnav_jax.language.phrasings_dev8 import is_plural, split_attributes
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

REL_WORDS = {
    "near": ("near", "nr", "near of", "close of", "close to"),
    "next_to": ("next to", "just next to", "nxt to"),
    "beside": ("beside", "just beside"),
    "by": ("by", "just by"),
    "on": ("on", "on the top of", "on top of"),
    "under": ("under", "below"),
    "above": ("above", "over"),
    "in": ("in", "inside of"),
    "with": ("with", "w/"),
    "in_room_with": ("in the same room as", "in same room as"),
    "in_front_of": ("in front of",),
    "behind": ("behind",),
    "opposite": ("opposite", "opposite of"),
    "left_of": ("to the left of", "on the left of"),
    "right_of": ("to the right of", "on the right of"),
}


def _rel(rng, r: Relation) -> str:
    """A relation and its anchor: 'nr the crib', 'w/ the work light', 'near of the sofa'."""
    return f"{_pick(rng, REL_WORDS[r.type])} {_anchor(rng, r.anchor)}"


def _anchor(rng, t: Target) -> str:
    pre, states = split_attributes(t)
    s = f"the {t.phrase}" + (f" that is {' and '.join(states)}" if states else "")
    for i, r in enumerate(t.relations):
        s += (" and " if i else " ") + _rel(rng, r)
    return s


def render_goal_dev11(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as the care home writes it: 'the sofa, grey one, in lounge rm', 'the lamp which is left on nr the
    bed', 'the warmest radiator in hall', 'the kettle x 3.5, y 2'. Relations come last."""
    t = sg.target
    pre, states = split_attributes(t)
    plural = is_plural(t.head)
    head_words = t.phrase[len(t.phrase) - len(t.head):] if t.phrase.endswith(t.head) else t.head
    state_before = len(states) == 1 and not pre and not prefix and rng.uniform() < 0.3
    one_after = bool(pre) and not prefix and rng.uniform() < 0.3
    out = "the " + (prefix + " " if prefix else "") + (states[0].replace(" ", "-") + " " if state_before else "")
    out += head_words if one_after else t.phrase
    if one_after:
        out += f", {' '.join(pre)} {'ones' if plural else 'one'},"
    if states and not state_before:
        left = "left " if all(x in ("open", "switched on", "switched off") for x in states) and rng.uniform() < 0.4 else ""
        out += f" {_pick(rng, ('that', 'which'))} {'are' if plural else 'is'} {left}{' and '.join(states)}"
    if hint:
        out += " " + hint
    if tail:
        out += " " + tail
    if sg.room:
        out += _pick(rng, (f" in the {sg.room}", f" in {sg.room} rm" if not sg.room.endswith("room") else f" in {sg.room}",
                           f" in {sg.room}"))
    for i, r in enumerate(t.relations):
        out += (" and " if i else " ") + _rel(rng, r)
    return " ".join(out.replace(",,", ",").split()).rstrip(",")


_T_UNITS = (("C", "c"), (" degree", "c"), (" degrees", "c"), (" deg", "c"), ("°", "c"))
_H_UNITS = (("%", "%"), (" percent", "%"), (" %", "%"))
_CMP = {"gt": ("more than", "bigger than", "higher than"), "ge": ("minimum", "not less than"),
        "lt": ("lower than", "less than", "smaller than"), "le": ("not more than", "maximum"),
        "approx": ("approx", "around", "about")}
_SUPER = {
    ("temperature_c", "max"): ("warmest", "hottest"), ("temperature_c", "min"): ("coldest", "coolest"),
    ("ndvi", "max"): ("healthiest", "greenest"), ("ndvi", "min"): ("least healthy", "unhealthiest"),
    ("humidity_pct", "max"): ("most humid", "dampest"), ("humidity_pct", "min"): ("driest", "least humid"),
}
_READ = {"temperature_c": "temp", "ndvi": "NDVI", "humidity_pct": "humidity"}


def render_sensor_dev11(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: 'warmest' before the noun, or after it ('with the max temp', 'with the highest humidity');
    thresholds after the noun ('temp more than 20 degree', 'with humidity approx 40%', 'NDVI bigger than
    0.5', 'temperature not more than minus eighteen degrees')."""
    rd = c.reading
    if c.is_superlative:
        if rng.uniform() < 0.5:
            return _pick(rng, _SUPER[(rd, c.comparator)]), "", c
        word = _pick(rng, ("max", "highest") if c.comparator == "max" else ("min", "lowest"))
        return "", f"with the {word} {_READ[rd]}", c
    txt = _fmt_value(rd, c.value)
    value = float(txt)
    if rd != "ndvi" and value == int(value) and abs(value) < 100 and rng.uniform() < 0.2:
        txt = number_words(int(value))
    cmp = _pick(rng, _CMP[c.comparator])
    if rd == "ndvi":
        return "", f"{_pick(rng, ('NDVI', 'with NDVI'))} {cmp} {txt}", SensorConstraint(rd, c.comparator, value, "")
    if rd == "temperature_c":
        u, code = _pick(rng, _T_UNITS)
        if txt[0].isalpha():
            u = " degrees"
        lead = _pick(rng, ("temp", "temperature", "with temperature", "with temp"))
        return "", f"{lead} {cmp} {txt}{u}", SensorConstraint(rd, c.comparator, value, code)
    u, code = _pick(rng, _H_UNITS)
    if txt[0].isalpha():
        u = " percent"
    return "", f"{_pick(rng, ('humidity', 'with humidity'))} {cmp} {txt}{u}", SensorConstraint(rd, c.comparator, value, code)


def hint_text_dev11(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'x 3.5, y 2', '(3.5 ; 2)', 'pos. 3.5/2', 'at point
    3.5,2', 'x:3.5 y:2'."""
    return _pick(rng, (f"x {x}, y {y}", f"({x} ; {y})", f"pos. {x}/{y}", f"at point {x},{y}", f"x:{x} y:{y}"))


def _nurse(rng, res: list[str], order: str) -> str:
    lead = _pick(rng, ("pls chk ", "Pls check ", "pls go to "))
    if len(res) == 1:
        return lead + res[0]
    if order == "strict":
        return lead + "".join((", then " if i else "") + r for i, r in enumerate(res)) + _pick(rng, (" - in that order", " (in order)"))
    return lead + " + ".join(res) + _pick(rng, (" (any order)", " - order not important"))


def _resident(rng, res: list[str], order: str) -> str:
    s = f"I wonder if you might pop along to {res[0]}"
    if len(res) == 1:
        return s + "? Thank you, dear."
    if order == "strict":
        mid = "".join(f", and after that, if it's no trouble, {r}" for r in res[1:-1])
        return s + mid + f", and lastly {res[-1]}. In that order, please."
    return s + "".join(f", and {r}" for r in res[1:]) + ", in whichever order suits you best."


def _planner(rng, res: list[str], order: str) -> str:
    if len(res) == 1:
        return f"Only stop: {res[0]}."
    if order == "strict":
        words = ("First", "Second", "Third", "Fourth", "Fifth")
        return " ".join(f"{'Last' if i == len(res) - 1 else words[i]}: {r}." for i, r in enumerate(res))
    return "Any order: " + ", ".join(res[:-1]) + " and " + res[-1] + "."


def _second_language(rng, res: list[str], order: str) -> str:
    first = _pick(rng, ("Please go at ", "Please you go to ", "Go at "))
    if len(res) == 1:
        return first + res[0] + "."
    if order == "strict":
        return first + res[0] + "".join(f", {_pick(rng, ('after go to', 'after you go', 'then you go to'))} {r}"
                                        for r in res[1:]) + "."
    return first + res[0] + "".join(f" and {r}" for r in res[1:]) + _pick(rng, (". The order is not important.",
                                                                              ". Order you can choose."))


def render_instruction_dev11(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people of a care home (a nurse's note, a resident,
    an activities plan, a carer writing in a second language). Strict texts say the order ('then', 'in that
    order', 'First: ... Last:', 'after go to'); free ones say it is open."""
    res = [r.strip().rstrip(",") for r in res]
    who = int(rng.integers(4))
    return (_nurse, _resident, _planner, _second_language)[who](rng, res, order)
