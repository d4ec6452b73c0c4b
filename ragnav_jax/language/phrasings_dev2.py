"""Unseen phrasings, second development set: templates for goals, sensor phrases, coordinates and instructions.

A third template set beside the seen one (`episodes.py`) and the unseen development one (`phrasings.py`):
the same four functions, arguments and meanings, with structures and wordings neither of them writes
(reduced relatives such as "located near", "kept on", "over in the kitchen"; dash and "i.e." appositions;
"currently" / "right now" states; "among those ..." superlative scope and "the warmest of the heaters";
"topping", "short of", "at or above", "or so"; "℃", "degrees centigrade", "% RH", ".70"; "(x: 3.5, y: 2)",
"x ≈ 3.5"; "Stop 1: ...", "1) ... 2) ...", arrows, "whichever way round"). It was the held-out test set
until parser round 2 was measured on it; parser round 3 was developed against it, and a new held-out
set (`phrasings_heldout.py`) took its place. Every draw comes from the NumPy generator passed in, so a
seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.phrasings import is_state, number_words
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# Relation wordings with the meanings of episodes.REL_TEXT / relation_holds (and types.RELATION_TYPES):
# (reduced forms after the noun, verb phrases after "that"/"which"). "{a}": the anchor; "{it}": the
# target's pronoun ("them" inside "among those ..."). "with": the anchor is on the target or near it.
_REL: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "near": (("not far from {a}", "located near {a}", "positioned close to {a}"),
             ("is not far from {a}", "is located near {a}")),
    "next_to": (("adjacent to {a}", "located next to {a}", "set next to {a}"),
                ("is adjacent to {a}", "is set next to {a}")),
    "beside": (("positioned beside {a}", "located beside {a}", "set beside {a}"), ("is positioned beside {a}",)),
    "by": (("over by {a}", "located by {a}", "positioned by {a}"), ("is over by {a}", "is located by {a}")),
    "on": (("kept on {a}", "set on top of {a}", "located on {a}"), ("is kept on {a}", "rests on top of {a}")),
    "with": (("with {a} either on top of {it} or beside {it}", "having {a} on {it} or next to {it}"),
             ("has {a} either on top of {it} or beside {it}",)),
    "in_room_with": (("in the room containing {a}", "located in the same room as {a}"),
                     ("is in the room that also holds {a}", "is located in the same room as {a}")),
    "under": (("beneath {a}", "located under {a}"), ("is located under {a}",)),
    "above": (("positioned above {a}", "located above {a}"), ("is positioned above {a}",)),
    "in": (("kept in {a}", "stored inside {a}"), ("is kept in {a}", "is stored inside {a}")),
    "in_front_of": (("positioned in front of {a}", "located in front of {a}"), ("is positioned in front of {a}",)),
    "behind": (("positioned behind {a}", "located behind {a}"), ("is positioned behind {a}",)),
    "opposite": (("located opposite {a}", "positioned opposite {a}"), ("is opposite {a}",)),
    "left_of": (("on the left-hand side of {a}", "positioned to the left of {a}"),
                ("is on the left-hand side of {a}",)),
    "right_of": (("on the right-hand side of {a}", "positioned to the right of {a}"),
                 ("is on the right-hand side of {a}",)),
}
_ROOM_RED = ("in the {r}", "over in the {r}", "inside the {r}", "located in the {r}")
_ROOM_REL = ("is in the {r}", "is over in the {r}", "is located in the {r}")
_ROOM_APP = ("the one in the {r}", "the one over in the {r}")
_MOD_APP = ("the {m} one", "i.e. the {m} one", "specifically the {m} one", "namely the {m} one")
_STATE_REL = ("is {s} right now", "is {s} at the moment", "is currently {s}")
_STATE_APP = ("the one that's currently {s}", "i.e. the one that's {s}", "the one that is {s} right now")
# States that "has been left ..." describes without changing them (what the object is now).
_LEFTABLE = frozenset(("switched on", "switched off", "turned on", "turned off", "open", "on", "off", "running",
                       "unlocked", "locked", "plugged in", "unplugged", "empty"))
_SCOPE = ("among those", "out of those", "of all those")


def _plural(head: str) -> str | None:
    """Plural of a head noun, or None where a plain rule could be wrong ('electronics', 'tv', 'shelf unit')."""
    if " of " in head:  # "chest of drawers" -> "chests of drawers"
        first, rest = head.split(" of ", 1)
        p = _plural(first)
        return p and f"{p} of {rest}"
    words = head.split(" ")
    last = words[-1]
    irregular = {"cactus": "cacti", "bookshelf": "bookshelves", "shelf": "shelves", "bonsai": "bonsai"}
    if last in irregular:
        p = irregular[last]
    elif len(last) < 3 or not last.replace("-", "").isalpha() or last.endswith(("s", "f", "fe")):
        return None
    elif last.endswith(("ch", "sh", "x", "z")):
        p = last + "es"
    elif last.endswith("y") and last[-2] not in "aeiou":
        p = last[:-1] + "ies"
    else:
        p = last + "s"
    return " ".join((*words[:-1], p))


def _relation(rng, r: Relation, clause: bool, it: str = "it", avoid: str = "") -> str:
    """One relation as a reduced phrase or (clause) a verb phrase; an anchor with relations of its own goes
    last, so 'it' never follows a nested anchor. Forms starting with `avoid` are skipped where others exist."""
    words = r.type.replace("_", " ")
    reduced, verbal = _REL.get(r.type, ((words + " {a}",), ("is " + words + " {a}",)))
    forms = verbal if clause else reduced
    if r.anchor.relations:
        fallback = "has, on {it} or next to {it}, {a}" if clause else "with {a}"
        forms = tuple(f for f in forms if f.endswith("{a}")) or (fallback,)
    forms = tuple(f for f in forms if not (avoid and f.startswith(avoid))) or forms
    return _pick(rng, forms).format(a=_anchor(rng, r.anchor), it=it)


def _anchor(rng, t: Target) -> str:
    """An anchor noun phrase: attributes before the noun, states as 'currently ...' (in a clause when the
    anchor has relations too), relations reduced."""
    states = " and ".join(a for a in t.attributes if is_state(a))
    out = "the " + " ".join((*(a for a in t.attributes if not is_state(a)), t.head))
    if states and t.relations:
        return f"{out} that is currently {states} and " + " and ".join(_relation(rng, r, True) for r in t.relations)
    if states:
        return f"{out} currently {states}"
    return out + "".join(" " + _relation(rng, r, False) for r in t.relations[:1]) + "".join(
        " and " + _relation(rng, r, False) for r in t.relations[1:])


def _assemble(rng, head: str, post: list[tuple[str, object]]) -> str:
    """Joins post-nominal pieces: 'red' reduced text, 'rel' (pronoun, verb phrase), 'app' an apposition
    (dashes when more follows, else parentheses). Consecutive relative clauses share an 'and'."""
    out, prev_pron = head, None
    for i, (kind, piece) in enumerate(post):
        if kind == "app":
            out += f" — {piece} —" if i < len(post) - 1 else f" ({piece})"
        elif kind == "red":
            out += f" {piece}"
        else:
            pron, vp = piece
            if prev_pron is not None and pron != "whose" and prev_pron != "whose":
                out += f" and {vp}"
            else:
                lead = " and " if prev_pron is not None else " "
                full = f"{pron} {vp}"
                if pron == "that" and vp.startswith("is ") and rng.uniform() < 0.5:
                    full = "that's " + vp[3:]
                out += lead + full
        prev_pron = piece[0] if kind == "rel" else None
    return out


def render_goal_dev2(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """'the kettle over in the kitchen adjacent to the sink', 'the warmest of the heaters in the study',
    'the heater — the black one — with a temperature topping 60 ℃', 'the lamp that's switched on right now'."""
    t = sg.target
    states = " and ".join(a for a in t.attributes if is_state(a))
    mods = " ".join(a for a in t.attributes if not is_state(a))
    room = sg.room
    if prefix in _PLURAL_OF and not (t.relations or states or hint or tail) and _plural(t.head) and rng.uniform() < 0.6:
        where = " " + _pick(rng, _ROOM_RED).format(r=room) if room else ""
        return f"the {prefix} of the {' '.join(filter(None, (mods, _plural(t.head))))}{where}"
    mods_pre = bool(mods) and (bool(prefix) or tail in _SUPER_TAILS or rng.uniform() < 0.65)
    head = "the " + " ".join(filter(None, (prefix, mods if mods_pre else "", t.head)))
    if tail in _SUPER_TAILS:  # the restrictions scope the superlative explicitly: "... among those in the kitchen"
        scope = (["currently " + states] if states else []) + ([_pick(rng, _ROOM_RED).format(r=room)] if room else [])
        scope += ([hint] if hint else []) + [_relation(rng, r, False, "them") for r in t.relations]
        return f"{head} {tail}" + (f" {_pick(rng, _SCOPE)} {' and '.join(scope)}" if scope else "")
    pron = _pick(rng, ("that", "which"))
    post: list[tuple[str, object]] = []
    app_free = True
    if mods and not mods_pre:
        post.append(("app", _pick(rng, _MOD_APP).format(m=mods)))
        app_free = False
    if hint:
        post.append(("red", hint))
    room_done, clauses = not room, False
    if room and tail and app_free and rng.uniform() < 0.5:  # set off before the reading: "— the one in the study —"
        post.append(("app", _pick(rng, _ROOM_APP).format(r=room)))
        room_done, app_free = True, False
    elif room and not tail:
        k = int(rng.integers(3 if app_free else 2))
        post.append([("red", _pick(rng, _ROOM_RED).format(r=room)),
                     ("rel", (pron, _pick(rng, _ROOM_REL).format(r=room))),
                     ("app", _pick(rng, _ROOM_APP).format(r=room))][k])
        room_done, app_free, clauses = True, app_free and k != 2, k == 1
    if tail:  # after a reading every piece is a clause ("... 60 ℃ currently on" misreads)
        m = re.match(r"(that|which|whose) (.*)", tail)
        post.append(("rel", (m.group(1), m.group(2))) if m else ("red", tail))
        clauses = True
    if states:
        leftable = all(s in _LEFTABLE for s in states.split(" and "))
        k = 1 if clauses else int(rng.integers(3 if app_free and not hint else 2))
        if k == 0 and (t.relations or not room_done or (post and post[-1][0] != "app")):
            k = 1  # "currently on" reads well only straight after the noun, with nothing after it
        if k == 0:
            post.append(("red", f"currently {states}"))
        elif k == 1:
            vp = _pick(rng, _STATE_REL + (("has been left {s}",) if leftable else ())).format(s=states)
            post.append(("rel", (pron, vp)))
            clauses = True
        else:
            post.append(("app", _pick(rng, _STATE_APP).format(s=states)))
    if not room_done:
        post.append(("rel", (pron, _pick(rng, _ROOM_REL).format(r=room))))
        clauses = True
    if t.relations:
        if clauses or rng.uniform() < 0.35:
            post += [("rel", (pron, _relation(rng, r, True))) for r in t.relations]
        else:  # one reduced piece: "located near X and kept on Y"
            avoid = post[-1][1].split()[0] if post and post[-1][0] == "red" else ""
            post.append(("red", " and ".join(_relation(rng, r, False, avoid=avoid) for r in t.relations)))
    return _assemble(rng, head, post)


