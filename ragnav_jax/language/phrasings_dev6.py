"""Sixth development phrasings: goal, sensor, coordinate and instruction templates (`unseen_dev6` split).

Written without reading the rule parser as the held-out set after parser round 6 (which parsed 15 / 192 of
its instructions on the test houses); parser round 7 was then developed against it. Beside the other sets:
the same four functions, arguments and meanings,
written by a fourth author who never read the rule parser. The style is written task notes and formal
requests, as a facility manager, a care worker or a researcher would leave them for a robot:

- instructions: complete sentences, task lists separated by semicolons and introduced by colons
  ("Task note: firstly, proceed to ...; secondly, inspect ...; finally, attend to ..."), numbered or lettered
  items ("(1) ...; (2) ...", "(a) ...; (b) ..."), formal verbs ("proceed to", "inspect", "locate", "attend to",
  "verify the condition of", "report to"), passive and impersonal forms ("in the first instance, the heater
  located in the kitchen is to be inspected", "it is requested that the robot visit ..."), purpose clauses
  and remarks that add no constraint (", in order to carry out a visual check", "(for the maintenance log)");
  strict order as "firstly ..., secondly ..., finally ...", "subsequently", "thereafter", "upon completion",
  "prior to", "in the order given"; free order as "the order of the visits is at the robot's discretion",
  "in an order of its choosing", "the sequence is not prescribed". Goals are always written in visiting order
  and never begin a sentence, so each goal's text appears verbatim.
- goals: restrictive relative clauses with "which"/"that"/"whose"/"where" ("the heater which is switched on and
  is located in the kitchen", "the heater whose temperature exceeds 50 °C and which is situated in the
  pantry", "the lamp located in the room where the grey sofa stands"), brackets and appositions ("the heater
  (the one located in the kitchen)", "the heater, namely the one in the kitchen"). Anchors come last, and an
  anchor carrying a clause of its own closes the goal; when two such anchors are needed the predicates are
  enumerated ("which (i) stands next to the sofa that is on the rug and (ii) is under the shelf that is by
  the door"), so nothing can attach to the wrong noun.
- numbers with formal units ("22.5 °C", "a relative humidity of 40 %", "an NDVI value of 0.30", "a temperature
  not exceeding 60 degrees Celsius", "a temperature in excess of 30 °C"); coordinates written formally ("at
  coordinates x = 3.50 m, y = 2.00 m", "at position (3.5 m, 2.0 m)", "at the location x: 3.5, y: 2");
  superlatives mostly formal, their scope stated ("the heater exhibiting the highest temperature", "the plant
  with the lowest NDVI value among those in the conservatory"), sometimes an adjective ("the warmest heater").

Every draw comes from the NumPy generator passed in, so a seed gives the same text.
"""

from __future__ import annotations

import re

import numpy as np

from ragnav_jax.language.episodes import _fmt_value, _pick
from ragnav_jax.language.types import SensorConstraint, Subgoal, Target

# ----------------------------------------------------------------------------------------------------
# Sensor phrases

_READING_NP = {  # the reading as a noun phrase with its article ("with" / "exhibiting" forms)
    "temperature_c": ("a temperature", "a measured temperature", "a recorded temperature"),
    "humidity_pct": ("a relative humidity", "a humidity level", "a relative humidity reading"),
    "ndvi": ("an NDVI value", "an NDVI reading", "a normalised difference vegetation index (NDVI)"),
}
_READING_WHOSE = {  # ... and after "whose"
    "temperature_c": ("temperature", "measured temperature", "recorded temperature"),
    "humidity_pct": ("relative humidity", "humidity level"),
    "ndvi": ("NDVI value", "NDVI reading", "normalised difference vegetation index (NDVI)"),
}
_READING_EXTREME = {"temperature_c": ("temperature", "recorded temperature"),
                    "humidity_pct": ("relative humidity", "humidity level"),
                    "ndvi": ("NDVI value", "NDVI reading")}
