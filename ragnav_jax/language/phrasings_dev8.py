"""Eighth development phrasings: goal, sensor, coordinate and instruction templates (`unseen_dev8` split).

Held-out set D (then `unseen`): measured after parser round 8 (93 of 192 instructions read back, closed-loop
success 0.682-0.693), and only then developed against, in round 9.

Written by a sixth author who never read the rule parser, to measure how far it generalises. Same four
functions, arguments and meanings as the other template sets. The style is messages typed into a home-robot
phone app by the people of one household:

- a parent in a hurry: terse, everything packed into one noun phrase ("the teal corduroy bean bag by the
  crib", "the games room's vintage jukebox", "the kettle (kitchen)"), "A, then B, then C. In that order.",
  "A → B → C", "Any order.";
- a teenager: lowercase, "rn", "plz", "u", "then the", "idc what order", full stops instead of lists, and
  now and then the order backwards ("check B rn. but before that find A": A is visited first);
- an older relative: polite and wordy ("Would you be so kind as to ...", "once you have done that",
  "and to finish, ...", "I'm not fussy about the order");
- a tidy-minded person: semicolon lists and numbered steps ("In this order: 1) ...; 2) ...; 3) ...").

Goals: attributes before the noun exactly as given; states ("switched on", "open", "empty") before the noun,
in a relative clause ("that's currently switched on") or in brackets right after the noun; the room as
"in the X", "(X)" or a possessive ("the nursery's ..."), always before any relation so that nothing after
an anchor can attach to it; anchors with their own relation take a relative clause ("next to the credenza
that's itself near the harp", "by the shelf unit that has the work light"). Readings: digits, words
("twenty-two", "minus eighteen"), decimals ("20.0", ".35", "0.40"), "°C", "deg", "degrees", "C", "%",
"percent", "per cent"; comparatives in everyday words ("hotter than", "at 20 °C or more", "no warmer than",
"scoring under .3 on NDVI", "at 52 deg, give or take"); superlatives as adjectives ("the coldest", "the least
healthy") or tails ("with the lowest humidity", "that's running hottest").
Coordinates: "(3.5, 2)", "x 3.5 y 2", "x=3.5, y=2", "3.5/2", "[3.5, 2]", "x: 3.5, y: 2", always x then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.phrasings import number_words
from ragnav_jax.language.phrasings_dev4 import _and
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Small helpers


def split_attributes(t: Target) -> tuple[list[str], list[str]]:
    """(attributes written before the noun, states) of a target: the phrase holds the former in order."""
    mods = t.phrase[: len(t.phrase) - len(t.head)].split() if t.phrase.endswith(t.head) else t.phrase.split()
    pre, states, i = [], [], 0
    for a in t.attributes:
        w = a.split()
        if w and mods[i : i + len(w)] == w:
            pre.append(a)
            i += len(w)
        else:
            states.append(a)
    return pre, states


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

_REL = {
    "near": ("near", "close to", "not far from"),
    "next_to": ("next to", "alongside", "just next to"),
    "beside": ("beside", "just beside"),
    "by": ("by", "just by"),
    "on": ("on", "on top of", "sitting on"),
    "under": ("under", "underneath", "beneath"),
    "above": ("above", "hanging above"),
    "in": ("in", "inside"),
    "with": ("with",),
    "in_room_with": ("in the same room as", "in the room with"),
    "in_front_of": ("in front of",),
    "behind": ("behind", "just behind"),
    "opposite": ("opposite", "across from", "facing"),
    "left_of": ("to the left of", "left of"),
    "right_of": ("to the right of",),
}


def is_plural(head: str) -> bool:
    """'shelves', 'drums' take 'that are'; 'cactus', 'glass', 'iris' do not."""
    w = head.split()[-1] if head.split() else head
    return w.endswith("s") and not w.endswith(("ss", "us", "is", "ics"))


def _rel_words(rng, r: Relation) -> str:
    """The words of a relation; 'in the same room as' before an anchor with a clause of its own, so the
    clause cannot be read as the room's."""
    if r.type == "in_room_with" and r.anchor.relations:
        return "in the same room as"
    return _pick(rng, _REL[r.type])


