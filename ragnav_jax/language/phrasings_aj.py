"""Held-out sentence set AJ: written by a helper who never read the project's instruction readers (the rule parser,
lexicon, tagger, sensor reader or any learned reader) nor any other set's wording, so that the readers meet authors
they have never seen.

Voices: one per whole instruction, picked by the generator.

- a railway platform announcer: departure-board layouts and public-address patter ('calling at', 'mind the gap');
  strict runs are a fixed calling pattern, free ones a rover ticket or a hop-on hop-off loop, and a single goal is
  a non-stop service;
- a knitting-pattern writer: rows and motifs ('Row 2: make your way to ...', 'cast off', 'weave in ends'); strict
  rows are worked as set, free motifs or granny squares in whatever order you like, a single goal is a one-motif
  pattern;
- a software ticket writer: an issue-tracker ticket ('Acceptance criteria', 'Definition of done', '- [ ]'); strict
  steps are blocked by the one before them or run as a pipeline of stages, free subtasks are independent backlog
  items, a single goal is a plain to-do ticket;
- a teenager texting a sibling: lower case, 'pls', 'idc', 'lol'; strict lists come 'IN THAT ORDER', free ones 'in
  literally any order', a single goal is one quick request.

Style guide. A goal is written 'the [room's] [superlative] [hyphenated states] [attributes] head', then its states
(a relative clause, or in brackets), its room ('in', 'over in', 'kept in', 'down in'), a sensor tail (set off as
'..., the one with ...' once a room stands between it and the noun, so that the tail belongs to the goal and a
superlative is read inside the room), a coordinate hint (x then y, always digits as given, nothing numeric after
it), and last its relations. Attributes may instead stand in an apposition ('the lamp (the teal wool one)'). An
anchor's own attributes and states come before its noun (or, for the last anchor, after it in a 'that is' clause);
an anchor's own relations stand in brackets ('the sofa (the one by the drums)') and deeper ones in a 'that is'
clause inside those brackets (or nested brackets where more follows), so every bracket closes before the goal's next
relation. A relative pronoun ('that is', 'which is') opens a goal's relations only straight after its noun; after a
room they are introduced by 'the one'. Sensor tails start with 'with', 'whose' or a participle ('reading',
'weighing', 'drawing', 'running'), so they agree with any head. Values stay exact: digits as the shortest exact
decimal, whole numbers sometimes in words, temperatures sometimes in Fahrenheit and large powers in kilowatts when
the conversion is an exact short decimal. Goal lists in a running sentence use semicolons unless every goal is a
bare noun phrase of at most four words. A single goal gets no order cue and no digit outside its own text.

Slips: the grep the brief suggested for phrasings_w.py also listed its private helpers' names and the first lines of
their docstrings (an anchor written '(found open)', numbers such as 'nought point six five' and '22,5', and the
names of W's four voices, which the brief lists anyway); their bodies and word lists were not read, and a state
bracket 'found ...' that had crept into this set from that listing was taken out again, as were a few cue phrases
that matched cues quoted in W's public docstrings. In tests/test_phrasings_dev8.py I saw, besides subgoals(), the
targets() strategy and constants it draws from (HEADS, MODS, STATES, ROOMS), the comment line above REL_WORDS (not
its contents), and lines 57-111 (its small text helpers, its wiring and determinism tests and the start of a test
that every head, attribute and relation word is written). In episodes.py I saw two lines on either side of each
render call (names such as describe_text, describe_location, resolve and _target, that a goal's text is its rendered
text stripped of spaces and commas, and that a single goal is given order 'strict'), and the first lines of _rng
after _renderer. In config.py I saw a few lines above EPISODE_SPLITS (imports and a comment) and a grep hit for the
split check. No reader module (parser, lexicon, tagger, sensor reader, readings, agreement, commands, adapters, llm)
was opened, nor any phrasings module but W (as above), nor any test_phrasings file but dev8's (as above).
"""