# Noun-phrase forms: "{n}" the reading, "{v}" the value with its unit.
_NP_FORMS = {
    "gt": ("{n} greater than {v}", "{n} in excess of {v}", "{n} exceeding {v}", "{n} above {v}",
           "{n} higher than {v}"),
    "ge": ("{n} of at least {v}", "{n} of no less than {v}", "{n} of {v} or more", "{n} not below {v}"),
    "lt": ("{n} below {v}", "{n} less than {v}", "{n} lower than {v}", "{n} of less than {v}"),
    "le": ("{n} not exceeding {v}", "{n} of at most {v}", "{n} of no more than {v}", "{n} of {v} or less"),
    "approx": ("{n} of approximately {v}", "{n} of about {v}", "{n} in the region of {v}", "{n} of roughly {v}"),
}
# "whose {n} ..." forms.
_WHOSE_FORMS = {
    "gt": ("exceeds {v}", "is greater than {v}", "is in excess of {v}", "is above {v}"),
    "ge": ("is at least {v}", "does not fall below {v}", "is no less than {v}", "is {v} or more"),
    "lt": ("is below {v}", "is less than {v}", "does not reach {v}", "is lower than {v}"),
    "le": ("does not exceed {v}", "is at most {v}", "is no greater than {v}", "is {v} or less"),
    "approx": ("is approximately {v}", "is about {v}", "is in the region of {v}", "is roughly {v}"),
}
_LEADS = ("with", "with", "exhibiting", "registering", "showing")
_SUPER_ADJ = {("temperature_c", "max"): ("warmest", "hottest"), ("temperature_c", "min"): ("coldest", "coolest"),
              ("humidity_pct", "max"): ("most humid",), ("humidity_pct", "min"): ("least humid", "driest")}


def _unit(rng, reading: str) -> tuple[str, str]:
    """(text after the number, unit code)."""
    if reading == "temperature_c":
        return _pick(rng, ((" °C", "c"), (" °C", "c"), ("°C", "c"), (" degrees Celsius", "c")))
    if reading == "humidity_pct":
        return _pick(rng, ((" %", "%"), ("%", "%"), (" per cent", "%"), (" percent", "%")))
    return "", ""


def _value_text(rng, reading: str, v: float) -> str:
    """The number as a formal writer puts it ('0.30', '60.0', '22.5'); it always denotes the same value."""
    v = 0.0 if v == 0 else float(v)
    plain = _fmt_value(reading, v)
    opts = [plain]
    if reading == "ndvi" and float(f"{v:.2f}") == float(plain):
        opts += [f"{v:.2f}", f"{v:.2f}"]
    if reading != "ndvi" and float(plain).is_integer() and abs(v) < 1000:
        opts.append(f"{float(plain):.1f}")
    return _pick(rng, opts)


def render_sensor_dev6(rng: np.random.Generator, c: SensorConstraint) -> tuple[str, str, SensorConstraint]:
    """(prefix adjective before the noun or '', phrase after the noun or '', the constraint exactly as written).

    Superlatives: mostly a tail ('exhibiting the highest temperature', 'with the lowest NDVI value', 'whose
    relative humidity is the highest'), sometimes an adjective ('warmest'; never for NDVI). Thresholds and
    approximate values: a tail starting 'with ', 'exhibiting ', 'registering ', 'showing ' or 'whose ', the
    value in digits with a formal unit ('a temperature in excess of 30 °C', 'whose relative humidity is
    approximately 40 %', 'an NDVI value of at least 0.30').
    """
    rd = c.reading
    if c.is_superlative:
        ext = "highest" if c.comparator == "max" else "lowest"
        adj = _SUPER_ADJ.get((rd, c.comparator))
        if adj and rng.uniform() < 0.25:
            return _pick(rng, adj), "", SensorConstraint(rd, c.comparator)
        name = _pick(rng, _READING_EXTREME[rd])
        tail = _pick(rng, (f"exhibiting the {ext} {name}", f"with the {ext} {name}", f"registering the {ext} {name}",
                           f"whose {name} is the {ext}"))
        return "", tail, SensorConstraint(rd, c.comparator)
    vtxt = _value_text(rng, rd, c.value)
    unit, code = _unit(rng, rd)
    v = vtxt + unit
    if rng.uniform() < 0.35:
        tail = f"whose {_pick(rng, _READING_WHOSE[rd])} " + _pick(rng, _WHOSE_FORMS[c.comparator]).format(v=v)
    else:
        tail = f"{_pick(rng, _LEADS)} " + _pick(rng, _NP_FORMS[c.comparator]).format(n=_pick(rng, _READING_NP[rd]), v=v)
    return "", tail, SensorConstraint(rd, c.comparator, float(vtxt), code)


# ----------------------------------------------------------------------------------------------------
# Coordinate hints


