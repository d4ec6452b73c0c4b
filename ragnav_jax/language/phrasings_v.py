"""Held-out phrasings of set V: goal, sensor, coordinate and instruction templates for the `unseen_v` split.

Written by a helper that never read the parser (nor its lexicon, tagger, readings, agreement or command code, nor
the evaluation code), before any run of any reader on these sentences, with only the interface of the earlier
template sets in view (`phrasings_u.py`, `phrasings_t.py` and the docstrings of the others). Same four functions,
arguments and meanings as the other template sets. The style is four people who send a home robot round a house
in the layout and words of their own job:

- a theatre director, as a script page or rehearsal notes: "ACT II, SCENE 3. The same, later that night.", "LX 1.
  ROBOT crosses to ...", "(beat)", "Cue 2. ROBOT drifts over to ...", "Cue 3. Exit ROBOT via ...", "BLACKOUT.", or
  "NOTES after Tuesday's run – for ROBOT", "you open at ...; on the line 'Is anyone there?' you move to ...; ...
  and your exit is via ..."; a fixed order as "cues run in strict running order – no jumping cues", "the blocking
  is set, so hit your marks in the order rehearsed"; a free one as "DEVISING SESSION", "◆" bullets, "visit them in
  any order you like – find it in the moment", "no set blocking yet, so wander between them in whatever order
  feels truthful"; one goal as "ROBOT alone on stage. ROBOT crosses to .... (beat) BLACKOUT.";
- a head chef calling a busy service: "ORDER IN! Three covers, three all day.", "Course 1 ▸ fire ...", "Last course
  ▸ ...", "Service! Fire ..., then ..., and finish on ...", "Yes chef!"; fixed as "fire them in the order called,
  course by course – nobody jumps a course", "in that order, course by course"; free as "MISE EN PLACE", "□"
  boxes, "knock these out in any order you like, just have the lot done before service", "no firing order on
  these – whichever's ready first, go"; one goal as "Service! A single cover: .... That's the whole ticket.";
- a football or rugby coach's team talk or game plan: "GAME PLAN – Saturday v Rovers", "Kick-off: ...",
  "Phase 2: switch play to ...", "Final whistle: ...", "First half, we get at .... Then we switch play to .... Final
  whistle at ...."; fixed as "stick to the game plan, phase by phase, in that order – nobody freelances"; free as
  "SET PIECES – training", "run the routines in whatever order you fancy", "no fixed order today, pick them off as
  the game opens up"; one goal as "Just the one job today: .... Go and win it.";
- a solicitor, as contract clauses or a formal letter: "MEMORANDUM OF ATTENDANCE", "WHEREAS the Principal requires
  the Robot to attend at certain places;", "NOW THIS DEED WITNESSETH as follows:", "1.1 The Robot shall first
  proceed to ... (hereinafter 'the First Chattel').", "1.2 Upon attending at the First Chattel, the Robot shall
  proceed to ...", "Dear Robot, Re: Your attendance on our client's behalf", "Yours faithfully"; fixed as "the
  attendances in clause 1 shall be made seriatim, strictly in the sequence there set out, notwithstanding that
  another route may be shorter", "the order of attendance is a condition of these instructions and may not be
  varied"; free as "in no particular sequence", "notwithstanding the order in which they are listed above, the
  Robot may attend them in any order it sees fit", "our client has no preference as to the order"; one goal as
  "the Robot shall proceed to ... and to no other place."

Goals: attributes before the noun, in a bracket "(teal and corduroy, if memory serves)" or as an aside ", answering
the description teal and corduroy,"; states before the noun ("the switched-on lamp"), as "(switched on, so I'm
told)" (before the aside, where there is one) or ", switched on as of this morning,"; the room as "in the X" or "up
in the X", always before any relation; relations in new words ("a spit and a cough from", "in the general area of",
"only a few yards from", "butted up next to", "nudging", "hard up next to", "sat just beside", "ranged beside",
"lingering by", "hanging about by", "stacked on", "lodged on", "wedged under", "squirrelled away under",
"overhanging", "way up above", "tucked into", "boxed up in", "rigged up with", "bearing", "in the very room that
has", "rooming with", "dead in front of", "placed smack in front of", "stashed behind", "away behind", "squaring up
to", "set over against", "a pace to the left of", "hard to the left of", "a pace to the right of", "hard to the
right of"); several relations joined by "and", ", and likewise" or ", plus"; an anchor with relations of its own
takes them in a bracket, "(specifically the one next to the record player)" or "(mind you, the one next to the
record player)". Readings: "has sailed past", "overshoots", "pips", "reaches ... or better", "doesn't fall short
of", "matches or passes", "falls short of", "doesn't get as far as", "undercuts", "never exceeds", "keeps to ... or
less", "peaks at ..., no higher", "hovers round", "reads ..., near as dammit", "sits within a smidge of", and their
participles ("sailing past", "undercutting", ...); frames "that ...", "whose humidity ...", "with its temperature
...", "(its NDVI ...)"; units "°C", "degrees", "degrees Celsius", "degrees centigrade", "%", "per cent", "percent",
"% RH"; numbers as digits, decimals ("40.0", ".65", "0.650"), words ("forty", "minus eighteen", "nought point six
five"), "minus 18", "18 degrees below freezing" and fractions in words ("22 and a half", "twenty-two and a half");
superlatives "the most blistering", "the most baking-hot", "the chilliest", "the most wintry", "the lushest", "the
most verdant", "the sickliest", "the least verdant", "the sultriest", "the most sodden", "the most desiccated",
"whose temperature is the highest of all", "that outdoes all others on NDVI", "with the loftiest humidity reading",
"whose NDVI is the lowest of all", "that comes in under all others on temperature", "with the lowliest humidity
reading". Coordinates: "where x equals 3.5 and y equals 2", "(abscissa 3.5, ordinate 2)", "at position x 3.5 · y 2",
"on the spike mark at x 3.5, y 2"; always x then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.template_text import attributes_and_states, number_words
from ragnav_jax.language.template_text import hyphenated as _hyphen
from ragnav_jax.language.template_text import tidy as _tidy
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Small helpers of this set's own

_ONES = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
         "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen")
_TENS = ("", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety")
_DIGIT_WORDS = ("nought", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "a spit and a cough from", "in the general area of", "only a few yards from"),
    "next_to": ("next to", "butted up next to", "nudging", "hard up next to"),
    "beside": ("beside", "sat just beside", "ranged beside"),
    "by": ("by", "lingering by", "hanging about by"),
    "on": ("on", "stacked on", "lodged on"),
    "under": ("under", "wedged under", "squirrelled away under"),
    "above": ("above", "overhanging", "way up above"),
    "in": ("in", "tucked into", "boxed up in"),
    "with": ("with", "rigged up with", "bearing"),
    "in_room_with": ("in the same room as", "in the very room that has", "rooming with"),
    "in_front_of": ("in front of", "dead in front of", "placed smack in front of"),
    "behind": ("behind", "stashed behind", "away behind"),
    "opposite": ("opposite", "squaring up to", "set over against"),
    "left_of": ("to the left of", "a pace to the left of", "hard to the left of"),
    "right_of": ("to the right of", "a pace to the right of", "hard to the right of"),
}
_JOINS = (" and ", ", and likewise ", ", plus ")


def _anchor_np(rng, t: Target, depth: int) -> str:
    """An anchor: attributes before the noun; states before it or, for an anchor without relations of its own, as
    '(switched on, so I'm told)'; the anchor's own relations in a bracket of their own."""
    _, states = attributes_and_states(t)
    out = "the "
    bracket_state = bool(states) and depth == 1 and not t.relations and rng.uniform() < 0.35
    if states and not bracket_state:
        out += _hyphen(states) + " "
    out += t.phrase
    if bracket_state:
        out += f" ({' and '.join(states)}, so I'm told)"
    if t.relations:
        inner = _rel_chain(rng, t.relations, depth + 1)
        if rng.uniform() < 0.5:
            out += f" (specifically the one {inner})"
        else:
            out += f" (mind you, the one {inner})"
    return out


def _rel_chain(rng, rels: tuple[Relation, ...], depth: int = 1) -> str:
    out = ""
    for i, r in enumerate(rels):
        part = f"{_pick(rng, REL_WORDS[r.type])} {_anchor_np(rng, r.anchor, depth)}"
        out = part if i == 0 else out + _pick(rng, _JOINS) + part
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS = ("in the {}", "in the {}", "up in the {}")


def _goal_np(rng, t: Target, prefix: str) -> str:
    """The goal's own noun phrase: 'the teal corduroy bean bag', 'the bean bag (teal and corduroy, if memory
    serves)', 'the bean bag, answering the description teal and corduroy,', 'the switched-on lamp', 'the lamp
    (switched on, so I'm told)', 'the lamp, switched on as of this morning,'. With a superlative adjective the
    attributes stay before the noun."""
    pre, states = attributes_and_states(t)
    if not t.phrase.endswith(t.head):  # a phrase of another shape: written as given, anything missing in a bracket
        missing = [a for a in t.attributes if a not in t.phrase.split()]
        out = "the " + (f"{prefix} " if prefix else "") + t.phrase
        return out + (f" ({' and '.join(missing)}, if memory serves)" if missing else "")
    head = t.phrase[len(t.phrase) - len(t.head):]
    attr_style = "before"
    if pre and not prefix:
        attr_style = _pick(rng, ("before", "before", "memory", "answering"))
    state_style = None
    if states:
        opts = ["before", "told", "asof"]
        if attr_style == "memory":
            opts.remove("told")  # never two round brackets in a row
        if attr_style == "answering":
            opts.remove("asof")  # one aside between commas is enough
        state_style = _pick(rng, opts)
    out = "the " + (f"{prefix} " if prefix else "")
    if state_style == "before":
        out += _hyphen(states) + " "
    if attr_style == "before":
        out += t.phrase
    elif attr_style == "memory":
        out += f"{head} ({' and '.join(pre)}, if memory serves)"
    elif state_style == "told":  # the bracket straight after the noun, then the aside
        out += f"{head} ({' and '.join(states)}, so I'm told), answering the description {' and '.join(pre)},"
        return out
    else:
        out += f"{head}, answering the description {' and '.join(pre)},"
    if state_style == "told":
        out += f" ({' and '.join(states)}, so I'm told)"
    elif state_style == "asof":
        out += f", {' and '.join(states)} as of this morning,"
    return out


_HAS_NUMBER = re.compile(r"\d|\b(" + "|".join(w for w in _ONES + _TENS + _DIGIT_WORDS if w) + r"|hundred|half)\b")


def render_goal_v(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set V writes it: 'the teal corduroy bean bag up in the nursery', 'the bean bag (teal and corduroy,
    if memory serves)', 'the lamp, switched on as of this morning,', 'the chilliest fridge in the pantry', 'the
    guitar (abscissa 3.5, ordinate 2)', 'the lamp butted up next to the credenza (specifically the one rigged up
    with the record player)'. The room comes before any relation (and before a superlative tail, which is read
    inside it); relations come last."""
    t = sg.target
    out = _goal_np(rng, Target(t.phrase, t.head, t.attributes), prefix)
    if hint:
        out += " " + hint
    room = _pick(rng, _ROOMS).format(sg.room) if sg.room else ""
    if tail:
        superlative = not _HAS_NUMBER.search(tail)
        if room and (superlative or rng.uniform() < 0.5):
            out += f" {room} {tail}"
        else:
            out += f" {tail}" + (f", {room}" if room else "")
    elif room:
        out += " " + room
    if t.relations:
        out += " " + _rel_chain(rng, t.relations)
    return _tidy(out)


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

# Finite predicates: after "that", "whose <reading>" or "(its <reading> ...)".
_FINITE = {
    "gt": ("has sailed past {n}", "overshoots {n}", "pips {n}"),
    "ge": ("reaches {n} or better", "doesn't fall short of {n}", "matches or passes {n}"),
    "lt": ("falls short of {n}", "doesn't get as far as {n}", "undercuts {n}"),
    "le": ("never exceeds {n}", "keeps to {n} or less", "peaks at {n}, no higher"),
    "approx": ("hovers round {n}", "reads {n}, near as dammit", "sits within a smidge of {n}"),
}
# Participles: after "with its <reading>".
_PARTICIPLE = {
    "gt": ("sailing past {n}", "overshooting {n}", "pipping {n}"),
    "ge": ("reaching {n} or better", "not falling short of {n}", "matching or passing {n}"),
    "lt": ("falling short of {n}", "not getting as far as {n}", "undercutting {n}"),
    "le": ("never exceeding {n}", "keeping to {n} or less", "peaking at {n}, no higher"),
    "approx": ("hovering round {n}", "reading {n}, near as dammit", "sitting within a smidge of {n}"),
}
_NAMES = {"temperature_c": "temperature", "humidity_pct": "humidity", "ndvi": "NDVI"}
_SUPER_ADJ = {
    ("temperature_c", "max"): ("warmest", "most blistering", "most baking-hot"),
    ("temperature_c", "min"): ("coldest", "chilliest", "most wintry"),
    ("ndvi", "max"): ("healthiest", "lushest", "most verdant"),
    ("ndvi", "min"): ("least healthy", "sickliest", "least verdant"),
    ("humidity_pct", "max"): ("most humid", "sultriest", "most sodden"),
    ("humidity_pct", "min"): ("driest", "most desiccated", "least humid"),
}


def _super_tails(name: str, comparator: str) -> tuple[str, ...]:
    if comparator == "max":
        return (f"whose {name} is the highest of all", f"that outdoes all others on {name}",
                f"with the loftiest {name} reading")
    return (f"whose {name} is the lowest of all", f"that comes in under all others on {name}",
            f"with the lowliest {name} reading")


_FRACTIONS = {0.25: "and a quarter", 0.5: "and a half", 0.75: "and three quarters"}


def _number(rng, reading: str, value: float, approx: bool = False) -> tuple[str, float, str]:
    """(the number as written, its value, how): digits, a decimal ('40.0', '.65', '0.650'), words ('forty', 'minus
    eighteen', 'nought point six five'), 'minus 18', a fraction in words ('22 and a half', 'twenty-two and a
    half'), or 'below' for a negative temperature near which (approx) to be written 'N degrees below freezing'."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    u = rng.uniform()
    if reading == "ndvi":
        if u < 0.2 and 0 <= v < 1 and len(txt) > 2:
            return "nought point " + " ".join(_DIGIT_WORDS[int(d)] for d in txt[2:]), v, "words"
        if u < 0.4 and txt.startswith("0."):
            return txt[1:], v, "digits"
        if u < 0.6 and "." in txt:
            return txt + "0" * (5 - len(txt)) if len(txt) < 5 else txt, v, "digits"
        return txt, v, "digits"
    if reading not in ("temperature_c", "humidity_pct"):
        return txt, v, "digits"
    whole, frac = int(abs(v)), abs(v) - int(abs(v))
    if v == int(v):
        if v < 0 and reading == "temperature_c" and approx and rng.uniform() < 0.3:  # '18 degrees below freezing'
            return (number_words(whole) if rng.uniform() < 0.3 else str(whole)), v, "below"
        if u < 0.25 and abs(v) < 1000:
            return number_words(int(v)), v, "words"
        if u < 0.4:
            txt = f"{v:.1f}"
    elif v > 0 and frac in _FRACTIONS and u < 0.5:
        lead = number_words(whole) if u < 0.2 and whole < 1000 else str(whole)
        return f"{lead} {_FRACTIONS[frac]}", v, "words" if lead != str(whole) else "fraction"
    if v < 0 and rng.uniform() < 0.5:
        return f"minus {txt[1:]}", v, "digits"
    return txt, v, "digits"


def _unit(rng, reading: str, how: str) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        if how == "below":
            return " degrees", "c"
        opts = (" degrees", " degrees Celsius", " degrees centigrade")
        if how == "digits":
            opts += ("°C", " °C")
        return _pick(rng, opts), "c"
    if reading == "humidity_pct":
        return _pick(rng, (" per cent", " percent") if how in ("words", "fraction") else
                     ("%", " per cent", " percent", "% RH")), "%"
    return "", ""


def render_sensor_v(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('chilliest', 'lushest', 'most desiccated') or a tail ('whose
    temperature is the highest of all', 'that comes in under all others on NDVI'); thresholds after the noun
    ('that has sailed past 60 °C', 'whose humidity never exceeds forty per cent', 'with its NDVI matching or passing
    .65', '(its temperature hovers round 18 degrees below freezing)', 'that falls short of 22 and a half %')."""
    rd = c.reading
    name = _NAMES.get(rd, rd.replace("_", " "))
    if c.is_superlative:
        adj = _SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, _super_tails(name, c.comparator)), c
    n, value, how = _number(rng, rd, c.value, c.comparator == "approx")
    unit, code = _unit(rng, rd, how)
    named = rd not in ("temperature_c", "humidity_pct")  # NDVI (and any other reading) is always named
    frame = _pick(rng, ("whose", "its", "bracket") if named else ("that", "that", "whose", "its", "bracket"))
    if frame != "that" and rd == "temperature_c" and how in ("digits", "words") and rng.uniform() < 0.2:
        unit, code = "", ""  # the reading is named: the unit may go
    num = f"{n}{unit} below freezing" if how == "below" else n + unit
    written = SensorConstraint(rd, c.comparator, value, code)
    if frame == "that":
        return "", "that " + _pick(rng, _FINITE[c.comparator]).format(n=num), written
    if frame == "whose":
        return "", f"whose {name} " + _pick(rng, _FINITE[c.comparator]).format(n=num), written
    if frame == "its":
        return "", f"with its {name} " + _pick(rng, _PARTICIPLE[c.comparator]).format(n=num), written
    return "", f"(its {name} " + _pick(rng, _FINITE[c.comparator]).format(n=num) + ")", written


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_v(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'where x equals 3.5 and y equals 2', '(abscissa 3.5,
    ordinate 2)', 'at position x 3.5 · y 2', 'on the spike mark at x 3.5, y 2'."""
    return _pick(rng, (f"where x equals {x} and y equals {y}", f"(abscissa {x}, ordinate {y})",
                       f"at position x {x} · y {y}", f"on the spike mark at x {x}, y {y}"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _sep(res: list[str]) -> str:
    return ";" if any("," in r for r in res) else ","


def _listed(rng, res: list[str]) -> str:
    """Goals in a running sentence: commas, or semicolons where a goal has commas of its own."""
    if any("," in r for r in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


_ROMAN = ("I", "II", "III", "IV", "V")
_DIRECTORS = ("Fenella", "Giles", "Marguerite", "Oz")
_DAYS = ("Monday", "Tuesday", "Wednesday", "Thursday", "Friday")
_SETTINGS = ("The same, later that night.", "Night. Silence.", "Early morning. Birdsong.", "As before.")
_MOVES = ("drifts over to", "makes for", "moves to", "crosses to", "finds the mark at")


def _theatre(rng, res: list[str], order: str) -> str:
    """A theatre director: a script page with cue numbers, or rehearsal notes."""
    who = _pick(rng, _DIRECTORS)
    if len(res) == 1:
        return _pick(rng, (f"ROBOT alone on stage. ROBOT crosses to {res[0]}. (beat) BLACKOUT.",
                           f"Monologue, darling – just you: find your spot at {res[0]} and hold it. Lovely. {who}"))
    n = len(res)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"ACT {_pick(rng, _ROMAN)}, SCENE {int(rng.integers(1, 6))}. {_pick(rng, _SETTINGS)}"]
            for i, r in enumerate(res):
                cue = _pick(rng, ("LX", "Cue", "SQ"))
                if i == 0:
                    lines.append(f"{cue} {i + 1}. ROBOT enters and {_pick(rng, _MOVES)} {r}.")
                elif i < n - 1:
                    lines.append(f"{cue} {i + 1}. ROBOT {_pick(rng, _MOVES)} {r}.")
                else:
                    lines.append(f"{cue} {i + 1}. Exit ROBOT via {r}.")
                if i < n - 1 and rng.uniform() < 0.6:
                    lines.append("(beat)")
            lines.append("BLACKOUT.")
            lines.append("Note to company: cues run in strict running order – no jumping cues.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"NOTES after {_pick(rng, _DAYS)}'s run – for ROBOT. Lovely energy tonight. You open at {res[0]}"
        mids = res[1:-1]
        for i, r in enumerate(mids):
            s += f"{sep} on the line 'Is anyone there?' you move to {r}" if i == 0 else f"{sep} (beat) then {r}"
        return s + (f"{sep} and your exit is via {res[-1]}. The blocking is set, so hit your marks in the order "
                    f"rehearsed. {who} x")
    if rng.uniform() < 0.5:
        body = "\n".join(f"◆ {r}" for r in res)
        return (f"DEVISING SESSION – ROBOT, you have {number_words(n)} marks to play with:\n{body}\nVisit them in any "
                "order you like – find it in the moment.")
    return (f"Notes from the devising session, ROBOT: today we're playing with {_listed(rng, res)}. No set blocking "
            f"yet, so wander between them in whatever order feels truthful. {who}")


_SITTINGS = ("the early sitting", "the late sitting", "the private party", "the pre-theatre menu")


def _kitchen(rng, res: list[str], order: str) -> str:
    """A head chef calling a busy service."""
    if len(res) == 1:
        return _pick(rng, (f"Service! A single cover: {res[0]}. That's the whole ticket. Yes chef!",
                           f"Order in, just the one – {res[0]}. Away! Heard? Heard, chef."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"ORDER IN! {_cap(w)} covers, {_pick(rng, _SITTINGS)} – that's {w} all day."]
            lines += [f"Course {i + 1} ▸ {'fire ' if i == 0 else ''}{r}" for i, r in enumerate(res[:-1])]
            lines.append(f"Last course ▸ {res[-1]}")
            lines.append("Fire them in the order called, course by course – nobody jumps a course. Yes chef!")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Service! Listen up, {w} all day: fire {res[0]}"
        s += "".join(f"{sep} then {r}" for r in res[1:-1])
        return s + f"{sep} and finish on {res[-1]}. In that order, course by course. Yes chef? YES CHEF!"
    if rng.uniform() < 0.5:
        body = "\n".join(f"□ {r}" for r in res)
        return (f"MISE EN PLACE – {w} jobs, {w} all day:\n{body}\nKnock these out in any order you like, just have "
                "the lot done before service.")
    return (f"Right, team – {_listed(rng, res)}, {w} all day. No firing order on these – whichever's ready first, "
            "go. Heard? Heard, chef!")


_OPPONENTS = ("Rovers", "the Harlequins", "Athletic", "the Vale")


def _coach(rng, res: list[str], order: str) -> str:
    """A football or rugby coach: a game plan or a team talk."""
    if len(res) == 1:
        return _pick(rng, (f"Just the one job today, lads: {res[0]}. Go and win it.",
                           f"Set piece, one routine only – {res[0]}. Nothing fancy. Come on!"))
    n = len(res)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"GAME PLAN – Saturday v {_pick(rng, _OPPONENTS)}", f"Kick-off: {res[0]}"]
            lines += [f"Phase {i + 2}: switch play to {r}" for i, r in enumerate(res[1:-1])]
            lines.append(f"Final whistle: {res[-1]}")
            lines.append("Stick to the game plan, phase by phase, in that order – nobody freelances.")
            return "\n".join(lines)
        s = f"Right, in you come. First half, we get at {res[0]}."
        s += "".join(f" {'Then we switch play to' if i == 0 else 'After that, set piece at'} {r}."
                     for i, r in enumerate(res[1:-1]))
        return s + f" Final whistle at {res[-1]}. Play it in that order – the plan only works phase by phase."
    if rng.uniform() < 0.5:
        body = "\n".join(f"• {r}" for r in res)
        return (f"SET PIECES – training ({number_words(n)} routines)\n{body}\nRun the routines in whatever order you "
                "fancy.")
    return (f"Listen in: {_listed(rng, res)}. No fixed order today – pick them off as the game opens up. Good "
            "luck, all of you.")


_FIRMS = ("Pettigrew, Hale & Dunmore", "Ashworth Lyle LLP", "Messrs Crabtree and Vane", "Ogilvy Rowntree, Solicitors")
_ORDINALS = ("First", "Second", "Third", "Fourth", "Fifth", "Sixth", "Seventh", "Eighth", "Ninth", "Tenth")


def _solicitor(rng, res: list[str], order: str) -> str:
    """A solicitor: contract clauses or a formal letter."""
    firm = _pick(rng, _FIRMS)
    if len(res) == 1:
        return _pick(rng, (f"WHEREAS the Robot has been duly instructed, the Robot shall proceed to {res[0]} and to no "
                           "other place.",
                           f"Dear Robot,\nWe are instructed that you should attend at {res[0]} at your earliest "
                           f"convenience.\nYours faithfully,\n{firm}"))
    n = len(res)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = ["MEMORANDUM OF ATTENDANCE",
                     "WHEREAS the Principal requires the Robot to attend at certain places;",
                     "NOW THIS DEED WITNESSETH as follows:"]
            prev = ""
            for i, r in enumerate(res):
                term = "Final" if i == n - 1 else _ORDINALS[i]
                if i == 0:
                    body = f"The Robot shall first proceed to {r}"
                else:
                    body = f"Upon attending at the {prev} Chattel, the Robot shall proceed to {r}"
                lines.append(f"1.{i + 1} {body} (hereinafter 'the {term} Chattel').")
                prev = term
            lines.append("2.1 The attendances in clause 1 shall be made seriatim, strictly in the sequence there set "
                         "out, notwithstanding that another route may be shorter.")
            return "\n".join(lines)
        sep = _sep(res)
        s = (f"Dear Robot,\nRe: Your attendance on our client's behalf\nWe write on behalf of our client, who "
             f"instructs us that you are to attend first at {res[0]}")
        s += "".join(f"{sep} thereafter at {r}" for r in res[1:-1])
        return s + (f"{sep} and lastly at {res[-1]}. The order of attendance is a condition of these instructions and "
                    f"may not be varied.\nYours faithfully,\n{firm}")
    if rng.uniform() < 0.5:
        letters = "abcdefghij"
        lines = ["WHEREAS the Principal requires the Robot to attend at certain places;",
                 "IT IS AGREED that the Robot shall attend at each of the following, in no particular sequence:"]
        ends = ["; and" if i == n - 2 else ";" if i < n - 2 else "." for i in range(n)]
        lines += [f"({letters[i]}) {r}{ends[i]}" for i, r in enumerate(res)]
        lines.append("Notwithstanding the order in which they are listed above, the Robot may attend them in any order "
                     "it sees fit.")
        return "\n".join(lines)
    return (f"Dear Sir or Madam,\nWe act for the owner of the property and write to ask that you attend at "
            f"{_listed(rng, res)}. Our client has no preference as to the order, and you may take them in whatever "
            f"order you find convenient.\nYours faithfully,\n{firm}")


def render_instruction_v(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a theatre director, a head chef, a coach, a
    solicitor). Goals stay in visiting order; strict texts say the order is fixed ('cues run in strict running
    order', 'hit your marks in the order rehearsed', 'in the order called, course by course', 'phase by phase, in
    that order', 'seriatim, strictly in the sequence there set out', 'may not be varied'), free ones say it is open
    ('in any order you like', 'no set blocking', 'no firing order', 'in whatever order you fancy', 'no fixed order',
    'in no particular sequence', 'no preference as to the order')."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(4))
    return (_theatre, _kitchen, _coach, _solicitor)[who](rng, res, order)
