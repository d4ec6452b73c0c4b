"""The `unseen_al` templates (set AL: an estate agent, a chess annotator, a quest-giver, a private eye): the same
seed writes the same text, and every piece of a goal, sensor phrase, hint and order cue is written down the way
the set's style guide says. Checked with small readers of the set's own wording, written here."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_phrasings_dev8 import subgoals

from ragnav_jax.language import phrasings_al as AL
from ragnav_jax.language.template_text import attributes_and_states, hyphenated
from ragnav_jax.language.types import READINGS, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])

ALL_FIXED = [c for cs in AL.FIXED.values() for c in cs]
ALL_OPEN = [c for cs in AL.OPEN.values() for c in cs]
SEQUENCE_WORDS = re.compile(r"\b(first|then|next|after|afterwards|finally|last|before|sequence)\b", re.I)


def _all_targets(t: Target):
    yield t
    for r in t.relations:
        yield from _all_targets(r.anchor)


def _numbers(text: str) -> list[float]:
    return [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", text)]


# ------------------------------------------------------------------------------------------ a reader of AL's numbers

_ONES = {w: i for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine",
                                     "ten", "eleven", "twelve", "thirteen", "fourteen", "fifteen", "sixteen",
                                     "seventeen", "eighteen", "nineteen"))}
_ONES["nought"] = 0
_TENS = {"twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "seventy": 70, "eighty": 80,
         "ninety": 90}


def _word_value(text: str) -> float | None:
    toks = re.sub(r"[-,():]", " ", text.lower()).split()
    i = next((k for k, w in enumerate(toks) if w in _ONES or w in _TENS or w == "minus"), None)
    if i is None:
        return None
    sign = 1.0
    if toks[i] == "minus":
        sign, i = -1.0, i + 1
    total, cur = 0, 0
    while i < len(toks):
        w = toks[i]
        if w in _ONES:
            cur += _ONES[w]
        elif w in _TENS:
            cur += _TENS[w]
        elif w == "hundred":
            cur *= 100
        elif w == "and" and i + 1 < len(toks) and (toks[i + 1] in _ONES or toks[i + 1] in _TENS):
            pass
        elif w == "and" and toks[i + 1: i + 3] == ["a", "half"]:
            return sign * (total + cur + 0.5)
        elif w == "point":
            digits = ""
            i += 1
            while i < len(toks) and toks[i] in _ONES and _ONES[toks[i]] < 10:
                digits += str(_ONES[toks[i]])
                i += 1
            return sign * float(f"{total + cur}.{digits}")
        else:
            break
        i += 1
    return sign * (total + cur)


def read_value(phrase: str, unit: str) -> float:
    """The value a phrase of AL's writes, in the reading's canonical unit."""
    found = re.findall(r"-?\d[\d,]*(?:\.\d+)?", phrase.replace("CO2", "CO"))
    v = float(found[0].replace(",", "")) if found else _word_value(phrase)
    assert v is not None, phrase
    if "below zero" in phrase:
        v = -v
    if unit == "f":
        v = (v - 32) * 5 / 9
    if unit == "kw":
        v = v * 1000
    return v


_MARKERS = (  # checked in this order; the first comparator with a marker in the phrase is the one read
    ("approx", ("about", "around", "roughly", "thereabouts", "in the region of", "approximately")),
    ("ge", ("at least", "or more", "or above", "no lower than", "not below", "no less than", "does not fall below",
            "no colder", "no cooler", "no quieter", "no lighter", "no dimmer")),
    ("le", ("at most", "or less", "or below", "no higher than", "not above", "no more than", "does not exceed",
            "no hotter", "no warmer", "no louder", "no heavier", "no brighter")),
    ("gt", ("over", "above", "higher than", "greater than", "in excess of", "more than", "exceeds", "hotter than",
            "warmer than", "louder than", "heavier than", "brighter than")),
    ("lt", ("under", "below", "lower than", "less than", "colder than", "cooler than", "quieter than",
            "lighter than", "dimmer than")),
)


def read_comparator(phrase: str) -> str:
    low = phrase.lower()
    for cmp, marks in _MARKERS:
        if any(re.search(rf"\b{re.escape(m)}\b", low) for m in marks):
            return cmp
    return "?"


_MIN_MARKS = ("lowest", "coldest", "chilliest", "driest", "least", "quietest", "dimmest", "dimly", "less", "colder",
              "drier")
_MAX_MARKS = ("highest", "hottest", "warmest", "dampest", "most", "loudest", "noisiest", "brightest", "brightly",
              "heaviest", "more", "hotter")


def read_superlative(text: str) -> str:
    low = text.lower()
    if any(re.search(rf"\b{m}\b", low) for m in _MIN_MARKS):
        return "min"
    return "max" if any(re.search(rf"\b{m}\b", low) for m in _MAX_MARKS) else "?"


_VALUES = {"temperature_c": st.integers(-30, 400).map(float) | st.sampled_from([20.5, -2.5, 37.5, 40.0, -40.0]),
           "ndvi": st.sampled_from([0.2, 0.35, 0.5, 0.65, 0.8, -0.1, 0.05]),
           "humidity_pct": st.integers(0, 100).map(float) | st.just(22.5),
           "co2_ppm": st.integers(300, 5000).map(float),
           "noise_db": st.integers(20, 120).map(float),
           "light_lux": st.integers(0, 20000).map(float),
           "battery_pct": st.integers(0, 100).map(float),
           "power_w": st.integers(0, 5000).map(float) | st.sampled_from([1500.0, 2000.0, 3200.0]),
           "weight_kg": st.integers(0, 900).map(float) | st.just(2.5),
           "pressure_hpa": st.integers(900, 1100).map(float)}


@st.composite
def thresholds(draw):
    rd = draw(st.sampled_from(READINGS))
    return SensorConstraint(rd, draw(st.sampled_from(("gt", "ge", "lt", "le", "approx"))), draw(_VALUES[rd]))


# ------------------------------------------------------------------------------------------ tests


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=5), seed=st.integers(0, 2**31), strict=st.booleans(),
       c=thresholds())
def test_same_seed_same_text(sgs, seed, strict, c):
    def run():
        rng = np.random.default_rng(seed)
        p, t, w = AL.render_sensor_al(rng, c)
        res = [AL.render_goal_al(rng, sg, prefix=p, tail=t, hint=AL.hint_text_al(rng, "3.5", "-2")) for sg in sgs]
        return p, t, w, res, AL.render_instruction_al(rng, res, "strict" if strict else "free")

    assert run() == run()


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31), with_hint=st.booleans())
def test_goal_writes_every_piece(sg, seed, with_hint):
    rng = np.random.default_rng(seed)
    hint = AL.hint_text_al(rng, "3.5", "2") if with_hint else ""
    g = AL.render_goal_al(rng, sg, hint=hint)
    assert g.startswith("the ") and ";" not in g and "  " not in g
    for t in _all_targets(sg.target):
        assert t.head in g
        pre, states = attributes_and_states(t)
        for a in pre:
            assert a in g
        if states:
            assert hyphenated(states) in g or all(s in g for s in states)
    if sg.room:
        assert sg.room in g
    if hint:
        assert hint in g and _numbers(g)[-2:] == [3.5, 2.0]
    assert g.count("(") == g.count(")")


def test_anchor_relations_sit_in_parentheses_after_their_anchor():
    inner = Target("olive drums", "drums", ("olive",))
    sofa = Target("teal sofa", "sofa", ("teal",), (Relation("beside", inner),))
    sg = Subgoal(0, Target("lamp", "lamp", (), (Relation("under", sofa),)))
    for seed in range(40):
        g = AL.render_goal_al(np.random.default_rng(seed), sg)
        m = re.search(r"the teal sofa \(([^()]*)\)", g)
        assert m and "the olive drums" in m.group(1), g


@SETTINGS
@given(sg=subgoals(), c=thresholds(), seed=st.integers(0, 2**31), x=st.sampled_from(["3.5", "-1.25", "0", "12"]),
       y=st.sampled_from(["2", "-4.5", "0.75"]))
def test_hint_numbers_come_last_x_then_y(sg, c, seed, x, y):
    rng = np.random.default_rng(seed)
    hint = AL.hint_text_al(rng, x, y)
    assert _numbers(hint) == [float(x), float(y)] and hint.index(x) < hint.rindex(y)
    p, t, _ = AL.render_sensor_al(rng, c)
    g = AL.render_goal_al(rng, sg, prefix=p, tail=t, hint=hint)
    assert _numbers(g)[-2:] == [float(x), float(y)] and t in g


@SETTINGS
@given(c=thresholds(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    p, t, w = AL.render_sensor_al(np.random.default_rng(seed), c)
    assert p == "" and t
    assert (w.reading, w.comparator, w.value) == (c.reading, c.comparator, c.value)
    assert w.unit in {"c", "f", "%", "ppm", "db", "lux", "w", "kw", "kg", "hpa", ""}
    assert read_value(t, w.unit) == c.value, t
    assert read_comparator(t) == c.comparator, t
    if w.unit == "f":
        assert "°F" in t or "Fahrenheit" in t
    if w.unit == "kw":
        assert "kW" in t or "kilowatts" in t


@SETTINGS
@given(rd=st.sampled_from(READINGS), cmp=st.sampled_from(("max", "min")), seed=st.integers(0, 2**31))
def test_superlatives_say_which_end(rd, cmp, seed):
    p, t, w = AL.render_sensor_al(np.random.default_rng(seed), SensorConstraint(rd, cmp))
    assert bool(p) != bool(t) and w == SensorConstraint(rd, cmp, None, "")
    assert read_superlative(p or t) == cmp, p or t
    assert not re.search(r"\d", (p + t).replace("CO2", "CO"))
    if t:
        assert t in AL._SUP_TAILS


@pytest.mark.parametrize("value,wanted", [(40.0, "104 °F"), (1500.0, "1.5 kW"), (22.5, "twenty-two and a half"),
                                          (0.65, "nought point six five"), (-4.0, "4 °C below zero"),
                                          (1500.0, "1,500"), (42.0, "forty-two")])
def test_number_formats_vary(value, wanted):
    rd = {"1.5 kW": "power_w", "1,500": "co2_ppm", "nought point six five": "ndvi",
          "twenty-two and a half": "weight_kg"}.get(wanted, "temperature_c")
    cmp = "approx" if "below zero" in wanted else "gt"
    seen = {AL.render_sensor_al(np.random.default_rng(s), SensorConstraint(rd, cmp, value))[1] for s in range(400)}
    assert any(wanted in t for t in seen), sorted(seen)[:10]


def test_unit_changes_only_when_exact():
    assert AL._fahrenheit(40.0) == "104" and AL._fahrenheit(-40.0) == "-40" and AL._fahrenheit(37.0) is None
    assert AL._kilowatts(1500.0) == "1.5" and AL._kilowatts(1550.0) is None and AL._kilowatts(900.0) is None
    for s in range(200):
        _, t, w = AL.render_sensor_al(np.random.default_rng(s), SensorConstraint("temperature_c", "lt", 37.0))
        assert w.unit == "c" and "°F" not in t


def test_superlative_goal_keeps_every_piece_restrictive():
    sg = Subgoal(0, Target("teal lamp", "lamp", ("teal",)), room="nursery")
    for s in range(60):
        rng = np.random.default_rng(s)
        p, t, _ = AL.render_sensor_al(rng, SensorConstraint("temperature_c", "max"))
        g = AL.render_goal_al(rng, sg, prefix=p, tail=t)
        assert "," not in g and "(" not in g and "which" not in g, g
        assert "nursery" in g and "teal" in g and "lamp" in g


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5), seed=st.integers(0, 2**31), strict=st.booleans())
def test_instruction_keeps_goals_in_order_and_says_the_order(sgs, seed, strict):
    rng = np.random.default_rng(seed)
    res = [AL.render_goal_al(rng, sg) for sg in sgs]
    text = AL.render_instruction_al(rng, res, "strict" if strict else "free")
    low, at = text.lower(), 0
    for g in res:  # every goal written as rendered, in visiting order
        k = low.find(g.lower(), at)
        assert k >= 0, (g, text)
        at = k + len(g)
    rest = low
    for g in sorted(res, key=len, reverse=True):
        rest = rest.replace(g.lower(), " ")
    fixed = [c for c in ALL_FIXED if c.lower() in rest]
    free = [c for c in ALL_OPEN if c.lower() in rest]
    if strict:
        assert len(fixed) == 1 and not free, text
    else:
        assert len(free) == 1 and not fixed, text
        assert not SEQUENCE_WORDS.search(rest) and not re.search(r"\d", rest), text


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31), strict=st.booleans())
def test_single_goal_has_no_order_cue_and_no_digit(sg, seed, strict):
    rng = np.random.default_rng(seed)
    g = AL.render_goal_al(rng, sg)
    text = AL.render_instruction_al(rng, [g], "strict" if strict else "free")
    assert g in text or AL._cap(g) in text
    rest = text.replace(AL._cap(g), " ").replace(g, " ").lower()
    assert not re.search(r"\d", rest), text
    assert not any(c.lower() in rest for c in ALL_FIXED + ALL_OPEN), text
    assert not SEQUENCE_WORDS.search(rest) and "order" not in rest, text


def test_cues_are_distinct_and_every_voice_speaks():
    for a in ALL_FIXED:
        assert not any(a.lower() in b.lower() or b.lower() in a.lower() for b in ALL_OPEN)
    assert set(AL.FIXED) == set(AL.OPEN) == set(AL.SINGLE) == set(AL.VOICES) and len(AL.VOICES) == 4
    res = ["the lamp", "the sofa", "the drums"]
    seen = set()
    for s in range(80):
        text = AL.render_instruction_al(np.random.default_rng(s), res, "strict")
        seen |= {v for v, cs in AL.FIXED.items() if any(c in text.lower() for c in (x.lower() for x in cs))}
    assert seen == set(AL.VOICES)


def test_commas_in_goals_bring_semicolons():
    res = ["the lamp, currently switched on, in the nursery", "the sofa where x = 3.5 and y = 2"]
    assert AL._items(np.random.default_rng(0), res) == f"{res[0]}; and {res[1]}"
    assert AL._items(np.random.default_rng(0), ["the lamp", "the sofa"]) == "the lamp and the sofa"
    res = ["the sofa where x = 3.5 and y = 2", "the lamp", "the drums"]
    assert AL._items(np.random.default_rng(0), res) == "the sofa where x = 3.5 and y = 2; the lamp; and the drums"


@pytest.mark.parametrize("rd", READINGS)
def test_awkward_values_come_back_exactly(rd):
    values = {"ndvi": (0.65, -0.15, 0.05, 0.0)}.get(rd, (-2.5, -4.0, 0.0, 22.5, 1500.0, 1013.0, 37.5))
    for v in values:
        for cmp in ("gt", "ge", "lt", "le", "approx"):
            for s in range(25):
                _, t, w = AL.render_sensor_al(np.random.default_rng(s), SensorConstraint(rd, cmp, v))
                assert read_value(t, w.unit) == v and read_comparator(t) == cmp, (t, v, cmp)
