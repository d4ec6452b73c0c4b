"""Training phrasings of set T1: goal, sensor, coordinate and instruction templates for the `unseen_train1` split.

Written to teach the learned instruction readers one more author: by a helper that never read the parser (nor its
lexicon, tagger, readings, agreement or command code, the readers' adapters, nor the evaluation code), with only the
interface of `phrasings_y.py` and `phrasings_x.py` and the docstrings of the other sets in view. Same four functions,
arguments and meanings as the other template sets. The style is two people who send a home robot round a house in
the words of their own trade or pastime:

- a ship's captain giving orders in naval idiom: sailing orders with numbered legs ("SAILING ORDERS – HMS Resolute,
  forenoon watch", "Leg the first: bear down on ...", "Leg the last: let go the anchor off ..."), or orders shouted
  to the officer of the watch ("Mr Pennywhistle! Hands to stations. We'll weigh and stand in for ...; once she's made
  that, beat up to ...; and to close the passage, let go the anchor off .... Make it so."); a fixed order as "sailed
  in the order written, leg after leg", "strictly one after another, in the order I gave them"; a free one as
  "LIBERTY BOATS – three landings, coxswain's choice" with "⚓" bullets, "in any rotation the coxswain pleases",
  "no sequence", "as the tide and the wind serve", "left to your own judgement"; one goal as "A single mooring
  today, ...: bring her alongside ... and pipe down.";
- a crochet or knitting pattern: "HARBOUR WRAP – a crochet pattern", "Hook: 4 mm · Yarn: DK", "Row 1: ch 1 and sc
  across to ...", "Row 3 (last row): sl st over to ... and fasten off.", or "Set-up: cast on at .... *K to ..., pm;
  rep from * to ..., pm. Finish: bind off at ...."; fixed as "work the rows consecutively, exactly as numbered", "in
  the sequence written – this stitch pattern can't be worked out of order"; free as "MOTIF BLANKET –
  join-as-you-go" with "◎" bullets, "in any order at all", "*pick any spot not yet done, work a square there; rep
  from * till none are left", "makes no difference – crocheter's choice"; one goal as "Quick make – just a single
  stitch to place: .... Weave in your ends and you're done."

Goals: attributes before the noun, in a bracket "(marks to look for: teal and corduroy)" or as an aside ", by
description teal and corduroy,"; states before the noun ("the switched-on lamp"), as "(switched on at last muster)" or
", logged as switched on,"; the room as "in the X", "in the X compartment" or "berthed in the X", always before any
relation; relations in new words ("within a cable's length of", "lying close aboard", "a few stitches from", "made
fast next to", "seamed up next to", "hove to beside", "stitched in beside", "riding at anchor by", "lying by",
"lashed on", "battened down on", "slung under", "battened under", "masthead-high over", "rigged above", "in the hold
of", "shipped inside", "crewed by", "trimmed with", "in the same cabin as", "sharing a cabin with", "dead ahead of",
"forward of", "astern of", "abaft", "bows-on to", "dead across from", "to port of", "off the port bow of", "to
starboard of", "off the starboard bow of", besides the plain words); several relations joined by "and", ", and
moreover" or ", and further"; an anchor with relations of its own takes them in a bracket, "(to wit, the one next to
the record player)" or "(that's to say the one next to the record player)".

Readings: above as "stands proud of", "rides higher than", "has risen clear of", "overtops", "is not ... or
under", "runs hotter than", "is damper than", "is greener than ... on the NDVI"; at least as "never sinks under",
"stands level with ... or above it", "reads ... minimum", "shows ... or more on the gauge", "has a low-water mark
of", "is at ... or hotter / damper / greener"; below as "rides lower than", "falls away below", "has dropped clear
below", "is not ... or over", "runs cooler than", "is drier than", "is less green than"; at most as "never creeps
over", "stands level with ... or under it", "reads ... maximum", "shows ... or less on the gauge", "has a high-water
mark of", "is at ... or colder / drier / less green"; about as "is nigh on", "sits within a hair's breadth of",
"reads ... by dead reckoning", "runs abreast of", "is a shade either side of"; frames "that ...", "whose humidity
...", "carrying a temperature that ...", "with an NDVI that ..."; units "°C", "° Celsius", "degrees Celsius", "deg
C", "degrees" (with words), "%", "per cent", "percent", "per cent relative humidity", "% r.h.", none when the
reading is named; numbers as digits, words ("forty", "minus four", "two hundred and fifty"), "minus 4", "4 degrees of
frost" (a temperature near which), "twenty-two point five", NDVI as ".65", "0.65", "point six five", "nought point
six five". Superlatives "the most torrid", "the most fevered", "the most furnace-like", "the most gelid", "the most
ice-bound", "the most shivery", "the greenest", "the most burgeoning", "the most full-leafed", "the most sallow",
"the most peaky", "the most wizened", "the dampest", "the most waterlogged", "the most fog-bound", "the most
desert-dry", "the most wrung-out", "the least damp", "whose temperature is the fleet's highest", "that carries the
greatest NDVI of the lot", "whose humidity rises above all its fellows", "with the temperature at the masthead",
"whose NDVI is the fleet's lowest", "that carries the least humidity of the lot", "whose temperature sinks beneath
all its fellows", "with the NDVI down in the bilges". Coordinates: "at longitude 3.5, latitude 2 on the house
chart", "(fix: x 3.5, y 2)", "at 3.5 across, 2 up (x then y)", "where the chart puts x at 3.5 and y at 2"; always x
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
    "near": ("near", "within a cable's length of", "lying close aboard", "a few stitches from"),
    "next_to": ("next to", "made fast next to", "seamed up next to"),
    "beside": ("beside", "hove to beside", "stitched in beside"),
    "by": ("by", "riding at anchor by", "lying by"),
    "on": ("on", "lashed on", "battened down on"),
    "under": ("under", "slung under", "battened under"),
    "above": ("above", "masthead-high over", "rigged above"),
    "in": ("in", "in the hold of", "shipped inside"),
    "with": ("with", "crewed by", "trimmed with"),
    "in_room_with": ("in the same room as", "in the same cabin as", "sharing a cabin with"),
    "in_front_of": ("in front of", "dead ahead of", "forward of"),
    "behind": ("behind", "astern of", "abaft"),
    "opposite": ("opposite", "bows-on to", "dead across from"),
    "left_of": ("to the left of", "to port of", "off the port bow of"),
    "right_of": ("to the right of", "to starboard of", "off the starboard bow of"),
}
_JOINS = (" and ", ", and moreover ", ", and further ")


def _anchor_np(rng, t: Target, depth: int) -> str:
    """An anchor: attributes before the noun; states before it or, for an anchor without relations of its own, as
    '(switched on at last muster)'; the anchor's own relations in a bracket of their own."""
    _, states = attributes_and_states(t)
    out = "the "
    bracket_state = bool(states) and depth == 1 and not t.relations and rng.uniform() < 0.35
    if states and not bracket_state:
        out += _hyphen(states) + " "
    out += t.phrase
    if bracket_state:
        out += f" ({' and '.join(states)} at last muster)"
    if t.relations:
        inner = _rel_chain(rng, t.relations, depth + 1)
        if rng.uniform() < 0.5:
            out += f" (to wit, the one {inner})"
        else:
            out += f" (that's to say the one {inner})"
    return out


