"""The `unseen_train3` training templates (set TRAIN3): wired, deterministic, and every piece of the ground truth is
written down.

Checked with small readers of their own (a goal reader that recovers head, attributes, states, room and nested
relations; words for comparators, readings, superlative direction, numbers, coordinates and order cues) that share
no code with the templates, over random subgoals drawn by hypothesis.
"""

from __future__ import annotations

import random
import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from template_checks import (
    check_coordinates,
    check_goal_layout,
    check_order,
    check_sensor,
    check_sensor_goal,
    reading_norm,
    spoken_numbers,
    target_truth,
)
from template_checks import (
    depths as _depths,
)
from test_phrasings_dev8 import HEADS, MODS, ROOMS, STATES, constraints, subgoals

from ragnav_jax.config import EPISODE_SPLITS
from ragnav_jax.language import phrasings_train3 as T
from ragnav_jax.language.episodes import UNSEEN_TEMPLATES, _renderer
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])


# ----------------------------------------------------------------------------------------------------
# Wiring and determinism


def test_split_is_wired():
    assert "unseen_train3" in EPISODE_SPLITS
    assert UNSEEN_TEMPLATES["unseen_train3"] == ("phrasings_train3", "train3")
    assert _renderer("unseen_train3", "goal") is T.render_goal_train3
    assert _renderer("unseen_train3", "sensor") is T.render_sensor_train3
    assert _renderer("unseen_train3", "hint") is T.hint_text_train3
    assert _renderer("unseen_train3", "instruction") is T.render_instruction_train3


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=4), c=constraints(), seed=st.integers(0, 2**31),
       strict=st.booleans())
def test_same_seed_same_text(sgs, c, seed, strict):
    """Every draw comes from the generator passed in: the global generators are stirred between the two runs."""

    def run(salt: int):
        random.seed(salt)
        np.random.seed(salt)
        rng = np.random.default_rng(seed)
        prefix, tail, written = T.render_sensor_train3(rng, c)
        res = [T.render_goal_train3(rng, sg, prefix=prefix, tail=tail, hint=T.hint_text_train3(rng, "3.5", "2"))
               for sg in sgs]
        return res, written, T.render_instruction_train3(rng, res, "strict" if strict else "free")

    assert run(0) == run(1) == run(7)


# ----------------------------------------------------------------------------------------------------
# A reader of TRAIN3's goals (its own phrase list, written apart from the templates)

REL_PHRASES = {
    "near": "near", "a short stroll from": "near", "within earshot of": "near",
    "next to": "next_to", "flush against": "next_to", "jammed up against": "next_to",
    "beside": "beside", "keeping watch beside": "beside", "hanging out beside": "beside",
    "by": "by", "loafing by": "by", "keeping vigil by": "by",
    "on": "on", "sprawled on": "on", "sat square on": "on",
    "under": "under", "lying low under": "under", "half-hidden under": "under",
    "above": "above", "lording it over": "above", "dangling above": "above",
    "in": "in", "bottled up in": "in", "sealed inside": "in",
    "with": "with", "loaded with": "with", "lugging": "with",
    "in the same room as": "in_room_with", "in the room that plays host to": "in_room_with",
    "in a room it shares with": "in_room_with",
    "in front of": "in_front_of", "out front of": "in_front_of", "in plain view in front of": "in_front_of",
    "behind": "behind", "in back of": "behind", "ducking behind": "behind",
    "opposite": "opposite", "eyeballing": "opposite", "glaring across at": "opposite",
    "to the left of": "left_of", "on the left flank of": "left_of", "a shuffle to the left of": "left_of",
    "to the right of": "right_of", "on the right flank of": "right_of", "a shuffle to the right of": "right_of",
}
_LONGEST = sorted(REL_PHRASES, key=len, reverse=True)
REL_WORDS: dict[str, tuple[str, ...]] = {}
for _p, _t in REL_PHRASES.items():
    REL_WORDS[_t] = (*REL_WORDS.get(_t, ()), _p)


def _top_relations(text: str) -> list[tuple[int, int, str]]:
    depth, out, i = _depths(text), [], 0
    while i < len(text):
        if depth[i] == 0 and (i == 0 or text[i - 1] == " "):
            hit = next((p for p in _LONGEST if text.startswith(p + " the ", i)), None)
            if hit:
                out.append((i, i + len(hit), REL_PHRASES[hit]))
                i += len(hit)
                continue
        i += 1
    return out


