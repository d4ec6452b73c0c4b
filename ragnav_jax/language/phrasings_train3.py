"""Training phrasings of set TRAIN3: goal, sensor, coordinate and instruction templates for the `unseen_train3` split.

Written to teach the learned instruction readers one more author, by a helper that never read the readers (nor
the parser, its lexicon, tagger, readings, agreement or command code, nor the evaluation code, nor any held-out
set), with only the interface of the earlier template sets in view (`phrasings_y.py`, `phrasings_x.py` and the
docstrings of the others). Same four functions, arguments and meanings as the other template sets. The style is
two people who send a home robot round a house in the words of their own trade:

- a hard-boiled private eye's case notes: "CASE FILE – The Business of the Vanishing Alibi", "Exhibit A: ...",
  "Exhibit B: ...", "Exhibit C (the clincher): ...", or "The trail picked up at .... From there it led me to ....
  At last it dead-ended at ...."; a fixed order as "work the exhibits in the order they're lettered – a gumshoe who
  jumps ahead fingers the wrong man", "follow the trail the way it runs, one clue after the next"; a free one as
  "LOOSE ENDS – three leads, none of them tied to another" with "‣" bullets, "shake them down in any sequence you
  choose; no lead hangs on the one before it", "none of them hangs on another, so tail them in whichever sequence
  your nose tells you"; one goal as "One lead and one lead only: .... Everything else in this town is a dead end.";
- a city tour guide's spiel: "GRAND TOUR OF THE HOUSE – the full circuit", "First sight: ...", "Second sight:
  ...", "Final sight: ...", or "Welcome aboard, ladies and gentlemen! On your left you'll see .... Coming up next,
  ...; and last but not least, ...."; fixed as "we see the sights strictly in the order on the itinerary, and the
  coach won't double back", "the itinerary runs in this order and we never double back"; free as "HOP-ON, HOP-OFF
  PASS – three sights included" with "☆" bullets, "the pass covers every sight, in any sequence you care to take
  them", "there's no itinerary this time – see them in whatever order your feet fancy"; one goal as "Today's tour
  has just the one stop: ....".

Goals: attributes before the noun, in a bracket "(the witness had it down as teal and corduroy)" or as an aside ",
in all its teal and corduroy glory,"; states before the noun ("the switched-on lamp"), as "(switched on at last
report)" or ", switched on to this day,"; the room as "in the X", "in the house's X" or "in the X of this house",
always before any relation; relations in new words ("a short stroll from", "within earshot of", "flush against",
"jammed up against", "keeping watch beside", "hanging out beside", "loafing by", "keeping vigil by", "sprawled on",
"sat square on", "lying low under", "half-hidden under", "lording it over", "dangling above", "bottled up in",
"sealed inside", "loaded with", "lugging", "in the room that plays host to", "in a room it shares with", "out front
of", "in plain view in front of", "in back of", "ducking behind", "eyeballing", "glaring across at", "on the left
flank of", "a shuffle to the left of", "on the right flank of", "a shuffle to the right of", besides the plain
words); several relations joined by "and", ", and what's more" or ", and for good measure"; an anchor with relations
of its own takes them in a bracket, "(to wit, the one next to the record player)" or "(the very one next to the
record player)". Readings: "overtakes", "has ... beat", "lands on the high side of", "never gets down to", "gets the
better of"; "never sags below", "has a floor of", "starts at ... and only goes up", "won't settle for less than";
"ducks under", "lands on the low side of", "doesn't climb as high as", "comes in beneath", "limbos under"; "stops
climbing at", "never pokes above", "hits the roof at", "goes as high as ... and not a notch more"; "hovers near",
"lands close to", "is ..., a hair either side", "runs at about"; and comparatives of the reading itself ("burns
hotter than", "runs colder than", "is every bit as warm as ..., if not warmer", "is ... or chillier", "is damper
than", "is drier than", "is ... or drier", "is greener than .6 on the NDVI scale", "is less green than", "is no
greener than", "is about as green as"); frames "that ...", "whose humidity ...", "whose temperature, the lab says,
...", "famous for an NDVI that ..."; units "°C", "degrees Celsius", "Celsius", "degrees" (with words), "%", "per
cent", "percent", "% relative humidity"; numbers as digits, words ("forty", "minus four", "three hundred and
eighty"), "minus 4", "negative 4", "twenty point five", NDVI as ".65", "0.65", "zero point six five";
superlatives "the most torrid", "the most feverish", "the most bone-chilling", "the most ice-cold", "the hardiest",
"the liveliest", "the most yellowed", "the puniest", "the swampiest", "the most waterlogged", "the most dried-out",
"the least damp", "whose temperature outranks every other one's", "that's top of the heap for NDVI", "that takes
the gold for humidity", "whose temperature is outranked by every other one's", "that's bottom of the heap for
NDVI", "that finishes last of the field on humidity". Coordinates: "(coordinates on file: x 3.5, y 2)", "where the
map puts x at 3.5 and y at 2", "at the spot the map calls x 3.5, y 2"; always x then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.template_text import attributes_and_states as split_modifiers
from ragnav_jax.language.template_text import listed as _listed
from ragnav_jax.language.template_text import tidy as _clean
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Small helpers of this set's own

_SMALL = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
          "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen")
_DECADES = ("", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety")


def words_for(n: int) -> str:
    """A whole number in words: 'minus four', 'sixty-five', 'three hundred and eighty'."""
    if n < 0:
        return "minus " + words_for(-n)
    if n < 20:
        return _SMALL[n]
    if n < 100:
        return _DECADES[n // 10] + ("-" + _SMALL[n % 10] if n % 10 else "")
    if n < 1000:
        rest = n % 100
        return _SMALL[n // 100] + " hundred" + (" and " + words_for(rest) if rest else "")
    return str(n)


def _joined(states: list[str]) -> str:
    return " ".join(s.replace(" ", "-") for s in states)


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "a short stroll from", "within earshot of"),
    "next_to": ("next to", "flush against", "jammed up against"),
    "beside": ("beside", "keeping watch beside", "hanging out beside"),
    "by": ("by", "loafing by", "keeping vigil by"),
    "on": ("on", "sprawled on", "sat square on"),
    "under": ("under", "lying low under", "half-hidden under"),
    "above": ("above", "lording it over", "dangling above"),
    "in": ("in", "bottled up in", "sealed inside"),
    "with": ("with", "loaded with", "lugging"),
    "in_room_with": ("in the same room as", "in the room that plays host to", "in a room it shares with"),
    "in_front_of": ("in front of", "out front of", "in plain view in front of"),
    "behind": ("behind", "in back of", "ducking behind"),
    "opposite": ("opposite", "eyeballing", "glaring across at"),
    "left_of": ("to the left of", "on the left flank of", "a shuffle to the left of"),
    "right_of": ("to the right of", "on the right flank of", "a shuffle to the right of"),
}
_LINKS = (" and ", ", and what's more ", ", and for good measure ")


def _anchor(rng, t: Target, depth: int) -> str:
    """An anchor: attributes before the noun; states before it or, for an anchor without relations of its own, as
    '(switched on at last report)'; the anchor's own relations in a bracket of their own."""
    _, states = split_modifiers(t)
    out = "the "
    bracketed = bool(states) and depth == 1 and not t.relations and rng.uniform() < 0.35
    if states and not bracketed:
        out += _joined(states) + " "
    out += t.phrase
    if bracketed:
        out += f" ({' and '.join(states)} at last report)"
    if t.relations:
        inner = _chain(rng, t.relations, depth + 1)
        out += f" (to wit, the one {inner})" if rng.uniform() < 0.5 else f" (the very one {inner})"
    return out


