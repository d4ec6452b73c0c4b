"""Held-out sentence set AR (split `unseen_ar`): four new people send the home robot round the house, each in the
layout and words of their own world, to measure afresh how the instruction readers cope with authors nobody tuned
them on.

Who wrote it: a helper session started inside the project for this one task, writing blind to the readers.

What it read: the `def` lines and docstrings of the four public functions of `language/phrasings_w.py` (printed
with an `ast` script, not their bodies, helpers or module docstring); `language/types.py` and
`language/template_text.py`, whole; `UNSEEN_TEMPLATES` and `_renderer` of `language/episodes.py` and
`EPISODE_SPLITS` of `config.py` (each printed alone with `ast`); `tests/test_heldout_sets.py`, whole; the
`subgoals()` and `targets()` strategies and HEADS, MODS, STATES, ROOMS of `tests/test_phrasings_dev8.py` (printed
alone with `ast`, with that file's import lines); `[tool.ruff]` of pyproject.toml; and, at run time, the value of
`types.READINGS` (the ten sensor keys) and `types.RELATION_TYPES`.

The four voices (one drawn per whole instruction, each with two layouts):
  * a village cricket captain ("Skip"): a dressing-room talk ('Right, lads, gather round', 'Opening up, ...',
    'Next in, ...', 'Last man in, ...', 'the batting order's set in stone today, nobody pads up out of turn',
    'it's only a friendly, so the batting order's open') and a team sheet pinned up in the pavilion ('TEAM SHEET:
    HOME FIXTURE', bullets, 'go in exactly as listed, top to bottom, no swaps', 'no set batting order this week');
  * a studio potter (Ros): a kiln-log whiteboard ('KILN LOG: glaze firing', dashed lines, 'load strictly in this
    order, bottom shelf up; swap anything round and the whole firing's ruined', 'BISQUE LOAD', 'no particular
    order for this lot; pack them in however they fit', 'slow cool, and no peeking till it's cold') and a note
    left on the wheel ('I'm off at the clay merchant's', 'start with ..., then ..., and finish with ...', 'it's
    like glaze coats, each goes on over the one before', 'they all come out of the same firing in the end');
  * an election returning officer: a published notice ('NOTICE OF ROUNDS', 'I, the undersigned, being the
    Returning Officer for this household, hereby give notice', lettered stations '(a)', '(b)', 'strictly in the
    sequence in which they appear, as ballot boxes are taken for verification', 'as on a ballot paper, the order
    of listing confers no precedence', 'By order of the Returning Officer') and a declaration at the count ('do
    hereby declare the order of attendance as follows. First, ... Second, ... Lastly, ...', 'the order so
    declared is final', 'in no order of precedence whatsoever', 'no objection shall be entertained on that
    score', 'I thank the count staff for their patience');
  * an amateur astronomer (Dave): an observing plan ('Observing plan for tonight (house session, seeing
    permitting)', starred lines, 'work through these top to bottom, in exactly this order, before each one sets',
    'everything's well placed all night, so tick them off in any order you like', 'Clear skies!') and a club
    chat post ('seeing's looking steady tonight', 'start on ...; once that's logged, slew across to ...; and
    finish up on ...', 'keep to that sequence, please, the sky won't wait for anyone', 'nothing sets before
    dawn, so there's no set order; hop between them however you like').

Style (one plain-English goal pool every voice shares; the voice lives only in the frame): a goal is 'the' +
[superlative adjective] + [states, hyphenated] + the attributes as the phrase gives them + the head noun as given;
states may instead follow after the room ('that is switched on', 'which are currently empty', 'that has been left
open'; only when no sensor tail follows). The room comes straight after the noun ('in the nursery') or before it
as a possessive ('the nursery's warmest teal lamp'), inside a superlative's scope; then the sensor tail ('with a
temperature of at least forty degrees Celsius', 'weighing 500 g or less', 'with the highest NDVI of the lot');
then the coordinate hint, x then y with the numbers as given and no digit after them ('at (3.5, 2)', 'at x 3.5,
y 2', 'at 3.5 across and 2 up'); relations last ('both next to the sofa (the one on the toolbox) and behind the
drums', 'by the lamp as well as under the shelves'). Sensor numbers are the shortest decimal that reads back, or
number words for whole numbers under a hundred; a second unit (°F, kW, grams, millibars) only where it converts
back exactly; carbon dioxide is spelled out. Goals are parted by new lines, semicolons, sentence ends or sequence
words, never by a bare 'and'; every goal is written once, in visiting order. Strict texts say the order is fixed,
free ones say it is open, in words; a single goal gets neither. No frame writes a digit.

Tests broken on purpose: (1) the strict cue of the astronomer's observing plan was cut to 'Work through these top
to bottom:'; `test_every_voice_and_frame_says_its_order[6]` and
`test_render_instruction_draws_every_voice_and_layout` failed ('no strict cue'), then the cue was restored. (2)
`hint_text_ar` was made to write y before x; `test_goal_carries_everything_in_place`, all four cases of
`test_hint_is_x_then_y_and_last` and the hypothesis test `test_any_goals_keep_heads_hint_and_order` failed, then
the order was restored and all eighteen passed again.

Slips: before writing anything I ran `git log --oneline | head -3` in the worktree to see where it stood; the
three commit subjects it printed mention a parser change about one-word sentences ('a bell-ringer's "Stand." read
as a goal'), development-set scores and round numbers. Beyond the list above I also saw file names (`ls` of the
language and tests folders) and, to look over my own sentences, printed a few `unseen_ar` episodes from
`generate_episodes` on the small scene `tests/test_heldout_sets.py` builds (instructions and their truth goals
only; I ran no reader, and no reader's output was shown). No other file was opened.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.template_text import attributes_and_states, both, hyphenated, number_words, plural
from ragnav_jax.language.types import SensorConstraint, Subgoal, Target


def _pick(rng: np.random.Generator, seq):
    return seq[int(rng.integers(len(seq)))]


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


# ------------------------------------------------------------------------------------------------------------
# Goals

_RELATION_WORDS = {
    "near": ("near", "close to", "not far from"),
    "next_to": ("next to", "alongside"),
    "beside": ("beside",),
    "by": ("by",),
    "on": ("on", "on top of", "sitting on"),
    "under": ("under", "underneath", "beneath"),
    "above": ("above", "up above"),
    "in": ("inside", "tucked inside"),
    "with": ("with",),
    "in_room_with": ("in the same room as", "sharing a room with"),
    "in_front_of": ("in front of",),
    "behind": ("behind", "round behind"),
    "opposite": ("opposite", "across from", "facing"),
    "left_of": ("to the left of", "left of"),
    "right_of": ("to the right of", "right of"),
}


def _noun(t: Target) -> tuple[list[str], list[str]]:
    """(attributes before the noun, then the head, as words; states)."""
    pre, states = attributes_and_states(t)
    return [*pre, t.head], states


def _anchor(rng: np.random.Generator, t: Target) -> str:
    """An anchor: 'the' + states (hyphenated) + phrase, its own relations in brackets right after it."""
    words, states = _noun(t)
    s = " ".join(["the", *([hyphenated(states)] if states else []), *words])
    if t.relations:
        many = plural(t.head)
        lead = _pick(rng, ("the ones", "which are", "themselves") if many else ("the one", "which is", "itself"))
        s += f" ({lead} {_relations(rng, t)})"
    return s


def _relations(rng: np.random.Generator, t: Target) -> str:
    parts = [f"{_pick(rng, _RELATION_WORDS.get(r.type, (r.type.replace('_', ' '),)))} {_anchor(rng, r.anchor)}"
             for r in t.relations]
    if len(parts) == 1:
        return parts[0]
    if len(parts) == 2:
        a, b = parts
        return _pick(rng, (f"both {a} and {b}", f"{a}, and also {b}", f"{a} as well as {b}"))
    return ", ".join(parts[:-1]) + ", and also " + parts[-1]


def render_goal_ar(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AR writes it: 'the nursery's warmest switched-on teal lamp', 'the teal lamp in the nursery
    that is switched on', 'the sofa in the games room with a temperature above 40 °C, at (3.5, 2)', 'the lamp
    both next to the sofa (the one on the toolbox) and behind the drums'. The room follows the noun or goes before
    it as a possessive (inside a superlative's scope); then the sensor tail; then the coordinate hint; relations
    last."""
    t = sg.target
    words, states = _noun(t)
    room = sg.room
    possessive = bool(room) and not room.endswith("s") and rng.random() < 0.4
    states_after = bool(states) and not tail and rng.random() < 0.5
    front = ["the"]
    if possessive:
        front.append(f"{room}'s")
    if prefix:
        front.append(prefix)
    if states and not states_after:
        front.append(hyphenated(states))
    s = " ".join([*front, *words])
    if room and not possessive:
        s += f" in the {room}"
    if states_after:
        many = plural(t.head)
        lead = _pick(rng, ("that are", "which are currently", "that have been left") if many
                     else ("that is", "which is currently", "that has been left"))
        s += f" {lead} {both(states)}"
    if tail:
        s += f" {tail}"
    if hint:
        s += (", " if states_after or tail else " ") + hint
    if t.relations:
        s += (", " if hint else " ") + _relations(rng, t)
    return s


