"""Set AD's own wording (ragnav_jax/language/phrasings_ad.py): a seed writes the same text, and a small reader written
here from set AD's own templates gets back from each goal, sensor phrase, coordinate hint and instruction everything
its arguments mean."""

from __future__ import annotations

import re
from collections import Counter

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ragnav_jax.language import phrasings_ad as ad
from ragnav_jax.language.template_text import hyphenated, number_words
from ragnav_jax.language.types import RELATION_TYPES, Relation, SensorConstraint, Subgoal, Target

FAST = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# ----------------------------------------------------------------------------------------------------
# Tiny inputs

HEADS = ("lamp", "drums", "bonsai tree", "kettle", "bookshelves", "armchair")
ANCHOR_HEADS = ("sofa", "rug", "door", "side table", "curtains", "piano")
ATTRS = ("teal", "wool", "oak", "striped")
STATES = ("switched on", "open", "empty", "folded")
ROOMS = ("kitchen", "living room", "nursery", "study")


@st.composite
def targets(draw, heads=HEADS, depth=0):
    head = draw(st.sampled_from(heads))
    pre = draw(st.lists(st.sampled_from(ATTRS), unique=True, max_size=2))
    states = draw(st.lists(st.sampled_from(STATES), unique=True, max_size=2))
    rels = ()
    if depth < 2:
        n = draw(st.integers(0, 2 if depth == 0 else 1))
        rels = tuple(Relation(draw(st.sampled_from(RELATION_TYPES)), draw(targets(ANCHOR_HEADS, depth + 1)))
                     for _ in range(n))
    return Target(" ".join([*pre, head]), head, tuple(pre + states), rels)


@st.composite
def subgoals(draw):
    return Subgoal(0, draw(targets()), room=draw(st.none() | st.sampled_from(ROOMS)))


def _value(draw, reading):
    if reading == "ndvi":
        return draw(st.integers(-30, 100)) / 100
    if reading == "temperature_c":
        return draw(st.integers(-120, 240)) / 4
    return draw(st.integers(0, 200)) / 2


@st.composite
def constraints(draw):
    reading = draw(st.sampled_from(("temperature_c", "humidity_pct", "ndvi")))
    cmp = draw(st.sampled_from(("gt", "ge", "lt", "le", "approx", "max", "min")))
    if cmp in ("max", "min"):
        return SensorConstraint(reading, cmp)
    return SensorConstraint(reading, cmp, _value(draw, reading))


# ----------------------------------------------------------------------------------------------------
# The small reader, written from set AD's templates

# every relation word -> its type; the longest word right before an anchor decides
REL_OF = {w: t for t, ws in ad.REL_WORDS.items() for w in ws}
REL_OF.update({w: "with" for w in (*ad.WITH_AFTER_IS, *ad.WITH_VERBS)})


def _anchor_pattern(t: Target) -> str:
    _, states = _split(t)
    front = re.escape(hyphenated(states)) + " " if states else ""
    return rf"\bthe (?:{front})?{re.escape(t.phrase)}\b"


def _split(t: Target) -> tuple[list[str], list[str]]:
    pre = [a for a in t.attributes if a in t.phrase.split()]
    return pre, [a for a in t.attributes if a not in pre]


def relation_types_before(text: str, anchor: Target) -> list[str]:
    """The relation type written right before each mention of `anchor` (None where no relation word is)."""
    out = []
    for m in re.finditer(_anchor_pattern(anchor), text):
        before = text[: m.start()].rstrip()
        best = None
        for w in REL_OF:
            if re.search(rf"(?:^|[\s(,]){re.escape(w)}$", before) and (best is None or len(w) > len(best)):
                best = w
        out.append(REL_OF.get(best))
    return out


def all_relations(t: Target):
    for r in t.relations:
        yield r
        yield from all_relations(r.anchor)


_WORD_NUMBERS = {number_words(i): i for i in range(0, 200)}
_DIGIT_WORDS = {w: str(i) for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight",
                                                  "nine"))}
_SPOKEN_FRACS = {" and a half": 0.5, " and a quarter": 0.25, " and three quarters": 0.75}
_SYMBOL_FRACS = {"½": 0.5, "¼": 0.25, "¾": 0.75}


def read_number(text: str) -> tuple[float, str]:
    """(the number a sensor phrase of set AD writes, the text with the number taken out)."""
    words_alt = "|".join(sorted(map(re.escape, _WORD_NUMBERS), key=len, reverse=True))
    m = re.search(rf"\b(\d+|{words_alt}) degrees? below freezing", text)
    if m:
        v = float(m.group(1)) if m.group(1).isdigit() else float(_WORD_NUMBERS[m.group(1)])
        return -v, text[: m.start()] + "#" + text[m.end():]
    m = re.search(r"(?<![\w.])(zero )?point((?: (?:zero|one|two|three|four|five|six|seven|eight|nine))+)", text)
    if m:
        v = float("0." + "".join(_DIGIT_WORDS[w] for w in m.group(2).split()))
        return v, text[: m.start()] + "#" + text[m.end():]
    m = re.search(r"\b(\d+)/(\d+)\b", text)
    if m:
        return int(m.group(1)) / int(m.group(2)), text[: m.start()] + "#" + text[m.end():]
    m = re.search(r"(minus |negative |-)?(\d+(?:\.\d+)?|\.\d+)([½¼¾])?", text)
    if m:
        v = float(m.group(2)) + (_SYMBOL_FRACS[m.group(3)] if m.group(3) else 0.0)
        return (-v if m.group(1) else v), text[: m.start()] + "#" + text[m.end():]
    fr = "|".join(map(re.escape, _SPOKEN_FRACS))
    m = re.search(rf"\b(minus |negative )?({words_alt})({fr})?\b", text)
    assert m, text
    v = _WORD_NUMBERS[m.group(2)] + (_SPOKEN_FRACS[m.group(3)] if m.group(3) else 0.0)
    return (-v if m.group(1) else v), text[: m.start()] + "#" + text[m.end():]


