"""Held-out phrasings of set S: goal, sensor, coordinate and instruction templates for the `unseen_s` split.

Written by an author who never read the parser (nor its lexicon, tagger, readings, agreement or grounding code,
nor the evaluation code), with only the interface of the earlier template sets in view. Same four functions,
arguments and meanings as the other template sets. The style is four people who send a home robot round a house
in the layout and words of their own pastime or office:

- a parent's treasure-hunt clue sheet for a children's party: "TREASURE HUNT for Maisie's party", "Clue 1 (start
  here): ...", "Clue 3 (the treasure!): ...", "Your trail starts at ...; from there it leads to ... and the
  treasure is waiting at ..."; a fixed order as "solve the clues in order", "follow the trail clue by clue", "each
  clue only makes sense once you've cracked the one before"; a free one as "it's a scramble, not a trail", "no
  trail to follow", "collect them in any order you like";
- a local-radio travel bulletin: "Time for the travel news", "your route this morning takes you first to ...,
  then on to ..., before you come off at ...", junctions ("J2 – the ..."), "Back to the studio"; fixed as "it's a
  one-way system round there, so stick to that sequence", "traffic is flowing one way only: take the junctions in
  number order"; free as "all roads are clear, so pick your own route between them", "no hold-ups anywhere: any
  running order will do";
- a bureaucratic request form with field labels: "FORM RA-42: REQUEST FOR ROBOT ATTENDANCE", "Section A –
  Locations", "A1. ...", tick boxes ("Order of attendance: [X] as listed in Section A   [ ] at the robot's
  discretion"), "Field 3 (final location): ..."; fixed as a ticked "[X] as listed", "MANDATORY – locations are to
  be attended in field order"; free as a ticked "[X] at the robot's discretion", "NOT PRESCRIBED (no fixed order)";
- a scout leader's orienteering card: "1st Ashdown Scouts – ORIENTEERING, LINE COURSE (Otter Patrol)", "Start:
  ... / Control 1: ... / Finish: ...", "Right, Otters, gather round"; fixed as "line course: punch the controls in
  the order shown", "controls in order, mind"; free as "score event", "score orienteering: visit the controls in
  any sequence you choose and plan your own route".

Goals: attributes before the noun, as "(think teal and corduroy)" or as "matching “teal, corduroy”"; states before
the noun ("the switched-on lamp"), as ", left switched on,", "(as found: switched on)" or ", showing as switched
on,"; the room as "in the X", "in the X area" or "(zone: X)", always before any relation; relations in new words
("a stride or two from", "within arm's length of", "not a million miles from", "flush next to", "right next door
to", "elbow to elbow with", "pulled up beside", "lined up beside", "tucked in by", "waiting by", "lying on",
"placed on", "up on", "pushed under", "nestled under", "down beneath", "hung above", "directly above", "perched
above", "sitting in", "packed inside", "nested in", "sporting", "boasting", "that carries", "in the room occupied
by", "in whatever room holds", "directly in front of", "set out in front of", "directly behind", "tucked away
behind", "back behind", "directly opposite", "face-on to", "a step to the left of", "immediately right of"); an
anchor with relations of its own takes them in brackets as "(you'll find it next to the record player)" or between
commas as ", which incidentally is next to the record player,". Readings: "clocking in above", "edging over",
"has edged past", "betters", "holding at ... or higher", "sitting at ... or beyond", "has made it to ... or
beyond", "with ... as its floor", "dipping under", "running below", "hasn't cracked", "undershoots", "holding at ...
or lower", "maxing out at", "maxes out at", "has ... as its upper bound", "within a whisker of", "pretty close to",
"reading somewhere about", "sits pretty close to"; frames "whose temp's ...", "with an NDVI score ...", "that ...
on NDVI"; units "°C", "Celsius", "degrees Celsius", "degs", "%", "percent", "% relative humidity", "percent
humidity"; numbers as digits, decimals, ".6", "0.60", words and "minus"; superlatives "the most sweltering", "the
hottest-reading", "the most frigid", "the nippiest", "the most flourishing", "the most robust", "the most ailing",
"the feeblest", "the most steamed-up", "the most arid", "that wins on temperature", "with the humidity to top them
all", "whose NDVI outranks all the others", "that comes last on NDVI", "whose humidity sits lowest". Coordinates:
"where the x-line 3.5 crosses the y-line 2", "at grid reference 3.5 × 2", "(x → 3.5, y → 2)", "at the
intersection of x = 3.5 and y = 2", "at first coordinate 3.5, second coordinate 2"; always x then y.

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

REL_WORDS = {
    "near": ("near", "a stride or two from", "within arm's length of", "not a million miles from"),
    "next_to": ("next to", "flush next to", "right next door to", "elbow to elbow with"),
    "beside": ("beside", "pulled up beside", "lined up beside"),
    "by": ("by", "tucked in by", "waiting by"),
    "on": ("on", "lying on", "placed on", "up on"),
    "under": ("under", "pushed under", "nestled under", "down beneath"),
    "above": ("above", "hung above", "directly above", "perched above"),
    "in": ("in", "sitting in", "packed inside", "nested in"),
    "with": ("with", "sporting", "boasting", "that carries"),
    "in_room_with": ("in the same room as", "in the room occupied by", "in whatever room holds"),
    "in_front_of": ("in front of", "directly in front of", "set out in front of"),
    "behind": ("behind", "directly behind", "tucked away behind", "back behind"),
    "opposite": ("opposite", "directly opposite", "face-on to"),
    "left_of": ("to the left of", "a step to the left of", "immediately left of"),
    "right_of": ("to the right of", "a step to the right of", "immediately right of"),
}


def _rel_words(rng, r: Relation, plural: bool) -> str:
    w = _pick(rng, REL_WORDS[r.type])
    return "that carry" if plural and w == "that carries" else w


def _hyphen_states(states: list[str]) -> str:
    return ", ".join(s.replace(" ", "-") for s in states)


def _anchor(rng, t: Target, last: bool) -> str:
    """An anchor: 'the open credenza', 'the lamp (as found: switched off)', and its own relations in brackets
    ('the credenza (you'll find it next to the record player)') or between commas ('the shelves, which
    incidentally are above the desk,'). When the anchor closes the goal (`last`) a closing comma is dropped."""
    _, states = split_attributes(t)
    if states and (t.relations or rng.uniform() < 0.6):
        s = f"the {_hyphen_states(states)} {t.phrase}"
    elif states:
        s = f"the {t.phrase} (as found: {' and '.join(states)})"
    else:
        s = f"the {t.phrase}"
    if not t.relations:
        return s
    plural = is_plural(t.head)
    if rng.uniform() < 0.5:
        inner = " and ".join(
            f"{_pick(rng, ('with', 'sporting')) if r.type == 'with' else _rel_words(rng, r, plural)} "
            f"{_anchor(rng, r.anchor, False)}" for r in t.relations)
        return f"{s} (you'll find {'them' if plural else 'it'} {inner})"
    clauses = []
    for r in t.relations:
        if r.type == "with":
            clauses.append(f"{'have' if plural else 'has'} {_anchor(rng, r.anchor, False)}")
        else:
            clauses.append(f"{'are' if plural else 'is'} {_rel_words(rng, r, plural)} {_anchor(rng, r.anchor, False)}")
    return f"{s}, which incidentally {' and '.join(clauses)}" + ("" if last else ",")


