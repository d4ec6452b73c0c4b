"""The `unseen_y` held-out templates (set Y): every piece of the ground truth is written down.

Checked with small readers of their own (a goal reader that recovers head, attributes, states, room and nested
relations; words for comparators, readings, units, numbers, coordinates and order cues) that share no code with
the templates, over random subgoals drawn by hypothesis. The split's wiring and the four functions' determinism
are checked in tests/test_heldout_sets.py.
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

from ragnav_jax.language import phrasings_y as Y
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# The whole phrases a reader of Y's goals splits on, each with its relation type (written apart from the templates)
Y_REL_PHRASES = {
    "near": "near", "in striking distance of": "near", "a hop, skip and jump from": "near",
    "next to": "next_to", "abutting": "next_to", "hip to hip with": "next_to", "neighbouring": "next_to",
    "beside": "beside", "at the side of": "beside", "at the elbow of": "beside",
    "by": "by", "idling by": "by", "dawdling by": "by",
    "on": "on", "lounging on": "on", "squatting on": "on",
    "under": "under", "hunkered under": "under", "dozing beneath": "under",
    "above": "above", "presiding over": "above", "poised above": "above",
    "in": "in", "cooped up in": "in", "holed up in": "in",
    "with": "with", "toting": "with", "twinned with": "with",
    "in the same room as": "in_room_with", "bunking with": "in_room_with", "in the same quarters as": "in_room_with",
    "in front of": "in_front_of", "out ahead of": "in_front_of", "posed in front of": "in_front_of",
    "behind": "behind", "in the lee of": "behind", "hanging back behind": "behind",
    "opposite": "opposite", "vis-à-vis": "opposite", "across the floor from": "opposite",
    "to the left of": "left_of", "at the left hand of": "left_of", "a smidge to the left of": "left_of",
    "to the right of": "right_of", "at the right hand of": "right_of", "a smidge to the right of": "right_of",
}
_BY_LENGTH = sorted(Y_REL_PHRASES, key=len, reverse=True)
Y_REL_WORDS: dict[str, tuple[str, ...]] = {}
for _p, _t in Y_REL_PHRASES.items():
    Y_REL_WORDS[_t] = (*Y_REL_WORDS.get(_t, ()), _p)
# check_goal's word test reads words without commas or non-ASCII letters: the same phrases in its spelling
Y_CHECK_WORDS = {t: tuple(" ".join(re.sub(r"[^a-z0-9\-'.%°]+", " ", w).split()) for w in ws)
                 for t, ws in Y_REL_WORDS.items()}


# ----------------------------------------------------------------------------------------------------
# A reader of Y's goals


def _relations_at_top(text: str) -> list[tuple[int, int, str]]:
    depth, out, i = _depths(text), [], 0
    while i < len(text):
        if depth[i] == 0 and (i == 0 or text[i - 1] == " "):
            for p in _BY_LENGTH:
                if text.startswith(p + " the ", i):
                    out.append((i, i + len(p), Y_REL_PHRASES[p]))
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
        seg = re.sub(r"(, not to mention|, and equally| and)\s*$", "", text[end:stop].strip())
        out.append((rtype, _read_np(seg.strip())))
    return out


def _read_np(seg: str) -> dict:
    """'the switched-on teal lamp (as in, the one next to the sofa)', 'the lamp (you want the teal one), which stands
    open', 'the lamp (switched on, by all accounts), teal and wool to look at'."""
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
        if m := re.fullmatch(r"(?:as in,|that being) the one (.+)", body):
            got["relations"] += _read_chain(m.group(1))
        elif m := re.fullmatch(r"(.+), by all accounts", body):
            got["states"] += m.group(1).split(" and ")
        elif m := re.fullmatch(r"you want the (.+) one", body):
            got["after"] += m.group(1).split(" and ")
        else:
            raise AssertionError(f"unknown bracket {body!r} in {seg!r}")
    parts = [p.strip() for p in plain.split(",") if p.strip()]
    for p in parts[1:]:
        if m := re.fullmatch(r"which stands (.+)", p):
            got["states"] += m.group(1).split(" and ")
        else:
            m = re.fullmatch(r"(.+) to look at", p)
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


_ROOM_RX = re.compile(r"in the (" + "|".join(sorted(ROOMS, key=len, reverse=True)) + r")( part of the house)?\b")


def read_goal(text: str) -> tuple[dict, str | None]:
    room = None
    m = _ROOM_RX.search(text)
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


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece_and_reads_back_exactly(sg, seed):
    text = Y.render_goal_y(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, Y_CHECK_WORDS)
    assert ") (" not in text and max(_depths(text), default=0) <= 1, text
    got, room = read_goal(text)
    assert reading_norm(got) == target_truth(sg.target), text
    assert room == sg.room, text


