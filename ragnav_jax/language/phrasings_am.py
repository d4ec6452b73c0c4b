"""Held-out phrasings of set AM: goal, sensor, coordinate and instruction templates for the `unseen_am` split.

Written by a helper that never read the instruction readers (not the parser, lexicon, tagger, sensor reader,
grounding, LLM adapter, nor any other template set's bodies), before any reader was run on these sentences. It saw
only the signatures and docstrings of set W's four public functions, `types.py`, `template_text.py`, the split
wiring (`UNSEEN_TEMPLATES`, `_renderer`, `EPISODE_SPLITS`), `tests/test_heldout_sets.py` and the `subgoals()`
test strategy. Same four functions, arguments and meanings as set W.

Voices (one per whole instruction, drawn from the generator):

- a scuba dive-master giving a pre-dive briefing: waypoints, "dive the plan", buddy pairs, slates, the ascent;
- a newspaper horoscope columnist: a star sign, planets, the cosmos, Mercury going retrograde;
- a Victorian telegram: clipped clauses separated by "STOP", "thence", "kindly", "regards";
- a rock band's tour manager reading out the itinerary: dates, load-in, the bus, the poster, routing.

Style guide.

- A goal is one noun phrase beginning with "the", whose head noun is written exactly as given. Attributes stand
  before the head in the phrase's own order or, now and then, in a bracket after it ("(the teal wool one)").
  States stand before the head hyphenated, in a bracket "(currently open)", or as an apposition between commas
  (", left open,"). The room is either a possessive before everything ("the nursery's hottest lamp") or follows
  the head ("in the nursery"); when a threshold tail is present the room comes after the tail, set off by a comma,
  and with a superlative tail the room is always possessive, so the superlative is read inside the room. A
  coordinate hint comes after any sensor tail (so its two numbers are the last two in the goal) and relations
  come last, each anchor a "the" phrase; an anchor's own relations sit in a bracket ("(itself on the drums)",
  "(which is on the drums)") so nobody can wonder which noun they belong to.
- Sensor values come back exactly: digits ("40", "-2.5", "−4", "1,200"), "minus 4", number words
  ("forty", "minus eighteen", "thirty-seven and a half"), "37½", NDVI as "0.65", ".65" or "zero point six five";
  a temperature that is a whole multiple of five degrees Celsius may be written in Fahrenheit (exactly converted,
  unit "f"), whole kilowatts in steps of a hundred watts as kW (unit "kw"). Units are always written for
  temperature (°C or °F), percent readings, ppm, dB, lux, W, kg and hPa; NDVI takes none.
- Coordinate hints name x and y and always give x then y.
- Fixed order, in each voice's jargon: "dive the plan ... in sequence", "no freelancing", "the order briefed", "not
  a fin-kick sooner"; "strict procession", "out of turn", "the heavens have already put your week in order", "the
  order is written in the sky"; "in sequence as wired", "in order given", "none ahead of its turn", "sequence
  essential"; "in the order they're booked", "running order", "only then", "same order as the poster". Free order:
  "in whatever sequence your air ... agree on", "no set order", "doesn't matter a jot"; "care not a jot", "however
  you please", "no sequence this time", "any order"; "any order convenient", "order of calls your own affair", "no
  preference as to order"; "no fixed routing", "routing's your call", "doesn't care which". A single goal gets
  neither kind of cue and no digit in the words around it.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.

Slips: while locating the allowed parts I also saw the directory listings of `ragnav_jax/language/` and `tests/`
(file names only), the `[tool.ruff]` section and the dev-dependency line of `pyproject.toml`, line 213 of
`config.py` (a `_check` on the split, shown by grep), the lines just after `_renderer` in `episodes.py` (the `_rng`
helper and the `_one_episode` signature), and, from a grep of `tests/test_phrasings_dev8.py`, the names of its
other constants and tests and the first line of its strict/free cue regexes. I printed `types.READINGS` (the tuple
of reading keys) to know which readings to word; `readings.py` itself was not opened. `template_text.listed`
imports `_pick` from `episodes.py`; I did not read `_pick` and use my own draw instead. While writing, I broke the
module on purpose twice (a wrong Fahrenheit offset; an order word in a single-goal text) to see the tests fail,
then restored it.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.template_text import (
    ONES,
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


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


# ------------------------------------------------------------------------------------------------ goals

_REL = {
    "near": ("near", "not far from", "a short hop from", "within a few paces of", "close by"),
    "next_to": ("next to", "right next to", "immediately alongside", "side by side with"),
    "beside": ("beside", "just beside", "at the side of"),
    "by": ("by", "right by", "down by"),
    "on": ("on", "sitting on top of", "balanced on", "standing on"),
    "under": ("under", "underneath", "down beneath", "below"),
    "above": ("above", "directly above", "high above"),
    "in": ("inside", "in", "kept inside", "tucked into"),
    "with": ("with", "together with", "accompanied by", "paired with"),
    "in_room_with": ("in the same room as", "in one and the same room as", "rooming with"),
    "in_front_of": ("in front of", "directly in front of", "out in front of"),
    "behind": ("behind", "round the back of", "tucked behind", "at the rear of"),
    "opposite": ("opposite", "across from", "facing", "directly across the room from"),
    "left_of": ("to the left of", "on the left of", "left of"),
    "right_of": ("to the right of", "on the right of", "right of"),
}
_STATE_LEADS = ("currently", "left", "presently")


def _rel_words(rng, kind: str) -> str:
    return _pick(rng, _REL.get(kind, (kind.replace("_", " "),)))


def _anchor(rng, t: Target, nested: bool = False) -> str:
    """An anchor: 'the open teal toolbox', 'the toolbox (currently open)', 'the sofa (itself on the drums)'. Inside
    another anchor's bracket (nested) states always stand before the noun, so brackets never nest."""
    pre, states = attributes_and_states(t)
    own = t.relations
    bracket_state = bool(states) and not own and not nested and rng.random() < 0.4
    words = ([] if bracket_state or not states else [hyphenated(states)]) + pre + [t.head]
    out = "the " + " ".join(words)
    if bracket_state:
        out += f" ({_pick(rng, _STATE_LEADS)} {both(states)})"
    if own:
        inner = " and ".join(f"{_rel_words(rng, r.type)} {_anchor(rng, r.anchor, True)}" for r in own)
        form = int(rng.integers(3))
        if form == 0:
            out += f" ({'themselves' if plural(t.head) else 'itself'} {inner})"
        elif form == 1:
            out += f" (which {is_are(t.head)} {inner})"
        else:
            out += f" (the {'ones' if plural(t.head) else 'one'} {inner})"
    return out


