"""Held-out phrasings of set T: goal, sensor, coordinate and instruction templates for the `unseen_t` split.

Written by a helper that never read the parser (nor its lexicon, tagger, readings, agreement or command code, nor
the evaluation code), before any run of any reader on these sentences, with only the interface of the earlier
template sets in view (`phrasings_s.py` and the docstrings of the others). Same four functions, arguments and
meanings as the other template sets. The style is four people who send a home robot round a house in the layout
and words of their own pastime or job:

- a knitter writing the errand up as a knitting pattern: "HALLWAY COWL – a pattern by Auntie Bev", "Needles: 4 mm
  · Tension: not critical", "Cast on at ...", "Row 2: knit across to ...", "Cast off at ...", "Happy knitting! Bev
  x", or chatty ("Think of this one like a scarf: cast on at ..., knit along to ..., and cast off at ..."); a
  fixed order as "work the rows in turn, as written – drop one and the whole thing unravels", "row by row, as
  written"; a free one as "GRANNY-SQUARE THROW", "Squares to make (three):" with "✿" bullets, "make the squares in
  whichever sequence takes your fancy – they're all stitched together at the end anyway", "knit them up as the
  mood takes you";
- a pub band's frontman with the set list: "THE RUSTY HINGES – SET LIST (Fri, the Crown, doors 8pm)", "1. ...",
  "ENCORE: ...", "we open with ..., segue into ..., and bring it home with ..."; fixed as "top to bottom, exactly
  as the list reads – no swapping songs round", "song order is locked in, same as rehearsal"; free as "open mic
  night", "shuffle the set however you fancy", "play 'em as the mood strikes";
- a birdwatcher's field notes: "SIGHTINGS LOG – Saturday" with clock times ("06:40  the ..."), "First hide: ... From
  there round the boardwalk to ..., on past the reed beds to ... and finish up at ... for a flask of tea", "Good
  birding!"; fixed as "walk
  the hides in sequence – doubling back just flushes everything", "in the order logged"; free as "Target list"
  with "☐" boxes, "no set walk – tick them off as you stumble on them", "whichever turns up first, go for it";
- a software tester's bug ticket or QA ask: "BUG-2291: Robot stalls on a multi-stop route", "Severity: minor |
  Build: 4.2.1", "Steps to reproduce:", "1) Send the robot to ...", "Expected: ... Actual: ...", "TICKET #482 –
  nav smoke test", "Stops to cover (3):"; fixed as "the repro is order-sensitive, so run the steps in the listed
  order", "same sequence every run, please – it's a regression check"; free as "order has no bearing on the
  result, we just need coverage", "visit them in arbitrary order".

Goals: attributes before the noun, split round it ("the teal bean bag (corduroy as well)"), in a "(field marks:
teal, corduroy)" or "(distinguishing features: teal, corduroy)" bracket, or after it with an ampersand (", teal &
corduroy,"); states before the noun ("the switched-on lamp"), as "(last seen switched on)", ", which should be
switched on,", ", reportedly switched on," or "(state = switched on)"; the room as "in the X", "round in the X" or
"across in the X", always before any relation; relations in new words ("within spitting distance of", "in the
vicinity of", "just a few feet from", "rubbing shoulders with", "squeezed in next to", "cosied up to", "standing
beside", "wedged beside", "loitering by", "kept by", "stood on", "plonked on top of", "parked on", "stuffed under",
"shoved underneath", "sitting below", "up above", "screwed to the wall above", "looming over", "crammed into",
"living inside", "shut inside", "decked out with", "kitted out with", "set up with", "in the room where you'll find",
"in one and the same room as", "just in front of", "sat in front of", "skulking behind", "at the rear of", "staring
across at", "on the far side of the room from", "just left of", "a touch to the left of", "just right of", "a touch
to the right of"); an anchor with relations of its own takes them in square brackets ("the credenza [next to the
record player]") or in a "(found ...)" bracket ("the credenza (found next to the record player)"). Readings:
"strictly above", "already past", "a notch above", "that has shot past", "that has risen above", "... or anything
above it", "... at a bare minimum", "that hits ... or goes beyond it", "strictly below", "a notch below", "not yet up
to", "that has fallen below", "that stops short of", "... or anything below it", "not a hair over", "that doesn't
get past", "... or close to it", "not far off", "..., a bit either way"; frames "whose temperature reading is ...",
"with its NDVI figure at ...", "(humidity-wise: ...)"; units "°C", "degrees", "degrees Celsius", "degrees on the
Celsius scale", "%", "per cent", "percent", "% rel. humidity"; numbers as digits, decimals, ".6", "0.60", words,
"minus" and the typeset minus sign ("−18"); superlatives "the fieriest", "the most scorching", "the most glacial",
"the most arctic", "the most vigorous", "the sprightliest", "the scraggliest", "the most bedraggled", "the
dankest", "the most bone-dry", "with the high score on temperature", "that leads the pack on NDVI", "with a
temperature second to none", "that brings up the rear on NDVI", "that's bottom of the league on temperature", "at
the foot of the humidity rankings". Coordinates: "with x at 3.5 and y at 2", "(dropped pin: x 3.5, y 2)", "at
x-position 3.5, y-position 2", "where x comes to 3.5 and y to 2"; always x then y.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.template_text import attributes_and_states as split_attributes
from ragnav_jax.language.template_text import hyphenated as _hyphen
from ragnav_jax.language.template_text import number_words
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Small helpers of this set's own


_ONES = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
         "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen")
_TENS = ("", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety")


def _tidy(s: str) -> str:
    s = " ".join(s.split())
    for a, b in ((",,", ","), (", ,", ","), (", (", " ("), (", [", " ["), (",)", ")"), (",]", "]")):
        s = s.replace(a, b)
    while s.endswith(","):
        s = s[:-1].rstrip()
    return s


# ----------------------------------------------------------------------------------------------------
# Relations and anchors

REL_WORDS = {
    "near": ("near", "within spitting distance of", "in the vicinity of", "just a few feet from"),
    "next_to": ("next to", "rubbing shoulders with", "squeezed in next to", "cosied up to"),
    "beside": ("beside", "standing beside", "wedged beside"),
    "by": ("by", "loitering by", "kept by"),
    "on": ("on", "stood on", "plonked on top of", "parked on"),
    "under": ("under", "stuffed under", "shoved underneath", "sitting below"),
    "above": ("above", "up above", "screwed to the wall above", "looming over"),
    "in": ("in", "crammed into", "living inside", "shut inside"),
    "with": ("with", "decked out with", "kitted out with", "set up with"),
    "in_room_with": ("in the same room as", "in the room where you'll find", "in one and the same room as"),
    "in_front_of": ("in front of", "just in front of", "sat in front of"),
    "behind": ("behind", "skulking behind", "at the rear of"),
    "opposite": ("opposite", "staring across at", "on the far side of the room from"),
    "left_of": ("to the left of", "just left of", "a touch to the left of"),
    "right_of": ("to the right of", "just right of", "a touch to the right of"),
}
_JOINS = (" and ", " and also ", ", plus ")


def _np(rng, t: Target, anchor: bool) -> str:
    """'the teal bean bag', 'the switched-on lamp', 'the lamp (last seen switched on)', and, for an anchor with
    relations of its own, those relations in square brackets or a '(found ...)' bracket."""
    pre, states = split_attributes(t)
    head_words = t.phrase[len(t.phrase) - len(t.head):] if t.phrase.endswith(t.head) else t.head
    out = "the "
    state_style = None
    if states:
        opts = ["before", "lastseen", "eq"] if anchor else ["before", "lastseen", "should", "reported", "eq"]
        state_style = _pick(rng, opts)
    attr_style = "before"
    if pre and not anchor:
        opts = ["before", "before", "marks"] + (["too", "amp"] if len(pre) > 1 else [])
        attr_style = _pick(rng, opts)
    if attr_style in ("marks", "too") and state_style in ("lastseen", "eq"):
        state_style = "before" if len(states) == 1 else "should"  # one bracket after the noun is enough
    if state_style == "before":
        out += _hyphen(states) + " "
    if attr_style == "before":
        out += t.phrase
    elif attr_style == "too":
        out += f"{pre[0]} {head_words} ({' and '.join(pre[1:])} as well)"
    elif attr_style == "marks":
        out += f"{head_words} ({_pick(rng, ('field marks', 'distinguishing features'))}: {', '.join(pre)})"
    else:
        out += f"{head_words}, {' & '.join(pre)},"
    if state_style == "lastseen":
        out += f" (last seen {' and '.join(states)})"
    elif state_style == "eq":
        out += f" (state = {' and '.join(states)})"
    elif state_style == "should":
        out += f", which should be {' and '.join(states)},"
    elif state_style == "reported":
        out += f", reportedly {' and '.join(states)},"
    if anchor and t.relations:
        inner = _rel_chain(rng, t.relations)
        # never two round brackets in a row, nor one inside another
        square = rng.uniform() < 0.5 or state_style in ("lastseen", "eq") or "(" in inner
        out += f" [{inner}]" if square else f" (found {inner})"
    return out


def _rel_chain(rng, rels: tuple[Relation, ...]) -> str:
    out = ""
    for i, r in enumerate(rels):
        part = f"{_pick(rng, REL_WORDS[r.type])} {_tidy(_np(rng, r.anchor, True))}"
        if i == 0:
            out = part
        else:
            join = _pick(rng, _JOINS)
            out = (out.rstrip(",") if join.startswith(",") else out) + join + part
    return out


# ----------------------------------------------------------------------------------------------------
# Goals

_ROOMS = ("in the {}", "in the {}", "round in the {}", "across in the {}")


def render_goal_t(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set T writes it: 'the teal bean bag (corduroy as well) round in the nursery', 'the bean bag (field
    marks: teal, corduroy)', 'the lamp, reportedly switched on,', 'the most glacial fridge across in the pantry', 'the
    guitar (dropped pin: x 3.5, y 2)', 'the lamp squeezed in next to the credenza [set up with the record player]'. The
    room comes before any relation (and before a superlative tail, which is read inside it); relations come last."""
    t = sg.target
    if prefix:  # a superlative adjective: the attributes stay before the noun with it
        pre, states = split_attributes(t)
        out = f"the {prefix} {t.phrase}"
        if states:
            out += f" (last seen {' and '.join(states)})"
    else:
        out = _np(rng, Target(t.phrase, t.head, t.attributes), anchor=False)
    if hint:
        out += " " + hint
    room = _pick(rng, _ROOMS).format(sg.room) if sg.room else ""
    if tail:
        superlative = not _HAS_NUMBER.search(tail)  # a superlative tail is read inside the room: room first
        if room and (superlative or rng.uniform() < 0.5):
            out += f" {room} {tail}"
        else:
            out += f" {tail}" + (f", {room}" if room else "")
    elif room:
        out += " " + room
    if t.relations:
        out += " " + _rel_chain(rng, t.relations)
    return _tidy(out)


