"""Held-out sentence set AK: instructions written by four new people, for measuring how the instruction readers
carry over to authors they have never seen.

Written by a helper that never read the project's readers (parser, lexicon, tagger, sensor reader, the LLM adapter or
any other set's wording). It knew only set W's four public signatures and docstrings, the task types, the shared
grammar helpers in template_text.py, and how episodes.py calls the four functions.

Voices (one per whole instruction):
- a film director reading out the day's call sheet / shot list ("SCENE 1: ...", "quiet on set");
- an examiner's question paper ("Q1. ... (4 marks)", "Answer ALL questions", "END OF PAPER");
- a speedrunner talking to their stream chat ("split 1: ...", glitchless vs any%, "GLHF");
- a grandmother's note left on the fridge ("Dear Robot, ... Love, Nan xx").

Style guide:
- A goal is one noun phrase starting with 'the' (or a room's possessive, "the kitchen's ..."), in this order: sensor
  prefix and the target's own attributes before the noun; then the room; then any states ("that is switched on",
  "left open", "(currently empty)"); then the sensor tail (read inside the room); then the coordinate hint; then
  the relations, always last. The head noun is written exactly as given.
- Anchors carry their states before the noun ("the closed king-size shelves"); an anchor's own relations go in
  brackets after it ("(itself near the appliance)"), so a careful reader always knows which noun they belong to.
  Relations of the goal itself are joined by commas and a final 'and'.
- Sensor values are written so that the exact value comes back: digits, whole numbers in words, "and a half", or an
  exact change of unit (kW, grams, millibars, Fahrenheit only where it is exact); the constraint returned keeps the
  canonical value and records the unit as written.
- Coordinate hints always write x then y, and nothing with a digit follows them in the goal.
- Each voice says a fixed order in its own jargon (script order, questions in sequence, glitchless route order, "in
  the order I've written them") and a free order likewise (shooting out of sequence, any order, any% sequence
  breaks, "whichever you fancy first"). A single goal gets neither kind of cue and no digit.

Slips: while checking the project's lint settings and looking up the `subgoals()` strategy, the helper also saw
the ruff section of pyproject.toml, the names of the other top-level functions in tests/test_phrasings_dev8.py
(one grep listing of its `def` lines), and three constant lines of that file (the start of HEADS, and STATES and
ROOMS); a directory listing also showed the file names under ragnav_jax/language and tests. Nothing of any
reader, and nothing of W's bodies or word lists, was seen.
"""

from __future__ import annotations

import dataclasses
from decimal import Decimal

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


def _chance(rng: np.random.Generator, p: float) -> bool:
    return bool(rng.random() < p)


# ---------------------------------------------------------------------------------------------------------------
# Relations

_REL_WORDS = {
    "near": ("near", "close to", "not far from", "in the vicinity of"),
    "next_to": ("next to", "right next to", "alongside"),
    "beside": ("beside", "just beside"),
    "by": ("by", "over by", "down by"),
    "on": ("on", "on top of", "sitting on", "resting on"),
    "under": ("under", "underneath", "beneath"),
    "above": ("above", "up above", "hanging above"),
    "in": ("inside", "tucked inside", "in"),
    "with": ("with", "complete with"),
    "in_room_with": ("in the same room as", "in the room with", "sharing a room with"),
    "in_front_of": ("in front of", "just in front of", "out in front of"),
    "behind": ("behind", "tucked behind", "round the back of"),
    "opposite": ("opposite", "across from", "facing", "directly opposite"),
    "left_of": ("to the left of", "on the left of", "just left of"),
    "right_of": ("to the right of", "on the right-hand side of", "just right of"),
}


def _rel_word(rng, kind: str) -> str:
    return _pick(rng, _REL_WORDS.get(kind, (kind.replace("_", " "),)))


