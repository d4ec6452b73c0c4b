"""Held-out phrasings of set AG, for the `unseen_ag` episode split.

Written by a helper that never read the parser (nor its lexicon, tagger, sensor reader, readings, agreement,
adapters, LLM or command code, nor the evaluation code), before any run of any reader on these sentences, with only
the interface of set W in view (the signatures and docstrings of its four public functions).

Voices (whole instructions; goals draw on a shared pool of their words):
  * an orienteering course planner: controls, line courses (fixed order) against score events (any order);
  * an archaeology site supervisor: a finds register worked through in order, or trench by trench as it suits;
  * a dog-agility handler talking to the robot as to a dog: a numbered sequence round against a gamblers' run;
  * a beekeeper on an inspection round: hives taken one after another, or foraging wherever it likes.

Style guide (what the templates below use):
  * Goals: the head noun as given; attributes before it, in brackets after it, as "of the ... variety" or
    "described as ..."; states hyphenated before the noun, as a "that is/are" clause, or after "currently",
    "left" or "sitting"; the room after the noun with several prepositions, as a relative clause or as a
    possessive before the noun; a superlative adjective right after the determiner; a sensor tail after the
    room; a coordinate hint after any sensor tail; relations last, each with its own wording per relation
    kind, nested anchors marked with "itself" or "the one ...".
  * Sensors: the reading named in several ways (temperature, temp, NDVI, vegetation index, humidity, RH, ...);
    thresholds and approximate values with their own comparison words; numbers as digits, whole numbers and
    halves in words, NDVI with a bare leading point; degrees as a symbol, "degrees C", Celsius, centigrade or
    Fahrenheit (only where the conversion is exact to one decimal); per cent as a symbol or in words;
    superlatives as an adjective before the noun or as a trailing phrase.
  * Coordinate hints: x then y, both named or x-by-y, plain digits with an ASCII minus.
  * Instructions: strict texts say the order is fixed, free ones say it is open, single goals say neither.

Slips: none in the forbidden files. In language/episodes.py the lines read round the four calls were a little wider
than the calls themselves (the bodies around the hint and sensor calls, the goal loop and `_pick`), and one grep for
the new split's name printed two unrelated lines of that file (a modality-tag table and an Episode constructor).
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.template_text import (
    attributes_and_states,
    both,
    hyphenated,
    is_are,
    listed,
    number_words,
    tidy,
)
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target


def _pick(rng: np.random.Generator, items):
    return items[int(rng.integers(len(items)))]


# ----------------------------------------------------------------------------------------------------
# Goals

REL_WORDS: dict[str, tuple[str, ...]] = {
    "near": ("close to", "not far from", "in the vicinity of", "a short hop from", "within a few paces of"),
    "next_to": ("next to", "adjacent to", "immediately adjoining", "abutting", "right up against"),
    "beside": ("beside", "at the side of", "to one side of", "flanking"),
    "by": ("by", "just by", "down by", "over by", "stood by"),
    "on": ("on", "on top of", "resting on", "perched on", "atop"),
    "under": ("under", "underneath", "beneath", "tucked under", "below"),
    "above": ("above", "up above", "directly over", "higher up than"),
    "in": ("in", "inside", "within", "tucked inside", "stowed in"),
    "with": ("with", "complete with", "sporting", "accompanied by"),
    "in_room_with": ("in the same room as", "sharing a room with", "in whichever room holds"),
    "in_front_of": ("in front of", "out in front of", "standing in front of"),
    "behind": ("behind", "round the back of", "tucked behind", "at the rear of"),
    "opposite": ("opposite", "across from", "facing", "over the way from", "straight across the room from"),
    "left_of": ("left of", "to the left of", "on the left-hand side of", "just left of"),
    "right_of": ("right of", "to the right of", "on the right-hand side of", "just right of"),
}

ROOM_FRAMES = ("in the {}", "over in the {}", "found in the {}", "that lives in the {}", "within the {}",
               "somewhere in the {}", "from the {}")
NESTED_FRAMES = (" (itself {})", ", the one {},")


def _np(rng: np.random.Generator, t: Target, det: str = "the", prefix: str = "", clause_ok: bool = True) -> str:
    """The noun phrase of a target without its relations: determiner, superlative, attributes, states, head."""
    head = t.head
    pre_det = f"{det} {prefix}".strip()
    if not t.phrase.endswith(head):  # a phrase with trailing words of its own ('... in a glazed planter')
        return f"{pre_det} {t.phrase}"
    pre, states = attributes_and_states(t)
    be = is_are(head)
    if pre and states:
        forms = [f"{pre_det} {hyphenated(states)} {' '.join(pre)} {head}",
                 f"{pre_det} {head} ({', '.join(pre)}; {both(states)})",
                 f"{pre_det} {head} described as {both(pre)} and {both(states)}"]
        if clause_ok:
            forms.append(f"{pre_det} {' '.join(pre)} {head} that {be} {both(states)}")
        return _pick(rng, forms)
    if pre:
        return _pick(rng, (f"{pre_det} {' '.join(pre)} {head}", f"{pre_det} {head} ({', '.join(pre)})",
                           f"{pre_det} {head} of the {' '.join(pre)} variety",
                           f"{pre_det} {head} described as {both(pre)}"))
    if states:
        forms = [f"{pre_det} {hyphenated(states)} {head}", f"{pre_det} {head} currently {both(states)}",
                 f"{pre_det} {head} left {both(states)}", f"{pre_det} {head} sitting {both(states)}"]
        if clause_ok:
            forms.append(f"{pre_det} {head} that {be} {both(states)}")
        return _pick(rng, forms)
    return f"{pre_det} {head}"


def _relation(rng: np.random.Generator, r: Relation) -> str:
    words = REL_WORDS.get(r.type, (r.type.replace("_", " "),))
    return f"{_pick(rng, words)} {_anchor(rng, r.anchor)}"


def _anchor(rng: np.random.Generator, a: Target) -> str:
    out = _np(rng, Target(a.phrase, a.head, a.attributes))
    if a.relations:
        out += _pick(rng, NESTED_FRAMES).format(" and ".join(_relation(rng, r) for r in a.relations))
    return out


def render_goal_ag(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AG writes it: the noun phrase (with any superlative prefix), the room, any sensor tail, any
    coordinate hint, then relations. The room comes before a superlative tail (which is read inside it); a hint
    comes after a numeric tail, so the text's last two numbers are the hint's."""
    t = sg.target
    bare = Target(t.phrase, t.head, t.attributes)
    room_text = ""
    if sg.room and rng.uniform() < 0.25:
        out = _np(rng, bare, det=f"the {sg.room}'s", prefix=prefix, clause_ok=not tail)
    else:
        out = _np(rng, bare, prefix=prefix, clause_ok=not tail)
        if sg.room:
            frames = ROOM_FRAMES if not tail else tuple(f for f in ROOM_FRAMES if not f.startswith("that"))
            room_text = _pick(rng, frames).format(sg.room)
    parts = [out, room_text, tail, hint]
    if t.relations:
        joiner = _pick(rng, (" and ", ", and also ", " as well as "))
        parts.append(joiner.join(_relation(rng, r) for r in t.relations))
    return tidy(" ".join(p for p in parts if p))