from __future__ import annotations

from decimal import Decimal

import numpy as np

from ragnav_jax.language.template_text import attributes_and_states, both, hyphenated, is_are, number_words, plural
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target


def _pick(rng: np.random.Generator, options):
    return options[int(rng.integers(len(options)))]


def _one(head: str) -> str:
    return "the ones" if plural(head) else "the one"


# ----------------------------------------------------------------------------------------------------
# Goals

# relation type -> phrases that follow a noun directly ('the lamp next to the sofa')
_REL_PLAIN = {
    "near": ("near", "close to", "not far from", "a short way from"),
    "next_to": ("next to", "right next to", "alongside"),
    "beside": ("beside", "just beside"),
    "by": ("by", "over by", "down by"),
    "on": ("on", "on top of", "resting on", "sitting on"),
    "under": ("under", "underneath", "beneath", "below"),
    "above": ("above", "up above", "directly above"),
    "in": ("in", "inside", "tucked inside"),
    "with": ("with", "accompanied by", "paired with"),
    "in_room_with": ("in the same room as", "sharing a room with", "in the room with"),
    "in_front_of": ("in front of", "just in front of", "out in front of"),
    "behind": ("behind", "tucked behind", "round the back of"),
    "opposite": ("opposite", "across from", "facing", "directly opposite"),
    "left_of": ("to the left of", "on the left-hand side of", "just left of"),
    "right_of": ("to the right of", "on the right-hand side of", "just right of"),
}
# the same after 'that is' / 'which is' ('with' would not read there)
_REL_AFTER_BE = {**_REL_PLAIN, "with": ("accompanied by", "paired with"),
                 "on": ("on", "on top of", "resting on"), "by": ("by", "over by")}

_STATE_PAREN = ("currently {s}", "left {s}", "{s} at the moment", "{s} right now")
_STATE_REL = ("that {be} {s}", "which {be} {s}", "which {be} still {s}", "that {be} currently {s}")
_ROOM_POST = ("in the {r}", "over in the {r}", "kept in the {r}", "down in the {r}", "in the {r}")


def _anchor(rng, t: Target, depth: int, last: bool) -> str:
    """An anchor: states (hyphenated) and attributes before the noun; its own relations in brackets at depth 1 and in
    a 'that is' clause deeper down; the last anchor without relations may take its states in a 'that is' clause."""
    pre, states = attributes_and_states(t)
    be = is_are(t.head)
    after_states = bool(states) and last and not t.relations and rng.uniform() < 0.35
    words = ([] if after_states or not states else [hyphenated(states)]) + pre + [t.head]
    s = "the " + " ".join(words)
    if after_states:
        s += f" that {be} {both(states)}"
    if t.relations:
        n = len(t.relations)
        rels = " and ".join(_rel(rng, r, depth + 1, last=i == n - 1, after_be=True) for i, r in enumerate(t.relations))
        if depth == 1:
            s += f" ({_pick(rng, (_one(t.head) + ' ' + rels, f'{_one(t.head)} that {be} {rels}'))})"
        elif last:
            s += f" that {be} {rels}"
        else:  # not the last of its list: brackets, so the next relation cannot be read as this anchor's
            s += f" ({'themselves' if plural(t.head) else 'itself'} {rels})"
    return s


def _rel(rng, r: Relation, depth: int, last: bool, after_be: bool) -> str:
    words = (_REL_AFTER_BE if after_be else _REL_PLAIN).get(r.type, (r.type.replace("_", " "),))
    return f"{_pick(rng, words)} {_anchor(rng, r.anchor, depth, last)}"


