"""Phrasings of set O: goal, sensor, coordinate and instruction templates for the `unseen_dev12` split.

Written after parser round 14, before any run of it and before any further parser change, by an author who never
read the parser (nor its lexicon, tagger or grounding code); set N, the held-out set before it, moved to
`unseen_dev11`. Measured fresh as the held-out set with parser rounds 14 and 15, then developed against in round
16; moved to this development split when set P (`phrasings_heldout.py`) took its place as `unseen`. Same four
functions, arguments and meanings as the other template sets. The style is four people who send a home robot on
errands in the words of their own trade or age:

- a warehouse picker's pick list: a header, numbered lines ("01  TEAL BEAN BAG IN THE NURSERY"), capitals,
  leading determiners dropped, a closing line on the sequence ("PICK SEQUENCE: BY LINE NO. - DO NOT SKIP AHEAD",
  "PICK SEQUENCE: ANY - PICKER'S CHOICE");
- a game master's quest text: "QUEST: ...", "Objective I: Seek out ...", "Objective II: ...", "The objectives
  must be completed in the order given"; or prose ("Thy first trial awaits at ... Only when it is done shalt thou
  venture to ... Thy final trial lies at ..."), free as "Seek them out in whatever order fate allows";
- a child dictating to a parent who types it up: "Robot go to ... And then go to ... You have to do it in THAT
  order OK", "You can pick the order", with the parent's note in brackets;
- a voice assistant reading the errand back: "Okay. Heading to ..., then ..., in exactly that order.",
  "Confirming your route: (1) ... (2) ...", "You said the order doesn't matter, so I'll take the quickest route."

Goals: attributes before the noun, in a relative clause ("the bean bag that's teal and corduroy") or set off by
commas ("the bean bag, teal and corduroy,"); states before the noun ("the switched-on toaster"), as "that
somebody's left switched on", "(currently open)", "that's empty"; the room as "in the X" or "(X)"; relations in
new words ("a few steps from", "sat next to", "stood by", "up on top of", "sat underneath", "round the back of",
"on the left-hand side of", "in the room that has", "stored in", "that's got"); an anchor with relations of its own
takes them in brackets ("the credenza (the one with the record player)"). Readings: "upwards of", "a minimum of",
"or above", "no lower than", "or below", "no higher than", "not above", "at the most", "in the region of", "round
about", "more or less", "whose thermometer shows"; units "°C", "°", "Celsius", "deg C", "degrees", "%",
"percent"; numbers as digits, decimals and words; superlatives "the toastiest", "the least warm", "the muggiest",
"with the bottom temperature reading", "whose NDVI reads highest", "the driest of the lot". Coordinates: "at
X3.5 Y2", "at 3.5 along and 2 up", "where x is 3.5 and y is 2", "at 3.5 m on x and 2 m on y", "at coordinates
3.5 (x), 2 (y)"; always x then y.

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
    "near": ("near", "a few steps from", "a short way from"),
    "next_to": ("next to", "sat next to", "directly next to"),
    "beside": ("beside", "right beside", "standing beside"),
    "by": ("by", "over by", "stood by"),
    "on": ("on", "sat on", "up on top of", "resting on"),
    "under": ("under", "underneath", "sat underneath", "directly below"),
    "above": ("above", "up above", "directly above"),
    "in": ("in", "inside", "stored in", "kept inside"),
    "with": ("with", "that has", "that's got"),
    "in_room_with": ("in the same room as", "in the room that has", "in the room containing"),
    "in_front_of": ("in front of", "right in front of", "directly in front of"),
    "behind": ("behind", "round the back of", "tucked behind"),
    "opposite": ("opposite", "facing", "directly opposite"),
    "left_of": ("to the left of", "on the left-hand side of", "just left of"),
    "right_of": ("to the right of", "on the right-hand side of", "just right of"),
}


def _rel_words(rng, r: Relation, plural: bool) -> str:
    w = _pick(rng, REL_WORDS[r.type])
    if plural and w == "that has":
        return "that have"
    if plural and w == "that's got":
        return "that have got"
    return w


_LEFT = ("open", "closed", "switched on", "switched off", "empty", "full")


def _states_before(rng, states: list[str], allowed: bool) -> bool:
    return allowed and len(states) == 1 and rng.uniform() < 0.35


def _anchor(rng, t: Target) -> str:
    """An anchor: 'the crib', 'the switched-off steam iron', 'the toy chest (open)', and its own relations in
    brackets after it: 'the open credenza (the one with the record player)'."""
    pre, states = split_attributes(t)
    plural = is_plural(t.head)
    if states and (t.relations or _states_before(rng, states, True)):
        s = f"the {' and '.join(x.replace(' ', '-') for x in states)} {t.phrase}"
    elif states:
        s = f"the {t.phrase} ({' and '.join(states)})"
    else:
        s = f"the {t.phrase}"
    if not t.relations:
        return s
    inner = " and ".join(f"{_rel_words(rng, r, plural)} {_anchor(rng, r.anchor)}" for r in t.relations)
    return f"{s} ({'the ones' if plural else 'the one'} {inner})"


def _relations(rng, t: Target) -> str:
    plural = is_plural(t.head)
    parts = [f"{_rel_words(rng, r, plural)} {_anchor(rng, r.anchor)}" for r in t.relations]
    if len(parts) < 2:
        return "".join(parts)
    joins = (" and ", ", and also ", " and also ")
    return parts[0] + "".join(_pick(rng, joins) + p for p in parts[1:])


# ----------------------------------------------------------------------------------------------------
# Goals


def render_goal_dev12(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set O writes it: 'the teal corduroy bean bag in the nursery', 'the bean bag that's teal and
    corduroy (nursery)', 'the switched-on toaster', 'the toy chest somebody's left open', 'the toastiest kiln in
    the craft room', 'the guitar at X3.5 Y2', 'the lamp sat next to the credenza (the one with the record
    player)'. The room comes before any relation; relations come last."""
    t = sg.target
    pre, states = split_attributes(t)
    plural = is_plural(t.head)
    head_words = t.phrase[len(t.phrase) - len(t.head):] if t.phrase.endswith(t.head) else t.head
    attr_style = "before"
    if pre and not prefix:
        attr_style = _pick(rng, ("before", "before", "before", "clause", "clause", "commas"))
    state_style = None
    if states:
        opts = ["clause", "clause", "bracket"]
        if len(states) == 1 and not prefix and attr_style == "before":
            opts.append("before")
        if all(s in _LEFT for s in states):
            opts.append("left")
        state_style = _pick(rng, opts)
    out = "the " + (prefix + " " if prefix else "")
    if state_style == "before":
        out += states[0].replace(" ", "-") + " "
    out += t.phrase if attr_style == "before" else head_words
    # attributes and states after the noun, as one clause where both are there
    post_words = (pre if attr_style == "clause" else []) + (states if state_style == "clause" else [])
    if attr_style == "commas":
        out += f", {' and '.join(pre)},"
    if post_words:
        that = _pick(rng, ("that's", "which is")) if not plural else _pick(rng, ("that are", "which are"))
        now = _pick(rng, ("", "", "currently ")) if state_style == "clause" and attr_style != "clause" else ""
        out += f" {that} {now}{' and '.join(post_words)}"
    if state_style == "bracket":
        out += f" ({_pick(rng, ('currently ', '', 'at the moment: '))}{' and '.join(states)})"
    elif state_style == "left":
        who = _pick(rng, ("that somebody's left", "that someone has left", f"that {'have' if plural else 'has'} been left"))
        out += f" {who} {' and '.join(states)}"
    if hint:
        out += " " + hint
    room = ""
    if sg.room:
        room = f"({sg.room})" if state_style != "bracket" and rng.uniform() < 0.25 else f"in the {sg.room}"
    if tail:
        if plural and tail.startswith("that's "):
            tail = "that are " + tail[len("that's "):]
        if room and not tail.startswith(("that", "whose")) and rng.uniform() < 0.5:  # a clause stays on the noun
            out += f" {room}, {tail}"
        else:
            out += f" {tail}" + ((", " if room.startswith("in ") else " ") + room if room else "")
    elif room:
        out += " " + room
    if t.relations:
        out += " " + _relations(rng, t)
    return " ".join(out.replace(",,", ",").split()).rstrip(",")


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