_HAS_NUMBER = re.compile(r"\d|\u2212|\b(" + "|".join(w for w in _ONES + _TENS if w) + r"|hundred)\b")


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

# Complements: after "is", after "with its <reading>", inside "(<reading>-wise: ...)".
_COMPLEMENT = {
    "gt": ("strictly above {n}", "already past {n}", "a notch above {n}"),
    "ge": ("{n} or anything above it", "{n} at a bare minimum"),
    "lt": ("strictly below {n}", "a notch below {n}", "not yet up to {n}"),
    "le": ("{n} or anything below it", "not a hair over {n}"),
    "approx": ("{n} or close to it", "not far off {n}", "{n}, a bit either way"),
}
# Finite predicates: after "that" or "whose <reading>".
_FINITE = {
    "gt": ("has shot past {n}", "has risen above {n}"),
    "ge": ("hits {n} or goes beyond it", "reads {n} or anything above it"),
    "lt": ("has fallen below {n}", "stops short of {n}"),
    "le": ("doesn't get past {n}", "reads {n} or anything below it"),
    "approx": ("reads {n} or close to it", "isn't far off {n}", "sits at {n}, a bit either way"),
}
_NAMES = {"temperature_c": ("temperature", "temperature reading"), "humidity_pct": ("humidity", "humidity level"),
          "ndvi": ("NDVI", "NDVI figure", "NDVI number")}
