"""Set AU's own wording (ragnav_jax/language/phrasings_au.py), checked with tiny inputs: every voice and layout
says a strict order is fixed and a free one open, in words, and a single goal neither; goals stand verbatim, in
order, set off by semicolons, new lines or sequence words, and the frames add no digit; each goal's head,
attributes, states, room, sensor tail, coordinate hint and relations stand where the style guide puts them;
sensor numbers and hints read back exactly; the same seed writes the same text.

Broken on purpose: (1) the job card's strict cue was swapped for a sign-off, and
test_order_cues_in_every_voice_and_frame (on the job card), test_the_public_writer_reaches_every_voice_and_frame
and test_same_seed_same_text failed; (2) hint_text_au wrote y before x in two of its five forms, and
test_goal_parts_in_place, test_hint_reads_back_x_then_y and test_sensor_tail_room_and_hint_in_their_places failed.
Both were restored."""

from __future__ import annotations

import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_phrasings_dev8 import subgoals

from ragnav_jax.language import phrasings_au as AU
from ragnav_jax.language.template_text import ONES, TENS, attributes_and_states, is_are
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

STRICT = re.compile(r"\bin (?:the|this|that) (?:order|sequence)\b|\bin route order\b|\bin log order\b|\bin sequence\b"
                    r"|\bout of (?:turn|sequence)\b|\bin turn\b|\bsame order\b|\border is fixed\b|\bdon't reorder\b"
                    r"|\bkeep to (?:that|it)\b|\bstrictly as listed\b|\bno jumping ahead\b|\bskip ahead\b"
                    r"|\bafter the one (?:above|before)\b", re.I)
FREE = re.compile(r"\bany order\b|\bwhatever order\b|\bwhichever order\b|\bno particular order\b|\bdiscretion\b"
                  r"|\bup to you\b|\byour call\b|\bnot important\b|\bdoesn't matter\b|\bnot relevant\b"
                  r"|\bno rounding order\b|\bfree course\b", re.I)
NUM = re.compile(r"-?\d+(?:\.\d+)?")
GOALS = ["the lamp", "the teal sofa in the nursery, at x 1.5, y -2", "the drums next to the toolbox",
         "the kitchen's olive cactus whose humidity is at most 40%", "the open chest freezer, where x is 3 and y is 4"]


def _write(voice: int, frame: int, seed: int, res: list[str], order: str) -> str:
    return AU._VOICES[voice](np.random.default_rng(seed), list(res), order, frame)


def _check_frame(text: str, res: list[str], order: str) -> None:
    low = text.lower()
    at, rest = 0, text
    for i, g in enumerate(res):  # verbatim, in order, never joined by a bare 'and'
        j = text.find(g, at)
        assert j >= 0, (g, text)
        if i:
            between = text[at:j]
            assert re.search(r";|\n|\bthen\b|\bafter that\b|\bfinally\b|\blast\b", between), (between, text)
            assert between.strip(" ,") != "and", text
        at = j + len(g)
        rest = rest.replace(g, " ", 1)
    assert not re.search(r"\d", rest), text  # the frame adds no digit
    if len(res) == 1:
        assert not STRICT.search(low) and not FREE.search(low), text
    elif order == "strict":
        assert STRICT.search(low) and not FREE.search(low), text
    else:
        assert FREE.search(low) and not STRICT.search(low), text


@pytest.mark.parametrize("voice", range(len(AU._VOICES)))
@pytest.mark.parametrize("frame", range(AU._FRAMES))
def test_order_cues_in_every_voice_and_frame(voice, frame):
    for seed in range(40):
        for n in (1, 2, 3, 5):
            for order in ("strict", "free"):
                _check_frame(_write(voice, frame, seed, GOALS[:n], order), GOALS[:n], order)


def test_the_public_writer_reaches_every_voice_and_frame(monkeypatch):
    seen = set()

    def spy(v, f):
        def call(rng, res, order, frame):
            seen.add((v, frame))
            return f(rng, res, order, frame)
        return call

    monkeypatch.setattr(AU, "_VOICES", tuple(spy(v, f) for v, f in enumerate(AU._VOICES)))
    for seed in range(300):
        n = 1 + seed % 4
        order = ("strict", "free")[seed % 2]
        _check_frame(AU.render_instruction_au(np.random.default_rng(seed), GOALS[:n], order), GOALS[:n], order)
    assert seen == {(v, f) for v in range(4) for f in range(AU._FRAMES)}