def render_goal_aj(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AJ writes it: 'the nursery's teal wool lamp', 'the lamp (the teal wool one) that is switched
    on', 'the switched-off lamp kept in the games room', 'the warmest lamp over in the kitchen', 'the lamp in the
    kitchen, the one with a temperature of at least 40 °C', 'the guitar at x = 3.5, y = 2', 'the lamp which is
    open, close to the sofa (the one by the drums) and under the shelves'. The head is written as given, the room
    before any sensor tail (a superlative tail is read inside the room), a coordinate hint after any sensor tail,
    and relations last."""
    t = sg.target
    head = t.head
    be = is_are(head)
    pre, states = attributes_and_states(t)
    room = sg.room
    rels = t.relations

    # where the states go: before the noun, in a relative clause, or in brackets (a relative clause would swallow a
    # sensor tail after it, so not then)
    state_mode = ""
    if states:
        state_mode = _pick(rng, ("hyphen", "paren") if tail else ("hyphen", "rel", "rel", "paren"))
    appos = bool(pre) and not prefix and rng.uniform() < 0.25
    poss = bool(room) and rng.uniform() < 0.3

    words = [prefix] if prefix else []
    if state_mode == "hyphen":
        words.append(hyphenated(states))
    if not appos:
        words += pre
    words.append(head)
    s = ("the " + (f"{room}'s " if poss else "")) + " ".join(words)
    if appos:
        inner = "the " + " ".join(pre) + (" ones" if plural(head) else " one")
        if state_mode == "paren":
            inner += ", " + _pick(rng, _STATE_PAREN).format(s=both(states))
            state_mode = "done"
        s += f" ({inner})"
    if state_mode == "rel":
        s += " " + _pick(rng, _STATE_REL).format(be=be, s=both(states))
    elif state_mode == "paren":
        s += f" ({_pick(rng, _STATE_PAREN).format(s=both(states))})"
    if room and not poss:
        s += " " + _pick(rng, _ROOM_POST).format(r=room)
    if tail:
        s += f", {_one(head)} {tail}" if room and not poss else f" {tail}"
    if hint:
        s += f" {hint}"
    if rels:
        n = len(rels)
        # a relative pronoun only straight after the noun (after a room it could be read as the room's); after a
        # room, 'the one' says whose the relations are
        frames = [""]
        if s.endswith(head):
            frames += [f"that {be} ", f"which {be} ", "which you'll find "]
        elif room and not poss and not tail and not hint and state_mode != "rel":
            frames += [f"{_one(head)} "]
        frame = _pick(rng, frames)
        after_be = bool(frame) and not frame.startswith("the one")
        parts = [_rel(rng, r, 1, last=i == n - 1, after_be=after_be) for i, r in enumerate(rels)]
        joined = " and ".join(parts) if n < 3 else ", ".join(parts[:-1]) + " and " + parts[-1]
        lead = "," if (hint or tail or state_mode in ("rel", "done") or "," in s or frame.startswith("the one")) else ""
        s += f"{lead} {frame}{joined}"
    return " ".join(s.split())


# ----------------------------------------------------------------------------------------------------
# Sensors

_NOUNS = {
    "temperature_c": ("temperature", "temperature reading"),
    "ndvi": ("NDVI", "NDVI reading", "vegetation index (NDVI)"),
    "humidity_pct": ("humidity", "relative humidity", "humidity reading"),
    "co2_ppm": ("CO2 level", "carbon dioxide level", "CO2 concentration"),
    "noise_db": ("noise level", "sound level"),
    "light_lux": ("light level", "brightness reading"),
    "battery_pct": ("battery charge", "battery level"),
    "power_w": ("power draw", "power consumption"),
    "weight_kg": ("weight", "measured weight"),
    "pressure_hpa": ("air pressure", "pressure reading", "barometric pressure"),
}
# reading -> the instrument that shows it
_METERS = {"temperature_c": ("thermometer", "temperature sensor"), "ndvi": ("NDVI sensor", "NDVI camera"),
           "humidity_pct": ("hygrometer", "humidity sensor"), "co2_ppm": ("CO2 sensor", "carbon dioxide meter"),
           "noise_db": ("sound meter", "decibel meter"), "light_lux": ("light meter",),
           "battery_pct": ("battery gauge",), "power_w": ("power meter", "wattmeter"), "weight_kg": ("scales",),
           "pressure_hpa": ("barometer",)}
# reading -> (superlative adjectives for max, for min); empty where only a tail reads well
_SUPER_ADJ = {
    "temperature_c": (("hottest", "warmest"), ("coldest", "coolest", "chilliest")),
    "ndvi": (("greenest", "leafiest"), ("least green", "least leafy")),
    "humidity_pct": (("most humid", "dampest"), ("driest", "least humid")),
    "noise_db": (("loudest", "noisiest"), ("quietest",)),
    "light_lux": (("brightest", "best-lit"), ("dimmest", "darkest")),
    "weight_kg": (("heaviest",), ()),
    "battery_pct": (("best-charged",), ()),
    "power_w": (("most power-hungry",), ()),
}
# reading -> (tails for max, tails for min), all starting with 'with' or a participle
_SUPER_TAIL = {
    "weight_kg": (("weighing the most",), ("weighing the least",)),
    "power_w": (("drawing the most power",), ("drawing the least power",)),
    "battery_pct": (("with the most charge left",), ("with the least charge left",)),
    "noise_db": (("making the most noise",), ("making the least noise",)),
}
_SUPER_GENERIC = (("with the highest {n} of the lot", "whose {n} is the highest of them all",
                   "showing the highest {n} reading"),
                  ("with the lowest {n} of the lot", "whose {n} is the lowest of them all",
                   "showing the lowest {n} reading"))

# comparator -> phrases after 'with a <noun>' (W: 'with'), after 'whose <noun> is' (B: 'be')
_CMP_WITH = {
    "gt": ("above {n}", "over {n}", "of more than {n}", "higher than {n}", "in excess of {n}"),
    "ge": ("of at least {n}", "of no less than {n}", "of {n} or more", "not below {n}", "of {n} or above"),
    "lt": ("below {n}", "under {n}", "of less than {n}", "lower than {n}"),
    "le": ("of at most {n}", "of no more than {n}", "of {n} or less", "not above {n}", "of {n} or under"),
    "approx": ("of about {n}", "of roughly {n}", "of approximately {n}", "of {n} or thereabouts",
               "in the region of {n}", "of around {n}"),
}
_CMP_BE = {
    "gt": ("above {n}", "over {n}", "more than {n}", "higher than {n}"),
    "ge": ("at least {n}", "{n} or more", "no less than {n}", "not below {n}"),
    "lt": ("below {n}", "under {n}", "less than {n}", "lower than {n}"),
    "le": ("at most {n}", "{n} or less", "no more than {n}", "not above {n}"),
    "approx": ("about {n}", "roughly {n}", "around {n}", "{n} or thereabouts", "somewhere near {n}"),
}
# reading -> comparator -> participle phrases of its own
_CMP_OWN = {
    "temperature_c": {"gt": ("running hotter than {n}", "running warmer than {n}"),
                      "ge": ("running no colder than {n}",), "lt": ("running colder than {n}",),
                      "le": ("running no hotter than {n}",), "approx": ("sitting at about {n}",)},
    "weight_kg": {"gt": ("weighing more than {n}", "weighing over {n}"), "ge": ("weighing at least {n}",),
                  "lt": ("weighing less than {n}", "weighing under {n}"), "le": ("weighing at most {n}",),
                  "approx": ("weighing about {n}", "weighing roughly {n}")},
    "power_w": {"gt": ("drawing more than {n}",), "ge": ("drawing at least {n}",), "lt": ("drawing less than {n}",),
                "le": ("drawing no more than {n}",), "approx": ("drawing about {n}",)},
    "noise_db": {"gt": ("sounding louder than {n}",), "lt": ("sounding quieter than {n}",),
                 "ge": ("sounding no quieter than {n}",), "le": ("sounding no louder than {n}",)},
    "battery_pct": {"gt": ("charged to more than {n}",), "ge": ("charged to at least {n}",),
                    "lt": ("charged to less than {n}",), "le": ("charged to no more than {n}",),
                    "approx": ("charged to about {n}",)},
}
# reading -> ((text after the number, unit code), ...) for the reading's own unit
_UNITS = {
    "temperature_c": ((" °C", "c"), ("°C", "c"), (" degrees", "c"), (" degrees Celsius", "c")),
    "ndvi": (("", ""),),
    "humidity_pct": (("%", "%"), (" per cent", "%"), (" percent", "%")),
    "co2_ppm": ((" ppm", "ppm"), (" parts per million", "ppm")),
    "noise_db": ((" dB", "db"), (" decibels", "db")),
    "light_lux": ((" lux", "lux"),),
    "battery_pct": (("%", "%"), (" per cent", "%")),
    "power_w": ((" W", "w"), (" watts", "w")),
    "weight_kg": ((" kg", "kg"), (" kilos", "kg"), (" kilograms", "kg")),
    "pressure_hpa": ((" hPa", "hpa"), (" hectopascals", "hpa"), (" millibars", "mbar")),
}


def _digits(v) -> str:
    """The shortest exact decimal: 40.0 -> '40', 0.65 -> '0.65', -4.0 -> '-4'."""
    return np.format_float_positional(float(v), trim="-")


def _dec_text(d: Decimal) -> str:
    s = format(d, "f")
    if "." in s:
        s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _an(noun: str) -> str:
    return "an" if noun[0].lower() in "aeiou" or noun.startswith("NDVI") else "a"


def _value_text(rng, reading: str, v: float) -> tuple[str, str]:
    """(the number with its unit as written, unit code); exact, converted only where the conversion is exact."""
    d = Decimal(_digits(v))
    if reading == "temperature_c" and rng.uniform() < 0.2:
        f = d * 9 / 5 + 32
        if -f.as_tuple().exponent <= 1 or f == f.to_integral_value():
            return _dec_text(f) + _pick(rng, (" °F", " degrees Fahrenheit")), "f"
    if reading == "power_w" and abs(v) >= 500 and rng.uniform() < 0.4:
        return _dec_text(d / 1000) + _pick(rng, (" kW", " kilowatts")), "kw"
    after, code = _pick(rng, _UNITS.get(reading, (("", ""),)))
    if float(v).is_integer() and abs(v) < 1000 and reading != "ndvi" and rng.uniform() < 0.25:
        if after in ("%",):
            after = " per cent"
        if after in (" °C", "°C"):
            after = " degrees"
        return number_words(int(v)) + after, code
    return _digits(v) + after, code


def render_sensor_aj(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('warmest', 'least green', 'most power-hungry') or a tail that
    starts with 'with', 'whose' or a participle ('with the highest humidity of the lot', 'whose air pressure is
    the lowest going', 'weighing the least'); thresholds after the noun, never a finite verb, so any head agrees
    ('with a temperature of at least 40 °C', 'whose humidity is 40% or less', 'running colder than 72.5 °F',
    'drawing more than 1.5 kW', 'with an NDVI of about 0.65'). The value kept is the reading's own (Celsius, watts,
    ...) exactly; the unit code says what was written ('c', 'f', '%', 'ppm', 'db', 'lux', 'w', 'kw', 'kg', 'hpa',
    'mbar', '' for NDVI)."""
    reading, cmp = c.reading, c.comparator
    nouns = _NOUNS.get(reading, (reading.replace("_", " "),))
    noun = _pick(rng, nouns)
    if cmp in ("max", "min"):
        hi = cmp == "max"
        adjs = _SUPER_ADJ.get(reading, ((), ()))[0 if hi else 1]
        written = SensorConstraint(reading, cmp, None, "")
        if adjs and rng.uniform() < 0.5:
            return _pick(rng, adjs), "", written
        own = _SUPER_TAIL.get(reading, ((), ()))[0 if hi else 1]
        options = tuple(x.format(n=nouns[0]) for x in _SUPER_GENERIC[0 if hi else 1]) + own
        return "", _pick(rng, options), written
    num, code = _value_text(rng, reading, float(c.value))
    written = SensorConstraint(reading, cmp, float(c.value), code)
    frames = ["with", "whose", "reading"]
    own = _CMP_OWN.get(reading, {}).get(cmp, ())
    if own:
        frames.append("own")
    frame = _pick(rng, frames)
    if frame == "own":
        tail = _pick(rng, own).format(n=num)
    elif frame == "with":
        tail = f"with {_an(noun)} {noun} " + _pick(rng, _CMP_WITH[cmp]).format(n=num)
    elif frame == "whose":
        tail = f"whose {nouns[0]} {_pick(rng, ('is', 'reads'))} " + _pick(rng, _CMP_BE[cmp]).format(n=num)
    else:
        meter = _pick(rng, _METERS.get(reading, ("sensor",)))
        tail = f"reading {_pick(rng, _CMP_BE[cmp]).format(n=num)} on the {meter}"
    return "", tail, written


# ----------------------------------------------------------------------------------------------------
# Coordinate hints

_HINTS = ("at x = {x}, y = {y}", "at grid reference ({x}, {y}), x first", "at the mark x {x} / y {y}",
          "at {x} on the x-axis and {y} on the y-axis", "at the spot marked x={x}, y={y}",
          "round about coordinates x {x}, y {y}", "at position (x {x}, y {y})")


def hint_text_aj(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y, both as given: 'at x = 3.5, y = 2', 'at grid
    reference (3.5, 2), x first', 'at 3.5 on the x-axis and 2 on the y-axis', 'at position (x 3.5, y 2)'."""
    return _pick(rng, _HINTS).format(x=x, y=y)


# ----------------------------------------------------------------------------------------------------
# Whole instructions

_ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth",
             "eleventh", "twelfth")


def _crowded(res: list[str]) -> bool:
    """A goal with commas, brackets or an 'and' of its own: lists of such goals need semicolons."""
    return any("," in r or "(" in r or " and " in r for r in res)


def _run(rng, res: list[str]) -> str:
    """Goals in a running sentence: 'A, B and C' while every goal is a bare noun phrase of at most four words (no
    room, relation or hint can hide in so few), else 'A; B; and C' ('A; and also B'), so that no goal's anchor can be
    read as a list of anchors."""
    if len(res) == 1:
        return res[0]
    if _crowded(res) or any(len(r.split()) > 4 for r in res):
        return "; ".join(res[:-1]) + ("; and also " if len(res) == 2 else "; and ") + res[-1]
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


def _then(res: list[str], word: str = "then") -> str:
    """Goals in order in a running sentence: 'A, then B, then C' ('A; then B' once a goal is crowded)."""
    sep = f"; {word} " if _crowded(res) else f", {word} "
    return sep.join(res)


def _ordinal(i: int) -> str:
    return _ORDINALS[i] if i < len(_ORDINALS) else "next"


def _announcer(rng, res: list[str], order: str) -> str:
    """A railway platform announcer: a departure board, or patter over the public address."""
    opener = _pick(rng, ("Platform announcement.", "Good afternoon, ladies and gentlemen.", "Attention please.",
                         "This is a customer announcement."))
    closer = _pick(rng, ("Mind the gap.", "Please stand clear of the closing doors.",
                         "Thank you for travelling with us today.", "Please keep your belongings with you."))
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"{opener} This service runs non-stop to {g}. {closer}",
                           f"{opener} The only stop on this service is {g}. {closer}",
                           f"DEPARTURES\nExpress service to: {g}\nNo other calling points. {closer}",
                           f"{opener} This is a direct train to {g}; please take your seats. {closer}"))
    if order == "strict":
        cue = _pick(rng, ("calling at each stop strictly in the order announced",
                          "stopping in that order and no other",
                          "and this train will not call at any stop out of sequence"))
        layout = int(rng.integers(3))
        if layout == 0:
            return f"{opener} The service now standing at this platform calls at {_then(res)}, {cue}. {closer}"
        if layout == 1:
            lines = [f"  {i + 1}. {g}" for i, g in enumerate(res)]
            rule = _pick(rng, ("Calling pattern fixed: stops are served in the order shown, top to bottom.",
                               "Stops are served in sequence only, from the top of the board down."))
            return "DEPARTURES\nCalling at:\n" + "\n".join(lines) + f"\n{rule} {closer}"
        lines = [f"{_ordinal(i).capitalize()} stop: {g}." for i, g in enumerate(res)]
        return (f"{opener} This is a stopping service, calling in turn at the following, in the order read out. "
                + " ".join(lines) + f" {closer}")
    cue = _pick(rng, ("in any order you choose", "in whichever order is handiest", "in no fixed order"))
    layout = int(rng.integers(3))
    if layout == 0:
        return f"{opener} Your rover ticket is valid at {_run(rng, res)}, {cue}. {closer}"
    if layout == 1:
        lines = [f"  * {g}" for g in res]
        rule = _pick(rng, ("There is no fixed calling pattern: alight at these stops in whatever order you fancy.",
                           f"Hop off at them {cue}; every stop on the loop is as good a start as any other."))
        return "HOP-ON HOP-OFF LOOP\nStops on this loop:\n" + "\n".join(lines) + f"\n{rule} {closer}"
    return (f"{opener} This service calls at the following stops, though not necessarily in the order announced: "
            f"{_run(rng, res)}. {closer}")