# ------------------------------------------------------------------------------------------------------------
# Sensors

# reading -> (noun for superlative tails, noun leads for thresholds, verb leads, max adjectives, min adjectives)
_READING_WORDS = {
    "temperature_c": ("temperature", ("with a temperature", "with a temperature reading"), (),
                      ("warmest", "hottest"), ("coldest", "coolest")),
    "ndvi": ("NDVI", ("with an NDVI", "with an NDVI reading"), (), (), ()),
    "humidity_pct": ("humidity", ("with a relative humidity", "with a humidity reading"), (),
                     ("most humid", "dampest"), ("driest", "least humid")),
    "co2_ppm": ("carbon dioxide level", ("with a carbon dioxide level", "with a carbon dioxide reading"), (), (), ()),
    "noise_db": ("noise level", ("with a noise level", "with a sound level"), (), ("loudest", "noisiest"),
                 ("quietest",)),
    "light_lux": ("light level", ("with a light level",), (), ("brightest",), ("dimmest", "darkest")),
    "battery_pct": ("battery charge", ("with a battery level", "with a battery charge"), (), (), ()),
    "power_w": ("power draw", ("with a power draw",), ("drawing",), ("most power-hungry",),
                ("least power-hungry",)),
    "weight_kg": ("weight", ("with a weight",), ("weighing",), ("heaviest",), ()),
    "pressure_hpa": ("air pressure", ("with an air pressure", "with an air pressure reading"), (), (), ()),
}

