"""Held-out sentence set AH (split `unseen_ah`): household-robot errands as four people would send them.

Written by a helper that never read any reader of instructions (parser, lexicon, tagger, sensor reader, ...), nor
any other set's wording; only set W's interface (the four functions' signatures and docstrings), types.py,
template_text.py and the wiring of the split were in view.

Voices (one per whole instruction): an auctioneer taking lots round the saleroom, a golf caddie reading the card to
his player, a yoga teacher calling a flow, and a wedding planner running the day's timeline.

Style guide. A goal is a noun phrase that starts with 'the' and keeps the head noun intact: attributes before the
noun, in brackets ('the lamp (the teal one)') or as 'of the ... sort', never with 'in' (kept for rooms and containers);
states as a hyphenated modifier, a 'that is ...' clause or 'currently ...'; the room next ('over in the study',
'found in the study'); then a sensor tail; then a coordinate hint (x before y, digits as given); relations last,
each anchor's own relations in brackets ('the one ...'). Every relation kind has its own words (near: 'not far from',
by: 'over by', beside: 'at the side of', ...). Sensor values are written exactly: digits, words, '... and a half',
Fahrenheit or kilowatts only where the conversion comes out clean; negations ('not above', 'no lower than') and
'or thereabouts' are used freely. Strict instructions always say the order is fixed in the voice's own idiom
(catalogue order, playing the card, the flow, the timeline); free ones say it is open; a single goal says neither
and carries no digit outside its goal.

Slips: glimpsed a few lines of config.py beyond EPISODE_SPLITS (the start of ROOM_TYPES, one check, a class header),
and the three-line body and import lines of tests/test_phrasings_dev8.py's `subgoals()`; nothing of any reader.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.template_text import (
    ONES,
    attributes_and_states,
    both,
    hyphenated,
    is_are,
    listed,
    number_words,
    plural,
    tidy,
)
from ragnav_jax.language.types import SensorConstraint, Subgoal, Target


def _pick(rng: np.random.Generator, xs):
    return xs[int(rng.integers(len(xs)))]


def _num(v: float) -> str:
    """A number as plain digits, ASCII minus, no exponent: 40.0 -> '40', -2.5 -> '-2.5'."""
    if float(v).is_integer():
        return str(int(v))
    return f"{v:.6f}".rstrip("0").rstrip(".")


def _clean(v: float, places: int) -> bool:
    return abs(round(v, places) - v) < 1e-9


# ---------------------------------------------------------------------------------------------------- relations
REL_WORDS = {
    "near": ("near", "close to", "not far from", "within easy reach of"),
    "next_to": ("next to", "right next to", "alongside", "immediately next to"),
    "beside": ("beside", "just beside", "at the side of"),
    "by": ("by", "over by", "down by"),
    "on": ("on", "on top of", "sitting on", "resting on"),
    "under": ("under", "underneath", "beneath", "tucked under"),
    "above": ("above", "up above", "hanging above", "directly above"),
    "in": ("in", "inside", "tucked inside", "kept in"),
    "with": ("with", "that has", "complete with", "that comes with"),
    "in_room_with": ("in the same room as", "sharing a room with", "in whichever room holds", "in the room with"),
    "in_front_of": ("in front of", "just in front of", "out in front of"),
    "behind": ("behind", "tucked behind", "round the back of"),
    "opposite": ("opposite", "across from", "facing", "directly opposite"),
    "left_of": ("to the left of", "on the left-hand side of", "just left of"),
    "right_of": ("to the right of", "on the right-hand side of", "just right of"),
}


def _noun(rng, t: Target, prefix: str = "") -> str:
    """'the [prefix] attrs head' with its states, in one of several shapes; no relations."""
    pre, states = attributes_and_states(t)
    one = "ones" if plural(t.head) else "one"
    shape = int(rng.integers(3)) if pre else 0
    if shape == 0:
        core = f"{' '.join(pre)} {t.head}"
    elif shape == 1:
        core = f"{t.head} (the {' '.join(pre)} {one})"
    else:
        core = f"{t.head} of the {both(pre)} sort"
    if not states:
        return _squash(f"the {prefix} {core}")
    way = int(rng.integers(4))
    if way == 0 and shape == 0:
        return _squash(f"the {prefix} {hyphenated(states)} {core}")
    if way == 1:
        return _squash(f"the {prefix} {core}, currently {both(states)},")
    if way == 2:
        return _squash(f"the {prefix} {core} which {is_are(t.head)} {both(states)} at the moment,")
    return _squash(f"the {prefix} {core} that {is_are(t.head)} {both(states)},")


def _squash(s: str) -> str:
    return " ".join(s.split())


def _anchor(rng, t: Target) -> str:
    text = _noun(rng, t)
    if t.relations:
        one = "ones" if plural(t.head) else "one"
        text = f"{text.rstrip(',')} (the {one} {_relations(rng, t.relations)})"
    return text


def _relations(rng, rels) -> str:
    parts = [f"{_pick(rng, REL_WORDS[r.type])} {_anchor(rng, r.anchor)}" for r in rels]
    return parts[0] if len(parts) == 1 else ", ".join(parts[:-1]) + " and " + parts[-1]


_ROOM = ("in the {r}", "over in the {r}", "found in the {r}", "that lives in the {r}", "along in the {r}")


def render_goal_ah(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AH writes it: 'the teal wool lamp over in the study', 'the lamp of the teal and wool sort',
    'the switched-on lamp', 'the lamp that is open, at x 3.5, y 2', 'the dampest cactus found in the bathroom',
    'the rug under the table (the one not far from the sofa)'. Order: noun with its attributes and states (and a
    superlative adjective `prefix`), room, sensor `tail`, coordinate `hint`, then relations. The head noun is kept
    verbatim; the hint's numbers are the last digits of the text."""
    t = sg.target
    text = _noun(rng, t, prefix)
    if sg.room:
        text += " " + _pick(rng, _ROOM).format(r=sg.room)
    if tail:
        text += (", " if rng.random() < 0.5 else " ") + tail
    if hint:
        text += ", " + hint
    if t.relations:
        text += ", " if (sg.room or tail or hint or text.endswith(",")) else " "
        text += _relations(rng, t.relations)
    return tidy(text)


