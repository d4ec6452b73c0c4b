"""Held-out sentence set AU (split `unseen_au`): multi-goal instructions by four new authors, written fresh to
measure how the instruction readers cope with people nobody tuned them on.

Who wrote it: a helper session started by the project, told to write a new held-out set without reading any
instruction reader or any other set's wording.

What it read: the `def` lines and docstrings of the four public functions of language/phrasings_w.py (not their
bodies, helpers or module docstring); language/types.py and language/template_text.py, whole; `UNSEEN_TEMPLATES`
and `_renderer` of language/episodes.py; `EPISODE_SPLITS` of config.py; tests/test_heldout_sets.py, whole; the
`subgoals` and `targets` strategies and the HEADS, MODS, STATES and ROOMS constants of
tests/test_phrasings_dev8.py; `[tool.ruff]` of pyproject.toml; and the value of `types.READINGS` (the sensor
keys), printed at run time.

The four voices (one drawn per whole instruction; each has three layouts, and a strict, free and one-goal form):
- a dinghy-club race officer: sailing instructions on the notice board ('SAILING INSTRUCTIONS', 'Marks shall be
  rounded in the order listed', 'Marks may be rounded in any order', 'Good sailing!'), a VHF call ('Race
  committee to all boats', 'no cutting the course', 'Race committee, out.') and a shore briefing ('gather round',
  'anyone who rounds out of turn gets disqualified', 'whatever order the wind gives you');
- a pest-control technician: a service sheet ('ROUTINE SERVICE VISIT', 'Monitoring points to inspect', 'in
  route order, top to bottom'), a text to the apprentice ('You're on the bait round today', 'it's the route in
  the logbook', 'Whatever order you fancy') and a job card ('Route order is fixed.', 'Order not important.');
- an auditor attending a stocktake: a memo ('Please perform test counts on the following items', '(a)', 'the
  sequence matters for cut-off testing', 'Reviewed by: audit manager'), an email ('could you please attend the
  following, in this order', 'Kind regards') and a working paper ('W/P', 'Count sequence: strictly as listed',
  'Conclusion: pending.');
- a metal detectorist: a forum post ('permission's sorted for the house', 'Signals to dig today', 'bagging the
  finds in sequence for the finds liaison officer', 'HH all'), a run-on note ('swing over', 'that's the order the
  signals came in') and field notes ('Signal log', 'Recover in log order, oldest signal first').

Style (the goal wording is one plain-English pool the four share; the voice lives in the frame): a goal is 'the'
+ [a superlative adjective] + [states] + the attributes as the phrase gives them + the head noun as given, or the
states follow ('that is switched on') when no room follows the noun; the room comes straight after the noun ('in
the nursery') or before it as a possessive ('the nursery's teal lamp'), inside a superlative's scope; then the
sensor tail; then the coordinate hint (x then y, as given); relations last, an anchor's own relations in brackets
right after it and a target's second relation joined by ', and also' or ', while also being'. Sensor values are
the shortest decimal that reads back, or number words for whole numbers under a hundred; Fahrenheit and kilowatts
only when they convert back exactly (the constraint keeps the canonical value, the unit as written); carbon
dioxide is spelled out. Goals are set off by semicolons, new lines or sequence words; strict texts say the order
is fixed, free texts say it is open, a single goal gets neither; the frames add no digits.

Tests broken on purpose (tests/test_phrasings_au.py): (1) the job card's strict cue was swapped for a sign-off,
and test_order_cues_in_every_voice_and_frame (on the job card),
test_the_public_writer_reaches_every_voice_and_frame and test_same_seed_same_text failed; (2) hint_text_au wrote y
before x in two of its five forms, and test_goal_parts_in_place, test_hint_reads_back_x_then_y and
test_sensor_tail_room_and_hint_in_their_places failed. Both were restored, and all the tests pass.

Slips: while looking up what test_phrasings_dev8.py imports, the import lines at its top (lines 7-19) were printed
(module imports only, no wording); the first thirty lines of tests/conftest.py (test-suite numerics and the
Hypothesis profile, no wording) were printed; and the grep of pyproject.toml for `[tool.ruff]` also showed the
`[tool.ruff.lint]` lines after it. No reader and no other set's wording was seen.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.template_text import (
    attributes_and_states,
    both,
    hyphenated,
    is_are,
    number_words,
    plural,
    tidy,
)
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target


def _pick(rng: np.random.Generator, options):
    return options[int(rng.integers(len(options)))]


# ----------------------------------------------------------------------------------------------------------------
# Goals (the shared plain-English pool)

_REL_WORDS = {
    "near": ("near", "close to"),
    "next_to": ("next to",),
    "beside": ("beside",),
    "by": ("by",),
    "on": ("on", "on top of"),
    "under": ("under", "beneath"),
    "above": ("above",),
    "in": ("inside",),
    "with": ("with",),
    "in_room_with": ("in the same room as",),
    "in_front_of": ("in front of",),
    "behind": ("behind",),
    "opposite": ("opposite", "across from"),
    "left_of": ("to the left of",),
    "right_of": ("to the right of",),
}


def _noun(t: Target) -> tuple[str, list[str]]:
    """(attributes as the phrase gives them + the head noun, the states)."""
    pre, states = attributes_and_states(t)
    if t.phrase and t.phrase.endswith(t.head):
        return t.phrase, states
    return " ".join([*pre, t.head]), states


def _relations(rng: np.random.Generator, rels: tuple[Relation, ...]) -> str:
    out = ""
    for i, r in enumerate(rels):
        words = f"{_pick(rng, _REL_WORDS.get(r.type, (r.type.replace('_', ' '),)))} {_anchor(rng, r.anchor)}"
        out = words if i == 0 else out + _pick(rng, (", and also ", ", while also being ")) + words
    return out


def _anchor(rng: np.random.Generator, a: Target) -> str:
    noun, states = _noun(a)
    s = "the " + (hyphenated(states) + " " if states else "") + noun
    if a.relations:
        many = plural(a.head)
        lead = _pick(rng, ("the ones" if many else "the one", "which are" if many else "which is",
                           "themselves" if many else "itself"))
        s += f" ({lead} {_relations(rng, a.relations)})"
    return s


def render_goal_au(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AU writes it: 'the warmest switched-on teal lamp in the nursery', 'the nursery's teal lamp',
    'the lamp that is switched on', 'the lamp in the kitchen whose humidity is at most 40%', 'the sofa, at x 3.5,
    y 2', 'the drums next to the sofa (the one beside the lamp), and also behind the toolbox'. The room comes
    straight after the noun or before it as a possessive, inside a superlative's scope; then the sensor tail;
    then the coordinate hint (x then y, no digit after it); relations last."""
    t = sg.target
    noun, states = _noun(t)
    room = None if not sg.room else _pick(rng, ("after", "after", "possessive"))
    states_after = bool(states) and room != "after" and not tail and rng.random() < 0.5
    lead = f"the {sg.room}'s" if room == "possessive" else "the"
    words = [lead, prefix, hyphenated(states) if states and not states_after else "", noun]
    s = " ".join(w for w in words if w)
    if states_after:
        s += f" that {is_are(t.head)} {both(states)}"
    if room == "after":
        s += f" in the {sg.room}"
    if tail:
        s += " " + tail
    if hint:
        s += ", " + hint
    if t.relations:
        s += (", " if (hint or tail or states_after) else " ") + _relations(rng, t.relations)
    return tidy(s)