# comparison cues, checked in this order (a later cue may sit inside an earlier one: 'more or less', 'not above')
CUES = (
    ("approx", ("about", "roughly", "approximately", "or so", "give or take", "more or less", "-ish", "≈", "~")),
    ("le", ("no more than", "not above", "or less", "or lower", "at most", "≤", "<=", "no warmer than",
            "no hotter than", "no damper than", "no more humid than")),
    ("ge", ("no less than", "not below", "or more", "or higher", "at least", "≥", ">=", "no colder than",
            "no drier than")),
    ("gt", ("over", "above", "more than", "higher than", "greater than", ">", "warmer than", "hotter than",
            "damper than", "more humid than")),
    ("lt", ("under", "below", "less than", "lower than", "<", "colder than", "cooler than", "drier than",
            "less humid than")),
)


def _has(text: str, cue: str) -> bool:
    if cue[0].isalpha() or cue[0] == "-":
        return re.search(rf"(?<![\w]){re.escape(cue)}\b", text) is not None
    return cue in text


def read_reading(text: str) -> str:
    if "NDVI" in text or "greenest" in text or "lushest" in text or "least green" in text or "sickliest" in text:
        return "ndvi"
    if re.search(r"humid|\bRH\b|hygrometer|%|per ?cent|damp|drie|\bair\b", text):
        return "humidity_pct"
    assert re.search(r"temp|thermometer|warm|hot|cold|cool|chill|degree|°|º|[\d½¼¾]C\b|freezing|\bC\b", text), text
    return "temperature_c"


def read_sensor(prefix: str, tail: str) -> SensorConstraint:
    """What a careful reader gets from set AD's sensor phrase."""
    text = (prefix + " " + tail).strip()
    reading = read_reading(text)
    if re.search(r"highest|\btop\b|hottest|warmest|most humid|dampest|greenest|lushest", text):
        return SensorConstraint(reading, "max")
    if re.search(r"lowest|\bbottom\b|coldest|chilliest|least humid|driest|least green|sickliest", text):
        return SensorConstraint(reading, "min")
    value, rest = read_number(tail)
    cmp = next(c for c, cues in CUES if any(_has(rest, q) for q in cues))
    if re.search(r"°C|ºC|[\d½¼¾]C\b|-ish C\b|degree|Celsius|centigrade|freezing", tail):
        unit = "c"
    elif re.search(r"%|per cent|percent", tail):
        unit = "%"
    else:
        unit = ""
    return SensorConstraint(reading, cmp, value, unit)


STRICT_CUES = ("in the order billed", "in that order", "in sequence", "order sent", "stick to that sequence",
               "in order from the ground up", "in that sequence", "printed order", "order written")
FREE_CUES = ("any order", "whichever comes first", "order's up to you", "any sequence", "whatever order",
             "no set sequence", "makes no difference", "ad libitum", "ad lib", "discretion")


# ----------------------------------------------------------------------------------------------------
# Tests


@FAST
@given(sgs=st.lists(subgoals(), min_size=1, max_size=4), c=constraints(), seed=st.integers(0, 2**31),
       strict=st.booleans())
def test_same_seed_same_text(sgs, c, seed, strict):
    def run():
        rng = np.random.default_rng(seed)
        res = [ad.render_goal_ad(rng, sg, hint=ad.hint_text_ad(rng, "3.5", "-2")) for sg in sgs]
        return res, ad.render_sensor_ad(rng, c), ad.render_instruction_ad(rng, res, "strict" if strict else "free")

    assert run() == run()


def test_relation_words_are_one_types_each():
    assert set(ad.REL_WORDS) == set(RELATION_TYPES)
    seen = Counter(w for ws in ad.REL_WORDS.values() for w in ws)
    assert all(n == 1 for n in seen.values()), seen


