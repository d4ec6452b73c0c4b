"""Held-out phrasings of set AE (split `unseen_ae`): goals, sensor phrases, coordinate hints and whole
instructions as four new people write them. Written by a helper that never read the parser (nor its lexicon,
tagger, sensor reader, readings, agreement, adapters, LLM or command code, nor the evaluation code), before any
run of any reader on these sentences, with only the interface of set W in view (the `def` lines and docstrings
of its four public functions).

The four voices (chosen at random per instruction by `render_instruction_ae`):

* a racing tipster: a punter's tip sheet, bets and forecasts, chatty and sure of himself;
* a prescribing doctor: a terse script with Latin shorthand, roman-numbered items and a closing directions line;
* a land surveyor: a field book, stations lettered and occupied in turn, clipped notes and abbreviations;
* a head butler: briefing a new footman below stairs, formal, deferential and fussy about the household.

Style guide (what every goal or sensor phrase may say, whichever voice carries it):

* goals: always 'the' + noun phrase; the head noun is written exactly as given. Attributes the target's phrase
  puts before the noun either stay there, go after it in brackets, in a 'that is/are ...' clause or in a
  'the ... one(s)' apposition; states (switched on, open, empty, ...) go hyphenated before the noun, or after it
  in brackets ('... at present', 'state: ...'), in a clause ('that is ...', 'which is ... just now') or an aside
  ('found ...'). Anchors get the same treatment but their states stay in brackets or before the noun, and an
  anchor's own relation goes in brackets ('(the one ...)', '(which is ...)'), so nesting is never ambiguous.
* rooms: 'in the R', 'through in the R', 'over in the R', '(room: R)', 'which lives in the R', 'kept in the R';
  the room comes straight after the noun phrase, before any sensor phrase and relation (no 'which lives' after a
  'which is' state clause).
* relations (own words for every kind): near 'not far from', 'in the neighbourhood of', 'handy for'; next_to
  'right up against', 'shoulder to shoulder with', 'immediately adjoining'; beside 'at the side of', 'sat at the
  side of'; by 'hard by', 'down by'; on 'resting on', 'perched on', 'atop'; under 'tucked beneath', 'stowed
  underneath'; above 'mounted above', 'hung above', 'higher up than'; in 'stowed inside', 'kept within', 'housed
  in'; with 'bearing', 'that has ... with it', 'with'; in_room_with 'sharing a room with', 'in whichever room
  holds'; in_front_of 'out in front of', 'just forward of', 'parked in front of'; behind 'round the back of',
  'tucked behind', 'at the rear of'; opposite 'over the way from', 'across the room from', 'facing'; left_of 'on
  the left-hand side of', 'off to the left of', 'left of'; right_of 'on the right-hand side of', 'off to the right
  of', 'right of'. A second relation of the same goal follows ', and also' or ' and'.
* readings: temperature ('temperature', 'temp', 'heat reading', 'thermometer reading'), humidity ('humidity',
  'relative humidity', 'RH', 'damp reading', 'hygrometer reading'), NDVI ('NDVI', 'vegetation index (NDVI)', 'leaf
  index (NDVI)', 'NDVI sensor reading'); any other reading by its key's words.
* comparisons: above 'over', 'above', 'more than', 'higher than', 'in excess of', 'upwards of', '>', 'hotter than',
  'damper than'; at least 'at least', 'no less than', 'not below', '... or more', '... or higher', '>=', '... or
  hotter', '... or damper'; below 'below', 'less than', 'lower than', 'shy of', 'beneath', '<', 'cooler than',
  'drier than'; at most 'at most', 'no more than', 'not above', '... or less', '... or lower', '... at the
  outside', '<=', '... or cooler', '... or drier'; approximately 'about', 'roughly', 'in the region of', '... or
  thereabouts', '..., give or take', 'round about', 'approx.', 'circa', 'c.'.
* numbers: plain digits (no exponent), whole numbers in words ('minus five', 'forty-two'), halves and quarters
  ('22 and a half', 'twenty-two and three-quarters'), decimals below one as 'nought point six five' or '.65',
  negatives as '-5', 'minus 5' or '5 degrees Celsius below zero'. Units: °C, 'degrees C', 'deg C', 'degrees Celsius',
  'degrees centigrade', 'C' after digits; °F / 'degrees Fahrenheit' only where the Fahrenheit figure is exact to a
  half degree (the constraint keeps the Celsius value, unit 'f'); '%', 'percent', 'per cent', '% RH'; or none.
* superlatives: adjectives before the noun (hottest, warmest / coldest, coolest, chilliest; dampest, muggiest,
  most humid / driest, least humid; leafiest, lushest / least leafy, least lush) or tails ('showing the highest X
  of them all', 'whose X comes out higher than any other's', 'that posts the top X figure' and their 'lowest',
  'lower', 'bottom' twins).
* coordinates: 'at x 3.5, y 2', 'at grid ref x=3.5 / y=2', 'at [3.5, 2] (x first, then y)', 'set out at X 3.5 m,
  Y 2 m', 'whose map position reads x 3.5 and y 2', 'pegged at x: 3.5, y: 2'; always x then y, always last in a
  goal when the goal has any relation, and no other digits after them.
* order: strict texts say the sequence is binding, free texts say any order will do, a single goal says neither.

Slips while writing (reported honestly): a grep of episodes.py for the renderer call sites also printed a few lines
of that file's own built-in (seen-split) templates, a look at its `_pick` helper printed the first lines of the
helper after it, and the lines around the call sites were read with a little context; a few dozen instructions of
this set were printed from `generate_episodes` (no reader run, no CLI) to check the wording; scratch scripts were
kept in /tmp outside the worktree and deleted. No parser, lexicon, reader or evaluation code was seen.
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
    plural,
    tidy,
)
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target


def _pick(rng: np.random.Generator, items):
    return items[int(rng.integers(len(items)))]


# ----------------------------------------------------------------------------------------------------
# Goals

REL_WORDS: dict[str, tuple[str, ...]] = {
    "near": ("not far from", "in the neighbourhood of", "handy for"),
    "next_to": ("right up against", "shoulder to shoulder with", "immediately adjoining"),
    "beside": ("at the side of", "sat at the side of"),
    "by": ("hard by", "down by"),
    "on": ("resting on", "perched on", "atop"),
    "under": ("tucked beneath", "stowed underneath"),
    "above": ("mounted above", "hung above", "higher up than"),
    "in": ("stowed inside", "kept within", "housed in"),
    "with": ("bearing", "with"),  # plus 'that has {a} with it'
    "in_room_with": ("sharing a room with", "in whichever room holds"),
    "in_front_of": ("out in front of", "just forward of", "parked in front of"),
    "behind": ("round the back of", "tucked behind", "at the rear of"),
    "opposite": ("over the way from", "across the room from", "facing"),
    "left_of": ("on the left-hand side of", "off to the left of", "left of"),
    "right_of": ("on the right-hand side of", "off to the right of", "right of"),
}

ROOM_FRAMES = ("in the {}", "through in the {}", "over in the {}", "(room: {})", "which lives in the {}",
               "kept in the {}")


def _one(head: str) -> str:
    return "ones" if plural(head) else "one"


def _relation(rng, r: Relation, depth: int) -> str:
    a = _np(rng, r.anchor, depth=depth + 1)
    if r.type == "with" and rng.uniform() < 0.35:
        return f"that has {a} with it"
    return f"{_pick(rng, REL_WORDS.get(r.type, (r.type.replace('_', ' '),)))} {a}"


def _np(rng, t: Target, prefix: str = "", depth: int = 0, clause_ok: bool = True) -> str:
    """'the' + the target's words; an anchor (depth > 0) carries its own relations in brackets."""
    pre, states = attributes_and_states(t)
    head = t.head
    lead = f"{prefix} " if prefix else ""
    after: list[str] = []
    # states: before the noun, or after it
    st_before = ""
    if states:
        k = int(rng.integers(5 if depth == 0 and clause_ok else 2))
        if k == 0:
            st_before = hyphenated(states)
        elif k == 1:
            after.append(_pick(rng, (f"({both(states)} at present)", f"(state: {', '.join(states)})")))
        elif k == 2:
            after.append(f" that {is_are(head)} {both(states)},")
        elif k == 3:
            after.append(f", which {is_are(head)} {both(states)} just now,")
        else:
            after.append(f", found {both(states)},")
    # attributes the phrase puts before the noun
    at_before = ""
    if pre:
        k = int(rng.integers(4 if depth == 0 and clause_ok and not after else 2))
        if k == 0 or (k == 3 and prefix):
            at_before = " ".join(pre)
        elif k == 1:
            after.insert(0, f"({', '.join(pre)})")
        elif k == 2:
            after.insert(0, f" that {is_are(head)} {both(pre)},")
        else:
            after.insert(0, f", the {both(pre)} {_one(head)},")
    out = f"the {lead}{st_before} {at_before} {head} " + " ".join(after)
    if depth > 0 and t.relations:
        rels = " and ".join(_relation(rng, r, depth) for r in t.relations)
        out = out.rstrip().rstrip(",") + " " + _pick(rng, (f"(the {_one(head)} {rels})", f"(which {is_are(head)} {rels})"))
    # a goal's own noun phrase keeps a closing comma after an aside; render_goal_ae tidies the whole goal
    return _clean(out) if depth == 0 else tidy(_clean(out))


