"""Set AN (split `unseen_an`): its goals keep every piece of the subgoal, its sensor phrases denote exactly the
constraint they return, its hints write x then y, and its instructions say strict or free order in words (and a
single goal neither), in all four voices. The readers in this file are the test's own: they know only what set AN
writes, so a change that loses a piece of a goal or a digit of a value fails here (checked by breaking the module
on purpose: see its docstring)."""

from __future__ import annotations

import re

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_phrasings_dev8 import subgoals

from ragnav_jax.config import EPISODE_SPLITS
from ragnav_jax.language import phrasings_an as an
from ragnav_jax.language.episodes import UNSEEN_TEMPLATES, _renderer
from ragnav_jax.language.template_text import attributes_and_states, number_words
from ragnav_jax.language.types import READINGS, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def test_split_is_wired():
    assert "unseen_an" in EPISODE_SPLITS and EPISODE_SPLITS.index("unseen_an") == EPISODE_SPLITS.index("unseen_am") + 1
    assert UNSEEN_TEMPLATES["unseen_an"] == ("phrasings_an", "an")
    assert _renderer("unseen_an", "goal") is an.render_goal_an
    assert _renderer("unseen_an", "sensor") is an.render_sensor_an
    assert _renderer("unseen_an", "hint") is an.hint_text_an
    assert _renderer("unseen_an", "instruction") is an.render_instruction_an


# ----------------------------------------------------------------------------------------------------
# goals

REL_WORDS = {
    "near": ("near", "close to", "not far from", "in the vicinity of"),
    "next_to": ("next to", "alongside"),
    "beside": ("beside",),
    "by": ("by",),
    "on": ("on", "on top of", "sitting on", "resting on"),
    "under": ("under", "underneath", "beneath"),
    "above": ("above",),
    "in": ("in", "inside"),
    "with": ("with", "that has", "that have"),
    "in_room_with": ("in the same room as", "sharing a room with", "in whichever room holds"),
    "in_front_of": ("in front of",),
    "behind": ("behind", "round the back of"),
    "opposite": ("opposite", "across from", "facing"),
    "left_of": ("left of",),
    "right_of": ("right of",),
}


def _has_words(text: str, words: str) -> bool:
    """`words` stands in `text` as whole words (hyphens and punctuation read as spaces, any case)."""
    def norm(s: str) -> str:
        return " " + " ".join(re.sub(r"[-(),;:.!?]", " ", s.lower()).split()) + " "

    return norm(words) in norm(text)


def _head_intact(text: str, head: str) -> bool:
    return re.search(r"(?<![\w-])" + re.escape(head) + r"(?![\w-])", text) is not None


def _all_targets(t: Target):
    yield t
    for r in t.relations:
        yield from _all_targets(r.anchor)


def _all_relations(t: Target):
    for r in t.relations:
        yield r
        yield from _all_relations(r.anchor)


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    text = an.render_goal_an(np.random.default_rng(seed), sg)
    assert text.startswith("the ")
    for t in _all_targets(sg.target):
        assert _head_intact(text, t.head), (t.head, text)
        pre, states = attributes_and_states(t)
        for a in pre + states:
            assert _has_words(text, a), (a, text)
    for r in _all_relations(sg.target):
        assert any(_has_words(text, w) for w in REL_WORDS[r.type]), (r.type, text)
    if sg.room:
        assert _has_words(text, "in the " + sg.room), text
    assert text.count("(") == text.count(")")


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31), x=st.integers(-900, 900), y=st.integers(-900, 900),
       c=st.sampled_from([SensorConstraint("temperature_c", "ge", 40.0), SensorConstraint("noise_db", "min"),
                          SensorConstraint("ndvi", "approx", 0.65), SensorConstraint("humidity_pct", "max")]))
