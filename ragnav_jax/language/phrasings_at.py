"""Held-out sentence set AT (split `unseen_at`): goals, sensor phrases, coordinate hints and whole instructions
written by four new people, to measure fresh how the instruction readers cope with authors nobody tuned them on.

Who wrote it: a helper session (an AI model) started by the project's own session, writing the set cold from a
brief, without reading any instruction reader or any other set's wording.

What it read: the `def` lines and docstrings of the four public functions of phrasings_w.py (printed with an `ast`
script; not their bodies, private helpers or module docstring); types.py and template_text.py whole; the
`UNSEEN_TEMPLATES` dict and `_renderer` of episodes.py and the `EPISODE_SPLITS` tuple of config.py (each printed
alone with `ast`); tests/test_heldout_sets.py whole; the `subgoals` and `targets` strategies and the HEADS, MODS,
STATES and ROOMS constants of tests/test_phrasings_dev8.py (printed alone with `ast`); `[tool.ruff]` of
pyproject.toml; and the value of `types.READINGS` (the ten canonical reading keys), printed at run time.

The voices (one drawn per whole instruction; the voice lives only in the frame round the goals):
- a cafe barista in the morning rush, calling tickets: 'Order up!', 'Tickets in the order they came in, no jumping
  the queue', 'First come, first served, yeah?', 'All one table, so any order you like', 'Ta, you're a star.';
  dashes like a ticket spike, a shouted run-on, or a scribbled First/Then/Last note;
- a tennis chair umpire and tournament referee: 'ORDER OF PLAY', 'none may be brought forward', 'followed by',
  'once that is finished', 'Quiet, please. Players ready? Play.', 'there is no fixed order of play today',
  'PRACTICE COURTS ... whichever comes free', 'Game, set and match';
- a university graduation-ceremony marshal: 'MARSHALS' BRIEFING: THE PROCESSION', 'must not change places', 'first
  to ...; thereafter to ...; and finally to ...', 'no overtaking', 'Mortarboards on, please', 'The photo stations
  may be visited in any order', 'Please be upstanding when the Chancellor enters';
- a pub quiz master: 'Right, settle down, pens at the ready!', 'Sequence round, so order counts', 'Wrong order, no
  points!', 'ANSWER SHEET: TEAM ROBOT' with lettered answers, 'It's a list round, so any order scores', 'No
  phones, no conferring!', 'Jokers at the ready'.
Each has three layouts for a strict order, three for a free one and two for a single goal.

Style guide, in brief: goal wording is one plain-English pool the four share. A goal is 'the' + [a superlative
adjective] + [states, hyphenated] + the target's phrase as given ('the warmest switched-on teal wool lamp');
states may instead follow ('that is switched on') when no room follows the noun and no sensor tail is written. The
room comes straight after the noun ('in the nursery') or before it as a possessive ('the nursery's warmest teal
lamp'), always inside a superlative's scope; then the sensor tail ('whose humidity is forty per cent or less',
'with the highest NDVI'); then the coordinate hint, x then y, numbers exactly as given and no digit after them
('at the point (3.5, 2)'); relations come last ('next to the sofa', ', the one under the shelves'). An anchor's
own relations go in brackets right after it ('the sofa (itself by the toolbox)'), and a second relation of the
target is joined by 'both ... and', ', and also' or 'as well as' with its preposition repeated. Sensor values are
written exactly: the shortest decimal that reads back, or number words for whole numbers under a hundred;
Fahrenheit or kilowatts only when the value converts back exactly, the returned constraint keeping the canonical
value with the unit as written ('f', 'kw'). Carbon dioxide is spelled out. Goals are set off by semicolons, new
lines or sequence words, never by a bare 'and'. Strict texts say in words that the order is fixed, free texts that
it is open; a single goal gets neither; the frame adds no digits.

Tests broken on purpose (tests/test_phrasings_at.py): (1) the barista's ticket-spike layout lost its strict cue
(its whole order clause cut, leaving a bare 'Tickets:'): test_order_cues_in_words failed on it; (2) the 'at x {x},
y {y}' hint was swapped to y then x: test_hint_reads_back_x_then_y and test_goal_writes_every_piece failed. Both
were restored and the tests pass again.

Slips: to find which top-level names of tests/test_phrasings_dev8.py to print, a listing of that file's top-level
definition names and kinds (names only, no bodies or values) was printed; and a plain `ls` of ragnav_jax/language/
and tests/ showed file names. Nothing else of those was read. The value of `types.READINGS` comes from readings.py
through types.py; only the tuple of key names was printed, nothing of readings.py itself. No reader, other set or
forbidden file was opened.
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


# ----------------------------------------------------------------------------------------------------------------
# Goals

_REL = {
    "near": ("near", "close to"),
    "next_to": ("next to", "right next to", "alongside"),
    "beside": ("beside",),
    "by": ("by",),
    "on": ("on", "on top of", "sitting on"),
    "under": ("under", "beneath", "underneath"),
    "above": ("above",),
    "in": ("inside",),
    "with": ("with",),
    "in_room_with": ("in the same room as", "in the room with"),
    "in_front_of": ("in front of",),
    "behind": ("behind",),
    "opposite": ("opposite", "across from", "facing"),
    "left_of": ("to the left of", "left of"),
    "right_of": ("to the right of", "right of"),
}


def _one(head: str) -> str:
    return "the ones" if plural(head) else "the one"


def _anchor(rng: np.random.Generator, t: Target) -> str:
    """An anchor: 'the' + hyphenated states + its phrase, its own relations in brackets right after it."""
    _, states = attributes_and_states(t)
    s = tidy(f"the {hyphenated(states)} {t.phrase}")
    if t.relations:
        leads = [_one(t.head)]
        if not any(r.type == "with" for r in t.relations):
            leads += ["themselves" if plural(t.head) else "itself", f"which {is_are(t.head)}"]
        s += f" ({_pick(rng, tuple(leads))} {_relations(rng, t.relations)})"
    return s


def _relation(rng: np.random.Generator, r: Relation) -> str:
    words = _REL.get(r.type, (r.type.replace("_", " "),))
    return f"{_pick(rng, words)} {_anchor(rng, r.anchor)}"


def _relations(rng: np.random.Generator, rels: tuple[Relation, ...]) -> str:
    parts = [_relation(rng, r) for r in rels]
    if len(parts) == 1:
        return parts[0]
    if len(parts) == 2:
        forms = ["{a}, and also {b}", "{a} as well as {b}"]
        if not any(r.type == "with" for r in rels):
            forms.append("both {a} and {b}")
        return _pick(rng, tuple(forms)).format(a=parts[0], b=parts[1])
    return ", ".join(parts[:-1]) + ", and also " + parts[-1]


def render_goal_at(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AT writes it: 'the warmest switched-on teal wool lamp in the nursery', "the nursery's teal lamp
    that is switched on", 'the drums in the games room whose humidity is forty per cent or less, at the point (3.5,
    2), both next to the sofa (itself by the toolbox) and behind the shelves'. Prefix is a superlative adjective
    written before the noun (after a possessive room); tail a sensor phrase written after the room; hint a
    coordinate hint written after the tail; relations come last."""
    t = sg.target
    _, states = attributes_and_states(t)
    room = sg.room
    possessive = bool(room) and rng.random() < 0.35
    states_after = bool(states) and not tail and not (room and not possessive) and rng.random() < 0.5
    det = f"the {room}'s" if possessive else "the"
    before = "" if states_after else hyphenated(states)
    s = f"{det} {prefix} {before} {t.phrase}"
    if room and not possessive:
        s += f" in the {room}"
    if states_after:
        s += f" that {is_are(t.head)} {both(states)}"
    if tail:
        s += " " + tail
    if hint:
        s += ", " + hint
    if t.relations:
        more = bool(tail or hint or (room and not possessive) or states_after)
        lead = _pick(rng, (", ", f", {_one(t.head)} ") if more else (" ", f", {_one(t.head)} "))
        s += lead + _relations(rng, t.relations)
    return tidy(s)