_BASE = {"temperature_c": "temperature", "humidity_pct": "humidity", "ndvi": "NDVI"}
_SUPER_ADJ = {
    ("temperature_c", "max"): ("warmest", "fieriest", "most scorching"),
    ("temperature_c", "min"): ("coldest", "most glacial", "most arctic"),
    ("ndvi", "max"): ("healthiest", "most vigorous", "sprightliest"),
    ("ndvi", "min"): ("least healthy", "scraggliest", "most bedraggled"),
    ("humidity_pct", "max"): ("most humid", "dankest"),
    ("humidity_pct", "min"): ("driest", "most bone-dry"),
}


def _super_tails(name: str, comparator: str) -> tuple[str, ...]:
    if comparator == "max":
        art = {"temperature": "a ", "NDVI": "an "}.get(name, "")
        return (f"with the high score on {name}", f"that leads the pack on {name}", f"with {art}{name} second to none")
    return (f"that brings up the rear on {name}", f"that's bottom of the league on {name}",
            f"at the foot of the {name} rankings")


def _number(rng, reading: str, value: float) -> tuple[str, float]:
    """(the number as written, its value): digits, a decimal, '.6' or '0.60', words, 'minus', the minus sign '−'."""
    txt = _fmt_value(reading, value)
    v = float(txt)
    if reading == "ndvi":
        u = rng.uniform()
        if u < 0.25:
            return f"{v:.2f}", v
        if u < 0.45 and txt.startswith("0."):
            return txt[1:], v
        return txt, v
    u = rng.uniform()
    if v == int(v):
        if u < 0.2 and abs(v) < 1000:
            return number_words(int(v)), v
        if u < 0.3:
            txt = f"{v:.1f}"
    if v < 0 and rng.uniform() < 0.5:
        return (f"minus {txt[1:]}" if rng.uniform() < 0.5 else "\u2212" + txt[1:]), v
    return txt, v


