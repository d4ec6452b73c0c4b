"""Held-out phrasings of set AA: goal, sensor, coordinate and instruction templates for the `unseen_aa` split.

Written by a helper that never read the parser (nor its lexicon, tagger, sensor reader, readings, agreement,
adapters, LLM or command code, nor the evaluation code), before any run of any reader on these sentences, with
only the interface of set W (`phrasings_w.py`) in view. Same four functions, arguments and meanings as the other
template sets. The style is four people who send a home robot round a house in voices of their own:

- a museum conservator's condition report: "CONDITION REPORT — ROUTE OF EXAMINATION", numbered findings "1.
  Examine ..., before anything else.", "2. Thereafter examine ....", "3. Examine ... last of all; survey then
  complete.", or "Proposed sequence of examination, viz.: first ...; thereafter ...; and finally ...."; fixed as
  "strictly in the numbered sequence", "no item is to be approached before the item preceding it", "the sequence
  is to be observed strictly", "no deviation from it is permitted"; free as "ITEMS NOTED FOR EXAMINATION (... in
  total; sequence at the examiner's discretion)" with "◇" bullets, "the order of inspection is immaterial", "in no
  prescribed sequence", "in whatever sequence proves convenient"; one goal as "Condition report, single object.";
- a sports-day PE teacher with a whistle and a megaphone: "*PHWEEEET!* RIGHT, EYES ON ME! THREE STATIONS, IN
  ORDER, NO SKIPPING!", "STATION ONE: ...!", "FINAL STATION: ...!", "SKIP ONE AND YOU'RE BACK TO THE START!", a
  countdown, or "OI! LISTEN UP! Sprint to ..., THEN leg it over to ..., and FINISH at ...! In that order, people,
  ONE AFTER THE OTHER!"; free as "CIRCUIT TIME! ... CONES, HIT THEM IN ANY ORDER YOU FANCY!" with "▲" bullets, "I'M
  NOT FUSSED WHICH ONE YOU TAG FIRST", "WHICHEVER YOU REACH FIRST", "nobody's keeping track of the order"; one goal
  as "ONE JOB AND ONE JOB ONLY: get yourself to ...!";
- a medieval-fantasy quest giver: "THE SCROLL OF TRIALS, to be undertaken in the order here set down", "The First
  Trial: seek thou ....", "The Last Trial: ....", "Let no trial be attempted ere the one before it be fulfilled.",
  or "Hear me, traveller: thy first trial lieth at ...; when that is done, thou shalt journey unto ...; and thy
  final trial awaiteth at ...."; free as "Hearken! The Oracle hath named ... relics, and the order of their finding
  mattereth not:" with "✦" bullets, "in whatsoever order thou wilt", "no relic taketh precedence over another",
  "as fortune guideth"; one goal as "but a single quest remaineth — seek thou ...";
- a bored teenager's voice note run through speech-to-text, lower case: "[voice memo, auto-transcribed] ok so like
  mum says you have to go to ... first and then after that go to ... and then last of all ... like literally in
  that exact order"; "don't like mix up the order"; free as "can you like go to ... oh and ... oh and also ...
  whatever order honestly it literally doesn't matter which one you do first i genuinely do not care"; one goal as
  "literally all you have to do is go to ... thats it".

Goals: attributes before the noun, in a bracket "(the teal wool variety)" or after "described as teal and wool";
states never before the goal's own noun but in an apposition ", currently switched on,", a clause "that happens to
be switched on" or a frame "in a switched-on state"; an anchor's states before its noun ("the switched-on drums")
or, for an anchor without relations of its own, "(currently open)"; the room as "in the X", "somewhere in the X",
"kept in the X", "within the X" or "in the room known as the X", always before any relation; relations in new
words ("a short hop from", "within easy reach of", "neighbouring", "right up against", "rubbing elbows with",
"immediately adjoining", "at the side of", "huddled beside", "just by", "stationed by", "balanced on", "sitting on
top of", "laid on", "underneath", "stashed below", "lurking beneath", "overhanging", "up above", "suspended over",
"inside", "contained in", "held within", "paired with", "accompanied by", "in one room with", "sharing quarters
with", "out in front of", "standing before", "just ahead of", "round the back of", "hidden behind", "across from",
"facing", "vis-a-vis", "left of", "off to the left of", "just left of", "right of", "off to the right of", "just
right of", besides the plain words), sometimes led in by ", located"; several relations joined by "and", ", plus"
or "and also"; an anchor with relations of its own takes them in a bracket "(the one next to the drums)", "(that
is, the ones next to the drums)", or between dashes "— the one next to the drums —" when more follows; deeper
down after ", the latter" when nothing follows in its bracket, else in square brackets "[the one behind ...]".

Readings: "clears", "sits north of", "goes beyond", "is ... and up", "doesn't dip below", "has a floor of", "sits
south of", "stays beneath", "is under the ... mark", "never goes above", "is ... or under", "has a ceiling of", "is
circa", "is ..., give or take", "is in the ballpark of", "is ... or so" (and their participles after "logging a
<reading>", their bare forms after "(<reading>: ...)"); frames "that ..." (temperatures only, always with a unit),
"whose <reading> ...", "logging a <reading> ...", "(<reading>: ...)"; readings named "temperature", "temp",
"humidity", "relative humidity", "NDVI", "NDVI value", "NDVI score"; units " degC", "ºC" (the ordinal sign), "°
Celsius", "°", " centigrade", " degrees centigrade", "%", " per cent", " pct", " percent" (none sometimes when the
reading is named); numbers as digits, "40.0", words, "a hundred and five", "negative 4", "negative four", "22½",
"twenty-two point five", NDVI as "0.65", "0.650", "zero point six five", "point six five", "sixty-five
hundredths", "six tenths"; superlatives "the balmiest", "the most scorching", "the most roasting", "the iciest",
"the most wintry", "the most arctic", "the most thriving", "the most vigorous", "the most luxuriant", "the most
languishing", "the feeblest", "the most poorly", "the dankest", "the most sodden", "the dewiest", "the most
desiccated", "the least dewy", "the most moisture-starved", "whose <reading> beats all comers", "with the top
<reading> of the lot", "that outdoes every rival on <reading>", "whose <reading> is the lowest of the bunch", "with
the bottom <reading> of the lot", "that trails every rival on <reading>". Coordinates: "pinned at x:3.5 / y:2",
"where x reads 3.5 and y reads 2", "at 3.5 m along the x-axis and 2 m along the y-axis", "at grid square [x 3.5 | y
2]", "at 3.5/2 (x/y)"; always x then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.template_text import attributes_and_states, number_words
from ragnav_jax.language.template_text import hyphenated as _hyphen
from ragnav_jax.language.template_text import plural as _plural
from ragnav_jax.language.template_text import tidy as _tidy
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Small helpers of this set's own


def _and(words: list[str]) -> str:
    return " and ".join(words)


def _ones(head: str) -> str:
    return "the ones" if _plural(head) else "the one"


def _a(word: str) -> str:
    return "an" if word[:1].lower() in "aeiou" or word.startswith("NDVI") else "a"


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "a short hop from", "within easy reach of", "neighbouring"),
    "next_to": ("next to", "right up against", "rubbing elbows with", "immediately adjoining"),
    "beside": ("beside", "at the side of", "huddled beside"),
    "by": ("by", "just by", "stationed by"),
    "on": ("on", "balanced on", "sitting on top of", "laid on"),
    "under": ("under", "underneath", "stashed below", "lurking beneath"),
    "above": ("above", "overhanging", "up above", "suspended over"),
    "in": ("in", "inside", "contained in", "held within"),
    "with": ("with", "paired with", "accompanied by"),
    "in_room_with": ("in the same room as", "in one room with", "sharing quarters with"),
    "in_front_of": ("in front of", "out in front of", "standing before", "just ahead of"),
    "behind": ("behind", "round the back of", "hidden behind"),
    "opposite": ("opposite", "across from", "facing", "vis-a-vis"),
    "left_of": ("left of", "off to the left of", "just left of"),
    "right_of": ("right of", "off to the right of", "just right of"),
}
_JOINS = (" and ", ", plus ", " and also ")
# words that read after ', located' (not 'located stationed by', 'located with', 'located sitting on top of')
_AFTER_LOCATED = {k: tuple(w for w in v if w.split()[0] in ("near", "a", "within", "next", "right", "immediately",
                                                             "beside", "at", "by", "just", "on", "under",
                                                             "underneath", "above", "up", "in", "inside", "out",
                                                             "round", "behind", "opposite", "across", "vis-a-vis",
                                                             "left", "off"))
                  for k, v in REL_WORDS.items()}


def _anchor_np(rng, t: Target, depth: int, more_follows: bool) -> str:
    """An anchor at `depth` (1: named by the goal itself). Attributes before the noun; states before it too, or
    '(currently open)' for an anchor without relations of its own. A depth-1 anchor's own relations go in a bracket
    ('(the one next to ...)', '(that is, the ones next to ...)') or between dashes when more of the goal follows
    ('— the one next to ... —'); deeper down after ', the latter' when nothing follows inside the enclosing
    bracket, else in square brackets ('[the one behind ...]')."""
    _, states = attributes_and_states(t)
    bracket_state = bool(states) and not t.relations and depth == 1 and rng.uniform() < 0.4
    out = "the "
    if states and not bracket_state:
        out += _hyphen(states) + " "
    out += t.phrase
    if bracket_state:
        out += f" (currently {_and(states)})"
    if not t.relations:
        return out
    inner = _rel_chain(rng, t.relations, depth + 1)
    if depth == 1:
        styles = ["bracket", "that_is"] + (["dash"] if more_follows else [])
        style = _pick(rng, styles)
        if style == "bracket":
            return out + f" ({_ones(t.head)} {inner})"
        if style == "that_is":
            return out + f" (that is, {_ones(t.head)} {inner})"
        return out + f" — {_ones(t.head)} {inner} —"
    if not more_follows:
        return out + f", the latter {inner}"
    return out + f" [{_ones(t.head)} {inner}]"


def _rel_chain(rng, rels: tuple[Relation, ...], depth: int = 1, located: bool = False) -> str:
    """Relations of one noun, each 'REL the anchor', joined. At depth 1 `more_follows` says whether another relation
    of the goal follows (dashes may close); below it, whether anything follows inside the enclosing bracket. With
    `located` the first relation's words read after ', located'."""
    out = ""
    for i, r in enumerate(rels):
        more = i + 1 < len(rels)
        words = _AFTER_LOCATED[r.type] if located and i == 0 else REL_WORDS[r.type]
        part = f"{_pick(rng, words)} {_anchor_np(rng, r.anchor, depth, more)}"
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

