"""The `unseen_x` held-out templates (set X): every piece of the ground truth is written down.

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
    reading_norm,
    spoken_numbers,
    target_truth,
)
from template_checks import (
    depths as _depths,
)
from test_phrasings_dev8 import HEADS, MODS, ROOMS, STATES, constraints, subgoals

from ragnav_jax.language import phrasings_x as X
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# The whole phrases a reader of X's goals splits on, each with its relation type (written apart from the templates)
X_REL_PHRASES = {
    "near": "near", "within hail of": "near", "in the neighbourhood of": "near",
    "next to": "next_to", "cheek by jowl with": "next_to", "shoulder to shoulder with": "next_to",
    "beside": "beside", "keeping company beside": "beside", "flanking": "beside",
    "by": "by", "posted by": "by", "moored by": "by",
    "on": "on", "riding on": "on", "enthroned on": "on",
    "under": "under", "sheltering under": "under", "skulking beneath": "under",
    "above": "above", "aloft over": "above", "hanging high over": "above",
    "in": "in", "nestled inside": "in", "stowed in": "in",
    "with": "with", "sporting": "with", "complete with": "with",
    "in the same room as": "in_room_with", "sharing a room with": "in_room_with",
    "in the room that also holds": "in_room_with",
    "in front of": "in_front_of", "fronting": "in_front_of", "standing before": "in_front_of",
    "behind": "behind", "lurking behind": "behind", "hidden round the back of": "behind",
    "opposite": "opposite", "over the way from": "opposite", "face to face with": "opposite",
    "to the left of": "left_of", "on the port side of": "left_of", "leftward of": "left_of",
    "to the right of": "right_of", "on the starboard side of": "right_of", "rightward of": "right_of",
}
_BY_LENGTH = sorted(X_REL_PHRASES, key=len, reverse=True)
X_REL_WORDS: dict[str, tuple[str, ...]] = {}
for _p, _t in X_REL_PHRASES.items():
    X_REL_WORDS[_t] = (*X_REL_WORDS.get(_t, ()), _p)


# ----------------------------------------------------------------------------------------------------
# A reader of X's goals


def _relations_at_top(text: str) -> list[tuple[int, int, str]]:
    depth, out, i = _depths(text), [], 0
    while i < len(text):
        if depth[i] == 0 and (i == 0 or text[i - 1] == " "):
            for p in _BY_LENGTH:
                if text.startswith(p + " the ", i):
                    out.append((i, i + len(p), X_REL_PHRASES[p]))
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
        seg = re.sub(r"(, as well as| and also| and)\s*$", "", text[end:stop].strip())
        out.append((rtype, _read_np(seg.strip())))
    return out


def _read_np(seg: str) -> dict:
    """'the switched-on teal lamp (namely the one next to the sofa)', 'the lamp of the teal sort (presently open)',
    'the lamp (described as teal), found switched on'."""
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
        if m := re.fullmatch(r"(?:namely|I mean) the one (.+)", body):
            got["relations"] += _read_chain(m.group(1))
        elif m := re.fullmatch(r"presently (.+)", body):
            got["states"] += m.group(1).split(" and ")
        elif m := re.fullmatch(r"described as (.+)", body):
            got["after"] += m.group(1).split(" and ")
        else:
            raise AssertionError(f"unknown bracket {body!r} in {seg!r}")
    parts = [p.strip() for p in plain.split(",") if p.strip()]
    for p in parts[1:]:
        m = re.fullmatch(r"found (.+)", p)
        assert m, (p, seg)
        got["states"] += m.group(1).split(" and ")
    words = " ".join(parts[0].split())
    if m := re.fullmatch(r"(.+) of the (.+) sort", words):
        words = m.group(1)
        got["after"] += m.group(2).split(" and ")
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
    room = None
    m = re.search(r"(?:down in|in) the (" + "|".join(sorted(ROOMS, key=len, reverse=True)) + r")\b", text)
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
    text = X.render_goal_x(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, X_REL_WORDS)
    assert ") (" not in text and max(_depths(text), default=0) <= 1, text
    got, room = read_goal(text)
    assert reading_norm(got) == target_truth(sg.target), text
    assert room == sg.room, text


def test_nested_goal_and_every_attribute_state_and_room_form():
    t = Target("teal wool lamp", "lamp", ("teal", "wool", "switched on"), (
        Relation("next_to", Target("sofa", "sofa", ("open",), (Relation("with", Target("drums", "drums")),))),
        Relation("under", Target("shelves", "shelves"))))
    rng = np.random.default_rng(0)
    texts = [X.render_goal_x(rng, Subgoal(0, t, room="music room")) for _ in range(300)]
    for text in texts:
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "music room", text
        assert text.index("music room") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
    for rx in (r"^the teal wool lamp", r"^the lamp of the teal and wool sort", r"^the lamp \(described as teal and wool\)",
               r"^the switched-on ", r"\(presently switched on\)", r", found switched on,", r"down in the music room",
               r"\(namely the one ", r"\(I mean the one "):
        assert any(re.search(rx, x) for x in texts), rx


def test_every_relation_word_is_used_and_read():
    rng = np.random.default_rng(7)
    for rtype in X.REL_WORDS:
        sg = Subgoal(0, Target("lamp", "lamp", (), (Relation(rtype, Target("sofa", "sofa")),)))
        seen = set()
        for _ in range(100):
            text = X.render_goal_x(rng, sg)
            assert read_goal(text)[0]["relations"][0][0] == rtype, text
            seen.add(text[len("the lamp "): -len(" the sofa")])
        assert seen == set(X_REL_WORDS[rtype]), rtype


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own

_DIGITS = {w: str(i) for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight",
                                              "nine"))}


def numbers_in(text: str) -> list[float]:
    """Every number: '-4', '.65', 'minus 4', 'minus four', 'zero point six five', 'point six five', '22½', '4 degrees
    below zero' ('the one' is a pronoun)."""
    t = text.lower().replace("°c", " c").replace("the one", "the ONE").replace("½", ".5")
    t = re.sub(r"(?:zero )?point((?: (?:" + "|".join(_DIGITS) + r"))+)",
               lambda m: "0." + "".join(_DIGITS[w] for w in m.group(1).split()), t)
    t = re.sub(r"([a-z]+(?:-[a-z]+)*|\d+(?:\.\d+)?) degrees below zero", r"minus \1 degrees", t)
    return spoken_numbers(re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)*", t))