def _unit(rng, reading: str, n: str) -> tuple[str, str]:
    """(text after the number, unit code)."""
    worded = n[-1].isalpha()
    if reading == "temperature_c":
        opts = (" degrees", " degrees Celsius", " degrees on the Celsius scale")
        return _pick(rng, opts if worded else ("°C", " °C", *opts)), "c"
    if reading == "humidity_pct":
        opts = (" per cent", " percent")
        return _pick(rng, opts if worded else ("%", "% rel. humidity", *opts)), "%"
    return "", ""


def render_sensor_t(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('fieriest', 'most glacial', 'scraggliest') or a tail ('with the high
    score on temperature', 'that's bottom of the league on NDVI'); thresholds after the noun ('that has shot past
    60 °C',
    'whose temperature reading is 40 or anything above it', 'with its humidity level not a hair over 30 per cent',
    '(NDVI-wise: .65 or close to it)', 'that stops short of −18 degrees')."""
    rd = c.reading
    base = _BASE.get(rd, rd.replace("_", " "))
    name = _pick(rng, _NAMES[rd]) if rd in _NAMES else base
    if c.is_superlative:
        adj = _SUPER_ADJ.get((rd, c.comparator))
        if adj is not None and rng.uniform() < 0.5:
            return _pick(rng, adj), "", c
        return "", _pick(rng, _super_tails(base, c.comparator)), c
    n, value = _number(rng, rd, c.value)
    unit, code = _unit(rng, rd, n)
    named = rd not in ("temperature_c", "humidity_pct")  # NDVI (and any other reading) is always named
    frame = _pick(rng, ("whose", "its", "wise") if named else ("that", "that", "whose", "its", "wise"))
    if frame != "that" and rd == "temperature_c" and rng.uniform() < 0.25:
        unit, code = "", ""  # the reading is named: the unit may go
    num = n + unit
    written = SensorConstraint(rd, c.comparator, value, code)
    if frame == "that":
        return "", "that " + _pick(rng, _FINITE[c.comparator]).format(n=num), written
    if frame == "whose":
        if rng.uniform() < 0.5:
            return "", f"whose {name} is " + _pick(rng, _COMPLEMENT[c.comparator]).format(n=num), written
        return "", f"whose {name} " + _pick(rng, _FINITE[c.comparator]).format(n=num), written
    if frame == "its":
        comp = _pick(rng, _COMPLEMENT[c.comparator])
        return "", f"with its {name} " + ("at " if comp.startswith("{n}") else "") + comp.format(n=num), written
    return "", f"({base}-wise: " + _pick(rng, _COMPLEMENT[c.comparator]).format(n=num) + ")", written


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_t(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'with x at 3.5 and y at 2', '(dropped pin: x 3.5, y
    2)', 'at x-position 3.5, y-position 2', 'where x comes to 3.5 and y to 2'."""
    return _pick(rng, (f"with x at {x} and y at {y}", f"(dropped pin: x {x}, y {y})",
                       f"at x-position {x}, y-position {y}", f"where x comes to {x} and y to {y}"))


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _cap(s: str) -> str:
    return s[:1].upper() + s[1:]


def _listed(rng, res: list[str]) -> str:
    """Goals in a running sentence: commas, or semicolons where a goal has commas of its own."""
    if any("," in r for r in res):
        return "; ".join(res[:-1]) + "; and " + res[-1]
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


def _count(n: int) -> str:
    return number_words(n)


_KNITTERS = ("Auntie Bev", "Nana Joan", "Marguerite", "Dot from the Tuesday group")
_PATTERNS = ("HALLWAY COWL", "ROBOT RAMBLE SCARF", "LANDING LEG-WARMERS", "STAIRCASE STRIPE SNOOD")


def _knitter(rng, res: list[str], order: str) -> str:
    """A knitter writing the errand up as a knitting pattern."""
    who = _pick(rng, _KNITTERS)
    first = who.split()[-1] if who.startswith(("Auntie", "Nana")) else who.split()[0]
    if len(res) == 1:
        return _pick(rng, (f"Just a quick one today, pet: a single motif, worked at {res[0]}. Happy knitting! "
                           f"{first} x",
                           f"Easy pattern, this – nothing to it but to cast on and off at {res[0]}. Love, {first} x"))
    n = len(res)
    if order == "strict":
        if rng.uniform() < 0.5:
            needles = _pick(rng, ("4 mm", "3.25 mm", "5mm", "6½ mm"))
            lines = [f"{_pick(rng, _PATTERNS)} – a pattern by {who}", f"Needles: {needles} · Tension: not critical",
                     f"Cast on at {res[0]}."]
            lines += [f"Row {i}: {_pick(rng, ('knit across to', 'purl back to', 'work along to'))} {r}."
                      for i, r in enumerate(res) if 0 < i < n - 1]
            lines.append(f"Cast off at {res[-1]}.")
            lines.append("Work the rows in turn, as written – drop one and the whole thing unravels.")
            lines.append(f"Happy knitting! {first} x")
            return "\n".join(lines)
        s = f"Evening, robot! Think of this one like a scarf: cast on at {res[0]}"
        s += "".join(f", {_pick(rng, ('knit along to', 'purl back to'))} {r}" for r in res[1:-1])
        return s + (f", and cast off at {res[-1]}. It's worked row by row, as written, so no skipping ahead. "
                    f"{first} x")
    if rng.uniform() < 0.5:
        body = "\n".join(f"✿ {_cap(r)}" for r in res)
        return (f"GRANNY-SQUARE THROW ({who}'s pattern)\nSquares to make ({_count(n)}):\n{body}\nMake the squares in "
                "whichever sequence takes your fancy – they're all stitched together at the end anyway.")
    return (f"No fixed pattern for these, love – just motifs at {_listed(rng, res)}. Knit them up as the mood takes "
            f"you! {first} x")


_BANDS = ("THE RUSTY HINGES", "SPLIT ENDS", "THE LATE BUSES", "DOG & DUCK SESSION BAND")
_VENUES = ("Fri, the Crown, doors 8pm", "Sat 14th, the Red Lion", "the Anchor, Thurs open mic, on at 9.30")


def _band(rng, res: list[str], order: str) -> str:
    """A pub band's frontman with the set list."""
    band = _pick(rng, _BANDS)
    if len(res) == 1:
        return _pick(rng, (f"One-song slot tonight, lads: {res[0]}. Make it count!",
                           f"{band} – short set. Just the one number tonight and that's {res[0]}. Cheers, all!"))
    n = len(res)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"{band} – SET LIST ({_pick(rng, _VENUES)})"]
            lines += [f"{i + 1}. {r}" for i, r in enumerate(res[:-1])]
            lines.append(f"ENCORE: {res[-1]}")
            lines.append("Top to bottom, exactly as the list reads – no swapping songs round.")
            return "\n".join(lines)
        s = f"Right, lads, here's tonight: we open with {res[0]}"
        if n == 2:
            return s + f" and bring it home with {res[-1]}. Song order is locked in, same as rehearsal."
        s += f", segue into {res[1]}"
        s += "".join(f", then {r}" for r in res[2:-1])
        return s + f", and bring it home with {res[-1]}. Song order is locked in, same as rehearsal."
    if rng.uniform() < 0.5:
        body = "\n".join(f"• {r}" for r in res)
        return (f"{band} – OPEN MIC NIGHT ({_count(n)} numbers)\n{body}\nShuffle the set however you fancy, the "
                "crowd won't know the difference.")
    return (f"Loose one tonight, lads: we've got {_listed(rng, res)} to get through, so play 'em as the mood strikes. "
            "Cheers!")