def test_room_then_sensor_then_hint_then_relations(sg, seed, x, y, c):
    rng = np.random.default_rng(seed)
    xs, ys = f"{x / 10:g}", f"{y / 10:g}"
    hint = an.hint_text_an(rng, xs, ys)
    prefix, tail, _ = an.render_sensor_an(rng, c)
    text = an.render_goal_an(rng, sg, prefix=prefix, tail=tail, hint=hint)
    assert hint in text and tail in text and (not prefix or f"the {prefix} " in text), text
    if tail:
        assert text.index(tail) < text.index(hint)
    if sg.room:
        assert text.index("the " + sg.room) < text.index(hint)
        if tail:
            assert text.index("the " + sg.room) < text.index(tail)
    if prefix:  # the superlative stands before the goal's own head
        assert text.index(prefix) < text.index(sg.target.head)
    nums = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", text)]
    assert nums[-2:] == [float(xs), float(ys)], text


def test_states_and_plurals_read_naturally():
    lamp = Target("teal wool lamp", "lamp", ("teal", "wool", "switched on"))
    drums = Target("drums", "drums", ("open",))
    seen = set()
    for seed in range(60):
        a = an.render_goal_an(np.random.default_rng(seed), Subgoal(0, lamp, room="nursery"))
        b = an.render_goal_an(np.random.default_rng(seed), Subgoal(0, drums))
        assert "lamps" not in a and " is " in a or "switched-on" in a, a
        assert " is " not in b and ("are" in b or "open drums" in b), b
        seen.add(a.split(" lamp")[0])
    assert {"the teal wool", "the switched-on teal wool"} <= seen and any("(teal, wool)" in a for a in [
        an.render_goal_an(np.random.default_rng(s), Subgoal(0, lamp)) for s in range(60)])


# ----------------------------------------------------------------------------------------------------
# sensor phrases

READ_NAMES = {"temperature_c": ("temperature", "warmest", "hottest", "coldest", "coolest"),
              "ndvi": ("ndvi",), "humidity_pct": ("humid", "dampest", "driest"), "co2_ppm": ("co2", "carbon dioxide"),
              "noise_db": ("noise", "sound", "loudest", "noisiest", "quietest"),
              "light_lux": ("light level", "illuminance", "brightest", "best-lit", "dimmest", "darkest"),
              "battery_pct": ("battery",), "power_w": ("power",), "weight_kg": ("weight", "mass", "heaviest"),
              "pressure_hpa": ("pressure",)}
MAX_WORDS = ("highest", "top", "warmest", "hottest", "most humid", "dampest", "loudest", "noisiest", "brightest",
             "best-lit", "heaviest", "most power-hungry")
MIN_WORDS = ("lowest", "coldest", "coolest", "least humid", "driest", "quietest", "dimmest", "darkest",
             "least power-hungry")
CMP_WORDS = (("le", ("not above", "at most", "no more than", "or less", "or lower")),
             ("ge", ("not below", "at least", "no less than", "or more", "or higher")),
             ("gt", ("above", "more than", "higher than", "in excess of", "greater than")),
             ("lt", ("below", "less than", "lower than", "under")),
             ("approx", ("about", "around", "roughly", "approximately", "in the region of")))
