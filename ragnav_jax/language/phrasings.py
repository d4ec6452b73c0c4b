"""Unseen-split phrasings: goal, sensor, coordinate and instruction templates for the held-out split.

The seen templates live in `episodes.py` (`render_goal`, `render_sensor`, `_hint_text`,
`render_instruction`); these renderers take the same arguments and say the same things with structures
and wordings the seen ones never produce (relative clauses, appositions, parentheticals, number words,
new units and order phrases), like R2R's val_unseen. The rule parser was written without seeing them.
Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import READING_TEXT, _fmt_value, _pick
from ragnav_jax.language.types import SensorConstraint, Subgoal, Target

# Attribute values that describe a state and read after the noun ("the lamp that is switched on").
STATE_VALUES = (
    "switched on", "switched off", "turned on", "turned off", "open", "closed", "empty", "full", "plugged in",
    "unplugged", "lit", "unlit", "running", "idle", "folded", "unfolded", "on", "off", "half full", "locked",
    "unlocked",
)


def is_state(attr: str) -> bool:
    """Whether an attribute is a state (written after the head noun) rather than a pre-nominal modifier."""
    return attr.strip().lower() in STATE_VALUES


# Relation wordings, same meanings as episodes.REL_TEXT: (after the noun, verb phrase after "that").
# "{a}" is the anchor. "with" means the anchor is on or next to the target, so it is never "on it" alone.
REL_UNSEEN: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "near": (("in the vicinity of {a}", "close by {a}"), ("is near {a}", "is close to {a}", "sits near {a}")),
    "next_to": (("right next to {a}", "sitting next to {a}"), ("sits next to {a}", "is right next to {a}")),
    "beside": (("standing beside {a}", "just beside {a}"), ("stands beside {a}", "is beside {a}")),
    "by": (("right by {a}", "standing by {a}"), ("stands by {a}", "is right by {a}")),
    "on": (("placed on {a}", "sitting on {a}", "resting on top of {a}"), ("sits on {a}", "is placed on {a}")),
    "with": (("with {a} on or next to it",), ("has {a} on or next to it", "has {a} on it or beside it")),
    "in_room_with": (("in the same room as {a}", "sharing a room with {a}"),
                     ("is in the room where {a} is", "shares a room with {a}")),
    "under": (("underneath {a}",), ("sits under {a}",)),
    "above": (("located above {a}",), ("is above {a}",)),
    "in": (("inside {a}",), ("is kept inside {a}",)),
    "in_front_of": (("right in front of {a}",), ("stands in front of {a}",)),
    "behind": (("just behind {a}",), ("stands behind {a}",)),
    "opposite": (("across from {a}", "facing {a}"), ("faces {a}",)),
    "left_of": (("to the left of {a}",), ("is to the left of {a}",)),
    "right_of": (("to the right of {a}",), ("is to the right of {a}",)),
}


def _relation(rng, rtype: str, anchor: str, clause: bool, nested: bool) -> tuple[str, str]:
    """(kind, text) of one relation; an anchor with relations of its own goes last ("with X near Y on it" is unclear)."""
    bare, rel = REL_UNSEEN.get(rtype, ((rtype.replace("_", " ") + " {a}",),) * 2)
    if nested:
        bare, rel = (tuple(f for f in forms if f.endswith("{a}")) for forms in (bare, rel))
        bare = bare or ("with {a}",)
    if clause and rel:
        return "rel", _pick(rng, rel).format(a=anchor)
    return "bare", _pick(rng, bare).format(a=anchor)


def _assemble(rng, head: str, post: list[tuple[str, str]]) -> str:
    """Joins post-nominal pieces: consecutive relative clauses share one "that"/"which" and an "and"."""
    out, prev, last, pron = head, "", "", _pick(rng, ("that", "which"))
    for kind, text in post:
        if kind in ("rel", "clause") and prev in ("rel", "clause"):
            text = re.sub(r"^(that|which) ", "", text)
            if prev == "rel" and kind == "rel" and text.startswith("is ") and last.startswith("is "):
                text = text[3:]
            out += f" and {text}"
        elif kind == "rel":
            lead = "that's" if pron == "that" and text.startswith("is ") and rng.uniform() < 0.3 else f"{pron} is"
            out += f" {lead} {text[3:]}" if text.startswith("is ") else f" {pron} {text}"
        elif kind == "comma":
            out += f", {text},"
        elif kind == "paren":
            out += f" ({text})"
        else:
            out += f" {text}"
        prev, last = kind, text
    return out


def _phrase(rng, t: Target, prefix: str = "", room: str | None = None, tail: str = "", hint: str = "",
            top: bool = False) -> str:
    """A noun phrase for t (goal when top, else an anchor), pieces in an order that keeps their scope."""
    states = [a for a in t.attributes if is_state(a)]
    mods = [a for a in t.attributes if not is_state(a)]
    whichever = tail.startswith("whichever")
    free = {"comma": top and not whichever, "paren": top}  # one aside per goal: two read badly

    def slot(kinds: tuple[str, ...]) -> str:
        k = _pick(rng, [k for k in kinds if free.get(k, True)])
        if k in free:
            free.update(comma=False, paren=False)
        return k

    # A room before a sensor phrase is set off ("the heater (in the kitchen) whose ..."), so the reading
    # cannot be read as the room's; decided first so a comma or parenthesis slot is left for it.
    room_piece = None
    if room:
        clause_tail = tail.startswith(("that ", "whose ", "which "))
        k = slot(("bare", "rel", "paren", "comma") if not tail or whichever else ("paren",) + ("rel",) * clause_tail)
        room_piece = (k, {"rel": f"is in the {room}", "comma": f"the one in the {room}"}.get(k, f"in the {room}"))
    pre, post = [prefix] if prefix else [], []
    if mods:
        words = " ".join(mods)
        k = slot(("pre", "pre", "rel", "comma", "paren") if len(mods) == 1 and top else
                 ("pre", "pre", "rel") if len(mods) == 1 else ("pre", "pre", "comma", "paren"))
        pre += [words] if k == "pre" else []
        post += [] if k == "pre" else [("rel", f"is {words}") if k == "rel" else (k, f"the {words} one")]
    if states:
        words = " and ".join(states)
        k = slot(("rel", "rel", "comma", "paren"))
        that = _pick(rng, ("that is", "that's"))
        post.append(("rel", f"is {words}") if k == "rel" else (k, f"the one {that} {words}"))
    if room_piece:
        post.append(room_piece)
    if tail and not whichever:
        post.append(("clause" if tail.startswith(("that ", "whose ", "which ")) else "bare", tail))
    if hint:
        post.append(("bare", hint))
    if len(t.relations) == 1:
        r = t.relations[0]
        clause = rng.uniform() < (0.5 if top else 0.8)  # inside an anchor a clause keeps "it" on the anchor
        post.append(_relation(rng, r.type, _phrase(rng, r.anchor), clause, bool(r.anchor.relations)))
    elif t.relations:
        rels = [_relation(rng, r.type, _phrase(rng, r.anchor), False, bool(r.anchor.relations)) for r in t.relations]
        post.append(("bare", " and ".join(text for _, text in rels)))
    out = _assemble(rng, "the " + " ".join((*pre, t.head)), post)
    return out + f", {tail}," if whichever else out


def render_goal_unseen(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """'the lamp that is switched on (in the study)', 'the heater, the black one, whose temperature ...'."""
    return _phrase(rng, sg.target, prefix, sg.room, tail, hint, top=True)


# ----------------------------------------------------------------------------------------------------
# Sensor constraints

_ONES = ("zero one two three four five six seven eight nine ten eleven twelve thirteen fourteen fifteen sixteen "
         "seventeen eighteen nineteen").split()
_TENS = ("", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety")


def number_words(n: int) -> str:
    """English words for an integer in [-100, 100]: 65 -> 'sixty-five', -5 -> 'minus five'."""
    if n < 0:
        return "minus " + number_words(-n)
    if n < 20:
        return _ONES[n]
    if n < 100:
        return _TENS[n // 10] + (f"-{_ONES[n % 10]}" if n % 10 else "")
    if n == 100:
        return "one hundred"
    raise ValueError(f"no words for {n}")


def _amount(rng, reading: str, v: float) -> tuple[str, float, str]:
    """(number and unit as written, the value it denotes, unit code): '65 ºC', 'seventy per cent', '.7'."""
    vtxt = _fmt_value(reading, v)
    value = float(vtxt)
    if reading == "ndvi":
        forms = [vtxt, f"{value:.2f}"] + ([vtxt[1:]] if vtxt.startswith("0.") else [])
        return _pick(rng, forms), value, ""
    words = value.is_integer() and abs(value) <= 100 and rng.uniform() < 0.3
    num = number_words(int(value)) if words else vtxt
    if reading == "temperature_c":
        units = (" degrees", " degrees Celsius") if words else (" degrees", " degrees Celsius", "°C", " °C", " ºC",
                                                                  " deg C", " degrees C")
        return num + _pick(rng, units), value, "c"
    return num + _pick(rng, (" percent", " per cent") if words else ("%", " percent", " per cent")), value, "%"


# Superlatives: (adjectives for "that is the X" / "whichever one is X", prefixes before the noun).
_SUPER_UNSEEN = {
    ("temperature_c", "max"): (("warmest", "hottest"), ("highest-temperature",)),
    ("temperature_c", "min"): (("coldest", "coolest", "chilliest"), ("lowest-temperature", "chilliest")),
    ("ndvi", "max"): (("greenest", "healthiest"), ("highest-NDVI",)),
    ("ndvi", "min"): (("least healthy",), ("lowest-NDVI",)),
    ("humidity_pct", "max"): (("most humid", "dampest"), ("highest-humidity",)),
    ("humidity_pct", "min"): (("driest", "least humid"), ("lowest-humidity",)),
}
# Thresholds: {n} the reading's name, {an} with an article, {v} the amount. "reads" forms name no reading
# and are kept for temperatures and humidity, whose units say which reading is meant.
_CMP_UNSEEN = {
    "gt": ("whose {n} exceeds {v}", "with {an} exceeding {v}", "with {an} in excess of {v}", "that reads more than {v}"),
    "ge": ("with {an} no lower than {v}", "whose {n} is {v} or more", "whose {n} is not below {v}",
           "that reads {v} or above"),
    "lt": ("whose {n} falls below {v}", "whose {n} does not reach {v}", "with {an} beneath {v}",
           "that reads less than {v}"),
    "le": ("with {an} no higher than {v}", "whose {n} is {v} or less", "whose {n} does not exceed {v}",
           "that reads {v} or below"),
    "approx": ("whose {n} is close to {v}", "with {an} in the region of {v}", "that reads somewhere around {v}",
               "with {an} of {v} or thereabouts"),
}
_RUNNING = {"gt": ("running hotter than {v}", "running warmer than {v}"),
            "lt": ("running cooler than {v}", "running colder than {v}")}


def render_sensor_unseen(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written)."""
    rd, name = c.reading, READING_TEXT[c.reading]
    if c.is_superlative:
        adjs, prefixes = _SUPER_UNSEEN[(rd, c.comparator)]
        ext = "highest" if c.comparator == "max" else "lowest"
        k = int(rng.integers(5))
        if k == 0:
            return _pick(rng, prefixes), "", c
        tail = (f"that is the {_pick(rng, adjs)}", f"whichever one is {_pick(rng, adjs)}",
                f"with the {ext} {name} reading of all", f"that reads the {ext} {name}")[k - 1]
        return "", tail, c
    amount, value, code = _amount(rng, rd, c.value)
    forms = [f for f in _CMP_UNSEEN[c.comparator] if rd != "ndvi" or not f.startswith("that reads")]
    if rd == "temperature_c":
        forms += _RUNNING.get(c.comparator, ())
    an = {"temperature": "a temperature", "NDVI": "an NDVI", "humidity": "humidity"}[name]
    return "", _pick(rng, forms).format(n=name, an=an, v=amount), SensorConstraint(rd, c.comparator, value, code)


