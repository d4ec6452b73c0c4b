"""Held-out phrasings of set W: goal, sensor, coordinate and instruction templates for the `unseen_w` split.

Written by a helper that never read the parser (nor its lexicon, tagger, sensor reader, readings, agreement,
adapters, LLM or command code, nor the evaluation code), before any run of any reader on these sentences, with
only the interface of the earlier template sets in view (`phrasings_z.py`, `phrasings_y.py`). Same four functions,
arguments and meanings as the other template sets. The style is four people who send a home robot round a house
in the layout and words of their own trade:

- a television cookery-show host talking to camera: a recipe card "WHISTLE-STOP HOTPOT – a recipe in three steps,
  serves one hungry robot", "Step one: pop over to ...", "Step three, to serve: dish up at ...", or "Right, lovely
  people, first we pop over to ..., then we nip across to ..., and to finish we dish up at ...."; a fixed order
  as "do the steps in the order they're written", "skip ahead and the whole thing curdles", "no shuffling the
  steps about", "one after the other, just like a soufflé"; a free one as "MISE EN PLACE – three bits to get
  ready, any which way" with "◦" bullets, "in whichever order suits you", "it all comes together in the end",
  "doesn't matter which you tackle first", "it all comes out in the gravy"; one goal as "just the one thing on
  today's menu: pop over to ...";
- a lighthouse keeper's logbook: "KEEPER'S LOG – Fastnet Rock, 14 March. Wind sou'-westerly, fresh.", "0600 Rounds
  begin. Make for ....", "0645 Thence to ....", "0730 Finish at .... Rounds complete.", or "Standing orders for
  the watch: first make for ...; then bear away for ...; and lastly to ...."; fixed as "in the order logged",
  "each only after the one above it", "in the order given", "none taken early"; free as "STANDING ORDERS – three
  stations to visit, sequence at keeper's discretion" with "⚓" bullets, "as tide and weather allow", "sequence
  immaterial", "whichever comes to hand first", "no order laid down"; one goal as "One duty only for the relief:
  make for ... and stand by there.";
- a lawyer drafting a contract clause: "The Robot shall, in the following sequence, attend upon: (a) ...
  (hereinafter the “First Station”); (b) ... (hereinafter the “Final Station”), provided always that no Station
  shall be attended before every Station preceding it in this Schedule has been attended.", or "The Robot shall
  first attend upon ..., and thereafter upon ..., and finally upon .... Time is of the essence as to sequence,
  ..."; fixed as "in the following sequence", "no station shall be attended before every station preceding it",
  "time is of the essence as to sequence", "only upon completion of the attendance preceding it"; free as "each of
  the following three premises (together, the “Stations”), in such order as the Robot may in its sole discretion
  determine:" with "(i)", "(ii)" items, "no station shall take precedence over any other", "in any sequence
  whatsoever", "of no consequence"; one goal as "The Robot shall attend upon ... and upon no other premises under
  this Agreement.";
- a radio football commentator: "ROBOT ROVERS v THE HOUSE – how the move was built, touch by touch", "First touch:
  ...!", "Touch number two: ...!", "And the finish: ... – GOAL!", or "And he's away down the wing – it's ...; now he
  cuts inside to ...; and he buries it at ...!"; fixed as "touch by touch", "every touch in its proper turn", "in
  that sequence, pass after pass", "the whole move breaks down"; free as "SET-PIECE OPTIONS – three runners, take
  your pick" with "►" bullets, "any of them could go first", "isn't fussed about the running order", "pick them
  off however he likes", "couldn't care less which comes first"; one goal as "It's a one-man show tonight, folks!
  He's away, all the way to ... – and that's the match!"

Goals: attributes before the noun, post-posed as "of the teal and wool kind" or in a bracket "(inventoried as teal
and wool)"; states before the noun ("the switched-on lamp"), in a relative clause "that somebody left switched on",
as an apposition ", reported switched on," or in a bracket "(state: switched on)"; an anchor's states before its
noun or, for an anchor without relations of its own, as "(found open)"; the room as "in the X", "down in the X",
"over in the X", "situated in the X", "whose berth is the X" or "whose home is the X", always before any relation;
relations in new words ("a stone's throw from", "within hailing distance of", "in the vicinity of", "cheek by jowl
with", "shoulder to shoulder with", "flanking", "parked up beside", "hard by", "loitering by", "perched on",
"resting upon", "atop", "tucked beneath", "sheltering under", "hovering over", "mounted above", "stowed in",
"nestled within", "complete with", "sporting", "sharing a room with", "in the selfsame room as", "planted in front
of", "just forward of", "astern of", "at the back of", "face to face with", "over the way from", "on the left-hand
side of", "on the port side of", "on the right-hand side of", "on the starboard side of", besides the plain words),
sometimes led in by "to be found"; several relations joined by "and", "as well as" or ", and furthermore,"; an
anchor with relations of its own takes them in a bracket "(itself next to the drums)", "(which, for the avoidance
of doubt, is next to the drums)", between dashes "— itself next to the drums —" when more follows, and deeper down
after ", which in turn is". Readings: "tops", "is in excess of", "runs past", "is not less than", "is ... or
upwards", "is ... at a minimum", "falls short of", "is shy of", "comes in under", "is not more than", "tops out
at", "is capped at", "hovers round", "is in the region of", "is ... or thereabouts" (and their participles after
"with a <reading>": "topping", "of ... or upwards", "coming in under", "hovering round", ...); frames "that ...",
"where the <reading> ...", "with a <reading> ..."; units "°C", "℃", "deg C", "degrees C", "Celsius", "degrees"
(with words), "degrees below zero" (a temperature below zero near which), none when the reading is named, "%", "%
RH", "per centum", "percent" (with words), "parts in the hundred"; numbers as digits, words ("forty", "minus four",
"one hundred and five"), "minus 4", "−4" (a true minus sign), the decimal comma ("22,5", "0,65"), "22 and a
half", "twenty-two and a half", NDVI as "0.65", ".65", "0,65", "65/100", "nought point six five", "nought point
nought five"; superlatives "the toastiest", "the most sweltering", "the most blistering", "the frostiest", "the
nippiest", "the most glacial", "the most verdant", "the most flourishing", "the perkiest", "the droopiest", "the
most wilted", "the most ailing", "the muggiest", "the clammiest", "the soggiest", "the most parched", "the most
arid", "the most bone-dry", "that tops the league for temperature", "with a humidity second to none", "whose NDVI
is the highest on record", "that props up the league for temperature", "with a humidity lower than all the rest",
"whose NDVI is the lowest on record". Coordinates: "at the point (x, y) = (3.5, 2)", "at posn 3.5E 2N", "at 3.5
along and 2 up", "with an x of 3.5 and a y of 2", "at easting 3.5, northing 2"; always x then y.

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


def _itself(head: str) -> str:
    return "themselves" if _plural(head) else "itself"


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "a stone's throw from", "within hailing distance of", "in the vicinity of"),
    "next_to": ("next to", "cheek by jowl with", "shoulder to shoulder with"),
    "beside": ("beside", "flanking", "parked up beside"),
    "by": ("by", "hard by", "loitering by"),
    "on": ("on", "perched on", "resting upon", "atop"),
    "under": ("under", "tucked beneath", "sheltering under"),
    "above": ("above", "hovering over", "mounted above"),
    "in": ("in", "stowed in", "nestled within"),
    "with": ("with", "complete with", "sporting"),
    "in_room_with": ("in the same room as", "sharing a room with", "in the selfsame room as"),
    "in_front_of": ("in front of", "planted in front of", "just forward of"),
    "behind": ("behind", "astern of", "at the back of"),
    "opposite": ("opposite", "face to face with", "over the way from"),
    "left_of": ("to the left of", "on the left-hand side of", "on the port side of"),
    "right_of": ("to the right of", "on the right-hand side of", "on the starboard side of"),
}
_JOINS = (" and ", " as well as ", ", and furthermore, ")
_NO_INTRO = ("with", "in_room_with")  # 'to be found' reads badly before these


def _anchor_np(rng, t: Target, depth: int, more_follows: bool) -> str:
    """An anchor: attributes and states before the noun, or '(found open)' for a top-level anchor without relations
    of its own; a top-level anchor's own relations in a bracket ('(itself next to ...)', '(which, for the avoidance
    of doubt, is next to ...)') or between dashes when more of the goal follows ('— itself next to ... —'); deeper
    down after ', which in turn is'."""
    _, states = attributes_and_states(t)
    out = "the "
    bracket_state = bool(states) and depth == 1 and not t.relations and rng.uniform() < 0.35
    if states and not bracket_state:
        out += _hyphen(states) + " "
    out += t.phrase
    if bracket_state:
        out += f" (found {_both(states)})"
    if t.relations:
        inner = _rel_chain(rng, t.relations, depth + 1)
        if depth > 1:
            out += f", which in turn {_is(t.head)} {inner}"
        else:
            styles = ["itself", "avoidance"] + (["dash"] if more_follows else [])
            style = _pick(rng, styles)
            if style == "itself":
                out += f" ({_itself(t.head)} {inner})"
            elif style == "avoidance":
                out += f" (which, for the avoidance of doubt, {_is(t.head)} {inner})"
            else:
                out += f" — {_itself(t.head)} {inner} —"
    return out


def _rel_chain(rng, rels: tuple[Relation, ...], depth: int = 1) -> str:
    out = ""
    for i, r in enumerate(rels):
        more = depth == 1 and i + 1 < len(rels)
        part = f"{_pick(rng, REL_WORDS[r.type])} {_anchor_np(rng, r.anchor, depth, more)}"
        if i == 0:
            out = part
        else:
            join = _pick(rng, _JOINS)
            if out.endswith("—") and join.startswith(","):
                join = " and "
            out += join + part
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS_IN = ("in the {}", "in the {}", "down in the {}", "over in the {}", "situated in the {}")
_ROOMS_WHOSE = ("whose berth is the {}", "whose home is the {}")


def _goal_np(rng, t: Target, prefix: str, clause_ok: bool) -> str:
    """The goal's own noun phrase: 'the teal wool lamp', 'the lamp of the teal and wool kind', 'the lamp
    (inventoried as teal and wool)', 'the switched-on lamp', 'the lamp that somebody left switched on', 'the lamp,
    reported switched on,', 'the lamp (state: switched on)'. With a superlative adjective (prefix) the attributes
    stay before the noun."""
    pre, states = attributes_and_states(t)
    if not t.phrase.endswith(t.head):  # a phrase of another shape: written as given, anything missing after it
        missing = [a for a in t.attributes if a not in t.phrase.split()]
        out = "the " + (f"{prefix} " if prefix else "") + t.phrase
        if not missing:
            return out
        return out + _pick(rng, (f" of the {_both(missing)} kind", f" (inventoried as {_both(missing)})"))
    head = t.phrase[len(t.phrase) - len(t.head):]
    attr_style = "before"
    if pre and not prefix:
        attr_style = _pick(rng, ("before", "before", "kind", "inventory"))
    state_style = None
    if states:
        opts = ["before", "left", "reported", "bracket"]
        if attr_style == "inventory":
            opts.remove("bracket")  # one bracket to a noun
        if not clause_ok:
            opts.remove("left")
        state_style = _pick(rng, opts)
    out = "the " + (f"{prefix} " if prefix else "")
    if state_style == "before":
        out += _hyphen(states) + " "
    out += t.phrase if attr_style == "before" else head
    if attr_style == "kind":
        out += f" of the {_both(pre)} kind"
    elif attr_style == "inventory":
        out += f" (inventoried as {_both(pre)})"
    if state_style == "left":
        out += f" that somebody left {_both(states)}"
    elif state_style == "reported":
        out += f", reported {_both(states)},"
    elif state_style == "bracket":
        out += f" (state: {_both(states)})"
    return out


_HAS_NUMBER = re.compile(r"\d|\b(" + "|".join(w for w in ONES + TENS if w) + r"|hundred|nought|half)\b")


def render_goal_w(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set W writes it: 'the teal wool lamp down in the nursery', 'the lamp of the teal and wool kind',
    'the lamp that somebody left switched on', 'the frostiest mini-fridge over in the pantry', 'the guitar at posn
    3.5E 2N', 'the lamp whose home is the nursery, cheek by jowl with the credenza (itself complete with the record
    player)'. The room comes before any relation (and before a superlative tail, which is read inside it); a
    coordinate hint comes after any number of a sensor tail; relations come last."""
    t = sg.target
    out = _goal_np(rng, Target(t.phrase, t.head, t.attributes), prefix, clause_ok=not tail)
    # a second relative clause ('that somebody left open whose home is ...') would stack: the room goes 'in the X'
    room_frames = _ROOMS_IN if tail or " that somebody left " in out else _ROOMS_IN + _ROOMS_WHOSE
    room = _pick(rng, room_frames).format(sg.room) if sg.room else ""
    numeric_tail = bool(tail) and bool(_HAS_NUMBER.search(tail))
    hint_first = bool(hint) and not numeric_tail and rng.uniform() < 0.5
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
        out += (", " if (tail or room.startswith("whose")) else " ") + hint
    if t.relations:
        comma = bool(tail) or bool(hint) or room.startswith("whose")
        intro = ""
        if t.relations[0].type not in _NO_INTRO and rng.uniform() < 0.25:
            intro = "to be found "
            comma = comma or bool(room)
        out += ("," if comma else "") + " " + intro + _rel_chain(rng, t.relations)
    return _tidy(out)


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