def _coord(rng, s: str) -> str:
    v = float(s)
    if v == 0:
        return _pick(rng, ("0", "0.0", "0.00"))
    opts = [s] + [t for t in (f"{v:.1f}", f"{v:.2f}", f"{v:g}") if float(t) == v]
    return _pick(rng, opts)


def hint_text_dev6(rng: np.random.Generator, x: str, y: str) -> str:
    """A coordinate hint in the scene frame (metres), x then y, written formally; every form starts with 'at'
    and keeps the two numbers apart ('at coordinates x = 3.50 m, y = 2.00 m', 'at position (3.5 m, 2.0 m)',
    'at the location x: 3.5, y: 2')."""
    X, Y = _coord(rng, x), _coord(rng, y)
    m = _pick(rng, (" m", " m", ""))
    return _pick(rng, (
        f"at coordinates x = {X}{m}, y = {Y}{m}",
        f"at position ({X}{m}, {Y}{m})",
        f"at the location x: {X}, y: {Y}",
        f"at the coordinates (x, y) = ({X}, {Y})",
        f"at the point x = {X}{m}, y = {Y}{m}",
        f"at x = {X}{m} and y = {Y}{m}",
        f"at map position ({X}, {Y})",
        f"at the position given by x = {X}{m} and y = {Y}{m}",
        f"at coordinates ({X}{m}, {Y}{m})",
    ))


# ----------------------------------------------------------------------------------------------------
# Goals

# Relation words after a noun ("the lamp next to the sofa") and as a predicate ("which stands next to ...").
_REL_COMPACT = {
    "near": ("near", "close to", "in the vicinity of", "in close proximity to", "located near"),
    "next_to": ("next to", "alongside", "situated next to", "positioned next to"),
    "beside": ("beside", "situated beside", "placed beside"),
    "by": ("by", "located by", "positioned by"),
    "on": ("on", "on top of", "resting on", "placed on", "sitting on"),
    "under": ("under", "beneath", "below", "underneath", "situated under"),
    "above": ("above", "positioned above", "situated above"),
    "in": ("in", "inside", "contained in", "placed inside"),
    "with": ("with",),
    "in_room_with": ("in the same room as", "in the room with", "located in the same room as"),
    "in_front_of": ("in front of", "positioned in front of", "situated in front of"),
    "behind": ("behind", "situated behind", "positioned behind"),
    "opposite": ("opposite", "across from", "facing", "situated opposite"),
    "left_of": ("to the left of", "on the left-hand side of", "positioned to the left of"),
    "right_of": ("to the right of", "on the right-hand side of", "positioned to the right of"),
}
_REL_VP = {
    "near": ("is near", "is located near", "stands close to", "is situated in the vicinity of",
             "is in close proximity to"),
    "next_to": ("is next to", "stands next to", "is positioned next to", "is located alongside"),
    "beside": ("is beside", "stands beside", "is situated beside"),
    "by": ("is by", "is located by", "is positioned by"),
    "on": ("is on", "rests on", "is placed on", "is on top of", "sits on"),
    "under": ("is under", "is located beneath", "is situated below", "is placed underneath"),
    "above": ("is above", "is positioned above", "is situated above"),
    "in": ("is in", "is inside", "is contained in", "is placed inside"),
    "with": ("is the one with",),
    "in_room_with": ("is in the same room as", "is located in the same room as", "is in the room with"),
    "in_front_of": ("is in front of", "stands in front of", "is positioned in front of"),
    "behind": ("is behind", "stands behind", "is located behind"),
    "opposite": ("is opposite", "stands opposite", "is situated across from", "faces"),
    "left_of": ("is to the left of", "stands to the left of", "is on the left-hand side of"),
    "right_of": ("is to the right of", "stands to the right of", "is on the right-hand side of"),
}
_PLURAL_VERB = {"is": "are", "has": "have", "stands": "stand", "rests": "rest", "sits": "sit", "faces": "face",
                "exhibits": "exhibit", "registers": "register", "shows": "show"}
_TAIL_VERB = {"with": "has", "exhibiting": "exhibits", "registering": "registers", "showing": "shows"}
_MARKS = ("i", "ii", "iii", "iv", "v", "vi", "vii", "viii")


def _is_plural(head: str) -> bool:
    w = head.split()[-1]
    return w.endswith("s") and not w.endswith(("ss", "us", "is"))


