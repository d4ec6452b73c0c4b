"""Held-out sentence set AV: goal, sensor, coordinate and instruction templates for the `unseen_av` split.

Who wrote it. A helper session started by the project, told to write a held-out set without reading any
instruction reader or any other set's wording. It read only: the `def` lines and docstrings of the four public
functions of phrasings_w.py (to learn the signatures and what each returns), language/types.py and
language/template_text.py whole, `UNSEEN_TEMPLATES` and `_renderer` of language/episodes.py, `EPISODE_SPLITS` of
config.py, tests/test_heldout_sets.py whole, the `subgoals` and `targets` strategies and the HEADS, MODS, STATES and
ROOMS constants of tests/test_phrasings_dev8.py, `[tool.ruff]` of pyproject.toml, and the value of `types.READINGS`
printed at run time.

The four voices (one is drawn per whole instruction; each has three layouts and a strict, a free and a one-goal
form; strict and free texts say in words that the order is fixed or open, a single goal gets neither):
  - a butler briefing the footman: a spoken word in the servants' hall, a duty sheet, a note pinned up for him;
  - a beekeeper on the apiary round: inspection notes, a mentor talking a novice through it, a round card;
  - a floor trader: an order ticket with legs, a shout across the trading floor, a morning note to the team;
  - a newspaper night editor sending a reporter out: an assignment memo, a word across the newsroom, a running
    list for the edition.
Frames add no digits; a strict list counts with ordinal words, a free list uses bullets.

The style of a goal (render_goal_av). The parts always stand in this order: the core noun phrase, then a state or
room clause, then the sensor tail, then the coordinate hint, then the relations. The core is "the", then the room
as a possessive when it is written there ("the nursery's ..."), then a superlative sensor adjective, then states
hyphenated before the noun when they are written there, then the attributes in the phrase's order, then the head;
or the head alone with the attributes after it in brackets ("... (the teal wool one)"). States otherwise follow the
noun in a relative clause (which carries the room too when the room follows the noun) or in brackets; a room not
written as a possessive follows the noun as "in the <room>". After the first post-noun part, each further part
(sensor tail, hint, relations) is set off with a comma. Relations are joined with "and" (commas before the last
when three or more); an anchor's own relations stand in brackets right after it, so nesting is never ambiguous.
A relation "in" is always written "inside" so it cannot be read as a room. Sensor numbers always come before the
hint, so a goal's last two numbers are the hint's x then y, written exactly as given.

Sensors (render_sensor_av): thresholds read "whose <reading> is <cmp> N", "where the <reading> reads <cmp> N" or
"with a <reading> of <cmp> N"; superlatives are an adjective before the noun ("hottest", "driest") or a tail
naming the highest or lowest reading. Numbers are digits, digits with a thousands comma, "minus N", or number words
for whole numbers; units vary (degrees Celsius or Fahrenheit, per cent or %, watts or kilowatts, kg or kilos, ...),
and another unit is written only when the number converts back to the canonical value exactly.

Tests broken on purpose (tests/test_phrasings_av.py says how they failed): (1) the trader's free ticket layout was
made to print its strict execution line; (2) render_goal_av was made to put the hint before the sensor tail. Both
were restored.

Slips. While locating the permitted pieces with grep, some lines outside them were printed: (a) the first line of
phrasings_w.py's module docstring and the first docstring lines of its private helpers `_anchor_np`, `_goal_np`,
`_nought_words`, `_number`, `_list`, `_comma`, `_cook`, `_keeper`, `_lawyer` and `_commentator` (their one-line
summaries, with a few of set W's example words: an anchor's state written '(found open)' when it has no relations,
'of the teal and wool kind', 'nought point six five', number formats such as '22,5', '.65' and 'minus 4', 'A, B
and C' against 'A, and also B', and that its voices were a cookery host, a lighthouse keeper, a lawyer and a
football commentator); (b) the `def` lines and top-level constant lines of language/episodes.py, including the
start of `FRAMES`, `REL_TEXT`, `_SUPER_ADJ`, `_CMP_WORDS` (gt: 'above', 'over', 'higher than', 'more than',
'greater than'), `VERBS` ('go to', 'visit', 'find', 'check', 'head over to', 'walk to', 'take me to', 'navigate
to', 'head to') and `POLITE`, and `MODALITIES`; one line of config.py that checks `episodes.split`; (c) the `def`,
constant and import lines of tests/test_phrasings_dev8.py, including the start of its `REL_WORDS`, `_UNITS`,
`_TENS`, `_VALUES` and the first line of its `STRICT_CUES` and `FREE_CUES` regexes (words such as 'first', 'then',
'in that order', 'after that', 'lastly', 'any order', "order doesn't matter", 'not fussy', 'whichever order');
(d) the first thirty lines of tests/conftest.py (environment set-up and the hypothesis profiles). No reader code
was seen. This set's wording was written without copying any of it; where a plain English word such as "first"
or "above" also stands there, it is here because people write it. One likeness to note: this set, too, writes a
plain anchor's state in brackets after it ("the drums (open)"); it was written that way to keep an anchor's
state from reading as a clause on the goal, but it was written after (a) was seen.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.template_text import attributes_and_states, both, hyphenated, is_are, number_words, plural
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target


def _pick(rng, items):
    """One item, drawn from the generator passed in."""
    return items[int(rng.integers(len(items)))]


# ----------------------------------------------------------------------------------------------------
# Goals

REL_WORDS = {
    "near": ("near", "close to"),
    "next_to": ("next to", "alongside"),
    "beside": ("beside",),
    "by": ("by",),
    "on": ("on", "on top of", "sitting on"),
    "under": ("under", "beneath", "below"),
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


def _and(parts: list[str]) -> str:
    """'a', 'a and b', 'a, b and c'."""
    if len(parts) <= 1:
        return "".join(parts)
    return ", ".join(parts[:-1]) + " and " + parts[-1]


def _one(head: str) -> str:
    return "ones" if plural(head) else "one"


def _anchor(rng, t: Target, depth: int = 1) -> str:
    """An anchor: states hyphenated and attributes before its noun (states in brackets after it for a plain anchor
    not itself in brackets); its own relations in brackets after it."""
    pre, states = attributes_and_states(t)
    rels = _relations(rng, t.relations, depth + 1)
    if states and not rels and depth == 1 and _pick(rng, (True, False)):
        return " ".join(("the", *pre, t.head)) + f" ({both(states)})"
    words = ["the"] + ([hyphenated(states)] if states else []) + pre + [t.head]
    np_ = " ".join(words)
    if rels:
        lead = _pick(rng, (f"the {_one(t.head)}", f"which {is_are(t.head)}"))
        np_ += f" ({lead} {rels})"
    return np_


def _relations(rng, rels: tuple[Relation, ...], depth: int = 1) -> str:
    return _and([f"{_pick(rng, REL_WORDS[r.type])} {_anchor(rng, r.anchor, depth)}" for r in rels])


def _fmt(v: float) -> str:
    """A number in plain digits, no exponent and no trailing zeros: 40.0 -> '40', 0.65 -> '0.65'."""
    return np.format_float_positional(float(v), trim="-")


def render_goal_av(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AV writes it: core noun phrase, then a state or room clause, then the sensor tail, then the
    coordinate hint, then the relations (see the module docstring). `prefix` is a superlative adjective written
    before the noun, `tail` a sensor phrase after it, `hint` a coordinate hint; a sensor or location the subgoal
    has but no prefix, tail or hint was given for is written here in canonical units and plain digits."""
    t = sg.target
    pre, states = attributes_and_states(t)
    v = is_are(t.head)
    if not prefix and not tail and sg.sensors:
        tail = " and ".join(_sensor_plain(c) for c in sg.sensors)
    if not hint and sg.location is not None:
        hint = hint_text_av(rng, _fmt(sg.location.x), _fmt(sg.location.y))
    room = sg.room
    room_mode = _pick(rng, ("poss", "after", "after")) if room else ""
    attr_mode = _pick(rng, ("front", "front", "after")) if pre and not prefix else "front"
    state_mode = ""
    if states:
        state_mode = _pick(rng, ("hyph", "clause", "paren") if attr_mode == "front" else ("hyph", "clause"))

    core = ["the"]
    if room_mode == "poss":
        core.append(f"{room}'s")
    if prefix:
        core.append(prefix)
    if state_mode == "hyph":
        core.append(hyphenated(states))
    if attr_mode == "front":
        core += pre
    core.append(t.head)
    text = " ".join(core)
    if attr_mode == "after":
        text += f" (the {' '.join(pre)} {_one(t.head)})"

    posts = []
    if state_mode == "clause" and room_mode == "after":
        posts.append(f"that {v} in the {room} and {both(states)}")
    else:
        first = ""
        if state_mode == "clause":
            first = f"that {v} {both(states)}"
        elif state_mode == "paren":
            first = f"({both(states)} at the moment)"
        if room_mode == "after":
            first = (first + " " if first else "") + f"in the {room}"
        if first:
            posts.append(first)
    if tail:
        posts.append(tail)
    if hint:
        posts.append(hint)
    if t.relations:
        posts.append(_relations(rng, t.relations))
    if posts:
        text += " " + posts[0] + "".join(", " + p for p in posts[1:])
    return text