def _relations(rng, rels: tuple[Relation, ...]) -> str:
    parts = [f"{_rel_words(rng, r.type)} {_anchor(rng, r.anchor)}" for r in rels]
    if len(parts) == 1:
        return parts[0]
    if len(parts) == 2:
        return _pick(rng, (f"{parts[0]} and {parts[1]}", f"{parts[0]}, and also {parts[1]}",
                           f"both {parts[0]} and {parts[1]}"))
    return ", ".join(parts[:-1]) + ", and " + parts[-1]


def render_goal_am(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AM writes it: 'the nursery's hottest teal lamp', 'the lamp (the teal wool one) in the
    nursery', 'the switched-on lamp whose temperature is above 40 °C, in the kitchen', 'the lamp, left open, at
    x = 3.5, y = 2, right next to the sofa (itself on the drums)'. A superlative tail is always read inside a
    possessive room; a threshold tail precedes the room; a coordinate hint follows any sensor tail; relations
    come last."""
    t = sg.target
    pre, states = attributes_and_states(t)
    sup = bool(tail) and any(c.is_superlative for c in sg.sensors)
    room = sg.room
    possessive = bool(room) and (sup or rng.random() < 0.3)
    # states: before the head, in a bracket, or as an apposition between commas
    a_after = len(pre) >= 1 and rng.random() < 0.2
    s_mode = _pick(rng, (0, 2) if a_after else (0, 1, 2)) if states else -1
    words: list[str] = []
    if possessive:
        words.append(f"{room}'s")
    if prefix:
        words.append(prefix)
    if s_mode == 0:
        words.append(hyphenated(states))
    if not a_after:
        words += pre
    words.append(t.head)
    out = "the " + " ".join(words)
    if a_after:
        out += f" (the {' '.join(pre)} {'ones' if plural(t.head) else 'one'})"
    if s_mode == 1:
        out += f" ({_pick(rng, _STATE_LEADS)} {both(states)})"
    elif s_mode == 2:
        out += f", {_pick(rng, _STATE_LEADS)} {both(states)},"
    after = False
    if tail:
        out += " " + tail
        after = True
    if room and not possessive:
        if tail:
            out += ", " + _pick(rng, ("in the", "found in the", "over in the")) + f" {room}"
        else:
            out += " " + _pick(rng, ("in the", "in the", "located in the", "over in the")) + f" {room}"
        after = True
    if hint:
        out += (", " if tail and not (room and not possessive) else " ") + hint
        after = True
    if t.relations:
        out += (", " if after or s_mode == 2 else " ") + _relations(rng, t.relations)
    return tidy(out)


# ------------------------------------------------------------------------------------------------ sensors

# reading -> (nouns, highest adjectives, lowest adjectives, "more" comparative, "less" comparative, units)
_READING = {
    "temperature_c": (("temperature",), ("hottest", "warmest"), ("coldest", "coolest", "chilliest"),
                      ("hotter", "warmer"), ("colder", "cooler")),
    "ndvi": (("NDVI", "NDVI reading", "NDVI score"), ("lushest", "most thriving"), ("sickliest", "most sickly"),
             (), ()),
    "humidity_pct": (("humidity", "relative humidity"), ("dampest", "most humid"), ("driest", "least humid"),
                     ("more humid",), ("less humid",)),
    "co2_ppm": (("CO2 level", "carbon dioxide level"), ("stuffiest",), (), (), ()),
    "noise_db": (("noise level", "sound level"), ("loudest", "noisiest"), ("quietest",), ("louder",), ("quieter",)),
    "light_lux": (("light level", "illuminance"), ("brightest", "best-lit"), ("dimmest", "darkest"),
                  ("brighter",), ("dimmer",)),
    "battery_pct": (("battery charge", "battery level"), ("most charged",), ("most drained",), (), ()),
    "power_w": (("power draw", "power consumption"), ("most power-hungry",), ("least power-hungry",), (), ()),
    "weight_kg": (("weight",), ("heaviest",), (), ("heavier",), ("lighter",)),
    "pressure_hpa": (("air pressure", "barometric pressure"), (), (), (), ()),
}
_PLAIN_UNITS = {  # reading -> ((written unit, unit code), ...), '{}' standing for the number
    "humidity_pct": (("{}%", "%"), ("{} per cent", "%"), ("{} percent", "%")),
    "battery_pct": (("{}%", "%"), ("{} per cent", "%"), ("{} percent", "%")),
    "co2_ppm": (("{} ppm", "ppm"), ("{} parts per million", "ppm")),
    "noise_db": (("{} dB", "db"), ("{} decibels", "db")),
    "light_lux": (("{} lux", "lux"),),
    "power_w": (("{} W", "w"), ("{} watts", "w")),
    "weight_kg": (("{} kg", "kg"), ("{} kilograms", "kg"), ("{} kilos", "kg")),
    "pressure_hpa": (("{} hPa", "hpa"), ("{} hectopascals", "hpa")),
}


def _digits(v: float) -> str:
    return str(int(v)) if float(v).is_integer() else repr(float(v))


def _number(rng, v: float, words_ok: bool = True) -> str:
    """v so that it reads back exactly: digits, a minus written three ways, words, halves, thousands commas."""
    forms = ["digits"]
    if words_ok and abs(v) < 1000 and (v * 2).is_integer():
        forms += ["words"]
    if (v * 2).is_integer() and not v.is_integer() and abs(v) >= 1:
        forms += ["half"]
    if v.is_integer() and abs(v) >= 1000:
        forms += ["commas"]
    if 0 < abs(v) < 1 and len(_digits(abs(v))) <= 6:
        forms += ["point"]
    form = _pick(rng, forms)
    neg = v < 0
    a = abs(v)
    if form == "words":
        whole = int(a)
        if a.is_integer():
            body = number_words(whole)
        else:
            body = (number_words(whole) + " and a half") if whole else "a half"
        return ("minus " if neg else "") + body
    if form == "half":
        body = f"{int(a)}½"
    elif form == "commas":
        body = f"{int(a):,}"
    elif form == "point":
        frac = _digits(a).split(".")[1]
        body = _pick(rng, ("zero point ", "point ")) + " ".join(ONES[int(d)] for d in frac)
        return ("minus " if neg else "") + body
    else:
        body = _digits(a)
        if 0 < a < 1 and rng.random() < 0.3:
            body = body[1:]  # '.65'
    if not neg:
        return body
    return _pick(rng, ("-", "minus ", "−")) + body


def _quantity(rng, c: SensorConstraint) -> tuple[str, str]:
    """(the value with its unit as written, the unit code)."""
    v = float(c.value)
    if c.reading == "temperature_c":
        if v.is_integer() and int(v) % 5 == 0 and rng.random() < 0.3:
            f = int(v) * 9 // 5 + 32
            n = _number(rng, float(f))
            return n + (" degrees Fahrenheit" if n[-1].isalpha() else _pick(rng, (" °F", " degrees Fahrenheit"))), "f"
        n = _number(rng, v)
        if n[-1].isalpha():
            return n + " " + _pick(rng, ("degrees Celsius", "degrees C", "Celsius")), "c"
        return n + _pick(rng, (" °C", "°C", " degrees Celsius")), "c"
    if c.reading == "ndvi":
        return _number(rng, v), ""
    if c.reading == "power_w" and v >= 1000 and (v / 100).is_integer() and rng.random() < 0.4:
        return f"{_digits(v / 1000)} kW", "kw"
    units = _PLAIN_UNITS.get(c.reading, (("{}", c.unit),))
    fmt, code = _pick(rng, units)
    n = _number(rng, v)
    if fmt == "{}%" and n[-1].isalpha():
        fmt, code = "{} per cent", "%"
    return fmt.format(n), code


_PRED = {  # after 'is' or 'its temperature'
    "gt": ("above {}", "over {}", "more than {}", "higher than {}", "greater than {}"),
    "ge": ("at least {}", "{} or above", "{} or higher", "no lower than {}", "not below {}"),
    "lt": ("below {}", "under {}", "less than {}", "lower than {}"),
    "le": ("at most {}", "{} or below", "{} or lower", "no higher than {}", "not above {}"),
    "approx": ("about {}", "roughly {}", "around {}", "approximately {}", "{} or so"),
}
_OF = {  # after 'a temperature of'
    "gt": ("over {}", "more than {}"),
    "ge": ("at least {}", "{} or more", "no less than {}"),
    "lt": ("under {}", "less than {}"),
    "le": ("at most {}", "{} or less", "no more than {}"),
    "approx": ("about {}", "roughly {}", "approximately {}", "{} or so"),
}


def _a(noun: str) -> str:
    return ("an " if noun[0].lower() in "aeiou" or noun.startswith("NDVI") else "a ") + noun


def render_sensor_am(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('hottest', 'lushest', 'most humid', 'quietest') or a tail ('with
    the highest temperature', 'whose NDVI is the lowest', 'that beats all the rest for humidity'); thresholds
    after the noun ('whose temperature is above 40 °C', 'with its humidity at most forty per cent', 'with an NDVI
    of about .65', 'that runs hotter than 104 °F', 'registering a humidity of 37½ per cent or more')."""
    nouns, hi, lo, more, less = _READING.get(c.reading, ((c.reading.replace("_", " "),), (), (), (), ()))
    noun = _pick(rng, nouns)
    if c.is_superlative:
        adjs = hi if c.comparator == "max" else lo
        if adjs and rng.random() < 0.5:
            return _pick(rng, adjs), "", SensorConstraint(c.reading, c.comparator, None, "")
        word = "highest" if c.comparator == "max" else "lowest"
        league = "beats all the rest" if word == "highest" else "comes bottom of the lot"
        tail = _pick(rng, (f"with the {word} {noun}", f"whose {noun} is the {word}", f"that {league} for {noun}"))
        return "", tail, SensorConstraint(c.reading, c.comparator, None, "")
    q, unit = _quantity(rng, c)
    cmp = c.comparator
    frames = ["whose", "its", "of", "logging"]
    adjs = more if cmp in ("gt", "ge") else less if cmp in ("lt", "le") else ()
    if cmp in ("ge", "le"):
        adjs = tuple(a for a in adjs if " " not in a)  # '40 °C or hotter', never '40 % or more humid'
    if adjs:
        frames.append("adj")
    frame = _pick(rng, frames)
    if frame == "whose":
        tail = f"whose {noun} is " + _pick(rng, _PRED[cmp]).format(q)
    elif frame == "its":
        tail = f"with its {noun} " + _pick(rng, _PRED[cmp]).format(q)
    elif frame == "of":
        tail = f"with {_a(noun)} of " + _pick(rng, _OF[cmp]).format(q)
    elif frame == "logging":
        tail = f"{_pick(rng, ('logging', 'registering'))} {_a(noun)} of " + _pick(rng, _OF[cmp]).format(q)
    else:
        adj = _pick(rng, adjs)
        verb = "that runs" if c.reading == "temperature_c" else "that is"
        tail = f"{verb} {adj} than {q}" if cmp in ("gt", "lt") else f"{verb} {q} or {adj}"
    return "", tail, SensorConstraint(c.reading, cmp, c.value, unit)


# ------------------------------------------------------------------------------------------------ hints


def hint_text_am(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at x = 3.5, y = 2', 'where the floor plan reads
    x 3.5, y 2', 'some 3.5 m along the x-axis and 2 m along the y-axis', 'pinned on the map at x 3.5 and y 2',
    'at the coordinates x:3.5 / y:2', 'at floor-plan point (x 3.5, y 2)'."""
    return _pick(rng, (
        f"at x = {x}, y = {y}",
        f"where the floor plan reads x {x}, y {y}",
        f"some {x} m along the x-axis and {y} m along the y-axis",
        f"pinned on the map at x {x} and y {y}",
        f"at the coordinates x:{x} / y:{y}",
        f"at floor-plan point (x {x}, y {y})",
    ))


# ------------------------------------------------------------------------------------------------ instructions


def _sep(res: list[str]) -> str:
    return "; " if any("," in r for r in res) else ", "


def _listed(rng, res: list[str]) -> str:
    if len(res) == 2:
        return f"{res[0]} and {res[1]}"
    sep = _sep(res)
    return sep.join(res[:-1]) + sep + "and " + res[-1]


def _n(res: list[str]) -> str:
    return number_words(len(res))


# dive-master


def _dive_strict(rng, res):
    form = int(rng.integers(3))
    if form == 0:
        opener = _pick(rng, ("Right, gather round for the dive briefing.",
                             "Okay team, masks on foreheads and listen up.", "Dive briefing, everyone, slates out."))
        sep = _sep(res)
        mids = [_pick(rng, ("fin across to ", "swim on to ", "work our way over to ")) + g for g in res[1:-1]]
        body = sep.join([f"we drop down to {res[0]}", *mids])
        return (f"{opener} We dive the plan, and the plan runs in sequence, no freelancing down there: {body}{sep}and "
                f"our last stop before the ascent is {res[-1]}. Dive the plan, plan the dive.")
    if form == 1:
        wps = " ".join(f"WP{i}: {_cap(g)}." for i, g in enumerate(res, 1))
        return (f"DIVE PLAN, {_n(res)} waypoints, to be hit in the order briefed (out of sequence is how buddies "
                f"lose each other). {wps} Then a slow ascent with a safety stop.")
    out = f"Buddy pairs: down we go to {res[0]}."
    for g in res[1:-1]:
        out += f" Once everyone has given the okay there, and not a fin-kick sooner, move on to {g}."
    out += (f" Once everyone has given the okay there, and not a fin-kick sooner, we finish at {res[-1]}. Then we "
            "ascend together. Same order for every pair.")
    return out


def _dive_free(rng, res):
    form = int(rng.integers(3))
    if form == 0:
        return (f"No fixed profile today. There are {_n(res)} markers to tag: {_listed(rng, res)}. Tag them in "
                "whatever sequence your air and your buddy agree on, so long as every one is on your slate before "
                "you surface.")
    if form == 1:
        marks = " ".join(f"⟡ {g}" for g in res)
        return (f"Scavenger dive! Markers on the bottom: {marks}. The route between them is entirely your call, "
                "no set order, just don't surface till they're all ticked off.")
    return (f"Fun dive, free navigation: find {_listed(rng, res)}. Which one you reach ahead of the others doesn't "
            "matter a jot to me.")


def _dive_single(rng, g):
    return _pick(rng, (
        f"Easy one today, a single-site dive: drop down to {g}, have a good look, and come back up nice and slow.",
        f"Just the one site on this dive: {g}. Descend, find it, give me the okay sign.",
        f"Short dive, lone objective: {g}. Bubbles up when you've found it.",
    ))


# horoscope columnist

_SIGNS = ("Aries", "Taurus", "Gemini", "Cancer", "Leo", "Virgo", "Libra", "Scorpio", "Sagittarius", "Capricorn",
          "Aquarius", "Pisces")


def _stars_strict(rng, res):
    sign = _pick(rng, _SIGNS)
    form = int(rng.integers(3))
    if form == 0:
        out = (f"{sign}: the planets march in strict procession this week, and so must you. "
               f"Begin with {res[0]}; ")
        for g in res[1:-1]:
            out += f"once Venus has smiled on that, move along to {g}; "
        return out + (f"and let the journey end at {res[-1]}. Take any of them out of turn and Mercury will go "
                      "retrograde on you.")
    if form == 1:
        steps = [f"First, {res[0]}."] + [f"Then {g}." for g in res[1:-1]] + [f"Last of all, {res[-1]}."]
        return (f"{sign}, the heavens have already put your week in order. " + " ".join(steps)
                + " Do not rearrange what the cosmos has arranged.")
    sep = _sep(res)
    body = sep.join([f"Seek out {res[0]}", *(f"and only after that {g}" for g in res[1:])])
    return (f"Your stars, {sign}: one visit leads to the next, as surely as the moon follows the sun. {body}. "
            "The order is written in the sky.")


def _stars_free(rng, res):
    sign = _pick(rng, _SIGNS)
    form = int(rng.integers(3))
    if form == 0:
        return (f"{sign}: the cosmos is in a relaxed mood. Awaiting you are {_listed(rng, res)}, and the stars "
                "care not a jot which you visit ahead of the others. Follow your heart's own path.")
    if form == 1:
        return (f"{sign}: the cards turn up {_n(res)} places for you: {_listed(rng, res)}. Shuffle them however you "
                "please; the universe has set no sequence this time.")
    marks = " ".join(f"✧ {g}" for g in res)
    return (f"{sign}, the stars are scattered freely this week: {marks}. Visit them in any order your intuition "
            "suggests, for none outranks another.")


def _stars_single(rng, g):
    sign = _pick(rng, _SIGNS)
    return _pick(rng, (
        f"{sign}: a quiet week with a single calling. The stars point you to {g}; go to it and be at peace.",
        f"{sign}: one destination glows in your chart: {g}. Trust the heavens and head there.",
    ))


# telegram


def _wire_strict(rng, res):
    form = int(rng.integers(3))
    if form == 0:
        body = " STOP ".join([f"Proceed to {res[0]}", *(f"thence to {g}" for g in res[1:])])
        return f"{body} STOP in sequence as wired STOP no deviation STOP"
    if form == 1:
        items = " STOP ".join(f"{number_words(i).upper()} {g}" for i, g in enumerate(res, 1))
        return (f"Urgent STOP call at {_n(res)} places in order given STOP {items} STOP none ahead of its turn STOP "
                "regards Aunt Maud")
    mids = [f"after which {g}" for g in res[1:-1]]
    body = " STOP ".join([f"Arrive at {res[0]}", *mids, f"finally {res[-1]}"])
    return f"{body} STOP sequence essential repeat essential STOP"


def _wire_free(rng, res):
    form = int(rng.integers(3))
    if form == 0:
        return f"Must call at {_listed(rng, res)} STOP any order convenient STOP all before nightfall STOP"
    if form == 1:
        body = " STOP ".join([f"Kindly look in on {res[0]}", *(f"also {g}" for g in res[1:])])
        return f"{body} STOP order of calls your own affair STOP"
    return (f"Wire confirms {_n(res)} calls STOP {_listed(rng, res)} STOP no preference as to order STOP report "
            "when done STOP")


def _wire_single(rng, g):
    return _pick(rng, (f"Kindly proceed to {g} STOP await further word STOP",
                       f"Go straight to {g} STOP nothing further STOP"))


# tour manager


def _tour_strict(rng, res):
    form = int(rng.integers(3))
    if form == 0:
        sep = _sep(res)
        mids = [_pick(rng, ("roll on to ", "head across to ", "play ")) + g for g in res[1:-1]]
        body = sep.join([f"we open at {res[0]}", *mids])
        return (f"Listen up, band: tour itinerary, and we play the dates in the order they're booked, no swapping "
                f"cities: {body}{sep}and we wrap the tour at {res[-1]}. Bus leaves at dawn.")
    if form == 1:
        nights = " · ".join(f"Night {i}: {g}" for i, g in enumerate(res, 1))
        return f"TOUR DATES, in running order (skip one and the whole tour falls over): {nights}."
    out = f"Right, crew. Load in at {res[0]}."
    for g in res[1:-1]:
        out += f" When that show's done, and only then, the bus heads for {g}."
    out += (f" When that show's done, and only then, we close at {res[-1]}. Same order as the poster, "
            "no exceptions.")
    return out


def _tour_free(rng, res):
    form = int(rng.integers(3))
    if form == 0:
        return (f"Festival season, so no fixed routing: we've got slots at {_listed(rng, res)}, and you can play them "
                "in whatever order the bus schedule likes. Just make sure every one gets played.")
    if form == 1:
        marks = " ".join(f"♪ {g}" for g in res)
        return f"Pop-up gigs this week, routing's your call: {marks}. Hit them in any order you fancy."
    return (f"{_cap(_n(res))} dates on the calendar: {_listed(rng, res)}. The promoter doesn't care which we "
            "play ahead of the others, so route it however's easiest.")


def _tour_single(rng, g):
    return _pick(rng, (f"One-off show this time, folks: a single gig at {g}, and we're done.",
                       f"Just the one date on this tour: {g}. Load in, play it, load out."))


_VOICES = ((_dive_strict, _dive_free, _dive_single), (_stars_strict, _stars_free, _stars_single),
           (_wire_strict, _wire_free, _wire_single), (_tour_strict, _tour_free, _tour_single))


def render_instruction_am(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a dive-master's briefing, a horoscope
    column, a telegram, a tour manager's itinerary). Goals stay in visiting order, each written once as rendered;
    strict texts say the order is fixed ('in sequence', 'no freelancing', 'the order briefed', 'not a fin-kick
    sooner', 'strict procession', 'out of turn', 'put your week in order', 'the order is written in the sky', 'in
    sequence as wired', 'in order given', 'none ahead of its turn', 'sequence essential', 'in the order they're
    booked', 'running order', 'only then', 'same order as the poster'), free ones say it is open ('in whatever
    sequence', 'no set order', 'doesn't matter a jot', 'care not a jot', 'however you please', 'no sequence this
    time', 'any order', 'any order convenient', 'order of calls your own affair', 'no preference as to order', 'no
    fixed routing', "routing's your call", "doesn't care which"). A single goal gets neither kind of cue and no
    digit."""
    strict, free, single = _VOICES[int(rng.integers(len(_VOICES)))]
    if len(res) == 1:
        return single(rng, res[0])
    return strict(rng, list(res)) if order == "strict" else free(rng, list(res))