# ----------------------------------------------------------------------------------------------------------------
# Sensor phrases

# reading -> (name, unit as written when canonical, symbols, words)
_READ = {
    "temperature_c": ("temperature", "c", ("°C", "degrees C"), ("degrees Celsius",)),
    "ndvi": ("NDVI", "", ("",), ("",)),
    "humidity_pct": ("humidity", "%", ("%",), ("per cent", "percent")),
    "co2_ppm": ("carbon dioxide level", "ppm", ("ppm",), ("parts per million",)),
    "noise_db": ("noise level", "db", ("dB",), ("decibels",)),
    "light_lux": ("light level", "lux", ("lux",), ("lux",)),
    "battery_pct": ("battery charge", "%", ("%",), ("per cent", "percent")),
    "power_w": ("power draw", "w", ("W",), ("watts",)),
    "weight_kg": ("weight", "kg", ("kg",), ("kilograms", "kilos")),
    "pressure_hpa": ("air pressure", "hpa", ("hPa",), ("hectopascals",)),
}
# superlative adjectives before the noun: reading -> (for max, for min)
_SUP_ADJ = {
    "temperature_c": (("warmest",), ("coldest", "chilliest")),
    "humidity_pct": (("most humid", "dampest"), ("driest", "least humid")),
    "noise_db": (("noisiest", "loudest"), ("quietest",)),
    "light_lux": (("best-lit", "most brightly lit"), ("dimmest", "most dimly lit")),
    "weight_kg": (("heaviest",), ("least heavy",)),
    "power_w": (("most power-hungry",), ("least power-hungry",)),
}
# superlative tails after the noun beyond 'with the highest/lowest NAME' and 'whose NAME is the highest/lowest'
_SUP_TAIL = {
    "battery_pct": (("with the fullest battery",), ("with the flattest battery",)),
    "weight_kg": (("weighing the most",), ("weighing the least",)),
    "power_w": (("drawing the most power",), ("drawing the least power",)),
}
_CMP = {
    "gt": ("above {v}", "over {v}", "more than {v}", "higher than {v}"),
    "ge": ("at least {v}", "{v} or more", "no less than {v}", "{v} or above"),
    "lt": ("below {v}", "under {v}", "less than {v}", "lower than {v}"),
    "le": ("at most {v}", "{v} or less", "no more than {v}", "{v} or below"),
    "approx": ("about {v}", "around {v}", "roughly {v}", "approximately {v}"),
}
_OF_OK = ("more than", "less than", "at least", "at most", "no ", "about", "around", "roughly", "approx", "{v}")