def _knitter(rng, res: list[str], order: str) -> str:
    """A knitting-pattern writer: numbered rows, or motifs and squares joined at the end."""
    verb = _pick(rng, ("make your way to", "work your way to", "go to"))
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"PATTERN NOTES\nSkill level: beginner.\nCast on and {verb} {g}. Cast off and weave in "
                           "ends.",
                           f"Simple one-motif pattern: {verb} {g}. Block gently to finish.",
                           f"You will need: one robot.\nMethod: {verb} {g}, and fasten off."))
    if order == "strict":
        layout = int(rng.integers(3))
        if layout == 0:
            rule = _pick(rng, ("Work the rows in order as set; never start a row until the previous row is done.",
                               "Follow the rows strictly in the order written.",
                               "Rows must be worked in sequence, or the whole piece unravels."))
            lines = [f"Row {i + 1}: {verb} {g}." for i, g in enumerate(res)]
            return "PATTERN\nCast on.\n" + "\n".join(lines) + f"\n{rule}\nCast off."
        if layout == 1:
            return (f"Cast on. Work as set, row by row and in this exact order: {verb} {_then(res, 'next')}. "
                    "Cast off and weave in ends.")
        lines = [f"Rnd {i + 1}: {verb} {g}." for i, g in enumerate(res)]
        return ("Worked in the round, each round only once the previous round is complete.\n" + "\n".join(lines)
                + "\nFasten off.")
    cue = _pick(rng, ("in any order", "in whatever order you like", "in no set order"))
    layout = int(rng.integers(2))
    if layout == 0:
        rule = _pick(rng, ("The order of working is entirely up to you.", f"Motifs may be worked {cue}."))
        lines = [f"* Motif: {verb} {g}." for g in res]
        return "MOTIFS (make one of each, then join)\n" + "\n".join(lines) + f"\n{rule}"
    return (f"Granny squares for this blanket, to be worked {cue}: {verb} {_run(rng, res)}. "
            "Join all the squares once they are done.")