_TEMP = {
    "gt": ("reading upwards of {n}", "with a temperature above {n}", "that's running hotter than {n}",
           "whose thermometer shows more than {n}", "that's warmer than {n}"),
    "ge": ("reading {n} or above", "with a temperature of at least {n}", "with a temperature no lower than {n}",
           "whose thermometer shows a minimum of {n}"),
    "lt": ("reading under {n}", "with a temperature below {n}", "that's cooler than {n}",
           "whose thermometer shows less than {n}", "that's colder than {n}"),
    "le": ("reading {n} or below", "with a temperature of at most {n}", "with a temperature no higher than {n}",
           "whose thermometer shows {n} at the most"),
    "approx": ("reading round about {n}", "with a temperature in the region of {n}",
               "whose thermometer shows approximately {n}", "at {n}, more or less,"),
}
_HUM = {
    "gt": ("with humidity above {n}", "whose humidity is more than {n}", "that's more humid than {n}",
           "reading upwards of {n} humidity"),
    "ge": ("with humidity of at least {n}", "whose humidity is {n} or above", "reading no lower than {n} humidity",
           "with a minimum of {n} humidity"),
    "lt": ("with humidity below {n}", "whose humidity is less than {n}", "that's drier than {n}",
           "reading under {n} humidity"),
    "le": ("with humidity of at most {n}", "whose humidity is {n} or below", "reading no higher than {n} humidity",
           "with humidity not above {n}"),
    "approx": ("with humidity in the region of {n}", "whose humidity is round about {n}",
               "reading approximately {n} humidity", "at {n} humidity, more or less,"),
}
_NDVI = {
    "gt": ("with an NDVI above {n}", "whose NDVI is more than {n}", "scoring upwards of {n} on NDVI",
           "with an NDVI reading greater than {n}"),
    "ge": ("with an NDVI of at least {n}", "whose NDVI is {n} or above", "with an NDVI no lower than {n}",
           "with a minimum NDVI of {n}"),
    "lt": ("with an NDVI below {n}", "whose NDVI is less than {n}", "with an NDVI reading under {n}",
           "with an NDVI lower than {n}"),
    "le": ("with an NDVI of at most {n}", "whose NDVI is {n} or below", "with an NDVI no higher than {n}",
           "with a maximum NDVI of {n}"),
    "approx": ("with an NDVI in the region of {n}", "whose NDVI is round about {n}", "with an NDVI of approximately {n}",
               "with an NDVI of {n}, more or less,"),
}
_T_UNITS = ("°C", " °C", " degrees", " degrees Celsius", " Celsius", "°", " deg C")
_H_UNITS = ("%", " %", " percent")
_SUPER_ADJ = {
    ("temperature_c", "max"): ("warmest", "hottest", "toastiest"),
    ("temperature_c", "min"): ("coldest", "coolest", "chilliest", "least warm"),
    ("ndvi", "max"): ("healthiest", "greenest", "lushest"),
    ("ndvi", "min"): ("least healthy", "sickliest", "least green"),
    ("humidity_pct", "max"): ("most humid", "dampest", "muggiest"),
    ("humidity_pct", "min"): ("driest", "least humid", "least damp"),
}
_SUPER_TAIL = {
    ("temperature_c", "max"): ("with the top temperature reading", "whose thermometer reads highest",
                               "that's running the hottest of the lot"),
    ("temperature_c", "min"): ("with the bottom temperature reading", "whose thermometer reads lowest",
                               "that's running the coldest of the lot"),
    ("ndvi", "max"): ("with the top NDVI score", "whose NDVI reads highest", "with the best NDVI of the lot"),
    ("ndvi", "min"): ("with the bottom NDVI score", "whose NDVI reads lowest", "with the poorest NDVI of the lot"),
    ("humidity_pct", "max"): ("with the top humidity reading", "whose humidity reads highest",
                              "that's the dampest of the lot"),
    ("humidity_pct", "min"): ("with the bottom humidity reading", "whose humidity reads lowest",
                              "that's the driest of the lot"),
}


