"""Held-out phrasings of set Y: goal, sensor, coordinate and instruction templates for the `unseen_y` split.

Written by a helper that never read the parser (nor its lexicon, tagger, readings, agreement or command code, nor
the evaluation code), before any run of any reader on these sentences, with only the interface of the earlier
template sets in view (`phrasings_x.py`, `phrasings_v.py` and the docstrings of the others). Same four functions,
arguments and meanings as the other template sets. The style is four people who send a home robot round a house
in the layout and words of their own job or pastime:

- a showjumping commentator, as a course plan or live commentary: "SHOWJUMPING – Hickstead, Class 4: the robot's
  round", "Fence 1: ...", "Fence 2 (oxer): ...", "Final fence: ...", or "Here we go, then! Away from the start
  and down to ..., round the turn to ..., and to finish, ...!"; a fixed order as "a standard round – the fences are
  jumped in numbered order, and a fence taken out of turn means elimination", "in exactly the order walked this
  morning"; a free one as "GAMBLER'S CHOICE – three fences, rider's choice of route" with "»" bullets, "jump them
  in whatever sequence you like", "it can take them in any order it likes – the route is entirely the rider's
  call"; one goal as "a jump-off against the clock, and just a single fence to clear: ...";
- a fairy-tale narrator: "Once upon a time a little robot was sent out on three errands ...", "On the first day
  it went to ....", "And on the last day of all it came to ....", "because it kept to the order, one errand after
  another, it lived happily ever after", or the old woman's words ("First you must go to ...; when that is done,
  go on to ...; and last of all, go to .... Do them in exactly that order, for if you go out of turn the spell
  will break."); free as "the fairy godmother gave the little robot three wishes to gather:" with "❧" bullets,
  "gather them in whatever order you please", "the wise owl told it that the order did not matter one bit – any
  one of them might come first"; one goal as "a little robot with only one errand in all the world: to find its
  way to ...";
- a sommelier's tasting notes: "TASTING FLIGHT – Light to Full-Bodied, three glasses", "Glass 1: .... Notes:
  crisp acidity.", or "Tonight's flight: we open with ..., move on to ..., and close with ...."; fixed as "taste
  strictly in the order poured – each glass sets the palate for the next", "in exactly this sequence – the flight
  is built to progress"; free as "OPEN BAR – three bottles uncorked" with "◇" bullets, "no set flight here –
  sample them in any order you fancy", "these aren't poured as a flight, so go round them in whatever order suits
  the palate"; one goal as "Just one glass this evening: .... Nothing else to pour.";
- a speedrunner's route notes: "ROUTE NOTES – House Tour, glitchless (RTA)", "split 1 – ...", "final split – ...
  (timer stops)", or "ok so the route for this attempt: timer starts, go straight to ..., then ..., and timer ends
  on ...."; fixed as "splits go in route order, no sequence breaks or the run's invalid", "gotta do these in route
  order, no skips"; free as "ALL COLLECTIBLES – order is free" with "*" bullets, "any order is legal, only the final
  time matters", "no forced order in this category – grab whatever's closest first"; one goal as "single-segment
  run: timer starts, go to ..., timer stops. that's the whole category."

Goals: attributes before the noun, in a bracket "(you want the teal and corduroy one)" or as an aside ", teal and
corduroy to look at,"; states before the noun ("the switched-on lamp"), as "(switched on, by all accounts)" or ",
which stands switched on,"; the room as "in the X" or "in the X part of the house", always before any relation;
relations in new words ("in striking distance of", "a hop, skip and jump from", "abutting", "hip to hip with",
"neighbouring", "at the side of", "at the elbow of", "idling by", "dawdling by", "lounging on", "squatting on",
"hunkered under", "dozing beneath", "presiding over", "poised above", "cooped up in", "holed up in", "toting",
"twinned with", "bunking with", "in the same quarters as", "out ahead of", "posed in front of", "in the lee of",
"hanging back behind", "vis-à-vis", "across the floor from", "at the left hand of", "a smidge to the left of", "at
the right hand of", "a smidge to the right of", besides the plain words); several relations joined by "and", ",
not to mention" or ", and equally"; an anchor with relations of its own takes them in a bracket, "(as in, the one
next to the record player)" or "(that being the one next to the record player)". Readings: "surpasses", "is up
past", "outpaces", "is ... at the lowest", "never drops below", "won't go under", "keeps below", "tucks in under",
"hasn't got up to", "is ... at the highest", "never climbs above", "won't go over", "is in and around", "is ... or
near it", "is getting on for"; frames "that ...", "whose humidity ...", "which has a temperature that ...",
"showing an NDVI that ..."; units "°C", "centigrade", "degrees on the thermometer", "degrees" (with words), none
when the reading is named, "%", "per cent", "pct", "per cent RH", "percent"; numbers as digits, words ("forty",
"minus four"), "minus 4", "4 below" (a temperature near which), "22 point 5", NDVI as ".65", "0.65", "sixty-five
hundredths", "six tenths"; superlatives "the most roasting", "the most sizzling", "the most polar", "the most
perishing", "the most luxuriant", "the bushiest", "the limpest", "the most shrivelled", "the stickiest", "the
dewiest", "the thirstiest", "the most powder-dry", "with a temperature nobody else can match", "that's number one
for NDVI", "whose humidity leaves the rest standing", "with a temperature nobody else can get down to", "that's dead
last for NDVI", "whose humidity the rest all beat". Coordinates: "at 3.5 on the horizontal and 2 on the vertical",
"(x marks 3.5, y marks 2)", "at 3.5, 2 (x, y order)", "at 3.5 m on the x scale and 2 m on the y scale"; always x
then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.template_text import attributes_and_states, number_words
from ragnav_jax.language.template_text import hyphenated as _hyphen
from ragnav_jax.language.template_text import listed as _listed
from ragnav_jax.language.template_text import tidy as _tidy
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Small helpers of this set's own

_ONES = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
         "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen")
_TENS = ("", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety")


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "in striking distance of", "a hop, skip and jump from"),
    "next_to": ("next to", "abutting", "hip to hip with", "neighbouring"),
    "beside": ("beside", "at the side of", "at the elbow of"),
    "by": ("by", "idling by", "dawdling by"),
    "on": ("on", "lounging on", "squatting on"),
    "under": ("under", "hunkered under", "dozing beneath"),
    "above": ("above", "presiding over", "poised above"),
    "in": ("in", "cooped up in", "holed up in"),
    "with": ("with", "toting", "twinned with"),
    "in_room_with": ("in the same room as", "bunking with", "in the same quarters as"),
    "in_front_of": ("in front of", "out ahead of", "posed in front of"),
    "behind": ("behind", "in the lee of", "hanging back behind"),
    "opposite": ("opposite", "vis-à-vis", "across the floor from"),
    "left_of": ("to the left of", "at the left hand of", "a smidge to the left of"),
    "right_of": ("to the right of", "at the right hand of", "a smidge to the right of"),
}
_JOINS = (" and ", ", not to mention ", ", and equally ")


def _anchor_np(rng, t: Target, depth: int) -> str:
    """An anchor: attributes before the noun; states before it or, for an anchor without relations of its own, as
    '(switched on, by all accounts)'; the anchor's own relations in a bracket of their own."""
    _, states = attributes_and_states(t)
    out = "the "
    bracket_state = bool(states) and depth == 1 and not t.relations and rng.uniform() < 0.35
    if states and not bracket_state:
        out += _hyphen(states) + " "
    out += t.phrase
    if bracket_state:
        out += f" ({' and '.join(states)}, by all accounts)"
    if t.relations:
        inner = _rel_chain(rng, t.relations, depth + 1)
        if rng.uniform() < 0.5:
            out += f" (as in, the one {inner})"
        else:
            out += f" (that being the one {inner})"
    return out