DIGIT_WORDS = ("nought", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine")
_NUMBER_WORDS = sorted(((number_words(n), n) for n in range(1000)), key=lambda p: -len(p[0]))
_WORD_RE = re.compile(r"\b(minus )?(" + "|".join(re.escape(w) for w, _ in _NUMBER_WORDS) + r"|nought)\b"
                      r"( and a half| point(?: (?:" + "|".join(DIGIT_WORDS) + r"))+)?")


def read_number(text: str) -> float:
    m = re.search(r"(?<![\w.])-?\d+(?:\.\d+)?", text)
    if m:
        return float(m.group())
    m = _WORD_RE.search(text)
    assert m, text
    n = 0 if m.group(2) == "nought" else dict(_NUMBER_WORDS)[m.group(2)]
    rest = m.group(3) or ""
    if rest == " and a half":
        v = n + 0.5
    elif rest:
        v = float(f"{n}." + "".join(str(DIGIT_WORDS.index(d)) for d in rest.split()[1:]))
    else:
        v = float(n)
    return -v if m.group(1) else v


def read_value(text: str) -> tuple[float, str]:
    """(the value in the reading's canonical unit, the unit the text wrote it in)."""
    w = read_number(text)
    if "°F" in text or "Fahrenheit" in text:
        return (w - 32) * 5 / 9, "f"
    if "kW" in text or "kilowatt" in text:
        return w * 1000, "kw"
    if "mbar" in text or "millibar" in text:
        return w, "mbar"
    return w, ""


def read_comparator(text: str) -> str:
    for cmp, words in CMP_WORDS:
        if any(re.search(r"\b" + w + r"\b", text) for w in words):
            return cmp
    raise AssertionError(text)


@st.composite
def constraints(draw):
    reading = draw(st.sampled_from(READINGS))
    comparator = draw(st.sampled_from(("lt", "le", "gt", "ge", "approx", "max", "min")))
    if comparator in ("max", "min"):
        return SensorConstraint(reading, comparator)
    value = draw(st.integers(-4000, 400000).map(lambda n: n / 100) | st.sampled_from([0.65, 22.5, 40.0, 1500.0])
                 | st.integers(-50, 5000).map(float))
    return SensorConstraint(reading, comparator, value)


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    prefix, tail, written = an.render_sensor_an(np.random.default_rng(seed), c)
    text = (prefix + " " + tail).strip()
    assert bool(prefix) != bool(tail), (prefix, tail)
    assert (written.reading, written.comparator) == (c.reading, c.comparator)
    assert any(w in text.lower() for w in READ_NAMES[c.reading]), text
    if c.is_superlative:
        assert written.value is None and written.unit == ""
        words = MAX_WORDS if c.comparator == "max" else MIN_WORDS
        assert any(re.search(r"\b" + w + r"\b", text) for w in words), text
        assert not re.search(r"\d", text.replace("CO2", "CO"))  # no threshold number
        return
    assert written.value == c.value
    value, other = read_value(tail)
    assert value == c.value, (tail, c)
    assert read_comparator(tail) == c.comparator, tail
    if other:
        assert written.unit == other
    elif c.reading == "temperature_c":
        assert written.unit == "c" and ("°C" in tail or "Celsius" in tail or "degrees C" in tail)
    elif c.reading in ("humidity_pct", "battery_pct"):
        assert written.unit == "%" and ("%" in tail or "per cent" in tail or "percent" in tail)
    elif c.reading == "ndvi":
        assert written.unit == ""


def test_number_formats_vary():
    seen_units, seen_words, seen_digits = set(), False, False
    for seed in range(400):
        for c in (SensorConstraint("temperature_c", "ge", 40.0), SensorConstraint("power_w", "lt", 1500.0),
                  SensorConstraint("pressure_hpa", "approx", 1013.0)):
            _, tail, written = an.render_sensor_an(np.random.default_rng(seed), c)
            seen_units.add(written.unit)
            seen_digits |= bool(re.search(r"\d", tail))
            seen_words |= "forty" in tail
    assert {"c", "f", "w", "kw", "hpa", "mbar"} <= seen_units and seen_words and seen_digits


# ----------------------------------------------------------------------------------------------------
# hints


@SETTINGS
@given(x=st.integers(-2000, 2000), y=st.integers(-2000, 2000), seed=st.integers(0, 2**31))
def test_hint_writes_x_then_y(x, y, seed):
    xs, ys = f"{x / 100:g}", f"{y / 100:g}"
    text = an.hint_text_an(np.random.default_rng(seed), xs, ys)
    nums = re.findall(r"-?\d+(?:\.\d+)?", text)
    assert nums == [xs, ys], text


# ----------------------------------------------------------------------------------------------------
# instructions

STRICT = ("in the sequence in which it stands", "strictly in the sequence set down", "taken out of turn",
          "once the item before it has been dealt with", "in precisely the sequence listed",
          "the sequence here is not negotiable", "in the order listed and not otherwise",
          "the running order of this show is fixed", "in exactly that sequence, never shuffled",
          "nothing out of sequence", "it has to be in that exact order", "do them out of order",
          "never swapped around")
FREE = ("in whatever sequence it pleases", "in no particular sequence", "in any sequence it sees fit",
        "in any sequence they prefer", "in no particular priority", "immaterial to my assessment",
        "in whatever order you fancy", "the order is entirely up to you", "the sequence is yours to play with",
        "any order!", "do not care what order", "whatever order it likes")
SEQUENCE_WORDS = ("first", "then", "next", "finally", "after that", "last", "order", "sequence", "turn")
VOICES = {"speaker": ("the house", "the ayes have it", "the motion", "the clerk", "order paper"),
          "reviewer": ("referee", "recommendation", "the authors", "major comments", "minor comments"),
          "fashion": ("darling", "sweetie"),
          "comedian": ("so i've got this robot", "folks", "that's the joke", "robots never ask", "my robot")}


def _frame(text: str, res: list[str]) -> str:
    """The instruction with its goals cut out, lower case."""
    low = text.lower()
    for g in res:
        low = low.replace(g.lower(), " <goal> ", 1)
    return low


def _voice(frame: str) -> str:
    found = [v for v, marks in VOICES.items() if any(m in frame for m in marks)]
    assert len(found) == 1, (found, frame)
    return found[0]


def _goals(sgs, seed):
    rng = np.random.default_rng(seed)
    return [an.render_goal_an(rng, sg) for sg in sgs]


def _check_instruction(res: list[str], text: str, strict: bool) -> str:
    """Every goal verbatim in visiting order; the order said in words (a single goal: no cue, no digit, no
    sequencing word); returns the voice."""
    low, at = text.lower(), 0
    for g in res:
        i = low.find(g.lower(), at)
        assert i >= 0, (g, text)
        at = i + len(g)
    frame = _frame(text, res)
    voice = _voice(frame)
    has_strict = any(c in frame for c in STRICT)
    has_free = any(c in frame for c in FREE)
    if len(res) == 1:
        assert not has_strict and not has_free, text
        assert not re.search(r"\d", frame), text
        assert not any(re.search(r"\b" + w + r"\b", frame) for w in SEQUENCE_WORDS), text
    elif strict:
        assert has_strict and not has_free, text
    else:
        assert has_free and not has_strict, text
    return voice


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=5), seed=st.integers(0, 2**31), strict=st.booleans())
def test_instruction_states_the_order_in_words(sgs, seed, strict):
    res = _goals(sgs, seed)
    text = an.render_instruction_an(np.random.default_rng(seed + 1), res, "strict" if strict else "free")
    _check_instruction(res, text, strict)


