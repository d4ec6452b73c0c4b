"""Held-out sentence set AL (split `unseen_al`): robot navigation instructions in four voices the readers have
never seen.

Written by a helper session that never read the project's readers (parser, lexicon, tagger, sensor reader,
grounding, LLM adapter) nor any other set's wording; it saw only W's public signatures and docstrings, types.py,
template_text.py, the split wiring and the hypothesis strategy for goals, so the wording below is its own.

The four voices, one per whole instruction (drawn from the seeded generator):

- an estate agent writing up a viewing schedule ("delighted to offer", "chain-free", "viewing essential");
- a chess annotator writing up a game ("the move order is forced", "the moves transpose", "!");
- a fantasy quest-giver sending a traveller out ("hear me, traveller", "the prophecy demands", "trials");
- a hard-boiled private eye's case notes ("leads", "shake it down", "the case don't care").

Goals, sensor phrases and coordinate hints are drawn before the voice is (each goal on its own), so they come
from one shared pool of plain but varied shapes with a little of every voice's colour ("handy for", "boasting",
"where the map marks", "if my notes are right").

Style guide:

- A goal is one noun phrase starting with 'the'; the head noun is written exactly as given, and every
  attribute, state and room word exactly as given (a state may be hyphenated before the noun: 'switched-on').
- Piece order after the noun: attributes written after it ('of the teal wool variety'), a state clause, the
  sensor tail, the room, the coordinate hint, and the relations last. The room may instead stand before the noun
  as a possessive ("the nursery's"). A superlative (before the noun or in the tail) ranges over everything else
  the goal says; so whenever a sensor phrase is present, nothing non-restrictive is used (no appositions,
  no ', which ...', no commas before the room or hint): every piece then narrows the candidates.
- A relation's anchor is 'the' + states + attributes + head; an anchor's own relations go in parentheses right
  after it ('(itself ...)', '(the one ...)', '(which in turn ...)'), so each relation belongs to one noun only.
  Relative clauses ('that sits ...', ', which stands ...') are used only right after the head noun, where
  nothing else could own them.
- Sensor values come back exactly: digits as given, whole number words ('forty-two', 'minus four'), 'and a half',
  decimals spoken digit by digit ('nought point six five'), thousands with a comma ('1,500'), below-zero
  temperatures only where the phrase is unambiguous (approximate values and 'hotter/colder than'), and unit
  changes only where exact (Fahrenheit when it is a whole number that converts back exactly; kilowatts for
  whole hundreds of watts). The returned constraint keeps the value in the canonical unit and records the unit
  as written ('c', 'f', '%', 'ppm', 'db', 'lux', 'w', 'kw', 'kg', 'hpa'; '' for NDVI and superlatives).
  Strict and non-strict thresholds are told apart ('over' vs '... or more' / 'at least' / 'no lower than';
  'under' vs 'at most' / '... or less' / 'not above'); an approximate value says 'about', 'roughly' etc.
- Coordinate hints give x then y in the scene frame, both numbers written verbatim in digits, with no other
  number after them in the goal.
- Fixed order vs free order is said in each voice's own jargon: the agent's viewings 'strictly in the order
  listed' vs 'chain-free'; the annotator's 'forced move order' vs 'the moves transpose'; the quest-giver's
  prophecy vs 'whatever order fate sends you'; the detective's 'work the leads in the order I wrote them down'
  vs 'the case don't care'. A free text carries no sequencing words. A single goal gets neither cue and no
  digit. Goals in a running list are parted by semicolons as soon as any of them has a comma or an 'and' of its
  own, so no goal's pieces can be read as the next goal.

Slips: while looking up the allowed lines I saw a little more than the brief allows: the listing of file names in
ragnav_jax/language/ and tests/; in episodes.py the `_rng` helper and the first lines of `_one_episode` (the
line range printed ran past `_renderer`); in tests/test_phrasings_dev8.py the first lines of its module
docstring, the `SETTINGS` and `REL_WORDS` constants, and a grep listing of its other top-level names (function
names such as `read_numbers`, `read_comparator`, `constraints`, the first line of `_VALUES`); the ruff section of
pyproject.toml (line length); and I printed `types.READINGS` at run time to learn the sensor keys (readings.py
itself was not opened). To look over the finished wording I also ran the project's episode generator
(`generate_episodes`, as tests/test_heldout_sets.py does) on one small scene and read the instructions and truth
it wrote; no reader was run. None of it was used to shape the wording beyond knowing the sensor keys.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from ragnav_jax.language.template_text import (
    ONES,
    attributes_and_states,
    both,
    hyphenated,
    listed,
    number_words,
    plural,
    tidy,
)
from ragnav_jax.language.types import READINGS, Relation, SensorConstraint, Subgoal, Target

VOICES = ("estate agent", "chess annotator", "quest giver", "private eye")


def _pick(rng: np.random.Generator, options):
    return options[int(rng.integers(len(options)))]


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _two(pl: bool, sing: str, plur: str) -> str:
    return plur if pl else sing


# ---------------------------------------------------------------------------------------------------- numbers


def _digits(v: float) -> str:
    v = float(v)
    if v.is_integer():
        return str(int(v))
    s = repr(v)
    if "e" in s or "n" in s:
        s = format(v, "f").rstrip("0").rstrip(".")
    return s


def _words(v: float) -> str | None:
    """Whole numbers and halves in words ('forty-two', 'minus two and a half'), or None."""
    v = float(v)
    if v.is_integer() and abs(v) < 1000:
        return number_words(int(v))
    if (2 * v).is_integer() and 1 <= abs(v) < 100:
        return ("minus " if v < 0 else "") + number_words(int(abs(v))) + " and a half"
    return None


def _point_words(v: float) -> str | None:
    """A decimal spoken digit by digit: 0.65 -> 'nought point six five'."""
    s = _digits(v)
    if "." not in s:
        return None
    neg = s.startswith("-")
    whole, frac = s.lstrip("-").split(".")
    if len(frac) > 3 or int(whole) >= 1000:
        return None
    w = "nought" if whole == "0" else number_words(int(whole))
    return ("minus " if neg else "") + w + " point " + " ".join("nought" if d == "0" else ONES[int(d)] for d in frac)


def _thousands(v: float) -> str | None:
    v = float(v)
    return f"{int(v):,}" if v.is_integer() and abs(v) >= 1000 else None


def _fahrenheit(v: float) -> str | None:
    """The same temperature in whole degrees Fahrenheit, when it converts back exactly."""
    f = Fraction(_digits(v)) * 9 / 5 + 32
    if f.denominator != 1:
        return None
    n = int(f)
    if (n - 32) * 5 / 9 != v or (n - 32) / 1.8 != v:
        return None
    return str(n)


def _kilowatts(v: float) -> str | None:
    v = float(v)
    if not (v.is_integer() and abs(v) >= 1000 and int(v) % 100 == 0):
        return None
    k = _digits(v / 1000)
    return k if float(k) * 1000 == v else None


def _amounts(reading: str, v: float, below_zero: bool) -> list[tuple[str, str]]:
    """Every way this set writes the value v of a reading, each with the unit as written."""
    d, w, th = _digits(v), _words(v), _thousands(v)
    out: list[tuple[str, str]] = []
    if reading == "temperature_c":
        out += [(f"{d} °C", "c"), (f"{d} degrees Celsius", "c")]
        if w:
            out.append((f"{w} degrees Celsius", "c"))
        if v < 0 and below_zero:
            out.append((f"{_digits(-v)} °C below zero", "c"))
        f = _fahrenheit(v)
        if f is not None:
            out += [(f"{f} °F", "f"), (f"{f} degrees Fahrenheit", "f")]
    elif reading == "ndvi":
        out.append((d, ""))
        pw = _point_words(v)
        if pw:
            out.append((pw, ""))
    elif reading in ("humidity_pct", "battery_pct"):
        out += [(f"{d}%", "%"), (f"{d} per cent", "%"), (f"{d} percent", "%")]
        if w:
            out.append((f"{w} per cent", "%"))
    elif reading == "co2_ppm":
        out += [(f"{th or d} ppm", "ppm"), (f"{d} parts per million", "ppm")]
        if w:
            out.append((f"{w} parts per million", "ppm"))
    elif reading == "noise_db":
        out += [(f"{d} dB", "db"), (f"{d} decibels", "db")]
        if w:
            out.append((f"{w} decibels", "db"))
    elif reading == "light_lux":
        out += [(f"{th or d} lux", "lux")]
        if w:
            out.append((f"{w} lux", "lux"))
    elif reading == "power_w":
        out += [(f"{d} W", "w"), (f"{th or d} watts", "w")]
        if w:
            out.append((f"{w} watts", "w"))
        k = _kilowatts(v)
        if k is not None:
            out += [(f"{k} kW", "kw"), (f"{k} kilowatts", "kw")]
    elif reading == "weight_kg":
        out += [(f"{d} kg", "kg"), (f"{d} kilograms", "kg"), (f"{d} kilos", "kg")]
        if w:
            out.append((f"{w} kilograms", "kg"))
    elif reading == "pressure_hpa":
        out += [(f"{th or d} hPa", "hpa"), (f"{d} hectopascals", "hpa")]
    else:
        out.append((d, ""))
    return out


# ---------------------------------------------------------------------------------------------------- sensors

_NOUN = {
    "temperature_c": ("temperature",),
    "ndvi": ("NDVI", "NDVI reading", "vegetation index (NDVI)"),
    "humidity_pct": ("humidity", "relative humidity"),
    "co2_ppm": ("CO2 level", "carbon dioxide level", "CO2 reading"),
    "noise_db": ("noise level", "sound level"),
    "light_lux": ("light level", "illuminance"),
    "battery_pct": ("battery level", "battery charge"),
    "power_w": ("power draw", "power consumption"),
    "weight_kg": ("weight",),
    "pressure_hpa": ("air pressure", "barometric pressure"),
}

# comparator words after a reading's noun ('with a temperature over ...', 'whose temperature is at least ...')
_CMP = {
    "gt": ("over {a}", "above {a}", "higher than {a}", "greater than {a}", "in excess of {a}"),
    "ge": ("at least {a}", "{a} or more", "{a} or above", "no lower than {a}", "not below {a}"),
    "lt": ("under {a}", "below {a}", "lower than {a}", "less than {a}"),
    "le": ("at most {a}", "{a} or less", "{a} or below", "no higher than {a}", "not above {a}"),
    "approx": ("about {a}", "around {a}", "roughly {a}", "{a} or thereabouts", "in the region of {a}",
               "approximately {a}"),
}
# comparator words after a verb ('weighing more than ...', 'drawing at most ...')
_VCMP = {
    "gt": ("more than {a}", "over {a}"),
    "ge": ("at least {a}", "{a} or more", "no less than {a}"),
    "lt": ("less than {a}", "under {a}"),
    "le": ("at most {a}", "no more than {a}", "{a} or less"),
    "approx": ("about {a}", "roughly {a}", "around {a}"),
}
# whose-clauses with a verb of their own
_WHOSE = {
    "gt": ("whose {n} exceeds {a}",),
    "ge": ("whose {n} reaches at least {a}", "whose {n} does not fall below {a}"),
    "lt": ("whose {n} stays below {a}",),
    "le": ("whose {n} does not exceed {a}",),
    "approx": ("whose {n} sits at about {a}",),
}
_VERB = {"weight_kg": "weighing", "power_w": "drawing", "battery_pct": "charged to", "noise_db": "registering",
         "light_lux": "lit to", "temperature_c": "running at"}
# (more, less) comparatives a threshold may be told with, and the participle in front of them
_MORE_LESS = {"temperature_c": ("running ", (("hotter", "colder"), ("warmer", "cooler"))),
              "noise_db": ("sounding ", (("louder", "quieter"),)),
              "weight_kg": ("", (("heavier", "lighter"),)),
              "light_lux": ("", (("brighter", "dimmer"),))}
_SUP_ADJ = {
    "temperature_c": (("hottest", "warmest"), ("coldest", "chilliest")),
    "humidity_pct": (("dampest", "most humid"), ("driest", "least humid")),
    "noise_db": (("loudest", "noisiest"), ("quietest",)),
    "light_lux": (("brightest", "most brightly lit"), ("dimmest", "most dimly lit")),
    "weight_kg": (("heaviest",), ()),
    "power_w": (("most power-hungry",), ("least power-hungry",)),
    "battery_pct": (("most fully charged",), ("least charged",)),
}
_SUP_VERB = {
    "temperature_c": ("running hotter than any other", "running colder than any other"),
    "weight_kg": ("weighing more than any other", "weighing less than any other"),
    "power_w": ("drawing more power than any other", "drawing less power than any other"),
    "noise_db": ("making more noise than any other", "making less noise than any other"),
    "light_lux": ("lit more brightly than any other", "lit more dimly than any other"),
    "battery_pct": ("holding more charge than any other", "holding less charge than any other"),
    "co2_ppm": ("with more carbon dioxide about it than any other", "with less carbon dioxide about it than any other"),
    "humidity_pct": ("sitting in more humid air than any other", "sitting in drier air than any other"),
}


def _art(noun: str) -> str:
    return "an" if noun[0].lower() in "aeio" or noun.startswith("NDVI") else "a"


def _needs_of(cmp_text: str) -> bool:
    return cmp_text.startswith(("at ", "{a}", "about", "around", "roughly", "approximately"))


def _sup_tails(r: str, noun: str, hi: bool) -> list[str]:
    word = "highest" if hi else "lowest"
    tails = [f"with the {word} {noun}", f"with the very {word} {noun}", f"whose {noun} is the {word}",
             f"having the {word} {noun}", f"boasting the {word} {noun}"]
    if r in _SUP_VERB:
        tails.append(_SUP_VERB[r][0 if hi else 1])
    return tails


# every superlative tail this set writes (a goal reads a tail as a superlative when it is one of these)
_SUP_TAILS = frozenset(t for r in READINGS for n in _NOUN.get(r, (r,)) for hi in (True, False)
                       for t in _sup_tails(r, n, hi))


def render_sensor_al(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('hottest', 'most power-hungry') or a tail ('with the lowest
    humidity', 'whose noise level is the highest', 'having the very lowest weight', 'running colder than
    any other'), none of them closed off ('of them all'), so the room, hint and relations after them still count
    in the comparison. Thresholds after the noun: 'with a temperature of at least 40 °C',
    'whose relative humidity is 40 per cent or less', '(NDVI: roughly nought point six five)', 'drawing more
    than 1.5 kW', 'running no colder than 104 °F', 'whose CO2 level stays below 800 ppm'.
    """
    r = c.reading
    if c.comparator in ("max", "min"):
        hi = c.comparator == "max"
        out = SensorConstraint(r, c.comparator, None, "")
        adjs = _SUP_ADJ.get(r, ((), ()))[0 if hi else 1]
        if adjs and rng.random() < 0.4:
            return _pick(rng, adjs), "", out
        noun = _pick(rng, _NOUN.get(r, (r,)))
        return "", _pick(rng, _sup_tails(r, noun, hi)), out
    cmp = c.comparator
    kinds = ["with", "whose", "paren", "whose-verb"]
    if r in _VERB:
        kinds.append("verb")
    if r in _MORE_LESS and cmp in ("gt", "ge", "lt", "le"):
        kinds.append("comparative")
    kind = _pick(rng, kinds)
    noun = _pick(rng, _NOUN.get(r, (r,)))
    amount, unit = _pick(rng, _amounts(r, float(c.value), below_zero=kind == "comparative" or cmp == "approx"))
    if kind == "comparative":
        lead, pairs = _MORE_LESS[r]
        more, less = _pick(rng, pairs)
        phrase = {"gt": f"{more} than {amount}", "lt": f"{less} than {amount}",
                  "ge": f"no {less} than {amount}", "le": f"no {more} than {amount}"}[cmp]
        phrase = lead + phrase
    elif kind == "verb":
        phrase = _VERB[r] + " " + _pick(rng, _VCMP[cmp]).format(a=amount)
    elif kind == "whose-verb":
        phrase = _pick(rng, _WHOSE[cmp]).format(n=noun, a=amount)
    else:
        cw = _pick(rng, _CMP[cmp])
        said = cw.format(a=amount)
        if kind == "with":
            phrase = f"with {_art(noun)} {noun} {'of ' if _needs_of(cw) else ''}{said}"
        elif kind == "whose":
            phrase = f"whose {noun} is {said}"
        else:
            phrase = f"({'NDVI' if '(' in noun else noun}: {said})"
    return "", phrase, SensorConstraint(r, cmp, float(c.value), unit)


