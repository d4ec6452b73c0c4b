"""Held-out set AJ (ragnav_jax/language/phrasings_aj.py): a railway announcer, a knitting-pattern writer, a software
ticket writer and a texting teenager. Every goal keeps its head, attributes, room and anchors; the instruction keeps
every goal's text in visiting order and says strict or free in its own words (a single goal neither, and no digit);
sensor values stay exact; coordinate hints are x then y."""

from __future__ import annotations

import re
from decimal import Decimal

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_phrasings_dev8 import subgoals

from ragnav_jax.config import EPISODE_SPLITS
from ragnav_jax.language import phrasings_aj as A
from ragnav_jax.language.episodes import UNSEEN_TEMPLATES, _renderer
from ragnav_jax.language.template_text import number_words
from ragnav_jax.language.types import READINGS, Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=50, deadline=None, suppress_health_check=[HealthCheck.too_slow])
NUM = r"-?\d+(?:\.\d+)?"

# the set's own cues (lower case), as a test of what it writes, not a reader
STRICT = ("strictly in the order announced", "stopping in that order", "out of sequence", "calling pattern fixed",
          "in sequence only", "in the order read out", "work the rows in order", "strictly in the order written",
          "worked in sequence", "in this exact order", "only once the previous round is complete",
          "blocked by the one before it", "hard ordering constraint", "stages run sequentially", "in that order",
          "do them in order", "dont skip ahead")
FREE = ("any order", "in whichever order", "in no fixed order", "no fixed calling pattern",
        "not necessarily in the order announced", "in whatever order", "in no set order", "entirely up to you",
        "independent", "unordered", "idc what order", "order doesnt matter", "whatever order u want")
VOICES = {"announcer": ("platform", "service", "departures", "announcement", "hop-on", "attention please",
                        "rover ticket", "mind the gap", "train", "ladies and gentlemen"),
          "knitter": ("cast on", "motif", "row 1", "rnd 1", "squares", "pattern notes", "fasten off"),
          "ticket": ("[task]", "[story]", "[backlog]", "[chore]", "quick ticket"),
          "texter": ("heyyy", "ok so", "hiii", "omg ok", "yo ")}


def _norm(text: str) -> str:
    return " " + re.sub(r"[^a-z0-9]+", " ", re.sub(r"'s\b", "", text.lower().replace("-", " "))) + " "


def _has(text: str, phrase: str) -> bool:
    return _norm(phrase) in _norm(text)


def _all_targets(t: Target):
    yield t
    for r in t.relations:
        yield from _all_targets(r.anchor)


def _without(text: str, res: list[str]) -> str:
    """The instruction with its goals taken out: what the voice itself wrote."""
    low = text.lower()
    for g in res:
        low = low.replace(g.lower(), " ", 1)
    return low


def test_split_is_wired():
    assert "unseen_aj" in EPISODE_SPLITS
    assert EPISODE_SPLITS.index("unseen_aj") == EPISODE_SPLITS.index("unseen_ai") + 1
    assert UNSEEN_TEMPLATES["unseen_aj"] == ("phrasings_aj", "aj")
    assert _renderer("unseen_aj", "goal") is A.render_goal_aj
    assert _renderer("unseen_aj", "sensor") is A.render_sensor_aj
    assert _renderer("unseen_aj", "hint") is A.hint_text_aj
    assert _renderer("unseen_aj", "instruction") is A.render_instruction_aj


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=4), seed=st.integers(0, 2**31), strict=st.booleans())
def test_same_seed_same_text(sgs, seed, strict):
    def run():
        rng = np.random.default_rng(seed)
        res = [A.render_goal_aj(rng, sg, hint=A.hint_text_aj(rng, "3.5", "2")) for sg in sgs]
        extra = A.render_sensor_aj(rng, SensorConstraint("temperature_c", "ge", 20.0))
        return res, extra, A.render_instruction_aj(rng, res, "strict" if strict else "free")

    assert run() == run()


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    text = A.render_goal_aj(np.random.default_rng(seed), sg)
    assert text.startswith("the ") and text == text.strip(" ,") and "\n" not in text and ";" not in text
    assert sg.target.head in text  # the head itself, unhyphenated and whole
    for t in _all_targets(sg.target):
        assert _has(text, t.head), (t.head, text)
        for a in t.attributes:
            assert _has(text, a), (a, text)
    if sg.room:
        assert _has(text, sg.room), text
    assert text.count("(") == text.count(")")


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=5), seed=st.integers(0, 2**31), strict=st.booleans())
def test_instruction_keeps_goals_in_order_and_says_the_order(sgs, seed, strict):
    rng = np.random.default_rng(seed)
    res = [A.render_goal_aj(rng, sg) for sg in sgs]
    text = A.render_instruction_aj(rng, res, "strict" if strict else "free")
    low, at = text.lower(), 0
    for sg, g in zip(sgs, res):
        assert sg.target.head in low
        found = low.find(g.lower(), at)
        assert found >= 0, (g, text)
        at = found + len(g)
    voice = _without(text, res)
    strict_cue, free_cue = any(c in voice for c in STRICT), any(c in voice for c in FREE)
    if len(res) == 1:
        assert not strict_cue and not free_cue and not re.search(r"\d", voice), text
    elif strict:
        assert strict_cue and not free_cue, text
    else:
        assert free_cue and not strict_cue, text