def _rel_chain(rng, rels: tuple[Relation, ...], depth: int = 1) -> str:
    out = ""
    for i, r in enumerate(rels):
        part = f"{_pick(rng, REL_WORDS[r.type])} {_anchor_np(rng, r.anchor, depth)}"
        out = part if i == 0 else out + _pick(rng, _JOINS) + part
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS = ("in the {}", "in the {}", "in the {} compartment", "berthed in the {}")


def _goal_np(rng, t: Target, prefix: str, no_bracket: bool) -> str:
    """The goal's own noun phrase: 'the teal corduroy bean bag', 'the bean bag (marks to look for: teal and
    corduroy)', 'the bean bag, by description teal and corduroy,', 'the switched-on lamp', 'the lamp (switched on at
    last muster)', 'the lamp, logged as switched on,'. With a superlative adjective the attributes stay before the
    noun; with a bracketed coordinate hint to follow (no_bracket), nothing is put in brackets."""
    pre, states = attributes_and_states(t)
    if not t.phrase.endswith(t.head):  # a phrase of another shape: written as given, anything missing in an aside
        missing = [a for a in t.attributes if a not in t.phrase.split()]
        out = "the " + (f"{prefix} " if prefix else "") + t.phrase
        return out + (f", by description {' and '.join(missing)}," if missing else "")
    head = t.phrase[len(t.phrase) - len(t.head):]
    attr_style = "before"
    if pre and not prefix:
        opts = ("before", "before", "aside") if no_bracket else ("before", "before", "marks", "aside")
        attr_style = _pick(rng, opts)
    state_style = None
    if states:
        opts = ["before", "logged"] if no_bracket else ["before", "muster", "logged"]
        if attr_style == "marks" and "muster" in opts:
            opts.remove("muster")  # never two round brackets in a row
        state_style = _pick(rng, opts)
    out = "the " + (f"{prefix} " if prefix else "")
    if state_style == "before":
        out += _hyphen(states) + " "
    if attr_style == "before":
        out += t.phrase
    else:
        out += head
    if state_style == "muster":  # the bracket straight after the noun
        out += f" ({' and '.join(states)} at last muster)"
    if attr_style == "marks":
        out += f" (marks to look for: {' and '.join(pre)})"
    elif attr_style == "aside":
        out += f", by description {' and '.join(pre)},"
    if state_style == "logged":
        out += f", logged as {' and '.join(states)},"
    return out