def _chain(rng, rels: tuple[Relation, ...], depth: int = 1) -> str:
    out = ""
    for i, r in enumerate(rels):
        part = f"{_pick(rng, REL_WORDS[r.type])} {_anchor(rng, r.anchor, depth)}"
        out = part if i == 0 else out + _pick(rng, _LINKS) + part
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS = ("in the {}", "in the {}", "in the house's {}", "in the {} of this house")


def _noun_phrase(rng, t: Target, prefix: str, no_bracket: bool) -> str:
    """The goal's own noun phrase: 'the teal corduroy bean bag', 'the bean bag (the witness had it down as teal and
    corduroy)', 'the bean bag, in all its teal and corduroy glory,', 'the switched-on lamp', 'the lamp (switched on
    at last report)', 'the lamp, switched on to this day,'. With a superlative adjective the attributes stay before
    the noun; with a bracketed coordinate hint to follow (no_bracket), no bracket is written here."""
    pre, states = split_modifiers(t)
    if not t.phrase.endswith(t.head):  # a phrase of another shape: written as given, anything missing in an aside
        missing = [a for a in t.attributes if a not in t.phrase.split()]
        out = "the " + (f"{prefix} " if prefix else "") + t.phrase
        return out + (f", in all its {' and '.join(missing)} glory," if missing else "")
    head = t.phrase[len(t.phrase) - len(t.head):]
    attr = "before"
    if pre and not prefix:
        attr = _pick(rng, ("before", "before", "glory") if no_bracket else ("before", "before", "witness", "glory"))
    state = None
    if states:
        opts = ["before"] if prefix else ["before", "report", "to this day"]
        if no_bracket and "report" in opts:
            opts.remove("report")
        if attr == "witness" and "report" in opts:
            opts.remove("report")  # never two round brackets in a row
        if attr == "glory" and "to this day" in opts:
            opts.remove("to this day")  # one aside between commas is enough
        state = _pick(rng, opts)
    out = "the " + (f"{prefix} " if prefix else "")
    if state == "before":
        out += _joined(states) + " "
    if attr == "before":
        out += t.phrase
    elif attr == "witness":
        out += f"{head} (the witness had it down as {' and '.join(pre)})"
    else:
        out += head
        if state == "report":  # the bracket straight after the noun, then the aside
            out += f" ({' and '.join(states)} at last report)"
            state = None
        out += f", in all its {' and '.join(pre)} glory,"
    if state == "report":
        out += f" ({' and '.join(states)} at last report)"
    elif state == "to this day":
        out += f", {' and '.join(states)} to this day,"
    return out