# ----------------------------------------------------------------------------------------------------------------
# Sensor phrases

# reading -> (noun after 'whose', noun after 'with', adjectives for max, adjectives for min, (more, less) verbs)
_READ = {
    "temperature_c": ("temperature", "a temperature", ("warmest",), ("coldest",),
                      ("running warmer than", "running colder than")),
    "ndvi": ("NDVI", "an NDVI", (), (), None),
    "humidity_pct": ("humidity", "humidity", ("most humid", "dampest"), ("driest", "least humid"), None),
    "co2_ppm": ("carbon dioxide level", "a carbon dioxide level", (), (), None),
    "noise_db": ("noise level", "a noise level", ("loudest", "noisiest"), ("quietest",),
                 ("sounding louder than", "sounding quieter than")),
    "light_lux": ("light level", "a light level", (), (), None),
    "battery_pct": ("battery level", "a battery level", (), (), None),
    "power_w": ("power draw", "a power draw", ("most power-hungry",), (), None),
    "weight_kg": ("weight", "a weight", ("heaviest",), (), ("weighing more than",
                                                                        "weighing less than")),
    "pressure_hpa": ("pressure", "a pressure", (), (), None),
}

# reading -> [(unit as written, written after digits, written after words)]: canonical units
_UNITS = {
    "temperature_c": [("c", "°C", "degrees Celsius")],
    "ndvi": [("", "", "")],
    "humidity_pct": [("%", "%", "per cent")],
    "co2_ppm": [("ppm", " ppm", "parts per million")],
    "noise_db": [("db", " dB", "decibels")],
    "light_lux": [("lux", " lux", "lux")],
    "battery_pct": [("%", "%", "per cent")],
    "power_w": [("w", " W", "watts")],
    "weight_kg": [("kg", " kg", "kilograms")],
    "pressure_hpa": [("hpa", " hPa", "hectopascals")],
}