def _number(rng, reading: str, value: float) -> tuple[str, float]:
    """(the number as written, its value): digits, a decimal, words for whole numbers, 'minus' for negatives."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    if reading == "ndvi":
        return (f"{v:.2f}" if rng.uniform() < 0.3 else txt), v
    if v == int(v):
        u = rng.uniform()
        if u < 0.2 and abs(v) < 100:
            return number_words(int(v)), v
        if u < 0.3:
            return f"{v:.1f}", v
        if v < 0 and u < 0.45:
            return f"minus {txt[1:]}", v
    return txt, v


def render_sensor_dev12(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('toastiest', 'least warm', 'muggiest') or a tail ('with the
    bottom temperature reading', 'whose NDVI reads highest', 'that's the driest of the lot'); thresholds after
    the noun ('reading upwards of 150 °C', 'whose humidity is 40% or below', 'with a minimum NDVI of 0.5',
    'at twenty-one degrees, more or less,')."""
    rd = c.reading
    if c.is_superlative:
        if rng.uniform() < 0.5:
            return _pick(rng, _SUPER_ADJ[(rd, c.comparator)]), "", c
        return "", _pick(rng, _SUPER_TAIL[(rd, c.comparator)]), c
    n, value = _number(rng, rd, c.value)
    if rd == "ndvi":
        return "", _pick(rng, _NDVI[c.comparator]).format(n=n), SensorConstraint(rd, c.comparator, value, "")
    if rd == "temperature_c":
        u = _pick(rng, (" degrees", " degrees Celsius")) if n[-1].isalpha() else _pick(rng, _T_UNITS)
        return "", _pick(rng, _TEMP[c.comparator]).format(n=n + u), SensorConstraint(rd, c.comparator, value, "c")
    u = " percent" if n[-1].isalpha() else _pick(rng, _H_UNITS)
    return "", _pick(rng, _HUM[c.comparator]).format(n=n + u), SensorConstraint(rd, c.comparator, value, "%")


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_dev12(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at X3.5 Y2', 'at 3.5 along and 2 up' (never
    for a negative number), 'where x is 3.5 and y is 2', 'at 3.5 m on x and 2 m on y', 'at coordinates 3.5 (x),
    2 (y)'."""
    forms = [f"at X{x} Y{y}", f"where x is {x} and y is {y}", f"at {x} m on x and {y} m on y",
             f"at coordinates {x} (x), {y} (y)"]
    if not x.startswith("-") and not y.startswith("-"):
        forms.append(f"at {x} along and {y} up")
    return _pick(rng, forms)


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _bare(goal: str) -> str:
    return goal[4:] if goal.startswith("the ") else goal


