"""The `unseen_z` held-out templates (set Z): every piece of the ground truth is written down.

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
    check_goal,
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

from ragnav_jax.language import phrasings_z as Z
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# The whole phrases a reader of Z's goals splits on, each with its relation type (written apart from the templates)
Z_REL_PHRASES = {
    "near": "near", "close at hand to": "near", "within a short stroll of": "near",
    "next to": "next_to", "pushed up against": "next_to", "jostling": "next_to",
    "beside": "beside", "sat alongside": "beside", "standing sentry beside": "beside",
    "by": "by", "keeping vigil by": "by", "mooching about by": "by",
    "on": "on", "sprawled on": "on", "sat up on": "on",
    "under": "under", "slung beneath": "under", "camped out under": "under",
    "above": "above", "dangling above": "above", "lording it over": "above",
    "in": "in", "snug inside": "in", "kept safe in": "in",
    "with": "with", "laden with": "with", "furnished with": "with",
    "in the same room as": "in_room_with", "cohabiting with": "in_room_with", "roomed together with": "in_room_with",
    "in front of": "in_front_of", "drawn up in front of": "in_front_of", "set down before": "in_front_of",
    "behind": "behind", "cowering behind": "behind", "hunkered down behind": "behind",
    "opposite": "opposite", "on the opposite wall to": "opposite", "gazing across at": "opposite",
    "to the left of": "left_of", "a hair to the left of": "left_of", "round to the left of": "left_of",
    "to the right of": "right_of", "a hair to the right of": "right_of", "round to the right of": "right_of",
}
_BY_LENGTH = sorted(Z_REL_PHRASES, key=len, reverse=True)
Z_REL_WORDS: dict[str, tuple[str, ...]] = {}
for _p, _t in Z_REL_PHRASES.items():
    Z_REL_WORDS[_t] = (*Z_REL_WORDS.get(_t, ()), _p)

# ----------------------------------------------------------------------------------------------------
# A reader of Z's goals


def _relations_at_top(text: str) -> list[tuple[int, int, str]]:
    """(start, end, type) of every relation phrase outside brackets, followed by 'the' (longest phrase first)."""
    depth, out, i = _depths(text), [], 0
    while i < len(text):
        if depth[i] == 0 and (i == 0 or text[i - 1] == " "):
            for p in _BY_LENGTH:
                if text.startswith(p + " the ", i):
                    out.append((i, i + len(p), Z_REL_PHRASES[p]))
                    i += len(p)
                    break
        i += 1
    return out


def _read_chain(text: str) -> list[tuple[str, dict]]:
    # 'that is itself ...' hangs the rest of the text on the anchor before it
    depth = _depths(text)
    at = next((m.start() for m in re.finditer(" that is itself ", text) if depth[m.start()] == 0), -1)
    if at >= 0:
        before, after = text[:at], text[at + len(" that is itself "):]
        chain = _read_chain(before)
        chain[-1][1]["relations"] += _read_chain(after)
        return chain
    rels = _relations_at_top(text)
    assert rels and text[: rels[0][0]].strip() == "", text
    out = []
    for k, (_, end, rtype) in enumerate(rels):
        stop = rels[k + 1][0] if k + 1 < len(rels) else len(text)
        seg = re.sub(r"(, and what's more,|, as well as being| and)\s*$", "", text[end:stop].strip())
        out.append((rtype, _read_np(seg.strip())))
    return out


def _read_np(seg: str) -> dict:
    """'the switched-on teal lamp (you know, next to the sofa)', 'the lamp (teal, you can't miss it), known to be
    open', 'the lamp (switched on, mind), a teal and wool affair', 'the sofa (to be precise, the sofa by the door)'."""
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
    heads = []
    for body in groups:
        if m := re.fullmatch(r"to be precise, the (.+)", body):
            rels = _relations_at_top(m.group(1))
            assert rels, body
            heads.append(m.group(1)[: rels[0][0]].strip())
            got["relations"] += _read_chain(m.group(1)[rels[0][0]:])
        elif m := re.fullmatch(r"you know, (.+)", body):
            got["relations"] += _read_chain(m.group(1))
        elif m := re.fullmatch(r"(.+), mind", body):
            got["states"] += m.group(1).split(" and ")
        elif m := re.fullmatch(r"(.+), you can't miss it", body):
            got["after"] += m.group(1).split(" and ")
        else:
            raise AssertionError(f"unknown bracket {body!r} in {seg!r}")
    parts = [p.strip() for p in plain.split(",") if p.strip()]
    for p in parts[1:]:
        if m := re.fullmatch(r"known to be (.+)", p):
            got["states"] += m.group(1).split(" and ")
        else:
            m = re.fullmatch(r"an? (.+) affair", p)
            assert m, (p, seg)
            got["after"] += m.group(1).split(" and ")
    words = " ".join(parts[0].split())
    assert words.startswith("the "), seg
    words = words[4:]
    head = max((h for h in HEADS if words == h or words.endswith(" " + h)), key=len)
    got["head"] = head
    assert all(h == head for h in heads), (heads, seg)  # '(to be precise, the sofa ...)' names the anchor again
    for w in words[: len(words) - len(head)].split():
        if w in MODS:
            got["attrs"].append(w)
        else:
            assert w.replace("-", " ") in STATES, (w, seg)
            got["states"].append(w.replace("-", " "))
    got["attrs"] += got.pop("after")
    return got


