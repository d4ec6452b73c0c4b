"""Training phrasings of set train4: goal, sensor, coordinate and instruction templates for the `unseen_train4` split.

Written to teach the learned instruction readers one more pair of authors, by a helper that never read the readers
(parser, lexicon, tagger, sensor reader, adapters, readings, agreement or command code) nor the evaluation code nor
the held-out sets, with only the interface of `phrasings_x.py` and `phrasings_y.py` and the docstrings of the older
sets in view. Same four functions, arguments and meanings as the other template sets. Two people send the robot
round the house:

- an insurance claims adjuster writing a site-inspection checklist: "SITE INSPECTION CHECKLIST – Claim Ref.
  HX-40417 (escape of water)", "Insured premises: ...", "1. Item of interest: .... Condition noted: ________",
  "Adjuster's memorandum: the inspection shall commence at ...; proceed thereafter to ...; and conclude at ...";
  a fixed order as "items are to be inspected strictly in numbered sequence – an item taken out of sequence must
  be re-inspected", "in the order stated above and no other"; a free one as "ITEMS OF INTEREST (sequence at the
  adjuster's discretion)" with "☐" boxes, "no sequence is prescribed", "the order of inspection has no bearing on
  the claim"; one goal as "SITE INSPECTION – single item of interest: .... No further items scheduled.";
- a kindergarten teacher setting small children a treasure hunt: "★ TREASURE HUNT for the Ladybird Class ★",
  "First clue: tiptoe over to ...", "Next clue: hop like a bunny to ...", "Last clue: ... – that's where the
  treasure is hiding!", "First we creep like mice to ..., then we stomp like dinosaurs to ..., and last of all we
  find ..."; fixed as "we do the clues in the right order, just like lining up for snack – no pushing in!", "one
  after the other, the way the clues go"; free as "★ FIND-IT GAME ★" with "♡" hearts, "find them in any order you
  like – whichever one your eyes spot first!", "any one can be first – you choose!"; one goal as "Just one
  treasure today, my little stars: ...!".

Goals: attributes before the noun, as "(listed as teal and corduroy)" or ", the one that's teal and corduroy,";
states before the noun ("the switched-on lamp"), as "(status on arrival: switched on)" or "(and it's switched
on!)"; the room as "in the X", "located within the X" or "way over in the X", always before any relation; relations in
new words ("proximate to", "just a teeny walk from", "contiguous with", "cuddled up next to", "abreast of",
"playing buddies beside", "situated by", "hanging about by", "affixed on", "having a nap on", "subjacent to",
"hiding like a mouse under", "installed above", "up high like a bird above", "contained within", "tucked up cosy
in", "incorporating", "keeping company with", "housed in a common room with", "sharing a playroom with", "forward
of", "peeking out in front of", "to the rear of", "playing peekaboo behind", "diametrically opposite", "making
faces at", "left-adjacent to", "on the left flank of", "right-adjacent to", "on the right flank of", besides the
plain words); several relations joined by "and", ", and additionally" or ", plus"; an anchor with relations of
its own takes them in a bracket, "(cross-reference: the one next to the record player)" or "(yes, the one next to
the record player)".

Readings: above as "exceeds", "is in excess of", "is not at or below", "sits higher up than", "has jumped right
over", "is bigger than", "ranks above", "is warmer / damper / greener than"; at least as "is equal to or greater
than", "does not fall short of", "is not less than", "reaches ... or goes higher still", "is ... or even bigger",
"is at least as warm / damp / green as"; below as "falls short of", "is not at or above", "is smaller than", "sits
lower down than", "hasn't climbed up to ... yet", "ranks below", "is chillier / drier / less green than"; at most as
"is equal to or less than", "does not exceed", "is not greater than", "stops at ... and not a crumb more", "is ...
or even smaller", "is not any warmer / damper / greener than"; about as "is approximately", "is estimated at",
"hovers close to", "is just about", "is somewhere round"; frames "that ...", "whose humidity ...", "with a logged
NDVI that ...", "– the one whose temperature ... –" (closed when anything follows); units "°C", "degrees Celsius",
"℃", "degrees" (with words), none when the reading is named, "%", "percent", "per cent", "%RH", "percent relative
humidity"; numbers as digits, words ("forty", "minus eighteen"), "minus 18", "twenty-two and a half", "22 and a
half", "18 degrees of frost" (a temperature near -18), NDVI as "0.65", ".65", "an NDVI of 0.65", "nought point six
five". Superlatives "the most piping-hot", "the most blistering", "the most red-hot", "the most ice-cold", "the most
wintry", "the most shivery", "the most verdant", "the most vibrant", "the most sprouty", "the most faded", "the most
washed-out", "the most poorly-leaved", "the most waterlogged", "the most saturated", "the most drippy", "the most
desert-dry", "the least damp", "the most crackly-dry", "with the maximum recorded temperature", "whose NDVI no other
item exceeds", "at the top of the humidity ladder", "ranked highest of all for NDVI", "that wins the warm-as-toast
prize", "with the minimum recorded humidity", "whose temperature no other item falls below", "at the bottom of the
NDVI ladder", "ranked lowest of all for temperature", "that wins the dry-as-a-biscuit prize". Coordinates: "at
survey point x 3.5, y 2", "(location reference: x = 3.5, y = 2)", "at the magic spot where x says 3.5 and y says 2",
"at 3.5 metres along the x line and 2 metres along the y line"; always x then y.

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
_DIGIT_WORDS = ("nought", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")


def _and(items: list[str]) -> str:
    return " and ".join(items)


def _add(out: str, piece: str, comma: bool) -> str:
    """`piece` after `out`: after a comma when asked; an open dash aside ('– the one whose ...') is closed first."""
    out = out.rstrip()
    if "–" in out and out.count("–") % 2:
        return f"{out} – {piece}"
    return out + (", " if comma else " ") + piece


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "proximate to", "just a teeny walk from"),
    "next_to": ("next to", "contiguous with", "cuddled up next to"),
    "beside": ("beside", "abreast of", "playing buddies beside"),
    "by": ("by", "situated by", "hanging about by"),
    "on": ("on", "affixed on", "having a nap on"),
    "under": ("under", "subjacent to", "hiding like a mouse under"),
    "above": ("above", "installed above", "up high like a bird above"),
    "in": ("in", "contained within", "tucked up cosy in"),
    "with": ("with", "incorporating", "keeping company with"),
    "in_room_with": ("in the same room as", "housed in a common room with", "sharing a playroom with"),
    "in_front_of": ("in front of", "forward of", "peeking out in front of"),
    "behind": ("behind", "to the rear of", "playing peekaboo behind"),
    "opposite": ("opposite", "diametrically opposite", "making faces at"),
    "left_of": ("to the left of", "left-adjacent to", "on the left flank of"),
    "right_of": ("to the right of", "right-adjacent to", "on the right flank of"),
}
_JOINS = (" and ", ", and additionally ", ", plus ")


def _anchor_np(rng, t: Target, depth: int) -> str:
    """An anchor: attributes before the noun; states before it or, for a first-level anchor without relations of
    its own, as '(status on arrival: open)'; the anchor's own relations in a bracket of their own."""
    _, states = attributes_and_states(t)
    out = "the "
    bracket_state = bool(states) and depth == 1 and not t.relations and rng.uniform() < 0.3
    if states and not bracket_state:
        out += _hyphen(states) + " "
    out += t.phrase
    if bracket_state:
        out += f" (status on arrival: {_and(states)})"
    if t.relations:
        inner = _rel_chain(rng, t.relations, depth + 1)
        out += f" ({_pick(rng, ('cross-reference: the one', 'yes, the one'))} {inner})"
    return out