_SITES = ("Saltmarsh Lane", "the reservoir", "Heron Flats", "the old gravel pits")


def _times(rng, n: int) -> list[str]:
    t = int(rng.integers(5 * 60 + 30, 7 * 60 + 30))
    out = []
    for _ in range(n):
        out.append(f"{t // 60:02d}:{t % 60:02d}")
        t += int(rng.integers(2, 10)) * 5
    return out


def _birder(rng, res: list[str], order: str) -> str:
    """A birdwatcher's field notes."""
    site = _pick(rng, _SITES)
    if len(res) == 1:
        return _pick(rng, (f"Only the one twitch on the pager today: {res[0]}. Good birding!",
                           f"Field notes, quiet morning at {site}: just a lone visitor worth chasing, at {res[0]}. "
                           "Bring the binoculars."))
    n = len(res)
    if order == "strict":
        if rng.uniform() < 0.5:
            lines = [f"SIGHTINGS LOG – {_pick(rng, ('Saturday', 'Sunday', 'bank holiday Monday'))}, {site}"]
            lines += [f"{tm}  {r}" for tm, r in zip(_times(rng, n), res)]
            lines.append("Walk them in the order logged, please – doubling back just flushes everything.")
            return "\n".join(lines)
        s = f"Field notes, dawn walk at {site}. First hide: {res[0]}. From there"
        legs = ("round the boardwalk to", "on past the reed beds to", "across the causeway to", "up the bank to")
        s += "".join(f" {_pick(rng, legs)} {r}," for r in res[1:-1])
        return s + (f"{' and' if n > 2 else ''} finish up at {res[-1]} for a flask of tea. Walk the hides in "
                    "sequence – doubling back just flushes everything.")
    if rng.uniform() < 0.5:
        body = "\n".join(f"☐ {_cap(r)}" for r in res)
        return (f"Target list for {site} ({_count(n)} to find):\n{body}\nNo set walk – tick them off as you stumble "
                "on them. Good birding!")
    return (f"Pager's buzzing! Reports in of {_listed(rng, res)}. Whichever turns up first, go for it – good "
            "birding!")


