"""Phrasings of set E: goal, sensor, coordinate and instruction templates for the `unseen_dev9` split.

Written after parser round 8, before round 9 was developed (on set D, now `unseen_dev8`), by a seventh author
who does not write parser rules; the held-out set (`unseen`) from round 9 to round 11, developed against in
round 12. Same four functions, arguments and
meanings as the other template sets. The style is notes left for the robot by the people of a shared house:

- a chatty flatmate: existentials and asides ("There's a lamp in the study that's been switched on, could
  you find it?", "I think the kettle is in the kitchen, go and look"), order as "before anything else",
  "save X for last", "do X before Y", "while you're at it" (free);
- a landlord taking inventory: telegraphic, one line per stop ("1. The kettle in the kitchen\n2. The bean bag,
  the teal one, near the crib. Order as listed."), "/" between stops, "Check: ...", "Any order.";
- an engineer: symbols and abbreviations ("kettle @ kitchen", "temp > 20°C", "x=3.5,y=2", "1/ ... 2/ ...",
  "->", "order: strict", "order: any");
- a grandparent dictating: long sentences joined by "and then", numbers in words, "the one that is".

Goals: attributes before the noun, after it ("the bean bag, the teal corduroy one") or comma-separated ("the
teal, corduroy bean bag"); states before the noun ("the open toy chest", "the switched-on lamp") or after it
("that's been switched on", "that's still open"); the room as "in the X", "over in the X", "down in the X",
a possessive, or a noun modifier ("the kitchen kettle"); relations in new words ("right by", "up against",
"a little way from", "across the room from", "on top of", "underneath", "that's got"). Readings: digits,
words, decimals, "°C", "ºC", "C", "degrees", "%", "percent", symbols (">", "<", ">=", "<=", "≥", "≤", "~",
"≈"); superlatives as "whichever X is hottest", "the hottest one", "the one reading lowest". Coordinates:
"@ 3.5,2", "at 3.5, 2", "near (3.5, 2)", "at x 3.5 / y 2", "at (x: 3.5, y: 2)", "at x≈3.5, y≈2", always x then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.phrasings import number_words
from ragnav_jax.language.phrasings_dev4 import _and
from ragnav_jax.language.phrasings_dev8 import is_plural, split_attributes
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Relations and anchors

_REL = {
    "near": ("near", "a little way from", "close by", "in the vicinity of"),
    "next_to": ("next to", "right next to", "up against"),
    "beside": ("beside", "right beside"),
    "by": ("by", "right by", "over by"),
    "on": ("on", "on top of", "resting on"),
    "under": ("under", "underneath", "below"),
    "above": ("above", "up above"),
    "in": ("in", "inside"),
    "with": ("with", "that's got"),
    "in_room_with": ("in the same room as",),
    "in_front_of": ("in front of", "just in front of"),
    "behind": ("behind", "round the back of"),
    "opposite": ("opposite", "across the room from", "facing"),
    "left_of": ("to the left of", "on the left of"),
    "right_of": ("to the right of", "on the right of"),
}


def _state_words(state: str, before: bool) -> str:
    """A state as written: hyphenated before the noun ('switched-on'), or as it is."""
    if before and " " in state:
        return state.replace(" ", "-")
    return state


def _rel(rng, r: Relation, plural: bool) -> str:
    """A relation and its anchor: 'right by the crib', "that's got the work light", 'with the kettle'."""
    a = _anchor(rng, r.anchor)
    w = _pick(rng, _REL[r.type])
    if w == "that's got" and plural:
        w = "that have got"
    return f"{w} {a}"


def _anchor(rng, t: Target) -> str:
    """An anchor noun phrase: a state before a bare noun or after it ('the lamp, still switched on,'), its own
    relations as a clause ('the credenza, which is next to the harp')."""
    pre, states = split_attributes(t)
    plural = is_plural(t.head)
    if len(states) == 1 and not pre:
        s = f"the {_state_words(states[0], True)} {t.phrase}"
    elif states:
        s = f"the {t.phrase} that {'are' if plural else 'is'} {' and '.join(states)}"
    else:
        s = f"the {t.phrase}"
    if not t.relations:
        return s
    parts = [_rel(rng, r, plural) for r in t.relations]
    be = "are" if plural else "is"
    have = "have got" if plural else "has got"
    clause = " and ".join(have + p[len(p.split(" got")[0]) + 4:] if p.startswith("that") else
                          p if p.startswith("with") else f"{be} {p}" for p in parts)
    return f"{s}, which {clause},"


# ----------------------------------------------------------------------------------------------------
# Goals


def render_goal_dev9(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as a housemate writes it: 'the bean bag, the teal corduroy one, right by the crib', 'the kitchen
    kettle', 'the switched-on lamp over in the study', 'the teal, corduroy bean bag', 'whichever heater in the
    pantry is hottest', 'the guitar @ 3.5,2'. Relations come last.
    """
    t = sg.target
    pre, states = split_attributes(t)
    plural = is_plural(t.head)
    room = sg.room
    head_words = t.phrase[len(t.phrase) - len(t.head):] if t.phrase.endswith(t.head) else t.head
    # attributes: before the noun, after it as "the X one(s)", or comma-separated before it
    attr_style = "before"
    if pre and not prefix:
        attr_style = _pick(rng, ("before", "before", "one", "comma" if len(pre) > 1 else "before"))
    # room: after the noun, possessive, or a noun modifier when nothing else stands before the noun
    room_style = None
    if room:
        opts = ["in", "in", "over", "down", "possessive"]
        if not pre and not prefix and not (states and len(states) == 1):
            opts.append("modifier")
        room_style = _pick(rng, opts)
    state_before = bool(states) and len(states) == 1 and not pre and not prefix and room_style != "modifier" \
        and rng.uniform() < 0.4
    det = f"the {room}'s " if room_style == "possessive" else "the "
    if room_style == "modifier":
        det += room + " "
    if prefix:
        det += prefix + " "
    if state_before:
        det += _state_words(states[0], True) + " "
    if attr_style == "one":
        s = f"{det}{head_words}, the {' '.join(pre)} {'ones' if plural else 'one'},"
    elif attr_style == "comma":
        s = f"{det}{', '.join(pre)} {head_words}"
    else:
        s = det + t.phrase
    post: list[str] = []
    if states and not state_before:
        be = "are" if plural else "'s"
        adv = _pick(rng, ("", "been ", "still ")) if all(x.startswith("switched") for x in states) else \
            _pick(rng, ("", "still "))
        post.append(f"that{' ' if plural else ''}{be} {adv}{' and '.join(states)}")
    if hint:
        post.append(hint)
    if room_style in ("in", "over", "down"):
        post.append({"in": "in the ", "over": "over in the ", "down": "down in the "}[room_style] + room)
    if tail:
        post.append(tail)
    for i, r in enumerate(t.relations):
        post.append(("and also " if i else "") + _rel(rng, r, plural))
    out = s
    for i, p in enumerate(post):
        sep = " " if i == 0 or out.endswith(",") or p.startswith("and also") else ", "
        out += sep + p
    return out.rstrip(" ,-").replace(",,", ",")


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