# ----------------------------------------------------------------------------------------------------
# Sensors

NOUNS = {
    "temperature_c": ("temperature",),
    "ndvi": ("NDVI", "NDVI reading"),
    "humidity_pct": ("humidity", "relative humidity"),
    "co2_ppm": ("carbon dioxide level", "carbon dioxide reading"),
    "noise_db": ("noise level", "sound level"),
    "light_lux": ("light level", "illuminance"),
    "battery_pct": ("battery charge", "battery level"),
    "power_w": ("power draw", "power consumption"),
    "weight_kg": ("weight",),
    "pressure_hpa": ("air pressure", "barometric pressure"),
}
# superlative adjectives written before the noun: (highest, lowest)
SUPER_ADJ = {
    "temperature_c": (("hottest", "warmest"), ("coldest", "coolest")),
    "humidity_pct": (("most humid", "dampest"), ("driest", "least humid")),
    "noise_db": (("loudest", "noisiest"), ("quietest",)),
    "light_lux": (("brightest", "best-lit"), ("darkest", "dimmest")),
    "weight_kg": (("heaviest",), ()),
    "power_w": (("most power-hungry",), ("least power-hungry",)),
}
# comparator phrases: (phrases that read after "is"/"reads", phrases that also read after "of"); N stands for the number
CMP = {
    "gt": ("above N", "over N", "more than N", "higher than N"),
    "lt": ("below N", "under N", "less than N", "lower than N"),
    "ge": ("at least N", "N or more", "no less than N", "N or higher"),
    "le": ("at most N", "N or less", "no more than N", "N or lower"),
    "approx": ("about N", "around N", "roughly N", "approximately N"),
}
CMP_OF = {
    "gt": ("more than N",),
    "lt": ("less than N",),
    "ge": ("at least N", "N or more"),
    "le": ("at most N", "N or less"),
    "approx": ("about N", "around N", "roughly N"),
}
# unit forms per reading: (text after the number, its singular, unit code, factor: canonical = written * factor)
UNITS = {
    "temperature_c": ((" °C", " °C", "c", 1), ("°C", "°C", "c", 1), (" degrees Celsius", " degree Celsius", "c", 1),
                      (" degrees C", " degree C", "c", 1)),
    "ndvi": (("", "", "", 1),),
    "humidity_pct": (("%", "%", "%", 1), (" per cent", " per cent", "%", 1), (" percent", " percent", "%", 1)),
    "co2_ppm": ((" ppm", " ppm", "ppm", 1), (" parts per million", " part per million", "ppm", 1)),
    "noise_db": ((" dB", " dB", "db", 1), (" decibels", " decibel", "db", 1)),
    "light_lux": ((" lux", " lux", "lux", 1), (" lx", " lx", "lux", 1)),
    "battery_pct": (("%", "%", "%", 1), (" per cent", " per cent", "%", 1), (" percent", " percent", "%", 1)),
    "power_w": ((" W", " W", "w", 1), (" watts", " watt", "w", 1), (" kW", " kW", "kw", 1000),
                (" kilowatts", " kilowatt", "kw", 1000)),
    "weight_kg": ((" kg", " kg", "kg", 1), (" kilograms", " kilogram", "kg", 1), (" kilos", " kilo", "kg", 1)),
    "pressure_hpa": ((" hPa", " hPa", "hpa", 1), (" hectopascals", " hectopascal", "hpa", 1)),
}
FAHRENHEIT = ((" °F", " °F"), (" degrees Fahrenheit", " degree Fahrenheit"))
# a unit written as a symbol, spelled out after a number in words ("forty per cent", not "forty %")
SPELLED = {" °C": (" degrees Celsius", " degree Celsius"), "°C": (" degrees Celsius", " degree Celsius"),
           "%": (" per cent", " per cent"), " dB": (" decibels", " decibel"), " kg": (" kilograms", " kilogram"),
           " lx": (" lux", " lux")}