def _tester(rng, res: list[str], order: str) -> str:
    """A software tester's bug ticket or QA ask."""
    if len(res) == 1:
        return _pick(rng, (f"QA note: please verify the robot can reach {res[0]}. That's the whole test case.",
                           f"Quick sanity check for the nav team – can the robot get itself to {res[0]}? Thanks!"))
    n = len(res)
    if order == "strict":
        if rng.uniform() < 0.5:
            build = f"{int(rng.integers(2, 6))}.{int(rng.integers(0, 10))}.{int(rng.integers(0, 20))}"
            lines = [f"BUG-{int(rng.integers(1000, 9999))}: Robot stalls on a multi-stop route",
                     f"Severity: minor | Build: {build}", "Steps to reproduce:", f"1) Send the robot to {res[0]}"]
            lines += [f"{i + 1}) Send it on to {r}" for i, r in enumerate(res) if 0 < i < n - 1]
            lines.append(f"{n}) End at {res[-1]}")
            lines.append("Expected: it arrives at every stop. Actual: it stalls somewhere along the way.")
            lines.append("Note: the repro is order-sensitive, so run the steps in the listed order.")
            return "\n".join(lines)
        s = f"Hey, quick QA ask: could the robot go to {res[0]}"
        s += "".join(f", then {r}" for r in res[1:-1])
        return s + f", and then {res[-1]}? Same sequence every run, please – it's a regression check. Thanks!"
    if rng.uniform() < 0.5:
        body = "\n".join(f"- {r}" for r in res)
        return (f"TICKET #{int(rng.integers(100, 999))} – nav smoke test\nStops to cover ({n}):\n{body}\n"
                "Order has no bearing on the result, we just need coverage.")
    return (f"QA ask: just confirm the robot can reach {_listed(rng, res)}. Visit them in arbitrary order – it's a "
            "coverage check.")


def render_instruction_t(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a knitter's pattern, a pub band's set list, a
    birdwatcher's field notes, a software tester's bug ticket). Goals stay in visiting order; strict texts say the
    order is fixed ('work the rows in turn', 'top to bottom, exactly as the list reads', 'walk the hides in
    sequence', 'run the steps in the listed order'), free ones say it is open ('whichever sequence takes your
    fancy', 'shuffle the set', 'tick them off as you stumble on them', 'in arbitrary order')."""
    res = [" ".join(r.split()).strip().rstrip(",").rstrip() for r in res]
    who = int(rng.integers(4))
    return (_knitter, _band, _birder, _tester)[who](rng, res, order)