def test_each_voice_speaks_and_single_goals_carry_no_cue():
    sg = Subgoal(0, Target("teal lamp", "lamp", ("teal",)), room="nursery")
    seen = {v: 0 for v in VOICES}
    for seed in range(200):
        for res, order in (([f"the lamp {seed}"], "strict"), (["the lamp", "the sofa", "the drums"], "free")):
            text = A.render_instruction_aj(np.random.default_rng(seed), res, order).lower()
            voice = _without(text, res)
            who = [v for v, marks in VOICES.items() if any(m in voice for m in marks)]
            assert len(who) == 1, text
            seen[who[0]] += 1
            if len(res) == 1:
                assert not any(c in voice for c in STRICT + FREE) and not re.search(r"\d", voice), text
            else:
                assert any(c in voice for c in FREE) and not any(c in voice for c in STRICT), text
    assert all(n > 20 for n in seen.values()), seen
    goal = A.render_goal_aj(np.random.default_rng(0), sg)
    assert "lamp" in goal and "teal" in goal and "nursery" in goal


@pytest.mark.parametrize("xy", [("3.5", "2"), ("-1.25", "0"), ("12", "-7.5"), ("0.5", "0.5")])
def test_hint_numbers_are_x_then_y(xy):
    x, y = xy
    sg = Subgoal(0, Target("lamp", "lamp", (), (Relation("near", Target("sofa", "sofa")),)), room="kitchen",
                 location=Location(float(x), float(y)))
    for seed in range(60):
        rng = np.random.default_rng(seed)
        hint = A.hint_text_aj(rng, x, y)
        assert re.findall(NUM, hint) == [x, y], hint
        text = A.render_goal_aj(rng, sg, hint=hint)
        assert [float(v) for v in re.findall(NUM, text)][-2:] == [float(x), float(y)], text
        assert text.index("lamp") < text.index(hint) < text.index("sofa"), text  # hint after the noun, before anchors


def _expected(written: SensorConstraint) -> set[str]:
    v = Decimal(A._digits(written.value))
    if written.unit == "f":
        return {A._dec_text(v * 9 / 5 + 32)}
    if written.unit == "kw":
        return {A._dec_text(v / 1000)}
    out = {A._digits(written.value)}
    if float(written.value).is_integer():
        out.add(number_words(int(written.value)))
    return out


@pytest.mark.parametrize("reading", READINGS)
def test_sensor_values_stay_exact(reading):
    for value in (40.0, 22.5, 0.65, -4.0, 1500.0, 1013.25, 7.0):
        for cmp in ("gt", "ge", "lt", "le", "approx"):
            c = SensorConstraint(reading, cmp, value)
            for seed in range(25):
                prefix, tail, written = A.render_sensor_aj(np.random.default_rng(seed), c)
                assert prefix == "" and tail and written.value == value, (prefix, tail, written)
                assert (written.reading, written.comparator) == (reading, cmp)
                body = tail.replace("CO2", "CO two")
                nums = set(re.findall(NUM, body))
                exp = _expected(written)
                assert nums & exp or any(w in body for w in exp if not w[0].isdigit() and w[0] != "-"), (tail, exp)
                assert len(nums) <= 1, tail  # one number, and only the value's
    for cmp in ("max", "min"):
        for seed in range(25):
            prefix, tail, written = A.render_sensor_aj(np.random.default_rng(seed), SensorConstraint(reading, cmp))
            assert bool(prefix) != bool(tail) and written == SensorConstraint(reading, cmp, None, "")
            assert not re.search(r"\d", (prefix + tail).replace("CO2", "")), (prefix, tail)


def test_temperatures_in_fahrenheit_convert_exactly():
    seen = set()
    for seed in range(300):
        c = SensorConstraint("temperature_c", "le", 22.5)
        _, tail, written = A.render_sensor_aj(np.random.default_rng(seed), c)
        assert written.value == 22.5
        if written.unit == "f":
            assert "72.5" in tail and "F" in tail, tail
        seen.add(written.unit)
    assert seen == {"c", "f"}


def test_sensor_tails_and_prefixes_sit_in_the_goal():
    sg = Subgoal(0, Target("teal lamp", "lamp", ("teal", "switched on")), room="kitchen",
                 sensors=(SensorConstraint("temperature_c", "max"),))
    for seed in range(80):
        rng = np.random.default_rng(seed)
        prefix, tail, _ = A.render_sensor_aj(rng, SensorConstraint("temperature_c", "max"))
        text = A.render_goal_aj(rng, sg, prefix=prefix, tail=tail)
        assert (prefix + tail) in text
        if prefix:
            assert text.index(prefix) < text.index("lamp"), text
        else:  # the room first, and the tail the goal's own
            assert text.index("kitchen") < text.index(tail) and text.index("lamp") < text.index(tail), text


def test_anchor_relations_are_bracketed():
    inner = Target("sofa", "sofa", (), (Relation("by", Target("drums", "drums")),))
    sg = Subgoal(0, Target("lamp", "lamp", (), (Relation("near", inner), Relation("under", Target("shelves",
                                                                                                  "shelves")))))
    for seed in range(40):
        text = A.render_goal_aj(np.random.default_rng(seed), sg)
        assert re.search(r"sofa \(the one[^()]*drums[^()]*\)", text), text
        assert text.index("lamp") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