def _anchor(rng, a: Target) -> str:
    """An anchor: states before the noun, its own relations in brackets right after it."""
    pre, states = attributes_and_states(a)
    words = ["the"]
    if states:
        words.append(hyphenated(states))
    words += pre
    words.append(a.head)
    out = " ".join(words)
    if a.relations:
        many = plural(a.head)
        leads = ("themselves", "the ones", "which are") if many else ("itself", "the one", "which is")
        lead = leads[1] if any(r.type == "with" for r in a.relations) else _pick(rng, leads)
        out += " (" + lead + " " + " and ".join(_relation(rng, r) for r in a.relations) + ")"
    return out


def _relation(rng, r: Relation) -> str:
    return _rel_word(rng, r.type) + " " + _anchor(rng, r.anchor)


# ---------------------------------------------------------------------------------------------------------------
# Goals


def render_goal_ak(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AK writes it: 'the teal wool lamp in the nursery', "the nursery's warmest lamp", 'the lamp
    (currently switched on) over in the nursery', 'the lamp that is teal and wool', 'the drums left open',
    'the lamp in the nursery whose temperature is at least 40 °C, at x = 3.5, y = 2', 'the lamp next to the
    credenza (itself complete with the record player) and under the shelves'.

    The sensor prefix goes before the noun and the target's own attributes; the room comes before the states, the
    sensor tail (so a superlative is read inside the room), the hint and the relations; the coordinate hint comes
    after any number of the sensor tail; the relations come last. The head noun is written exactly as given."""
    t = sg.target
    pre, states = attributes_and_states(t)
    many = plural(t.head)
    be = is_are(t.head)
    room = sg.room
    prefix = prefix.strip()
    tail = tail.strip()
    hint = hint.strip()

    # the noun phrase itself, with the room as a possessive now and then
    possessive = bool(room) and not room.endswith("s") and _chance(rng, 0.25)
    state_mode = _pick(rng, ("pre", "that", "left", "bracket")) if states else ""
    if state_mode == "pre" and prefix:
        state_mode = "that"
    attrs_after = bool(pre) and not states and not prefix and not possessive and _chance(rng, 0.3)
    words = [f"the {room}'s" if possessive else "the"]
    if prefix:
        words.append(prefix)
    if state_mode == "pre":
        words.append(hyphenated(states))
    if not attrs_after:
        words += pre
    words.append(t.head)
    out = " ".join(words)

    if state_mode == "bracket":
        out += " (" + _pick(rng, ("currently", "at the moment", "presently")) + " " + both(states) + ")"
    if room and not possessive:
        out += " " + _pick(rng, ("in", "in", "over in", "down in", "found in")) + f" the {room}"
    clause = False  # whether a relative clause or tail now ends the phrase
    if attrs_after:
        out += f" that {be} " + both(pre)
        clause = True
    if state_mode == "left":
        out += " " + _pick(rng, ("left", "that has been left" if not many else "that have been left")) + " "
        out += both(states)
        clause = True
    if state_mode == "that":
        out += " " + _pick(rng, (f"that {be}", f"which {be}")) + " " + both(states)
        clause = True
    if tail:
        out += (", " if clause else " ") + tail
        clause = True
    if hint:
        out += (", " if clause else " ") + hint
        clause = True
    if t.relations:
        rels = [_relation(rng, r) for r in t.relations]
        joined = rels[0] if len(rels) == 1 else ", ".join(rels[:-1]) + " and " + rels[-1]
        bare = any(r.type == "with" for r in t.relations)
        if clause:
            out += ", " + ("" if bare else _pick(rng, ("", "and " + ("they are " if many else "it is "))))
        else:
            out += " " + ("" if bare else _pick(rng, ("", "", f"that {be} ", f"which {be} ")))
        out += joined
    return tidy(out)


# ---------------------------------------------------------------------------------------------------------------
# Sensor phrases

_NOUNS = {
    "temperature_c": ("temperature", "temperature", "temp"),
    "ndvi": ("NDVI", "NDVI reading", "NDVI score"),
    "humidity_pct": ("humidity", "relative humidity"),
    "co2_ppm": ("carbon dioxide level", "CO₂ level", "CO₂ concentration"),
    "noise_db": ("noise level", "sound level"),
    "light_lux": ("light level", "illuminance"),
    "battery_pct": ("battery level", "battery charge"),
    "power_w": ("power draw", "power consumption", "wattage"),
    "weight_kg": ("weight", "mass"),
    "pressure_hpa": ("air pressure", "barometric pressure"),
}
_ADJ_MAX = {"temperature_c": ("warmest", "hottest"), "humidity_pct": ("most humid", "dampest"),
            "noise_db": ("loudest", "noisiest"), "light_lux": ("brightest", "best-lit"),
            "weight_kg": ("heaviest",), "power_w": ("most power-hungry",)}
_ADJ_MIN = {"temperature_c": ("coldest", "coolest", "chilliest"), "humidity_pct": ("driest", "least humid"),
            "noise_db": ("quietest",), "light_lux": ("dimmest",), "power_w": ("least power-hungry",)}
_TAIL_MAX = {"co2_ppm": ("with the most carbon dioxide in the air",), "battery_pct": ("with the most charge left",),
             "power_w": ("drawing the most power",), "weight_kg": ("weighing the most",)}
_TAIL_MIN = {"co2_ppm": ("with the least carbon dioxide in the air",), "battery_pct": ("with the least charge left",),
             "power_w": ("drawing the least power",), "weight_kg": ("weighing the least",)}
# comparative adjectives for threshold phrases: reading -> (more, less)
_COMPARATIVE = {"temperature_c": (("warmer", "hotter"), ("colder", "cooler")), "noise_db": (("louder",), ("quieter",)),
                "weight_kg": (("heavier",), ("lighter",)), "light_lux": (("brighter",), ("dimmer",)),
                "humidity_pct": (("more humid",), ("drier",))}
_CMP = {
    "gt": ("above {v}", "over {v}", "more than {v}", "higher than {v}", "greater than {v}", "in excess of {v}"),
    "ge": ("at least {v}", "{v} or more", "{v} or higher", "no less than {v}", "not below {v}"),
    "lt": ("below {v}", "under {v}", "less than {v}", "lower than {v}"),
    "le": ("at most {v}", "{v} or less", "{v} or lower", "no more than {v}", "not above {v}"),
    "approx": ("about {v}", "around {v}", "roughly {v}", "{v} or thereabouts", "in the region of {v}"),
}
# phrases that read naturally after "a temperature of ..."
_TAKES_OF = ("at ", "{v}", "no ", "about", "around", "roughly", "more than", "less than", "over", "under")


def _plain(v: float) -> str:
    """The shortest decimal text that reads back as exactly v: 40.0 -> '40', 0.65 -> '0.65'."""
    v = float(v)
    if v == int(v) and abs(v) < 1e15:
        return str(int(v))
    s = repr(v)
    if "e" in s or "E" in s:
        s = np.format_float_positional(v, trim="-")
    return s


def _dec_text(d: Decimal) -> str:
    s = format(d.normalize(), "f")
    return s if "." not in s else s.rstrip("0").rstrip(".")


def _scaled(v: float, factor: Decimal, up: bool) -> str | None:
    """v in another unit (multiplied or divided by factor) when that is exact both ways, else None."""
    d = Decimal(_plain(v))
    w = d * factor if up else d / factor
    s = _dec_text(w)
    back = float(s) / float(factor) if up else float(s) * float(factor)
    if back != v or len(s.replace("-", "").replace(".", "")) > 8:
        return None
    return s


def _fahrenheit(v: float) -> str | None:
    d = Decimal(_plain(v))
    f = d * 9 / 5 + 32
    s = _dec_text(f)
    if "." in s and len(s.split(".")[1]) > 1:
        return None
    x = float(s)
    if (x - 32) * 5 / 9 != v or (x - 32) / 1.8 != v:
        return None
    return s


def _count(rng, v: float) -> tuple[str, bool]:
    """(a number as digits, in words (whole numbers up to a hundred) or as 'N and a half'; whether it is spelt)."""
    if v == int(v) and 0 <= v <= 100 and _chance(rng, 0.25):
        return number_words(int(v)), True
    if 0 < v < 100 and v - int(v) == 0.5 and _chance(rng, 0.3):
        return f"{int(v)} and a half", True
    return _plain(v), False


def _value(rng, c: SensorConstraint) -> tuple[str, str]:
    """(the value with its unit as written, the unit's short name)."""
    v = float(c.value)
    r = c.reading
    if r == "temperature_c":
        f = _fahrenheit(v)
        if f is not None and _chance(rng, 0.2):
            return _pick(rng, (f"{f} °F", f"{f} degrees Fahrenheit")), "f"
        if v < 0 and c.comparator == "approx" and _chance(rng, 0.4):
            return f"{_plain(-v)} degrees below zero", "c"
        n, spelt = _count(rng, v)
        if spelt:
            return _pick(rng, (f"{n} degrees", f"{n} degrees Celsius")), "c"
        return _pick(rng, (f"{n} °C", f"{n}°C", f"{n} degrees", f"{n} degrees Celsius")), "c"
    if r == "ndvi":
        return _plain(v), ""
    if r in ("humidity_pct", "battery_pct"):
        n, spelt = _count(rng, v)
        if spelt:
            return _pick(rng, (f"{n} per cent", f"{n} percent")), "%"
        return _pick(rng, (f"{n}%", f"{n} per cent", f"{n} percent")), "%"
    if r == "co2_ppm":
        return _pick(rng, (f"{_plain(v)} ppm", f"{_plain(v)} parts per million")), "ppm"
    if r == "noise_db":
        return _pick(rng, (f"{_plain(v)} dB", f"{_plain(v)} decibels")), "db"
    if r == "light_lux":
        return _pick(rng, (f"{_plain(v)} lux", f"{_plain(v)} lx")), "lux"
    if r == "power_w":
        kw = _scaled(v, Decimal(1000), up=False)
        if kw is not None and abs(v) >= 100 and _chance(rng, 0.4):
            return _pick(rng, (f"{kw} kW", f"{kw} kilowatts")), "kw"
        return _pick(rng, (f"{_plain(v)} W", f"{_plain(v)} watts")), "w"
    if r == "weight_kg":
        g = _scaled(v, Decimal(1000), up=True)
        if g is not None and 0 < abs(v) < 1 and _chance(rng, 0.5):
            return _pick(rng, (f"{g} g", f"{g} grams")), "g"
        return _pick(rng, (f"{_plain(v)} kg", f"{_plain(v)} kilos", f"{_plain(v)} kilograms")), "kg"
    if r == "pressure_hpa":
        if _chance(rng, 0.3):
            return _pick(rng, (f"{_plain(v)} millibars", f"{_plain(v)} mbar")), "mbar"
        return _pick(rng, (f"{_plain(v)} hPa", f"{_plain(v)} hectopascals")), "hpa"
    return _plain(v), c.unit


def render_sensor_ak(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('warmest', 'most humid', 'quietest', 'most power-hungry') or a tail
    ('with the highest NDVI', 'whose air pressure is the lowest', 'with the least charge left'); thresholds after
    the noun ('whose temperature is at least 40 °C', 'with a humidity of forty per cent or less', 'where the NDVI
    reads about 0.65', 'colder than 22 and a half degrees', 'with a power draw in excess of 1.5 kW'). The
    value keeps its exact amount (a change of unit is exact: kW, grams, millibars, Fahrenheit); the returned
    constraint keeps the canonical value and records the unit as written ('c', 'f', '%', 'kw', 'g', ...)."""
    r = c.reading
    noun = _pick(rng, _NOUNS.get(r, (r.replace("_", " "),)))
    if c.comparator in ("max", "min"):
        hi = c.comparator == "max"
        adjs = (_ADJ_MAX if hi else _ADJ_MIN).get(r, ())
        if adjs and _chance(rng, 0.5):
            return _pick(rng, adjs), "", c
        most = "highest" if hi else "lowest"
        tails = [f"with the {most} {noun}", f"whose {noun} is the {most}", f"with the {most} {noun} of them all",
                 f"boasting the {most} {noun}"]
        tails += list((_TAIL_MAX if hi else _TAIL_MIN).get(r, ()))
        return "", _pick(rng, tails), c
    if c.value is None:  # a threshold with no number cannot be written; say the reading only
        return "", f"with a {noun} reading", c
    cmp_text = _pick(rng, _CMP.get(c.comparator, ("{v}",)))
    val, unit = _value(rng, c)
    written = dataclasses.replace(c, unit=unit)
    comps = _COMPARATIVE.get(r)
    if comps and c.comparator in ("gt", "lt") and _chance(rng, 0.3):
        adj = _pick(rng, comps[0] if c.comparator == "gt" else comps[1])
        return "", f"{adj} than {val}", written
    phrase = cmp_text.format(v=val)
    frames = [f"whose {noun} is {phrase}", f"where the {noun} reads {phrase}"]
    a = "an" if noun[0] in "aeiouAEIOU" or noun.startswith("NDVI") else "a"
    if cmp_text.startswith(_TAKES_OF):
        frames.append(f"with {a} {noun} of {phrase}")
    else:
        frames.append(f"with {a} {noun} {phrase}")
    if cmp_text.startswith("not "):
        frames = [f for f in frames if "reads" not in f]
    return "", _pick(rng, frames), written


# ---------------------------------------------------------------------------------------------------------------
# Coordinate hints


def hint_text_ak(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at (3.5, 2)', 'at x = 3.5, y = 2', 'at map
    position (3.5 m, 2 m)', 'at the coordinates x 3.5, y 2', 'at grid point x:3.5 y:2', 'sitting 3.5 m along x and
    2 m along y'. The two numbers are written exactly as given."""
    return _pick(rng, (
        f"at ({x}, {y})",
        f"at x = {x}, y = {y}",
        f"at map position ({x} m, {y} m)",
        f"at the coordinates x {x}, y {y}",
        f"at grid point x:{x} y:{y}",
        f"sitting {x} m along x and {y} m along y",
        f"marked on the plan at x={x} / y={y}",
    ))


# ---------------------------------------------------------------------------------------------------------------
# Whole instructions


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _director(rng, res: list[str], order: str) -> str:
    moves = ("the robot crosses to {g}", "the robot makes its way over to {g}", "we track the robot across to {g}",
             "the robot arrives at {g}", "in a hero shot, the robot reaches {g}")
    if len(res) == 1:
        g = _pick(rng, moves).format(g=res[0])
        return _pick(rng, (
            f"Just the one set-up on today's call sheet: {g}. Quiet on set... and action!",
            f"CALL SHEET, ROBOT UNIT. A single shot today: {g}. Get it and that's a wrap.",
            f"Right, everyone, a one-shot day. {_cap(g)}. Lovely. Action when you're ready.",
        ))
    head = _pick(rng, ("CALL SHEET, ROBOT UNIT.", "Right, everyone, here's today's shot list.",
                       "SHOOTING SCHEDULE, ROBOT UNIT:"))
    label = _pick(rng, ("SCENE {i}: ", "Sc. {i} — ", "Shot {i}: ", "Setup {i}: "))
    items = " ".join(label.format(i=i + 1) + _cap(_pick(rng, moves).format(g=g)) + "." for i, g in enumerate(res))
    if order == "strict":
        cue = _pick(rng, (
            "We shoot in script order today: no scene gets turned over until the one ahead of it is done.",
            "Continuity is everything on this one, so we go strictly in sequence, top to bottom.",
            "Shooting order is story order. Nobody jumps ahead.",
        ))
    else:
        cue = _pick(rng, (
            "We're shooting out of sequence today, so take these in whatever order suits; it all gets cut together"
            " in the edit.",
            "Shooting order is entirely flexible on this one; the editor will put it right in post.",
            "No running order today: pick them off in any order that suits the crew.",
        ))
    end = _pick(rng, ("Quiet on set, please.", "Let's make some movies, people.", "And... action!"))
    if _chance(rng, 0.5):
        return f"{head} {cue} {items} {end}"
    return f"{head} {items} {cue} {end}"


def _examiner(rng, res: list[str], order: str) -> str:
    verbs = ("Navigate to", "Make your way to", "Locate and drive to", "Go to", "Reach")
    if len(res) == 1:
        g = _pick(rng, verbs) + " " + res[0]
        return _pick(rng, (
            f"PRACTICAL NAVIGATION, PAPER ONE. This paper contains a single compulsory question. {g}. "
            "(Ten marks.) END OF PAPER.",
            f"EXAMINATION IN PRACTICAL NAVIGATION. Do not turn over until told to do so. Answer the question below. "
            f"{g}. Pens down when you have finished.",
            f"There is only one question on this paper. {g}. END OF PAPER.",
        ))
    head = _pick(rng, ("PRACTICAL NAVIGATION, PAPER ONE. Time allowed: as long as it takes.",
                       "EXAMINATION IN PRACTICAL NAVIGATION. Do not turn over until told to do so.",
                       "ROBOT NAVIGATION: END-OF-TERM EXAMINATION."))
    if order == "strict":
        cue = _pick(rng, (
            "INSTRUCTIONS TO CANDIDATES: answer ALL questions, in the order in which they are set; do not begin a"
            " question until the one before it is complete.",
            "INSTRUCTIONS TO CANDIDATES: questions must be attempted strictly in sequence.",
            "Candidates must work through the questions in the order printed, each one only after the one above it.",
        ))
    else:
        cue = _pick(rng, (
            "INSTRUCTIONS TO CANDIDATES: answer ALL questions; they may be attempted in any order.",
            "INSTRUCTIONS TO CANDIDATES: candidates may answer the questions in whichever order they prefer.",
            "Answer ALL questions. The order in which you attempt them is left entirely to you.",
        ))
    style = _pick(rng, ("q", "question", "letter"))
    items = []
    for i, g in enumerate(res):
        v = _pick(rng, verbs)
        if style == "q":
            items.append(f"Q{i + 1}. {v} {g}. ({int(rng.integers(2, 9))} marks)")
        elif style == "question":
            items.append(f"Question {i + 1}: {v} {g}.")
        else:
            items.append(f"({'abcdefghijklmnopqrstuvwxyz'[i % 26]}) {v} {g}.")
    end = _pick(rng, ("END OF PAPER.", "Check your answers before handing in.", "Pens down when you have finished."))
    return f"{head} {cue} {' '.join(items)} {end}"


def _speedrunner(rng, res: list[str], order: str) -> str:
    verbs = ("touch", "hit", "get to", "tag")
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (
            f"ok chat, single-segment category today, just the one split: {_pick(rng, verbs)} {g}. timer starts now.",
            f"one-split run, chat. {_pick(rng, verbs)} {g}. that's the timer stopped. GLHF.",
            f"alright chat, short one: {_pick(rng, verbs)} {g}, that's the whole run. let's go.",
        ))
    head = _pick(rng, ("ok chat, route for this run:", "alright chat, here's today's route:", "RUN PLAN, chat:"))
    label = _pick(rng, ("split {i}: ", "S{i} — ", "split {i} → "))
    items = " | ".join(label.format(i=i + 1) + _pick(rng, verbs) + " " + g for i, g in enumerate(res))
    if order == "strict":
        cue = _pick(rng, (
            "category is glitchless, route order, no sequence breaks: take a split out of order and it's a reset.",
            "splits go in route order, each one after the last, or I reset.",
            "fixed route, no skips, every split in order.",
        ))
    else:
        cue = _pick(rng, (
            "category is any%, sequence breaks allowed, so grab the splits in whatever order is fastest.",
            "open route this time, the splits can go in any order.",
            "no fixed route on this one, take the splits however you like.",
        ))
    end = _pick(rng, ("GLHF.", "let's get a PB.", "timer starts now."))
    if _chance(rng, 0.5):
        return f"{head} {items}. {cue} {end}"
    return f"{head} {cue} {items}. {end}"


def _after(head: str, text: str) -> str:
    """Text that follows a letter's greeting: a capital after '!' or '.', as it was after a comma."""
    return _cap(text) if head.endswith(("!", ".")) else text


def _nan(rng, res: list[str], order: str) -> str:
    verbs = ("pop over to", "nip over to", "go and find", "call in at")
    head = _pick(rng, ("Dear Robot,", "Morning, pet!", "Robot love,"))
    end = _pick(rng, ("Love, Nan xx", "Thank you, dear. Nan x", "Ta-ra, love Nan"))
    if len(res) == 1:
        return f"{head} {_after(head, 'just')} the one little job today: could you {_pick(rng, verbs)} {res[0]}? {end}"
    intro = _pick(rng, ("a few little jobs while I'm out:", "could you do these for your old Nan:",
                        "here's what wants doing today:"))
    if order == "strict":
        n = len(res)
        parts = []
        for i, g in enumerate(res):
            v = _pick(rng, verbs)
            if i == 0:
                parts.append(f"first {v} {g}")
            elif i == n - 1:
                parts.append(_pick(rng, ("and last of all", "and then finally")) + f" {v} {g}")
            else:
                parts.append(_pick(rng, ("then", "after that", "then after that")) + f" {v} {g}")
        items = "; ".join(parts) + "."
        cue = _pick(rng, ("Do them in the order I've written them, there's a love, or I'll get in a muddle.",
                          "One after the other, in this order, mind.",
                          "Please keep to that order, pet, each one only when the one before it's done."))
    else:
        if _chance(rng, 0.5):
            items = " ".join(f"• {_pick(rng, verbs)} {g}" for g in res) + "."
        else:
            items = "could you " + "; ".join(f"{_pick(rng, verbs)} {g}" for g in res) + "."
        cue = _pick(rng, ("I don't mind what order you do them in, dear.",
                          "Whichever you fancy first, pet, it all gets done in the end.",
                          "Any order will do, I'm not fussy."))
    if _chance(rng, 0.5):
        return f"{head} {_after(head, intro)} {items} {cue} {end}"
    if head.endswith(",") and not cue.startswith("I "):
        cue = cue[:1].lower() + cue[1:]
    return f"{head} {cue} {_cap(intro)} {items} {end}"


_VOICES = (_director, _examiner, _speedrunner, _nan)


def render_instruction_ak(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a film director reading the call sheet, an
    examiner's question paper, a speedrunner talking to chat, a grandmother's note on the fridge). Goals stay in
    visiting order, each written once as rendered; strict texts say the order is fixed ('we shoot in script
    order', 'strictly in sequence', 'story order', 'in the order in which they are set', 'each one only after the
    one above it', 'glitchless, route order, no sequence breaks', 'every split in order', 'in the order I've
    written them', 'first ... then ... last of all'), free ones say it is open ('shooting out of sequence', 'in
    any order that suits the crew', 'may be attempted in any order', 'left entirely to you', 'any%, sequence
    breaks allowed', 'the splits can go in any order', 'whichever you fancy first', 'any order will do'). A single
    goal gets neither kind of cue and no digit."""
    voice = _pick(rng, _VOICES)
    return tidy(voice(rng, list(res), order))
