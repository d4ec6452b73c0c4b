"""Set AM's own wording (ragnav_jax/language/phrasings_am.py): every goal keeps its head, pieces and hint, numbers
come back exactly, the four voices say fixed and free order in their own words, and a single goal gets no cue."""

from __future__ import annotations

import re

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_phrasings_dev8 import subgoals

from ragnav_jax.language import phrasings_am as M
from ragnav_jax.language.template_text import attributes_and_states
from ragnav_jax.language.types import READINGS, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=50, deadline=None, suppress_health_check=[HealthCheck.too_slow])

STRICT_CUES = (r"in sequence, no freelancing|in the order briefed|not a fin-kick sooner|strict procession|out of turn|"
               r"put your week in order|order is written in the sky|in sequence as wired|in order given|"
               r"none ahead of its turn|sequence essential|in the order they're booked|in running order|only then|"
               r"same order as the poster")
FREE_CUES = (r"whatever sequence|no set order|doesn't matter a jot|care not a jot|however you please|"
             r"no sequence this time|any order|order of calls your own affair|no preference as to order|"
             r"no fixed routing|routing's your call|doesn't care which")
VOICES = {"dive": r"\bdive\b|Buddy pairs|DIVE PLAN|No fixed profile",
          "stars": "|".join(M._SIGNS),
          "wire": r"\bSTOP\b",
          "tour": r"\btour\b|TOUR DATES|Festival season|Pop-up gigs|dates on the calendar|One-off show|Load in at"}

_WORDS = {w: i for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine",
                                       "ten", "eleven", "twelve", "thirteen", "fourteen", "fifteen", "sixteen",
                                       "seventeen", "eighteen", "nineteen"))}
_WORDS |= {w: 10 * i for i, w in enumerate(("twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty",
                                             "ninety"), 2)}
_NUMBER_WORD = r"(?:" + "|".join(sorted(_WORDS, key=len, reverse=True)) + r")"


def _read_value(text: str, unit: str) -> float:
    """The number a sensor phrase writes, in the reading's canonical unit (a small reader of AM's own formats)."""
    text = text.replace("CO2", "")
    m = re.search(r"\b(minus )?(?:zero )?point((?: " + _NUMBER_WORD + r"\b)+)", text)
    if m:
        v = float("0." + "".join(str(_WORDS[w]) for w in m.group(2).split()))
        v = -v if m.group(1) else v
    elif m := re.search(r"(minus |-|−)?(\d[\d,]*(?:\.\d+)?|\.\d+)(½)?", text):
        v = float(m.group(2).replace(",", "")) + (0.5 if m.group(3) else 0.0)
        v = -v if m.group(1) else v
    else:
        m = re.search(r"\b(minus )?((?:" + _NUMBER_WORD + r"|a half)(?:[ -](?:" + _NUMBER_WORD
                      + r"|hundred|and|a|half)\b)*)\b", text)
        assert m, text
        v = 0.0
        for w in re.split(r"[ -]", m.group(2)):
            if w in _WORDS:
                v += _WORDS[w]
            elif w == "hundred":
                v *= 100
            elif w == "half":
                v += 0.5
        v = -v if m.group(1) else v
    if unit == "f":
        return (v - 32) * 5 / 9
    if unit == "kw":
        return v * 1000
    return v


def _anchors(t: Target):
    for r in t.relations:
        yield r.anchor
        yield from _anchors(r.anchor)


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    text = M.render_goal_am(np.random.default_rng(seed), sg)
    assert text.startswith("the ") and re.search(rf"\b{re.escape(sg.target.head)}\b", text), text
    for t in (sg.target, *_anchors(sg.target)):
        pre, states = attributes_and_states(t)
        assert t.head in text
        for a in pre:
            assert a in text, (a, text)
        for s in states:
            assert s in text or s.replace(" ", "-") in text, (s, text)
    if sg.room:
        assert sg.room in text
    assert text.count("(") == text.count(")") and not re.search(r"\d", text)


_VALUES = st.integers(-30, 400).map(float) | st.sampled_from([20.5, -2.5, 37.5, 0.65, 0.05, -0.1, 1013.25, 1500.0,
                                                              1200.0, 2000.0, 0.5])


@SETTINGS
@given(reading=st.sampled_from(READINGS), cmp=st.sampled_from(["gt", "ge", "lt", "le", "approx"]), value=_VALUES,
       seed=st.integers(0, 2**31))
def test_numbers_come_back_exactly(reading, cmp, value, seed):
    prefix, tail, written = M.render_sensor_am(np.random.default_rng(seed), SensorConstraint(reading, cmp, value))
    assert prefix == "" and tail and (written.reading, written.comparator, written.value) == (reading, cmp, value)
    assert abs(_read_value(tail, written.unit) - value) < 1e-9, (tail, written)
    if reading == "temperature_c":
        assert written.unit in ("c", "f") and ("F" in tail) == (written.unit == "f")


