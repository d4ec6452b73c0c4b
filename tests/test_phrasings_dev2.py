"""Second development set of unseen phrasings: deterministic, states after the noun, relation and superlative meanings kept,
numbers that denote the written constraint (read back by an independent reader), coordinates read back,
strict/free wording, and clean punctuation."""

import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ragnav_jax.language.phrasings import STATE_VALUES
from ragnav_jax.language.phrasings_dev2 import (
    hint_text_dev2,
    render_goal_dev2,
    render_instruction_dev2,
    render_sensor_dev2,
)
from ragnav_jax.language.types import RELATION_TYPES, Relation, SensorConstraint, Subgoal, Target

HEADS = ("lamp", "sofa", "kettle", "fern", "coffee machine", "desk", "heater", "cabinet")
MODS = ("red", "oak", "gold-framed", "grey fabric", "king-size", "black")
ROOMS = ("kitchen", "living room", "study", "greenhouse")


def T(head, attrs=(), rels=()):
    return Target(" ".join(a for a in (*attrs, head)), head, tuple(attrs), tuple(Relation(t, a) for t, a in rels))


def gen(seed):
    return np.random.default_rng(seed)


# An independent reader of the amounts a sensor phrase may write: digits ("-12", ".70", "minus 12") or words.
_WORDS = {w: i for i, w in enumerate(
    "zero one two three four five six seven eight nine ten eleven twelve thirteen fourteen fifteen sixteen "
    "seventeen eighteen nineteen".split())}
_WORDS.update({w: 10 * k for k, w in enumerate("twenty thirty forty fifty sixty seventy eighty ninety".split(), 2)})
_UNITS = {"temperature_c": ("℃", "°C", "°", "degrees", "Celsius"), "humidity_pct": ("%", "percent", "per cent"),
          "ndvi": ("NDVI",)}


def read_amount(text):
    text = text.replace("−", "-")
    m = re.search(r"(?<![\w.])(minus )?(-?(?:\d+(?:\.\d+)?|\.\d+))", text)
    if m:
        return -float(m.group(2)) if m.group(1) else float(m.group(2))
    m = re.search(r"(minus )?(one hundred|[a-z]+(?:-[a-z]+)?) (?=degrees|percent|per cent)", text)
    n = 100 if m.group(2) == "one hundred" else sum(_WORDS[p] for p in m.group(2).split("-"))
    return -float(n) if m.group(1) else float(n)


_CUES = {"gt": ("topping", "tops", "surpassing", "at more than", "with more than", "scoring over"),
         "ge": ("at or above", "or higher", "no less than"),
         "lt": ("stays under", "short of", "of under", "at less than", "with under", "scoring under"),
         "le": ("at or below", "or lower", "no greater than", "no more than"),
         "approx": ("hovers around", " near ", "or so", "neighbourhood of")}
_HIGH = ("highest", "maximum", "warmest", "hottest", "greenest", "healthiest", "most humid", "dampest")
_LOW = ("lowest", "minimum", "coldest", "coolest", "least healthy", "driest", "least humid")


def _word(w):
    """w as a whole word ('running' in 'hottest-running' is part of a prefix, not the state)."""
    return rf"(?<![\w-]){w}(?![\w-])"


def test_determinism():
    sg = Subgoal(0, T("lamp", ("red", "switched on"), [("next_to", T("sofa", ("grey fabric",)))]), room="study")
    for c in (SensorConstraint("temperature_c", "gt", 60.0), SensorConstraint("ndvi", "max")):
        for seed in range(20):
            def run(rng, c=c):
                p, t, w = render_sensor_dev2(rng, c)
                goals = [render_goal_dev2(rng, sg, p, t, hint_text_dev2(rng, "3.5", "2")) for _ in range(3)]
                return (p, t, w, goals, render_instruction_dev2(rng, goals, "strict"),
                        render_instruction_dev2(rng, goals, "free"))
            assert run(gen(seed)) == run(gen(seed))


@pytest.mark.parametrize("state", STATE_VALUES)
def test_states_follow_the_head_noun_and_every_attribute_is_written(state):
    for seed in range(24):
        rng = gen(seed)
        mods = (MODS[seed % len(MODS)],) if seed % 3 else ()
        rels = [("near", T("sofa"))] if seed % 4 == 1 else []
        sg = Subgoal(0, T("heater", (*mods, state), rels), room=ROOMS[seed % 4] if seed % 2 else None)
        prefix, tail, _ = render_sensor_dev2(rng, SensorConstraint("temperature_c", ("max", "gt")[seed % 2], 50.0)) \
            if seed % 5 == 0 else ("", "", None)
        text = render_goal_dev2(rng, sg, prefix, tail)
        head = text.index("heater")
        assert re.search(_word(state), text[head:]) and not re.search(_word(state), text[:head]), text
        assert all(m in text for m in mods) and (sg.room is None or f" the {sg.room}" in text), text


