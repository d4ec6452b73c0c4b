"""Held-out sentence set AN (episode split `unseen_an`): goals, sensor phrases, coordinate hints and whole
instructions in four voices that no earlier set used.

Who wrote it: a helper session that never read the project's instruction readers (parser, lexicon, tagger,
sensor reader, grounding, LLM adapter, agreement, readings, evaluation) nor any other `phrasings_*.py` module,
so that the set measures, fresh, how the readers cope with phrasings nobody tuned them on.

What was read: the signatures and docstrings of the four public functions of `phrasings_w.py` (not their bodies);
`types.py` and `template_text.py` whole; `UNSEEN_TEMPLATES` and `_renderer` in `episodes.py`; `EPISODE_SPLITS`
in `config.py`; `tests/test_heldout_sets.py` whole; the `subgoals()` strategy of `tests/test_phrasings_dev8.py`.

The four voices (one per whole instruction, drawn from the generator passed in):
  * the Speaker of a parliament running the day's business ("Order, order", "the Ayes have it", the Order Paper);
  * an academic peer reviewer writing a referee's report ("major comments", "recommendation: minor revision");
  * a fashion editor briefing a model ("darling", "this season's look", the show's running order);
  * a stand-up comedian doing a bit about their robot ("so I've got this robot, right?", "I'm here all week").

Style guide.
  * Goals: always start with "the"; the head noun is written exactly as given (never pluralised, hyphenated or
    split); attributes the phrase puts before the noun are kept in its order ("the teal wool lamp"), or moved
    behind it ("the lamp that is teal and wool", "the lamp (teal, wool)"); states ("switched on", "open") come as
    "that is open", "which is currently switched on" or hyphenated before the noun ("the switched-on lamp").
    Then, in this order: the room ("over in the kitchen"), a sensor tail, a coordinate hint, and the relations
    last. A relation's own relations sit in brackets after its anchor ("(the one beside the lamp)"); sibling
    relations are joined with "and".
  * Sensor phrases: a superlative is an adjective before the noun ("the warmest", "the most humid") or a tail
    ("whose noise level is the lowest of the lot"); a threshold is a tail ("whose humidity is 40% or less",
    "registering air pressure in the region of 1013 millibars"). Values are written exactly: digits (shortest
    form), words ("forty", "twenty-two and a half", "nought point six five"), or an exactly convertible other
    unit (degrees Fahrenheit, kilowatts, millibars); the returned constraint keeps the canonical value.
  * Coordinate hints: x then y, each number exactly as passed in ("at (3.5, 2)", "where x is 3.5 and y is 2").
  * Instructions: each goal written once, verbatim, in visiting order. Strict texts say in words that the order
    is fixed ("strictly in the sequence set down", "in precisely the sequence listed", "the running order of this
    show is fixed", "it has to be in that exact order"); free texts say it is open ("in whatever sequence it
    pleases", "in any sequence they prefer", "in whatever order you fancy", "any order"). A single goal gets
    neither kind of cue, no sequencing word and no digit.
  * Frames avoid nouns that could be scene objects (no "chair", "speaker", "table", "wardrobe", "floor") and
    avoid relation words right before a goal.

Tests: tests/test_phrasings_an.py. They were checked against a module broken on purpose, one break at a
time (each break failed at least one test; the module was restored after each): the head noun pluralised, the
Speaker's strict cues reworded away, values written to one decimal, "at most" written as "below", the hint
written y before x, relations dropped, goals listed in reverse, and Python's own `random` used instead of the
generator passed in.

Slips (seen beyond the allowed list, by accident): the private `def` lines of phrasings_w.py (names and
arguments, as printed by the prescribed `grep -n "^def "`); the `_rng` function that follows `_renderer` in
episodes.py; one line of config.py that checks `episodes.split` against EPISODE_SPLITS; the `def` lines (names
only) of test_phrasings_dev8.py's other helpers and tests; the HEAD commit message (about room_scores.py and a
"distinctiveness" figure); the `[tool.ruff]` part of pyproject.toml and the file list of ragnav_jax/language/;
at run time, the READINGS tuple (printed through types.py) and some subgoals() examples drawn by hypothesis.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.template_text import (
    attributes_and_states,
    both,
    hyphenated,
    is_are,
    number_words,
    plural,
    tidy,
)
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target


def _pick(rng: np.random.Generator, options):
    return options[int(rng.integers(len(options)))]


# ----------------------------------------------------------------------------------------------------
# goals

_REL = {
    "near": ("near", "close to", "not far from", "in the vicinity of"),
    "next_to": ("next to", "right next to", "alongside"),
    "beside": ("beside", "just beside"),
    "by": ("by", "right by", "standing by"),
    "on": ("on", "on top of", "sitting on", "resting on"),
    "under": ("under", "underneath", "beneath"),
    "above": ("above", "directly above", "up above"),
    "in": ("in", "inside", "tucked inside"),
    "with": ("with", "that {comes} with", "that {has}"),
    "in_room_with": ("in the same room as", "sharing a room with", "in whichever room holds"),
    "in_front_of": ("in front of", "just in front of", "out in front of"),
    "behind": ("behind", "just behind", "round the back of"),
    "opposite": ("opposite", "across from", "facing", "directly opposite"),
    "left_of": ("to the left of", "on the left of", "left of"),
    "right_of": ("to the right of", "on the right of", "right of"),
}

_ROOM = ("in the {room}", "over in the {room}", "down in the {room}", "located in the {room}",
         "somewhere in the {room}")


def _rel_word(rng, rel: Relation, owner: Target) -> str:
    w = _pick(rng, _REL[rel.type])
    many = plural(owner.head)
    return w.format(comes="come" if many else "comes", has="have" if many else "has")


def _np(rng, t: Target, prefix: str = "", brackets: bool = True) -> tuple[str, bool]:
    """The noun phrase of a target with its attributes and states (no relations); and whether it ends in a clause.
    Without `brackets`, attributes are never put in brackets (an anchor whose own relations come in brackets)."""
    pre, states = attributes_and_states(t)
    v = is_are(t.head)
    clause = False
    form = int(rng.integers(3 if brackets else 2)) if pre else 0
    if form == 1:  # the lamp that is teal and wool (and open)
        return f"the {prefix} {t.head} that {v} {both(pre + states)}", True
    if form == 2:
        base = f"the {prefix} {t.head} ({', '.join(pre)})"
    else:
        base = f"the {prefix} {' '.join(pre)} {t.head}"
    if states:
        how = int(rng.integers(4))
        if how == 0:
            base, clause = f"{base} that {v} {both(states)}", True
        elif how == 1:
            base, clause = f"{base} which {v} currently {both(states)}", True
        elif how == 2:
            base, clause = f"{base} that {v} {both(states)} right now", True
        elif form == 0:
            base = f"the {prefix} {hyphenated(states)} {' '.join(pre)} {t.head}"
        else:
            base, clause = f"{base} that {v} {both(states)}", True
    return base, clause


def _relations(rng, t: Target, depth: int = 1) -> str:
    parts = []
    for r in t.relations:
        parts.append(f"{_rel_word(rng, r, t)} {_anchor(rng, r.anchor, depth)}")
    if len(parts) <= 2:
        return " and ".join(parts)
    return ", ".join(parts[:-1]) + " and " + parts[-1]


def _anchor(rng, t: Target, depth: int) -> str:
    """An anchor at `depth` (1: a relation of the goal itself); attributes go in brackets only where no other
    brackets are around (no relations of its own, not inside another anchor's brackets)."""
    base, _ = _np(rng, t, brackets=depth == 1 and not t.relations)
    if t.relations:
        one = "ones" if plural(t.head) else "one"
        base = f"{base} (the {one} {_relations(rng, t, depth + 1)})"
    return base


def render_goal_an(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AN writes it: 'the teal wool lamp over in the nursery', 'the lamp (teal, wool)', 'the lamp
    that is teal and wool and switched on', 'the warmest mini-fridge located in the pantry', 'the guitar where x
    is 3.5 and y is 2', 'the lamp down in the nursery, sharing a room with the credenza (the one that comes with
    the record player)'. `prefix` goes just before the noun's other modifiers, `tail` after the room; the room
    comes before any sensor tail (a superlative tail is read inside it), a coordinate hint after the sensor tail
    (so its numbers are the last of the goal), and relations last."""
    t = sg.target
    text, clause = _np(rng, t, prefix)
    extra = False
    if sg.room:
        text += " " + _pick(rng, _ROOM).format(room=sg.room)
        extra = True
    if tail:
        text += " " + tail
        extra = True
    if hint:
        text += " " + hint
        extra = True
    if t.relations:
        text += (", " if extra or clause else " ") + _relations(rng, t)
    return tidy(text)


# ----------------------------------------------------------------------------------------------------
# sensor phrases

_NAME = {
    "temperature_c": ("temperature", "air temperature"),
    "ndvi": ("NDVI", "NDVI (vegetation index)"),
    "humidity_pct": ("humidity", "relative humidity"),
    "co2_ppm": ("CO2 level", "carbon dioxide level", "CO2 concentration"),
    "noise_db": ("noise level", "sound level"),
    "light_lux": ("light level", "illuminance"),
    "battery_pct": ("battery charge", "battery level"),
    "power_w": ("power draw", "power consumption"),
    "weight_kg": ("weight", "mass"),
    "pressure_hpa": ("air pressure", "barometric pressure"),
}

# reading -> (unit as written, units after digits, units after words)
_UNITS = {
    "temperature_c": ("c", ("°C", " °C", " degrees Celsius", " degrees C"), (" degrees Celsius",)),
    "ndvi": ("", ("",), ("",)),
    "humidity_pct": ("%", ("%", " per cent", " percent"), (" per cent", " percent")),
    "co2_ppm": ("ppm", (" ppm", " parts per million"), (" parts per million",)),
    "noise_db": ("db", (" dB", " decibels"), (" decibels",)),
    "light_lux": ("lux", (" lux", " lx"), (" lux",)),
    "battery_pct": ("%", ("%", " per cent"), (" per cent",)),
    "power_w": ("w", (" W", " watts"), (" watts",)),
    "weight_kg": ("kg", (" kg", " kilograms", " kilos"), (" kilograms", " kilos")),
    "pressure_hpa": ("hpa", (" hPa", " hectopascals"), (" hectopascals",)),
}

# other units a value may be written in: reading -> (unit, units after digits, units after words, to, back)
_OTHER = {
    "temperature_c": ("f", ("°F", " °F", " degrees Fahrenheit"), (" degrees Fahrenheit",),
                      lambda v: v * 9 / 5 + 32, lambda w: (w - 32) * 5 / 9),
    "power_w": ("kw", (" kW", " kilowatts"), (" kilowatts",), lambda v: v / 1000, lambda w: w * 1000),
    "pressure_hpa": ("mbar", (" mbar", " millibars"), (" millibars",), lambda v: v, lambda w: w),
}

_ADJ = {
    ("temperature_c", "max"): ("warmest", "hottest"),
    ("temperature_c", "min"): ("coldest", "coolest"),
    ("humidity_pct", "max"): ("most humid", "dampest"),
    ("humidity_pct", "min"): ("least humid", "driest"),
    ("noise_db", "max"): ("loudest", "noisiest"),
    ("noise_db", "min"): ("quietest",),
    ("light_lux", "max"): ("brightest", "best-lit"),
    ("light_lux", "min"): ("dimmest", "darkest"),
    ("weight_kg", "max"): ("heaviest",),
    ("power_w", "max"): ("most power-hungry",),
    ("power_w", "min"): ("least power-hungry",),
}

_SUPER_TAIL = {
    "max": ("with the highest {name}", "whose {name} is the highest of the lot", "boasting the top {name} reading"),
    "min": ("with the lowest {name}", "whose {name} is the lowest of the lot", "showing the lowest {name} reading"),
}

_CMP = {
    "gt": ("above {q}", "more than {q}", "higher than {q}", "in excess of {q}", "greater than {q}"),
    "lt": ("below {q}", "less than {q}", "lower than {q}", "under {q}"),
    "ge": ("at least {q}", "no less than {q}", "{q} or more", "{q} or higher", "not below {q}"),
    "le": ("at most {q}", "no more than {q}", "{q} or less", "{q} or lower", "not above {q}"),
    "approx": ("about {q}", "around {q}", "roughly {q}", "approximately {q}", "in the region of {q}"),
}

_THRESH_TAIL = ("whose {name} is {c}", "where the {name} reads {c}", "registering {name} {c}",
                "with its {name} {c}")

_DIGIT = ("nought", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")


def _digits(v: float) -> str | None:
    """The shortest decimal text that reads back as exactly v ('40', '0.65', '-2.5'); None if there is none
    short enough to write."""
    s = repr(float(v))
    if "e" in s or "n" in s:
        return None
    if s.endswith(".0"):
        s = s[:-2]
    if s == "-0":
        s = "0"
    return s if float(s) == float(v) and len(s.split(".")[-1]) <= 6 else None


def _words(s: str) -> str | None:
    """Digits as words ('40' -> 'forty', '22.5' -> 'twenty-two and a half', '0.65' -> 'nought point six five');
    None where words would be clumsy."""
    neg = s.startswith("-")
    body = s[1:] if neg else s
    whole, _, frac = body.partition(".")
    n = int(whole)
    if n >= 1000 or len(frac) > 3:
        return None
    if not frac:
        w = number_words(n)
    elif frac == "5" and n >= 1:
        w = number_words(n) + " and a half"
    else:
        w = ("nought" if n == 0 else number_words(n)) + " point " + " ".join(_DIGIT[int(d)] for d in frac)
    return ("minus " + w) if neg else w


def _quantity(rng, reading: str, value: float) -> tuple[str, str]:
    """(the value with its unit as text, the unit as written)."""
    unit, after_digits, after_words = _UNITS[reading]
    v = float(value)
    if reading in _OTHER and rng.random() < 0.3:
        o_unit, o_digits, o_words, to, back = _OTHER[reading]
        w = round(to(v), 4)
        s = _digits(w)
        if s is not None and back(float(s)) == v:
            unit, after_digits, after_words, v = o_unit, o_digits, o_words, float(s)
    s = _digits(v)
    if s is None:  # not expected for sensor thresholds; write every digit repr gives
        return repr(v) + _pick(rng, after_digits), unit
    words = _words(s)
    if words is not None and rng.random() < 0.3:
        return words + _pick(rng, after_words), unit
    return s + _pick(rng, after_digits), unit


def render_sensor_an(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('warmest', 'most humid', 'least power-hungry') or a tail ('with
    the highest NDVI', 'whose noise level is the lowest of the lot', 'boasting the top CO2 level reading');
    thresholds after the noun ('whose temperature is above 40 °C', 'where the humidity reads 40 per cent or
    less', 'registering NDVI about nought point six five', 'with its power draw at least 1.5 kW', 'whose
    barometric pressure is in the region of 1013 millibars'). The constraint returned keeps reading, comparator
    and the value in the canonical unit; its unit is the one written ('c', 'f', '%', 'ppm', 'db', 'lux', 'w',
    'kw', 'kg', 'hpa', 'mbar', or '' for NDVI and superlatives)."""
    name = _pick(rng, _NAME[c.reading])
    if c.comparator in ("max", "min"):
        adj = _ADJ.get((c.reading, c.comparator), ())
        if adj and rng.random() < 0.5:
            return _pick(rng, adj), "", SensorConstraint(c.reading, c.comparator, None, "")
        tail = _pick(rng, _SUPER_TAIL[c.comparator]).format(name=name)
        return "", tail, SensorConstraint(c.reading, c.comparator, None, "")
    q, unit = _quantity(rng, c.reading, c.value)
    cmp_text = _pick(rng, _CMP[c.comparator]).format(q=q)
    tail = _pick(rng, _THRESH_TAIL).format(name=name, c=cmp_text)
    return "", tail, SensorConstraint(c.reading, c.comparator, float(c.value), unit)


# ----------------------------------------------------------------------------------------------------
# coordinate hints

_HINT = ("at ({x}, {y})", "at map position ({x}, {y})", "where x is {x} and y is {y}", "at x = {x}, y = {y}",
         "placed {x} metres east and {y} metres north of the origin")


def hint_text_an(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y, each number exactly as passed in: 'at (3.5, 2)',
    'at map position (3.5, 2)', 'where x is 3.5 and y is 2', 'at x = 3.5, y = 2', 'placed 3.5 metres east and
    2 metres north of the origin'."""
    return _pick(rng, _HINT).format(x=x, y=y)


# ----------------------------------------------------------------------------------------------------
# whole instructions


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _and(res: list[str], word: str = "and") -> str:
    """Goals in a running sentence: commas (semicolons where a goal has commas or an 'and' of its own), the last
    after `word`; two goals: 'A and B' ('A, and B' or 'A; and B' where a goal has an 'and' or commas)."""
    if len(res) == 2:
        if any("," in r for r in res):
            return f"{res[0]}; {word} {res[1]}"
        if any(" and " in r for r in res):
            return f"{res[0]}, {word} {res[1]}"
        return f"{res[0]} {word} {res[1]}"
    sep = "; " if any("," in r or " and " in r for r in res) else ", "
    return sep.join(res[:-1]) + f"{sep}{word} " + res[-1]


def _steps(res: list[str], first: str, mid: str, last: str, sep: str = "; ") -> str:
    """Goals in visiting order, each after its sequencing word: 'first, A; next, B; and finally, C'. A comma
    separator becomes a semicolon where a goal has commas of its own."""
    if sep == ", " and any("," in g for g in res):
        sep = "; "
    out = [first.format(g=res[0])]
    out += [mid.format(g=g) for g in res[1:-1]]
    out.append(last.format(g=res[-1]))
    return sep.join(out)


def _letters(res: list[str]) -> str:
    return "; ".join(f"({chr(97 + i)}) {g}" for i, g in enumerate(res))


def _speaker(rng, res: list[str], order: str) -> str:
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (
            f"The question is that the robot do now proceed to {g}. As many as are of that opinion say Aye. "
            "The Ayes have it, the Ayes have it.",
            f"I call upon the robot to make its way to {g}. The robot has the House's leave to go.",
            f"Honourable members will know the motion before the House: that the robot be instructed to go to "
            f"{g}. The motion is agreed to.",
        ))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            seq = _steps(res, "first, {g}", "next, {g}", "and finally, {g}")
            return ("Order, order. The House will now take the business on the Order Paper in the sequence in "
                    f"which it stands: {seq}. No item may be reached before the item preceding it has been "
                    "disposed of.")
        if k == 1:
            seq = _steps(res, "{g}", "then {g}", "and then {g}")
            return (f"The question is that the robot do visit, strictly in the sequence set down, {seq}. I will "
                    "not permit any item to be taken out of turn. The Ayes have it.")
        seq = _steps(res, "{g}", "{g}", "and {g}")
        return ("The Clerk will read the items in turn. The robot shall attend "
                f"{seq}, each only once the item before it has been dealt with.")
    k = int(rng.integers(3))
    if k == 0:
        return (f"Order, order. The House has before it {_and(res)}. The robot may take these matters in "
                "whatever sequence it pleases; I shall not insist on any sequence at all.")
    if k == 1:
        return (f"The motion is that the robot do attend to {_and(res)}, in no particular sequence, the House "
                "having agreed that it matters not which is taken first. The Ayes have it.")
    return (f"Honourable members have asked that the robot visit {_and(res)}. It may do so in any sequence it "
            "sees fit. The motion is agreed to.")


def _reviewer(rng, res: list[str], order: str) -> str:
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (
            f"Referee's report. Summary: the submission requires the robot to reach {g}. I have no further "
            "comments. Recommendation: accept.",
            f"I thank the authors for an interesting submission. My only request is that the robot locate {g}. "
            "Recommendation: accept with minor revisions.",
            f"Report to the editor. The central claim stands or falls on the robot going to {g}; the "
            "authors should make sure that it does. Recommendation: minor revision.",
        ))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            return ("Referee's report. The authors ask the robot to visit several objects, and I must insist "
                    "that they be visited in precisely the sequence listed, since each point builds on the one "
                    f"before it: {_letters(res)}. A reordered version would not be acceptable. "
                    "Recommendation: major revision.")
        if k == 1:
            seq = _steps(res, "First, the robot should reach {g}.",
                         "Only once that is addressed should it move on to {g}.",
                         "Finally, and only after all of the above, {g}.", sep=" ")
            return f"Major comments. {seq} The sequence here is not negotiable."
        return (f"Summary of required changes, to be made in the order listed and not otherwise: {_letters(res)}. "
                "Each change depends on the one before it. Recommendation: minor revision.")
    k = int(rng.integers(3))
    if k == 0:
        return (f"Referee's report. The robot is asked to locate {_and(res)}. The authors may address these "
                "points in any sequence they prefer; I have no view on which comes first. Recommendation: "
                "minor revision.")
    if k == 1:
        return (f"Minor comments, in no particular priority: {_letters(res)}. These can be tackled in whatever "
                "sequence is convenient.")
    return (f"I would ask the authors to have the robot visit {_and(res)}. The sequence in which this is done is "
            "immaterial to my assessment. Recommendation: accept with minor revisions.")


def _fashion(rng, res: list[str], order: str) -> str:
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (
            f"Darling, listen. The only piece that matters this season is {g}. Go and find it, and do it "
            "fabulously.",
            f"Sweetie, the look is simple: {_cap(g)}. Strut straight over there and own it.",
            f"Darling, everyone who is anyone is going to {g} this season. Be seen there. Ciao!",
        ))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            seq = _steps(res, "opening the show, {g}", "then {g}", "and closing it, {g}")
            return (f"Darling, the running order of this show is fixed: {seq}. Swap a single look and the whole "
                    "collection falls apart.")
        if k == 1:
            seq = _steps(res, "start with {g}", "then {g}", "then {g}", sep=", ")
            return (f"Sweetie, it's all about layering, and layering has rules: {seq}, in exactly that sequence, "
                    "never shuffled.")
        seq = _steps(res, "first, {g}", "after that, {g}", "and last of all, {g}")
        return (f"Darling, the looks go down the catwalk exactly as I list them, one after the other: {seq}. "
                "Nothing out of sequence, ever.")
    k = int(rng.integers(3))
    if k == 0:
        return (f"Darling, this season is all about effortless mix-and-match: {_and(res)}. Wear them in "
                "whatever order you fancy, there are no rules.")
    if k == 1:
        return (f"Sweetie, the capsule collection for today: {_and(res, _pick(rng, ('and', 'plus')))}. The "
                "order is entirely up to you, darling; mood over method.")
    return (f"Darling, you simply must be seen at {_and(res)}. Which comes first? Nobody cares, darling, the "
            "sequence is yours to play with.")


