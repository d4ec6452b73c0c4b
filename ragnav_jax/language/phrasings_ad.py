"""Held-out phrasings of set AD: goal, sensor, coordinate and instruction templates for the `unseen_ad` split.

Written by a helper that never read the parser (nor its lexicon, tagger, sensor reader, readings, agreement,
adapters, LLM or command code, nor the evaluation code), before any run of any reader on these sentences, with only
the interface of set W in view (`phrasings_w.py`: its four functions, their arguments, return values and meanings).
Same four functions, arguments and meanings as the other template sets. The style is four people who send a home
robot round a house in the layout and words of their own pastime or trade:

- a stage magician doing patter for an audience, the robot being "my mechanical assistant": a playbill "THE GREAT
  ZANZIBAR PRESENTS – three feats of wonder, performed strictly in the order billed" with "The Opening Feat: my
  assistant appears at ...", "The Second Feat: ...", "The Grand Finale: ...", or patter "Watch closely now! First my
  assistant appears at ..., then – abracadabra! – at ..., and for the grand finale, at ...."; a fixed order as
  "strictly in the order billed", "each feat only once the one billed before it is done", "the order is the whole
  illusion", "exactly in that order, or the spell is broken"; a free one as "Pick a card, any card!" with playing-card
  suits as bullets ("♠", "♥", "♦", "♣"), "shuffle them how you like", "the order they're turned up in makes no
  difference to the trick", "in any order at all", "the magic works whichever comes first"; one goal as "tonight
  just one illusion" or "one trick only";
- a radio amateur passing traffic over the air: "G4RBT de M0HSE: three items of traffic for the robot, to be worked
  in sequence as numbered. Over." with "Item one: .... Break.", "Item three: .... End of traffic.", "Work them
  strictly in the order sent – no skipping ahead. How copy? Over.", or "Robot, base. First go to ...; after that,
  ...; and last of all .... Stick to that sequence – I say again, stick to that sequence. Over."; free as "CQ CQ,
  calling the robot: three contacts wanted for the log, work them in any order you like" with "»" bullets, "order
  doesn't matter, just get every one in the log", "any sequence copies fine", "order's up to you"; one goal as
  "Single item of traffic: proceed to .... Nothing further. Over and out." or "one message only";
- a rock-climbing guidebook writer: a route topo "CRACK OF DOOM – three pitches, climbed in order from the ground up"
  with "P1  Climb to .... Belay.", "P2  Traverse to .... Belay.", "P3  Finish at ... and top out.", "Pitches go in
  sequence: each one only after the one before it.", or "Start at ..., step across to ..., and pull through to
  finish at .... Climb it in that sequence – there's no other way up."; free as "BOULDER CIRCUIT – three problems,
  tick them in any order" with "◇" bullets, "no set sequence: hop between them however you like", or "all go, and
  you can tick them in whatever order you fancy"; one goal as "A short solo line: climb straight to ..., then lower
  off." or "just the single problem here";
- an orchestra conductor reading from the score: a programme "SUITE DOMESTIQUE in three movements – to be played in
  the printed order, attacca" with Roman-numbered movements and tempo marks ("I. Allegro con brio – ...", "II.
  Andante – ...", "III. Presto – ..."), "Attacca throughout: straight on from each movement into the next, in the
  order written.", or "From the top, everyone! We begin at ..., then on to ..., and the coda is .... Exactly as
  written in the score, in that order – no skipping bars!"; free as "ENCORES, ad libitum – three pieces, play them in
  any order you please" with "♪" bullets and "the running order is entirely at the player's discretion", or "run
  through ..., in whatever order you like – ad lib."; one goal as "Tonight's programme is a single movement: ...."
  or "Solo cadenza – just the one passage".

Goals (the same for every voice): attributes before the noun ("the teal wool lamp"), in a clause ("the lamp that's
teal and wool", "which is teal and wool"), in a bracket ("the lamp (teal, wool)", "(teal and wool)") or as an
apposition ("the lamp, a teal wool one,"); states hyphenated before the noun ("the switched-on lamp"), in a clause
("that's currently switched on"), in a bracket ("(currently switched on)", "(switched on right now)") or as an
aside (", presently switched on,"); clauses merge into one ("the lamp that is teal and wool and is currently switched
on and lives in the nursery"); the room as a possessive ("the nursery's lamp"), "in the nursery", "somewhere in the
nursery", "located in the nursery", "(room: nursery)" or in a clause "that lives in the nursery"; with a sensor tail
the room is a possessive or a bracket, or comes after the tail behind a comma. Relations: near "near", "near to",
"not far from", "close to", "in the neighbourhood of"; next to "next to", "right next to", "adjacent to",
"immediately next to"; beside "beside", "right beside", "just beside", "at the side of"; by "by", "over by", "down
by", "right by"; on "on", "on top of", "sitting on", "up on"; under "under", "underneath", "beneath", "down
underneath"; above "above", "up above", "directly over", "hanging above"; in "inside", "in", "kept inside", "housed
in"; with "with", "accompanied by", "paired with", and in a clause "that has"/"that have"; same room "in the same room
as", "in the room with", "in one room with"; in front of "in front of", "just in front of", "directly in front of",
"placed in front of"; behind "behind", "just behind", "round the back of", "tucked behind"; opposite "opposite",
"across from", "facing", "straight across from"; left "to the left of", "left of", "just left of", "on the left of";
right likewise. The first relation plain or after "that's"/"which is"; further ones after " and also " or ", and
it's also "; an anchor's states hyphenated before it or "(currently open)"; an anchor's own relations in a bracket
"(which is itself next to ...)", "(the one next to ...)", or, when nothing follows, after ", the one"; deeper ones
after "that is"/"that has". Readings: "whose temperature is ...", "with a humidity of ...", "reading ...", "where the
thermometer reads ...", "where the hygrometer reads ...", a bracket with a symbol "(temp > 30 °C)", "(RH ≤ 40%)",
"(NDVI ≈ 0.65)" (">", "≥", ">=", "<", "≤", "<=", "≈", "~"), and comparatives "running warmer than", "running no colder
than", "with air damper than", "with air drier than"; comparisons "over", "above", "more than", "higher than",
"greater than", "at least", "or more", "or higher", "no less than", "not below", "under", "below", "less than",
"lower than", "at most", "or less", "or lower", "no more than", "not above", "about", "roughly", "approximately",
"or so", ", give or take", "more or less", "-ish"; names "temperature", "temp", "humidity", "relative humidity",
"RH", "NDVI", "vegetation index (NDVI)"; numbers as digits, words ("thirty", "minus four", "negative four"), "minus 4",
"negative 4", "-4", "4 degrees below freezing", halves and quarters ("22½", "22¼", "twenty-two and a half"), NDVI as
"0.65", ".65", "zero point six five", "point six five", a fraction "13/20"; units "°C", " °C", "C", "ºC", " degrees
Celsius", " degrees centigrade", " degrees", "%", " %", " per cent", " percent", "% RH", " percent RH", "% humidity",
" per cent humidity", none when the reading is named; superlatives "hottest", "warmest", "highest-temperature",
"coldest", "chilliest", "lowest-temperature", "most humid", "dampest", "highest-humidity", "least humid", "driest",
"lowest-humidity", "greenest", "lushest", "highest-NDVI", "least green", "sickliest", "lowest-NDVI", and tails "with
the highest/lowest temperature of the lot", "whose humidity reads highest/lowest of all", "(top/bottom NDVI of the
bunch)", "running hottest/coldest of all". Coordinates (x then y, digits with an ASCII minus): "at x = 3.5, y = 2",
"at x3.5 y2", "at the point x 3.5 m / y 2 m", "at 3.5 m along x and 2 m along y", "at coordinates x: 3.5, y: 2",
"where x reads 3.5 and y reads 2", "[x 3.5 | y 2]", "at grid x 3.5, y 2".

Slips while writing: in `episodes.py` the author read, besides `UNSEEN_TEMPLATES`, the code around the four
functions' call sites (`describe_location`, the end of `describe_sensor`, `_one_episode`) and the two-line bodies of
the `_pick` and `_fmt_value` helpers (value formatting, no reader code); this module imports neither but rounds values
the same way (NDVI to two places, others as `:g` writes them). A first smoke run, started outside the worktree,
imported the package from the main checkout and stopped at an ImportError; nothing of it was read.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from ragnav_jax.language.template_text import attributes_and_states, number_words
from ragnav_jax.language.template_text import both as _both
from ragnav_jax.language.template_text import hyphenated as _hyphen
from ragnav_jax.language.template_text import is_are as _is
from ragnav_jax.language.template_text import listed as _listed
from ragnav_jax.language.template_text import plural as _plural
from ragnav_jax.language.template_text import tidy as _tidy
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Small helpers of this set's own


def _pick(rng: np.random.Generator, items):
    return items[int(rng.integers(len(items)))]


def _canon(reading: str, v: float) -> str:
    """A value as this set writes it before dressing it up: NDVI to two places, anything else as `:g` writes it."""
    if reading == "ndvi":
        return f"{v:.2f}".rstrip("0").rstrip(".") if v != 0 else "0"
    return f"{v:g}"


def _that_is(head: str) -> str:
    return "that are" if _plural(head) else "that's"


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "near to", "not far from", "close to", "in the neighbourhood of"),
    "next_to": ("next to", "right next to", "adjacent to", "immediately next to"),
    "beside": ("beside", "right beside", "just beside", "at the side of"),
    "by": ("by", "over by", "down by", "right by"),
    "on": ("on", "on top of", "sitting on", "up on"),
    "under": ("under", "underneath", "beneath", "down underneath"),
    "above": ("above", "up above", "directly over", "hanging above"),
    "in": ("inside", "in", "kept inside", "housed in"),
    "with": ("with", "accompanied by", "paired with"),
    "in_room_with": ("in the same room as", "in the room with", "in one room with"),
    "in_front_of": ("in front of", "just in front of", "directly in front of", "placed in front of"),
    "behind": ("behind", "just behind", "round the back of", "tucked behind"),
    "opposite": ("opposite", "across from", "facing", "straight across from"),
    "left_of": ("to the left of", "left of", "just left of", "on the left of"),
    "right_of": ("to the right of", "right of", "just right of", "on the right of"),
}
WITH_AFTER_IS = ("accompanied by", "paired with")  # 'with' after a form of 'to be'
WITH_VERBS = ("has", "have")  # 'with' as the verb of a clause: 'that has the monitor'


def _pred(rng, head: str, r: Relation, depth: int, closing: bool) -> str:
    """A relation as the predicate of a clause about `head`: 'is next to the sofa', 'has the monitor'."""
    anchor = _anchor_np(rng, r.anchor, depth, closing)
    if r.type == "with":
        if rng.uniform() < 0.5:
            return ("have " if _plural(head) else "has ") + anchor
        return f"{_is(head)} {_pick(rng, WITH_AFTER_IS)} {anchor}"
    return f"{_is(head)} {_pick(rng, REL_WORDS[r.type])} {anchor}"


def _anchor_np(rng, t: Target, depth: int, closing: bool) -> str:
    """An anchor: 'the open drawer', 'the drawer (currently open)' for a top-level anchor without relations; a
    top-level anchor's own relations in a bracket '(which is itself next to ...)', '(the one next to ...)', or after
    ', the one' when nothing follows (`closing` False); deeper down after 'that is' / 'that has'."""
    _, states = attributes_and_states(t)
    if not t.phrase.endswith(t.head):
        states = [a for a in t.attributes if a not in t.phrase]
    bracket = bool(states) and depth == 1 and not t.relations and rng.uniform() < 0.35
    out = "the " + (_hyphen(states) + " " if states and not bracket else "") + t.phrase
    if bracket:
        out += f" ({_pick(rng, ('currently', 'presently'))} {_both(states)})"
    if not t.relations:
        return out
    preds = [_pred(rng, t.head, r, depth + 1, True) for r in t.relations]
    if depth > 1:
        return out + " " + " and ".join("that " + p for p in preds)
    styles = ["itself", "one"] + ([] if closing else ["comma"])
    style = _pick(rng, styles)
    if style == "itself":
        pron = "themselves" if _plural(t.head) else "itself"
        body = " and ".join(_insert_after_verb(p, pron) for p in preds)
        return out + f" (which {body})"
    one = "the ones" if _plural(t.head) else "the one"
    body = " and ".join("that " + p for p in preds)
    body = body[len("that "):] if body.startswith("that is ") or body.startswith("that are ") else body
    body = body[len("is "):] if body.startswith("is ") else body[len("are "):] if body.startswith("are ") else body
    if style == "one":
        return out + f" ({one} {body})"
    return out + f", {one} {body}"


def _insert_after_verb(pred: str, pron: str) -> str:
    """'is next to the sofa' -> 'is itself next to the sofa'; 'has the monitor' -> 'itself has the monitor'."""
    verb, _, rest = pred.partition(" ")
    if verb in ("is", "are"):
        return f"{verb} {pron} {rest}"
    return f"{pron} {pred}"


def _relations(rng, head: str, rels: tuple[Relation, ...], lead: bool) -> str:
    """A goal's relations: the first plain ('next to the sofa') or after "that's" / 'which is'; further ones after
    ' and also ' or ', and it's also '."""
    out = ""
    for i, r in enumerate(rels):
        closing = i + 1 < len(rels)
        if i == 0:
            if lead:
                pred = _pred(rng, head, r, 1, closing)
                out = ("which " if rng.uniform() < 0.5 else "that ") + pred
            elif r.type == "with":
                out = f"{_pick(rng, REL_WORDS['with'])} {_anchor_np(rng, r.anchor, 1, closing)}"
            else:
                out = f"{_pick(rng, REL_WORDS[r.type])} {_anchor_np(rng, r.anchor, 1, closing)}"
            continue
        if rng.uniform() < 0.5:
            out += f" and also {_pick(rng, REL_WORDS[r.type])} {_anchor_np(rng, r.anchor, 1, closing)}"
        else:
            pred = _pred(rng, head, r, 1, closing)
            it = "they" if _plural(head) else "it"
            verb, _, rest = pred.partition(" ")
            if verb in ("is", "are"):
                out += f", and {it}{chr(39)}{'re' if verb == 'are' else 's'} also {rest}"
            else:
                out += f", and {it} also {pred}"
    return out