def _that_is(rng, plural: bool, extra: tuple[str, ...] = ()) -> str:
    opts = ("that are", "which are", "that are" ) if plural else ("that is", "that's", "which is")
    return _pick(rng, opts + tuple(f"{opts[0]} {e}" for e in extra))


def _that_has(rng, plural: bool) -> str:
    return _pick(rng, ("that have", "which have") if plural else ("that has", "which has"))


def _anchor(rng, t: Target) -> str:
    """An anchor noun phrase: a state before a bare noun ('the switched off steam iron') or in brackets after
    a modified one ('the burgundy tumble dryer (switched on)'); its own relations as a relative clause."""
    pre, states = split_attributes(t)
    plural = is_plural(t.head)
    if states and not pre and len(states) == 1:
        s = f"the {states[0]} {t.phrase}"
    elif states:
        s = f"the {t.phrase} ({' and '.join(states)})"
    else:
        s = f"the {t.phrase}"
    rels = list(t.relations)
    if not rels:
        return s
    if len(rels) == 1 and rels[0].type == "with" and not rels[0].anchor.relations and rng.uniform() < 0.5:
        return f"{s} with {_anchor(rng, rels[0].anchor)}"
    rels.sort(key=lambda r: bool(r.anchor.relations))  # a clause-bearing anchor goes last
    parts = []
    for i, r in enumerate(rels):
        a = _anchor(rng, r.anchor)
        if r.type == "with":
            parts.append(f"{_that_has(rng, plural) if i == 0 else ('have' if plural else 'has')} {a}")
        else:
            lead = _that_is(rng, plural, ("itself",) if not plural else ()) if i == 0 else ""
            parts.append(f"{lead} {_rel_words(rng, r)} {a}".strip())
    return f"{s} " + " and ".join(parts)


def _relations(rng, t: Target) -> str:
    """The target's relations, after everything else in the goal: a prepositional phrase or a clause."""
    rels = sorted(t.relations, key=lambda r: bool(r.anchor.relations))
    plural = is_plural(t.head)
    if len(rels) == 1:
        r = rels[0]
        a = _anchor(rng, r.anchor)
        if r.type == "with":
            return _pick(rng, (f"with {a}", f"with {a}", f"{_that_has(rng, plural)} {a}"))
        if r.type == "on" and rng.uniform() < 0.3:
            return f"{_pick(rng, ('sitting on', 'standing on', 'resting on'))} {a}"
        if rng.uniform() < 0.7:
            return f"{_rel_words(rng, r)} {a}"
        return f"{_that_is(rng, plural)} {_rel_words(rng, r)} {a}"
    be, have = ("are", "have") if plural else ("is", "has")
    parts = [f"{have} {_anchor(rng, r.anchor)}" if r.type == "with" else f"{be} {_rel_words(rng, r)} {_anchor(rng, r.anchor)}"
             for r in rels]
    return "that " + " and ".join(parts[:-1]) + " and also " + parts[-1]


# ----------------------------------------------------------------------------------------------------
# Goals


