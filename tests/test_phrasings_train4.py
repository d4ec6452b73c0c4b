"""The `unseen_train4` training templates (set train4): wired, deterministic, and every piece of the truth written.

Checked with small readers of their own (a goal reader that recovers head, attributes, states, room and nested
relations; words for comparators, readings, units, numbers, coordinates and order cues) that share no code with
the templates, over random subgoals drawn by hypothesis.
"""

from __future__ import annotations

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
from ragnav_jax.language import phrasings_train4 as T
from ragnav_jax.language.episodes import UNSEEN_TEMPLATES, _renderer
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# The whole phrases a reader of train4's goals splits on, each with its relation type (written apart from the
# templates)
REL_PHRASES = {
    "near": "near", "proximate to": "near", "just a teeny walk from": "near",
    "next to": "next_to", "contiguous with": "next_to", "cuddled up next to": "next_to",
    "beside": "beside", "abreast of": "beside", "playing buddies beside": "beside",
    "by": "by", "situated by": "by", "hanging about by": "by",
    "on": "on", "affixed on": "on", "having a nap on": "on",
    "under": "under", "subjacent to": "under", "hiding like a mouse under": "under",
    "above": "above", "installed above": "above", "up high like a bird above": "above",
    "in": "in", "contained within": "in", "tucked up cosy in": "in",
    "with": "with", "incorporating": "with", "keeping company with": "with",
    "in the same room as": "in_room_with", "housed in a common room with": "in_room_with",
    "sharing a playroom with": "in_room_with",
    "in front of": "in_front_of", "forward of": "in_front_of", "peeking out in front of": "in_front_of",
    "behind": "behind", "to the rear of": "behind", "playing peekaboo behind": "behind",
    "opposite": "opposite", "diametrically opposite": "opposite", "making faces at": "opposite",
    "to the left of": "left_of", "left-adjacent to": "left_of", "on the left flank of": "left_of",
    "to the right of": "right_of", "right-adjacent to": "right_of", "on the right flank of": "right_of",
}
_BY_LENGTH = sorted(REL_PHRASES, key=len, reverse=True)
REL_WORDS: dict[str, tuple[str, ...]] = {}
for _p, _t in REL_PHRASES.items():
    REL_WORDS[_t] = (*REL_WORDS.get(_t, ()), _p)


def test_split_is_wired():
    assert "unseen_train4" in EPISODE_SPLITS
    assert UNSEEN_TEMPLATES["unseen_train4"] == ("phrasings_train4", "train4")
    assert _renderer("unseen_train4", "goal") is T.render_goal_train4
    assert _renderer("unseen_train4", "sensor") is T.render_sensor_train4
    assert _renderer("unseen_train4", "hint") is T.hint_text_train4
    assert _renderer("unseen_train4", "instruction") is T.render_instruction_train4


@settings(max_examples=15, deadline=None)
@given(sgs=st.lists(subgoals(), min_size=1, max_size=4), c=constraints(), seed=st.integers(0, 2**31),
       strict=st.booleans())
def test_same_seed_same_text(sgs, c, seed, strict):
    def run():
        rng = np.random.default_rng(seed)
        prefix, tail, written = T.render_sensor_train4(rng, c)
        res = [T.render_goal_train4(rng, sg, prefix=prefix, tail=tail, hint=T.hint_text_train4(rng, "3.5", "2"))
               for sg in sgs]
        return res, written, T.render_instruction_train4(rng, res, "strict" if strict else "free")

    assert run() == run()


# ----------------------------------------------------------------------------------------------------
# A reader of train4's goals


def _relations_at_top(text: str) -> list[tuple[int, int, str]]:
    depth, out, i = _depths(text), [], 0
    while i < len(text):
        if depth[i] == 0 and (i == 0 or text[i - 1] == " "):
            for p in _BY_LENGTH:
                if text.startswith(p + " the ", i):
                    out.append((i, i + len(p), REL_PHRASES[p]))
                    i += len(p)
                    break
        i += 1
    return out