_NUMERIC = re.compile(r"\d|\b(" + "|".join(w for w in _SMALL + _DECADES if w and w != "one") + r"|hundred)\b")


def render_goal_train3(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set TRAIN3 writes it: 'the teal corduroy bean bag in the house's nursery', 'the bean bag (the
    witness had it down as teal and corduroy)', 'the lamp, switched on to this day,', 'the most frigid fridge in the
    pantry', 'the guitar (coordinates on file: x 3.5, y 2)', 'the lamp flush against the credenza (to wit, the one
    loaded with the record player)'. The room comes before any relation (and before a superlative tail, which is
    read inside it); relations come last."""
    t = sg.target
    boxed_hint = hint.startswith("(")
    out = _noun_phrase(rng, Target(t.phrase, t.head, t.attributes), prefix, boxed_hint)
    room = _pick(rng, _ROOMS).format(sg.room) if sg.room else ""
    numeric = bool(tail) and bool(_NUMERIC.search(tail))
    hint_early = bool(hint) and rng.uniform() < 0.5
    if hint_early:
        out += " " + hint + ("," if not boxed_hint and (tail or room) else "")
    if tail:
        if room and (not numeric or rng.uniform() < 0.5):
            out += f" {room} {tail}"
        else:
            out += f" {tail}" + (f", {room}" if room else "")
    elif room:
        out += " " + room
    if hint and not hint_early:
        out += ("," if tail and not boxed_hint else "") + " " + hint
    if t.relations:
        comma = bool(tail) or (bool(hint) and not hint_early and not boxed_hint)
        out += ("," if comma else "") + " " + _chain(rng, t.relations)
    return _clean(out)


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

# Finite predicates, after "that", "whose <reading>", "whose <reading>, the lab says," or "famous for a <reading> that".
_VERBS = {
    "gt": ("overtakes {n}", "has {n} beat", "lands on the high side of {n}", "never gets down to {n}",
           "gets the better of {n}"),
    "ge": ("never sags below {n}", "has a floor of {n}", "starts at {n} and only goes up", "won't settle for less "
           "than {n}"),
    "lt": ("ducks under {n}", "lands on the low side of {n}", "doesn't climb as high as {n}", "comes in beneath {n}",
           "limbos under {n}"),
    "le": ("stops climbing at {n}", "never pokes above {n}", "hits the roof at {n}", "goes as high as {n} and not a "
           "notch more"),
    "approx": ("hovers near {n}", "lands close to {n}", "is {n}, a hair either side", "runs at about {n}"),
}
# Comparatives of the reading itself, after "that": the number (NDVI: '.6 on the NDVI scale') carries the reading.
_LIKE = {
    "temperature_c": {"gt": ("burns hotter than {n}", "runs warmer than {n}"),
                      "ge": ("is every bit as warm as {n}, if not warmer",),
                      "lt": ("runs colder than {n}", "keeps cooler than {n}"),
                      "le": ("is {n} or chillier", "is no warmer than {n}"),
                      "approx": ("feels about as warm as {n}",)},
    "humidity_pct": {"gt": ("is damper than {n}",), "ge": ("is every bit as damp as {n}, if not damper",),
                     "lt": ("is drier than {n}",), "le": ("is {n} or drier", "is no damper than {n}"),
                     "approx": ("is about as damp as {n}",)},
    "ndvi": {"gt": ("is greener than {n}",), "ge": ("is every bit as green as {n}, if not greener",),
             "lt": ("is less green than {n}",), "le": ("is no greener than {n}",),
             "approx": ("is about as green as {n}",)},
}
_NAMES = {"temperature_c": "temperature", "humidity_pct": "humidity", "ndvi": "NDVI"}
_ADJ = {
    ("temperature_c", "max"): ("warmest", "most torrid", "most feverish"),
    ("temperature_c", "min"): ("coldest", "most bone-chilling", "most ice-cold"),
    ("ndvi", "max"): ("healthiest", "hardiest", "liveliest"),
    ("ndvi", "min"): ("least healthy", "most yellowed", "puniest"),
    ("humidity_pct", "max"): ("most humid", "swampiest", "most waterlogged"),
    ("humidity_pct", "min"): ("driest", "most dried-out", "least damp"),
}


def _ranking(name: str, comparator: str) -> tuple[str, ...]:
    if comparator == "max":
        return (f"whose {name} outranks every other one's", f"that's top of the heap for {name}",
                f"that takes the gold for {name}")
    return (f"whose {name} is outranked by every other one's", f"that's bottom of the heap for {name}",
            f"that finishes last of the field on {name}")


_DIGIT_NAMES = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")


def _written_number(rng, reading: str, value: float) -> tuple[str, float, bool]:
    """(the number as written, its value, whether in words): digits ('40', '-4', '.65', '0.65', '20.5'), words
    ('forty', 'minus four', 'three hundred and eighty', 'twenty point five', 'zero point six five'), 'minus 4',
    'negative 4'."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    u = rng.uniform()
    if reading == "ndvi":
        if txt.startswith("0.") and u < 0.2:
            return "zero point " + " ".join(_DIGIT_NAMES[int(d)] for d in txt[2:]), v, True
        if txt.startswith("0.") and u < 0.6:
            return txt[1:], v, False
        return txt, v, False
    if reading not in ("temperature_c", "humidity_pct"):
        return txt, v, False
    whole = int(abs(v))
    if v == int(v):
        if u < 0.3 and abs(v) < 1000:
            return words_for(int(v)), v, True
        if v < 0 and u < 0.5:
            return f"minus {whole}", v, False
        if v < 0 and u < 0.65:
            return f"negative {whole}", v, False
    elif v > 0 and re.fullmatch(r"\d+\.\d", txt) and u < 0.3:
        return f"{words_for(whole)} point {_DIGIT_NAMES[int(txt[-1])]}", v, True
    elif v < 0 and u < 0.4:
        return f"minus {txt[1:]}", v, False
    return txt, v, False