def _relations(rng, t: Target) -> str:
    plural = is_plural(t.head)
    n = len(t.relations)
    parts = [f"{_rel_words(rng, r, plural)} {_anchor(rng, r.anchor, i == n - 1)}" for i, r in enumerate(t.relations)]
    out = parts[0] if parts else ""
    for p in parts[1:]:
        join = _pick(rng, (" and ", " and also ", ", and "))
        out += (" " + join.lstrip(", ") if out.endswith(",") else join) + p
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS = ("in the {}", "in the {}", "in the {} area", "(zone: {})")


def render_goal_s(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set S writes it: 'the teal corduroy bean bag in the nursery area', 'the bean bag (think teal and
    corduroy) (zone: nursery)', 'the toy chest, left open,', 'the most sweltering kiln in the craft room', 'the
    guitar where the x-line 3.5 crosses the y-line 2', 'the lamp flush next to the credenza (you'll find it with the
    record player)'. The room comes before any relation; relations come last."""
    t = sg.target
    pre, states = split_attributes(t)
    head_words = t.phrase[len(t.phrase) - len(t.head):] if t.phrase.endswith(t.head) else t.head
    attr_style = "before"
    if pre and not prefix:
        attr_style = _pick(rng, ("before", "before", "think", "matching"))
    state_style = None
    if states:
        opts = ["left", "found", "showing"]
        if not prefix and len(states) == 1:
            opts += ["before", "before"]
        state_style = _pick(rng, opts)
    out = "the " + (prefix + " " if prefix else "")
    if state_style == "before":
        out += _hyphen_states(states) + " "
    out += t.phrase if attr_style == "before" else head_words
    if attr_style == "think":
        out += f" (think {' and '.join(pre)})"
    elif attr_style == "matching":
        out += f" matching “{', '.join(pre)}”"
    if state_style == "left":
        out += f", left {' and '.join(states)},"
    elif state_style == "found":
        out += f" (as found: {' and '.join(states)})"
    elif state_style == "showing":
        out += f", showing as {' and '.join(states)},"
    if hint:
        out += " " + hint
    room = _pick(rng, _ROOMS).format(sg.room) if sg.room else ""
    if tail:
        if room and rng.uniform() < 0.5:
            out += f" {room}, {tail}"
        else:
            out += f" {tail}" + (f", {room}" if room[:1].isalpha() else f" {room}" if room else "")
    elif room:
        out += " " + room
    if t.relations:
        out += " " + _relations(rng, t)
    out = " ".join(out.replace(",,", ",").replace(", ,", ",").replace(", (", " (").split())
    while out.endswith(","):
        out = out[:-1].rstrip()
    return out


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

