"""Held-out phrasings of set X: goal, sensor, coordinate and instruction templates for the `unseen_x` split.

Written by a helper that never read the parser (nor its lexicon, tagger, readings, agreement or command code, nor
the evaluation code), before any run of any reader on these sentences, with only the interface of the earlier
template sets in view (`phrasings_v.py` and the docstrings of the others). Same four functions, arguments and
meanings as the other template sets. The style is four people who send a home robot round a house in the layout
and words of their own job or pastime:

- a weather forecaster, as a broadcast script: "WEATHER SCRIPT – the robot's round", "Dawn: starting off over
  ...", "Mid-morning: moving east through the morning to ...", "Overnight: clearing at last to ...", or "Good
  evening. ... things get going first over ..., then a band of activity reaching ..., and by nightfall it all
  settles over ..."; a fixed order as "the system tracks through strictly in that sequence – no skipping ahead on
  the chart", "in exactly that sequence, one region after the next"; a free one as "...and now the outlook.
  Scattered bright spells are expected over:" with "~" bullets, "these could turn up in any order at all", "arriving
  in no set sequence – take them however the day unfolds"; one goal as "one settled spell only, centred over ...";
- a museum curator's exhibition catalogue: "EXHIBITION CATALOGUE – Things Left Where They Were", "Exhibit 1. The
  ... . Provenance: the house collection.", "On loan for this showing.", or a curator's note "the visit begins with
  ..., proceeds to ..., and closes on ..."; fixed as "please view the works in catalogue order", "follow the
  numbered sequence, exhibit by exhibit", "the works are hung as a narrative, so they must be seen in the order
  described"; free as "SALON HANG – unnumbered works (three)" with "▪" bullets, "there is no set route: browse them
  in any order you please", "there is no prescribed route through the display"; one goal as "Single-work display.
  On loan for this showing only: ...";
- an expedition log with waypoints: "EXPEDITION LOG – day four", "Waypoint Alpha: ...", "Waypoint Bravo (steady
  bearing): ...", "Summit push: ...", or "Broke camp at first light and made for ..., took a fresh bearing for
  ..., and made the summit push to ..."; fixed as "waypoints to be made good in sequence, Alpha onward – no short
  cuts", "route held leg by leg, in the order planned"; free as "BASE CAMP – caches to check (three)" with "◦"
  bullets, "caches can be visited in any order the weather allows", "no fixed route between them – take them in
  whichever order the conditions favour"; one goal as "One objective only: summit push to ...";
- a poet writing rhyming couplets or a limerick, a goal inside each line: "First go to ..., without delay, / then
  on to ..., come what may;", "Keep to the order of my rhyme: / each line in turn, none out of time."; free as "In
  any order, as you please, / go visit each of these with ease:", "No line need come before the rest – / go
  however you think best."; one goal as a limerick ("A robot, both tidy and keen, / was asked just to go and be
  seen / at ... – no more, ...") or "Just go to ... and there remain – / that's all I ask in this refrain."

Goals: attributes before the noun, as "of the teal and corduroy sort" or in a bracket "(described as teal and
corduroy)"; states before the noun ("the switched-on lamp"), as "(presently switched on)" or ", found switched
on,"; the room as "in the X" or "down in the X", always before any relation; relations in new words ("within hail
of", "in the neighbourhood of", "cheek by jowl with", "shoulder to shoulder with", "keeping company beside",
"flanking", "posted by", "moored by", "riding on", "enthroned on", "sheltering under", "skulking beneath", "aloft
over", "hanging high over", "nestled inside", "stowed in", "sporting", "complete with", "sharing a room with", "in
the room that also holds", "fronting", "standing before", "lurking behind", "hidden round the back of", "over the
way from", "face to face with", "on the port side of", "leftward of", "on the starboard side of", "rightward of",
besides the plain words); several relations joined by "and", ", as well as" or " and also"; an anchor with
relations of its own takes them in a bracket, "(namely the one next to the record player)" or "(I mean the one
next to the record player)". Readings: "tops", "runs higher than", "pushes beyond", "never dips under", "stands at
... or upward", "touches ... at the very least", "stays shy of", "runs lower than", "sits south of", "tops out at",
"goes no further than", "is capped at", "is in the region of", "is somewhere about", "is close on", and their
participles; frames "that ...", "whose humidity ...", "where the temperature ...", "with an NDVI that ...", "[NDVI
...]"; units "°C", "degrees C", "Celsius", "degrees" (with words), "%", "per cent", "percent", "% humidity"; numbers
as digits, words ("forty", "minus four"), "minus 4", "4 degrees below zero", "22½", NDVI as ".65", "zero point six
five", "point six five"; superlatives "the most sweltering", "the toastiest", "the frostiest", "the nippiest", "the
leafiest", "the most flourishing", "the droopiest", "the most withered", "the muggiest", "the clammiest", "the most
parched", "the most arid", "whose temperature ranks highest", "that leads every other on NDVI", "with the humidity
at the very top", "whose NDVI ranks lowest", "that trails every other on temperature", "with the humidity at the
very bottom". Coordinates: "plotted at x 3.5 and y 2", "(grid x 3.5, grid y 2)", "at x 3.5 / y 2", "at the point
(3.5, 2) on the plan"; always x then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.template_text import attributes_and_states, number_words
from ragnav_jax.language.template_text import hyphenated as _hyphen
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Small helpers of this set's own

_ONES = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
         "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen")
_TENS = ("", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety")


def _tidy(s: str) -> str:
    s = " ".join(s.split())
    for a, b in ((",,", ","), (", ,", ","), (", (", " ("), (",)", ")"), (", [", " [")):
        s = s.replace(a, b)
    while s.endswith(","):
        s = s[:-1].rstrip()
    return s


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "within hail of", "in the neighbourhood of"),
    "next_to": ("next to", "cheek by jowl with", "shoulder to shoulder with"),
    "beside": ("beside", "keeping company beside", "flanking"),
    "by": ("by", "posted by", "moored by"),
    "on": ("on", "riding on", "enthroned on"),
    "under": ("under", "sheltering under", "skulking beneath"),
    "above": ("above", "aloft over", "hanging high over"),
    "in": ("in", "nestled inside", "stowed in"),
    "with": ("with", "sporting", "complete with"),
    "in_room_with": ("in the same room as", "sharing a room with", "in the room that also holds"),
    "in_front_of": ("in front of", "fronting", "standing before"),
    "behind": ("behind", "lurking behind", "hidden round the back of"),
    "opposite": ("opposite", "over the way from", "face to face with"),
    "left_of": ("to the left of", "on the port side of", "leftward of"),
    "right_of": ("to the right of", "on the starboard side of", "rightward of"),
}
_JOINS = (" and ", ", as well as ", " and also ")


def _anchor_np(rng, t: Target, depth: int) -> str:
    """An anchor: attributes before the noun; states before it or, for an anchor without relations of its own, as
    '(presently switched on)'; the anchor's own relations in a bracket of their own."""
    _, states = attributes_and_states(t)
    out = "the "
    bracket_state = bool(states) and depth == 1 and not t.relations and rng.uniform() < 0.35
    if states and not bracket_state:
        out += _hyphen(states) + " "
    out += t.phrase
    if bracket_state:
        out += f" (presently {' and '.join(states)})"
    if t.relations:
        inner = _rel_chain(rng, t.relations, depth + 1)
        if rng.uniform() < 0.5:
            out += f" (namely the one {inner})"
        else:
            out += f" (I mean the one {inner})"
    return out


