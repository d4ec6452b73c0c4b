"""Set AF's own wording (ragnav_jax/language/phrasings_af.py): the same seed writes the same text, and a small reader
written here from AF's own templates recovers what each goal, sensor phrase, hint and instruction was given."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ragnav_jax.language.phrasings_af import hint_text_af, render_goal_af, render_instruction_af, render_sensor_af
from ragnav_jax.language.types import RELATION_TYPES, Relation, SensorConstraint, Subgoal, Target

FAST = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# ----------------------------------------------------------------------------------------------------
# The reader's word lists (AF's templates, written out again here)

RELS = {
    "near": ("near", "close to", "not far from", "in the vicinity of", "within a stone's throw of"),
    "next_to": ("next to", "right next to", "parked next to", "snug next to"),
    "beside": ("beside", "just beside", "set beside", "tucked in beside"),
    "by": ("by", "right by", "sat by", "standing by"),
    "on": ("on", "on top of", "perched on", "sat on top of", "resting on"),
    "under": ("under", "underneath", "beneath", "tucked under"),
    "above": ("above", "directly above", "up above", "high above"),
    "in": ("in", "inside", "stowed inside", "kept in"),
    "with": ("with", "sporting", "carrying", "bearing"),
    "in_room_with": ("in the same room as", "sharing a room with", "in the room that also holds"),
    "in_front_of": ("in front of", "right in front of", "just in front of", "out in front of"),
    "behind": ("behind", "round the back of", "tucked behind", "right behind"),
    "opposite": ("opposite", "across from", "facing", "directly opposite", "across the way from"),
    "left_of": ("to the left of", "left of", "on the left-hand side of", "off to the left of"),
    "right_of": ("to the right of", "on the right-hand side of", "off to the right of", "on the right of"),
}
PHRASE_TO_REL = {p: k for k, ps in RELS.items() for p in ps}
ROOM_FRAMES = ("in the {}", "through in the {}", "out in the {}", "from the {}", "(room: {})", "the {}'s")

READING_WORDS = {"temperature_c": ("temperature", "temp", "hottest", "warmest", "coldest", "coolest", "chilliest"),
                 "humidity_pct": ("humidity", "rh", "dampest", "most humid", "driest", "least humid"),
                 "ndvi": ("ndvi", "greenness", "greenest", "lushest", "least green", "palest")}
MAX_WORDS = ("hottest", "warmest", "dampest", "most humid", "greenest", "lushest", "highest", "beats all the others")
MIN_WORDS = ("coldest", "coolest", "chilliest", "driest", "least humid", "least green", "palest", "lowest")
# checked in this order: the first whose phrase is present decides
CMP_WORDS = (("ge", ("not below", "no lower than", "or more", "or above", "at least")),
             ("le", ("not above", "no higher than", "or less", "or below", "at the very most", "at most")),
             ("approx", ("about", "roughly", "around", "in the region of", "or thereabouts", "give or take")),
             ("gt", ("above", "over", "higher than", "more than", "north of", "in excess of")),
             ("lt", ("below", "under", "lower than", "less than", "south of")))

ONES = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
        "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen")
TENS = {"twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "seventy": 70, "eighty": 80, "ninety": 90}
FRACS = {"one tenth": 0.1, "one fifth": 0.2, "one quarter": 0.25, "three tenths": 0.3, "two fifths": 0.4,
         "one half": 0.5, "three fifths": 0.6, "seven tenths": 0.7, "three quarters": 0.75, "four fifths": 0.8,
         "nine tenths": 0.9}
PARTS = {"and a quarter": 0.25, "and a half": 0.5, "and three quarters": 0.75}
DIGITS = {"nought": 0, **{w: i for i, w in enumerate(ONES[:10])}}


def _whole(words: list[str]) -> int:
    n, cur = 0, 0
    for w in words:
        if w in TENS:
            cur += TENS[w]
        elif w in ONES:
            cur += ONES.index(w)
        elif w == "hundred":
            cur *= 100
        elif w == "and":
            continue
        else:
            raise ValueError(w)
    return n + cur


def read_number(s: str) -> float:
    """A value as AF writes it (digits, words, halves, fractions, spoken decimals, 'below zero'), read back."""
    s = s.lower()
    neg_zero = "below zero" in s
    s = s.replace("below zero", "")
    m = re.search(r"-?\d*\.?\d+", s)
    if m:
        v = float(m.group())
    else:
        for f, fv in FRACS.items():
            if re.search(rf"\b{f}\b", s):
                return fv
        words = re.findall(r"[a-z]+", s.replace("-", " "))
        numeric = set(ONES) | set(TENS) | {"hundred", "minus", "point", "nought", "and", "a", "half", "quarter",
                                           "quarters"}
        run: list[str] = []
        for w in words:
            if w in numeric:
                run.append(w)
            elif run and any(x in ONES or x in TENS or x == "nought" for x in run):
                break
            else:
                run = []
        text = " ".join(run).strip()
        for w in ("and", "a"):  # a run may pick up a leading frame word
            while text.startswith(w + " "):
                text = text[len(w) + 1:]
        sign = -1.0 if text.startswith("minus ") else 1.0
        text = text.removeprefix("minus ")
        part = 0.0
        for p, pv in PARTS.items():
            if text.endswith(p):
                part, text = pv, text[: -len(p)].strip()
        if " point " in text or text.startswith("nought point"):
            a, b = text.split(" point ")
            v = (0 if a == "nought" else _whole(a.split())) + float("0." + "".join(str(DIGITS[d]) for d in b.split()))
        else:
            v = _whole(text.split())
        v = sign * (v + part)
    if neg_zero:
        v = -v
    if "°f" in s or "fahrenheit" in s:
        v = (v - 32) * 5 / 9
    return v


def read_sensor(text: str) -> SensorConstraint:
    """The reader: a goal's sensor words -> the constraint they say."""
    low = text.lower()
    readings = [r for r, ws in READING_WORDS.items() if any(re.search(rf"\b{w}\b", low) for w in ws)]
    assert len(readings) == 1, text
    rd = readings[0]
    if any(w in low for w in MAX_WORDS):
        return SensorConstraint(rd, "max")
    if any(w in low for w in MIN_WORDS):
        return SensorConstraint(rd, "min")
    probe = low.replace("below zero", "")
    for cmp, words in CMP_WORDS:
        if any(re.search(rf"\b{w}\b", probe) for w in words):
            return SensorConstraint(rd, cmp, read_number(low))
    raise AssertionError(text)


