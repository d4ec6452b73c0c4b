"""Training phrasings of set Train2: goal, sensor, coordinate and instruction templates for the `unseen_train2` split.

Written to teach the learned instruction readers one more pair of authors, by a helper that never read the parser
(nor its lexicon, tagger, readings, agreement or command code, nor the evaluation code), with only the interface of
the earlier template sets in view (`phrasings_y.py`, `phrasings_x.py` and the docstrings of the others). Same four
functions, arguments and meanings as the other template sets. Two people write here, and a whole instruction is in
one voice: the first of the four functions called with a generator draws the voice, every later call with that
same generator writes in it, and `render_instruction_train2` closes it (so the next episode draws afresh).

- an estate agent showing buyers round: "VIEWING ITINERARY – The Old Rectory, Little Hadlow", "First viewing: ...",
  "Final viewing: ...", or the patter "Do come in! We'll begin at ..., then do step through to ..., and we'll
  finish the tour at ..."; a fixed order as "viewings are to be made strictly in the order listed", "please follow
  the tour in the order set out – the vendors are most particular about it"; a free one as "KEY FEATURES" with "•"
  bullets, "an open viewing: take the features in whichever sequence you prefer", "no need to go round in any
  particular order"; one goal as "a single-feature viewing today: .... It really must be seen.";
- a teenager texting: lower case, "rn", "tbh", "ngl", "lowkey", "u", "pls", "n" for and, "em" for them; "ok so
  first: ... / then: ... / last: ...", "can u go to ... first, then ..., then ... pls"; fixed as "has to be that
  exact order tho", "dont mix up the order"; free as "stuff to check rn:" with "-" bullets, "order doesnt matter
  lowkey", "do em in whatever order tbh"; one goal as "just go to ... rn thx thats it".

Goals: attributes before the noun, as "(a charming teal and corduroy specimen)" or ", teal and corduroy no less," (the
agent), ", the teal n corduroy one," or "(teal n corduroy, u cant miss it)" (the teenager); states before the noun
("the switched-on lamp"), as "(left switched on for viewings)" or ", which the vendors keep switched on,", or as ",
thats switched on rn," or "(switched on atm)"; the room as "in the X", "in the well-appointed X", "in the
light-filled X", "within the X", "inside the X", always before any relation; relations in new words ("moments from",
"within easy reach of", "immediately alongside", "sat neatly next to", "sited beside", "handily placed by",
"showcased on", "set neatly beneath", "elevated above", "commanding views over", "enclosed in", "complemented by",
"benefitting from", "in a room also home to", "taking centre stage in front of", "discreetly set behind", "with
views across to", "sited to the left of"; "rly close to", "right nxt to", "chillin by", "sittin on", "undr", "abv",
"stuck in", "w", "rockin", "in the same rm as", "infront of", "bhind", "on the other side from", "lil bit left of",
besides the plain words); several relations joined by "and", ", whilst also", ", and indeed", " n " or " n also ";
an anchor with relations of its own takes them in a bracket ("(the very one next to the record player)", "(which is
to say, the one ...)", "(the one ... obvs)", "(like the one ...)"), and an anchor's state may stand in one ("(left
open)", "(open rn)").

Readings, the agent: "streets ahead of", "a step up from", "that clears ... with room to spare" (above); "from ...
upwards", "pitched at ... or higher", "never slips beneath" (at least); "never quite reaches", "held beneath", "a
step down from" (below); "that stops at", "never rises beyond", "of ... or below" (at most); "in the order of", "a
stone's throw either side of", "pitched somewhere near" (about); the teenager: "thats higher than", "that smashes",
"goes over", "above ... fr" (above); "30c+", "isnt under", "or more tbh" (at least); "doesnt even hit", "sub 30c",
"lower than ... ngl", "cant even reach" (below); "30c max", "doesnt go over", "or lower" (at most); "bout",
"somewhere round", "close-ish to" (about). Units "°C", "degrees Celsius", "degrees", "c" ("30c"), "°", "degs",
"deg", "%", "per cent", "percent", "pct"; numbers as digits, words ("thirty-five", "minus four"), "minus 4", "neg
4", "-4", halves ("20 and a half"), NDVI as ".65" or "0.65". Superlatives "the most piping-hot", "the most tropical",
"the most bracing", "the most ice-cold", "the most well-tended", "the most blooming", "the most neglected", "the
most tired-looking", "the most damp-prone", "the most condensation-prone", "the least damp-prone", "the most
moisture-free", "whose temperature heads the listings", "ranked first of all for NDVI", "with a humidity that
outranks every other on the books" (and "sits at the bottom of the listings", "ranked last of all", "that every other
on the books outranks"); "the most boiling", "the most heated", "the most freezing", "the most frozen", "the most
alive", "the healthiest lookin", "the deadest", "the most dyin", "the swampiest", "the sweatiest", "the most dried
out", "the least swampy", "thats top tier temp-wise", "w the highest humidity of em all", "that beats every other
one on ndvi" (and "bottom tier", "the lowest ... of em all", "that loses to every other one on ..."). Coordinates:
"at plot reference x 3.5, y 2", "(co-ordinates per the particulars: x 3.5, y 2)", "positioned at 3.5 on the x axis
and 2 on the y axis", "@ x 3.5 y 2", "(its at x 3.5, y 2)", "at 3.5, 2 (x then y)"; always x then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.template_text import attributes_and_states, number_words
from ragnav_jax.language.template_text import hyphenated as _hyphen
from ragnav_jax.language.template_text import tidy as _tidy
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

AGENT, TEEN = "agent", "teen"

# ----------------------------------------------------------------------------------------------------
# The voice of one instruction: drawn from the generator at its first use, kept until the instruction is written.
# Each entry holds the generator itself, so its id cannot be reused by another generator while the entry lives.

_VOICES: dict[int, tuple[np.random.Generator, str]] = {}
_MAX_VOICES = 256


def _voice(rng: np.random.Generator) -> str:
    got = _VOICES.get(id(rng))
    if got is not None and got[0] is rng:
        return got[1]
    voice = AGENT if rng.uniform() < 0.5 else TEEN
    while len(_VOICES) >= _MAX_VOICES:
        _VOICES.pop(next(iter(_VOICES)))
    _VOICES[id(rng)] = (rng, voice)
    return voice


def _close_voice(rng: np.random.Generator) -> str:
    voice = _voice(rng)
    _VOICES.pop(id(rng), None)
    return voice


# ----------------------------------------------------------------------------------------------------
# Small helpers of this set's own

_ONES = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
         "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen")
_TENS = ("", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety")


def _and(voice: str, items: list[str]) -> str:
    return (" and " if voice == AGENT else " n ").join(items)


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    AGENT: {
        "near": ("near", "moments from", "within easy reach of"),
        "next_to": ("next to", "immediately alongside", "sat neatly next to"),
        "beside": ("beside", "sited beside", "placed handsomely beside"),
        "by": ("by", "handily placed by", "set by"),
        "on": ("on", "resting on", "showcased on"),
        "under": ("under", "set neatly beneath", "beneath"),
        "above": ("above", "elevated above", "commanding views over"),
        "in": ("in", "enclosed in", "fitted into"),
        "with": ("with", "complemented by", "benefitting from"),
        "in_room_with": ("in the same room as", "in a room also home to", "in the same space as"),
        "in_front_of": ("in front of", "in pride of place in front of", "taking centre stage in front of"),
        "behind": ("behind", "discreetly set behind", "set back behind"),
        "opposite": ("opposite", "with views across to", "directly facing"),
        "left_of": ("to the left of", "set to the left of", "sited to the left of"),
        "right_of": ("to the right of", "set to the right of", "sited to the right of"),
    },
    TEEN: {
        "near": ("near", "rly close to", "kinda near"),
        "next_to": ("next to", "right nxt to", "nxt to"),
        "beside": ("beside", "literally beside"),
        "by": ("by", "chillin by"),
        "on": ("on", "sittin on", "chillin on"),
        "under": ("under", "undr", "jammed under"),
        "above": ("above", "abv", "hangin above"),
        "in": ("in", "inside of", "stuck in"),
        "with": ("with", "w", "rockin"),
        "in_room_with": ("in the same room as", "in the same rm as", "in the room w"),
        "in_front_of": ("in front of", "right in front of", "infront of"),
        "behind": ("behind", "bhind", "round behind"),
        "opposite": ("opposite", "on the other side from", "across from"),
        "left_of": ("left of", "to the left of", "lil bit left of"),
        "right_of": ("right of", "to the right of", "lil bit right of"),
    },
}
_JOINS = {AGENT: (" and ", ", whilst also ", ", and indeed "), TEEN: (" and ", " n ", " n also ")}


def _anchor_np(rng, voice: str, t: Target, depth: int) -> str:
    """An anchor: attributes before the noun; states before it or, for an anchor without relations of its own, in a
    bracket ('(left open)', '(open rn)'); the anchor's own relations in a bracket of their own."""
    _, states = attributes_and_states(t)
    out = "the "
    bracket_state = bool(states) and depth == 1 and not t.relations and rng.uniform() < 0.35
    if states and not bracket_state:
        out += _hyphen(states) + " "
    out += t.phrase
    if bracket_state:
        out += f" (left {' and '.join(states)})" if voice == AGENT else f" ({' n '.join(states)} rn)"
    if t.relations:
        inner = _rel_chain(rng, voice, t.relations, depth + 1)
        if voice == AGENT:
            out += f" (the very one {inner})" if rng.uniform() < 0.5 else f" (which is to say, the one {inner})"
        else:
            out += f" (the one {inner} obvs)" if rng.uniform() < 0.5 else f" (like the one {inner})"
    return out


