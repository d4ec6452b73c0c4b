"""Held-out sentence set AS (split `unseen_as`): multi-goal instructions for the home robot, written fresh by
four people nobody tuned a reader on. It measures how the instruction readers cope with new authors; the goals
themselves are the episode generator's, only the words round them are this set's.

Who wrote it: a helper session started by the project, told to write a new set without reading any reader or any
other set's wording, and working only in its own worktree.

What it read: the `def` lines and docstrings of the four public functions of phrasings_w.py (not their bodies,
private helpers or module docstring); types.py and template_text.py, whole; the `UNSEEN_TEMPLATES` dict and the
`_renderer` function of episodes.py (printed alone with `ast`); the `EPISODE_SPLITS` tuple of config.py (printed
alone with `ast`); tests/test_heldout_sets.py, whole; the `subgoals()` strategy of tests/test_phrasings_dev8.py
with the `targets` strategy and HEADS, MODS, STATES and ROOMS it draws from (printed alone with `ast`); the
`[tool.ruff]` table of pyproject.toml; and the value of `types.READINGS` (the ten reading keys), printed at run
time, since a sensor phrase has to name its reading.

The four voices (one drawn per whole instruction):
  * A site foreman's snag list before handover: a 'SNAG LIST' header and dashed lines, or a spoken walk-round
    ('few snags for you before the client walks round', 'wants making good', 'Start with ...', 'Last of all,
    ...'); fixed order as 'don't touch a snag till the one above it's signed off', 'the trades are booked in that
    sequence'; open as 'pick them off however suits you', 'Don't matter what order you do 'em in'; signs off
    'Ta. Shout if owt's not right.'
  * A cycling team's directeur sportif on race radio: run-on bursts ('Okay, can you hear me? Good.', 'First up,
    ...', 'To finish, ...', 'Full gas when it counts. Allez allez!'); fixed order as 'no freelancing', 'like the
    route of the stage, nothing out of turn'; open as 'freelance it', 'hit them whenever you see a gap'.
  * A household committee's minutes secretary: 'MINUTES OF THE HOUSEHOLD COMMITTEE', 'Apologies: none.', 'It was
    RESOLVED that ...', lettered items, 'ACTION: robot.', 'There being no further business, the meeting closed.',
    or an 'Any other business' minute ending 'carried.'; fixed order as 'strictly in the order minuted', 'in the
    order set out below and in no other'; open as 'Members did not consider the sequence material', 'No order of
    priority was agreed'.
  * A camera-club leader's photo-walk shot list: 'Photo walk: shot list', 'Shot:' lines, 'Happy snapping!', or a
    chatty 'Golden hour's nearly here' run with 'open with ...; next, ...; and wrap with ...'; fixed order as
    'we're chasing the light round the house, so no skipping ahead'; open as 'we'll sort it all out in the edit',
    'shoot them as you come across them'.

Style guide (goal wording is one plain pool the voices share; the voice lives in the frame): a goal is 'the' +
[superlative adjective] + [states, hyphenated] + the attributes as the phrase gives them + the head noun as given,
or the states follow ('that is switched on') when the room is absent or possessive; the room follows the noun ('in
the nursery') or precedes it as a possessive ('the nursery's warmest teal lamp'), inside the superlative's scope;
then the sensor tail ('with a humidity of at most forty per cent', 'weighing more than 2.5 kg', 'with the highest
air pressure'); then the coordinate hint, x then y, numbers exactly as given and no digit after them; relations
last ('next to the sofa (the one on top of the drums)', two of a target's as 'both next to ... and behind ...').
Sensor values are the shortest decimal that reads back or number words for whole numbers under a hundred; °F and
kW only when they convert back exactly (the constraint keeps the canonical value, unit as written: 'f', 'kw');
the unit keys 'db', 'lux', 'w', 'kg' and 'hpa' are this author's guess from the examples in types.py ('c', 'f',
'%', 'ppm', 'kw'), since the reading table itself was not opened; carbon dioxide is spelled out. Goals are set
apart by new lines, semicolons, sentences or sequence words, never a bare 'and'. Strict texts say in words that
the order is fixed, free ones that it is open, a single goal says neither; frames hold no digit.

Tests broken on purpose: (1) the foreman's second strict cue was cut down to 'Take them, no jumping ahead.' (no
longer saying the order is fixed in words of order): test_order_cues failed; restored. (2) hint_text_as wrote y
before x: test_goal_parts and test_hint_reads_x_then_y failed; restored.

Slips: None.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.template_text import (
    attributes_and_states,
    hyphenated,
    is_are,
    number_words,
    plural,
    tidy,
)
from ragnav_jax.language.types import SensorConstraint, Subgoal, Target


def _pick(rng: np.random.Generator, options):
    return options[int(rng.integers(len(options)))]


# ----------------------------------------------------------------------------------------------------
# Goals


_REL = {
    "near": ("near", "close to"),
    "next_to": ("next to", "alongside"),
    "beside": ("beside",),
    "by": ("by",),
    "on": ("on", "on top of"),
    "under": ("under", "underneath"),
    "above": ("above",),
    "in": ("inside",),
    "with": ("with",),
    "in_room_with": ("in the same room as", "in the room with"),
    "in_front_of": ("in front of",),
    "behind": ("behind",),
    "opposite": ("opposite", "across from"),
    "left_of": ("to the left of",),
    "right_of": ("to the right of",),
}


def _core(t: Target) -> tuple[str, list[str]]:
    """(the attributes as the phrase gives them plus the head, the states)."""
    pre, states = attributes_and_states(t)
    core = t.phrase if t.phrase.endswith(t.head) else " ".join([*pre, t.head])
    return core, states


def _anchor(rng: np.random.Generator, t: Target) -> str:
    core, states = _core(t)
    out = "the " + (hyphenated(states) + " " if states else "") + core
    if t.relations:
        lead = _pick(rng, ("the ones " if plural(t.head) else "the one ", f"which {is_are(t.head)} ", "itself "))
        if lead == "itself " and plural(t.head):
            lead = "themselves "
        parts = [_relation(rng, r) for r in t.relations]
        out += " (" + lead + parts[0] + "".join(", and also " + p for p in parts[1:]) + ")"
    return out


def _relation(rng: np.random.Generator, r) -> str:
    return _pick(rng, _REL.get(r.type, (r.type.replace("_", " "),))) + " " + _anchor(rng, r.anchor)


def render_goal_as(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AS writes it: 'the warmest switched-on teal lamp in the nursery', "the nursery's teal lamp
    that is switched on", 'the drums in the games room with a noise level of at most fifty decibels, at x 3.5, y
    2', 'the sofa both next to the lamp (the one on top of the drums) and behind the toolbox'. The room comes
    before the sensor tail (so a superlative tail is read inside it), the coordinate hint after the tail, the
    relations last."""
    t = sg.target
    core, states = _core(t)
    after = bool(states) and bool(rng.integers(2))
    possessive = sg.room is not None and (after or bool(rng.integers(2)))
    words = ["the"]
    if possessive:
        words = [f"the {sg.room}'s"]
    if prefix:
        words.append(prefix)
    if states and not after:
        words.append(hyphenated(states))
    words.append(core)
    out = " ".join(words)
    if after:
        out += f" that {is_are(t.head)} " + " and ".join(states)
    if sg.room is not None and not possessive:
        out += f" in the {sg.room}"
    if tail:
        out += (", " if after else " ") + tail
    if hint:
        out += (", " if tail or after else " ") + hint
    if t.relations:
        rels = [_relation(rng, r) for r in t.relations]
        if len(rels) == 2:
            joined = "both " + rels[0] + " and " + rels[1]
        else:
            joined = rels[0] + "".join(", and also " + r for r in rels[1:])
        out += (", " if tail or hint or after else " ") + joined
    return tidy(out)