@FAST
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_says_what_it_means(sg, seed):
    rng = np.random.default_rng(seed)
    text = ad.render_goal_ad(rng, sg)
    t = sg.target
    assert t.head in text and text == " ".join(text.split())
    pre, states = _split(t)
    for a in pre:
        assert re.search(rf"\b{a}\b", text), (a, text)
    for s in states:
        assert s in text or s.replace(" ", "-") in text, (s, text)
    if sg.room:
        assert re.search(rf"the {sg.room}\b|\b{sg.room}'s |room: {sg.room}\)", text), text
    # every relation, nested ones included, is read back with its own type
    wanted: dict[str, Counter] = {}
    anchors = {}
    for r in all_relations(t):
        key = _anchor_pattern(r.anchor)
        anchors[key] = r.anchor
        wanted.setdefault(key, Counter())[r.type] += 1
    for key, types in wanted.items():
        got = Counter(relation_types_before(text, anchors[key]))
        assert all(got[k] >= n for k, n in types.items()), (types, got, text)
    # the room is said before any relation
    if sg.room and t.relations:
        first_rel = min(m.start() for r in t.relations for m in re.finditer(_anchor_pattern(r.anchor), text))
        assert text.find(sg.room) < first_rel, text


@FAST
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_says_what_it_means(c, seed):
    prefix, tail, written = ad.render_sensor_ad(np.random.default_rng(seed), c)
    assert bool(prefix) != bool(tail)
    assert (written.reading, written.comparator) == (c.reading, c.comparator)
    got = read_sensor(prefix, tail)
    if c.is_superlative:
        assert written == c and (got.reading, got.comparator, got.value) == (c.reading, c.comparator, None)
        assert not re.search(r"\d", prefix + tail)
        return
    rounding = 0.005 if c.reading == "ndvi" else 1e-9
    assert abs(written.value - c.value) <= rounding
    assert (got.reading, got.comparator, got.unit) == (written.reading, written.comparator, written.unit), (
        prefix, tail, written)
    assert got.value == pytest.approx(written.value, abs=1e-9), (tail, written)


@FAST
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_keeps_the_sensor_phrase(c, sg, seed):
    rng = np.random.default_rng(seed)
    prefix, tail, _ = ad.render_sensor_ad(rng, c)
    text = ad.render_goal_ad(rng, sg, prefix=prefix, tail=tail)
    assert prefix in text and tail in text and sg.target.head in text
    if tail and f"in the {sg.room}" in text:  # with a sensor tail, 'in the <room>' comes after it
        assert text.index(f"in the {sg.room}") > text.index(tail), text


coords = st.integers(-200, 200).map(lambda v: v / 10)


@FAST
@given(x=coords, y=coords, short=st.booleans(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_hint_says_x_then_y(x, y, short, sg, seed):
    xs, ys = ((f"{v:g}" if short else f"{v:.1f}") for v in (x, y))
    rng = np.random.default_rng(seed)
    hint = ad.hint_text_ad(rng, xs, ys)
    assert re.search(rf"x\D{{0,7}}{re.escape(xs)}\b", hint) or re.search(rf"{re.escape(xs)} m along x", hint), hint
    assert re.search(rf"y\D{{0,7}}{re.escape(ys)}\b", hint) or re.search(rf"{re.escape(ys)} m along y", hint), hint
    text = ad.render_goal_ad(rng, sg, hint=hint)
    nums = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", text)]
    assert nums[-2:] == [x, y], text


GOALS = ("the lamp", "the teal kettle in the kitchen", "the drums, presently empty, next to the sofa",
         "the piano at x = 1.5, y = -2", "the nursery's bonsai tree", "the armchair (room: study) beside the rug")


@FAST
@given(goals=st.lists(st.sampled_from(GOALS), unique=True, min_size=1, max_size=5), strict=st.booleans(),
       seed=st.integers(0, 2**31))
def test_instruction_says_every_goal_and_the_order(goals, strict, seed):
    order = "strict" if strict else "free"
    text = ad.render_instruction_ad(np.random.default_rng(seed), list(goals), order)
    low = text.lower()
    spots = [low.find(g.lower()) for g in goals]
    assert all(s >= 0 for s in spots) and spots == sorted(spots), text
    assert all(low.count(g.lower()) == 1 for g in goals), text
    strict_cue = any(q in low for q in STRICT_CUES)
    free_cue = any(q in low for q in FREE_CUES)
    if len(goals) == 1:
        assert not strict_cue and not free_cue, text
        assert not re.search(r"\d", low.replace(goals[0].lower(), "")), text
    elif strict:
        assert strict_cue and not free_cue, text
    else:
        assert free_cue and not strict_cue, text


VOICE_MARKS = {"magician": ("assistant",),
               "radio amateur": ("robot, base", "this is base", "base to robot", "over.", "standing by"),
               "climber": ("climb", "pitch", "problem", "lower off", "top out", "session"),
               "conductor": ("movement", "score", "encore", "ad lib", "cadenza", "concert")}


def test_every_voice_writes_every_kind_of_text():
    """Over a few seeds each of the four voices writes a strict, a free and a single-goal text."""
    seen = set()
    for seed in range(60):
        rng = np.random.default_rng(seed)
        for order, goals in (("strict", GOALS[:3]), ("free", GOALS[2:5]), ("strict", GOALS[:1])):
            text = ad.render_instruction_ad(rng, list(goals), order).lower()
            voices = [v for v, marks in VOICE_MARKS.items() if any(m in text for m in marks)]
            assert len(voices) == 1, text
            seen.add((voices[0], order, len(goals) == 1))
    assert len(seen) == 12, seen