# ---------------------------------------------------------------------------------------------------- sensors
_NAME = {
    "temperature_c": ("temperature", "temp", "thermometer reading"),
    "ndvi": ("NDVI", "NDVI reading", "NDVI (vegetation index)"),
    "humidity_pct": ("humidity", "relative humidity", "humidity reading"),
    "co2_ppm": ("CO2 level", "carbon dioxide level", "CO2 reading"),
    "noise_db": ("noise level", "sound level", "decibel reading"),
    "light_lux": ("light level", "brightness", "light reading"),
    "battery_pct": ("battery charge", "battery level", "charge level"),
    "power_w": ("power draw", "power use", "wattage"),
    "weight_kg": ("weight", "mass"),
    "pressure_hpa": ("air pressure", "barometric pressure", "pressure reading"),
}
_UNITS = {  # reading -> ((text after the number, unit as written), ...)
    "temperature_c": ((" °C", "c"), (" degrees C", "c"), (" degrees Celsius", "c")),
    "ndvi": (("", ""),),
    "humidity_pct": (("%", "%"), (" per cent", "%"), (" percent", "%")),
    "battery_pct": (("%", "%"), (" per cent", "%"), (" percent", "%")),
    "co2_ppm": ((" ppm", "ppm"), (" parts per million", "ppm")),
    "noise_db": ((" dB", "db"), (" decibels", "db")),
    "light_lux": ((" lux", "lux"),),
    "power_w": ((" W", "w"), (" watts", "w")),
    "weight_kg": ((" kg", "kg"), (" kilos", "kg"), (" kilograms", "kg")),
    "pressure_hpa": ((" hPa", "hpa"), (" hectopascals", "hpa"), (" millibars", "mbar")),
}
_SUP_ADJ = {("temperature_c", "max"): ("warmest", "hottest"), ("temperature_c", "min"): ("coldest", "coolest"),
            ("humidity_pct", "max"): ("dampest", "most humid"), ("humidity_pct", "min"): ("driest",),
            ("noise_db", "max"): ("loudest", "noisiest"), ("noise_db", "min"): ("quietest",),
            ("light_lux", "max"): ("brightest", "best-lit"), ("light_lux", "min"): ("darkest", "dimmest"),
            ("weight_kg", "max"): ("heaviest",)}