def test_nested_goal_and_every_attribute_state_and_room_form():
    t = Target("teal wool lamp", "lamp", ("teal", "wool", "switched on"), (
        Relation("next_to", Target("sofa", "sofa", ("open",), (Relation("with", Target("drums", "drums")),))),
        Relation("under", Target("shelves", "shelves", ("empty",)))))
    rng = np.random.default_rng(0)
    texts = [Y.render_goal_y(rng, Subgoal(0, t, room="music room")) for _ in range(300)]
    for text in texts:
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "music room", text
        assert text.index("music room") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
    for rx in (r"^the teal wool lamp", r"^the lamp \(you want the teal and wool one\)",
               r"^the switched-on lamp, teal and wool to look at,", r"^the switched-on ", r"^the lamp \(switched on, by all "
               r"accounts\), teal and wool to look at,", r", which stands switched on,", r"in the music room part of "
               r"the house", r"\(as in, the one ", r"\(that being the one ", r"the shelves \(empty, by all accounts\)",
               r"the empty shelves", r", not to mention ", r", and equally "):
        assert any(re.search(rx, x) for x in texts), rx


def test_every_relation_word_is_used_and_read():
    rng = np.random.default_rng(7)
    for rtype in Y.REL_WORDS:
        sg = Subgoal(0, Target("lamp", "lamp", (), (Relation(rtype, Target("sofa", "sofa")),)))
        seen = set()
        for _ in range(100):
            text = Y.render_goal_y(rng, sg)
            assert read_goal(text)[0]["relations"][0][0] == rtype, text
            seen.add(text[len("the lamp "): -len(" the sofa")])
        assert seen == set(Y_REL_WORDS[rtype]), rtype


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own


def _as_number(tok: str) -> bool:
    return bool(spoken_numbers([tok]))


def numbers_in(text: str) -> list[float]:
    """Every number: '-4', '.65', 'minus 4', 'minus four', '22 point 5', 'sixty-five hundredths', 'six tenths', '4
    below' ('the one', 'the teal one)' and 'number one' are no numbers)."""
    t = text.lower().replace("°c", " c")
    t = re.sub(r"\bone\b(?=\))|(?<=the )one\b|(?<=number )one\b", "ONE", t)
    t = re.sub(r"(\d+) point (\d+)", r"\1.\2", t)

    def fraction(m: re.Match) -> str:
        k = spoken_numbers([m.group(1)])
        assert len(k) == 1, m.group(0)
        return f"{k[0] / (10 if m.group(2).startswith('tenth') else 100):.2f}"

    t = re.sub(r"([a-z]+(?:-[a-z]+)?) (hundredths?|tenths?)\b", fraction, t)
    t = re.sub(r"(\d+(?:\.\d+)?|[a-z]+(?:-[a-z]+)?) below\b",
               lambda m: f"minus {m.group(1)}" if _as_number(m.group(1)) else m.group(0), t)
    return spoken_numbers(re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)*", t))


def comparator_of(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"in and around|or near it|getting on for", "approx"),
                  (r"at the lowest|drops below|won't go under", "ge"),
                  (r"at the highest|climbs above|won't go over", "le"),
                  (r"surpass|up past|outpaces", "gt"),
                  (r"keeps below|tucks in under|hasn't got up to", "lt")):
        if re.search(rx, t):
            return c
    return "?"


