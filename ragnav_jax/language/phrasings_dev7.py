"""Seventh development phrasings: goal, sensor, coordinate and instruction templates (`unseen_dev7` split).

The held-out set after parser round 7 (which parsed 124 / 192 of it on the test houses; the README's third
closed-loop held-out table, C, uses it with that parser); parser round 8 was then developed against it. the same four functions, arguments
and meanings, written by a fifth author who never read the rule parser. The style is a careful human tester
probing a home robot with tricky but natural English, written by hand to check that the robot really
understands:

- goals: stacked prenominal modifiers as given ("the small grey fabric sofa"), attributes moved into an
  apposition ("the kettle — the copper one —") or a relative clause ("the sofa, which is grey,"); states as
  relative clauses ("the lamp that's been left switched on", "the toolbox which is open") or before the noun
  when one word ("the empty recycling bin"); the room directly or in brackets ("the heater (in the pantry)");
  anything further in a "the one ..." apposition ("the lamp in the study, the one next to the sofa");
  anchors with clauses of their own ("next to the table that has the monitor") always come last, and a second
  clause-bearing anchor restarts with "and that same lamp is also ...", so nothing attaches to the wrong noun;
- readings: numbers as digits ("25", "-5", ".7", "0.70"), words ("twenty-five", "minus five", "zero point
  seven") and units "°C", "ºC", "degrees", "degrees Celsius", "%", "per cent", "percent"; comparatives in new
  ways ("no warmer than 20 degrees", "at least as humid as 60 percent", "at 20 °C or cooler", "reading 40 % or
  more"); superlatives as adjectives ("the coolest lamp"), "whichever lamp in the study is the coolest" or
  "the one with the highest temperature reading out of every lamp in the study";
- coordinates: "(3.5, 2)", "x = 3.5, y = 2", "x=3.5 m, y=2 m", "[3.5, 2]", "x three point five, y two";
- strict order: "before anything else ...", "..., and only after that ...", "leave X until last", "save X for
  the end", numbered steps, "your first stop ..., your second ..., and your last ..."; free order: "any order's
  fine", "I don't mind which you do first", "in whatever order suits you", "there's no set order".

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.types import SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Numbers

_ONES = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
         "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen")
_TENS = ("", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety")


def _int_words(n: int) -> str:
    """0 <= n < 1000 in words: 'twenty-five', 'three hundred and eighty', 'nine hundred'."""
    if n < 20:
        return _ONES[n]
    if n < 100:
        return _TENS[n // 10] + ("" if n % 10 == 0 else "-" + _ONES[n % 10])
    rest = n % 100
    return f"{_ONES[n // 100]} hundred" + ("" if rest == 0 else " and " + _int_words(rest))


def _words(text: str) -> str | None:
    """A decimal numeral ('-5', '0.65', '22.5', '3') in words, or None where that would be clumsy."""
    m = re.fullmatch(r"(-?)(\d+)(?:\.(\d+))?", text)
    if not m or int(m.group(2)) >= 1000 or (m.group(3) and len(m.group(3)) > 2):
        return None
    out = ("minus " if m.group(1) and float(text) != 0 else "") + _int_words(int(m.group(2)))
    if m.group(3):
        out += " point " + " ".join(_ONES[int(d)] for d in m.group(3))
    return out


def _digits(rng, text: str) -> str:
    """The numeral as typed: '-5' or '−5' (a typographic minus), '.7' for '0.7', '0.70' for '0.7'."""
    if text.startswith("-") and rng.uniform() < 0.25:
        return "\u2212" + text[1:]
    if text.startswith("0.") and rng.uniform() < 0.35:
        return text[1:]
    if re.fullmatch(r"0\.\d", text) and rng.uniform() < 0.2:
        return text + "0"
    return text


def _amount(rng, reading: str, vtxt: str, need_unit: bool) -> tuple[str, str]:
    """(number with its unit as written, unit code)."""
    words = _words(vtxt) if rng.uniform() < 0.3 else None
    num = words if words is not None else _digits(rng, vtxt)
    if reading == "temperature_c":
        if not need_unit and rng.uniform() < 0.15:
            return num, ""
        if words is not None:
            return num + _pick(rng, (" degrees", " degrees Celsius")), "c"
        return num + _pick(rng, (" °C", "°C", " ºC", " degrees", " degrees Celsius", " degrees C")), "c"
    if reading == "humidity_pct":
        if not need_unit and rng.uniform() < 0.15:
            return num, ""
        if words is not None:
            return num + _pick(rng, (" per cent", " percent")), "%"
        return num + _pick(rng, ("%", " %", " per cent", " percent")), "%"
    return num, ""


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

# (reading, comparator) -> templates; {v} is the amount. "named" ones name the reading (no unit needed).
_CMP = {
    ("temperature_c", "gt"): (("warmer than {v}", 0), ("hotter than {v}", 0), ("with a temperature above {v}", 1),
                              ("reading more than {v}", 0), ("whose temperature is over {v}", 1)),
    ("temperature_c", "ge"): (("that's at least {v}", 0), ("reading {v} or more", 0), ("no cooler than {v}", 0),
                              ("with a temperature of at least {v}", 1), ("at {v} or warmer", 0),
                              ("whose temperature is no lower than {v}", 1)),
    ("temperature_c", "lt"): (("cooler than {v}", 0), ("colder than {v}", 0), ("with a temperature below {v}", 1),
                              ("reading less than {v}", 0), ("whose temperature is under {v}", 1)),
    ("temperature_c", "le"): (("no warmer than {v}", 0), ("no hotter than {v}", 0), ("at {v} or cooler", 0),
                              ("with a temperature of at most {v}", 1), ("reading {v} or less", 0),
                              ("whose temperature is no higher than {v}", 1)),
    ("temperature_c", "approx"): (("at roughly {v}", 0), ("reading about {v}", 0),
                                  ("with a temperature of around {v}", 1), ("whose temperature is close to {v}", 1),
                                  ("at approximately {v}", 0)),
    ("humidity_pct", "gt"): (("more humid than {v}", 0), ("with humidity above {v}", 1),
                             ("whose humidity reads over {v}", 1)),
    ("humidity_pct", "ge"): (("at least as humid as {v}", 0), ("with humidity of at least {v}", 1),
                             ("reading {v} humidity or more", 0), ("whose humidity is no lower than {v}", 1)),
    ("humidity_pct", "lt"): (("drier than {v}", 0), ("less humid than {v}", 0), ("with humidity below {v}", 1),
                             ("whose humidity is under {v}", 1)),
    ("humidity_pct", "le"): (("no more humid than {v}", 0), ("with humidity of at most {v}", 1),
                             ("reading {v} humidity or less", 0), ("whose humidity is no higher than {v}", 1)),
    ("humidity_pct", "approx"): (("with humidity around {v}", 1), ("whose humidity is roughly {v}", 1),
                                 ("with a humidity reading of about {v}", 1)),
    ("ndvi", "gt"): (("with an NDVI above {v}", 1), ("whose NDVI is greater than {v}", 1),
                     ("with an NDVI reading over {v}", 1)),
    ("ndvi", "ge"): (("with an NDVI of {v} or more", 1), ("whose NDVI is at least {v}", 1),
                     ("with an NDVI no lower than {v}", 1)),
    ("ndvi", "lt"): (("with an NDVI below {v}", 1), ("whose NDVI is less than {v}", 1),
                     ("with an NDVI reading under {v}", 1)),
    ("ndvi", "le"): (("with an NDVI of {v} or less", 1), ("whose NDVI is at most {v}", 1),
                     ("with an NDVI no higher than {v}", 1)),
    ("ndvi", "approx"): (("with an NDVI of about {v}", 1), ("whose NDVI is roughly {v}", 1),
                         ("with an NDVI somewhere around {v}", 1)),
}
_SUP_ADJ = {("temperature_c", "max"): ("hottest", "warmest"), ("temperature_c", "min"): ("coolest", "coldest"),
            ("humidity_pct", "max"): ("most humid", "dampest"), ("humidity_pct", "min"): ("driest", "least humid"),
            ("ndvi", "max"): ("healthiest", "greenest"), ("ndvi", "min"): ("least healthy",)}
_SUP_TAIL = {
    ("temperature_c", "max"): ("with the highest temperature reading", "that's reading the highest temperature",
                               "with the highest temperature"),
    ("temperature_c", "min"): ("with the lowest temperature reading", "that reads the lowest temperature",
                               "with the lowest temperature"),
    ("humidity_pct", "max"): ("with the highest humidity", "with the highest humidity reading"),
    ("humidity_pct", "min"): ("with the lowest humidity", "that reads the lowest humidity"),
    ("ndvi", "max"): ("with the highest NDVI", "whose NDVI is the highest"),
    ("ndvi", "min"): ("with the lowest NDVI", "whose NDVI is the lowest"),
}


def render_sensor_dev7(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: a prefix adjective ('coolest', 'most humid') or a tail that reads after 'the one'
    ('with the highest temperature reading'); thresholds: a tail that reads after the noun or after 'the one'
    ('no warmer than 20 degrees', 'at least as humid as 60 percent', 'with an NDVI of .7 or more').
    """
    rd = c.reading
    if c.is_superlative:
        if rng.uniform() < 0.5:
            return _pick(rng, _SUP_ADJ[(rd, c.comparator)]), "", c
        return "", _pick(rng, _SUP_TAIL[(rd, c.comparator)]), c
    vtxt = _fmt_value(rd, c.value)
    template, named = _pick(rng, _CMP[(rd, c.comparator)])
    amount, code = _amount(rng, rd, vtxt, need_unit=not named)
    return "", template.format(v=amount), SensorConstraint(rd, c.comparator, float(vtxt), code)


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_dev7(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y, as a tester types it: every form starts with
    'at', 'around' or 'located' and reads after a noun or after 'the one'."""
    xw, yw = _words(x), _words(y)
    forms = [f"at ({x}, {y})", f"at x = {x}, y = {y}", f"at x={x} m, y={y} m", f"around the point ({x}, {y})",
             f"at position [{x}, {y}]", f"located at x {x} and y {y}", f"at (x, y) = ({x}, {y})",
             f"at roughly x = {x}, y = {y}"]
    if xw and yw:
        forms.append(f"at x {xw}, y {yw}")
    return _pick(rng, forms)


# ----------------------------------------------------------------------------------------------------
# Goals


def _split_attrs(t: Target) -> tuple[list[str], list[str]]:
    """(modifiers written before the noun, states) — the phrase holds the modifiers, never the states."""
    before = t.phrase[: len(t.phrase) - len(t.head)].split() if t.phrase.endswith(t.head) else t.phrase.split()
    mods, states = [], []
    for a in t.attributes:
        words = a.split()
        hit = any(before[i:i + len(words)] == words for i in range(len(before) - len(words) + 1))
        (mods if hit else states).append(a)
    return mods, states


_PREP = {
    "near": ("near", "close to", "not far from"),
    "next_to": ("next to", "right next to", "alongside"),
    "beside": ("beside", "right beside"),
    "by": ("by", "over by", "just by"),
    "on": ("on", "on top of", "sitting on"),
    "under": ("under", "underneath", "beneath"),
    "above": ("above", "directly above"),
    "in": ("in", "inside"),
    "with": ("with",),
    "in_room_with": ("in the same room as", "in the room with", "sharing a room with"),
    "in_front_of": ("in front of", "right in front of"),
    "behind": ("behind", "tucked behind"),
    "opposite": ("opposite", "across from", "facing"),
    "left_of": ("to the left of",),
    "right_of": ("to the right of",),
}


def _state_pred(rng, state: str) -> str:
    """'is switched on', "has been left open"."""
    if state in ("switched on", "switched off", "open") and rng.uniform() < 0.35:
        return f"has been left {state}"
    return f"is {state}"


def _rel_pred(rng, rtype: str, anchor_text: str) -> str:
    """A relation as a verb phrase: 'is next to the sofa', 'has the monitor'."""
    if rtype == "with":
        return f"has {anchor_text}"
    return f"is {_pick(rng, _PREP[rtype])} {anchor_text}"


def _that(preds: list[str], rng) -> str:
    """'that's switched on and is next to the sofa' from ['is switched on', 'is next to the sofa']."""
    first = preds[0]
    if first.startswith("is ") and rng.uniform() < 0.6:
        first = "that's " + first[3:]
    else:
        first = "that " + first
    return " and ".join([first, *preds[1:]])


def _has_clause(t: Target) -> bool:
    return bool(_split_attrs(t)[1] or t.relations)


def _anchor(rng, t: Target) -> str:
    """An anchor noun phrase; its states and own relations in a 'that ...' clause (clause-bearing anchor last)."""
    _, states = _split_attrs(t)
    preds = [_state_pred(rng, s) for s in states]
    rels = sorted(t.relations, key=lambda r: _has_clause(r.anchor))
    preds += [_rel_pred(rng, r.type, _anchor(rng, r.anchor)) for r in rels]
    return f"the {t.phrase}" + (" " + _that(preds, rng) if preds else "")


def _relations(rng, t: Target, head: str, lead: str) -> str:
    """The goal's relations after the rest of it; lead: '' (bare prepositions follow) or 'one' (after 'the
    one'). Plain anchors first; after a clause-bearing anchor the goal is named again."""
    rels = sorted(t.relations, key=lambda r: _has_clause(r.anchor))
    out, restart = [], False
    for i, r in enumerate(rels):
        a = _anchor(rng, r.anchor)
        prep = "with" if r.type == "with" else _pick(rng, _PREP[r.type])
        if restart:
            out.append(f", and that same {head} is also {prep} {a}" if r.type != "with"
                       else f", and that same {head} also has {a}")
        else:
            out.append((" and " if i else " ") + f"{prep} {a}")
        restart = restart or _has_clause(r.anchor)
    return "".join(out)


def render_goal_dev7(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "",
                         hint: str = "") -> str:
    """'the small grey fabric sofa', 'the kettle — the copper one — in the kitchen', 'the lamp that's been
    left switched on (in the study)', 'the heater in the pantry, the one no warmer than 20 degrees', 'whichever
    lamp in the study is the coolest', 'the one with the highest NDVI out of every fern in the sunroom', 'the
    guitar at (3.5, 2)', 'the lamp next to the table that has the monitor'."""
    t = sg.target
    mods, states = _split_attrs(t)
    sup = any(c.is_superlative for c in sg.sensors)
    room = f"in the {sg.room}" if sg.room else ""

    # Superlative by a tail, scoped over everything else: "the one with ... out of every lamp in the study".
    if sup and tail and not prefix and (t.relations or hint or states or rng.uniform() < 0.5):
        rest = [room] if room else []
        if hint:
            rest.append(hint)
        body = f"the one {tail} out of every {t.phrase}"
        if states:
            body += " " + _that([_state_pred(rng, s) for s in states], rng)
            rest = [f"and is {x}" for x in rest]
        body += "".join(" " + x for x in rest)
        return body + _relations(rng, t, t.head, "")
    # Superlative by an adjective over the head and room: "whichever lamp in the study is the coolest".
    if prefix and sup and room and not (t.relations or hint or states or tail) and rng.uniform() < 0.45:
        return f"whichever {t.phrase} {room} is {_pick(rng, ('the ', ''))}{prefix}"

    # The noun phrase.
    appos = ""
    one_word = [s for s in states if s in ("open", "closed", "empty", "full")]
    pre_state = ""
    if one_word and not prefix and rng.uniform() < 0.35:
        pre_state = one_word[0]
        states = [s for s in states if s != pre_state]
    if mods and not prefix and not pre_state and rng.uniform() < 0.3:
        head_np = f"the {t.head}"
        if len(mods) == 1 and " " not in mods[0] and rng.uniform() < 0.5:
            appos = f", which is {mods[0]},"
        else:
            appos = f" — the {' '.join(mods)} one —"
    else:
        head_np = "the " + " ".join(x for x in (prefix, pre_state, t.phrase) if x)
    text = head_np + appos

    # What follows the noun: one thing directly, the rest in a 'the one ...' apposition, relations last.
    direct, extras, kind = "", [], ""
    if states:
        preds = [_state_pred(rng, s) for s in states]
        if not t.relations and not appos.startswith(" —") and (appos.endswith(",") or rng.uniform() < 0.3):
            if appos.endswith(","):
                text, direct = text[:-1], " and " + " and ".join(preds) + ","
            else:
                direct = ", which " + " and ".join(preds) + ","
            kind = "which"
        else:
            direct, kind = " " + _that(preds, rng), "that"
        if room:
            extras.append(room)
    elif room:
        style = rng.uniform()
        paren = not appos and ((tail and style < 0.35) or style >= 0.8)
        direct, kind = (f" ({room})", "room") if paren else (f" {room}", "room")
    if tail:
        if not direct:
            direct, kind = f" {tail}", "tail"
        else:
            extras.append(tail)
    if hint:
        if not direct:
            direct, kind = f" {hint}", "tail"
        else:
            extras.append(hint)
    text += direct
    if extras:
        if text.endswith(","):
            text = text[:-1]
        text += ", the one " + " and ".join(extras)
        text += " and" if t.relations else ","  # the apposition is closed before whatever follows the goal
    elif t.relations and kind == "tail":
        text += " and"
    elif t.relations and kind == "that":
        text += " and is"
    if text.endswith(" —") and not t.relations:  # an apposition closing at the very end: commas instead
        text = text[: -len(" —")].replace(" — the ", ", the ", 1) + ","
    rels = _relations(rng, t, t.head, "")
    if rels and text.endswith(" and is") and rels.lstrip().startswith("with "):
        return text[: -len(" is")] + " has " + rels.lstrip()[len("with "):]
    return text + rels


# ----------------------------------------------------------------------------------------------------
# Instructions

_VERBS = ("head for", "make for", "go and have a look at", "swing round to", "pay a visit to", "go over to",
          "take a look at", "drop by", "track down", "find your way to", "go and find", "get yourself over to")
_GERUND = {"head for": "heading for", "make for": "making for", "go and have a look at": "having a look at",
           "swing round to": "swinging round to", "pay a visit to": "paying a visit to", "go over to": "going over to",
           "take a look at": "taking a look at", "drop by": "dropping by", "track down": "tracking down",
           "find your way to": "finding your way to", "go and find": "finding",
           "get yourself over to": "getting yourself over to"}
_ORDINAL = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth")


def _short(goal: str) -> bool:
    return len(goal.split()) <= 4 and not any(ch in goal for ch in ",—()")


def _visit(rng, goal: str) -> str:
    """A verb and the goal: 'head for the lamp', 'pay the lamp a visit' (short goals only)."""
    if _short(goal) and rng.uniform() < 0.2:
        return f"pay {goal} a visit"
    return f"{_pick(rng, _VERBS)} {goal}"


def _end(goal: str) -> str:
    return goal[:-1] if goal.endswith(",") else goal


def _sentence(s: str) -> str:
    s = s.strip().rstrip(",")
    for a, b in ((",,", ","), (", ,", ","), (",.", "."), (",;", ";"), (",:", ":"), (",?", "?"), (", —", " —")):
        s = s.replace(a, b)
    if not s.endswith((".", "?", "!")):
        s += "?" if s.lower().startswith(("could you", "would you", "can you")) else "."
    return s[0].upper() + s[1:]


def _lst(rng, res: list[str], verbs: bool = False) -> str:
    """'A, B and C', or with semicolons when a goal holds a comma or a dash."""
    items = [_visit(rng, r) if verbs else r for r in res]
    if len(items) == 1:
        return _end(items[0])
    heavy = any(ch in r for r in res for ch in ",—(")
    if heavy:
        return "; ".join(_end(i) for i in items[:-1]) + "; and " + _end(items[-1])
    return ", ".join(items[:-1]) + _pick(rng, (" and ", ", and ")) + items[-1]


def render_instruction_dev7(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, as a careful tester writes it: strict texts spell the visiting
    order out ('before anything else', 'and only after that', 'leave X until last', numbered steps); free
    ones say the order is open ('any order's fine', 'I don't mind which you do first')."""
    n = len(res)
    polite = _pick(rng, ("", "", "", "please ", "would you ", "could you "))
    if n == 1:
        k = int(rng.integers(3))
        if k == 0:
            return _sentence(f"{polite}{_visit(rng, _end(res[0]))}")
        if k == 1:
            return _sentence(f"I'd like you to {_visit(rng, res[0])}, please")
        return _sentence(f"just the one stop this time: {_visit(rng, _end(res[0]))}")
    if order == "free":
        k = int(rng.integers(6))
        which = "which you do first" if n == 2 else "what order you take them in"
        if k == 0:
            return _sentence(f"{polite}{_pick(rng, _VERBS)} {_lst(rng, res)} — any order's fine")
        if k == 1:
            return _sentence(f"I need you to {_lst(rng, res, verbs=True)}. I don't mind {which}")
        if k == 2:
            return _sentence(f"{_pick(rng, _VERBS)} these in whatever order suits you: {_lst(rng, res)}")
        if k == 3:
            return _sentence(f"there's no set order for this one: {_lst(rng, res, verbs=True)}")
        if k == 4:
            return _sentence(f"{polite}{_pick(rng, _VERBS)} each of the following, in any sequence you like: "
                             f"{_lst(rng, res)}")
        return " ".join([_sentence(f"{_pick(rng, _VERBS)} {_lst(rng, res)}"),
                         _sentence(_pick(rng, ("the order is entirely up to you", "sequence them however you like",
                                               "you pick the order")))])
    k = int(rng.integers(6))
    if k == 0:  # before anything else ... then ... leave Z until last
        out = [_sentence(f"before anything else, {_visit(rng, _end(res[0]))}")]
        for r in res[1:-1]:
            out.append(_sentence(f"{_pick(rng, ('then', 'after that,', 'next,'))} {_visit(rng, _end(r))}"))
        last = res[-1]
        out.append(_sentence(_pick(rng, (f"leave {last} until last", f"save {last} for the end",
                                         f"finally, {_visit(rng, last)}"))))
        return " ".join(out)
    if k == 1:  # A, and only after that B
        s = f"{polite}{_visit(rng, res[0])}"
        for r in res[1:]:
            s += f", and only {_pick(rng, ('after that', 'after that', 'then'))} {_visit(rng, r)}"
        return _sentence(s)
    if k == 2:  # numbered steps
        steps = "; ".join(f"({i + 1}) {_visit(rng, _end(r))}" for i, r in enumerate(res))
        return _sentence(f"{_pick(rng, ('please do these in exactly this order', 'in this order, one after the other'))}: {steps}")
    if k == 3:  # start by ...ing A. Once that's done, B. Finish up at Z.
        v = _pick(rng, _VERBS)
        out = [_sentence(f"start by {_GERUND[v]} {_end(res[0])}")]
        for r in res[1:-1]:
            out.append(_sentence(f"once that's done, {_visit(rng, _end(r))}"))
        out.append(_sentence(f"finish up by {_GERUND[_pick(rng, _VERBS)]} {_end(res[-1])}"))
        return " ".join(out)
    if k == 4:  # your first stop ..., your second ..., and your last ...
        parts = [f"your {_ORDINAL[i]} stop is {_end(r)}" for i, r in enumerate(res[:-1])]
        parts.append(f"your last stop is {_end(res[-1])}")
        return " ".join(_sentence(p) for p in parts)
    # To begin with, A; when you're done there, B; ... Z comes last.
    s = f"to begin with, {_visit(rng, res[0])}"
    for r in res[1:-1]:
        s += f"; when you're done there, {_visit(rng, _end(r))}"
    s += f"; {res[-1]} comes last"
    return _sentence(s)