_SUP_TAIL = {"max": ("with the highest {n}", "whose {n} beats all the others", "with a {n} higher than any other",
                     "with the {n} that's highest of the lot"),
             "min": ("with the lowest {n}", "whose {n} is lower than any other", "with a {n} lower than all the rest",
                     "with the {n} that's lowest of the lot")}
_CMP = {
    "gt": ("with {a} {n} above {v}", "whose {n} is over {v}", "showing {a} {n} of more than {v}",
           "with {a} {n} higher than {v}", "with {a} {n} that exceeds {v}"),
    "ge": ("with {a} {n} of at least {v}", "whose {n} is {v} or more", "with {a} {n} no lower than {v}",
           "with {a} {n} not below {v}"),
    "lt": ("with {a} {n} below {v}", "whose {n} is under {v}", "showing {a} {n} of less than {v}",
           "with {a} {n} lower than {v}", "with {a} {n} short of {v}"),
    "le": ("with {a} {n} of at most {v}", "whose {n} is {v} or less", "with {a} {n} no higher than {v}",
           "with {a} {n} not above {v}", "with {a} {n} that tops out at {v}"),
    "approx": ("with {a} {n} of about {v}", "whose {n} sits somewhere around {v}", "showing {a} {n} of roughly {v}",
               "with {a} {n} in the region of {v}", "with {a} {n} of {v} or thereabouts"),
}


def _spoken(rng, v: float) -> str:
    """v in words now and then ('forty', 'minus four', 'twenty-two and a half'), else digits."""
    if rng.random() < 0.35 and abs(v) < 1000:
        if float(v).is_integer():
            return number_words(int(v))
        if abs(v) >= 1 and float(v * 2).is_integer():
            return number_words(int(v)) + " and a half"
    return _num(v)


def _amount(rng, reading: str, v: float) -> tuple[str, str]:
    """(the amount as written, the unit as written) for value v in the reading's canonical unit."""
    if reading == "temperature_c":
        f = v * 9 / 5 + 32
        if _clean(f, 1) and rng.random() < 0.3:
            return f"{_spoken(rng, round(f, 1))} degrees Fahrenheit", "f"
        if v < 0 and rng.random() < 0.4:
            return f"{_spoken(rng, -v)} degrees below zero", "c"
    if reading == "power_w" and v >= 100 and _clean(v / 1000, 3) and rng.random() < 0.4:
        return f"{_num(round(v / 1000, 3))} {_pick(rng, ('kW', 'kilowatts'))}", "kw"
    if reading == "ndvi":
        return _num(v), ""
    said = _spoken(rng, v)
    units = _UNITS[reading]
    if any(ch.isalpha() for ch in said):  # 'forty per cent', never 'forty%'
        units = tuple(u for u in units if len(u[0]) > 4) or units
    text, unit = _pick(rng, units)
    return f"{said}{text}", unit