def reading_of(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|health|luxuriant|bush|limp|shrivel", t):
        return "ndvi"
    if re.search(r"humid|sticki|dewi|driest|thirsti|powder|%|per ?cent|pct", t):
        return "humidity_pct"
    if re.search(r"temperature|warmest|roasting|sizzl|coldest|polar|perishing|°|degree|centigrade", t):
        return "temperature_c"
    return "?"


_LOW = r"coldest|polar|perishing|least|limpest|shrivelled|driest|thirstiest|powder|get down to|dead last|rest all beat"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = Y.render_sensor_y(np.random.default_rng(seed), c)
    check_sensor(rendered, c, comparator_of, _LOW, r"°c|degree|centigrade|thermometer", r"(?i)%|per ?cent|pct",
                 numbers_in, reading_of)
    text = (rendered[0] + " " + rendered[1]).strip()
    assert "(" not in text and "  " not in text, text
    if re.search(r"\d below|[a-z] below$", text):
        assert c.comparator == "approx" and rendered[2].value < 0 and rendered[2].unit == "", text
        assert text.startswith(("whose temperature", "which has a temperature", "showing a temperature")), text
    if not rendered[2].unit and not c.is_superlative:  # a unitless number always has its reading named
        assert re.search(r"temperature|humidity|ndvi", text.lower()), text


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase_after_the_head(c, sg, seed):
    check_sensor_goal(Y.render_sensor_y, Y.render_goal_y, c, sg, seed, numbers_in)


@SETTINGS
@given(c=constraints(), sg=subgoals(), x=st.floats(-20, 40).map(lambda v: round(v, 1)),
       y=st.floats(-20, 40).map(lambda v: round(v, 1)), seed=st.integers(0, 2**31))
def test_a_goal_with_sensor_and_hint_ends_on_the_coordinates(c, sg, x, y, seed):
    """The hint's numbers come last in the goal (after any number of the sensor phrase), and brackets never stack."""
    rng = np.random.default_rng(seed)
    prefix, tail, _ = Y.render_sensor_y(rng, c)
    hint = Y.hint_text_y(rng, f"{x:.1f}", f"{y:.1f}")
    text = Y.render_goal_y(rng, sg, prefix=prefix, tail=tail, hint=hint)
    nums = numbers_in(text)
    assert nums[-2:] == [pytest.approx(x), pytest.approx(y)], text
    assert len(nums) == 2 + (not c.is_superlative), text
    assert ") (" not in text and max(_depths(text), default=0) <= 1 and text.count("(") == text.count(")"), text


def test_number_formats_frames_and_superlatives_vary():
    rng = np.random.default_rng(3)
    cold = {Y.render_sensor_y(rng, SensorConstraint("temperature_c", "approx", -4.0))[1] for _ in range(300)}
    for rx in (r"minus four", r"minus 4\b", r"\b(4|four) below$", r"-4\b", r"^that ", r"^whose ",
               r"^which has a temperature that ", r"^showing a temperature that ", r"centigrade",
               r"degrees on the thermometer", r"°C"):
        assert any(re.search(rx, t) for t in cold), rx
    assert all(numbers_in(t) == [-4.0] for t in cold)
    half = {Y.render_sensor_y(rng, SensorConstraint("humidity_pct", "lt", 22.5))[1] for _ in range(200)}
    for rx in (r"22 point 5", r"22\.5", r"\bpct\b", r"per cent RH", r"%"):
        assert any(re.search(rx, t) for t in half), rx
    ndvi = {Y.render_sensor_y(rng, SensorConstraint("ndvi", "gt", 0.65))[1] for _ in range(200)}
    for rx in (r"(?<![\d])\.65\b", r"0\.65\b", r"sixty-five hundredths", r"with an NDVI|showing an NDVI"):
        assert any(re.search(rx, t) for t in ndvi), rx
    tenths = {Y.render_sensor_y(rng, SensorConstraint("ndvi", "le", 0.6))[1] for _ in range(100)}
    assert any("six tenths" in t for t in tenths) and all(numbers_in(t) == [0.6] for t in tenths)
    sup = {Y.render_sensor_y(rng, SensorConstraint("humidity_pct", "max")) for _ in range(200)}
    assert {"most humid", "stickiest", "dewiest"} <= {p for p, _, _ in sup}
    assert {"with a humidity nobody else can match", "that's number one for humidity",
            "whose humidity leaves the rest standing"} <= {t for _, t, _ in sup}
    for cmp in ("gt", "ge", "lt", "le", "approx"):
        seen = {comparator_of(Y.render_sensor_y(rng, SensorConstraint("temperature_c", cmp, 30.0))[1])
                for _ in range(60)}
        assert seen == {cmp}, (cmp, seen)


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(Y.hint_text_y, Y.render_goal_y, Y.render_instruction_y, x, y, seed)


def test_every_coordinate_form_is_used():
    rng = np.random.default_rng(4)
    hints = {Y.hint_text_y(rng, "-3.5", "2.0") for _ in range(100)}
    assert hints == {"at -3.5 on the horizontal and 2.0 on the vertical", "(x marks -3.5, y marks 2.0)",
                     "at -3.5, 2.0 (x, y order)", "at -3.5 m on the x scale and 2.0 m on the y scale"}
    goal = Y.render_goal_y(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(-3.5, 2.0)),
                           hint="(x marks -3.5, y marks 2.0)")
    assert goal == "the guitar (x marks -3.5, y marks 2.0)"


STRICT_CUES = r"numbered order|out of turn|order walked|kept to the order|in exactly that order|order poured|" \
              r"exactly this sequence|route order|no sequence breaks"