def _picker(rng, res: list[str], order: str) -> str:
    """A warehouse pick list: header, numbered lines, capitals, and a line on the picking sequence."""
    caps = rng.uniform() < 0.75
    items = [_bare(r).upper() if caps else _bare(r) for r in res]
    head = _pick(rng, ("PICK LIST - ROBOT", "ROBOT PICK LIST", "PICKING SHEET / HOUSE ROBOT"))
    if len(items) == 1:
        return f"{head}\nITEM: {items[0]}\nEND OF LIST"
    if order == "strict":
        body = "\n".join(f"{i + 1:02d}  {r}" for i, r in enumerate(items))
        foot = _pick(rng, ("PICK SEQUENCE: BY LINE NO. - DO NOT SKIP AHEAD", "PICK IN LINE ORDER",
                           "FOLLOW THE LINE ORDER, TOP TO BOTTOM"))
    else:
        numbered = rng.uniform() < 0.5
        body = "\n".join((f"{i + 1:02d}  " if numbered else "-  ") + r for i, r in enumerate(items))
        foot = _pick(rng, ("PICK SEQUENCE: ANY - PICKER'S CHOICE", "LINES MAY BE PICKED IN ANY SEQUENCE",
                           "NO FIXED SEQUENCE - PICKER'S CHOICE"))
    return f"{head}\nLN  ITEM\n{body}\n{foot if caps else foot.capitalize()}"


_ROMAN = ("I", "II", "III", "IV", "V", "VI", "VII", "VIII")
_TITLES = ("The Household Trials", "Errand of the Tireless Servant", "The Long Hallway", "A Quest Most Domestic")
_COUNT = {2: "Two", 3: "Three", 4: "Four", 5: "Five", 6: "Six", 7: "Seven", 8: "Eight"}


