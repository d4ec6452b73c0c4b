"""Set AP's own wording (ragnav_jax/language/phrasings_ap.py): every goal keeps its head noun, attributes, room and
anchors; sensor values come back exactly from the text; coordinate hints read x then y; whole instructions keep the
goals once each in visiting order and say in words whether that order is fixed or free (a single goal says neither);
and the same generator state writes the same text."""

from __future__ import annotations

import math
import re

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_phrasings_dev8 import subgoals

from ragnav_jax.language import phrasings_ap as AP
from ragnav_jax.language.template_text import ONES, TENS
from ragnav_jax.language.types import READINGS, Target

SET = settings(max_examples=50, deadline=None, suppress_health_check=[HealthCheck.too_slow])
NUM = r"-?\d+(?:\.\d+)?"

# ------------------------------------------------------------------------------------------------ helpers


def _has(text: str, phrase: str) -> bool:
    return re.search(r"(?<![\w-])" + re.escape(phrase) + r"(?![\w-])", text) is not None


def _targets(t: Target):
    yield t
    for r in t.relations:
        yield from _targets(r.anchor)


_WORD = {w: i for i, w in enumerate(ONES)} | {w: 10 * i for i, w in enumerate(TENS) if w}


def read_value(text: str) -> float:
    """The one number of a sensor phrase of this set, in digits or in words."""
    text = text.replace("CO2", "CO-two")
    found = re.findall(NUM, text)
    if found:
        assert len(found) == 1, text
        return float(found[0])
    if "nought point" in text:
        neg = "minus nought" in text
        digits = text.split("nought point ", 1)[1].split()
        ds = "".join(str(ONES.index(d)) for d in digits if d in ONES)
        return float(("-" if neg else "") + "0." + ds)
    words = re.findall(r"[a-z]+", text.lower().replace("co-two", "").replace("-", " "))
    total, seen, neg, half = 0, False, False, False
    for i, w in enumerate(words):
        if w == "minus":
            neg = True
        elif w in _WORD:
            total += _WORD[w]
            seen = True
        elif w == "hundred":
            total *= 100
        elif w == "half" and words[i - 1] == "a":
            half = True
    assert seen, text
    v = total + (0.5 if half else 0.0)
    return -v if neg else v


def read_unit(text: str) -> tuple[str, float]:
    """(unit code, factor or marker) of a sensor phrase of this set."""
    for key, code in (("°F", "f"), ("Fahrenheit", "f"), ("°C", "c"), ("degrees C", "c"), ("kW", "kw"),
                      (" W", "w"), ("watts", "w"), ("%", "%"), ("per cent", "%"), ("percent", "%"),
                      ("ppm", "ppm"), ("parts per million", "ppm"), ("dB", "db"), ("decibels", "db"),
                      ("lux", "lux"), ("kg", "kg"), ("kilo", "kg"), ("hPa", "hpa"), ("millibars", "mbar")):
        if key in text:
            return code
    return ""


def canonical(v: float, unit: str) -> float:
    return (v - 32.0) * 5.0 / 9.0 if unit == "f" else v * 1000.0 if unit == "kw" else v


def read_comparator(text: str) -> str:
    checks = (("approx", r"about|roughly|region of|more or less|somewhere near"),
              ("ge", r"at least|or more\b|no lower than|or above|not below|or warmer"),
              ("le", r"or less\b|at most|no higher than|or below|not over|or cooler|no more than"),
              ("gt", r"\bover\b|above|more than|higher than|in excess of|hotter than|louder than|brighter than"),
              ("lt", r"under|below|less than|lower than|beneath|colder than|quieter than|dimmer than"))
    for cmp_, pat in checks:
        if re.search(pat, text):
            return cmp_
    raise AssertionError(text)


_VALUES = {"temperature_c": st.integers(-30, 400).map(float) | st.sampled_from([20.5, -2.5, 37.5, 40.0]),
           "ndvi": st.sampled_from([0.65, 0.2, -0.1, 0.85, 0.5, 0.123]),
           "humidity_pct": st.integers(0, 100).map(float), "battery_pct": st.integers(0, 100).map(float),
           "co2_ppm": st.integers(300, 5000).map(float), "noise_db": st.integers(20, 120).map(float),
           "light_lux": st.integers(0, 2000).map(float), "power_w": st.sampled_from([60.0, 1500.0, 2000.0, 1234.0]),
           "weight_kg": st.sampled_from([2.5, 12.0, 0.75, 150.0]),
           "pressure_hpa": st.sampled_from([1013.25, 990.0, 1020.0])}