def hint_text_unseen(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in a new format; the numbers are x and y (sometimes padded: '3.5' -> '3.50')."""
    x, y = (s + "0" if re.fullmatch(r"-?\d+\.\d", s) and rng.uniform() < 0.2 else s for s in (x, y))
    return _pick(rng, (
        f"at position ({x}, {y})", f"at the point x {x}, y {y}", f"around ({x} m, {y} m)", f"at x: {x} and y: {y}",
        f"at coordinates x={x}; y={y}", f"where x is {x} and y is {y}", f"at map position [{x}, {y}]",
        f"in the vicinity of ({x}, {y})",
    ))


# ----------------------------------------------------------------------------------------------------
# Instructions

# (base form, -ing form): imperatives the seen VERBS list never uses.
VERBS_UNSEEN = (
    ("reach", "reaching"), ("stop at", "stopping at"), ("swing past", "swinging past"),
    ("make a stop at", "making a stop at"), ("head for", "heading for"), ("pop over to", "popping over to"),
    ("make for", "making for"), ("drop in at", "dropping in at"), ("get yourself to", "getting yourself to"),
    ("track down", "tracking down"), ("seek out", "seeking out"), ("wander over to", "wandering over to"),
)
_ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth")


def _tidy(s: str) -> str:
    """Closes up punctuation where a goal's closing apposition comma meets the next mark."""
    s = re.sub(r",\s*([,.;:?])", r"\1", s)
    s = re.sub(r",\s*—", " —", s)
    s = re.sub(r"\s{2,}", " ", s).strip()
    return s[0].upper() + s[1:]


def _list(rng, res: list[str]) -> str:
    """'X, Y and Z'; semicolons between goals when one has commas of its own (an apposition, a hint)."""
    if len(res) > 2 and any("," in r for r in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


def render_instruction_unseen(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals; strict texts state the order, free ones that it is open."""
    v = lambda: _pick(rng, VERBS_UNSEEN)[0]  # noqa: E731
    ing = lambda: _pick(rng, VERBS_UNSEEN)[1]  # noqa: E731
    n = len(res)
    if n == 1:
        g = res[0]
        return _tidy(_pick(rng, (
            f"{v()} {g}.", f"please {v()} {g}.", f"your job is to {v()} {g}.", f"I'd love it if you could {v()} {g}.",
            f"could you {v()} {g}?", f"would you mind {ing()} {g}?", f"I want you to {v()} {g}.",
            f"all I need is for you to {v()} {g}.",
        )))
    if order == "free":
        lst = _list(rng, res)
        k = int(rng.integers(8))
        s = (f"{v()} {lst} — the order is your call.",
             f"{v()} {'both ' if n == 2 else ''}{lst}, in any sequence you like.",
             f"{v()} {lst} in whatever order works best.",
             f"here are the stops, in no set order: {lst}.",
             f"I need you to {v()} {lst}. Which one comes first doesn't matter.",
             f"whichever order suits you, {v()} {lst}.",
             f"{v()} {lst}. Any order is fine.",
             f"{v()} {lst}. You can pick the order yourself.")[k]
        return _tidy(s)
    k = int(rng.integers(8 if n == 2 else 7))
    if k == 0:
        mid = "".join(f"; {_pick(rng, ('after that', 'next', 'following that'))}, {v()} {r}" for r in res[1:-1])
        s = f"start off at {res[0]}{mid}{'; wrap up with ' if n > 2 else ' and wrap up with '}{res[-1]}."
    elif k == 1:
        mid = "".join(f", then {r}" for r in res[1:-1])
        s = f"{res[0]} comes first{mid}, " + (f"and {res[-1]} comes last." if n > 2 else f"then {res[-1]}.")
    elif k == 2:
        conn = ("once you're done there", "when you've finished there", "once that's done", "after that")
        return " ".join(_tidy(f"{v()} {res[0]}.") if i == 0 else _tidy(f"{_pick(rng, conn)}, {v()} {r}.")
                        for i, r in enumerate(res))
    elif k == 3:
        mid = "".join(f", then {v()} {r}" for r in res[1:-1])
        s = f"before anything else, {v()} {res[0]}{mid}, " + (f"and last of all {v()} {res[-1]}." if n > 2 else
                                                             f"and then {v()} {res[-1]}.")
    elif k == 4:
        mid = "".join(f", your {_ORDINALS[i + 1]} is {r}" for i, r in enumerate(res[1:-1]))
        s = f"your first stop is {res[0]}{mid}, and your last is {res[-1]}."
    elif k == 5:
        s = _pick(rng, (f"in exactly this order, {v()} {_list(rng, res)}.", f"{v()} {_list(rng, res)}, in exactly that order."))
    elif k == 6:
        mid = "".join(f", {_pick(rng, ('move on to', 'carry on to'))} {r}" for r in res[1:-1])
        s = f"begin by {ing()} {res[0]}{mid}, and end up at {res[-1]}."
    else:
        s = f"{v()} {res[0]} before you {v()} {res[1]}."
    return _tidy(s)