def _unit_for(rng, reading: str, in_words: bool) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        if in_words:
            return _pick(rng, (" degrees", " degrees Celsius")), "c"
        return _pick(rng, (" °C", "°C", " degrees Celsius", " Celsius")), "c"
    if reading == "humidity_pct":
        if in_words:
            return _pick(rng, (" per cent", " percent")), "%"
        return _pick(rng, ("%", " per cent", " percent", "% relative humidity")), "%"
    return "", ""


def render_sensor_train3(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('most torrid', 'hardiest', 'least damp') or a ranking tail ('whose
    temperature outranks every other one's', 'that's bottom of the heap for NDVI'); thresholds after the noun
    ('that overtakes 60 °C', 'whose humidity hits the roof at forty per cent', 'famous for an NDVI that never sags
    below .65', 'that burns hotter than 60 °C', 'that is greener than 0.65 on the NDVI scale', 'whose temperature,
    the lab says, hovers near minus 4 degrees Celsius')."""
    rd = c.reading
    name = _NAMES.get(rd, rd.replace("_", " "))
    if c.is_superlative:
        adj = _ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, _ranking(name, c.comparator)), c
    n, value, in_words = _written_number(rng, rd, c.value)
    unit, code = _unit_for(rng, rd, in_words)
    written = SensorConstraint(rd, c.comparator, value, code)
    article = "an" if name == "NDVI" or name[:1] in "aeiou" else "a"
    if rd in _LIKE and rng.uniform() < 0.3:  # a comparative of the reading itself
        num = f"{n} on the NDVI scale" if rd == "ndvi" else n + unit
        return "", "that " + _pick(rng, _LIKE[rd][c.comparator]).format(n=num), written
    named = rd not in ("temperature_c", "humidity_pct")  # NDVI (and any other reading) is always named
    frame = _pick(rng, ("whose", "lab", "famous") if named else ("that", "that", "whose", "lab", "famous"))
    verb = _pick(rng, _VERBS[c.comparator]).format(n=n + unit)
    if frame == "that":
        return "", "that " + verb, written
    if frame == "whose":
        return "", f"whose {name} {verb}", written
    if frame == "lab":
        return "", f"whose {name}, the lab says, {verb}", written
    return "", f"famous for {article} {name} that {verb}", written


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_train3(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: '(coordinates on file: x 3.5, y 2)', 'where the map
    puts x at 3.5 and y at 2', 'at the spot the map calls x 3.5, y 2'."""
    return _pick(rng, (f"(coordinates on file: x {x}, y {y})", f"where the map puts x at {x} and y at {y}",
                       f"at the spot the map calls x {x}, y {y}"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _sep(res: list[str]) -> str:
    return ";" if any("," in r for r in res) else ","


_CASES = ("the Vanishing Alibi", "the Midnight Caller", "the Broken Promise", "the Blue Monday Job",
          "the Lady in the Raincoat")
_LETTERS = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
_TRAIL = ("From there it led me to", "Next it took me to", "Then the scent carried on to", "After that I turned up at")


def _detective(rng, res: list[str], order: str) -> str:
    """A hard-boiled private eye: a case file of exhibits, or the trail as it ran."""
    if len(res) == 1:
        return _pick(rng, (f"One lead and one lead only: {res[0]}. Everything else in this town is a dead end.",
                           f"Short case, this. The only stop on the trail is {res[0]}, and the rest is smoke."))
    n = len(res)
    w = words_for(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"CASE FILE – The Business of {_pick(rng, _CASES)}"]
            for i, r in enumerate(res):
                tag = " (the clincher)" if i == n - 1 else ""
                lines.append(f"Exhibit {_LETTERS[i] if i < len(_LETTERS) else i + 1}{tag}: {r}")
            lines.append("Work the exhibits in the order they're lettered – a gumshoe who jumps ahead fingers the "
                         "wrong man.")
            return "\n".join(lines)
        s = f"It was raining when the trail picked up at {res[0]}."
        s += "".join(f" {_pick(rng, _TRAIL)} {r}." for r in res[1:-1])
        return s + (f" At last it dead-ended at {res[-1]}. Follow the trail the way it runs, one clue after the next – "
                    "no cutting corners.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"‣ {r}" for r in res)
        return (f"LOOSE ENDS – {w} leads, none of them tied to another\n{body}\nShake them down in any sequence you "
                "choose; no lead hangs on the one before it.")
    return (f"Plenty of leads on the desk tonight: {_listed(rng, res)}. None of them hangs on another, so tail them "
            "in whichever sequence your nose tells you.")


_TOURS = ("the full circuit", "the morning departure", "highlights edition", "the grand loop")
_ORDINAL = ("First", "Second", "Third", "Fourth", "Fifth", "Sixth", "Seventh", "Eighth", "Ninth", "Tenth")
_PATTER = ("Coming up next, we have", "Then, if you follow my umbrella, there's", "After that, on your right, is",
           "Just round the corner now is")


def _tour_guide(rng, res: list[str], order: str) -> str:
    """A city tour guide: an itinerary of sights, or the spiel from the front of the coach."""
    if len(res) == 1:
        return _pick(rng, (f"Today's tour has just the one stop: {res[0]}. Cameras at the ready, folks!",
                           f"And on your right you'll see {res[0]} – the sole sight on today's programme."))
    n = len(res)
    w = words_for(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"GRAND TOUR OF THE HOUSE – {_pick(rng, _TOURS)}"]
            for i, r in enumerate(res[:-1]):
                lines.append(f"{_ORDINAL[i] if i < len(_ORDINAL) else 'Next'} sight: {r}")
            lines.append(f"Final sight: {res[-1]}")
            lines.append("Stay with the umbrella, folks – we see the sights strictly in the order on the itinerary, "
                         "and the coach won't double back.")
            return "\n".join(lines)
        s = f"Welcome aboard, ladies and gentlemen! On your left you'll see {res[0]}."
        s += "".join(f" {_pick(rng, _PATTER)} {r}." for r in res[1:-1])
        return s + (f" And last but not least, {res[-1]}. Please keep up – the itinerary runs in this order and we "
                    "never double back.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"☆ {r}" for r in res)
        return (f"HOP-ON, HOP-OFF PASS – {w} sights included\n{body}\nThe pass covers every sight, in any sequence you "
                "care to take them.")
    return (f"Free afternoon, folks! Highlights on offer: {_listed(rng, res)}. There's no itinerary this time – see "
            "them in whatever order your feet fancy.")


def render_instruction_train3(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of two people (a hard-boiled private eye, a city tour guide).
    Goals stay in visiting order; strict texts say the order is fixed ('in the order they're lettered', 'jumps
    ahead', 'the way it runs', 'one clue after the next', 'in the order on the itinerary', 'won't double back',
    'runs in this order'), free ones say it is open ('any sequence you choose', 'no lead hangs on', 'hangs on
    another', 'whichever sequence your nose', 'any sequence you care', 'no itinerary', 'whatever order your feet')."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(2))
    return (_detective, _tour_guide)[who](rng, res, order)
