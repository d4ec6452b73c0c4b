"""Held-out sentence set AO (split `unseen_ao`): four new voices for measuring, fresh, how the instruction readers
cope with phrasings nobody tuned them on.

Who wrote it: a helper session that never read the readers (parser, lexicon, tagger, sensor reader, grounding, LLM
adapter, agreement, evaluation) nor any other `phrasings_*.py` body. What it read: the signatures and docstrings of
the four public functions of `phrasings_w.py`; `types.py` and `template_text.py` whole; `UNSEEN_TEMPLATES` and
`_renderer` in `episodes.py`; `EPISODE_SPLITS` in `config.py`; `tests/test_heldout_sets.py` whole; the `subgoals()`
strategy in `tests/test_phrasings_dev8.py` (and printed sample values it draws, to see what targets look like).

The four voices (one per whole instruction, drawn from the generator passed in):
  * a reference librarian writing a call slip for the stacks ('retrieve in the order on this slip', 'browse
    them in whatever order you like');
  * a diplomatic protocol officer briefing a state visit ('strict order of precedence', 'no order of precedence
    applies');
  * a flight attendant making a cabin announcement ('in exactly that boarding order, please do not board out of
    turn', 'in whichever order suits you');
  * a mathematician writing a proof ('a fixed sequence: each term is visited only after its predecessor', 'the
    visiting order is arbitrary; any permutation will do').

Style guide: a goal reads 'the [superlative] [attributes] HEAD [states] [room] [sensor tail] [coordinate hint]
[relations]'; the head is written exactly as given; attributes stay before the noun or come as 'of the A and B
variety'; states come hyphenated before the noun or as 'that is / currently S'; the room comes before any relation
and before a superlative tail, which is read inside it; a coordinate hint is x then y in digits and is the last thing
with digits in a goal; an anchor's own relations sit in parentheses after it. Sensor values are exact: digits (the
shortest decimal of the value), words for whole numbers, or an exact unit change (°F, kW, g, mbar) whose decimal
converts back exactly. Goals keep visiting order and appear once each, verbatim. Multi-goal texts always say in words
whether the order is fixed or free; a single goal gets neither cue and no digit in its frame.

Checked by breaking it on purpose once (dropping the free-order clause of the protocol officer, and writing sensor
values rounded to one decimal): tests/test_phrasings_ao.py failed, then passed again once restored.

Slips: while printing the allowed regions I also saw, by accident: the `_rng` function right after `_renderer` in
`episodes.py`; one line of `config.py` that checks `episodes.split` against `EPISODE_SPLITS`; the `def _pick`
signature line of `episodes.py` (from a grep for `_renderer`); and the small helpers `_words`, `_has` and
`_all_targets` that follow `subgoals()` in `tests/test_phrasings_dev8.py`. Nothing else.
"""

from __future__ import annotations

from decimal import Decimal

import numpy as np

from ragnav_jax.language import template_text as tt
from ragnav_jax.language.template_text import attributes_and_states, both, hyphenated, listed, number_words, tidy
from ragnav_jax.language.types import SensorConstraint, Subgoal, Target

VOICES = ("librarian", "protocol officer", "flight attendant", "mathematician")


def _pick(rng: np.random.Generator, items):
    return items[int(rng.integers(len(items)))]


# ----------------------------------------------------------------------------------------------------
# Goals

_REL = {
    "near": ("near", "not far from", "within easy reach of"),
    "next_to": ("next to", "alongside", "right next to"),
    "beside": ("beside",),
    "by": ("by",),
    "on": ("on", "on top of", "resting on"),
    "under": ("under", "beneath", "underneath"),
    "above": ("above", "over"),
    "in": ("in", "inside"),
    "with": ("with", "complete with", "that has"),
    "in_room_with": ("in the same room as", "in the room with", "sharing a room with"),
    "in_front_of": ("in front of", "just in front of"),
    "behind": ("behind", "just behind"),
    "opposite": ("opposite", "across from", "facing"),
    "left_of": ("to the left of", "on the left-hand side of"),
    "right_of": ("to the right of", "on the right-hand side of"),
}
_ROOM = ("in the {r}", "over in the {r}", "found in the {r}", "kept in the {r}")