def _np(a: Target) -> str:
    states = [x for x in a.attributes if x not in a.phrase.split()]
    pre = [x for x in a.attributes if x in a.phrase.split()]
    return "the " + " ".join([*(s.replace(" ", "-") for s in states), *pre, a.head])


def _rel_before(text: str, idx: int) -> str:
    before = text[:idx].rstrip()
    best = max((p for p in PHRASE_TO_REL if re.search(rf"(^|[\s(,]){re.escape(p)}$", before)), key=len)
    return PHRASE_TO_REL[best]


def check_relations(text: str, t: Target, nested: bool = False) -> None:
    for r in t.relations:
        a = _np(r.anchor)
        idx = text.index(a)
        assert _rel_before(text, idx) == r.type, (r.type, text)
        head = text[:idx]
        depth = head.count("(") - head.count(")")
        if nested:
            assert depth >= 1 or re.search(r"- the one [\w' -]*$", head), text
        else:
            assert depth == 0, text
        check_relations(text, r.anchor, nested=True)


# ----------------------------------------------------------------------------------------------------
# Inputs

HEADS = ("toaster", "guitar", "bean bag", "drum kit", "night-light", "hi-fi speaker")
ANCHORS = ("credenza", "workbench", "lectern", "jukebox", "easel", "kiln", "bureau")
PRE = ("teal", "glossy", "vintage", "corduroy")
STATES = ("switched on", "open", "empty")
ROOMS = ("pantry", "games room", "music room")