# Predicates that read after the noun, after "whose temp's" or after "with a temperature".
_PARTICIPLE = {
    "gt": ("clocking in above {n}", "edging over {n}"),
    "ge": ("holding at {n} or higher", "sitting at {n} or beyond"),
    "lt": ("dipping under {n}", "running below {n}"),
    "le": ("holding at {n} or lower", "maxing out at {n}"),
    "approx": ("within a whisker of {n}", "pretty close to {n}", "reading somewhere about {n}"),
}
# Predicates with a finite verb: after "that" or "whose temperature".
_FINITE = {
    "gt": ("betters {n}", "has edged past {n}"),
    "ge": ("has made it to {n} or beyond", "has {n} as its floor"),
    "lt": ("hasn't cracked {n}", "undershoots {n}"),
    "le": ("maxes out at {n}", "has {n} as its upper bound"),
    "approx": ("sits pretty close to {n}", "comes within a whisker of {n}"),
}
_NAMES = {"temperature_c": ("temperature", "temp"), "humidity_pct": ("humidity", "relative humidity"),
          "ndvi": ("NDVI", "NDVI score")}
_T_UNITS = ("°C", " °C", " degrees Celsius", " Celsius", " degs")
_H_UNITS = ("%", " %", " percent", " % relative humidity", " percent humidity")
_SUPER_ADJ = {
    ("temperature_c", "max"): ("warmest", "most sweltering", "hottest-reading"),
    ("temperature_c", "min"): ("coldest", "most frigid", "nippiest"),
    ("ndvi", "max"): ("healthiest", "most flourishing", "most robust"),
    ("ndvi", "min"): ("least healthy", "most ailing", "feeblest"),
    ("humidity_pct", "max"): ("most humid", "most steamed-up"),
    ("humidity_pct", "min"): ("driest", "most arid", "least humid"),
}


