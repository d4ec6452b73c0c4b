"""Held-out sentence set AI (episode split `unseen_ai`).

Written by a helper that never read any of the project's instruction readers, their word lists or any other held-out
set's wording; the only things in view were set W's four public signatures and docstrings (the interface), the task
types (`types.py`), the shared grammar helpers (`template_text.py`) and how `episodes.py` calls the four functions.

Voices (one per whole instruction):
  * a parcel-depot dispatcher talking a driver through the day's run sheet (drops, manifest, routing, signed for);
  * a lab technician writing a sampling protocol (SOP, steps, sampling points, no deviation from sequence);
  * a birdwatcher on a survey walk (tick list, transect, wish list, log it in the notebook);
  * a dance choreographer blocking a routine (marks, counts of eight, travel pattern, freestyle section).

Style guide. A goal reads as plain household English whoever sends it: 'the' + [room's] + [superlative] +
[hyphenated states] + phrase, then a 'that's ...' clause for states (or the attributes, moved after the noun), the
room ('in', 'over in', 'somewhere in'), the sensor tail, the coordinate hint (x then y, plain numbers) and last the
relations, joined by 'and'; an anchor's own relations go in brackets right after it ('(the one on the rug)'), so
nesting is never in doubt. The room always comes before a superlative tail, which is read inside it. Sensor values
keep their exact value: Celsius may be written in whole Fahrenheit, watts in kilowatts, kilograms under one in grams,
hectopascals as millibars, small whole numbers in words. Strict instructions always say the order is fixed (often
negated: 'no jumping drops', 'never out of sequence'); free ones always say it is open; a single goal says neither
and the framing never uses digits.

Slips: printed `types.READINGS` (the sensor-key tuple types.py re-exports) to learn the ten reading keys; while
looking for the allowed parts, also saw the body of the `subgoals()` strategy and ~35 following lines of
tests/test_phrasings_dev8.py (its wiring and determinism tests) and, in episodes.py, the two-line `_pick` and the
three-line `_rng` helpers; ran the episode generator (no reader) on this split to read its instructions. Nothing of
any reader, lexicon or other set's wording was seen.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.template_text import attributes_and_states, both, hyphenated, listed, number_words, plural
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target


def _pick(rng: np.random.Generator, items):
    return items[int(rng.integers(len(items)))]


def _fmt(v: float) -> str:
    v = float(v)
    return str(int(v)) if v.is_integer() and abs(v) < 1e12 else repr(v)


# ----------------------------------------------------------------------------------------------------
# Goals

REL = {
    "near": ("near", "close to", "not far from", "in the neighbourhood of"),
    "next_to": ("next to", "right next to", "alongside", "immediately next to"),
    "beside": ("beside", "just beside", "at the side of"),
    "by": ("by", "over by", "down by", "standing by"),
    "on": ("on", "on top of", "sitting on", "resting on"),
    "under": ("under", "underneath", "beneath", "tucked under"),
    "above": ("above", "up above", "directly above", "mounted above"),
    "in": ("inside", "in", "stowed inside", "kept in"),
    "with": ("with", "complete with"),
    "in_room_with": ("in the same room as", "in the room with", "sharing a room with", "in whichever room holds"),
    "in_front_of": ("in front of", "just in front of", "right in front of"),
    "behind": ("behind", "round the back of", "tucked behind", "just behind"),
    "opposite": ("opposite", "across from", "facing", "directly opposite"),
    "left_of": ("to the left of", "left of", "on the left-hand side of", "just left of"),
    "right_of": ("to the right of", "on the right-hand side of", "just right of", "off to the right of"),
}


def _rels(rng: np.random.Generator, rels: tuple[Relation, ...]) -> str:
    out = []
    for i, r in enumerate(rels):
        word = _pick(rng, REL.get(r.type, (r.type.replace("_", " "),)))
        glue = "" if i == 0 else _pick(rng, ("and ", "and also "))
        out.append(f"{glue}{word} {_anchor(rng, r.anchor)}")
    return " ".join(out)


def _anchor(rng: np.random.Generator, t: Target) -> str:
    """An anchor: its states hyphenated before the phrase, its own relations in brackets straight after it."""
    _, states = attributes_and_states(t)
    text = "the " + (hyphenated(states) + " " if states else "") + t.phrase
    if t.relations:
        leads = ("the one", "that one") if any(r.type == "with" for r in t.relations) else ("the one", "itself")
        text += f" ({_pick(rng, leads)} {_rels(rng, t.relations)})"
    return text


def render_goal_ai(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AI writes it: 'the teal wool lamp over in the nursery', 'the nursery's lamp that's switched on',
    'the lamp that's teal and wool', 'the warmest lamp somewhere in the pantry', 'the lamp at x 3.5, y 2', 'the lamp in
    the study right next to the sofa (the one on top of the rug) and also behind the desk'. prefix (a superlative
    adjective) goes before the noun, tail (a sensor phrase) after the room; the hint follows; relations come last."""
    t = sg.target
    pre, states = attributes_and_states(t)
    rest = t.phrase[: len(t.phrase) - len(t.head)].strip() if t.phrase.endswith(t.head) else None
    room_style = _pick(rng, ("poss", "in", "in", "over", "somewhere", "found")) if sg.room else ""
    if room_style == "poss" and sg.room.endswith("s"):
        room_style = "in"
    words = ["the"]
    if room_style == "poss":
        words.append(f"{sg.room}'s")
    if prefix:
        words.append(prefix)
    clause = []
    if states and _pick(rng, (True, False)):
        clause = list(states)
    elif states:
        words.append(hyphenated(states))
    if pre and rest == " ".join(pre) and not prefix and int(rng.integers(3)) == 0:
        words.append(t.head)
        clause = list(pre) + clause
    else:
        words.append(t.phrase)
    if clause:
        be = "are" if plural(t.head) else "is"
        lead = _pick(rng, (f"that {be}", f"which {be}", "that's" if be == "is" else "that are"))
        words.append(f"{lead} {_pick(rng, ('', 'currently ')) if set(clause) <= set(states) else ''}{both(clause)}")
    if clause and room_style in ("somewhere", "found"):  # 'switched off to be found in' reads badly
        room_style = "over"
    if room_style and room_style != "poss":
        words.append({"in": "in the", "over": "over in the", "somewhere": "somewhere in the",
                      "found": "to be found in the"}[room_style] + f" {sg.room}")
    if tail:
        words.append(tail)
    if hint:
        words.append(hint)
    text = " ".join(w for w in words if w)
    if t.relations:
        text += (", " if tail or hint else " ") + _rels(rng, t.relations)
    return " ".join(text.split())