_ROOMS = ("in the {}", "in the {}", "somewhere in the {}", "kept in the {}", "within the {}",
          "in the room known as the {}")


def _state_text(rng, states: list[str], style: str, head: str) -> str:
    if style == "currently":
        return f", currently {_and(states)},"
    if style == "happens":
        return f" that {'happen' if _plural(head) else 'happens'} to be {_and(states)}"
    words = _and([s.replace(' ', '-') for s in states])
    return f" in {_a(words)} {words} state"


def _goal_np(rng, t: Target, prefix: str, clause_ok: bool, bracket_ok: bool) -> str:
    """The goal's own noun phrase: 'the teal wool lamp', 'the lamp (the teal wool variety)', 'the lamp described
    as teal and wool', then any states: 'the lamp, currently switched on,', 'the lamp that happens to be switched
    on', 'the lamp in a switched-on state'. With a superlative adjective (prefix) the attributes stay before the
    noun."""
    pre, states = attributes_and_states(t)
    lead = "the " + (f"{prefix} " if prefix else "")
    if not t.phrase.endswith(t.head):  # a phrase of another shape: written as given, anything missing after it
        missing = [a for a in t.attributes if a not in t.phrase.split()]
        if not missing:
            return lead + t.phrase
        forms = [f" described as {_and(missing)}"] + ([f" (the {' '.join(missing)} variety)"] if bracket_ok else [])
        return lead + t.phrase + _pick(rng, forms)
    head = t.phrase[len(t.phrase) - len(t.head):]
    attr_style = "before"
    if pre and not prefix:
        attr_style = _pick(rng, ("before", "before", "variety", "described") if bracket_ok else
                           ("before", "before", "described"))
    out = lead + (t.phrase if attr_style == "before" else head)
    if attr_style == "variety":
        out += f" (the {' '.join(pre)} variety)"
    elif attr_style == "described":
        out += f" described as {_and(pre)}"
    if states:
        opts = ["currently", "state"] + (["happens"] if clause_ok else [])
        out += _state_text(rng, states, _pick(rng, opts), t.head)
    return out


