"""Phrasings of set M: goal, sensor, coordinate and instruction templates for the `unseen_dev10` split.

Written in round 12, before any run of it, after the round's parser changes were made on set E (now
`unseen_dev9`); measured fresh with the round-12 parser, then developed against in round 13. Same four functions, arguments and meanings as the other
template sets. The style is first messages typed or spoken into a household robot's app by four new users:

- a smart-speaker transcript: lower case, no punctuation, fillers ("um", "uh", "okay so"), coordinates as
  said aloud ("at x 4.2 y 7"), goals joined by "and then", "after that";
- an office manager's email: a greeting, "Please could the robot attend the following:", one bullet a line
  ("• the boiler (garage)"), "In the order above, please." / "Any order is fine.", a sign-off with a name;
- a checklist: "[ ]" boxes, one item a line, determiners dropped ("[ ] kettle in kitchen"), "(in this order)";
- a teenager's text: "2" for "to", "thn" / "n then" between goals, "ty", no capitals, determiners mostly
  dropped ("go 2 teal bean bag by the crib thn kettle").

Goals: attributes before the noun, or after it as "(the teal one)" / "- the teal one -"; states before the
noun or after it ("that's on", "which is still open", "that is currently switched off"); the room as "in the
X", "(in the X)", "from the X"; relations in other words ("adjacent to", "just by", "across from",
"at the back of", "sitting on", "that has"). Readings: "at least", "no more than", "more than", "less than",
"roughly", "approx.", "°C", "deg", "degrees C", "%", "% humidity", "percent"; superlatives as "the warmest",
"the X that's warmest", "the X reading the highest temp". Coordinates: "at (3.5, 2)", "position 3.5, 2",
"x=3.5 y=2", "coords 3.5/2", "at 3.5 2", spoken "x three point five y two"; always x then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.phrasings import number_words
from ragnav_jax.language.phrasings_dev8 import is_plural, split_attributes
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "close to", "not far from", "around"),
    "next_to": ("next to", "adjacent to", "right next to"),
    "beside": ("beside", "at the side of"),
    "by": ("by", "just by"),
    "on": ("on", "sitting on", "on top of"),
    "under": ("under", "beneath"),
    "above": ("above", "over"),
    "in": ("in", "inside"),
    "with": ("with", "that has"),
    "in_room_with": ("in the same room as", "in the room with"),
    "in_front_of": ("in front of",),
    "behind": ("behind", "at the back of"),
    "opposite": ("opposite", "across from"),
    "left_of": ("to the left of", "left of"),
    "right_of": ("to the right of", "right of"),
}


def _rel(rng, r: Relation, plural: bool) -> str:
    """A relation and its anchor: 'adjacent to the crib', 'that has the work light'."""
    w = _pick(rng, REL_WORDS[r.type])
    if w == "that has" and plural:
        w = "that have"
    return f"{w} {_anchor(rng, r.anchor)}"


def _anchor(rng, t: Target) -> str:
    """An anchor noun phrase; its own state as a clause, its own relations after 'which is'."""
    pre, states = split_attributes(t)
    s = f"the {t.phrase}" + (f" that is {' and '.join(states)}" if states else "")
    for i, r in enumerate(t.relations):
        rel = _rel(rng, r, is_plural(t.head))
        s += (" and" if i else "") + (" " if rel.startswith(("with", "that")) else " which is ") + rel
    return s


# ----------------------------------------------------------------------------------------------------
# Goals


def render_goal_dev10(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as a new user writes it: 'the teal bean bag (nursery)', 'the bean bag - the teal one - in the
    nursery', 'the lamp that's on from the study', 'the warmest radiator in the hall', 'the kettle at (3.5, 2)'.
    Relations come last."""
    t = sg.target
    pre, states = split_attributes(t)
    plural = is_plural(t.head)
    head_words = t.phrase[len(t.phrase) - len(t.head):] if t.phrase.endswith(t.head) else t.head
    state_before = len(states) == 1 and not pre and not prefix and rng.uniform() < 0.4
    one_after = bool(pre) and not prefix and rng.uniform() < 0.35
    out = "the " + (prefix + " " if prefix else "") + (states[0].replace(" ", "-") + " " if state_before else "")
    out += head_words if one_after else t.phrase
    if one_after:
        out += _pick(rng, (f" (the {' '.join(pre)} {'ones' if plural else 'one'})",
                           f" - the {' '.join(pre)} {'ones' if plural else 'one'} -"))
    if states and not state_before:
        be = "are" if plural else _pick(rng, ("'s", " is"))
        out += _pick(rng, (f" that{be}", f" which{' are' if plural else ' is'}")) + _pick(rng, (" ", " still ", " currently ")) \
            + " and ".join(states)
    if hint:
        out += " " + hint
    if tail:
        out += " " + tail
    if sg.room:
        out += _pick(rng, (f" in the {sg.room}", f" (in the {sg.room})", f" from the {sg.room}", f" in the {sg.room}"))
    for i, r in enumerate(t.relations):
        out += (" and " if i else " ") + _rel(rng, r, plural)
    return " ".join(out.split()).rstrip(" -")


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