# ----------------------------------------------------------------------------------------------------
# Sensors

NAMES = {"temperature_c": ("temperature", "temperature reading"), "ndvi": ("NDVI", "NDVI reading"),
         "humidity_pct": ("humidity", "relative humidity"), "co2_ppm": ("CO2 level", "carbon dioxide level"),
         "noise_db": ("noise level", "sound level"), "light_lux": ("light level", "illuminance"),
         "battery_pct": ("battery level", "battery charge"), "power_w": ("power draw", "power consumption"),
         "weight_kg": ("weight",), "pressure_hpa": ("air pressure", "barometric pressure")}
ADJ = {("temperature_c", "max"): ("warmest", "hottest"), ("temperature_c", "min"): ("coldest", "coolest"),
       ("humidity_pct", "max"): ("most humid", "dampest"), ("humidity_pct", "min"): ("driest", "least humid"),
       ("noise_db", "max"): ("loudest", "noisiest"), ("noise_db", "min"): ("quietest",),
       ("light_lux", "max"): ("brightest", "best-lit"), ("light_lux", "min"): ("dimmest", "darkest"),
       ("weight_kg", "max"): ("heaviest",), ("power_w", "max"): ("most power-hungry",),
       ("power_w", "min"): ("least power-hungry",)}
SUP_TAIL = {"max": ("with the highest {n}", "whose {n} is the highest of the lot", "with the biggest {n} reading",
                    "reading highest for {n}"),
            "min": ("with the lowest {n}", "whose {n} is the lowest of the lot", "with the smallest {n} reading",
                    "reading lowest for {n}")}