_HAS_NUMBER = re.compile(r"\d|\b(" + "|".join(w for w in _ONES + _TENS if w and w != "one") +
                         r"|hundred|point)\b")


def render_goal_train1(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set T1 writes it: 'the teal corduroy bean bag in the nursery compartment', 'the bean bag (marks to
    look for: teal and corduroy)', 'the lamp, logged as switched on,', 'the most gelid chest freezer berthed in the
    pantry', 'the guitar (fix: x 3.5, y 2)', 'the lamp made fast next to the credenza (to wit, the one trimmed with
    the record player)'. The room comes before any relation (and before a superlative tail, which is read inside
    it); a coordinate hint comes after any number of a sensor tail; relations come last."""
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

# Finite predicates of any reading: after "that", "whose <reading>", "carrying a <reading> that" or "with a
# <reading> that".
_FINITE = {
    "gt": ("stands proud of {n}", "rides higher than {n}", "has risen clear of {n}", "overtops {n}",
           "is not {n} or under"),
    "ge": ("never sinks under {n}", "stands level with {n} or above it", "reads {n} minimum",
           "shows {n} or more on the gauge", "has a low-water mark of {n}"),
    "lt": ("rides lower than {n}", "falls away below {n}", "has dropped clear below {n}", "is not {n} or over"),
    "le": ("never creeps over {n}", "stands level with {n} or under it", "reads {n} maximum",
           "shows {n} or less on the gauge", "has a high-water mark of {n}"),
    "approx": ("is nigh on {n}", "sits within a hair's breadth of {n}", "reads {n} by dead reckoning",
               "runs abreast of {n}", "is a shade either side of {n}"),
}
# Predicates in the reading's own words, after "that" (NDVI is named after the number).
_OWN_WORDS = {
    "temperature_c": {"gt": "runs hotter than {n}", "ge": "is at {n} or hotter", "lt": "runs cooler than {n}",
                      "le": "is at {n} or colder"},
    "humidity_pct": {"gt": "is damper than {n}", "ge": "is at {n} or damper", "lt": "is drier than {n}",
                     "le": "is at {n} or drier"},
    "ndvi": {"gt": "is greener than {n} on the NDVI", "ge": "is at {n} or greener on the NDVI",
             "lt": "is less green than {n} on the NDVI", "le": "is at {n} or less green on the NDVI"},
}
_NAMES = {"temperature_c": "temperature", "humidity_pct": "humidity", "ndvi": "NDVI"}
_SUPER_ADJ = {
    ("temperature_c", "max"): ("most torrid", "most fevered", "most furnace-like"),
    ("temperature_c", "min"): ("most gelid", "most ice-bound", "most shivery"),
    ("ndvi", "max"): ("greenest", "most burgeoning", "most full-leafed"),
    ("ndvi", "min"): ("most sallow", "most peaky", "most wizened"),
    ("humidity_pct", "max"): ("dampest", "most waterlogged", "most fog-bound"),
    ("humidity_pct", "min"): ("most desert-dry", "most wrung-out", "least damp"),
}


def _super_tails(name: str, comparator: str) -> tuple[str, ...]:
    if comparator == "max":
        return (f"whose {name} is the fleet's highest", f"that carries the greatest {name} of the lot",
                f"whose {name} rises above all its fellows", f"with the {name} at the masthead")
    return (f"whose {name} is the fleet's lowest", f"that carries the least {name} of the lot",
            f"whose {name} sinks beneath all its fellows", f"with the {name} down in the bilges")


_DIGITS = ("nought", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")


def _number(rng, reading: str, value: float, approx: bool = False) -> tuple[str, float, str]:
    """(the number as written, its value, how): digits ('40', '-4', '.65', '0.65'), words ('forty', 'minus four',
    'twenty-two point five', 'point six five', 'nought point six five'), 'minus 4', 'minus 2.5', or 'frost' for a
    negative whole temperature near which (approx), to be written 'four degrees of frost'."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    u = rng.uniform()
    if reading == "ndvi":
        if txt.startswith("0.") and u < 0.35:
            spoken = "point " + " ".join(_DIGITS[int(d)] for d in txt[2:])
            return ("nought " + spoken if rng.uniform() < 0.5 else spoken), v, "words"
        if u < 0.65 and txt.startswith("0."):
            return txt[1:], v, "digits"
        return txt, v, "digits"
    if reading not in ("temperature_c", "humidity_pct"):
        return txt, v, "digits"
    whole = int(abs(v))
    if v == int(v):
        if v < 0 and reading == "temperature_c" and approx and rng.uniform() < 0.4:  # 'four degrees of frost'
            return (number_words(whole) if rng.uniform() < 0.5 else str(whole)), v, "frost"
        if u < 0.3 and abs(v) < 1000:
            return number_words(int(v)), v, "words"
        if u < 0.55 and v < 0:
            return f"minus {whole}", v, "digits"
    elif re.fullmatch(r"-?\d+\.\d", txt):
        if v > 0 and u < 0.3:
            return f"{number_words(whole)} point {_DIGITS[int(txt[-1])]}".replace("nought", "zero"), v, "words"
        if v < 0 and u < 0.6:
            return f"minus {txt[1:]}", v, "digits"
    return txt, v, "digits"