_ROOM_RX = re.compile(r"(?:right there )?in the (" + "|".join(sorted(ROOMS, key=len, reverse=True)) + r")\b")


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
    text = Z.render_goal_z(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, Z_REL_WORDS)
    assert ") (" not in text and max(_depths(text), default=0) <= 1, text
    got, room = read_goal(text)
    assert reading_norm(got) == target_truth(sg.target), text
    assert room == sg.room, text


def test_nested_goal_and_every_attribute_state_and_room_form():
    t = Target("teal wool lamp", "lamp", ("teal", "wool", "switched on"), (
        Relation("next_to", Target("sofa", "sofa", ("open",), (Relation("with", Target("drums", "drums")),))),
        Relation("under", Target("shelves", "shelves", ("empty",)))))
    rng = np.random.default_rng(0)
    texts = [Z.render_goal_z(rng, Subgoal(0, t, room="music room")) for _ in range(300)]
    for text in texts:
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "music room", text
        assert text.index("music room") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
    for rx in (r"^the teal wool lamp", r"^the lamp \(teal and wool, you can't miss it\)",
               r"^the lamp, a teal and wool affair,", r"^the switched-on lamp, a teal and wool affair,",
               r"^the lamp \(switched on, mind\), a teal and wool affair,", r", known to be switched on,",
               r" right there in the music room ", r"^[^(]* in the music room ", r"\(to be precise, the sofa ",
               r"\(you know, ", r"the shelves \(empty, mind\)", r"the empty shelves", r", and what's more, ",
               r", as well as being ", r"the open sofa"):
        assert any(re.search(rx, x) for x in texts), rx
    # 'an' before a vowel
    olive = {Z.render_goal_z(rng, Subgoal(0, Target("olive sofa", "sofa", ("olive",)))) for _ in range(60)}
    assert "the sofa, an olive affair" in olive and not any(" a olive" in x for x in olive)


def test_a_phrase_of_another_shape_keeps_every_attribute():
    """A phrase that does not end on its head is written as given; attributes it lacks follow in an aside."""
    t = Target("bean bag chair", "bean bag", ("teal", "corduroy", "bean"))
    rng = np.random.default_rng(11)
    plain = {Z.render_goal_z(rng, Subgoal(0, t, room="nursery")) for _ in range(40)}
    hinted = {Z.render_goal_z(rng, Subgoal(0, t), hint="(x/y fix: 1.0, 2.0)") for _ in range(40)}
    for text in plain:
        assert re.match(r"the bean bag chair \(teal and corduroy, you can't miss it\) (right there )?in the nursery$",
                        text), text
    assert hinted == {"the bean bag chair, a teal and corduroy affair (x/y fix: 1.0, 2.0)"}
    assert Z.render_goal_z(rng, Subgoal(0, Target("bean bag chair", "bean bag", ("bean",)))) == "the bean bag chair"


def test_deeper_anchors_hang_on_their_own_noun():
    """Below the first bracket an anchor's own relations follow 'that is itself', so nothing nests a bracket."""
    inner = Target("drums", "drums", ("switched on",), (Relation("behind", Target("toolbox", "toolbox")),))
    t = Target("lamp", "lamp", (), (Relation("by", Target("sofa", "sofa", (), (Relation("near", inner),))),))
    rng = np.random.default_rng(5)
    for _ in range(100):
        text = Z.render_goal_z(rng, Subgoal(0, t, room="nursery"))
        assert max(_depths(text)) <= 1 and " that is itself " in text, text
        check_goal(text, Subgoal(0, t, room="nursery"), Z_REL_WORDS, "{}")
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "nursery", text