# unit label -> (symbol after digits, spelled after digits or words)
_UNIT_TEXT = {
    "c": (" °C", " degrees Celsius"), "f": (" °F", " degrees Fahrenheit"), "%": ("%", " per cent"),
    "ppm": (" ppm", " parts per million"), "db": (" dB", " decibels"), "lux": (" lux", " lux"),
    "w": (" W", " watts"), "kw": (" kW", " kilowatts"), "kg": (" kg", " kilograms"), "g": (" g", " grams"),
    "hpa": (" hPa", " hectopascals"), "mbar": (" mbar", " millibars"), "": ("", ""),
}
_CANONICAL_UNIT = {"temperature_c": "c", "ndvi": "", "humidity_pct": "%", "co2_ppm": "ppm", "noise_db": "db",
                   "light_lux": "lux", "battery_pct": "%", "power_w": "w", "weight_kg": "kg", "pressure_hpa": "hpa"}

# comparator -> forms after a noun lead ('with a temperature ...'), forms after a verb lead ('weighing ...')
_NOUN_FORMS = {
    "gt": ("above {v}", "over {v}", "higher than {v}", "of more than {v}"),
    "lt": ("below {v}", "under {v}", "lower than {v}", "of less than {v}"),
    "ge": ("of at least {v}", "of {v} or more", "no lower than {v}", "of {v} or above"),
    "le": ("of at most {v}", "of {v} or less", "no higher than {v}", "not above {v}"),
    "approx": ("of about {v}", "of roughly {v}", "of around {v}", "close to {v}"),
}
_VERB_FORMS = {
    "gt": ("more than {v}", "over {v}"),
    "lt": ("less than {v}", "under {v}"),
    "ge": ("at least {v}", "{v} or more"),
    "le": ("at most {v}", "{v} or less", "no more than {v}"),
    "approx": ("about {v}", "roughly {v}", "around {v}"),
}