@st.composite
def targets(draw, heads, depth=0):
    head = draw(heads)
    pre = draw(st.lists(st.sampled_from(PRE), unique=True, max_size=2))
    states = draw(st.lists(st.sampled_from(STATES), unique=True, max_size=1))
    rels = ()
    if depth < 2:
        rels = tuple(draw(st.lists(st.builds(Relation, st.sampled_from(RELATION_TYPES), targets(heads, depth + 1)),
                                   max_size=2 if depth == 0 else 1)))
    return Target(" ".join([*pre, head]), head, tuple(pre + states), rels)


def _all_heads(t: Target) -> list[str]:
    return [t.head] + [h for r in t.relations for h in _all_heads(r.anchor)]


@st.composite
def goals(draw):
    t = draw(targets(st.sampled_from(HEADS)))
    # give each anchor its own head, so that the reader finds each one once
    names = iter(draw(st.permutations(ANCHORS)))

    def rename(x: Target) -> Target:
        rs = []
        for r in x.relations:
            a = rename(r.anchor)
            h = next(names)
            rs.append(Relation(r.type, Target(a.phrase[: len(a.phrase) - len(a.head)] + h, h, a.attributes,
                                              a.relations)))
        return Target(x.phrase, x.head, x.attributes, tuple(rs))

    t = rename(t)
    if len(_all_heads(t)) > len(ANCHORS) + 1:
        t = Target(t.phrase, t.head, t.attributes)
    room = draw(st.sampled_from((None, *ROOMS)))
    return Subgoal(0, t, room=room)


SENSORS = st.one_of(
    st.builds(SensorConstraint, st.sampled_from(("temperature_c", "humidity_pct", "ndvi")),
              st.sampled_from(("max", "min"))),
    st.builds(SensorConstraint, st.just("temperature_c"), st.sampled_from(("gt", "ge", "lt", "le", "approx")),
              st.sampled_from((40.0, -18.0, 22.5, 5.25, 180.0, 3.0, -3.75, 37.2))),
    st.builds(SensorConstraint, st.just("humidity_pct"), st.sampled_from(("gt", "ge", "lt", "le", "approx")),
              st.sampled_from((40.0, 55.5, 72.0, 30.25))),
    st.builds(SensorConstraint, st.just("ndvi"), st.sampled_from(("gt", "ge", "lt", "le", "approx")),
              st.sampled_from((0.65, 0.6, 0.5, 0.25, 0.3, 0.72))),
)
COORDS = st.sampled_from(("3.5", "2", "-2", "0", "-1.5", "12.0", "7"))


# ----------------------------------------------------------------------------------------------------
# Tests


@FAST
@given(sg=goals(), c=SENSORS, seed=st.integers(0, 2**31), x=COORDS, y=COORDS, with_hint=st.booleans())
def test_same_seed_same_text(sg, c, seed, x, y, with_hint):
    def run():
        rng = np.random.default_rng(seed)
        prefix, tail, written = render_sensor_af(rng, c)
        hint = hint_text_af(rng, x, y) if with_hint else ""
        g = render_goal_af(rng, sg, prefix=prefix, tail=tail, hint=hint)
        return g, written, render_instruction_af(rng, [g, g + " again"], "strict")

    assert run() == run()


@FAST
@given(sg=goals(), seed=st.integers(0, 2**31))
def test_goal_says_head_attributes_states_room_and_relations(sg, seed):
    text = render_goal_af(np.random.default_rng(seed), sg)
    t = sg.target
    assert t.head in text
    for a in t.attributes:
        assert a in text or a.replace(" ", "-") in text, (a, text)
    if sg.room:
        assert any(f.format(sg.room) in text for f in ROOM_FRAMES), text
    else:
        assert not any(r in text for r in ROOMS)
    check_relations(text, t)


@FAST
@given(sg=goals(), seed=st.integers(0, 2**31), x=COORDS, y=COORDS, c=st.one_of(st.none(), SENSORS))
def test_hint_numbers_come_last_x_then_y(sg, seed, x, y, c):
    rng = np.random.default_rng(seed)
    prefix, tail = "", ""
    if c is not None:
        prefix, tail, _ = render_sensor_af(rng, c)
    text = render_goal_af(rng, sg, prefix=prefix, tail=tail, hint=hint_text_af(rng, x, y))
    nums = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", text)]
    assert nums[-2:] == [float(x), float(y)], text
    check_relations(text, sg.target)