# ----------------------------------------------------------------------------------------------------
# Sensor phrases

# reading -> (adjectives for max, tails for max, adjectives for min, tails for min)
_SUPER = {
    "temperature_c": (("warmest", "hottest"), ("with the highest temperature",),
                      ("coldest", "coolest"), ("with the lowest temperature",)),
    "ndvi": ((), ("with the highest NDVI", "with the highest NDVI reading"),
             (), ("with the lowest NDVI", "with the lowest NDVI reading")),
    "humidity_pct": (("dampest", "most humid"), ("with the highest humidity",),
                     ("driest", "least humid"), ("with the lowest humidity",)),
    "co2_ppm": ((), ("with the highest carbon dioxide level", "with the most carbon dioxide around it"),
                (), ("with the lowest carbon dioxide level", "with the least carbon dioxide around it")),
    "noise_db": (("loudest", "noisiest"), ("with the highest noise level",),
                 ("quietest",), ("with the lowest noise level",)),
    "light_lux": (("brightest", "best-lit"), ("with the most light on it",),
                  ("dimmest", "worst-lit"), ("with the least light on it",)),
    "battery_pct": ((), ("with the most battery charge left", "with the highest battery level"),
                    (), ("with the least battery charge left", "with the lowest battery level")),
    "power_w": (("most power-hungry",), ("drawing the most power",),
                ("least power-hungry",), ("drawing the least power",)),
    "weight_kg": (("heaviest",), ("that weighs the most",), (), ("that weighs the least",)),
    "pressure_hpa": ((), ("with the highest air pressure",), (), ("with the lowest air pressure",)),
}