# ----------------------------------------------------------------------------------------------------
# Sensor constraints

# Reading names: (name, with article).
_NAMES = {"temperature_c": (("temperature", "a temperature"), ("temperature reading", "a temperature reading")),
          "humidity_pct": (("humidity", "humidity"), ("humidity level", "a humidity level"),
                           ("relative humidity", "a relative humidity")),
          "ndvi": (("NDVI", "an NDVI"), ("NDVI value", "an NDVI value"), ("NDVI score", "an NDVI score"))}
# Thresholds naming the reading: {n} name, {an} with article, {v} the amount.
_CMP = {
    "gt": ("with {an} topping {v}", "whose {n} tops {v}", "with {an} surpassing {v}"),
    "ge": ("whose {n} is at or above {v}", "with {an} of {v} or higher", "with {an} no less than {v}"),
    "lt": ("whose {n} stays under {v}", "with {an} short of {v}", "with {an} of under {v}"),
    "le": ("whose {n} is at or below {v}", "with {an} of {v} or lower", "with {an} no greater than {v}"),
    "approx": ("whose {n} hovers around {v}", "with {an} near {v}", "with {an} of {v} or so",
               "whose {n} is in the neighbourhood of {v}"),
}
# The amount first, the reading named by its unit or after it.
_AMOUNT_FIRST = {
    "temperature_c": {"gt": "running at more than {v}", "ge": "running at {v} or higher",
                      "lt": "running at less than {v}", "le": "running at no more than {v}",
                      "approx": "running at {v} or so"},
    "humidity_pct": {"gt": "with more than {v} humidity", "ge": "with no less than {v} humidity",
                     "lt": "with under {v} humidity", "le": "with no more than {v} humidity",
                     "approx": "with {v} humidity or so"},
    "ndvi": {"gt": "scoring over {v} NDVI", "ge": "scoring {v} NDVI or higher", "lt": "scoring under {v} NDVI",
             "le": "scoring {v} NDVI or lower", "approx": "scoring {v} NDVI or so"},
}
# Superlatives: adjectives (before the noun, or in "the warmest of the heaters") and tails.
_SUPER_ADJ = {
    ("temperature_c", "max"): ("warmest", "hottest"), ("temperature_c", "min"): ("coldest", "coolest"),
    ("ndvi", "max"): ("greenest", "healthiest"), ("ndvi", "min"): ("least healthy",),
    ("humidity_pct", "max"): ("most humid", "dampest"), ("humidity_pct", "min"): ("driest", "least humid"),
}
_PLURAL_OF = frozenset(w for ws in _SUPER_ADJ.values() for w in ws)  # "the warmest of the heaters"