def comparator_of(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"in the region of|somewhere about|close on", "approx"),
                  (r"dip(s|ping) under|or upward|at the very least", "ge"),
                  (r"tops? out at|topping out|no further than|capped at", "le"),
                  (r"\btop(s|ping)\b|higher than|pushing beyond|pushes beyond", "gt"),
                  (r"shy of|lower than|south of", "lt")):
        if re.search(rx, t):
            return c
    return "?"


def reading_of(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|health|leaf|flourish|droop|wither", t):
        return "ndvi"
    if re.search(r"humid|mugg|clamm|driest|parched|arid|%|per ?cent", t):
        return "humidity_pct"
    if re.search(r"temperature|warmest|swelter|toast|coldest|frost|nipp|°|degree|celsius", t):
        return "temperature_c"
    return "?"


_LOW = r"coldest|frostiest|nippiest|least|droopiest|withered|driest|parched|arid|lowest|trails|bottom"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = X.render_sensor_x(np.random.default_rng(seed), c)
    check_sensor(rendered, c, comparator_of, _LOW, r"°c|degree|celsius", r"(?i)%|per ?cent", numbers_in, reading_of)
    text = (rendered[0] + " " + rendered[1]).strip()
    assert text.count("[") == text.count("]"), text
    if "below zero" in text:
        assert c.comparator == "approx" and rendered[2].value < 0, text


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase_after_the_head(c, sg, seed):
    rng = np.random.default_rng(seed)
    prefix, tail, _ = X.render_sensor_x(rng, c)
    sg = Subgoal(0, Target(sg.target.phrase, sg.target.head, sg.target.attributes), room=sg.room)
    text = X.render_goal_x(rng, sg, prefix=prefix, tail=tail)
    assert text.startswith("the " + (prefix + " " if prefix else "")), text
    if tail:
        assert tail in text and text.index(sg.target.head) < text.index(tail), text
        if sg.room and c.is_superlative:
            assert text.index(sg.room) < text.index(tail), text
    assert numbers_in(text) == ([] if c.is_superlative else [pytest.approx(c.value, abs=0.006)]), text


def test_number_formats_frames_and_superlatives_vary():
    rng = np.random.default_rng(3)
    cold = {X.render_sensor_x(rng, SensorConstraint("temperature_c", "approx", -4.0))[1] for _ in range(300)}
    for rx in (r"minus four", r"minus 4\b", r"\b(4|four) degrees below zero", r"-4\b", r"^that ", r"^whose ",
               r"^where the temperature ", r"^with a temperature that ", r"^\[temperature "):
        assert any(re.search(rx, t) for t in cold), rx
    assert all(numbers_in(t) == [-4.0] for t in cold)
    half = {X.render_sensor_x(rng, SensorConstraint("humidity_pct", "lt", 22.5))[1] for _ in range(100)}
    assert any("22½" in t for t in half) and any("22.5" in t for t in half)
    ndvi = {X.render_sensor_x(rng, SensorConstraint("ndvi", "gt", 0.65))[1] for _ in range(200)}
    for rx in (r"(?<![\d])\.65\b", r"0\.65\b", r"zero point six five", r"(?<!zero )point six five", r"with an NDVI"):
        assert any(re.search(rx, t) for t in ndvi), rx
    sup = {X.render_sensor_x(rng, SensorConstraint("humidity_pct", "max")) for _ in range(200)}
    assert {"most humid", "muggiest", "clammiest"} <= {p for p, _, _ in sup}
    assert {"whose humidity ranks highest", "that leads every other on humidity",
            "with the humidity at the very top"} <= {t for _, t, _ in sup}


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(X.hint_text_x, X.render_goal_x, X.render_instruction_x, x, y, seed)


def test_every_coordinate_form_is_used():
    rng = np.random.default_rng(4)
    hints = {X.hint_text_x(rng, "-3.5", "2.0") for _ in range(100)}
    assert hints == {"plotted at x -3.5 and y 2.0", "(grid x -3.5, grid y 2.0)", "at x -3.5 / y 2.0",
                     "at the point (-3.5, 2.0) on the plan"}
    goal = X.render_goal_x(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(-3.5, 2.0)),
                           hint="at x -3.5 / y 2.0")
    assert goal == "the guitar at x -3.5 / y 2.0"