def _comedian(rng, res: list[str], order: str) -> str:
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (
            f"So I've got this robot, right? Lovely thing. And I say to it: go to {g}. And it just looks at "
            "me. Thank you, you've been a great crowd!",
            f"Right, here's one. A robot walks into a house and somebody tells it: find {g}. That's it. That's "
            "the joke. I'm here all week.",
            f"You ever notice how robots never ask why? I told mine to go to {g} and off it went. No questions. "
            "Wish my kids were like that.",
        ))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            seq = _steps(res, "go to {g}", "then {g}", "then {g}", sep=", ")
            return (f"So I've got this robot, right? And I tell it: {seq}. And it has to be in that exact order. "
                    "Not shuffled, not mixed up, that exact order, because apparently I'm that guy now.")
        if k == 1:
            seq = _steps(res, "first up, {g}", "after that, {g}", "and only then, {g}")
            return (f"Here's my robot's to-do list, folks: {seq}. Do them out of order and the whole bit dies. "
                    "Thank you, goodnight!")
        seq = _steps(res, "{g}", "then {g}", "and then {g}", sep=", ")
        return (f"My robot's got a routine, like me: {seq}. Same running order every night, never swapped "
                "around, or the punchline makes no sense.")
    k = int(rng.integers(3))
    if k == 0:
        return (f"So I've got this robot, right? I tell it: go and find {_and(res)}. Which one first? Doesn't "
                "matter! Any order! It's a robot, it has no preferences. Honestly, folks.")
    if k == 1:
        return (f"Here's the thing about my robot: it's got to hit {_and(res)}, and I genuinely do not care what "
                "order it does them in. Surprise me, buddy.")
    return (f"My robot's to-do list tonight: {_and(res)}. In what order? Whatever order it likes, mate, I'm a "
            "comedian, not a project manager.")


