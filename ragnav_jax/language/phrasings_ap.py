"""Held-out sentence set AP (split `unseen_ap`): goals, sensor phrases, coordinate hints and whole instructions
written in four new voices, for measuring how the instruction readers cope with phrasings nobody tuned them on.

Who wrote it: a helper session that never read the readers (parser, lexicon, tagger, sensor reader, readings,
agreement, adapters, llm, commands), nor the evaluation or memory code, nor any other set's body. What it read:
the `def` lines and docstrings of the four public functions of `phrasings_w.py` (the interface only);
`types.py` and `template_text.py` whole; the `UNSEEN_TEMPLATES` dict and the `_renderer` function of
`episodes.py`; the `EPISODE_SPLITS` tuple of `config.py`; `tests/test_heldout_sets.py` whole; and the
`subgoals()` strategy of `tests/test_phrasings_dev8.py` (with the `targets()` strategy it draws from, plus
printed sample values). `READINGS` was printed through `types.READINGS`.

The four voices (one per whole instruction, drawn from the generator passed in):

- a heating engineer's job sheet: "JOB SHEET", "Call two:", "attend", "make good", "parts on van", "sign off
  when done", "don't jump the queue", "whatever suits the van route", "all the one invoice";
- a hairdresser chatting in the salon chair: "Right, babe", "okay hun", "gorgeous", "you can't tone before
  you've lifted", "whatever order you fancy", "it all comes out gorgeous either way", "cup of tea?";
- a church bell-ringers' tower captain: "Look to!", "Stand.", "ring these in rounds, each bell in its proper
  place", "none out of turn", "call changes tonight, any bell may lead", "no set method", "Treble's going,
  she's gone", "kettle's on in the vestry";
- a DIY YouTuber's video script: "Hey guys, welcome back to the channel!", "don't skip ahead in the video",
  "first up", "no wrong way round", "smash that like button", "link in the description".

Style guide. A goal is "the" + [a superlative adjective] + the phrase's own words in order + the head noun,
exactly as given; or the head with its attributes after it ("the lamp that's teal and wool"); or with the
room as a possessive before it ("the kitchen's warmest lamp"). States go before the noun hyphenated
("the switched-on lamp") or in a clause ("that is open", "which is empty at the moment"). Then, in this
order: the room ("in", "over in", "kept in" the room), the sensor phrase (a threshold or superlative tail,
read inside the room), the coordinate hint (digits exactly as given, x then y, nothing numeric after it),
and the relations last. A goal's last relation comes after "and also" or "and"; an anchor's states are always
hyphenated before it, and an anchor's own relations sit in parentheses ("(the one by the drums)"), or, only when
the anchor ends the goal, in a "that is ..." clause. Sensor values are written in digits or in words ("forty per
cent", "twenty-two and a half degrees Celsius", "nought point six five"), sometimes in another unit
(Fahrenheit, kW, millibars), and the returned constraint keeps the canonical value with the unit as written.
Every whole instruction keeps the goals verbatim, once each, in visiting order; a multi-goal text says in words
whether the order is fixed ("in this exact order", "strictly in sequence", "none out of turn") or free
("no set order", "whatever order you fancy", "no wrong way round"); a single goal gets neither and no digit.

Tests broken on purpose: (1) the DIY YouTuber's free frame was changed to say "in this exact order", and
(2) the bell-ringer's strict chain was made to drop its last goal; tests/test_phrasings_ap.py failed on both
(test_goals_once_in_order_and_order_told caught both, test_each_goal_written_exactly_once caught the second),
and both were restored; the tests pass again.

Slips (seen outside the allowed regions, by accident, not used): the `grep '^def '` of `phrasings_w.py` showed the
names of its private helpers (`_itself`, `_anchor_np`, `_rel_chain`, `_goal_np`, `_article`, `_super_tails`,
`_nought_words`, `_number`, `_unit`, `_cap`, `_sep`, `_list`, `_comma`, `_cook`, `_keeper`, `_lawyer`,
`_commentator`); printing `EPISODE_SPLITS` also showed the first lines of `ROOM_TYPES` in `config.py` and a
grep hit on its `_check(self.split in EPISODE_SPLITS ...)` line; printing `_renderer` also showed the first
lines of `_rng` in `episodes.py`; a grep of `tests/test_phrasings_dev8.py` for top-level names showed its
import lines, the first lines of its constants (SETTINGS, HEADS, MODS, STATES, ROOMS, REL_WORDS, _UNITS, _TENS,
_VALUES), its test and helper function names, and the first lines of its STRICT_CUES and FREE_CUES regexes
(phrases such as "first", "then", "in that order", "lastly", "last of all", "any order", "order doesn't
matter", "whichever order"). This set's frames were written to avoid leaning on those cue phrases.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.template_text import (
    ONES,
    attributes_and_states,
    both,
    hyphenated,
    is_are,
    listed,
    number_words,
    plural,
    tidy,
)
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target


def _pick(rng, seq):
    return seq[int(rng.integers(len(seq)))]


def _chance(rng, p: float) -> bool:
    return float(rng.random()) < p


# ------------------------------------------------------------------------------------------------ goals

_REL = {
    "near": ("near", "close to", "not far from"),
    "next_to": ("next to", "right next to", "alongside"),
    "beside": ("beside", "just beside"),
    "by": ("by", "just by"),
    "on": ("on", "on top of", "sitting on"),
    "under": ("under", "underneath", "below"),
    "above": ("above", "up above"),
    "in": ("inside", "in"),
    "with": ("with", "complete with"),
    "in_room_with": ("in the same room as", "sharing a room with"),
    "in_front_of": ("in front of", "just in front of"),
    "behind": ("behind", "tucked behind"),
    "opposite": ("opposite", "across from", "facing"),
    "left_of": ("to the left of", "on the left-hand side of"),
    "right_of": ("to the right of", "on the right-hand side of"),
}


def _rel_word(rng, r: Relation) -> str:
    return _pick(rng, _REL.get(r.type, (r.type.replace("_", " "),)))


def _anchor(rng, t: Target, last: bool) -> str:
    """An anchor: states hyphenated before it; its own relations in parentheses, or a clause when it ends the goal."""
    pre, states = attributes_and_states(t)
    if not t.phrase.endswith(t.head):
        states = [a for a in t.attributes if a not in t.phrase]
    np_ = tidy(f"the {hyphenated(states)} {t.phrase}")
    if not t.relations:
        return np_
    inner = " and ".join(f"{_rel_word(rng, r)} {_anchor(rng, r.anchor, False)}" for r in t.relations)
    if last and _chance(rng, 0.5):
        return f"{np_} that {is_are(t.head)} {inner}"
    return f"{np_} ({'the ones' if plural(t.head) else 'the one'} {inner})"


def _relations(rng, rels: tuple[Relation, ...]) -> str:
    """The goal's own relations: the first as it stands, the last after 'and also' or 'and'."""
    out = []
    for i, r in enumerate(rels):
        piece = f"{_rel_word(rng, r)} {_anchor(rng, r.anchor, i == len(rels) - 1)}"
        if i and i == len(rels) - 1:
            piece = _pick(rng, ("and also ", "and also ", "and ")) + piece
        out.append(piece)
    return ", ".join(out)