# What each relation may be called, independently of the renderer: the words right before the anchor.
_REL_WORDS = {
    "near": r"(near|close to|not far from)", "next_to": r"(next to|adjacent to)", "beside": r"beside",
    "by": r"\bby", "on": r"\bon( top of)?", "with": r"(with|having|has|next to it,)",
    "in_room_with": r"(same room as|room containing|room that also holds)", "under": r"(under|beneath)",
    "above": r"above", "in": r"(in|inside)", "in_front_of": r"in front of", "behind": r"behind",
    "opposite": r"opposite", "left_of": r"(left-hand side of|left of)", "right_of": r"(right-hand side of|right of)",
}


@pytest.mark.parametrize("rtype", RELATION_TYPES)
def test_relations_keep_their_meaning(rtype):
    for seed in range(30):
        rng = gen(seed)
        anchor = T("sofa", ("grey fabric",), [("on", T("rug"))] if seed % 3 == 0 else [])
        text = render_goal_dev2(rng, Subgoal(0, T("lamp", (), [(rtype, anchor)])))
        assert re.search(_REL_WORDS[rtype] + " the grey fabric sofa", text), text
        if rtype == "with" and "it" in text.split():  # the anchor is on the target or beside it, never only on it
            assert re.search(r"on (top of )?it or (beside|next to) it", text), text


def test_superlative_scope_and_plurals():
    rng = gen(3)
    forms = set()
    for k in range(300):
        head = ("heater", "cactus", "bench", "peace lily", "chest of drawers", "electronics", "tv")[k % 7]
        prefix, tail, w = render_sensor_dev2(rng, SensorConstraint("temperature_c", "max"))
        text = render_goal_dev2(rng, Subgoal(0, T(head), room="kitchen"), prefix, tail)
        m = re.fullmatch(r"the \w+ of the (.+?) (in|over in|inside|located in) the kitchen", text)
        if m:
            forms.add("plural")
            assert m.group(1) in ("heaters", "cacti", "benches", "peace lilies", "chests of drawers"), text
        # the room restricts what the superlative ranges over: never left between the noun and the reading
        assert text.index("kitchen") > max(text.find(x) for x in _HIGH), text
        assert any(e in text for e in _HIGH) and not any(e in text for e in _LOW), text
        forms.add("prefix" if prefix else tail.split()[0])
    assert {"plural", "prefix", "running", "with", "that", "showing"} <= forms


@pytest.mark.parametrize("reading,values", [
    ("temperature_c", [-24.0, -12.0, 0.0, 7.0, 20.0, 57.5, 60.0, 65.0, 99.0, 100.0, 140.0, 950.0]),
    ("humidity_pct", [5.0, 30.0, 65.0, 70.0, 100.0]),
    ("ndvi", [-0.25, 0.0, 0.05, 0.2, 0.65, 0.7]),
])
def test_sensor_text_denotes_the_written_constraint(reading, values):
    rng = gen(1)
    for v in values:
        for cmp_ in ("gt", "ge", "lt", "le", "approx"):
            for _ in range(20):
                prefix, tail, w = render_sensor_dev2(rng, SensorConstraint(reading, cmp_, v))
                assert prefix == "" and (w.reading, w.comparator, w.value) == (reading, cmp_, v)
                assert read_amount(tail) == v, tail
                assert w.unit == {"temperature_c": "c", "humidity_pct": "%", "ndvi": ""}[reading]
                assert any(u in tail for u in _UNITS[reading]), tail
                assert [c for c, cues in _CUES.items() if any(q in f" {tail} " for q in cues)] == [cmp_], tail
    for cmp_ in ("max", "min"):
        seen = set()
        for _ in range(60):
            prefix, tail, w = render_sensor_dev2(rng, SensorConstraint(reading, cmp_))
            assert w == SensorConstraint(reading, cmp_) and bool(prefix) != bool(tail)
            seen.add("prefix" if prefix else tail.split()[0])
            text = prefix + tail
            assert any(e in text for e in (_HIGH if cmp_ == "max" else _LOW)), text
            assert not any(e in text for e in (_LOW if cmp_ == "max" else _HIGH)), text
        assert len(seen) >= 3


