"""Held-out phrasings of set Q: goal, sensor, coordinate and instruction templates for the `unseen_q` split.

Written by an author who never read the parser (nor its lexicon, tagger, readings, agreement or grounding code,
nor the evaluation code), with only the interface of the earlier template sets in view. Same four functions,
arguments and meanings as the other template sets. The style is four people who send a home robot round a house
in the layout and words of their own trade or hobby:

- a ship's captain giving orders or writing the log: "ORDERS OF THE WATCH", "First heading: make for ...", "Next
  heading: ...", "Final heading: come to rest at ...", "Helm, listen sharp. Set a course for ...; thence to ...;
  and bring her in at ...", "Captain out."; a fixed order as "steer these headings in the order given; no
  deviation", "in that sequence and no other", "the order of calls is not to be changed"; a free one as "ports of
  call (any order, the navigator's choice)", "in whatever order the wind favours", "of no consequence";
- a recipe-style method: a made-up dish name as the title, "Method", "Step 1: Begin with ...", "Step 3: Finish
  with ...", "Once that's done, move on to ...", "You'll need to visit:" with bullets; fixed as "work through the
  steps in order, don't skip ahead", "the order matters: follow it step by step, exactly as written", "in strict
  sequence"; free as "add them in any order, it all comes out the same", "in whatever order you fancy", "no method
  to follow";
- a museum audio-guide script: "Please press play to begin.", "[Track 2] When you're ready, please continue to
  ...", "Our tour ends at ...", "Stop A: ...", "This guided tour opens at ..., moves on to ... and closes at ...";
  fixed as "follow the tracks in numbered sequence", "kindly keep to the order of the tour", "in alphabetical
  order"; free as "self-guided", "free-roaming tour (no fixed route)", "in any order you please", "whatever order
  catches your eye";
- a detective's case notes: "CASE NOTES - the Pemberton affair", lower-case roman numerals "(ii) ...", "Started at
  ..., went on to ..., and was last sighted at ...", "Inspector's orders: begin your inquiries at ..."; fixed as
  "retrace it exactly", "same order as the statement", "walk it in exactly that order", "the sequence is part of
  the evidence"; free as "sequence immaterial", "neither here nor there", "whatever order your instincts suggest".

Goals: attributes before the noun, as "(teal/corduroy)", ", described as teal and corduroy," or "of the teal,
corduroy variety"; states before the noun ("the switched-on lamp"), as ", presently switched on,", ", which was
open when I last looked," or "(empty at the time of writing)"; the room as "in the X", "inside the X" or
"somewhere in the X", always before any relation; relations in new words ("within a few paces of", "a couple of
steps from", "adjoining", "right alongside", "pressed up next to", "tucked beside", "set down beside", "stationed
by", "out by", "upon", "resting upon", "laid on", "down underneath", "stowed beneath", "hanging above", "high
above", "up over", "held in", "tucked inside", "paired with", "together with", "that comes with", "sharing a room with", "in
the room housing", "squarely in front of", "hidden behind", "concealed behind", "squarely facing", "a little to the
left of", "on the right side of"); an anchor with relations of its own takes them in a "which in turn" clause, in
brackets ("the credenza (which in turn has the record player)") or, when it closes the goal, after a comma.
Readings: "registering over", "that's crept above", "that's climbed higher than", "or upward", "at the very least",
"bottoming out at", "shy of", "hasn't climbed to", "beneath", "at the outside", "as its ceiling", "doesn't go
beyond", "topping out at", "something like", "on or about", "plus or minus a touch", "near enough"; units "°C",
"°", "C", "degrees", "degrees Celsius", "%", "percent", "per cent"; numbers as digits, decimals, ".6", words and
"minus"; superlatives "the balmiest", "the frostiest", "the iciest", "the best-thriving", "the most wilted", "the
droopiest", "the soggiest", "the moistest", "the most parched", "that logs the highest temperature", "whose NDVI
comes out lowest", "with the top NDVI score", "that's the driest of all". Coordinates: "at the point where x reads
3.5 and y reads 2", "at 3.5 on the x-axis and 2 on the y-axis", "at waypoint 3.5 | 2", "at map reference 3.5, 2",
"logged at x-value 3.5, y-value 2", sometimes in brackets; always x then y.

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
    "near": ("near", "within a few paces of", "a couple of steps from", "not far from", "close to"),
    "next_to": ("next to", "adjoining", "right alongside", "pressed up next to"),
    "beside": ("beside", "tucked beside", "set down beside", "sitting beside"),
    "by": ("by", "stationed by", "set by", "out by"),
    "on": ("on", "upon", "resting upon", "laid on"),
    "under": ("under", "down underneath", "stowed beneath", "below"),
    "above": ("above", "hanging above", "high above", "up over"),
    "in": ("in", "inside", "held in", "tucked inside"),
    "with": ("with", "paired with", "together with", "that comes with"),
    "in_room_with": ("in the same room as", "sharing a room with", "in the room housing"),
    "in_front_of": ("in front of", "squarely in front of", "set in front of"),
    "behind": ("behind", "hidden behind", "back behind", "concealed behind"),
    "opposite": ("opposite", "facing", "across from", "squarely facing"),
    "left_of": ("to the left of", "a little to the left of", "on the left side of", "left of"),
    "right_of": ("to the right of", "a little to the right of", "on the right side of", "right of"),
}
# after "which in turn": the "with" relation as a verb
_WITH_VERB = (("has", "have"), ("comes with", "come with"), ("is paired with", "are paired with"))


def _rel_words(rng, r: Relation, plural: bool) -> str:
    w = _pick(rng, REL_WORDS[r.type])
    return "that come with" if plural and w == "that comes with" else w


def _in_turn(rng, r: Relation, plural: bool) -> str:
    """The relation as the predicate of a 'which in turn' clause: 'is stowed beneath', 'has', 'come with'."""
    if r.type == "with":
        return _pick(rng, _WITH_VERB)[1 if plural else 0]
    return f"{'are' if plural else 'is'} {_pick(rng, REL_WORDS[r.type])}"


def _hyphened(states: list[str]) -> str:
    return " and ".join(s.replace(" ", "-") for s in states)


def _anchor(rng, t: Target, last: bool) -> str:
    """An anchor: 'the sofa', 'the switched-off steam iron', 'the toy chest (presently open)', and its own relations
    in a 'which in turn' clause: 'the credenza (which in turn has the record player)' or, when the anchor closes the
    goal (`last`), 'the credenza, which in turn is stowed beneath the shelves'."""
    _, states = split_attributes(t)
    if states and (t.relations or rng.uniform() < 0.6):
        s = f"the {_hyphened(states)} {t.phrase}"
    elif states:
        s = f"the {t.phrase} (presently {' and '.join(states)})"
    else:
        s = f"the {t.phrase}"
    if not t.relations:
        return s
    plural = is_plural(t.head)
    inner = " and ".join(f"{_in_turn(rng, r, plural)} {_anchor(rng, r.anchor, False)}" for r in t.relations)
    if last and rng.uniform() < 0.5:
        return f"{s}, which in turn {inner}"
    return f"{s} (which in turn {inner})"


def _relations(rng, t: Target) -> str:
    plural = is_plural(t.head)
    n = len(t.relations)
    parts = [f"{_rel_words(rng, r, plural)} {_anchor(rng, r.anchor, i == n - 1)}" for i, r in enumerate(t.relations)]
    out = parts[0] if parts else ""
    for p in parts[1:]:
        out += _pick(rng, (" and ", " and ", " and also ", ", and ")) + p
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS = ("in the {}", "in the {}", "inside the {}", "somewhere in the {}")
_KINDS = ("variety", "kind", "sort")


def render_goal_q(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set Q writes it: 'the teal corduroy bean bag somewhere in the nursery', 'the bean bag
    (teal/corduroy) inside the nursery', 'the bean bag of the teal, corduroy variety', 'the toy chest, presently
    open,', 'the lamp, which was switched on when I last looked,', 'the balmiest kiln in the craft room', 'the
    guitar at waypoint 3.5 | 2', 'the lamp pressed up next to the credenza (which in turn has the record player)'.
    The room comes before any relation; relations come last."""
    t = sg.target
    pre, states = split_attributes(t)
    plural = is_plural(t.head)
    head_words = t.phrase[len(t.phrase) - len(t.head):] if t.phrase.endswith(t.head) else t.head
    attr_style = "before"
    if pre and not prefix:
        attr_style = _pick(rng, ("before", "before", "before", "slash", "described", "kind"))
    state_style = None
    if states:
        opts = ["presently", "looked"] + ([] if attr_style == "slash" else ["writing"])
        if len(states) == 1 and attr_style == "before":
            opts += ["before", "before"]
        state_style = _pick(rng, opts)
    out = "the " + (prefix + " " if prefix else "")
    if state_style == "before":
        out += _hyphened(states) + " "
    out += t.phrase if attr_style == "before" else head_words
    if attr_style == "slash":
        out += f" ({'/'.join(pre)})"
    elif attr_style == "described":
        out += f", described as {' and '.join(pre)},"
    elif attr_style == "kind":
        out += f" of the {', '.join(pre)} {_pick(rng, _KINDS)}"
    st = " and ".join(states)
    if state_style == "presently":
        out += f", presently {st},"
    elif state_style == "looked":
        out += f", which {'were' if plural else 'was'} {st} when I last looked,"
    elif state_style == "writing":
        out = out.rstrip(",") + f" ({st} at the time of writing)"
    if hint:
        out += " " + (f"({hint})" if rng.uniform() < 0.25 else hint)
    room = _pick(rng, _ROOMS).format(sg.room) if sg.room else ""
    if tail:
        if plural and tail.startswith("that's "):
            tail = "that are " + tail[len("that's "):]
        if room and rng.uniform() < 0.5:
            comma = "" if tail.startswith(("that", "whose", "with")) else _pick(rng, ("", ","))
            out += f" {room}{comma} {tail}"
        else:
            out += f" {tail}" + (f" {room}" if room else "")
    elif room:
        out += " " + room
    if t.relations:
        out += " " + _relations(rng, t)
    out = " ".join(out.replace(",,", ",").replace(", ,", ",").split())
    while out.endswith(","):
        out = out[:-1].rstrip()
    return out


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