# ----------------------------------------------------------------------------------------------------
# Sensors

NAMES: dict[str, tuple[str, ...]] = {
    "temperature_c": ("temperature", "temp", "heat level"),
    "humidity_pct": ("humidity", "relative humidity", "RH", "air moisture"),
    "ndvi": ("NDVI", "vegetation index", "NDVI greenness score"),
}
SUPER_ADJ: dict[tuple[str, str], tuple[str, ...]] = {
    ("temperature_c", "max"): ("hottest", "warmest"),
    ("temperature_c", "min"): ("coldest", "chilliest"),
    ("humidity_pct", "max"): ("dampest", "muggiest"),
    ("humidity_pct", "min"): ("driest",),
    ("ndvi", "max"): ("greenest", "leafiest"),
    ("ndvi", "min"): ("least green", "palest-leaved"),
}
SUPER_TAIL = {"max": ("with the highest {} of the lot", "that comes top on {}", "whose {} beats all the others"),
              "min": ("with the lowest {} of the lot", "that comes bottom on {}", "whose {} is lower than all the others")}
CMP_WORDS: dict[str, tuple[str, ...]] = {
    "gt": ("above", "over", "more than", "in excess of", "topping"),
    "ge": ("at least", "no less than", "not under", "{} or more", "{} and upward"),
    "lt": ("below", "under", "less than", "short of"),
    "le": ("at most", "no more than", "not exceeding", "{} or less", "capped at"),
    "approx": ("around", "roughly", "{} or thereabouts", "in the region of", "more or less"),
}
SENSOR_FRAMES = ("with {a} {name} of {cmp}", "whose {name} is {cmp}", "logging {a} {name} of {cmp}",
                 "showing {cmp} on the {name}")