def _unit(rng, reading: str, how: str) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        if how == "frost":
            return " degrees of frost", "c"
        if how == "words":
            return _pick(rng, (" degrees", " degrees Celsius")), "c"
        return _pick(rng, (" °C", "°C", " ° Celsius", " degrees Celsius", " deg C")), "c"
    if reading == "humidity_pct":
        if how == "words":
            return _pick(rng, (" per cent", " percent", " per cent relative humidity")), "%"
        return _pick(rng, ("%", " per cent", " percent", " per cent relative humidity", " % r.h.")), "%"
    return "", ""


def render_sensor_train1(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('most gelid', 'greenest', 'least damp') or a tail ('whose
    temperature is the fleet's highest', 'with the NDVI down in the bilges'); thresholds after the noun ('that
    stands proud of 60 °C', 'whose humidity never creeps over forty per cent', 'with an NDVI that never sinks under
    point six five', 'whose temperature is nigh on four degrees of frost', 'that runs cooler than 22.5 ° Celsius',
    'that is greener than .65 on the NDVI')."""
    rd = c.reading
    name = _NAMES.get(rd, rd.replace("_", " "))
    if c.is_superlative:
        adj = _SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, _super_tails(name, c.comparator)), c
    n, value, how = _number(rng, rd, c.value, c.comparator == "approx")
    unit, code = _unit(rng, rd, how)
    own = _OWN_WORDS.get(rd, {}).get(c.comparator)
    if own is not None and rng.uniform() < 0.3:  # the reading's own words say which reading it is
        return "", "that " + own.format(n=n + unit), SensorConstraint(rd, c.comparator, value, code)
    # NDVI (and any other reading) is always named, and so is a temperature in degrees of frost
    named = rd not in ("temperature_c", "humidity_pct") or how == "frost"
    frame = _pick(rng, ("whose", "carrying", "witha") if named else ("that", "that", "whose", "carrying", "witha"))
    if frame != "that" and rd == "temperature_c" and how == "digits" and rng.uniform() < 0.15:
        unit, code = "", ""  # the reading is named: the unit may go
    if frame != "that" and unit.endswith("relative humidity"):
        unit = " per cent"  # the reading is named already
    written = SensorConstraint(rd, c.comparator, value, code)
    finite = _pick(rng, _FINITE[c.comparator]).format(n=n + unit)
    article = "an" if name == "NDVI" or name[:1] in "aeiou" else "a"
    if frame == "that":
        return "", "that " + finite, written
    if frame == "whose":
        return "", f"whose {name} {finite}", written
    if frame == "carrying":
        return "", f"carrying {article} {name} that {finite}", written
    return "", f"with {article} {name} that {finite}", written


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_train1(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at longitude 3.5, latitude 2 on the house chart',
    '(fix: x 3.5, y 2)', 'at 3.5 across, 2 up (x then y)', 'where the chart puts x at 3.5 and y at 2'."""
    return _pick(rng, (f"at longitude {x}, latitude {y} on the house chart", f"(fix: x {x}, y {y})",
                       f"at {x} across, {y} up (x then y)", f"where the chart puts x at {x} and y at {y}"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _sep(res: list[str]) -> str:
    return ";" if any("," in r for r in res) else ","


_ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth")
_SHIPS = ("HMS Resolute", "HMS Indefatigable", "the brig Sparrowhawk", "HMS Tenacious", "the frigate Lively")
_WATCHES = ("forenoon", "afternoon", "middle", "morning")
_OFFICERS = ("Mr Pennywhistle", "Mr Fairweather", "Mr Quayle", "Mr Bosanquet")
_LEG_VERBS = ("bear down on", "beat up to", "run down to", "haul round for", "come about for")


def _captain(rng, res: list[str], order: str) -> str:
    """A ship's captain: sailing orders with numbered legs, or orders to the officer of the watch."""
    officer = _pick(rng, _OFFICERS)
    if len(res) == 1:
        return _pick(rng, (f"A single mooring today, {officer}: bring her alongside {res[0]} and pipe down.",
                           f"A short passage today – stand in for {res[0]}, drop the hook, and that's the whole "
                           "cruise."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"SAILING ORDERS – {_pick(rng, _SHIPS)}, {_pick(rng, _WATCHES)} watch"]
            for i, r in enumerate(res[:-1]):
                nth = _ORDINALS[i] if i < len(_ORDINALS) else "next"
                lines.append(f"Leg the {nth}: {_pick(rng, _LEG_VERBS)} {r}")
            lines.append(f"Leg the last: let go the anchor off {res[-1]}")
            lines.append("These legs are to be sailed in the order written, leg after leg; any officer who alters "
                         "the sequence will answer for it.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"{officer}! Hands to stations. We'll weigh and stand in for {res[0]}"
        for i, r in enumerate(res[1:-1]):
            lead = "once she's made that," if i == 0 else "then"
            s += f"{sep} {lead} {_pick(rng, _LEG_VERBS)} {r}"
        return s + (f"{sep} and to close the passage, let go the anchor off {res[-1]}. Take them strictly one after "
                    "another, in the order I gave them – I'll not have the passage shuffled. Make it so.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"⚓ {r}" for r in res)
        return (f"LIBERTY BOATS – {w} landings, coxswain's choice\n{body}\nThe boats may touch at them in any "
                "rotation the coxswain pleases; Their Lordships lay down no sequence.")
    return (f"Orders for the jolly boat: call at {_listed(rng, res)} – {w} calls in all – taking them as the tide and "
            f"the wind serve; the order of calling is left to your own judgement, {officer}.")


_PATTERNS = ("HARBOUR WRAP", "BOSUN'S BEANIE", "SEA-SPRAY SHAWL", "GALLEY POTHOLDER", "FOG-BANK COWL")
_STITCHES = ("sc", "hdc", "dc", "tr")


def _pattern(rng, res: list[str], order: str) -> str:
    """A crochet or knitting pattern: numbered rows, a '*...; rep from *' repeat, or motifs."""
    if len(res) == 1:
        return _pick(rng, (f"Quick make – just a single stitch to place: {res[0]}. Weave in your ends and you're "
                           "done.",
                           f"Tiny motif, worked in a single round: join with a sl st at {res[0]} and fasten off. "
                           "That's all there is to it!"))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"{_pick(rng, _PATTERNS)} – a crochet pattern", "Hook: 4 mm · Yarn: DK · Gauge: not critical",
                     f"Row 1: ch 1 and sc across to {res[0]}."]
            for i, r in enumerate(res[1:-1]):
                lines.append(f"Row {i + 2}: turn; {_pick(rng, _STITCHES)} along to {r}.")
            lines.append(f"Row {n} (last row): sl st over to {res[-1]} and fasten off.")
            lines.append("Work the rows consecutively, exactly as numbered – each row sits on the one before it, so a "
                         "skipped row means frogging back.")
            return "\n".join(lines)
        s = f"Set-up: cast on at {res[0]}."
        if n > 2:
            s += f" *K to {res[1]}, pm;" + "".join(f" rep from * to {r}, pm;" for r in res[2:-1])
            s = s[:-1] + "."
        return s + (f" Finish: bind off at {res[-1]}. Work the steps in the sequence written – this stitch pattern "
                    "can't be worked out of order.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"◎ {r}" for r in res)
        return (f"MOTIF BLANKET – join-as-you-go\nMotifs to make ({w}):\n{body}\nThe motifs can be worked in any "
                "order at all; they're joined up at the end, so no motif has to come before another.")
    return (f"Scrap-yarn project, free-form: work a granny square at each of these spots – {_listed(rng, res)} – {w} "
            "squares in all. *Pick any spot not yet done, work a square there; rep from * till none are left. Which "
            "one you start with makes no difference – crocheter's choice.")


def render_instruction_train1(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of two people (a ship's captain, a crochet or knitting
    pattern). Goals stay in visiting order; strict texts say the order is fixed ('in the order written', 'leg after
    leg', 'one after another, in the order I gave them', 'consecutively', 'in the sequence written', 'out of
    order'), free ones say it is open ('any rotation', 'no sequence', 'as the tide and the wind serve', 'left to
    your own judgement', 'in any order at all', 'makes no difference', 'crocheter's choice')."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(2))
    return (_captain, _pattern)[who](rng, res, order)
