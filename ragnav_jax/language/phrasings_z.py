"""Held-out phrasings of set Z: goal, sensor, coordinate and instruction templates for the `unseen_z` split.

Written by a helper that never read the parser (nor its lexicon, tagger, readings, agreement or command code, nor
the evaluation code), before any run of any reader on these sentences, with only the interface of the earlier
template sets in view (`phrasings_y.py`, `phrasings_x.py` and the docstrings of the others). Same four functions,
arguments and meanings as the other template sets. The style is four people who send a home robot round a house
in the layout and words of their own job or pastime:

- a mission-control flight director, as an EVA timeline or over the loop: "EVA TIMELINE – Homestead (Flight:
  Aurora)", "MET 0:25  Task 1 – translate to ...", "MET 1:10  Closeout – proceed to ...", or "All flight
  controllers, this is Flight. Crew is go for EVA. First task, translate to ...; then translate to ...; and close
  out at ...."; a fixed order as "work the tasks in timeline order", "nothing out of sequence", "in the order
  read"; a free one as "GET-AHEAD TASKS (three) – crew's discretion" with "▹" bullets, "the ground has no
  constraint on order", "worked in any sequence the crew likes", "Flight's got no preference"; one goal as "this is
  a single-task EVA. Translate to ... and hold there.";
- a gardener's plan for the weekend: "GARDEN PLAN – the long border, early spring", "Plot A: ...", "Plot C (last to
  go in): ...", or "Right, here's the plan for Saturday. Start by digging in at ..., then work along to ..., and
  finish off at ...."; fixed as "work it in succession, plot by plot as lettered", "keep to that succession and no
  other"; free as "ODD JOBS ROUND THE GARDEN (three) – no particular succession" with "✽" bullets, "in whatever
  order the weather allows", "it doesn't matter a jot which comes first"; one goal as "Only one job in the garden
  this week: ....";
- a ceilidh caller: "THE ROBOT'S REEL – a jig in three figures, called by Morag", "Figure one: advance to ...",
  "Last figure: promenade home to ...", or "Right, take your partners, please! Off you go to ..., swing over to ...,
  and promenade all the way home to ...."; fixed as "dance the figures just as they're called, figure by figure",
  "dance it the way I call it – no running ahead of the caller"; free as "FREE-FOR-ALL – three spots on the floor,
  no set calls" with "♪" bullets, "in whatever order the tune carries you", "no calls for this one", "in whichever
  order the band carries you"; one goal as "Just the one figure in this dance, folks: promenade down to ... and take
  a bow.";
- a chess annotator: "Robot – The House, club night (annotated)", "1. ...!", "2. ...!?", "3. ... – and mate.", or
  "Annotator's note: the robot opens at ..., develops towards ..., and delivers mate at ...."; fixed as "the moves
  must be played in exactly this order; transpose any two and the combination collapses", "move order is
  everything here"; free as "ENDGAME STUDY – three squares to occupy, move order free" with "♙" bullets, "every line
  transposes", "the move order is irrelevant here", "it all transposes into the same position"; one goal as "A
  one-mover: the robot plays straight to ..., and that's mate."

Goals: attributes before the noun, as an aside ", a teal and corduroy affair," or in a bracket "(teal and corduroy,
you can't miss it)"; states before the noun ("the switched-on lamp"), as "(switched on, mind)" or ", known to be
switched on,"; the room as "in the X" or "right there in the X", always before any relation; relations in new words
("close at hand to", "within a short stroll of", "pushed up against", "jostling", "sat alongside", "standing sentry
beside", "keeping vigil by", "mooching about by", "sprawled on", "sat up on", "slung beneath", "camped out under",
"dangling above", "lording it over", "snug inside", "kept safe in", "laden with", "furnished with", "cohabiting
with", "roomed together with", "drawn up in front of", "set down before", "cowering behind", "hunkered down
behind", "on the opposite wall to", "gazing across at", "a hair to the left of", "round to the left of", "a hair to
the right of", "round to the right of", besides the plain words); several relations joined by "and", ", and what's
more," or ", as well as being"; an anchor with relations of its own takes them in a bracket, "(to be precise, the
credenza next to the record player)" or "(you know, next to the record player)", and deeper down "that is itself
next to ...". Readings: "has nosed above", "has poked its head above", "reads more than", "never sinks beneath", "is
... or more, never less", "holds firm at ... or above", "hasn't touched", "reads less than", "hasn't made it as high
as", "is ... or lower, never more", "goes up to ... and stops there", "never rises higher than", "is nigh on",
"reads ..., a shade either side", "is just about"; frames "that ...", "the humidity of which ...", "for which the
temperature ..."; units "°C", "degrees Celsius", "on the Celsius scale", "degrees" (with words), "degrees of frost"
(a temperature below zero near which), none when the reading is named, "%", "per-cent", "percent"; numbers as
digits, words ("forty", "minus four", "a hundred and five"), "minus 4", "four degrees of frost", the raised decimal
point ("22·5", "0·65"), "twenty-two point five", NDVI as ".65", "0.65", "0·65", "point sixty-five", "point six",
"point oh five"; superlatives "the most torrid", "the most scalding", "the most ice-cold", "the most
bone-chilling", "the heartiest", "the most burgeoning", "the peakiest", "the puniest", "the swampiest", "the most
waterlogged", "the dustiest", "the most tinder-dry", "that sets the high-water mark for temperature", "that takes top
prize for NDVI", "with the all-time-high humidity", "that sets the low-water mark for temperature", "that takes the
wooden spoon for NDVI", "with the all-time-low humidity". Coordinates: "at the spot whose x is 3.5 and whose y is
2", "(x/y fix: 3.5, 2)", "at x=3.5 & y=2", "at the coordinate pair (3.5, 2)"; always x then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.template_text import attributes_and_states
from ragnav_jax.language.template_text import hyphenated as _hyphen
from ragnav_jax.language.template_text import listed as _listed
from ragnav_jax.language.template_text import tidy as _tidy
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Small helpers of this set's own

_ONES = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
         "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen")
_TENS = ("", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety")


def number_words(n: int) -> str:
    """A whole number in words: 'minus four', 'sixty-five', 'a hundred and five', 'three hundred'."""
    if n < 0:
        return "minus " + number_words(-n)
    if n < 20:
        return _ONES[n]
    if n < 100:
        return _TENS[n // 10] + ("-" + _ONES[n % 10] if n % 10 else "")
    if n < 1000:
        rest = n % 100
        hundreds = "a hundred" if n // 100 == 1 else _ONES[n // 100] + " hundred"
        return hundreds + (" and " + number_words(rest) if rest else "")
    return str(n)


def _article(word: str) -> str:
    return "an" if word[:1].lower() in "aeiou" else "a"


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "close at hand to", "within a short stroll of"),
    "next_to": ("next to", "pushed up against", "jostling"),
    "beside": ("beside", "sat alongside", "standing sentry beside"),
    "by": ("by", "keeping vigil by", "mooching about by"),
    "on": ("on", "sprawled on", "sat up on"),
    "under": ("under", "slung beneath", "camped out under"),
    "above": ("above", "dangling above", "lording it over"),
    "in": ("in", "snug inside", "kept safe in"),
    "with": ("with", "laden with", "furnished with"),
    "in_room_with": ("in the same room as", "cohabiting with", "roomed together with"),
    "in_front_of": ("in front of", "drawn up in front of", "set down before"),
    "behind": ("behind", "cowering behind", "hunkered down behind"),
    "opposite": ("opposite", "on the opposite wall to", "gazing across at"),
    "left_of": ("to the left of", "a hair to the left of", "round to the left of"),
    "right_of": ("to the right of", "a hair to the right of", "round to the right of"),
}
_JOINS = (" and ", ", and what's more, ", ", as well as being ")


def _anchor_np(rng, t: Target, depth: int) -> str:
    """An anchor: attributes before the noun; states before it or, for an anchor without relations of its own, as
    '(switched on, mind)'; the anchor's own relations in a bracket of their own ('(to be precise, the credenza next
    to ...)', '(you know, next to ...)'), or deeper down as 'that is itself next to ...'."""
    _, states = attributes_and_states(t)
    out = "the "
    bracket_state = bool(states) and depth == 1 and not t.relations and rng.uniform() < 0.35
    if states and not bracket_state:
        out += _hyphen(states) + " "
    out += t.phrase
    if bracket_state:
        out += f" ({' and '.join(states)}, mind)"
    if t.relations:
        inner = _rel_chain(rng, t.relations, depth + 1)
        if depth > 1:
            out += f" that is itself {inner}"
        elif rng.uniform() < 0.5:
            out += f" (to be precise, the {t.head} {inner})"
        else:
            out += f" (you know, {inner})"
    return out