def _rel_chain(rng, voice: str, rels: tuple[Relation, ...], depth: int = 1) -> str:
    out = ""
    for i, r in enumerate(rels):
        part = f"{_pick(rng, REL_WORDS[voice][r.type])} {_anchor_np(rng, voice, r.anchor, depth)}"
        out = part if i == 0 else out + _pick(rng, _JOINS[voice]) + part
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS = {AGENT: ("in the {}", "in the {}", "in the well-appointed {}", "in the light-filled {}", "within the {}"),
          TEEN: ("in the {}", "in the {}", "inside the {}")}


def _goal_np(rng, voice: str, t: Target, prefix: str, no_bracket: bool) -> str:
    """The goal's own noun phrase: 'the teal corduroy bean bag', 'the bean bag (a charming teal and corduroy
    specimen)', 'the bean bag, teal and corduroy no less,', 'the bean bag, the teal n corduroy one,', 'the bean bag
    (teal n corduroy, u cant miss it)', 'the switched-on lamp', 'the lamp (left switched on for viewings)', 'the
    lamp, which the vendors keep switched on,', 'the lamp, thats switched on rn,', 'the lamp (switched on atm)'.
    With a superlative adjective (prefix) or a bracketed hint to follow (no_bracket), all stands before the noun."""
    pre, states = attributes_and_states(t)
    if not t.phrase.endswith(t.head):  # a phrase of another shape: written as given, anything missing in an aside
        missing = [a for a in t.attributes if a not in t.phrase.split()]
        out = "the " + (f"{prefix} " if prefix else "") + t.phrase
        return out + (f", {_and(voice, missing)} no less," if voice == AGENT else
                      f", the {_and(voice, missing)} one,") if missing else out
    head = t.phrase[len(t.phrase) - len(t.head):]
    plain = bool(prefix) or no_bracket
    attr_style = "before"
    if pre and not plain:
        attr_style = _pick(rng, ("before", "before", "bracket", "aside"))
    state_style = None
    if states:
        opts = ["before"] if plain else ["before", "bracket", "aside"]
        if attr_style == "bracket" and "bracket" in opts:
            opts.remove("bracket")  # never two round brackets in a row
        state_style = _pick(rng, opts)
    out = "the " + (f"{prefix} " if prefix else "")
    if state_style == "before":
        out += _hyphen(states) + " "
    if attr_style == "before":
        out += t.phrase
    elif attr_style == "bracket":
        out += (f"{head} (a charming {_and(voice, pre)} specimen)" if voice == AGENT else
                f"{head} ({_and(voice, pre)}, u cant miss it)")
    else:
        out += f"{head}, {_and(voice, pre)} no less," if voice == AGENT else f"{head}, the {_and(voice, pre)} one,"
    s = _and(voice, states)
    if state_style == "bracket" and attr_style == "aside":  # the bracket straight after the noun, then the aside
        bracket = f" (left {s} for viewings)" if voice == AGENT else f" ({s} atm)"
        aside = f"{_and(voice, pre)} no less," if voice == AGENT else f"the {_and(voice, pre)} one,"
        return f"the {head}{bracket}, {aside}"
    if state_style == "bracket":
        out += f" (left {s} for viewings)" if voice == AGENT else f" ({s} atm)"
    elif state_style == "aside":
        out += f", which the vendors keep {s}," if voice == AGENT else f", thats {s} rn,"
    return out


