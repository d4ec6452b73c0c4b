"""The `unseen_u` held-out templates (set U): every piece of the ground truth is written down.

Checked with small readers of their own (a goal reader that recovers head, attributes, states, room and nested
relations; words for comparators, readings, units, numbers, coordinates and order cues) that share no code with
the templates, over random subgoals drawn by hypothesis. Whole generated episode files are checked for determinism
here; the split's wiring and the four functions' determinism in tests/test_heldout_sets.py.
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

from ragnav_jax.language import phrasings_u as U
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# U's words for each relation, written here apart from the templates' own table (a reader's list)
U_REL_WORDS = {
    "near": ("near", "hailing distance of", "handy for", "great distance from"),
    "next_to": ("next to", "hugging"),
    "beside": ("beside",), "by": ("by",),
    "on": ("on",), "under": ("under",),
    "above": ("above", "over the top of", "towering over"), "in": ("in", "inside"),
    "with": ("with",),
    "in_room_with": ("same room as", "room shared with", "room along with"),
    "in_front_of": ("in front of",), "behind": ("behind",),
    "opposite": ("opposite", "eyeing up", "facing off with"),
    "left_of": ("left of",), "right_of": ("right of",),
}
# The whole phrases a reader of U's goals splits on, each with its relation type.
U_REL_PHRASES = {
    "near": "near", "within hailing distance of": "near", "handy for": "near", "no great distance from": "near",
    "next to": "next_to", "hugging": "next_to", "snuggled next to": "next_to", "immediately next to": "next_to",
    "beside": "beside", "huddled beside": "beside", "posted beside": "beside",
    "by": "by", "camped by": "by", "hovering by": "by",
    "on": "on", "sitting pretty on": "on", "piled on": "on", "laid out on": "on",
    "under": "under", "hiding under": "under", "crouched under": "under",
    "above": "above", "over the top of": "above", "towering over": "above",
    "in": "in", "bundled inside": "in", "locked away in": "in",
    "with": "with", "fitted with": "with", "equipped with": "with", "that goes with": "with",
    "in the same room as": "in_room_with", "in the room shared with": "in_room_with",
    "in a room along with": "in_room_with",
    "in front of": "in_front_of", "plumb in front of": "in_front_of", "standing guard in front of": "in_front_of",
    "behind": "behind", "sheltering behind": "behind", "peeking out from behind": "behind",
    "opposite": "opposite", "eyeing up": "opposite", "facing off with": "opposite",
    "to the left of": "left_of", "a shade to the left of": "left_of", "over on the left of": "left_of",
    "to the right of": "right_of", "a shade to the right of": "right_of", "over on the right of": "right_of",
}
_BY_LENGTH = sorted(U_REL_PHRASES, key=len, reverse=True)


# ----------------------------------------------------------------------------------------------------
# A reader of U's goals: head, attributes, states, room and relations, nested


def _relations_at_top(text: str) -> list[tuple[int, int, str]]:
    """(start, end, type) of every relation phrase outside brackets that is followed by 'the' ('by the look of it'
    is an aside, not a relation)."""
    depth, out, i = _depths(text), [], 0
    while i < len(text):
        if depth[i] == 0 and (i == 0 or text[i - 1] == " ") and not text.startswith("by the look of it", i):
            for p in _BY_LENGTH:
                if text.startswith(p + " the ", i):
                    out.append((i, i + len(p), U_REL_PHRASES[p]))
                    i += len(p)
                    break
        i += 1
    return out


def _read_chain(text: str) -> list[tuple[str, dict]]:
    """'hugging the sofa as well as under the shelf' -> [('next_to', sofa), ('under', shelf)]."""
    rels = _relations_at_top(text)
    assert rels and text[: rels[0][0]].strip() == "", text
    out = []
    for k, (_, end, rtype) in enumerate(rels):
        stop = rels[k + 1][0] if k + 1 < len(rels) else len(text)
        seg = re.sub(r"(, and also| as well as| and)\s*$", "", text[end:stop].strip())
        out.append((rtype, _read_np(seg.strip())))
    return out


def _read_np(seg: str) -> dict:
    """A noun phrase of U: 'the switched-on teal-and-wool lamp (the one next to the sofa, I mean)', 'the lamp (teal +
    wool), switched on at the moment,', 'the lamp, teal and wool by the look of it (it'll be empty)'."""
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
        if m := re.fullmatch(r"the one (.+), I mean", body):
            got["relations"] += _read_chain(m.group(1))
        elif m := re.fullmatch(r"that's the one (.+)", body):
            got["relations"] += _read_chain(m.group(1))
        elif m := re.fullmatch(r"it'll be (.+)", body):
            got["states"] += m.group(1).split(" and ")
        elif " + " in body:
            got["after"] += body.split(" + ")
        else:
            raise AssertionError(f"unknown bracket {body!r} in {seg!r}")
    parts = [p.strip() for p in plain.split(",") if p.strip()]
    for p in parts[1:]:
        if m := re.fullmatch(r"(.+) at the moment", p):
            got["states"] += m.group(1).split(" and ")
        elif m := re.fullmatch(r"(.+) by the look of it", p):
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
        elif "-and-" in w:
            got["attrs"] += w.split("-and-")
        else:
            assert w.replace("-", " ") in STATES, (w, seg)
            got["states"].append(w.replace("-", " "))
    got["attrs"] += got.pop("after")
    return got


def read_goal(text: str) -> tuple[dict, str | None]:
    """(the target read back, the room) from a goal written without hint or sensor phrase."""
    room = None
    m = re.search(r"(?:back in|in) the (" + "|".join(sorted(ROOMS, key=len, reverse=True)) + r")\b", text)
    if m:
        room = m.group(1)
        text = text[: m.start()] + text[m.end():]
    text = " ".join(text.split())
    rels = _relations_at_top(text)
    main = text[: rels[0][0]] if rels else text
    got = _read_np(main.strip())
    if rels:
        got["relations"] += _read_chain(text[rels[0][0]:])
    return got, room


# ----------------------------------------------------------------------------------------------------
# Goals


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece(sg, seed):
    text = U.render_goal_u(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, U_REL_WORDS)
    assert ") (" not in text and max(_depths(text), default=0) <= 1, text  # no brackets in a row, nor one in another


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_reads_back_exactly(sg, seed):
    text = U.render_goal_u(np.random.default_rng(seed), sg)
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
        text = U.render_goal_u(rng, Subgoal(0, t, room="music room"))
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "music room", text
        assert text.index("music room") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
        forms.add("mean" if "drums, I mean)" in text else "that's" if "(that's the one " in text else "?")
    assert forms == {"mean", "that's"}


def test_attributes_states_and_rooms_take_every_form():
    rng = np.random.default_rng(2)
    t = Target("vintage wool toolbox", "toolbox", ("vintage", "wool", "empty"))
    texts = [U.render_goal_u(rng, Subgoal(0, t)) for _ in range(400)]
    for rx in (r"^the (empty )?vintage wool toolbox", r"^the (empty )?vintage-and-wool toolbox",
               r"^the (empty )?toolbox \(vintage \+ wool\)", r"toolbox, vintage and wool by the look of it",
               r", empty at the moment", r"\(it'll be empty\)", r"^the empty vintage"):
        assert any(re.search(rx, x) for x in texts), rx
    assert not any(") (" in x for x in texts)
    hyph = Target("king-size gold-framed toolbox", "toolbox", ("king-size", "gold-framed"))
    assert not any("-and-" in U.render_goal_u(rng, Subgoal(0, hyph)) for _ in range(100))  # no 'king-size-and-...'
    rooms = {re.sub(r"^the kettle ", "", U.render_goal_u(rng, Subgoal(0, Target("kettle", "kettle"), room="pantry")))
             for _ in range(80)}
    assert rooms == {"in the pantry", "back in the pantry"}


def test_every_relation_word_is_used_and_read():
    rng = np.random.default_rng(7)
    for rtype in U.REL_WORDS:
        sg = Subgoal(0, Target("lamp", "lamp", (), (Relation(rtype, Target("sofa", "sofa")),)))
        seen = set()
        for _ in range(150):
            text = U.render_goal_u(rng, sg)
            got, _ = read_goal(text)
            assert got["relations"][0][0] == rtype, text
            seen.add(text[len("the lamp "): -len(" the sofa")])
        assert seen == set(U.REL_WORDS[rtype]), rtype


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own


def numbers_in(text: str) -> list[float]:
    """Every number in the text: '-18', '.6', '0.60', '20½', 'minus 18', 'minus eighteen', 'three hundred and five',
    '18 degrees below zero'."""
    t = text.lower().replace("½", ".5")
    t = re.sub(r"(\d+(?:\.\d+)?)((?:°c| °c| degrees celsius| degrees| degs c)) below zero", r"-\1\2", t)
    toks = re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)*", t)
    return spoken_numbers(toks)


def comparator_of(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"thereabouts|ballpark|neighbourhood of", "approx"),
                  (r"\btops\b|and no more|capped at", "le"),
                  (r"or over|or more|\bfrom\b.*\bup\b|not a jot under", "ge"),
                  (r"broken through|gone beyond|over and above|comfortably over|something over", "gt"),
                  (r"dropped under|up short of|something under|comfortably under", "lt")):
        if re.search(rx, t):
            return c
    return "?"


def reading_of(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|health|thriving|perkiest|sorriest|wilted", t):
        return "ndvi"
    if re.search(r"humid|hygrometer|clamm|sogg|driest|arid|%|per ?cent", t):
        return "humidity_pct"
    if re.search(r"temperature|thermometer|warmest|balm|swelter|coldest|frost|nipp|°|degree|celsius|degs", t):
        return "temperature_c"
    return "?"


_LOW = r"coldest|frostiest|nippiest|least|sorriest|wilted|driest|arid|props up|lowest"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    prefix, tail, written = rendered = U.render_sensor_u(np.random.default_rng(seed), c)
    check_sensor(rendered, c, comparator_of, _LOW, r"°c|degree|celsius|degs c", r"(?i)%|per ?cent", numbers_in, reading_of)
    text = (prefix + " " + tail).strip()
    if c.is_superlative:
        return
    assert text.count("(") == text.count(")"), text
    if "below zero" in text:  # only ever said of a temperature near which the thing should be
        assert c.comparator == "approx" and written.value < 0, text


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase(c, sg, seed):
    check_sensor_goal(U.render_sensor_u, U.render_goal_u, c, sg, seed, numbers_in)


def test_number_formats_vary():
    rng = np.random.default_rng(3)
    seen = set()
    for _ in range(400):
        _, tail, _ = U.render_sensor_u(rng, SensorConstraint("temperature_c", "approx", -18.0))
        seen.add("words" if "minus eighteen" in tail else "minus" if "minus 18" in tail else
                 "below" if re.search(r"\b18(\.0)?(°C| degrees( Celsius)?) below zero", tail) else
                 "decimal" if "-18.0" in tail else "digits" if "-18" in tail else "?")
    assert seen == {"words", "minus", "below", "decimal", "digits"}
    lt = {U.render_sensor_u(rng, SensorConstraint("temperature_c", "lt", -18.0))[1] for _ in range(100)}
    assert not any("below zero" in t for t in lt)
    halves = {U.render_sensor_u(rng, SensorConstraint("humidity_pct", "gt", 37.5))[1] for _ in range(100)}
    assert any("37½" in t for t in halves) and any("37.5" in t for t in halves)
    ndvi = {U.render_sensor_u(rng, SensorConstraint("ndvi", "gt", 0.6))[1] for _ in range(200)}
    assert any(re.search(r"(?<![\d])\.6\b", t) for t in ndvi) and any("0.60" in t for t in ndvi)
    assert all(numbers_in(t) == [pytest.approx(0.6)] for t in ndvi)
    assert any(t.startswith("(the NDVI ") for t in ndvi) and any(t.startswith("with NDVI logged at ") for t in ndvi)
    hum = {U.render_sensor_u(rng, SensorConstraint("humidity_pct", "le", 40.0))[1] for _ in range(200)}
    assert any("40% tops" in t for t in hum) and any("forty per cent" in t for t in hum)
    assert any(t.startswith("(the hygrometer puts it at") for t in hum)
    temp = {U.render_sensor_u(rng, SensorConstraint("temperature_c", "approx", 321.0))[1] for _ in range(300)}
    assert any("three hundred and twenty-one" in t for t in temp) and any("degs C" in t for t in temp)
    assert all(numbers_in(t) == [321.0] for t in temp)


def test_superlatives_take_adjectives_and_tails():
    rng = np.random.default_rng(5)
    got = {U.render_sensor_u(rng, SensorConstraint("temperature_c", "min")) for _ in range(200)}
    assert {"coldest", "frostiest", "nippiest"} <= {p for p, _, _ in got if p}
    assert {"that props up the temperature table", "with the lowest temperature of the bunch",
            "whose temperature is the lowest going"} <= {t for _, t, _ in got if t}
    got = {U.render_sensor_u(rng, SensorConstraint("ndvi", "max"))[1] for _ in range(200)}
    assert {"that tops the NDVI chart", "with an NDVI higher than any other", "whose NDVI beats all comers"} <= got


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(U.hint_text_u, U.render_goal_u, U.render_instruction_u, x, y, seed)


def test_every_coordinate_form_is_used():
    rng = np.random.default_rng(4)
    hints = {U.hint_text_u(rng, "-3.5", "2.0") for _ in range(200)}
    for rx in (r"at easting -3\.5, northing 2\.0", r"\(x -3\.5 \| y 2\.0\)",
               r"where the x-coordinate reads -3\.5 and the y-coordinate 2\.0",
               r"marked on the floor plan at x = -3\.5, y = 2\.0"):
        assert any(re.fullmatch(rx, h) for h in hints), rx
    assert len(hints) == 4
    goal = U.render_goal_u(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(-3.5, 2.0)),
                           hint="(x -3.5 | y 2.0)")
    assert goal == "the guitar (x -3.5 | y 2.0)"


STRICT_CUES = r"strictly in the order shown|in the order announced|does not skip stops|in exactly this sequence|" \
              r"keep to this sequence|no jumping ahead|strictly in catalogue order|taken out of turn|" \
              r"strictly by the catalogue numbers|in the order they were laid|out of turn|the order the cards fell"
FREE_CUES = r"in any order|in either direction|whatever order|no set sequence|whichever feels right|no set route|" \
            r"order means nothing|as the spirit moves|doesn't mind"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_keep_their_order(sgs, seed, strict):
    check_order(U.render_goal_u, U.render_instruction_u, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [U.render_goal_u(rng, sg) for sg in sgs]
    text = U.render_instruction_u(rng, res, "strict" if strict else "free")
    low = text.lower()
    if strict:  # a strict text also says so in words of its own
        assert re.search(STRICT_CUES, low), text
    at = 0
    for r in res:  # every goal is written whole, in visiting order
        at = low.find(r.lower(), at)
        assert at >= 0, (r, text)
        at += len(r)


_ROMAN = {"I": 1, "II": 2, "III": 3, "IV": 4, "V": 5, "VI": 6, "VII": 7, "VIII": 8}


@SETTINGS
@given(n=st.integers(2, 8), seed=st.integers(0, 2**31), strict=st.booleans())
def test_stated_counts_and_numbered_lines_agree_with_the_goals(n, seed, strict):
    heads = (*HEADS, "kettle", "toaster")
    res = [f"the {h}" for h in heads[:n]]
    text = U.render_instruction_u(np.random.default_rng(seed), res, "strict" if strict else "free")
    for m in re.finditer(r"(\d+) (?:stations|poses to explore|lots on view|cards, face down)", text):
        assert int(m.group(1)) == n, text
    lines = text.split("\n")
    goal_lines = [ln for ln in lines if re.search(r"\bthe (" + "|".join(heads[:n]) + r")\b", ln, flags=re.I)]
    if len(lines) > 1:  # a layout of one goal a line, numbered in visiting order where numbered
        assert len(goal_lines) == n, text
        nums = [int(m.group(1)) for ln in goal_lines if (m := re.match(r"(?:LOT |Pose )(\d+) ", ln))]
        if nums:
            assert nums == list(range(1, len(nums) + 1)), text
        roman = [_ROMAN[m.group(1)] for ln in goal_lines if (m := re.match(r"([IVX]+)\. ", ln))]
        if roman:
            assert roman == list(range(1, n + 1)), text
    lots = re.findall(r"\blot (one|two|three|four|five|six|seven|eight)\b", text)
    if lots:  # spoken lot numbers count up, one a goal
        words = ("one", "two", "three", "four", "five", "six", "seven", "eight")
        assert lots == list(words[:n]), text


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_and_keeps_the_goal(sg, seed):
    rng = np.random.default_rng(seed)
    goal = U.render_goal_u(rng, sg)
    text = U.render_instruction_u(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text), text
    assert not re.search(FREE_CUES, text.lower()), text


def test_every_register_is_used():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    texts = [U.render_instruction_u(rng, res, order) for order in ("strict", "free") for _ in range(80)]
    marks = (r"platform|calling at|rail rover|hop-on", r"pose|namaste|flow", r"\blots?\b|buyer's premium|viewing",
             r"cards?\b|spread")
    for m in marks:
        assert any(re.search(m, t.lower()) for t in texts), m
    assert any("\n" in t for t in texts) and any("\n" not in t for t in texts)  # multi-line and paragraphs
    assert len(set(texts)) > 40
    singles = [U.render_instruction_u(rng, res[:1], "strict") for _ in range(60)]
    single_marks = (r"non-stop|mind the gap", r"pose|breathe|breath", r"single-lot|hammer", r"card")
    for m in single_marks:
        assert any(re.search(m, t.lower()) for t in singles), m


# ----------------------------------------------------------------------------------------------------
# Whole episode files (the checks every held-out set shares: tests/test_heldout_sets.py)


def test_unseen_u_sensor_numbers_are_the_constraints():
    """The written number of a reading is the constraint's, in the goal's own text."""
    from test_heldout_sets import SMALL

    from ragnav_jax.config import load_config
    from ragnav_jax.language.episodes import generate_episodes
    from ragnav_jax.world.generator import generate_scene

    scene = generate_scene(load_config(None, SMALL).world, 5, 0)
    for p in generate_episodes([scene], load_config(None, [*SMALL, "episodes.split=unseen_u"]).episodes, seed=3):
        for sg in p.truth.subgoals:
            for c in sg.sensors:
                if not c.is_superlative:
                    assert numbers_in(sg.text) == [pytest.approx(c.value, abs=0.006)], sg.text