@st.composite
def constraints(draw):
    reading = draw(st.sampled_from(READINGS))
    cmp_ = draw(st.sampled_from(("lt", "le", "gt", "ge", "approx", "max", "min")))
    value = None if cmp_ in ("max", "min") else draw(_VALUES[reading])
    return AP.SensorConstraint(reading, cmp_, value, "")


# ------------------------------------------------------------------------------------------------ goals


@SET
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    text = AP.render_goal_ap(np.random.default_rng(seed), sg)
    assert _has(text, sg.target.head), text
    for t in _targets(sg.target):
        assert _has(text, t.head), (t.head, text)
        for a in t.attributes:
            assert _has(text, a) or _has(text, a.replace(" ", "-")), (a, text)
    if sg.room:
        assert _has(text, sg.room), text
    assert text.count("(") == text.count(")") and not re.search(r"\d", text)


@SET
@given(sg=subgoals(), c=constraints(), seed=st.integers(0, 2**31), x=st.integers(-900, 900), y=st.integers(-900, 900))
def test_goal_keeps_sensor_then_hint(sg, c, seed, x, y):
    """The sensor words stand in the goal verbatim and the hint's numbers come last, x then y."""
    rng = np.random.default_rng(seed)
    xs, ys = f"{x / 100:g}", f"{y / 10:g}"
    pre, tail, _ = AP.render_sensor_ap(rng, c)
    text = AP.render_goal_ap(rng, sg, prefix=pre, tail=tail, hint=AP.hint_text_ap(rng, xs, ys))
    assert _has(text, sg.target.head) and (not pre or pre in text) and (not tail or tail in text), text
    nums = [float(v) for v in re.findall(NUM, text)]
    assert nums[-2:] == [float(xs), float(ys)], text


# ------------------------------------------------------------------------------------------------ sensors


@SET
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_values_come_back_from_the_text(c, seed):
    pre, tail, got = AP.render_sensor_ap(np.random.default_rng(seed), c)
    assert (got.reading, got.comparator) == (c.reading, c.comparator)
    if c.is_superlative:
        assert got.value is None and bool(pre) != bool(tail) and not re.search(r"\d", (pre + tail).replace("CO2", ""))
        words = pre + " " + tail
        up = re.search(r"highest|top|most(?! or)|warmest|hottest|dampest|loudest|noisiest|brightest|best-|heaviest",
                       words)
        down = re.search(r"lowest|smallest|least|coldest|coolest|driest|quietest|dimmest", words)
        assert bool(up) == (c.comparator == "max") and bool(down) == (c.comparator == "min"), words
        return
    assert pre == "" and tail, tail
    unit = read_unit(tail)
    assert got.unit == unit and got.value == c.value, (tail, got)
    assert math.isclose(canonical(read_value(tail), unit), c.value, rel_tol=1e-9, abs_tol=1e-9), (tail, c)
    assert read_comparator(tail) == c.comparator, tail


def test_sensor_wording_varies():
    rng = np.random.default_rng(0)
    seen = {AP.render_sensor_ap(rng, AP.SensorConstraint("temperature_c", "ge", 40.0))[1] for _ in range(300)}
    assert any("°F" in s for s in seen) and any("forty" in s for s in seen) and any("40 °C" in s for s in seen)
    ndvi = {AP.render_sensor_ap(rng, AP.SensorConstraint("ndvi", "approx", 0.65))[1] for _ in range(200)}
    assert any("nought point six five" in s for s in ndvi) and any("0.65" in s for s in ndvi)
    power = {AP.render_sensor_ap(rng, AP.SensorConstraint("power_w", "gt", 1500.0))[1] for _ in range(200)}
    assert any("1.5 kW" in s for s in power)


# ------------------------------------------------------------------------------------------------ hints