def test_hints_carry_the_given_numbers():
    rng = gen(2)
    for x, y in (("3.5", "2"), ("-1.2", "0.0"), ("10", "-4.25")):
        forms = set()
        for _ in range(60):
            h = hint_text_dev2(rng, x, y)
            nums = re.findall(r"-?\d+(?:\.\d+)?", h.replace("−", "-"))
            forms.add(re.sub(r"[-−]?\d+(\.\d+)?", "#", h))
            assert [float(n) for n in nums] == [float(x), float(y)], h
            axes = re.findall(r"\b[xy]\b", h)  # named axes come x first, as the numbers do
            assert axes[:2] in ([], ["x", "y"]), h
        assert len(forms) >= 6


_STRICT = ("first things first", "in order", "in this order", "your first stop", "kick off at", "→", "first of all",
           "in sequence", "and, after that,")
_FREE = ("any order", "of your choosing", "no required order", "whichever way round", "entirely up to you",
         "no fixed order", "you decide the order", "however you like")


@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_strict_and_free_wording(n):
    rng = gen(n)
    goals = [render_goal_dev2(rng, Subgoal(0, T(h, ("black", "switched off")), room="study")) for h in HEADS[:n]]
    for _ in range(60):
        for order in ("strict", "free"):
            text = render_instruction_dev2(rng, goals, order)
            low = text.lower()
            assert all(g.lower() in low for g in goals), text
            assert text[0].isupper() and text[-1] in ".?", text
            if n == 1:
                rest = low.replace(goals[0].lower(), "")
                assert rest.count(".") + rest.count("?") == 1, text
            elif order == "strict":
                assert any(c in low for c in _STRICT) and not any(c in low for c in _FREE), text
            else:
                assert any(c in low for c in _FREE), text


def _clean(text):
    bad = ("  ", ",,", ", ,", "()", "( )", " ,", ",.", ",;", ";;", ",?", " ;", " ?", " :", " )", "( ", "— —")
    return not any(b in text for b in bad) and not re.search(r" \.(\s|$)", text) and text == text.strip()


_targets = st.recursive(
    st.builds(T, st.sampled_from(HEADS), st.lists(st.sampled_from(MODS + STATE_VALUES), max_size=3, unique=True)),
    lambda inner: st.builds(T, st.sampled_from(HEADS), st.lists(st.sampled_from(MODS + STATE_VALUES), max_size=2,
                                                                unique=True),
                            st.lists(st.tuples(st.sampled_from(RELATION_TYPES), inner), max_size=2)),
    max_leaves=4,
)
_sensors = st.one_of(
    st.none(),
    st.builds(SensorConstraint, st.sampled_from(("temperature_c", "ndvi", "humidity_pct")),
              st.sampled_from(("max", "min"))),
    st.builds(SensorConstraint, st.just("temperature_c"), st.sampled_from(("gt", "ge", "lt", "le", "approx")),
              st.integers(-30, 400).map(float)),
    st.builds(SensorConstraint, st.just("humidity_pct"), st.sampled_from(("gt", "ge", "lt", "le", "approx")),
              st.integers(0, 100).map(float)),
    st.builds(SensorConstraint, st.just("ndvi"), st.sampled_from(("gt", "ge", "lt", "le", "approx")),
              st.integers(-5, 20).map(lambda k: k * 0.05)),
)
_goals = st.tuples(_targets, st.one_of(st.none(), st.sampled_from(ROOMS)), _sensors, st.booleans())


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(_goals, min_size=1, max_size=5), st.integers(0, 2**31), st.sampled_from(("strict", "free")))
def test_renderers_never_raise_and_write_clean_text(goals, seed, order):
    rng = gen(seed)
    texts = []
    for target, room, sensor, hinted in goals:
        prefix, tail, written = render_sensor_dev2(rng, sensor) if sensor else ("", "", None)
        hint = hint_text_dev2(rng, f"{rng.uniform(-9, 9):.1f}", "2") if hinted else ""
        sg = Subgoal(0, target, room=room, sensors=(written,) if written else ())
        g = render_goal_dev2(rng, sg, prefix, tail, hint)
        assert _clean(g) and g.startswith("the ") and g.count("—") % 2 == 0 and not g.endswith((",", "—")), g
        head = g.index(target.head) if target.head in g else len(g)
        assert not any(re.search(_word(s), g[:head]) for s in target.attributes if s in STATE_VALUES), g
        texts.append(g)
    text = render_instruction_dev2(rng, texts, order)
    assert _clean(text), text
    assert all(g in text or g[0].upper() + g[1:] in text for g in texts), text