def _rel_chain(rng, rels: tuple[Relation, ...], depth: int = 1) -> str:
    out = ""
    for i, r in enumerate(rels):
        part = f"{_pick(rng, REL_WORDS[r.type])} {_anchor_np(rng, r.anchor, depth)}"
        out = part if i == 0 else out + _pick(rng, _JOINS) + part
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS = ("in the {}", "in the {}", "in the {} part of the house")


def _goal_np(rng, t: Target, prefix: str, no_bracket: bool) -> str:
    """The goal's own noun phrase: 'the teal corduroy bean bag', 'the bean bag (you want the teal and corduroy one)',
    'the bean bag, teal and corduroy to look at,', 'the switched-on lamp', 'the lamp (switched on, by all
    accounts)', 'the lamp, which stands switched on,', 'the lamp (switched on, by all accounts), teal to look at,'.
    With a superlative adjective the attributes stay before the noun; with a bracketed coordinate hint to follow
    (no_bracket), everything stands before the noun."""
    pre, states = attributes_and_states(t)
    if not t.phrase.endswith(t.head):  # a phrase of another shape: written as given, anything missing in an aside
        missing = [a for a in t.attributes if a not in t.phrase.split()]
        out = "the " + (f"{prefix} " if prefix else "") + t.phrase
        return out + (f", {' and '.join(missing)} to look at," if missing else "")
    head = t.phrase[len(t.phrase) - len(t.head):]
    attr_style = "before"
    if pre and not prefix and not no_bracket:
        attr_style = _pick(rng, ("before", "before", "want", "aside"))
    state_style = None
    if states:
        opts = ["before"] if no_bracket else ["before", "accounts", "stands"]
        if attr_style == "want":
            opts.remove("accounts")  # never two round brackets in a row
        if attr_style == "aside":
            opts.remove("stands")  # one aside between commas is enough
        state_style = _pick(rng, opts)
    out = "the " + (f"{prefix} " if prefix else "")
    if state_style == "before":
        out += _hyphen(states) + " "
    if attr_style == "before":
        out += t.phrase
    elif attr_style == "want":
        out += f"{head} (you want the {' and '.join(pre)} one)"
    elif state_style == "accounts":  # the bracket straight after the noun, then the aside
        return out + f"{head} ({' and '.join(states)}, by all accounts), {' and '.join(pre)} to look at,"
    else:
        out += f"{head}, {' and '.join(pre)} to look at,"
    if state_style == "accounts":
        out += f" ({' and '.join(states)}, by all accounts)"
    elif state_style == "stands":
        out += f", which stands {' and '.join(states)},"
    return out