def _read_chain(text: str) -> list[tuple[str, dict]]:
    rels = _relations_at_top(text)
    assert rels and text[: rels[0][0]].strip() == "", text
    out = []
    for k, (_, end, rtype) in enumerate(rels):
        stop = rels[k + 1][0] if k + 1 < len(rels) else len(text)
        seg = re.sub(r"(, and additionally|, plus| and)\s*$", "", text[end:stop].strip())
        out.append((rtype, _read_np(seg.strip().rstrip(","))))
    return out


def _read_np(seg: str) -> dict:
    """'the switched-on teal lamp (yes, the one next to the sofa)', 'the lamp (listed as teal and wool)', 'the lamp
    (status on arrival: open), the one that's teal and wool', 'the lamp (and it's empty!)'."""
    got = {"attrs": [], "after": [], "states": [], "relations": []}
    depth, groups, plain, i = _depths(seg), [], "", 0
    while i < len(seg):
        if seg[i] == "(" and depth[i] == 1:
            j = i
            while not (seg[j] == ")" and depth[j] == 1):
                j += 1
            groups.append(seg[i + 1: j])
            i = j + 1
            continue
        plain += seg[i]
        i += 1
    for body in groups:
        if m := re.fullmatch(r"(?:cross-reference:|yes,) the one (.+)", body):
            got["relations"] += _read_chain(m.group(1))
        elif m := re.fullmatch(r"status on arrival: (.+)|and it's (.+)!", body):
            got["states"] += (m.group(1) or m.group(2)).split(" and ")
        elif m := re.fullmatch(r"listed as (.+)", body):
            got["after"] += m.group(1).split(" and ")
        else:
            raise AssertionError(f"unknown bracket {body!r} in {seg!r}")
    parts = [p.strip() for p in plain.split(",") if p.strip()]
    for p in parts[1:]:
        m = re.fullmatch(r"the one that's (.+)", p)
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


_ROOM_RX = re.compile(r"(?:located within |way over in |in )the (" + "|".join(sorted(ROOMS, key=len, reverse=True))
                      + r")\b")


def read_goal(text: str) -> tuple[dict, str | None]:
    room = None
    m = _ROOM_RX.search(text)
    if m and _depths(text)[m.start()] == 0:
        room = m.group(1)
        text = " ".join((text[: m.start()] + " " + text[m.end():]).split())
    rels = _relations_at_top(text)
    main = text[: rels[0][0]] if rels else text
    got = _read_np(main.strip().rstrip(","))
    if rels:
        got["relations"] += _read_chain(text[rels[0][0]:])
    return got, room


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece_and_reads_back_exactly(sg, seed):
    text = T.render_goal_train4(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, REL_WORDS)
    got, room = read_goal(text)
    assert reading_norm(got) == target_truth(sg.target), text
    assert room == sg.room, text


def test_nested_goal_and_every_attribute_state_and_room_form():
    t = Target("teal wool lamp", "lamp", ("teal", "wool", "switched on"), (
        Relation("next_to", Target("sofa", "sofa", ("open",), (Relation("with", Target("drums", "drums")),))),
        Relation("under", Target("shelves", "shelves", ("empty",)))))
    rng = np.random.default_rng(0)
    texts = [T.render_goal_train4(rng, Subgoal(0, t, room="music room")) for _ in range(200)]
    for text in texts:
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "music room", text
        assert text.index("music room") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
    for rx in (r"^the teal wool lamp", r"\(listed as teal and wool\)", r", the one that's teal and wool,",
               r"^the switched-on ", r"\(status on arrival: switched on\)", r"\(and it's switched on!\)",
               r"located within the music room", r"way over in the music room", r"\(cross-reference: the one ",
               r"\(yes, the one ", r"the shelves \(status on arrival: empty\)", r"the empty shelves",
               r", and additionally ", r", plus "):
        assert any(re.search(rx, x) for x in texts), rx