def _digits(v: float) -> str:
    """The shortest decimal that reads back as v ('40', '0.65', '-4.5')."""
    return np.format_float_positional(float(v), unique=True, trim="-")


def _few_places(s: str) -> bool:
    return "." not in s or len(s.split(".")[1]) <= 2


def _other_unit(reading: str, v: float) -> tuple[str, str] | None:
    """(unit label, number as written) in a second unit, only where it converts back to v exactly."""
    if reading == "temperature_c":
        s = _digits(v * 9 / 5 + 32)
        f = float(s)
        if _few_places(s) and (f - 32) * 5 / 9 == v and (f - 32) / 1.8 == v:
            return "f", s
    if reading == "power_w" and abs(v) >= 100:
        s = _digits(v / 1000)
        if _few_places(s) and float(s) * 1000 == v:
            return "kw", s
    if reading == "weight_kg" and 0 < abs(v) < 10:
        s = _digits(v * 1000)
        if _few_places(s) and float(s) / 1000 == v:
            return "g", s
    if reading == "pressure_hpa":
        return "mbar", _digits(v)
    return None


def _value_text(rng: np.random.Generator, reading: str, v: float) -> tuple[str, str]:
    """(the value with its unit as written, the unit label)."""
    unit, num = _CANONICAL_UNIT.get(reading, ""), _digits(v)
    other = _other_unit(reading, v)
    if other is not None and rng.random() < 0.35:
        unit, num = other
    sym, spelled = _UNIT_TEXT[unit]
    x = float(num)
    if unit and x.is_integer() and abs(x) < 100 and rng.random() < 0.4:
        return number_words(int(x)) + spelled, unit
    return num + _pick(rng, (sym, spelled)), unit