# comparator -> wordings around the value: '{v}' is the value with its unit
_WITH = {"gt": ("above {v}", "over {v}", "higher than {v}"), "lt": ("below {v}", "under {v}", "lower than {v}"),
         "ge": ("of at least {v}", "of {v} or more"), "le": ("of at most {v}", "of {v} or less", "no higher than {v}"),
         "approx": ("of about {v}", "of roughly {v}", "of around {v}")}
_WHOSE = {"gt": ("above {v}", "over {v}", "more than {v}", "higher than {v}"),
          "lt": ("below {v}", "under {v}", "less than {v}", "lower than {v}"),
          "ge": ("at least {v}", "{v} or more", "no less than {v}"),
          "le": ("at most {v}", "{v} or less", "no more than {v}"),
          "approx": ("about {v}", "roughly {v}", "around {v}")}


def _decimal(v: float) -> str:
    return np.format_float_positional(float(v), trim="-")


def _whole(v: float) -> bool:
    return float(v).is_integer() and -100 < v < 100


def _amount(rng: np.random.Generator, v: float, digits_unit: str, words_unit: str) -> str:
    """The value with its unit: number words for whole numbers under a hundred (sometimes), else digits."""
    if _whole(v) and words_unit and rng.random() < 0.5:
        return f"{number_words(int(v))} {words_unit}"
    if not digits_unit:
        return _decimal(v)
    return _decimal(v) + (digits_unit if digits_unit.startswith((" ", "%", "°")) else " " + digits_unit)


def _fahrenheit(c: float) -> str | None:
    f = _decimal(c * 9 / 5 + 32)
    if len(f.split(".")[-1]) > 1 and "." in f:
        return None
    back = float(f)
    return f if (back - 32) * 5 / 9 == c and (back - 32) / 1.8 == c else None


def _kilowatts(w: float) -> str | None:
    if abs(w) < 100:
        return None
    kw = _decimal(w / 1000)
    return kw if float(kw) * 1000 == w and len(kw.split(".")[-1]) <= 3 else None