FREE_CUES = r"whatever sequence you like|any order it likes|rider's call|whatever order you please|" \
            r"order did not matter|any order you fancy|whatever order suits|any order is legal|no forced order"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_stay_whole_in_order(sgs, seed, strict):
    check_order(Y.render_goal_y, Y.render_instruction_y, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [Y.render_goal_y(rng, sg) for sg in sgs]
    low = Y.render_instruction_y(rng, res, "strict" if strict else "free").lower()
    if strict:
        assert re.search(STRICT_CUES, low), low
    at = 0
    for r in res:
        at = low.find(r.lower(), at)
        assert at >= 0, (r, low)
        at += len(r)


_OWN_HEADS = ("kettle", "toaster", "guitar", "harp", "heater", "fern", "lamp", "sofa")
_WORDS = {w: i for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight"))}
_ORDS = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth")


@SETTINGS
@given(n=st.integers(2, 8), seed=st.integers(0, 2**31), strict=st.booleans())
def test_counts_numbers_and_days_agree_with_the_goals(n, seed, strict):
    res = [f"the {h}" for h in _OWN_HEADS[:n]]
    text = Y.render_instruction_y(np.random.default_rng(seed), res, "strict" if strict else "free")
    for m in re.finditer(r"\b(\w+) (fences,|obstacles|errands|wishes|glasses|bottles|pickups)", text):
        assert _WORDS[m.group(1)] == n, text
    lines = text.split("\n")
    goal_lines = [ln for ln in lines if re.search(r"\bthe (" + "|".join(_OWN_HEADS[:n]) + r")\b", ln)]
    if len(goal_lines) > 1:
        assert len(goal_lines) == n, text
        for word, last in (("Fence", "Final fence: "), ("Glass", None), ("split", "final split – ")):
            nums = [int(m.group(1)) for ln in goal_lines if (m := re.match(word + r" (\d+)\b", ln))]
            if nums:
                assert nums == list(range(1, n + (last is None))), text
                if last:
                    assert goal_lines[-1].startswith(last), text
        days = [m.group(1) for ln in goal_lines if (m := re.match(r"On the (\w+) day", ln))]
        if days:
            assert days == list(_ORDS[: n - 1]) and goal_lines[-1].startswith("And on the last day"), text
    at = 0
    for r in res:  # every goal once, in order, never run into the next word
        m = re.compile(re.escape(r) + r"(?![\w-])").search(text, at)
        assert m, (r, text)
        at = m.end()


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_and_keeps_the_goal(sg, seed):
    rng = np.random.default_rng(seed)
    goal = Y.render_goal_y(rng, sg)
    text = Y.render_instruction_y(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text), text
    assert not re.search(FREE_CUES, text.lower()) and not re.search(STRICT_CUES, text.lower()), text


def test_every_author_is_used_and_a_seed_repeats():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    texts = [Y.render_instruction_y(rng, res, order) for order in ("strict", "free") for _ in range(80)]
    for m in (r"showjumping|fence|gambler's choice|here we go", r"once upon a time|old woman|fairy godmother",
              r"tasting|glass|sommelier|open bar", r"route|split|collectibles|speedrun|timer"):
        assert any(re.search(m, t.lower()) for t in texts), m
    for some, cues in ((texts[:80], STRICT_CUES), (texts[80:], FREE_CUES)):  # every cue of each order is written
        got = {c for t in some for c in re.findall(cues, t.lower())}
        assert got == set(cues.split("|")), set(cues.split("|")) - got
    assert any("\n" in t for t in texts) and any("\n" not in t for t in texts)
    assert len(set(texts)) > 40
    singles = [Y.render_instruction_y(rng, res[:1], "strict") for _ in range(80)]
    for m in (r"jump-off|one fence only", r"only one errand|nowhere else", r"just one glass|by the glass only",
              r"single-segment|one stop only"):
        assert any(re.search(m, t.lower()) for t in singles), m
    again = [Y.render_instruction_y(np.random.default_rng(9), res, "free") for _ in range(2)]
    assert again[0] == again[1]


def test_unseen_y_sensor_numbers_are_the_constraints():
    """The written number of a reading is the constraint's, in the goal's own text."""
    from test_heldout_sets import SMALL

    from ragnav_jax.config import load_config
    from ragnav_jax.language.episodes import generate_episodes
    from ragnav_jax.world.generator import generate_scene

    scene = generate_scene(load_config(None, SMALL).world, 5, 0)
    eps = generate_episodes([scene], load_config(None, [*SMALL, "episodes.split=unseen_y"]).episodes, seed=3)
    assert eps
    for p in eps:
        for sg in p.truth.subgoals:
            numbers = numbers_in(sg.text)
            for c in sg.sensors:
                if not c.is_superlative:
                    assert pytest.approx(c.value, abs=0.006) in numbers, sg.text
            if sg.location is not None:
                assert numbers[-2:] == [pytest.approx(sg.location.x), pytest.approx(sg.location.y)], sg.text