def _agree(vp: str, plural: bool) -> str:
    if not plural:
        return vp
    w, _, rest = vp.partition(" ")
    return (_PLURAL_VERB.get(w, w) + (" " + rest if rest else "")).replace("is the one with", "are the ones with") \
        .replace("are the one with", "are the ones with")


def _split_attrs(t: Target) -> tuple[list[str], list[str]]:
    """(modifiers written in the phrase before the head, states written around it)."""
    words, hw = t.phrase.split(), t.head.split()
    pre = set(words[: len(words) - len(hw)] if words[-len(hw):] == hw else words)
    mods = [a for a in t.attributes if all(w in pre for w in a.split())]
    return mods, [a for a in t.attributes if a not in mods]


class _Item:
    """One restriction of a noun: a predicate after 'which'/'that' (vp, singular), a compact form after the
    noun (or None), a 'whose' clause, and whether it ends in a noun carrying a clause of its own."""

    def __init__(self, kind: str, vp: str | None = None, compact: str | None = None, whose: str | None = None,
                 bearing: bool = False):
        self.kind, self.vp, self.compact, self.whose, self.bearing = kind, vp, compact, whose, bearing


def _np(rng, t: Target, depth: int) -> tuple[str, bool]:
    """An anchor noun phrase and whether it carries a clause ('the sofa that is on the rug')."""
    states = _split_attrs(t)[1]
    pre = [s for s in states if " " not in s and rng.uniform() < 0.5]
    post = [s for s in states if s not in pre]
    items = _state_items(rng, post) + _relation_items(rng, t, depth)
    head = "the " + "".join(f"{s} " for s in pre) + t.phrase
    if not items:
        return head, False
    pl = _is_plural(t.head)
    return f"{head} {_pick(rng, ('that', 'which'))} {_join_vps(rng, items, pl, depth)}", True


def _state_items(rng, states: list[str]) -> list[_Item]:
    if not states:
        return []
    return [_Item("state", _pick(rng, ("is ", "is ", "is currently ")) + " and ".join(states))]


def _relation_items(rng, t: Target, depth: int) -> list[_Item]:
    out = []
    for r in t.relations:
        a, bearing = _np(rng, r.anchor, depth + 1)
        if r.type == "in_room_with" and not bearing and rng.uniform() < 0.3:
            aux = _agree(_pick(rng, ("stands", "is located", "is situated")), _is_plural(r.anchor.head))
            out.append(_Item("rel", f"is located in the room where {a} {aux}", f"in the room where {a} {aux}",
                             bearing=True))
            continue
        out.append(_Item("rel", f"{_pick(rng, _REL_VP[r.type])} {a}", f"{_pick(rng, _REL_COMPACT[r.type])} {a}",
                         bearing=bearing))
    out.sort(key=lambda i: i.bearing)  # a clause-bearing anchor closes the clause
    return out


def _join_vps(rng, items: list[_Item], plural: bool, depth: int) -> str:
    """'is switched on, is located in the kitchen and stands next to the sofa'; with two or more clause-bearing
    anchors, enumerated: '(i) stands next to the sofa that is on the rug and (ii) is under the shelf ...'."""
    vps = [_agree(i.vp, plural) for i in items]
    if sum(i.bearing for i in items) >= 2 or (len(vps) >= 3 and any("," in v for v in vps)):
        marks = _MARKS if depth == 0 else tuple(m.upper() for m in _MARKS)
        vps = [f"({marks[k % len(marks)]}) {v}" for k, v in enumerate(vps)]
    if len(vps) == 1:
        return vps[0]
    return ", ".join(vps[:-1]) + " and " + vps[-1]


def _clause(rng, items: list[_Item], plural: bool) -> str:
    """A restrictive relative clause over the items; a 'whose' clause comes first."""
    whose = [i.whose for i in items if i.whose]
    rest = [i for i in items if not i.whose]
    if not rest:
        return " and ".join(whose)
    if whose:
        body = _join_vps(rng, rest, plural, 0)
        sep = " and which " if len(rest) == 1 else ", and which "
        return " and ".join(whose) + sep + body
    return f"{_pick(rng, ('which', 'that', 'which'))} {_join_vps(rng, rest, plural, 0)}"