_HAS_NUMBER = re.compile(r"\d|\b(" + "|".join(w for w in _ONES + _TENS if w and w != "one") + r"|hundred)\b")


def render_goal_train2(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal in the instruction's voice: 'the teal corduroy bean bag in the well-appointed nursery', 'the lamp
    (left switched on for viewings) moments from the credenza (the very one complemented by the record player)',
    'the most bracing mini-fridge within the games room', 'the bean bag, the teal n corduroy one, inside the nursery
    rly close to the crib', 'the guitar @ x 3.5 y 2'. The room comes before any relation (and before a superlative
    tail, which is read inside it); a coordinate hint comes after any number of a sensor tail; relations come last."""
    voice = _voice(rng)
    t = sg.target
    out = _goal_np(rng, voice, Target(t.phrase, t.head, t.attributes), prefix, hint.startswith("("))
    room = _pick(rng, _ROOMS[voice]).format(sg.room) if sg.room else ""
    numeric_tail = bool(tail) and bool(_HAS_NUMBER.search(tail))
    hint_first = bool(hint) and not numeric_tail and rng.uniform() < 0.6
    if hint_first:
        out += " " + hint
    if tail:  # a superlative is read inside the room; a threshold stays with the noun, the room after a comma
        out += f" {room} {tail}" if room and not numeric_tail else f" {tail}" + (f", {room}" if room else "")
    elif room:
        out += " " + room
    if hint and not hint_first:
        out += (", " if numeric_tail and not (room and out.endswith(room)) else " ") + hint
    if t.relations:
        out += ("," if tail else "") + " " + _rel_chain(rng, voice, t.relations)
    return _tidy(out)


# ----------------------------------------------------------------------------------------------------
# Sensor phrases
#
# Each idiom is a template: {n} the number with its unit, {nm} the reading's name, {an} the name with its article.
# One without {nm} or {an} leaves the reading to its unit, so it is only used for a temperature or a humidity that
# has one. A leading '#' marks an idiom that only takes digits ('30c+').

_IDIOMS = {
    AGENT: {
        "gt": ("with {an} streets ahead of {n}", "boasting {an} a step up from {n}",
               "whose {nm} clears {n} with room to spare", "that clears {n} with room to spare"),
        "ge": ("boasting {an} from {n} upwards", "with {an} pitched at {n} or higher",
               "whose {nm} never slips beneath {n}", "that never slips beneath {n}"),
        "lt": ("whose {nm} never quite reaches {n}", "with {an} held beneath {n}", "boasting {an} a step down from {n}",
               "that never quite reaches {n}"),
        "le": ("with {an} that stops at {n}", "whose {nm} never rises beyond {n}", "boasting {an} of {n} or below",
               "that never rises beyond {n}"),
        "approx": ("with {an} in the order of {n}", "boasting {an} a stone's throw either side of {n}",
                   "whose {nm} is pitched somewhere near {n}", "that sits in the order of {n}"),
    },
    TEEN: {
        "gt": ("w {nm} thats higher than {n}", "where the {nm} goes over {n}", "that smashes {n}",
               "thats above {n} fr"),
        "ge": ("#w {nm} {n}+", "where the {nm} isnt under {n}", "#thats {n}+", "thats {n} or more tbh"),
        "lt": ("w {nm} that doesnt even hit {n}", "where the {nm} is lower than {n} ngl", "thats sub {n}",
               "that cant even reach {n}"),
        "le": ("w {nm} {n} max", "where the {nm} doesnt go over {n}", "thats {n} max", "thats {n} or lower"),
        "approx": ("w {nm} bout {n}", "where the {nm} is close-ish to {n}", "thats somewhere round {n}",
                   "thats bout {n}"),
    },
}
_NAMES = {AGENT: {"temperature_c": "temperature", "humidity_pct": "humidity", "ndvi": "NDVI"},
          TEEN: {"temperature_c": "temp", "humidity_pct": "humidity", "ndvi": "ndvi"}}
_SUPER_ADJ = {
    AGENT: {("temperature_c", "max"): ("most piping-hot", "most tropical"),
            ("temperature_c", "min"): ("most bracing", "most ice-cold"),
            ("ndvi", "max"): ("most well-tended", "most blooming"),
            ("ndvi", "min"): ("most neglected", "most tired-looking"),
            ("humidity_pct", "max"): ("most damp-prone", "most condensation-prone"),
            ("humidity_pct", "min"): ("least damp-prone", "most moisture-free")},
    TEEN: {("temperature_c", "max"): ("most boiling", "most heated"),
           ("temperature_c", "min"): ("most freezing", "most frozen"),
           ("ndvi", "max"): ("most alive", "healthiest lookin"),
           ("ndvi", "min"): ("deadest", "most dyin"),
           ("humidity_pct", "max"): ("swampiest", "sweatiest"),
           ("humidity_pct", "min"): ("most dried out", "least swampy")},
}
_SUPER_TAILS = {
    (AGENT, "max"): ("whose {nm} heads the listings", "ranked first of all for {nm}",
                     "with {an} that outranks every other on the books"),
    (AGENT, "min"): ("whose {nm} sits at the bottom of the listings", "ranked last of all for {nm}",
                     "with {an} that every other on the books outranks"),
    (TEEN, "max"): ("thats top tier {nm}-wise", "w the highest {nm} of em all", "that beats every other one on {nm}"),
    (TEEN, "min"): ("thats bottom tier {nm}-wise", "w the lowest {nm} of em all",
                    "that loses to every other one on {nm}"),
}


def _number(rng, voice: str, reading: str, value: float) -> tuple[str, float, str]:
    """(the number as written, its value, how): digits ('35', '-4', '.65', '0.65', '20.5'), words ('thirty-five',
    'minus four'), 'minus 4', 'neg 4', a half as '20 and a half' or 'twenty and a half'."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    u = rng.uniform()
    if reading == "ndvi" or reading not in ("temperature_c", "humidity_pct"):
        if txt.startswith("0.") and u < 0.5:
            return txt[1:], v, "digits"
        return txt, v, "digits"
    whole = int(abs(v))
    if v == int(v):
        if u < (0.3 if voice == AGENT else 0.12) and abs(v) < 1000:
            return number_words(int(v)), v, "words"
        if v < 0 and u < 0.65:
            return (f"minus {whole}" if voice == AGENT else f"neg {whole}"), v, "digits"
    elif v > 0 and abs(v) - whole == 0.5 and voice == AGENT and u < 0.45:
        if u < 0.2 and whole < 1000:
            return f"{number_words(whole)} and a half", v, "words"
        return f"{whole} and a half", v, "words"
    elif v < 0 and u < 0.5:
        return (f"minus {txt[1:]}" if voice == AGENT else f"neg {txt[1:]}"), v, "digits"
    return txt, v, "digits"