def _rel_chain(rng, rels: tuple[Relation, ...], depth: int = 1) -> str:
    out = ""
    for i, r in enumerate(rels):
        part = f"{_pick(rng, REL_WORDS[r.type])} {_anchor_np(rng, r.anchor, depth)}"
        out = part if i == 0 else out + _pick(rng, _JOINS) + part
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS = ("in the {}", "in the {}", "located within the {}", "way over in the {}")


def _goal_np(rng, t: Target, prefix: str, bare: bool) -> str:
    """The goal's own noun phrase: 'the teal corduroy bean bag', 'the bean bag (listed as teal and corduroy)', 'the
    bean bag, the one that's teal and corduroy,', 'the switched-on lamp', 'the lamp (status on arrival:
    switched on)', 'the lamp (and it's switched on!)'. With a superlative adjective (prefix) everything stays before
    the noun; with `bare` (a bracketed hint or a numeric sensor tail follows) no bracket and no aside is written."""
    pre, states = attributes_and_states(t)
    if not t.phrase.endswith(t.head):  # a phrase of another shape: written as given, anything missing in a bracket
        missing = [a for a in t.attributes if a not in t.phrase.split()]
        out = "the " + (f"{prefix} " if prefix else "") + t.phrase
        return out + (f" (listed as {_and(missing)})" if missing else "")
    head = t.phrase[len(t.phrase) - len(t.head):]
    attr_style = "before"
    if pre and not prefix and not bare:
        attr_style = _pick(rng, ("before", "before", "listed", "kid"))
    state_style = None
    if states:
        opts = ["before"] if (prefix or bare) else ["before", "noted", "cheer"]
        if attr_style == "listed":
            opts = ["before"]  # never two round brackets in a row
        state_style = _pick(rng, opts)
    out = "the " + (f"{prefix} " if prefix else "")
    if state_style == "before":
        out += _hyphen(states) + " "
    if attr_style == "before":
        out += t.phrase
    elif attr_style == "listed":
        out += f"{head} (listed as {_and(pre)})"
    else:
        out += head
    if state_style == "noted":
        out += f" (status on arrival: {_and(states)})"
    elif state_style == "cheer":
        out += f" (and it's {_and(states)}!)"
    if attr_style == "kid":
        out += f", the one that's {_and(pre)},"
    return out