_HAS_NUMBER = re.compile(r"\d|\b(" + "|".join(w for w in _ONES + _TENS if w and w != "one") +
                         r"|hundred|hundredths?|tenths?)\b")


def render_goal_y(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set Y writes it: 'the teal corduroy bean bag in the nursery part of the house', 'the bean bag (you
    want the teal and corduroy one)', 'the lamp, which stands switched on,', 'the most polar fridge in the pantry',
    'the guitar (x marks 3.5, y marks 2)', 'the lamp hip to hip with the credenza (as in, the one toting the record
    player)'. The room comes before any relation (and before a superlative tail, which is read inside it); a
    coordinate hint comes after any number of a sensor tail; relations come last."""
    t = sg.target
    bracket_hint = hint.startswith("(")
    out = _goal_np(rng, Target(t.phrase, t.head, t.attributes), prefix, bracket_hint)
    room = _pick(rng, _ROOMS).format(sg.room) if sg.room else ""
    numeric_tail = bool(tail) and bool(_HAS_NUMBER.search(tail))
    hint_first = bool(hint) and not numeric_tail and rng.uniform() < 0.6
    if hint_first:
        out += " " + hint
    if tail:
        if room and (not numeric_tail or rng.uniform() < 0.5):
            out += f" {room} {tail}"
        else:
            out += f" {tail}" + (f", {room}" if room else "")
    elif room:
        out += " " + room
    if hint and not hint_first:
        out += (", " if numeric_tail and not (room and out.endswith(room)) else " ") + hint
    if t.relations:
        out += ("," if tail else "") + " " + _rel_chain(rng, t.relations)
    return _tidy(out)


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

# Finite predicates: after "that", "whose <reading>", "which has a <reading> that" or "showing a <reading> that".
_FINITE = {
    "gt": ("surpasses {n}", "is up past {n}", "outpaces {n}"),
    "ge": ("is {n} at the lowest", "never drops below {n}", "won't go under {n}"),
    "lt": ("keeps below {n}", "tucks in under {n}", "hasn't got up to {n}"),
    "le": ("is {n} at the highest", "never climbs above {n}", "won't go over {n}"),
    "approx": ("is in and around {n}", "is {n} or near it", "is getting on for {n}"),
}
_NAMES = {"temperature_c": "temperature", "humidity_pct": "humidity", "ndvi": "NDVI"}
_SUPER_ADJ = {
    ("temperature_c", "max"): ("warmest", "most roasting", "most sizzling"),
    ("temperature_c", "min"): ("coldest", "most polar", "most perishing"),
    ("ndvi", "max"): ("healthiest", "most luxuriant", "bushiest"),
    ("ndvi", "min"): ("least healthy", "limpest", "most shrivelled"),
    ("humidity_pct", "max"): ("most humid", "stickiest", "dewiest"),
    ("humidity_pct", "min"): ("driest", "thirstiest", "most powder-dry"),
}


def _super_tails(name: str, comparator: str) -> tuple[str, ...]:
    if comparator == "max":
        return (f"with a {name} nobody else can match", f"that's number one for {name}",
                f"whose {name} leaves the rest standing")
    return (f"with a {name} nobody else can get down to", f"that's dead last for {name}",
            f"whose {name} the rest all beat")


def _fraction_words(txt: str) -> str | None:
    """'0.65' -> 'sixty-five hundredths', '0.6' -> 'six tenths', '0.01' -> 'one hundredth'; None otherwise."""
    if not txt.startswith("0.") or len(txt) > 4:
        return None
    d = txt[2:]
    k = int(d)
    if k == 0:
        return None
    word = "tenth" if len(d) == 1 else "hundredth"
    return f"{number_words(k)} {word}" + ("" if k == 1 else "s")


def _number(rng, reading: str, value: float, approx: bool = False) -> tuple[str, float, str]:
    """(the number as written, its value, how): digits ('40', '-4', '.65', '0.65'), words ('forty', 'minus four',
    'sixty-five hundredths', 'six tenths'), 'minus 4', 'minus 2.5', '22 point 5', or 'below' for a negative
    temperature near which (approx) to be written 'N below' with no unit."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    u = rng.uniform()
    if reading == "ndvi":
        frac = _fraction_words(txt)
        if frac is not None and u < 0.3:
            return frac, v, "words"
        if u < 0.65 and txt.startswith("0."):
            return txt[1:], v, "digits"
        return txt, v, "digits"
    if reading not in ("temperature_c", "humidity_pct"):
        return txt, v, "digits"
    whole = int(abs(v))
    if v == int(v):
        if v < 0 and reading == "temperature_c" and approx and rng.uniform() < 0.35:  # 'four below'
            return (number_words(whole) if rng.uniform() < 0.5 else str(whole)), v, "below"
        if u < 0.3 and abs(v) < 1000:
            return number_words(int(v)), v, "words"
        if u < 0.55 and v < 0:
            return f"minus {whole}", v, "digits"
    elif v > 0 and re.fullmatch(r"\d+\.\d", txt) and u < 0.35:
        return txt.replace(".", " point "), v, "digits"
    elif v < 0 and u < 0.5:
        return f"minus {txt[1:]}", v, "digits"
    return txt, v, "digits"