def _clean(s: str) -> str:
    s = " ".join(s.split()).replace(" ,", ",")
    while ",," in s:
        s = s.replace(",,", ",")
    return s


def render_goal_ae(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AE writes it: 'the' + noun phrase (a superlative `prefix` straight before the words), then the
    room, then a sensor `tail`, then the relations, with a coordinate `hint` last (or straight after the noun
    phrase when nothing else follows but a room). Every attribute, state, room, relation, anchor (with its own
    attributes, states and relations), the sensor phrase and the hint are written once."""
    t = sg.target
    parts = [_np(rng, Target(t.phrase, t.head, t.attributes), prefix, clause_ok=not tail)]
    if sg.room:
        # no second 'which' clause after a state's ('the bowl, which is full just now, which lives in ...')
        frames = tuple(f for f in ROOM_FRAMES if not f.startswith("which")) if " which " in parts[0] else ROOM_FRAMES
        parts.append(_pick(rng, (" ", " ", ", ")) + _pick(rng, frames).format(sg.room))
    if tail:
        parts.append(f", {tail}," if sg.room or rng.uniform() < 0.5 else f" {tail}")
    if t.relations:
        rels = [_relation(rng, r, 0) for r in t.relations]
        text = rels[0]
        for r in rels[1:]:
            text += _pick(rng, (f", and also {r}", f" and {r}"))
        parts.append(f", {text}" if (sg.room or tail) and rng.uniform() < 0.6 else f" {text}")
    if hint:
        if not tail and not t.relations and rng.uniform() < 0.5:
            parts.insert(1, f" {hint},")
        else:
            parts.append(_pick(rng, (f", {hint}", f" {hint}")))
    return tidy(_clean("".join(parts)))


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

NAMES = {"temperature_c": ("temperature", "temp", "heat reading"),
         "humidity_pct": ("humidity", "relative humidity", "RH", "damp reading"),
         "ndvi": ("NDVI", "vegetation index (NDVI)", "leaf index (NDVI)")}
DEVICES = {"temperature_c": "thermometer", "humidity_pct": "hygrometer", "ndvi": "NDVI sensor"}
SUPER_ADJ = {("temperature_c", "max"): ("hottest", "warmest"),
             ("temperature_c", "min"): ("coldest", "coolest", "chilliest"),
             ("humidity_pct", "max"): ("dampest", "muggiest", "most humid"),
             ("humidity_pct", "min"): ("driest", "least humid"),
             ("ndvi", "max"): ("leafiest", "lushest"),
             ("ndvi", "min"): ("least leafy", "least lush")}
SUPER_TAIL = {"max": ("showing the highest {n} of them all", "whose {n} comes out higher than any other's",
                      "that posts the top {n} figure"),
              "min": ("showing the lowest {n} of them all", "whose {n} comes out lower than any other's",
                      "that posts the bottom {n} figure")}
# comparator -> value frames ({v}: the number with its unit)
CMP_FRAMES = {
    "gt": ("over {v}", "above {v}", "more than {v}", "higher than {v}", "in excess of {v}", "upwards of {v}"),
    "ge": ("at least {v}", "no less than {v}", "not below {v}", "{v} or more", "{v} or higher"),
    "lt": ("below {v}", "less than {v}", "lower than {v}", "shy of {v}", "beneath {v}"),
    "le": ("at most {v}", "no more than {v}", "not above {v}", "{v} or less", "{v} or lower", "{v} at the outside"),
    "approx": ("about {v}", "roughly {v}", "in the region of {v}", "{v} or thereabouts", "{v}, give or take",
               "round about {v}", "approx. {v}", "circa {v}"),
}
CMP_SYMBOLS = {"gt": ">", "ge": ">=", "lt": "<", "le": "<=", "approx": "c."}
# comparative adjectives of a reading (temperature, humidity): gt/lt 'hotter than', ge/le '{v} or hotter'
COMPARATIVES = {"temperature_c": ("hotter", "cooler"), "humidity_pct": ("damper", "drier")}


def fmt(v: float) -> str:
    """Plain digits, no exponent, no trailing zeros: 40.0 -> '40', 0.65 -> '0.65', -2.5 -> '-2.5'."""
    s = f"{v:.6f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


_DIGIT_WORDS = ("nought", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")


def number_forms(v: float) -> list[str]:
    """Every way set AE writes the number v exactly (digits, words, halves and quarters, 'nought point ...')."""
    out = [fmt(v)]
    neg = v < 0
    a = abs(v)
    whole = int(a)
    frac = a - whole
    if neg:
        out.append("minus " + fmt(a))
    if frac < 1e-9 and a < 1000:
        out.append(number_words(-whole if neg else whole))
    elif a >= 1 and a < 1000:
        for f, w in ((0.5, "a half"), (0.25, "a quarter"), (0.75, "three-quarters")):
            if abs(frac - f) < 1e-9:
                sign = "minus " if neg else ""
                out += [f"{sign}{whole} and {w}", f"{sign}{number_words(whole)} and {w}"]
    elif 0 < a < 1:
        dec = fmt(a)[2:]
        if len(dec) <= 3:
            sign = "minus " if neg else ""
            out.append(sign + "nought point " + " ".join(_DIGIT_WORDS[int(d)] for d in dec))
            if not neg:
                out.append("." + dec)
    return out


def _is_digits(n: str) -> bool:
    """A number written in plain digits ('40', '-5', '.65'), which a bare symbol unit may follow."""
    return bool(n) and all(ch.isdigit() or ch in "-." for ch in n)


def _value(rng, rd: str, v: float, cmp: str) -> tuple[str, str]:
    """(the number with its unit as written, the unit code)."""
    n = _pick(rng, number_forms(v))
    digits = _is_digits(n)
    if rd == "temperature_c":
        f = v * 9 / 5 + 32
        if abs(f * 2 - round(f * 2)) < 1e-6 and abs(f) < 2000 and rng.uniform() < 0.25:
            fn = _pick(rng, number_forms(round(f * 2) / 2))
            units = (" °F", " degrees Fahrenheit", "F", "°F") if _is_digits(fn) else (" degrees Fahrenheit",)
            return fn + _pick(rng, units), "f"
        if v < 0 and cmp != "lt" and rng.uniform() < 0.3:
            return _pick(rng, number_forms(-v)) + " degrees Celsius below zero", "c"
        if rng.uniform() < 0.15:
            return n, ""
        words = (" degrees C", " degrees Celsius", " degrees centigrade")
        return n + _pick(rng, words + ((" °C", " deg C", "C", "°C") if digits else ())), "c"
    if rd == "humidity_pct":
        if rng.uniform() < 0.2:
            return n, ""
        return n + _pick(rng, (" percent", " per cent") + (("%", "% RH") if digits else ())), "%"
    return n, ""


def _name(rng, rd: str) -> str:
    return _pick(rng, NAMES.get(rd, (rd.replace("_", " "),)))


def render_sensor_ae(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('hottest', 'least lush') or a tail ('showing the lowest humidity
    of them all', 'whose temp comes out higher than any other's', 'that posts the top NDVI figure'). Thresholds and
    approximate values: a tail ('whose temperature is over 40 °C', 'with its RH 40% or more', '(NDVI c. 0.65)',
    'running hotter than forty degrees C', 'whose hygrometer reading is at most 40 per cent'). The value
    is written exactly (Fahrenheit only where the Celsius value is exact in it; the constraint keeps Celsius)."""
    rd = c.reading
    if c.is_superlative:
        adj = SUPER_ADJ.get((rd, c.comparator))
        written = SensorConstraint(rd, c.comparator, None, "")
        if adj is not None and rng.uniform() < 0.45:
            return _pick(rng, adj), "", written
        return "", _pick(rng, SUPER_TAIL[c.comparator]).format(n=_name(rng, rd)), written
    vtext, code = _value(rng, rd, float(c.value), c.comparator)
    written = SensorConstraint(rd, c.comparator, float(c.value), code)
    name = _name(rng, rd)
    k = int(rng.integers(5))
    if k == 0 and rd in COMPARATIVES and c.comparator != "approx":
        up, down = COMPARATIVES[rd]
        word = up if c.comparator in ("gt", "ge") else down
        phrase = f"{word} than {vtext}" if c.comparator in ("gt", "lt") else f"{vtext} or {word}"
        return "", _pick(rng, (f"running {phrase}", f"that's {phrase}")), written
    if k == 1 and _is_digits(vtext) and "below zero" not in vtext:
        return "", f"({name} {CMP_SYMBOLS[c.comparator]} {vtext})", written
    frame = _pick(rng, CMP_FRAMES[c.comparator]).format(v=vtext)
    if k == 2 and rd in DEVICES:
        return "", f"whose {DEVICES[rd]} reading is {frame}", written
    if k == 3:
        return "", f"with its {name} {frame}", written
    return "", f"whose {name} is {frame}", written


# ----------------------------------------------------------------------------------------------------
# Coordinate hints


def hint_text_ae(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at x 3.5, y 2', 'at grid ref x=3.5 / y=2', 'at
    [3.5, 2] (x first, then y)', 'set out at X 3.5 m, Y 2 m', 'whose map position reads x 3.5 and y 2', 'pegged
    at x: 3.5, y: 2'."""
    return _pick(rng, (f"at x {x}, y {y}", f"at grid ref x={x} / y={y}", f"at [{x}, {y}] (x first, then y)",
                       f"set out at X {x} m, Y {y} m", f"whose map position reads x {x} and y {y}",
                       f"pegged at x: {x}, y: {y}"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions: four voices

STRICT_CUES = {
    "tipster": ("straight forecast", "exact finishing order", "in the order I've called them", "each leg only after the one before"),
    "doctor": ("in the sequence prescribed", "each item only after the one before", "strictly in the order written"),
    "surveyor": ("occupy in the order booked", "in order of station", "no station out of sequence"),
    "butler": ("in precisely this order", "strict succession", "in the order I give them"),
}
FREE_CUES = {
    "tipster": ("combination forecast", "any finishing order", "whichever comes home first"),
    "doctor": ("order at the patient's discretion", "in any order", "sequence not specified"),
    "surveyor": ("no set sequence", "in whatever order suits", "order of occupation immaterial"),
    "butler": ("whatever order you see fit", "no preference as to sequence", "as you find convenient"),
}
_ROMAN = ("i", "ii", "iii", "iv", "v", "vi", "vii", "viii", "ix", "x", "xi", "xii")


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _roman(i: int) -> str:
    return _ROMAN[i] if i < len(_ROMAN) else str(i + 1)


def _letter(i: int) -> str:
    return chr(ord("A") + i) if i < 26 else str(i + 1)


def _semi(res: list[str]) -> str:
    return "; ".join(res)


def _tipster(rng, res: list[str], order: str) -> str:
    if len(res) == 1:
        return _pick(rng, (f"Just the one banker today, folks: {res[0]}. Nap of the day, nothing else on the card.",
                           f"Only one runner worth backing: get yourself to {res[0]} and keep your money in your pocket for the rest.",
                           f"Today's single: {res[0]}. Lump on, can't see it getting beat."))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            return (f"Straight forecast, and it has to come in the exact finishing order: {res[0]}, "
                    + ", ".join(f"then {r}" for r in res[1:]) + ". Get them the wrong way round and the slip's in the bin.")
        if k == 1:
            labels = ("first past the post", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth")
            legs = [f"{labels[i] if i < len(labels) else 'next'}: {r}" for i, r in enumerate(res)]
            return "Tricast special, in the order I've called them. " + _cap(_semi(legs)) + "."
        return ("Accumulator for you, each leg only after the one before has landed: "
                + _semi([f"leg {number_words(i + 1)}, {r}" for i, r in enumerate(res)]) + ". Miss one out of turn and the whole acca's down.")
    k = int(rng.integers(3))
    if k == 0:
        return f"Combination forecast, so any finishing order pays out: get yourself to {listed(rng, res)}."
    if k == 1:
        return f"Box these up, whichever comes home first is fine by me: {_semi(res)}. All of them need to land, mind."
    return f"My each-way fancies, any finishing order: {listed(rng, res)}. Collect on the lot."


def _doctor(rng, res: list[str], order: str) -> str:
    if len(res) == 1:
        return _pick(rng, (f"Rx: {res[0]}. Sig.: attend once, stat.",
                           f"Rx. Visit {res[0]}. One dose only; no repeats.",
                           f"Script for the robot: {res[0]}. Sig.: go there, stat."))
    items = " ".join(f"({_roman(i)}) {r};" for i, r in enumerate(res)).rstrip(";")
    if order == "strict":
        return _pick(rng, (f"Rx: {items}. Sig.: visit in the sequence prescribed, each item only after the one before.",
                           f"Rx, to be taken strictly in the order written: {items}. No doubling up, no skipping ahead.",
                           f"Course of visits: {res[0]}, then " + ", then ".join(res[1:])
                           + ". Sig.: strictly in the order written."))
    return _pick(rng, (f"Rx: {items}. Sig.: p.r.n., order at the patient's discretion; complete the full course.",
                       f"Rx: visit {listed(rng, res)}, in any order. All of them before discharge.",
                       f"Rx: {items}. Sig.: sequence not specified; every item to be taken."))


def _surveyor(rng, res: list[str], order: str) -> str:
    if len(res) == 1:
        return _pick(rng, (f"Field book: single shot required, {res[0]}. That's the day's fieldwork.",
                           f"Obs. req'd: {res[0]}. Nothing else to pick up today.",
                           f"Set-out: one point only, {res[0]}. Book it and close."))
    stations = _semi([f"Stn {_letter(i)}, {r}" for i, r in enumerate(res)])
    if order == "strict":
        return _pick(rng, (f"Traverse, occupy in the order booked: {stations}. Close on the last.",
                           f"Field book, stations in order of station: {stations}. No station out of sequence.",
                           f"Run the line: {res[0]}, then " + ", then ".join(res[1:])
                           + "; occupy in the order booked, no station out of sequence."))
    return _pick(rng, (f"Detail pick-up, no set sequence: {stations}. Observe them all.",
                       f"Obs. req'd, in whatever order suits the traverse: {listed(rng, res)}.",
                       f"Field book, order of occupation immaterial: {stations}. Pick up every one."))


def _butler(rng, res: list[str], order: str) -> str:
    if len(res) == 1:
        return _pick(rng, (f"Just the one errand this morning, if you would be so good: {res[0]}. That will be all.",
                           f"You will attend to {res[0]}, and then consider yourself at liberty.",
                           f"A single duty today: {res[0]}. Her Ladyship asks nothing further."))
    if order == "strict":
        later = ", ".join(f"thereafter {r}" for r in res[1:-1])
        seq = f"first {res[0]}, " + (f"{later}, " if later else "") + f"and only then {res[-1]}"
        return _pick(rng, (f"If you would be so good, attend in precisely this order: {seq}. His Lordship is most particular.",
                           f"In strict succession, please: {_semi(res)}. One does not go ahead of oneself in this house.",
                           f"The rounds, in the order I give them: {seq}."))
    return _pick(rng, (f"At your convenience, and in whatever order you see fit: {listed(rng, res)}.",
                       f"Her Ladyship has no preference as to sequence: {_semi(res)}. Do see that none is overlooked.",
                       f"Attend to {listed(rng, res)}, as you find convenient."))


VOICES = {"tipster": _tipster, "doctor": _doctor, "surveyor": _surveyor, "butler": _butler}


def render_instruction_ae(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a racing tipster, a prescribing doctor, a
    land surveyor, a head butler). Goals stay in visiting order, each written once as rendered; strict texts say
    the order is binding (STRICT_CUES), free ones say it is open (FREE_CUES). A single goal gets neither cue and no
    digit."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = _pick(rng, tuple(VOICES))
    return VOICES[who](rng, res, order)