def _read_chain(text: str) -> list[tuple[str, dict]]:
    rels = _top_relations(text)
    assert rels and text[: rels[0][0]].strip() == "", text
    out = []
    for k, (_, end, rtype) in enumerate(rels):
        stop = rels[k + 1][0] if k + 1 < len(rels) else len(text)
        seg = re.sub(r"(, and what's more|, and for good measure| and)\s*$", "", text[end:stop].strip())
        out.append((rtype, _read_np(seg.strip())))
    return out


def _read_np(seg: str) -> dict:
    """'the switched-on teal lamp (to wit, the one next to the sofa)', 'the lamp (the witness had it down as teal),
    open to this day', 'the lamp (open at last report), in all its teal glory'."""
    got = {"attrs": [], "after": [], "states": [], "relations": []}
    depth, groups, plain, i = _depths(seg), [], "", 0
    while i < len(seg):
        if seg[i] == "(" and depth[i] == 1:
            j = i
            while not (seg[j] == ")" and depth[j] == 1):
                j += 1
            groups.append(seg[i + 1 : j])
            i = j + 1
            continue
        plain += seg[i]
        i += 1
    for body in groups:
        if m := re.fullmatch(r"(?:to wit, the one|the very one) (.+)", body):
            got["relations"] += _read_chain(m.group(1))
        elif m := re.fullmatch(r"(.+) at last report", body):
            got["states"] += m.group(1).split(" and ")
        elif m := re.fullmatch(r"the witness had it down as (.+)", body):
            got["after"] += m.group(1).split(" and ")
        else:
            raise AssertionError(f"unknown bracket {body!r} in {seg!r}")
    parts = [p.strip() for p in plain.split(",") if p.strip()]
    for p in parts[1:]:
        if m := re.fullmatch(r"(.+) to this day", p):
            got["states"] += m.group(1).split(" and ")
        else:
            m = re.fullmatch(r"in all its (.+) glory", p)
            assert m, (p, seg)
            got["after"] += m.group(1).split(" and ")
    words = " ".join(parts[0].split())
    assert words.startswith("the "), seg
    words = words[4:]
    head = max((h for h in HEADS if words == h or words.endswith(" " + h)), key=len)
    got["head"] = head
    for w in words[: len(words) - len(head)].split():
        if w in MODS:
            got["attrs"].append(w)
        else:
            assert w.replace("-", " ") in STATES, (w, seg)
            got["states"].append(w.replace("-", " "))
    got["attrs"] += got.pop("after")
    return got


_ROOM_RX = re.compile(r"in the (?:house's )?(" + "|".join(sorted(ROOMS, key=len, reverse=True)) +
                      r")(?: of this house)?\b")


def read_goal(text: str) -> tuple[dict, str | None]:
    room = None
    if m := _ROOM_RX.search(text):
        room = m.group(1)
        text = text[: m.start()] + text[m.end():]
    text = " ".join(text.split())
    rels = _top_relations(text)
    got = _read_np((text[: rels[0][0]] if rels else text).strip().rstrip(","))
    if rels:
        got["relations"] += _read_chain(text[rels[0][0]:])
    return got, room


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece_and_reads_back_exactly(sg, seed):
    text = T.render_goal_train3(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, REL_WORDS)
    assert ") (" not in text and max(_depths(text), default=0) <= 1, text
    got, room = read_goal(text)
    assert reading_norm(got) == target_truth(sg.target), text
    assert room == sg.room, text


def test_every_goal_form_and_relation_word_is_used_and_read():
    t = Target("teal wool lamp", "lamp", ("teal", "wool", "switched on"), (
        Relation("next_to", Target("sofa", "sofa", ("open",), (Relation("with", Target("drums", "drums")),))),
        Relation("under", Target("shelves", "shelves", ("empty",)))))
    rng = np.random.default_rng(0)
    texts = [T.render_goal_train3(rng, Subgoal(0, t, room="music room")) for _ in range(200)]
    for text in texts:
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "music room", text
        assert text.index("music room") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
    for rx in (r"^the teal wool lamp", r"^the lamp \(the witness had it down as teal and wool\)", r"^the switched-on ",
               r"in all its teal and wool glory", r"\(switched on at last report\)", r", switched on to this day,",
               r"in the house's music room", r"in the music room of this house", r"\(to wit, the one ",
               r"\(the very one ", r"the shelves \(empty at last report\)", r", and what's more ",
               r", and for good measure "):
        assert any(re.search(rx, x) for x in texts), rx
    for rtype in T.REL_WORDS:
        sg = Subgoal(0, Target("lamp", "lamp", (), (Relation(rtype, Target("sofa", "sofa")),)))
        seen = set()
        for _ in range(40):
            text = T.render_goal_train3(rng, sg)
            assert read_goal(text)[0]["relations"] == [(rtype, {"attrs": [], "states": [], "relations": [],
                                                                  "head": "sofa"})], text
            seen.add(text[len("the lamp "): -len(" the sofa")])
        assert seen == set(REL_WORDS[rtype]), rtype


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own