_VOICES = (_speaker, _reviewer, _fashion, _comedian)


def render_instruction_an(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (the Speaker of a parliament, an academic
    peer reviewer, a fashion editor, a stand-up comedian). Goals stay in visiting order, each written once as
    rendered; strict texts say the order is fixed ('in the sequence in which it stands', 'strictly in the
    sequence set down', 'not permit any item to be taken out of turn', 'each only once the item before it has
    been dealt with', 'in precisely the sequence listed', 'the sequence here is not negotiable', 'in the order
    listed and not otherwise', 'the running order of this show is fixed', 'in exactly that sequence, never
    shuffled', 'nothing out of sequence', 'it has to be in that exact order', 'do them out of order and the
    whole bit dies', 'same running order every night, never swapped around'); free ones say it is open ('in
    whatever sequence it pleases', 'in no particular sequence', 'in any sequence it sees fit', 'in any sequence
    they prefer', 'in no particular priority', 'immaterial to my assessment', 'in whatever order you fancy',
    'the order is entirely up to you', 'the sequence is yours to play with', 'any order!', 'I genuinely do not
    care what order', 'whatever order it likes'). A single goal gets neither kind of cue and no digit."""
    voice = _VOICES[int(rng.integers(len(_VOICES)))]
    return tidy(voice(rng, list(res), order))
