"""Held-out phrasings of set AC: goal, sensor, coordinate and instruction templates for the `unseen_ac` split.

Written by a helper that never read the parser (nor its lexicon, tagger, sensor reader, readings, agreement,
adapters, LLM or command code, nor the evaluation code), before any run of any reader on these sentences, with
only the interface of set W in view (`phrasings_w.py`). (Two slips, as it reported them: to write its test reader it imported
tests/test_phrasings_dev8.py and printed its word lists and a few of its draws; and after the set and its tests were
finished it ran a plain `git diff`, which showed an uncommitted change of the tagger's, round 26's anchor rule. It
changed nothing in the set afterwards.) Same four functions, arguments and meanings as the other
template sets. The style is four people, each with a voice of their own, who send a home robot round a house:

- a drill sergeant giving field orders: an operation order "OPERATION DUST BUNNY – ORDERS FOR THE ROBOT",
  "MISSION: secure three objectives, in sequence.", "OBJ ALPHA – ...", "OBJ BRAVO – ...", "EXECUTION: take each
  OBJ in the order listed. Do NOT advance until the previous OBJ is secured.", or barked sentences "Listen up, tin
  can! First you hit .... Then you push on to .... Last, you take .... In that order – no skipping, no
  freelancing!"; free as "TARGET LIST" with "• OBJ:" lines, "order of attack at your discretion", "in any order
  you see fit", or "I don't care which you hit first, just get 'em all done"; one goal as "Single objective,
  soldier: .... Move out!";
- an Elizabethan player speaking in the old style: "Hark, good engine, and heed well my charge:", "First, hie thee
  unto ...;", "Thence unto ...;", "And last of all, unto ....", "in this order and no other, nor seek the latter
  ere the former be done", or "Prithee, gentle automaton, go first unto ..., then wend thy way unto ..., and at
  the last repair unto ...; mark me well, each in its turn, and none before its time."; free as "in what order
  thou wilt" with "❧" lines, "'tis all one to me which thou seekest first", "as it please thee", "the order thereof
  matters not a whit"; one goal as "One errand only I lay upon thee: hie thee unto ..., and there abide.";
- a hushed nature-documentary narrator, third person and present tense, with "…": "And here, in the stillness of
  the house, the robot begins its daily round … first, it makes its way to A … then, and only then, to B … until at
  last it arrives at C. The route never varies: each stop must come before the next.", or "The journey, in three
  stages:" with "—" lines, "Always in this order. In the wild, there is no skipping ahead."; free as "Which comes
  first? It seems not to matter in the slightest … it will wander between them as the fancy takes it." or "Its
  foraging grounds, in no particular order:" with "·" lines, "in whatever order it pleases"; one goal as "Quietly
  now … the robot sets out for a single destination: ....";
- a cowboy trail boss, drawling: "Alright, partner, here's how we ride:", "First stop – ....", "Next stop – ....",
  "Last stop, end o' the trail – ....", "Ride 'em in that order, y'hear? Don't go jumpin' ahead of the herd.", or
  "Saddle up, partner. Head on over to ... first, then mosey on to ..., and wind up at .... In that order, mind – no
  cuttin' corners."; free as "Here's the round-up, partner – three spots, in whatever order suits ya:" with "★"
  lines, "Don't matter none which one ya hit first", "ain't no never-mind which ya do first"; one goal as "Just the
  one job today, partner: mosey on over to ..., and that's the day's work done."

Goals: attributes before the noun, post-posed as "described as teal and wool" or tagged in a bracket "(tagged teal &
wool)"; states before the noun ("the switched-on lamp"), in a relative clause "which is switched on" / "which are
empty", as an aside ", currently switched on," or in a bracket "(switched on at last look)"; an anchor's states
before its noun or, for an anchor without relations of its own, as "(open at last look)"; the room as "in the X",
"through in the X", "out in the X", "that lives in the X" / "that live in the X" or "(room: X)", always before any
relation; relations in new words ("not far from", "within reach of", "a short hop from", "right alongside", "snug
against", "hard up against", "at the side of", "standing beside", "over by", "just by", "lying on", "set upon",
"propped on", "underneath", "slung under", "lurking under", "high above", "hung above", "up above", "inside",
"housed in", "sitting inside", "having", "bearing", "fitted with", "in the room that also holds", "in a room
together with", "right in front of", "just in front of", "out in front of", "round the back of", "tucked behind",
"in back of", "directly across from", "straight across from", "vis-a-vis", "just left of", "off to the left of",
"just right of", "off to the right of", besides the plain words), sometimes led in by ", i.e. the one"; several
relations joined by "and", "and also" or ", plus"; an anchor with relations of its own takes them in a bracket "(the
one next to the drums)", "(which is next to the drums)" / "(which has the drums)", or, as the goal's last relation,
in a relative clause "that is next to the drums" / "that has the drums"; deeper down "that is ..." again, in square
brackets where more follows. Readings: "clears", "beats", "goes beyond", "is over the ... mark", "is no lower than",
"is ... or above", "comes to ... or more", "stays beneath", "doesn't reach", "is under the ... mark", "is no higher
than", "is ... or below", "maxes out at", "doesn't go over", "is ... or so", "is in the ballpark of", "is close on",
"is circa" (and their participles after "with its <reading>" or "with a <reading> reading": "clearing", "beyond",
"of ... or above", "beneath", "not reaching", "maxing out at", "not going over", "of ... or so", "close on", ...);
frames "that ...", "with its <reading> ...", "whose <reading> reading ...", "with a <reading> reading ..."; reading
names "temperature", "temp", "humidity", "relative humidity", "NDVI", "vegetation index"; units "°C", "C" ("40C"),
"centigrade", "degrees centigrade", "degrees Celsius", "degrees" (with words), "%", "per cent", "percent", "pc",
none when the reading is named; numbers as digits, words ("forty", "minus four", "negative four", "one hundred and
five"), "minus 4", "negative 4", "22½", "twenty-two point five", NDVI as "0.65", ".65", "point six five", "zero
point six five", "65 hundredths", "sixty-five hundredths", "six tenths"; superlatives "the balmiest", "the most
scorching", "the most roasting", "the chilliest", "the iciest", "the most frigid", "the lushest", "the most
thriving", "the most vigorous", "the sickliest", "the most withered", "the feeblest", "the dankest", "the most
sodden", "the moistest", "the most desiccated", "the least muggy", "the least damp", "with the top <reading>
reading", "whose <reading> beats every other", "that reads highest for <reading>", "with the bottom <reading>
reading", "whose <reading> undercuts every other", "that reads lowest for <reading>". Coordinates: "at map ref
3.5/2", "where x reads 3.5 and y reads 2", "at a point 3.5 m east and 2 m north of the origin", "at the pin [3.5 |
2]", "at the spot marked x 3.5 / y 2"; always x then y.

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


def _has(head: str) -> str:
    return "have" if _plural(head) else "has"


def _one(head: str) -> str:
    return "ones" if _plural(head) else "one"


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "not far from", "within reach of", "a short hop from"),
    "next_to": ("next to", "right alongside", "snug against", "hard up against"),
    "beside": ("beside", "at the side of", "standing beside"),
    "by": ("by", "over by", "just by"),
    "on": ("on", "lying on", "set upon", "propped on"),
    "under": ("under", "underneath", "slung under", "lurking under"),
    "above": ("above", "high above", "hung above", "up above"),
    "in": ("in", "inside", "housed in", "sitting inside"),
    "with": ("with", "having", "bearing", "fitted with"),
    "in_room_with": ("in the same room as", "in the room that also holds", "in a room together with"),
    "in_front_of": ("in front of", "right in front of", "just in front of", "out in front of"),
    "behind": ("behind", "round the back of", "tucked behind", "in back of"),
    "opposite": ("opposite", "directly across from", "straight across from", "vis-a-vis"),
    "left_of": ("to the left of", "just left of", "off to the left of"),
    "right_of": ("to the right of", "just right of", "off to the right of"),
}
_JOINS = (" and ", " and also ", ", plus ")


def _predicate(rng, head: str, rtype: str) -> str:
    """A relation after 'which' or 'that': 'is next to', 'are lying on', 'has' / 'have' for a 'with'."""
    if rtype == "with":
        return _has(head)
    return f"{_is(head)} {_pick(rng, REL_WORDS[rtype])}"


def _missing(t: Target) -> list[str]:
    """Attributes a phrase of another shape (one that does not end on its head) does not write itself."""
    if t.phrase.endswith(t.head):
        return []
    return [a for a in t.attributes if a not in t.phrase.split()]


def _anchor_np(rng, t: Target, depth: int, more_follows: bool) -> str:
    """An anchor: states before the noun, or '(open at last look)' for a top-level anchor without relations of its
    own. A top-level anchor's own relations go in a bracket ('(the one next to ...)', '(which is next to ...)',
    '(which has ...)') or, when nothing follows it, in a relative clause ('that is next to ...'); deeper down in a
    relative clause again, in square brackets when more of its level follows."""
    _, states = attributes_and_states(t)
    out = "the "
    bracket_state = bool(states) and depth == 1 and not t.relations and rng.uniform() < 0.35
    if states and not bracket_state:
        out += _hyphen(states) + " "
    out += t.phrase
    missing = _missing(t)
    if missing:
        out += f" described as {_both(missing)}"
    if bracket_state:
        out += f" ({_both(states)} at last look)"
    if t.relations:
        if depth == 1:
            styles = ["one", "which"] + ([] if more_follows else ["that"])
            style = _pick(rng, styles)
            if style == "one":
                out += f" (the {_one(t.head)} {_rel_chain(rng, t.relations, depth + 1)})"
            elif style == "which":
                out += f" (which {_pred_chain(rng, t, depth + 1)})"
            else:
                out += f" that {_pred_chain(rng, t, depth + 1)}"
        else:
            clause = f"that {_pred_chain(rng, t, depth + 1)}"
            out += f" [{clause}]" if more_follows else f" {clause}"
    return out


def _pred_chain(rng, t: Target, depth: int) -> str:
    """The target's relations as predicates: 'is next to the drums and is under the shelves', 'has the drums'."""
    out = ""
    for i, r in enumerate(t.relations):
        more = i + 1 < len(t.relations)
        part = f"{_predicate(rng, t.head, r.type)} {_anchor_np(rng, r.anchor, depth, more)}"
        out = part if i == 0 else out + _pick(rng, _JOINS) + part
    return out