# reading -> what a threshold tail calls the quantity
_QTY = {
    "temperature_c": ("a temperature",),
    "ndvi": ("an NDVI", "an NDVI reading"),
    "humidity_pct": ("a humidity", "a relative humidity"),
    "co2_ppm": ("a carbon dioxide level", "a carbon dioxide reading"),
    "noise_db": ("a noise level", "a sound level"),
    "light_lux": ("a light level", "a light reading"),
    "battery_pct": ("a battery level", "a battery charge"),
    "power_w": ("a power draw",),
    "weight_kg": ("a weight",),
    "pressure_hpa": ("an air pressure", "a pressure reading"),
}

_CMP = {
    "gt": ("above {q}", "of more than {q}", "higher than {q}"),
    "ge": ("of at least {q}", "of {q} or more", "no lower than {q}"),
    "lt": ("below {q}", "of less than {q}", "lower than {q}"),
    "le": ("of at most {q}", "of {q} or less", "no higher than {q}"),
    "approx": ("of about {q}", "of around {q}", "of roughly {q}"),
}
_VERB_CMP = {
    "gt": ("more than {q}",), "ge": ("at least {q}", "{q} or more"), "lt": ("less than {q}", "under {q}"),
    "le": ("at most {q}", "no more than {q}"), "approx": ("about {q}", "roughly {q}"),
}

# unit as written -> (symbol after digits, words (singular, plural)); the symbol None means words only
_UNITS = {
    "c": (" °C", ("degree Celsius", "degrees Celsius")),
    "f": (" °F", ("degree Fahrenheit", "degrees Fahrenheit")),
    "%": ("%", ("per cent", "per cent")),
    "ppm": (" ppm", ("part per million", "parts per million")),
    "db": (" dB", ("decibel", "decibels")),
    "lux": (" lux", ("lux", "lux")),
    "w": (" W", ("watt", "watts")),
    "kw": (" kW", ("kilowatt", "kilowatts")),
    "kg": (" kg", ("kilogram", "kilograms")),
    "hpa": (" hPa", ("hectopascal", "hectopascals")),
    "": ("", ("", "")),
}
_CANON_UNIT = {"temperature_c": "c", "ndvi": "", "humidity_pct": "%", "co2_ppm": "ppm", "noise_db": "db",
               "light_lux": "lux", "battery_pct": "%", "power_w": "w", "weight_kg": "kg", "pressure_hpa": "hpa"}


def _digits(v: float) -> str:
    """The shortest decimal that reads back as v."""
    v = float(v)
    if v.is_integer():
        return str(int(v))
    return np.format_float_positional(v, unique=True, trim="-")


def _quantity(rng: np.random.Generator, v: float, unit: str) -> str:
    """v in the unit as written: number words for a whole number under a hundred (sometimes), else digits."""
    symbol, (one, many) = _UNITS[unit]
    whole = float(v).is_integer() and abs(v) < 100
    if whole and (not unit or rng.integers(2)):
        n = int(v)
        w = number_words(n)
        return w + (" " + (one if abs(n) == 1 else many) if unit else "")
    txt = _digits(v)
    if unit and (symbol is None or rng.integers(3) == 0):
        return txt + " " + (one if float(v) in (1.0, -1.0) else many)
    return txt + symbol


def _alternative(c: SensorConstraint) -> tuple[str, float] | None:
    """A non-canonical unit that converts back to exactly c.value: (unit, value in it), or None."""
    v = float(c.value)
    if c.reading == "temperature_c":
        f = float(_digits(v * 9 / 5 + 32))
        if (f - 32) * 5 / 9 == v and (f - 32) / 1.8 == v:
            return "f", f
    if c.reading == "power_w" and abs(v) >= 1000:
        k = float(_digits(v / 1000))
        if k * 1000 == v:
            return "kw", k
    return None


