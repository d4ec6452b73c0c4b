"""The `unseen_t` held-out templates (set T): every piece of the ground truth is written down.

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
    reading_norm,
    spoken_numbers,
    target_truth,
)
from test_phrasings_dev8 import HEADS, MODS, ROOMS, STATES, _has, constraints, subgoals

from ragnav_jax.language import phrasings_t as T
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# T's words for each relation, written here apart from the templates' own table (a reader's list)
T_REL_WORDS = {
    "near": ("near", "spitting distance of", "vicinity of", "few feet from"),
    "next_to": ("next to", "rubbing shoulders with", "cosied up to"),
    "beside": ("beside",), "by": ("by",),
    "on": ("on", "on top of"), "under": ("under", "underneath", "below"),
    "above": ("above", "looming over"), "in": ("in", "into", "inside"),
    "with": ("with",),
    "in_room_with": ("same room as", "room where you'll find"),
    "in_front_of": ("in front of",), "behind": ("behind", "rear of"),
    "opposite": ("opposite", "staring across at", "far side of the room from"),
    "left_of": ("left of",), "right_of": ("right of",),
}
# The whole phrases a reader of T's goals splits on, each with its relation type.
T_REL_PHRASES = {
    "near": "near", "within spitting distance of": "near", "in the vicinity of": "near", "just a few feet from": "near",
    "next to": "next_to", "rubbing shoulders with": "next_to", "squeezed in next to": "next_to",
    "cosied up to": "next_to",
    "beside": "beside", "standing beside": "beside", "wedged beside": "beside",
    "by": "by", "loitering by": "by", "kept by": "by",
    "on": "on", "stood on": "on", "plonked on top of": "on", "parked on": "on",
    "under": "under", "stuffed under": "under", "shoved underneath": "under", "sitting below": "under",
    "above": "above", "up above": "above", "screwed to the wall above": "above", "looming over": "above",
    "in": "in", "crammed into": "in", "living inside": "in", "shut inside": "in",
    "with": "with", "decked out with": "with", "kitted out with": "with", "set up with": "with",
    "in the same room as": "in_room_with", "in the room where you'll find": "in_room_with",
    "in one and the same room as": "in_room_with",
    "in front of": "in_front_of", "just in front of": "in_front_of", "sat in front of": "in_front_of",
    "behind": "behind", "skulking behind": "behind", "at the rear of": "behind",
    "opposite": "opposite", "staring across at": "opposite", "on the far side of the room from": "opposite",
    "to the left of": "left_of", "just left of": "left_of", "a touch to the left of": "left_of",
    "to the right of": "right_of", "just right of": "right_of", "a touch to the right of": "right_of",
}
_BY_LENGTH = sorted(T_REL_PHRASES, key=len, reverse=True)


# ----------------------------------------------------------------------------------------------------
# A reader of T's goals: head, attributes, states, room and relations, nested


def _depths(text: str) -> list[int]:
    out, d = [], 0
    for ch in text:
        if ch in "([":
            d += 1
        out.append(d)
        if ch in ")]":
            d -= 1
    return out


def _relations_at_top(text: str) -> list[tuple[int, int, str]]:
    """(start, end, type) of every relation phrase outside brackets that is followed by 'the'."""
    depth, out, i = _depths(text), [], 0
    while i < len(text):
        if depth[i] == 0 and (i == 0 or text[i - 1] == " "):
            for p in _BY_LENGTH:
                if text.startswith(p + " the ", i):
                    out.append((i, i + len(p), T_REL_PHRASES[p]))
                    i += len(p)
                    break
        i += 1
    return out


def _read_chain(text: str) -> list[tuple[str, dict]]:
    """'next to the sofa and also under the shelf' -> [('next_to', sofa), ('under', shelf)]."""
    rels = _relations_at_top(text)
    assert rels and text[: rels[0][0]].strip() == "", text
    out = []
    for k, (_, end, rtype) in enumerate(rels):
        stop = rels[k + 1][0] if k + 1 < len(rels) else len(text)
        seg = re.sub(r"(,? plus| and also| and)\s*$", "", text[end:stop].strip())
        out.append((rtype, _read_np(seg.strip())))
    return out


def _read_np(seg: str) -> dict:
    """A noun phrase of T: 'the switched-on teal lamp (wool as well) [next to the sofa]', 'the lamp, teal & wool,'."""
    got = {"attrs": [], "after": [], "states": [], "relations": []}
    depth, groups, plain = _depths(seg), [], ""
    i = 0
    while i < len(seg):  # take out the bracketed groups
        if seg[i] in "([" and depth[i] == 1:
            j = i
            while not (seg[j] in ")]" and depth[j] == 1):
                j += 1
            groups.append(seg[i : j + 1])
            i = j + 1
            continue
        plain += seg[i]
        i += 1
    for g in groups:
        body = g[1:-1]
        if g.startswith("["):
            got["relations"] += _read_chain(body)
        elif body.startswith("found "):
            got["relations"] += _read_chain(body[len("found "):])
        elif m := re.fullmatch(r"(?:last seen |state = )(.+)", body):
            got["states"] += m.group(1).split(" and ")
        elif m := re.fullmatch(r"(?:field marks|distinguishing features): (.+)", body):
            got["after"] += m.group(1).split(", ")
        elif m := re.fullmatch(r"(.+) as well", body):
            got["after"] += m.group(1).split(" and ")
        else:
            raise AssertionError(f"unknown bracket {g!r} in {seg!r}")
    parts = [p.strip() for p in plain.split(",") if p.strip()]
    for p in parts[1:]:
        if m := re.fullmatch(r"(?:which should be|reportedly) (.+)", p):
            got["states"] += m.group(1).split(" and ")
        else:
            got["after"] += p.split(" & ")
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
    m = re.search(r"(?:round in|across in|in) the (" + "|".join(sorted(ROOMS, key=len, reverse=True)) + r")\b", text)
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
    text = T.render_goal_t(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, T_REL_WORDS)
    assert text.count("[") == text.count("]"), text


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_reads_back_exactly(sg, seed):
    text = T.render_goal_t(np.random.default_rng(seed), sg)
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
        text = T.render_goal_t(rng, Subgoal(0, t, room="music room"))
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "music room", text
        assert text.index("music room") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
        forms.add("square" if "drums]" in text else "found" if "(found " in text else "?")
    assert forms == {"square", "found"}


def test_attributes_states_and_rooms_take_every_form():
    rng = np.random.default_rng(2)
    t = Target("vintage wool toolbox", "toolbox", ("vintage", "wool", "empty"))
    texts = [T.render_goal_t(rng, Subgoal(0, t)) for _ in range(400)]
    for rx in (r"^the (empty )?vintage wool toolbox", r"^the (empty )?vintage toolbox \(wool as well\)",
               r"\((field marks|distinguishing features): vintage, wool\)", r"toolbox, vintage & wool",
               r"\(last seen empty\)", r"\(state = empty\)", r", which should be empty", r", reportedly empty",
               r"^the empty vintage"):
        assert any(re.search(rx, x) for x in texts), rx
    assert not any(") (" in x for x in texts)  # never two round brackets in a row
    rooms = {re.sub(r"^the kettle ", "", T.render_goal_t(rng, Subgoal(0, Target("kettle", "kettle"), room="pantry")))
             for _ in range(80)}
    assert rooms == {"in the pantry", "round in the pantry", "across in the pantry"}


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own


def numbers_in(text: str) -> list[float]:
    """Every number in the text: '-18', '−18', '.6', '0.60', 'minus 18', 'minus eighteen', 'three hundred and
    five'."""
    toks = re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)*", text.lower().replace("\u2212", "-"))
    return spoken_numbers(toks)