def _super_tails(reading: str, comparator: str) -> tuple[str, ...]:
    ext, most = ("highest", "maximum") if comparator == "max" else ("lowest", "minimum")
    out = tuple(f.format(n=n) for n, _ in _NAMES[reading]
                for f in (f"with the {most} {{n}}", f"that has the {ext} {{n}}", f"showing the {ext} {{n}}"))
    if reading == "temperature_c":
        out += ("running the hottest", "running the warmest") if comparator == "max" else ("running the coldest",
                                                                                             "running the coolest")
    return out


_SUPER_TAILS = frozenset(t for rd, c in _SUPER_ADJ for t in _super_tails(rd, c))


def _amount(rng, reading: str, v: float, rh: bool) -> tuple[str, float, str]:
    """(number and unit as written, the value it denotes, unit code): '60 ℃', 'sixty degrees C', '.70'."""
    vtxt = _fmt_value(reading, v)
    value = float(vtxt)
    if reading == "ndvi":
        forms = [vtxt] + ([f"{value:.2f}", f"{value:.2f}"[1:]] if 0 < value < 1 else [])
        return _pick(rng, forms), value, ""
    if value.is_integer() and abs(value) <= 100 and rng.uniform() < 0.3:
        num, words = number_words(int(value)), True
    else:
        num, words = ("minus " + _fmt_value(reading, -value) if value < 0 and rng.uniform() < 0.4 else vtxt), False
    if reading == "temperature_c":
        units = ((" degrees C", " degrees centigrade", " degrees Celsius") if words else
                 (" ℃", "℃", " °C", "°", " degrees centigrade", " Celsius"))
        return num + _pick(rng, units), value, "c"
    units = (" per cent", " percent") if words else ("%", " %", " per cent") + (("% RH",) if rh else ())
    return num + _pick(rng, units), value, "%"


