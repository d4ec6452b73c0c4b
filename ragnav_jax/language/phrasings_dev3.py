"""Third development phrasings: goal, sensor, coordinate and instruction templates (`unseen_dev3` split).

Written without reading the rule parser as the held-out set after parser round 3 (which parsed 15 / 192
of its instructions on the test houses); parser round 4 was then developed against it.

A fourth template set beside the seen one (`episodes.py`) and the two development ones (`phrasings.py`,
`phrasings_dev2.py`): the same four functions, arguments and meanings, written without reading the rule
parser, with structures and wordings none of the other sets produces:

- rooms as possessives ("the pantry's kettle") and as clauses ("that lives in", "we keep in",
  "you'll find in"), or a parenthesis "(the pantry one)";
- one-word states before the noun ("the open toolbox"), participle states as "that has been switched on",
  bare parentheses "(switched on)", "(teal)";
- relations such as "a stone's throw from", "side by side with", "perched on", "tucked under", "straight
  across from", "to the sofa's left", "in whichever room the sofa is in" and, for "with", an object relative
  "the desk that the monitor is on or near";
- readings named "temp", "RH", "NDVI index"; thresholds "north of", "south of", "above the 60-degree mark",
  "60 C and up", "40% or under", "give or take", "60-ish", symbols "(temp > 60 °C)", "(RH ≤ 40%)";
  numbers as digits, words up to the hundreds, "60.0", "point six", "minus"/"negative", "below zero";
  units "C", "degC", "° C";
- superlatives as "whichever heater in the pantry is warmest", "the pantry's warmest heater", "warmer than any
  other one in there", "whose temp is the highest in the pantry", "with the top temp";
- coordinates as "whose coordinates are (3.5, 2)", "at x/y = 3.5/2", "at {x: 3.5, y: 2}", "at (x, y) = (3.5, 2)",
  "with an x of three point five and a y of negative two";
- instructions with new verbs and polite questions ("would you be able to", "any chance you could");
  strict order as ordinal adverbs ("A first, B second and C last"), "start with ... finish with", lettered and
  "#1" lists, "Step one: ...", "Next stop:", "before you ...", "not until you've been to", "only then",
  "afterwards"; free order as "I'm not fussed about the order", "either one can come first", bullets.

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.phrasings import is_state
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Numbers

_ONES = ("zero one two three four five six seven eight nine ten eleven twelve thirteen fourteen fifteen sixteen "
         "seventeen eighteen nineteen").split()
_TENS = ("", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety")


def words(n: int) -> str:
    """English words for an integer in [-999, 999]: 120 -> 'one hundred and twenty', -5 -> 'minus five'."""
    if n < 0:
        return "minus " + words(-n)
    if n < 20:
        return _ONES[n]
    if n < 100:
        return _TENS[n // 10] + (f"-{_ONES[n % 10]}" if n % 10 else "")
    if n < 1000:
        rest = n % 100
        return f"{_ONES[n // 100]} hundred" + (f" and {words(rest)}" if rest else "")
    raise ValueError(f"no words for {n}")


def decimal_words(s: str) -> str | None:
    """'3.5' -> 'three point five', '-0.25' -> 'minus zero point two five'; None outside [-999, 999]."""
    neg = s.startswith("-")
    s = s.lstrip("-")
    whole, _, frac = s.partition(".")
    if not whole.isdigit() or int(whole) > 999 or (frac and not frac.isdigit()):
        return None
    out = words(int(whole)) + (" point " + " ".join(_ONES[int(d)] for d in frac) if frac else "")
    return ("minus " if neg else "") + out


# ----------------------------------------------------------------------------------------------------
# Noun phrases

# States that read well before the noun ("the open toolbox"), and participles ("that has been switched on").
_PRENOMINAL = frozenset(("open", "closed", "empty", "full", "lit", "unlit", "running", "idle", "folded", "unfolded",
                         "locked", "unlocked", "unplugged"))
_PARTICIPLE = frozenset(("switched on", "switched off", "turned on", "turned off", "plugged in", "unplugged",
                         "folded", "unfolded", "locked", "unlocked", "closed"))

# Relations with the meanings of types.RELATION_TYPES (episodes.relation_holds): (reduced forms after the
# noun, verb phrases for "that ..."). "{a}" is the anchor. "with" (the anchor is on the target or near it)
# is an object relative, "the desk that the monitor is on or near", built in `_relation`.
_REL: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "near": (("a few steps from {a}", "a stone's throw from {a}", "near to {a}"),
             ("is a few steps from {a}", "sits a stone's throw from {a}", "stands near to {a}")),
    "next_to": (("alongside {a}", "side by side with {a}", "directly next to {a}"),
                ("stands alongside {a}", "sits directly next to {a}")),
    "beside": (("at the side of {a}", "immediately beside {a}"), ("stands at the side of {a}", "sits immediately beside {a}")),
    "by": (("down by {a}", "just by {a}"), ("sits just by {a}", "is down by {a}")),
    "on": (("perched on {a}", "standing on top of {a}", "up on {a}"), ("stands on {a}", "is perched on {a}")),
    "under": (("tucked under {a}", "below {a}"), ("is tucked under {a}", "sits below {a}")),
    "above": (("up above {a}", "over {a}"), ("is up above {a}", "is over {a}")),
    "in": (("tucked inside {a}", "sitting in {a}", "within {a}"), ("is tucked inside {a}", "sits within {a}")),
    "in_room_with": (("in whichever room {a} is in", "in the room {a} is in"),
                     ("is in whichever room {a} is in", "is in the room {a} is in")),
    "in_front_of": (("directly in front of {a}", "out in front of {a}"), ("stands directly in front of {a}",)),
    "behind": (("directly behind {a}", "tucked behind {a}"), ("is tucked behind {a}", "stands directly behind {a}")),
    "opposite": (("directly opposite {a}", "straight across from {a}"),
                 ("sits directly opposite {a}", "is straight across from {a}")),
    "left_of": (("just left of {a}", "on the left of {a}", "to {p} left"), ("sits just left of {a}", "is to {p} left")),
    "right_of": (("just right of {a}", "on the right of {a}", "to {p} right"),
                 ("sits just right of {a}", "is to {p} right")),
}
# "with" as an object relative, the anchor first ("the desk that the monitor is on or near"), or, where the
# anchor has clauses of its own, last ("the desk that either supports or stands near the monitor that ...").
_WITH = ("{a} is on or near", "{a} rests on or stands near", "{a} sits on or close to")
_WITH_LAST = "either supports or stands near {a}"
_ROOM_WITH_LAST = (("in the room where you'll find {a}",), ("is in the room where you'll find {a}",))
_PLURAL_VERBS = {"is": "are", "has": "have", "sits": "sit", "stands": "stand", "lives": "live", "rests": "rest",
                 "supports": "support"}


def is_plural(head: str) -> bool:
    """Whether a head noun takes a plural verb ('drums', 'shelves', 'electronics'); singular nouns ending in
    -ss, -us, -is and a few others are not."""
    last = head.split()[-1].lower()
    return (last.endswith("s") and not last.endswith(("ss", "us", "is"))
            and last not in ("lens", "gas", "canvas", "atlas", "chaos"))


def _agree(vp: str, plural: bool) -> str:
    """A verb phrase for a plural subject: 'is switched on' -> 'are switched on', 'rests on or stands near'."""
    if not plural:
        return vp
    words = vp.split(" ")
    out = [_PLURAL_VERBS.get(w, w) if i == 0 or words[i - 1] in ("or", "and", "either") else w
           for i, w in enumerate(words)]
    return " ".join(out)


def _anchor(rng, t: Target) -> tuple[str, bool]:
    """(anchor noun phrase, whether it ends with its head noun, so that "the sofa's left" can be said)."""
    states = [a for a in t.attributes if is_state(a)]
    mods = [a for a in t.attributes if not is_state(a)]
    plural = is_plural(t.head)
    pre = []
    if len(states) == 1 and states[0] in _PRENOMINAL and rng.uniform() < 0.6:
        pre, states = states, []
    out = "the " + " ".join((*pre, *mods, t.head))
    clauses = []
    if states:
        s = " and ".join(states)
        vp = f"has been {s}" if all(x in _PARTICIPLE for x in states) and rng.uniform() < 0.5 else f"is {s}"
        clauses.append(_agree(vp, plural))
    rels = [_relation(rng, r, bool(clauses) or rng.uniform() < 0.6, plural) for r in t.relations]
    if clauses or any(k != "red" for k, _ in rels):
        parts = clauses + [f"{_agree('is', plural)} {x}" if k == "red" else x for k, x in rels]
        return f"{out} that " + " and ".join(_strip_that(p, i) for i, p in enumerate(parts)), False
    if rels:
        return out + " " + " and ".join(x for _, x in rels), False
    return out, True


def _strip_that(vp: str, i: int) -> str:
    """Object relatives keep their own "that" ("that the lamp is on or near"); the first loses it."""
    return vp[5:] if i == 0 and vp.startswith("that ") else vp


def _relation(rng, r: Relation, clause: bool, plural: bool = False) -> tuple[str, str]:
    """('red', reduced phrase), ('rel', verb phrase agreeing with a plural target) or ('obj', 'that X is on or
    near') for one relation. An anchor with clauses of its own goes last."""
    a, ends_with_head = _anchor(rng, r.anchor)
    if r.type == "with":
        if not ends_with_head:
            return "rel", _agree(_WITH_LAST, plural).format(a=a)
        return "obj", "that " + _agree(_pick(rng, _WITH), is_plural(r.anchor.head)).format(a=a)
    red, vps = _REL.get(r.type, ((r.type.replace("_", " ") + " {a}",), ("is " + r.type.replace("_", " ") + " {a}",)))
    if r.type == "in_room_with" and not ends_with_head:
        red, vps = _ROOM_WITH_LAST
    forms = vps if clause else red
    if not ends_with_head:
        forms = tuple(f for f in forms if "{p}" not in f) or forms
    form = _pick(rng, forms)
    if clause:
        return "rel", _agree(form, plural).format(a=a, p=a + "'s")
    return "red", form.format(a=a, p=a + "'s")


def _join_clauses(rng, clauses: list[tuple[str, str]]) -> str:
    """'that X and Y', 'that X, whose Y and that Z': (pronoun, verb phrase) pairs, a pronoun repeated where
    the clause is not a plain subject relative or follows one that is not."""
    out, prev = [], None
    for pron, vp in clauses:
        if prev is not None and pron not in ("whose", "obj") and prev not in ("whose", "obj"):
            out.append(vp)
        else:
            out.append(vp if pron == "obj" else f"{pron} {vp}")
        prev = pron
    if len(out) == 1:
        return out[0]
    return ", ".join(out[:-1]) + " and " + out[-1]


# Superlatives: adjectives, comparatives, extremes and reading names.
_SUP_ADJ = {
    ("temperature_c", "max"): ("warmest", "hottest"), ("temperature_c", "min"): ("coldest", "coolest"),
    ("ndvi", "max"): ("greenest", "healthiest"), ("ndvi", "min"): ("least healthy", "least green"),
    ("humidity_pct", "max"): ("most humid", "dampest"), ("humidity_pct", "min"): ("driest", "least humid"),
}
_COMPARATIVE = {"warmest": "warmer", "hottest": "hotter", "coldest": "colder", "coolest": "cooler",
                "greenest": "greener", "healthiest": "healthier", "least healthy": "less healthy",
                "least green": "less green", "most humid": "more humid", "dampest": "damper", "driest": "drier",
                "least humid": "less humid"}
_SUP_NAMES = {"temperature_c": ("temp", "temperature"), "humidity_pct": ("humidity", "RH"),
              "ndvi": ("NDVI", "NDVI index")}
_EXT = {"max": ("highest", "top"), "min": ("lowest",)}


def _super_tails() -> dict[str, tuple[str, str]]:
    """Every superlative tail the sensor renderer writes -> (form, adjective where the form cannot be used)."""
    out = {}
    for (rd, cmp_), adjs in _SUP_ADJ.items():
        for adj in adjs:
            out[f"whichever is {adj}"] = ("whichever", adj)
            out[f"that is {_COMPARATIVE[adj]} than any other"] = ("comparative", adj)
        for ext in _EXT[cmp_]:
            for n in _SUP_NAMES[rd]:
                out[f"with the {ext} {n}"] = ("with", adjs[0])
        for n in _SUP_NAMES[rd]:
            out[f"whose {n} is the {_EXT[cmp_][0]}"] = ("whose", adjs[0])
    return out


_SUPER_TAILS = _super_tails()


def _room_piece(rng, room: str, kinds: tuple[str, ...]) -> tuple[str, object]:
    k = _pick(rng, kinds)
    if k == "pos":
        return "pos", f"{room}'s"
    if k == "rel":
        return "rel", ("that" if rng.uniform() < 0.5 else "which", f"lives in the {room}")
    if k == "obj":
        return "obj", _pick(rng, (f"that we keep in the {room}", f"that you'll find in the {room}",
                                  f"that we've got in the {room}"))
    if k == "paren":
        return "paren", f"the {room} one"
    return "red", f"in the {room}"


def _tail_kind(tail: str) -> str:
    if tail.startswith("("):
        return "paren"
    if re.match(r"(that|which|whose) ", tail):
        return "rel"
    return "red"


def _np(rng, t: Target, room: str | None, adj: str = "", tail: str = "", hint: str = "") -> str:
    """A goal noun phrase: pieces before the noun, then parentheses, reduced phrases, relative clauses and
    the relations last (so nothing can attach to an anchor). After a relative clause only clauses follow."""
    states = [a for a in t.attributes if is_state(a)]
    mods = [a for a in t.attributes if not is_state(a)]
    plural = is_plural(t.head)
    pre_room, pre_state = "", ""
    parens: list[str] = []
    reds: list[str] = []
    clauses: list[tuple[str, str]] = []
    tail_kind = _tail_kind(tail) if tail else ""
    if tail_kind == "paren":
        parens.append(tail[1:-1])
    if room:
        kinds = ("pos", "rel", "obj") if tail_kind == "rel" else ("pos", "rel", "obj", "paren", "red")
        if parens:
            kinds = tuple(k for k in kinds if k != "paren")
        k, piece = _room_piece(rng, room, kinds)
        if k == "pos":
            pre_room = piece
        elif k == "paren":
            parens.append(piece)
        elif k == "red":
            reds.append(piece)
        elif k == "obj":
            clauses.append(("obj", piece))
        else:
            clauses.append((piece[0], _agree(piece[1], plural)))
    if mods and not parens and rng.uniform() < 0.2:
        parens.append(" ".join(mods))
        mods = []
    if states:
        s = " and ".join(states)
        opts = ["rel", "rel"] + (["pre", "pre"] if len(states) == 1 and states[0] in _PRENOMINAL else [])
        opts += ["paren"] if not parens else []
        k = _pick(rng, opts)
        if k == "pre":
            pre_state = states[0]
        elif k == "paren":
            parens.append(s)
        else:
            pron = "that" if rng.uniform() < 0.6 else "which"
            vp = f"has been {s}" if all(x in _PARTICIPLE for x in states) and rng.uniform() < 0.6 else f"is {s}"
            clauses.insert(0, (pron, _agree(vp, plural)))
    if hint:
        m = re.match(r"(that|which|whose) (.*)", hint)
        if m:
            clauses.append((m.group(1), m.group(2)))
        else:
            reds.insert(0, hint)
    if tail and tail_kind != "paren":
        m = re.match(r"(that|which|whose) (.*)", tail)
        if m:
            clauses.append((m.group(1), m.group(2) if m.group(1) == "whose" else _agree(m.group(2), plural)))
        else:
            reds.append(tail)
    rel_clause = bool(clauses) or (len(t.relations) == 1 and rng.uniform() < 0.45)
    pron = "that" if rng.uniform() < 0.6 else "which"
    rel_red = []
    for r in t.relations:
        k, text = _relation(rng, r, rel_clause, plural)
        if k == "red":
            rel_red.append(text)
        else:
            clauses.append(("obj", text) if k == "obj" else (pron, text))
    room_red = f"in the {room}"
    if room_red in reds and clauses:  # "the freezer in the pantry that's open": the room would look open
        reds.remove(room_red)
        at = sum(1 for c in clauses[:1] if c[1].startswith(("is ", "are ", "has been ", "have been ")))
        clauses.insert(at, (pron, _agree(f"is {room_red}", plural)))
    head = " ".join(x for x in ("the", pre_room, adj, pre_state, *mods, t.head) if x)
    out = head
    if parens:  # at most one: the room, attribute and state pieces take a parenthesis only while none is set
        out += f" ({parens[0]})"
    for p in reds:
        out += f" {p}"
    if rel_red:
        out += " " + " and ".join(rel_red)
    if clauses:
        text = _join_clauses(rng, clauses)
        if text.startswith("that is ") and rng.uniform() < 0.3:
            text = "that's " + text[8:]
        out += " " + text
    return out


def _superlative(rng, sg: Subgoal, adj: str, form: str, tail: str) -> str | None:
    """A superlative goal whose restrictions (head, attributes, room) all scope the extreme; None where the
    form cannot hold them (states, relations or a hint: the caller puts the adjective before the noun)."""
    t = sg.target
    if any(is_state(a) for a in t.attributes) or t.relations:
        return None
    mods = " ".join(a for a in t.attributes if not is_state(a))
    noun = " ".join(x for x in (mods, t.head) if x)
    room = sg.room
    be = "are" if is_plural(t.head) else "is"
    where = f" in the {room}" if room else ""
    if form == "comparative" and be == "are":
        form = "whichever"
    if form == "prefix":
        k = int(rng.integers(3 if room else 2))
        if k == 0:
            form = "whichever"
        elif not room:
            return f"the {adj} {noun}"
        elif k == 1:
            return f"the {room}'s {adj} {noun}"
        else:
            return f"the {adj} {noun} you can find in the {room}"
    if form == "whichever":
        return f"whichever {noun}{where} {be} {_pick(rng, ('', 'the '))}{adj}"
    if form == "comparative":
        comp = _COMPARATIVE[adj]
        if room:
            pron = _pick(rng, ("that", "which"))
            return f"the {noun} {pron} lives in the {room} and is {comp} than any other one in there"
        return f"the {noun} that is {comp} than any other {noun}"
    if form == "with":
        return f"the {noun} {tail}" + (f" in the {room}" if room else "")
    if form == "whose":
        return f"the {noun} {tail}" + (f" in the {room}" if room else _pick(rng, ("", " of them all", " of the lot")))
    return None


def render_goal_dev3(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "",
                        hint: str = "") -> str:
    """'the pantry's kettle', 'the open toolbox tucked under the bench', 'whichever heater in the garage is
    warmest', 'the dehumidifier that lives in the laundry room and whose RH is south of 40%'."""
    sup = _SUPER_TAILS.get(tail)
    if sup or (prefix and not tail):
        form = sup[0] if sup else "prefix"
        adj = prefix or sup[1]
        if not hint:
            got = _superlative(rng, sg, adj, form, tail)
            if got is not None:
                return got
        return _np(rng, sg.target, sg.room, adj=adj, hint=hint)
    return _np(rng, sg.target, sg.room, adj=prefix, tail=tail, hint=hint)


# ----------------------------------------------------------------------------------------------------
# Sensor constraints

# Reading names: (name, with an article).
_NAMES = {"temperature_c": (("temp", "a temp"), ("temperature", "a temperature")),
          "humidity_pct": (("humidity", "a humidity"), ("RH", "an RH"), ("relative humidity", "a relative humidity")),
          "ndvi": (("NDVI", "an NDVI"), ("NDVI index", "an NDVI index"),
                   ("vegetation index (NDVI)", "a vegetation index (NDVI)"))}
# Thresholds after "whose N is" ("is") and after "that has a N" ("of"); {v} the amount, {m} a compact amount.
_CMP = {
    "gt": {"is": ("north of {v}", "past {v}", "above the {m} mark"), "of": ("north of {v}", "above the {m} mark")},
    "ge": {"is": ("{v} or greater", "{v} and up", "{v} at the very least"),
           "of": ("of {v} or greater", "of {v} and up", "of {v} at the very least")},
    "lt": {"is": ("south of {v}", "below the {m} mark"), "of": ("south of {v}", "below the {m} mark")},
    "le": {"is": ("{v} or under", "{v} and under"), "of": ("of {v} or under", "of up to {v}", "of {v} and under")},
    "approx": {"is": ("{v} give or take", "in the ballpark of {v}", "more or less {v}", "{ish}"),
               "of": ("of {v} give or take", "in the ballpark of {v}", "of more or less {v}", "of {ish}")},
}
_SYMBOL = {"gt": (">",), "ge": ("≥", ">="), "lt": ("<",), "le": ("≤", "<="), "approx": ("≈", "~")}
_T_UNITS = (" C", "C", " degC", "° C", " °C", " degrees")
_H_UNITS = ("%", " percent")


def _amount(rng, reading: str, v: float, style: str = "free") -> tuple[str, float, str]:
    """(number and unit as written, the value it denotes, unit code). style 'free': digits, '60.0', words,
    'minus'/'negative', 'below zero'; 'mark': a compact amount ('60-degree', '60 °C', '40%'); 'symbol': digits;
    'ish': '60-ish degrees' (integers from 0)."""
    vtxt = _fmt_value(reading, v)
    value = float(vtxt)
    neg = value < 0
    mag = vtxt.lstrip("-")
    if reading == "ndvi":
        forms = [vtxt, vtxt]
        if style == "free":
            w = decimal_words(mag)
            if w and "." in mag:
                forms += [w, w.replace("zero point", "point")]
            elif w:
                forms += [w]
            if neg:
                forms = [f if f == vtxt else "minus " + f for f in forms] + [f"negative {mag}"]
        return _pick(rng, forms), value, ""
    integer = value.is_integer()
    temp = reading == "temperature_c"
    if style == "symbol":
        unit = _pick(rng, (" °C", "°C", " C")) if temp else "%"
        return vtxt + unit, value, "c" if temp else "%"
    if style == "mark":
        if temp and integer and value >= 0 and rng.uniform() < 0.6:
            num = words(int(value)) if value < 100 and rng.uniform() < 0.3 else vtxt
            return f"{num}-degree", value, "c"
        return vtxt + (_pick(rng, (" °C", "C", " C")) if temp else "%"), value, "c" if temp else "%"
    if style == "ish":
        num = words(int(value)) if rng.uniform() < 0.4 and value < 100 else vtxt
        return f"{num}-ish" + (" degrees" if temp else " percent"), value, "c" if temp else "%"
    k = rng.uniform()
    if integer and abs(value) <= 999 and k < 0.3:
        num, as_words = words(int(abs(value))), True
    elif integer and k < 0.4:
        num, as_words = mag + ".0", False
    else:
        num, as_words = mag, False
    if temp:
        if neg and rng.uniform() < 0.35:
            return f"{num} degrees below zero", value, "c"
        unit = _pick(rng, (" degrees", " degrees Celsius") if as_words else _T_UNITS)
    else:
        unit = " percent" if as_words else _pick(rng, _H_UNITS)
    if neg:
        num = _pick(rng, ("minus ", "negative ") if as_words else ("-", "minus ", "negative ")) + num
    if temp and not as_words and rng.uniform() < 0.1:
        return num, value, ""  # the reading is named: "whose temp is north of 60"
    return num + unit, value, "c" if temp else "%"


def render_sensor_dev3(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written)."""
    rd = c.reading
    if c.is_superlative:
        adj = _pick(rng, _SUP_ADJ[(rd, c.comparator)])
        k = int(rng.integers(5))
        if k == 0:
            return adj, "", c
        if k == 1:
            return "", f"whichever is {adj}", c
        if k == 2:
            return "", f"that is {_COMPARATIVE[adj]} than any other", c
        if k == 3:
            return "", f"with the {_pick(rng, _EXT[c.comparator])} {_pick(rng, _SUP_NAMES[rd])}", c
        return "", f"whose {_pick(rng, _SUP_NAMES[rd])} is the {_EXT[c.comparator][0]}", c
    k = int(rng.integers(5))
    if k == 0:  # symbols: "(temp > 60 °C)"
        n = _pick(rng, (_SUP_NAMES[rd]))
        amount, value, code = _amount(rng, rd, c.value, "symbol")
        sym = _pick(rng, _SYMBOL[c.comparator])
        gap = "" if sym == "~" else " "
        return "", f"({n} {sym}{gap}{amount})", SensorConstraint(rd, c.comparator, value, code)
    frame = "is" if k in (1, 2) else "of"
    forms = _CMP[c.comparator][frame]
    if c.value < 0:  # "past -18" could go either way
        forms = tuple(f for f in forms if not f.startswith("past"))
    form = _pick(rng, forms)
    if "{ish}" in form and not (rd != "ndvi" and float(_fmt_value(rd, c.value)).is_integer()
                                and float(_fmt_value(rd, c.value)) >= 1):
        form = _CMP[c.comparator][frame][0]
    style = "mark" if "{m}" in form else "ish" if "{ish}" in form else "free"
    amount, value, code = _amount(rng, rd, c.value, style)
    phrase = form.format(v=amount, m=amount, ish=amount)
    n, an = _pick(rng, _NAMES[rd])
    lead = f"whose {n} is " if frame == "is" else f"{_pick(rng, ('that', 'which'))} has {an} "
    return "", lead + phrase, SensorConstraint(rd, c.comparator, value, code)


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_dev3(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres); the numbers written are x and y."""

    def spoken(s: str) -> str:
        k = rng.uniform()
        w = decimal_words(s)
        if w and k < 0.3:
            return w.replace("minus", "negative") if rng.uniform() < 0.5 else w
        if s.startswith("-") and k < 0.6:
            return _pick(rng, ("minus ", "negative ")) + s[1:]
        return s

    k = int(rng.integers(7))
    if k == 0:
        return f"whose coordinates are ({x}, {y})"
    if k == 1:
        return f"whose map position is x {spoken(x)}, y {spoken(y)}"
    if k == 2:
        return f"at x/y = {x}/{y}"
    if k == 3:
        return f"at {{x: {x}, y: {y}}}"
    if k == 4:
        return f"at {x} (x) and {y} (y)"
    if k == 5:
        return f"at (x, y) = ({x}, {y})"
    return f"with an x of {spoken(x)} and a y of {spoken(y)}"


# ----------------------------------------------------------------------------------------------------
# Instructions

# (base, -ing): imperatives the seen VERBS and the development sets never use.
VERBS_HELDOUT = (
    ("find your way to", "finding your way to"), ("make a beeline for", "making a beeline for"),
    ("wheel over to", "wheeling over to"), ("scoot over to", "scooting over to"), ("zip over to", "zipping over to"),
    ("head across to", "heading across to"), ("pull up at", "pulling up at"), ("make a trip to", "making a trip to"),
    ("trundle over to", "trundling over to"), ("go round to", "going round to"),
)
_ORD = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth")
_STEP = ("one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten")


def _cap(s: str) -> str:
    return s[0].upper() + s[1:]


def _tidy(s: str) -> str:
    s = re.sub(r"\s{2,}", " ", s).strip()
    s = re.sub(r",\s*([,.;:?])", r"\1", s)
    return _cap(s)


def _busy(res: list[str]) -> bool:
    """Whether a plain 'A, B and C' could be misread: a goal has commas or 'and' of its own, or a goal before
    the last ends in another noun phrase ('the iron near the board and the bag': is the bag an anchor?)."""
    return any("," in r or " and " in r or ";" in r for r in res) or any(r.count("the ") > 1 for r in res[:-1])


def _list(rng, res: list[str]) -> str:
    """'A, B and C'; semicolons (for two goals ', and also' or ', plus') where `_busy`."""
    if _busy(res):
        if len(res) == 2:
            return f"{res[0]}{_pick(rng, (', and also ', ', plus '))}{res[1]}"
        return "; ".join(res[:-1]) + "; and " + res[-1]
    if len(res) == 2:
        return f"{res[0]} and {res[1]}"
    return ", ".join(res[:-1]) + _pick(rng, (" and ", ", and ")) + res[-1]


def _markers(rng, n: int) -> list[str]:
    k = int(rng.integers(3))
    if k == 0:
        return [f"({chr(97 + i)})" for i in range(n)]
    if k == 1:
        return [f"#{i + 1}" for i in range(n)]
    return [f"{i + 1}{('st', 'nd', 'rd')[i] if i < 3 else 'th'}:" for i in range(n)]


def _single(rng, g: str) -> str:
    v, ing = _pick(rng, VERBS_HELDOUT)
    return _tidy(_pick(rng, (
        f"would you be able to {v} {g}?", f"do you think you could {v} {g}?", f"any chance you could {v} {g}?",
        f"go ahead and {v} {g}.", f"mind {ing} {g}?", f"I was wondering if you could {v} {g}.",
        f"is it possible for you to {v} {g}?", f"{v} {g} when you get a moment.",
    )))


def _free(rng, res: list[str]) -> str:
    v = lambda: _pick(rng, VERBS_HELDOUT)[0]  # noqa: E731
    n = len(res)
    p = _pick(rng, ("", "", "please "))
    lst = _list(rng, res)
    k = int(rng.integers(8))
    end = ". " if _busy(res) else "; "  # after a list with semicolons, a sentence of its own
    if k == 0:
        s = f"{p}{v()} {lst}{end}I'm not fussed about the order."
    elif k == 1:
        s = f"{p}{v()} {lst}. It makes no difference which one you do first."
    elif k == 2:
        s = f"no need to stick to the order I've listed them in: {v()} {lst}."
    elif k == 3:
        s = f"could you {v()} {lst}? The order isn't important."
    elif k == 4:
        s = f"{v()} each of these, in no special order: " + " ".join(f"• {r}" for r in res) + "."
    elif k == 5:
        s = f"the order is flexible: {v()} {lst}."
    elif k == 6:
        s = (f"{p}{v()} {lst} — either one can come first." if n == 2 else
             f"{p}{v()} {lst}{end}{'F' if end == '. ' else 'f'}eel free to shuffle the order.")
    else:
        s = f"would you mind {_pick(rng, VERBS_HELDOUT)[1]} {lst}? You're free to choose the sequence."
    return _tidy(s)


def _strict(rng, res: list[str]) -> str:
    v = lambda: _pick(rng, VERBS_HELDOUT)[0]  # noqa: E731
    ing = lambda: _pick(rng, VERBS_HELDOUT)[1]  # noqa: E731
    n = len(res)
    busy = _busy(res)
    sep = "; " if busy else ", "
    p = _pick(rng, ("", "", "please "))
    plain = not any(re.search(r"\d|\b(that|which|whose|whichever|than)\b", r) for r in res)
    ks = list(range(0 if plain else 1, 8)) + ([8, 8] if n == 2 else [9] if n == 3 else [])
    k = _pick(rng, ks)
    if k == 0:  # ordinal adverbs: "A first, B second and C last"
        head = [f"{r} {_ORD[i]}" for i, r in enumerate(res[:-1])]
        last = f"{res[-1]} {'second' if n == 2 else 'last'}"
        s = f"{p}{v()} " + sep.join(head) + (f"{sep}and " if busy or n > 2 and rng.uniform() < 0.5 else " and ") + last
        return _tidy(s + ".")
    if k == 1:  # start with ... finish with
        mid = "".join(f"{sep}go on to {r}" for r in res[1:-1])
        end = f"{sep}and finish with {res[-1]}" if n > 2 else f" and finish with {res[-1]}"
        return _tidy(f"start with {res[0]}{mid}{end}.")
    if k == 2:  # a marked list
        intro = _pick(rng, (f"{p}{v()} these in the order listed", "go through the following in the order given",
                            f"{v()} the following, keeping to this order"))
        marks = _markers(rng, n)
        colon = ". " if marks[0].endswith(":") else ": "  # "1st: ..." after a sentence, not after a colon
        return _tidy(f"{intro}{colon}" + "; ".join(f"{m} {r}" for m, r in zip(marks, res)) + ".")
    if k == 3:  # Step one: ...
        return " ".join(_tidy(f"step {_STEP[i]}: {v()} {r}.") for i, r in enumerate(res))
    if k == 4:  # Next stop: ...
        parts = [_tidy(f"{p}{v()} {res[0]}.")]
        parts += [_tidy(f"next stop: {r}.") for r in res[1:-1]]
        parts.append(_tidy(f"{'final stop' if n > 2 else 'next stop'}: {res[-1]}."))
        return " ".join(parts)
    if k == 5:  # a polite question with "afterwards"
        mid = "".join(f"{sep}afterwards {r}" for r in res[1:-1])
        end = f"{sep}and at the very end {res[-1]}" if n > 2 else f"{',' if busy else ''} and afterwards {res[-1]}"
        return _tidy(f"would you mind {ing()} {res[0]}{mid}{end}?")
    if k == 6:  # semicolons: "to begin with; follow that with; end with"
        if n == 2:
            return _tidy(f"{v()} {res[0]} to begin with, and end with {res[-1]}.")
        mid = "".join(f"; follow that with {r}" for r in res[1:-1])
        return _tidy(f"{v()} {res[0]} to begin with{mid}; and end with {res[-1]}.")
    if k == 7:  # as listed
        return _tidy(f"order matters here: {v()} {_list(rng, res)}, exactly as listed.")
    if k == 8:  # two goals: before / not until / only then
        a, b = res
        return _tidy(_pick(rng, (
            f"before you {v()} {b}, {v()} {a}.", f"before {ing()} {b}, {v()} {a}.",
            f"{v()} {b}, but not until you've been to {a}.", f"{v()} {a}, and only then {v()} {b}.",
        )))
    a, b, c = res  # three goals
    return _tidy(f"{v()} {a}; only then {v()} {b}; and only after that, {v()} {c}.")


def render_instruction_dev3(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals; strict texts state the order, free ones that it is open."""
    if len(res) == 1:
        return _single(rng, res[0])
    return _free(rng, res) if order == "free" else _strict(rng, res)