def render_sensor_ar(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('warmest', 'driest', 'most power-hungry') or a tail ('with the
    highest NDVI', 'whose carbon dioxide level is the lowest', 'with the highest weight of the lot'); thresholds
    after the noun ('with a temperature above 40 °C', 'with a relative humidity of at most forty per cent', 'weighing
    500 g or less', 'with an air pressure close to 1013 millibars', 'running hotter than 104 °F')."""
    noun, leads, verbs, up, down = _READING_WORDS.get(
        c.reading, (c.reading.replace("_", " "), (f"with a {c.reading.replace('_', ' ')} reading",), (), (), ()))
    if c.is_superlative:
        adjectives = up if c.comparator == "max" else down
        written = SensorConstraint(c.reading, c.comparator, None, "")
        if adjectives and rng.random() < 0.5:
            return _pick(rng, adjectives), "", written
        most = "highest" if c.comparator == "max" else "lowest"
        tail = _pick(rng, (f"with the {most} {noun}", f"whose {noun} is the {most}",
                           f"with the {most} {noun} of the lot"))
        return "", tail, written
    value, unit = _value_text(rng, c.reading, float(c.value))
    written = SensorConstraint(c.reading, c.comparator, float(c.value), unit)
    if c.reading == "temperature_c" and c.comparator in ("gt", "lt") and rng.random() < 0.25:
        return "", f"running {'hotter' if c.comparator == 'gt' else 'cooler'} than {value}", written
    if verbs and rng.random() < 0.5:
        return "", f"{_pick(rng, verbs)} {_pick(rng, _VERB_FORMS[c.comparator]).format(v=value)}", written
    return "", f"{_pick(rng, leads)} {_pick(rng, _NOUN_FORMS[c.comparator]).format(v=value)}", written


def hint_text_ar(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at (3.5, 2)', 'at x 3.5, y 2', 'at the point
    x = 3.5, y = 2', 'at 3.5 across and 2 up', 'with x at 3.5 and y at 2', 'at position x 3.5 / y 2'."""
    return _pick(rng, (f"at ({x}, {y})", f"at x {x}, y {y}", f"at the point x = {x}, y = {y}",
                       f"at {x} across and {y} up", f"with x at {x} and y at {y}", f"at position x {x} / y {y}"))


# ------------------------------------------------------------------------------------------------------------
# Whole instructions: four people, two layouts each. Every frame gets (rng, goals, order) with order one of
# 'strict', 'free' or 'single' (one goal), and writes each goal once, in the order given.

def _run_on_sep(res: list[str]) -> str:
    return "; " if any("," in r for r in res) else ", "


def _cricket_talk(rng, res, order):
    intro = _pick(rng, ("Right, lads, gather round, quick word before we walk out.",
                        "Listen up, you lot, skipper speaking."))
    out = _pick(rng, ("Heads up and play straight, lads.", "Keep it tight out there, and enjoy it. Skip."))
    if order == "single":
        return f"{intro} Just the one job today: {res[0]}. {out}"
    if order == "free":
        cue = _pick(rng, ("It's only a friendly, so the batting order's open; go in whichever way suits you.",
                          "No batting order today, lads; sort it out among yourselves, any order you like."))
        return f"{intro} {cue} On the team sheet: {'; '.join(res)}. {out}"
    cue = _pick(rng, ("The batting order's set in stone today, nobody pads up out of turn.",
                      "We bat in the order I read it out, and nobody goes in before the one above them."))
    lines = [f"Opening up, {res[0]}."]
    lines += [_pick(rng, ("Next in, {g}.", "Then {g}.", "After that, {g}.")).format(g=g) for g in res[1:-1]]
    lines.append(f"Last man in, {res[-1]}.")
    return " ".join([intro, cue, *lines, out])


def _cricket_sheet(rng, res, order):
    bullets = "\n".join(f"• {g}" for g in res)
    out = _pick(rng, ("Whites washed, please. Skip", "Any problems, see the skipper."))
    if order == "single":
        return f"TEAM SHEET\nJust the one job this week:\n{bullets}\nCheers, Skip"
    if order == "free":
        cue = _pick(rng, ("No set batting order this week, go in whichever way suits you.",
                          "Friendly, so the batting order's up to you: any order will do."))
        return f"TEAM SHEET: FRIENDLY\n{cue}\n{bullets}\n{out}"
    cue = _pick(rng, ("Batting order is final: go in exactly as listed, top to bottom, no swaps.",
                      "Batting order below, in exactly this order, and nobody goes in early."))
    return f"TEAM SHEET: HOME FIXTURE\n{cue}\n{bullets}\n{out}"


def _potter_board(rng, res, order):
    lines = "\n".join(f"- {g}" for g in res)
    out = _pick(rng, ("Slow cool, and no peeking till it's cold. Ros", "Mind the elements. Ros (studio)"))
    if order == "single":
        return f"KILN LOG\nOnly this on today:\n{lines}\n{out}"
    if order == "free":
        cue = _pick(rng, ("No particular order for this lot; pack them in however they fit.",
                          "Any order's fine for this load, it all fires together."))
        return f"BISQUE LOAD\n{cue}\n{lines}\n{out}"
    cue = _pick(rng, ("Load strictly in this order, bottom shelf up; swap anything round and the whole firing's "
                      "ruined.", "Strictly in the order written, please, like glaze coats, each over the one before."))
    return f"KILN LOG: glaze firing\n{cue}\n{lines}\n{out}"


def _potter_note(rng, res, order):
    intro = _pick(rng, ("Morning! I'm off at the clay merchant's till lunch, so could you do the studio rounds?",
                        "Morning, love. Throwing all day, hands covered in slip, so over to you for the rounds."))
    out = _pick(rng, ("Ta, Ros", "Muddy thanks, Ros"))
    if order == "single":
        return f"{intro} Just see to {res[0]}. {out}"
    if order == "free":
        cue = _pick(rng, ("Doesn't matter what order you do them in; they all come out of the same firing in the "
                          "end.", "Any order you like, love, no rush."))
        return f"{intro} On the list: {'; '.join(res)}. {cue} {out}"
    sep = _run_on_sep(res)
    parts = [f"Start with {res[0]}"]
    parts += [_pick(rng, ("then {g}", "after that {g}", "next {g}")).format(g=g) for g in res[1:-1]]
    parts.append(f"and finish with {res[-1]}")
    cue = _pick(rng, ("Keep to that order; it's like glaze coats, each goes on over the one before or the lot "
                      "crawls.", "Keep to that order, mind, or it's back to the wedging bench."))
    return f"{intro} {sep.join(parts)}. {cue} {out}"


_LETTERS = "abcdefghijklmnopqrstuvw"


def _letter(i: int) -> str:
    return _LETTERS[i % len(_LETTERS)] * (i // len(_LETTERS) + 1)


def _officer_notice(rng, res, order):
    who = "I, the undersigned, being the Returning Officer for this household, hereby give notice that the robot"
    out = _pick(rng, ("By order of the Returning Officer.", "Dated this day. Signed, the Returning Officer."))
    if order == "single":
        return f"NOTICE OF ROUNDS\n{who} shall attend the following station:\n(a) {res[0]}.\n{out}"
    if order == "free":
        what = (" shall attend each of the stations set out below in whatever order it sees fit; as on a ballot "
                "paper, the order of listing confers no precedence.")
    else:
        what = (" shall attend the stations set out below strictly in the sequence in which they appear, each to "
                "be completed before the next is begun, as ballot boxes are taken for verification.")
    items = "\n".join(f"({_letter(i)}) {g}{';' if i < len(res) - 1 else '.'}" for i, g in enumerate(res))
    return f"{_pick(rng, ('NOTICE OF ROUNDS', 'STATEMENT OF STATIONS TO BE ATTENDED'))}\n{who}{what}\n{items}\n{out}"


_ORDINALS = ("First", "Second", "Third", "Fourth", "Fifth", "Sixth", "Seventh", "Eighth", "Ninth", "Tenth")


def _officer_declaration(rng, res, order):
    who = "I, the Returning Officer for this household, do hereby declare"
    out = _pick(rng, ("I thank the count staff for their patience.", "Thank you all, and good night."))
    if order == "single":
        return f"{who} that the robot shall attend {res[0]}. {out}"
    if order == "free":
        cue = _pick(rng, ("The robot may take them in whatever order it chooses, and no objection shall be "
                          "entertained on that score.", "The sequence of attendance is left wholly to the robot."))
        listing = "; ".join(res)
        return (f"{who} that the robot shall attend the following, in no order of precedence whatsoever: {listing}. "
                f"{cue} {out}")
    lines = [f"{_ORDINALS[i] if i < len(_ORDINALS) else 'Next'}, {g}." for i, g in enumerate(res[:-1])]
    lines.append(f"Lastly, {res[-1]}.")
    cue = _pick(rng, ("The order so declared is final, and no station may be attended out of its turn.",
                      "The order so declared is final and may not be varied."))
    return " ".join([f"{who} the order of attendance as follows.", *lines, cue, out])


def _astronomer_list(rng, res, order):
    head = _pick(rng, ("Observing plan for tonight (house session, seeing permitting)",
                       "Tonight's target list for the bot"))
    stars = "\n".join(f"* {g}" for g in res)
    out = _pick(rng, ("Clear skies!", "Clear skies, and log everything. Dave"))
    if order == "single":
        return f"{head}\nJust a single target tonight:\n{stars}\n{out}"
    if order == "free":
        cue = _pick(rng, ("Everything's well placed all night, so tick them off in any order you like:",
                          "All of these stay up till dawn; any order will do:"))
    else:
        cue = _pick(rng, ("Work through these top to bottom, in exactly this order, before each one sets; no "
                          "skipping ahead:", "Strictly in the order listed, please, or we'll lose them behind "
                          "the rooftops:"))
    return f"{head}\n{cue}\n{stars}\n{out}"


def _astronomer_post(rng, res, order):
    hi = _pick(rng, ("Hi all, seeing's looking steady tonight", "Evening all, transparency's superb tonight"))
    out = _pick(rng, ("Clear skies, Dave", "Clear skies! Dave"))
    if order == "single":
        return f"{hi}, so the bot has a single target: {res[0]}. {out}"
    if order == "free":
        cue = _pick(rng, ("Nothing sets before dawn, so there's no set order; hop between them however you like.",
                          "No set order tonight, take them as they come."))
        return f"{hi}, so here are the bot's targets: {'; '.join(res)}. {cue} {out}"
    parts = [f"start on {res[0]}"]
    parts += [_pick(rng, ("once that's logged, slew across to {g}", "next, {g}", "then {g}")).format(g=g)
              for g in res[1:-1]]
    parts.append(f"and finish up on {res[-1]}")
    cue = _pick(rng, ("Keep to that sequence, please, the sky won't wait for anyone.",
                      "Stick to that order, it's the order they cross the meridian."))
    return f"{hi}, so here's the run for the bot: {'; '.join(parts)}. {cue} {out}"


# (voice, layout, frame); render_instruction_ar draws one of these per whole instruction
FRAMES = (
    ("cricket captain", "dressing-room talk", _cricket_talk),
    ("cricket captain", "team sheet", _cricket_sheet),
    ("studio potter", "kiln-log whiteboard", _potter_board),
    ("studio potter", "note on the wheel", _potter_note),
    ("returning officer", "published notice", _officer_notice),
    ("returning officer", "declaration at the count", _officer_declaration),
    ("amateur astronomer", "observing plan", _astronomer_list),
    ("amateur astronomer", "club chat post", _astronomer_post),
)


def render_instruction_ar(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a village cricket captain, a studio
    potter, an election returning officer, an amateur astronomer), each in one of two layouts. Goals stay in
    visiting order, each written once as rendered; strict texts say the order is fixed ('the batting order's set
    in stone today, nobody pads up out of turn', 'go in exactly as listed, top to bottom, no swaps', 'load
    strictly in this order, bottom shelf up', 'keep to that order', 'strictly in the sequence in which they
    appear', 'the order so declared is final', 'in exactly this order, before each one sets', 'keep to that
    sequence'), free ones say it is open ('the batting order's open', 'no set batting order this week', 'no
    particular order for this lot', 'doesn't matter what order you do them in', 'in whatever order it sees fit',
    'in no order of precedence whatsoever', 'tick them off in any order you like', 'no set order tonight'). A
    single goal gets neither kind of cue; no frame writes a digit."""
    _, _, frame = FRAMES[int(rng.integers(len(FRAMES)))]
    return frame(rng, list(res), "single" if len(res) == 1 else order)
