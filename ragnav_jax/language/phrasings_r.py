"""Held-out phrasings of set R: goal, sensor, coordinate and instruction templates for the `unseen_r` split.

Written by an author who never read the parser (nor its lexicon, tagger, readings, agreement or grounding code,
nor the evaluation code), with only the interface of the earlier template sets in view. Same four functions,
arguments and meanings as the other template sets. The style is four people who send a home robot round a house
in the layout and words of their own trade, or in a hurry:

- a pilot filing a flight plan or calling it over the radio: "FLIGHT PLAN - callsign SPARROW", phonetic waypoints
  ("WPT ALPHA  the ...", "WPT BRAVO  the ..."), "Sparrow, cleared to depart. Proceed direct to ..., then track to
  ..., and land at .... Over."; a fixed order as "route as filed: fly the waypoints in sequence, no direct-to",
  "sequence as filed, no shortcuts"; a free one as "sequence at pilot's discretion", "direct routing approved
  between all of them, take them however you like";
- a wedding planner's running order: "RUNNING ORDER - the Okafor & Lindqvist wedding", "First thing: ... / Once
  that's done: ... / Last thing before the speeches: ...", times in words ("At quarter past nine, ..."), a
  sign-off with a heart; fixed as "keep to this running order exactly", "the photographer is timing everything
  off it, so nothing gets swapped round"; free as "these can slot in wherever suits", "whichever you get to
  first is fine, none of it moves the schedule";
- a lawyer's drafting: "SCHEDULE 1 - LOCATIONS TO BE ATTENDED", defined terms ("'First Location' means the ...;
  'Second Location' means the ..."), "IT IS HEREBY AGREED that the Robot shall proceed to ..., whereupon it shall
  proceed to ..."; fixed as "in ascending order of designation", "in that order and not otherwise", "time and
  sequence being of the essence"; free as "in such order as the Robot may in its absolute discretion determine",
  "the order of attendance shall not be material", "in any order whatsoever";
- a hurried phone call, transcribed: "[call transcript]", fillers, false starts and self-corrections whose last
  word stands ("the te- the teal bean bag", "the lamp - no, sorry - the lamp over by the desk", "then the sofa -
  no wait, hang on, the lamp first, then the sofa"), "cheers, bye"; fixed as "in that order, yeah? that exact
  order", "same order I said it"; free as "any old order", "order-wise I'm not bothered", "mix and match".

Goals: attributes before the noun, as "(look for: teal, corduroy)", "- you'll know it, it's teal and corduroy -"
or ", such bean bag being teal and corduroy,"; states before the noun ("the switched-on lamp"), as "in its
switched-on state", ", which you'll find switched on," or "(switched on as we speak)"; the room as "in the X",
"within the X", "along in the X" or "situate in the X", always before any relation; relations in new words ("a
short hop from", "no distance at all from", "cheek by jowl with", "shoulder to shoulder with", "parked beside",
"drawn up beside", "over by", "along by", "balanced on", "propped on", "sheltered under", "slotted under", "fixed
above", "suspended above", "stashed in", "kept inside", "accompanied by", "teamed with", "kept company by", "in the
room that's home to", "in the room containing", "sharing four walls with", "planted in front of", "round behind",
"lurking behind", "across the way from", "face to face with", "over to the left of", "leftward of"); an anchor with
relations of its own repeats its noun between dashes ("the credenza - the credenza that's accompanied by the
record player -") or takes "whose spot is" / "which has ... with it" between commas. Readings: "that's cleared",
"that's tipped over", "running higher than", "whose reading beats", "that outstrips", "that doesn't dip below",
"that meets or beats", "at ... or past it", "that's not made it to", "that comes in under", "that trails", "that sits
lower than", "that stays at or under", "held to ... or under", "within a limit of", "whose reading doesn't break",
"hovering at", "at a rough", "reading pretty much", "at an estimated", "near as makes no odds"; units "°C",
"degrees", "degrees Celsius", "C", "%", "percent", "per cent", "percent RH"; numbers as digits, decimals, ".6",
words and "minus"; superlatives "the highest-temperature", "the lowest-NDVI", "the perkiest", "that comes top on
humidity", "with the lowest NDVI in the line-up", "that beats the rest on temperature", "that trails the rest on
NDVI". Coordinates: "at x co-ordinate 3.5, y co-ordinate 2", "at position <3.5, 2>", "3.5 metres along x and 2
metres along y", "at the spot marked x 3.5, y 2", "at plan position 3.5 E / 2 N", sometimes in brackets; always x
then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.phrasings import number_words
from ragnav_jax.language.phrasings_dev8 import is_plural, split_attributes
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Relations and anchors

# Every wording reads both after a noun ("the lamp parked beside the sofa") and after "that's" ("the lamp that's
# parked beside the sofa").
REL_WORDS = {
    "near": ("near", "a short hop from", "no distance at all from", "only a short way from"),
    "next_to": ("next to", "directly next to", "cheek by jowl with", "shoulder to shoulder with"),
    "beside": ("beside", "parked beside", "drawn up beside", "lined up beside"),
    "by": ("by", "over by", "along by", "parked by"),
    "on": ("on", "balanced on", "propped on", "standing on"),
    "under": ("under", "sheltered under", "slotted under", "lurking under"),
    "above": ("above", "fixed above", "suspended above", "directly above"),
    "in": ("in", "stashed in", "sat in", "kept inside"),
    "with": ("with", "accompanied by", "teamed with", "kept company by"),
    "in_room_with": ("in the same room as", "in the room that's home to", "in the room containing",
                     "sharing four walls with"),
    "in_front_of": ("in front of", "right in front of", "parked in front of", "planted in front of"),
    "behind": ("behind", "round behind", "away behind", "lurking behind"),
    "opposite": ("opposite", "directly opposite", "across the way from", "face to face with"),
    "left_of": ("to the left of", "over to the left of", "to the immediate left of", "leftward of"),
    "right_of": ("to the right of", "over to the right of", "to the immediate right of", "rightward of"),
}


def _rel(rng, r: Relation) -> str:
    return _pick(rng, REL_WORDS[r.type])


def _states_before(states: list[str]) -> str:
    return " ".join(s.replace(" ", "-") for s in states)


def _anchor(rng, t: Target, last: bool, depth: int = 0) -> str:
    """An anchor: 'the switched-on lamp', 'the lamp (found open)', and its own relations either between dashes with
    the noun repeated ('the credenza - the credenza that's accompanied by the record player -') or between commas
    ('the credenza, whose spot is by the harp,', 'the desk, which has the monitor with it,'). A closing anchor
    (`last`) drops its closing mark; deeper anchors use brackets so that the marks never nest."""
    _, states = split_attributes(t)
    if states and (t.relations or rng.uniform() < 0.65):
        s = f"the {_states_before(states)} {t.phrase}"
    elif states:
        s = f"the {t.phrase} (found {' and '.join(states)})"
    else:
        s = f"the {t.phrase}"
    if not t.relations:
        return s
    plural = is_plural(t.head)
    if depth > 0:  # inside a clause already: brackets
        inner = " and ".join(f"{_rel(rng, r)} {_anchor(rng, r.anchor, False, depth + 1)}" for r in t.relations)
        return f"{s} ({'the ones' if plural else 'the one'} {inner})"
    if rng.uniform() < 0.5:
        inner = " and ".join(f"{_rel(rng, r)} {_anchor(rng, r.anchor, False, depth + 1)}" for r in t.relations)
        be = "that are" if plural else "that's"
        return f"{s} — the {t.head} {be} {inner}" + ("" if last else " —")
    spots = [r for r in t.relations if r.type != "with"]
    withs = [r for r in t.relations if r.type == "with"]
    clauses = []
    if spots:
        lead = _pick(rng, ("whose spot is", "whose place is")) if not plural else "whose spot is"
        clauses.append(lead + " " + " and ".join(f"{_rel(rng, r)} {_anchor(rng, r.anchor, False, depth + 1)}"
                                                 for r in spots))
    for r in withs:
        clauses.append(f"which {'have' if plural else 'has'} {_anchor(rng, r.anchor, False, depth + 1)} with "
                       f"{'them' if plural else 'it'}")
    return f"{s}, " + " and ".join(clauses) + ("" if last else ",")


def _relations(rng, t: Target) -> str:
    n = len(t.relations)
    parts = [f"{_rel(rng, r)} {_anchor(rng, r.anchor, i == n - 1)}" for i, r in enumerate(t.relations)]
    out = parts[0] if parts else ""
    for p in parts[1:]:
        join = _pick(rng, (" and ", " and also ", ", as well as "))
        out += (" " + join.lstrip(", ") if out.endswith(("—", ",")) else join) + p
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS = ("in the {}", "in the {}", "within the {}", "along in the {}", "situate in the {}")


def render_goal_r(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set R writes it: 'the teal corduroy bean bag along in the nursery', 'the bean bag (look for: teal,
    corduroy) within the nursery', 'the toy chest in its open state', 'the lamp, which you'll find switched on,',
    'the highest-temperature kiln situate in the craft room', 'the guitar at position <3.5, 2>', 'the lamp
    cheek by jowl with the credenza - the credenza that's accompanied by the record player'. The room comes before
    any relation; relations come last."""
    t = sg.target
    pre, states = split_attributes(t)
    plural = is_plural(t.head)
    head_words = t.phrase[len(t.phrase) - len(t.head):] if t.phrase.endswith(t.head) else t.head
    attr_style = "before"
    if pre and not prefix:
        attr_style = _pick(rng, ("before", "before", "before", "look", "know", "such"))
    state_style = None
    if states:
        opts = ["in_its", "find", "as_we_speak"]
        if len(states) == 1 and attr_style in ("before", "look"):
            opts += ["before", "before"]
        state_style = _pick(rng, opts)
    out = "the " + (prefix + " " if prefix else "")
    if state_style == "before":
        out += _states_before(states) + " "
    out += t.phrase if attr_style == "before" else head_words
    attrs = " and ".join(pre)
    if attr_style == "look":
        out += f" (look for: {', '.join(pre)})"
    elif attr_style == "know":
        it, its = ("them", "they're") if plural else ("it", "it's")
        out += f" — you'll know {it}, {its} {attrs} —"
    elif attr_style == "such":
        out += f", such {head_words} being {attrs},"
    st = " and ".join(states)
    if state_style == "in_its":
        out += f" in {'their' if plural else 'its'} {' and '.join(x.replace(' ', '-') for x in states)} state"
    elif state_style == "find":
        out += f", which you'll find {st},"
    elif state_style == "as_we_speak":
        out += f" ({st} as we speak)"
    if hint:
        out += " " + (f"({hint[3:]})" if hint.startswith("at ") and rng.uniform() < 0.3 else hint)
    room = _pick(rng, _ROOMS).format(sg.room) if sg.room else ""
    if tail:
        if room and rng.uniform() < 0.5:
            out += f" {room} {tail}"
        else:
            out += f" {tail}" + (f", {room}" if room else "")
    elif room:
        out += " " + room
    if t.relations:
        out += " " + _relations(rng, t)
    out = " ".join(out.replace(",,", ",").replace(", ,", ",").split())
    while out.endswith((",", "—")):
        out = out[:-1].rstrip()
    return out


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

_CMP = {
    "gt": ("that's cleared {n}", "that's tipped over {n}", "running higher than {n}", "whose reading beats {n}",
           "that outstrips {n}"),
    "ge": ("that doesn't dip below {n}", "that meets or beats {n}", "at {n} or past it"),
    "lt": ("that's not made it to {n}", "that comes in under {n}", "that trails {n}", "that sits lower than {n}"),
    "le": ("that stays at or under {n}", "held to {n} or under", "within a limit of {n}",
           "whose reading doesn't break {n}"),
    "approx": ("hovering at {n}", "at a rough {n}", "reading pretty much {n}", "at an estimated {n}",
               "at {n}, near as makes no odds"),
}
_NAMED = {"temperature_c": ("with a temperature", "temperature-wise"), "humidity_pct": ("with the humidity",
          "humidity-wise"), "ndvi": ("with an NDVI", "NDVI-wise")}
_T_UNITS = ("°C", " °C", " C", " degrees", " degrees Celsius")
_H_UNITS = ("%", " %", " percent", " per cent", " percent RH")
_SUPER_ADJ = {
    ("temperature_c", "max"): ("warmest", "hottest", "highest-temperature"),
    ("temperature_c", "min"): ("coolest", "coldest", "lowest-temperature"),
    ("ndvi", "max"): ("healthiest", "greenest", "highest-NDVI", "perkiest"),
    ("ndvi", "min"): ("least healthy", "lowest-NDVI"),
    ("humidity_pct", "max"): ("most humid", "dampest", "highest-humidity"),
    ("humidity_pct", "min"): ("driest", "least humid", "lowest-humidity"),
}
_SUPER_TAIL = {
    "max": ("that comes top on {r}", "with the highest {r} in the line-up", "that beats the rest on {r}"),
    "min": ("that comes bottom on {r}", "with the lowest {r} in the line-up", "that trails the rest on {r}"),
}
_R_NAME = {"temperature_c": "temperature", "humidity_pct": "humidity", "ndvi": "NDVI"}


def _number(rng, reading: str, value: float) -> tuple[str, float]:
    """(the number as written, its value): digits, a decimal, '.6', words for whole numbers, 'minus' for negatives."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    if reading == "ndvi":
        u = rng.uniform()
        if u < 0.3:
            return f"{v:.2f}", v
        if u < 0.5 and txt.startswith("0."):
            return txt[1:], v
        return txt, v
    if v == int(v):
        u = rng.uniform()
        if u < 0.2 and abs(v) < 100:
            return number_words(int(v)), v
        if u < 0.3:
            return f"{v:.1f}", v
        if v < 0 and u < 0.45:
            return f"minus {txt[1:]}", v
    return txt, v


def render_sensor_r(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('highest-temperature', 'perkiest', 'lowest-humidity') or a tail
    ('that comes top on NDVI', 'with the lowest temperature in the line-up', 'that trails the rest on humidity');
    thresholds after the noun ('that's tipped over 60 °C', 'that stays at or under 40 per cent', 'with an NDVI
    hovering at .65', 'temperature-wise, at a rough twenty-one degrees')."""
    rd = c.reading
    name = _R_NAME.get(rd, rd.replace("_", " "))
    if c.is_superlative:
        adj = _SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, _SUPER_TAIL[c.comparator]).format(r=name), c
    n, value = _number(rng, rd, c.value)
    form = _pick(rng, _CMP[c.comparator])
    if rd == "ndvi":
        lead = _pick(rng, _NAMED[rd])
        if lead.endswith("-wise"):
            return "", f"{lead}, {form.format(n=n)}", SensorConstraint(rd, c.comparator, value, "")
        return "", f"{lead} {form.format(n=n)}", SensorConstraint(rd, c.comparator, value, "")
    if rd == "temperature_c":
        if rng.uniform() < 0.2:  # the reading named: the unit may go
            lead = _pick(rng, _NAMED[rd])
            sep = ", " if lead.endswith("-wise") else " "
            return "", f"{lead}{sep}{form.format(n=n)}", SensorConstraint(rd, c.comparator, value, "")
        u = _pick(rng, (" degrees", " degrees Celsius")) if n[-1].isalpha() else _pick(rng, _T_UNITS)
        return "", form.format(n=n + u), SensorConstraint(rd, c.comparator, value, "c")
    if rd == "humidity_pct":
        u = _pick(rng, (" percent", " per cent")) if n[-1].isalpha() else _pick(rng, _H_UNITS)
        lead = _pick(rng, _NAMED[rd] + ("",))
        if not lead:  # humidity only from the unit: say "humidity" after it (RH says it already)
            n_u = n + u + ("" if u.endswith("RH") else " humidity")
            return "", form.format(n=n_u), SensorConstraint(rd, c.comparator, value, "%")
        sep = ", " if lead.endswith("-wise") else " "
        return "", f"{lead}{sep}{form.format(n=n + u)}", SensorConstraint(rd, c.comparator, value, "%")
    text = f"with a {name} reading {form.format(n=n)}"
    return "", text, SensorConstraint(rd, c.comparator, value, "")


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_r(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at x co-ordinate 3.5, y co-ordinate 2', 'at position
    <3.5, 2>', 'at the spot marked x 3.5, y 2', and, never for a negative number, '3.5 metres along x and 2 metres
    along y' and 'at plan position 3.5 E / 2 N'."""
    forms = [f"at x co-ordinate {x}, y co-ordinate {y}", f"at position ⟨{x}, {y}⟩", f"at the spot marked x {x}, y {y}"]
    if not x.startswith("-") and not y.startswith("-"):
        forms += [f"{x} metres along x and {y} metres along y", f"at plan position {x} E / {y} N"]
    return _pick(rng, forms)


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _listed(rng, res: list[str]) -> str:
    """Goals in a running sentence: commas, or semicolons where a goal has commas of its own."""
    if any("," in r or "—" in r for r in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


_PHONETIC = ("ALPHA", "BRAVO", "CHARLIE", "DELTA", "ECHO", "FOXTROT", "GOLF", "HOTEL")
_CALLSIGNS = ("SPARROW", "KESTREL", "NIMBUS", "MAGPIE")


def _pilot(rng, res: list[str], order: str) -> str:
    """A pilot's flight plan, or the same route called over the radio."""
    cs = _pick(rng, _CALLSIGNS)
    call = cs.capitalize()
    if len(res) == 1:
        return _pick(rng, (f"{call}, cleared direct to {res[0]}. Report on arrival. Over.",
                           f"FLIGHT PLAN — callsign {cs}\nDestination: {res[0]}\nNo intermediate waypoints."))
    wpts = _PHONETIC[: len(res)]
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            lines = "\n".join(f"WPT {w}  {r}" for w, r in zip(wpts, res))
            foot = _pick(rng, ("Route as filed: fly the waypoints in sequence, no direct-to.",
                               "Waypoints to be flown in the sequence filed, " + " – ".join(wpts) + "."))
            return f"FLIGHT PLAN — callsign {cs}\n{lines}\n{foot}"
        if k == 1:
            s = f"{call}, cleared to depart. Proceed direct to {res[0]}"
            s += "".join(f", then track to {r}" for r in res[1:-1])
            s += f", and land at {res[-1]}. Sequence as filed, no shortcuts. Over."
            return s
        s = f"Pre-flight, reading back: first leg to {res[0]}"
        s += "".join(f"; next leg, {r}" for r in res[1:-1])
        s += f"; final leg, {res[-1]}. Legs flown in that sequence, no shortcuts. {call}."
        return s
    k = int(rng.integers(3))
    if k == 0:
        lines = "\n".join(f"WPT {w}  {r}" for w, r in zip(wpts, res))
        return f"FLIGHT PLAN — callsign {cs}\n{lines}\nSequence at pilot's discretion."
    if k == 1:
        return (f"{call}, you're cleared to call at {_listed(rng, res)}. Direct routing approved between all of "
                "them, take them however you like. Over and out.")
    return (f"Tower to {call}: points to visit are {_listed(rng, res)}. Sequence at pilot's discretion, "
            "report when all are done.")


_COUPLES = ("Okafor & Lindqvist", "Hartley–Mbeki", "Delacroix / Nakamura", "Finnegan & Roe")
_PLANNERS = ("Priya", "Tamsin", "Gabriel", "Ines")
_TIMES = ("At nine o'clock", "At quarter past nine", "At half past nine", "At quarter to ten", "At ten o'clock")


def _wedding(rng, res: list[str], order: str) -> str:
    """A wedding planner's running order for the day, with a sign-off."""
    couple, planner = _pick(rng, _COUPLES), _pick(rng, _PLANNERS)
    sign = _pick(rng, (f"Thanks a million — {planner} ♥", f"Love, {planner} (your planner)", f"xx {planner}"))
    if len(res) == 1:
        return _pick(rng, (f"Last-minute job before the ceremony, lovely: pop along to {res[0]}. {sign}",
                           f"RUNNING ORDER — the {couple} wedding\nOnly item: {res[0]}\n{sign}"))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            lines = [f"First thing: {res[0]}"] + [f"Once that's done: {r}" for r in res[1:-1]]
            lines.append(f"Last thing before the speeches: {res[-1]}")
            return (f"RUNNING ORDER — the {couple} wedding\n" + "\n".join(lines)
                    + f"\nPlease keep to this running order exactly.\n{sign}")
        if k == 1:
            parts = [f"{_TIMES[i]}, {r}." for i, r in enumerate(res)]
            return ("Right, here's the plan for the morning. " + " ".join(parts)
                    + " The photographer is timing everything off it, so nothing gets swapped round. " + sign)
        s = f"Morning! Could you start with {res[0]}"
        s += "".join(f", move on to {r}" for r in res[1:-1])
        s += f" and wrap things up with {res[-1]}? Keep to this running order exactly, it's all been timed. {sign}"
        return s
    k = int(rng.integers(3))
    if k == 0:
        lines = "\n".join(f"♡ {_cap(r)}" for r in res)
        return (f"Bits and bobs for the {couple} wedding — these can slot in wherever suits:\n{lines}\n{sign}")
    if k == 1:
        return (f"Could you also have a quick look at {_listed(rng, res)} before the guests arrive? "
                f"Whichever you get to first is fine, none of it moves the schedule. {sign}")
    lines = "\n".join(f"– {r}" for r in res)
    return f"Floating jobs (no slot in the running order, do them whenever suits):\n{lines}\n{sign}"


_ORDINALS = ("First", "Second", "Third", "Fourth", "Fifth", "Sixth", "Seventh", "Eighth")


def _legal(rng, res: list[str], order: str) -> str:
    """A lawyer's drafting: a schedule of defined locations, or one long operative clause."""
    if len(res) == 1:
        return _pick(rng, (f"The Robot shall attend {res[0]} forthwith.",
                           f"IT IS HEREBY AGREED that the Robot shall attend {res[0]} without delay."))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            defs = ";\n".join(f"“{_ORDINALS[i]} Location” means {r}" for i, r in enumerate(res))
            return ("SCHEDULE 1 — LOCATIONS TO BE ATTENDED\nIn this Schedule:\n" + defs + ".\n"
                    "The Robot shall attend each Location in ascending order of designation, time and sequence "
                    "being of the essence.")
        if k == 1:
            s = f"IT IS HEREBY AGREED that the Robot shall proceed to {res[0]}"
            s += "".join(f", whereupon it shall proceed to {r}" for r in res[1:])
            return s + ", in that order and not otherwise."
        s = f"The Robot shall attend, in the order in which they are set out below and in no other order, {res[0]}"
        s += "".join(f"; thereupon {r}" for r in res[1:-1])
        return s + f"; and lastly {res[-1]}."
    k = int(rng.integers(3))
    if k == 0:
        return (f"The Robot shall, in such order as it may in its absolute discretion determine, attend each of "
                f"the following: {'; '.join(res[:-1])}; and {res[-1]}. For the avoidance of doubt, the order of "
                "attendance shall not be material.")
    if k == 1:
        return (f"“Locations” means, collectively, {_listed(rng, res)}, all of which may be attended in any order "
                "whatsoever.")
    lines = "\n".join(f"— {r};" for r in res)
    return ("SCHEDULE 2 — LOCATIONS (ORDER NOT MATERIAL)\nThe Robot shall attend the following, in such order as it "
            f"may in its absolute discretion determine:\n{lines[:-1]}.")


_FILLERS = ("um, ", "er, ", "like, ", "")
_HELLO = ("[call transcript] Hiya, it's me — sorry, bad signal. ", "[call transcript] Hey, quick one, I can't stay on "
          "long. ", "[call transcript] Hi hi, it's me, I'm running late so listen. ")
_BYE = (" Cheers, bye!", " Ta, love you, bye.", " Right, gotta go, bye bye.")


def _stammer(rng, goal: str) -> str:
    """The goal with a false start before it: 'the te— the teal bean bag', 'the lamp — no, sorry — the lamp over by
    the desk'. What stands is the whole goal, said last."""
    words = goal.split()
    if len(words) < 2 or words[0] != "the" or not words[1][:1].isalpha():
        return goal
    if rng.uniform() < 0.5 or len(words) < 3:
        w = words[1].rstrip(",;:")
        return f"the {w[: max(2, len(w) // 2)]}— {goal}"
    return f"the {words[1].rstrip(',;:')} — no, sorry — {goal}"


def _phone(rng, res: list[str], order: str) -> str:
    """A hurried phone call as transcribed: false starts and corrections, where the last thing said stands."""
    hi, bye = _pick(rng, _HELLO), _pick(rng, _BYE)
    say = [(_stammer(rng, r) if rng.uniform() < 0.35 else r) for r in res]
    if len(res) == 1:
        return f"{hi}Can you go to {_pick(rng, _FILLERS)}{say[0]}?{bye}"
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:  # jumps ahead, takes it back
            j = int(rng.integers(len(res) - 1))
            s = f"{hi}So go to " + "".join(f"{say[i]}, then " for i in range(j))
            s += (f"{res[j + 1]} — no wait, hang on, {res[j]} first, then {say[j + 1]}"
                  + "".join(f", then {r}" for r in say[j + 2:]))
            return s + f". In that order, yeah? That exact order.{bye}"
        if k == 1:
            s = f"{hi}Okay so first {say[0]}" + "".join(f", and then {_pick(rng, _FILLERS)}{r}" for r in say[1:])
            return s + f" — same order I said it, okay?{bye}"
        s = f"{hi}Start at {say[0]}" + "".join(f", after that {r}" for r in say[1:-1]) + f", and end with {say[-1]}"
        return s + f". In that order, yeah?{bye}"
    k = int(rng.integers(3))
    if k == 0:
        return f"{hi}Can you do {_listed(rng, say)}? Any old order, honestly.{bye}"
    if k == 1:
        return f"{hi}I need you to check {_listed(rng, say)} — order-wise I'm not bothered.{bye}"
    return f"{hi}List for you: {_listed(rng, say)}. Mix and match, whatever's easiest.{bye}"


def render_instruction_r(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a pilot's flight plan or radio call, a
    wedding planner's running order, a lawyer's drafting, a hurried phone call with self-corrections). Goals are
    said in visiting order (a phone call may jump ahead and take it back: 'the sofa - no wait, hang on, the lamp
    first, then the sofa'); strict texts say the order is fixed ('fly the waypoints in sequence', 'keep to this
    running order exactly', 'in that order and not otherwise', 'that exact order'), free ones say it is open
    ('sequence at pilot's discretion', 'these can slot in wherever suits', 'shall not be material', 'any old
    order')."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip("—").rstrip() for r in res]
    who = int(rng.integers(4))
    return (_pilot, _wedding, _legal, _phone)[who](rng, res, order)