# Finite predicates (after "that" or "where the <reading>") and participles (after "with a <reading>").
_FINITE = {
    "gt": ("tops {n}", "is in excess of {n}", "runs past {n}"),
    "ge": ("is not less than {n}", "is {n} or upwards", "is {n} at a minimum"),
    "lt": ("falls short of {n}", "is shy of {n}", "comes in under {n}"),
    "le": ("is not more than {n}", "tops out at {n}", "is capped at {n}"),
    "approx": ("hovers round {n}", "is in the region of {n}", "is {n} or thereabouts"),
}
_PARTICIPLE = {
    "gt": ("topping {n}", "in excess of {n}", "running past {n}"),
    "ge": ("not less than {n}", "of {n} or upwards", "of {n} at a minimum"),
    "lt": ("falling short of {n}", "shy of {n}", "coming in under {n}"),
    "le": ("not more than {n}", "topping out at {n}", "capped at {n}"),
    "approx": ("hovering round {n}", "in the region of {n}", "of {n} or thereabouts"),
}
_NAMES = {"temperature_c": "temperature", "humidity_pct": "humidity", "ndvi": "NDVI"}
_SUPER_ADJ = {
    ("temperature_c", "max"): ("toastiest", "most sweltering", "most blistering"),
    ("temperature_c", "min"): ("frostiest", "nippiest", "most glacial"),
    ("ndvi", "max"): ("most verdant", "most flourishing", "perkiest"),
    ("ndvi", "min"): ("droopiest", "most wilted", "most ailing"),
    ("humidity_pct", "max"): ("muggiest", "clammiest", "soggiest"),
    ("humidity_pct", "min"): ("most parched", "most arid", "most bone-dry"),
}