def _unit(rng, reading: str, how: str) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        if how == "below":
            return "", ""
        if how == "words":
            return _pick(rng, (" degrees", " centigrade", " degrees on the thermometer")), "c"
        return _pick(rng, (" °C", "°C", " centigrade", " degrees on the thermometer")), "c"
    if reading == "humidity_pct":
        if how == "words":
            return _pick(rng, (" per cent", " percent")), "%"
        return _pick(rng, ("%", " per cent", " pct", " per cent RH")), "%"
    return "", ""


def render_sensor_y(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('most polar', 'bushiest', 'thirstiest') or a tail ('that's number
    one for temperature', 'whose NDVI the rest all beat'); thresholds after the noun ('that surpasses 60 °C', 'whose
    humidity is forty per cent at the highest', 'showing an NDVI that never drops below sixty-five hundredths',
    'whose temperature is in and around 4 below', 'which has a humidity that keeps below 22 point 5 pct')."""
    rd = c.reading
    name = _NAMES.get(rd, rd.replace("_", " "))
    if c.is_superlative:
        adj = _SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, _super_tails(name, c.comparator)), c
    n, value, how = _number(rng, rd, c.value, c.comparator == "approx")
    unit, code = _unit(rng, rd, how)
    # NDVI (and any other reading) is always named, and so is a temperature written without its unit
    named = rd not in ("temperature_c", "humidity_pct") or how == "below"
    frame = _pick(rng, ("whose", "hasa", "showing") if named else ("that", "that", "whose", "hasa", "showing"))
    if frame != "that" and rd == "temperature_c" and how == "digits" and rng.uniform() < 0.15:
        unit, code = "", ""  # the reading is named: the unit may go
    written = SensorConstraint(rd, c.comparator, value, code)
    finite = _pick(rng, _FINITE[c.comparator]).format(n=n + " below" if how == "below" else n + unit)
    article = "an" if name == "NDVI" or name[:1] in "aeiou" else "a"
    if frame == "that":
        return "", "that " + finite, written
    if frame == "whose":
        return "", f"whose {name} {finite}", written
    if frame == "hasa":
        return "", f"which has {article} {name} that {finite}", written
    return "", f"showing {article} {name} that {finite}", written


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_y(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at 3.5 on the horizontal and 2 on the vertical',
    '(x marks 3.5, y marks 2)', 'at 3.5, 2 (x, y order)', 'at 3.5 m on the x scale and 2 m on the y scale'."""
    return _pick(rng, (f"at {x} on the horizontal and {y} on the vertical", f"(x marks {x}, y marks {y})",
                       f"at {x}, {y} (x, y order)", f"at {x} m on the x scale and {y} m on the y scale"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _sep(res: list[str]) -> str:
    return ";" if any("," in r for r in res) else ","


_SHOWS = ("Hickstead", "the County Show", "Olympia", "the Royal Highland", "Badminton Park")
_FENCES = ("oxer", "upright", "combination", "treble", "triple bar")
_TURNS = ("round the turn to", "across to", "swinging back to", "then it's a long gallop down to", "a tight line to")


def _commentator(rng, res: list[str], order: str) -> str:
    """A showjumping commentator: a course plan or live commentary."""
    if len(res) == 1:
        return _pick(rng, (f"A jump-off against the clock, and just a single fence to clear: {res[0]}. Over you go!",
                           f"One fence only in this final test – {res[0]} – and that's the whole round. "
                           "Let's see if it goes clear."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"SHOWJUMPING – {_pick(rng, _SHOWS)}, Class {int(rng.integers(1, 9))}: the robot's round"]
            for i, r in enumerate(res[:-1]):
                kind = f" ({_pick(rng, _FENCES)})" if i and rng.uniform() < 0.4 else ""
                lines.append(f"Fence {i + 1}{kind}: {r}")
            lines.append(f"Final fence: {res[-1]}")
            lines.append("It's a standard round – the fences are jumped in numbered order, and a fence taken out of "
                         "turn means elimination.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Here we go, then! Away from the start and down to {res[0]}"
        s += "".join(f"{sep} {_pick(rng, _TURNS)} {r}" for r in res[1:-1])
        return s + (f"{sep} and to finish, {res[-1]}! They must jump them in exactly the order walked this morning – "
                    "a fence out of turn and the bell goes.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"» {r}" for r in res)
        return (f"GAMBLER'S CHOICE – {w} fences, rider's choice of route\n{body}\nIn this class the robot picks its "
                "own line: jump them in whatever sequence you like, so long as each one is cleared.")
    return (f"It's a Gambler's Choice this afternoon, so the robot has {_listed(rng, res)} to clear – {w} obstacles in "
            "all – and it can take them in any order it likes; the route is entirely the rider's call.")


_ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth")


def _fairy_tale(rng, res: list[str], order: str) -> str:
    """A fairy-tale narrator: days of a quest, the old woman's words, or the fairy godmother's wishes."""
    if len(res) == 1:
        return _pick(rng, (f"Once upon a time there was a little robot with only one errand in all the world: to find "
                           f"its way to {res[0]}. And so it did, and it lived happily ever after.",
                           f"“Go to {res[0]},” said the old woman, “and nowhere else.” And off the little robot "
                           "went."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"Once upon a time a little robot was sent out on {w} errands, and it had to do them in just the "
                     "order the old woman told it, or the spell would be broken."]
            for i, r in enumerate(res[:-1]):
                verb = "went to" if i == 0 else _pick(rng, ("went on to", "travelled to", "made its way to"))
                lines.append(f"On the {_ORDINALS[i] if i < len(_ORDINALS) else 'next'} day it {verb} {r}.")
            lines.append(f"And on the last day of all it came to {res[-1]}.")
            lines.append("And because it kept to the order, one errand after another, it lived happily ever after.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"“Listen carefully, little robot,” said the old woman. “First you must go to {res[0]}"
        s += "".join(f"{sep} {_pick(rng, ('when that is done, go on to', 'after that, go to', 'next, go to'))} {r}"
                     for r in res[1:-1])
        return s + (f"{sep} and last of all, go to {res[-1]}. Do them in exactly that order, for if you go out of turn "
                    "the spell will break.”")
    if rng.uniform() < 0.5:
        body = "\n".join(f"❧ {r}" for r in res)
        return (f"Once upon a time the fairy godmother gave the little robot {w} wishes to gather:\n{body}\n“Gather "
                "them in whatever order you please,” she said, “for the magic cares not which comes first.”")
    return (f"In a house at the edge of the wood there lived a little robot, and its task was to visit "
            f"{_listed(rng, res)}. The wise owl told it that the order did not matter one bit – any one of them might "
            "come first.")


_FLIGHTS = ("Light to Full-Bodied", "A Tour of the Loire", "Old World Reds", "Cool-Climate Whites", "Rhône Valley")
_TASTING = ("crisp acidity", "soft tannins", "a lingering finish", "silky and supple", "ripe and generous",
            "bright and zesty", "a touch of spice")


def _sommelier(rng, res: list[str], order: str) -> str:
    """A sommelier: a tasting flight with numbered glasses, or the evening's notes."""
    if len(res) == 1:
        return _pick(rng, (f"Just one glass this evening: {res[0]}. Nothing else to pour.",
                           f"By the glass only – {res[0]} – and that's the whole list tonight."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"TASTING FLIGHT – {_pick(rng, _FLIGHTS)}, {w} glasses"]
            lines += [f"Glass {i + 1}: {r}. Notes: {_pick(rng, _TASTING)}." for i, r in enumerate(res)]
            lines.append("Taste strictly in the order poured – each glass sets the palate for the next, so no going "
                         "back and forth.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Tonight's flight, from the sommelier: we open with {res[0]}"
        s += "".join(f"{sep} {_pick(rng, ('move on to', 'follow with', 'carry on to'))} {r}" for r in res[1:-1])
        return s + (f"{sep} and close with {res[-1]}. Please taste them in exactly this sequence – the flight is built "
                    "to progress, light to full.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"◇ {r}" for r in res)
        return f"OPEN BAR – {w} bottles uncorked\n{body}\nNo set flight here – sample them in any order you fancy."
    return (f"At the tasting table tonight: {_listed(rng, res)}. These aren't poured as a flight, so guests may go "
            "round them in whatever order suits the palate.")


def _speedrunner(rng, res: list[str], order: str) -> str:
    """A speedrunner's route notes: splits, or a chatty route."""
    if len(res) == 1:
        return _pick(rng, (f"single-segment run: timer starts, go to {res[0]}, timer stops. that's the whole category.",
                           f"IL attempt, one stop only – {res[0]}. reset if you miss it."))
    n = len(res)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"ROUTE NOTES – House Tour, {_pick(rng, ('glitchless', 'no major glitches', 'restricted'))} (RTA)"]
            lines += [f"split {i + 1} – {r}" for i, r in enumerate(res[:-1])]
            lines.append(f"final split – {res[-1]} (timer stops)")
            lines.append("splits go in route order, no sequence breaks or the run's invalid.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"ok so the route for this attempt: timer starts, go straight to {res[0]}"
        s += "".join(f"{sep} {_pick(rng, ('then', 'then straight to', 'after that'))} {r}" for r in res[1:-1])
        return s + (f"{sep} and timer ends on {res[-1]}. gotta do these in route order, no skips, no sequence "
                    "breaks.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"* {r}" for r in res)
        return (f"ALL COLLECTIBLES – {number_words(n)} pickups, order is free\n{body}\nroute them however you want, "
                "any order is legal, only the final time matters.")
    return (f"for the all-collectibles category you need {_listed(rng, res)}. no forced order in this category – grab "
            "whatever's closest first.")


def render_instruction_y(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a showjumping commentator, a fairy-tale
    narrator, a sommelier, a speedrunner). Goals stay in visiting order; strict texts say the order is fixed ('in
    numbered order', 'out of turn', 'the order walked', 'kept to the order', 'in exactly that order', 'the order
    poured', 'in exactly this sequence', 'route order', 'no sequence breaks'), free ones say it is open ('whatever
    sequence you like', 'any order it likes', 'the rider's call', 'whatever order you please', 'the order did not
    matter', 'any order you fancy', 'whatever order suits the palate', 'any order is legal', 'no forced order')."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(4))
    return (_commentator, _fairy_tale, _sommelier, _speedrunner)[who](rng, res, order)