def test_every_relation_word_is_used_and_read():
    rng = np.random.default_rng(7)
    for rtype in Z.REL_WORDS:
        sg = Subgoal(0, Target("lamp", "lamp", (), (Relation(rtype, Target("sofa", "sofa")),)))
        seen = set()
        for _ in range(100):
            text = Z.render_goal_z(rng, sg)
            assert read_goal(text)[0]["relations"][0][0] == rtype, text
            seen.add(text[len("the lamp "): -len(" the sofa")])
        assert seen == set(Z_REL_WORDS[rtype]), rtype


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own


def _word_value(w: str) -> float:
    k = spoken_numbers([w])
    assert len(k) == 1, w
    return k[0]


def numbers_in(text: str) -> list[float]:
    """Every number: '-4', '.65', '0·65', '22·5', 'minus 4', 'minus four', 'a hundred and five', 'twenty-two point
    five', 'point sixty-five', 'point oh five', '4 degrees of frost', 'four degrees of frost'."""
    t = text.lower().replace("°c", " c").replace("·", ".")
    t = re.sub(r"\ba hundred\b", "one hundred", t)
    t = re.sub(r"\b([a-z]+(?:-[a-z]+)?) point ([a-z]+)\b",
               lambda m: f"{_word_value(m.group(1)) + _word_value(m.group(2)) / 10:g}"
               if spoken_numbers([m.group(1)]) else m.group(0), t)
    t = re.sub(r"\bpoint oh ([a-z]+)\b", lambda m: f"{_word_value(m.group(1)) / 100:.2f}", t)
    t = re.sub(r"\bpoint ([a-z]+(?:-[a-z]+)?)\b",  # 'point six' is tenths, 'point sixty-five' hundredths
               lambda m: f"{_word_value(m.group(1)) / (10 if _word_value(m.group(1)) < 10 else 100):.2f}", t)
    t = re.sub(r"(\d+(?:\.\d+)?|[a-z]+(?:-[a-z]+)?) degrees of frost\b",
               lambda m: f"minus {m.group(1)} degrees" if spoken_numbers([m.group(1)]) else m.group(0), t)
    return spoken_numbers(re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)*", t))


def comparator_of(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"nigh on|a shade either side|just about", "approx"),
                  (r"sinks beneath|or more, never less|holds firm at", "ge"),
                  (r"or lower, never more|and stops there|rises higher than", "le"),
                  (r"nosed above|poked its head above|reads more than", "gt"),
                  (r"hasn't touched|reads less than|made it as high as", "lt")):
        if re.search(rx, t):
            return c
    return "?"