def _quest(rng, res: list[str], order: str) -> str:
    """A game master's quest text: a titled list of objectives, or prose in an old-fashioned voice."""
    title = _pick(rng, _TITLES)
    seek = lambda: _pick(rng, ("Seek out", "Journey to", "Find", "Reach"))  # noqa: E731
    if len(res) == 1:
        return _pick(rng, (f"QUEST: {title}\nSole objective: {seek().lower()} {res[0]}.",
                           f"Hear me, brave machine! A single trial awaits thee at {res[0]}. Go forth."))
    if rng.uniform() < 0.5:
        if order == "strict":
            lines = [f"Objective {_ROMAN[i]}: {seek()} {r}." for i, r in enumerate(res)]
            close = _pick(rng, ("The objectives must be completed in the order given.",
                                "Complete them in the order given, or the quest is lost."))
        else:
            lines = [f"Objective: {seek()} {r}." for r in res]
            close = _pick(rng, ("The objectives may be completed in any order.",
                                "Complete the objectives in any order you choose."))
        return f"QUEST: {title}\n" + "\n".join(lines) + "\n" + close
    if order == "strict":
        s = f"Hear me, brave machine! Thy first trial awaits at {res[0]}."
        for r in res[1:-1]:
            s += f" Only when it is done shalt thou venture to {r}."
        s += f" Thy final trial lies at {res[-1]}. Stray not from this path."
        return s
    listed = "; ".join(res[:-1]) + "; and " + res[-1]
    return (f"{_COUNT.get(len(res), 'Many')} relics lie hidden in this house: {listed}. "
            + _pick(rng, ("Seek them out in whatever order fate allows.", "No order is decreed; gather them as thou wilt.")))


_KIDS = ("Maisie", "Leo", "Ava", "Sam", "Priya", "Tom")


def _child(rng, res: list[str], order: str) -> str:
    """A child dictating, typed up by a parent: short sentences, 'And then', shouting capitals, a parent's note."""
    kid = _pick(rng, _KIDS)
    opener = _pick(rng, (f"Dictated by {kid} (age four), typed up by me:\n", f"{kid} wants to send the robot on a mission. "
                         "In their words:\n", f"From {kid}, who made me write it down exactly:\n", ""))
    if len(res) == 1:
        return opener + f"Robot can you please go to {res[0]}. Thank you robot!!"
    if order == "strict":
        s = f"Robot you have to go to {res[0]} first. "
        s += "".join(f"And then go to {r}. " for r in res[1:-1])
        s += f"And then LAST go to {res[-1]}. You have to do it in THAT order OK."
        note = _pick(rng, ("", "", " (The order matters to them, so please stick to it.)"))
        return opener + s + note
    s = f"Robot go and see {res[0]}" + "".join(f" and {r}" for r in res[1:]) + ". "
    s += _pick(rng, ("You can pick the order.", "It doesn't matter what order.", "Go to them in any order you like."))
    note = _pick(rng, ("", "", " (Any order is fine - they just want them all visited.)"))
    return opener + s + note


def _readback(rng, res: list[str], order: str) -> str:
    """A voice assistant confirming what it heard before it sets off."""
    if len(res) == 1:
        return _pick(rng, (f"Okay. Heading to {res[0]} now.", f"Got it - on my way to {res[0]}.",
                           f"Sure. Going to {res[0]}."))
    if order == "strict":
        k = int(rng.integers(3))
        if k == 0:
            return f"Okay. Heading to {res[0]}" + "".join(f"; then {r}" for r in res[1:]) + " - in exactly that order."
        if k == 1:
            return "Confirming your route: " + " ".join(f"({i + 1}) {r};" for i, r in enumerate(res))[:-1] + \
                ". I'll visit them one after the other, as listed."
        ords = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth")
        parts = [f"{ords[i]}, {r}" for i, r in enumerate(res[:-1])] + [f"and last, {res[-1]}"]
        return f"Got it. {_COUNT.get(len(res), 'Several')} stops, in this order: " + "; ".join(parts) + "."
    listed = "; ".join(res[:-1]) + "; and " + res[-1]
    return _pick(rng, (f"Okay. I'll visit {listed}. You said the order doesn't matter, so I'll take the quickest route.",
                       f"Got it: {listed}. I'll choose the order myself to save time.",
                       f"Sure - adding {listed}. Since any order works, I'll plan the shortest path."))


def render_instruction_dev12(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a warehouse pick list, a game master's
    quest, a child dictating to a parent, a voice assistant's read-back). Goals stay in visiting order; strict
    texts say the order is fixed ('BY LINE NO.', 'in the order given', 'in THAT order', 'in exactly that order'),
    free ones say it is open ('PICKER'S CHOICE', 'in whatever order fate allows', 'You can pick the order',
    'I'll choose the order myself')."""
    res = [" ".join(r.split()).strip().rstrip(",") for r in res]
    who = int(rng.integers(4))
    return (_picker, _quest, _child, _readback)[who](rng, res, order)