def _article(name: str) -> str:
    return "an" if name == "NDVI" or name[:1].lower() in "aeiou" else "a"


def _super_tails(name: str, comparator: str) -> tuple[str, ...]:
    art = _article(name)
    if comparator == "max":
        return (f"that tops the league for {name}", f"with {art} {name} second to none",
                f"whose {name} is the highest on record")
    return (f"that props up the league for {name}", f"with {art} {name} lower than all the rest",
            f"whose {name} is the lowest on record")


_DIGIT_WORDS = ("nought", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")


def _nought_words(txt: str) -> str:
    """'0.65' -> 'nought point six five', '0.05' -> 'nought point nought five', '0.6' -> 'nought point six'."""
    return "nought point " + " ".join(_DIGIT_WORDS[int(d)] for d in txt[2:])


def _number(rng, reading: str, value: float, approx: bool) -> tuple[str, float, str]:
    """(the number as written, its value, how): 'digits' ('40', '-4', '22,5', '0,65', '.65', 'minus 4', '−4'),
    'words' ('forty', 'minus four', 'twenty-two and a half', '22 and a half', 'nought point six five'), 'frac'
    ('65/100', an NDVI), or 'subzero' for a whole temperature below zero near which ('4 degrees below zero')."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    u = rng.uniform()
    if reading == "ndvi":
        if 0 < v < 1 and re.fullmatch(r"0\.\d\d?", txt):
            if u < 0.2:
                return _nought_words(txt), v, "words"
            if u < 0.35:
                return f"{round(v * 100)}/100", v, "frac"
            if u < 0.55:
                return txt.replace(".", ","), v, "digits"
            if u < 0.75:
                return txt[1:], v, "digits"
        elif "." in txt and u < 0.3:
            return txt.replace(".", ","), v, "digits"
        return txt, v, "digits"
    if reading not in ("temperature_c", "humidity_pct"):
        return txt, v, "digits"
    whole = int(abs(v))
    if v == int(v):
        if v < 0 and reading == "temperature_c" and approx and rng.uniform() < 0.4:
            mag = number_words(whole) if rng.uniform() < 0.5 else str(whole)
            return f"{mag} degree{'' if whole == 1 else 's'} below zero", v, "subzero"
        if u < 0.3 and abs(v) < 1000:
            return number_words(int(v)), v, "words"
        if v < 0 and u < 0.45:
            return f"minus {whole}", v, "digits"
        if v < 0 and u < 0.6:
            return f"\u2212{whole}", v, "digits"
        return txt, v, "digits"
    if re.fullmatch(r"-?\d+\.\d+", txt):
        if txt.endswith(".5") and u < 0.35:
            sign = "minus " if v < 0 else ""
            mag = number_words(whole) if whole < 100 and rng.uniform() < 0.5 else str(whole)
            return f"{sign}{mag} and a half", v, "words"
        if u < 0.65:
            return txt.replace(".", ","), v, "digits"
    return txt, v, "digits"


def _unit(rng, reading: str, how: str) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        if how == "subzero":
            return "", "c"
        if how == "words":
            return _pick(rng, (" degrees", " degrees C")), "c"
        return _pick(rng, ("°C", " °C", " deg C", " degrees C", "℃", " Celsius")), "c"
    if reading == "humidity_pct":
        if how == "words":
            return _pick(rng, (" per centum", " percent", " parts in the hundred")), "%"
        return _pick(rng, ("%", " % RH", " per centum", " parts in the hundred")), "%"
    return "", ""


def render_sensor_w(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('frostiest', 'most verdant', 'most bone-dry') or a tail ('that tops
    the league for temperature', 'with an NDVI lower than all the rest', 'whose humidity is the highest on
    record'); thresholds after the noun ('that tops 60 °C', 'where the humidity is not more than forty per centum',
    'with an NDVI of 0,65 or upwards', 'that hovers round four degrees below zero', 'with a temperature coming in
    under 22 and a half degrees')."""
    rd = c.reading
    name = _NAMES.get(rd, rd.replace("_", " "))
    if c.is_superlative:
        adj = _SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, _super_tails(name, c.comparator)), c
    n, value, how = _number(rng, rd, c.value, c.comparator == "approx")
    unit, code = _unit(rng, rd, how)
    if abs(value) == 1:
        unit = unit.replace("degrees", "degree")  # 'one degree C', 'minus 1 degree'

    named = rd not in ("temperature_c", "humidity_pct")  # NDVI (and any other reading) is always named
    frame = _pick(rng, ("where", "with") if named else ("that", "that", "where", "with"))
    if frame != "that" and how == "digits" and not named and rng.uniform() < 0.15:
        unit, code = "", ""  # the reading is named: the unit may go
    written = SensorConstraint(rd, c.comparator, value, code)
    if frame == "with":
        return "", f"with {_article(name)} {name} " + _pick(rng, _PARTICIPLE[c.comparator]).format(n=n + unit), written
    finite = _pick(rng, _FINITE[c.comparator]).format(n=n + unit)
    if frame == "that":
        return "", "that " + finite, written
    return "", f"where the {name} {finite}", written


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_w(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at the point (x, y) = (3.5, 2)', 'at posn 3.5E
    2N', 'at 3.5 along and 2 up', 'with an x of 3.5 and a y of 2', 'at easting 3.5, northing 2'."""
    return _pick(rng, (f"at the point (x, y) = ({x}, {y})", f"at posn {x}E {y}N", f"at {x} along and {y} up",
                       f"with an x of {x} and a y of {y}", f"at easting {x}, northing {y}"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _sep(res: list[str]) -> str:
    return ";" if any("," in r for r in res) else ","


def _list(rng, res: list[str]) -> str:
    """Goals in a running sentence: 'A, B and C' for bare goals, 'A, and also B' once a goal has words of its own
    after the noun, and semicolons ('A; B; and also C') where a goal has commas of its own."""
    if any("," in r for r in res):
        return "; ".join(res[:-1]) + "; and also " + res[-1]
    if all(re.fullmatch(r"the [\w'-]+(?: [\w'-]+)?", r) for r in res):
        return _listed(rng, res)
    return ", ".join(res[:-1]) + ", and also " + res[-1]


def _comma(goal: str) -> str:
    """A comma to close a goal that has commas of its own before the sentence goes on."""
    return "," if "," in goal else ""


_DISHES = ("THE ROBOT'S ROUND-THE-HOUSE TRAYBAKE", "WHISTLE-STOP HOTPOT", "TUESDAY TEATIME LASAGNE",
           "CLOCKWORK CRUMBLE", "SPRING-CLEAN SPONGE")
_TROT = ("pop over to", "nip across to", "whizz round to", "toddle along to")
_CHAT = ("then we nip across to", "once that's done, we whizz round to",
         "next – and this is the fun bit – we toddle along to")


def _cook(rng, res: list[str], order: str) -> str:
    """A television cookery-show host: a recipe card, or patter to camera."""
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"Right, lovely people, just the one thing on today's menu: pop over to {g}, and that's our "
                           "dish done. Easy peasy!",
                           f"Quickest recipe in the book, this – nip across to {g}, give it a wave, and we're "
                           "finished before the adverts."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"{_pick(rng, _DISHES)} – a recipe in {w} steps, serves one hungry robot"]
            lines += [f"Step {number_words(i + 1)}: {_pick(rng, _TROT)} {r}" for i, r in enumerate(res[:-1])]
            lines.append(f"Step {w}, to serve: dish up at {res[-1]}")
            lines.append("Do the steps in the order they're written, lovely people – skip ahead and the whole thing "
                         "curdles.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Right, lovely people, first we pop over to {res[0]}"
        s += "".join(f"{sep} {_pick(rng, _CHAT)} {r}" for r in res[1:-1])
        return s + (f"{sep} and to finish we dish up at {res[-1]}. Now, no shuffling the steps about – one after the "
                    "other, just like a soufflé!")
    if rng.uniform() < 0.5:
        body = "\n".join(f"◦ {r}" for r in res)
        return (f"MISE EN PLACE – {w} bits to get ready, any which way\n{body}\nGet these done in whichever order "
                "suits you, my loves – it all comes together in the end.")
    return (f"While that's baking, be a love and visit {_list(rng, res)}. Doesn't matter which you tackle first, "
            "darlings – it all comes out in the gravy!")


_ROCKS = ("Fastnet Rock", "Bishop Rock", "Skerryvore", "Longships", "Eddystone", "Muckle Flugga")
_MONTHS = ("January", "February", "March", "April", "May", "June", "July", "August", "September", "October",
           "November", "December")
_WINDS = ("sou'-westerly, fresh", "nor'-easterly, light airs", "westerly, strong", "southerly, moderate",
          "easterly, backing northerly")
_THENCE = ("Thence to", "Onward to", "Then bear away for")
_ORDERS = ("thence to", "then bear away for", "after which, on to")


def _keeper(rng, res: list[str], order: str) -> str:
    """A lighthouse keeper's logbook: timed log lines, standing orders, or a memo."""
    if len(res) == 1:
        g, c = res[0], _comma(res[0])
        return _pick(rng, (f"Log entry. Quiet watch, sea slight. One duty only for the relief: make for {g}{c} and "
                           "stand by there.",
                           f"Fog all night, horn sounding. Single errand logged: {g}. Nothing further."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            day, month = int(rng.integers(1, 29)), _pick(rng, _MONTHS)
            lines = [f"KEEPER'S LOG – {_pick(rng, _ROCKS)}, {day} {month}. Wind {_pick(rng, _WINDS)}."]
            mins = int(rng.integers(8, 16)) * 30
            for i, r in enumerate(res):
                stamp = f"{mins // 60:02d}{mins % 60:02d}"
                if i == 0:
                    lines.append(f"{stamp} Rounds begin. Make for {r}.")
                elif i < n - 1:
                    lines.append(f"{stamp} {_pick(rng, _THENCE)} {r}.")
                else:
                    lines.append(f"{stamp} Finish at {r}. Rounds complete.")
                mins += int(rng.integers(2, 10)) * 10
            lines.append("Stations to be worked in the order logged, each only after the one above it.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Wind {_pick(rng, _WINDS)}. Standing orders for the watch: first make for {res[0]}"
        s += "".join(f"{sep} {_pick(rng, _ORDERS)} {r}" for r in res[1:-1])
        return s + f"{sep} and lastly to {res[-1]}. Stations in the order given, none taken early."
    if rng.uniform() < 0.5:
        body = "\n".join(f"⚓ {r}" for r in res)
        return (f"STANDING ORDERS – {w} stations to visit, sequence at keeper's discretion\n{body}\nVisit as tide "
                "and weather allow; sequence immaterial.")
    return (f"Memo in the log: during the watch call at {_list(rng, res)} – whichever comes to hand first, no order "
            "laid down.")


_ORDINAL_TERMS = ("First", "Second", "Third", "Fourth", "Fifth", "Sixth", "Seventh", "Eighth", "Ninth", "Tenth")
_LETTERS = "abcdefghijklmnopqrstuvwxyz"
_ROMAN = ("i", "ii", "iii", "iv", "v", "vi", "vii", "viii", "ix", "x", "xi", "xii")
_SCHEDULES = ("SCHEDULE C – ATTENDANCE", "SCHEDULE B – ATTENDANCE OF THE ROBOT", "ANNEX D – ROUNDS",
              "ANNEX C – SEQUENCE OF ATTENDANCE")


def _lawyer(rng, res: list[str], order: str) -> str:
    """A lawyer drafting a clause: a lettered schedule with defined terms, or one long sentence."""
    if len(res) == 1:
        g, c = res[0], _comma(res[0])
        return _pick(rng, (f"The Robot shall attend upon {g}{c} and upon no other premises under this Agreement.",
                           f"Sole Obligation. The Robot shall forthwith attend upon {g}, whereupon this Agreement "
                           "shall be fully performed."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [_pick(rng, _SCHEDULES), "The Robot shall, in the following sequence, attend upon:"]
            for i, r in enumerate(res):
                letter = _LETTERS[i] if i < len(_LETTERS) else f"z{i}"
                if i == n - 1:
                    lines.append(f"({letter}) {r} (hereinafter the “Final Station”),")
                else:
                    term = _ORDINAL_TERMS[i] if i < len(_ORDINAL_TERMS) else "Further"
                    lines.append(f"({letter}) {r} (hereinafter the “{term} Station”);" + (" and" if i == n - 2 else ""))
            lines.append("provided always that no Station shall be attended before every Station preceding it in this "
                         "Schedule has been attended.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"The Robot shall first attend upon {res[0]}"
        s += "".join(f"{sep} and thereafter upon {r}" for r in res[1:-1])
        return s + (f"{sep} and finally upon {res[-1]}. Time is of the essence as to sequence, and each attendance "
                    "shall take place only upon completion of the attendance preceding it.")
    if rng.uniform() < 0.5:
        items = [f"({_ROMAN[i] if i < len(_ROMAN) else 'x' + str(i)}) {r};" for i, r in enumerate(res)]
        items[-1] = items[-1][:-1] + "."
        items[-2] += " and"
        body = "\n".join(items)
        return (f"The Robot shall attend upon each of the following {w} premises (together, the “Stations”), in such "
                f"order as the Robot may in its sole discretion determine:\n{body}\nNo Station shall take precedence "
                "over any other.")
    return (f"Notwithstanding anything to the contrary herein, the Robot may, in any sequence whatsoever, attend upon "
            f"{_list(rng, res)}, the order of attendance being of no consequence.")


_TEAMS = ("ROBOT ROVERS", "ATHLETICO AUTOMATA", "CIRCUIT CITY", "REAL ROBOTICA", "SPROCKET WANDERERS")
_RUNS = ("now he cuts inside to", "he plays it on to", "what a run, on to", "he's skipped past a defender, on to")


def _commentator(rng, res: list[str], order: str) -> str:
    """A radio football commentator: how the move was built, or live and breathless."""
    if len(res) == 1:
        g, c = res[0], _comma(res[0])
        return _pick(rng, (f"It's a one-man show tonight, folks! He's away, all the way to {g}{c} – and that's the "
                           "match!",
                           f"Just the one chance in this game and here it comes – he's straight through to {g}! What a "
                           "finish!"))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"{_pick(rng, _TEAMS)} v THE HOUSE – how the move was built, touch by touch",
                     f"First touch: {res[0]}!"]
            lines += [f"Touch number {number_words(i + 2)}: {r}!" for i, r in enumerate(res[1:-1])]
            lines.append(f"And the finish: {res[-1]} – GOAL!")
            lines.append("Every touch in its proper turn – you can't score till you've built the move!")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"And he's away down the wing – it's {res[0]}"
        s += "".join(f"{sep} {_pick(rng, _RUNS)} {r}" for r in res[1:-1])
        return s + (f"{sep} and he buries it at {res[-1]}! It had to go in that sequence, pass after pass, or the whole "
                    "move breaks down!")
    if rng.uniform() < 0.5:
        body = "\n".join(f"► {r}" for r in res)
        return (f"SET-PIECE OPTIONS – {w} runners, take your pick\n{body}\nAny of them could go first – the gaffer "
                "isn't fussed about the running order.")
    return (f"He's got options everywhere: {_list(rng, res)}! He can pick them off however he likes – the crowd "
            "couldn't care less which comes first!")


def render_instruction_w(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a cookery-show host, a lighthouse keeper, a
    lawyer, a football commentator). Goals stay in visiting order, each written once as rendered; strict texts say
    the order is fixed ('in the order they're written', 'skip ahead and the whole thing curdles', 'no shuffling the
    steps about', 'just like a soufflé', 'in the order logged', 'each only after the one above it', 'in the order
    given', 'none taken early', 'in the following sequence', 'no station shall be attended before every station
    preceding it', 'time is of the essence as to sequence', 'only upon completion of the attendance preceding it',
    'touch by touch', 'every touch in its proper turn', 'in that sequence, pass after pass', 'the whole move breaks
    down'), free ones say it is open ('any which way', 'whichever order suits you', 'it all comes together in the
    end', 'doesn't matter which you tackle first', 'comes out in the gravy', 'sequence at keeper's discretion', 'as
    tide and weather allow', 'sequence immaterial', 'whichever comes to hand first', 'no order laid down', 'in such
    order as the robot may in its sole discretion determine', 'no station shall take precedence over any other',
    'in any sequence whatsoever', 'of no consequence', 'take your pick', 'any of them could go first', 'isn't fussed
    about the running order', 'pick them off however he likes', 'couldn't care less which comes first'). A single
    goal gets neither kind of cue and no digit."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(4))
    return (_cook, _keeper, _lawyer, _commentator)[who](rng, res, order)
