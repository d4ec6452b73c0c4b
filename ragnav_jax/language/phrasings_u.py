"""Held-out phrasings of set U: goal, sensor, coordinate and instruction templates for the `unseen_u` split.

Written by a helper that never read the parser (nor its lexicon, tagger, readings, agreement or command code, nor
the evaluation code), before any run of any reader on these sentences, with only the interface of the earlier
template sets in view (`phrasings_t.py` and the docstrings of the others). Same four functions, arguments and
meanings as the other template sets. The style is four people who send a home robot round a house in the layout
and words of their own job or pastime:

- a railway station announcer, as a departure board or over the tannoy: "PLATFORM 3 · 10.14 stopping service",
  "Calling at:" with one stop a line, "Terminating at: ...", "The train now standing at platform two is the 10.14
  stopping service, calling at ..., ..., and terminating at ...", "Please mind the gap."; a fixed order as "this
  service calls at each stop strictly in the order shown", "stops are served in the order announced – this train
  does not skip stops"; a free one as "RAIL ROVER – valid at any of these stations, in any order and in either
  direction", "hop on and off in whatever order you like, the ticket doesn't mind"; one goal as "runs non-stop to
  ...";
- a yoga teacher's class plan or spoken cues: "SUNRISE FLOW · 45 min · all levels", "Pose 1 → ...", "Final rest →
  ...", "Inhale, and arrive at .... Exhale, and flow on to .... And finally, settle into stillness at ...",
  "Namaste"; fixed as "move through the poses in exactly this sequence – each one prepares you for the next",
  "keep to this sequence, one breath at a time – no jumping ahead"; free as "OPEN PRACTICE", "○" bullets, "flow
  between them in whatever order your body asks for", "no set sequence tonight – go to whichever feels right";
- an auctioneer's catalogue or rostrum patter: "HARGREAVES & DAUGHTER – Fine & Decorative Sale, Tues 11 June,
  10.30am", "Buyer's premium 25% + VAT", "LOT 1  the ...", "We open the sale with lot one, the ...; lot two, the
  ...; and our final lot of the day, lot three, the ...", "Going once, going twice ... sold!"; fixed as "lots will
  be offered strictly in catalogue order – no lot taken out of turn", "we go strictly by the catalogue numbers";
  free as "VIEWING DAY", "browse the lots in whatever order suits you – viewing is open, there is no set route",
  "wander round them in any order you fancy";
- a tarot reader laying a spread: "THE SPREAD, as laid for the robot (Madame Zora)", "I. The Past – ...", "II. The
  Present – ...", "V. The Outcome – ...", "your path begins at ..., winds on to ..., and ends at ..."; fixed as
  "turn the cards in the order they were laid – read out of turn, they lie", "walk it in exactly the order the
  cards fell"; free as "A SCATTERED SPREAD", "✧" bullets, "no card outranks another here – turn them over in
  whatever order calls to you", "the order means nothing in a scattered spread, so visit them as the spirit moves
  you".

Goals: attributes before the noun, joined with hyphens ("the teal-and-corduroy bean bag"), in a plus bracket ("the
bean bag (teal + corduroy)") or as an aside (", teal and corduroy by the look of it,"); states before the noun
("the switched-on lamp"), as ", switched on at the moment," or "(it'll be switched on)"; the room as "in the X" or
"back in the X", always before any relation; relations in new words ("within hailing distance of", "handy for", "no
great distance from", "hugging", "snuggled next to", "immediately next to", "huddled beside", "posted beside",
"camped by", "hovering by", "sitting pretty on", "piled on", "laid out on", "hiding under", "crouched under", "over
the top of", "towering over", "bundled inside", "locked away in", "fitted with", "equipped with", "that goes with",
"in the room shared with", "in a room along with", "plumb in front of", "standing guard in front of", "sheltering
behind", "peeking out from behind", "eyeing up", "facing off with", "a shade to the left of", "over on the left of",
"a shade to the right of", "over on the right of"); several relations joined by "and", "as well as" or ", and
also"; an anchor with relations of its own takes them in a bracket, "(the one next to the record player, I mean)"
or "(that's the one next to the record player)". Readings: "that has broken through", "that has gone beyond", "that
runs over and above", "comfortably over", "something over", "... or over", "reads from ... up", "not a jot under",
"that has dropped under", "that comes up short of", "something under", "comfortably under", "is capped at", "...
tops", "... and no more", "... or thereabouts", "in the neighbourhood of", "ballpark ..."; frames "whose humidity
...", "with temperature logged at ...", "(the thermometer puts it at ...)", "(the hygrometer puts it at ...)", "(the
NDVI scan puts it at ...)"; units "°C", "degrees", "degrees Celsius", "degs C", "%", "per cent", "percent"; numbers
as digits, decimals ("40.0", ".6", "0.60"), words ("forty", "minus eighteen"), "minus 18", "18 degrees below zero"
and halves ("20½"); superlatives "the balmiest", "the most sweltering", "the frostiest", "the nippiest", "the most
thriving", "the perkiest", "the sorriest-looking", "the most wilted", "the clammiest", "the soggiest", "the most
arid", "that tops the temperature chart", "with a temperature higher than any other", "whose NDVI beats all
comers", "that props up the humidity table", "with the lowest NDVI of the bunch", "whose temperature is the lowest
going". Coordinates: "at easting 3.5, northing 2", "(x 3.5 | y 2)", "where the x-coordinate reads 3.5 and the
y-coordinate 2", "marked on the floor plan at x = 3.5, y = 2"; always x then y.

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

# ----------------------------------------------------------------------------------------------------
# Small helpers of this set's own

_ONES = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
         "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen")
_TENS = ("", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety")


def _head_words(t: Target) -> str:
    return t.phrase[len(t.phrase) - len(t.head):] if t.phrase.endswith(t.head) else t.head


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "within hailing distance of", "handy for", "no great distance from"),
    "next_to": ("next to", "hugging", "snuggled next to", "immediately next to"),
    "beside": ("beside", "huddled beside", "posted beside"),
    "by": ("by", "camped by", "hovering by"),
    "on": ("on", "sitting pretty on", "piled on", "laid out on"),
    "under": ("under", "hiding under", "crouched under"),
    "above": ("above", "over the top of", "towering over"),
    "in": ("in", "bundled inside", "locked away in"),
    "with": ("with", "fitted with", "equipped with", "that goes with"),
    "in_room_with": ("in the same room as", "in the room shared with", "in a room along with"),
    "in_front_of": ("in front of", "plumb in front of", "standing guard in front of"),
    "behind": ("behind", "sheltering behind", "peeking out from behind"),
    "opposite": ("opposite", "eyeing up", "facing off with"),
    "left_of": ("to the left of", "a shade to the left of", "over on the left of"),
    "right_of": ("to the right of", "a shade to the right of", "over on the right of"),
}
_JOINS = (" and ", " as well as ", ", and also ")


def _anchor_np(rng, t: Target, depth: int) -> str:
    """An anchor: attributes before the noun; states before it or, for an anchor without relations of its own, as
    '(it'll be switched on)'; the anchor's own relations in a bracket of their own."""
    pre, states = attributes_and_states(t)
    out = "the "
    bracket_state = bool(states) and depth == 1 and not t.relations and rng.uniform() < 0.35
    if states and not bracket_state:
        out += _hyphen(states) + " "
    out += t.phrase
    if bracket_state:
        out += f" (it'll be {' and '.join(states)})"
    if t.relations:
        inner = _rel_chain(rng, t.relations, depth + 1)
        if rng.uniform() < 0.5:
            out += f" (the one {inner}, I mean)"
        else:
            out += f" (that's the one {inner})"
    return out


def _rel_chain(rng, rels: tuple[Relation, ...], depth: int = 1) -> str:
    out = ""
    for i, r in enumerate(rels):
        part = f"{_pick(rng, REL_WORDS[r.type])} {_anchor_np(rng, r.anchor, depth)}"
        out = part if i == 0 else out + _pick(rng, _JOINS) + part
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS = ("in the {}", "in the {}", "back in the {}")


def _goal_np(rng, t: Target, prefix: str) -> str:
    """The goal's own noun phrase: 'the teal corduroy bean bag', 'the teal-and-corduroy bean bag', 'the bean bag (teal
    + corduroy)', 'the bean bag, teal and corduroy by the look of it,', 'the switched-on lamp', 'the lamp, switched on
    at the moment,', 'the lamp (it'll be switched on)'. With a superlative adjective the attributes stay before the
    noun."""
    pre, states = attributes_and_states(t)
    head = _head_words(t)
    attr_style = "before"
    if pre and not prefix:
        opts = ["before", "before", "look"]
        if len(pre) > 1:
            opts += ["plus"]
            if not any(("-" in a or " " in a) for a in pre):
                opts += ["joined"]
        attr_style = _pick(rng, opts)
    state_style = None
    if states:
        opts = ["before", "moment", "bracket"]
        if attr_style == "plus":
            opts.remove("bracket")  # never two round brackets in a row
        if attr_style == "look":
            opts.remove("moment")  # one aside between commas is enough
        state_style = _pick(rng, opts)
    out = "the " + (f"{prefix} " if prefix else "")
    if state_style == "before":
        out += _hyphen(states) + " "
    if attr_style == "before":
        out += t.phrase
    elif attr_style == "joined":
        out += "-and-".join(pre) + " " + head
    elif attr_style == "plus":
        out += f"{head} ({' + '.join(pre)})"
    else:
        out += f"{head}, {' and '.join(pre)} by the look of it,"
    if state_style == "moment":
        out += f", {' and '.join(states)} at the moment,"
    elif state_style == "bracket":
        out += f" (it'll be {' and '.join(states)})"
    return out


_HAS_NUMBER = re.compile(r"\d|½|\b(" + "|".join(w for w in _ONES + _TENS if w) + r"|hundred)\b")


def render_goal_u(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set U writes it: 'the teal-and-corduroy bean bag back in the nursery', 'the bean bag (teal +
    corduroy)', 'the lamp, switched on at the moment,', 'the frostiest fridge in the pantry', 'the guitar (x 3.5 | y
    2)', 'the lamp snuggled next to the credenza (the one fitted with the record player, I mean)'. The room comes
    before any relation (and before a superlative tail, which is read inside it); relations come last."""
    t = sg.target
    out = _goal_np(rng, Target(t.phrase, t.head, t.attributes), prefix)
    if hint:
        out += " " + hint
    room = _pick(rng, _ROOMS).format(sg.room) if sg.room else ""
    if tail:
        superlative = not _HAS_NUMBER.search(tail)
        if room and (superlative or rng.uniform() < 0.6):
            out += f" {room} {tail}"
        else:
            out += f" {tail}" + (f", {room}" if room else "")
    elif room:
        out += " " + room
    if t.relations:
        out += " " + _rel_chain(rng, t.relations)
    return _tidy(out)


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

# After "puts it at" / "logged at": a noun-like amount.
_AMOUNT = {
    "gt": ("comfortably over {n}", "something over {n}"),
    "ge": ("{n} or over", "{n} or more"),
    "lt": ("comfortably under {n}", "something under {n}"),
    "le": ("{n} tops", "{n} and no more"),
    "approx": ("{n} or thereabouts", "ballpark {n}"),
}
# Finite predicates: after "that" or "whose <reading>".
_FINITE = {
    "gt": ("has broken through {n}", "has gone beyond {n}", "runs over and above {n}"),
    "ge": ("comes in at {n} or over", "reads from {n} up", "is not a jot under {n}"),
    "lt": ("has dropped under {n}", "comes up short of {n}"),
    "le": ("is capped at {n}", "comes in at {n} tops", "reads {n} and no more"),
    "approx": ("comes in at {n} or thereabouts", "sits in the neighbourhood of {n}", "reads ballpark {n}"),
}
_NAMES = {"temperature_c": "temperature", "humidity_pct": "humidity", "ndvi": "NDVI"}
_GAUGES = {"temperature_c": ("thermometer", "temperature gauge"), "humidity_pct": ("hygrometer", "humidity gauge"),
           "ndvi": ("NDVI scan", "NDVI meter")}
_SUPER_ADJ = {
    ("temperature_c", "max"): ("warmest", "balmiest", "most sweltering"),
    ("temperature_c", "min"): ("coldest", "frostiest", "nippiest"),
    ("ndvi", "max"): ("healthiest", "most thriving", "perkiest"),
    ("ndvi", "min"): ("least healthy", "sorriest-looking", "most wilted"),
    ("humidity_pct", "max"): ("most humid", "clammiest", "soggiest"),
    ("humidity_pct", "min"): ("driest", "least humid", "most arid"),
}


def _super_tails(name: str, comparator: str) -> tuple[str, ...]:
    if comparator == "max":
        art = {"temperature": "a ", "NDVI": "an "}.get(name, "")
        return (f"that tops the {name} chart", f"with {art}{name} higher than any other",
                f"whose {name} beats all comers")
    return (f"that props up the {name} table", f"with the lowest {name} of the bunch",
            f"whose {name} is the lowest going")


def _number(rng, reading: str, value: float, approx: bool = False) -> tuple[str, float, str]:
    """(the number as written, its value, how): digits, a decimal ('40.0', '.6', '0.60'), words, 'minus 18', a half
    ('20½'), or 'below' for a negative temperature near which (approx) to be written 'N <unit> below zero'."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    if reading == "ndvi":
        u = rng.uniform()
        if u < 0.25:
            return f"{v:.2f}", v, "digits"
        if u < 0.5 and txt.startswith("0."):
            return txt[1:], v, "digits"
        return txt, v, "digits"
    u = rng.uniform()
    if v == int(v):
        if u < 0.2 and abs(v) < 1000:
            return number_words(int(v)), v, "words"
        if u < 0.3:
            txt = f"{v:.1f}"
    elif v > 0 and v * 2 == int(v * 2) and u < 0.4:
        return f"{int(v)}½", v, "digits"
    if v < 0:
        w = rng.uniform()
        if reading == "temperature_c" and w < 0.35 and approx:  # '18 degrees below zero or thereabouts'
            return txt[1:], v, "below"
        if w < 0.6:
            return f"minus {txt[1:]}", v, "digits"
    return txt, v, "digits"


def _unit(rng, reading: str, how: str) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        opts = (" degrees", " degrees Celsius")
        if how == "digits":
            opts += ("°C", " °C", " degs C")
        if how == "below":
            opts += ("°C",)
        return _pick(rng, opts), "c"
    if reading == "humidity_pct":
        return _pick(rng, (" per cent", " percent") if how == "words" else ("%", " per cent", " percent")), "%"
    return "", ""


def render_sensor_u(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('balmiest', 'frostiest', 'sorriest-looking') or a tail ('that tops
    the temperature chart', 'that props up the humidity table'); thresholds after the noun ('that has broken through
    60 °C', 'whose humidity is capped at 40 per cent', 'with NDVI logged at .6 or over', '(the thermometer puts it
    at 18 degrees below zero or thereabouts)', 'that comes up short of 20½%')."""
    rd = c.reading
    name = _NAMES.get(rd, rd.replace("_", " "))
    if c.is_superlative:
        adj = _SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, _super_tails(name, c.comparator)), c
    n, value, how = _number(rng, rd, c.value, c.comparator == "approx")
    unit, code = _unit(rng, rd, how)
    named = rd not in ("temperature_c", "humidity_pct")  # NDVI (and any other reading) is always named
    frame = _pick(rng, ("whose", "logged", "gauge") if named else ("that", "that", "whose", "logged", "gauge"))
    if frame in ("whose", "logged") and rd == "temperature_c" and how == "digits" and rng.uniform() < 0.25:
        unit, code = "", ""  # the reading is named: the unit may go
    num = f"{n}{unit} below zero" if how == "below" else n + unit
    written = SensorConstraint(rd, c.comparator, value, code)
    if frame == "that":
        return "", "that " + _pick(rng, _FINITE[c.comparator]).format(n=num), written
    if frame == "whose":
        return "", f"whose {name} " + _pick(rng, _FINITE[c.comparator]).format(n=num), written
    if frame == "logged":
        return "", f"with {name} logged at " + _pick(rng, _AMOUNT[c.comparator]).format(n=num), written
    gauge = _pick(rng, _GAUGES.get(rd, (f"{name} sensor",)))
    return "", f"(the {gauge} puts it at " + _pick(rng, _AMOUNT[c.comparator]).format(n=num) + ")", written


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_u(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at easting 3.5, northing 2', '(x 3.5 | y 2)', 'where
    the x-coordinate reads 3.5 and the y-coordinate 2', 'marked on the floor plan at x = 3.5, y = 2'."""
    return _pick(rng, (f"at easting {x}, northing {y}", f"(x {x} | y {y})",
                       f"where the x-coordinate reads {x} and the y-coordinate {y}",
                       f"marked on the floor plan at x = {x}, y = {y}"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _listed(rng, res: list[str]) -> str:
    """Goals in a running sentence: commas, or semicolons where a goal has commas of its own."""
    if any("," in r for r in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


def _sep(res: list[str]) -> str:
    return ";" if any("," in r for r in res) else ","


def _clock(rng, lo: int = 6, hi: int = 22) -> str:
    return f"{int(rng.integers(lo, hi)):02d}.{int(rng.integers(0, 12)) * 5:02d}"


_PLATFORMS = ("1", "2", "3", "4", "5", "6", "7", "8")
_LINES = ("the Ferndale branch", "the Coast Line", "Southern Counties Rail", "the Valley Line")


def _railway(rng, res: list[str], order: str) -> str:
    """A railway station announcer: a departure board or a tannoy announcement."""
    if len(res) == 1:
        return _pick(rng, (f"Platform announcement: the shuttle now boarding runs non-stop to {res[0]}. Please stand "
                           "clear of the doors.",
                           f"This is a non-stop service. Next and only stop: {res[0]}. Please mind the gap."))
    n = len(res)
    plat = _pick(rng, _PLATFORMS)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"PLATFORM {plat} · {_clock(rng)} stopping service · {_pick(rng, _LINES)}", "Calling at:"]
            lines += [f"   {_cap(r)}" for r in res[:-1]]
            lines.append(f"Terminating at: {_cap(res[-1])}")
            lines.append("This service calls at each stop strictly in the order shown.")
            return "\n".join(lines)
        p = number_words(int(plat)) if rng.uniform() < 0.5 else plat
        sep = _sep(res)
        s = (f"Good {_pick(rng, ('morning', 'afternoon', 'evening'))}. The train now standing at platform {p} is the "
             f"{_clock(rng)} stopping service, calling at {res[0]}")
        s += "".join(f"{sep} {r}" for r in res[1:-1])
        return s + (f"{sep} and terminating at {res[-1]}. Stops are served in the order announced – this train does "
                    "not skip stops. Please mind the gap.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"  ▸ {_cap(r)}" for r in res)
        return (f"RAIL ROVER · off-peak day ticket · {_pick(rng, _LINES)}\nValid at any of these {n} stations, in any "
                f"order and in either direction:\n{body}\nBreak your journey wherever you like.")
    return (f"Customer information: your hop-on hop-off ticket covers {_listed(rng, res)}. Hop on and off in whatever "
            "order you like, the ticket doesn't mind.")


_CLASSES = ("SUNRISE FLOW", "GENTLE HATHA", "SLOW VINYASA", "LUNCHTIME STRETCH")
_TEACHERS = ("Priya", "Jonno", "Saoirse", "Meg")


def _yoga(rng, res: list[str], order: str) -> str:
    """A yoga teacher's class plan or spoken cues."""
    who = _pick(rng, _TEACHERS)
    if len(res) == 1:
        return _pick(rng, (f"Just one pose this morning, friends: hold yourself at {res[0]}, and breathe. Namaste, "
                           f"{who}",
                           f"A short practice today – all we need is {res[0]}. Stay there, soften, and let the "
                           "breath do the work."))
    n = len(res)
    mins = _pick(rng, ("45 min", "60 minutes", "an hour", "30-minute"))
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"{_pick(rng, _CLASSES)} · {mins} · all levels · with {who}"]
            lines += [f"Pose {i + 1} → {r}" for i, r in enumerate(res[:-1])]
            lines.append(f"Final rest → {res[-1]}")
            lines.append("Move through the poses in exactly this sequence – each one prepares you for the next.")
            lines.append("Namaste 🙏")
            return "\n".join(lines)
        s = f"Let's begin. Inhale, and arrive at {res[0]}."
        breath = ("Exhale", "Inhale")
        s += "".join(f" {breath[i % 2]}, and flow on to {r}." for i, r in enumerate(res[1:-1]))
        return s + (f" And finally, settle into stillness at {res[-1]}. Keep to this sequence, one breath at a time – "
                    f"no jumping ahead. Namaste, {who}")
    if rng.uniform() < 0.5:
        body = "\n".join(f"○ {r}" for r in res)
        return (f"OPEN PRACTICE · {mins} · {n} poses to explore\n{body}\nFlow between them in whatever order your "
                "body asks for.")
    return (f"Free flow tonight, everyone: {_listed(rng, res)} are all waiting for you. No set sequence tonight – go "
            f"to whichever feels right. {who} x")


_HOUSES = ("HARGREAVES & DAUGHTER", "PENNYWORTH'S SALEROOMS", "THE OLD CORN EXCHANGE AUCTIONS", "BRIGG & TALLIS")
_SALES = ("Fine & Decorative Sale", "Spring Sale", "Household Contents Sale", "Antiques & Interiors")
_DAYS = ("Tues 11 June", "Sat 3rd May", "Wednesday 14/02", "Thurs 9 Oct")
_ORDINAL = ("one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten")


def _auction(rng, res: list[str], order: str) -> str:
    """An auctioneer's catalogue or rostrum patter."""
    house = _pick(rng, _HOUSES)
    if len(res) == 1:
        return _pick(rng, (f"A single-lot sale today, ladies and gentlemen: {res[0]}. Going once, going twice ... "
                           "sold!",
                           f"Only the one lot left on the books this afternoon – {res[0]}. Have a good look before "
                           "the hammer falls."))
    n = len(res)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"{house} – {_pick(rng, _SALES)}, {_pick(rng, _DAYS)}, {_clock(rng, 9, 12).lstrip('0')}am"
                     if rng.uniform() < 0.5 else f"{house} – {_pick(rng, _SALES)}",
                     f"Buyer's premium {_pick(rng, ('25%', '22.5%', '20%'))} + VAT"]
            lines += [f"LOT {i + 1}  {r}" for i, r in enumerate(res)]
            lines.append("Lots will be offered strictly in catalogue order – no lot taken out of turn.")
            return "\n".join(lines)
        s = f"Ladies and gentlemen, good afternoon. We open the sale with lot one, {res[0]}"
        s += "".join(f"; lot {_ORDINAL[i + 1]}, {r}" for i, r in enumerate(res[1:-1]))
        return s + (f"; and our final lot of the day, lot {_ORDINAL[n - 1]}, {res[-1]}. We go strictly by the "
                    "catalogue numbers, so please bear with us.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"– {r}" for r in res)
        return (f"{house} · VIEWING DAY · {n} lots on view\n{body}\nBrowse the lots in whatever order suits you – "
                "viewing is open, there is no set route.")
    return (f"Viewing is open all morning, folks: do have a look at {_listed(rng, res)} before bidding starts – "
            "wander round them in any order you fancy.")


_READERS = ("Madame Zora", "Auntie Rosalind", "Mystic Maud", "Esmeralda of the Pier")
_POSITIONS = ("The Past", "The Present", "The Future", "The Hidden Hand", "The Obstacle", "The Counsel",
              "Hopes and Fears")
_ROMAN = ("I", "II", "III", "IV", "V", "VI", "VII", "VIII", "IX", "X")


def _tarot(rng, res: list[str], order: str) -> str:
    """A tarot reader laying a spread."""
    who = _pick(rng, _READERS)
    if len(res) == 1:
        return _pick(rng, (f"One card drawn, and only one: {res[0]}. Go where it points, my dear.",
                           f"The deck is quiet tonight, pet – it shows a single card, and it shows {res[0]}. That is "
                           f"where you must go. {who}"))
    n = len(res)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"THE SPREAD, as laid for the robot ({who})"]
            lines += [f"{_ROMAN[i]}. {_POSITIONS[i % len(_POSITIONS)]} – {r}" for i, r in enumerate(res[:-1])]
            lines.append(f"{_ROMAN[n - 1]}. The Outcome – {res[-1]}")
            lines.append("Turn the cards in the order they were laid – read out of turn, they lie.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Sit, sit. The cards have spoken, my dear: your path begins at {res[0]}"
        s += "".join(f"{sep} winds on to {r}" for r in res[1:-1])
        return s + (f"{sep} and ends at {res[-1]}. Walk it in exactly the order the cards fell – the spirits are "
                    "particular about that.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"✧ {r}" for r in res)
        return (f"A SCATTERED SPREAD ({n} cards, face down) – {who}\n{body}\nNo card outranks another here – turn "
                "them over in whatever order calls to you.")
    return (f"The cards fell in a heap tonight, dearie: {_listed(rng, res)}. The order means nothing in a scattered "
            "spread, so visit them as the spirit moves you.")


def render_instruction_u(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a railway announcer, a yoga teacher, an
    auctioneer, a tarot reader). Goals stay in visiting order; strict texts say the order is fixed ('calls at each
    stop strictly in the order shown', 'in exactly this sequence', 'strictly in catalogue order', 'in the order they
    were laid'), free ones say it is open ('in any order and in either direction', 'whatever order your body asks
    for', 'in whatever order suits you', 'whatever order calls to you')."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(4))
    return (_railway, _yoga, _auction, _tarot)[who](rng, res, order)