def _ticket(rng, res: list[str], order: str) -> str:
    """A software ticket writer: an issue-tracker ticket, or a story with a pipeline."""
    verb = _pick(rng, ("Robot navigates to", "Robot reaches", "Robot is at"))
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"[TASK] Send the robot to {g}\nPriority: normal\nAssignee: robot\nStatus: to do",
                           f"Quick ticket: the robot should navigate to {g}. Definition of done: robot is there. "
                           "Thanks!",
                           f"[CHORE] Navigate to {g}\nLabels: robot, errand\nNo further details."))
    if order == "strict":
        layout = int(rng.integers(2))
        if layout == 0:
            lines = [f"{i + 1}. {verb} {g}" for i, g in enumerate(res)]
            dep = _pick(rng, ("Dependencies: sequential; each step is blocked by the one before it.",
                              "Hard ordering constraint: do not start a step until the previous step is closed."))
            return ("[TASK] Robot errand run\nPriority: high\nAcceptance criteria:\n" + "\n".join(lines)
                    + f"\n{dep}\nDefinition of done: every step closed, in the listed order.")
        return ("[STORY] As the operator I need the robot to visit these in sequence.\nPipeline: "
                + " -> ".join(res) + "\nStages run sequentially; no stage may start before the previous stage passes.")
    layout = int(rng.integers(2))
    if layout == 0:
        lines = [f"- [ ] navigate to {g}" for g in res]
        return ("[TASK] Robot errand sweep\nSubtasks (independent; pick them up in any order):\n" + "\n".join(lines)
                + "\nNo dependencies between subtasks.")
    return (f"[BACKLOG] Places for the robot to visit: {_run(rng, res)}.\nThese items are unordered; parallelise or "
            "pick them up in any order you like.")


