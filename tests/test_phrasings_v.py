"""The `unseen_v` held-out templates (set V): every piece of the ground truth is written down.

Checked with small readers of their own (a goal reader that recovers head, attributes, states, room and nested
relations; words for comparators, readings, units, numbers, coordinates and order cues) that share no code with
the templates, over random subgoals drawn by hypothesis. Whole generated episode files are checked here for the
numbers of their readings; the split's wiring and the four functions' determinism in tests/test_heldout_sets.py.
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

from ragnav_jax.language import phrasings_v as V
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# V's words for each relation, written here apart from the templates' own table (a reader's list)
V_REL_WORDS = {
    "near": ("near", "spit and a cough from", "general area of", "few yards from"),
    "next_to": ("next to", "nudging"),
    "beside": ("beside",), "by": ("by",),
    "on": ("on",), "under": ("under",),
    "above": ("above", "overhanging"), "in": ("in", "into"),
    "with": ("with", "bearing"),
    "in_room_with": ("same room as", "very room that has", "rooming with"),
    "in_front_of": ("in front of",), "behind": ("behind",),
    "opposite": ("opposite", "squaring up to", "over against"),
    "left_of": ("left of",), "right_of": ("right of",),
}
# The whole phrases a reader of V's goals splits on, each with its relation type.
V_REL_PHRASES = {
    "near": "near", "a spit and a cough from": "near", "in the general area of": "near",
    "only a few yards from": "near",
    "next to": "next_to", "butted up next to": "next_to", "nudging": "next_to", "hard up next to": "next_to",
    "beside": "beside", "sat just beside": "beside", "ranged beside": "beside",
    "by": "by", "lingering by": "by", "hanging about by": "by",
    "on": "on", "stacked on": "on", "lodged on": "on",
    "under": "under", "wedged under": "under", "squirrelled away under": "under",
    "above": "above", "overhanging": "above", "way up above": "above",
    "in": "in", "tucked into": "in", "boxed up in": "in",
    "with": "with", "rigged up with": "with", "bearing": "with",
    "in the same room as": "in_room_with", "in the very room that has": "in_room_with", "rooming with": "in_room_with",
    "in front of": "in_front_of", "dead in front of": "in_front_of", "placed smack in front of": "in_front_of",
    "behind": "behind", "stashed behind": "behind", "away behind": "behind",
    "opposite": "opposite", "squaring up to": "opposite", "set over against": "opposite",
    "to the left of": "left_of", "a pace to the left of": "left_of", "hard to the left of": "left_of",
    "to the right of": "right_of", "a pace to the right of": "right_of", "hard to the right of": "right_of",
}
_BY_LENGTH = sorted(V_REL_PHRASES, key=len, reverse=True)


# ----------------------------------------------------------------------------------------------------
# A reader of V's goals: head, attributes, states, room and relations, nested


def _relations_at_top(text: str) -> list[tuple[int, int, str]]:
    """(start, end, type) of every relation phrase outside brackets that is followed by 'the'."""
    depth, out, i = _depths(text), [], 0
    while i < len(text):
        if depth[i] == 0 and (i == 0 or text[i - 1] == " "):
            for p in _BY_LENGTH:
                if text.startswith(p + " the ", i):
                    out.append((i, i + len(p), V_REL_PHRASES[p]))
                    i += len(p)
                    break
        i += 1
    return out


def _read_chain(text: str) -> list[tuple[str, dict]]:
    """'nudging the sofa, plus wedged under the shelf' -> [('next_to', sofa), ('under', shelf)]."""
    rels = _relations_at_top(text)
    assert rels and text[: rels[0][0]].strip() == "", text
    out = []
    for k, (_, end, rtype) in enumerate(rels):
        stop = rels[k + 1][0] if k + 1 < len(rels) else len(text)
        seg = re.sub(r"(, and likewise|, plus| and)\s*$", "", text[end:stop].strip())
        out.append((rtype, _read_np(seg.strip())))
    return out


def _read_np(seg: str) -> dict:
    """A noun phrase of V: 'the switched-on teal wool lamp (specifically the one next to the sofa)', 'the lamp (teal
    and wool, if memory serves), switched on as of this morning,', 'the lamp (empty, so I'm told), answering the
    description teal and wool'."""
    got = {"attrs": [], "after": [], "states": [], "relations": []}
    depth, groups, plain = _depths(seg), [], ""
    i = 0
    while i < len(seg):  # take out the bracketed groups
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
        if m := re.fullmatch(r"(?:specifically|mind you,) the one (.+)", body):
            got["relations"] += _read_chain(m.group(1))
        elif m := re.fullmatch(r"(.+), so I'm told", body):
            got["states"] += m.group(1).split(" and ")
        elif m := re.fullmatch(r"(.+), if memory serves", body):
            got["after"] += m.group(1).split(" and ")
        else:
            raise AssertionError(f"unknown bracket {body!r} in {seg!r}")
    parts = [p.strip() for p in plain.split(",") if p.strip()]
    for p in parts[1:]:
        if m := re.fullmatch(r"(.+) as of this morning", p):
            got["states"] += m.group(1).split(" and ")
        elif m := re.fullmatch(r"answering the description (.+)", p):
            got["after"] += m.group(1).split(" and ")
        else:
            raise AssertionError(f"unknown aside {p!r} in {seg!r}")
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


def read_goal(text: str) -> tuple[dict, str | None]:
    """(the target read back, the room) from a goal written without hint or sensor phrase."""
    room = None
    m = re.search(r"(?:up in|in) the (" + "|".join(sorted(ROOMS, key=len, reverse=True)) + r")\b", text)
    if m:
        room = m.group(1)
        text = text[: m.start()] + text[m.end():]
    text = " ".join(text.split())
    rels = _relations_at_top(text)
    main = text[: rels[0][0]] if rels else text
    got = _read_np(main.strip().rstrip(","))
    if rels:
        got["relations"] += _read_chain(text[rels[0][0]:])
    return got, room


# ----------------------------------------------------------------------------------------------------
# Goals


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece_and_reads_back_exactly(sg, seed):
    text = V.render_goal_v(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, V_REL_WORDS)
    assert ") (" not in text and max(_depths(text), default=0) <= 1, text  # no brackets in a row, nor one in another
    got, room = read_goal(text)
    assert reading_norm(got) == target_truth(sg.target), text
    assert room == sg.room, text


def test_reader_reads_a_nested_goal():
    t = Target("teal wool lamp", "lamp", ("teal", "wool", "switched on"), (
        Relation("next_to", Target("sofa", "sofa", ("open",), (Relation("with", Target("drums", "drums")),))),
        Relation("under", Target("shelves", "shelves"))))
    rng = np.random.default_rng(0)
    forms = set()
    for _ in range(120):
        text = V.render_goal_v(rng, Subgoal(0, t, room="music room"))
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "music room", text
        assert text.index("music room") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
        forms.add("specifically" if "(specifically the one " in text else "mind" if "(mind you, the one " in text
                  else "?")
    assert forms == {"specifically", "mind"}


def test_attributes_states_and_rooms_take_every_form():
    rng = np.random.default_rng(2)
    t = Target("vintage wool toolbox", "toolbox", ("vintage", "wool", "empty"))
    texts = [V.render_goal_v(rng, Subgoal(0, t)) for _ in range(400)]
    for rx in (r"^the (empty )?vintage wool toolbox", r"^the (empty )?toolbox \(vintage and wool, if memory serves\)",
               r"^the (empty )?toolbox, answering the description vintage and wool",
               r"^the toolbox \(empty, so I'm told\), answering the description vintage and wool$",
               r", empty as of this morning$", r"wool toolbox \(empty, so I'm told\)$", r"^the empty vintage"):
        assert any(re.search(rx, x) for x in texts), rx
    assert not any(") (" in x or x.endswith(",") for x in texts)
    rooms = {re.sub(r"^the kettle ", "", V.render_goal_v(rng, Subgoal(0, Target("kettle", "kettle"), room="pantry")))
             for _ in range(80)}
    assert rooms == {"in the pantry", "up in the pantry"}


def test_every_relation_word_is_used_and_read():
    rng = np.random.default_rng(7)
    for rtype in V.REL_WORDS:
        sg = Subgoal(0, Target("lamp", "lamp", (), (Relation(rtype, Target("sofa", "sofa")),)))
        seen = set()
        for _ in range(150):
            text = V.render_goal_v(rng, sg)
            got, _ = read_goal(text)
            assert got["relations"][0][0] == rtype, text
            seen.add(text[len("the lamp "): -len(" the sofa")])
        assert seen == set(V.REL_WORDS[rtype]), rtype
    two = Subgoal(0, Target("lamp", "lamp", (), (Relation("near", Target("sofa", "sofa")),
                                                 Relation("on", Target("rug", "rug")))))
    joins = {re.search(r"sofa(.*?) (?:stacked on|lodged on|on) the rug$", V.render_goal_v(rng, two)).group(1)
             for _ in range(120)}
    assert joins == {" and", ", and likewise", ", plus"}


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own

_FRACTION = {"half": 0.5, "quarter": 0.25, "three quarters": 0.75}
_DIGITS = {w: str(i) for i, w in enumerate(("nought", "one", "two", "three", "four", "five", "six", "seven", "eight",
                                              "nine"))}


def numbers_in(text: str) -> list[float]:
    """Every number in the text: '-18', '.65', '0.650', 'minus 18', 'minus eighteen', 'nought point six five', '22 and
    a half', 'twenty-two and a half', '18 degrees below freezing' ('the one' is a pronoun, not a number)."""
    t = text.lower().replace("°c", " c").replace("the one", "the ONE")
    t = re.sub(r"nought point((?: (?:" + "|".join(_DIGITS) + r"))+)",
               lambda m: "0." + "".join(_DIGITS[w] for w in m.group(1).split()), t)
    t = re.sub(r"([a-z]+(?:-[a-z]+)*|\d+(?:\.\d+)?) degrees below freezing", r"minus \1 degrees", t)
    out: list[float] = []
    for k, chunk in enumerate(re.split(r" and (a half|a quarter|three quarters)\b", t)):
        if k % 2:  # a fraction: it belongs to the number just before it
            out[-1] += _FRACTION[chunk.removeprefix("a ")]
            continue
        out += spoken_numbers(re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)*", chunk))
    return out


def comparator_of(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"hover(s|ing) round|near as dammit|within a smidge of", "approx"),
                  (r"or better|(doesn't|not) fall(ing)? short of|match(es|ing) or pass", "ge"),
                  (r"never exceed|or less\b|no higher", "le"),
                  (r"sail(ed|ing) past|overshoot|\bpip(s|ping)\b", "gt"),
                  (r"fall(s|ing)? short of|as far as|undercut", "lt")):
        if re.search(rx, t):
            return c
    return "?"


