"""Held-out phrasings of set AF (split `unseen_af`): four people who send a home robot round a house, each in the
layout and words of their own job or pastime.

Written by a helper that never read the parser (nor its lexicon, tagger, sensor reader, readings, agreement,
adapters, LLM or command code, nor the evaluation code), before any run of any reader on these sentences, with only
the interface of set W in view.

Voices (whole instructions, `render_instruction_af`):

- a rally co-driver reading pace notes: terse calls, arrows and slashes between the stages, flat-out and
  no-cutting talk, a flying finish;
- a bingo caller: eyes-down patter, goals drawn out of the drum one after another, a full house at the end;
- a police radio dispatcher: control-to-unit calls, "be advised", "respond", "copy", "over";
- a parish vicar reading the Sunday notices: ordinals (firstly, secondly ...), long courteous sentences, a blessing
  at the end.

Style guide of the goals (`render_goal_af`; shared by all four voices, since a goal is written before its
instruction's voice is drawn):

- goal: the determiner "the", then the head as given. Attributes written before the noun in the target's phrase go
  before the noun in order, or after it as a comma aside or "(the X and Y one)"; states (attributes not in
  the phrase) go hyphenated before the noun, in brackets, in a "that is/are ..." clause or after "currently".
  Rooms: "in the R", "through in the R", "out in the R", "from the R", "(room: R)", or possessive "the R's ...".
  Relations come last, anchors with their own attributes and states before their noun and their own relations in
  brackets ("itself ..." / "the one ...") or between dashes; a second relation of the goal follows ", and also".
- relations (own words, each keeps its core word): near: near, close to, not far from, in the vicinity of, within a
  stone's throw of; next_to: next to, right next to, parked next to, snug next to; beside: beside, just beside, set
  beside, tucked in beside; by: by, right by, sat by, standing by; on: on, on top of, perched on, sat on top of,
  resting on; under: under, underneath, beneath, tucked under; above: above, directly above, up above, high above;
  in: in, inside, stowed inside, kept in; with: with, sporting, carrying, bearing; in_room_with: in the same room
  as, sharing a room with, in the room that also holds; in_front_of: in front of, right in front of, just in front
  of, out in front of; behind: behind, round the back of, tucked behind, right behind; opposite: opposite, across
  from, facing, directly opposite, across the way from; left_of: to the left of, left of, on the left-hand side of,
  off to the left of; right_of: to the right of, on the right-hand side of, off to the right of, on the right of.
- readings: temperature / temp; humidity / relative humidity / RH / air humidity; NDVI /
  greenness index / NDVI score; other readings by their key with spaces.
- comparisons: gt above, over, higher than, more than, north of, in excess of; ge at least, X or more, X or above,
  no lower than, not below; lt below, under, lower than, less than, south of; le at most, X or less, X or below, no
  higher than, not above, X at the very most; approx about, roughly, around, in the region of, X or thereabouts,
  X give or take. Frames: "whose N is ...", "whose N reads ...", "with N ...", "(N: ...)", "- N ... -".
- numbers: digits ("22.5", "-18", ".65"), words ("forty", "minus eighteen"), halves and quarters ("22 and a half",
  "minus three and a quarter"), fractions below one ("three fifths", "seven tenths"), spoken decimals ("nought
  point six five"), "N below zero"; units: °C, degrees, degrees C, deg C, degrees Celsius, C (unit "c"); Fahrenheit
  rounded to a whole degree, °F / degrees Fahrenheit (unit "f", value converted back to Celsius); %, per cent,
  percent, % RH (unit "%"); NDVI without unit.
- superlatives: before the noun (hottest, warmest, coldest, coolest, chilliest, dampest, most humid, driest, least
  humid, greenest, lushest, least green, palest) or a tail ("with the highest N of any", "with the lowest N of any",
  "whose N beats all the others", "whose N is the lowest going", "(highest N of the lot)",
  "(lowest N of the lot)").
- coordinates, x then y, ASCII minus: "at x {x}, y {y}", "at co-ords ({x}, {y})", "where x reads {x} and y reads
  {y}", "at position x = {x} / y = {y}", "at the spot marked x {x} and y {y}", "at [x {x} | y {y}]".

Order words of the instructions: strict ones say the order is fixed (note order only, no cutting; in the order
they're drawn; attend in sequence as given; in that order, please), free ones say it is open (free route, your
line; dab them in any order; no priority between calls, your discretion; in no particular order).

Slips: twice, early on, Python started from the worktree's scratch folder (without the worktree on its path)
imported the package `ragnav_jax` (its `__init__`, and on the first try `ragnav_jax.language` while failing to find
this module) from the main checkout through the environment's editable install; nothing there was read, printed
(but the package's path) or changed, and every later run used this worktree.
"""