def _rel_chain(rng, rels: tuple[Relation, ...], depth: int = 1) -> str:
    out = ""
    for i, r in enumerate(rels):
        part = f"{_pick(rng, REL_WORDS[r.type])} {_anchor_np(rng, r.anchor, depth)}"
        out = part if i == 0 else out + _pick(rng, _JOINS) + part
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS = ("in the {}", "in the {}", "in the {}", "right there in the {}")


def _goal_np(rng, t: Target, prefix: str, no_bracket: bool) -> str:
    """The goal's own noun phrase: 'the teal corduroy bean bag', 'the bean bag, a teal and corduroy affair,', 'the
    bean bag (teal and corduroy, you can't miss it)', 'the switched-on lamp', 'the lamp (switched on, mind)', 'the
    lamp, known to be switched on,'. With a superlative adjective the attributes stay before the noun; with a
    bracketed coordinate hint to follow (no_bracket), everything stands before the noun."""
    pre, states = attributes_and_states(t)
    if not t.phrase.endswith(t.head):  # a phrase of another shape: written as given, anything missing in an aside
        missing = [a for a in t.attributes if a not in t.phrase.split()]
        out = "the " + (f"{prefix} " if prefix else "") + t.phrase
        if not missing:
            return out
        said = " and ".join(missing)
        return out + (f", {_article(said)} {said} affair," if no_bracket else f" ({said}, you can't miss it)")
    head = t.phrase[len(t.phrase) - len(t.head):]
    attr_style = "before"
    if pre and not prefix and not no_bracket:
        attr_style = _pick(rng, ("before", "before", "affair", "miss"))
    state_style = None
    if states:
        opts = ["before"] if no_bracket else ["before", "mind", "known"]
        if attr_style == "miss":
            opts.remove("mind")  # never two round brackets on one noun
        state_style = _pick(rng, opts)
    out = "the " + (f"{prefix} " if prefix else "")
    if state_style == "before":
        out += _hyphen(states) + " "
    out += t.phrase if attr_style == "before" else head
    if state_style == "mind":
        out += f" ({' and '.join(states)}, mind)"
    said = " and ".join(pre)
    if attr_style == "affair":
        out += f", {_article(said)} {said} affair,"
    elif attr_style == "miss":
        out += f" ({said}, you can't miss it)"
    if state_style == "known":
        out += f", known to be {' and '.join(states)},"
    return out