def reading_of(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|health|lush|verdant|sickl", t):
        return "ndvi"
    if re.search(r"humid|sultr|sodden|driest|desiccat|%|per ?cent", t):
        return "humidity_pct"
    if re.search(r"temperature|warmest|blister|baking|coldest|chill|wintry|°|degree", t):
        return "temperature_c"
    return "?"


_LOW = r"coldest|chilliest|wintry|least|sickliest|driest|desiccated|lowest|lowliest|under all"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    prefix, tail, written = rendered = V.render_sensor_v(np.random.default_rng(seed), c)
    check_sensor(rendered, c, comparator_of, _LOW, r"°c|degree", r"(?i)%|per ?cent", numbers_in, reading_of)
    text = (prefix + " " + tail).strip()
    assert text.count("(") == text.count(")"), text
    if "below freezing" in text:  # only ever said of a temperature near which the thing should be
        assert c.comparator == "approx" and written.value < 0, text


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase(c, sg, seed):
    check_sensor_goal(V.render_sensor_v, V.render_goal_v, c, sg, seed, numbers_in)


def test_number_formats_and_frames_vary():
    rng = np.random.default_rng(3)
    seen = set()
    for _ in range(400):
        _, tail, _ = V.render_sensor_v(rng, SensorConstraint("temperature_c", "approx", -18.0))
        seen.add("words" if "minus eighteen" in tail else "minus" if "minus 18" in tail else
                 "below" if re.search(r"\b(18|eighteen) degrees below freezing", tail) else
                 "decimal" if "-18.0" in tail else "digits" if "-18" in tail else "?")
    assert seen == {"words", "minus", "below", "decimal", "digits"}
    lt = {V.render_sensor_v(rng, SensorConstraint("temperature_c", "lt", -18.0))[1] for _ in range(100)}
    assert not any("below" in t for t in lt)
    halves = {V.render_sensor_v(rng, SensorConstraint("humidity_pct", "gt", 37.5))[1] for _ in range(200)}
    assert {"37 and a half", "thirty-seven and a half", "37.5"} <= {m for t in halves for m in re.findall(
        r"thirty-seven and a half|37 and a half|37\.5", t)}
    assert all(numbers_in(t) == [37.5] for t in halves)
    ndvi = {V.render_sensor_v(rng, SensorConstraint("ndvi", "gt", 0.65))[1] for _ in range(300)}
    for rx in (r"(?<![\d])\.65\b", r"0\.650\b", r"nought point six five", r"^whose NDVI ", r"^with its NDVI ",
               r"^\(its NDVI "):
        assert any(re.search(rx, t) for t in ndvi), rx
    assert all(numbers_in(t) == [pytest.approx(0.65)] for t in ndvi)
    hum = {V.render_sensor_v(rng, SensorConstraint("humidity_pct", "le", 40.0))[1] for _ in range(300)}
    for rx in (r"40% RH", r"forty per ?cent", r"^that ", r"40\.0"):
        assert any(re.search(rx, t) for t in hum), rx
    temp = {V.render_sensor_v(rng, SensorConstraint("temperature_c", "approx", 321.0))[1] for _ in range(300)}
    assert any("three hundred and twenty-one" in t for t in temp) and any("degrees centigrade" in t for t in temp)
    assert all(numbers_in(t) == [321.0] for t in temp)


def test_superlatives_take_adjectives_and_tails():
    rng = np.random.default_rng(5)
    got = {V.render_sensor_v(rng, SensorConstraint("temperature_c", "min")) for _ in range(200)}
    assert {"coldest", "chilliest", "most wintry"} <= {p for p, _, _ in got if p}
    assert {"whose temperature is the lowest of all", "that comes in under all others on temperature",
            "with the lowliest temperature reading"} <= {t for _, t, _ in got if t}
    got = {V.render_sensor_v(rng, SensorConstraint("ndvi", "max"))[1] for _ in range(200)}
    assert {"whose NDVI is the highest of all", "that outdoes all others on NDVI",
            "with the loftiest NDVI reading"} <= got


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(V.hint_text_v, V.render_goal_v, V.render_instruction_v, x, y, seed)


def test_every_coordinate_form_is_used():
    rng = np.random.default_rng(4)
    hints = {V.hint_text_v(rng, "-3.5", "2.0") for _ in range(200)}
    assert hints == {"where x equals -3.5 and y equals 2.0", "(abscissa -3.5, ordinate 2.0)",
                     "at position x -3.5 · y 2.0", "on the spike mark at x -3.5, y 2.0"}
    goal = V.render_goal_v(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(-3.5, 2.0)),
                           hint="(abscissa -3.5, ordinate 2.0)")
    assert goal == "the guitar (abscissa -3.5, ordinate 2.0)"