def _rel_chain(rng, rels: tuple[Relation, ...], depth: int = 1) -> str:
    out = ""
    for i, r in enumerate(rels):
        more = i + 1 < len(rels)
        part = f"{_pick(rng, REL_WORDS[r.type])} {_anchor_np(rng, r.anchor, depth, more)}"
        out = part if i == 0 else out + _pick(rng, _JOINS) + part
    return out


# ----------------------------------------------------------------------------------------------------
# Goals


def _goal_np(rng, t: Target, prefix: str, clause_ok: bool) -> tuple[str, bool, bool]:
    """(the goal's own noun phrase, whether it ends on a clause, whether it holds a bracket): 'the teal wool
    lamp', 'the lamp described as teal and wool', 'the lamp (tagged teal & wool)', 'the switched-on lamp', 'the lamp
    which is switched on', 'the lamp, currently switched on,', 'the lamp (switched on at last look)'. With a
    superlative adjective (prefix) the attributes stay before the noun."""
    pre, states = attributes_and_states(t)
    lead = "the " + (f"{prefix} " if prefix else "")
    if not t.phrase.endswith(t.head):  # a phrase of another shape: written as given, anything missing after it
        missing = _missing(t)
        if not missing:
            return lead + t.phrase, False, False
        if clause_ok and rng.uniform() < 0.5:
            return lead + t.phrase + f" described as {_both(missing)}", True, False
        return lead + t.phrase + f" (tagged {' & '.join(missing)})", False, True
    head = t.phrase[len(t.phrase) - len(t.head):]
    attr_style = "before"
    if pre and not prefix:
        attr_style = _pick(rng, ("before", "before", "tagged") + (("described",) if clause_ok else ()))
    state_style = None
    if states:
        opts = ["before", "which", "currently", "bracket"]
        if attr_style == "tagged":
            opts.remove("bracket")  # one bracket to a noun
        if not clause_ok or attr_style == "described":
            opts.remove("which")  # no relative clause on a tail, nor straight after 'described as ...'
        state_style = _pick(rng, opts)
    out = lead
    if state_style == "before":
        out += _hyphen(states) + " "
    out += t.phrase if attr_style == "before" else head
    if attr_style == "described":
        out += f" described as {_both(pre)}"
    elif attr_style == "tagged":
        out += f" (tagged {' & '.join(pre)})"
    if state_style == "which":
        out += f" which {_is(t.head)} {_both(states)}"
    elif state_style == "currently":
        out += f", currently {_both(states)},"
    elif state_style == "bracket":
        out += f" ({_both(states)} at last look)"
    # a trailing 'described as ...' or 'which is ...' is closed by a comma before anything else follows
    return out, state_style == "which" or attr_style == "described", attr_style == "tagged" or state_style == "bracket"