def _digits(v: float) -> str:
    return np.format_float_positional(float(v), trim="-")


def _fahrenheit(v: float) -> str | None:
    """v °C in °F, when the written number converts back to exactly v."""
    s = _digits(round(v * 9 / 5 + 32, 2))
    return s if (float(s) - 32) * 5 / 9 == v else None


def _kilowatts(v: float) -> str | None:
    """v W in kW, when the written number converts back to exactly v."""
    s = _digits(round(v / 1000, 3))
    return s if float(s) * 1000 == v else None


def _amount(rng: np.random.Generator, v: float, symbols: tuple[str, ...], words: tuple[str, ...]) -> str:
    """A value with its unit: number words for whole numbers under a hundred (sometimes), else digits."""
    use_words = rng.random() < 0.4
    if use_words and float(v).is_integer() and abs(v) < 100:
        return f"{number_words(int(v))} {_pick(rng, words)}".strip()
    sym = _pick(rng, symbols)
    num = _digits(v)
    if sym == "%":
        return num + "%"
    return f"{num} {sym}".strip()


def render_sensor_at(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('warmest', 'most humid', 'quietest', 'heaviest', 'best-lit') or a
    tail ('with the highest NDVI', 'whose carbon dioxide level is the lowest', 'with the flattest battery',
    'drawing the most power'); thresholds after the noun, naming the reading ('whose temperature is above 104 °F',
    'where the humidity reads forty per cent or less', 'with a power draw reading of at least 1.5 kW', 'whose
    NDVI is about 0.65')."""
    name, unit, symbols, words = _READ.get(c.reading, (c.reading.split("_")[0], "", ("",), ("",)))
    if c.comparator in ("max", "min"):
        hi = c.comparator == "max"
        adjs = _SUP_ADJ.get(c.reading)
        if adjs and rng.random() < 0.5:
            return _pick(rng, adjs[0 if hi else 1]), "", SensorConstraint(c.reading, c.comparator, None, "")
        word = "highest" if hi else "lowest"
        tails = [f"with the {word} {name}", f"whose {name} is the {word}"]
        tails += list(_SUP_TAIL.get(c.reading, ((), ()))[0 if hi else 1])
        return "", _pick(rng, tuple(tails)), SensorConstraint(c.reading, c.comparator, None, "")
    v = float(c.value)
    alt = None
    if c.reading == "temperature_c" and rng.random() < 0.3:
        f = _fahrenheit(v)
        if f is not None:
            alt = (float(f), "f", ("°F", "degrees F"), ("degrees Fahrenheit",))
    elif c.reading == "power_w" and rng.random() < 0.4 and abs(v) >= 1000:
        k = _kilowatts(v)
        if k is not None:
            alt = (float(k), "kw", ("kW",), ("kilowatts",))
    if alt is not None:
        v, unit, symbols, words = alt
    amount = _amount(rng, v, symbols, words)
    an = "an" if name in ("NDVI", "air pressure") else "a"
    form = _pick(rng, ("whose {name} is {cv}", "where the {name} reads {cv}", "with " + an + " {name} reading of {cv}"))
    options = _CMP.get(c.comparator, ("{v}",))
    if "reading of" in form:
        options = tuple(o for o in options if o.startswith(_OF_OK)) or options
    cv = _pick(rng, options).format(v=amount)
    tail = form.format(name=name, cv=cv)
    return "", tail, SensorConstraint(c.reading, c.comparator, c.value, unit)


# ----------------------------------------------------------------------------------------------------------------
# Coordinate hints

_HINTS = ("at x {x}, y {y}", "at the point ({x}, {y})", "at coordinates x = {x}, y = {y}", "around x {x} and y {y}",
          "at {x} metres along x and {y} metres along y", "at the spot where x is {x} and y is {y}")


def hint_text_at(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y, numbers exactly as given: 'at x 3.5, y 2', 'at
    the point (3.5, 2)', 'at coordinates x = 3.5, y = 2', 'around x 3.5 and y 2', 'at 3.5 metres along x and 2
    metres along y', 'at the spot where x is 3.5 and y is 2'."""
    return _pick(rng, _HINTS).format(x=x, y=y)


# ----------------------------------------------------------------------------------------------------------------
# Whole instructions: four people, each with strict, free and single-goal layouts


def _lines(res: list[str], mark: str) -> str:
    return "\n".join(mark + g for g in res)


def _ended(res: list[str], mid: str, last: str) -> str:
    return "\n".join(g + (last if i == len(res) - 1 else mid) for i, g in enumerate(res))


_CAFE_OPEN = ("Order up!", "Right, here's the run, love.", "Rush is on, so listen up.",
              "Morning! Grinder's going, so quick one.")
_CAFE_BYE = ("Ta!", "Cheers, lovely.", "Shout when you're done.", "Ta, you're a star.")


def _cafe(rng: np.random.Generator, res: list[str], kind: str) -> tuple[int, str]:
    op, bye = _pick(rng, _CAFE_OPEN), _pick(rng, _CAFE_BYE)
    if kind == "single":
        i = int(rng.integers(2))
        return i, (f"{op} Just the one ticket: {res[0]}. {bye}",
                   f"Quiet spell, only the one ticket:\n— {res[0]}\n{bye}")[i]
    i = int(rng.integers(3))
    if kind == "strict":
        if i == 0:
            return i, f"{op} Tickets in the order they came in, no jumping the queue:\n{_lines(res, '— ')}\n{bye}"
        if i == 1:
            return i, f"{op} Oldest ticket first: {'; then '.join(res)}. First come, first served, yeah? {bye}"
        marks = ["First: "] + ["Then: "] * (len(res) - 2) + ["Last: " if len(res) > 2 else "Then: "]
        body = "\n".join(m + g for m, g in zip(marks, res))
        return i, f"Swamped here! Do me a run, oldest ticket first and nothing pulled early?\n{body}\n{bye}"
    if i == 0:
        return i, f"{op} All one table, so any order you like:\n{_lines(res, '— ')}\n{bye}"
    if i == 1:
        return i, f"{op} No queue on these, grab them in whatever order suits: {'; '.join(res)}. {bye}"
    return i, ("Big table, this one, and it all goes out together, so the order doesn't matter a jot.\n"
               f"{_lines(res, '• ')}\n{bye}")


def _umpire(rng: np.random.Generator, res: list[str], kind: str) -> tuple[int, str]:
    if kind == "single":
        i = int(rng.integers(2))
        return i, (f"Quiet, please. One match only: {res[0]}. Players ready? Play.",
                   f"TODAY ON COURT\n{res[0]}\nGame, set and match. Thank you.")[i]
    i = int(rng.integers(3))
    if kind == "strict":
        if i == 0:
            body = "\n".join(g if j == 0 else "followed by " + g for j, g in enumerate(res))
            return i, ("ORDER OF PLAY\nMatches in the order listed; none may be brought forward.\n"
                       f"{body}\nQuiet, please. Players ready? Play.")
        if i == 1:
            return i, ("Quiet, please. Ladies and gentlemen, the robot's schedule today is fixed, match after match: "
                       f"{'; followed by '.join(res)}. No changes to the order of play. Thank you.")
        rest = "; ".join("once that is finished, " + g for g in res[1:])
        return i, (f"From the referee's desk: the order of play is fixed today. Begin with {res[0]}; {rest}. "
                   "Game, set and match. Thank you.")
    if i == 0:
        return i, ("PRACTICE COURTS\nThe following may be taken in any order, whichever comes free:\n"
                   f"{_lines(res, '')}\nKeep sessions short, please. Thank you.")
    if i == 1:
        return i, ("Quiet, please. There is no fixed order of play today; the robot may take these on in any "
                   f"order it likes: {'; '.join(res)}. Players ready. Play.")
    return i, ("Referee's note: these are unscheduled, so there is no order of play to keep to. Call them on as "
               f"you please.\n{_lines(res, '– ')}\nThank you, ladies and gentlemen.")


def _marshal(rng: np.random.Generator, res: list[str], kind: str) -> tuple[int, str]:
    if kind == "single":
        i = int(rng.integers(2))
        return i, (f"MARSHAL'S NOTE\nA single presentation this afternoon: {res[0]}.\n"
                   "Please be upstanding when the Chancellor enters.",
                   f"Good afternoon, graduands. Just the one stop for the robot today: {res[0]}. Congratulations!")[i]
    i = int(rng.integers(3))
    if kind == "strict":
        if i == 0:
            return i, ("MARSHALS' BRIEFING: THE PROCESSION\nThe robot will process in the order printed below and "
                       f"must not change places.\n{_lines(res, '• ')}\n"
                       "Please be upstanding. Congratulations to all our graduates.")
        if i == 1:
            steps = [f"first to {res[0]}"] + [f"thereafter to {g}" for g in res[1:-1]] + [f"and finally to {res[-1]}"]
            return i, ("Good afternoon, graduands, and welcome. The robot leads the procession: "
                       f"{'; '.join(steps)}. Please keep your places in the procession, no overtaking. "
                       "Mortarboards on, please.")
        return i, ("Order of procession (please keep strictly to it):\n"
                   f"{_ended(res, ', then', '.')}\nThe ceremony begins promptly; do not be late.")
    if i == 0:
        return i, ("AFTER THE CEREMONY: PHOTOGRAPHS\nThe photo stations may be visited in any order; there is no "
                   f"queue to keep to.\n{_lines(res, '• ')}\nCongratulations once again to all our graduates.")
    if i == 1:
        return i, ("Good afternoon. The reception has no fixed running order, so the robot may circulate as it "
                   f"pleases: {'; '.join(res)}. Congratulations, graduates!")
    return i, ("Marshal's note: for the drinks reception, call in at these in whatever order you like.\n"
               f"{_ended(res, ';', '.')}\nDo enjoy the afternoon.")


def _letter(i: int) -> str:
    return chr(ord("A") + i) if i < 26 else chr(ord("A") + i // 26 - 1) + chr(ord("A") + i % 26)


def _quiz(rng: np.random.Generator, res: list[str], kind: str) -> tuple[int, str]:
    if kind == "single":
        i = int(rng.integers(2))
        return i, (f"Tie-breaker, folks, just the one question: {res[0]}. Pens down after that!",
                   f"ANSWER SHEET: TEAM ROBOT\nBonus question:\n{res[0]}\nSheets in when you're done, please!")[i]
    i = int(rng.integers(3))
    if kind == "strict":
        if i == 0:
            return i, ("Right, settle down, pens at the ready! Sequence round, so order counts: they go in the "
                       f"order I read them out.\n{_ended(res, '.', '.')}\nNo phones, no conferring!")
        if i == 1:
            body = "\n".join(f"{_letter(j)}) {g}" for j, g in enumerate(res))
            return i, ("ANSWER SHEET: TEAM ROBOT\nSequence round. Answers only score in the order written, no "
                       f"swapping.\n{body}\nSheets in when you're done, please!")
        return i, ("Okay folks, quickfire sequence round, and the order matters: "
                   f"{'; then '.join(res)}. Wrong order, no points! Jokers at the ready.")
    if i == 0:
        return i, ("Right, pens at the ready! It's a list round, so any order scores.\n"
                   f"{_ended(res, '.', '.')}\nNo phones, no conferring!")
    if i == 1:
        return i, ("ANSWER SHEET: TEAM ROBOT\nList round. Order doesn't matter, just get them all.\n"
                   f"{_lines(res, '• ')}\nSheets in when you're done, please!")
    return i, ("Okay folks, bonus round, and you can take these in any order you fancy: "
               f"{'; '.join(res)}. Points for the lot, whichever you get to first. Jokers at the ready!")


VOICES = {"barista": _cafe, "umpire": _umpire, "marshal": _marshal, "quizmaster": _quiz}


def _compose(rng: np.random.Generator, res: list[str], order: str) -> tuple[str, str, int, str]:
    """(voice, 'strict' | 'free' | 'single', layout index, text): what render_instruction_at writes, and how."""
    voice = _pick(rng, tuple(VOICES))
    kind = "single" if len(res) == 1 else ("strict" if order == "strict" else "free")
    layout, text = VOICES[voice](rng, list(res), kind)
    return voice, kind, layout, text


def render_instruction_at(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a cafe barista calling tickets, a tennis
    umpire, a graduation-ceremony marshal, a pub quiz master). Goals stay in visiting order, each written once as
    rendered, set off by new lines, semicolons or sequence words; strict texts say the order is fixed ('in the
    order they came in', 'no jumping the queue', 'none may be brought forward', 'must not change places', 'order
    counts'), free ones that it is open ('any order you like', 'no fixed order of play', 'may be visited in any
    order', 'any order scores'). A single goal gets neither kind of cue; the frame writes no digit."""
    return _compose(rng, res, order)[3]