def _noun(rng: np.random.Generator, t: Target, prefix: str = "") -> str:
    """'the [prefix] [attributes] head [states]' with the attributes and states in one of a few layouts."""
    pre, states = attributes_and_states(t)
    head = t.head
    if pre and rng.random() < 0.3:
        core = f"{prefix} {head} of the {both(pre)} variety"
    else:
        core = f"{prefix} {' '.join(pre)} {head}"
    if states:
        if rng.random() < 0.4:
            core = f"{prefix} {hyphenated(states)} {core[len(prefix):].strip()}"
        else:
            core += " " + _pick(rng, ("that {v} {s}", "currently {s}", "which {v} {s} at present")).format(
                s=both(states), v=tt.is_are(head))
    return tidy("the " + core)


def _relations(rng: np.random.Generator, t: Target) -> str:
    parts = [f"{_pick(rng, _REL.get(r.type, (r.type.replace('_', ' '),)))} {_anchor(rng, r.anchor)}"
             for r in t.relations]
    out = ""
    for i, p in enumerate(parts):
        out += p if i == 0 else _pick(rng, (" and also ", " as well as ")) + p
    return out


def _anchor(rng: np.random.Generator, t: Target) -> str:
    text = _noun(rng, t)
    if t.relations:
        text += f" ({_pick(rng, ('the one', 'itself', 'which is'))} {_relations(rng, t)})"
    return text