def render_sensor_ah(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective ('warmest', 'driest', 'best-lit', 'heaviest') or a tail ('with the lowest CO2 level',
    'whose noise level beats all the others'); thresholds after the noun ('with a temperature not below 40 °C',
    'whose humidity is forty per cent or less', 'with an NDVI of 0.65 or thereabouts', 'with a power draw above
    1.5 kW', 'with a temp short of seventy-two and a half degrees Fahrenheit')."""
    name = _pick(rng, _NAME[c.reading])
    if c.is_superlative:
        adj = _SUP_ADJ.get((c.reading, c.comparator))
        written = SensorConstraint(c.reading, c.comparator, None, "")
        if adj and rng.random() < 0.5:
            return _pick(rng, adj), "", written
        return "", _pick(rng, _SUP_TAIL[c.comparator]).format(n=name), written
    amount, unit = _amount(rng, c.reading, float(c.value))
    art = "an" if name[0] in "aeiouAEIO" or name.startswith("NDVI") else "a"
    tail = _pick(rng, _CMP[c.comparator]).format(a=art, n=name, v=amount)
    return "", tail, SensorConstraint(c.reading, c.comparator, float(c.value), unit)


# ---------------------------------------------------------------------------------------------------- hints
_HINT = ("at x {x}, y {y}", "at ({x}, {y}) on the floor plan", "at the spot {x} m across and {y} m up",
         "at map reference x = {x}, y = {y}", "at {x} along the x axis and {y} along the y axis",
         "parked at grid point ({x}, {y})")


def hint_text_ah(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y, digits as given: 'at x 3.5, y 2', 'at (3.5, 2) on the
    floor plan', 'at the spot 3.5 m across and 2 m up', 'at map reference x = 3.5, y = 2', 'parked at grid point
    (3.5, 2)'."""
    return _pick(rng, _HINT).format(x=x, y=y)


# ---------------------------------------------------------------------------------------------------- instructions
ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth")


def _ord(k: int) -> str:
    return ORDINALS[k] if k < len(ORDINALS) else "next"


def _count(k: int) -> str:
    return ONES[k] if k < len(ONES) else "next"


def _chain(rng, res: list[str], first: tuple, mids: tuple, last: tuple) -> str:
    sep = "; " if any("," in r for r in res) else ", "
    out = f"{_pick(rng, first)} {res[0]}"
    for r in res[1:-1]:
        out += f"{sep}{_pick(rng, mids)} {r}"
    return out + f"{sep}{_pick(rng, last)} {res[-1]}"


def _auctioneer(rng, res, order):
    if len(res) == 1:
        return _pick(rng, ("Next lot, and a fine one: {g}. Robot, make your way over and view it, please.",
                           "On the block now, ladies and gentlemen: {g}. Robot, off you go to inspect it.",
                           "Our only lot this afternoon is {g}; robot, go and give it a proper viewing.")
                     ).format(g=res[0])
    if order == "strict":
        if rng.random() < 0.5:
            lots = "; ".join(f"lot {_count(k + 1)} is {g}" for k, g in enumerate(res))
            return (f"We sell in catalogue order, no exceptions: {lots}. Robot, view each lot only once the one before "
                    "it has gone under the hammer.")
        seq = _chain(rng, res, ("first",), ("then", "after that", "next"),
                     ("and to close the sale,", "and last of all,"))
        return _pick(rng, ("Strictly in the order printed in the catalogue, please: {s}. No lot jumps the queue.",
                           "The running order is the catalogue order and it does not change: {s}. Don't go viewing "
                           "a lot before its turn.")).format(s=seq)
    return _pick(rng, ("These lots can be viewed in any order you like, robot; catalogue order doesn't bind you here: "
                       "{l}.", "Viewing is open, so wander round however you please: {l}. No set order.",
                       "Mixed lots with no running order: {l}. Take them whichever way round suits you.")
                 ).format(l=listed(rng, res))


def _caddie(rng, res, order):
    if len(res) == 1:
        return _pick(rng, ("Right, just the one shot here, boss. Line it up and get yourself to {g}. Nice and smooth.",
                           "Here's your target: {g}. Take dead aim and go.",
                           "Only one flag to find today, and that's {g}. Nice easy tempo.")).format(g=res[0])
    if order == "strict":
        if rng.random() < 0.5:
            holes = "; ".join(f"the {_ord(k)} is {g}" for k, g in enumerate(res))
            return (f"Play it as the card reads, hole by hole: {holes}. Don't tee off on a hole before you've holed "
                    "out on the one before it.")
        seq = _chain(rng, res, ("start at", "tee off at"), ("then", "on to", "after that"),
                     ("and finish at", "and walk in at"))
        return _pick(rng, ("We're playing these in order, no skipping holes: {s}.",
                           "Stick to the card, one after another: {s}. Play one out of turn and it's a penalty.")
                     ).format(s=seq)
    return _pick(rng, ("Shotgun start today, so begin wherever you like and play them in any order: {l}.",
                       "No set order on these, boss; pick whichever flag you fancy first: {l}.",
                       "Practice round, so the order's up to you: {l}.")).format(l=listed(rng, res))


def _yoga(rng, res, order):
    if len(res) == 1:
        return _pick(rng, ("Let's settle in. Breathe in, and as you breathe out, let yourself drift over to {g}. "
                           "Namaste.", "Find your centre, soften the shoulders, and gently make your way to {g}.",
                           "Ground through the wheels, lengthen the spine, and glide across to {g}.")).format(g=res[0])
    if order == "strict":
        seq = _chain(rng, res, ("begin at", "start your practice at"), ("flow on to", "then move to", "from there, to"),
                     ("and come to rest at", "and close the practice at"))
        return _pick(rng, ("We'll move through this sequence in order, each pose flowing into the next: {s}. "
                           "No jumping ahead in the flow.",
                           "Follow the sequence just as I call it, never ahead of my cue: {s}.",
                           "This flow only works in the order given: {s}. Honour each step before you move on.")
                     ).format(s=seq)
    return _pick(rng, ("There's no right order today; let your body choose where to go first: {l}.",
                       "Free flow now: visit these in whatever order feels good: {l}.",
                       "Go wherever you feel drawn first, the order doesn't matter at all: {l}.")
                 ).format(l=listed(rng, res))


def _planner(rng, res, order):
    if len(res) == 1:
        return _pick(rng, ("Quick one before the guests arrive: can you pop over to {g}, please? Thanks, lovely.",
                           "Just the one job on my clipboard for you: {g}. Off you go, and smile for the photographer!",
                           "Could you nip to {g} for me? That's all I need before the speeches.")).format(g=res[0])
    if order == "strict":
        seq = _chain(rng, res, ("first", "to open the day,"), ("then", "after that", "once that's done,"),
                     ("and finally", "and to finish,"))
        return _pick(rng, ("The running order is set in stone, exactly as on the timeline: {s}. Do not reshuffle; the "
                           "bride will notice.", "Follow the day's schedule to the letter: {s}. Nothing happens before "
                           "the thing ahead of it on the timeline.", "Like the order of service, one after the other "
                           "and never out of turn: {s}.")).format(s=seq)
    return _pick(rng, ("None of these are on the timeline, so do them in any order you like: {l}.",
                       "Loose ends for the reception, in any order, just get them all ticked off: {l}.",
                       "Whichever of these you get to first is fine, there's no fixed order: {l}.")
                 ).format(l=listed(rng, res))


VOICES = (_auctioneer, _caddie, _yoga, _planner)


def render_instruction_ah(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (an auctioneer, a golf caddie, a yoga teacher,
    a wedding planner). Goals stay in visiting order, each written once as rendered; strict texts say the order is
    fixed ('we sell in catalogue order, no exceptions', 'no lot jumps the queue', 'play it as the card reads, hole by
    hole', 'play one out of turn and it's a penalty', 'no jumping ahead in the flow', 'never ahead of my cue', 'set in
    stone, exactly as on the timeline', 'never out of turn'), free ones that it is open ('in any order you like',
    'no set order', 'shotgun start', 'the order's up to you', 'let your body choose where to go first', 'no fixed
    order'). A single goal gets neither kind of cue and no digit."""
    return _pick(rng, VOICES)(rng, list(res), order)