# after '{name}' ('with a temperature ...', 'showing a temperature ...') and after 'is' ('whose temperature is ...')
AFTER_NAME = {"gt": ("above {v}", "over {v}", "higher than {v}", "in excess of {v}"),
              "ge": ("of at least {v}", "of {v} or more", "no lower than {v}", "not below {v}"),
              "lt": ("below {v}", "lower than {v}", "of less than {v}"),
              "le": ("of at most {v}", "of {v} or less", "no higher than {v}", "not above {v}"),
              "approx": ("of about {v}", "of around {v}", "of roughly {v}", "of {v} or thereabouts",
                         "in the region of {v}")}
AFTER_IS = {"gt": ("above {v}", "more than {v}", "over {v}", "higher than {v}"),
            "ge": ("at least {v}", "{v} or more", "not below {v}", "no less than {v}"),
            "lt": ("below {v}", "less than {v}", "lower than {v}"),
            "le": ("at most {v}", "{v} or less", "not above {v}", "no more than {v}"),
            "approx": ("about {v}", "around {v}", "roughly {v}", "{v} or thereabouts")}


def _value(rng: np.random.Generator, reading: str, v: float) -> tuple[str, str]:
    """(the value with its unit as written, the unit key); the number is always exactly v in the unit written."""
    n = _fmt(v)
    words = float(v).is_integer() and 0 <= v < 1000 and int(rng.integers(4)) == 0
    w = number_words(int(v)) if words else n
    if reading == "temperature_c":
        f = round(v * 9 / 5 + 32)
        if abs((f - 32) * 5 / 9 - v) < 1e-9 and int(rng.integers(4)) == 0:
            return _pick(rng, (f"{f} °F", f"{f} degrees Fahrenheit")), "f"
        if float(v).is_integer() and -1000 < v < 0 and int(rng.integers(3)) == 0:
            return f"{number_words(int(-v))} degrees below zero", "c"
        if words and v > 0:
            return f"{w} degrees Celsius", "c"
        return _pick(rng, (f"{n} °C", f"{n}°C", f"{n} degrees Celsius", f"{n} degrees C")), "c"
    if reading in ("humidity_pct", "battery_pct"):
        return (f"{w} per cent" if words else _pick(rng, (f"{n}%", f"{n} per cent", f"{n} percent"))), "%"
    if reading == "co2_ppm":
        return f"{w} {_pick(rng, ('ppm', 'parts per million'))}", "ppm"
    if reading == "noise_db":
        return f"{w} {_pick(rng, ('dB', 'decibels'))}", "db"
    if reading == "light_lux":
        return f"{w} lux", "lux"
    if reading == "power_w":
        k = round(v / 1000, 3)
        if v >= 1000 and abs(k * 1000 - v) < 1e-9 and _pick(rng, (True, False)):
            return f"{_fmt(k)} {_pick(rng, ('kW', 'kilowatts'))}", "kw"
        return f"{w} {_pick(rng, ('W', 'watts'))}", "w"
    if reading == "weight_kg":
        g = round(v * 1000)
        if 0 < v < 1 and abs(g / 1000 - v) < 1e-12 and _pick(rng, (True, False)):
            return f"{g} {_pick(rng, ('g', 'grams'))}", "g"
        return f"{w} {_pick(rng, ('kg', 'kilos', 'kilograms'))}", "kg"
    if reading == "pressure_hpa":
        return _pick(rng, ((f"{n} hPa", "hpa"), (f"{n} millibars", "mbar")))
    return n, ""