def comparator_of(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"close to it|far off|bit either way", "approx"),
                  (r"anything above|bare minimum|goes beyond", "ge"),
                  (r"anything below|hair over|get past", "le"),
                  (r"strictly above|already past|notch above|shot past|risen above", "gt"),
                  (r"strictly below|notch below|not yet up to|fallen below|stops short", "lt")):
        if re.search(rx, t):
            return c
    return "?"


def reading_of(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|health|vigorous|spright|scraggl|bedraggled", t):
        return "ndvi"
    if re.search(r"humid|dank|dri|dry|%|per ?cent", t):
        return "humidity_pct"
    if re.search(r"temp|warm|fier|scorch|cold|glacial|arctic|°|degree|celsius", t):
        return "temperature_c"
    return "?"


_LOW = r"cold|glacial|arctic|least|scraggl|bedraggled|dri|bone-dry|rear|bottom|foot of"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    prefix, tail, written = rendered = T.render_sensor_t(np.random.default_rng(seed), c)
    check_sensor(rendered, c, comparator_of, _LOW, r"°c|degree|celsius", r"(?i)%|per ?cent", numbers_in, reading_of)
    text = (prefix + " " + tail).strip()
    if c.is_superlative:
        return
    assert text.count("(") == text.count(")"), text


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase(c, sg, seed):
    rng = np.random.default_rng(seed)
    prefix, tail, _ = T.render_sensor_t(rng, c)
    sg = Subgoal(0, Target(sg.target.phrase, sg.target.head, sg.target.attributes), room=sg.room)
    text = T.render_goal_t(rng, sg, prefix=prefix, tail=tail)
    assert _has(text, sg.target.head), text
    if sg.room:
        assert _has(text, sg.room), text
    if prefix:  # a superlative adjective stands right before the noun phrase
        assert text.startswith(f"the {prefix} {sg.target.phrase}"), text
    else:
        assert tail in text and text.index(sg.target.head) < text.index(tail), text
        if sg.room and c.is_superlative:  # a superlative is read inside the room: the room comes first
            assert text.index(sg.room) < text.index(tail), text
    assert numbers_in(text) == ([] if c.is_superlative else [pytest.approx(c.value, abs=0.006)]), text


def test_number_formats_vary():
    rng = np.random.default_rng(3)
    seen = set()
    for _ in range(400):
        _, tail, _ = T.render_sensor_t(rng, SensorConstraint("temperature_c", "lt", -18.0))
        seen.add("words" if "minus eighteen" in tail else "minus" if "minus 18" in tail else
                 "sign" if "\u221218" in tail else "decimal" if "-18.0" in tail else "digits" if "-18" in tail else "?")
    assert seen == {"words", "minus", "sign", "decimal", "digits"}
    ndvi = {T.render_sensor_t(rng, SensorConstraint("ndvi", "gt", 0.6))[1] for _ in range(200)}
    assert any(re.search(r"(?<![\d])\.6\b", t) for t in ndvi) and any("0.60" in t for t in ndvi)
    assert all(numbers_in(t) == [pytest.approx(0.6)] for t in ndvi)
    assert any(t.startswith("(NDVI-wise: ") for t in ndvi) and any(t.startswith("with its NDVI figure ") for t in ndvi)
    hum = {T.render_sensor_t(rng, SensorConstraint("humidity_pct", "le", 40.0))[1] for _ in range(200)}
    assert any("% rel. humidity" in t for t in hum) and any("forty per cent" in t for t in hum)
    temp = {T.render_sensor_t(rng, SensorConstraint("temperature_c", "approx", 321.0))[1] for _ in range(300)}
    assert any("three hundred and twenty-one" in t for t in temp) and any("on the Celsius scale" in t for t in temp)
    assert all(numbers_in(t) == [321.0] for t in temp)


def test_superlatives_take_adjectives_and_tails():
    rng = np.random.default_rng(5)
    got = {T.render_sensor_t(rng, SensorConstraint("temperature_c", "min")) for _ in range(200)}
    assert {"coldest", "most glacial", "most arctic"} <= {p for p, _, _ in got if p}
    assert {"that brings up the rear on temperature", "that's bottom of the league on temperature",
            "at the foot of the temperature rankings"} <= {t for _, t, _ in got if t}
    got = {T.render_sensor_t(rng, SensorConstraint("ndvi", "max"))[1] for _ in range(200)}
    assert {"with the high score on NDVI", "that leads the pack on NDVI", "with an NDVI second to none"} <= got


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(T.hint_text_t, T.render_goal_t, T.render_instruction_t, x, y, seed)


def test_every_coordinate_form_is_used():
    rng = np.random.default_rng(4)
    hints = {T.hint_text_t(rng, "-3.5", "2.0") for _ in range(200)}
    for rx in (r"with x at -3\.5 and y at 2\.0", r"\(dropped pin: x -3\.5, y 2\.0\)",
               r"at x-position -3\.5, y-position 2\.0", r"where x comes to -3\.5 and y to 2\.0"):
        assert any(re.fullmatch(rx, h) for h in hints), rx
    goal = T.render_goal_t(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(-3.5, 2.0)),
                           hint="(dropped pin: x -3.5, y 2.0)")
    assert goal == "the guitar (dropped pin: x -3.5, y 2.0)"