@SET
@given(x=st.integers(-2000, 2000), y=st.integers(-2000, 2000), seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    xs, ys = f"{x / 100:g}", f"{y / 100:g}"
    text = AP.hint_text_ap(np.random.default_rng(seed), xs, ys)
    assert [float(v) for v in re.findall(NUM, text)] == [float(xs), float(ys)], text


# ------------------------------------------------------------------------------------------------ instructions

STRICT = re.compile(r"in the order listed|don't jump the queue|strictly in sequence|order's fixed|in this exact order|"
                    r"no skipping ahead|in the order I say|none out of turn|in strict sequence|keep to the call|"
                    r"don't skip ahead|in exactly this order|in the order you see them", re.I)
FREE = re.compile(r"no set order|up to you|at your discretion|whatever order|pick whichever|makes no odds|"
                  r"any bell may lead|no set method|no right order|no wrong way round|whichever way round|"
                  r"whatever sequence|yours to choose", re.I)
SEQUENCE_WORDS = re.compile(r"\b(first|then|next|finally|lastly|after that|to finish)\b", re.I)
VOICES = {"plumber": r"JOB SHEET|Work order|Van sheet", "stylist": r"babe|hun\b|lovely",
          "ringer": r"Look to!|Tower captain|Practice night", "vlogger": r"guys|everyone!"}


def _frame(text: str, res: list[str]) -> str:
    """The instruction with its goals cut out (checks they stand once each, in visiting order)."""
    low, at, out = text.lower(), 0, []
    for g in res:
        i = low.find(g.lower(), at)
        assert i >= 0, (g, text)
        out.append(text[at:i])
        at = i + len(g)
    out.append(text[at:])
    return " <G> ".join(out)


@SET
@given(sgs=st.lists(subgoals(), min_size=1, max_size=6), seed=st.integers(0, 2**31), strict=st.booleans())
def test_goals_once_in_order_and_order_told(sgs, seed, strict):
    rng = np.random.default_rng(seed)
    res = [AP.render_goal_ap(rng, sg) for sg in sgs]
    text = AP.render_instruction_ap(rng, res, "strict" if strict else "free")
    frame = _frame(text, res)
    assert frame.count("<G>") == len(res)
    if len(res) == 1:
        assert not STRICT.search(frame) and not FREE.search(frame) and not SEQUENCE_WORDS.search(frame), text
        assert not re.search(r"\d", frame) and "order" not in frame.lower().replace("work order", ""), text
    elif strict:
        assert STRICT.search(frame) and not FREE.search(frame), text
    else:
        assert FREE.search(frame) and not STRICT.search(frame) and not SEQUENCE_WORDS.search(frame), text


@SET
@given(n=st.integers(1, 7), seed=st.integers(0, 2**31), strict=st.booleans())
def test_each_goal_written_exactly_once(n, seed, strict):
    res = [f"the quokka-{ONES[i + 1]} widget" for i in range(n)]
    text = AP.render_instruction_ap(np.random.default_rng(seed), res, "strict" if strict else "free")
    assert all(text.count(g) == 1 for g in res), text
    assert [text.index(g) for g in res] == sorted(text.index(g) for g in res), text


def test_all_four_voices_write():
    rng = np.random.default_rng(7)
    seen = set()
    for _ in range(200):
        text = AP.render_instruction_ap(rng, ["the lamp", "the drums"], "strict")
        hits = [v for v, pat in VOICES.items() if re.search(pat, text)]
        assert len(hits) == 1, text
        seen.update(hits)
    assert seen == set(VOICES)


@SET
@given(sgs=st.lists(subgoals(), min_size=1, max_size=4), seed=st.integers(0, 2**31), strict=st.booleans(),
       c=constraints())
def test_same_state_same_text(sgs, seed, strict, c):
    def run():
        rng = np.random.default_rng(seed)
        pre, tail, got = AP.render_sensor_ap(rng, c)
        res = [AP.render_goal_ap(rng, sg, pre, tail, AP.hint_text_ap(rng, "3.5", "2")) for sg in sgs]
        return res, got, AP.render_instruction_ap(rng, res, "strict" if strict else "free")

    assert run() == run()