def render_goal_dev8(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as a household member types it: 'the teal corduroy bean bag by the crib', 'the games room's
    vintage jukebox', 'the toy chest (open) in the nursery', 'the heater in the pantry that's over 20 °C', 'the
    coldest chest freezer in the garage', 'the guitar at x 3.5 y 2', 'the lamp next to the credenza that has
    the record player'. Relations always come last, so nothing written after an anchor belongs to the goal.
    """
    t = sg.target
    pre, states = split_attributes(t)
    plural = is_plural(t.head)
    room = sg.room
    pre_noun = f"{prefix} " if prefix else ""
    # room: possessive, bracketed straight after the noun, or "in the X" after the noun's own modifiers
    room_style = None
    if room:
        room_style = _pick(rng, ("in", "in", "in", "possessive", "bracket"))
    # states: before the noun (one state, no superlative adjective), in brackets, or a relative clause
    state_style = None
    if states:
        before_ok = len(states) == 1 and not prefix and (not pre or " " not in states[0])  # not "switched off vintage"
        opts = ["clause", "clause", "bracket"] + (["before"] if before_ok else [])
        state_style = _pick(rng, opts)
        if state_style == "bracket" and room_style == "bracket":
            state_style = "clause"
    det = f"the {room}'s " if room_style == "possessive" else "the "
    before = (states[0] + " ") if state_style == "before" else ""
    s = det + pre_noun + before + t.phrase
    post: list[tuple[str, str]] = []  # (kind, text) of the modifiers after the noun, in order
    if state_style == "bracket":
        s += " (" + " and ".join(states) + ")"
    if room_style == "bracket":
        s += f" ({_pick(rng, (room, 'in the ' + room))})"
    if state_style == "clause":
        post.append(("state", f"{_that_is(rng, plural, ('currently',))} {' and '.join(states)}"))
    if hint:
        post.append(("hint", hint))
    if room_style == "in":
        post.append(("room", f"in the {room}"))
    if tail:
        if plural and tail.startswith("that's "):
            tail = "that are " + tail[len("that's "):]
        post.append(("tail", tail))
    if t.relations:
        post.append(("rel", _relations(rng, t)))
    out = s
    for i, (kind, text) in enumerate(post):
        if i == 0:
            out += " " + text
        elif kind == "tail" and post[i - 1][0] == "room" and text.startswith(("that", "which", "whose", "with")):
            out += ", the one " + text  # "the heater in the pantry, the one that's over 20 °C": not the pantry's
        else:
            out += ", " + text  # every further modifier restarts after a comma, so it belongs to the goal
    return out


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

_TEMP_UNITS = ((" °C", "c"), ("°C", "c"), (" degrees", "c"), (" deg", "c"), (" degrees C", "c"), (" C", "c"),
               (" degrees Celsius", "c"))
_HUM_UNITS = (("%", "%"), (" %", "%"), (" percent", "%"), (" per cent", "%"))


def _number(rng, reading: str, value: float) -> tuple[str, float]:
    """(the number as written, its value)."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    if reading == "ndvi":
        if 0 < v < 1:
            return _pick(rng, (txt, txt, txt[1:] if txt.startswith("0.") else txt, f"{v:.2f}")), v
        return txt, v
    if v == int(v):
        u = rng.uniform()
        if u < 0.22 and abs(v) < 100:
            return number_words(int(v)), v
        if u < 0.34:
            return f"{v:.1f}", v
        if v < 0 and u < 0.5:
            return f"minus {txt[1:]}", v
    return txt, v


_TEMP_TAILS = {
    "gt": ("that's warmer than {n}{u}", "running hotter than {n}{u}", "reading over {n}{u}", "at more than {n}{u}",
           "with a temperature above {n}{u}", "that's above {n}{u}"),
    "ge": ("at {n}{u} or more", "that's at least {n}{u}", "reading {n}{u} or higher", "that's no cooler than {n}{u}",
           "with a temperature of at least {n}{u}", "at {n}{u} or warmer"),
    "lt": ("that's colder than {n}{u}", "reading under {n}{u}", "at less than {n}{u}", "running cooler than {n}{u}",
           "with a temperature below {n}{u}", "that's below {n}{u}"),
    "le": ("at {n}{u} or less", "that's at most {n}{u}", "reading {n}{u} or lower", "that's no warmer than {n}{u}",
           "with a temperature of at most {n}{u}", "at {n}{u} or colder"),
    "approx": ("at about {n}{u}", "reading roughly {n}{u}", "that's around {n}{u}", "sitting at approximately {n}{u}",
               "with a temperature of about {n}{u}", "at {n}{u}, give or take"),
}
_HUM_TAILS = {
    "gt": ("that's more humid than {n}{u}", "with humidity above {n}{u}", "reading over {n}{u} humidity",
           "at more than {n}{u} humidity"),
    "ge": ("with humidity of at least {n}{u}", "at {n}{u} humidity or more", "that's no drier than {n}{u}",
           "reading {n}{u} humidity or higher"),
    "lt": ("that's drier than {n}{u}", "with humidity below {n}{u}", "reading under {n}{u} humidity",
           "that's less humid than {n}{u}"),
    "le": ("with humidity of {n}{u} or less", "at most {n}{u} humidity", "that's no more humid than {n}{u}",
           "reading {n}{u} humidity or lower"),
    "approx": ("at about {n}{u} humidity", "with humidity around {n}{u}", "reading roughly {n}{u} humidity",
               "with humidity of approximately {n}{u}"),
}
_NDVI_TAILS = {
    "gt": ("with an NDVI above {n}", "whose NDVI is over {n}", "with NDVI higher than {n}", "scoring more than {n} on NDVI"),
    "ge": ("with an NDVI of {n} or more", "with NDVI at least {n}", "whose NDVI is no lower than {n}",
           "scoring {n} or higher on NDVI"),
    "lt": ("with an NDVI under {n}", "whose NDVI is below {n}", "with NDVI less than {n}", "scoring under {n} on NDVI"),
    "le": ("with an NDVI of {n} or less", "with NDVI at most {n}", "whose NDVI is no higher than {n}",
           "scoring {n} or lower on NDVI"),
    "approx": ("with an NDVI of about {n}", "whose NDVI is roughly {n}", "with NDVI around {n}",
               "scoring approximately {n} on NDVI"),
}
_SUPER_PREFIX = {
    ("temperature_c", "max"): ("warmest", "hottest"),
    ("temperature_c", "min"): ("coldest", "chilliest"),
    ("ndvi", "max"): ("healthiest", "lushest"),
    ("ndvi", "min"): ("least healthy", "sickliest"),
    ("humidity_pct", "max"): ("most humid", "dampest"),
    ("humidity_pct", "min"): ("driest", "least humid"),
}
_SUPER_TAIL = {
    ("temperature_c", "max"): ("with the highest temperature", "that's running hottest", "reading the highest temperature"),
    ("temperature_c", "min"): ("with the lowest temperature", "that's running coldest", "reading the lowest temperature"),
    ("ndvi", "max"): ("with the highest NDVI", "with the best NDVI score", "whose NDVI is highest"),
    ("ndvi", "min"): ("with the lowest NDVI", "with the worst NDVI score", "whose NDVI is lowest"),
    ("humidity_pct", "max"): ("with the highest humidity", "reading the most humid", "whose humidity is highest"),
    ("humidity_pct", "min"): ("with the lowest humidity", "reading the driest", "whose humidity is lowest"),
}


def render_sensor_dev8(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective ('coldest', 'most humid', 'least healthy') or a tail ('with the lowest
    humidity', 'that's running hottest'); thresholds: a tail that reads after the noun or after 'the one'
    ('that's no warmer than 20 °C', 'at 45 percent humidity or more', 'with an NDVI of .35 or less',
    'reading under minus eighteen degrees', 'at about 60%').
    """
    rd = c.reading
    if c.is_superlative:
        if rng.uniform() < 0.5:
            return _pick(rng, _SUPER_PREFIX[(rd, c.comparator)]), "", c
        return "", _pick(rng, _SUPER_TAIL[(rd, c.comparator)]), c
    n, value = _number(rng, rd, c.value)
    if rd == "ndvi":
        return "", _pick(rng, _NDVI_TAILS[c.comparator]).format(n=n), SensorConstraint(rd, c.comparator, value, "")
    if rd == "temperature_c":
        pat = _pick(rng, _TEMP_TAILS[c.comparator])
        if "temperature" in pat and rng.uniform() < 0.3:
            u, code = "", ""
        else:
            u, code = _pick(rng, _TEMP_UNITS)
        if n[0].isalpha() and u.startswith("°"):  # "twenty °C" reads oddly: words take a spelled unit
            u = " degrees"
        return "", pat.format(n=n, u=u), SensorConstraint(rd, c.comparator, value, code)
    pat = _pick(rng, _HUM_TAILS[c.comparator])
    if pat.startswith("with humidity") and rng.uniform() < 0.3:
        u, code = "", ""
    else:
        u, code = _pick(rng, _HUM_UNITS)
    if n[0].isalpha() and "%" in u:
        u = " percent"
    return "", pat.format(n=n, u=u), SensorConstraint(rd, c.comparator, value, code)


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_dev8(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y, as typed on a phone: '(3.5, 2)', 'at x 3.5 y
    2', 'at x=3.5, y=2', 'around 3.5/2', 'at [3.5, 2]', 'at x: 3.5, y: 2', 'at position 3.5, 2'. Every form
    reads straight after a noun.
    """
    return _pick(rng, (
        f"({x}, {y})", f"at ({x}, {y})", f"at x {x} y {y}", f"at x={x}, y={y}", f"around {x}/{y}",
        f"at [{x}, {y}]", f"at x: {x}, y: {y}", f"at position {x}, {y}", f"at roughly ({x}, {y})",
        f"around x {x}, y {y}", f"at coords {x},{y}", f"at ({x} m, {y} m)",
    ))


# ----------------------------------------------------------------------------------------------------
# Whole instructions

_VERBS = ("go to", "head to", "check on", "have a look at", "pop over to", "swing by", "stop at", "visit",
          "go and look at", "find", "get over to", "look in on")
_TEEN_VERBS = ("go to", "go check", "check", "swing by", "go see", "find", "head to")
_WORDY_VERBS = ("go to", "visit", "look in on", "pop along to", "have a look at", "call in at", "make your way to")


def _finish(s: str, cap: bool = True) -> str:
    s = s.strip().replace(" ,", ",").replace(",,", ",").replace(",.", ".").replace(",?", "?").replace(",;", ";")
    if not s.endswith((".", "?", "!")):
        s += "."
    return s[0].upper() + s[1:] if cap else s


def _risky(res: list[str]) -> bool:
    """Goals whose text would blur a plain comma / 'and' list: inner commas, 'and', brackets, clauses, anchors."""
    return any(("," in r or " and " in r or " with " in r or "(" in r or " that" in r or " which" in r
                or len(r.split()) > 5) for r in res)


def _short(r: str) -> bool:
    """A goal plain enough to take 'first' / 'last' after it without the word reading as part of it."""
    return len(r.split()) <= 4 and not any(ch.isdigit() for ch in r) and "(" not in r and " that" not in r


def _lower_start(s: str) -> str:
    return s if s.startswith("I ") else s[0].lower() + s[1:]


def _parent(rng, res: list[str], order: str) -> str:
    v = _pick(rng, ("", "", "check ", "go to ", "visit "))
    n = len(res)
    if n == 1:
        return _finish(f"{v}{res[0]}" + _pick(rng, ("", "", ". Asap", ". Quick please", " please")))
    if order == "strict":
        k = int(rng.integers(4))
        if k == 0:
            if _short(res[0]):
                return _finish(f"{v}{res[0]} first" + "".join(f", then {r}" for r in res[1:])) + " In that order."
            return _finish(f"first {v}{res[0]}" + "".join(f", then {r}" for r in res[1:])) + " In that order."
        if k == 1:
            return _finish(" → ".join(res)) + _pick(rng, (" In that order.", " Strictly in that order."))
        if k == 2:
            mid = "".join(f", then {r}" for r in res[1:-1])
            end = f", {res[-1]} last" if _short(res[-1]) else f", and last of all {res[-1]}"
            return _finish(f"first {v}{res[0]}{mid}{end}")
        return _finish(f"{v}{res[0]}" + "".join(f", after that {r}" for r in res[1:])) + " Keep to that order."
    if _risky(res):
        return _finish("; ".join(res)) + _pick(rng, (" Any order.", " Order doesn't matter.", " Whatever order."))
    lst = ", ".join(res[:-1]) + " and " + res[-1]
    return _finish(f"{v}{lst}") + _pick(rng, (" Any order.", " Order doesn't matter.", " Whatever order is quickest."))


def _teen(rng, res: list[str], order: str) -> str:
    v = _pick(rng, _TEEN_VERBS)
    please = _pick(rng, (" plz", " pls", " rn", " rn plz", ""))
    n = len(res)
    if n == 1:
        s = _pick(rng, (f"{v} {res[0]}{please}", f"can u {v} {res[0]}{please}", f"yo {v} {res[0]}{please}"))
        return s.lower().rstrip(",")
    if order == "strict":
        k = int(rng.integers(4))
        if k == 0:
            if _risky(res):
                s = f"first {v} {res[0]}" + "".join(f". then {r}" for r in res[1:]) + please
            elif _short(res[0]):
                s = f"{v} {res[0]} first" + "".join(f" then {r}" for r in res[1:]) + please
            else:
                s = f"first {v} {res[0]}" + "".join(f" then {r}" for r in res[1:]) + please
        elif k == 1:
            s = f"can u {v} {res[0]}{please}. after that {res[1]}" + "".join(f". then {r}" for r in res[2:])
            s += ". in that order"
        elif k == 2 and n == 2:
            s = f"{v} {res[1]}{please}. but before that {_pick(rng, _TEEN_VERBS)} {res[0]}"
        else:
            s = f"first {res[0]}. then {res[1]}" + "".join(f". then {r}" for r in res[2:]) + f". that order{please}"
        return s.lower()
    free = _pick(rng, ("any order is fine", "idc what order", "order doesnt matter", "whatever order u want"))
    if n == 2 and rng.uniform() < 0.4:
        free = _pick(rng, ("idc which one first", "doesnt matter which first"))
    if _risky(res):
        s = f"{v} {res[0]}. also {res[1]}" + "".join(f". also {r}" for r in res[2:]) + f"{please}. {free}"
    else:
        s = f"{v} {', '.join(res[:-1])} and {res[-1]}{please}, {free}"
    return s.lower()


def _wordy(rng, res: list[str], order: str) -> str:
    v = _pick(rng, _WORDY_VERBS)
    open_ = _pick(rng, ("Would you be so kind as to", "Would you be a dear and", "I wonder if you could",
                        "Could you possibly"))
    thanks = _pick(rng, (" Thank you ever so much.", " Many thanks.", " Thank you, dear.", ""))
    n = len(res)
    if n == 1:
        return _finish(f"{open_} {v} {res[0]}?") + thanks
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            if n == 2:
                s = f"{open_} first {v} {res[0]}, and once you have done that, {res[1]}"
            else:
                s = f"{open_} first {v} {res[0]}; once you have done that, {res[1]}"
                s += "".join(f"; after that, {r}" for r in res[2:-1]) + f"; and to finish, {res[-1]}"
            return _finish(s + "?") + thanks
        if k == 1:
            sep = "; " if _risky(res) else ", "
            s = f"To begin with, {_lower_start(open_)} {v} {res[0]}" + "".join(f"{sep}then {r}" for r in res[1:-1])
            s += f"{sep}and, at the very end, {res[-1]}" if n > 2 else f"{sep}and after that {res[-1]}"
            return _finish(s + "?") + " Please keep to that order." + thanks
        steps = [f"To start with, {_lower_start(open_)} {v} {res[0]}?"]
        steps += [f"After that, please {_pick(rng, _WORDY_VERBS)} {r}." for r in res[1:-1]]
        steps += [f"And lastly, {_pick(rng, _WORDY_VERBS)} {res[-1]}."]
        return " ".join(_finish(x) for x in steps) + thanks
    free = _pick(rng, ("I'm not fussy about the order.", "The order makes no difference to me.",
                       "Do them in whichever order suits you.", "Any order will do."))
    if n == 2:
        s = f"{open_} {v} {res[0]}, and also {res[1]}" if _risky(res) else f"{open_} {v} {res[0]} and {res[1]}"
    elif _risky(res):
        s = f"{open_} {v} {res[0]}" + "".join(f"; and {r}" if i == n - 2 else f"; {r}" for i, r in enumerate(res[1:]))
    else:
        s = f"{open_} {v} {_and(res)}"
    return _finish(s + "?") + " " + free + thanks


def _tidy(rng, res: list[str], order: str) -> str:
    n = len(res)
    if n == 1:
        return _finish(_pick(rng, (f"Task: {res[0]}", f"One stop: {res[0]}", f"Please {_pick(rng, _VERBS)} {res[0]}")))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            return _finish("In this order: " + "; ".join(f"{i + 1}) {r}" for i, r in enumerate(res)))
        if k == 1:
            return _finish("; ".join(f"Step {i + 1}: {r}" for i, r in enumerate(res)))
        return _finish(f"Route, in order: {res[0]}; " + "; ".join(f"then {r}" for r in res[1:]))
    head = _pick(rng, ("To visit (any order): ", "Stops, order not important: ", "Please cover these, in any order: ",
                       "Checklist (order up to you): "))
    return _finish(head + "; ".join(res))


def render_instruction_dev8(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, typed into the app by one of four household members (a rushed
    parent, a teenager, an older relative, a tidy list-maker). Strict texts spell the visiting order out
    ('first ... then ...', 'A → B → C. In that order.', 'B. but before that A', numbered steps, 'and to
    finish, ...'); free ones say it is open ('any order', 'idc what order', 'I'm not fussy about the order').
    """
    res = [r.strip().rstrip(",") for r in res]
    who = int(rng.integers(4))
    return (_parent, _teen, _wordy, _tidy)[who](rng, res, order)