GOALS = ["the teal wool lamp in the nursery", "the sofa (grey, fabric), next to the credenza",
         "the guitar at (3.5, 2)", "the drums that are open, behind the piano and facing the harp",
         "the warmest kettle over in the kitchen"]


def test_every_voice_states_the_order():
    """Every frame of every voice, for one to five goals and both orders (hypothesis draws too few seeds to
    reach them all)."""
    seen = set()
    for seed in range(300):
        for n in range(1, 6):
            for strict in (True, False):
                res = GOALS[:n] if seed % 2 else GOALS[5 - n:]
                text = an.render_instruction_an(np.random.default_rng(seed), res, "strict" if strict else "free")
                seen.add((_check_instruction(res, text, strict), min(n, 2), strict, text.split(":")[0][:25]))
    kinds = [(v, n, o) for v, n, o, _ in seen]  # every voice: three frames for each kind of instruction
    assert sorted(set(kinds)) == sorted((v, n, o) for v in VOICES for n in (1, 2) for o in (True, False))
    assert all(kinds.count(k) == 3 for k in kinds), sorted(seen)


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=5), seed=st.integers(0, 2**31), strict=st.booleans())
def test_same_seed_same_text(sgs, seed, strict):
    def run():
        rng = np.random.default_rng(seed)
        res = [an.render_goal_an(rng, sg, hint=an.hint_text_an(rng, "3.5", "2")) for sg in sgs]
        return res, an.render_sensor_an(rng, SensorConstraint("humidity_pct", "le", 40.0)), \
            an.render_instruction_an(rng, res, "strict" if strict else "free")

    assert run() == run()


def test_all_four_voices_are_reached():
    goals = ["the teal wool lamp in the nursery", "the sofa next to the credenza", "the guitar at (3.5, 2)"]
    seen = {n: set() for n in (1, 2, 3)}
    for seed in range(200):
        for n in (1, 2, 3):
            for order in ("strict", "free"):
                text = an.render_instruction_an(np.random.default_rng(seed), goals[:n], order)
                seen[n].add(_voice(_frame(text, goals[:n])))
    assert all(v == set(VOICES) for v in seen.values()), seen