_DIGITS = "zero|one|two|three|four|five|six|seven|eight|nine"


def numbers_in(text: str) -> list[float]:
    """Every number: '-4', '.65', 'minus 4', 'negative 4', 'minus four', 'twenty point five', 'zero point six five'
    ('the one', 'the very one' and 'one's' are no numbers)."""
    t = text.lower().replace("°c", " c").replace("negative ", "minus ")
    t = re.sub(r"(?<=the )one\b|(?<=very )one\b|\bone(?='s)", "ONE", t)

    def point(m: re.Match) -> str:
        whole = spoken_numbers([m.group(1)])
        assert len(whole) == 1, m.group(0)
        return f"{whole[0]:g}." + "".join(str(_DIGITS.split('|').index(d)) for d in m.group(2).split())

    t = re.sub(r"([a-z]+(?:-[a-z]+)?) point ((?:(?:" + _DIGITS + r") ?)+)\b", point, t)
    return spoken_numbers(re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)*", t))


def comparator_of(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"hovers near|lands close to|a hair either side|runs at about|about as", "approx"),
                  (r"sags below|a floor of|only goes up|settle for less|every bit as", "ge"),
                  (r"stops climbing|pokes above|hits the roof|not a notch more|or chillier|or drier|no (warmer|damper|"
                   r"greener) than", "le"),
                  (r"overtakes|\bbeat\b|high side|never gets down|better of|(hotter|warmer|damper|greener) than", "gt"),
                  (r"ducks under|low side|climb as high|comes in beneath|limbos|(colder|cooler|drier) than|less green",
                   "lt")):
        if re.search(rx, t):
            return c
    return "?"