def _phrases(t: Target):
    yield t
    for r in t.relations:
        yield from _phrases(r.anchor)


HINTS = (("3.5", "2"), ("-1.25", "0"), ("10", "7.75"), ("0.5", "-3"))


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(sg=subgoals(), seed=st.integers(0, 2**31), hint=st.sampled_from((None, *HINTS)))
def test_goal_parts_in_place(sg, seed, hint):
    rng = np.random.default_rng(seed)
    h = "" if hint is None else AU.hint_text_au(rng, *hint)
    text = AU.render_goal_au(rng, sg, hint=h)
    t = sg.target
    _, states = attributes_and_states(t)
    assert text.startswith("the ") and t.head in text and t.phrase in text, text
    for s in states:  # before the noun, hyphenated, or after it in a clause
        assert f"{s.replace(' ', '-')} {t.phrase}" in text or f"{t.phrase} that {is_are(t.head)} {s}" in text, text
    if sg.room:  # straight after the noun, or a possessive before it
        assert f"{t.phrase} in the {sg.room}" in text or text.startswith(f"the {sg.room}'s "), text
    nums = NUM.findall(text)
    if hint is None:
        assert nums == []
    else:
        assert nums == list(hint), text  # x then y, exactly as given, no other digit
        assert text.index(h) > text.index(t.phrase)
    anchors = list(_phrases(t))[1:]
    for a in anchors:
        assert f" {a.phrase}" in text, (a.phrase, text)
        if a.relations:  # an anchor's own relations in brackets straight after it
            assert re.search(re.escape(a.phrase) + r" \((?:the one|the ones|which is|which are|itself|themselves) ",
                             text), text
    if t.relations and h:  # relations come after the hint
        assert text.rindex(f" {t.relations[0].anchor.phrase}") > text.index(h)


def test_hint_reads_back_x_then_y():
    for seed in range(60):
        for x, y in HINTS:
            h = AU.hint_text_au(np.random.default_rng(seed), x, y)
            assert NUM.findall(h) == [x, y], h
            assert h.index(" x") < h.index(" y") if " x" in h and " y" in h else True
            assert re.search(r"\bx\b", h) and re.search(r"\by\b", h), h


_WORD = {w: i for i, w in enumerate(ONES)} | {w: 10 * i for i, w in enumerate(TENS) if w}
_WORDS = re.compile(r"\b(minus )?(" + "|".join(sorted((w for w in _WORD), key=len, reverse=True))
                    + r")(?:-(" + "|".join(ONES[1:10]) + r"))?\b")


def _read_number(text: str) -> float:
    digits = NUM.findall(text)
    if digits:
        assert len(digits) == 1, text
        return float(digits[0])
    m = _WORDS.search(text)
    assert m, text
    n = _WORD[m.group(2)] + (_WORD[m.group(3)] if m.group(3) else 0)
    return float(-n if m.group(1) else n)


UNITS = ((r"°F|Fahrenheit", "f"), (r"°C|Celsius", "c"), (r"kW\b|kilowatts", "kw"), (r"%|per cent", "%"),
         (r"ppm|parts per million", "ppm"), (r"dB\b|decibels", "db"), (r"\blux\b", "lux"), (r"\bW\b|watts", "w"),
         (r"\bkg\b|kilograms", "kg"), (r"hPa|hectopascals", "hpa"))
NAMES = {"temperature_c": r"temperature|warmer|colder|warmest|coldest", "ndvi": r"NDVI",
         "humidity_pct": r"humid|dri|damp", "co2_ppm": r"carbon dioxide",
         "noise_db": r"nois|louder|quieter|loudest|quietest", "light_lux": r"light level", "battery_pct": r"battery",
         "power_w": r"power", "weight_kg": r"weigh|heaviest", "pressure_hpa": r"pressure"}
CMP = {"gt": r"above|over|more than|higher than|warmer|louder",
       "lt": r"below|under|less than|lower than|colder|quieter",
       "ge": r"at least|or more|no less than", "le": r"at most|or less|no more than|no higher than",
       "approx": r"about|roughly|around", "max": r"highest|warmest|most|dampest|loudest|noisiest|heaviest",
       "min": r"lowest|coldest|driest|least|quietest"}