STRICT_CUES = r"strictly in that sequence|no skipping ahead|exactly that sequence|one region after the next|" \
              r"catalogue order|numbered sequence|exhibit by exhibit|in the order described|made good in sequence|" \
              r"no short cuts|leg by leg|in the order planned|order of my rhyme|each line in turn"
FREE_CUES = r"in any order|no set sequence|however the day unfolds|no set route|no prescribed route|" \
            r"no fixed route|whichever order|no line need come before"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_stay_whole_in_order(sgs, seed, strict):
    check_order(X.render_goal_x, X.render_instruction_x, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [X.render_goal_x(rng, sg) for sg in sgs]
    low = X.render_instruction_x(rng, res, "strict" if strict else "free").lower()
    if strict:
        assert re.search(STRICT_CUES, low), low
    at = 0
    for r in res:
        at = low.find(r.lower(), at)
        assert at >= 0, (r, low)
        at += len(r)


_OWN_HEADS = ("kettle", "toaster", "guitar", "harp", "heater", "fern", "lamp", "sofa")
_WORDS = {w: i for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight"))}


@SETTINGS
@given(n=st.integers(2, 8), seed=st.integers(0, 2**31), strict=st.booleans())
def test_counts_numbers_waypoints_and_rhymes_agree_with_the_goals(n, seed, strict):
    res = [f"the {h}" for h in _OWN_HEADS[:n]]
    text = X.render_instruction_x(np.random.default_rng(seed), res, "strict" if strict else "free")
    for m in re.finditer(r"\b(\w+) spots|works \((\w+)\)|check \((\w+)\)", text):
        assert _WORDS[next(g for g in m.groups() if g)] == n, text
    lines = text.split("\n")
    goal_lines = [ln for ln in lines if re.search(r"\bthe (" + "|".join(_OWN_HEADS[:n]) + r")\b", ln)]
    if len(goal_lines) > 1:
        assert len(goal_lines) == n, text
        nums = [int(m.group(1)) for ln in goal_lines if (m := re.match(r"Exhibit (\d+)\. ", ln))]
        assert nums in ([], list(range(1, n + 1))), text
        wps = [m.group(1) for ln in goal_lines if (m := re.match(r"Waypoint (\w+)", ln))]
        if wps:
            assert wps == ["Alpha", "Bravo", "Charlie", "Delta", "Echo", "Foxtrot", "Golf"][: n - 1], text
            assert goal_lines[-1].startswith("Summit push: "), text
    verse = lines[2:-2] if text.startswith("In any order, as you please,\n") else \
        lines[:-2] if "Keep to the order of my rhyme:" in lines else []
    if verse:  # the couplets rhyme, two lines at a time, and every goal has its line
        assert len(verse) == n + n % 2 and not text.count(".."), text
        ends = [re.search(r"(\w+)\W*$", ln).group(1) for ln in verse]
        for a, b in zip(ends[::2], ends[1::2]):
            assert a[-2:] == b[-2:] or {a, b} in ({"delay", "may"}, {"stray", "way"}, {"delay", "say"},
                                                  {"stray", "say"}, {"tread", "said"}), (a, b, text)


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_and_keeps_the_goal(sg, seed):
    rng = np.random.default_rng(seed)
    goal = X.render_goal_x(rng, sg)
    text = X.render_instruction_x(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text), text
    assert not re.search(FREE_CUES, text.lower()), text


def test_every_author_is_used_and_a_seed_repeats():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    texts = [X.render_instruction_x(rng, res, order) for order in ("strict", "free") for _ in range(80)]
    for m in (r"outlook|weather script|forecast|band of activity|moving east", r"exhibit|catalogue|curator|salon hang",
              r"waypoint|summit push|base camp|bearing", r"rhyme|as you please,\n|the verse"):
        assert any(re.search(m, t.lower()) for t in texts), m
    assert any("\n" in t for t in texts) and any("\n" not in t for t in texts)
    assert len(set(texts)) > 40
    singles = [X.render_instruction_x(rng, res[:1], "strict") for _ in range(80)]
    for m in (r"settled spell|single bright patch", r"single-work display|sole exhibit", r"one objective|single waypoint",
              r"tidy and keen|this refrain"):
        assert any(re.search(m, t.lower()) for t in singles), m
    again = [X.render_instruction_x(np.random.default_rng(9), res, "free") for _ in range(2)]
    assert again[0] == again[1]


def test_unseen_x_sensor_numbers_are_the_constraints():
    """The written number of a reading is the constraint's, in the goal's own text."""
    from test_heldout_sets import SMALL

    from ragnav_jax.config import load_config
    from ragnav_jax.language.episodes import generate_episodes
    from ragnav_jax.world.generator import generate_scene

    scene = generate_scene(load_config(None, SMALL).world, 5, 0)
    eps = generate_episodes([scene], load_config(None, [*SMALL, "episodes.split=unseen_x"]).episodes, seed=3)
    assert eps
    for p in eps:
        for sg in p.truth.subgoals:
            for c in sg.sensors:
                if not c.is_superlative:
                    assert numbers_in(sg.text) == [pytest.approx(c.value, abs=0.006)], sg.text