@FAST
@given(c=SENSORS, seed=st.integers(0, 2**31), room=st.sampled_from((None, *ROOMS)))
def test_sensor_phrase_says_reading_comparison_value_and_superlative(c, seed, room):
    rng = np.random.default_rng(seed)
    prefix, tail, written = render_sensor_af(rng, c)
    assert (written.reading, written.comparator) == (c.reading, c.comparator)
    if c.is_superlative:
        assert written.value is None and bool(prefix) != bool(tail)
    else:
        assert not prefix and tail and abs(written.value - c.value) <= 0.3  # Fahrenheit rounds to a whole degree
    text = render_goal_af(rng, Subgoal(0, Target("toaster", "toaster"), room=room), prefix=prefix, tail=tail)
    got = read_sensor(text)
    assert (got.reading, got.comparator) == (written.reading, written.comparator), text
    if not c.is_superlative:
        assert got.value == pytest.approx(written.value, abs=1e-6), text


def test_number_formats_and_units_all_turn_up():
    seen_units, texts = set(), []
    for seed in range(400):
        rng = np.random.default_rng(seed)
        _, tail, w = render_sensor_af(rng, SensorConstraint("temperature_c", "approx", -18.0))
        seen_units.add(w.unit)
        texts.append(tail)
    joined = " | ".join(texts)
    assert seen_units == {"c", "f"}
    for piece in ("-18", "minus eighteen", "below zero", "°F"):
        assert piece in joined, piece


@FAST
@given(x=COORDS, y=COORDS, seed=st.integers(0, 2**31))
def test_hint_is_x_then_y(x, y, seed):
    h = hint_text_af(np.random.default_rng(seed), x, y)
    assert [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", h)] == [float(x), float(y)]
    said = [re.search(rf"\b{k}\W*(?:reads )?{re.escape(v)}(?![\d.])", h) for k, v in (("x", x), ("y", y))]
    assert all(said) or re.search(rf"co-ords \({re.escape(x)}, {re.escape(y)}\)", h), h


STRICT = ("note order only", "each in turn as noted", "in sequence, no shortcuts", "in the order they're drawn",
          "calls in strict order", "attend in sequence as given", "strictly in the order received",
          "in this sequence only", "in that order", "first on")
FREE = ("any order you like", "no set running order", "the order's open", "any order:", "order doesn't matter",
        "no priority between calls", "in any sequence", "respond in whatever order", "in no particular order",
        "none taking precedence", "in whatever order is convenient")


@FAST
@given(sgs=st.lists(goals(), min_size=1, max_size=4), seed=st.integers(0, 2**31), strict=st.booleans())
def test_instruction_keeps_every_goal_in_order_and_says_the_order(sgs, seed, strict):
    rng = np.random.default_rng(seed)
    res = [render_goal_af(rng, sg) for sg in sgs]
    order = "strict" if strict or len(res) == 1 else "free"
    text = render_instruction_af(rng, res, order)
    at = 0
    for r in res:
        i = text.find(r, at)
        assert i >= 0, (r, text)
        at = i + len(r)
    low = text.lower()
    if len(res) > 1:
        says_strict = any(w in low for w in STRICT)
        says_free = any(w in low for w in FREE)
        assert (says_strict, says_free) == (order == "strict", order == "free"), text


def test_all_four_voices_and_every_relation_wording_turn_up():
    voices = {"stage": 0, "eyes down": 0, "over.": 0, "notice": 0}
    for seed in range(200):
        rng = np.random.default_rng(seed)
        low = render_instruction_af(rng, ["the toaster", "the kiln"], ("strict", "free")[seed % 2]).lower()
        for k in voices:
            voices[k] += k in low
    assert all(voices.values()), voices
    seen = set()
    for seed in range(300):
        rng = np.random.default_rng(seed)
        for kind in RELATION_TYPES:
            g = render_goal_af(rng, Subgoal(0, Target("toaster", "toaster",
                                                      relations=(Relation(kind, Target("kiln", "kiln")),))))
            seen.add(g[len("the toaster"):g.index("the kiln")].strip(" ,"))
    assert seen == set(PHRASE_TO_REL)