CONSTRAINTS = [SensorConstraint(r, c, v) for r, vals in (
    ("temperature_c", (40.0, 22.5, -4.0, 20.0, 37.0)), ("ndvi", (0.65, 0.3)), ("humidity_pct", (40.0, 62.5)),
    ("co2_ppm", (800.0,)), ("noise_db", (55.0,)), ("light_lux", (300.0,)), ("battery_pct", (15.0,)),
    ("power_w", (1500.0, 60.0, 2250.0)), ("weight_kg", (12.5,)), ("pressure_hpa", (1013.0,)))
    for v in vals for c in ("gt", "lt", "ge", "le", "approx")]
CONSTRAINTS += [SensorConstraint(r, c) for r in NAMES for c in ("max", "min")]


@pytest.mark.parametrize("c", CONSTRAINTS, ids=lambda c: f"{c.reading}-{c.comparator}-{c.value}")
def test_sensor_values_read_back(c):
    units = set()
    for seed in range(30):
        prefix, tail, got = AU.render_sensor_au(np.random.default_rng(seed), c)
        text = f"{prefix} {tail}".strip()
        assert text and (bool(prefix) != bool(tail)), (prefix, tail)
        assert re.search(NAMES[c.reading], text, re.I) and re.search(CMP[c.comparator], text), text
        assert "co2" not in text.lower() and "₂" not in text
        if c.is_superlative:
            assert got == SensorConstraint(c.reading, c.comparator, None, "") and not re.search(r"\d", text)
            continue
        unit = next((u for pat, u in UNITS if re.search(pat, text)), "")
        n = _read_number(text)
        back = (n - 32) * 5 / 9 if unit == "f" else n * 1000 if unit == "kw" else n
        assert back == c.value, (text, c)
        assert got == SensorConstraint(c.reading, c.comparator, c.value, unit), (text, got)
        units.add(unit)
    if c.reading == "co2_ppm" and not c.is_superlative:
        assert units == {"ppm"}
    if c.value in (40.0, 1500.0) and c.reading in ("temperature_c", "power_w"):  # both units get written
        assert units == ({"c", "f"} if c.reading == "temperature_c" else {"w", "kw"}), units


def test_sensor_tail_room_and_hint_in_their_places():
    sg = Subgoal(0, Target("teal lamp", "lamp", ("teal", "switched on"),
                           (Relation("next_to", Target("sofa", "sofa", (), (Relation("behind", Target("drums",
                                                                                                     "drums")),))),
                            Relation("opposite", Target("toolbox", "toolbox")))), room="nursery")
    seen_possessive = seen_after = False
    for seed in range(80):
        rng = np.random.default_rng(seed)
        c = CONSTRAINTS[seed % len(CONSTRAINTS)]
        prefix, tail, got = AU.render_sensor_au(rng, c)
        h = AU.hint_text_au(rng, "3.5", "-2")
        text = AU.render_goal_au(rng, sg, prefix, tail, h)
        if prefix:  # the superlative adjective scopes over the room
            assert text.startswith(f"the {prefix} ") or text.startswith(f"the nursery's {prefix} "), text
        if text.startswith("the nursery's "):
            seen_possessive = True
        else:
            seen_after = True
            assert "teal lamp in the nursery" in text, text
            if tail:
                assert text.index("in the nursery") < text.index(tail), text
        if tail:
            assert text.index(tail) < text.index(h), text
        assert NUM.findall(text)[-2:] == ["3.5", "-2"], text
        assert text.index(h) < text.index("next to the sofa (") < text.index("behind the drums)"), text
        assert re.search(r"\), (?:and also|while also being) (?:opposite|across from) the toolbox$", text), text
    assert seen_possessive and seen_after


def test_same_seed_same_text():
    sgs = [Subgoal(0, Target("teal lamp", "lamp", ("teal", "open")), room="kitchen"),
           Subgoal(1, Target("drums", "drums", (), (Relation("near", Target("sofa", "sofa")),))),
           Subgoal(2, Target("olive cactus", "cactus", ("olive",)), room="nursery")]

    def run(seed, order):
        rng = np.random.default_rng(seed)
        res = []
        for i, sg in enumerate(sgs):
            prefix, tail, _ = AU.render_sensor_au(rng, CONSTRAINTS[(seed + i) % len(CONSTRAINTS)])
            res.append(AU.render_goal_au(rng, sg, prefix, tail, AU.hint_text_au(rng, "3.5", "2")))
        return AU.render_instruction_au(rng, res, order), res

    for seed in range(30):
        for order in ("strict", "free"):
            text, res = run(seed, order)
            assert (text, res) == run(seed, order)
            _check_frame(text, res, order)