def render_sensor_as(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('warmest', 'most humid', 'least power-hungry') or a tail ('with
    the highest NDVI', 'with the least carbon dioxide around it', 'that weighs the most'); thresholds after the
    noun ('with a temperature of at least 104 °F', 'with a humidity of at most forty per cent', 'with a power draw
    above 1.5 kW', 'weighing at least 2.5 kg', 'with an NDVI of roughly 0.65')."""
    if c.is_superlative:
        up, up_tails, down, down_tails = _SUPER[c.reading]
        adjectives, tails = (up, up_tails) if c.comparator == "max" else (down, down_tails)
        written = SensorConstraint(c.reading, c.comparator, None, "")
        if adjectives and rng.integers(2):
            return _pick(rng, adjectives), "", written
        return "", _pick(rng, tails), written
    unit, value = _CANON_UNIT[c.reading], float(c.value)
    alt = _alternative(c)
    if alt is not None and rng.integers(3) == 0:
        unit, value = alt
    q = _quantity(rng, value, unit)
    written = SensorConstraint(c.reading, c.comparator, float(c.value), unit)
    if c.reading == "weight_kg" and rng.integers(2):
        return "", "weighing " + _pick(rng, _VERB_CMP[c.comparator]).format(q=q), written
    if c.reading == "power_w" and rng.integers(2):
        return "", "drawing " + _pick(rng, _VERB_CMP[c.comparator]).format(q=q), written
    return "", f"with {_pick(rng, _QTY[c.reading])} " + _pick(rng, _CMP[c.comparator]).format(q=q), written


def hint_text_as(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at x 3.5, y 2', 'at the point (3.5, 2)',
    'around x = 3.5, y = 2', 'at coordinates x 3.5 and y 2', 'at the spot where x is 3.5 and y is 2'."""
    return _pick(rng, ("at x {x}, y {y}", "at the point ({x}, {y})", "around x = {x}, y = {y}",
                       "at coordinates x {x} and y {y}", "at the spot where x is {x} and y is {y}")).format(x=x, y=y)


# ----------------------------------------------------------------------------------------------------
# Whole instructions: four people, two frames each


def _strict_steps(rng: np.random.Generator, res: list[str], first, middle, last) -> list[str]:
    """Each goal led by a sequence word: first, middle ones, last."""
    out = [_pick(rng, first).format(g=res[0])]
    out += [_pick(rng, middle).format(g=g) for g in res[1:-1]]
    out.append(_pick(rng, last).format(g=res[-1]))
    return out


# --- a site foreman's snag list

_FOREMAN_STRICT = ("Work down the list top to bottom in the order written; don't touch a snag till the one above "
                   "it's signed off.",
                   "Take them in that order, no jumping ahead, the trades are booked in that sequence.",
                   "Same order as listed, one after the other, no skipping about.")
_FOREMAN_FREE = ("Order's not important, pick them off however suits you.",
                 "Do them in any order you like, as long as they all get done.",
                 "No set sequence on these, whichever you reach first is fine by me.")
_FOREMAN_SIGN = ("Cheers, site foreman", "Ta. Shout if owt's not right.", "Make good and report back. Foreman")


def _foreman_list(rng: np.random.Generator, res: list[str], order: str) -> str:
    head = _pick(rng, ("SNAG LIST: walk-round before handover", "Snagging, house walk-round", "SNAGS OUTSTANDING"))
    if len(res) == 1:
        intro = _pick(rng, ("Robot, this wants making good before the client comes round:",
                            "Item still to be made good:"))
        return f"{head}\n{intro}\n– {res[0]}\n{_pick(rng, _FOREMAN_SIGN)}"
    intro = _pick(rng, ("Robot, the following want making good before the client comes round:",
                        "Items still to be made good:", "Right, here's what's left on the snag list:"))
    lines = "\n".join("– " + g for g in res)
    cue = _pick(rng, _FOREMAN_STRICT if order == "strict" else _FOREMAN_FREE)
    return f"{head}\n{intro}\n{lines}\n{cue}\n{_pick(rng, _FOREMAN_SIGN)}"


def _foreman_talk(rng: np.random.Generator, res: list[str], order: str) -> str:
    opening = _pick(rng, ("Right robot, few snags for you before the client walks round.",
                          "Morning robot, bit of snagging wants doing before handover."))
    close = _pick(rng, ("Cheers.", "Ta, robot.", "Nice one."))
    if len(res) == 1:
        return f"{opening} Only snag left is {res[0]}. {close}"
    if order == "strict":
        steps = _strict_steps(rng, res, ("Start with {g}.", "First off, {g}."),
                              ("Then {g}.", "After that, {g}.", "Next, {g}."), ("Last of all, {g}.", "Finish on {g}."))
        cue = _pick(rng, ("Keep to that order, mind, don't jump ahead.", "In that order, mind, one at a time."))
        return f"{opening} {' '.join(steps)} {cue} {close}"
    body = "; ".join(res)
    cue = _pick(rng, ("Don't matter what order you do 'em in.", "Any order's fine, just get 'em done."))
    return f"{opening} There's {body}. {cue} {close}"


# --- a cycling team's directeur sportif on race radio

_DS_STRICT = ("We ride them in the order I call them, no freelancing.",
              "One after the other in exactly this order; you don't go for the next until the last one's done.",
              "Stick to this order, like the route of the stage, nothing out of turn.")
_DS_FREE = ("No set order today, freelance it, take them however you like.",
            "The order doesn't matter, hit them whenever you see a gap.",
            "Any of them can come first, it's your call out there.")


def _ds_brief(rng: np.random.Generator, res: list[str], order: str) -> str:
    opening = _pick(rng, ("Okay, can you hear me? Good.", "Okay, listen up, this is the plan for today's stage.",
                          "Okay robot, DS here, this is how we ride it today."))
    close = _pick(rng, ("Stay calm, ride smart, allez!", "Full gas when it counts. Allez allez!", "Chapeau, let's go."))
    if len(res) == 1:
        return f"{opening} Only objective today is {res[0]}. {close}"
    if order == "strict":
        steps = _strict_steps(rng, res, ("First up, {g}.", "We open with {g}."),
                              ("Then {g}.", "After that, {g}.", "Next up, {g}."), ("To finish, {g}.", "Finally, {g}."))
        return f"{opening} {_pick(rng, _DS_STRICT)} {' '.join(steps)} {close}"
    first = _pick(rng, ("We want {g}.", "Keep an eye out for {g}."))
    others = ("We also want {g}.", "Don't forget {g}.", "Plus there's {g}.")
    rest = [others[int(i) % len(others)] for i in rng.permutation(max(len(res) - 1, len(others)))]
    body = " ".join([first.format(g=res[0])] + [lead.format(g=g) for lead, g in zip(rest, res[1:])])
    return f"{opening} {body} {_pick(rng, _DS_FREE)} {close}"


def _ds_bursts(rng: np.random.Generator, res: list[str], order: str) -> str:
    head = _pick(rng, ("Stage plan, from the DS.", "DS here, listen in."))
    close = _pick(rng, ("Copy? Good. Allez!", "Save your legs, boys. Allez!"))
    if len(res) == 1:
        return f"{head}\nAll we want today:\n{res[0]}.\n{close}"
    if order == "strict":
        lines = [res[0]] + ["then " + g for g in res[1:]]
        cue = _pick(rng, ("In this order, no exceptions:", "Exactly this order, nothing out of turn:"))
        return f"{head}\n{cue}\n" + ";\n".join(lines) + f".\n{close}"
    cue = _pick(rng, ("Order's up to you, freelance it:", "No set order on these, take them however you like:"))
    return f"{head}\n{cue}\n" + ";\n".join(res) + f".\n{close}"


# --- a household committee's minutes secretary

_MIN_STRICT = ("strictly in the order minuted, no item to be taken before those above it are complete",
               "in the sequence recorded below, as agreed by the meeting; no item to be brought forward",
               "in the order set out below and in no other")
_MIN_FREE = ("Members did not consider the sequence material; the robot may take the items in whatever order it "
             "sees fit.",
             "No order of priority was agreed; any order is acceptable to the committee.",
             "The meeting noted that the items may be taken in any order.")
_LETTERS = "abcdefghijklmnopqrstuvwxyz"


def _minutes(rng: np.random.Generator, res: list[str], order: str) -> str:
    head = ("MINUTES OF THE HOUSEHOLD COMMITTEE\nPresent: Secretary, Treasurer; the robot in attendance.\n"
            + _pick(rng, ("Apologies: none.", "Apologies: received from the Treasurer's partner.")))
    end = _pick(rng, ("ACTION: robot.\nThere being no further business, the meeting closed.",
                      "ACTION: robot, to report back at the next meeting.\nMeeting closed."))
    if len(res) == 1:
        return f"{head}\nMatters arising\nIt was RESOLVED that the robot attend to {res[0]}.\n{end}"
    if order == "strict":
        items = "\n".join(f"({_LETTERS[i % 26]}) {g}" + (";" if i < len(res) - 1 else ".") for i, g in enumerate(res))
        return (f"{head}\nMatters arising\nIt was RESOLVED that the robot attend to the following, "
                f"{_pick(rng, _MIN_STRICT)}:\n{items}\n{end}")
    items = "\n".join("• " + g for g in res)
    return (f"{head}\nMatters arising\nIt was AGREED that the robot attend to the following. "
            f"{_pick(rng, _MIN_FREE)}\n{items}\n{end}")


def _minutes_aob(rng: np.random.Generator, res: list[str], order: str) -> str:
    head = "Any other business"
    carried = _pick(rng, ("Proposed by the Treasurer, seconded by the Secretary; carried.",
                          "Agreed without objection."))
    if len(res) == 1:
        return f"{head}\nThe Secretary asked that the robot see to {res[0]}. {carried}"
    if order == "strict":
        steps = _strict_steps(rng, res, ("first, {g}",), ("then {g}", "thereafter {g}"), ("finally, {g}",))
        cue = _pick(rng, ("The items are to be taken strictly in the order stated.",
                          "The sequence above was agreed and is not to be varied."))
        return (f"{head}\nThe Secretary asked that the robot see to the following in turn: {'; '.join(steps)}. "
                f"{cue} {carried}")
    cue = _pick(rng, ("The order was left open; any item may be taken first.",
                      "No order of priority was agreed between them."))
    return f"{head}\nThe Secretary asked that the robot see to {'; '.join(res)}. {cue} {carried}"


# --- a camera-club leader's photo-walk shot list

_PHOTO_STRICT = ("Shoot them in the order listed; we're chasing the light round the house, so no skipping ahead.",
                 "Keep to the running order, shot by shot, top to bottom; the light won't wait.",
                 "Take them in exactly this sequence, each shot only once the one before it's done.")
_PHOTO_FREE = ("No particular order, shoot them as you come across them.",
               "Order doesn't matter, we'll sort it all out in the edit.",
               "Any order you fancy, just make sure every shot gets taken.")
_PHOTO_SIGN = ("Happy snapping!", "Watch your exposure, and have fun!", "See you at review night!")


def _photo_list(rng: np.random.Generator, res: list[str], order: str) -> str:
    head = _pick(rng, ("Photo walk: shot list", "Photo club walk, shot list"))
    intro = _pick(rng, ("Morning all! Here's what I'm after today:", "Shots wanted for today's walk:"))
    mark = _pick(rng, ("Shot: ", "• "))
    lines = "\n".join(mark + g for g in res)
    if len(res) == 1:
        return f"{head}\n{intro}\n{lines}\n{_pick(rng, _PHOTO_SIGN)}"
    cue = _pick(rng, _PHOTO_STRICT if order == "strict" else _PHOTO_FREE)
    return f"{head}\n{intro}\n{lines}\n{cue}\n{_pick(rng, _PHOTO_SIGN)}"


def _photo_chat(rng: np.random.Generator, res: list[str], order: str) -> str:
    sign = _pick(rng, _PHOTO_SIGN)
    if len(res) == 1:
        return f"Only shot I need today is {res[0]}. Keep it sharp! {sign}"
    if order == "strict":
        steps = _strict_steps(rng, res, ("open with {g}",), ("next, {g}", "then {g}"), ("and wrap with {g}",))
        return (f"Golden hour's nearly here, so here's the running order for the shots: {'; '.join(steps)}. "
                f"No skipping ahead, the light moves round the house as we go. {sign}")
    return f"On my wish list today: {'; '.join(res)}. {_pick(rng, _PHOTO_FREE)} {sign}"


# (voice, frame) -> writer; one drawn per instruction
_FRAMES = (("foreman", _foreman_list), ("foreman", _foreman_talk), ("ds", _ds_brief), ("ds", _ds_bursts),
           ("minutes", _minutes), ("minutes", _minutes_aob), ("photo", _photo_list), ("photo", _photo_chat))


def render_instruction_as(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a site foreman's snag list, a cycling
    directeur sportif on race radio, a household committee's minutes secretary, a camera-club photo-walk leader).
    Goals stay in visiting order, each written once as rendered; strict texts say the order is fixed ('in the order
    written', 'no freelancing', 'strictly in the order minuted', 'Shoot them in the order listed'), free ones say
    it is open ('pick them off however suits you', 'freelance it', 'No order of priority was agreed', 'we'll sort
    it all out in the edit'). A single goal gets neither kind of cue and no digit."""
    _, frame = _FRAMES[int(rng.integers(len(_FRAMES)))]
    return frame(rng, list(res), order)
