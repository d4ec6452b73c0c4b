"""Held-out phrasings of set AB: goal, sensor, coordinate and instruction templates for the `unseen_ab` split.

Written by a helper that never read the parser (nor its lexicon, tagger, sensor reader, readings, agreement,
adapters, LLM or command code, nor the evaluation code), before any run of any reader on these sentences, with
only the interface of set W in view (`phrasings_w.py`). (While wiring the split into config.py it saw the
uncommitted comment of round 25's grounding change there, which names "described as" frames; it reports that its own
attribute frames were chosen before that.) Same four functions, arguments and meanings as the other
template sets. The style is four people who send a home robot round a house, each in a register of their own:

- an old-fashioned telegram, the frame in capitals and every goal closed by "STOP": "CABLE TO HOUSE ROBOT STOP CALL
  FIRST AT ... STOP NEXT AT ... STOP LAST AT ... STOP", or numbered lines "URGENT – THREE CALLS IN STRICT SEQUENCE",
  "ONE: ... STOP", "TWO: ... STOP"; a fixed order as "KEEP TO THIS ORDER", "ORDER AS CABLED", "NO CALL OUT OF TURN",
  "IN STRICT SEQUENCE", "DO NOT RPT NOT ALTER ORDER"; a free one as "ANY ORDER WILL DO", "ORDER OF CALLS YOUR
  CHOICE", "ORDER OPTIONAL", "SEQUENCE YOURS TO CHOOSE"; one goal as "ONE CALL ONLY STOP ... STOP NOTHING FURTHER";
- a sat-nav voice: "Route planned: 3 waypoints.", "Waypoint 1 of 3: ....", "Destination: ....", or spoken "Starting
  route guidance. Proceed to .... After that, continue to .... Finally, your destination: ...."; fixed as "in the
  order shown", "waypoint order is locked", "the route must be followed in this sequence"; free as "Multi-stop
  route: 3 waypoints, order unset" with "→" lines, "may be reached in any sequence", "the route will be optimised",
  "visiting order: flexible", "the fastest route will be chosen for you"; one goal as "Destination set: ....";
- a town crier: "Oyez! Oyez! Oyez! Hear ye, all good folk! The robot of this house is bidden to go first unto ...;
  thence unto ...; and last of all unto ...!", or a "PROCLAMATION" with "Item the first: ....", "Item the last:
  ...."; fixed as "each in its due turn", "in that order and no other", "in order as here cried", "let none be
  visited out of turn"; free as "in what order it please", "no order is decreed", "in no set order", "as the fancy
  takes it" (with "❧" lines); one goal as "summoned to ..., and to nowhere else this day";
- a holidaymaker's postcard home: "Greetings from Lisbon! Weather glorious.", "Dear Robot,", numbered "1) ..."
  lines or "be a dear and first see to ..., then ..., and then finally ...", signed "Love, Bev & Tony xx"; fixed as
  "in exactly this order", "strictly that order", "in that order, mind", "don't jumble them up"; free as "no
  particular order" (with "–" lines), "whichever way round you fancy", "in any old order", "it really doesn't
  matter"; one goal as "only one little favour this time" or "just the one job while we're away".

Goals: attributes before the noun, after it as "described as teal and wool" or in a square-bracket tag "[teal,
wool]"; states before the noun ("the switched-on lamp"), as an apposition ", currently switched on,", in a clause
"that stands switched on" ("that stand" after a plural) or in a bracket "(switched on at the moment)"; an anchor's
states before its noun or, for an anchor without relations of its own, as "(open at present)"; the room as "in the
X", "out in the X", "up in the X", "from the X", "that lives in the X" ("that live" after a plural) or "belonging to
the X", always before any relation; relations in new words ("not far from", "a short hop from", "within easy reach
of", "snug up against", "immediately adjoining", "rubbing elbows with", "at the side of", "pulled up beside", "set
down beside", "right by", "close by", "stood by", "sitting up on", "balanced on", "laid on", "underneath", "lurking
beneath", "slid under", "suspended above", "hanging over", "high above", "inside", "packed inside", "held within",
"carrying", "kitted out with", "bearing", "under the same ceiling as", "in the room that also holds", "out in front
of", "to the fore of", "round the back of", "hidden behind", "in back of", "directly across from", "staring across
at", "off to the left of", "leftward of", "off to the right of", "rightward of", besides the plain words); several
relations joined by "and", ", and" or "and also"; an anchor with relations of its own takes them in a bracket
"(which is next to the drums)", "(that is next to the drums)", and deeper down after ", which for its part is"
(between dashes "— which for its part is ... —" when more of the bracket follows). Readings named "temperature",
"temp", "humidity", "relative humidity", "RH", "NDVI", "NDVI score", "vegetation index"; thresholds after "whose
<reading>": "clears", "reads higher than", "sits north of", "is no lower than", "is ... or over", "never dips
below", "stays beneath", "doesn't reach", "sits south of", "is no higher than", "is ... or under", "never climbs
past", "is circa", "is give or take", "is within a whisker of"; after "with a <reading>" or "showing a <reading>":
"clearing", "reading higher than", "north of", "no lower than", "of ... or over", "never dipping below", "staying
beneath", "not reaching", "south of", "no higher than", "of ... or under", "never climbing past", "of circa", "of
... give or take", "within a whisker of"; straight after the noun, the unit naming the reading: "reading higher
than", "running north of", "clearing", "reading no lower than", "reading ... or over", "never dipping below",
"staying beneath", "running south of", "not reaching", "reading no higher than", "reading ... or under", "never
climbing past", "reading circa", "running at ... give or take", "sitting within a whisker of" (no verb that agrees
with the noun, so "the drums" read as well as "the lamp"); units "C" ("40C"), "°" ("40°"), "degC", "degrees
centigrade", "centigrade", "degrees" (with words), none when the reading is named, "%", "per cent", "pct"; numbers
as digits, words ("forty", "minus four", "negative four", "one hundred and five"), "minus 4", "negative 4", "22½",
"22 point 5", "twenty-two point five", NDVI as "0.65", "point six five", "zero point six five", "sixty-five
hundredths", "six tenths"; superlatives "the balmiest", "the most scorching", "the most baking", "the chilliest",
"the iciest", "the most wintry", "the lushest", "the most thriving", "the most vigorous", "the sickliest", "the most
withered", "the most bedraggled", "the steamiest", "the dankest", "the stickiest", "the most desiccated", "the least
damp", "the most dried-out", "whose <reading> beats all the others", "with a <reading> nobody else can match",
"coming out top on <reading>", "whose <reading> is lower than all the others", "with a <reading> nobody else can
undercut", "coming out bottom on <reading>". Coordinates: "where x is 3.5 and y is 2", "at X3.5 Y2", "at the spot
marked x 3.5, y 2", "at [x 3.5 | y 2]", "at x-axis 3.5, y-axis 2"; always x then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.template_text import ONES, TENS, attributes_and_states, number_words
from ragnav_jax.language.template_text import both as _both
from ragnav_jax.language.template_text import hyphenated as _hyphen
from ragnav_jax.language.template_text import is_are as _is
from ragnav_jax.language.template_text import listed as _listed
from ragnav_jax.language.template_text import plural as _plural
from ragnav_jax.language.template_text import tidy as _tidy
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Small helpers of this set's own


def _its(head: str) -> str:
    return "their" if _plural(head) else "its"


def _missing(t: Target) -> list[str]:
    """Attributes a phrase of another shape (one that does not end on its head) does not write itself."""
    words = t.phrase.split()
    return [a for a in t.attributes if not all(w in words for w in a.split())]


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "not far from", "a short hop from", "within easy reach of"),
    "next_to": ("next to", "snug up against", "immediately adjoining", "rubbing elbows with"),
    "beside": ("beside", "at the side of", "pulled up beside", "set down beside"),
    "by": ("by", "right by", "close by", "stood by"),
    "on": ("on", "sitting up on", "balanced on", "laid on"),
    "under": ("under", "underneath", "lurking beneath", "slid under"),
    "above": ("above", "suspended above", "hanging over", "high above"),
    "in": ("in", "inside", "packed inside", "held within"),
    "with": ("with", "carrying", "kitted out with", "bearing"),
    "in_room_with": ("in the same room as", "under the same ceiling as", "in the room that also holds"),
    "in_front_of": ("in front of", "out in front of", "to the fore of"),
    "behind": ("behind", "round the back of", "hidden behind", "in back of"),
    "opposite": ("opposite", "directly across from", "staring across at"),
    "left_of": ("to the left of", "off to the left of", "leftward of"),
    "right_of": ("to the right of", "off to the right of", "rightward of"),
}
_JOINS = (" and ", ", and ", " and also ")


def _anchor_np(rng, t: Target, depth: int, last: bool) -> str:
    """An anchor: its states before the noun, or '(open at present)' for a top-level anchor without relations of
    its own; attributes a phrase of another shape lacks in a tag '[teal, wool]'; a top-level anchor's own relations
    in a bracket ('(which is next to ...)', '(that is next to ...)'); deeper down after ', which for its part is',
    between dashes when more of the bracket follows it (`last` False)."""
    _, states = attributes_and_states(t)
    out = "the "
    bracket_state = bool(states) and depth == 1 and not t.relations and rng.uniform() < 0.35
    if states and not bracket_state:
        out += _hyphen(states) + " "
    out += t.phrase
    if not t.phrase.endswith(t.head) and _missing(t):
        out += " [" + ", ".join(_missing(t)) + "]"
    if bracket_state:
        out += f" ({_both(states)} at present)"
    if t.relations:
        inner = _rel_chain(rng, t.relations, depth + 1)
        if depth > 1:
            clause = f"which for {_its(t.head)} part {_is(t.head)} {inner}"
            out += f", {clause}" if last else f" — {clause} —"
        else:
            out += f" ({_pick(rng, ('which', 'that'))} {_is(t.head)} {inner})"
    return out


def _rel_chain(rng, rels: tuple[Relation, ...], depth: int = 1, last: bool = True) -> str:
    """Relations joined by 'and', ', and' or 'and also'. `last`: nothing of the enclosing bracket follows."""
    out = ""
    for i, r in enumerate(rels):
        is_last = last and i + 1 == len(rels)
        part = f"{_pick(rng, REL_WORDS[r.type])} {_anchor_np(rng, r.anchor, depth, is_last)}"
        if i == 0:
            out = part
        else:
            join = _pick(rng, _JOINS)
            if out.endswith("—"):
                join = " and "
            out += join + part
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS_IN = ("in the {}", "in the {}", "out in the {}", "up in the {}", "from the {}", "belonging to the {}")
_ROOMS_CLAUSE = ("that {} in the {}",)


def _goal_np(rng, t: Target, prefix: str, clause_ok: bool) -> str:
    """The goal's own noun phrase: 'the teal wool lamp', 'the lamp described as teal and wool', 'the lamp [teal,
    wool]', 'the switched-on lamp', 'the lamp, currently switched on,', 'the lamp that stands switched on', 'the
    lamp (switched on at the moment)'. With a superlative adjective (prefix) the attributes stay before the noun."""
    pre, states = attributes_and_states(t)
    lead = "the " + (f"{prefix} " if prefix else "")
    if not t.phrase.endswith(t.head):  # a phrase of another shape: written as given, anything missing after it
        missing = _missing(t)
        out = lead + t.phrase
        if not missing:
            return out
        return out + _pick(rng, (f" described as {_both(missing)}", " [" + ", ".join(missing) + "]"))
    head = t.phrase[len(t.phrase) - len(t.head):]
    attr_style = "before"
    if pre and not prefix:
        attr_style = _pick(rng, ("before", "before", "described", "tag"))
    state_style = None
    if states:
        opts = ["before", "currently", "stands", "moment"]
        if attr_style == "described" or not clause_ok:
            opts.remove("stands")  # 'described as teal that stands open' would hang the clause on 'teal'
        state_style = _pick(rng, opts)
    out = lead
    if state_style == "before":
        out += _hyphen(states) + " "
    out += t.phrase if attr_style == "before" else head
    if attr_style == "described":
        out += f" described as {_both(pre)}"
    elif attr_style == "tag":
        out += " [" + ", ".join(pre) + "]"
    if state_style == "currently":
        out += f", currently {_both(states)},"
    elif state_style == "stands":
        out += f" that {'stand' if _plural(t.head) else 'stands'} {_both(states)}"
    elif state_style == "moment":
        out += f" ({_both(states)} at the moment)"
    return out