_T_UNITS = (("°C", "c"), (" °C", "c"), (" deg", "c"), (" degrees C", "c"), (" degrees", "c"), ("C", "c"))
_H_UNITS = (("%", "%"), (" percent", "%"), ("% humidity", "%"))
_CMP = {"gt": ("more than", "above", "over"), "ge": ("at least", "no less than"), "lt": ("less than", "below", "under"),
        "le": ("no more than", "at most"), "approx": ("roughly", "approx.", "about")}
_SUPER = {
    ("temperature_c", "max"): ("warmest", "hottest"), ("temperature_c", "min"): ("coldest", "coolest"),
    ("ndvi", "max"): ("healthiest", "greenest"), ("ndvi", "min"): ("least healthy", "sickest"),
    ("humidity_pct", "max"): ("most humid", "dampest"), ("humidity_pct", "min"): ("driest", "least humid"),
}
_READ = {"temperature_c": ("temp", "temperature"), "ndvi": ("NDVI", "NDVI score"), "humidity_pct": ("humidity",)}


def _spoken(rng, v: float, reading: str) -> tuple[str, float]:
    """(the number as written, its value): digits, or words for whole numbers ('twenty-one')."""
    txt = _fmt_value(reading, v)
    val = float(txt)
    if reading != "ndvi" and val == int(val) and abs(val) < 100 and rng.uniform() < 0.25:
        return number_words(int(val)), val
    return txt, val