from __future__ import annotations

import math

import numpy as np

from ragnav_jax.language.template_text import attributes_and_states, both, hyphenated, is_are, number_words, tidy
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target


def _pick(rng: np.random.Generator, seq):
    return seq[int(rng.integers(len(seq)))]


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


# ----------------------------------------------------------------------------------------------------
# Goals

REL_WORDS: dict[str, tuple[str, ...]] = {
    "near": ("near", "close to", "not far from", "in the vicinity of", "within a stone's throw of"),
    "next_to": ("next to", "right next to", "parked next to", "snug next to"),
    "beside": ("beside", "just beside", "set beside", "tucked in beside"),
    "by": ("by", "right by", "sat by", "standing by"),
    "on": ("on", "on top of", "perched on", "sat on top of", "resting on"),
    "under": ("under", "underneath", "beneath", "tucked under"),
    "above": ("above", "directly above", "up above", "high above"),
    "in": ("in", "inside", "stowed inside", "kept in"),
    "with": ("with", "sporting", "carrying", "bearing"),
    "in_room_with": ("in the same room as", "sharing a room with", "in the room that also holds"),
    "in_front_of": ("in front of", "right in front of", "just in front of", "out in front of"),
    "behind": ("behind", "round the back of", "tucked behind", "right behind"),
    "opposite": ("opposite", "across from", "facing", "directly opposite", "across the way from"),
    "left_of": ("to the left of", "left of", "on the left-hand side of", "off to the left of"),
    "right_of": ("to the right of", "on the right-hand side of", "off to the right of", "on the right of"),
}

_ROOM_AFTER = ("in the {}", "through in the {}", "out in the {}", "from the {}", "(room: {})")


def _rel_word(rng: np.random.Generator, kind: str) -> str:
    return _pick(rng, REL_WORDS.get(kind, (kind.replace("_", " "),)))


def _anchor(rng: np.random.Generator, a: Target, depth: int) -> str:
    """An anchor: 'the' + its attributes and states before the noun, its own relations in brackets or dashes."""
    if a.phrase.endswith(a.head):
        pre, states = attributes_and_states(a)
        words = [hyphenated(states)] if states else []
        np_ = "the " + " ".join([*words, *pre, a.head])
    else:
        np_ = "the " + a.phrase
    if not a.relations:
        return np_
    parts = [f"{_rel_word(rng, r.type)} {_anchor(rng, r.anchor, depth + 1)}" for r in a.relations]
    inner = ", and also ".join(parts)
    plain = all(not r.anchor.relations for r in a.relations)
    frames = ["({})".format("itself " + inner), "({})".format("the one " + inner)]
    if depth == 1 and plain:
        frames.append(f"- the one {inner} -")
    return np_ + " " + _pick(rng, frames)


def _relations(rng: np.random.Generator, rels: tuple[Relation, ...]) -> str:
    parts = [f"{_rel_word(rng, r.type)} {_anchor(rng, r.anchor, 1)}" for r in rels]
    return ", and also ".join(parts)


def _states_after(rng: np.random.Generator, head: str, states: list[str], closing: bool) -> str:
    """States after the noun; `closing`: something follows, so a clause gets a comma after it."""
    opts = [f"({both(states)})", f", currently {both(states)},"]
    if not closing:
        opts.append(f"that {is_are(head)} {both(states)}")
    else:
        opts.append(f"that {is_are(head)} {both(states)},")
    return _pick(rng, opts)