def _unit(rng, voice: str, reading: str, how: str) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        if voice == AGENT:
            return _pick(rng, (" degrees", " degrees Celsius") if how == "words" else
                         ("°C", " °C", " degrees Celsius", " degrees")), "c"
        return _pick(rng, (" degrees", " degs") if how == "words" else ("c", "°", " degs", " deg")), "c"
    if reading == "humidity_pct":
        if voice == AGENT:
            return _pick(rng, (" per cent",) if how == "words" else ("%", " per cent", " percent")), "%"
        return _pick(rng, (" percent",) if how == "words" else ("%", " percent", " pct")), "%"
    return "", ""


def _article(name: str) -> str:
    return ("an " if name.upper() == "NDVI" or name[:1] in "aeiou" else "a ") + name


def render_sensor_train2(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('most bracing', 'swampiest') or a tail ('whose temperature heads the
    listings', 'thats bottom tier ndvi-wise'); thresholds after the noun ('with a temperature streets ahead of 30
    °C', 'whose humidity never slips beneath forty per cent', 'boasting an NDVI a step down from .65', 'thats sub
    30c', 'w ndvi 0.6+', 'where the temp is close-ish to neg 4 degs')."""
    voice = _voice(rng)
    rd = c.reading
    name = _NAMES[voice].get(rd, rd.replace("_", " "))
    if c.is_superlative:
        adj = _SUPER_ADJ[voice].get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, _SUPER_TAILS[(voice, c.comparator)]).format(nm=name, an=_article(name)), c
    n, value, how = _number(rng, voice, rd, c.value)
    unit, code = _unit(rng, voice, rd, how)
    idioms = [i for i in _IDIOMS[voice][c.comparator] if not (i.startswith("#") and how != "digits")]
    if not unit:  # NDVI (and any reading without a unit) is always named
        idioms = [i for i in idioms if "{nm}" in i or "{an}" in i]
    idiom = _pick(rng, idioms).lstrip("#")
    named = "{nm}" in idiom or "{an}" in idiom
    if named and unit and rd == "temperature_c" and how == "digits" and rng.uniform() < 0.15:
        unit, code = "", ""  # the reading is named: the unit may go
    written = SensorConstraint(rd, c.comparator, value, code)
    return "", idiom.format(n=n + unit, nm=name, an=_article(name)), written


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_train2(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y, in the instruction's voice: 'at plot reference x 3.5,
    y 2', '(co-ordinates per the particulars: x 3.5, y 2)', 'positioned at 3.5 on the x axis and 2 on the y axis';
    '@ x 3.5 y 2', '(its at x 3.5, y 2)', 'at 3.5, 2 (x then y)'."""
    if _voice(rng) == AGENT:
        return _pick(rng, (f"at plot reference x {x}, y {y}", f"(co-ordinates per the particulars: x {x}, y {y})",
                           f"positioned at {x} on the x axis and {y} on the y axis"))
    return _pick(rng, (f"@ x {x} y {y}", f"(its at x {x}, y {y})", f"at {x}, {y} (x then y)"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions

_ORDINALS = ("First", "Second", "Third", "Fourth", "Fifth", "Sixth", "Seventh", "Eighth", "Ninth", "Tenth")
_PROPERTIES = ("The Old Rectory, Little Hadlow", "Orchard House", "Wisteria Cottage", "The Granary, Mill Lane",
               "Rose Villa, Church Row", "The Coach House")
_GREETINGS = ("Do come in!", "Lovely to see you – mind the step.", "Isn't it a glorious day for a viewing?",
              "Welcome, welcome – shoes on is fine.")
_STEPS = ("then do step through to", "from there, do pop through to", "after which we move on to",
          "then it's just a short stroll to")


def _sep(res: list[str]) -> str:
    return ";" if len(res) > 2 and any("," in r for r in res) else ","


def _listed(rng, res: list[str], joins: tuple[str, str]) -> str:
    """Goals in a running sentence: commas, or semicolons where a goal has commas of its own."""
    if len(res) == 2:
        return f"{res[0]} and {res[1]}"
    if any("," in r for r in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return ", ".join(res[:-1]) + _pick(rng, joins) + res[-1]


def _agent(rng, res: list[str], order: str) -> str:
    """An estate agent: a viewing itinerary or the patter of the tour; key features for a free order."""
    if len(res) == 1:
        return _pick(rng, (f"A single-feature viewing today: {res[0]}. It really must be seen to be believed.",
                           f"Just the one to show you this morning – {res[0]} – and that's the whole itinerary, "
                           "I promise."))
    n = len(res)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"VIEWING ITINERARY – {_pick(rng, _PROPERTIES)}"]
            lines += [f"{_ORDINALS[i] if i < len(_ORDINALS) else 'Next'} viewing: {r}" for i, r in enumerate(res[:-1])]
            lines.append(f"Final viewing: {res[-1]}")
            lines.append("Viewings are to be made strictly in the order listed, as arranged with the vendors.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"{_pick(rng, _GREETINGS)} We'll begin at {res[0]}"
        s += "".join(f"{sep} {_pick(rng, _STEPS)} {r}" for r in res[1:-1])
        return s + (f"{sep} and we'll finish the tour at {res[-1]}. Do please follow the tour in the order set out – "
                    "the vendors are most particular about it.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"• {r}" for r in res)
        return (f"KEY FEATURES – {_pick(rng, _PROPERTIES)} ({number_words(n)} not to be missed)\n{body}\nAn open "
                "viewing: take the features in whichever sequence you prefer.")
    return (f"{_pick(rng, _GREETINGS)} It's an open house today, so do wander: {_listed(rng, res, (' and ', ', and '))}. "
            "No need to go round in any particular order – see them however suits you.")


def _teen(rng, res: list[str], order: str) -> str:
    """A teenager texting: lower case, abbreviations, lines or one run-on message."""
    if len(res) == 1:
        return _pick(rng, (f"just go to {res[0]} rn thx thats it", f"only need u at {res[0]} tbh, nothing else lol"))
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = ["ok so", f"first: {res[0]}"] + [f"then: {r}" for r in res[1:-1]] + [f"last: {res[-1]}"]
            lines.append(_pick(rng, ("has to be that exact order tho", "dont mix up the order pls")))
            return "\n".join(lines)
        glue = " and" if any("," in r for r in res) else ","
        s = f"hey can u go to {res[0]} first"
        s += "".join(f"{glue} then {r}" for r in res[1:-1])
        return s + f"{',' if glue == ',' else ''} and finish at {res[-1]} rn. " + _pick(rng, ("that exact order pls or mom gets mad",
                                                                         "dont mix up the order ngl"))
    if rng.uniform() < 0.5:
        body = "\n".join(f"- {r}" for r in res)
        return f"stuff to check rn:\n{body}\ndo em in whatever order tbh, just get all of em"
    if any("," in r for r in res):
        listed = " and also ".join(res)
    else:
        listed = ", ".join(res[:-1]) + _pick(rng, (" n ", " and ")) + res[-1]
    return f"can u hit {listed} rn? order doesnt matter lowkey"


def render_instruction_train2(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, in the voice its goals were written in (an estate agent or a
    teenager texting), which this call then closes. Goals stay in visiting order; strict texts say the order is
    fixed ('strictly in the order listed', 'follow the tour in the order set out', 'that exact order', 'dont mix up
    the order'), free ones say it is open ('whichever sequence you prefer', 'no need to go round in any particular
    order', 'whatever order tbh', 'order doesnt matter')."""
    voice = _close_voice(rng)
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    return (_agent if voice == AGENT else _teen)(rng, res, order)