def render_sensor_dev2(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written)."""
    rd = c.reading
    if c.is_superlative:
        if rng.uniform() < 0.4:
            extra = {("temperature_c", "max"): ("hottest-running",), ("temperature_c", "min"): ("coolest-running",)}
            return _pick(rng, _SUPER_ADJ[(rd, c.comparator)] + extra.get((rd, c.comparator), ())), "", c
        return "", _pick(rng, _super_tails(rd, c.comparator)), c
    n, an = _pick(rng, _NAMES[rd])
    named = rng.uniform() < 0.7
    amount, value, code = _amount(rng, rd, c.value, rh=named and n in ("humidity", "humidity level"))
    form = _pick(rng, _CMP[c.comparator]) if named else _AMOUNT_FIRST[rd][c.comparator]
    tail = form.format(n=n, an=an, v=amount)
    return "", tail, SensorConstraint(rd, c.comparator, value, code)


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_dev2(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres); the numbers are x and y, sometimes padded ('2' -> '2.0')
    or with a typographic minus."""

    def style(s: str) -> str:
        if re.fullmatch(r"-?\d+", s) and rng.uniform() < 0.2:
            s += ".0"
        return s.replace("-", "−") if rng.uniform() < 0.15 else s

    x, y = style(x), style(y)
    return _pick(rng, (
        f"at (x: {x}, y: {y})", f"at x ≈ {x} and y ≈ {y}", f"at x-coordinate {x} and y-coordinate {y}",
        f"sitting {x} m along the x-axis and {y} m along the y-axis from the origin",
        f"at approximately x={x} and y={y}", f"at the (x, y) position ({x}, {y})",
        f"found at the point with x = {x} and y = {y}", f"positioned at roughly ({x}, {y})",
    ))


# ----------------------------------------------------------------------------------------------------
# Instructions