def _article(word: str) -> str:
    return "an" if word[:1].lower() in "aeiou" or word.startswith(("NDVI", "RH")) else "a"


def _num(rng: np.random.Generator, v: float) -> str:
    """A number as digits, or in words when whole or a half."""
    if float(v).is_integer() and abs(v) < 1000 and rng.uniform() < 0.35:
        return number_words(int(v))
    if (2 * v).is_integer() and not float(v).is_integer() and v > 0 and rng.uniform() < 0.4:
        whole = int(v)
        return f"{whole} and a half" if rng.uniform() < 0.5 else f"{number_words(whole)} and a half"
    return f"{v:g}"


def _quantity(rng: np.random.Generator, rd: str, v: float) -> tuple[str, str]:
    """(the value with its unit as written, the unit key)."""
    if rd == "temperature_c":
        f = v * 9 / 5 + 32
        if abs(f - round(f, 1)) < 1e-9 and rng.uniform() < 0.25:
            f = round(f, 1) + 0.0
            return _pick(rng, (f"{f:g}°F", f"{f:g} degrees Fahrenheit", f"{f:g} deg F")), "f"
        n = _num(rng, v)
        if not n[-1].isdigit():
            return f"{n} degrees " + _pick(rng, ("Celsius", "centigrade", "C")), "c"
        return _pick(rng, (f"{n}°C", f"{n} °C", f"{n} degrees C", f"{n} degrees Celsius", f"{n} deg C")), "c"
    if rd == "humidity_pct":
        n = _num(rng, v)
        if not n[-1].isdigit():
            return f"{n} " + _pick(rng, ("per cent", "percent")), "%"
        return _pick(rng, (f"{n}%", f"{n} per cent", f"{n} percent")), "%"
    if rd == "ndvi":
        if 0 < v < 1 and rng.uniform() < 0.4:
            return f"{v:g}"[1:] if f"{v:g}".startswith("0.") else f"{v:g}", ""
        return f"{v:g}", ""
    return _num(rng, v), ""