_NUMBERISH = re.compile(r"\d|½|\b(zero|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|thirteen|"
                        r"fourteen|fifteen|sixteen|seventeen|eighteen|nineteen|twenty|thirty|forty|fifty|sixty|"
                        r"seventy|eighty|ninety|hundred|point|tenths?|hundredths?)\b")


def render_goal_aa(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AA writes it: 'the teal wool lamp somewhere in the nursery', 'the lamp (the teal wool
    variety), currently switched on,', 'the lamp described as teal and wool that happens to be open', 'the iciest
    mini-fridge kept in the pantry', 'the guitar pinned at x:3.5 / y:2', 'the lamp in the nursery, rubbing elbows
    with the credenza (the one paired with the record player)'. The room comes before any relation (and before a
    superlative tail, which is read inside it); a coordinate hint comes after any number of a sensor tail;
    relations come last."""
    t = sg.target
    bracket_ok = not tail.startswith("(")  # never two brackets on end
    out = _goal_np(rng, Target(t.phrase, t.head, t.attributes), prefix, clause_ok=not tail, bracket_ok=bracket_ok)
    room = _pick(rng, _ROOMS).format(sg.room) if sg.room else ""
    numeric_tail = bool(tail) and bool(_NUMBERISH.search(tail))
    hint_first = bool(hint) and not numeric_tail and rng.uniform() < 0.5
    if hint_first:
        out += " " + hint
    if tail:
        if not numeric_tail:  # a superlative is read inside the room: the room first
            out += (f" {room}," if room else "") + f" {tail}"
        elif room and tail.startswith("logging") and rng.uniform() < 0.5:  # 'the X, that ...' would hang on the room
            out += f" {room}, {tail}"
        else:
            out += f" {tail}" + (f", {room}" if room else "")
    elif room:
        out += " " + room
    if hint and not hint_first:
        out += (", " if tail else " ") + hint
    if t.relations:
        located = not (tail or hint) and bool(_AFTER_LOCATED[t.relations[0].type]) and rng.uniform() < 0.25
        out += ", located " if located else ", " if (tail or hint or (room and rng.uniform() < 0.4)) else " "
        out += _rel_chain(rng, t.relations, located=located)
    return _tidy(out)


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

# Finite predicates (after "that" or "whose <reading>") and participles (after "logging a <reading>"); the bare
# form after "(<reading>: ...)" is the participle without a leading "of ".
_FINITE = {
    "gt": ("clears {n}", "sits north of {n}", "goes beyond {n}"),
    "ge": ("is {n} and up", "doesn't dip below {n}", "has a floor of {n}"),
    "lt": ("sits south of {n}", "stays beneath {n}", "is under the {n} mark"),
    "le": ("never goes above {n}", "is {n} or under", "has a ceiling of {n}"),
    "approx": ("is circa {n}", "is {n}, give or take", "is in the ballpark of {n}", "is {n} or so"),
}
_PARTICIPLE = {
    "gt": ("north of {n}", "clearing {n}", "beyond {n}"),
    "ge": ("of {n} and up", "not dipping below {n}", "floored at {n}"),
    "lt": ("south of {n}", "staying beneath {n}", "under the {n} mark"),
    "le": ("never going above {n}", "of {n} or under", "of {n} at the outside"),
    "approx": ("of circa {n}", "of {n}, give or take", "in the ballpark of {n}", "of {n} or so"),
}
_NAMES = {"temperature_c": ("temperature", "temp"), "humidity_pct": ("humidity", "relative humidity"),
          "ndvi": ("NDVI", "NDVI value", "NDVI score")}
_SUPER_ADJ = {
    ("temperature_c", "max"): ("balmiest", "most scorching", "most roasting"),
    ("temperature_c", "min"): ("iciest", "most wintry", "most arctic"),
    ("ndvi", "max"): ("most thriving", "most vigorous", "most luxuriant"),
    ("ndvi", "min"): ("most languishing", "feeblest", "most poorly"),
    ("humidity_pct", "max"): ("dankest", "most sodden", "dewiest"),
    ("humidity_pct", "min"): ("most desiccated", "least dewy", "most moisture-starved"),
}


def _super_tails(name: str, comparator: str) -> tuple[str, ...]:
    if comparator == "max":
        return (f"whose {name} beats all comers", f"with the top {name} of the lot",
                f"that outdoes every rival on {name}")
    return (f"whose {name} is the lowest of the bunch", f"with the bottom {name} of the lot",
            f"that trails every rival on {name}")


_DIGIT_WORDS = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")


def _ndvi(txt: str, u: float) -> tuple[str, str]:
    """An NDVI in (0, 1) with one or two decimals: '0.65', '0.650', 'zero point six five', 'point six five',
    'sixty-five hundredths', 'six tenths'."""
    digits = txt[2:]
    spoken = " ".join(_DIGIT_WORDS[int(d)] for d in digits)
    if u < 0.15:
        return f"zero point {spoken}", "words"
    if u < 0.3:
        return f"point {spoken}", "words"
    if u < 0.45:
        k = int(digits)
        unit = "tenth" if len(digits) == 1 else "hundredth"
        return f"{number_words(k)} {unit}{'' if k == 1 else 's'}", "words"
    if u < 0.6:
        return txt + "0" * (3 - len(digits)), "digits"
    return txt, "digits"


def _number(rng, reading: str, value: float) -> tuple[str, float, str]:
    """(the number as written, its value, how): 'digits' ('40', '40.0', '-4', 'negative 4', '22.5', '22½', '0.650')
    or 'words' ('forty', 'negative four', 'a hundred and five', 'twenty-two point five', 'zero point six five')."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    u = rng.uniform()
    if reading == "ndvi":
        if 0 < v < 1 and re.fullmatch(r"0\.\d\d?", txt):
            written, how = _ndvi(txt, u)
            return written, v, how
        return txt, v, "digits"
    if reading not in ("temperature_c", "humidity_pct"):
        return txt, v, "digits"
    whole = int(abs(v))
    neg = v < 0
    if v == int(v):
        if u < 0.3 and abs(v) < 1000:
            words = number_words(whole)
            if words.startswith("one hundred") and rng.uniform() < 0.5:
                words = "a" + words[3:]
            return (_pick(rng, ("negative ", "minus ")) if neg else "") + words, v, "words"
        if neg and u < 0.45:
            return f"negative {whole}", v, "digits"
        if 0.45 <= u < 0.57:
            return f"{txt}.0", v, "digits"
        return txt, v, "digits"
    if re.fullmatch(r"-?\d+\.5", txt):
        if u < 0.25:
            return ("-" if neg else "") + f"{whole}½", v, "digits"
        if u < 0.45 and whole < 100:
            sign = _pick(rng, ("negative ", "minus ")) if neg else ""
            return f"{sign}{number_words(whole)} point five", v, "words"
        if neg and u < 0.6:
            return f"negative {whole}.5", v, "digits"
    return txt, v, "digits"