def _clause(p: str) -> bool:
    return p.startswith(("that", "which", "whose", "where"))


def _and(words: list[str]) -> str:
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " and " + words[-1]


def render_goal_ap(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AP writes it: 'the teal wool lamp over in the nursery', 'the lamp that's teal and wool',
    'the switched-on lamp', 'the nursery's warmest lamp', 'the drums that are open, kept in the games room, with a
    temperature of at least 40 °C, at x = 3.5, y = 2, near the sofa (the one by the shelves) and also behind the
    closed drums'. Order: noun (with any superlative adjective), states, room, sensor tail, coordinate hint,
    relations."""
    t = sg.target
    pre, states = attributes_and_states(t)
    in_phrase = t.phrase.endswith(t.head)
    adj = prefix.strip()
    room = sg.room
    possessive = bool(room) and _chance(rng, 0.2)
    lead = f"the {room}'s" if possessive else "the"
    post: list[str] = []
    if not in_phrase:  # the phrase is not attributes + head: write it as it stands
        np_ = f"{lead} {adj} {t.phrase}"
        states = [a for a in t.attributes if a not in t.phrase]
    elif pre and _chance(rng, 0.25):
        np_ = f"{lead} {adj} {t.head}"
        that = "that are" if plural(t.head) else _pick(rng, ("that's", "that is"))
        post.append(f"{that} {_and(pre + states)}")
        states = []
    elif states and _chance(rng, 0.45):
        np_ = f"{lead} {adj} {hyphenated(states)} {' '.join(pre)} {t.head}"
        states = []
    else:
        np_ = f"{lead} {adj} {' '.join(pre)} {t.head}"
    if states:
        post.append(_pick(rng, (f"that {is_are(t.head)} {both(states)}",
                                f"which {is_are(t.head)} {both(states)} at the moment")))
    if room and not possessive:
        kept = "that are kept in" if plural(t.head) else "that's kept in"
        post.append(_pick(rng, ("in", "over in") if post else ("in", "over in", kept, "in")) + f" the {room}")
    if tail.strip():
        post.append(tail.strip())
    if hint.strip():
        post.append(hint.strip())
    text = tidy(np_)
    for i, p in enumerate(post):  # after a clause, always a comma, so nothing reads as part of it
        text += (", " if i and (_clause(post[i - 1]) or _chance(rng, 0.6)) else " ") + p
    if t.relations:
        text += (", " if post else " ") + _relations(rng, t.relations)
    return tidy(text)


# ------------------------------------------------------------------------------------------------ sensors

def _fmt(v: float) -> str:
    s = format(float(v), ".12g")
    return "0" if s == "-0" else s


def _words(v: float) -> str | None:
    """A value in words, or None when words would not be exact or natural."""
    if abs(v) >= 1000:
        return None
    if float(v).is_integer():
        return number_words(int(v))
    if (2 * v).is_integer() and int(v) != 0:
        return number_words(int(v)) + " and a half"
    m = re.fullmatch(r"(-?)0\.(\d{1,3})", _fmt(v))
    if m:
        return ("minus " if m.group(1) else "") + "nought point " + " ".join(ONES[int(d)] for d in m.group(2))
    return None


def _f_of(c: float) -> float:
    return c * 9.0 / 5.0 + 32.0


# reading -> names, units (suffix after the number, unit as written, canonical -> written, words allowed)
_NAMES = {
    "temperature_c": ("temperature", "temp"),
    "ndvi": ("NDVI", "NDVI value"),
    "humidity_pct": ("humidity", "relative humidity"),
    "co2_ppm": ("CO2 level", "CO₂ level", "carbon dioxide level"),
    "noise_db": ("noise level", "sound level"),
    "light_lux": ("light level", "brightness"),
    "battery_pct": ("battery level", "battery charge"),
    "power_w": ("power draw", "wattage"),
    "weight_kg": ("weight",),
    "pressure_hpa": ("air pressure", "barometric pressure"),
}
_UNITS = {
    "temperature_c": ((" °C", "c", None, False), ("°C", "c", None, False), (" degrees C", "c", None, False),
                      (" degrees Celsius", "c", None, True), (" °F", "f", _f_of, False),
                      (" degrees Fahrenheit", "f", _f_of, True)),
    "ndvi": (("", "", None, True),),
    "humidity_pct": (("%", "%", None, False), (" per cent", "%", None, True), (" percent", "%", None, True)),
    "co2_ppm": ((" ppm", "ppm", None, True), (" parts per million", "ppm", None, True)),
    "noise_db": ((" dB", "db", None, False), (" decibels", "db", None, True)),
    "light_lux": ((" lux", "lux", None, True),),
    "battery_pct": (("%", "%", None, False), (" per cent", "%", None, True)),
    "power_w": ((" W", "w", None, False), (" watts", "w", None, True), (" kW", "kw", lambda w: w / 1000.0, False)),
    "weight_kg": ((" kg", "kg", None, False), (" kilos", "kg", None, True), (" kilograms", "kg", None, True)),
    "pressure_hpa": ((" hPa", "hpa", None, False), (" millibars", "mbar", None, True)),
}
_THRESH = {
    "gt": ("with {a} {r} over {v}", "whose {r} is above {v}", "with {a} {r} of more than {v}",
           "with its {r} reading higher than {v}", "with {a} {r} in excess of {v}"),
    "ge": ("with {a} {r} of at least {v}", "whose {r} is {v} or more", "with {a} {r} no lower than {v}",
           "with its {r} reading {v} or above", "with {a} {r} not below {v}"),
    "lt": ("with {a} {r} under {v}", "whose {r} is below {v}", "with {a} {r} of less than {v}",
           "with its {r} reading lower than {v}", "with {a} {r} that stays beneath {v}"),
    "le": ("with {a} {r} of {v} or less", "whose {r} is at most {v}", "with {a} {r} no higher than {v}",
           "with its {r} reading {v} or below", "with {a} {r} not over {v}"),
    "approx": ("with {a} {r} of about {v}", "whose {r} is somewhere near {v}", "with its {r} reading roughly {v}",
               "with {a} {r} in the region of {v}", "with {a} {r} of more or less {v}"),
}
_VIVID = {  # reading-specific thresholds: the unit alone says which reading it is
    "temperature_c": {"gt": ("running hotter than {v}",), "lt": ("colder than {v}",), "ge": ("at {v} or warmer",),
                      "le": ("at {v} or cooler",), "approx": ("sitting at about {v}",)},
    "noise_db": {"gt": ("louder than {v}",), "lt": ("quieter than {v}",)},
    "light_lux": {"gt": ("brighter than {v}",), "lt": ("dimmer than {v}",)},
    "weight_kg": {"gt": ("weighing more than {v}",), "lt": ("weighing less than {v}",),
                  "ge": ("weighing {v} or more",), "le": ("weighing no more than {v}",),
                  "approx": ("weighing about {v}",)},
    "power_w": {"gt": ("drawing more than {v}",), "lt": ("drawing less than {v}",), "approx": ("drawing about {v}",)},
}
_SUPER_ADJ = {  # reading -> (max adjectives, min adjectives)
    "temperature_c": (("warmest", "hottest"), ("coldest", "coolest")),
    "humidity_pct": (("dampest", "most humid"), ("driest",)),
    "noise_db": (("loudest", "noisiest"), ("quietest",)),
    "light_lux": (("brightest", "best-lit"), ("dimmest",)),
    "weight_kg": (("heaviest",), ()),
    "power_w": (("most power-hungry",), ("least power-hungry",)),
    "battery_pct": (("best-charged",), ()),
}
_SUPER_TAIL = {
    "max": ("with the highest {r} of the lot", "whose {r} is the highest", "with the top {r} reading",
            "reading highest for {r}"),
    "min": ("with the lowest {r} of the lot", "whose {r} is the lowest", "reading lowest for {r}",
            "with the smallest {r} reading"),
}
_SUPER_VIVID = {
    "weight_kg": {"max": ("weighing the most",), "min": ("weighing the least",)},
    "battery_pct": {"max": ("with the most charge left",), "min": ("with the least charge left",)},
    "power_w": {"max": ("drawing the most power",), "min": ("drawing the least power",)},
}


def _article(name: str) -> str:
    return "an" if name.startswith(("NDVI", "air")) else "a"


def _value_text(rng, reading: str, v: float) -> tuple[str, str]:
    """(the value with its unit as written, the unit code)."""
    options = []
    for suffix, code, conv, words_ok in _UNITS.get(reading, (("", "", None, False),)):
        w = v if conv is None else conv(v)
        if conv is not None:  # another unit: only where the written number is short and exact
            s = _fmt(round(w, 3))
            if not np.isclose(float(s), w, rtol=0, atol=1e-9) or abs(w) < 1:
                continue
            w = float(s)
        options.append((suffix, code, w, words_ok))
    suffix, code, w, words_ok = _pick(rng, options)
    said = _words(w) if words_ok else None
    num = said if said is not None and _chance(rng, 0.45) else _fmt(w)
    return num + suffix, code


def render_sensor_ap(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('warmest', 'dampest', 'most power-hungry') or a tail ('with the
    highest NDVI of the lot', 'whose CO2 level is the lowest', 'weighing the most'); thresholds after the noun
    ('with a temperature over 40 °C', 'whose humidity is at most forty per cent', 'with an NDVI of about nought
    point six five', 'weighing no more than 12 kilos', 'drawing more than 1.5 kW', 'at 104 °F or warmer'). The
    value returned stays in the reading's canonical unit; the unit is the one written."""
    name = _pick(rng, _NAMES.get(c.reading, (c.reading.replace("_", " "),)))
    if c.comparator in ("max", "min"):
        adjs = _SUPER_ADJ.get(c.reading, ((), ()))[0 if c.comparator == "max" else 1]
        if adjs and _chance(rng, 0.5):
            return _pick(rng, adjs), "", SensorConstraint(c.reading, c.comparator, None, "")
        tails = _SUPER_TAIL[c.comparator] + _SUPER_VIVID.get(c.reading, {}).get(c.comparator, ())
        return "", _pick(rng, tails).format(r=name), SensorConstraint(c.reading, c.comparator, None, "")
    text, unit = _value_text(rng, c.reading, float(c.value))
    forms = _THRESH[c.comparator] + _VIVID.get(c.reading, {}).get(c.comparator, ())
    phrase = _pick(rng, forms).format(a=_article(name), r=name, v=text)
    return "", phrase, SensorConstraint(c.reading, c.comparator, float(c.value), unit)


# ------------------------------------------------------------------------------------------------ hints

def hint_text_ap(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at x = 3.5, y = 2', 'at co-ordinates (3.5, 2)',
    'where x is 3.5 and y is 2', 'at 3.5 m on the x axis and 2 m on the y axis', 'at map ref [3.5 / 2]'."""
    return _pick(rng, (f"at x = {x}, y = {y}", f"at co-ordinates ({x}, {y})", f"where x is {x} and y is {y}",
                       f"at {x} m on the x axis and {y} m on the y axis", f"at map ref [{x} / {y}]",
                       f"at the spot marked x {x}, y {y}"))


# ------------------------------------------------------------------------------------------------ instructions

_ORD = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth")


def _sep(res: list[str]) -> str:
    return "; " if any("," in r for r in res) else ", "


def _free_list(rng, res: list[str]) -> str:
    """Goals in no set order: a plain running list for short bare goals, else semicolons, so that no goal's
    relations can run on into the next goal."""
    if all("," not in g and len(g.split()) <= 4 for g in res):
        return listed(rng, res)
    return "; ".join(res[:-1]) + _pick(rng, ("; and ", "; ")) + res[-1]


def _chain(rng, res: list[str], words: tuple[str, str, str]) -> str:
    """Goals in a fixed sequence: (opening word, middle word, closing word), e.g. ('first', 'then', 'to finish')."""
    start, mid, end = words
    sep = _sep(res)
    out = [f"{start} {res[0]}"]
    for g in res[1:-1]:
        out.append(f"{mid} {g}")
    out.append(f"{end} {res[-1]}")
    return sep.join(out)


def _plumber(rng, res: list[str], order: str) -> str:
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"JOB SHEET — single call. Attend: {g}. Sign off when done.",
                           f"Work order for the robot: attend {g}. Make good once finished. No access issues reported.",
                           f"Van sheet. Call-out to {g}. Parts on van."))
    n = number_words(len(res))
    if order == "strict":
        form = int(rng.integers(3))
        if form == 0:
            calls = " | ".join(f"Call {number_words(i + 1)}: {g}" for i, g in enumerate(res))
            return f"JOB SHEET — {n} calls, attend in the order listed and don't jump the queue. {calls}. " \
                   "Sign off when done."
        if form == 1:
            return "Work order for the robot. Do these strictly in sequence, each one finished before the next is " \
                   f"started: {_chain(rng, res, ('', 'then', 'then'))}. Make good and leave site tidy."
        return f"Van sheet: {_chain(rng, res, ('first', 'then', 'and lastly'))}. Order's fixed — customer wants " \
               "them done in that sequence."
    form = int(rng.integers(3))
    if form == 0:
        return f"JOB SHEET — {n} calls, no set order, do them however suits the van route: {' | '.join(res)}. " \
               "Sign off when done."
    if form == 1:
        return f"Work order for the robot: {_free_list(rng, res)}. Sequence is up to you, it's all the one invoice."
    return f"Van sheet, running order of calls at your discretion: {_free_list(rng, res)}. Parts on van."


def _stylist(rng, res: list[str], order: str) -> str:
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"Right, babe, just a quick one today: pop over to {g}. Gorgeous.",
                           f"Okay hun, sit back and relax, all you need to find today is {g}. Looking fab.",
                           f"So lovely, what we're after today is {g}. You'll love it."))
    if order == "strict":
        form = int(rng.integers(3))
        if form == 0:
            return "Right, babe, here's what we're doing today, and we do it in this exact order — you can't tone " \
                   f"before you've lifted, can you? {_chain(rng, res, ('First', 'then', 'and to finish'))}. Gorgeous."
        if form == 1:
            return "Okay hun, sit back. The order really matters with this one, so no skipping ahead: " \
                   f"{_chain(rng, res, ('start with', 'once that is done,', 'and after that,'))}. You'll love it."
        return "So lovely, it's like a colour job, step by step, in the order I say: " \
               f"{_chain(rng, res, ('', 'then', 'then'))}. Fab."
    form = int(rng.integers(3))
    if form == 0:
        return "Right, babe, honestly do these in whatever order you fancy, it all comes out gorgeous either way: " \
               f"{_free_list(rng, res)}. Cup of tea?"
    if form == 1:
        return "Okay hun, no set order for this lot, just pick whichever you like: " \
               f"{_free_list(rng, res)}. Looking fab."
    return f"So what we're doing today, lovely, in whatever order suits you: {_free_list(rng, res)}. The sequence " \
           "makes no odds, trust me."


def _ringer(rng, res: list[str], order: str) -> str:
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"Look to! Treble's going, she's gone, ring out to {g}. Stand.",
                           f"Tower captain's notice: a single bell tonight, {g}. That's all.",
                           f"Practice night. Just the tenor to ring in: {g}. Kettle's on in the vestry."))
    if order == "strict":
        form = int(rng.integers(3))
        if form == 0:
            return "Look to! We'll ring these in rounds, each bell in its proper place and none out of turn: " \
                   f"{_chain(rng, res, ('', 'then', 'then'))}. Stand."
        if form == 1:
            lead = f"{res[0]} leads"
            rest = "".join(f", then {g}" if _sep(res) == ", " else f"; then {g}" for g in res[1:])
            return f"Tower captain's notice: the touch is called in strict sequence — {lead}{rest} — ring them in " \
                   "that sequence and no other. That's all."
        return "Practice night. Keep to the call: " \
               f"{_chain(rng, res, ('first', 'after that', 'and to bring it round'))}. Don't clash and don't " \
               "jump a place."
    form = int(rng.integers(3))
    if form == 0:
        return f"Look to! Call changes tonight, any bell may lead and the sequence is yours to choose: " \
               f"{_free_list(rng, res)}. Stand."
    if form == 1:
        return f"Tower captain's notice: ring these in whatever order you please, no set method tonight: " \
               f"{_free_list(rng, res)}. That's all."
    return f"Practice night, no set method: ring each once, in whatever sequence it falls: {_free_list(rng, res)}. " \
           "Kettle's on in the vestry."


def _vlogger(rng, res: list[str], order: str) -> str:
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"Hey guys, welcome back to the channel! Quick video today, we're heading to {g}. "
                           "Smash that like button!",
                           f"What's up everyone! Today's mini-build is all about {g}. Link in the description.",
                           f"Okay guys, super quick one: grab the camera and go to {g}. Don't forget to subscribe!"))
    if order == "strict":
        form = int(rng.integers(3))
        if form == 0:
            return "Hey guys, welcome back to the channel! Today's build goes in a set order, so don't skip ahead " \
                   f"in the video: {_chain(rng, res, ('first up,', 'next,', 'and finally,'))}. Smash that like button!"
        if form == 1:
            return "What's up everyone! Quick heads-up before we start: do these in exactly this order or the " \
                   f"whole build falls apart: {_chain(rng, res, ('', 'then', 'then'))}. Link in the description."
        return "Okay guys, step by step, in the order you see them on screen: " \
               f"{_chain(rng, res, ('first', 'then', 'then'))}. Don't forget to subscribe!"
    form = int(rng.integers(3))
    if form == 0:
        return "Hey guys, welcome back to the channel! No right order for today's build, do these whichever way " \
               f"round you like: {_free_list(rng, res)}. Smash that like button!"
    if form == 1:
        return "What's up everyone! You can honestly tackle these in whatever order, there's no wrong way round: " \
               f"{_free_list(rng, res)}. Drop a comment below!"
    return f"Okay guys, the order is totally up to you on this one: {_free_list(rng, res)}. Don't forget to subscribe!"


_VOICES = (_plumber, _stylist, _ringer, _vlogger)


def render_instruction_ap(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a heating engineer's job sheet, a
    hairdresser in the salon chair, a bell-ringers' tower captain, a DIY YouTuber). Goals stay in visiting order,
    each written once as rendered; strict texts say the order is fixed ('attend in the order listed', 'don't jump
    the queue', 'strictly in sequence', 'order's fixed', 'in this exact order', 'no skipping ahead', 'in the
    order I say', 'none out of turn', 'in strict sequence', 'keep to the call', 'don't skip ahead in the video',
    'in exactly this order'), free ones say it is open ('no set order', 'sequence is up to you', 'at your
    discretion', 'whatever order you fancy', 'pick whichever you like', 'makes no odds', 'any bell may lead',
    'no set method', 'no right order', 'no wrong way round', 'totally up to you'). A single goal gets neither kind
    of cue and no digit."""
    voice = _pick(rng, _VOICES)
    return tidy(voice(rng, list(res), order))