# ----------------------------------------------------------------------------------------------------
# Goals


def _goal_np(rng, sg: Subgoal, prefix: str, tail: str) -> tuple[str, str]:
    """(the goal's noun phrase with its attributes, states and room; where the room went: 'front' (before the noun,
    or none), 'end' (the phrase ends with it), 'bracket', or 'after' when it must still be added after a sensor
    tail). One bracket to a noun, a sensor tail's bracket included; no clause beside a sensor tail."""
    t = sg.target
    pre, states = attributes_and_states(t)
    shaped = t.phrase.endswith(t.head) and t.phrase == " ".join([*pre, t.head])
    if not t.phrase.endswith(t.head):
        pre, states = [], [a for a in t.attributes if a not in t.phrase]
    head = t.head if shaped else t.phrase
    clause_ok = not tail
    brackets = int(tail.startswith("("))

    attr = "front"
    if pre and shaped:
        attr = _pick(rng, ("front", "front", "clause", "bracket", "one") if clause_ok else ("front", "front", "bracket",
                                                                                             "one"))
    if attr == "bracket":
        brackets += 1
    state = None
    if states:
        opts = ["front", "clause", "bracket", "aside"]
        if not clause_ok:
            opts.remove("clause")
        if brackets:
            opts.remove("bracket")
        state = _pick(rng, opts)
        brackets += state == "bracket"
    room = None
    if sg.room:
        if tail:
            room = _pick(rng, ("poss", "after", "after") + (() if brackets else ("bracket",)))
        else:
            opts = ["in", "in", "somewhere", "located", "poss"]
            if clause_ok:
                opts.append("clause")
            if not brackets:
                opts.append("bracket")
            room = _pick(rng, opts)

    out = "the "
    if room == "poss":
        out += f"{sg.room}'s "
    if prefix:
        out += prefix + " "
    if state == "front":
        out += _hyphen(states) + " "
    out += t.phrase if attr == "front" else head
    if attr == "bracket":
        out += f" ({', '.join(pre) if rng.uniform() < 0.5 else _both(pre)})"
    elif attr == "one":
        out += f", {'some' if _plural(t.head) else 'a'} {' '.join(pre)} {'ones' if _plural(t.head) else 'one'},"
    if state == "bracket":
        out += f" ({_pick(rng, ('currently ' + _both(states), _both(states) + ' right now'))})"
    elif state == "aside":
        out += f", presently {_both(states)},"
    parts = []
    if attr == "clause":
        parts.append(f"{_is(t.head)} {_both(pre)}")
    if state == "clause":
        parts.append(f"{_is(t.head)} currently {_both(states)}")
    where = {"in": f"in the {sg.room}", "somewhere": f"somewhere in the {sg.room}",
             "located": f"located in the {sg.room}"}.get(room or "")
    if parts and where:  # a room after a clause goes into the clause: 'that's teal and is located in the nursery'
        parts.append(f"{_is(t.head)} {where}")
        room, where = "clause", None
    elif room == "clause":
        parts.append(("live" if _plural(t.head) else "lives") + f" in the {sg.room}")
    if len(parts) == 1 and parts[0].startswith(("is ", "are ")) and rng.uniform() < 0.5:
        out += f" {_that_is(t.head)} {parts[0].split(' ', 1)[1]}"
    elif parts:
        out += " " + _pick(rng, ("that", "which")) + " " + " and ".join(parts)
    if where:
        out += " " + where
    elif room == "bracket":
        out += f" (room: {sg.room})"
    if room in ("in", "somewhere", "located", "clause"):
        return out, "end"
    return out, room if room in ("after", "bracket") else "front"