_HAS_NUMBER = re.compile(r"\d|\b(" + "|".join(w for w in _ONES + _TENS if w and w != "one") +
                         r"|hundred|nought|half)\b")


def render_goal_train4(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "",
                       hint: str = "") -> str:
    """A goal as set train4 writes it: 'the teal corduroy bean bag way over in the nursery', 'the bean bag (listed
    as teal and corduroy)', 'the lamp (status on arrival: switched on)', 'the most ice-cold mini-fridge in the
    pantry', 'the guitar at survey point x 3.5, y 2', 'the lamp contiguous with the credenza (yes, the one
    incorporating the record player)'. The room comes before any relation (and before a superlative tail, which is
    read inside it); a coordinate hint comes after any number of a sensor tail; relations come last."""
    t = sg.target
    numeric_tail = bool(tail) and bool(_HAS_NUMBER.search(tail))
    out = _goal_np(rng, Target(t.phrase, t.head, t.attributes), prefix, hint.startswith("(") or numeric_tail)
    room = _pick(rng, _ROOMS).format(sg.room) if sg.room else ""
    hint_first = bool(hint) and not numeric_tail and not hint.startswith("(") and rng.uniform() < 0.5
    if hint_first:
        out += " " + hint
    last_is_tail = False
    if tail:
        if room and (not numeric_tail or rng.uniform() < 0.5):
            out = _add(out + " " + room, tail, False)
            last_is_tail = True
        else:
            out = _add(out, tail, False)
            last_is_tail = not room
            if room:
                out = _add(out, room, True)
    elif room:
        out += " " + room
    if hint and not hint_first:
        out = _add(out, hint, bool(tail) and last_is_tail)
    if t.relations:
        out = _add(out, _rel_chain(rng, t.relations), bool(tail or hint))
    return _tidy(out)


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