_HAS_NUMBER = re.compile(r"\d|\b(" + "|".join(w for w in _ONES + _TENS if w) + r"|hundred|point|oh|frost)\b")


def render_goal_z(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set Z writes it: 'the teal corduroy bean bag right there in the nursery', 'the bean bag, a teal and
    corduroy affair,', 'the lamp, known to be switched on,', 'the most ice-cold mini-fridge in the pantry', 'the
    guitar (x/y fix: 3.5, 2)', 'the lamp jostling the credenza (you know, laden with the record player)'. The room
    comes before any relation (and before a superlative tail, which is read inside it); a coordinate hint comes
    after any number of a sensor tail; relations come last."""
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

# Finite predicates: after "that", "the <reading> of which" or "for which the <reading>".
_FINITE = {
    "gt": ("has nosed above {n}", "has poked its head above {n}", "reads more than {n}"),
    "ge": ("never sinks beneath {n}", "is {n} or more, never less", "holds firm at {n} or above"),
    "lt": ("hasn't touched {n}", "reads less than {n}", "hasn't made it as high as {n}"),
    "le": ("is {n} or lower, never more", "goes up to {n} and stops there", "never rises higher than {n}"),
    "approx": ("is nigh on {n}", "reads {n}, a shade either side", "is just about {n}"),
}
_NAMES = {"temperature_c": "temperature", "humidity_pct": "humidity", "ndvi": "NDVI"}
_SUPER_ADJ = {
    ("temperature_c", "max"): ("warmest", "most torrid", "most scalding"),
    ("temperature_c", "min"): ("coldest", "most ice-cold", "most bone-chilling"),
    ("ndvi", "max"): ("healthiest", "heartiest", "most burgeoning"),
    ("ndvi", "min"): ("least healthy", "peakiest", "puniest"),
    ("humidity_pct", "max"): ("most humid", "swampiest", "most waterlogged"),
    ("humidity_pct", "min"): ("driest", "dustiest", "most tinder-dry"),
}


def _super_tails(name: str, comparator: str) -> tuple[str, ...]:
    if comparator == "max":
        return (f"that sets the high-water mark for {name}", f"that takes top prize for {name}",
                f"with the all-time-high {name}")
    return (f"that sets the low-water mark for {name}", f"that takes the wooden spoon for {name}",
            f"with the all-time-low {name}")


def _point_words(txt: str) -> str | None:
    """'0.65' -> 'point sixty-five', '0.6' -> 'point six', '0.05' -> 'point oh five'; None otherwise."""
    if not re.fullmatch(r"0\.\d\d?", txt) or float(txt) == 0:
        return None
    d = txt[2:]
    if d.startswith("0"):
        return "point oh " + _ONES[int(d[1])]
    return "point " + number_words(int(d))


def _number(rng, reading: str, value: float, approx: bool = False) -> tuple[str, float, str]:
    """(the number as written, its value, how): digits ('40', '-4', '.65', '0.65', '22·5', '0·65', 'minus 4',
    'minus 2.5'), words ('forty', 'minus four', 'a hundred and five', 'twenty-two point five', 'point sixty-five'),
    or 'frost' for a whole negative temperature near which (approx), to be written 'N degrees of frost'."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    u = rng.uniform()
    if reading == "ndvi":
        words = _point_words(txt)
        if words is not None and u < 0.25:
            return words, v, "words"
        if u < 0.45 and "." in txt:
            return txt.replace(".", "·"), v, "digits"
        if u < 0.75 and txt.startswith("0."):
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
        if u < 0.5 and v < 0:
            return f"minus {whole}", v, "digits"
        return txt, v, "digits"
    if not re.fullmatch(r"-?\d+\.\d+", txt):
        return txt, v, "digits"
    mag = txt.lstrip("-")
    if u < 0.3:
        return ("-" if v < 0 else "") + mag.replace(".", "·"), v, "digits"
    if u < 0.5 and v > 0 and re.fullmatch(r"\d+\.\d", mag) and whole < 1000:
        return f"{number_words(whole)} point {_ONES[int(mag[-1])]}", v, "words"
    if u < 0.75 and v < 0:
        return f"minus {mag}", v, "digits"
    return txt, v, "digits"


def _unit(rng, reading: str, how: str) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        if how == "frost":
            return " degrees of frost", "c"
        if how == "words":
            return _pick(rng, (" degrees", " degrees Celsius")), "c"
        return _pick(rng, ("°C", " °C", " degrees Celsius", " on the Celsius scale")), "c"
    if reading == "humidity_pct":
        if how == "words":
            return _pick(rng, (" percent", " per-cent")), "%"
        return _pick(rng, ("%", " %", " per-cent", " percent")), "%"
    return "", ""


def render_sensor_z(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('most ice-cold', 'heartiest', 'dustiest') or a tail ('that sets the
    high-water mark for temperature', 'that takes the wooden spoon for NDVI', 'with the all-time-low humidity');
    thresholds after the noun ('that has nosed above 60 °C', 'the humidity of which is forty per-cent or lower, never
    more', 'for which the NDVI never sinks beneath point sixty-five', 'that is nigh on four degrees of frost', 'the
    temperature of which reads 22·5 on the Celsius scale, a shade either side')."""
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
    frame = _pick(rng, ("ofwhich", "forwhich") if named else ("that", "that", "ofwhich", "forwhich"))
    if frame != "that" and how == "digits" and not named and rng.uniform() < 0.15:
        unit, code = "", ""  # the reading is named: the unit may go
    written = SensorConstraint(rd, c.comparator, value, code)
    finite = _pick(rng, _FINITE[c.comparator]).format(n=n + unit)
    if frame == "that":
        return "", "that " + finite, written
    if frame == "ofwhich":
        return "", f"the {name} of which {finite}", written
    return "", f"for which the {name} {finite}", written


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_z(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at the spot whose x is 3.5 and whose y is 2', '(x/y
    fix: 3.5, 2)', 'at x=3.5 & y=2', 'at the coordinate pair (3.5, 2)'."""
    return _pick(rng, (f"at the spot whose x is {x} and whose y is {y}", f"(x/y fix: {x}, {y})", f"at x={x} & y={y}",
                       f"at the coordinate pair ({x}, {y})"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _sep(res: list[str]) -> str:
    return ";" if any("," in r for r in res) else ","


def _comma(goal: str) -> str:
    """A comma to close a goal that has commas of its own before the sentence goes on."""
    return "," if "," in goal else ""


_MISSIONS = ("Homestead", "Lamplighter", "Long Corridor", "Hearthside", "Quiet Harbour")
_FLIGHTS = ("Aurora", "Polaris", "Meridian", "Kestrel", "Granite")
_TRANSLATE = ("translate to", "move to", "proceed to")
_LOOP = ("All flight controllers, this is Flight.", "CAPCOM, Flight – pass this up to the crew.",
         "Flight, CAPCOM, reading up the plan.")


def _flight_director(rng, res: list[str], order: str) -> str:
    """A mission-control flight director: an EVA timeline, or the plan read over the loop."""
    if len(res) == 1:
        g, c = res[0], _comma(res[0])
        return _pick(rng, (f"All flight controllers, Flight: this is a single-task EVA. Translate to {g}{c} and hold "
                           "there. That's the whole timeline.",
                           f"CAPCOM, pass up a contingency EVA – just the one task: get to {g}{c} and stand by. Flight "
                           "out."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"EVA TIMELINE – {_pick(rng, _MISSIONS)} (Flight: {_pick(rng, _FLIGHTS)})"]
            met = int(rng.integers(5, 25))
            for i, r in enumerate(res):
                stamp = f"MET {met // 60}:{met % 60:02d}"
                label = f"Task {i + 1}" if i < n - 1 else "Closeout"
                lines.append(f"{stamp}  {label} – {_pick(rng, _TRANSLATE)} {r}")
                met += int(rng.integers(10, 40))
            lines.append("Work the tasks in timeline order. No get-aheads, and nothing out of sequence without a call "
                         "from Flight.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"{_pick(rng, _LOOP)} Crew is go for EVA. First task, translate to {res[0]}"
        s += "".join(f"{sep} {_pick(rng, ('then translate to', 'after that, proceed to', 'next up,'))} {r}"
                     for r in res[1:-1])
        return s + (f"{sep} and close out at {res[-1]}. Timeline is locked – work the tasks in the order read, "
                    "nothing out of sequence.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"▹ {r}" for r in res)
        return (f"GET-AHEAD TASKS ({w}) – crew's discretion\n{body}\nSequence is the crew's call; the ground has no "
                "constraint on order.")
    return (f"CAPCOM to crew: if you get ahead of the timeline, you can pick up {_listed(rng, res)} – {w} get-ahead "
            "tasks, worked in any sequence the crew likes. Flight's got no preference.")


_BORDERS = ("the long border", "the cottage patch", "the south-facing border", "the allotment", "the herb corner")
_SEASONS = ("early spring", "late autumn", "the May bank holiday", "high summer", "before the first frosts")
_DAYS = ("Saturday", "Sunday", "the weekend", "tomorrow morning")
_ALONG = ("then work along to", "after that, move on to", "then it's over to")
_LETTERS = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"


def _gardener(rng, res: list[str], order: str) -> str:
    """A gardener: the weekend's garden plan, lettered plot by plot, or a note of odd jobs."""
    if len(res) == 1:
        return _pick(rng, (f"Only one job in the garden this week: {res[0]}. Everything else can wait till spring.",
                           f"Just the one thing to see to out there – {res[0]} – and then you can put your feet up."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"GARDEN PLAN – {_pick(rng, _BORDERS)}, {_pick(rng, _SEASONS)}"]
            for i, r in enumerate(res):
                letter = _LETTERS[i] if i < len(_LETTERS) else f"Z{i}"
                lines.append(f"Plot {letter}: {r}" if i < n - 1 else f"Plot {letter} (last to go in): {r}")
            lines.append("Work it in succession, plot by plot as lettered – each patch wants the one before it "
                         "settled first.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Right, here's the plan for {_pick(rng, _DAYS)}. Start by digging in at {res[0]}"
        s += "".join(f"{sep} {_pick(rng, _ALONG)} {r}" for r in res[1:-1])
        return s + (f"{sep} and finish off at {res[-1]}. Keep to that succession and no other – it's how the soil "
                    "settles.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"✽ {r}" for r in res)
        return (f"ODD JOBS ROUND THE GARDEN ({w}) – no particular succession\n{body}\nGet round them in whatever order "
                "the weather allows.")
    return (f"While you're out with the trowel, look in on {_listed(rng, res)}. It doesn't matter a jot which comes "
            "first – they'll all keep till you get there.")


_DANCES = ("THE ROBOT'S REEL", "THE HOOVER HORNPIPE", "THE CORRIDOR JIG", "THE LANDING STRATHSPEY")
_KINDS = ("jig", "reel", "strathspey")
_CALLERS = ("Morag", "Hamish", "Aunt Effie", "Callum")
_STEPS = ("advance to", "swing over to", "set and turn to", "dance up to", "gallop across to")
_MOVES = ("swing over to", "set and turn to", "then gallop across to", "then dance up to")


def _caller(rng, res: list[str], order: str) -> str:
    """A ceilidh caller: a dance in figures, or the calls shouted over the band."""
    if len(res) == 1:
        g, c = res[0], _comma(res[0])
        return _pick(rng, (f"Just the one figure in this dance, folks: promenade down to {g}{c} and take a bow.",
                           f"A wee solo turn to finish the night – swing on over to {res[0]}, and that's your dance "
                           "done."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            dance, kind, caller = _pick(rng, _DANCES), _pick(rng, _KINDS), _pick(rng, _CALLERS)
            lines = [f"{dance} – a {kind} in {w} figures, called by {caller}"]
            lines += [f"Figure {number_words(i + 1)}: {_pick(rng, _STEPS)} {r}" for i, r in enumerate(res[:-1])]
            lines.append(f"Last figure: promenade home to {res[-1]}")
            lines.append("Dance the figures just as they're called, figure by figure – get them out of step and the "
                         "whole dance ends up in a fankle.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Right, take your partners, please! Off you go to {res[0]}"
        s += "".join(f"{sep} {_pick(rng, _MOVES)} {r}" for r in res[1:-1])
        return s + (f"{sep} and promenade all the way home to {res[-1]}. And dance it the way I call it – no running "
                    "ahead of the caller!")
    if rng.uniform() < 0.5:
        body = "\n".join(f"♪ {r}" for r in res)
        return (f"FREE-FOR-ALL – {w} spots on the floor, no set calls\n{body}\nDance to them in whatever order the "
                "tune carries you.")
    return (f"No calls for this one, it's a free dance: make your way to {_listed(rng, res)}, in whichever order the "
            "band carries you.")


_EVENTS = ("club night", "a friendly", "the Tuesday blitz", "county league, round two")
_MARKS = ("", "", "", "!", "!?")
_DEVELOP = ("develops towards", "switches play to", "presses on to", "regroups at")


def _chess(rng, res: list[str], order: str) -> str:
    """A chess annotator: the game score with marks, or a note on the combination."""
    if len(res) == 1:
        return _pick(rng, (f"A one-mover: the robot plays straight to {res[0]}, and that's mate. Nothing more to it.",
                           f"White to play and win at once – the only move is to {res[0]}."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"Robot – The House, {_pick(rng, _EVENTS)} (annotated)"]
            lines += [f"{i + 1}. {r}{_pick(rng, _MARKS)}" for i, r in enumerate(res[:-1])]
            lines.append(f"{n}. {res[-1]} – and mate.")
            lines.append("The moves must be played in exactly this order; transpose any two and the combination "
                         "collapses.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Annotator's note: the robot opens at {res[0]}"
        s += "".join(f"{sep} {_pick(rng, _DEVELOP)} {r}" for r in res[1:-1])
        return s + (f"{sep} and delivers mate at {res[-1]}. Move order is everything here – play them out of sequence "
                    "and the attack falls apart.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"♙ {r}" for r in res)
        return (f"ENDGAME STUDY – {w} squares to occupy, move order free\n{body}\nEvery line transposes, so play them "
                "in any order you like – the final position is the same.")
    return (f"However it's played, the robot needs to reach {_listed(rng, res)}. The move order is irrelevant here; it "
            "all transposes into the same position.")


def render_instruction_z(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a flight director, a gardener, a ceilidh
    caller, a chess annotator). Goals stay in visiting order; strict texts say the order is fixed ('timeline order',
    'out of sequence', 'in the order read', 'in succession', 'plot by plot', 'that succession', 'just as they're
    called', 'figure by figure', 'the way I call it', 'running ahead of the caller', 'in exactly this order', 'the
    combination collapses', 'move order is everything'), free ones say it is open ('crew's discretion', 'no
    constraint on order', 'any sequence the crew likes', 'no particular succession', 'whatever order the weather
    allows', 'doesn't matter a jot which comes first', 'no set calls', 'whatever order the tune carries you', 'no
    calls for this one', 'whichever order the band carries you', 'move order free', 'every line transposes', 'move
    order is irrelevant')."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(4))
    return (_flight_director, _gardener, _caller, _chess)[who](rng, res, order)