# (base, -ing, past participle): imperatives neither the seen VERBS nor phrasings.VERBS_UNSEEN use.
VERBS_HELDOUT = (
    ("travel to", "travelling to", "travelled to"), ("proceed to", "proceeding to", "proceeded to"),
    ("roll over to", "rolling over to", "rolled over to"), ("drop by", "dropping by", "dropped by"),
    ("call at", "calling at", "called at"), ("move over to", "moving over to", "moved over to"),
    ("make it to", "making it to", "made it to"), ("take a look at", "taking a look at", "taken a look at"),
    ("hop over to", "hopping over to", "hopped over to"), ("nip over to", "nipping over to", "nipped over to"),
)
_COUNT = ("two", "three", "four", "five", "six", "seven", "eight", "nine", "ten")
_ORD = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth")


def _cap(s: str) -> str:
    return s[0].upper() + s[1:]


def _list(rng, res: list[str]) -> str:
    """'X, Y and Z'; semicolons (or 'as well as' for two) when a goal has its own commas or 'and'."""
    busy = any("," in r or " and " in r for r in res)
    if len(res) == 2:
        return f"{res[0]} as well as {res[1]}" if busy else f"{res[0]} and {res[1]}"
    if busy:
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


def _numbered(rng, res: list[str]) -> str:
    return _pick(rng, (" ", "; ")).join(f"{i}) {r}" for i, r in enumerate(res, 1))


def render_instruction_dev2(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals; strict texts state the order, free ones that it is open."""
    v = lambda: _pick(rng, VERBS_HELDOUT)[0]  # noqa: E731
    pp = lambda: _pick(rng, VERBS_HELDOUT)[2]  # noqa: E731
    n = len(res)
    if n == 1:
        g = res[0]
        return _cap(_pick(rng, (
            f"kindly {v()} {g}.", f"your task: {v()} {g}.", f"{v()} {g}, please.", f"would you {v()} {g}?",
            f"if you could {v()} {g}, that would be great.", f"I'd appreciate it if you'd {v()} {g}.",
            f"time to {v()} {g}.",
        )))
    p = _pick(rng, ("", "", "kindly ", "please "))
    if order == "free":
        k = int(rng.integers(7))
        s = (f"I need {_COUNT[n - 2]} things {_pick(rng, ('checked', 'visited', 'looked at'))}: {_list(rng, res)}. "
             "Any order will do.",
             f"{p}{v()} {_list(rng, res)}, in an order of your choosing.",
             f"there's no required order here: {v()} {_list(rng, res)}.",
             f"{v()} {_list(rng, res)}, whichever way round you like." if n == 2 else
             f"{p}{v()} {_list(rng, res)}; the sequence is entirely up to you.",
             f"{p}{v()} all of these, in no fixed order: {_numbered(rng, res)}.",
             f"you decide the order: {v()} {_list(rng, res)}.",
             f"{p}{v()} {_list(rng, res)}. Order them however you like.")[k]
        return _cap(s)
    k = int(rng.integers(9 if n == 2 else 8))
    if k == 0:
        s = [f"first things first: {v()} {res[0]}."] + [f"next up, {v()} {r}." for r in res[1:-1]]
        s.append(f"{'to finish' if n > 2 else 'next up'}, {v()} {res[-1]}.")
    elif k == 1:
        s = ["follow this route in order."] + [f"stop {i}: {r}." for i, r in enumerate(res, 1)]
    elif k == 2:
        s = [f"{p}{v()} the following, in this order: {_numbered(rng, res)}."]
    elif k == 3:
        mid = "".join(f", {r} your {_ORD[i]}" for i, r in enumerate(res[1:-1], 1))
        end = f", and {res[-1]} your last." if n > 2 else f" and {res[-1]} your second."
        s = [f"make {res[0]} your first stop{mid}{end}"]
    elif k == 4:
        mid = "".join(f", press on to {r}" for r in res[1:-1])
        s = [f"kick off at {res[0]}{mid}{',' if n > 2 else ''} and round things off at {res[-1]}."]
    elif k == 5:
        s = [f"{_pick(rng, ('follow this route', 'take this route', 'route to take'))}: {' → '.join(res)}."]
    elif k == 6:
        s = [f"{v()} {res[0]} first of all."] + [f"having {pp()} that one, {v()} {r}." for r in res[1:]]
    elif k == 7:
        s = [f"{p}{v()} the following in sequence: {'; '.join(res)}."]
    else:
        s = [f"{p}{v()} {res[0]} and, after that, {v()} {res[1]}."]
    return " ".join(_cap(x) for x in s)
