"""Fifth development phrasings: goal, sensor, coordinate and instruction templates (`unseen_dev5` split).

Written without reading the rule parser as the held-out set after parser round 5 (which parsed 87 / 192 of
its instructions on the test houses; the README's second closed-loop held-out table uses it with that
parser); parser round 6 was then developed against it. Beside the other sets: the same four functions, arguments and meanings, written by yet another author
who never read the rule parser. The style is requests as they come out of speech recognition when people talk
to a home robot, and messages typed by non-native English speakers:

- spoken: lower case, no punctuation, fillers at the seams ("um", "uh", "okay so", "alright", "you know",
  "like" before a verb), run-ons joined by "and then", "and after that", "so then"; numbers mostly as spoken
  words ("twenty two point five degrees", "zero point three", "minus five", "three hundred and eighty"),
  sometimes digits; coordinates spoken ("at x three point five y two", "at three point five comma two");
  superlatives and comparatives as people say them ("the one that's the warmest", "whichever amplifier in the
  workshop is the hottest", "hotter than fifty");
- non-native: simple present-tense sentences with capitals and stops ("Please go and check the guitar. After
  that you go to the harp."), "after you go to ..., go to ...", "you can choose the order", "degree" for
  "degrees", the article dropped before a reading ("with temperature over fifty") but never before a goal or
  anchor noun.
- goals: "the teal guitar in the music room", "the amplifier that's switched on and is next to the harp",
  "the empty toolbox", "the guitar you know the one in the music room", anchors with clauses of their own
  last ("next to the sofa that's on the rug", "next to whichever sofa is on the rug"); a second clause-bearing
  anchor is restarted with "and the same lamp is also ...", so nothing can attach to the wrong noun.
- free order: "doesn't matter which one first", "in any order you want", "you can choose the order";
  strict order: "first ... and then ...", "step one ... step two ...", "start with ... and finish at ...".

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.types import SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Words

# Object states as the scenes name them; written after the noun ("that's switched on") or before it.
STATES = frozenset(("switched on", "switched off", "turned on", "turned off", "open", "closed", "empty", "full",
                    "plugged in", "unplugged", "locked", "unlocked", "folded", "unfolded"))
# States said before the noun of a goal ("the empty toolbox"); anchors take any state before the noun.
_PRE_STATES = frozenset(("open", "closed", "empty", "full", "locked", "unlocked", "folded", "unfolded",
                         "unplugged"))

_ONES = ("zero one two three four five six seven eight nine ten eleven twelve thirteen fourteen fifteen sixteen "
         "seventeen eighteen nineteen").split()
_TENS = ("", "", "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety")


def int_words(rng, n: int) -> str:
    """0..999 as spoken ('twenty two', 'three hundred and eighty'); larger numbers stay digits."""
    if n < 20:
        return _ONES[n]
    if n < 100:
        return _TENS[n // 10] + (f" {_ONES[n % 10]}" if n % 10 else "")
    if n < 1000:
        h, rest = divmod(n, 100)
        lead = "a hundred" if h == 1 and rng.uniform() < 0.3 else f"{_ONES[h]} hundred"
        if not rest:
            return lead
        return f"{lead}{' and' if rng.uniform() < 0.6 else ''} {int_words(rng, rest)}"
    return str(n)


def spoken_number(rng, s: str, digits_p: float = 0.3) -> str:
    """A number written as digits ('22.5', '-3') or as speech recognition writes a spoken one ('twenty two
    point five', 'minus three', 'point six five'); `s` is the number as a decimal string."""
    if rng.uniform() < digits_p:
        return s
    neg = s.startswith("-")
    mag = s.lstrip("-")
    ip, _, fp = mag.partition(".")
    fp = fp.rstrip("0")
    n = int(ip or "0")
    if fp:
        frac = "point " + " ".join(_ONES[int(d)] for d in fp)
        out = frac if n == 0 and rng.uniform() < 0.35 else f"{int_words(rng, n)} {frac}"
    else:
        out = int_words(rng, n)
    if neg and (n or fp):
        out = _pick(rng, ("minus ", "minus ", "negative ")) + out
    return out


def is_plural(head: str) -> bool:
    """'drums', 'shelves' take plural verbs; 'glass', 'cactus', 'lens', 'chaise longue' do not."""
    last = head.split()[-1].lower()
    return (last.endswith("s") and not last.endswith(("ss", "us", "is"))
            and last not in ("lens", "gas", "canvas", "atlas", "bus"))


_PL = {"is": "are", "has": "have", "reads": "read"}


def _agree(verb: str, plural: bool) -> str:
    return _PL.get(verb, verb) if plural else verb


def _split(t: Target) -> tuple[list[str], list[str]]:
    """(modifiers said before the noun, states). The generator's phrase holds the modifiers and the head,
    never the states, so an attribute not in the phrase before the head is a state."""
    pre = f" {t.phrase[: -len(t.head)]} " if t.phrase.endswith(t.head) else f" {t.phrase} "
    mods, states = [], []
    for a in t.attributes:
        (states if a in STATES or f" {a} " not in pre else mods).append(a)
    return mods, states


def _body(mods: list[str], head: str, pre: list[str] = ()) -> str:
    return " ".join((*pre, *mods, head))


# ----------------------------------------------------------------------------------------------------
# Readings


_READING = {"temperature_c": ("temperature", "temp"), "humidity_pct": ("humidity",), "ndvi": ("ndvi",)}
_SUP_ADJ = {
    ("temperature_c", "max"): ("hottest", "warmest"),
    ("temperature_c", "min"): ("coldest", "coolest"),
    ("ndvi", "max"): ("healthiest", "greenest"),
    ("ndvi", "min"): ("least healthy", "unhealthiest"),
    ("humidity_pct", "max"): ("most humid", "dampest"),
    ("humidity_pct", "min"): ("driest", "least humid"),
}


def _sup_tails() -> dict[str, tuple[str, str]]:
    """Every superlative tail the sensor renderer writes -> (reading, comparator)."""
    out = {}
    for (rd, cmp_), adjs in _SUP_ADJ.items():
        ext = "highest" if cmp_ == "max" else "lowest"
        for a in adjs:
            out[f"that's the {a}"] = (rd, cmp_)
        for name in _READING[rd]:
            for lead in ("with the", "that has the"):
                out[f"{lead} {ext} {name}"] = (rd, cmp_)
            if rd == "humidity_pct":
                out[f"with the {'most' if cmp_ == 'max' else 'least'} humidity"] = (rd, cmp_)
    return out


_SUP_TAILS = _sup_tails()
_ADJ_INFO = {a: k for k, adjs in _SUP_ADJ.items() for a in adjs}

# Comparator phrases around an amount {a}; the flag: the phrase ends with the amount (so a noun can follow).
_CMP = {
    "gt": (("over {a}", True), ("above {a}", True), ("more than {a}", True), ("higher than {a}", True)),
    "ge": (("at least {a}", True), ("{a} or more", False), ("{a} or higher", False), ("{a} or above", False),
           ("no less than {a}", True), ("not less than {a}", True)),
    "lt": (("under {a}", True), ("below {a}", True), ("less than {a}", True), ("lower than {a}", True)),
    "le": (("at most {a}", True), ("{a} or less", False), ("{a} or lower", False), ("{a} or below", False),
           ("no more than {a}", True), ("not more than {a}", True)),
    "approx": (("about {a}", True), ("around {a}", True), ("roughly {a}", True), ("approximately {a}", True),
               ("{a} or so", False), ("more or less {a}", True)),
}
_COMPARATIVE = {("temperature_c", "gt"): ("hotter than", "warmer than"),
                ("temperature_c", "lt"): ("colder than", "cooler than")}


def _cmp(rng, cmp_: str, a: str, prefix_only: bool = False) -> str:
    opts = [f for f, pre in _CMP[cmp_] if pre or not prefix_only]
    return _pick(rng, opts).format(a=a)


def _temp_unit(rng) -> str:
    """A temperature unit after a number: 'degrees', 'degrees celsius', non-native 'degree'."""
    return _pick(rng, (" degrees", " degrees", " degrees", " degrees celsius", " degrees celsius", " degree"))


def render_sensor_dev5(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: a prefix adjective ('hottest') or a tail ('that's the hottest', 'with the lowest ndvi');
    thresholds: a tail starting 'that's ', 'that has ', 'with ' or 'whose '."""
    rd = c.reading
    if c.is_superlative:
        if rng.uniform() < 0.4:
            return _pick(rng, _SUP_ADJ[(rd, c.comparator)]), "", c
        tails = sorted(t for t, k in _SUP_TAILS.items() if k == (rd, c.comparator))
        return "", _pick(rng, tails), c
    vtxt = _fmt_value(rd, c.value)
    value = float(vtxt)
    num = spoken_number(rng, vtxt)
    cmp_ = c.comparator
    if rd == "temperature_c":
        unit = _temp_unit(rng)
        style = rng.uniform()
        if (rd, cmp_) in _COMPARATIVE and style < 0.25:  # "that's hotter than fifty (degrees)"
            u = unit if rng.uniform() < 0.6 else ""
            adj = _pick(rng, _COMPARATIVE[(rd, cmp_)])
            return "", f"that's {adj} {num}{u}", SensorConstraint(rd, cmp_, value, "c" if u else "")
        if style < 0.5:  # reading named, unit optional
            u = unit if rng.uniform() < 0.6 else ""
            name = _pick(rng, _READING[rd])
            if cmp_ == "approx" and rng.uniform() < 0.5:
                lead = _pick(rng, (f"with a {name} of", f"that has a {name} of"))
            else:
                lead = _pick(rng, (f"with a {name}", f"with the {name}", f"with {name}", f"whose {name} is",
                                   f"that has {name}"))
            return "", f"{lead} {_cmp(rng, cmp_, num + u)}", SensorConstraint(rd, cmp_, value, "c" if u else "")
        leads = ("that's", "that's reading", "that's at") if cmp_ == "approx" else ("that's", "that's reading")
        lead = _pick(rng, leads)
        return "", f"{lead} {_cmp(rng, cmp_, num + unit)}", SensorConstraint(rd, cmp_, value, "c")
    if rd == "humidity_pct":
        pct = _pick(rng, (" percent", " percent", " per cent")) if not num[-1].isdigit() or rng.uniform() < 0.6 \
            else "%"
        a = num + pct
        k = int(rng.integers(5))
        if k == 0:
            tail = f"that's {_cmp(rng, cmp_, a, prefix_only=True)} humidity"
        elif k == 1:
            tail = f"with {_cmp(rng, cmp_, a, prefix_only=True)} humidity"
        elif k == 2:
            tail = f"whose humidity is {_cmp(rng, cmp_, a)}"
        elif k == 3 and cmp_ == "approx":
            tail = f"that has a humidity of {_cmp(rng, cmp_, a)}"
        else:
            tail = f"{_pick(rng, ('with humidity', 'with the humidity', 'that has humidity'))} {_cmp(rng, cmp_, a)}"
        return "", tail, SensorConstraint(rd, cmp_, value, "%")
    name = _pick(rng, _READING[rd])
    k = int(rng.integers(4))
    if k == 0:
        tail = f"whose {name} is {_cmp(rng, cmp_, num)}"
    elif k == 1:
        tail = f"that has an {name} of {_cmp(rng, cmp_, num, prefix_only=True)}"
    elif k == 2:
        tail = f"with an {name} reading {_cmp(rng, cmp_, num)}"
    else:
        tail = f"{_pick(rng, (f'with an {name}', f'with {name}'))} {_cmp(rng, cmp_, num)}"
    return "", tail, SensorConstraint(rd, cmp_, value, "")


def _pred_of_tail(tail: str) -> tuple[str, str]:
    """A sensor tail as a predicate of the goal: 'that's over fifty' -> ('is', 'over fifty'), 'with X' ->
    ('has', 'X'), 'whose temp is X' -> ('whose', 'temp is X')."""
    for lead, verb in (("that's ", "is"), ("that has ", "has"), ("with ", "has"), ("whose ", "whose")):
        if tail.startswith(lead):
            return verb, tail[len(lead):]
    return "is", tail


# ----------------------------------------------------------------------------------------------------
# Coordinates


def hint_text_dev5(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y, spoken; every form starts with 'at' or
    'around', and the two numbers are always kept apart by 'y', 'comma' or 'and'."""
    digits_p = 0.0 if rng.uniform() < 0.7 else 1.0
    xs, ys = spoken_number(rng, x, digits_p), spoken_number(rng, y, digits_p)
    return _pick(rng, (
        f"at x {xs} y {ys}", f"at x {xs} and y {ys}", f"at x equals {xs} y equals {ys}", f"at {xs} comma {ys}",
        f"around x {xs} y {ys}", f"at position {xs} comma {ys}", f"at the position x {xs} and y {ys}",
        f"at coordinates {xs} and {ys}", f"around {xs} comma {ys}", f"at the point x {xs} y {ys}",
    ))


# ----------------------------------------------------------------------------------------------------
# Goals

_REL_REDUCED = {
    "near": ("near", "close to", "near to", "not far from"),
    "next_to": ("next to", "right next to"),
    "beside": ("beside",),
    "by": ("by", "right by"),
    "on": ("on", "on top of"),
    "under": ("under", "underneath", "beneath"),
    "above": ("above",),
    "in": ("in", "inside"),
    "in_room_with": ("in the same room as", "in the room with"),
    "in_front_of": ("in front of",),
    "behind": ("behind", "in back of"),
    "opposite": ("opposite", "across from", "facing"),
    "left_of": ("to the left of", "on the left of"),
    "right_of": ("to the right of", "on the right of"),
}


def _nested(t: Target) -> bool:
    return bool(t.relations)


def _anchor(rng, t: Target) -> str:
    """An anchor noun phrase. States go before the noun ('the switched on lamp') or into its own clause; an
    anchor's relations close it off: 'the sofa that's on the rug', 'whichever sofa is on the rug'."""
    mods, states = _split(t)
    plural = is_plural(t.head)
    pre = states if (t.relations or rng.uniform() < 0.75) else []
    post = [] if pre else states
    preds = [("is", s, False, False) for s in post] + [p[:4] for p in _rel_preds(rng, t.relations, plural)]
    if not preds:
        return "the " + _body(mods, t.head, pre)
    if (len(t.relations) == 1 and not post and preds[0][0] == "is" and not _nested(t.relations[0].anchor)
            and rng.uniform() < 0.4):
        return f"whichever {_body(mods, t.head, pre)} {_agree('is', plural)} {preds[0][1]}"
    return f"the {_body(mods, t.head, pre)} {_clause(rng, preds, plural, t.head)}"


def _rel_preds(rng, rels, plural: bool) -> list[tuple[str, str, bool, bool, str]]:
    """Relations as predicates (verb, rest, ends with an anchor, anchor has a clause, reduced text); anchors
    with clauses of their own last."""
    rels = sorted(rels, key=lambda r: _nested(r.anchor))
    out = []
    for r in rels:
        a = _anchor(rng, r.anchor)
        nested = _nested(r.anchor) or a.startswith("whichever") or " that" in a
        if r.type == "with":
            it = "them" if plural else "it"
            if nested:
                out.append(("has", f"on {it} or near {it} {a}", True, True, f"with {a}"))
            else:
                out.append(("has", f"{a} on {it} or near {it}", False, False, f"with {a}"))
        else:
            rest = f"{_pick(rng, _REL_REDUCED[r.type])} {a}"
            out.append(("is", rest, True, nested, rest))
    return out


def _clause(rng, preds, plural: bool, head: str) -> str:
    """'that's switched on and in the kitchen and is next to the sofa': a relative clause over the
    predicates (verb, rest, ends with an anchor, anchor has a clause), coordinated so that each one after an
    anchor names its verb again, and one after a clause-bearing anchor names the goal again."""
    verb, rest, after_anchor, closed = preds[0]
    if verb == "is":
        lead = _pick(rng, ("that are", "which are") if plural else ("that's", "that's", "that is", "which is"))
        s = f"{lead} {rest}"
    elif verb == "whose":
        s = f"whose {rest}"
    else:
        s = f"{_pick(rng, ('that', 'which'))} {_agree(verb, plural)} {rest}"
    prev = verb
    for verb, rest, ends_anchor, nested in preds[1:]:
        if closed:
            if verb == "is":
                s += f" and the same {head} {_agree('is', plural)} also {rest}"
            else:
                s += f" and the same {head} also {_agree(verb, plural)} {rest}"
        elif verb == "whose":
            s += f" and whose {rest}"
        elif verb == "is" and prev == "is" and not after_anchor and rng.uniform() < 0.6:
            s += f" and {rest}"
        else:
            s += f" and {_agree(verb, plural)} {rest}"
        prev, after_anchor, closed = verb, ends_anchor, closed or nested
    return s


def render_goal_dev5(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "",
                         hint: str = "") -> str:
    """'the teal guitar in the music room', 'the amplifier that's switched on and is next to the harp', 'the
    hottest amplifier in the workshop', 'whichever amplifier in the workshop has the highest temp', 'the heater
    that's in the pantry and is over fifty degrees', 'the guitar at x three y two'."""
    t = sg.target
    mods, states = _split(t)
    plural = is_plural(t.head)
    sup = _ADJ_INFO.get(prefix) if prefix else _SUP_TAILS.get(tail)
    if prefix and sup is None:  # an adjective this set does not know: still said before the noun
        sup = ("", "")
    pre, post = [], list(states)
    if states and all(s in _PRE_STATES for s in states) and rng.uniform() < 0.4:
        pre, post = list(states), []
    # (verb, rest, ends with an anchor, anchor has a clause) + the reduced text where one exists
    preds: list[tuple[str, str, bool, bool]] = [("is", s, False, False) for s in post]
    reduced: list[str | None] = [None] * len(post)
    if sg.room:
        preds.append(("is", f"in the {sg.room}", False, False))
        reduced.append(f"in the {sg.room}")
    if hint:
        preds.append(("is", hint, False, False))
        reduced.append(hint)
    if tail and sup is None:
        preds.append((*_pred_of_tail(tail), False, False))
        reduced.append(None)
    rel = _rel_preds(rng, t.relations, plural)
    preds += [p[:4] for p in rel]
    reduced += [p[4] for p in rel]
    with_after_room = sg.room is not None and any(r.type == "with" for r in t.relations)
    can_reduce = all(x is not None for x in reduced) and len(t.relations) <= 1 and not with_after_room

    if sup is not None:
        adjs = _SUP_ADJ.get(sup, (prefix,))
        adj = prefix or _pick(rng, adjs)
        simple_scope = can_reduce and not any(p[3] for p in rel) and not hint
        if not preds and tail and rng.uniform() < 0.5:
            return f"the {_body(mods, t.head, pre)} {_agree_tail(tail, plural)}"
        use_which = simple_scope and rng.uniform() < (0.3 if prefix else 0.6)
        if use_which:
            if tail and not prefix:
                verb, rest = _pred_of_tail(tail)
            else:
                verb, rest = "is", f"the {adj}"
            scope = " ".join(x for x in reduced if x)
            scope = f" {scope}" if scope else ""
            return f"whichever {_body(mods, t.head, pre)}{scope} {_agree(verb, plural)} {rest}"
        np_ = f"the {adj} {_body(mods, t.head, pre)}"
    else:
        np_ = f"the {_body(mods, t.head, pre)}"
    if not preds:
        return np_
    if can_reduce and rng.uniform() < 0.55:
        return f"{np_} {' '.join(reduced)}"
    if len(preds) == 1 and not rel and sup is None and rng.uniform() < 0.25:  # "the guitar the one in the ..."
        verb, rest = preds[0][:2]
        one = _pick(rng, ("the one", "you know the one"))
        if reduced[0] is not None and rng.uniform() < 0.5:
            return f"{np_} {one} {reduced[0]}"
        if verb == "is":
            return f"{np_} {one} that's {rest}"
        if verb == "whose":
            return f"{np_} {one} whose {rest}"
        return f"{np_} {one} that {verb} {rest}"
    return f"{np_} {_clause(rng, preds, plural, t.head)}"


def _agree_tail(tail: str, plural: bool) -> str:
    if plural and tail.startswith("that's "):
        return "that are " + tail[len("that's "):]
    if plural and tail.startswith("that has "):
        return "that have " + tail[len("that has "):]
    return tail


# ----------------------------------------------------------------------------------------------------
# Instructions

_OPEN = ("", "", "", "um ", "uh ", "okay so ", "alright ", "alright so ", "hey robot ", "so um ", "okay um ")
_ASK = ("", "", "", "can you ", "could you ", "i want you to ", "i need you to ", "please ", "i'd like you to ")
_VERBS = ("go to", "go to", "go check", "go and check", "check", "check on", "head to", "head over to", "swing by",
          "go over to", "find", "visit", "take a look at", "stop at", "get to", "look at")
_THEN = ("and then", "and then", "and then um", "and after that", "so then", "then", "and then uh",
         "after that", "and when you're done there")
_FREE_TAIL = ("doesn't matter which one first", "in any order you want", "any order is fine",
              "the order doesn't matter", "in whatever order is easier", "you can pick the order",
              "order doesn't matter", "in any order")
_FREE_HEAD = ("in any order you want", "doesn't matter the order", "in any order", "okay so in any order")
_NUM_END = set(_ONES) | set(_TENS[2:]) | {"hundred", "point"}


def _ends_with_number(g: str) -> bool:
    last = g.split()[-1]
    return last in _NUM_END or last[-1].isdigit()


def _busy(res: list[str]) -> bool:
    """Whether a bare 'A and B' could be misread: some goal but the last names a room, an anchor, a second
    clause or a number of its own."""
    return any(" the " in g[4:] or " and " in g or "whichever" in g or _ends_with_number(g) for g in res[:-1])


def _speech(rng, res: list[str], order: str) -> str:
    v = lambda: _pick(rng, _VERBS)  # noqa: E731
    like = lambda: "like " if rng.uniform() < 0.1 else ""  # noqa: E731
    op, ask = _pick(rng, _OPEN), _pick(rng, _ASK)
    n = len(res)
    if n == 1:
        return f"{op}{ask}{v()} {res[0]}"
    if order == "free":
        busy = _busy(res)
        if busy or rng.uniform() < 0.4:
            lst = f" and {like()}".join(f"{v()} {g}" for g in res)
            k = int(rng.integers(3))
            if k == 0:
                return f"{op}{ask}{lst} {_pick(rng, _FREE_TAIL)}"
            if k == 1:
                return f"{op}{_pick(rng, _FREE_HEAD)} {lst}"
            return f"{op}{ask}{lst} you know {_pick(rng, ('in any order you want', 'whatever order'))}"
        lst = " and ".join(res)
        k = int(rng.integers(2))
        if k == 0:
            return f"{op}{ask}{v()} {lst} {_pick(rng, _FREE_TAIL)}"
        return f"{op}{_pick(rng, _FREE_HEAD)} {v()} {lst}"
    k = int(rng.integers(6))
    if k == 0:  # "go to A and then B and after that go to C"
        s = f"{op}{ask}{v()} {res[0]}"
        for g in res[1:]:
            s += f" {_pick(rng, _THEN)} {like()}{v() + ' ' if rng.uniform() < 0.6 else ''}{g}"
        return s
    if k == 1:  # "first go to A then B and finally C"
        s = f"{op}first {v()} {res[0]}"
        for g in res[1:-1]:
            s += f" {_pick(rng, _THEN)} {v()} {g}"
        return s + f" {_pick(rng, ('and then finally', 'and last', 'and finally'))} {v()} {res[-1]}"
    if k == 2 and not _ends_with_number(res[0]):  # "go to A first and then B"
        s = f"{op}{ask}{v()} {res[0]} first"
        for g in res[1:]:
            s += f" {_pick(rng, _THEN)} {v()} {g}"
        return s
    if k == 3:  # "step one go to A step two check B"
        steps = " ".join(f"step {_ONES[i + 1]} {v()} {g}" for i, g in enumerate(res))
        return f"{op or _pick(rng, ('okay so ', 'alright ', ''))}do this in order {steps}"
    if k == 4:  # "start with A and then B and finish at C"
        mid = "".join(f" {_pick(rng, _THEN)} {v()} {g}" for g in res[1:-1])
        return f"{op}start with {res[0]}{mid} and {_pick(rng, ('finish at', 'end with', 'finish with'))} {res[-1]}"
    # "after you go to A go to B and after that C"
    s = f"{op}after you {_pick(rng, ('go to', 'check', 'visit'))} {res[0]} {v()} {res[1]}"
    for g in res[2:]:
        s += f" {_pick(rng, ('and after that', 'and then'))} {v()} {g}"
    return s


_NN_VERBS = ("go to", "go and check", "please go to", "please go and check", "visit", "check", "go and see",
             "find")


_NN_FREE = ("Order is not important.", "You can choose the order.", "Any order is ok.", "The order does not matter.",
            "Do it in any order you want.")


def _cap(s: str) -> str:
    return s[0].upper() + s[1:]


def _nonnative(rng, res: list[str], order: str) -> str:
    """Typed by a non-native speaker: short present-tense sentences with capitals and stops."""
    v = lambda: _pick(rng, _NN_VERBS)  # noqa: E731
    n = len(res)
    if n == 1:
        return _cap(f"{_pick(rng, ('', 'hello, ', 'robot, '))}{v()} {res[0]}.")
    if order == "free":
        busy = _busy(res)
        if busy:
            body = ". ".join(_cap(f"{_pick(rng, ('', 'also ', 'and '))}{v()} {g}") if i else _cap(f"{v()} {g}")
                             for i, g in enumerate(res))
        else:
            body = _cap(f"{v()} {', '.join(res[:-1])} and {res[-1]}")
        return f"{body}. {_pick(rng, _NN_FREE)}"
    k = int(rng.integers(4))
    if k == 0:
        s = _cap(f"first {v()} {res[0]}.")
        for g in res[1:-1]:
            s += " " + _cap(f"{_pick(rng, ('after that', 'then'))} you {_pick(rng, ('go to', 'check', 'visit'))} {g}.")
        end = _pick(rng, ("at the end", "in the end", "last"))
        s += " " + _cap(f"{end} you {_pick(rng, ('go to', 'check', 'visit'))} {res[-1]}.")
        return s
    if k == 1:
        s = _cap(f"after you go to {res[0]}, {v()} {res[1]}.")
        for g in res[2:]:
            s += " " + _cap(f"after that {v()} {g}.")
        return s
    if k == 2:
        s = _cap(f"you go to {res[0]}")
        for g in res[1:]:
            s += f", then you {_pick(rng, ('go to', 'check', 'visit'))} {g}"
        return s + ". " + _pick(rng, ("Please follow this order.", "Please keep this order.", "In this order please."))
    s = _cap(f"{v()} {res[0]}.")
    for g in res[1:]:
        s += " " + _cap(f"{_pick(rng, ('then', 'after that', 'next'))} {v()} {g}.")
    return s


def render_instruction_dev5(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals: a speech-recognition transcript (lower case, no punctuation,
    fillers) or a message typed by a non-native speaker; strict texts state the order, free ones that it is
    open."""
    if rng.uniform() < 0.65:
        return " ".join(_speech(rng, res, order).split())
    return _nonnative(rng, res, order)