def render_sensor_dev10(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: 'warmest' before the noun, or after it ('that's warmest', 'reading the highest temp');
    thresholds after the noun ('with a temp of at least 20°C', 'humidity more than 60%', 'NDVI roughly 0.4',
    'reading no more than minus eighteen degrees')."""
    rd = c.reading
    if c.is_superlative:
        adj = _pick(rng, _SUPER[(rd, c.comparator)])
        k = int(rng.integers(3))
        if k == 0:
            return adj, "", c
        if k == 1 and " " not in adj:
            return "", f"that's {adj}", c
        hi = "highest" if c.comparator == "max" else "lowest"
        return "", f"reading the {hi} {_pick(rng, _READ[rd])}", c
    n, value = _spoken(rng, c.value, rd)
    cmp = _pick(rng, _CMP[c.comparator])
    if rd == "ndvi":
        return "", f"{_pick(rng, ('with an NDVI', 'NDVI', 'NDVI score'))} {cmp} {n}", SensorConstraint(rd, c.comparator, value, "")
    if rd == "temperature_c":
        u, code = _pick(rng, _T_UNITS)
        if n[0].isalpha():
            u = " degrees"
        lead = _pick(rng, ("with a temp of", "reading", "temp", "at a temperature of"))
        return "", f"{lead} {cmp} {n}{u}", SensorConstraint(rd, c.comparator, value, code)
    u, code = _pick(rng, _H_UNITS)
    if n[0].isalpha():
        u = " percent"
    if u == "% humidity":
        return "", f"at {cmp} {n}{u}", SensorConstraint(rd, c.comparator, value, code)
    return "", f"{_pick(rng, ('humidity', 'with humidity'))} {cmp} {n}{u}", SensorConstraint(rd, c.comparator, value, code)


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_dev10(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at (3.5, 2)', 'position 3.5, 2', 'x=3.5 y=2',
    'coords 3.5/2', 'at 3.5 2'."""
    return _pick(rng, (f"at ({x}, {y})", f"position {x}, {y}", f"x={x} y={y}", f"coords {x}/{y}", f"at {x} {y}",
                       f"around ({x},{y})"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _bare(goal: str) -> str:
    """A goal with its leading determiner dropped, as lists and texts are typed: 'the kettle' -> 'kettle'."""
    return goal[4:] if goal.startswith("the ") else goal


_SPOKEN_PAIR = re.compile(r"(?:at \(|position |x=|coords |at |around \()(?P<x>-?\d+(?:\.\d+)?)(?:, ?| y=|/| )"
                          r"(?P<y>-?\d+(?:\.\d+)?)\)?")


def _speaker(rng, res: list[str], order: str) -> str:
    """Lower case, no punctuation; a coordinate pair as said aloud ('at x 3.5 y 2')."""
    words = []
    for r in res:
        r = _SPOKEN_PAIR.sub(lambda m: f"at x {m.group('x')} y {m.group('y')}", r)
        words.append(" ".join(r.replace(",", " ").replace("(", " ").replace(")", " ").replace(" - ", " ").split()))
    lead = _pick(rng, ("okay so um ", "uh ", "hey robot ", ""))
    verb = _pick(rng, ("go to ", "can you go to ", "i need you to check "))
    if len(words) == 1:
        return lead + verb + words[0]
    joins = (" and then ", " after that ", " and then uh ")
    s = lead + verb + words[0] + "".join(_pick(rng, joins) + w for w in words[1:])
    if order == "free":
        s += _pick(rng, (" doesn't matter what order", " any order is fine", " in whatever order"))
    return s


def _email(rng, res: list[str], order: str) -> str:
    hello = _pick(rng, ("Hi,", "Hello,", "Good morning,"))
    ask = _pick(rng, ("Please could the robot attend the following:", "Could you send the robot to:",
                      "The robot needs to visit:"))
    bullet = _pick(rng, ("• ", "- ", "* "))
    body = "\n".join(bullet + r[0].upper() + r[1:] for r in res)
    if order == "strict":
        tail = _pick(rng, ("In the order above, please.", "Please keep to this order.", "Order as listed."))
    else:
        tail = _pick(rng, ("Any order is fine.", "The order doesn't matter.", "In whatever order suits."))
    if len(res) == 1:
        tail = "Many thanks."
    sign = _pick(rng, ("Kind regards,\nPat", "Thanks,\nSam", "Best,\nJo"))
    return f"{hello}\n\n{ask}\n{body}\n\n{tail}\n\n{sign}"


def _checklist(rng, res: list[str], order: str) -> str:
    head = _pick(rng, ("Robot checklist", "TODO", "Tasks"))
    if len(res) > 1:
        head += " (in this order)" if order == "strict" else " (any order)"
    return head + ":\n" + "\n".join(f"[ ] {_bare(r)}" for r in res)


def _teen(rng, res: list[str], order: str) -> str:
    items = [_bare(r) if rng.uniform() < 0.7 else r for r in res]
    s = "go 2 " + items[0] + "".join(_pick(rng, (" thn ", " n then ", " then ")) + r for r in items[1:])
    if order == "free" and len(res) > 1:
        s += _pick(rng, (" any order", " whatever order"))
    return s + _pick(rng, (" ty", " thx", ""))


def render_instruction_dev10(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four new users (a smart-speaker transcript, an office
    email, a checklist, a teenager's text). Strict texts keep the goals in visiting order and, in the email and
    the checklist, say so; free ones say the order is open."""
    res = [r.strip().rstrip(",") for r in res]
    who = int(rng.integers(4))
    return (_speaker, _email, _checklist, _teen)[who](rng, res, order)