def test_every_relation_word_is_used_and_read():
    rng = np.random.default_rng(7)
    for rtype in T.REL_WORDS:
        sg = Subgoal(0, Target("lamp", "lamp", (), (Relation(rtype, Target("sofa", "sofa")),)))
        seen = set()
        for _ in range(40):
            text = T.render_goal_train4(rng, sg)
            assert read_goal(text)[0]["relations"][0][0] == rtype, text
            seen.add(text[len("the lamp "): -len(" the sofa")])
        assert seen == set(REL_WORDS[rtype]), rtype


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own

_DIGITS = {w: str(i) for i, w in enumerate(("nought", "one", "two", "three", "four", "five", "six", "seven", "eight",
                                            "nine"))}


def _half(m: re.Match) -> str:
    k = spoken_numbers(m.group(1).split())
    assert len(k) == 1, m.group(0)
    return f"{k[0] + 0.5:g}"


def numbers_in(text: str) -> list[float]:
    """Every number: '-18', '.65', 'minus 18', 'minus eighteen', '22 and a half', 'twenty-two and a half', 'nought
    point six five', '18 degrees of frost' ('the one', 'that's one' are no numbers)."""
    t = " " + text.lower().replace("°c", " c").replace("℃", " c") + " "
    t = re.sub(r"\b(the|that's|any|only|just) one\b", r"\1 ONE", t)
    t = re.sub(r"nought point ((?:(?:" + "|".join(_DIGITS) + r")\b ?)+)",
               lambda m: "0." + "".join(_DIGITS[w] for w in m.group(1).split()) + " ", t)
    t = re.sub(r"\b(\d+) and a half\b", r"\1.5", t)
    t = re.sub(r"\b([a-z]+(?:-[a-z]+)?(?: hundred(?: and [a-z]+(?:-[a-z]+)?)?)?) and a half\b", _half, t)
    t = re.sub(r"(\d+(?:\.\d+)?|[a-z]+(?:-[a-z]+)?) degrees of frost", r"minus \1 degrees", t)
    return spoken_numbers(re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)*", t))


def comparator_of(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"approximately|estimated at|hovers close to|just about|somewhere round", "approx"),
                  (r"equal to or greater|not fall short of|not less than|goes higher still|or even bigger|"
                   r"at least as", "ge"),
                  (r"equal to or less|not exceed|not greater than|not a crumb more|or even smaller|"
                   r"not any (warmer|damper|greener)", "le"),
                  (r"exceeds|in excess of|not at or below|higher up than|jumped right over|bigger than|ranks above|"
                   r"(warmer|damper|greener) than", "gt"),
                  (r"falls short of|not at or above|smaller than|lower down than|climbed up to|ranks below|"
                   r"(chillier|drier|less green) than", "lt")):
        if re.search(rx, t):
            return c
    return "?"