def reading_of(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|health|heartiest|burgeon|peakiest|puniest", t):
        return "ndvi"
    if re.search(r"humid|swamp|waterlogged|driest|dustiest|tinder|%|per-?cent", t):
        return "humidity_pct"
    if re.search(r"temperature|warmest|torrid|scalding|coldest|ice-cold|bone-chilling|°|degree|celsius", t):
        return "temperature_c"
    return "?"


_LOW = r"coldest|ice-cold|bone-chilling|least|peakiest|puniest|driest|dustiest|tinder|low-water|wooden spoon|" \
       r"all-time-low"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = Z.render_sensor_z(np.random.default_rng(seed), c)
    check_sensor(rendered, c, comparator_of, _LOW, r"°c|degree|celsius", r"(?i)%|per-?cent", numbers_in, reading_of)
    text = (rendered[0] + " " + rendered[1]).strip()
    assert "(" not in text and "  " not in text, text
    if "frost" in text:
        assert c.comparator == "approx" and rendered[2].value < 0 and rendered[2].unit == "c", text
        assert re.search(r"\b(\d+|[a-z]+(-[a-z]+)?) degrees of frost$", text) and "minus" not in text, text
    if not rendered[2].unit and not c.is_superlative:  # a unitless number always has its reading named
        assert re.search(r"(the (temperature|humidity|ndvi) of which|for which the (temperature|humidity|ndvi)) ",
                         text.lower()), text


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase_after_the_head(c, sg, seed):
    check_sensor_goal(Z.render_sensor_z, Z.render_goal_z, c, sg, seed, numbers_in)


@SETTINGS
@given(c=constraints(), sg=subgoals(), x=st.floats(-20, 40).map(lambda v: round(v, 1)),
       y=st.floats(-20, 40).map(lambda v: round(v, 1)), seed=st.integers(0, 2**31))
def test_a_goal_with_sensor_and_hint_ends_on_the_coordinates(c, sg, x, y, seed):
    """The hint's numbers come last in the goal (after any number of the sensor phrase), and brackets never stack."""
    rng = np.random.default_rng(seed)
    prefix, tail, _ = Z.render_sensor_z(rng, c)
    hint = Z.hint_text_z(rng, f"{x:.1f}", f"{y:.1f}")
    text = Z.render_goal_z(rng, sg, prefix=prefix, tail=tail, hint=hint)
    nums = numbers_in(text)
    assert nums[-2:] == [pytest.approx(x), pytest.approx(y)], text
    assert len(nums) == 2 + (not c.is_superlative), text
    assert ") (" not in text and max(_depths(text), default=0) <= 1 and text.count("(") == text.count(")"), text
    # the reader still finds head, attributes, states and room once the sensor phrase and hint are cut out
    cut = " ".join(text.replace(tail, " ").replace(hint, " ").split()) if tail else text.replace(hint, " ")
    if prefix:
        cut = cut.replace(f"the {prefix} ", "the ", 1)
    got, room = read_goal(_tidy_cut(cut))
    assert reading_norm(got) == target_truth(sg.target), (text, cut)
    assert room == sg.room, text


def _tidy_cut(s: str) -> str:
    s = " ".join(s.split())
    for a, b in ((" ,", ","), (",,", ","), (", ,", ",")):
        s = s.replace(a, b)
    return s.strip().rstrip(",")


@SETTINGS
@given(v=st.integers(-30, -1).map(float) | st.sampled_from([-0.5, -2.5, -12.5]), cmp=st.sampled_from(("approx", "lt")),
       seed=st.integers(0, 2**31))
def test_temperatures_below_zero_keep_their_sign(v, cmp, seed):
    """'four degrees of frost', 'minus 4', '-4' and 'minus four' all write a value below zero, in °C."""
    prefix, tail, written = Z.render_sensor_z(np.random.default_rng(seed), SensorConstraint("temperature_c", cmp, v))
    assert not prefix and written == SensorConstraint("temperature_c", cmp, v, written.unit), tail
    assert numbers_in(tail) == [v] and comparator_of(tail) == cmp, tail
    assert written.unit == ("c" if re.search(r"°c|degree|celsius", tail.lower()) else ""), tail


def test_number_formats_frames_and_superlatives_vary():
    rng = np.random.default_rng(3)
    cold = {Z.render_sensor_z(rng, SensorConstraint("temperature_c", "approx", -4.0))[1] for _ in range(300)}
    for rx in (r"minus four", r"minus 4\b", r"\b4 degrees of frost$", r"\bfour degrees of frost$", r"(?<!\w)-4\b",
               r"^that ", r"^the temperature of which ", r"^for which the temperature ", r"on the Celsius scale",
               r"degrees Celsius", r"°C", r"nigh on", r"a shade either side", r"just about"):
        assert any(re.search(rx, t) for t in cold), rx
    assert all(numbers_in(t) == [-4.0] for t in cold)
    half = {Z.render_sensor_z(rng, SensorConstraint("temperature_c", "lt", 22.5))[1] for _ in range(200)}
    for rx in (r"twenty-two point five", r"22\.5", r"22·5"):
        assert any(re.search(rx, t) for t in half), rx
    assert all(numbers_in(t) == [22.5] for t in half)
    neg = {Z.render_sensor_z(rng, SensorConstraint("temperature_c", "ge", -2.5))[1] for _ in range(200)}
    for rx in (r"minus 2\.5", r"(?<!\w)-2\.5", r"(?<!\w)-2·5"):
        assert any(re.search(rx, t) for t in neg), rx
    assert all(numbers_in(t) == [-2.5] for t in neg)
    hot = {Z.render_sensor_z(rng, SensorConstraint("temperature_c", "gt", 105.0))[1] for _ in range(100)}
    assert any("a hundred and five" in t for t in hot) and all(numbers_in(t) == [105.0] for t in hot)
    damp = {Z.render_sensor_z(rng, SensorConstraint("humidity_pct", "le", 40.0))[1] for _ in range(200)}
    for rx in (r"\d%", r"\d %", r"per-cent", r"percent", r"forty"):
        assert any(re.search(rx, t) for t in damp), rx
    ndvi = {Z.render_sensor_z(rng, SensorConstraint("ndvi", "gt", 0.65))[1] for _ in range(200)}
    for rx in (r"(?<![\d·])\.65\b", r"0\.65\b", r"0·65", r"point sixty-five", r"^the NDVI of which",
               r"^for which the NDVI"):
        assert any(re.search(rx, t) for t in ndvi), rx
    assert all(numbers_in(t) == [0.65] for t in ndvi)
    for v, words in ((0.6, "point six"), (0.05, "point oh five")):
        got = {Z.render_sensor_z(rng, SensorConstraint("ndvi", "le", v))[1] for _ in range(100)}
        assert any(t.endswith(words) for t in got) and all(numbers_in(t) == [v] for t in got), got
    sup = {Z.render_sensor_z(rng, SensorConstraint("humidity_pct", "max")) for _ in range(200)}
    assert {"most humid", "swampiest", "most waterlogged"} <= {p for p, _, _ in sup}
    assert {"that sets the high-water mark for humidity", "that takes top prize for humidity",
            "with the all-time-high humidity"} <= {t for _, t, _ in sup}
    for cmp in ("gt", "ge", "lt", "le", "approx"):
        seen = {comparator_of(Z.render_sensor_z(rng, SensorConstraint("temperature_c", cmp, 30.0))[1])
                for _ in range(60)}
        assert seen == {cmp}, (cmp, seen)


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(Z.hint_text_z, Z.render_goal_z, Z.render_instruction_z, x, y, seed)


def test_every_coordinate_form_is_used():
    rng = np.random.default_rng(4)
    hints = {Z.hint_text_z(rng, "-3.5", "2.0") for _ in range(100)}
    assert hints == {"at the spot whose x is -3.5 and whose y is 2.0", "(x/y fix: -3.5, 2.0)", "at x=-3.5 & y=2.0",
                     "at the coordinate pair (-3.5, 2.0)"}
    goal = Z.render_goal_z(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(-3.5, 2.0)),
                           hint="(x/y fix: -3.5, 2.0)")
    assert goal == "the guitar (x/y fix: -3.5, 2.0)"