def _rel_chain(rng, rels: tuple[Relation, ...], depth: int = 1) -> str:
    out = ""
    for i, r in enumerate(rels):
        part = f"{_pick(rng, REL_WORDS[r.type])} {_anchor_np(rng, r.anchor, depth)}"
        out = part if i == 0 else out + _pick(rng, _JOINS) + part
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS = ("in the {}", "in the {}", "down in the {}")


def _goal_np(rng, t: Target, prefix: str) -> str:
    """The goal's own noun phrase: 'the teal corduroy bean bag', 'the bean bag of the teal and corduroy sort', 'the
    bean bag (described as teal and corduroy)', 'the switched-on lamp', 'the lamp (presently switched on)', 'the
    lamp, found switched on,'. With a superlative adjective the attributes stay before the noun."""
    pre, states = attributes_and_states(t)
    if not t.phrase.endswith(t.head):  # a phrase of another shape: written as given, anything missing in a bracket
        missing = [a for a in t.attributes if a not in t.phrase.split()]
        out = "the " + (f"{prefix} " if prefix else "") + t.phrase
        return out + (f" (described as {' and '.join(missing)})" if missing else "")
    head = t.phrase[len(t.phrase) - len(t.head):]
    attr_style = "before"
    if pre and not prefix:
        attr_style = _pick(rng, ("before", "before", "sort", "described"))
    state_style = None
    if states:
        opts = ["before", "presently", "found"]
        if attr_style == "described":
            opts.remove("presently")  # never two round brackets in a row
        state_style = _pick(rng, opts)
    out = "the " + (f"{prefix} " if prefix else "")
    if state_style == "before":
        out += _hyphen(states) + " "
    if attr_style == "before":
        out += t.phrase
    elif attr_style == "sort":
        out += f"{head} of the {' and '.join(pre)} sort"
    else:
        out += f"{head} (described as {' and '.join(pre)})"
    if state_style == "presently":
        out += f" (presently {' and '.join(states)})"
    elif state_style == "found":
        out += f", found {' and '.join(states)},"
    return out