def render_sensor_ag(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('warmest', 'least green') or a trailing phrase naming the reading
    and whether it is the highest or lowest; thresholds and approximate values after the noun, the reading named,
    the comparison in set AG's words and the value with its unit."""
    rd = c.reading
    name = _pick(rng, NAMES.get(rd, (rd.replace("_", " "),)))
    if c.is_superlative:
        adj = SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", SensorConstraint(rd, c.comparator, None, "")
        return "", _pick(rng, SUPER_TAIL[c.comparator]).format(name), SensorConstraint(rd, c.comparator, None, "")
    qty, unit = _quantity(rng, rd, float(c.value))
    cmp = _pick(rng, CMP_WORDS[c.comparator])
    cmp = cmp.format(qty) if "{}" in cmp else f"{cmp} {qty}"
    tail = _pick(rng, SENSOR_FRAMES).format(a=_article(name), name=name, cmp=cmp)
    return "", tail, SensorConstraint(rd, c.comparator, float(c.value), unit)


# ----------------------------------------------------------------------------------------------------
# Coordinate hints

HINT_FRAMES = ("at grid x {x}, y {y}", "at the spot x = {x}, y = {y}", "at map point {x} by {y} (x by y)",
               "at co-ords x{x} y{y}", "where the house plan puts x at {x} and y at {y}",
               "at ({x}; {y}) on the plan, x first and y second")


def hint_text_ag(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y, each number written as given."""
    return _pick(rng, HINT_FRAMES).format(x=x, y=y)


# ----------------------------------------------------------------------------------------------------
# Whole instructions

ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth")


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _then(rng, res: list[str]) -> str:
    sep = "; " if any("," in r for r in res) else ", "
    word = _pick(rng, ("then ", "after that ", "next "))
    return (sep + word).join(res)


def _ordinal(rng, res: list[str]) -> str:
    return "; ".join(f"{ORDINALS[i] if i < len(ORDINALS) else 'after that'}, {r}" for i, r in enumerate(res))


def _numbered(label: str):
    def f(rng, res: list[str]) -> str:
        return " ".join(f"{label} {i + 1}: {r}." for i, r in enumerate(res))
    return f


def _semis(rng, res: list[str]) -> str:
    return "; ".join(res)


STRICT = {
    "orienteering": (
        ("Line course today, controls to be punched in the order shown. {g}", _numbered("Control")),
        ("Classic fixed-sequence course: {g}. Miss one out or swap two and you're disqualified.", _then),
        ("This one's a line event, so the sequence is fixed: {g}.", _ordinal),
    ),
    "archaeology": (
        ("Work through the finds register strictly in order, top of the list down. {g}", _numbered("Find")),
        ("Record these in sequence, no jumping ahead (stratigraphy matters): {g}.", _then),
        ("Go find by find in exactly this order: {g}.", _ordinal),
    ),
    "agility": (
        ("Sequence round, pup! Take the obstacles as numbered. {g}", _numbered("Obstacle")),
        ("Heel! We run it in the order I call it: {g}. Out of order is a refusal.", _then),
        ("Good dog, same order every time now: {g}.", _ordinal),
    ),
    "beekeeping": (
        ("Hive inspection round, in this order and no other. {g}", _numbered("Hive")),
        ("Like frames in a brood box, one after the other in the order listed: {g}.", _then),
        ("Follow the foragers' route in strict sequence: {g}.", _ordinal),
    ),
}
FREE = {
    "orienteering": (
        ("Score event: get to {g}, in whatever order your route choice favours.", listed),
        ("Controls, any order (score format): {g}.", _semis),
        ("No set sequence, it's a score course: {g}. Pick your own line between them.", listed),
    ),
    "archaeology": (
        ("Finds to check, in no particular sequence: {g}.", listed),
        ("Log {g}; go to them in whatever order the trench allows.", listed),
        ("The register's unordered this season, so any order will do: {g}.", _semis),
    ),
    "agility": (
        ("Gamblers' round, any order you like, pup: {g}.", listed),
        ("Go on, fetch: {g}. Whichever you reach first, I'm not fussed.", listed),
        ("Free run, your own order: {g}.", _semis),
    ),
    "beekeeping": (
        ("Forage wherever you please, little worker: {g}. The order's up to the colony.", listed),
        ("Check on {g}; whichever first, the bees won't mind.", listed),
        ("No fixed round today, visit in any order: {g}.", _semis),
    ),
}
SINGLE = {
    "orienteering": ("One control only on this course: {g}.", "Sprint leg with a single control, {g}."),
    "archaeology": ("Just one find to check today: {g}.", "Single small find to look at: {g}."),
    "agility": ("Find it! {g}. Good dog.", "Go on then, off you go to {g}."),
    "beekeeping": ("Only one hive wants a look today: {g}.", "Just the one stop on the round, {g}."),
}
VOICES = tuple(STRICT)


def render_instruction_ag(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (an orienteering planner, an archaeology site
    supervisor, a dog-agility handler, a beekeeper). Goals stay in visiting order, each written once as rendered;
    strict texts say the order is fixed, free ones say it is open; a single goal is just sent for."""
    voice = _pick(rng, VOICES)
    if len(res) == 1:
        return _cap(_pick(rng, SINGLE[voice]).format(g=res[0]))
    frame, build = _pick(rng, STRICT[voice] if order == "strict" else FREE[voice])
    return _cap(frame.format(g=build(rng, res)))


__all__ = ["render_goal_ag", "render_sensor_ag", "hint_text_ag", "render_instruction_ag"]