STRICT_CUES = r"timeline order|out of sequence|in the order read|in succession|plot by plot|that succession|" \
              r"just as they're called|figure by figure|the way i call it|running ahead of the caller|" \
              r"in exactly this order|the combination collapses|move order is everything"
FREE_CUES = r"crew's discretion|no constraint on order|any sequence the crew likes|no particular succession|" \
            r"whatever order the weather allows|doesn't matter a jot which comes first|no set calls|" \
            r"whatever order the tune carries you|no calls for this one|whichever order the band carries you|" \
            r"move order free|every line transposes|move order is irrelevant"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_stay_whole_in_order(sgs, seed, strict):
    check_order(Z.render_goal_z, Z.render_instruction_z, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [Z.render_goal_z(rng, sg) for sg in sgs]
    low = Z.render_instruction_z(rng, res, "strict" if strict else "free").lower()
    if strict:
        assert re.search(STRICT_CUES, low), low
    at = 0
    for r in res:
        at = low.find(r.lower(), at)
        assert at >= 0, (r, low)
        at += len(r)


_OWN_HEADS = ("guitar", "harp", "kiln", "crib", "easel", "cello", "lectern", "jukebox")
_WORDS = {w: i for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight"))}


@SETTINGS
@given(n=st.integers(2, 8), seed=st.integers(0, 2**31), strict=st.booleans())
def test_counts_numbers_and_letters_agree_with_the_goals(n, seed, strict):
    _check_counts(n, seed, strict)


def test_counts_agree_over_a_sweep_of_seeds():
    for n in range(2, 9):
        for seed in range(40):
            _check_counts(n, seed, seed % 2 == 0)


def _check_counts(n: int, seed: int, strict: bool) -> None:
    res = [f"the {h}" for h in _OWN_HEADS[:n]]
    text = Z.render_instruction_z(np.random.default_rng(seed), res, "strict" if strict else "free")
    counted = (r"\b(?!the\b)(\w+) (figures|spots on the floor|squares to occupy|get-ahead tasks)"
               r"|(?:TASKS|GARDEN) \((\w+)\)")
    for m in re.finditer(counted, text):
        assert _WORDS[m.group(1) or m.group(3)] == n, text
    lines = text.split("\n")
    goal_lines = [ln for ln in lines if re.search(r"\bthe (" + "|".join(_OWN_HEADS[:n]) + r")\b", ln)]
    if len(goal_lines) > 1:
        assert len(goal_lines) == n, text
        tasks = [int(m.group(1)) for ln in goal_lines if (m := re.search(r"  Task (\d+) – ", ln))]
        if tasks:
            assert tasks == list(range(1, n)) and "  Closeout – " in goal_lines[-1], text
            stamps = [int(a) * 60 + int(b) for ln in goal_lines for a, b in re.findall(r"^MET (\d+):(\d\d)  ", ln)]
            assert len(stamps) == n and stamps == sorted(set(stamps)), text
        plots = [m.group(1) for ln in goal_lines if (m := re.match(r"Plot ([A-Z]):? ", ln))]
        if plots:
            assert plots == list("ABCDEFGH"[:n]) and goal_lines[-1].startswith(f"Plot {plots[-1]} (last to go in): ")
            assert text.count("(last to go in)") == 1, text
        figures = [_WORDS[m.group(1)] for ln in goal_lines if (m := re.match(r"Figure (\w+): ", ln))]
        if figures or goal_lines[-1].startswith("Last figure"):
            assert figures == list(range(1, n)) and goal_lines[-1].startswith("Last figure: promenade home to "), text
        moves = [int(m.group(1)) for ln in goal_lines if (m := re.match(r"(\d+)\. ", ln))]
        if moves:
            assert moves == list(range(1, n + 1)) and goal_lines[-1].endswith(" – and mate."), text
    at = 0
    for r in res:  # every goal once, in order, never run into the next word
        m = re.compile(re.escape(r) + r"(?![\w-])").search(text, at)
        assert m, (r, text)
        at = m.end()


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_and_keeps_the_goal(sg, seed):
    rng = np.random.default_rng(seed)
    goal = Z.render_goal_z(rng, sg)
    text = Z.render_instruction_z(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text), text
    assert not re.search(FREE_CUES, text.lower()) and not re.search(STRICT_CUES, text.lower()), text


def test_every_author_is_used_and_a_seed_repeats():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the guitar", "the kiln"]
    texts = [Z.render_instruction_z(rng, res, order) for order in ("strict", "free") for _ in range(120)]
    for m in (r"eva|flight|capcom|crew", r"garden|plot|trowel|digging", r"figure|partners|caller|dance",
              r"mate|move order|endgame|transpos"):
        assert any(re.search(m, t.lower()) for t in texts), m
    for some, cues in ((texts[:120], STRICT_CUES), (texts[120:], FREE_CUES)):  # every cue of each order is written
        got = {c for t in some for c in re.findall(cues, t.lower())}
        assert got == set(cues.split("|")), set(cues.split("|")) - got
    assert any("\n" in t for t in texts) and any("\n" not in t for t in texts)
    assert len(set(texts)) > 60
    singles = [Z.render_instruction_z(rng, res[:1], "strict") for _ in range(80)]
    for m in (r"single-task eva|contingency eva", r"only one job in the garden|just the one thing",
              r"just the one figure|wee solo turn", r"one-mover|the only move"):
        assert any(re.search(m, t.lower()) for t in singles), m
    again = [Z.render_instruction_z(np.random.default_rng(9), res, "free") for _ in range(2)]
    assert again[0] == again[1]


def test_unseen_z_sensor_numbers_are_the_constraints():
    """The written number of a reading is the constraint's, in the goal's own text."""
    from test_heldout_sets import SMALL

    from ragnav_jax.config import load_config
    from ragnav_jax.language.episodes import generate_episodes
    from ragnav_jax.world.generator import generate_scene

    scene = generate_scene(load_config(None, SMALL).world, 5, 0)
    eps = generate_episodes([scene], load_config(None, [*SMALL, "episodes.split=unseen_z"]).episodes, seed=3)
    assert eps
    for p in eps:
        for sg in p.truth.subgoals:
            numbers = numbers_in(sg.text)
            for c in sg.sensors:
                if not c.is_superlative:
                    assert pytest.approx(c.value, abs=0.006) in numbers, sg.text
            if sg.location is not None:
                assert numbers[-2:] == [pytest.approx(sg.location.x), pytest.approx(sg.location.y)], sg.text
