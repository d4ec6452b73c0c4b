"""Set AQ: a held-out sentence set, wired as the split `unseen_aq`.

Who wrote it: a helper session that never read the instruction readers (the rule parser, the tagger, the sensor
reader, the verifier) nor the body of any other sentence set. What it read, and nothing else of the repository:
the `def` lines and docstrings of the four public functions of `ragnav_jax/language/phrasings_w.py` (not their
bodies, private helpers or module docstring); `ragnav_jax/language/types.py` and
`ragnav_jax/language/template_text.py`, whole; the `UNSEEN_TEMPLATES` dict and the `_renderer` function of
`ragnav_jax/language/episodes.py`; the `EPISODE_SPLITS` tuple of `ragnav_jax/config.py`;
`tests/test_heldout_sets.py`, whole; and the `subgoals()` strategy of `tests/test_phrasings_dev8.py` with the
strategy and constants it draws from (`targets`, HEADS, MODS, STATES, ROOMS), plus a few values it drew.

The four voices (one is drawn per whole instruction, from the generator passed in):

- a London black-cab driver talking to the fare: 'Right you are, guv', 'first stop', 'no doubling back',
  'same as you told me', 'whatever order the traffic's kind', 'I'll work out the best run myself', 'hop in';
- a paranormal investigator's vigil plan: 'VIGIL PLAN', 'sweep these locations', 'log readings at each',
  'run an EVP session', 'activity builds from one location to the next', 'follow the energy';
- a Cold War spy handler's brief to an asset: 'EYES ONLY', 'Drop ALPHA:', 'deviate and the network is blown',
  'sequence at your discretion', 'they watch for patterns', 'burn after reading', 'handler to asset';
- a club snooker player planning a break: 'pot', 'screw back for', 'stun through onto', 'colours in sequence',
  'take one out of turn and it's a foul', 'they're all reds, this lot', 'open table', 'frame ball'.

Style guide. Goal wording is one plain-English pool that every voice shares; the voice lives in the frame round
the goals (its layout, its joining words and its order cue). A goal is 'the' + [a superlative adjective] +
[states, hyphenated] + the attributes as the phrase writes them + the head noun exactly as given; states may
instead follow ('that is switched on'). The room comes straight after the noun ('in the nursery', 'over in the
nursery', '(nursery)') or before it as a possessive ('the nursery's teal lamp'), always inside a superlative's
scope ('the kitchen's warmest lamp', 'the lamp in the kitchen with the highest temperature'); then the sensor
tail; then the coordinate hint (written x then y, with the numbers exactly as given and no other digit after
them); relations come last. An anchor's own relations sit in brackets right after it ('near the sofa (the one
next to the drums)'), and a target's own second relation is joined by 'both ... and ...' or ', and also', so
nothing attaches to the wrong noun. Sensor values are written exactly: digits as the shortest decimal that reads
back to the value, or number words for whole numbers under a hundred; a unit other
than the canonical one (°F, kW) is used only when the value converts back exactly, and the returned constraint
keeps the canonical value with the unit as written ('c', 'f', '%', 'ppm', 'db', 'lux', 'w', 'kw', 'kg', 'hpa',
or '' when none is written). Carbon dioxide is spelt out, never 'CO2', so no stray digit enters a goal. Goals are
set off from each other by semicolons, new lines or sequence words, never by a bare 'and' that an anchor could
swallow. Strict texts say the order is fixed, free texts say it is open, in words (STRICT_CUES / FREE_CUES); a
single goal gets neither and the frame adds no digit.

Tests broken on purpose: (1) the cabbie's strict cue sentence ('Strictly in that order, mind, same as you told
me.') was replaced by a neutral 'Sit back, guv.'. The hypothesis test over drawn goals missed it in its forty
examples, so a deterministic test that walks every voice and frame over many seeds was added
(test_every_voice_and_frame_says_its_order), and it failed on the broken text. (2) The hint 'at x {x}, y {y}' was
written with y first; test_sensor_and_hint_stand_in_the_goal_with_x_then_y_last failed. Both were restored and
the whole file passes again.

Slips: (1) printing the `_renderer` function of episodes.py with a line range that ran long showed the next
lines as well: the whole of `_rng` (a seeded generator per seed, scene and modality) and the first lines of
`_one_episode` (a permutation of the scene's objects and a draw of the number of goals). (2) A grep for
EPISODE_SPLITS in config.py also printed one line that checks `episodes.split` against it. (3) A grep for top-level
`def` lines in tests/test_phrasings_dev8.py printed the names (only) of its other helpers and tests. (4) The
`[tool.ruff]` section of pyproject.toml was read for the line length. No reader, no other set's body and no other
part of those files was seen.
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

VOICES = ("cabbie", "ghost_hunter", "spy_handler", "snooker_player")

# Order cues, per voice: every multi-goal text holds one of its kind and none of the other kind.
STRICT_CUES = {
    "cabbie": ("strictly in that order", "in the order you said it", "no doubling back"),
    "ghost_hunter": ("strictly in the order listed", "do not skip ahead", "the sequence matters here"),
    "spy_handler": ("in this exact sequence", "deviate and the network is blown", "before the one listed above it"),
    "snooker_player": ("colours in sequence", "out of turn and it's a foul", "no going out of turn"),
}
FREE_CUES = {
    "cabbie": ("not bothered which comes first", "whatever order the traffic's kind", "any order you like"),
    "ghost_hunter": ("in any order", "follow the energy", "order doesn't matter"),
    "spy_handler": ("sequence at your discretion", "in any sequence you choose", "they watch for patterns"),
    "snooker_player": ("they're all reds", "any order you fancy", "doesn't matter which one you go for first"),
}


def _pick(rng: np.random.Generator, seq):
    return seq[int(rng.integers(len(seq)))]


# ------------------------------------------------------------------------------------------------ sensors

# reading -> (noun, article before the noun, meter, superlative adjectives (max, min) or empty)
_READING_WORDS = {
    "temperature_c": ("temperature", "a", "thermometer", (("warmest", "hottest"), ("coldest", "coolest"))),
    "ndvi": ("NDVI", "an", "NDVI sensor", ((), ())),
    "humidity_pct": ("humidity", "a", "hygrometer", (("most humid",), ("least humid",))),
    "co2_ppm": ("carbon dioxide level", "a", "carbon dioxide monitor", ((), ())),
    "noise_db": ("noise level", "a", "sound meter", (("loudest", "noisiest"), ("quietest",))),
    "light_lux": ("light level", "a", "light meter", (("brightest", "best-lit"), ("dimmest", "darkest"))),
    "battery_pct": ("battery charge", "a", "battery gauge", ((), ())),
    "power_w": ("power draw", "a", "power meter", (("most power-hungry",), ("least power-hungry",))),
    "weight_kg": ("weight", "a", "scales", (("heaviest",), ())),
    "pressure_hpa": ("air pressure", "an", "barometer", ((), ())),
}

# reading -> ways to write a value in the canonical unit: (template, unit code, takes number words)
_UNITS = {
    "temperature_c": (("{} °C", "c", False), ("{} degrees Celsius", "c", True), ("{}°C", "c", False)),
    "ndvi": (("{}", "", False),),
    "humidity_pct": (("{} %", "%", False), ("{} per cent", "%", True), ("{}%", "%", False)),
    "co2_ppm": (("{} ppm", "ppm", False), ("{} parts per million", "ppm", False)),
    "noise_db": (("{} dB", "db", False), ("{} decibels", "db", True)),
    "light_lux": (("{} lux", "lux", False),),
    "battery_pct": (("{} %", "%", False), ("{} per cent", "%", True)),
    "power_w": (("{} W", "w", False), ("{} watts", "w", False)),
    "weight_kg": (("{} kg", "kg", False), ("{} kilos", "kg", True), ("{} kilograms", "kg", True)),
    "pressure_hpa": (("{} hPa", "hpa", False), ("{} hectopascals", "hpa", False)),
}

_CMP = {
    "gt": ("over {}", "above {}", "more than {}"),
    "lt": ("under {}", "below {}", "less than {}"),
    "ge": ("at least {}", "{} or more", "no less than {}"),
    "le": ("at most {}", "{} or less", "no more than {}"),
    "approx": ("about {}", "roughly {}", "around {}", "{} or thereabouts"),
}


def _digits(v: float) -> str:
    """The shortest decimal that reads back to v ('0.65', '40', '-18', '1013.25')."""
    return np.format_float_positional(float(v), trim="-")


def _fahrenheit(v: float) -> int | None:
    f = v * 9 / 5 + 32
    if abs(f - round(f)) > 1e-9:
        return None
    f = round(f)
    return f if (f - 32) * 5 / 9 == v and (f - 32) / 1.8 == v else None


def _kilowatts(v: float) -> str | None:
    if abs(v) < 1000:
        return None
    s = _digits(v / 1000)
    return s if float(s) * 1000 == v else None


def _value_text(rng: np.random.Generator, reading: str, v: float) -> tuple[str, str]:
    """(the value with its unit as written, the unit's code)."""
    forms = list(_UNITS.get(reading, (("{}", "", False),)))
    if reading == "temperature_c" and _fahrenheit(v) is not None:
        forms += [("{} °F", "f", False), ("{} degrees Fahrenheit", "f", True)]
    if reading == "power_w" and _kilowatts(v) is not None:
        forms += [("{} kW", "kw", False)]
    tmpl, unit, words = _pick(rng, forms)
    if unit == "f":
        n = float(_fahrenheit(v))
    elif unit == "kw":
        return tmpl.format(_kilowatts(v)), unit
    else:
        n = float(v)
    if words and n.is_integer() and abs(n) < 100 and rng.random() < 0.5:
        return tmpl.format(number_words(int(n))), unit
    return tmpl.format(_digits(n)), unit


def render_sensor_aq(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: an adjective before the noun ('warmest', 'quietest', 'most power-hungry') or a tail ('with the
    highest NDVI', 'giving the lowest reading on the barometer', '(battery charge: the lowest going)'); thresholds
    after the noun ('with a temperature of over 40 °C', 'reading 40 per cent or less on the hygrometer',
    '(NDVI: about 0.65)', 'with the thermometer showing at least 104 degrees Fahrenheit'). The value returned is
    the canonical one; the unit is the one written.
    """
    noun, art, meter, (big, small) = _READING_WORDS.get(
        c.reading, (c.reading.replace("_", " "), "a", c.reading.replace("_", " ") + " sensor", ((), ())))
    if c.is_superlative:
        hi = c.comparator == "max"
        adjs = big if hi else small
        out = SensorConstraint(c.reading, c.comparator, None, "")
        if adjs and rng.random() < 0.5:
            return _pick(rng, adjs), "", out
        word = "highest" if hi else "lowest"
        tail = _pick(rng, (f"with the {word} {noun}", f"giving the {word} reading on the {meter}",
                           f"({noun}: the {word} going)"))
        return "", tail, out
    val, unit = _value_text(rng, c.reading, float(c.value))
    cmp = _pick(rng, _CMP.get(c.comparator, ("{}",))).format(val)
    of = "" if cmp.startswith(("over", "above", "under", "below", "more", "less")) else " of"
    tail = _pick(rng, (f"with {art} {noun}{of} {cmp}", f"reading {cmp} on the {meter}", f"({noun}: {cmp})",
                       f"with the {meter} showing {cmp}"))
    return "", tail, SensorConstraint(c.reading, c.comparator, float(c.value), unit)


# ------------------------------------------------------------------------------------------------ hints


def hint_text_aq(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y, the numbers exactly as given: 'at x 3.5, y 2',
    'at plan position (3.5, 2)', 'where x reads 3.5 and y reads 2', 'pinned at 3.5 across and 2 up',
    'at co-ordinates x = 3.5, y = 2'."""
    return _pick(rng, (f"at x {x}, y {y}", f"at plan position ({x}, {y})", f"where x reads {x} and y reads {y}",
                       f"pinned at {x} across and {y} up", f"at co-ordinates x = {x}, y = {y}"))


# ------------------------------------------------------------------------------------------------ goals

_RELATION_WORDS = {
    "near": ("near", "close to", "not far from"),
    "next_to": ("next to", "right next to", "alongside"),
    "beside": ("beside", "just beside"),
    "by": ("by", "right by"),
    "on": ("on", "on top of", "sitting on"),
    "under": ("under", "underneath", "beneath"),
    "above": ("above", "up above"),
    "in": ("inside", "tucked inside"),
    "with": ("with", "that comes with"),
    "in_room_with": ("in the same room as", "sharing a room with"),
    "in_front_of": ("in front of", "just in front of"),
    "behind": ("behind", "round the back of"),
    "opposite": ("opposite", "across from", "facing"),
    "left_of": ("to the left of", "on the left-hand side of"),
    "right_of": ("to the right of", "on the right-hand side of"),
}


def _relation(rng: np.random.Generator, r: Relation) -> str:
    words = _pick(rng, _RELATION_WORDS.get(r.type, (r.type.replace("_", " "),)))
    return f"{words} {_anchor(rng, r.anchor)}"


def _anchor(rng: np.random.Generator, a: Target) -> str:
    pre, states = attributes_and_states(a)
    if states and rng.random() < 0.6:
        np_ = " ".join(["the", hyphenated(states), *pre, a.head])
    elif states:
        np_ = " ".join(["the", *pre, a.head, "that", is_are(a.head), both(states)])
    else:
        np_ = " ".join(["the", *pre, a.head])
    if not a.relations:
        return np_
    rels = " and ".join(_relation(rng, r) for r in a.relations)
    one = "ones" if plural(a.head) else "one"
    inner = _pick(rng, (f"the {one} {rels}", f"that's the {a.head} {rels}", f"which {is_are(a.head)} {rels}"))
    return f"{np_} ({inner})"


def _relations(rng: np.random.Generator, rels: tuple[Relation, ...]) -> str:
    """A target's own relations, joined so that none can be read as an anchor's: 'both near A and opposite B',
    'near A, and also opposite B'."""
    out = [_relation(rng, r) for r in rels]
    if len(out) == 1:
        return out[0]
    if len(out) == 2 and rng.random() < 0.5:
        return f"both {out[0]} and {out[1]}"
    return ", ".join(out[:-1]) + ", and also " + out[-1]


def render_goal_aq(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "", hint: str = "") -> str:
    """A goal as set AQ writes it: 'the teal wool lamp in the nursery', 'the switched-on lamp over in the
    kitchen', 'the nursery's warmest lamp', 'the drums that are empty (games room)', 'the lamp in the kitchen
    reading under 22 °C on the thermometer at x 3.5, y 2', 'the sofa both close to the toolbox (the one right
    by the open drums) and facing the lamp'. The room sits next to the noun, inside any superlative's scope; a sensor
    tail follows it, then the coordinate hint (x then y, the last numbers of the goal), and relations come last,
    an anchor's own relations in brackets after it."""
    t = sg.target
    pre, states = attributes_and_states(t)
    head = t.head
    states_before = bool(states) and rng.random() < 0.5
    core = " ".join([*([prefix] if prefix else []), *([hyphenated(states)] if states_before else []), *pre, head])
    room = sg.room
    room_mode = None
    if room:
        modes = ["in", "over", "possessive"] + ([] if (prefix or tail) else ["bracket"])
        room_mode = _pick(rng, modes)
    parts = [f"the {room}'s {core}" if room_mode == "possessive" else f"the {core}"]
    if states and not states_before:
        parts.append(f"that {is_are(head)} {both(states)}")
    if room_mode == "in":
        parts.append(f"in the {room}")
    elif room_mode == "over":
        parts.append(f"{_pick(rng, ('over', 'down'))} in the {room}")
    elif room_mode == "bracket":
        parts.append(f"({room})")
    if tail:
        parts.append(tail)
    if hint:
        parts.append(hint)
    if t.relations:
        parts.append((", " if (tail or hint) else "") + _relations(rng, t.relations))
    return tidy(" ".join(parts).replace(" , ", ", "))


# ------------------------------------------------------------------------------------------------ instructions

_PHONETIC = ("ALPHA", "BRAVO", "CHARLIE", "DELTA", "ECHO", "FOXTROT", "GOLF", "HOTEL", "INDIA", "JULIETT", "KILO",
             "LIMA", "MIKE", "NOVEMBER", "OSCAR", "PAPA")


def _semis(res: list[str], last: str = "and ") -> str:
    """Goals set off by semicolons, the last one after `last`: 'a; b; and c'."""
    if len(res) == 1:
        return res[0]
    return "; ".join(res[:-1]) + "; " + last + res[-1]


def _cabbie(rng, res, order):
    if len(res) == 1:
        return _pick(rng, (f"Hop in, guv. Where to? Off to {res[0]}? Lovely, I know just where that is. Sit back.",
                           f"Evening, guv. Just the one drop: {res[0]}. Right you are, off we go."))
    if order == "strict":
        if rng.random() < 0.5:
            mid = "".join(f"; then {g}" for g in res[1:-1])
            return (f"Right you are, guv. First stop, {res[0]}{mid}; and last stop, {res[-1]}. "
                    "Strictly in that order, mind, same as you told me.")
        mid = "".join(f"; then on to {g}" for g in res[1:-1])
        return (f"Hop in, guv. Let me read it back: {res[0]}{mid}; and we finish at {res[-1]}. "
                "Done in the order you said it, no doubling back.")
    if rng.random() < 0.5:
        return (f"Hop in, guv. Drops today: {_semis(res)}. You're not bothered which comes first, so I'll take "
                "'em in whatever order the traffic's kind.")
    return (f"Right, guv, I've got 'em: {_semis(res, 'plus ')}. Any order you like, you said, so I'll work out "
            "the best run myself.")


def _ghost_hunter(rng, res, order):
    head = "VIGIL PLAN — robot investigator"
    if len(res) == 1:
        return _pick(rng, (f"{head}\nLocation: {res[0]}.\nRun an EVP session there and log everything you pick up.",
                           f"Tonight's investigation centres on {res[0]}. Set up, run an EVP session and log "
                           "every reading."))
    bullets = "\n".join(f"• {g}" for g in res)
    if order == "strict":
        if rng.random() < 0.5:
            return (f"{head}\nSweep these locations strictly in the order listed; do not skip ahead, activity "
                    f"builds from one location to the next.\n{bullets}\nLog readings at each before moving on.")
        mid = "".join(f" When that's logged, move to {g}." for g in res[1:-1])
        return (f"Tonight's investigation. Start with {res[0]}.{mid} Finish at {res[-1]}. The sequence matters "
                "here: spirits respond to the order of the sweep.")
    if rng.random() < 0.5:
        return f"{head}\nLocations to sweep, in any order (follow the energy):\n{bullets}\nRun an EVP session at each."
    return (f"Tonight's investigation covers {_semis(res)}. Order doesn't matter: the activity moves about, so go "
            "wherever feels most active.")


def _spy_handler(rng, res, order):
    if len(res) == 1:
        return _pick(rng, (f"EYES ONLY.\nSingle drop: {res[0]}.\nService it, leave nothing behind, burn this.",
                           f"Handler to asset. Your drop is {res[0]}. Service it and get out. Burn after reading."))
    if order == "strict":
        if rng.random() < 0.5:
            lines = "\n".join(f"Drop {_PHONETIC[i] if i < len(_PHONETIC) else 'NEXT'}: {g}." for i, g in
                              enumerate(res))
            return (f"EYES ONLY.\nService the drops in this exact sequence; deviate and the network is blown.\n"
                    f"{lines}\nThis message will not be repeated.")
        mid = "".join(f" Only after that, {g}." for g in res[1:-1])
        return (f"Handler to asset. Proceed to {res[0]}.{mid} Last of all, {res[-1]}. Do not service any drop "
                "before the one listed above it.")
    if rng.random() < 0.5:
        return (f"EYES ONLY.\nDrops to service: {_semis(res)}.\nSequence at your discretion; vary it, they watch "
                "for patterns.\nBurn after reading.")
    return (f"Handler to asset. Service these in any sequence you choose: {_semis(res)}. Never the same route "
            "twice. Burn after reading.")


_SHOTS = ("screw back for", "stun through onto", "run through for", "bring it round for", "drop in for")


def _snooker_player(rng, res, order):
    if len(res) == 1:
        return _pick(rng, (f"One ball left on the table: {res[0]}. Nice and smooth, just roll it in.",
                           f"Frame ball: {res[0]}. Don't overthink it, just cue through straight."))
    if order == "strict":
        if rng.random() < 0.5:
            mid = "".join(f"; {_pick(rng, _SHOTS)} {g}" for g in res[1:-1])
            return (f"Right, here's the break. Pot {res[0]}{mid}; and finish on {res[-1]}. Colours in sequence, "
                    "this: take one out of turn and it's a foul.")
        mid = "".join(f"; then position for {g}" for g in res[1:-1])
        return (f"Frame plan: {res[0]} to start{mid}; then {res[-1]} to finish. Same as the colours, yellow to "
                "black, with no going out of turn.")
    if rng.random() < 0.5:
        return (f"They're all reds, this lot, so pot them in any order you fancy: {_semis(res)}. Just keep the "
                "break ticking over.")
    return (f"Open table: {_semis(res)}. Doesn't matter which one you go for first, just pick whichever leaves "
            "you position.")


_FRAMES = {"cabbie": _cabbie, "ghost_hunter": _ghost_hunter, "spy_handler": _spy_handler,
           "snooker_player": _snooker_player}


def render_instruction_aq(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, by one of four people (a London cabbie, a paranormal
    investigator, a spy handler, a snooker player), drawn once from the generator. Goals stay in visiting order,
    each written once as rendered, set off by semicolons, new lines or sequence words; strict texts say the
    order is fixed ('strictly in that order', 'no doubling back', 'do not skip ahead', 'in this exact sequence',
    'deviate and the network is blown', 'colours in sequence', 'out of turn and it's a foul'), free ones say it
    is open ('any order you like', 'whatever order the traffic's kind', 'in any order', 'follow the energy',
    'sequence at your discretion', 'they watch for patterns', 'they're all reds', 'any order you fancy'). A
    single goal gets neither kind of cue and no digit."""
    voice = _pick(rng, VOICES)
    return _FRAMES[voice](rng, list(res), order)