def reading_of(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|verdant|vibrant|sprout|faded|washed-out|poorly|green|droopy", t):
        return "ndvi"
    if re.search(r"humid|damp|drier|drippy|waterlog|saturat|desert-dry|crackly|%|percent|per cent|puddle|biscuit",
                 t):
        return "humidity_pct"
    if re.search(r"temperature|°c|℃|degree|warm|chill|piping|blister|red-hot|ice-cold|wintry|shivery|snowman", t):
        return "temperature_c"
    return "?"


_LOW = r"ice-cold|wintry|shivery|faded|washed-out|poorly|desert-dry|least damp|crackly|minimum|falls below|" \
       r"bottom|lowest|snowman|biscuit|droopy"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = T.render_sensor_train4(np.random.default_rng(seed), c)
    check_sensor(rendered, c, comparator_of, _LOW, r"°c|℃|degree", r"(?i)%|per ?cent", numbers_in, reading_of)
    text = (rendered[0] + " " + rendered[1]).strip()
    assert "(" not in text and "  " not in text, text
    if "frost" in text:
        assert c.comparator == "approx" and rendered[2].value < 0, text
    if not rendered[2].unit and not c.is_superlative:  # a unitless number always has its reading named
        assert re.search(r"temperature|humidity|ndvi", text.lower()), text


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase_after_the_head(c, sg, seed):
    check_sensor_goal(T.render_sensor_train4, T.render_goal_train4, c, sg, seed, numbers_in)


@SETTINGS
@given(c=constraints(), sg=subgoals(), x=st.floats(-20, 40).map(lambda v: round(v, 1)),
       y=st.floats(-20, 40).map(lambda v: round(v, 1)), seed=st.integers(0, 2**31))
def test_a_goal_with_sensor_hint_and_relations_keeps_every_number_and_piece(c, sg, x, y, seed):
    """The hint's numbers come last (after any number of the sensor phrase); head, room and anchors stay whole."""
    rng = np.random.default_rng(seed)
    prefix, tail, written = T.render_sensor_train4(rng, c)
    hint = T.hint_text_train4(rng, f"{x:.1f}", f"{y:.1f}")
    text = T.render_goal_train4(rng, sg, prefix=prefix, tail=tail, hint=hint)
    nums = numbers_in(text)
    assert nums[-2:] == [pytest.approx(x), pytest.approx(y)], text
    assert nums[:-2] == ([] if c.is_superlative else [pytest.approx(written.value)]), text
    assert text.count("(") == text.count(")") and "  " not in text and not text.endswith(("–", ",")), text
    if sg.room:
        assert f"the {sg.room}" in text, text
    low = text.lower()
    assert low.find(sg.target.head) < min((low.find(r.anchor.head) for r in sg.target.relations), default=10**6) \
        or any(sg.target.head in r.anchor.head for r in sg.target.relations), text
    if sg.target.relations:  # the sensor phrase and the hint come before the first anchor
        first = min(low.find(" the " + r.anchor.phrase) for r in sg.target.relations)
        assert low.rfind(f"{y:.1f}", 0, first) > 0, text


def test_every_superlative_says_its_reading_and_direction():
    """Every superlative word of every reading, read by our own word lists (not the templates' tables)."""
    rng = np.random.default_rng(11)
    for rd in ("temperature_c", "humidity_pct", "ndvi"):
        for cmp in ("max", "min"):
            c = SensorConstraint(rd, cmp)
            seen = {T.render_sensor_train4(rng, c)[:2] for _ in range(150)}
            assert len(seen) == 3 + 5, (rd, cmp, seen)  # three adjectives, five tails
            for prefix, tail in seen:
                text = (prefix + " " + tail).strip()
                assert reading_of(text) == rd and bool(re.search(_LOW, text)) == (cmp == "min"), text
                assert numbers_in(text) == [], text


def test_number_formats_frames_and_superlatives_vary():
    rng = np.random.default_rng(3)
    cold = {T.render_sensor_train4(rng, SensorConstraint("temperature_c", "approx", -18.0))[1] for _ in range(200)}
    for rx in (r"minus eighteen", r"minus 18\b", r"-18\b", r"\b(18|eighteen) degrees of frost", r"^that ",
               r"^whose ", r"^with a logged temperature that ", r"^– the one whose temperature ", r"°C", r"℃"):
        assert any(re.search(rx, t) for t in cold), rx
    assert all(numbers_in(t) == [-18.0] for t in cold)
    half = {T.render_sensor_train4(rng, SensorConstraint("humidity_pct", "lt", 22.5))[1] for _ in range(200)}
    for rx in (r"\b22 and a half", r"twenty-two and a half", r"22\.5", r"%RH", r"percent relative humidity",
               r"drier than"):
        assert any(re.search(rx, t) for t in half), rx
    assert all(numbers_in(t) == [22.5] for t in half)
    ndvi = {T.render_sensor_train4(rng, SensorConstraint("ndvi", "gt", 0.65))[1] for _ in range(200)}
    for rx in (r"(?<![\d])\.65\b", r"0\.65\b", r"nought point six five", r"an NDVI of", r"greener than"):
        assert any(re.search(rx, t) for t in ndvi), rx
    for (rd, cmp), adjs in T._SUPER_ADJ.items():
        sup = {T.render_sensor_train4(rng, SensorConstraint(rd, cmp)) for _ in range(120)}
        assert set(adjs) <= {p for p, _, _ in sup}, (rd, cmp)
        assert len({t for _, t, _ in sup if t}) == 5, (rd, cmp)
    for rd, value in (("temperature_c", 30.0), ("humidity_pct", 40.0), ("ndvi", 0.4)):
        for cmp in ("gt", "ge", "lt", "le", "approx"):
            seen = {T.render_sensor_train4(rng, SensorConstraint(rd, cmp, value))[1] for _ in range(120)}
            assert {comparator_of(s) for s in seen} == {cmp}, (rd, cmp, seen)
            assert {reading_of(s) for s in seen} == {rd} and all(numbers_in(s) == [value] for s in seen), seen
            if rd == "temperature_c":  # many idioms for each comparison
                assert len({re.sub(r"^(that|whose temperature|with a logged temperature that|– the one whose "
                                   r"temperature) |thirty.*|30.*", "", s) for s in seen}) >= 5, cmp


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(T.hint_text_train4, T.render_goal_train4, T.render_instruction_train4, x, y, seed)


STRICT_CUES = r"strictly in numbered sequence|out of sequence|in the order stated above and no other|" \
              r"in the right order|one after the other"
FREE_CUES = r"adjuster's discretion|no sequence is prescribed|whatever order is convenient|no bearing on the claim|" \
            r"in any order you like|any one can be first"
_COUNTS = {w: i for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight"))}


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_stay_whole_in_order(sgs, seed, strict):
    check_order(T.render_goal_train4, T.render_instruction_train4, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [T.render_goal_train4(rng, sg) for sg in sgs]
    text = T.render_instruction_train4(rng, res, "strict" if strict else "free")
    if strict:
        assert re.search(STRICT_CUES, text.lower()), text
    at = 0
    for r in res:  # every goal once, whole, in visiting order
        m = re.compile(re.escape(r) + r"(?![\w-])").search(text, at)
        assert m, (r, text)
        at = m.end()
    for m in re.finditer(r"\b(" + "|".join(_COUNTS) + r") (?:items|treasures)\b|Items of interest: (\w+),", text):
        assert _COUNTS[m.group(1) or m.group(2)] == len(sgs), text
    numbered = [int(m.group(1)) for m in re.finditer(r"^(\d+)\. Item of interest: ", text, re.M)]
    assert numbered in ([], list(range(1, len(sgs) + 1))), text


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_and_keeps_the_goal(sg, seed):
    rng = np.random.default_rng(seed)
    goal = T.render_goal_train4(rng, sg)
    text = T.render_instruction_train4(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text), text
    assert not re.search(FREE_CUES, text.lower()) and not re.search(STRICT_CUES, text.lower()), text


def test_both_authors_and_every_cue_are_used():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    texts = [T.render_instruction_train4(rng, res, order) for order in ("strict", "free") for _ in range(60)]
    for m in (r"inspection|item of interest|claim", r"treasure|clue|little"):
        assert any(re.search(m, t.lower()) for t in texts), m
    for some, cues in ((texts[:60], STRICT_CUES), (texts[60:], FREE_CUES)):
        got = {c for t in some for c in re.findall(cues, t.lower())}
        assert got == set(cues.split("|")), set(cues.split("|")) - got
    assert any("\n" in t for t in texts) and any("\n" not in t for t in texts)