STRICT_CUES = r"rows in turn|row by row|as written|unravels|top to bottom|locked in|as the list reads|" \
              r"hides in sequence|order logged|flushes everything|in the listed order|order-sensitive|" \
              r"same sequence every run"
FREE_CUES = r"whichever sequence|as the mood|shuffle the set|stumble on them|whichever turns up first|" \
            r"no bearing on the result|arbitrary order"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_keep_their_order(sgs, seed, strict):
    check_order(T.render_goal_t, T.render_instruction_t, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [T.render_goal_t(rng, sg) for sg in sgs]
    text = T.render_instruction_t(rng, res, "strict" if strict else "free")
    low = text.lower()
    if strict:  # a strict text also says so in words of its own
        assert re.search(STRICT_CUES, low), text
    at = 0
    for r in res:  # every goal is written whole, in visiting order
        at = low.find(r.lower(), at)
        assert at >= 0, (r, text)
        at += len(r)


@SETTINGS
@given(n=st.integers(2, 5), seed=st.integers(0, 2**31), strict=st.booleans())
def test_stated_counts_and_clock_times_agree_with_the_goals(n, seed, strict):
    res = [f"the {h}" for h in HEADS[:n]]
    text = T.render_instruction_t(np.random.default_rng(seed), res, "strict" if strict else "free")
    words = ("zero", "one", "two", "three", "four", "five")
    for m in re.finditer(r"\((\w+)(?: numbers| to find)?\):", text):  # '(three):', '(4):', '(two to find):'
        assert m.group(1) in (str(n), words[n]), text
    for m in re.finditer(r"\((\w+) numbers\)", text):
        assert m.group(1) == words[n], text
    times = re.findall(r"^(\d\d):(\d\d)  the ", text, flags=re.M)
    if times:  # a sightings log: one line a goal, the clock always going forward
        mins = [int(h) * 60 + int(m) for h, m in times]
        assert len(mins) == n and mins == sorted(set(mins)), text
    rows = re.findall(r"^(Cast on at|Row \d+:|Cast off at|\d+\.|ENCORE:|\d+\)) ", text, flags=re.M)
    if rows:  # a numbered layout: one line a goal
        assert len(rows) == n, text
        nums = [int(re.search(r"\d+", r).group()) for r in rows if re.search(r"\d", r)]
        assert nums == sorted(nums) and len(set(nums)) == len(nums), text


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_and_keeps_the_goal(sg, seed):
    rng = np.random.default_rng(seed)
    goal = T.render_goal_t(rng, sg)
    text = T.render_instruction_t(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text), text
    assert not re.search(FREE_CUES, text.lower()), text


def test_every_register_is_used():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    texts = [T.render_instruction_t(rng, res, order) for order in ("strict", "free") for _ in range(80)]
    marks = (r"knit|cast on|squares", r"set list|encore|lads|open mic", r"sightings|hide|birding",
             r"bug-|qa ask|ticket|steps to reproduce")
    for m in marks:
        assert any(re.search(m, t.lower()) for t in texts), m
    assert any("\n" in t for t in texts) and any("\n" not in t for t in texts)  # multi-line and paragraphs
    singles = [T.render_instruction_t(rng, res[:1], "strict") for _ in range(60)]
    single_marks = (r"knitting|pattern", r"lads|number tonight", r"birding|binoculars", r"qa note|test case|nav team")
    for m in single_marks:
        assert any(re.search(m, t.lower()) for t in singles), m