def _unit(rng, reading: str, how: str, value: float) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        if how == "words":
            deg = "degree" if abs(value) == 1 else "degrees"
            return _pick(rng, (f" {deg} centigrade", " centigrade")), "c"
        return _pick(rng, (" degC", "ºC", "° Celsius", "°", " centigrade", " degrees centigrade")), "c"
    if reading == "humidity_pct":
        if how == "words":
            return _pick(rng, (" per cent", " percent")), "%"
        return _pick(rng, ("%", " per cent", " pct")), "%"
    return "", ""


def render_sensor_aa(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('iciest', 'most thriving', 'least dewy') or a tail ('whose
    temperature beats all comers', 'with the bottom NDVI of the lot', 'that trails every rival on humidity');
    thresholds after the noun ('that clears 60 degC', 'whose humidity never goes above forty per cent', 'logging an
    NDVI of circa 0.650', '(temp: south of negative 4ºC)', 'whose temperature is 22½°, give or take')."""
    rd = c.reading
    names = _NAMES.get(rd, (rd.replace("_", " "),))
    name = _pick(rng, names)
    if c.is_superlative:
        adj = _SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, _super_tails(name, c.comparator)), c
    n, value, how = _number(rng, rd, c.value)
    unit, code = _unit(rng, rd, how, value)
    frames = ("that", "whose", "logging", "colon") if rd == "temperature_c" else ("whose", "logging", "colon")
    frame = _pick(rng, frames)
    if frame != "that" and how == "digits" and code and rng.uniform() < 0.15:
        unit, code = "", ""  # the reading is named: the unit may go
    written = SensorConstraint(rd, c.comparator, value, code)
    if frame == "that":
        return "", "that " + _pick(rng, _FINITE[c.comparator]).format(n=n + unit), written
    if frame == "whose":
        return "", f"whose {name} " + _pick(rng, _FINITE[c.comparator]).format(n=n + unit), written
    part = _pick(rng, _PARTICIPLE[c.comparator]).format(n=n + unit)
    if frame == "logging":
        return "", f"logging {_a(name)} {name} {part}", written
    return "", f"({name}: {part.removeprefix('of ')})", written


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_aa(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'pinned at x:3.5 / y:2', 'where x reads 3.5 and y
    reads 2', 'at 3.5 m along the x-axis and 2 m along the y-axis', 'at grid square [x 3.5 | y 2]', 'at 3.5/2
    (x/y)'."""
    return _pick(rng, (f"pinned at x:{x} / y:{y}", f"where x reads {x} and y reads {y}",
                       f"at {x} m along the x-axis and {y} m along the y-axis", f"at grid square [x {x} | y {y}]",
                       f"at {x}/{y} (x/y)"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _semi(res: list[str]) -> str:
    """The separator before the next goal in a running sentence: a semicolon once any goal has commas."""
    return ";" if any("," in r for r in res) else ","


def _comma(goal: str) -> str:
    return "," if "," in goal else ""


_REPORTS = ("CONDITION REPORT — ROUTE OF EXAMINATION", "CONSERVATION SURVEY — SEQUENCE OF INSPECTION",
            "CONDITION CHECK — OBJECTS FOR EXAMINATION")


def _conservator(rng, res: list[str], order: str) -> str:
    """A museum conservator's condition report: numbered findings, or one hedged, abbreviated sentence."""
    n = len(res)
    if n == 1:
        g, c = res[0], _comma(res[0])
        return _pick(rng, (f"Condition report, single object. Finding: {g}{c} is to be examined in situ; no other "
                           "item requires attention at present (n.b. note any damage observed).",
                           f"Object for examination, viz. {g}. Kindly examine it and record its condition; nothing "
                           "further is requested, cf. the survey brief."))
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [_pick(rng, _REPORTS),
                     "Findings are to be taken strictly in the numbered sequence; n.b. no item is to be approached "
                     "before the item preceding it has been examined."]
            for i, r in enumerate(res):
                if i == 0:
                    lines.append(f"{i + 1}. Examine {r}, before anything else.")
                elif i < n - 1:
                    lines.append(f"{i + 1}. Thereafter examine {r}.")
                else:
                    lines.append(f"{i + 1}. Examine {r} last of all; survey then complete.")
            return "\n".join(lines)
        mids = "".join(f"; thereafter {r}" for r in res[1:-1])
        return (f"Proposed sequence of examination, viz.: first {res[0]}{mids}; and finally {res[-1]}. The sequence "
                "is to be observed strictly (cf. the handling protocol); no deviation from it is permitted.")
    w = number_words(n)
    if rng.uniform() < 0.5:
        body = "\n".join(f"◇ {r}" for r in res)
        return (f"ITEMS NOTED FOR EXAMINATION ({w} in total; sequence at the examiner's discretion)\n{body}\nN.b. "
                "the order of inspection is immaterial to the findings.")
    return (f"Further items for examination, in no prescribed sequence: {'; '.join(res[:-1])}; and {res[-1]}. It is "
            "recommended that the examiner proceed in whatever sequence proves convenient (cf. general survey "
            "notes).")


_DASHES = ("THEN leg it over to", "THEN jog on to", "THEN hustle over to")


def _pe_teacher(rng, res: list[str], order: str) -> str:
    """A sports-day PE teacher with a whistle and a megaphone: stations called out, or one shouted run."""
    n = len(res)
    if n == 1:
        g, c = res[0], _comma(res[0])
        return _pick(rng, (f"*PHWEEP!* ONE JOB AND ONE JOB ONLY: get yourself to {g}! MOVE IT, MOVE IT!",
                           f"RIGHT, YOU! Off to {g}{c} and that's the session! ON MY WHISTLE... *PHEEP!*"))
    W = number_words(n).upper()
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"*PHWEEEET!* RIGHT, EYES ON ME! {W} STATIONS, IN ORDER, NO SKIPPING!"]
            lines += [f"STATION {number_words(i + 1).upper()}: {r}!" for i, r in enumerate(res[:-1])]
            lines.append(f"FINAL STATION: {res[-1]}!")
            lines.append("Do them in that order — SKIP ONE AND YOU'RE BACK TO THE START! Ready? THREE... TWO... "
                         "ONE... GO!")
            return "\n".join(lines)
        sep = _semi(res)
        s = f"OI! LISTEN UP! Sprint to {res[0]}"
        s += "".join(f"{sep} {_pick(rng, _DASHES)} {r}" for r in res[1:-1])
        return s + f"{sep} and FINISH at {res[-1]}! In that order, people, ONE AFTER THE OTHER! Off you go!"
    if rng.uniform() < 0.5:
        body = "\n".join(f"▲ {r}" for r in res)
        return (f"CIRCUIT TIME! {W} CONES, HIT THEM IN ANY ORDER YOU FANCY!\n{body}\nMix 'em up however you want — "
                "I'M NOT FUSSED WHICH ONE YOU TAG FIRST! GO GO GO!")
    return (f"FREE-FOR-ALL, TEAM! Tag {'; '.join(res[:-1])}; and {res[-1]} — WHICHEVER YOU REACH FIRST, nobody's "
            "keeping track of the order! *PHEEP!*")


_ORDINALS = ("First", "Second", "Third", "Fourth", "Fifth", "Sixth", "Seventh", "Eighth", "Ninth", "Tenth")
_ONWARD = ("when that is done, thou shalt journey unto", "thence shalt thou fare unto",
           "and after, thy road leadeth to")


def _quest_giver(rng, res: list[str], order: str) -> str:
    """A medieval-fantasy quest giver: a scroll of trials, or a speech in archaic English."""
    n = len(res)
    if n == 1:
        g, c = res[0], _comma(res[0])
        return _pick(rng, (f"Hear me, traveller: but a single quest remaineth — seek thou {g}{c} and thy deeds shall "
                           "be sung in every tavern.",
                           f"The Oracle speaketh of but one relic: {g}. Go thither, brave soul, and thy quest is "
                           "done."))
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = ["THE SCROLL OF TRIALS, to be undertaken in the order here set down"]
            for i, r in enumerate(res[:-1]):
                lines.append(f"The {_ORDINALS[i] if i < len(_ORDINALS) else 'Next'} Trial: seek thou {r}.")
            lines.append(f"The Last Trial: seek thou {res[-1]}.")
            lines.append("Let no trial be attempted ere the one before it be fulfilled.")
            return "\n".join(lines)
        sep = _semi(res)
        s = f"Hear me, traveller: thy first trial lieth at {res[0]}"
        s += "".join(f"{sep} {_pick(rng, _ONWARD)} {r}" for r in res[1:-1])
        return s + (f"{sep} and thy final trial awaiteth at {res[-1]}. Let no trial be attempted ere the one before "
                    "it be fulfilled, for thus it is written.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"✦ {r}" for r in res)
        return (f"Hearken! The Oracle hath named {number_words(n)} relics, and the order of their finding mattereth "
                f"not:\n{body}\nGather them in whatsoever order thou wilt.")
    return (f"Go forth, brave one, and seek out {'; '.join(res[:-1])}; and {res[-1]}. No relic taketh precedence "
            "over another: take them as fortune guideth thy steps.")


_AND_THEN = ("and then after that go to", "and then once youre done there go to", "and then like after that")


def _teenager(rng, res: list[str], order: str) -> str:
    """A bored teenager's voice note through speech-to-text: lower case, run-ons, 'like', 'literally'."""
    n = len(res)
    memo = "[voice memo, auto-transcribed] "
    if n == 1:
        g = res[0]
        return memo + _pick(rng, (f"heyyy so literally all you have to do is go to {g} thats it like thats "
                                  "literally it bye",
                                  f"ok so um can you go to {g} like now please ok thanks"))
    if order == "strict":
        if rng.uniform() < 0.5:
            s = f"ok so like mum says you have to go to {res[0]} first"
            s += "".join(f" {_pick(rng, _AND_THEN)} {r}" for r in res[1:-1])
            return memo + s + (f" and then last of all {res[-1]} like literally in that exact order or she'll "
                               "literally lose it ok bye")
        s = f"um hi ok so first go to {res[0]}"
        s += "".join(f" and then {r}" for r in res[1:-1])
        return memo + s + (f" and then {res[-1]} last and like don't like mix up the order because she will "
                           "actually check ok thanks")
    s = f"hiii ok so can you like go to {res[0]}"
    s += "".join(f" oh and {r}" for r in res[1:-1])
    return memo + s + (f" oh and also {res[-1]} whatever order honestly it literally doesn't matter which one you do "
                       "first i genuinely do not care ok bye")


def render_instruction_aa(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a museum conservator, a PE teacher, a quest
    giver, a teenager's voice note). Goals stay in visiting order, each written once as rendered; strict texts say
    the order is fixed ('strictly in the numbered sequence', 'no item is to be approached before the item preceding
    it', 'the sequence is to be observed strictly', 'no deviation from it is permitted', 'in order, no skipping',
    'skip one and you're back to the start', 'in that order, people', 'one after the other', 'to be undertaken in
    the order here set down', 'let no trial be attempted ere the one before it be fulfilled', 'in that exact order',
    'don't like mix up the order'), free ones say it is open ('sequence at the examiner's discretion', 'the order of
    inspection is immaterial', 'in no prescribed sequence', 'in whatever sequence proves convenient', 'in any order
    you fancy', 'i'm not fussed which one you tag first', 'whichever you reach first', 'nobody's keeping track of the
    order', 'the order of their finding mattereth not', 'in whatsoever order thou wilt', 'no relic taketh precedence
    over another', 'as fortune guideth', 'whatever order honestly', 'literally doesn't matter which one you do
    first', 'i genuinely do not care'). A single goal gets neither kind of cue and no digit."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(4))
    return (_conservator, _pe_teacher, _quest_giver, _teenager)[who](rng, res, order)