_HAS_NUMBER = re.compile(r"\d|½|\b(" + "|".join(w for w in _ONES + _TENS if w and w != "one") + r"|hundred|point)\b")


def render_goal_x(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set X writes it: 'the teal corduroy bean bag down in the nursery', 'the bean bag of the teal and
    corduroy sort', 'the lamp, found switched on,', 'the frostiest fridge in the pantry', 'the guitar (grid x 3.5,
    grid y 2)', 'the lamp cheek by jowl with the credenza (namely the one complete with the record player)'. The
    room comes before any relation (and before a superlative tail, which is read inside it); relations come last."""
    t = sg.target
    out = _goal_np(rng, Target(t.phrase, t.head, t.attributes), prefix)
    if hint:
        out += " " + hint
    room = _pick(rng, _ROOMS).format(sg.room) if sg.room else ""
    if tail:
        superlative = not _HAS_NUMBER.search(tail)
        if room and (superlative or rng.uniform() < 0.5):
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

# Finite predicates: after "that", "whose <reading>", "where the <reading>", "with a <reading> that" or "[<reading>".
_FINITE = {
    "gt": ("tops {n}", "runs higher than {n}", "pushes beyond {n}"),
    "ge": ("never dips under {n}", "stands at {n} or upward", "touches {n} at the very least"),
    "lt": ("stays shy of {n}", "runs lower than {n}", "sits south of {n}"),
    "le": ("tops out at {n}", "goes no further than {n}", "is capped at {n}"),
    "approx": ("is in the region of {n}", "is somewhere about {n}", "is close on {n}"),
}
# Participles: after "[<reading>" in the bracket frame, which reads as a note.
_PARTICIPLE = {
    "gt": ("topping {n}", "running higher than {n}", "pushing beyond {n}"),
    "ge": ("never dipping under {n}", "standing at {n} or upward", "touching {n} at the very least"),
    "lt": ("staying shy of {n}", "running lower than {n}", "sitting south of {n}"),
    "le": ("topping out at {n}", "going no further than {n}", "capped at {n}"),
    "approx": ("in the region of {n}", "somewhere about {n}", "close on {n}"),
}
_NAMES = {"temperature_c": "temperature", "humidity_pct": "humidity", "ndvi": "NDVI"}
_SUPER_ADJ = {
    ("temperature_c", "max"): ("warmest", "most sweltering", "toastiest"),
    ("temperature_c", "min"): ("coldest", "frostiest", "nippiest"),
    ("ndvi", "max"): ("healthiest", "leafiest", "most flourishing"),
    ("ndvi", "min"): ("least healthy", "droopiest", "most withered"),
    ("humidity_pct", "max"): ("most humid", "muggiest", "clammiest"),
    ("humidity_pct", "min"): ("driest", "most parched", "most arid"),
}


def _super_tails(name: str, comparator: str) -> tuple[str, ...]:
    if comparator == "max":
        return (f"whose {name} ranks highest", f"that leads every other on {name}",
                f"with the {name} at the very top")
    return (f"whose {name} ranks lowest", f"that trails every other on {name}",
            f"with the {name} at the very bottom")


_NDVI_DIGITS = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")


def _number(rng, reading: str, value: float, approx: bool = False) -> tuple[str, float, str]:
    """(the number as written, its value, how): digits ('40', '-4', '.65'), words ('forty', 'minus four', 'zero
    point six five', 'point six five'), 'minus 4', a half as '22½', or 'below' for a negative temperature near which
    (approx) to be written 'N degrees below zero'."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    u = rng.uniform()
    if reading == "ndvi":
        if 0 <= v < 1 and txt.startswith("0.") and u < 0.4:
            digits = " ".join(_NDVI_DIGITS[int(d)] for d in txt[2:])
            return ("zero point " if u < 0.2 else "point ") + digits, v, "words"
        if u < 0.65 and txt.startswith("0."):
            return txt[1:], v, "digits"
        return txt, v, "digits"
    if reading not in ("temperature_c", "humidity_pct"):
        return txt, v, "digits"
    whole, frac = int(abs(v)), abs(v) - int(abs(v))
    if v == int(v):
        if v < 0 and reading == "temperature_c" and approx and rng.uniform() < 0.3:  # '4 degrees below zero'
            return (number_words(whole) if rng.uniform() < 0.4 else str(whole)), v, "below"
        if u < 0.5 and abs(v) < 1000:
            if u < 0.3:
                return number_words(int(v)), v, "words"
            if v < 0:
                return f"minus {whole}", v, "digits"
    elif v > 0 and frac == 0.5 and u < 0.5:
        return f"{whole}½", v, "digits"
    return txt, v, "digits"


def _unit(rng, reading: str, how: str) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        if how == "below":
            return " degrees", "c"
        if how == "words":
            return _pick(rng, (" degrees", " degrees C", " degrees Celsius")), "c"
        return _pick(rng, (" °C", "°C", " degrees C", " Celsius")), "c"
    if reading == "humidity_pct":
        if how == "words":
            return _pick(rng, (" per cent", " percent")), "%"
        return _pick(rng, ("%", " per cent", " percent", "% humidity")), "%"
    return "", ""


def render_sensor_x(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('frostiest', 'leafiest', 'most parched') or a tail ('whose
    temperature ranks highest', 'that trails every other on NDVI'); thresholds after the noun ('that tops 60 °C',
    'whose humidity goes no further than forty per cent', 'with an NDVI that never dips under .65', 'where the
    temperature is in the region of 4 degrees below zero', '[humidity staying shy of 22½%]')."""
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
    frames = ("whose", "where", "witha", "square") if named else ("that", "that", "whose", "where", "witha", "square")
    frame = _pick(rng, frames)
    num = f"{n}{unit} below zero" if how == "below" else n + unit
    written = SensorConstraint(rd, c.comparator, value, code)
    finite = _pick(rng, _FINITE[c.comparator]).format(n=num)
    if frame == "that":
        return "", "that " + finite, written
    if frame == "whose":
        return "", f"whose {name} {finite}", written
    if frame == "where":
        return "", f"where the {name} {finite}", written
    if frame == "witha":
        article = "an" if name == "NDVI" or name[:1] in "aeiou" else "a"
        return "", f"with {article} {name} that {finite}", written
    return "", f"[{name} " + _pick(rng, _PARTICIPLE[c.comparator]).format(n=num) + "]", written


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_x(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'plotted at x 3.5 and y 2', '(grid x 3.5, grid y
    2)', 'at x 3.5 / y 2', 'at the point (3.5, 2) on the plan'."""
    return _pick(rng, (f"plotted at x {x} and y {y}", f"(grid x {x}, grid y {y})", f"at x {x} / y {y}",
                       f"at the point ({x}, {y}) on the plan"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _sep(res: list[str]) -> str:
    return ";" if any("," in r for r in res) else ","


def _listed(rng, res: list[str]) -> str:
    """Goals in a running sentence: commas, or semicolons where a goal has commas of its own."""
    if any("," in r for r in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


_SLOTS = ("Dawn", "Early morning", "Mid-morning", "Late morning", "Midday", "Early afternoon", "Mid-afternoon",
          "Late afternoon", "Evening", "Late evening")
_FORECAST_MOVES = ("moving east through the morning to", "then a band of activity reaching", "drifting on later to",
                   "pushing through towards")
_GREETINGS = ("Good evening.", "Good morning, and here's the forecast.", "Hello again.")


def _forecast(rng, res: list[str], order: str) -> str:
    """A weather forecaster: a broadcast script or a spoken forecast."""
    if len(res) == 1:
        return _pick(rng, (f"And now the outlook for the robot: one settled spell only, centred over {res[0]}. "
                           "Nothing else on the charts.",
                           f"Tonight's forecast is a simple one – a single bright patch over {res[0]}, and that's "
                           "your lot. Back to the studio."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            slots = list(_SLOTS[: min(n - 1, len(_SLOTS))]) + ["Overnight"]
            lines = ["WEATHER SCRIPT – the robot's round", f"{slots[0]}: starting off over {res[0]}"]
            for i, r in enumerate(res[1:-1]):
                lines.append(f"{slots[i + 1] if i + 1 < len(slots) - 1 else 'Later'}: "
                             f"{_pick(rng, _FORECAST_MOVES)} {r}")
            lines.append(f"{slots[-1]}: clearing at last to {res[-1]}")
            lines.append("The system tracks through strictly in that sequence – no skipping ahead on the chart.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"{_pick(rng, _GREETINGS)} For the robot's round, things get going first over {res[0]}"
        s += "".join(f"{sep} {_pick(rng, _FORECAST_MOVES)} {r}" for r in res[1:-1])
        return s + (f"{sep} and by nightfall it all settles over {res[-1]}. It tracks through in exactly that "
                    "sequence, one region after the next.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"~ {r}" for r in res)
        return (f"...and now the outlook. Scattered bright spells are expected over {w} spots:\n{body}\nThese could "
                "turn up in any order at all through the day – the charts can't say which comes first.")
    return (f"And now the outlook: sunny intervals for {_listed(rng, res)}, {w} spots in all, arriving in no set "
            "sequence – take them however the day unfolds.")


_SHOWS = ("Things Left Where They Were", "Domestic Interiors", "The Quiet House", "Objects at Rest")
_NOTES = ("Provenance: the house collection.", "On loan for this showing.", "Provenance unrecorded.",
          "Recently acquired.", "On long-term loan from a private lender.")


def _curator(rng, res: list[str], order: str) -> str:
    """A museum curator: an exhibition catalogue with numbered exhibits, or a curator's note."""
    if len(res) == 1:
        return _pick(rng, (f"Single-work display. On loan for this showing only: {res[0]}. Nothing else is on view.",
                           f"Catalogue entry, sole exhibit: {res[0]}. Provenance: the house collection."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"EXHIBITION CATALOGUE – {_pick(rng, _SHOWS)}",
                     "The route is numbered; please view the works in catalogue order."]
            lines += [f"Exhibit {i + 1}. {_cap(r)}. {_pick(rng, _NOTES)}" for i, r in enumerate(res)]
            lines.append("Visitors are asked to follow the numbered sequence, exhibit by exhibit.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Curator's note. The visit begins with {res[0]}"
        s += "".join(f"{sep} proceeds to {r}" for r in res[1:-1])
        return s + (f"{sep} and closes on {res[-1]}. The works are hung as a narrative, so they must be seen in the "
                    "order described.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"▪ {r}" for r in res)
        return f"SALON HANG – unnumbered works ({w})\n{body}\nThere is no set route: browse them in any order you please."
    return (f"Curator's note: this display brings together {_listed(rng, res)}. There is no prescribed "
            "route through the display – wander among them as you please.")


_WAYPOINTS = ("Alpha", "Bravo", "Charlie", "Delta", "Echo", "Foxtrot", "Golf", "Hotel", "India")


def _expedition(rng, res: list[str], order: str) -> str:
    """A sailor's or mountaineer's expedition log with waypoints."""
    if len(res) == 1:
        return _pick(rng, (f"Log entry. One objective only: summit push to {res[0]}. Then stand down.",
                           f"Short day out – a single waypoint, {res[0]}, and no further."))
    n = len(res)
    day = number_words(int(rng.integers(2, 12)))
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"EXPEDITION LOG – day {day}"]
            for i, r in enumerate(res[:-1]):
                name = _WAYPOINTS[i] if i < len(_WAYPOINTS) else f"{_WAYPOINTS[-1]}-{i}"
                flavour = " (steady bearing)" if i and rng.uniform() < 0.4 else ""
                lines.append(f"Waypoint {name}{flavour}: {r}")
            lines.append(f"Summit push: {res[-1]}")
            lines.append("Waypoints to be made good in sequence, Alpha onward – no short cuts across the ridge.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Log, day {day}. Broke camp at first light and made for {res[0]}"
        s += "".join(f"{sep} {_pick(rng, ('took a fresh bearing for', 'pressed on to', 'crossed over to'))} {r}"
                     for r in res[1:-1])
        return s + f"{sep} and made the summit push to {res[-1]}. Route held leg by leg, in the order planned."
    if rng.uniform() < 0.5:
        body = "\n".join(f"◦ {r}" for r in res)
        return (f"BASE CAMP – caches to check ({number_words(n)})\n{body}\nCaches can be visited in any order the "
                "weather allows.")
    return (f"Base camp notes, day {day}: caches lie at {_listed(rng, res)}. No fixed route between them – take them "
            "in whichever order the conditions favour.")


_COUPLETS = ((", without delay,", ", come what may;"), (", at morning light,", ", till fall of night;"),
             (", at a steady tread,", ", as I have said;"), (", and do not stray,", ", along the way;"),
             (", all care and grace,", ", and find its place;"))
# A closing line for a goal left without its rhyme: it rhymes with the second line of the goal's couplet.
_CLOSERS = ("and that is all I have to say.", "and all will be right.", "and nothing more said.",
            "and that is all I have to say.", "and leave no trace.")
_LEADS = ("then on to", "next seek out", "and after, find", "then wander to", "then call at")


def _poet(rng, res: list[str], order: str) -> str:
    """A poet: rhyming couplets (one goal a line) or a limerick."""
    if len(res) == 1:
        return _pick(rng, (f"A robot, both tidy and keen,\nwas asked just to go and be seen\nat {res[0]} – no more,\n"
                           "no errand, no chore;\njust the single, the sole, the serene.",
                           f"Just go to {res[0]} and there remain –\nthat's all I ask in this refrain."))
    n = len(res)
    start = int(rng.integers(len(_COUPLETS)))
    ends = [_COUPLETS[(start + i // 2) % len(_COUPLETS)][i % 2] for i in range(n)]
    closer = _CLOSERS[(start + (n - 1) // 2) % len(_COUPLETS)]
    if order == "strict":
        lines = []
        for i, r in enumerate(res):
            lead = "First go to" if i == 0 else "At last, arrive at" if i == n - 1 else _pick(rng, _LEADS)
            lines.append(f"{_cap(lead)} {r}{ends[i]}")
        if n % 2:
            lines.append(closer)
        lines[-1] = lines[-1].rstrip(",;.") + "."
        lines += ["Keep to the order of my rhyme:", "each line in turn, none out of time."]
        return "\n".join(lines)
    if rng.uniform() < 0.5:
        lines = ["In any order, as you please,", "go visit each of these with ease:"]
        lines += [f"{_pick(rng, ('Visit', 'Seek', 'Find'))} {r}{ends[i]}" for i, r in enumerate(res)]
        if n % 2:
            lines.append(closer)
        lines[-1] = lines[-1].rstrip(",;.") + "."
        lines += ["No line need come before the rest –", "go however you think best."]
        return "\n".join(lines)
    return (f"Go find {_listed(rng, res)} –\nno line need come before the rest;\nin any order, as you please:"
            "\nthe verse is loose, so take your ease.")


def render_instruction_x(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a weather forecaster, a museum curator, an
    expedition log, a poet). Goals stay in visiting order; strict texts say the order is fixed ('strictly in that
    sequence', 'one region after the next', 'catalogue order', 'exhibit by exhibit', 'in the order described',
    'made good in sequence', 'leg by leg, in the order planned', 'keep to the order of my rhyme'), free ones say it
    is open ('in any order', 'no set sequence', 'no set route', 'no prescribed route', 'no fixed route', 'whichever
    order', 'no line need come before the rest')."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(4))
    return (_forecast, _curator, _expedition, _poet)[who](rng, res, order)