def _noun(rng: np.random.Generator, t: Target, prefix: str, room_first: str, closing: bool) -> str:
    """'the' + [room's] + [superlative] + attributes + head + states, in one of several layouts."""
    lead = "the " + (f"{room_first}'s " if room_first else "") + (f"{prefix} " if prefix else "")
    if not t.phrase.endswith(t.head):
        return lead + t.phrase
    pre, states = attributes_and_states(t)
    layout = rng.uniform()
    if pre and layout < 0.3:  # attributes after the noun
        if rng.uniform() < 0.5:
            out = lead + t.head + ", " + ", ".join(pre) + ","
        else:
            out = lead + t.head + f" (the {both(pre)} one)"
        if states:
            out += " " + _states_after(rng, t.head, states, closing)
        return out
    if states and rng.uniform() < 0.4:  # states hyphenated before the noun
        return lead + " ".join([hyphenated(states), *pre, t.head])
    out = lead + " ".join([*pre, t.head])
    if states:
        out += " " + _states_after(rng, t.head, states, closing)
    return out


def render_goal_af(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AF writes it: the noun phrase (room possessive or superlative prefix before it), then the room,
    the sensor tail, the coordinate hint (always after any number of the tail) and last the relations."""
    t = sg.target
    room_first = sg.room if sg.room and rng.uniform() < 0.25 else ""
    room_after = _pick(rng, _ROOM_AFTER).format(sg.room) if sg.room and not room_first else ""
    rels = _relations(rng, t.relations) if t.relations else ""
    closing = bool(room_after or tail or hint or rels)
    out = _noun(rng, t, prefix, room_first, closing)
    if room_after:
        out += " " + room_after
    has_number = any(ch.isdigit() for ch in tail)
    if hint and tail and not has_number and rng.uniform() < 0.5:
        out += ", " + hint + ", " + tail
    else:
        if tail:
            out += (", " if room_after and tail.startswith(("whose", "with")) else " ") + tail
        if hint:
            out += (", " if tail or rng.uniform() < 0.5 else " ") + hint
    if rels:
        out += (", " if (tail or hint or rng.uniform() < 0.4) else " ") + rels
    return tidy(out).replace(" ,", ",")


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

_NAMES: dict[str, tuple[str, ...]] = {
    "temperature_c": ("temperature", "temp"),
    "humidity_pct": ("humidity", "relative humidity", "RH", "air humidity"),
    "ndvi": ("NDVI", "greenness index", "NDVI score"),
}
_PREDS: dict[str, tuple[str, ...]] = {
    "gt": ("above {}", "over {}", "higher than {}", "more than {}", "north of {}", "in excess of {}"),
    "ge": ("at least {}", "{} or more", "{} or above", "no lower than {}", "not below {}"),
    "lt": ("below {}", "under {}", "lower than {}", "less than {}", "south of {}"),
    "le": ("at most {}", "{} or less", "{} or below", "no higher than {}", "not above {}", "{} at the very most"),
    "approx": ("about {}", "roughly {}", "around {}", "in the region of {}", "{} or thereabouts", "{}, give or take"),
}
_SUPER_ADJ: dict[tuple[str, str], tuple[str, ...]] = {
    ("temperature_c", "max"): ("hottest", "warmest"),
    ("temperature_c", "min"): ("coldest", "coolest", "chilliest"),
    ("humidity_pct", "max"): ("dampest", "most humid"),
    ("humidity_pct", "min"): ("driest", "least humid"),
    ("ndvi", "max"): ("greenest", "lushest"),
    ("ndvi", "min"): ("least green", "palest"),
}
_SUPER_TAIL = {
    "max": ("with the highest {} of any", "whose {} beats all the others", "(highest {} of the lot)"),
    "min": ("with the lowest {} of any", "whose {} is the lowest going", "(lowest {} of the lot)"),
}
_FRACTIONS = {0.1: "one tenth", 0.2: "one fifth", 0.25: "one quarter", 0.3: "three tenths", 0.4: "two fifths",
              0.5: "one half", 0.6: "three fifths", 0.7: "seven tenths", 0.75: "three quarters", 0.8: "four fifths",
              0.9: "nine tenths"}
_PARTS = {0.25: "and a quarter", 0.5: "and a half", 0.75: "and three quarters"}
_DIGIT_WORDS = ("nought", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")


def _digits(v: float) -> str:
    return f"{v:g}"


def _number(rng: np.random.Generator, v: float, below_zero_ok: bool) -> tuple[str, bool]:
    """(v written in one of several formats, whether it was written as 'N below zero')."""
    v = round(v, 6)
    whole = float(v).is_integer()
    frac = round(abs(v) - math.floor(abs(v)), 6)
    opts: list[tuple[str, bool]] = [(_digits(v), False)]
    if whole and abs(v) < 1000:
        opts.append((number_words(int(v)), False))
    if not whole and frac in _PARTS and abs(v) >= 1 and abs(v) < 1000:
        n = int(math.floor(abs(v)))
        w = number_words(n) if rng.uniform() < 0.5 else str(n)
        opts.append((("minus " if v < 0 else "") + f"{w} {_PARTS[frac]}", False))
    if 0 < v < 1 and round(v, 6) in _FRACTIONS:
        opts.append((_FRACTIONS[round(v, 6)], False))
    if 0 < v < 1:
        opts.append((_digits(v)[1:] if _digits(v).startswith("0.") else _digits(v), False))
    if not whole and abs(v) < 1000:
        s = f"{abs(v):g}"
        if "e" not in s and len(s.split(".")[1]) <= 2:
            n, d = s.split(".")
            head = "nought" if n == "0" else number_words(int(n))
            opts.append((("minus " if v < 0 else "") + head + " point " + " ".join(_DIGIT_WORDS[int(x)] for x in d),
                         False))
    if v < 0 and below_zero_ok:
        a = -v
        opts.append((number_words(int(a)) if a.is_integer() and rng.uniform() < 0.5 else _digits(a), True))
    return _pick(rng, opts)


def _value_text(rng: np.random.Generator, c: SensorConstraint, cmp: str) -> tuple[str, SensorConstraint]:
    """The value with its unit, and the constraint exactly as written."""
    v = float(c.value)
    rd = c.reading
    below_ok = cmp in ("gt", "approx")
    if rd == "temperature_c":
        if rng.uniform() < 0.2:  # Fahrenheit, to the whole degree
            f = int(round(v * 9 / 5 + 32))
            num, _ = _number(rng, float(f), False)
            unit = _pick(rng, (" °F", " degrees Fahrenheit", "°F"))
            if not num[-1].isdigit() and not unit.startswith(" "):
                unit = " °F"
            return num + unit, SensorConstraint(rd, cmp, (f - 32) * 5 / 9, "f")
        num, below = _number(rng, v, below_ok)
        if below:
            return num + _pick(rng, (" degrees below zero", " below zero", " °C below zero")), \
                SensorConstraint(rd, cmp, v, "c")
        unit = _pick(rng, ("°C", " °C", " degrees", " degrees C", " deg C", " degrees Celsius", "C"))
        if not num[-1].isdigit() and not unit.startswith(" "):
            unit = " °C"
        return num + unit, SensorConstraint(rd, cmp, v, "c")
    if rd == "humidity_pct":
        num, _ = _number(rng, v, False)
        unit = _pick(rng, ("%", " per cent", " percent", "% RH"))
        if unit.startswith("%") and not num[-1].isdigit():
            unit = " per cent"
        return num + unit, SensorConstraint(rd, cmp, v, "%")
    if rd == "ndvi":
        num, _ = _number(rng, v, False)
        return num, SensorConstraint(rd, cmp, v, "")
    num = _digits(v)
    return num + (f" {c.unit}" if c.unit else ""), SensorConstraint(rd, cmp, v, c.unit)


def render_sensor_af(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('hottest', 'least humid', 'lushest') or a tail ('with the lowest
    temp of any', 'whose RH beats all the others', '(highest NDVI of the lot)'); thresholds after the noun ('whose
    temperature is above 40 °C', 'with humidity forty per cent or less', '(NDVI: roughly three fifths)')."""
    rd = c.reading
    name = _pick(rng, _NAMES.get(rd, (rd.replace("_", " "),)))
    if c.is_superlative:
        adj = _SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.45:
            return _pick(rng, adj), "", SensorConstraint(rd, c.comparator, None, "")
        return "", _pick(rng, _SUPER_TAIL[c.comparator]).format(name), SensorConstraint(rd, c.comparator, None, "")
    cmp = c.comparator
    if cmp not in _PREDS:
        cmp = "approx"
    val, written = _value_text(rng, c, cmp)
    pred = _pick(rng, _PREDS[cmp]).format(val)
    frame = _pick(rng, ("whose {n} is {p}", "whose {n} reads {p}", "with {n} {p}", "({n}: {p})", "- {n} {p} -"))
    if frame.startswith("with") and pred.endswith("give or take"):
        frame = "({n}: {p})"
    return "", frame.format(n=name, p=pred), written


# ----------------------------------------------------------------------------------------------------
# Coordinate hints


def hint_text_af(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at x 3.5, y 2', 'at co-ords (3.5, 2)', 'where x
    reads 3.5 and y reads 2', 'at position x = 3.5 / y = 2', 'at the spot marked x 3.5 and y 2', 'at [x 3.5 | y 2]'."""
    return _pick(rng, (f"at x {x}, y {y}", f"at co-ords ({x}, {y})", f"where x reads {x} and y reads {y}",
                       f"at position x = {x} / y = {y}", f"at the spot marked x {x} and y {y}",
                       f"at [x {x} | y {y}]"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions

_ORDINALS = ("Firstly", "Secondly", "Thirdly", "Fourthly", "Fifthly", "Sixthly", "Seventhly", "Eighthly",
             "Ninthly", "Tenthly")


def _running(rng: np.random.Generator, res: list[str]) -> str:
    """Goals in a running sentence: commas, or semicolons where a goal has commas of its own."""
    if len(res) == 2:
        return f"{res[0]} and {res[1]}"
    if any("," in r for r in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


# rally co-driver reading pace notes
def _rally(rng: np.random.Generator, res: list[str], order: str) -> str:
    if len(res) == 1:
        return _pick(rng, (f"Short stage, one note only: flat out to {res[0]}. Flying finish there.",
                           f"Ready ... go! Single note: {res[0]}, and that's the finish.",
                           f"Stage notes: start, {res[0]}, stop. Nothing else on this one."))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            return ("Stage notes, read in order: go, " + ", then ".join(res)
                    + ", flying finish. Note order only, don't cut.")
        if k == 1:
            return "Running order: " + " → ".join(res) + ". Each in turn as noted; no cutting, no skipping ahead."
        return ("Ready ... go! Flat to " + res[0] + "; "
                + "; ".join(f"keep in, straight on to {r}" for r in res[1:])
                + ". Stick to the notes in sequence, no shortcuts.")
    k = int(rng.integers(3))
    if k == 0:
        return f"Free-route stage: {_running(rng, res)}. Any order you like, your line, your call."
    if k == 1:
        return "Notes for the stage, no set running order, pick your own line: " + " / ".join(res) + ". Go when ready."
    return f"Ready ... go! Hit {_running(rng, res)}. The order's open, drive it however flows best."


# bingo caller
def _bingo(rng: np.random.Generator, res: list[str], order: str) -> str:
    if len(res) == 1:
        return _pick(rng, (f"On its own ... {res[0]}! Eyes down for that one and that's your lot.",
                           f"Eyes down, look in: just the one out of the drum tonight, {res[0]}. House!",
                           f"One ball only, folks: {res[0]}. Dab it and shout."))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            mids = "".join(f" Next out, {r}." for r in res[1:-1])
            return (f"Eyes down, look in! First out of the drum, {res[0]}.{mids} And the last one, {res[-1]}."
                    " Mark them off in the order they're drawn, no jumping the calls.")
        if k == 1:
            return ("Here they come, in the order they're drawn and no other: " + " ... ".join(res)
                    + ". Full house only if you dab them one by one as called.")
        return (f"Eyes down! Calls in strict order tonight: {_running(rng, res)}, each one only after the one "
                "called before it.")
    k = int(rng.integers(3))
    if k == 0:
        return f"Eyes down! Tonight's card: {_running(rng, res)}. Dab them in any order you like, it's a full house we want."
    if k == 1:
        return ("All on the one card, so mark them off as they come to you, any order: " + " ... ".join(res)
                + ". House!")
    return f"Eyes down, look in, order doesn't matter on this card: {_running(rng, res)}."


# police radio dispatcher
def _dispatch(rng: np.random.Generator, res: list[str], order: str) -> str:
    if len(res) == 1:
        return _pick(rng, (f"Control to mobile unit: single call, respond to {res[0]}. Over.",
                           f"Dispatch: attend {res[0]}, routine, no further calls. Copy?",
                           f"Be advised, one job only: {res[0]}. Over."))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            return (f"Control to mobile unit: respond first to {res[0]}, "
                    + ", ".join(f"then proceed to {r}" for r in res[1:])
                    + ". Attend in sequence as given, do not deviate. Over.")
        if k == 1:
            return ("Be advised, calls to be attended strictly in the order received: " + "; ".join(res)
                    + ". Copy?")
        return ("Dispatch, stacked calls, in this sequence only: " + "; next, ".join(res)
                + ". Clear each before the next. Over.")
    k = int(rng.integers(3))
    if k == 0:
        return f"All units, be on the lookout for {_running(rng, res)}. No priority between calls, your discretion. Over."
    if k == 1:
        return "Control to mobile unit, open calls, attend in any sequence: " + "; ".join(res) + ". Copy?"
    return f"Dispatch: {_running(rng, res)}. Equal priority, respond in whatever order suits. Over."


# parish vicar reading the notices
def _vicar(rng: np.random.Generator, res: list[str], order: str) -> str:
    if len(res) == 1:
        return _pick(rng, (f"Just the one notice this week: would our robot kindly call on {res[0]}. Thank you.",
                           f"A single notice before the final hymn: a visit, please, to {res[0]}. God bless.",
                           f"Only one notice today, dear friends: {res[0]} awaits a visit."))
    if order == "strict":
        k = int(rng.integers(2))
        if k == 0:
            body = " ".join(f"{_ORDINALS[i] if i < len(_ORDINALS) else 'Next'}, {r}." for i, r in enumerate(res))
            return ("A few notices before we say the grace, to be visited in that order, please. " + body
                    + " In that order, as set out on the sheet. God bless.")
        return (f"Some notices this Sunday. Would our robot please call first on {res[0]}, "
                + ", ".join(f"and after that on {r}" for r in res[1:])
                + ", in that order and no other. Thank you all.")
    k = int(rng.integers(3))
    if k == 0:
        return f"Some notices this Sunday: {_running(rng, res)}, in no particular order, as the spirit moves you."
    if k == 1:
        return ("A few notices, dear friends, none taking precedence over another: " + "; ".join(res)
                + ". Visit them in any order you please. God bless.")
    return f"Before the final hymn, a round of visits in whatever order is convenient: {_running(rng, res)}."


_VOICES = (_rally, _bingo, _dispatch, _vicar)


def render_instruction_af(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a rally co-driver, a bingo caller, a police
    dispatcher, a parish vicar). Goals stay in visiting order, each written once as rendered; strict texts say the
    order is fixed, free ones say it is open; a single goal is one call."""
    voice = _VOICES[int(rng.integers(len(_VOICES)))]
    return tidy(voice(rng, list(res), order))