def _texter(rng, res: list[str], order: str) -> str:
    """A teenager texting a sibling: lower case, in a rush."""
    opener = _pick(rng, ("heyyy", "ok so", "hiii", "omg ok", "yo"))
    closer = _pick(rng, ("ty!!", "thx ur the best", "love u", "k bye", "pls dont forget"))
    if len(res) == 1:
        g = res[0]
        return _pick(rng, (f"{opener} can u go to {g}?? {closer}", f"{opener} pls just go to {g} {closer}",
                           f"{opener} mum wants u to go to {g} {closer}"))
    if order == "strict":
        layout = int(rng.integers(3))
        if layout == 0:
            return (f"{opener} mum says go to {_then(res)}. IN THAT ORDER, she was very specific lol {closer}")
        if layout == 1:
            lines = [f"{i + 1}) {g}" for i, g in enumerate(res)]
            return (f"{opener} go here:\n" + "\n".join(lines) + "\ndo them in order ok?? not joking, order matters "
                    + closer)
        return (f"{opener} first go to {res[0]}. " + " ".join(f"then {g}." for g in res[1:])
                + f" dont skip ahead!! {closer}")
    cue = _pick(rng, ("whenever, idc what order tbh", "in literally any order", "order doesnt matter"))
    layout = int(rng.integers(2))
    if layout == 0:
        return f"{opener} can u hit up {_run(rng, res)}? {cue} {closer}"
    lines = [f"- {g}" for g in res]
    return f"{opener} places to go:\n" + "\n".join(lines) + f"\nwhatever order u want honestly, {closer}"


_VOICES = (_announcer, _knitter, _ticket, _texter)


def render_instruction_aj(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a railway platform announcer, a
    knitting-pattern writer, a software ticket writer, a teenager texting a sibling). Goals stay in visiting order,
    each written once as rendered; strict texts say the order is fixed ('calling at each stop strictly in the order
    announced', 'calling pattern fixed', 'in the order read out', 'work the rows in order as set', 'each round only
    once the previous round is complete', 'blocked by the one before it', 'stages run sequentially', 'IN THAT
    ORDER', 'dont skip ahead'), free ones say it is open ('rover ticket', 'in whichever order is handiest', 'not
    necessarily in the order announced', 'motifs may be worked in any order', 'the order of working is entirely up to
    you', 'independent; pick them up in any order', 'these items are unordered', 'idc what order', 'in literally any
    order'). A single goal gets neither kind of cue and no digit."""
    return _pick(rng, _VOICES)(rng, list(res), order)