_HAS_NUMBER = re.compile(r"\d|½|\b(" + "|".join(w for w in ONES + TENS if w) + r"|hundred|hundredths?|tenths?)\b")


def render_goal_ab(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AB writes it: 'the teal wool lamp out in the nursery', 'the lamp described as teal and wool',
    'the lamp [teal, wool], currently switched on,', 'the chilliest mini-fridge from the pantry', 'the guitar at
    X3.5 Y2', 'the lamp that lives in the nursery, snug up against the credenza (which is bearing the record
    player)'. The room comes before any relation (and before a superlative tail, which is read inside it); a
    coordinate hint comes after any number of a sensor tail; relations come last."""
    t = sg.target
    out = _goal_np(rng, Target(t.phrase, t.head, t.attributes), prefix, clause_ok=not tail)
    clause = bool(re.search(r" that stands? ", out))
    room_frames = _ROOMS_IN if tail or clause else _ROOMS_IN + _ROOMS_CLAUSE
    room = ""
    if sg.room:
        frame = _pick(rng, room_frames)
        room = frame.format("live" if _plural(t.head) else "lives", sg.room) if frame in _ROOMS_CLAUSE else \
            frame.format(sg.room)
    numeric_tail = bool(tail) and bool(_HAS_NUMBER.search(tail))
    hint_first = bool(hint) and not numeric_tail and rng.uniform() < 0.5
    if hint_first:
        out += " " + hint
    if tail:
        if room and (not numeric_tail or rng.uniform() < 0.5):
            out += f" {room} {tail}"
        else:
            out += f" {tail}" + (f", {room}" if room else "")
    elif room:
        out += " " + room
    room_clause = room.startswith("that ")
    if hint and not hint_first:
        out += (", " if (tail or room_clause or clause) else " ") + hint
    if t.relations:
        comma = bool(tail) or bool(hint) or room_clause or clause
        out += ("," if comma else "") + " " + _rel_chain(rng, t.relations)
    return _tidy(out)


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

# Finite predicates (after "whose <reading>"), participles (after "with/showing a <reading>") and bare participles
# (straight after the noun, the unit naming the reading): none agrees with the noun, so a plural head reads right.
_FINITE = {
    "gt": ("clears {n}", "reads higher than {n}", "sits north of {n}"),
    "ge": ("is no lower than {n}", "is {n} or over", "never dips below {n}"),
    "lt": ("stays beneath {n}", "doesn't reach {n}", "sits south of {n}"),
    "le": ("is no higher than {n}", "is {n} or under", "never climbs past {n}"),
    "approx": ("is circa {n}", "is give or take {n}", "is within a whisker of {n}"),
}
_PARTICIPLE = {
    "gt": ("clearing {n}", "reading higher than {n}", "north of {n}"),
    "ge": ("no lower than {n}", "of {n} or over", "never dipping below {n}"),
    "lt": ("staying beneath {n}", "not reaching {n}", "south of {n}"),
    "le": ("no higher than {n}", "of {n} or under", "never climbing past {n}"),
    "approx": ("of circa {n}", "of {n} give or take", "within a whisker of {n}"),
}
_BARE = {
    "gt": ("reading higher than {n}", "running north of {n}", "clearing {n}"),
    "ge": ("reading no lower than {n}", "reading {n} or over", "never dipping below {n}"),
    "lt": ("staying beneath {n}", "running south of {n}", "not reaching {n}"),
    "le": ("reading no higher than {n}", "reading {n} or under", "never climbing past {n}"),
    "approx": ("reading circa {n}", "running at {n} give or take", "sitting within a whisker of {n}"),
}
_NAMES = {"temperature_c": ("temperature", "temperature", "temp"),
          "humidity_pct": ("humidity", "relative humidity", "RH"),
          "ndvi": ("NDVI", "NDVI score", "vegetation index")}
_SUPER_ADJ = {
    ("temperature_c", "max"): ("balmiest", "most scorching", "most baking"),
    ("temperature_c", "min"): ("chilliest", "iciest", "most wintry"),
    ("ndvi", "max"): ("lushest", "most thriving", "most vigorous"),
    ("ndvi", "min"): ("sickliest", "most withered", "most bedraggled"),
    ("humidity_pct", "max"): ("steamiest", "dankest", "stickiest"),
    ("humidity_pct", "min"): ("most desiccated", "least damp", "most dried-out"),
}


def _article(name: str) -> str:
    return "an" if name.startswith(("NDVI", "RH")) or name[:1].lower() in "aeiou" else "a"


def _super_tails(name: str, comparator: str) -> tuple[str, ...]:
    art = _article(name)
    if comparator == "max":
        return (f"whose {name} beats all the others", f"with {art} {name} nobody else can match",
                f"coming out top on {name}")
    return (f"whose {name} is lower than all the others", f"with {art} {name} nobody else can undercut",
            f"coming out bottom on {name}")


_DIGIT_WORDS = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")


def _ndvi_words(rng, txt: str) -> str:
    """'0.65' -> 'point six five', 'zero point six five' or 'sixty-five hundredths'; '0.6' -> 'six tenths'."""
    digits = txt[2:]
    u = rng.uniform()
    if u < 0.35:
        return "point " + " ".join(_DIGIT_WORDS[int(d)] for d in digits)
    if u < 0.65:
        return "zero point " + " ".join(_DIGIT_WORDS[int(d)] for d in digits)
    k = int(digits)
    part = "tenth" if len(digits) == 1 else "hundredth"
    return f"{number_words(k)} {part}{'' if k == 1 else 's'}"


def _number(rng, reading: str, value: float) -> tuple[str, float, str]:
    """(the number as written, its value, how): 'digits' ('40', '-4', 'minus 4', 'negative 4', '22½', '22 point
    5', '0.65') or 'words' ('forty', 'minus four', 'negative four', 'twenty-two point five', 'point six five',
    'zero point six five', 'sixty-five hundredths')."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    u = rng.uniform()
    if reading == "ndvi":
        if 0 < v < 1 and re.fullmatch(r"0\.\d\d?", txt) and u < 0.6:
            return _ndvi_words(rng, txt), v, "words"
        return txt, v, "digits"
    if reading not in ("temperature_c", "humidity_pct"):
        return txt, v, "digits"
    whole = int(abs(v))
    neg = v < 0
    if v == int(v):
        if u < 0.3 and abs(v) < 1000:
            w = number_words(int(v))
            if neg and rng.uniform() < 0.5:
                w = "negative" + w[len("minus"):]
            return w, v, "words"
        if neg and u < 0.45:
            return f"minus {whole}", v, "digits"
        if neg and u < 0.6:
            return f"negative {whole}", v, "digits"
        return txt, v, "digits"
    if re.fullmatch(r"-?\d+\.5", txt):
        sign = _pick(rng, ("minus ", "negative ")) if neg else ""
        if u < 0.25 and whole > 0:
            return f"{sign or ''}{whole}½" if not neg or rng.uniform() < 0.5 else f"-{whole}½", v, "digits"
        if u < 0.5 and whole < 100:
            return f"{sign}{number_words(whole)} point five", v, "words"
        if u < 0.65:
            return f"{sign}{whole} point 5", v, "digits"
    return txt, v, "digits"


def _unit(rng, reading: str, how: str, value: float, n: str) -> tuple[str, str]:
    """(text after the number, unit code). 'C' and '°' go only straight onto a digit or '½' ('40C', '22½°')."""
    if reading == "temperature_c":
        if how == "words":
            unit = _pick(rng, (" degrees", " degrees centigrade"))
        elif " point " in n:
            unit = _pick(rng, (" degC", " degrees centigrade", " centigrade"))
        else:
            unit = _pick(rng, ("C", "C", "°", " degC", " degrees centigrade", " centigrade"))
        if abs(value) == 1:
            unit = unit.replace("degrees", "degree")  # 'one degree', 'minus 1 degree centigrade'
        return unit, "c"
    if reading == "humidity_pct":
        if how == "words":
            return " per cent", "%"
        return _pick(rng, ("%", "%", " per cent", " pct")), "%"
    return "", ""


def render_sensor_ab(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('chilliest', 'most thriving', 'least damp') or a tail ('whose
    temperature beats all the others', 'with an NDVI nobody else can undercut', 'coming out top on RH');
    thresholds after the noun ('clearing 60C', 'whose humidity is no higher than forty per cent', 'with an NDVI
    score of point six five or over', 'showing a temp of circa minus four degrees', 'staying beneath 22½°')."""
    rd = c.reading
    name = _pick(rng, _NAMES.get(rd, (rd.replace("_", " "),)))
    if c.is_superlative:
        adj = _SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, _super_tails(name, c.comparator)), c
    n, value, how = _number(rng, rd, c.value)
    unit, code = _unit(rng, rd, how, value, n)

    named = rd not in ("temperature_c", "humidity_pct")  # NDVI (and any other reading) is always named
    frame = _pick(rng, ("whose", "with", "showing") if named else ("bare", "bare", "whose", "with", "showing"))
    if frame != "bare" and how == "digits" and not named and rng.uniform() < 0.15:
        unit, code = "", ""  # the reading is named: the unit may go
    written = SensorConstraint(rd, c.comparator, value, code)
    if frame in ("with", "showing"):
        said = _pick(rng, _PARTICIPLE[c.comparator]).format(n=n + unit)
        return "", f"{frame} {_article(name)} {name} {said}", written
    if frame == "bare":
        return "", _pick(rng, _BARE[c.comparator]).format(n=n + unit), written
    return "", f"whose {name} " + _pick(rng, _FINITE[c.comparator]).format(n=n + unit), written


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_ab(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'where x is 3.5 and y is 2', 'at X3.5 Y2', 'at the
    spot marked x 3.5, y 2', 'at [x 3.5 | y 2]', 'at x-axis 3.5, y-axis 2'."""
    return _pick(rng, (f"where x is {x} and y is {y}", f"at X{x} Y{y}", f"at the spot marked x {x}, y {y}",
                       f"at [x {x} | y {y}]", f"at x-axis {x}, y-axis {y}"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _sep(res: list[str]) -> str:
    return ";" if any("," in r for r in res) else ","


def _list(rng, res: list[str]) -> str:
    """Goals in a running sentence: 'A, B and C' for bare goals; semicolons ('A; B; and C') once a goal has words of
    its own after the noun, so the next goal cannot be read as one more anchor."""
    if all(re.fullmatch(r"the [\w'-]+(?: [\w'-]+)?", r) for r in res):
        return _listed(rng, res)
    if len(res) == 2:
        return f"{res[0]}; and {res[1]}"
    return "; ".join(res[:-1]) + "; and " + res[-1]


def _comma(goal: str) -> str:
    """A comma to close a goal that has commas of its own before the sentence goes on."""
    return "," if "," in goal else ""


_STRICT_CABLE = ("KEEP TO THIS ORDER STOP", "ORDER AS CABLED STOP", "NO CALL OUT OF TURN STOP")
_NEXT_CABLE = ("NEXT AT", "THEN AT", "AFTER THAT AT")
_TO = ("CABLE TO HOUSE ROBOT", "TELEGRAM FOR HOUSE ROBOT", "WIRE TO ROBOT AT HOME")
_SIGN = ("REGARDS HOUSEHOLD", "FONDEST REGARDS", "SIGNED THE FAMILY")


def _telegram(rng, res: list[str], order: str) -> str:
    """An old-fashioned telegram: the frame in capitals, each goal closed by STOP."""
    to = _pick(rng, _TO)
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"{to} STOP ONE CALL ONLY STOP {g} STOP NOTHING FURTHER STOP {_pick(rng, _SIGN)}",
                           f"{to} STOP PLS CALL AT {g} STOP THAT IS ALL STOP {_pick(rng, _SIGN)}"))
    n = len(res)
    w = number_words(n).upper()
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"URGENT – {w} CALLS IN STRICT SEQUENCE"]
            lines += [f"{number_words(i + 1).upper()}: {r} STOP" for i, r in enumerate(res)]
            lines.append("DO NOT RPT NOT ALTER ORDER STOP " + _pick(rng, _SIGN))
            return "\n".join(lines)
        s = f"{to} STOP CALL FIRST AT {res[0]} STOP "
        s += "".join(f"{_pick(rng, _NEXT_CABLE)} {r} STOP " for r in res[1:-1])
        return s + f"LAST AT {res[-1]} STOP {_pick(rng, _STRICT_CABLE)} {_pick(rng, _SIGN)}"
    if rng.uniform() < 0.5:
        lines = [f"{to} – {w} CALLS REQUIRED ORDER OPTIONAL"]
        lines += [f"CALL AT {r} STOP" for r in res]
        lines.append("SEQUENCE YOURS TO CHOOSE STOP " + _pick(rng, _SIGN))
        return "\n".join(lines)
    s = f"{to} STOP CALLS NEEDED AT {res[0]} STOP " + "".join(f"{r} STOP " for r in res[1:])
    return s + _pick(rng, ("ANY ORDER WILL DO STOP ", "ORDER OF CALLS YOUR CHOICE STOP ")) + _pick(rng, _SIGN)


_THEN_NAV = ("After that, continue to", "Then continue to", "Next, head to")


def _satnav(rng, res: list[str], order: str) -> str:
    """A sat-nav voice: a planned route of waypoints, or spoken guidance."""
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"Destination set: {g}. Starting route guidance.",
                           f"Navigating to {g}. You will arrive at your destination shortly."))
    n = len(res)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"Route planned: {n} waypoints."]
            lines += [f"Waypoint {i + 1} of {n}: {r}." for i, r in enumerate(res[:-1])]
            lines.append(f"Destination: {res[-1]}.")
            lines.append(_pick(rng, ("Please follow the waypoints in the order shown.",
                                     "Waypoint order is locked.")))
            return "\n".join(lines)
        s = f"Starting route guidance. Proceed to {res[0]}."
        s += "".join(f" {_pick(rng, _THEN_NAV)} {r}." for r in res[1:-1])
        return s + (f" Finally, your destination: {res[-1]}. "
                    + _pick(rng, ("The route must be followed in this sequence.", "Waypoint order is locked.")))
    if rng.uniform() < 0.5:
        body = "\n".join(f"→ {r}" for r in res)
        return (f"Multi-stop route: {n} waypoints, order unset.\n{body}\nThe waypoints may be reached in any sequence; "
                "the route will be optimised.")
    return (f"Waypoints added: {_list(rng, res)}. Visiting order: flexible – the fastest route will be chosen for "
            "you.")


_ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth",
             "eleventh", "twelfth")
_GOD_SAVE = ("God save the King!", "God save the Queen!", "Thus it is proclaimed!")


def _crier(rng, res: list[str], order: str) -> str:
    """A town crier: a proclamation with items, or one long cry."""
    if len(res) == 1:
        g, c = res[0], _comma(res[0])
        return _pick(rng, (f"Oyez! Oyez! Oyez! Hear ye! The robot is summoned to {g}{c} and to nowhere else this day! "
                           f"{_pick(rng, _GOD_SAVE)}",
                           f"Hear ye, hear ye! Let the robot betake itself to {g}{c} and there be done!"))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = ["PROCLAMATION", f"Be it known that the robot shall make {w} visits, in order as here cried:"]
            for i, r in enumerate(res):
                which = "last" if i == n - 1 else _ORDINALS[i] if i < len(_ORDINALS) else "next"
                lines.append(f"Item the {which}: {r}.")
            lines.append("Let none be visited out of turn! Oyez!")
            return "\n".join(lines)
        s = f"Oyez! Oyez! Oyez! Hear ye, all good folk! The robot of this house is bidden to go first unto {res[0]}"
        s += "".join(f"; thence unto {r}" for r in res[1:-1])
        return s + (f"; and last of all unto {res[-1]}! "
                    + _pick(rng, ("Each in its due turn!", "In that order and no other!")) + " "
                    + _pick(rng, _GOD_SAVE))
    if rng.uniform() < 0.5:
        body = "\n".join(f"❧ {r}" for r in res)
        return (f"PROCLAMATION\nHear ye! The robot hath {w} calls to pay, and may pay them in no set order, as the "
                f"fancy takes it:\n{body}\n{_pick(rng, _GOD_SAVE)}")
    return (f"Oyez! Oyez! The robot is bidden to visit {_list(rng, res)}, in what order it please! No order is "
            f"decreed! {_pick(rng, _GOD_SAVE)}")