_T_UNITS = (("°C", "c"), (" °C", "c"), ("ºC", "c"), ("C", "c"), (" degrees", "c"), (" deg C", "c"))
_H_UNITS = (("%", "%"), (" %", "%"), (" percent", "%"))
_SYM = {"gt": (">", "above", "over"), "ge": (">=", "≥", "at or above"), "lt": ("<", "below", "under"),
        "le": ("<=", "≤", "at or below"), "approx": ("~", "≈", "around")}


def _number(rng, reading: str, value: float) -> tuple[str, float]:
    """(the number as written, its value): digits, one decimal place, words, or a bare leading point."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    if reading == "ndvi":
        return (txt[1:] if txt.startswith("0.") and rng.uniform() < 0.3 else txt), v
    if v == int(v):
        u = rng.uniform()
        if u < 0.2 and abs(v) < 100:
            return number_words(int(v)), v
        if u < 0.3:
            return f"{v:.1f}", v
    return txt, v


_SUPER = {
    ("temperature_c", "max"): ("hottest", "warmest"), ("temperature_c", "min"): ("coldest", "coolest"),
    ("ndvi", "max"): ("healthiest", "greenest"), ("ndvi", "min"): ("least healthy", "unhealthiest"),
    ("humidity_pct", "max"): ("most humid", "dampest"), ("humidity_pct", "min"): ("driest", "least humid"),
}
_SUPER_READ = {"temperature_c": ("temperature", "temp"), "ndvi": ("NDVI",), "humidity_pct": ("humidity",)}


def render_sensor_dev9(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: 'hottest' before the noun, or after it ('- the hottest one', 'that reads the lowest
    humidity', 'with the highest temp'); thresholds after the noun in symbols or words ('reading > 20°C',
    'with temp >= 45%', 'at or below minus eighteen degrees', 'NDVI ~ .35', 'with humidity under 40 percent').
    """
    rd = c.reading
    if c.is_superlative:
        adj = _pick(rng, _SUPER[(rd, c.comparator)])
        k = int(rng.integers(4))
        if k == 0:
            return adj, "", c
        if k == 1:
            return "", f"- the {adj} one -", c
        hi = "highest" if c.comparator == "max" else "lowest"
        return "", _pick(rng, (f"that reads the {hi} {_pick(rng, _SUPER_READ[rd])}",
                               f"with the {hi} {_pick(rng, _SUPER_READ[rd])}")), c
    n, value = _number(rng, rd, c.value)
    sym = _pick(rng, _SYM[c.comparator])
    if rd == "ndvi":
        lead = _pick(rng, ("with NDVI", "NDVI", "with an NDVI"))
        return "", f"{lead} {sym} {n}", SensorConstraint(rd, c.comparator, value, "")
    if rd == "temperature_c":
        u, code = _pick(rng, _T_UNITS)
        if n[0].isalpha():
            u, code = " degrees", "c"
        lead = _pick(rng, ("reading", "with temp", "with a temperature", "at a temperature"))
        return "", f"{lead} {sym} {n}{u}", SensorConstraint(rd, c.comparator, value, code)
    u, code = _pick(rng, _H_UNITS)
    if n[0].isalpha():
        u = " percent"
    lead = _pick(rng, ("with humidity", "humidity", "at a humidity"))
    return "", f"{lead} {sym} {n}{u}", SensorConstraint(rd, c.comparator, value, code)


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_dev9(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: '@ 3.5,2', 'at 3.5, 2', 'near (3.5, 2)', 'at x
    3.5 / y 2', 'at (x: 3.5, y: 2)', 'at x≈3.5, y≈2', 'located at 3.5 2'. Every form reads straight after a
    noun."""
    return _pick(rng, (f"@ {x},{y}", f"at {x}, {y}", f"near ({x}, {y})", f"at x {x} / y {y}", f"at (x: {x}, y: {y})",
                       f"at x≈{x}, y≈{y}", f"located at {x} {y}", f"@ ({x}, {y})", f"at point ({x},{y})"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _end(s: str) -> str:
    s = s.strip().replace(" ,", ",").replace(",,", ",").replace(",.", ".").replace(",?", "?").replace(", -", " -")
    return s if s.endswith((".", "?", "!")) else s + "."


def _cap(s: str) -> str:
    return s[0].upper() + s[1:]


def _flatmate(rng, res: list[str], order: str) -> str:
    ask = _pick(rng, ("could you find it?", "can you go and check on it?", "go and have a look, would you?"))
    n = len(res)
    if n == 1:
        return _pick(rng, (_cap(_end(f"there's {res[0]}, {ask}")),
                           _cap(_end(f"could you nip over to {res[0]}?")),
                           _cap(_end(f"I need you at {res[0]}"))))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            s = f"Before anything else, go to {res[0]}."
            s += "".join(f" After that, {r}." for r in res[1:-1])
            return _end(s + f" Save {res[-1]} for last")
        if k == 1 and n == 2:
            return _cap(_end(f"do {res[0]} before {res[1]}, please"))
        s = f"Start off at {res[0]}." + "".join(f" From there, make your way to {r}." for r in res[1:-1])
        return _end(s + f" Finish up at {res[-1]}") + " Order matters."
    s = f"Could you drop by {res[0]}" + "".join(f"? And while you're at it, {r}" for r in res[1:]) + "?"
    return _end(s) + _pick(rng, (" No particular order.", " Whatever order you like.", " Order's up to you."))


def _landlord(rng, res: list[str], order: str) -> str:
    lines = [_cap(r) for r in res]
    if len(lines) == 1:
        return _end(f"Check: {lines[0]}")
    sep = _pick(rng, ("\n", " / ", ". "))
    if order == "strict":
        return sep.join(f"{i + 1}. {x}" if sep != ". " else f"({i + 1}) {x}" for i, x in enumerate(lines)) + \
            _pick(rng, (". Order as listed.", ". In the order given."))
    return sep.join(lines) + _pick(rng, (". Any order.", ". Order not important."))


def _engineer(rng, res: list[str], order: str) -> str:
    n = len(res)
    if n == 1:
        return _pick(rng, (f"goto: {res[0]}", f"target = {res[0]}", f"nav to {res[0]}"))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            return " -> ".join(res) + " (order: strict)"
        if k == 1:
            return " ".join(f"{i + 1}/ {r}" for i, r in enumerate(res)) + " - in sequence"
        return "seq: " + "; ".join(res)
    return _pick(rng, ("targets (any order): ", "order: any | ", "unordered: ")) + "; ".join(res)


def _grandparent(rng, res: list[str], order: str) -> str:
    n = len(res)
    if n == 1:
        return _cap(_end(f"now dear I want you to go over to {res[0]}"))
    if order == "strict":
        sep = ", " if any(" and " in r or "," in r for r in res) else " "
        s = f"now dear first of all go to {res[0]}" + "".join(f"{sep}and then after that {r}" for r in res[1:-1])
        s += f"{sep}and then last of all {res[-1]}"
        return _cap(_end(s))
    s = f"now dear I'd like you to see to {_and(res)}" if all("," not in r for r in res) else \
        f"now dear I'd like you to see to {res[0]}" + "".join(f", and also {r}" for r in res[1:])
    return _cap(_end(s)) + _pick(rng, (" It doesn't matter which you do first.", " Whichever order you please."))


def render_instruction_dev9(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, left by one of four housemates (a chatty flatmate, a landlord
    taking inventory, an engineer, a grandparent dictating). Strict texts spell the visiting order out
    ('Before anything else ... Save X for last', numbered lines, 'A -> B (order: strict)', 'first of all ...
    and then last of all'); free ones say it is open ('while you're at it', 'Any order.', 'order: any')."""
    res = [r.strip().rstrip(",") for r in res]
    who = int(rng.integers(4))
    return (_flatmate, _landlord, _engineer, _grandparent)[who](rng, res, order)