def render_sensor_ai(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective ('warmest', 'least humid', 'most power-hungry') or a tail ('with the highest NDVI',
    'whose CO2 level is the lowest of the lot'); thresholds after the noun ('with a temperature of at least 20 °C',
    'whose humidity is not above forty per cent', 'showing a power draw in excess of 1.5 kW', 'whose weight is about
    250 grams'). The constraint keeps its canonical value; its unit is the one written."""
    name = _pick(rng, NAMES.get(c.reading, (c.reading.replace("_", " "),)))
    if c.comparator in ("max", "min"):
        adj = ADJ.get((c.reading, c.comparator))
        written = SensorConstraint(c.reading, c.comparator, None, "")
        if adj and _pick(rng, (True, False)):
            return _pick(rng, adj), "", written
        return "", _pick(rng, SUP_TAIL[c.comparator]).format(n=name), written
    val, unit = _value(rng, c.reading, float(c.value))
    art = "an" if name[0].lower() in "aeiou" or name.startswith("NDVI") else "a"
    frame = int(rng.integers(3))
    if frame == 0:
        tail = f"with {art} {name} " + _pick(rng, AFTER_NAME[c.comparator]).format(v=val)
    elif frame == 1:
        tail = f"showing {art} {name} " + _pick(rng, AFTER_NAME[c.comparator]).format(v=val)
    else:
        tail = f"whose {name} is " + _pick(rng, AFTER_IS[c.comparator]).format(v=val)
    return "", tail, SensorConstraint(c.reading, c.comparator, c.value, unit)


def hint_text_ai(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at (3.5, 2)', 'at x 3.5, y 2', 'at the point x = 3.5,
    y = 2', 'with coordinates x 3.5 and y 2', 'at 3.5 m along x and 2 m along y'."""
    return _pick(rng, (f"at ({x}, {y})", f"at x {x}, y {y}", f"at the point x = {x}, y = {y}",
                       f"with coordinates x {x} and y {y}", f"at {x} m along x and {y} m along y"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _seq(rng: np.random.Generator, res: list[str], first: tuple, mids: tuple, last: tuple) -> str:
    """Goals in a fixed running order: 'first A, then B and finally C' (semicolons where a goal has commas)."""
    sep = "; " if any("," in r for r in res) else ", "
    out = f"{_pick(rng, first)} {res[0]}"
    for r in res[1:-1]:
        out += f"{sep}{_pick(rng, mids)} {r}"
    return out + f"{sep}{_pick(rng, last)} {res[-1]}"


def _list(rng: np.random.Generator, res: list[str]) -> str:
    """Goals with no order: the shared layout, but semicolons wherever a goal has an 'and' of its own."""
    if any(" and " in r or "," in r for r in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return listed(rng, res)


def _numbered(res: list[str], word: str, verb: str = "") -> str:
    return " ".join(f"{word} {number_words(i + 1)}: {verb}{r}." for i, r in enumerate(res))


def _courier(rng: np.random.Generator, res: list[str], order: str) -> str:
    n, g = len(res), res[0]
    if n == 1:
        return _pick(rng, (f"Depot to robot: single drop on your sheet today, {g}. Get it signed for and head back.",
                           f"Just the one job on the manifest: a collection from {g}. Scan it and you're done.",
                           f"One parcel, one address: {g}. Don't you dare leave a card."))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            run = _seq(rng, res, ("first", "start with"), ("then", "next"), ("and last of all", "and finish with"))
            return f"Run sheet's loaded in delivery order: {run}. Work it top to bottom, no jumping drops."
        if k == 1:
            return f"{_numbered(res, 'Drop')} Keep to the drop numbers; the customers are expecting you in that order."
        run = _seq(rng, res, ("kick off at",), ("after that",), ("and wrap up at",))
        return f"Route's locked, so don't re-sequence it: {run}."
    got = _list(rng, res)
    return _pick(rng, (f"Drops for today: {got}. Route them however suits you, they're all on the same van.",
                       f"You've got {number_words(n)} drops on the sheet: {got}. Your call on the routing, no set "
                       "sequence.",
                       f"Collections today from {got}. Drop order's entirely up to you."))


def _lab(rng: np.random.Generator, res: list[str], order: str) -> str:
    n, g = len(res), res[0]
    if n == 1:
        return _pick(rng, (f"Sampling protocol: collect a single reading at {g}. Label it and log the time.",
                           f"SOP: position the unit at {g} and hold for the measurement.",
                           f"Please take one sample from {g}; no replicates needed."))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            return (f"Protocol, to be run exactly as written. {_numbered(res, 'Step', 'proceed to ')} Steps are "
                    "sequential: do not begin a step until the previous one is complete.")
        if k == 1:
            run = _seq(rng, res, ("sample",), ("then", "followed by"), ("and finally",))
            return f"Run the following in the order listed, with no deviation from sequence: {run}."
        run = _seq(rng, res, ("begin at",), ("then move to",), ("and end at",))
        return f"Sequence is critical (risk of carry-over otherwise): {run}."
    got = _list(rng, res)
    return _pick(rng, (f"Sampling points, order of collection not critical: {got}.",
                       "Collect from each of the following; sampling order has no bearing on the result, so randomise "
                       f"if you like: {got}.",
                       f"Sites to sample: {got}. Any order is acceptable per the SOP."))


def _birder(rng: np.random.Generator, res: list[str], order: str) -> str:
    n, g = len(res), res[0]
    if n == 1:
        return _pick(rng, (f"Only one on the wish list today: {g}. Approach slowly, no sudden moves.",
                           f"One tick needed, and it's {g}. Sit tight when you get there.",
                           f"Reported sighting: {g}. Go and get it in the notebook, quietly."))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            run = _seq(rng, res, ("start at",), ("then", "on to"), ("and finish at",))
            return (f"Walking the transect, so stick to the route in this exact order: {run}. Don't double back and "
                    "don't skip ahead.")
        if k == 1:
            run = _seq(rng, res, ("",), ("then",), ("then",))
            return f"Today's list, to be ticked top to bottom and never out of sequence: {run}."
        run = _seq(rng, res, ("begin with",), ("carry on to",), ("and end the walk at",))
        return f"Proper survey walk this, so the order's fixed: {run}."
    got = _list(rng, res)
    return _pick(rng, (f"Today's tick list: {got}. Tick them off as they turn up, no set order; birds don't keep "
                       "timetables.",
                       f"Wish list: {got}. Any order's fine, just get them all in the notebook.",
                       f"Hoping for {got}. Whichever you see first, log first."))


def _dancer(rng: np.random.Generator, res: list[str], order: str) -> str:
    n, g = len(res), res[0]
    if n == 1:
        return _pick(rng, (f"From the top! Five, six, seven, eight, and travel to {g}. Hit that mark and hold.",
                           f"One mark in this combination: {g}. Arrive on the count and freeze.",
                           f"Let's keep it simple, darling: just {g}. Land it clean."))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            run = _seq(rng, res, ("on the first eight hit",), ("on the next eight",), ("and on the last eight",))
            return f"The routine is set, so no swapping counts: {run}."
        if k == 1:
            run = _seq(rng, res, ("",), ("then",), ("then",))
            return (f"Travel pattern, exactly as blocked: {run}. Same order every time; swap the steps and it's a "
                    "different dance.")
        run = _seq(rng, res, ("start at",), ("then",), ("finishing on",))
        return f"Mark by mark, in sequence: {run}. Never jump ahead of the count."
    got = _list(rng, res)
    return _pick(rng, (f"This section's freestyle: hit {got}, in any order you feel. Just make sure every mark gets "
                       "hit.",
                       f"Marks to hit: {got}. The order's yours to choreograph.",
                       f"Improv round! Visit {got} in whatever order feels right."))


VOICES = (_courier, _lab, _birder, _dancer)


def render_instruction_ai(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a parcel-depot dispatcher, a lab technician, a
    birdwatcher, a choreographer). Goals stay in visiting order, each written once as rendered; strict texts say the
    order is fixed ('no jumping drops', 'no deviation from sequence', 'never out of sequence', 'no swapping counts'),
    free ones that it is open ('route them however suits you', 'order of collection not critical', 'whichever you see
    first, log first', 'the order's yours to choreograph'). A single goal gets neither kind of cue and no digit."""
    text = _pick(rng, VOICES)(rng, list(res), order)
    return " ".join(text.split())