def render_goal_ao(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AO writes it: 'the teal wool lamp over in the nursery', 'the lamp of the teal and wool variety',
    'the switched-on lamp', 'the lamp currently open', 'the warmest mini-fridge kept in the pantry', 'the guitar at
    the point (3.5, 2)', 'the shelves to the left of the appliance (the one next to the tool chest) and also beside
    the lamp'. The room comes before any relation and before a superlative tail (read inside it); a coordinate hint
    comes after a sensor tail; relations come last."""
    parts = [_noun(rng, sg.target, prefix)]
    if sg.room:
        parts.append(_pick(rng, _ROOM).format(r=sg.room))
    if tail:
        parts.append(tail)
    if hint:
        parts.append(hint)
    if sg.target.relations:
        parts.append(_relations(rng, sg.target))
    return tidy(" ".join(parts))


# ----------------------------------------------------------------------------------------------------
# Sensors

# reading -> (names, [(unit as written, scale, offset, symbol forms, word forms)]); written = value * scale + offset
_D = Decimal
_PCT = [("%", _D(1), _D(0), ("{}%",), ("{} per cent", "{} percent"))]
_SENS = {
    "temperature_c": (("temperature", "air temperature"),
                      [("c", _D(1), _D(0), ("{} °C", "{}°C"), ("{} degrees Celsius", "{} degrees C")),
                       ("f", _D("1.8"), _D(32), ("{} °F",), ("{} degrees Fahrenheit",))]),
    "ndvi": (("NDVI", "vegetation index (NDVI)"), [("", _D(1), _D(0), ("{}",), ())]),
    "humidity_pct": (("humidity", "relative humidity"), _PCT),
    "co2_ppm": (("carbon dioxide level", "CO₂ concentration"),
                [("ppm", _D(1), _D(0), ("{} ppm",), ("{} parts per million",))]),
    "noise_db": (("noise level", "sound level"), [("db", _D(1), _D(0), ("{} dB",), ("{} decibels",))]),
    "light_lux": (("light level", "illuminance"), [("lux", _D(1), _D(0), ("{} lux", "{} lx"), ("{} lux",))]),
    "battery_pct": (("battery charge", "battery level"), _PCT),
    "power_w": (("power draw", "power consumption"),
                [("w", _D(1), _D(0), ("{} W",), ("{} watts",)),
                 ("kw", _D("0.001"), _D(0), ("{} kW",), ("{} kilowatts",))]),
    "weight_kg": (("weight", "mass"),
                  [("kg", _D(1), _D(0), ("{} kg",), ("{} kilograms", "{} kilos")),
                   ("g", _D(1000), _D(0), ("{} g",), ("{} grams",))]),
    "pressure_hpa": (("air pressure", "barometric pressure"),
                     [("hpa", _D(1), _D(0), ("{} hPa",), ("{} hectopascals",)),
                      ("mbar", _D(1), _D(0), ("{} mbar",), ("{} millibars",))]),
}
_MOST = {"temperature_c": (("warmest", "hottest"), ("coolest", "coldest")),
         "humidity_pct": (("most humid",), ("least humid", "driest")),
         "noise_db": (("loudest", "noisiest"), ("quietest",)),
         "light_lux": (("brightest",), ("dimmest", "darkest")),
         "battery_pct": (("most charged",), ("least charged",)),
         "power_w": (("most power-hungry",), ("least power-hungry",)),
         "ndvi": (("greenest",), ("least green",))}
_CMP = {
    "gt": ("with {a} {n} above {q}", "whose {n} is more than {q}", "with {a} {n} higher than {q}"),
    "ge": ("with {a} {n} of at least {q}", "whose {n} is {q} or more", "with {a} {n} no lower than {q}"),
    "lt": ("with {a} {n} below {q}", "whose {n} is less than {q}", "with {a} {n} lower than {q}"),
    "le": ("with {a} {n} of at most {q}", "whose {n} is {q} or less", "with {a} {n} no higher than {q}"),
    "approx": ("with {a} {n} of about {q}", "whose {n} is roughly {q}", "with {a} {n} of approximately {q}"),
    "max": ("with the highest {n} of all", "whose {n} is the highest", "that has the greatest {n}"),
    "min": ("with the lowest {n} of all", "whose {n} is the lowest", "that has the least {n}"),
}


def _plain(d: Decimal) -> str:
    """A decimal without exponent or trailing zeros: 40.0 -> '40', 0.650 -> '0.65', -0.5 -> '-0.5'."""
    s = format(d.normalize(), "f")
    return "0" if s in ("-0", "") else s


def render_sensor_ao(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('warmest', 'least humid', 'most power-hungry') or a tail ('with the
    highest temperature of all', 'whose CO₂ concentration is the lowest'); thresholds after the noun ('with a
    temperature above 40 °C', 'whose humidity is forty per cent or less', 'with an NDVI of about 0.65', 'with a
    power draw of at least 1.5 kW', 'with a temperature no lower than 104 degrees Fahrenheit'). Unit changes are
    exact in decimal, so the written number converts back to the value without rounding."""
    names, units = _SENS.get(c.reading, ((c.reading.replace("_", " "),), [("", _D(1), _D(0), ("{}",), ())]))
    name = _pick(rng, names)
    if c.is_superlative:
        if c.reading in _MOST and rng.random() < 0.5:
            return _pick(rng, _MOST[c.reading][c.comparator == "min"]), "", SensorConstraint(c.reading, c.comparator)
        return "", _pick(rng, _CMP[c.comparator]).format(n=name, a=""), SensorConstraint(c.reading, c.comparator)
    unit, scale, offset, symbols, words = _pick(rng, units)
    written = _D(repr(float(c.value))) * scale + offset
    integral = written == written.to_integral_value() and abs(written) < 1000
    if words and integral and rng.random() < 0.4:
        q = _pick(rng, words).format(number_words(int(written)))
    else:
        q = _pick(rng, symbols + words).format(_plain(written))
    art = "an" if name[0] in "aeiouAEIOU" or name.startswith("NDVI") else "a"
    tail = _pick(rng, _CMP.get(c.comparator, _CMP["approx"])).format(n=name, a=art, q=q)
    return "", tail, SensorConstraint(c.reading, c.comparator, c.value, unit)


# ----------------------------------------------------------------------------------------------------
# Coordinate hints


def hint_text_ao(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y: 'at the point ({x}, {y})', 'at x {x}, y {y}', 'at
    coordinates x = {x}, y = {y}', 'positioned {x} m along x and {y} m along y', 'whose position is x {x} and y
    {y}'."""
    return _pick(rng, ("at the point ({x}, {y})", "at x {x}, y {y}", "at coordinates x = {x}, y = {y}",
                       "positioned {x} m along x and {y} m along y", "whose position is x {x} and y {y}")
                 ).format(x=x, y=y)


# ----------------------------------------------------------------------------------------------------
# Whole instructions


def _seq(rng: np.random.Generator, res: list[str], first: str, then: str, last: str) -> str:
    """'first A, then B, then C, and finally D' in a voice's own words; semicolons where a goal has commas."""
    sep = "; " if any("," in r for r in res) else ", "
    out = f"{first} {res[0]}"
    for r in res[1:-1]:
        out += f"{sep}{then} {r}"
    return out + f"{sep}{last} {res[-1]}"


def _librarian(rng, res, order):
    if len(res) == 1:
        return _pick(rng, ("Reference desk, library request: kindly retrieve {g} from the stacks. Quiet, please.",
                           "A patron of the library has reserved {g}; would you fetch it from the stacks?",
                           "Library call slip. Item wanted: {g}. Please bring it to the issue desk.")
                     ).format(g=res[0])
    if order == "strict":
        return _pick(rng, (
            lambda: f"Library call slip for the stacks: retrieve {listed(rng, res)}, strictly in the order on this "
                    "slip, one after another, never out of sequence.",
            lambda: "Reshelving run through the library stacks, in call-number order as written here: "
                    + _seq(rng, res, "begin with", "after that", "and last of all") + ". No item before its turn.",
            lambda: f"Interlibrary loan, to be collected in exactly the order listed: {listed(rng, res)}. "
                    "Please keep to the sequence on the slip.",
        ))()
    return _pick(rng, (
        lambda: f"Library call slip: retrieve {listed(rng, res)} from the stacks, in whatever order you like; the "
                "catalogue doesn't mind which comes first.",
        lambda: f"Browsing list for the library stacks: {listed(rng, res)}. Browse them in any order at all.",
        lambda: f"A patron of the library would like {listed(rng, res)}. There is no set order for fetching them; "
                "whichever order suits your round.",
    ))()


def _protocol(rng, res, order):
    if len(res) == 1:
        return _pick(rng, ("Protocol note: the delegation's sole call today is upon {g}.",
                           "Your Excellency is expected at {g}; protocol asks that you present yourself there.",
                           "Programme of the visit, per protocol: a courtesy call at {g}.")).format(g=res[0])
    if order == "strict":
        return _pick(rng, (
            lambda: f"Protocol note for the visit. Calls, in strict order of precedence: {listed(rng, res)}. Each "
                    "call is paid only after the one before it, exactly as set out here.",
            lambda: "Your Excellency, the programme runs in fixed sequence: "
                    + _seq(rng, res, "first a call upon", "thereafter", "and lastly") + ". No call may be made "
                    "ahead of its turn.",
            lambda: f"Order of precedence for today's calls by the delegation, which protocol forbids altering: "
                    f"{listed(rng, res)}, in exactly that order.",
        ))()
    return _pick(rng, (
        lambda: f"Protocol note: no order of precedence applies to today's calls, namely {listed(rng, res)}; the "
                "delegation may pay them in any order it pleases.",
        lambda: f"Your Excellency, an informal programme with precedence waived: call upon {listed(rng, res)} in "
                "whatever order is convenient.",
        lambda: f"For the delegation, per protocol, the calls {listed(rng, res)} carry equal rank, so their order "
                "is entirely at your discretion.",
    ))()


def _cabin(rng, res, order):
    if len(res) == 1:
        return _pick(rng, ("Ladies and gentlemen, this is your cabin crew. Please make your way to {g}. Thank you "
                           "for flying with us.",
                           "Cabin crew here: would the robot kindly proceed to {g} and take its seat there.",
                           "Ladies and gentlemen, for your comfort, your destination this evening is {g}.")
                     ).format(g=res[0])
    if order == "strict":
        return _pick(rng, (
            lambda: "Ladies and gentlemen, we'll be boarding by zones this evening: "
                    + _seq(rng, res, "please make your way first to", "then to", "and finally to")
                    + ", in exactly that boarding order. Please do not board out of turn.",
            lambda: f"Cabin crew, service will come through the aisle in order: {listed(rng, res)}, in that order and "
                    "no other, row by row.",
            lambda: f"Ladies and gentlemen, please visit {listed(rng, res)} strictly in the order announced; each "
                    "stop only after the one before it.",
        ))()
    return _pick(rng, (
        lambda: f"Ladies and gentlemen, the duty-free trolley is open: visit {listed(rng, res)} in whichever order "
                "suits you. There's no queue order this evening.",
        lambda: f"Cabin crew here. At your leisure, please drop in on {listed(rng, res)}, in any order you like.",
        lambda: f"Ladies and gentlemen, you are free to stretch your legs and call at {listed(rng, res)}; the order "
                "is entirely up to you.",
    ))()


def _proof(rng, res, order):
    if len(res) == 1:
        return _pick(rng, ("Let the target be {g}. It suffices to reach it. ∎",
                           "Claim: the robot can reach {g}. Proof: left as an exercise to the robot. QED",
                           "Consider {g}. We show the robot arrives there. ∎")).format(g=res[0])
    if order == "strict":
        return _pick(rng, (
            lambda: f"Let the goals be enumerated as {listed(rng, res)}. They form a fixed sequence: each term is "
                    "visited only after its predecessor. ∎",
            lambda: "Define the route by induction: "
                    + _seq(rng, res, "the base case is", "the next step is", "and the final step is")
                    + ". The order is forced; permuting the steps is not permitted. QED",
            lambda: f"Theorem. The robot visits {listed(rng, res)} in exactly the order enumerated, and in no other "
                    "order. ∎",
        ))()
    return _pick(rng, (
        lambda: f"Consider the unordered set {{{listed(rng, res)}}}. The visiting order is arbitrary; any "
                "permutation will do. ∎",
        lambda: f"Lemma. The robot visits {listed(rng, res)}. Without loss of generality they may be taken in any "
                "order. QED",
        lambda: f"Let the goals be {listed(rng, res)}. Since the order of visits does not matter, any order "
                "suffices. ∎",
    ))()


_WRITERS = (_librarian, _protocol, _cabin, _proof)


def render_instruction_ao(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a reference librarian, a diplomatic protocol
    officer, a flight attendant, a mathematician). Goals stay in visiting order, each written once as rendered;
    strict texts say the order is fixed ('strictly in the order on this slip', 'never out of sequence', 'strict
    order of precedence', 'no call may be made ahead of its turn', 'in exactly that boarding order', 'do not board
    out of turn', 'in that order and no other', 'each term is visited only after its predecessor', 'the order is
    forced'), free ones say it is open ('in whatever order you like', 'browse them in any order', 'no set order',
    'no order of precedence applies', 'precedence waived', 'at your discretion', 'in whichever order suits you',
    'the order is entirely up to you', 'the visiting order is arbitrary', 'any permutation will do', 'in any
    order'). A single goal gets neither kind of cue and no digit."""
    writer = _pick(rng, _WRITERS)
    return tidy(writer(rng, list(res), order))