STRICT_CUES = r"strict running order|no jumping cues|in the order rehearsed|blocking is set|in the order called|" \
              r"course by course|jumps a course|in that order|phase by phase|nobody freelances|seriatim|" \
              r"strictly in the sequence|may not be varied|order of attendance is a condition"
FREE_CUES = r"in any order|whatever order|no set blocking|no firing order|whichever's ready first|no fixed order|" \
            r"pick them off|no particular sequence|no preference as to the order"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_keep_their_order(sgs, seed, strict):
    check_order(V.render_goal_v, V.render_instruction_v, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [V.render_goal_v(rng, sg) for sg in sgs]
    text = V.render_instruction_v(rng, res, "strict" if strict else "free")
    low = text.lower()
    if strict:  # a strict text also says so in words of its own
        assert re.search(STRICT_CUES, low), text
    at = 0
    for r in res:  # every goal is written whole, in visiting order
        at = low.find(r.lower(), at)
        assert at >= 0, (r, text)
        at += len(r)


_OWN_HEADS = ("kettle", "toaster", "guitar", "harp", "heater", "fern", "lamp", "sofa")
_WORDS = {w: i for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight"))}


@SETTINGS
@given(n=st.integers(2, 8), seed=st.integers(0, 2**31), strict=st.booleans())
def test_stated_counts_and_numbered_lines_agree_with_the_goals(n, seed, strict):
    res = [f"the {h}" for h in _OWN_HEADS[:n]]
    text = V.render_instruction_v(np.random.default_rng(seed), res, "strict" if strict else "free")
    for m in re.finditer(r"\b(\w+) (?:covers|all day|jobs|marks to play with|routines\))", text):
        assert _WORDS[m.group(1).lower()] == n, text
    lines = text.split("\n")
    goal_lines = [ln for ln in lines if re.search(r"\bthe (" + "|".join(_OWN_HEADS[:n]) + r")\b", ln)]
    if len(goal_lines) > 1:  # a layout of one goal a line, numbered in visiting order where numbered
        assert len(goal_lines) == n, text
        for rx, first in ((r"(?:LX|Cue|SQ) (\d+)\. ", 1), (r"Course (\d+) ▸ ", 1), (r"Phase (\d+): ", 2),
                          (r"1\.(\d+) ", 1)):
            nums = [int(m.group(1)) for ln in goal_lines if (m := re.match(rx, ln))]
            if nums:
                assert nums == list(range(first, first + len(nums))), text
        letters = [m.group(1) for ln in goal_lines if (m := re.match(r"\(([a-j])\) ", ln))]
        if letters:
            assert letters == list("abcdefghij"[:n]), text
    terms = re.findall(r"hereinafter 'the (\w+) Chattel'", text)
    if terms:  # defined terms count up and the last is the final one
        assert terms == ["First", "Second", "Third", "Fourth", "Fifth", "Sixth", "Seventh"][: n - 1] + ["Final"], text


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_and_keeps_the_goal(sg, seed):
    rng = np.random.default_rng(seed)
    goal = V.render_goal_v(rng, sg)
    text = V.render_instruction_v(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text), text
    assert not re.search(FREE_CUES, text.lower()), text


def test_every_register_is_used_and_a_seed_repeats():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    texts = [V.render_instruction_v(rng, res, order) for order in ("strict", "free") for _ in range(80)]
    marks = (r"robot enters|\bcue\b|blocking|devising|rehearsed", r"covers|all day|mise en place|\bchef\b",
             r"game plan|kick-off|final whistle|set pieces|switch play", r"whereas|hereinafter|yours faithfully")
    for m in marks:
        assert any(re.search(m, t.lower()) for t in texts), m
    assert any("\n" in t for t in texts) and any("\n" not in t for t in texts)  # multi-line and paragraphs
    assert len(set(texts)) > 40
    singles = [V.render_instruction_v(rng, res[:1], "strict") for _ in range(60)]
    single_marks = (r"robot alone on stage|monologue", r"single cover|just the one –", r"one job today|set piece",
                    r"whereas|dear robot")
    for m in single_marks:
        assert any(re.search(m, t.lower()) for t in singles), m
    again = [V.render_instruction_v(np.random.default_rng(9), res, "free") for _ in range(2)]
    assert again[0] == again[1]


# ----------------------------------------------------------------------------------------------------
# Whole episode files (the checks every held-out set shares: tests/test_heldout_sets.py)


def test_unseen_v_sensor_numbers_are_the_constraints():
    """The written number of a reading is the constraint's, in the goal's own text."""
    from test_heldout_sets import SMALL

    from ragnav_jax.config import load_config
    from ragnav_jax.language.episodes import generate_episodes
    from ragnav_jax.world.generator import generate_scene

    scene = generate_scene(load_config(None, SMALL).world, 5, 0)
    eps = generate_episodes([scene], load_config(None, [*SMALL, "episodes.split=unseen_v"]).episodes, seed=3)
    assert eps
    for p in eps:
        for sg in p.truth.subgoals:
            for c in sg.sensors:
                if not c.is_superlative:
                    assert numbers_in(sg.text) == [pytest.approx(c.value, abs=0.006)], sg.text