def _sensor_item(tail: str) -> _Item:
    if tail.startswith("whose "):
        return _Item("sensor", compact=tail, whose=tail)
    w, _, rest = tail.partition(" ")
    if w in _TAIL_VERB:
        return _Item("sensor", f"{_TAIL_VERB[w]} {rest}", tail)
    return _Item("sensor", f"is {tail}", tail)  # another author's tail ('at about 60 degrees')


def render_goal_dev6(rng: np.random.Generator, sg: Subgoal, prefix: str = "", tail: str = "",
                         hint: str = "") -> str:
    """'the heater located in the kitchen', 'the lamp which is switched on and stands next to the grey sofa',
    'the heater whose temperature exceeds 50 °C and which is situated in the pantry', 'the plant with the lowest
    NDVI value among those in the conservatory', 'the warmest heater in the kitchen', 'the heater (the one
    located at coordinates x = 3.50 m, y = 2.00 m)'. Anchors come last; the scope of a superlative is stated
    ('among those ...') or is the whole noun phrase after the adjective."""
    t = sg.target
    plural = _is_plural(t.head)
    states = _split_attrs(t)[1]
    pre = [s for s in states if " " not in s and rng.uniform() < 0.5]
    post = [s for s in states if s not in pre]
    head = "the " + (f"{prefix} " if prefix else "") + "".join(f"{s} " for s in pre) + t.phrase

    items: list[_Item] = _state_items(rng, post)
    if sg.room:
        room = sg.room
        items.append(_Item("room", _pick(rng, (f"is located in the {room}", f"is situated in the {room}",
                                              f"is in the {room}", f"is to be found in the {room}")),
                           _pick(rng, (f"in the {room}", f"in the {room}", f"located in the {room}",
                                       f"situated in the {room}"))))
    if hint:
        verb = "positioned" if "position" not in hint else "located"
        items.append(_Item("hint", f"{_pick(rng, ('is to be found', f'is {verb}', 'is situated'))} {hint}",
                           _pick(rng, (hint, hint, f"situated {hint}", f"{verb} {hint}"))))
    superlative = bool(tail) and bool(re.search(r"\b(highest|lowest)\b", tail))
    if tail and not superlative:
        items.append(_sensor_item(tail))
    rng.shuffle(items)
    items.sort(key=lambda i: i.whose is None)  # 'whose' first
    items += _relation_items(rng, t, 0)

    if superlative:
        text = f"{head} {tail}"
        if not items:
            return text
        if len(items) == 1 and items[0].compact and rng.uniform() < 0.5:
            return f"{text} among those {items[0].compact}"
        return f"{text} among those {_clause(rng, items, True)}"
    if not items:
        return head
    if len(items) == 1 and items[0].compact:
        k = rng.uniform()
        one = "the ones" if plural else "the one"
        if k < 0.45:
            return f"{head} {items[0].compact}"
        if k < 0.6 and not prefix:
            return f"{head} ({one} {items[0].compact})"
        if k < 0.7 and not prefix:
            return f"{head}, namely {one} {items[0].compact}"
    return f"{head} {_clause(rng, items, plural)}"


# ----------------------------------------------------------------------------------------------------
# Instructions

# (base form, gerund, past participle for the passive or None)
_VERBS = (
    ("proceed to", "proceeding to", None),
    ("proceed to", "proceeding to", None),
    ("inspect", "inspecting", "inspected"),
    ("inspect", "inspecting", "inspected"),
    ("visit", "visiting", "visited"),
    ("locate", "locating", None),
    ("attend to", "attending to", "attended to"),
    ("verify the condition of", "verifying the condition of", None),
    ("examine", "examining", "examined"),
    ("navigate to", "navigating to", None),
    ("report to", "reporting to", None),
    ("check", "checking", "checked"),
)
_PASSIVE = tuple(v for v in _VERBS if v[2])
_ORDINALS = ("firstly", "secondly", "thirdly", "fourthly", "fifthly", "sixthly", "seventhly", "eighthly")
_HEADERS = ("", "", "", "", "task note: ", "request: ", "note for the robot: ", "maintenance request: ",
            "care round: ", "instructions: ")
_PURPOSE = (", in order to carry out a visual check", ", for the purpose of a routine inspection",
            ", for inspection purposes", ", so that a visual check can be carried out",
            " (for the maintenance log)", " (this forms part of the weekly safety round)",
            " (no intervention is required)")
_CLOSINGS = ("", "", "", "", " Any irregularities should be noted in the log.", " Thank you.",
             " No further action is required.")