_TEMP = {
    "gt": ("registering over {n}", "that's crept above {n}", "that's climbed higher than {n}",
           "that's gotten warmer than {n}", "logging a temperature above {n}"),
    "ge": ("registering {n} or upward", "that's reached {n} at the very least", "with a temperature bottoming out at {n}",
           "holding at {n} or upward"),
    "lt": ("registering under {n}", "that's shy of {n}", "that's gotten cooler than {n}",
           "logging a temperature beneath {n}", "that hasn't climbed to {n}"),
    "le": ("registering {n} at the outside", "with {n} as its ceiling", "that doesn't go beyond {n}",
           "with a temperature topping out at {n}"),
    "approx": ("registering something like {n}", "registering on or about {n}", "sitting at {n} plus or minus a touch",
               "with a temperature of {n} near enough"),
}
_HUM = {
    "gt": ("registering over {n} humidity", "with humidity that's crept above {n}", "that's more humid than {n}",
           "logging humidity higher than {n}"),
    "ge": ("with humidity of {n} or upward", "with humidity at {n} at the very least", "with humidity bottoming out at {n}"),
    "lt": ("with humidity shy of {n}", "that's drier than {n}", "registering under {n} humidity",
           "logging humidity beneath {n}"),
    "le": ("with humidity of {n} at the outside", "with humidity topping out at {n}",
           "with humidity that doesn't go beyond {n}"),
    "approx": ("with humidity of something like {n}", "registering on or about {n} humidity",
               "with humidity at {n} plus or minus a touch", "with humidity of {n} near enough"),
}
_NDVI = {
    "gt": ("with an NDVI over {n}", "scoring higher than {n} on NDVI", "with an NDVI that's crept above {n}",
           "with an NDVI score above {n}"),
    "ge": ("with an NDVI of {n} or upward", "with an NDVI bottoming out at {n}", "scoring {n} at the very least on NDVI"),
    "lt": ("with an NDVI shy of {n}", "with an NDVI value under {n}", "scoring beneath {n} on NDVI"),
    "le": ("with an NDVI of {n} at the outside", "with an NDVI topping out at {n}", "with an NDVI that doesn't go beyond {n}"),
    "approx": ("with an NDVI of something like {n}", "with an NDVI on or about {n}", "with an NDVI value of {n} near enough"),
}
_OTHER = {  # any other reading: named, no unit
    "gt": ("with a {r} reading over {n}",), "ge": ("with a {r} reading of {n} or upward",),
    "lt": ("with a {r} reading shy of {n}",), "le": ("with a {r} reading of {n} at the outside",),
    "approx": ("with a {r} reading of something like {n}",),
}
_NAMED_TEMP = ("logging a temperature", "with a temperature")  # the reading is named: the unit may go
_T_UNITS = (" °C", "°C", "°", " C", " degrees", " degrees Celsius")
_H_UNITS = ("%", " %", " percent", " per cent")
_SUPER_ADJ = {
    ("temperature_c", "max"): ("warmest", "hottest", "balmiest"),
    ("temperature_c", "min"): ("coldest", "coolest", "frostiest", "iciest"),
    ("ndvi", "max"): ("healthiest", "greenest", "best-thriving"),
    ("ndvi", "min"): ("least healthy", "most wilted", "droopiest"),
    ("humidity_pct", "max"): ("most humid", "dampest", "soggiest", "moistest"),
    ("humidity_pct", "min"): ("driest", "least humid", "most parched"),
}
_SUPER_TAIL = {
    ("temperature_c", "max"): ("that logs the highest temperature", "whose temperature comes out highest",
                               "that's the hottest of all"),
    ("temperature_c", "min"): ("that logs the lowest temperature", "whose temperature comes out lowest",
                               "that's the coolest of all"),
    ("ndvi", "max"): ("that logs the highest NDVI", "whose NDVI comes out highest", "with the top NDVI score"),
    ("ndvi", "min"): ("that logs the lowest NDVI", "whose NDVI comes out lowest", "with the bottom NDVI score"),
    ("humidity_pct", "max"): ("that logs the highest humidity", "whose humidity comes out highest",
                              "that's the dampest of all"),
    ("humidity_pct", "min"): ("that logs the lowest humidity", "whose humidity comes out lowest",
                              "that's the driest of all"),
}