def render_goal_ad(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AD writes it: 'the teal wool lamp in the nursery', "the nursery's switched-on lamp", 'the lamp
    (teal, wool) that's currently switched on', 'the hottest kettle somewhere in the kitchen', 'the kettle whose
    temperature is over 30 °C, in the kitchen', 'the guitar at x = 3.5, y = 2', 'the lamp located in the nursery
    next to the credenza (which is itself with the record player)'. The room comes before a coordinate hint and any
    relation; a coordinate hint comes after everything but the relations, so its numbers are the goal's last; the
    relations come last."""
    t = sg.target
    out, room_at = _goal_np(rng, sg, prefix, tail)
    if tail:
        out += " " + tail
        if room_at == "after":
            out += f", in the {sg.room}"
    if hint:
        out += (", " if tail or room_at == "end" else " ") + hint
    if t.relations:
        # after a room, a hint or a sensor tail a comma keeps the relation off them; no 'which is' after a room
        comma = bool(tail) or bool(hint) or room_at == "end" or out.endswith(")") and rng.uniform() < 0.5
        lead = (not tail and not hint and room_at != "end" and rng.uniform() < 0.3 and " that" not in out
                and " which " not in out)
        out += ("," if comma else "") + " " + _relations(rng, t.head, t.relations, lead)
    return _tidy(out)


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

CMP_WORDS = {
    "gt": ("over {n}", "above {n}", "more than {n}", "higher than {n}", "greater than {n}"),
    "ge": ("at least {n}", "{n} or more", "{n} or higher", "no less than {n}", "not below {n}"),
    "lt": ("under {n}", "below {n}", "less than {n}", "lower than {n}"),
    "le": ("at most {n}", "{n} or less", "{n} or lower", "no more than {n}", "not above {n}"),
    "approx": ("about {n}", "roughly {n}", "approximately {n}", "{n} or so", "{n}, give or take", "more or less {n}"),
}
# after 'with a <reading> of'
OF_WORDS = {
    "gt": ("over {n}", "more than {n}"),
    "ge": ("at least {n}", "{n} or more", "{n} or higher", "no less than {n}"),
    "lt": ("under {n}", "less than {n}"),
    "le": ("at most {n}", "{n} or less", "{n} or lower", "no more than {n}"),
    "approx": CMP_WORDS["approx"],
}
SYMBOLS = {"gt": (">",), "ge": ("≥", ">="), "lt": ("<",), "le": ("≤", "<="), "approx": ("≈", "~")}
# comparatives with no name of the reading: temperature after 'running', humidity after 'with air'
WARMTH = {"gt": ("warmer than", "hotter than"), "ge": ("no colder than", "at least as warm as"),
          "lt": ("colder than", "cooler than"), "le": ("no warmer than", "no hotter than"),
          "approx": ("at about", "at roughly")}
DAMPNESS = {"gt": ("damper than", "more humid than"), "ge": ("at least as damp as", "no drier than"),
            "lt": ("drier than", "less humid than"), "le": ("no damper than", "no more humid than"),
            "approx": ("at about", "at roughly")}
NAMES = {"temperature_c": ("temperature",), "humidity_pct": ("humidity", "relative humidity"),
         "ndvi": ("NDVI", "vegetation index (NDVI)")}
SHORT_NAMES = {"temperature_c": ("temp", "temperature"), "humidity_pct": ("RH", "humidity"), "ndvi": ("NDVI",)}
INSTRUMENTS = {"temperature_c": "thermometer", "humidity_pct": "hygrometer", "ndvi": "NDVI"}
SUPER_ADJ = {
    ("temperature_c", "max"): ("hottest", "warmest", "highest-temperature"),
    ("temperature_c", "min"): ("coldest", "chilliest", "lowest-temperature"),
    ("humidity_pct", "max"): ("most humid", "dampest", "highest-humidity"),
    ("humidity_pct", "min"): ("least humid", "driest", "lowest-humidity"),
    ("ndvi", "max"): ("greenest", "lushest", "highest-NDVI"),
    ("ndvi", "min"): ("least green", "sickliest", "lowest-NDVI"),
}
SUPER_TAILS = {
    "max": ("with the highest {name} of the lot", "whose {name} reads highest of all", "(top {name} of the bunch)"),
    "min": ("with the lowest {name} of the lot", "whose {name} reads lowest of all", "(bottom {name} of the bunch)"),
}
RUNNING = {"max": "running hottest of all", "min": "running coldest of all"}

_DIGITS = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")
_FRACS = {0.5: ("½", " and a half"), 0.25: ("¼", " and a quarter"), 0.75: ("¾", " and three quarters")}


def _number(rng, reading: str, value: float) -> tuple[str, float, str]:
    """(the number as written, its value, how): 'digits' ('30', '-4', 'minus 4', 'negative 4', '22½', '.65',
    '0.65'), 'words' ('thirty', 'minus four', 'twenty-two and a half', 'zero point six five', 'point six five'),
    'frac' ('13/20', an NDVI), or 'subzero' (a whole temperature below zero: '4 degrees below freezing')."""
    txt = _canon(reading, value)
    v = float(txt)
    u = rng.uniform()
    if reading == "ndvi":
        if 0 < v < 1:
            decimals = txt[2:]
            fr = Fraction(txt)
            if u < 0.15:
                return "zero point " + " ".join(_DIGITS[int(d)] for d in decimals), v, "words"
            if u < 0.3:
                return "point " + " ".join(_DIGITS[int(d)] for d in decimals), v, "words"
            if u < 0.45 and fr.denominator <= 20:
                return f"{fr.numerator}/{fr.denominator}", v, "frac"
            if u < 0.65:
                return txt[1:], v, "digits"
            return txt, v, "digits"
        if v < 0 and u < 0.4:
            return "minus " + txt[1:], v, "digits"
        if v in (0.0, 1.0) and u < 0.3:
            return ("zero", "one")[int(v)], v, "words"
        return txt, v, "digits"
    if reading not in ("temperature_c", "humidity_pct"):
        return txt, v, "digits"
    whole = int(abs(v))
    frac = round(abs(v) - whole, 2)
    if v == int(v):
        if v < 0 and reading == "temperature_c" and u < 0.2:
            return f"{number_words(whole) if rng.uniform() < 0.5 else whole}", v, "subzero"
        if u < 0.35 and abs(v) < 1000:
            words = number_words(int(v))
            if v < 0 and rng.uniform() < 0.5:
                words = "negative " + words[len("minus "):]
            return words, v, "words"
        if v < 0 and u < 0.55:
            return f"{_pick(rng, ('minus', 'negative'))} {whole}", v, "digits"
        return txt, v, "digits"
    if frac in _FRACS and u < 0.5:
        sign = ("minus " if rng.uniform() < 0.5 else "-") if v < 0 else ""
        sym, spoken = _FRACS[frac]
        if rng.uniform() < 0.5 or whole >= 1000:
            return f"{sign}{whole}{sym}", v, "digits"
        sign = "minus " if v < 0 else ""
        return f"{sign}{number_words(whole)}{spoken}", v, "words"
    return txt, v, "digits"


_TEMP_DIGITS = ("°C", " °C", "C", "ºC", " degrees Celsius", " degrees centigrade")
_TEMP_WORDS = (" degrees", " degrees Celsius", " degrees centigrade")
_HUM_DIGITS = ("%", " %", " per cent", " percent", "% RH", " percent RH")
_HUM_WORDS = (" per cent", " percent")
_HUM_NAMED = ("% RH", "% humidity", " per cent humidity", " percent RH")  # units that name the reading


def _unit(rng, reading: str, how: str, n: str, must_name: bool = False) -> tuple[str, str]:
    """(the number with its unit, the unit code)."""
    if reading == "temperature_c":
        if how == "subzero":
            return f"{n} degree{'' if n in ('1', 'one') else 's'} below freezing", "c"
        unit = _pick(rng, _TEMP_WORDS if how == "words" else _TEMP_DIGITS)
        if unit.startswith(" degrees") and n in ("1", "one", "-1", "minus one", "negative one", "minus 1",
                                                  "negative 1"):
            unit = unit.replace("degrees", "degree")
        return n + (" " + unit.lstrip() if n.endswith("-ish") else unit), "c"
    if reading == "humidity_pct":
        if must_name:
            unit = _pick(rng, _HUM_NAMED if how != "words" else (" per cent humidity", " percent humidity"))
        else:
            unit = _pick(rng, _HUM_WORDS if how == "words" else _HUM_DIGITS)
        return n + (" " + unit.lstrip() if n.endswith("-ish") else unit), "%"
    return n, ""


def _article(name: str) -> str:
    return "an" if name.startswith("NDVI") else "a"


def render_sensor_ad(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('hottest', 'least humid', 'highest-NDVI') or a tail ('with the lowest
    humidity of the lot', 'whose NDVI reads highest of all', '(top temperature of the bunch)', 'running coldest of
    all'); thresholds after the noun ('whose temperature is over 30 °C', 'with a humidity of 40% or less', 'reading
    at least thirty degrees', 'where the hygrometer reads under 40 per cent', '(NDVI ≈ 13/20)', 'running warmer
    than 4 degrees below freezing', 'with air drier than 40% RH')."""
    rd = c.reading
    names = NAMES.get(rd, (rd.replace("_", " "),))
    if c.is_superlative:
        adj = SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        opts = [s.format(name=_pick(rng, names)) for s in SUPER_TAILS[c.comparator]]
        if rd == "temperature_c":
            opts.append(RUNNING[c.comparator])
        return "", _pick(rng, opts), c

    n, value, how = _number(rng, rd, c.value)
    known = rd in NAMES
    frames = ["whose", "with"]
    if known:
        frames += ["instrument"]
        if how == "digits" and "minus" not in n and "negative" not in n:
            frames += ["symbol"]
        if rd in ("temperature_c", "humidity_pct"):
            frames += ["comparative"]
        if rd == "temperature_c":
            frames += ["reading"]
    frame = _pick(rng, frames)
    cmp = c.comparator
    if cmp == "approx" and how == "digits" and not n.startswith(("-", "minus", "negative")) and rng.uniform() < 0.15:
        n += "-ish"
        words = "{n}"
    else:
        words = _pick(rng, (OF_WORDS if frame == "with" else CMP_WORDS)[cmp])

    if frame == "comparative":
        if rd == "temperature_c":
            num, code = _unit(rng, rd, how, n)
            tail = f"running {_pick(rng, WARMTH[cmp])} {num}"
        else:
            num, code = _unit(rng, rd, how, n, must_name=True)
            tail = f"with air {_pick(rng, DAMPNESS[cmp])} {num}"
        return "", tail, SensorConstraint(rd, cmp, value, code)
    if frame == "symbol":
        num, code = _unit(rng, rd, how, n.removesuffix("-ish"))
        if rng.uniform() < 0.3 and rd != "ndvi":
            num, code = n.removesuffix("-ish"), ""
        tail = f"({_pick(rng, SHORT_NAMES[rd])} {_pick(rng, SYMBOLS[cmp])} {num})"
        return "", tail, SensorConstraint(rd, cmp, value, code)
    if frame == "reading":
        num, code = _unit(rng, rd, how, n)
        return "", "reading " + words.format(n=num), SensorConstraint(rd, cmp, value, code)

    num, code = _unit(rng, rd, how, n)
    if known and how == "digits" and code and rng.uniform() < 0.15:
        num, code = n, ""  # the reading is named: the unit may go
    said = words.format(n=num)
    if frame == "instrument":
        return "", f"where the {INSTRUMENTS[rd]} reads {said}", SensorConstraint(rd, cmp, value, code)
    name = _pick(rng, names)
    if frame == "whose":
        return "", f"whose {name} is {said}", SensorConstraint(rd, cmp, value, code)
    return "", f"with {_article(name)} {name} of {said}", SensorConstraint(rd, cmp, value, code)


# ----------------------------------------------------------------------------------------------------
# Coordinates

HINTS = ("at x = {x}, y = {y}", "at x{x} y{y}", "at the point x {x} m / y {y} m", "at {x} m along x and {y} m along y",
         "at coordinates x: {x}, y: {y}", "where x reads {x} and y reads {y}", "[x {x} | y {y}]",
         "at grid x {x}, y {y}")


def hint_text_ad(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y, both as the digits given: 'at x = 3.5, y = 2', 'at
    x3.5 y2', 'at the point x 3.5 m / y 2 m', 'at 3.5 m along x and 2 m along y', 'at coordinates x: 3.5, y: 2',
    'where x reads 3.5 and y reads 2', '[x 3.5 | y 2]', 'at grid x 3.5, y 2'."""
    return _pick(rng, HINTS).format(x=x, y=y)


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _sep(res: list[str]) -> str:
    return ";" if any("," in r for r in res) else ","


def _inline(rng, res: list[str]) -> str:
    """Goals in a running sentence: 'A, B and C', or with semicolons where a goal has commas of its own."""
    if any("," in r for r in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return _listed(rng, res)


def _end(goal: str) -> str:
    """A full stop after a goal, unless it ends in one already."""
    return "" if goal.endswith((".", "!", "?")) else "."


_MAGI = ("THE GREAT ZANZIBAR", "MADAME MYSTERIA", "THE AMAZING PROSPERO", "SIGNOR ABRACADABRO", "THE MYSTIFYING MARVO")
_FEATS = ("Opening", "Second", "Third", "Fourth", "Fifth", "Sixth", "Seventh", "Eighth", "Ninth", "Tenth")
_SUITS = ("♠", "♥", "♦", "♣")
_THEN_MAGIC = ("then – abracadabra! – at", "then, hey presto, at", "next – and keep your eyes on it – at")


def _magician(rng, res: list[str], order: str) -> str:
    """A stage magician's patter: a playbill of feats, patter to the audience, or a deck of cards."""
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"Ladies and gentlemen, tonight just one illusion: my mechanical assistant will appear, as "
                           f"if by magic, at {g}. Ta-da!",
                           f"Nothing up my sleeve – one trick only this evening: off you go to {g}, my mechanical "
                           "assistant, and take a bow."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"{_pick(rng, _MAGI)} PRESENTS – {w} feats of wonder, performed strictly in the order billed"]
            for i, r in enumerate(res[:-1]):
                feat = _FEATS[i] if i < len(_FEATS) else "Next"
                lines.append(f"The {feat} Feat: my assistant appears at {r}{_end(r)}")
            lines.append(f"The Grand Finale: my assistant appears at {res[-1]}{_end(res[-1])}")
            lines.append("Each feat only once the one billed before it is done – the order is the whole illusion!")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Watch closely now! First my assistant appears at {res[0]}"
        s += "".join(f"{sep} {_pick(rng, _THEN_MAGIC)} {r}" for r in res[1:-1])
        return s + (f"{sep} and for the grand finale, at {res[-1]}. Exactly in that order, mind, or the spell is "
                    "broken!")
    if rng.uniform() < 0.5:
        body = "\n".join(f"{_SUITS[i % 4]} {r}" for i, r in enumerate(res))
        return (f"Pick a card, any card! {_cap(w)} cards in the deck, each a place my assistant must visit:\n{body}\n"
                "Shuffle them how you like – the order they're turned up in makes no difference to the trick.")
    return (f"For this next wonder my assistant will visit {_inline(rng, res)} – in any order at all, ladies and "
            "gentlemen; the magic works whichever comes first.")


_CALLS = ("G4RBT", "M0HSE", "2E0BOT", "G3VAC", "M7ROV", "GW4MOP")


def _ham(rng, res: list[str], order: str) -> str:
    """A radio amateur passing traffic: numbered items, a spoken message, or a call for contacts."""
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"Base to Robot, base to Robot. Single item of traffic: proceed to {g}. Nothing further. "
                           "Over and out.",
                           f"Robot, this is base, one message only – go to {g}{_end(g)} Base out."))
    n = len(res)
    w = number_words(n)
    me, you = (str(c) for c in rng.choice(_CALLS, size=2, replace=False))
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"{you} de {me}: {w} items of traffic for the robot, to be worked in sequence as numbered. Over."]
            for i, r in enumerate(res):
                close = "End of traffic." if i == n - 1 else "Break."
                lines.append(f"Item {number_words(i + 1)}: {r}{_end(r)} {close}")
            lines.append("Work them strictly in the order sent – no skipping ahead. How copy? Over.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Robot, base. First go to {res[0]}"
        s += "".join(f"{sep} after that, {r}" for r in res[1:-1])
        return s + (f"{sep} and last of all {res[-1]}. Stick to that sequence – I say again, stick to that sequence. "
                    "Over.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"» {r}" for r in res)
        return (f"CQ CQ, {me} calling the robot: {w} contacts wanted for the log, work them in any order you like:\n"
                f"{body}\nOrder doesn't matter, just get every one in the log. {me} standing by.")
    return (f"Robot, base. You need {_inline(rng, res)} in your log – order's up to you, any sequence copies fine. "
            "Over.")


_ROUTES = ("CRACK OF DOOM", "THE HOUSEMAID'S CHIMNEY", "STAIRWAY DIRECT", "SLAB AND TICKLE", "THE LONG REACH")
_MOVES = ("Traverse to", "Move up to", "Step across to", "Pull through to")


def _climber(rng, res: list[str], order: str) -> str:
    """A rock-climbing guidebook: a pitch-by-pitch topo, a route description, or a boulder circuit."""
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"A short solo line: climb straight to {g}, then lower off. Classic.",
                           f"Just the single problem here – {g}. Top out and walk off."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"{_pick(rng, _ROUTES)} – {w} pitches, climbed in order from the ground up"]
            lines.append(f"P1  Climb to {res[0]}{_end(res[0])} Belay.")
            lines += [f"P{i + 2}  {_pick(rng, _MOVES)} {r}{_end(r)} Belay." for i, r in enumerate(res[1:-1])]
            lines.append(f"P{n}  Finish at {res[-1]} and top out.")
            lines.append("Pitches go in sequence: each one only after the one before it.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Start at {res[0]}"
        s += "".join(f"{sep} {_pick(rng, _MOVES).lower()} {r}" for r in res[1:-1])
        return s + (f"{sep} and pull through to finish at {res[-1]}. Climb it in that sequence – there's no other way "
                    "up.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"◇ {r}" for r in res)
        return (f"BOULDER CIRCUIT – {w} problems, tick them in any order\n{body}\nNo set sequence: hop between them "
                "however you like.")
    return (f"Good spot for a session: {_inline(rng, res)} all go, and you can tick them in whatever order you "
            "fancy.")


_PIECES = ("SUITE DOMESTIQUE", "SONATA FOR ROBOT AND HOUSEHOLD", "THE HOUSEWORK SYMPHONY", "DIVERTIMENTO DOMESTICO")
_TEMPI = ("Allegro con brio", "Andante", "Presto", "Adagio", "Scherzo: Vivace", "Moderato", "Largo", "Allegretto")
_ROMAN = ("I", "II", "III", "IV", "V", "VI", "VII", "VIII", "IX", "X", "XI", "XII")


def _conductor(rng, res: list[str], order: str) -> str:
    """An orchestra conductor: a programme of movements, rehearsal talk, or encores ad libitum."""
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"Tonight's programme is a single movement: {g}. That's the whole concert.",
                           f"Solo cadenza – just the one passage for the robot: {g}. Fine."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"{_pick(rng, _PIECES)} in {w} movements – to be played in the printed order, attacca"]
            tempi = [str(t) for t in rng.permutation(_TEMPI)]
            for i, r in enumerate(res):
                num = _ROMAN[i] if i < len(_ROMAN) else f"No. {number_words(i + 1)}"
                lines.append(f"{num}. {tempi[i % len(tempi)]} – {r}")
            lines.append("Attacca throughout: straight on from each movement into the next, in the order written.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"From the top, everyone! We begin at {res[0]}"
        s += "".join(f"{sep} then on to {r}" for r in res[1:-1])
        return s + (f"{sep} and the coda is {res[-1]}. Exactly as written in the score, in that order – no skipping "
                    "bars!")
    if rng.uniform() < 0.5:
        body = "\n".join(f"♪ {r}" for r in res)
        return (f"ENCORES, ad libitum – {w} pieces, play them in any order you please\n{body}\nThe running order is "
                "entirely at the player's discretion.")
    return f"Warm-up: run through {_inline(rng, res)}, in whatever order you like – ad lib."


VOICES = (_magician, _ham, _climber, _conductor)


def render_instruction_ad(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a stage magician, a radio amateur, a climbing
    guidebook writer, an orchestra conductor). Goals stay in visiting order, each written once as rendered; strict
    texts say the order is fixed, free ones say it is open (see the module docstring), and a single goal gets
    neither kind of cue and no digit."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    return VOICES[int(rng.integers(len(VOICES)))](rng, res, order)