_REQUEST = ("please ", "kindly ", "the robot is requested to ", "the robot should ", "it is requested that the robot ",
            "the robot is asked to ")


def _v(rng) -> tuple[str, str, str | None]:
    return _VERBS[int(rng.integers(len(_VERBS)))]


def _purpose(rng, p: float = 0.15) -> str:
    return _pick(rng, _PURPOSE) if rng.uniform() < p else ""


def _passive_ok(g: str) -> bool:
    """A goal may be the subject of a passive sentence when it carries no clause ('... that is on the rug is to
    be inspected' would read as the rug's)."""
    return not re.search(r"\b(which|that|whose|where|among)\b|\(i\)|,", g)


def _finish(rng, s: str) -> str:
    s = s.strip()
    if not s.endswith("."):
        s += "."
    s = s[0].upper() + s[1:] + _pick(rng, _CLOSINGS)
    return s


def _semi_list(rng, items: list[str]) -> str:
    """'A; B; and C' (semicolons: goals may hold commas)."""
    if len(items) == 1:
        return items[0]
    return "; ".join(items[:-1]) + (_pick(rng, ("; ", "; and ")) if len(items) > 2 else "; ") + items[-1]


def render_instruction_dev6(rng: np.random.Generator, res: list[str], order: str) -> str:
    """A whole instruction over rendered goals, as a written task note or formal request: strict texts state the
    visiting order ('firstly ...; secondly ...; finally ...', 'in the order given: (1) ...; (2) ...', 'prior
    to', 'upon completion', 'thereafter'), free ones that it is open ('in an order of its choosing', 'the order
    of the visits is at the robot's discretion', 'the sequence is not prescribed'). Goals are written in the
    order given, verbatim, never at the start of a sentence."""
    n = len(res)
    hdr = _pick(rng, _HEADERS)
    if n == 1:
        g = res[0]
        k = int(rng.integers(6))
        if k == 5 and _passive_ok(g):
            return _finish(rng, f"{hdr or 'request: '}{g} is to be {_pick(rng, _PASSIVE)[2]}{_purpose(rng, 0.3)}")
        if k >= 4:
            return _finish(rng, f"{hdr}{_pick(rng, _REQUEST)}{_v(rng)[0]} {g}{_purpose(rng, 0.3)}")
        return _finish(rng, f"{hdr}{_pick(rng, _REQUEST[:2])}{_v(rng)[0]} {g}{_purpose(rng, 0.3)}")
    if order == "free":
        return _free(rng, res, hdr)
    return _strict(rng, res, hdr)