_PLACES = ("Lisbon", "the Algarve", "Lake Garda", "Crete", "Whitby", "Tenerife", "Bruges")
_WEATHER = ("Weather glorious.", "Sun out all day.", "Bit of drizzle but lovely.", "Scorching here!",
            "Sea like a millpond.")
_NAMES_POST = ("Bev & Tony", "Sue and Dave", "Mags and Phil", "Ros & Kit")


def _postcard(rng, res: list[str], order: str) -> str:
    """A holidaymaker's postcard home: numbered jobs, a dashed list, or a chatty paragraph."""
    place, weather, sign = _pick(rng, _PLACES), _pick(rng, _WEATHER), f"Love, {_pick(rng, _NAMES_POST)} xx"
    if len(res) == 1:
        g, c = res[0], _comma(res[0])
        return _pick(rng, (f"Greetings from {place}! Only one little favour this time, Robot: look in on {g}. That's "
                           f"all! {sign}",
                           f"{weather} Just the one job while we're away – see to {g}{c} and then put your feet up! "
                           f"{sign}"))
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"Greetings from {place}!", "Dear Robot,",
                     f"{weather} Could you do a little round for us, in exactly this order?"]
            lines += [f"{i + 1}) {r}" for i, r in enumerate(res)]
            lines += ["Strictly that order, please – it's how we always do it!", sign]
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Hello from {place}! {weather} Before we're back, be a dear and first see to {res[0]}"
        s += "".join(f"{sep} then {r}" for r in res[1:-1])
        return s + f"{sep} and then finally {res[-1]} – in that order, mind, don't jumble them up! {sign}"
    if rng.uniform() < 0.5:
        body = "\n".join(f"– {r}" for r in res)
        return (f"Wish you were here, {place} is heaven!\nDear Robot,\nIf you get a minute, would you look in on these "
                f"for us – no particular order:\n{body}\nDo them whichever way round you fancy! {sign}")
    return (f"Postcard from {place}! {weather} While we're away, could you check on {_list(rng, res)}? In any old "
            f"order – it really doesn't matter! {sign}")


def render_instruction_ab(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a telegram sender, a sat-nav voice, a town
    crier, a holidaymaker writing a postcard). Goals stay in visiting order, each written once as rendered; strict
    texts say the order is fixed ('keep to this order', 'order as cabled', 'no call out of turn', 'in strict
    sequence', 'do not rpt not alter order', 'in the order shown', 'waypoint order is locked', 'the route must be
    followed in this sequence', 'each in its due turn', 'in that order and no other', 'in order as here cried', 'let
    none be visited out of turn', 'in exactly this order', 'strictly that order', 'in that order, mind', 'don't
    jumble them up'), free ones say it is open ('any order will do', 'order of calls your choice', 'order optional',
    'sequence yours to choose', 'order unset', 'may be reached in any sequence', 'the route will be optimised',
    'visiting order: flexible', 'the fastest route will be chosen for you', 'in what order it please', 'no order is
    decreed', 'in no set order', 'as the fancy takes it', 'no particular order', 'whichever way round you fancy',
    'in any old order', 'it really doesn't matter'). A single goal gets neither kind of cue and no digit."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(4))
    return (_telegram, _satnav, _crier, _postcard)[who](rng, res, order)