WORDS_OK = ("temperature_c", "humidity_pct", "battery_pct", "noise_db", "weight_kg", "light_lux")


def _article(noun: str) -> str:
    return "an" if noun[0] in "aeiouAEIOU" or noun.startswith("NDVI") else "a"


def _digits(rng, x: float) -> str:
    """Digits for a written number: a thousands comma sometimes, 'minus' for a negative sometimes."""
    s = _fmt(abs(x))
    whole, dot, frac = s.partition(".")
    if len(whole) > 3 and _pick(rng, (True, False)):
        groups = []
        while len(whole) > 3:
            groups.insert(0, whole[-3:])
            whole = whole[:-3]
        whole = ",".join([whole, *groups])
    s = whole + dot + frac
    if x < 0:
        s = _pick(rng, ("-", "minus ")) + s
    return s


def _exact_f(c: float) -> str | None:
    """Fahrenheit digits that convert back to c exactly, or None."""
    f = round(c * 9 / 5 + 32, 1)
    txt = _fmt(f)
    back = float(txt)
    if (back - 32) * 5 / 9 == c and (back - 32) / 1.8 == c:
        return txt
    return None


def _number(rng, reading: str, value: float) -> tuple[str, str, float]:
    """(the number and its unit as written, unit code, the value converted back to canonical units)."""
    forms = list(UNITS[reading])
    if reading == "temperature_c" and _exact_f(value) is not None and rng.random() < 0.3:
        txt = _exact_f(value)
        after, single = _pick(rng, FAHRENHEIT)
        back = (float(txt) - 32) * 5 / 9
        num = _digits(rng, float(txt))
        return num + (single if float(txt) == 1 else after), "f", back
    after, single, code, factor = _pick(rng, forms)
    written = value / factor
    if factor != 1 and (float(_fmt(written)) * factor != value or abs(written) < 0.1):
        after, single, code, factor = forms[0]
        written = value
    back = float(_fmt(written)) * factor
    if (reading in WORDS_OK and float(written).is_integer() and abs(written) < 1000 and factor == 1
            and rng.random() < 0.25):
        num = number_words(int(written))
        after, single = SPELLED.get(after, (after, single))
    else:
        num = _digits(rng, written)
    return num + (single if abs(written) == 1 else after), code, back