def _strict(rng, res: list[str], hdr: str) -> str:
    n = len(res)
    k = int(rng.integers(8))
    if k == 3 and not all(_passive_ok(g) for g in res):
        k = 0
    if k == 0:  # firstly ...; secondly ...; finally ...
        last = _pick(rng, ("finally", "lastly", None))
        parts = [f"{(last if i == n - 1 and last else _ORDINALS[i])}, {_v(rng)[0]} {g}{_purpose(rng)}"
                 for i, g in enumerate(res)]
        return _finish(rng, hdr + "; ".join(parts))
    if k == 1:  # the robot is requested to A and, upon completion, to B; thereafter, it should C
        s = f"the robot is requested to {_v(rng)[0]} {res[0]} and, upon completion, to {_v(rng)[0]} {res[1]}"
        for i, g in enumerate(res[2:], start=2):
            adv = "finally" if i == n - 1 and rng.uniform() < 0.5 else _pick(rng, ("thereafter", "subsequently"))
            s += f"; {adv}, it should {_v(rng)[0]} {g}"
        return _finish(rng, hdr + s)
    if k == 2:  # ... in the order given: (1) A; (2) B
        lead = _pick(rng, ("it is requested that the robot ", "the robot is requested to ", "please "))
        when = _pick(rng, ("in the order given", "in the sequence listed", "in the following order"))
        verb = _pick(rng, ("visit", "attend to", "inspect", "proceed to"))
        lst = "; ".join(f"({i + 1}) {g}" for i, g in enumerate(res))
        return _finish(rng, f"{hdr}{lead}{verb} the following, {when}: {lst}")
    if k == 3:  # passive: in the first instance, A is to be inspected; subsequently, B is to be visited
        parts = [f"in the first instance, {res[0]} is to be {_pick(rng, _PASSIVE)[2]}"]
        for i, g in enumerate(res[1:], start=1):
            adv = _pick(rng, ("finally", "lastly")) if i == n - 1 else _pick(rng, ("subsequently", "thereafter"))
            parts.append(f"{adv}, {g} is to be {_pick(rng, _PASSIVE)[2]}")
        return _finish(rng, hdr + "; ".join(parts))
    if k == 4:  # A prior to B; upon completion of this, C
        v0, v1 = _v(rng), _v(rng)
        s = f"{_pick(rng, ('please ', 'kindly ', 'the robot should '))}{v0[0]} {res[0]} prior to {v1[1]} {res[1]}"
        for g in res[2:]:
            s += f"; {_pick(rng, ('upon completion of this', 'thereafter', 'subsequently'))}, {_v(rng)[0]} {g}"
        return _finish(rng, hdr + s)
    if k == 5:  # numbered task list
        when = _pick(rng, ("to be carried out in the order given", "in the sequence listed"))
        lines = [f"{i + 1}. {_v(rng)[0].capitalize()} {g}{_purpose(rng)}." for i, g in enumerate(res)]
        return _finish(rng, f"task list ({when}): " + " ".join(lines))
    if k == 6:  # separate sentences
        s = [f"{hdr}the robot should first {_v(rng)[0]} {res[0]}."]
        for i, g in enumerate(res[1:], start=1):
            if i == n - 1:
                s.append(f"Finally, it is to {_v(rng)[0]} {g}.")
            else:
                s.append(f"{_pick(rng, ('Thereafter', 'Subsequently', 'Upon completion'))}, it is to {_v(rng)[0]} {g}.")
        return _finish(rng, " ".join(s))
    # upon completion of the visit to A, proceed to B; subsequently, C
    s = f"upon completion of the visit to {res[0]}, the robot is to {_v(rng)[0]} {res[1]}"
    for g in res[2:]:
        s += f"; {_pick(rng, ('subsequently', 'thereafter'))}, it should {_v(rng)[0]} {g}"
    return _finish(rng, hdr + s)


def _free(rng, res: list[str], hdr: str) -> str:
    k = int(rng.integers(8))
    if k == 0:
        verb = _pick(rng, ("visit", "attend to", "inspect", "proceed to"))
        return _finish(rng, f"{hdr}the robot is requested to {verb} the following, in an order of its choosing: "
                            + _semi_list(rng, res))
    if k == 1:
        s = f"{hdr}{_pick(rng, ('please ', 'kindly '))}" + _semi_list(rng, [f"{_v(rng)[0]} {g}" for g in res])
        return _finish(rng, s + ". " + _pick(rng, ("The order of the visits is at the robot's discretion.",
                                                     "The sequence is not prescribed.",
                                                     "The order in which this is done is immaterial.")))
    if k == 2:
        letters = "abcdefgh"
        lst = "; ".join(f"({letters[i]}) {_v(rng)[0]} {g}{_purpose(rng)}" for i, g in enumerate(res))
        return _finish(rng, f"tasks ({_pick(rng, ('the sequence is not prescribed', 'in no prescribed order'))}): {lst}")
    if k == 3:
        verb = _pick(rng, ("visit", "attend to", "inspect"))
        return _finish(rng, f"{hdr}it is requested that the robot {verb} each of the following, the order being "
                            f"immaterial: " + _semi_list(rng, res))
    if k == 4:
        return _finish(rng, f"{hdr}in an order of its choosing, the robot should "
                            + _semi_list(rng, [f"{_v(rng)[0]} {g}" for g in res]))
    if k == 5:
        return _finish(rng, f"{hdr}no particular sequence is required. "
                            + _semi_list(rng, [f"{_v(rng)[0].capitalize() if i == 0 else _v(rng)[0]} {g}"
                                               for i, g in enumerate(res)]))
    if k == 6:
        pp = _pick(rng, _PASSIVE)[2]
        return _finish(rng, f"{hdr}each of the following is to be {pp}, in whatever sequence the robot considers "
                            f"most efficient: " + _semi_list(rng, res))
    s = f"{hdr}{_pick(rng, ('please ', 'kindly '))}" + _semi_list(rng, [f"{_v(rng)[0]} {g}" for g in res])
    return _finish(rng, s + " (the order of the visits is left to the robot)")