def reading_of(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|health|hardiest|liveliest|yellowed|puniest|green", t):
        return "ndvi"
    if re.search(r"humid|swamp|waterlogged|dried|damp|dr(y|i)|%|per ?cent", t):
        return "humidity_pct"
    if re.search(r"temperature|warm|torrid|fever|chill|cold|cool|hotter|°|degree|celsius", t):
        return "temperature_c"
    return "?"


_LOW = r"coldest|bone-chilling|ice-cold|least|yellowed|puniest|driest|dried-out|outranked by|bottom of the heap|" \
       r"last of the field"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = T.render_sensor_train3(np.random.default_rng(seed), c)
    check_sensor(rendered, c, comparator_of, _LOW, r"°c|degree|celsius", r"(?i)%|per ?cent", numbers_in, reading_of)
    text = (rendered[0] + " " + rendered[1]).strip()
    assert "(" not in text and "  " not in text, text
    if not rendered[2].unit and not c.is_superlative:  # a unitless number always has its reading named
        assert re.search(r"temperature|humidity|ndvi", text.lower()), text


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase_after_the_head(c, sg, seed):
    check_sensor_goal(T.render_sensor_train3, T.render_goal_train3, c, sg, seed, numbers_in)


def test_number_formats_frames_superlatives_and_directions_vary():
    rng = np.random.default_rng(3)
    cold = {T.render_sensor_train3(rng, SensorConstraint("temperature_c", "le", -4.0))[1] for _ in range(300)}
    for rx in (r"minus four", r"minus 4\b", r"negative 4\b", r"(?<!\w)-4\b", r"^that ", r"^whose temperature ",
               r"^whose temperature, the lab says, ", r"^famous for a temperature that ", r"degrees Celsius", r"°C",
               r"or chillier|no warmer than"):
        assert any(re.search(rx, t) for t in cold), rx
    assert all(numbers_in(t) == [-4.0] for t in cold)
    half = {T.render_sensor_train3(rng, SensorConstraint("humidity_pct", "gt", 22.5))[1] for _ in range(200)}
    for rx in (r"twenty-two point five", r"22\.5", r"% relative humidity", r"per cent", r"damper than"):
        assert any(re.search(rx, t) for t in half), rx
    ndvi = {T.render_sensor_train3(rng, SensorConstraint("ndvi", "ge", 0.65))[1] for _ in range(200)}
    for rx in (r"(?<![\d])\.65\b", r"0\.65\b", r"zero point six five", r"famous for an NDVI", r"on the NDVI scale"):
        assert any(re.search(rx, t) for t in ndvi), rx
    assert all(numbers_in(t) == [0.65] for t in ndvi)
    for rd in ("temperature_c", "humidity_pct", "ndvi"):
        for cmp in ("max", "min"):
            sup = {T.render_sensor_train3(rng, SensorConstraint(rd, cmp)) for _ in range(80)}
            assert len({p for p, _, _ in sup if p}) == 3 and len({t for _, t, _ in sup if t}) == 3, (rd, cmp)
            assert all(bool(re.search(_LOW, (p + t))) == (cmp == "min") for p, t, _ in sup), sup
        for cmp in ("gt", "ge", "lt", "le", "approx"):
            seen = {comparator_of(T.render_sensor_train3(rng, SensorConstraint(rd, cmp, 30.0 if rd != "ndvi" else 0.3))
                                  [1]) for _ in range(80)}
            assert seen == {cmp}, (rd, cmp, seen)


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(T.hint_text_train3, T.render_goal_train3, T.render_instruction_train3, x, y, seed)


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_a_goal_with_sensor_and_hint_keeps_every_number(c, sg, seed):
    rng = np.random.default_rng(seed)
    prefix, tail, written = T.render_sensor_train3(rng, c)
    hint = T.hint_text_train3(rng, "3.5", "-7.3")
    text = T.render_goal_train3(rng, sg, prefix=prefix, tail=tail, hint=hint)
    nums = numbers_in(text)
    want = [3.5, -7.3] + ([] if c.is_superlative else [written.value])
    assert sorted(nums) == pytest.approx(sorted(want), abs=1e-9), text
    assert nums.index(3.5) + 1 == nums.index(-7.3), text  # x, then y
    assert ") (" not in text and max(_depths(text), default=0) <= 1 and text.count("(") == text.count(")"), text


STRICT_CUES = r"order they're lettered|jumps ahead|the way it runs|one clue after the next|order on the itinerary|" \
              r"double back|runs in this order"
FREE_CUES = r"any sequence you choose|no lead hangs on|hangs on another|whichever sequence your nose|" \
            r"any sequence you care|no itinerary|whatever order your feet"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_stay_whole_in_order(sgs, seed, strict):
    check_order(T.render_goal_train3, T.render_instruction_train3, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [T.render_goal_train3(rng, sg) for sg in sgs]
    low = T.render_instruction_train3(rng, res, "strict" if strict else "free").lower()
    if strict:
        assert re.search(STRICT_CUES, low), low
    at = 0
    for r in res:
        at = low.find(r.lower(), at)
        assert at >= 0, (r, low)
        at += len(r)


_OWN = ("kettle", "toaster", "guitar", "harp", "heater", "fern", "lamp", "sofa")
_COUNT = {w: i for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight"))}


@SETTINGS
@given(n=st.integers(1, 8), seed=st.integers(0, 2**31), strict=st.booleans())
def test_counts_letters_and_ordinals_agree_with_the_goals(n, seed, strict):
    res = [f"the {h}" for h in _OWN[:n]]
    text = T.render_instruction_train3(np.random.default_rng(seed), res, "strict" if strict else "free")
    for m in re.finditer(r"\b(\w+) (?:leads,|sights included)", text):
        assert _COUNT[m.group(1)] == n, text
    if n == 1:
        assert not re.search(r"\d", text) and not re.search(STRICT_CUES + "|" + FREE_CUES, text.lower()), text
    letters = re.findall(r"^Exhibit (\w)", text, re.M)
    if letters:
        assert letters == list("ABCDEFGH"[:n]) and text.split("\n")[n].startswith("Exhibit " + "ABCDEFGH"[n - 1] +
                                                                                   " (the clincher): "), text
    sights = re.findall(r"^(\w+) sight: ", text, re.M)
    if sights:
        assert sights == ["First", "Second", "Third", "Fourth", "Fifth", "Sixth", "Seventh"][: n - 1] + ["Final"]
    at = 0
    for r in res:  # every goal once, in order, never run into the next word
        m = re.compile(re.escape(r) + r"(?![\w-])").search(text, at)
        assert m, (r, text)
        at = m.end()


def test_both_writers_every_cue_and_a_seed_repeats():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    texts = [T.render_instruction_train3(rng, res, order) for order in ("strict", "free") for _ in range(60)]
    for m in (r"exhibit|case file|trail|loose ends|leads", r"sight|tour|itinerary|on your left|hop-on"):
        assert any(re.search(m, t.lower()) for t in texts), m
    for some, cues in ((texts[:60], STRICT_CUES), (texts[60:], FREE_CUES)):  # every cue of each order is written
        got = {c for t in some for c in re.findall(cues, t.lower())}
        assert got == set(cues.split("|")), set(cues.split("|")) - got
    assert any("\n" in t for t in texts) and any("\n" not in t for t in texts)
    again = [T.render_instruction_train3(np.random.default_rng(9), res, "free") for _ in range(2)]
    assert again[0] == again[1]