def render_sensor_av(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun where the reading has one ('hottest', 'driest', 'loudest') or a tail
    ('with the highest NDVI', 'whose air pressure is the lowest'); thresholds: a tail naming the reading, a
    comparison and a number with its unit ('whose temperature is at least 104 °F', 'where the humidity reads
    forty per cent or less', 'with a power draw of more than 1.5 kW')."""
    noun = _pick(rng, NOUNS[c.reading])
    if c.comparator in ("max", "min"):
        hi = c.comparator == "max"
        adjs = SUPER_ADJ.get(c.reading, ((), ()))[0 if hi else 1]
        word = "highest" if hi else "lowest"
        if adjs and _pick(rng, (True, False)):
            return _pick(rng, adjs), "", SensorConstraint(c.reading, c.comparator, None, "")
        tail = _pick(rng, (f"with the {word} {noun}", f"whose {noun} is the {word}", f"whose {noun} is {word}"))
        return "", tail, SensorConstraint(c.reading, c.comparator, None, "")
    num, code, back = _number(rng, c.reading, float(c.value))
    frame = int(rng.integers(3))
    if frame == 2:
        phr = _pick(rng, CMP_OF[c.comparator]).replace("N", num)
        tail = f"with {_article(noun)} {noun} of {phr}"
    else:
        phr = _pick(rng, CMP[c.comparator]).replace("N", num)
        # "reads" wants the plain noun: "where the NDVI reads ...", not "where the NDVI reading reads ..."
        tail = f"whose {noun} is {phr}" if frame == 0 else f"where the {NOUNS[c.reading][0]} reads {phr}"
    return "", tail, SensorConstraint(c.reading, c.comparator, back, code)


def _sensor_plain(c: SensorConstraint) -> str:
    """A constraint in canonical units and plain digits, for a subgoal whose sensor came with no phrase."""
    noun = NOUNS[c.reading][0]
    if c.comparator in ("max", "min"):
        return f"with the {'highest' if c.comparator == 'max' else 'lowest'} {noun}"
    after, single = UNITS[c.reading][0][:2]
    num = _fmt(c.value) + (single if abs(c.value) == 1 else after)
    return f"whose {noun} is {CMP[c.comparator][0].replace('N', num)}"


# ----------------------------------------------------------------------------------------------------
# Coordinate hints

HINTS = ("at coordinates ({x}, {y})", "at x = {x} m, y = {y} m", "where x is {x} and y is {y}",
         "at map point x {x} / y {y}")


def hint_text_av(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y, the numbers exactly as given: 'at coordinates (x, y)',
    'at x = X m, y = Y m', 'where x is X and y is Y', 'at map point x X / y Y'."""
    return _pick(rng, HINTS).format(x=x, y=y)


# ----------------------------------------------------------------------------------------------------
# Whole instructions: four voices, each with three layouts

ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth",
            "eleventh", "twelfth")

# what each voice says about the order: the tests check that a strict text holds one of its strict cues and no
# free cue, a free text the reverse, and a one-goal text neither.
CUES = {
    "butler": {
        "strict": ("take them in precisely the order I have set them down",
                   "strictly in the sequence given, and not otherwise", "one after another, exactly as listed"),
        "free": ("the sequence is entirely at your discretion", "I have no preference as to the sequence",
                 "take them in whatever sequence you find convenient"),
    },
    "beekeeper": {
        "strict": ("keep to this order, no skipping ahead", "work them in the order written, like boxes down a row",
                   "the order here is fixed"),
        "free": ("the order is up to you", "no fixed order to it", "go round them however suits the bees"),
    },
    "trader": {
        "strict": ("strictly sequential, top of the ticket down", "in exactly this sequence, no leg jumps the queue",
                   "no leg goes before the one ahead of it is filled"),
        "free": ("sequence discretionary, no priority between legs", "fill them in whatever sequence the market allows",
                 "no leg has priority over another"),
    },
    "editor": {
        "strict": ("stick to this running order", "cover them in the order they run on the page plan",
                   "the running order is fixed"),
        "free": ("the order you cover them in is your call", "no particular order, it all goes in the same edition",
                 "chase them in whatever order you like"),
    },
}


def _cue(rng, voice: str, order: str) -> str:
    return _pick(rng, CUES[voice][order])


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _has_comma(res: list[str]) -> bool:
    """Whether a goal has commas or an "and" of its own, so goals must be set apart with semicolons."""
    return any("," in r or " and " in r for r in res)


def _series(res: list[str], last: str = "and") -> str:
    """Goals in a running sentence: 'A, B and C', or 'A; B; and C' once a goal has a comma or an "and" of its own."""
    if len(res) == 1:
        return res[0]
    if len(res) == 2:
        return f"{res[0]} {last} {res[1]}" if not _has_comma(res) else f"{res[0]}; {last} {res[1]}"
    if _has_comma(res):
        return "; ".join(res[:-1]) + f"; {last} " + res[-1]
    return ", ".join(res[:-1]) + f" {last} " + res[-1]


def _chain(res: list[str], between: str, final: str) -> str:
    """A strict running sentence: 'A; <between> B; <final> C' (commas when no goal has a comma or an "and")."""
    sep = "; " if _has_comma(res) else ", "
    out = res[0]
    for i, r in enumerate(res[1:], start=1):
        out += sep + (final if i == len(res) - 1 else between) + " " + r
    return out


def _ordinal(i: int) -> str:
    return ORDINALS[i] if i < len(ORDINALS) else "next"


def _butler(rng, res: list[str], order: str, layout: int) -> str:
    """A butler briefing the footman: a spoken word, a duty sheet, or a note pinned up for him."""
    one = len(res) == 1
    if layout == 0:
        open_ = _pick(rng, ("A word, if you please, before you begin your rounds.",
                            "A moment of your time before you go about the house, if you would."))
        close = _pick(rng, ("That will be all.", "Very good. That will be all.", "Do try not to dawdle."))
        if one:
            return f"{open_} You will kindly attend to {res[0]}. {close}"
        if order == "strict":
            body = "You will attend to " + _chain(res, "thereafter", "and finally")
        else:
            body = "You will attend to " + _series(res)
        return f"{open_} {body}. {_cap(_cue(rng, 'butler', order))}. {close}"
    if layout == 1:
        head = _pick(rng, ("Duties for the footman", "Footman's duties, this morning", "The footman's duties"))
        if one:
            return f"{head}:\n- {res[0]}.\nReport to me when it is done."
        if order == "strict":
            lines = [f"{_cap(_ordinal(i))}, {r}." for i, r in enumerate(res)]
        else:
            lines = [f"- {r}." for r in res]
        cue = _cap(_cue(rng, "butler", order))
        return f"{head}:\n" + "\n".join(lines) + f"\n{cue}.\nReport to me when they are done."
    sign = _pick(rng, ("the butler", "your butler", "Butler"))
    if one:
        return f"Footman,\nKindly see to {res[0]}.\nWith thanks, {sign}"
    if order == "strict":
        body = _chain(res, "then", "and lastly")
    else:
        body = _series(res)
    return f"Footman,\nKindly see to {body}.\n{_cap(_cue(rng, 'butler', order))}.\nWith thanks, {sign}"


def _beekeeper(rng, res: list[str], order: str, layout: int) -> str:
    """A beekeeper on the apiary round: inspection notes, a mentor talking a novice through it, or a round card."""
    one = len(res) == 1
    if layout == 0:
        head = _pick(rng, ("Apiary round. Smoker lit, veil on.", "Round notes: calm day, bees gentle.",
                           "Apiary round, warm and still."))
        if one:
            return f"{head}\nThe one stop today: {res[0]}.\nClose up gently."
        cue = _cap(_cue(rng, "beekeeper", order))
        if order == "strict":
            lines = [f"{_cap(_ordinal(i))} stop: {r}." for i, r in enumerate(res)]
        else:
            lines = [f"Stop: {r}." for r in res]
        return f"{head}\n{cue}.\n" + "\n".join(lines) + "\nClose up gently."
    if layout == 1:
        open_ = _pick(rng, ("Right, suit up and stay calm, they can smell nerves.",
                            "Gloves on, slow hands, no sudden moves."))
        close = _pick(rng, ("And don't swat.", "Mind the guard bees.", "Easy does it."))
        if one:
            return f"{open_} We're only looking in on {res[0]} today. {close}"
        if order == "strict":
            body = "We're looking in on " + _chain(res, "moving on to", "and finishing at")
        else:
            body = "We're looking in on " + _series(res)
        return f"{open_} {body}. {_cap(_cue(rng, 'beekeeper', order))}. {close}"
    head = _pick(rng, ("ROUND CARD", "Hive round card", "APIARY ROUND CARD"))
    if one:
        return f"{head}\nStop: {res[0]}\nQueen seen? Note it on the back."
    lines = [f"Stop: {r}" for r in res]
    cue = _cue(rng, "beekeeper", order)
    return f"{head}\n" + "\n".join(lines) + f"\nOrder: {cue}.\nQueen seen? Note it on the back."


def _trader(rng, res: list[str], order: str, layout: int) -> str:
    """A floor trader: an order ticket with legs, a shout across the trading floor, or a morning note."""
    one = len(res) == 1
    if layout == 0:
        head = _pick(rng, ("ORDER TICKET", "Order ticket", "TICKET"))
        if one:
            return f"{head}\nSide: visit\nLeg: {res[0]}\nGood till filled."
        if order == "strict":
            lines = [f"{_cap(_ordinal(i))} leg: {r}" for i, r in enumerate(res)]
        else:
            lines = [f"Leg: {r}" for r in res]
        cue = _cap(_cue(rng, "trader", order))
        return f"{head}\nSide: visit\n" + "\n".join(lines) + f"\nExecution: {cue}.\nGood till filled."
    if layout == 1:
        open_ = _pick(rng, ("Listen up, floor!", "Heads up, everyone!", "Eyes on me, team!"))
        close = _pick(rng, ("Go, go, go!", "Move it!", "Let's trade!"))
        if one:
            return f"{open_} Just the one: get me to {res[0]}! {close}"
        if order == "strict":
            body = "Get me to " + _chain(res, "after it", "and after that")
        else:
            body = "Get me to " + _series(res)
        return f"{open_} {body}! {_cap(_cue(rng, 'trader', order))}! {close}"
    head = _pick(rng, ("Morning note.", "Morning note to the team.", "Pre-open note."))
    close = _pick(rng, ("Stay nimble.", "Trade safe.", "No heroics."))
    if one:
        return f"{head} One position on the blotter today: {res[0]}. {close}"
    body = _chain(res, "then", "and finally") if order == "strict" else _series(res)
    return f"{head} On the blotter today: {body}. {_cap(_cue(rng, 'trader', order))}. {close}"


def _editor(rng, res: list[str], order: str, layout: int) -> str:
    """A newspaper night editor sending a reporter out: a memo, a word across the newsroom, or a running list."""
    one = len(res) == 1
    if layout == 0:
        head = _pick(rng, ("ASSIGNMENT\nFrom: night editor", "ASSIGNMENT", "Assignment, night shift"))
        close = _pick(rng, ("File before deadline.", "Copy to me before we go to press.", "Keep it tight."))
        if one:
            return f"{head}\nStory: {res[0]}\n{close}"
        if order == "strict":
            lines = [f"{_cap(_ordinal(i))} story: {r}" for i, r in enumerate(res)]
        else:
            lines = [f"Story: {r}" for r in res]
        cue = _cap(_cue(rng, "editor", order))
        return f"{head}\n" + "\n".join(lines) + f"\nOrder: {cue}.\n{close}"
    if layout == 1:
        open_ = _pick(rng, ("Grab your coat.", "You, yes you, grab your coat.", "Coat on, we're short-staffed."))
        close = _pick(rng, ("And no overtime claims.", "Deadline waits for nobody.", "Ring in if it changes."))
        if one:
            return f"{open_} I need you at {res[0]}, nothing else tonight. {close}"
        if order == "strict":
            body = "Start at " + _chain(res, "after that", "and wrap up at")
        else:
            body = "I need you at " + _series(res)
        return f"{open_} {body}. {_cap(_cue(rng, 'editor', order))}. {close}"
    head = _pick(rng, ("Tonight's running list", "Running list for the late edition", "Late edition list"))
    if one:
        return f"{head}:\nLead: {res[0]}.\nNothing else runs."
    if order == "strict":
        lines = [f"Lead: {res[0]}."] + [f"{_cap(_ordinal(i))} story: {r}." for i, r in enumerate(res) if i]
    else:
        lines = [f"Story: {r}." for r in res]
    return f"{head} ({_cue(rng, 'editor', order)}):\n" + "\n".join(lines)


VOICES = {"butler": _butler, "beekeeper": _beekeeper, "trader": _trader, "editor": _editor}
LAYOUTS = 3


def render_instruction_av(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a butler, a beekeeper, a floor trader, a
    newspaper night editor), each in one of three layouts. Goals stay in visiting order, each written once exactly
    as rendered; strict texts say in words that the order is fixed, free ones that it is open, and a single goal
    gets neither kind of cue. The frames add no digit."""
    voice = _pick(rng, tuple(VOICES))
    layout = int(rng.integers(LAYOUTS))
    return VOICES[voice](rng, list(res), order, layout)