# Finite predicates, after "that", "whose <reading>", "with a logged <reading> that" or "– the one whose <reading>"
# (a dash aside the goal closes when anything follows it).
_FINITE = {
    "gt": ("exceeds {n}", "is in excess of {n}", "is not at or below {n}", "sits higher up than {n}",
           "has jumped right over {n}", "is bigger than {n}", "ranks above {n}"),
    "ge": ("is equal to or greater than {n}", "does not fall short of {n}", "is not less than {n}",
           "reaches {n} or goes higher still", "is {n} or even bigger"),
    "lt": ("falls short of {n}", "is not at or above {n}", "is smaller than {n}", "sits lower down than {n}",
           "hasn't climbed up to {n} yet", "ranks below {n}"),
    "le": ("is equal to or less than {n}", "does not exceed {n}", "is not greater than {n}",
           "stops at {n} and not a crumb more", "is {n} or even smaller"),
    "approx": ("is approximately {n}", "is estimated at {n}", "hovers close to {n}", "is just about {n}",
               "is somewhere round {n}"),
}
# Comparatives of the thing itself, after "that" only: the number carries its unit, or NDVI is named with it.
_OWN = {
    "temperature_c": {"gt": ("is warmer than {n}",), "ge": ("is at least as warm as {n}",),
                      "lt": ("is chillier than {n}",), "le": ("is not any warmer than {n}",)},
    "humidity_pct": {"gt": ("is damper than {n}",), "ge": ("is at least as damp as {n}",),
                     "lt": ("is drier than {n}",), "le": ("is not any damper than {n}",)},
    "ndvi": {"gt": ("is greener than {n}",), "ge": ("is at least as green as {n}",),
             "lt": ("is less green than {n}",), "le": ("is not any greener than {n}",)},
}
_NAMES = {"temperature_c": "temperature", "humidity_pct": "humidity", "ndvi": "NDVI"}
_SUPER_ADJ = {
    ("temperature_c", "max"): ("most piping-hot", "most blistering", "most red-hot"),
    ("temperature_c", "min"): ("most ice-cold", "most wintry", "most shivery"),
    ("ndvi", "max"): ("most verdant", "most vibrant", "most sprouty"),
    ("ndvi", "min"): ("most faded", "most washed-out", "most poorly-leaved"),
    ("humidity_pct", "max"): ("most waterlogged", "most saturated", "most drippy"),
    ("humidity_pct", "min"): ("most desert-dry", "least damp", "most crackly-dry"),
}
_PRIZES = {
    ("temperature_c", "max"): "warm-as-toast", ("temperature_c", "min"): "cold-as-a-snowman",
    ("ndvi", "max"): "green-as-a-frog", ("ndvi", "min"): "droopy-daisy",
    ("humidity_pct", "max"): "wet-as-a-puddle", ("humidity_pct", "min"): "dry-as-a-biscuit",
}


def _super_tails(rd: str, name: str, comparator: str) -> tuple[str, ...]:
    if comparator == "max":
        out = (f"with the maximum recorded {name}", f"whose {name} no other item exceeds",
               f"at the top of the {name} ladder", f"ranked highest of all for {name}")
    else:
        out = (f"with the minimum recorded {name}", f"whose {name} no other item falls below",
               f"at the bottom of the {name} ladder", f"ranked lowest of all for {name}")
    prize = _PRIZES.get((rd, comparator))
    return out + ((f"that wins the {prize} prize",) if prize else ())