_HAS_NUMBER = re.compile(r"\d|½|\b(" + "|".join(w for w in ONES + TENS if w) + r"|hundred|point|hundredths|tenths)\b")


def render_goal_ac(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AC writes it: 'the teal wool lamp through in the nursery', 'the lamp described as teal and
    wool', 'the lamp which is switched on', 'the chilliest mini-fridge out in the kitchen', 'the guitar at map ref
    3.5/2', 'the lamp (room: nursery), i.e. the one right alongside the credenza (the one having the record player)'.
    The room comes before any relation (and before a superlative tail, which is read inside it); a coordinate hint
    comes after any number of a sensor tail; relations come last."""
    t = sg.target
    out, clause, bracket = _goal_np(rng, Target(t.phrase, t.head, t.attributes), prefix, clause_ok=not tail)
    room = ""
    if sg.room:
        frames = ["in the {}", "in the {}", "through in the {}", "out in the {}"]
        if not clause and not tail:  # never two relative clauses on end
            frames.append("that live in the {}" if _plural(t.head) else "that lives in the {}")
        if not bracket:  # one bracket to a noun
            frames.append("(room: {})")
        room = _pick(rng, frames).format(sg.room)
    numeric_tail = bool(tail) and bool(_HAS_NUMBER.search(tail))
    # a hint that ends on a noun of its own ('... of the origin') or a clause ('where x reads ...') goes last
    hint_first = bool(hint) and not numeric_tail and hint.startswith("at ") and not hint.endswith("origin") \
        and rng.uniform() < 0.5
    if hint_first:
        out += ("," if clause else "") + " " + hint
    if tail:
        if room and (not numeric_tail or rng.uniform() < 0.5):
            out += f" {room} {tail}"
        else:
            out += f" {tail}" + (f", {room}" if room else "")
    elif room:
        out += ("," if clause else "") + " " + room  # 'the lamp which is open, in the nursery'
    clause = clause or room.startswith("that ")
    if hint and not hint_first:
        out += (", " if (tail or clause) else " ") + hint
    if t.relations:
        # a comma after a room, so 'in the games room with the drums' cannot read as a room that has the drums
        comma = bool(tail) or bool(hint) or clause or (bool(room) and not room.startswith("("))
        intro = ""
        if rng.uniform() < 0.2:
            intro = f"i.e. the {_one(t.head)} "
            comma = True
        out += ("," if comma else "") + " " + intro + _rel_chain(rng, t.relations)
    return _tidy(out)


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

# Finite predicates (after "that" or "whose <reading> reading") and participles (after "with its <reading>" or
# "with a <reading> reading").
_FINITE = {
    "gt": ("clears {n}", "beats {n}", "goes beyond {n}", "is over the {n} mark"),
    "ge": ("is no lower than {n}", "is {n} or above", "comes to {n} or more"),
    "lt": ("stays beneath {n}", "doesn't reach {n}", "is under the {n} mark"),
    "le": ("is no higher than {n}", "is {n} or below", "maxes out at {n}", "doesn't go over {n}"),
    "approx": ("is {n} or so", "is in the ballpark of {n}", "is close on {n}", "is circa {n}"),
}
_PARTICIPLE = {
    "gt": ("clearing {n}", "beating {n}", "beyond {n}", "over the {n} mark"),
    "ge": ("no lower than {n}", "of {n} or above", "of {n} or more"),
    "lt": ("beneath {n}", "not reaching {n}", "under the {n} mark"),
    "le": ("no higher than {n}", "of {n} or below", "maxing out at {n}", "not going over {n}"),
    "approx": ("of {n} or so", "in the ballpark of {n}", "close on {n}", "of circa {n}"),
}
_NAMES = {"temperature_c": ("temperature", "temp"), "humidity_pct": ("humidity", "relative humidity"),
          "ndvi": ("NDVI", "vegetation index")}
_SUPER_ADJ = {
    ("temperature_c", "max"): ("balmiest", "most scorching", "most roasting"),
    ("temperature_c", "min"): ("chilliest", "iciest", "most frigid"),
    ("ndvi", "max"): ("lushest", "most thriving", "most vigorous"),
    ("ndvi", "min"): ("sickliest", "most withered", "feeblest"),
    ("humidity_pct", "max"): ("dankest", "most sodden", "moistest"),
    ("humidity_pct", "min"): ("most desiccated", "least muggy", "least damp"),
}


def _article(name: str) -> str:
    return "an" if name == "NDVI" or name[:1].lower() in "aeiou" else "a"


def _super_tails(name: str, comparator: str) -> tuple[str, ...]:
    if comparator == "max":
        return (f"with the top {name} reading", f"whose {name} beats every other", f"that reads highest for {name}")
    return (f"with the bottom {name} reading", f"whose {name} undercuts every other", f"that reads lowest for {name}")


_DIGIT_WORDS = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")


def _point_words(digits: str) -> str:
    """'65' -> 'six five'."""
    return " ".join(_DIGIT_WORDS[int(d)] for d in digits)


def _number(rng, reading: str, value: float) -> tuple[str, float, str]:
    """(the number as written, its value, how): 'digits' ('40', '-4', '.65', '22½', 'minus 4', 'negative 4', '65
    hundredths') or 'words' ('forty', 'minus four', 'negative four', 'twenty-two point five', 'point six five', 'zero
    point six five', 'sixty-five hundredths', 'six tenths')."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    u = rng.uniform()
    if reading == "ndvi":
        m = re.fullmatch(r"0\.(\d\d?)", txt)
        if m and v > 0:
            dec = m.group(1)
            if u < 0.15:
                return "zero point " + _point_words(dec), v, "words"
            if u < 0.3:
                return "point " + _point_words(dec), v, "words"
            if u < 0.45:
                k = int(dec)
                denom = "hundredths" if len(dec) == 2 else "tenths"
                if rng.uniform() < 0.5:
                    return f"{k} {denom}", v, "digits"
                return f"{number_words(k)} {denom}", v, "words"
            if u < 0.65:
                return txt[1:], v, "digits"
        return txt, v, "digits"
    if reading not in ("temperature_c", "humidity_pct"):
        return txt, v, "digits"
    neg = _pick(rng, ("minus", "negative"))
    whole = int(abs(v))
    if v == int(v):
        if u < 0.3 and abs(v) < 1000:
            return (f"{neg} " if v < 0 else "") + number_words(whole), v, "words"
        if v < 0 and u < 0.55:
            return f"{neg} {whole}", v, "digits"
        return txt, v, "digits"
    m = re.fullmatch(r"-?(\d+)\.(\d+)", txt)
    if m:
        sign = f"{neg} " if v < 0 else ""
        if m.group(2) == "5" and u < 0.3:
            lead = _pick(rng, (sign, "-")) if v < 0 else ""
            return f"{lead}{whole or ''}½", v, "digits"  # '22½', '-2½', 'minus ½'
        if u < 0.55 and whole < 1000:
            return f"{sign}{number_words(whole)} point {_point_words(m.group(2))}", v, "words"
    return txt, v, "digits"


def _unit(rng, reading: str, how: str, number: str) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        if how == "words":
            return _pick(rng, (" degrees", " degrees centigrade", " degrees Celsius")), "c"
        opts = ["°C", " °C", " centigrade", " degrees centigrade"]
        if re.search(r"[\d½]$", number):
            opts.append("C")  # '40C', '22½C'
        return _pick(rng, opts), "c"
    if reading == "humidity_pct":
        if how == "words":
            return _pick(rng, (" per cent", " percent")), "%"
        return _pick(rng, ("%", " per cent", " percent", " pc")), "%"
    return "", ""


def render_sensor_ac(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('chilliest', 'most thriving', 'least muggy') or a tail ('with the
    top temperature reading', 'whose humidity undercuts every other', 'that reads highest for NDVI'); thresholds
    after the noun ('that clears 60 °C', 'whose humidity reading is no higher than forty per cent', 'with its NDVI
    of point six five or so', 'with a temp reading not reaching 22½C')."""
    rd = c.reading
    names = _NAMES.get(rd, (rd.replace("_", " "),))
    name = _pick(rng, names)
    if c.is_superlative:
        adj = _SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, _super_tails(name, c.comparator)), c
    n, value, how = _number(rng, rd, c.value)
    unit, code = _unit(rng, rd, how, n)
    if abs(value) == 1:
        unit = unit.replace("degrees", "degree")  # 'one degree', 'minus one degree Celsius'

    named = rd not in ("temperature_c", "humidity_pct")  # NDVI (and any other reading) is always named
    frames = ("its", "whose", "a") if named else ("that", "that", "its", "whose", "a")
    frame = _pick(rng, frames)
    if frame != "that" and how == "digits" and not named and rng.uniform() < 0.15:
        unit, code = "", ""  # the reading is named: the unit may go
    written = SensorConstraint(rd, c.comparator, value, code)
    if frame == "its":
        return "", f"with its {name} " + _pick(rng, _PARTICIPLE[c.comparator]).format(n=n + unit), written
    if frame == "a":
        return "", f"with {_article(name)} {name} reading " + _pick(rng, _PARTICIPLE[c.comparator]).format(
            n=n + unit), written
    finite = _pick(rng, _FINITE[c.comparator]).format(n=n + unit)
    if frame == "that":
        return "", "that " + finite, written
    return "", f"whose {name} reading {finite}", written


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_ac(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at map ref 3.5/2', 'where x reads 3.5 and y reads
    2', 'at a point 3.5 m east and 2 m north of the origin', 'at the pin [3.5 | 2]', 'at the spot marked x 3.5 / y
    2'."""
    return _pick(rng, (f"at map ref {x}/{y}", f"where x reads {x} and y reads {y}",
                       f"at a point {x} m east and {y} m north of the origin", f"at the pin [{x} | {y}]",
                       f"at the spot marked x {x} / y {y}"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _bare(r: str) -> bool:
    return bool(re.fullmatch(r"the [\w'-]+(?: [\w'-]+)?", r))


def _sep(res: list[str]) -> str:
    return ";" if any("," in r or ";" in r for r in res) else ","


def _list(rng, res: list[str]) -> str:
    """Goals in a running sentence: 'A, B and C' for bare goals, semicolons ('A; B; and C', 'A; and also B') once a
    goal has words of its own after the noun, so no goal reads as one more anchor of the one before."""
    if all(_bare(r) for r in res):
        return _listed(rng, res)
    if len(res) == 2:
        return f"{res[0]}; and also {res[1]}"
    return "; ".join(res[:-1]) + "; and " + res[-1]


def _comma(goal: str) -> str:
    """A comma to close a goal that has commas of its own before the sentence goes on."""
    return "," if "," in goal else ""


_OPS = ("OPERATION DUST BUNNY", "OPERATION TIN SOLDIER", "OPERATION HOUSE CALL", "OPERATION CLEAN SWEEP",
        "OPERATION NIGHT WATCH")
_NATO = ("ALPHA", "BRAVO", "CHARLIE", "DELTA", "ECHO", "FOXTROT", "GOLF", "HOTEL", "INDIA", "JULIETT", "KILO",
         "LIMA", "MIKE", "NOVEMBER", "OSCAR", "PAPA", "QUEBEC", "ROMEO", "SIERRA", "TANGO", "UNIFORM", "VICTOR",
         "WHISKEY", "XRAY", "YANKEE", "ZULU")
_PUSH = ("Then you push on to", "After that, you move on", "Next, you advance on")


def _sergeant(rng, res: list[str], order: str) -> str:
    """A drill sergeant: an operation order with lettered objectives, or barked sentences."""
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"Single objective, soldier: {g}. Move out!",
                           f"Listen up, tin can. Your mission today is {g}, and nothing else. Dismissed!"))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"{_pick(rng, _OPS)} – ORDERS FOR THE ROBOT", f"MISSION: secure {w} objectives, in sequence."]
            lines += [f"OBJ {_NATO[i] if i < len(_NATO) else 'ZULU-' + _NATO[i % len(_NATO)]} – {r}"
                      for i, r in enumerate(res)]
            lines.append("EXECUTION: take each OBJ in the order listed. Do NOT advance until the previous OBJ is "
                         "secured.")
            return "\n".join(lines)
        s = f"Listen up, tin can! First you hit {res[0]}."
        s += "".join(f" {_pick(rng, _PUSH)} {r}." for r in res[1:-1])
        return s + f" Last, you take {res[-1]}. In that order – no skipping, no freelancing! Move it!"
    if rng.uniform() < 0.5:
        body = "\n".join(f"• OBJ: {r}" for r in res)
        return (f"{_pick(rng, _OPS)} – TARGET LIST\n{_cap(w)} objectives, order of attack at your discretion:\n{body}\n"
                "Hit them in any order you see fit, soldier.")
    return (f"Right, maggot, your targets are {_list(rng, res)}. I don't care which you hit first, just get 'em all "
            "done before chow!")


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


_THENCE = ("Thence unto", "Then get thee unto", "Anon, unto")
_WEND = ("then wend thy way unto", "thereafter unto", "anon betake thee unto")


def _player(rng, res: list[str], order: str) -> str:
    """An Elizabethan player: a charge in lines, or one long courtly sentence."""
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"One errand only I lay upon thee: hie thee unto {g}, and there abide.",
                           f"Away, good engine, unto {g}! Thy labours then are ended."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = ["Hark, good engine, and heed well my charge:", f"First, hie thee unto {res[0]};"]
            lines += [f"{_pick(rng, _THENCE)} {r};" for r in res[1:-1]]
            lines.append(f"And last of all, unto {res[-1]}.")
            lines.append("Take them in this order and no other, nor seek the latter ere the former be done.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Prithee, gentle automaton, go first unto {res[0]}"
        s += "".join(f"{sep} {_pick(rng, _WEND)} {r}" for r in res[1:-1])
        return s + (f"{sep} and at the last repair unto {res[-1]}; mark me well, each in its turn, and none before its "
                    "time.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"❧ {r}" for r in res)
        return (f"Lo, here be {w} places thou must visit, in what order thou wilt:\n{body}\n'Tis all one to me which "
                "thou seekest first.")
    return f"Go thou unto {_list(rng, res)}, as it please thee; the order thereof matters not a whit."


_ONWARD = ("then, and only then, to", "next – never sooner – to", "from there, to")


def _narrator(rng, res: list[str], order: str) -> str:
    """A hushed nature-documentary narrator: the robot's round told as it happens, or set out in stages."""
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"Quietly now … the robot sets out for a single destination: {g}.",
                           f"Alone in the hush of the house, the robot has but one goal … {g}."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            s = ("And here, in the stillness of the house, the robot begins its daily round … first, it makes its way "
                 f"to {res[0]} …")
            s += "".join(f" {_pick(rng, _ONWARD)} {r} …" for r in res[1:-1])
            return s + (f" until at last it arrives at {res[-1]}. The route never varies: each stop must come before "
                        "the next.")
        lines = [f"The journey, in {w} stages:", f"— first, {res[0]};"]
        lines += [f"— then {r};" for r in res[1:-1]]
        lines.append(f"— and finally, {res[-1]}.")
        lines.append("Always in this order. In the wild, there is no skipping ahead.")
        return "\n".join(lines)
    if rng.uniform() < 0.5:
        return (f"Watch closely now … the robot has {w} places to visit: {_list(rng, res)}. Which comes first? It seems "
                "not to matter in the slightest … it will wander between them as the fancy takes it.")
    body = "\n".join(f"· {r}" for r in res)
    return (f"Its foraging grounds, in no particular order:\n{body}\nIt will visit each of them in whatever order it "
            "pleases.")


_MOSEY = ("then mosey on to", "then ride on over to", "after that, trot along to")


def _trail_boss(rng, res: list[str], order: str) -> str:
    """A cowboy trail boss: the stops of the trail, or a drawled sentence."""
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"Just the one job today, partner: mosey on over to {g}, and that's the day's work done.",
                           f"Only errand on the trail today: {g}. Giddy-up!"))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = ["Alright, partner, here's how we ride:", f"First stop – {res[0]}."]
            lines += [f"Next stop – {r}." for r in res[1:-1]]
            lines.append(f"Last stop, end o' the trail – {res[-1]}.")
            lines.append("Ride 'em in that order, y'hear? Don't go jumpin' ahead of the herd.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Saddle up, partner. Head on over to {res[0]}{_comma(res[0])} first"
        s += "".join(f"{sep} {_pick(rng, _MOSEY)} {r}" for r in res[1:-1])
        return s + f"{sep} and wind up at {res[-1]}. In that order, mind – no cuttin' corners."
    if rng.uniform() < 0.5:
        body = "\n".join(f"★ {r}" for r in res)
        return (f"Here's the round-up, partner – {w} spots, in whatever order suits ya:\n{body}\nDon't matter none "
                "which one ya hit first.")
    return f"Reckon you oughta call in at {_list(rng, res)} – ain't no never-mind which ya do first."


def render_instruction_ac(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a drill sergeant, an Elizabethan player, a
    nature-documentary narrator, a cowboy trail boss). Goals stay in visiting order, each written once as rendered;
    strict texts say the order is fixed ('in sequence', 'in the order listed', 'do not advance until the previous
    obj is secured', 'in that order – no skipping, no freelancing', 'in this order and no other', 'nor seek the
    latter ere the former be done', 'each in its turn, and none before its time', 'then, and only then', 'the route
    never varies', 'each stop must come before the next', 'always in this order', 'there is no skipping ahead', 'ride
    'em in that order', 'don't go jumpin' ahead of the herd', 'in that order, mind', 'no cuttin' corners'), free ones
    say it is open ('order of attack at your discretion', 'in any order you see fit', 'i don't care which you hit
    first', 'in what order thou wilt', ''tis all one to me which thou seekest first', 'as it please thee', 'matters
    not a whit', 'it seems not to matter in the slightest', 'as the fancy takes it', 'in no particular order', 'in
    whatever order it pleases', 'in whatever order suits ya', 'don't matter none which one ya hit first', 'ain't no
    never-mind which ya do first'). A single goal gets neither kind of cue and no digit."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(4))
    return (_sergeant, _player, _narrator, _trail_boss)[who](rng, res, order)
