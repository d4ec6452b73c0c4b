"""Fourth development phrasings: goal, sensor, coordinate and instruction templates (`unseen_dev4` split).

Written without reading the rule parser as the held-out set after parser round 4 (which parsed 81 / 192 of
its instructions on the test houses; the closed-loop held-out results in the README use it with that
parser); parser round 5 was then developed against it. Beside the seen templates and unseen_dev1-3:
the same four functions, arguments and meanings, written by another author who never read the rule parser.
The style is how people actually type requests to a home robot: terse or chatty, contractions, sentences
without final punctuation, occasionally all lower case, US and UK words.

- goals: "the kettle in the kitchen", "the open toolbox in the garage", "the lamp that's switched on in the
  study", "the desk that's in the study and has the monitor on or near it", reduced relatives ("the lamp by
  the window"), relative clauses with that / which / whose / where ("in the room where the piano is"), a
  parenthetical "(the one that's over 50 degrees)" after a room; anchors with clauses of their own are
  written "whichever sofa is by the window", so nothing after them can attach to the goal by mistake;
- readings: "that's over 50 degrees", "that's hotter than 50°C", "with under 30% humidity", "whose temp is
  50 or more", "with an NDVI of at least .6", "with temp > 50 C"; numbers as digits, "50.0", words
  ("fifty-five"), negatives ("-18", "minus 18", "18 degrees below zero"); units "°C", "C", "degrees",
  "degrees Celsius", "°", "%", "percent", "per cent";
- superlatives: "the hottest kettle in the kitchen", "whichever kettle in the kitchen is hottest",
  "whichever plant in the sunroom has the lowest humidity", "the fern with the highest NDVI", "the kettle
  that's the hottest" (the room and every other restriction always inside the scope of the extreme);
- coordinates: "at (3.5, 2)", "around x=3.5, y=2", "at x 3.5m, y 2m", "at position 3.5, 2 on the map";
- instructions: "check X then Y", "first ..., then ..., and finally ...", "... after that I'd like you to ...",
  "once you're done, ...", numbered steps "in this order: 1) ... 2) ...", "before you ..., ..."; free order as
  "any order is fine", "order doesn't matter", "whatever order works for you", "(any order)".

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.phrasings import number_words
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Words and small helpers

# Object states (the scene's "state" attribute: written after the noun or as a participle before it).
STATES = frozenset(("switched on", "switched off", "turned on", "turned off", "open", "closed", "empty", "full",
                    "plugged in", "unplugged", "locked", "unlocked", "folded", "unfolded"))
# States that read well before the noun of a goal ("the open toolbox", "the empty bin").
_SHORT_STATES = frozenset(("open", "closed", "empty", "full", "locked", "unlocked", "folded", "unfolded",
                           "unplugged"))
# "the switched on amplifier" is fine for an anchor too (people type it without a hyphen).
_PRE_STATES = STATES

def is_plural(head: str) -> bool:
    """'drums', 'shelves', 'electronics' take plural verbs; 'glass', 'cactus', 'lens' do not."""
    last = head.split()[-1].lower()
    return (last.endswith("s") and not last.endswith(("ss", "us", "is"))
            and last not in ("lens", "gas", "canvas", "atlas", "bus"))


_PL = {"is": "are", "has": "have", "sits": "sit", "stands": "stand", "reads": "read"}


def _v(verb: str, plural: bool) -> str:
    return _PL.get(verb, verb) if plural else verb


def _split(t: Target) -> tuple[list[str], list[str]]:
    """(modifiers written before the noun, states). A state is a known state word or an attribute the phrase
    leaves out (the generator writes states after the noun, so its phrases never hold them)."""
    phrase_words = f" {t.phrase} "
    mods, states = [], []
    for a in t.attributes:
        if a in STATES or f" {a} " not in phrase_words:
            states.append(a)
        else:
            mods.append(a)
    return mods, states


def _body(mods: list[str], head: str, pre: list[str] = ()) -> str:
    return " ".join((*pre, *mods, head))


def _and(items: list[str]) -> str:
    if len(items) == 1:
        return items[0]
    return ", ".join(items[:-1]) + " and " + items[-1]


# ----------------------------------------------------------------------------------------------------
# Relations (meanings as in types.RELATION_TYPES / episodes.relation_holds)

_REL_WORDS: dict[str, tuple[str, ...]] = {
    "near": ("near", "close to", "not far from"),
    "next_to": ("next to", "right next to"),
    "beside": ("beside", "right beside"),
    "by": ("by", "over by", "right by"),
    "on": ("on", "on top of", "sitting on"),
    "under": ("under", "underneath", "beneath"),
    "above": ("above", "just above"),
    "in": ("in", "inside"),
    "in_room_with": ("in the same room as", "in the room with"),
    "in_front_of": ("in front of", "right in front of"),
    "behind": ("behind", "just behind"),
    "opposite": ("opposite", "across from", "facing"),
    "left_of": ("to the left of", "on the left of"),
    "right_of": ("to the right of", "on the right of"),
}


def _anchor(rng, t: Target) -> tuple[str, bool]:
    """(anchor noun phrase, whether it is complex). States go before the noun ("the switched on amplifier");
    an anchor with relations of its own becomes "whichever sofa is by the window", which closes itself off."""
    mods, states = _split(t)
    plural = is_plural(t.head)
    pre = states if len(states) <= 1 else [" and ".join(states)]
    body = _body(mods, t.head, pre)
    if not t.relations:
        return f"the {body}", False
    preds = [_rel_pred(rng, r, plural, simple_only=False) for r in _order_rels(rng, t.relations)]
    return f"whichever {body} {_preds_text(preds, plural, lead=False)}", True


def _order_rels(rng, rels: tuple[Relation, ...]) -> list[Relation]:
    """Relations whose anchors have relations of their own go last (nothing can follow them)."""
    return sorted(rels, key=lambda r: bool(r.anchor.relations))


def _rel_reduced(rng, r: Relation) -> str:
    a, _ = _anchor(rng, r.anchor)
    if r.type == "with":
        return f"with {a}"
    words = _REL_WORDS.get(r.type, (r.type.replace("_", " "),))
    return f"{_pick(rng, words)} {a}"


def _rel_pred(rng, r: Relation, plural: bool, simple_only: bool = True) -> tuple[str, str]:
    """(verb, rest) for a relation said as a predicate: ('is', 'next to the sofa'), ('has', 'the monitor on
    or near it'), ('is', 'in the room where the piano is')."""
    a, complex_ = _anchor(rng, r.anchor)
    if r.type == "with":
        it = "them" if plural else "it"
        if complex_:
            return "has", f"on or near {it} {a}"
        return "has", f"{a} " + _pick(rng, (f"on or near {it}", f"on {it} or near {it}"))
    if r.type == "in_room_with" and not complex_ and rng.uniform() < 0.4:
        return "is", f"in the room where {a} {_v('is', is_plural(r.anchor.head))}"
    words = _REL_WORDS.get(r.type, (r.type.replace("_", " "),))
    w = _pick(rng, words)
    verb = "is"
    if r.type in ("next_to", "beside", "by", "on", "near", "opposite", "behind") and rng.uniform() < 0.3:
        verb = _pick(rng, ("sits", "stands"))
        if w == "sitting on":
            w = "on"
    return verb, f"{w} {a}"


def _preds_text(preds: list[tuple[str, str]], plural: bool, lead: bool = True, pron: str = "that") -> str:
    """Coordinated predicates of one subject: 'that's switched on, in the kitchen and next to the sofa',
    'whose temp is over 50 and that's next to the sofa'. Without lead, no pronoun before the first ('is by the
    window' after 'whichever sofa')."""
    out = []
    prev = None
    for i, (verb, rest) in enumerate(preds):
        if verb == "whose":
            piece = f"whose {rest}"
        elif i == 0:
            if not lead:
                piece = f"{_v(verb, plural)} {rest}"
            elif verb == "is" and not plural and pron == "that":
                piece = f"that's {rest}"
            else:
                piece = f"{pron} {_v(verb, plural)} {rest}"
        elif prev == "whose":  # "whose temp is over 50 and that's next to the sofa": the subject is the goal again
            piece = ("that's " if verb == "is" and not plural else f"that {_v(verb, plural)} ") + rest
        elif verb == "is" and prev == "is":
            piece = rest
        else:
            piece = f"{_v(verb, plural)} {rest}"
        out.append(piece)
        prev = verb
    return _and(out)


# ----------------------------------------------------------------------------------------------------
# Sensor constraints

# Superlative words: (reading, comparator) -> adjectives; names of the readings; extremes.
SUPERLATIVES = {
    ("temperature_c", "max"): ("hottest", "warmest"), ("temperature_c", "min"): ("coldest", "coolest"),
    ("humidity_pct", "max"): ("most humid", "dampest"), ("humidity_pct", "min"): ("driest", "least humid"),
    ("ndvi", "max"): ("healthiest", "greenest"), ("ndvi", "min"): ("least healthy", "unhealthiest"),
}
_READING_NAMES = {"temperature_c": ("temperature", "temp", "temperature reading"),
                  "humidity_pct": ("humidity", "humidity level", "humidity reading"),
                  "ndvi": ("NDVI", "NDVI reading", "NDVI value")}
_EXTREME = {"max": "highest", "min": "lowest"}


def _superlative_tails() -> dict[str, tuple[str, str, str, str]]:
    """Every superlative tail the sensor renderer writes -> (kind, adjective, reading, comparator)."""
    out = {}
    for (rd, cmp_), adjs in SUPERLATIVES.items():
        for adj in adjs:
            out[f"whichever is {adj}"] = ("whichever", adj, rd, cmp_)
            out[f"that's the {adj}"] = ("thats", adj, rd, cmp_)
            out[f"that's {adj}"] = ("thats", adj, rd, cmp_)
        for name in _READING_NAMES[rd]:
            out[f"with the {_EXTREME[cmp_]} {name}"] = ("with", adjs[0], rd, cmp_)
            out[f"whose {name} is the {_EXTREME[cmp_]}"] = ("whose", adjs[0], rd, cmp_)
            out[f"whose {name} is {_EXTREME[cmp_]}"] = ("whose", adjs[0], rd, cmp_)
    return out


_SUP_TAILS = _superlative_tails()

# Comparator wordings; {a} is the amount with its unit.
_CORES = {
    "gt": ("over {a}", "above {a}", "more than {a}", "higher than {a}", "greater than {a}"),
    "ge": ("at least {a}", "{a} or more", "{a} or higher", "{a} or above", "no less than {a}", "not below {a}"),
    "lt": ("under {a}", "below {a}", "less than {a}", "lower than {a}"),
    "le": ("at most {a}", "{a} or less", "{a} or lower", "{a} or below", "no more than {a}", "not above {a}"),
    "approx": ("about {a}", "around {a}", "roughly {a}", "approximately {a}", "{a} or so", "somewhere around {a}"),
}
# Temperature words that name the reading themselves ("hotter than 50 degrees").
_TEMP_CORES = {"gt": ("hotter than {a}", "warmer than {a}"), "ge": ("{a} or hotter", "{a} or warmer", "no cooler than {a}"),
               "lt": ("colder than {a}", "cooler than {a}"), "le": ("{a} or colder", "{a} or cooler", "no warmer than {a}"),
               "approx": ()}
# Cores that read well straight after the reading's name ("with a temperature over 50 degrees").
_PREP_CORES = ("over ", "above ", "under ", "below ", "about ", "around ")
_SYMBOLS = {"gt": (">",), "ge": (">=",), "lt": ("<",), "le": ("<=",), "approx": ("~",)}
_T_UNITS = (" degrees", "°C", " °C", " C", "C", " degrees C", " degrees Celsius", "°")
_T_WORD_UNITS = (" degrees", " degrees Celsius")
_H_UNITS = ("%", " percent", " per cent")


def _amount(rng, rd: str, v: float, unit: str = "maybe", below_zero: bool = False) -> tuple[str, float, str]:
    """(number as written with its unit, the value it denotes, unit code). unit: 'yes' | 'maybe' (a temperature
    may go without one where the reading is named) | 'symbol' (digits and a compact unit)."""
    vtxt = _fmt_value(rd, v)
    value = float(vtxt)
    neg = value < 0
    mag = vtxt.lstrip("-")
    if rd == "ndvi":
        forms = [mag, mag]
        if mag.startswith("0.") and unit != "symbol":
            forms.append(mag[1:])  # ".6"
        if "." in mag and len(mag.split(".")[1]) == 1:
            forms.append(mag + "0")  # "0.60"
        num = _pick(rng, forms)
        if neg:
            num = (_pick(rng, ("-", "minus ", "negative ")) if unit != "symbol" else "-") + num
        return num, value, ""
    temp = rd == "temperature_c"
    integer = value.is_integer()
    k = rng.uniform()
    as_words = False
    if unit == "symbol":
        num = vtxt
    else:
        if integer and abs(value) < 100 and k < 0.2:
            num, as_words = number_words(int(abs(value))), True
        elif integer and k < 0.3:
            num = mag + ".0"
        else:
            num = mag
        if neg and temp and below_zero and rng.uniform() < 0.35:
            return f"{num} degrees below zero", value, "c"
        if neg:
            num = _pick(rng, ("minus ", "negative ") if as_words else ("-", "-", "minus ", "negative ")) + num
    if temp:
        if unit == "symbol":
            return num + _pick(rng, ("°C", " C", "C", " °C")), value, "c"
        if unit == "maybe" and not as_words and rng.uniform() < 0.3:
            return num, value, ""
        return num + _pick(rng, _T_WORD_UNITS if as_words else _T_UNITS), value, "c"
    if unit == "symbol":
        return num + "%", value, "%"
    return num + _pick(rng, (" percent", " per cent") if as_words else _H_UNITS), value, "%"


def _core(rng, rd: str, cmp_: str, v: float, named: bool, unit: str = "maybe", after: str = "",
          prep_only: bool = False, after_of: bool = False) -> tuple[str, float, str]:
    """A comparator phrase with its amount: ('over 50 degrees', 50.0, 'c'). Without `named` the phrase itself
    must say it is a temperature (a unit or 'hotter than'); `after` goes after the amount ('% humidity')."""
    forms = list(_CORES[cmp_]) + (list(_TEMP_CORES[cmp_]) if rd == "temperature_c" else [])
    if prep_only and any(f.startswith(_PREP_CORES) for f in forms):
        forms = [f for f in forms if f.startswith(_PREP_CORES)]
    if after_of:  # "a temperature of ...": not "of not above", "of hotter than"
        forms = [f for f in forms if not f.startswith(("not ", "hotter", "warmer", "colder", "cooler", "no cooler",
                                                        "no warmer"))]
    form = _pick(rng, forms)
    temp_word = rd == "temperature_c" and ("hotter" in form or "warmer" in form or "colder" in form
                                           or "cooler" in form)
    below_zero = rd == "temperature_c" and any(w in form for w in ("about", "around", "roughly", "approximately",
                                                                   "hotter than", "warmer than", "colder than",
                                                                   "cooler than"))
    u = unit if (named or temp_word) else "yes"
    amount, value, code = _amount(rng, rd, v, u, below_zero)
    return form.format(a=amount + after), value, code


def render_sensor_dev4(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written)."""
    rd = c.reading
    if c.is_superlative:
        adj = _pick(rng, SUPERLATIVES[(rd, c.comparator)])
        ext = _EXTREME[c.comparator]
        name = _pick(rng, _READING_NAMES[rd])
        k = int(rng.integers(6))
        if k <= 1:
            return adj, "", c
        if k == 2:
            return "", f"whichever is {adj}", c
        if k == 3:
            return "", f"with the {ext} {name}", c
        if k == 4:
            return "", f"whose {name} is{_pick(rng, (' the ', ' '))}{ext}", c
        return "", f"that's{_pick(rng, (' the ', ' '))}{adj}", c
    cmp_ = c.comparator
    if rng.uniform() < 0.12:  # "with temp > 50 C"
        name = {"temperature_c": "temp", "humidity_pct": "humidity", "ndvi": "NDVI"}[rd]
        amount, value, code = _amount(rng, rd, c.value, "symbol")
        sym = _pick(rng, _SYMBOLS[cmp_])
        return "", f"with {name} {sym}{'' if sym == '~' else ' '}{amount}", SensorConstraint(rd, cmp_, value, code)
    if rd == "temperature_c":
        k = int(rng.integers(5))
        if k == 0:  # "that's over 50 degrees", "that's hotter than 50°C"
            core, value, code = _core(rng, rd, cmp_, c.value, named=False)
            tail = f"that's {core}"
        elif k == 1:  # "that's reading over 50 degrees"
            core, value, code = _core(rng, rd, cmp_, c.value, named=False)
            tail = f"that's reading {core}" if not core.startswith(("hotter", "warmer", "colder", "cooler")) \
                else f"that's {core}"
        elif k == 2:  # "with a temperature of over 50 degrees", "with a temp above 50"
            prep = cmp_ in ("gt", "lt", "approx") and rng.uniform() < 0.4
            core, value, code = _core(rng, rd, cmp_, c.value, named=True, prep_only=prep, after_of=not prep)
            name = _pick(rng, ("a temperature", "a temp"))
            tail = f"with {name} {core}" if prep else f"with {name} of {core}"
        else:  # "whose temp is 50 or more"
            core, value, code = _core(rng, rd, cmp_, c.value, named=True)
            if core.startswith(("hotter", "warmer", "colder", "cooler", "no cooler", "no warmer")):
                tail = f"that's {core}"
            else:
                tail = f"whose {_pick(rng, ('temperature', 'temp', 'temperature reading'))} is {core}"
        return "", tail, SensorConstraint(rd, cmp_, value, code)
    if rd == "humidity_pct":
        k = int(rng.integers(4))
        if k == 0:  # "with under 30% humidity", "with 40% humidity or less"
            core, value, code = _core(rng, rd, cmp_, c.value, named=True, unit="yes", after=" humidity")
            tail = f"with {core}"
        elif k == 1:  # "with humidity under 30%", "with a humidity level of about 45 percent"
            prep = cmp_ in ("gt", "lt", "approx") and rng.uniform() < 0.5
            core, value, code = _core(rng, rd, cmp_, c.value, named=True, unit="yes", prep_only=prep,
                                      after_of=not prep)
            tail = f"with humidity {core}" if prep else f"with {_pick(rng, ('a humidity', 'a humidity level'))} of {core}"
        else:  # "whose humidity is at most 40%"
            core, value, code = _core(rng, rd, cmp_, c.value, named=True, unit="yes")
            tail = f"whose {_pick(rng, ('humidity', 'humidity level', 'humidity reading'))} is {core}"
        return "", tail, SensorConstraint(rd, cmp_, value, code)
    k = int(rng.integers(3))  # NDVI
    if k == 0:
        prep = cmp_ in ("gt", "lt", "approx") and rng.uniform() < 0.5
        core, value, code = _core(rng, rd, cmp_, c.value, named=True, prep_only=prep, after_of=not prep)
        tail = f"with {_pick(rng, ('an NDVI', 'NDVI'))} {core}" if prep else f"with an NDVI of {core}"
    else:
        core, value, code = _core(rng, rd, cmp_, c.value, named=True)
        tail = f"whose {_pick(rng, _READING_NAMES['ndvi'])} is {core}"
    return "", tail, SensorConstraint(rd, cmp_, value, code)


def _tail_pred(tail: str) -> tuple[str, str] | None:
    """A threshold tail as a predicate of the goal: 'that's over 50' -> ('is', 'over 50'), 'with X' ->
    ('has', 'X'), 'whose temp is X' -> ('whose', 'temp is X'); None for anything else."""
    if tail.startswith("that's "):
        return "is", tail[7:]
    if tail.startswith("with "):
        return "has", tail[5:]
    if tail.startswith("whose "):
        return "whose", tail[6:]
    return None


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_dev4(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y; every form starts with a preposition."""

    def minus(s: str) -> str:
        return ("minus " + s[1:]) if s.startswith("-") and rng.uniform() < 0.5 else s

    k = int(rng.integers(10))
    if k == 0:
        return f"at ({x}, {y})"
    if k == 1:
        return f"around ({x},{y})"
    if k == 2:
        return f"at x={x}, y={y}"
    if k == 3:
        return f"around x = {x}, y = {y}"
    if k == 4:
        return f"at x {minus(x)} y {minus(y)}"
    if k == 5:
        return f"at position {x}, {y}"
    if k == 6:
        return f"at coords ({x}, {y})"
    if k == 7:
        return f"at x {x}m, y {y}m"
    if k == 8:
        return f"at ({x}, {y}) on the map"
    return f"at roughly x {minus(x)}, y {minus(y)}"


# ----------------------------------------------------------------------------------------------------
# Goals


def _rooms(rng, room: str) -> str:
    return _pick(rng, (f"in the {room}", f"in the {room}", f"over in the {room}", f"down in the {room}"))


def _state_pred(rng, states: list[str]) -> tuple[str, str]:
    s = " and ".join(states)
    if len(states) == 1 and states[0] in ("open", "closed", "switched on", "switched off") and rng.uniform() < 0.25:
        return "has", f"been left {s}"
    return "is", s


def _superlative(rng, sg: Subgoal, mods, states, info) -> str | None:
    """A superlative whose scope is everything else the goal says: 'the hottest kettle in the kitchen',
    'whichever kettle in the kitchen is hottest', 'whichever fern has the highest NDVI'."""
    kind, adj, rd, cmp_ = info
    t = sg.target
    plural = is_plural(t.head)
    body = _body(mods, t.head, states)
    rels = _order_rels(rng, t.relations)
    plain = not (sg.room or states or rels)
    if kind == "prefix" or any(r.anchor.relations for r in rels):
        return None
    reduced = ([_rooms(rng, sg.room)] if sg.room else []) + [" and ".join(_rel_reduced(rng, r) for r in rels)] * bool(rels)
    rest = (" " + " ".join(reduced)) if reduced else ""
    name = _pick(rng, _READING_NAMES[rd])
    ext = _EXTREME[cmp_]
    if plain and kind == "with":
        return f"the {body} with the {ext} {name}"
    if plain and kind == "whose":
        return f"the {body} whose {name} is {_pick(rng, ('the ', ''))}{ext}"
    if plain and kind == "thats":
        return f"the {body} {'that are' if plural else _pick(rng, ('that is', 'that', 'which is'))} the {adj}".replace(
            "that the", "that's the")
    if kind in ("with", "whose"):
        return f"whichever {body}{rest} {_v('has', plural)} the {ext} {name}"
    return f"whichever {body}{rest} {_v('is', plural)} {_pick(rng, ('', 'the '))}{adj}"


def render_goal_dev4(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "",
                         hint: str = "") -> str:
    """'the kettle in the kitchen', 'the lamp that's switched on in the study', 'the hottest kettle in the
    kitchen', 'the heater in the pantry (the one that's over 50 degrees)', 'the mug at (3.5, 2)'."""
    t = sg.target
    mods, states = _split(t)
    plural = is_plural(t.head)
    sup = ("prefix", prefix, "", "") if prefix and not tail else _SUP_TAILS.get(tail)
    if sup is not None and not hint:
        got = _superlative(rng, sg, mods, states, sup)
        if got is not None:
            return got
    adj = ""
    if sup is not None:  # an extreme with a coordinate hint or a nested anchor: the adjective before the noun
        adj, tail = sup[1], ""
    # States before the noun where short ("the open toolbox"), else a clause after it.
    pre_states: list[str] = []
    if states and all(s in _SHORT_STATES for s in states) and rng.uniform() < 0.5:
        pre_states, states = ([states[0]] if len(states) == 1 else [" and ".join(states)]), []
    head_np = "the " + _body(mods, t.head, [*([adj] if adj else []), *pre_states])
    rels = _order_rels(rng, t.relations)
    tpred = _tail_pred(tail) if tail else None
    has_with_rel = any(r.type == "with" for r in rels)

    # The pieces, each as a predicate of the goal (verb, rest) and, where it has one, a reduced phrase.
    preds: list[tuple[str, str]] = []
    if states:
        preds.append(_state_pred(rng, states))
    if sg.room:
        preds.append(("is", f"in the {sg.room}"))
    if hint:
        preds.append(("is", hint))
    if tail:
        preds.append(tpred if tpred else ("raw", tail))
    rel_preds = [_rel_pred(rng, r, plural) for r in rels]
    n = len(preds) + len(rel_preds)
    if n == 0:
        return head_np
    pron = _pick(rng, ("that", "that", "which"))

    if tail and n == 1 and tpred is not None:  # "the kettle that's over 50 degrees"
        return f"{head_np} {tail}"
    if tail and tpred is None:  # a tail this set did not write: after everything else
        others = [p for p in preds if p[0] != "raw"] + rel_preds
        return f"{head_np} {_preds_text(others, plural, pron=pron)} {tail}".replace("  ", " ") if others \
            else f"{head_np} {tail}"
    if tail:
        # Room and threshold only: "the heater in the pantry (the one that's over 50 degrees)".
        if sg.room and not states and not hint and not rels and rng.uniform() < 0.35:
            one = "ones" if plural else "one"
            t2 = tail if not plural else tail.replace("that's ", "that are ", 1)
            return f"{head_np} {_rooms(rng, sg.room)} (the {one} {t2})"
        return f"{head_np} {_preds_text(preds + rel_preds, plural, pron=pron)}"
    # No threshold: a clause of coordinated predicates, or reduced phrases (after a state clause, if any).
    # Reduced phrases after a state clause only for the room ("the lamp that's switched on in the study").
    mixed_ok = not (sg.room and has_with_rel) and (not states or (sg.room and not hint and not rels))
    if n == 1 and not states and rng.uniform() < 0.7:
        if sg.room:
            return f"{head_np} {_rooms(rng, sg.room)}"
        if hint:
            return f"{head_np} {hint}"
        return f"{head_np} {_rel_reduced(rng, rels[0])}"
    if mixed_ok and rng.uniform() < 0.55:
        parts = []
        if states:
            verb, rest = _state_pred(rng, states)
            parts.append(_preds_text([(verb, rest)], plural, pron=pron))
        if sg.room:
            parts.append(_rooms(rng, sg.room))
        if hint:
            parts.append(hint)
        if rels:
            parts.append(" and ".join(_rel_reduced(rng, r) for r in rels))
        return f"{head_np} " + " ".join(parts)
    return f"{head_np} {_preds_text(preds + rel_preds, plural, pron=pron)}"


# ----------------------------------------------------------------------------------------------------
# Instructions

VERBS = ("go to", "head to", "head over to", "go over to", "swing by", "swing past", "stop by", "pop over to",
         "nip over to", "check", "check on", "check out", "go check", "go check out", "have a look at",
         "take a look at", "grab a look at", "go look at", "go see", "visit", "find", "go find", "get to",
         "make your way to", "roll over to", "drop by", "look in on")
_OPENERS = ("", "", "", "", "hey, ", "hi, ", "ok so ", "right, ", "hey robot, ", "quick one: ", "so ")
_POLITE = ("", "", "", "please ", "could you ", "can you ", "would you ", "I need you to ", "I'd like you to ",
           "I want you to ")
_CLOSERS = ("", "", "", "", ", thanks", " thanks", ", cheers", " pls", ", ta", " please")
_QUESTION = ("could you ", "can you ", "would you ")
_FREE_AFTER_COMMA = ("in any order", "any order is fine", "no particular order", "in whatever order you like",
                     "order doesn't matter", "in whichever order is easiest", "whatever order works for you")
_FREE_SENTENCE = ("any order is fine", "order doesn't matter", "the order's up to you", "I don't mind what order",
                  "do them in whatever order you like", "doesn't matter what order", "no particular order")


def _busy(res: list[str]) -> bool:
    """Whether a plain 'A, B and C' could be misread: a goal has commas, 'and' or brackets of its own, or a
    goal before the last ends in another noun phrase or a clause ('the lamp next to the sofa and the rug')."""
    return (any("," in r or " and " in r or "(" in r for r in res)
            or any(len(re.findall(r"\b(the|whichever)\b", r)) > 1 or re.search(r"\b(that|which|whose)\b", r)
                   for r in res[:-1]))


def _free_list(rng, res: list[str], v) -> str:
    """'A, B and C'; each goal with its own verb where `_busy` ('A, check B and swing by C')."""
    if _busy(res) or rng.uniform() < 0.2:
        rest = [f"{v()} {r}" for r in res[1:]]
        return res[0] + "".join(f", {r}" for r in rest[:-1]) + f"{', and ' if _busy(res) else ' and '}{rest[-1]}"
    if len(res) == 2:
        return f"{res[0]} and {res[1]}"
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


def _finish(rng, s: str, question: bool) -> str:
    """Punctuation and case as people type them: proper sentences, no final stop, or all lower case."""
    s = re.sub(r"\s{2,}", " ", s).strip()
    s = re.sub(r",\s*([,.;:?!])", r"\1", s)
    style = rng.uniform()
    s = re.sub(r"(^|[.?!] )([a-z])", lambda m: m.group(1) + m.group(2).upper(), s)
    end = "?" if question else _pick(rng, (".", ".", ".", "!"))
    if style < 0.6:
        return s if s.endswith((".", "?", "!")) else s + end
    if style < 0.85 or re.search(r"\d ?C\b|[A-Z]{2}", s.replace("NDVI", "")):
        return s.rstrip(".")
    s = s.lower()
    return s if rng.uniform() < 0.6 else (s if s.endswith((".", "?", "!")) else s + end)


def _single(rng, g: str) -> str:
    o, p = _pick(rng, _OPENERS), _pick(rng, _POLITE)
    c = _pick(rng, ("", "", " please", " pls") if p in _QUESTION else _CLOSERS)
    if "please" in c and "please" in p:
        c = ""
    return _finish(rng, f"{o}{p}{_pick(rng, VERBS)} {g}{c}", p in _QUESTION)


def _free(rng, res: list[str]) -> str:
    v = lambda: _pick(rng, VERBS)  # noqa: E731
    o, p = _pick(rng, _OPENERS), _pick(rng, _POLITE)
    lst = _free_list(rng, res, v)
    k = int(rng.integers(6))
    if p in _QUESTION and k in (0, 5):  # a question goes first: "could you check A and B? any order is fine"
        k = 1
    if k == 0:
        return _finish(rng, f"{o}{p}{v()} {lst}, {_pick(rng, _FREE_AFTER_COMMA)}", False)
    if k == 1:
        end = _pick(rng, _FREE_SENTENCE)
        return _finish(rng, f"{o}{p}{v()} {lst}{'?' if p in _QUESTION else '.'} {end}", False)
    if k == 2:
        return _finish(rng, f"{o}{v()} {lst} (any order)", False)
    if k == 3:
        lead = _pick(rng, ("in any order, ", "no particular order: ", "any order is fine: ", "order doesn't matter - "))
        return _finish(rng, f"{o}{lead}{v()} {lst}", False)
    if k == 4:
        q = _pick(rng, _QUESTION)
        end = _pick(rng, ("I don't mind which order", "doesn't matter which order you go in",
                          "whatever order works for you"))
        return _finish(rng, f"{o}{q}{v()} {lst}? {end}", False)
    end = _pick(rng, ("order doesn't matter", "any order", "whatever order"))
    return _finish(rng, f"{o}{p}{v()} {lst} - {end}", False)


def _strict(rng, res: list[str]) -> str:
    v = lambda: _pick(rng, VERBS)  # noqa: E731
    n = len(res)
    busy = _busy(res)
    o, p = _pick(rng, _OPENERS), _pick(rng, _POLITE)
    ks = list(range(8)) + ([8, 8] if n == 2 else [])
    k = _pick(rng, ks)
    if k == 0:  # "check X then Y then Z", "check X, then check Y"
        s = f"{o}{p}{v()} {res[0]}"
        for r in res[1:]:
            sep = _pick(rng, (", then ", ", and then ", ", then {v} ")) if busy else \
                _pick(rng, (" then ", ", then ", " and then ", ", then {v} "))
            s += sep.replace("{v}", v()) + r
        return _finish(rng, s, p in _QUESTION)
    if k == 1:  # "first X, then Y, and finally Z"
        s = f"{o}first {v()} {res[0]}"
        for r in res[1:-1]:
            s += f", then {r}"
        s += f", {_pick(rng, ('and finally', 'and lastly', 'and then finally')) if n > 2 else 'then'} {res[-1]}"
        return _finish(rng, s, False)
    if k == 2:  # one sentence a goal
        parts = [f"{o}{v()} {res[0]}."]
        for r in res[1:-1]:
            parts.append(f"{_pick(rng, ('after that', 'then', 'next', 'once you are done with that', 'when that is done'))}"
                         f"{_pick(rng, (', ', ' '))}{v()} {r}.".replace("you are", "you're").replace("that is", "that's"))
        parts.append(f"{_pick(rng, ('after that', 'then', 'finally', 'lastly')) if n > 2 else _pick(rng, ('after that', 'then', 'once you are done'))}"
                     f"{_pick(rng, (', ', ' '))}{v()} {res[-1]}.".replace("you are", "you're"))
        return _finish(rng, " ".join(parts), False)
    if k == 3:  # chatty: "could you X? after that I'd like you to Y"
        s = f"{o}{_pick(rng, _QUESTION)}{v()} {res[0]}? after that I'd like you to {v()} {res[1]}"
        for r in res[2:-1]:
            s += f", then {v()} {r}"
        if n > 2:
            s += f", {_pick(rng, ('and then', 'and finally', 'and lastly'))} {v()} {res[-1]}"
        return _finish(rng, s, False)
    if k == 4:  # numbered steps
        intro = _pick(rng, ("do these in order", "in this order please", "in this order", "do these in this order",
                            "one after another, in this order"))
        style = _pick(rng, ("{i})", "{i}.", "({i})"))
        sep = "; " if busy or style == "{i}." else _pick(rng, (" ", ", ", "; "))
        steps = [f"{style.format(i=i + 1)} {v()} {r}" for i, r in enumerate(res)]
        return _finish(rng, f"{o}{intro}: " + sep.join(steps), False)
    if k == 5:  # "X, once you're done there, Y"
        s = f"{o}{_pick(rng, ('', 'please '))}{v()} {res[0]}"
        links = [". once you're done, ", ", and once you're done there, ", ". when that's done, ", ". after that, "]
        for r in res[1:]:
            link = _pick(rng, links)
            links = [x for x in links if x != link] or [". after that, "]
            s += f"{link}{v()} {r}"
        return _finish(rng, s, False)
    if k == 6:  # "X first, then Y"
        s = f"{o}{p}{v()} {res[0]} first"
        for r in res[1:]:
            s += f", then {r}"
        return _finish(rng, s, p in _QUESTION)
    if k == 7:  # "start at X, ... and end up at Z"
        s = f"{o}start at {res[0]}"
        for r in res[1:-1]:
            s += f", then {v()} {r}"
        s += f", and end up at {res[-1]}"
        return _finish(rng, s, False)
    a, b = res  # two goals, the later one named first
    if rng.uniform() < 0.5:
        return _finish(rng, f"{o}before you {v()} {b}, {v()} {a}", False)
    return _finish(rng, f"{o}{v()} {b}, but {v()} {a} first", False)


def render_instruction_dev4(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals; strict texts state the order, free ones that it is open."""
    if len(res) == 1:
        return _single(rng, res[0])
    return _free(rng, res) if order == "free" else _strict(rng, res)