def _super_tails(name: str, comparator: str) -> tuple[str, ...]:
    if comparator == "max":
        return (f"that wins on {name}", f"with the {name} to top them all", f"whose {name} outranks all the others")
    return (f"that comes last on {name}", f"with the lowest {name} of any", f"whose {name} sits lowest")


def _number(rng, reading: str, value: float) -> tuple[str, float]:
    """(the number as written, its value): digits, a decimal, '.6' or '0.60', words for whole numbers, 'minus'."""
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


def _unit(rng, reading: str, n: str) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        return (_pick(rng, (" degrees Celsius", " Celsius", " degs")) if n[-1].isalpha() else _pick(rng, _T_UNITS)), "c"
    if reading == "humidity_pct":
        return (_pick(rng, (" percent", " percent humidity")) if n[-1].isalpha() else _pick(rng, _H_UNITS)), "%"
    return "", ""


def render_sensor_s(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('most sweltering', 'nippiest', 'most ailing') or a tail ('that wins
    on temperature', 'with the lowest NDVI of any', 'whose humidity sits lowest'); thresholds after the noun
    ('clocking in above 60 °C', 'whose temp's holding at 40 or higher', 'that hasn't cracked 30 percent humidity',
    'with an NDVI score within a whisker of .65', 'that betters 0.60 on NDVI')."""
    rd = c.reading
    name = _pick(rng, _NAMES[rd]) if rd in _NAMES else rd.replace("_", " ")
    if c.is_superlative:
        adj = _SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, _super_tails(name, c.comparator)), c
    n, value = _number(rng, rd, c.value)
    unit, code = _unit(rng, rd, n)
    named = rd not in ("temperature_c", "humidity_pct")  # NDVI and any other reading are always named
    frame = _pick(rng, ("whose", "with", "that") if named else ("bare", "bare", "that", "whose", "with"))
    if frame in ("whose", "with") and rd == "temperature_c" and rng.uniform() < 0.25:
        unit, code = "", ""  # the reading is named: the unit may go
    num = n + unit
    if frame == "bare":
        return "", _pick(rng, _PARTICIPLE[c.comparator]).format(n=num), SensorConstraint(rd, c.comparator, value, code)
    if frame == "that":
        text = "that " + _pick(rng, _FINITE[c.comparator]).format(n=num)
        if named:
            text += f" on {name}"
        return "", text, SensorConstraint(rd, c.comparator, value, code)
    if frame == "whose":
        if rng.uniform() < 0.5:
            text = f"whose {name}'s " + _pick(rng, _PARTICIPLE[c.comparator]).format(n=num)
        else:
            text = f"whose {name} " + _pick(rng, _FINITE[c.comparator]).format(n=num)
        return "", text, SensorConstraint(rd, c.comparator, value, code)
    art = "" if rd == "humidity_pct" else ("an " if name[:1] in "AEIOUaeiou" or name.startswith("NDVI") else "a ")
    text = f"with {art}{name} " + _pick(rng, _PARTICIPLE[c.comparator]).format(n=num)
    return "", text, SensorConstraint(rd, c.comparator, value, code)


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_s(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'where the x-line 3.5 crosses the y-line 2', 'at
    grid reference 3.5 × 2', '(x → 3.5, y → 2)', 'at the intersection of x = 3.5 and y = 2', 'at first coordinate
    3.5, second coordinate 2'."""
    return _pick(rng, (f"where the x-line {x} crosses the y-line {y}", f"at grid reference {x} × {y}",
                       f"(x → {x}, y → {y})", f"at the intersection of x = {x} and y = {y}",
                       f"at first coordinate {x}, second coordinate {y}"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _listed(rng, res: list[str]) -> str:
    """Goals in a running sentence: commas, or semicolons where a goal has commas of its own."""
    if any("," in r for r in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


_KIDS = ("Maisie", "Theo", "Priya", "Oskar", "Nell")


def _treasure(rng, res: list[str], order: str) -> str:
    """A parent's treasure-hunt clue sheet for a children's party."""
    kid = _pick(rng, _KIDS)
    if len(res) == 1:
        return _pick(rng, (f"TREASURE HUNT for {kid}'s party. Only a single clue this time: the treasure is hidden "
                           f"at {res[0]}. Happy hunting!",
                           f"Psst, treasure hunter! The prize is tucked away at {res[0]}. Off you go, and no peeking "
                           "at the answers!"))
    n = len(res)
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            lines = [f"Clue 1 (start here): {res[0]}"] + [f"Clue {i + 1}: {r}" for i, r in enumerate(res) if 0 < i < n - 1]
            lines.append(f"Clue {n} (the treasure!): {res[-1]}")
            return (f"TREASURE HUNT for {kid}'s party\n" + "\n".join(lines)
                    + "\nSolve the clues in order: each clue only makes sense once you've cracked the one before.")
        if k == 1:
            s = f"Calling all treasure hunters! Your trail starts at {res[0]}."
            s += "".join(f" From there it leads on to {r}." for r in res[1:-1])
            s += f" And the treasure is waiting at {res[-1]}. Follow the trail clue by clue – no jumping ahead!"
            return s
        s = f"Riddle sheet for {kid}'s team. First you must seek {res[0]};"
        s += "".join(f" next, hop along to {r};" for r in res[1:-1])
        return s + f" and last of all, X marks the spot at {res[-1]}. Solve the clues in order, or the riddle won't work!"
    if rng.uniform() < 0.5:
        body = "\n".join(f"• {_cap(r)}" for r in res)
        return (f"TREASURE HUNT – {kid}'s team\nGold coins have been hidden at:\n{body}\nIt's a scramble, not a trail: "
                "collect them in any order you like.")
    return (f"Treasure alert! Coins are stashed at {_listed(rng, res)}. Grab them in any order you like – no trail to "
            "follow, just find them all!")


def _radio(rng, res: list[str], order: str) -> str:
    """A local-radio travel bulletin read out for the robot."""
    if len(res) == 1:
        return _pick(rng, (f"Travel news now: just a single destination on the board for our robot listener this "
                           f"morning, {res[0]}. Drive safely, and back to the studio.",
                           f"And the travel: the robot's only trip today is out to {res[0]}. No delays reported."))
    if order == "strict":
        if rng.uniform() < 0.5:
            s = f"Time for the travel news. Robot, your route this morning takes you first to {res[0]}"
            s += "".join(f", then on to {r}" for r in res[1:-1])
            return s + (f", before you come off at {res[-1]}. It's a one-way system round there, so stick to that "
                        "sequence. Back to the studio!")
        lines = [f"J{i + 1} – {r}" for i, r in enumerate(res)]
        return ("TRAVEL BULLETIN for the robot\n" + "\n".join(lines)
                + "\nTraffic is flowing one way only: take the junctions in number order.")
    if rng.uniform() < 0.5:
        return (f"A quick round-up before the news: our robot's stops today are {_listed(rng, res)}. All roads are "
                "clear, so pick your own route between them.")
    body = "\n".join(f"– {r}" for r in res)
    return f"TRAVEL ROUND-UP\n{body}\nNo hold-ups anywhere: any running order will do."


_DEPTS = ("Facilities Office", "Household Services Unit", "Dept. of Domestic Affairs", "Estates Management")


def _form(rng, res: list[str], order: str) -> str:
    """A bureaucratic request form with field labels and tick boxes."""
    dept = _pick(rng, _DEPTS)
    if len(res) == 1:
        return _pick(rng, (f"REQUEST FOR ROBOT ATTENDANCE (Form RA)\nLocation to be attended: {res[0]}\n"
                           f"Authorised by: {dept}",
                           f"Form RA, request for attendance. Applicant: {dept}. Location: {res[0]}. "
                           "Please retain this form for your records."))
    num = int(rng.integers(10, 99))
    if rng.uniform() < 0.5:
        lines = "\n".join(f"  A{i + 1}. {r}" for i, r in enumerate(res))
        ticks = ("[X] as listed in Section A   [ ] at the robot's discretion" if order == "strict"
                 else "[ ] as listed in Section A   [X] at the robot's discretion")
        return (f"FORM RA-{num}: REQUEST FOR ROBOT ATTENDANCE\nApplicant: {dept}\nSection A – Locations\n{lines}\n"
                f"Section B – Order of attendance: {ticks}\nSection C – Signature: ________")
    if order == "strict":
        n = len(res)
        lines = [f"Field 1 (first location): {res[0]}"]
        lines += [f"Field {i + 1} (next location): {r}" for i, r in enumerate(res) if 0 < i < n - 1]
        lines.append(f"Field {n} (final location): {res[-1]}")
        lines.append(f"Field {n + 1} (sequence): MANDATORY – locations are to be attended in field order.")
        return f"Application for household inspection visit, ref. {dept}/{num}\n" + "\n".join(lines)
    return (f"Application for household inspection visit, ref. {dept}/{num}\nField 1 (locations to be attended): "
            + "; ".join(res) + ".\nField 2 (sequence): NOT PRESCRIBED (no fixed order).")


_PATROLS = {"Otter": "Otters", "Kingfisher": "Kingfishers", "Badger": "Badgers", "Curlew": "Curlews", "Wolf": "Wolves"}


def _orienteering(rng, res: list[str], order: str) -> str:
    """A scout leader's orienteering card, or the briefing that goes with it."""
    patrol = _pick(rng, tuple(_PATROLS))
    if len(res) == 1:
        return (f"Orienteering practice, {patrol} Patrol: only a single control to find today – {res[0]}. Dib it and "
                "you're done. Woggles straight, scouts!")
    n = len(res)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"Start: {res[0]}"] + [f"Control {i}: {r}" for i, r in enumerate(res) if 0 < i < n - 1]
            lines.append(f"Finish: {res[-1]}")
            return (f"1st Ashdown Scouts – ORIENTEERING, LINE COURSE ({patrol} Patrol)\n" + "\n".join(lines)
                    + "\nLine course: punch the controls in the order shown. A swapped control means disqualification.")
        s = f"Right, {_PATROLS[patrol]}, gather round. Line course today. Head out to {res[0]}"
        s += "".join(f", pick up {r}" for r in res[1:-1])
        return s + f", and run in at {res[-1]}. Controls in order, mind – swap any round and you're disqualified."
    if rng.uniform() < 0.5:
        body = "\n".join(f"○ {r}" for r in res)
        return (f"SCORE EVENT – {patrol} Patrol\nControls:\n{body}\nScore orienteering: visit the controls in any "
                "sequence you choose and plan your own route.")
    return (f"{_PATROLS[patrol]}! Score event this afternoon: the controls are {_listed(rng, res)}. Any sequence you choose – "
            "plan your own route!")


def render_instruction_s(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a parent's treasure-hunt clue sheet, a
    local-radio travel bulletin, a bureaucratic request form, a scout leader's orienteering card). Goals stay in
    visiting order; strict texts say the order is fixed ('solve the clues in order', 'one-way system', '[X] as
    listed', 'line course'), free ones say it is open ('a scramble, not a trail', 'pick your own route', '[X] at the
    robot's discretion', 'score event')."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(4))
    return (_treasure, _radio, _form, _orienteering)[who](rng, res, order)