# ---------------------------------------------------------------------------------------------------- hints

_HINTS = ("at ({x}, {y}) on the floor plan", "at x {x}, y {y}", "where x = {x} and y = {y}",
          "at the point with x {x} and y {y}", "with coordinates x {x} and y {y}", "positioned at ({x}, {y})",
          "at {x} on the x axis and {y} on the y axis", "where the map marks x {x}, y {y}",
          "at grid position ({x}, {y})", "at x = {x} m, y = {y} m", "at ({x}, {y}) if my notes are right",
          "on the square at x {x}, y {y}")


def hint_text_al(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y, both written verbatim in digits: 'at (3.5, 2) on
    the floor plan', 'where x = 3.5 and y = 2', 'at 3.5 on the x axis and 2 on the y axis', 'where the map marks
    x 3.5, y 2', 'at x = 3.5 m, y = 2 m'."""
    return _pick(rng, _HINTS).format(x=x, y=y)


# ---------------------------------------------------------------------------------------------------- goals

_PREP = {
    "near": ("near", "close to", "not far from", "within easy reach of", "handy for"),
    "next_to": ("next to", "right next to", "immediately next to"),
    "beside": ("beside", "just beside", "right beside"),
    "by": ("by", "right by", "hard by"),
    "on": ("on", "on top of", "upon"),
    "under": ("under", "underneath", "beneath"),
    "above": ("above", "directly above", "up above"),
    "in": ("inside", "within", "tucked inside"),
    "with": ("with", "boasting"),
    "in_room_with": ("in the same room as", "sharing a room with", "in whichever room holds"),
    "in_front_of": ("in front of", "just in front of", "out in front of"),
    "behind": ("behind", "just behind", "round the back of"),
    "opposite": ("opposite", "directly opposite", "across from", "facing"),
    "left_of": ("to the left of", "on the left-hand side of", "left of"),
    "right_of": ("to the right of", "on the right-hand side of", "right of"),
}
_PARTICIPLES = ("sitting", "standing", "placed", "positioned", "to be found")


def _anchor(rng: np.random.Generator, t: Target) -> str:
    """'the' + states + attributes + head; the anchor's own relations in parentheses right after it."""
    pre, states = attributes_and_states(t)
    words = ["the", *([hyphenated(states)] if states else []), *pre, t.head]
    s = " ".join(words)
    if t.relations:
        pl = plural(t.head)
        form = int(rng.integers(4))
        if form == 0:
            inner = _two(pl, "itself ", "themselves ") + _joined([_prep(rng, r) for r in t.relations])
        elif form == 1:
            inner = _two(pl, "the one ", "the ones ") + _joined([_prep(rng, r) for r in t.relations])
        elif form == 2:
            inner = _two(pl, "which itself ", "which themselves ") + _joined(
                [_verb(rng, r, pl) for r in t.relations])
        else:
            inner = "which in turn " + _joined([_verb(rng, r, pl) for r in t.relations])
        s += f" ({inner})"
    return s


def _joined(parts: list[str], also: bool = False) -> str:
    if len(parts) == 1:
        return parts[0]
    last = ("and also " if also else "and ") + parts[-1]
    return ", ".join(parts[:-1]) + (", " if len(parts) > 2 else " ") + last


def _prep(rng: np.random.Generator, r: Relation) -> str:
    word = _pick(rng, _PREP.get(r.type, (r.type.replace("_", " "),)))
    return f"{word} {_anchor(rng, r.anchor)}"


def _verb(rng: np.random.Generator, r: Relation, pl: bool) -> str:
    if r.type == "with":
        v = _pick(rng, (("has", "have"), ("comes with", "come with"), ("boasts", "boast")))
        return f"{_two(pl, *v)} {_anchor(rng, r.anchor)}"
    if r.type == "in_room_with":
        v = _pick(rng, (("shares a room with", "share a room with"),
                        ("is in the same room as", "are in the same room as")))
        return f"{_two(pl, *v)} {_anchor(rng, r.anchor)}"
    v = _pick(rng, (("is", "are"), ("sits", "sit"), ("stands", "stand")))
    return f"{_two(pl, *v)} {_prep(rng, r)}"


def _relations(rng: np.random.Generator, rels: tuple[Relation, ...], pl: bool, right_after_head: bool,
               restrictive: bool) -> str:
    forms = ["prep", "both"] if len(rels) > 1 else ["prep"]
    if right_after_head:
        forms.append("that")
        if not restrictive:
            forms.append("which")
    if not restrictive:
        forms.append("participle")
    form = _pick(rng, forms)
    if form == "prep":
        return " " + _joined([_prep(rng, r) for r in rels])
    if form == "both":
        ps = [_prep(rng, r) for r in rels]
        return " both " + " and ".join(ps) if len(ps) == 2 else " " + _joined(ps, also=True)
    if form == "that":
        return " that " + _joined([_verb(rng, r, pl) for r in rels])
    if form == "which":
        return ", which " + _joined([_verb(rng, r, pl) for r in rels], also=True)
    parts = []
    for r in rels:
        p = _prep(rng, r)
        plain = r.type in ("with", "in_room_with") or p.startswith("tucked")
        parts.append(p if plain else f"{_pick(rng, _PARTICIPLES)} {p}")
    return ", " + _joined(parts)


def render_goal_al(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AL writes it: 'the switched-on teal wool lamp in the nursery', 'the lamp of the teal wool
    variety', 'the lamp (switched on at the moment)', 'the nursery's hottest lamp', 'the mini-fridge whose
    temperature is 4 °C or below, over in the pantry', 'the guitar where x = 3.5 and y = 2', 'the lamp in the
    nursery, both beside the credenza (the one with the record player) and under the shelves'. Order after the
    noun: post-noun attributes, a state clause, the sensor tail, the room, the coordinate hint (after any number
    of the tail), the relations last. After a threshold tail the later pieces are set off by commas (so none of
    them hangs on the tail's own words); with a superlative every piece is restrictive (no commas before the room,
    no appositions, no ', which'), so the superlative ranges over everything else the goal says.
    """
    t = sg.target
    head = t.head
    pl = plural(head)
    pre, states = attributes_and_states(t)
    mode = "superlative" if prefix or tail in _SUP_TAILS else ("threshold" if tail else "")
    room = sg.room
    room_before = bool(room) and rng.random() < 0.2
    attr_form = _pick(rng, ("pre", "pre", "variety") + (() if mode else ("appos",))) if pre else ""
    state_form = ""
    if states:
        state_forms = ["pre"] + ([] if mode == "superlative" else ["that"])
        if not mode:
            state_forms += ["currently"] + ([] if attr_form == "appos" else ["paren"])
        state_form = _pick(rng, state_forms)
    words = ["the"]
    if room_before:
        words.append(f"{room}'s")
    if prefix:
        words.append(prefix)
    if state_form == "pre":
        words.append(hyphenated(states))
    if attr_form == "pre":
        words += pre
    words.append(head)
    s = " ".join(words)
    after_head = True  # nothing yet stands between the head and what comes next
    if attr_form == "variety":
        s += f" of the {' '.join(pre)} {_pick(rng, ('variety', 'sort'))}"
        after_head = False
    elif attr_form == "appos":
        s += f" (the {' '.join(pre)} {_two(pl, 'one', 'ones')})"
        after_head = False
    st = both(states)
    if state_form == "that":
        s += " that " + _pick(rng, (_two(pl, "is ", "are ") + st, _two(pl, "has been left ", "have been left ") + st))
        after_head = False
    elif state_form == "paren":
        s += f" ({st} at the moment)"
        after_head = False
    elif state_form == "currently":
        s += f", currently {st},"
        after_head = False
    sep = " "
    if tail:
        s += (", " if state_form == "that" and mode == "threshold" else " ") + tail
        after_head = False
        if mode == "threshold":
            sep = ", "  # what follows a threshold is set off from the tail's own words
    if room and not room_before:
        forms = ("in", "over in", "down in", "kept in", "located in", "to be found in")
        if not mode and after_head:
            forms += ("which lives in",)
        form = _pick(rng, forms)
        s += (", which lives in the " + room + ",") if form == "which lives in" else f"{sep}{form} the {room}"
        after_head = False
    if hint:
        if mode == "superlative":
            s += " " + hint
        elif mode == "threshold":
            s += sep + hint
        else:
            s += _pick(rng, (" ", ", ")) + hint
        after_head = False
    if t.relations:
        rel = _relations(rng, t.relations, pl, after_head, mode == "superlative")
        if (hint or mode == "threshold") and not after_head and not rel.startswith(","):
            rel = "," + rel
        s += rel
    return tidy(s)


# ---------------------------------------------------------------------------------------------------- instructions

_ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth")

FIXED = {
    "estate agent": ("viewings are strictly in the order listed",
                     "this is a chain, and it completes in sequence or not at all",
                     "kindly keep to the schedule as set out, each viewing only after the one before it",
                     "no jumping the queue, as every viewing waits its turn on the list"),
    "chess annotator": ("the move order is forced",
                        "only in exactly this sequence; any transposition is a blunder",
                        "each move only after the previous one has been played",
                        "deviate from this move order and the whole combination collapses"),
    "quest giver": ("the prophecy demands they be sought in this very order",
                    "each trial opens the way to the next, so take them as I have named them",
                    "stray from the order of the telling and the spell is broken"),
    "private eye": ("work the leads in the order I wrote them down, no skipping",
                    "each lead only after the last one's been shaken down",
                    "follow the trail the way it was laid, one stop after another"),
}
OPEN = {
    "estate agent": ("view them in any order you like", "chain-free, so no set order applies",
                     "the viewings can be taken in whatever order suits",
                     "no onward chain: start with whichever takes your fancy"),
    "chess annotator": ("the moves transpose freely", "move order is immaterial here",
                        "any move order reaches the same position",
                        "these can be played in any order without spoiling anything"),
    "quest giver": ("seek them in whatever order fate sends you",
                    "the old magic cares not in what order they are found",
                    "wander where the road leads and take them as they come", "no order binds this quest"),
    "private eye": ("work them in any order you like, the case don't care",
                    "no order to it, shake them down as you find them",
                    "whichever lead you pull on, the knot comes loose all the same"),
}
SINGLE = {
    "estate agent": ("Just come to the market: {g}. Early viewing highly recommended.",
                     "Viewing by appointment only: {g}, and well worth the visit.",
                     "We are proud to present {g}, a genuinely rare opportunity.",
                     "{G} has just come to the market. Viewing essential."),
    "chess annotator": ("Best here is simply {g}!", "White's strongest continuation is {g}!",
                        "The key idea in this position: {g}.", "{G}! Clearly the strongest move in the position."),
    "quest giver": ("Hear me, traveller! Your quest is to seek out {g}.",
                    "A humble task for one so brave: find {g}, and the realm will sing of your deeds.",
                    "The oracle has spoken of a single thing: {g}. Go!"),
    "private eye": ("One lead, and one lead only: {g}. Go shake it down.",
                    "The whole case hangs on {g}. Get over there.",
                    "Case notes, small hours, raining again. Somebody wants {g} found, and they're paying."),
}


def _items(rng: np.random.Generator, res: list[str]) -> str:
    """Goals in a running sentence; semicolons between them as soon as one has a comma or an 'and' of its own."""
    if any("," in g or " and " in g for g in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return listed(rng, res)


def _seq(rng, res: list[str], opener: str, middles: tuple[str, ...], closer: str) -> str:
    """Goals one sentence each, in order: opener for the first, a middle word for the rest, closer for the last."""
    out = [_cap(opener.format(g=res[0]))]
    for g in res[1:-1]:
        out.append(_cap(_pick(rng, middles).format(g=g)))
    out.append(_cap(closer.format(g=res[-1])))
    return " ".join(s + "." for s in out)


def _strict(rng, voice: str, res: list[str], cue: str) -> str:
    n = len(res)
    form = int(rng.integers(3))
    if voice == "estate agent":
        if form == 0:
            return f"We are delighted to offer viewings of {_items(rng, res)}. Please note: {cue}."
        if form == 1:
            labels = [f"Viewing {number_words(i + 1)}: {g}." for i, g in enumerate(res)]
            return " ".join(labels) + f" {_cap(cue)}."
        return _seq(rng, res, "Today's schedule opens with {g}", ("then on to {g}", "after that, {g}"),
                    "and it closes with {g}") + f" {_cap(cue)}."
    if voice == "chess annotator":
        if form == 0:
            return " ".join(f"{i + 1}. {g}!" for i, g in enumerate(res)) + f" Note that {cue}."
        if form == 1:
            return _seq(rng, res, "Strongest is {g}", ("only then {g}", "next comes {g}"),
                        "and finally {g}") + f" {_cap(cue)}!"
        return f"The main line runs {_items(rng, res)}, {_pick(rng, ('in that order', 'move by move'))}. {_cap(cue)}."
    if voice == "quest giver":
        if form == 0:
            return f"Hear me, traveller! {_cap(number_words(n))} trials await you: {_items(rng, res)}. {_cap(cue)}."
        if form == 1:
            return _seq(rng, res, "Begin with {g}", ("only then seek {g}", "after that, {g}"),
                        "and last of all, {g}") + f" {_cap(cue)}."
        return f"The scroll names {number_words(n)} things to be found, and {cue}: {_items(rng, res)}."
    if form == 0:
        return f"Leads, in the order they came to me: {_items(rng, res)}. {_cap(cue)}."
    if form == 1:
        return "The trail goes like this. " + _seq(rng, res, "First, {g}", ("then {g}", "after that, {g}"),
                                                   "last stop, {g}") + f" {_cap(cue)}."
    return f"Case notes, small hours: {_items(rng, res)}. {_cap(cue)}. Keep your eyes open."


def _free(rng, voice: str, res: list[str], cue: str) -> str:
    n = len(res)
    form = int(rng.integers(3))
    items = _items(rng, res)
    if voice == "estate agent":
        return (f"Now available to view: {items}. {_cap(cue)}.", f"A rare opportunity to see {items}; {cue}.",
                f"Fresh to the market this week are {items}; {cue}.")[form]
    if voice == "chess annotator":
        return (f"White has several useful moves here: {items}. {_cap(cue)}.",
                f"The plan involves {items}; {cue}.", f"All of {items} are strong, and {cue}.")[form]
    if voice == "quest giver":
        return (f"Go forth, brave one, and find {items}. {_cap(cue)}.",
                f"{_cap(number_words(n))} treasures lie scattered across this land: {items}. {_cap(cue)}.",
                f"The oracle asks for {items}; {cue}.")[form]
    return (f"Got {number_words(n)} leads and a bad feeling: {items}. {_cap(cue)}.",
            f"Case notes, small hours. Somebody wants {items} found. {_cap(cue)}.",
            f"Here's what I've got: {items}; {cue}.")[form]


def render_instruction_al(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (an estate agent, a chess annotator, a
    fantasy quest-giver, a private eye). Goals stay in visiting order, each written once as rendered; strict texts
    say the order is fixed in the voice's own jargon (`FIXED`: 'viewings are strictly in the order listed', 'the
    move order is forced', 'the prophecy demands they be sought in this very order', 'work the leads in the order
    I wrote them down'), free ones say it is open (`OPEN`: 'chain-free, so no set order applies', 'the moves
    transpose freely', 'seek them in whatever order fate sends you', 'the case don't care') and carry no
    sequencing words. A single goal gets neither kind of cue and no digit (`SINGLE`)."""
    voice = _pick(rng, VOICES)
    if len(res) == 1:
        return _pick(rng, SINGLE[voice]).format(g=res[0], G=_cap(res[0]))
    if order == "strict":
        return _strict(rng, voice, res, _pick(rng, FIXED[voice]))
    return _free(rng, voice, res, _pick(rng, OPEN[voice]))