def _number(rng, reading: str, value: float, approx: bool = False) -> tuple[str, float, str]:
    """(the number as written, its value, how): digits ('40', '-18', '.65', '0.65'), words ('forty', 'minus
    eighteen', 'twenty-two and a half', 'nought point six five'), 'minus 18', '22 and a half', or 'frost' for a
    negative whole temperature near which (approx) to be written 'N degrees of frost'."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    u = rng.uniform()
    if reading == "ndvi":
        if txt.startswith("0.") and u < 0.25:
            return "nought point " + " ".join(_DIGIT_WORDS[int(d)] for d in txt[2:]), v, "words"
        if txt.startswith("0.") and u < 0.6:
            return txt[1:], v, "digits"
        return txt, v, "digits"
    if reading not in ("temperature_c", "humidity_pct"):
        return txt, v, "digits"
    whole = int(abs(v))
    if v == int(v):
        if v < 0 and reading == "temperature_c" and approx and rng.uniform() < 0.35:
            return (number_words(whole) if rng.uniform() < 0.5 else str(whole)), v, "frost"
        if u < 0.3 and abs(v) < 1000:
            return number_words(int(v)), v, "words"
        if u < 0.55 and v < 0:
            return f"minus {whole}", v, "digits"
    elif abs(v) - whole == 0.5 and u < 0.4:
        sign = "minus " if v < 0 else ""
        if u < 0.2 and whole < 1000:
            return f"{sign}{number_words(whole)} and a half", v, "words"
        return f"{sign}{whole} and a half", v, "digits"
    elif v < 0 and u < 0.5:
        return f"minus {txt[1:]}", v, "digits"
    return txt, v, "digits"


def _unit(rng, reading: str, how: str) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        if how == "frost":
            return " degrees of frost", "c"
        if how == "words":
            return _pick(rng, (" degrees", " degrees Celsius")), "c"
        return _pick(rng, (" °C", "°C", " degrees Celsius", " ℃")), "c"
    if reading == "humidity_pct":
        if how == "words":
            return _pick(rng, (" percent", " per cent")), "%"
        return _pick(rng, ("%", " percent", " per cent", "%RH", " percent relative humidity")), "%"
    return "", ""


def render_sensor_train4(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('most ice-cold', 'most verdant', 'least damp') or a tail ('with the
    maximum recorded temperature', 'whose NDVI no other item falls below', 'at the top of the humidity ladder',
    'that wins the dry-as-a-biscuit prize'); thresholds after the noun ('that exceeds 60 °C', 'whose humidity is
    not greater than forty percent', 'with a logged NDVI that does not fall short of .65', 'that is greener than
    an NDVI of 0.65', 'whose temperature is approximately 18 degrees of frost', '– the one whose humidity is
    smaller than 22 and a half %RH' (a dash aside, closed by the goal when anything follows))."""
    rd = c.reading
    name = _NAMES.get(rd, rd.replace("_", " "))
    if c.is_superlative:
        adj = _SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.45:
            return _pick(rng, adj), "", c
        return "", _pick(rng, _super_tails(rd, name, c.comparator)), c
    n, value, how = _number(rng, rd, c.value, c.comparator == "approx")
    unit, code = _unit(rng, rd, how)
    own = _OWN.get(rd, {}).get(c.comparator)
    if own is not None and rng.uniform() < 0.25:  # 'that is warmer than 40 °C', 'that is greener than an NDVI of .6'
        if rd == "ndvi":
            num = f"an NDVI of {n}"
        elif rd == "humidity_pct" and rng.uniform() < 0.5:
            num = f"{n}{unit} humidity" if not unit.endswith(("humidity", "RH")) else n + unit
        else:
            num = n + unit
        return "", "that " + _pick(rng, own).format(n=num), SensorConstraint(rd, c.comparator, value, code)
    # NDVI (and any other reading) is always named, and so is a temperature given in degrees of frost
    named = rd not in ("temperature_c", "humidity_pct") or how == "frost"
    frame = _pick(rng, ("whose", "logged", "kid") if named else ("that", "that", "whose", "logged", "kid"))
    if frame != "that" and rd in ("temperature_c", "humidity_pct") and how == "digits" and rng.uniform() < 0.15:
        unit, code = "", ""  # the reading is named: the unit may go
    written = SensorConstraint(rd, c.comparator, value, code)
    finite = _pick(rng, _FINITE[c.comparator]).format(n=n + unit)
    if frame == "that":
        return "", "that " + finite, written
    if frame == "whose":
        return "", f"whose {name} {finite}", written
    if frame == "logged":
        return "", f"with a logged {name} that {finite}", written
    return "", f"– the one whose {name} {finite}", written


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_train4(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at survey point x 3.5, y 2', '(location reference:
    x = 3.5, y = 2)', 'at the magic spot where x says 3.5 and y says 2', 'at 3.5 metres along the x line and 2
    metres along the y line'."""
    return _pick(rng, (f"at survey point x {x}, y {y}", f"(location reference: x = {x}, y = {y})",
                       f"at the magic spot where x says {x} and y says {y}",
                       f"at {x} metres along the x line and {y} metres along the y line"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _sep(res: list[str]) -> str:
    return ";" if any("," in r for r in res) else ","


_PERILS = ("escape of water", "storm damage", "accidental damage", "fire and smoke", "subsidence", "theft")
_REMARKS = ("Condition noted: ________", "Photographs required.", "Condition noted: see photo log.",
            "Measurements to be taken.")


def _claim_ref(rng) -> str:
    letters = "".join(_pick(rng, "ABCDEFGHJKLMNPRSTUVWXYZ") for _ in range(2))
    return f"{letters}-{int(rng.integers(10000, 99999))}"


def _adjuster(rng, res: list[str], order: str) -> str:
    """An insurance claims adjuster: a site-inspection checklist or a memorandum."""
    if len(res) == 1:
        return _pick(rng, (f"SITE INSPECTION – single item of interest: {res[0]}. Condition noted: ________. "
                           "No further items scheduled.",
                           f"Claim file note: only one item of interest on this visit, namely {res[0]}. Nothing "
                           "else is to be inspected."))
    n = len(res)
    w = number_words(n)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"SITE INSPECTION CHECKLIST – Claim Ref. {_claim_ref(rng)} ({_pick(rng, _PERILS)})",
                     f"Items of interest: {w}, to be inspected strictly in numbered sequence."]
            lines += [f"{i + 1}. Item of interest: {r}. {_pick(rng, _REMARKS)}" for i, r in enumerate(res)]
            lines.append("An item taken out of sequence must be re-inspected; do not proceed to the next item until "
                         "the current one is signed off.")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Adjuster's memorandum: the inspection shall commence at {res[0]}"
        s += "".join(f"{sep} {_pick(rng, ('proceed thereafter to', 'continue on to', 'move on to'))} {r}"
                     for r in res[1:-1])
        return s + (f"{sep} and conclude at {res[-1]}. The items are to be inspected in the order stated above and "
                    "no other.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"☐ {r}" for r in res)
        return (f"ITEMS OF INTEREST – Claim Ref. {_claim_ref(rng)} ({w} items, sequence at the adjuster's "
                f"discretion)\n{body}\nNo sequence is prescribed: tick each box as the item is inspected, in "
                "whatever order is convenient on site.")
    return (f"For this claim the items of interest are {_listed(rng, res)} – {w} items in all. The order of "
            "inspection has no bearing on the claim; take them as convenient.")


_CLASSES = ("Ladybird", "Sunflower", "Caterpillar", "Rainbow", "Little Owls")
_MOVES = ("hop like a bunny to", "stomp like a dinosaur over to", "waddle like a penguin to", "flap like a butterfly "
          "to", "slither like a snake to", "gallop like a pony to")
_ORDINAL_CLUES = ("First", "Second", "Third", "Fourth", "Fifth", "Sixth", "Seventh", "Eighth", "Ninth", "Tenth")


def _teacher(rng, res: list[str], order: str) -> str:
    """A kindergarten teacher: a treasure hunt for small children."""
    if len(res) == 1:
        return _pick(rng, (f"Just one treasure today, my little stars: {res[0]}! Go and find it, quiet as a mouse.",
                           f"Shh, boys and girls – Teddy has hidden only one surprise, and it's at {res[0]}. Off "
                           "you go!"))
    n = len(res)
    w = number_words(n)
    cls = _pick(rng, _CLASSES)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"★ TREASURE HUNT for the {cls} Class ★"]
            for i, r in enumerate(res[:-1]):
                move = "tiptoe over to" if i == 0 else _pick(rng, _MOVES)
                lines.append(f"{_ORDINAL_CLUES[i] if i < len(_ORDINAL_CLUES) else 'Next'} clue: {move} {r}.")
            lines.append(f"Last clue: {_pick(rng, _MOVES)} {res[-1]} – that's where the treasure is hiding!")
            lines.append("We do the clues in the right order, just like lining up for snack – no pushing in!")
            return "\n".join(lines)
        sep = _sep(res)
        s = f"Okay, my little explorers, ears open! First we creep like mice to {res[0]}"
        s += "".join(f"{sep} then we {_pick(rng, _MOVES)} {r}" for r in res[1:-1])
        return s + (f"{sep} and last of all we find {res[-1]}. One after the other, the way the clues go – no "
                    "jumping ahead!")
    if rng.uniform() < 0.5:
        body = "\n".join(f"♡ {r}" for r in res)
        return (f"★ FIND-IT GAME for the {cls} Class ★ – {w} treasures to spot!\n{body}\nYou can find them in any "
                "order you like – whichever one your eyes spot first!")
    return (f"Treasure time, sweet peas! Can you find {_listed(rng, res)}? That's {w} treasures, and any one can be "
            "first – you choose!")


def render_instruction_train4(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of two people (an insurance claims adjuster, a kindergarten
    teacher). Goals stay in visiting order; strict texts say the order is fixed ('strictly in numbered sequence',
    'out of sequence', 'in the order stated above and no other', 'in the right order', 'one after the other'),
    free ones say it is open ('sequence at the adjuster's discretion', 'no sequence is prescribed', 'whatever order
    is convenient', 'has no bearing on the claim', 'in any order you like', 'any one can be first')."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(2))
    return (_adjuster, _teacher)[who](rng, res, order)