def render_sensor_au(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('warmest', 'most humid', 'quietest', 'heaviest') or a tail ('with
    the highest NDVI', 'whose carbon dioxide level is the lowest'); thresholds after the noun ('with a temperature
    above 40°C', 'whose humidity is at most forty per cent', 'with an NDVI of about 0.65', 'running warmer than
    104°F', 'with a power draw of 1.5 kW or more')."""
    whose, with_, up, down, verbs = _READ.get(c.reading, (c.reading.replace("_", " "), "a " +
                                                          c.reading.replace("_", " "), (), (), None))
    if c.is_superlative:
        hi = c.comparator == "max"
        adjectives = up if hi else down
        if adjectives and rng.random() < 0.5:
            return _pick(rng, adjectives), "", SensorConstraint(c.reading, c.comparator, None, "")
        word = "highest" if hi else "lowest"
        tail = _pick(rng, (f"with the {word} {whose}", f"whose {whose} is the {word}"))
        return "", tail, SensorConstraint(c.reading, c.comparator, None, "")
    v = float(c.value)
    unit, digits_unit, words_unit = _UNITS.get(c.reading, [("", "", "")])[0]
    shown = v
    if c.reading == "temperature_c" and rng.random() < 0.3 and _fahrenheit(v) is not None:
        unit, digits_unit, words_unit, shown = "f", "°F", "degrees Fahrenheit", float(_fahrenheit(v))
    elif c.reading == "power_w" and rng.random() < 0.4 and _kilowatts(v) is not None:
        unit, digits_unit, words_unit, shown = "kw", " kW", "kilowatts", float(_kilowatts(v))
    if unit == "f":  # digits exactly as the conversion wrote them
        amount = _fahrenheit(v) + digits_unit
        if _whole(shown) and rng.random() < 0.5:
            amount = f"{number_words(int(shown))} {words_unit}"
    elif unit == "kw":
        amount = _kilowatts(v) + digits_unit
    else:
        amount = _amount(rng, shown, digits_unit, words_unit)
    forms = ["with", "whose"]
    if verbs is not None and c.comparator in ("gt", "lt"):
        forms.append("verb")
    form = _pick(rng, forms)
    if form == "verb":
        tail = f"{verbs[0 if c.comparator == 'gt' else 1]} {amount}"
    elif form == "with":
        tail = f"with {with_} " + _pick(rng, _WITH[c.comparator]).format(v=amount)
    else:
        tail = f"whose {whose} is " + _pick(rng, _WHOSE[c.comparator]).format(v=amount)
    return "", tail, SensorConstraint(c.reading, c.comparator, c.value, unit)


# ----------------------------------------------------------------------------------------------------------------
# Coordinate hints

def hint_text_au(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at x 3.5, y 2', 'around x = 3.5, y = 2', 'at
    coordinates x 3.5 and y 2', 'where x is 3.5 and y is 2', 'at the position 3.5 along x and 2 along y'."""
    return _pick(rng, (f"at x {x}, y {y}", f"around x = {x}, y = {y}", f"at coordinates x {x} and y {y}",
                       f"where x is {x} and y is {y}", f"at the position {x} along x and {y} along y"))


# ----------------------------------------------------------------------------------------------------------------
# Whole instructions: four voices, three layouts each


def _then(res: list[str], first: str, mid: str, last: str) -> str:
    """'first A; then B; then C; finally D' (for two goals, 'first A; then B')."""
    out = first + res[0]
    for i, g in enumerate(res[1:], start=1):
        out += (last if i == len(res) - 1 and len(res) > 2 else mid) + g
    return out


def _race_officer(rng, res, order, frame):
    one, strict = len(res) == 1, order == "strict"
    if frame == 0:  # sailing instructions on the club notice board
        head = _pick(rng, ("SAILING INSTRUCTIONS — House Series", "COURSE FOR TODAY'S RACE",
                           "Sailing Instructions: the Indoor Pursuit"))
        sign = _pick(rng, ("Good sailing! — Race Officer", "Fair winds. R.O.",
                           "Race Officer, on behalf of the Race Committee"))
        if one:
            return f"{head}\nCourse — a single mark to be rounded:\n  - {res[0]}\n{sign}"
        cue = _pick(rng, ("Marks shall be rounded in the order listed.",
                          "Marks are to be rounded in the order given; a boat rounding a mark out of sequence "
                          "shall retire.",
                          "Round the marks in turn as listed: no mark may be rounded before the one above it.")
                    if strict else
                    ("Marks may be rounded in any order.",
                     "This is a free course: the order of rounding is at each skipper's discretion.",
                     "No rounding order is set; take the marks in whatever order the breeze favours."))
        lines = "\n".join(f"  - {g}" for g in res)
        return f"{head}\nCourse — marks to be rounded:\n{lines}\n{cue}\n{sign}"
    if frame == 1:  # on the VHF before the start
        call = "Race committee to all boats, race committee to all boats."
        out = _pick(rng, ("Race committee, out.", "Over."))
        if one:
            return f"{call} Single mark for this race: {res[0]}. {out}"
        if strict:
            course = _then(res, "", "; then ", "; last mark, ")
            cue = _pick(rng, ("Marks in that order — no cutting the course.",
                              "Round them in the order I gave, each one after the one before."))
            return f"{call} Course for this race: {course}. {cue} {out}"
        cue = _pick(rng, ("Round them in any order you like.", "Rounding order is your call, skippers.",
                          "The order is up to you."))
        return f"{call} Marks for this race: {'; '.join(res)}. {cue} {out}"
    # the briefing on the slipway
    hello = _pick(rng, ("Right, gather round, everyone.", "Morning, sailors — briefing time."))
    bye = _pick(rng, ("Have a good race, all.", "Good luck, everyone."))
    if one:
        return f"{hello} Dead simple today, just the one mark: {res[0]}. {bye}"
    if strict:
        course = _then(res, "start by rounding ", "; then on to ", "; then last of all ")
        cue = _pick(rng, ("Take them in the order I've said — anyone who rounds out of turn gets disqualified, "
                          "no arguments.", "Same order as I've read them out, please; no short cuts."))
        return f"{hello} Nice simple course today: {course}. {cue} {bye}"
    cue = _pick(rng, ("Pick them off in whatever order the wind gives you.",
                      "Any order you like — just get round all of them."))
    return f"{hello} Free course today. The marks are {'; '.join(res)}. {cue} {bye}"


def _pest_control(rng, res, order, frame):
    one, strict = len(res) == 1, order == "strict"
    if frame == 0:  # the service sheet
        head = _pick(rng, ("ROUTINE SERVICE VISIT — RODENT MONITORING", "SERVICE VISIT: INSECT MONITORING ROUND",
                           "PEST CONTROL — SCHEDULED INSPECTION"))
        tech = "Technician: " + _pick(rng, ("Lee", "M. Okafor", "Sam (field tech)"))
        if one:
            return f"{head}\nMonitoring point to inspect:\n• {res[0]}\n{tech}"
        cue = _pick(rng, ("Inspect in route order, top to bottom — the same route every visit so the log stays "
                          "comparable.", "Work the points in the sequence shown; do not skip ahead.",
                          "Points to be inspected in the order listed, each after the one above it.")
                    if strict else
                    ("Points may be inspected in any order this visit.",
                     "No set route this time — inspect in whichever order is convenient.",
                     "Inspection order is not important."))
        lines = "\n".join(f"• {g}" for g in res)
        return f"{head}\nMonitoring points to inspect:\n{lines}\n{cue}\n{tech}"
    if frame == 1:  # a text to the apprentice
        hello = _pick(rng, ("Morning! You're on the bait round today.", "Alright mate, bait round for you today."))
        bye = _pick(rng, ("Cheers.", "Ta.", "Any bother, ring me."))
        if one:
            return f"{hello} Just the one station to check: {res[0]}. {bye}"
        if strict:
            route = _then(res, "Start with ", "; then ", "; last of all ")
            cue = _pick(rng, ("Keep to that order, yeah — it's the route in the logbook.",
                              "Same order as always, mind, or the log's useless."))
            return f"{hello} {route}. {cue} {bye}"
        cue = _pick(rng, ("Whatever order you fancy, just make sure they all get checked.",
                          "Do them in any order you like."))
        return f"{hello} Stations: {'; '.join(res)}. {cue} {bye}"
    # a one-line job card
    if one:
        return f"Job card — station check: {res[0]}."
    if strict:
        route = _then(res, "", "; after that, ", "; after that, ")
        cue = _pick(rng, ("Route order is fixed.", "Follow the route as written, in that order."))
        return f"Job card — station check: {route}. {cue}"
    cue = _pick(rng, ("Order not important.", "Any order will do."))
    return f"Job card — station check: {'; '.join(res)}. {cue}"


def _auditor(rng, res, order, frame):
    one, strict = len(res) == 1, order == "strict"
    if frame == 0:  # the attendance memo
        head = _pick(rng, ("STOCKTAKE ATTENDANCE — TEST COUNTS",
                           "Inventory count attendance: items selected for test counting"))
        if one:
            return (f"{head}\nPrepared by: audit senior\nPlease perform a test count on the following item:\n"
                    f"(a) {res[0]}\nReviewed by: audit manager")
        cue = _pick(rng, ("Counts are to be performed in the sequence listed, each only after the count above it "
                          "has been completed.", "Please perform the counts strictly in the order set out above; "
                          "the sequence matters for cut-off testing.")
                    if strict else
                    ("The counts may be performed in any order.", "The order of counting is at the counter's "
                     "discretion."))
        lines = "\n".join(f"({'abcdefghijklmnopqrstuvwxyz'[i % 26]}) {g}" for i, g in enumerate(res))
        return (f"{head}\nPrepared by: audit senior\nPlease perform test counts on the following items:\n{lines}\n"
                f"{cue}\nReviewed by: audit manager")
    if frame == 1:  # an email to the count team
        name = _pick(rng, ("Priya, Audit Senior", "The audit team"))
        hello = "Hi,\n\nFor tomorrow's stocktake, could you please attend"
        if one:
            return f"{hello} just the one item: {res[0]}.\n\nKind regards,\n{name}"
        if strict:
            cue = _pick(rng, ("Please don't reorder these — the sequence matters for our cut-off work.",
                              "Please keep to that sequence; each count relies on the one before."))
            return (f"{hello} the following, in this order: {_then(res, 'first ', '; then ', '; finally ')}."
                    f"\n\n{cue}\n\nKind regards,\n{name}")
        cue = _pick(rng, ("The order doesn't matter, as long as every item is covered.",
                          "Feel free to take them in any order."))
        return f"{hello} the following: {'; '.join(res)}.\n\n{cue}\n\nKind regards,\n{name}"
    # a working paper
    head = _pick(rng, ("W/P: Inventory — test count selection",
                       "Working paper: stock — items selected for test count"))
    if one:
        return f"{head}\nItem selected:\n▸ {res[0]}\nConclusion: pending."
    cue = _pick(rng, ("as listed, each in turn, no item before the one above it.", "strictly as listed.")
                if strict else ("any order; sequence not relevant to the test.", "at the counter's discretion."))
    lines = "\n".join(f"▸ {g}" for g in res)
    return f"{head}\nItems selected:\n{lines}\nCount sequence: {cue}\nConclusion: pending."


def _detectorist(rng, res, order, frame):
    one, strict = len(res) == 1, order == "strict"
    sign = _pick(rng, ("HH all", "Happy hunting!", "HH, Gaz"))
    if frame == 0:  # a post on the club forum
        hello = _pick(rng, ("Right lads, permission's sorted for the house.",
                            "Evening all — finally got permission on the house."))
        if one:
            return f"{hello} Just the one signal to dig today:\n- {res[0]}\n{sign}"
        cue = _pick(rng, ("Dig them in the order I logged them — I'm bagging the finds in sequence for the finds "
                          "liaison officer.", "Same order as the list please, every find gets bagged in sequence.")
                    if strict else
                    ("Dig them in whatever order suits, it's all going in one finds bag anyway.",
                     "No particular order, just don't leave any undug."))
        lines = "\n".join(f"- {g}" for g in res)
        return f"{hello} Signals to dig today:\n{lines}\n{cue}\n{sign}"
    if frame == 1:  # a run-on note
        if one:
            return f"Good strong signal on {res[0]} — worth a dig. {sign}"
        if strict:
            route = _then(res, "First, swing over ", "; then ", "; then finally ")
            return f"{route} — that's the order the signals came in, so keep to it. {sign}"
        cue = _pick(rng, ("no particular order, dig whichever you fancy.", "order's up to you."))
        return f"Good signals on {'; '.join(res)} — {cue} {sign}"
    # field notes
    head = _pick(rng, ("Field notes — house permission", "Detecting log — house permission"))
    if one:
        return f"{head}\nSignal log:\n• {res[0]}\nHH"
    cue = _pick(rng, ("Recover in log order, oldest signal first.", "Dig in the order logged; no jumping ahead.")
                if strict else ("Recover in any order.", "Dig order doesn't matter."))
    lines = "\n".join(f"• {g}" for g in res)
    return f"{head}\nSignal log:\n{lines}\n{cue}\nHH"


_VOICES = (_race_officer, _pest_control, _auditor, _detectorist)
_FRAMES = 3


def render_instruction_au(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a dinghy-club race officer, a pest-control
    technician, an auditor at a stocktake, a metal detectorist), each in one of three layouts. Goals stay in
    visiting order, each written once as rendered, set off by semicolons, new lines or sequence words; strict
    texts say the order is fixed ('Marks shall be rounded in the order listed', 'in route order', 'in the
    sequence listed', 'in the order I logged them'), free ones say it is open ('Marks may be rounded in any
    order', 'Whatever order you fancy', 'at the counter's discretion', 'No particular order'). A single goal gets
    neither kind of cue, and no frame adds a digit."""
    voice = int(rng.integers(len(_VOICES)))
    frame = int(rng.integers(_FRAMES))
    return _VOICES[voice](rng, list(res), order, frame)