@SETTINGS
@given(reading=st.sampled_from(READINGS), cmp=st.sampled_from(["max", "min"]), seed=st.integers(0, 2**31))
def test_superlatives_carry_no_number(reading, cmp, seed):
    prefix, tail, written = M.render_sensor_am(np.random.default_rng(seed), SensorConstraint(reading, cmp))
    assert bool(prefix) != bool(tail) and written == SensorConstraint(reading, cmp, None, "")
    assert not re.search(r"\d", prefix + tail.replace("CO2", ""))


def test_a_few_exact_values():
    seen = set()
    for seed in range(300):
        _, tail, w = M.render_sensor_am(np.random.default_rng(seed), SensorConstraint("temperature_c", "ge", 40.0))
        seen.add(w.unit)
        assert abs(_read_value(tail, w.unit) - 40.0) < 1e-9, tail
    assert seen == {"c", "f"}
    assert _read_value("whose NDVI is roughly zero point six five", "") == 0.65
    assert _read_value("that runs −2½ °C or cooler", "c") == -2.5
    assert _read_value("of more than thirty-seven and a half per cent", "%") == 37.5
    assert _read_value("that is more than 1.5 kW", "kw") == 1500.0


@SETTINGS
@given(x=st.sampled_from(["3.5", "-1.25", "0", "12", "7.75"]), y=st.sampled_from(["2", "-4.5", "0.5", "10"]),
       sg=subgoals(), seed=st.integers(0, 2**31))
def test_hint_gives_x_then_y_last(x, y, sg, seed):
    rng = np.random.default_rng(seed)
    hint = M.hint_text_am(rng, x, y)
    assert re.findall(r"-?\d+(?:\.\d+)?", hint) == [x, y] and "x" in hint and "y" in hint
    prefix, tail, c = M.render_sensor_am(rng, SensorConstraint("temperature_c", "lt", 22.5))
    sg = Subgoal(0, sg.target, room=sg.room, sensors=(c,))
    text = M.render_goal_am(rng, sg, prefix, tail, hint)
    assert re.findall(r"-?\d+(?:\.\d+)?", text)[-2:] == [x, y], text


def _wrapper(text: str, res: list[str]) -> str:
    """The instruction with its goals cut out, checking they stand in visiting order, each as rendered (a goal that
    opens a sentence may have its first letter raised)."""
    at, out = 0, ""
    for r in res:
        i = text.lower().find(r.lower(), at)
        assert i >= 0 and text[i + 1:i + len(r)] == r[1:], (r, text)
        out += text[at:i] + " ‹goal› "
        at = i + len(r)
    return out + text[at:]


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=5), seed=st.integers(0, 2**31), strict=st.booleans())
def test_instruction_keeps_goals_and_says_the_order(sgs, seed, strict):
    rng = np.random.default_rng(seed)
    res = [M.render_goal_am(rng, sg, hint=M.hint_text_am(rng, "3.5", "2")) for sg in sgs]
    text = M.render_instruction_am(rng, res, "strict" if strict else "free")
    for sg in sgs:
        assert sg.target.head in text
    rest = _wrapper(text, res)
    if len(res) == 1:
        assert not re.search(STRICT_CUES, rest) and not re.search(FREE_CUES, rest) and not re.search(r"\d", rest)
        assert not re.search(r"\b(first|then|next|last|lastly|finally|after)\b", rest, re.I), rest
    elif strict:
        assert re.search(STRICT_CUES, rest) and not re.search(FREE_CUES, rest), rest
    else:
        assert re.search(FREE_CUES, rest) and not re.search(STRICT_CUES, rest), rest
        assert not re.search(r"\b(first|then|next|last|lastly|finally|after that)\b", rest, re.I), rest


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=4), seed=st.integers(0, 2**31), strict=st.booleans())
def test_same_seed_same_text(sgs, seed, strict):
    def run():
        rng = np.random.default_rng(seed)
        res = [M.render_goal_am(rng, sg, hint=M.hint_text_am(rng, "1.5", "-3")) for sg in sgs]
        sensor = M.render_sensor_am(rng, SensorConstraint("humidity_pct", "le", 40.0))
        return res, sensor, M.render_instruction_am(rng, res, "strict" if strict else "free")

    assert run() == run()


def test_every_voice_speaks_in_every_mode():
    goals = ["the lamp", "the teal sofa in the nursery", "the drums"]
    for order, res in (("strict", goals), ("free", goals), ("strict", goals[:1])):
        seen = set()
        for seed in range(200):
            text = M.render_instruction_am(np.random.default_rng(seed), res, order)
            hits = [v for v, pat in VOICES.items() if re.search(pat, text)]
            assert len(hits) == 1, (hits, text)
            seen.add(hits[0])
        assert seen == set(VOICES), (order, seen)