def _number(rng, reading: str, value: float) -> tuple[str, float]:
    """(the number as written, its value): digits, a decimal, '.6', words for whole numbers, 'minus' for negatives."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    if reading == "ndvi":
        u = rng.uniform()
        if u < 0.2:
            return f"{v:.2f}", v
        if u < 0.4 and txt.startswith("0."):
            return txt[1:], v
        return txt, v
    if v == int(v):
        u = rng.uniform()
        if u < 0.15 and abs(v) < 100:
            return number_words(int(v)), v
        if u < 0.25:
            return f"{v:.1f}", v
        if v < 0 and u < 0.45:
            return f"minus {txt[1:]}", v
    return txt, v


def render_sensor_q(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('balmiest', 'frostiest', 'most wilted', 'most parched') or a tail
    ('that logs the highest temperature', 'whose NDVI comes out lowest', "that's the driest of all"); thresholds
    after the noun ("that's shy of 60 °C", 'registering 40 % or upward', 'with an NDVI on or about .65', 'with a
    temperature topping out at twenty-one degrees')."""
    rd = c.reading
    if c.is_superlative:
        adj, tails = _SUPER_ADJ.get((rd, c.comparator)), _SUPER_TAIL.get((rd, c.comparator))
        if adj is None:
            name = rd.replace("_", " ")
            return "", f"that logs the {'highest' if c.comparator == 'max' else 'lowest'} {name} reading", c
        if rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, tails), c
    n, value = _number(rng, rd, c.value)
    if rd == "ndvi":
        return "", _pick(rng, _NDVI[c.comparator]).format(n=n), SensorConstraint(rd, c.comparator, value, "")
    if rd == "temperature_c":
        form = _pick(rng, _TEMP[c.comparator])
        if form.startswith(_NAMED_TEMP) and rng.uniform() < 0.3:
            return "", form.format(n=n), SensorConstraint(rd, c.comparator, value, "")
        u = _pick(rng, (" degrees", " degrees Celsius")) if n[-1].isalpha() else _pick(rng, _T_UNITS)
        return "", form.format(n=n + u), SensorConstraint(rd, c.comparator, value, "c")
    if rd == "humidity_pct":
        u = _pick(rng, (" percent", " per cent")) if n[-1].isalpha() else _pick(rng, _H_UNITS)
        return "", _pick(rng, _HUM[c.comparator]).format(n=n + u), SensorConstraint(rd, c.comparator, value, "%")
    text = _pick(rng, _OTHER[c.comparator]).format(r=rd.replace("_", " "), n=n)
    return "", text, SensorConstraint(rd, c.comparator, value, "")


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_q(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at the point where x reads 3.5 and y reads 2', 'at
    3.5 on the x-axis and 2 on the y-axis', 'at waypoint 3.5 | 2', 'at map reference 3.5, 2', 'logged at x-value
    3.5, y-value 2'."""
    return _pick(rng, (f"at the point where x reads {x} and y reads {y}", f"at {x} on the x-axis and {y} on the y-axis",
                       f"at waypoint {x} | {y}", f"at map reference {x}, {y}", f"logged at x-value {x}, y-value {y}"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _bare(goal: str) -> str:
    return goal[4:] if goal.startswith("the ") else goal


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _listed(rng, res: list[str]) -> str:
    """Goals in a running sentence: commas, or semicolons where a goal has commas of its own."""
    if any("," in r for r in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


def _orders(rng, res: list[str], order: str) -> str:
    """A ship's captain: orders of the watch, orders to the helm, or the log."""
    if len(res) == 1:
        return _pick(rng, (f"Captain to helm: make for {res[0]} and report back once we're there.",
                           f"Orders, short and sweet: steer us to {res[0]}. That is all. Captain out."))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            lines = [f"First heading: make for {res[0]}."] + [f"Next heading: {r}." for r in res[1:-1]]
            lines.append(f"Final heading: come to rest at {res[-1]}.")
            return ("ORDERS OF THE WATCH\n" + "\n".join(lines)
                    + "\nSteer these headings in the order given; no deviation.")
        if k == 1:
            s = f"Helm, listen sharp. Set a course for {res[0]}" + "".join(f"; thence to {r}" for r in res[1:-1])
            s += "; and" if len(res) > 2 else ", and"
            return s + f" bring her in at {res[-1]}. We sail them in that sequence and no other. Captain out."
        s = f"Captain's log. Orders came through at dawn: we are to call at {res[0]} first"
        s += "".join(f", then at {r}" for r in res[1:-1])
        return s + (f", and only then put in at {res[-1]}. The Admiral was plain that the order of calls is not to be "
                    "changed.")
    k = int(rng.integers(3))
    if k == 0:
        return ("Ports of call for today (any order, the navigator's choice):\n"
                + "\n".join(f"⚓ {_cap(_bare(r))}" for r in res))
    if k == 1:
        return f"Captain to helm: we're to call at {_listed(rng, res)}. Take them in whatever order the wind favours."
    return (f"Captain's log. Today's orders: touch at {_listed(rng, res)}. Which of them we reach first is of no "
            "consequence to the Admiral.")


_DISHES = ("A TIDY LITTLE ROUND", "HOUSE-CHECK HOTPOT", "SUNDAY ROUND-UP", "GRANDMA'S ERRAND CRUMBLE")


def _recipe(rng, res: list[str], order: str) -> str:
    """A recipe-style method: a dish name as the title, numbered steps or a list of what you'll need."""
    dish = _pick(rng, _DISHES)
    if len(res) == 1:
        return _pick(rng, (f"A one-step recipe: simply head to {res[0]}. Serve immediately.",
                           f"{dish}\nMethod: make your way to {res[0]}, and that's it. Done!"))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            lines = [f"Step 1: Begin with {res[0]}."] + [f"Step {i + 2}: Then {r}." for i, r in enumerate(res[1:-1])]
            lines.append(f"Step {len(res)}: Finish with {res[-1]}.")
            return (f"{dish}\nMethod\n" + "\n".join(lines)
                    + "\nWork through the steps in order; don't skip ahead, or it won't come together.")
        if k == 1:
            s = f"Here's the method. Start by heading to {res[0]}."
            s += "".join(f" Once that's done, move on to {r}." for r in res[1:-1])
            return s + (f" To finish, make your way to {res[-1]}. Like any good bake, the order matters: follow it "
                        "step by step, exactly as written.")
        mid = "".join(f"; next, {r}" for r in res[1:-1])
        return f"Method (in strict sequence): first {res[0]}{mid}; lastly, {res[-1]}. Don't change the sequence."
    k = int(rng.integers(3))
    if k == 0:
        return (f"{dish}\nYou'll need to visit:\n" + "\n".join(f"• {_cap(_bare(r))}" for r in res)
                + "\nMethod: collect them all. Add them in any order; it all comes out the same.")
    if k == 1:
        return (f"Ingredients for this one, gathered in whatever order you fancy: {_listed(rng, res)}. No method to "
                "follow, really; just get them all.")
    return f"Stops to gather, in any order you like, much like weighing out the dry ingredients: {_listed(rng, res)}."


def _audio_guide(rng, res: list[str], order: str) -> str:
    """A museum audio-guide script: tracks, lettered stops, or a spoken welcome."""
    if len(res) == 1:
        return _pick(rng, (f"Welcome. This short audio tour has just a single stop: {res[0]}. Take your time, and enjoy.",
                           f"[Press play] Please make your way to {res[0]}, where our tour begins and ends."))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            lines = [f"[Track 1] Our tour begins at {res[0]}."]
            lines += [f"[Track {i + 2}] When you're ready, please continue to {r}." for i, r in enumerate(res[1:-1])]
            lines.append(f"[Track {len(res)}] Our tour ends at {res[-1]}. Thank you for visiting.")
            return ("Welcome to the house tour. Please press play to begin.\n" + "\n".join(lines)
                    + "\nPlease follow the tracks in numbered sequence; the commentary builds as you go.")
        if k == 1:
            s = f"Good afternoon and welcome. This guided tour opens at {res[0]}"
            s += "".join(f", moves on to {r}" for r in res[1:-1])
            return s + (f", and closes at {res[-1]}. Kindly keep to the order of the tour, as each stop follows on from "
                        "the previous stop.")
        lines = [f"Stop {'ABCDEFGH'[i]}: {r}" for i, r in enumerate(res)]
        return "\n".join(lines) + "\nVisitors are asked to take the stops in alphabetical order."
    k = int(rng.integers(3))
    if k == 0:
        return (f"Welcome! This is a self-guided visit. The highlights are {_listed(rng, res)}. You're free to visit "
                "the exhibits in any order you please.")
    if k == 1:
        return ("Exhibits on today's free-roaming tour (no fixed route):\n" + "\n".join(f"◆ {_cap(_bare(r))}" for r in res)
                + "\nWander between them as you wish.")
    return f"Audio guide, self-paced edition: listen in at {_listed(rng, res)}, in whatever order catches your eye."


_AFFAIRS = ("Pemberton", "Ashworth", "Greaves", "Holloway")
_ROMAN = ("i", "ii", "iii", "iv", "v", "vi", "vii", "viii")


def _casebook(rng, res: list[str], order: str) -> str:
    """A detective's case notes: a case heading, numbered leads, the suspect's route, an inspector's orders."""
    case = f"CASE NOTES – the {_pick(rng, _AFFAIRS)} affair"
    if len(res) == 1:
        return _pick(rng, (f"{case}\nOnly a single lead worth chasing: {res[0]}. Go and have a discreet look.",
                           f"Hunch: the whole thing turns on {res[0]}. Take a quiet look and report back."))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            lines = [f"({_ROMAN[i]}) {r}" for i, r in enumerate(res)]
            return (f"{case}\nThe witness was precise about the route, so retrace it exactly:\n" + "\n".join(lines)
                    + "\nSame order as the statement; any other and the timeline falls apart.")
        if k == 1:
            s = f"Note to self: retrace the suspect's steps. Started at {res[0]}"
            s += "".join(f", went on to {r}" for r in res[1:-1])
            return s + f", and was last sighted at {res[-1]}. Walk it in exactly that order."
        s = f"Inspector's orders: begin your inquiries at {res[0]}"
        s += "".join(f"; only after that, move to {r}" for r in res[1:-1])
        return s + f"; and conclude at {res[-1]}. The sequence is part of the evidence, so keep to it."
    k = int(rng.integers(3))
    if k == 0:
        return (f"{case}\nLeads to chase (sequence immaterial):\n" + "\n".join(f"» {_cap(_bare(r))}" for r in res)
                + "\nCover every lead; whichever comes first is neither here nor there.")
    if k == 1:
        return f"The clues point to {_listed(rng, res)}. Check them all; the order of inquiry is neither here nor there."
    return f"Inspector's orders: look into {_listed(rng, res)}, in whatever order your instincts suggest."


def render_instruction_q(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a ship's captain's orders or log, a
    recipe-style method, a museum audio-guide script, a detective's case notes). Goals stay in visiting order;
    strict texts say the order is fixed ('in the order given', 'work through the steps in order', 'in numbered
    sequence', 'walk it in exactly that order'), free ones say it is open ("the navigator's choice", 'in any order;
    it all comes out the same', 'self-guided', 'neither here nor there')."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(4))
    return (_orders, _recipe, _audio_guide, _casebook)[who](rng, res, order)
