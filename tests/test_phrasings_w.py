"""The `unseen_w` held-out templates (set W): every piece of the ground truth is written down.

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
    tidy_commas,
    word_number,
)
from template_checks import (
    depths as _depths,
)
from test_phrasings_dev8 import HEADS, MODS, ROOMS, STATES, constraints, subgoals

from ragnav_jax.language import phrasings_w as W
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# The whole phrases a reader of W's goals splits on, each with its relation type (written apart from the templates)
W_REL_PHRASES = {
    "near": "near", "a stone's throw from": "near", "within hailing distance of": "near",
    "in the vicinity of": "near",
    "next to": "next_to", "cheek by jowl with": "next_to", "shoulder to shoulder with": "next_to",
    "beside": "beside", "flanking": "beside", "parked up beside": "beside",
    "by": "by", "hard by": "by", "loitering by": "by",
    "on": "on", "perched on": "on", "resting upon": "on", "atop": "on",
    "under": "under", "tucked beneath": "under", "sheltering under": "under",
    "above": "above", "hovering over": "above", "mounted above": "above",
    "in": "in", "stowed in": "in", "nestled within": "in",
    "with": "with", "complete with": "with", "sporting": "with",
    "in the same room as": "in_room_with", "sharing a room with": "in_room_with",
    "in the selfsame room as": "in_room_with",
    "in front of": "in_front_of", "planted in front of": "in_front_of", "just forward of": "in_front_of",
    "behind": "behind", "astern of": "behind", "at the back of": "behind",
    "opposite": "opposite", "face to face with": "opposite", "over the way from": "opposite",
    "to the left of": "left_of", "on the left-hand side of": "left_of", "on the port side of": "left_of",
    "to the right of": "right_of", "on the right-hand side of": "right_of", "on the starboard side of": "right_of",
}
_BY_LENGTH = sorted(W_REL_PHRASES, key=len, reverse=True)
W_REL_WORDS: dict[str, tuple[str, ...]] = {}
for _p, _t in W_REL_PHRASES.items():
    W_REL_WORDS[_t] = (*W_REL_WORDS.get(_t, ()), _p)

# ----------------------------------------------------------------------------------------------------
# A reader of W's goals


def _undash(text: str) -> str:
    """'the sofa — itself next to the drums — and ...' read as 'the sofa (itself next to the drums) and ...'."""
    return re.sub(r" — ((?:itself|themselves) [^—]+?) —", r" (\1)", text)


def _relations_at_top(text: str) -> list[tuple[int, int, str]]:
    """(start, end, type) of every relation phrase outside brackets, followed by 'the' (longest phrase first)."""
    depth, out, i = _depths(text), [], 0
    while i < len(text):
        if depth[i] == 0 and (i == 0 or text[i - 1] == " "):
            for p in _BY_LENGTH:
                if text.startswith(p + " the ", i):
                    out.append((i, i + len(p), W_REL_PHRASES[p]))
                    i += len(p)
                    break
        i += 1
    return out


_JOIN_AT_END = re.compile(r"(?:,? and furthermore,?| as well as| and)\s*$")


def _read_chain(text: str) -> list[tuple[str, dict]]:
    # ', which in turn is ...' hangs the rest of the text on the anchor before it
    depth = _depths(text)
    at = next((m for m in re.finditer(r", which in turn (?:is|are) ", text) if depth[m.start()] == 0), None)
    if at is not None:
        chain = _read_chain(text[: at.start()])
        chain[-1][1]["relations"] += _read_chain(text[at.end():])
        return chain
    rels = _relations_at_top(text)
    assert rels and text[: rels[0][0]].strip() == "", text
    out = []
    for k, (_, end, rtype) in enumerate(rels):
        stop = rels[k + 1][0] if k + 1 < len(rels) else len(text)
        seg = _JOIN_AT_END.sub("", text[end:stop].strip())
        out.append((rtype, _read_np(seg.strip().rstrip(","))))
    return out


def _read_np(seg: str) -> dict:
    """'the switched-on teal lamp (itself next to the sofa)', 'the lamp (inventoried as teal), reported open', 'the
    lamp of the teal and wool kind that somebody left switched on', 'the shelves (found empty)', 'the lamp (state:
    open)', 'the sofa (which, for the avoidance of doubt, is by the door)'."""
    got = {"attrs": [], "after": [], "states": [], "relations": []}
    depth, plain, i = _depths(seg), "", 0
    while i < len(seg):
        if seg[i] == "(" and depth[i] == 1:
            j = i
            while not (seg[j] == ")" and depth[j] == 1):
                j += 1
            body = seg[i + 1 : j]
            if m := re.fullmatch(r"(?:itself|themselves) (.+)", body):
                got["relations"] += _read_chain(m.group(1))
            elif m := re.fullmatch(r"which, for the avoidance of doubt, (?:is|are) (.+)", body):
                got["relations"] += _read_chain(m.group(1))
            elif m := re.fullmatch(r"(?:state:|found) (.+)", body):
                got["states"] += m.group(1).split(" and ")
            elif m := re.fullmatch(r"inventoried as (.+)", body):
                got["after"] += m.group(1).split(" and ")
            else:
                raise AssertionError(f"unknown bracket {body!r} in {seg!r}")
            i = j + 1
            continue
        plain += seg[i]
        i += 1
    parts = [p.strip() for p in plain.split(",") if p.strip()]
    for p in parts[1:]:
        m = re.fullmatch(r"reported (.+)", p)
        assert m, (p, seg)
        got["states"] += m.group(1).split(" and ")
    words = " ".join(parts[0].split())
    if m := re.search(r" that somebody left (.+)$", words):
        got["states"] += m.group(1).split(" and ")
        words = words[: m.start()]
    if m := re.search(r" of the (.+) kind$", words):
        got["after"] += m.group(1).split(" and ")
        words = words[: m.start()]
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


_ROOM_RX = re.compile(r"(?:, )?\b(?:(?:down |over |situated )?in the|whose (?:berth|home) is the) ("
                      + "|".join(sorted(ROOMS, key=len, reverse=True)) + r")\b,?")




def read_goal(text: str) -> tuple[dict, str | None]:
    room = None
    m = _ROOM_RX.search(text)
    if m:
        room = m.group(1)
        text = text[: m.start()] + " " + text[m.end():]
    text = _undash(tidy_commas(text))
    rels = _relations_at_top(text)
    main = text[: rels[0][0]] if rels else text
    main = re.sub(r",?\s*to be found\s*$", "", main.strip())
    got = _read_np(tidy_commas(main))
    if rels:
        got["relations"] += _read_chain(text[rels[0][0]:])
    return got, room


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece_and_reads_back_exactly(sg, seed):
    text = W.render_goal_w(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, W_REL_WORDS)
    assert ") (" not in text and max(_depths(text), default=0) <= 1, text
    got, room = read_goal(text)
    assert reading_norm(got) == target_truth(sg.target), text
    assert room == sg.room, text


def test_nested_goal_and_every_attribute_state_and_room_form():
    t = Target("teal wool lamp", "lamp", ("teal", "wool", "switched on"), (
        Relation("next_to", Target("sofa", "sofa", ("open",), (Relation("with", Target("drums", "drums")),))),
        Relation("under", Target("shelves", "shelves", ("empty",)))))
    rng = np.random.default_rng(0)
    texts = [W.render_goal_w(rng, Subgoal(0, t, room="music room")) for _ in range(400)]
    for text in texts:
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "music room", text
        assert text.index("music room") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
    for rx in (r"^the teal wool lamp", r"^the lamp of the teal and wool kind", r"^the lamp \(inventoried as teal and "
               r"wool\)", r"^the switched-on lamp", r" that somebody left switched on ", r", reported switched on,",
               r"\(state: switched on\)", r" in the music room ", r" down in the music room ",
               r" over in the music room ", r" situated in the music room ", r" whose berth is the music room, ",
               r" whose home is the music room, ", r"\(itself complete with the drums\)|\(itself with the drums\)",
               r"\(which, for the avoidance of doubt, is ", r" — itself [a-z ]+ the drums — ", r"the shelves \(found "
               r"empty\)", r"the empty shelves", r" as well as ", r", and furthermore, ", r"the open sofa",
               r" to be found "):
        assert any(re.search(rx, x) for x in texts), rx
    # never two relative clauses on end, and never two brackets on one noun
    assert not any(re.search(r"that somebody left switched on whose", x) for x in texts)
    assert not any(re.search(r"\(inventoried as [a-z ]+\) \(", x) for x in texts)


def test_plural_anchors_agree():
    t = Target("lamp", "lamp", (), (Relation("by", Target("drums", "drums", (), (
        Relation("near", Target("cactus", "cactus", (), (Relation("on", Target("shelves", "shelves")),))),))),))
    rng = np.random.default_rng(2)
    texts = {W.render_goal_w(rng, Subgoal(0, t)) for _ in range(100)}
    assert any("(themselves near the cactus, which in turn is " in x for x in texts), texts
    assert any("(which, for the avoidance of doubt, are near the cactus, which in turn is " in x for x in texts)
    assert not any("drums (itself" in x or "drums, which in turn is" in x for x in texts)


def test_a_phrase_of_another_shape_keeps_every_attribute():
    """A phrase that does not end on its head is written as given; attributes it lacks follow it."""
    t = Target("bean bag chair", "bean bag", ("teal", "corduroy", "bean"))
    rng = np.random.default_rng(11)
    plain = {W.render_goal_w(rng, Subgoal(0, t, room="nursery")) for _ in range(60)}
    for text in plain:
        assert re.match(r"the bean bag chair (of the teal and corduroy kind|\(inventoried as teal and corduroy\)) "
                        r"((down |over |situated )?in the|whose (berth|home) is the) nursery$", text), text
    assert W.render_goal_w(rng, Subgoal(0, Target("bean bag chair", "bean bag", ("bean",)))) == "the bean bag chair"


def test_deeper_anchors_hang_on_their_own_noun():
    """Below the first bracket an anchor's own relations follow ', which in turn is', so nothing nests a bracket."""
    inner = Target("drums", "drums", ("switched on",), (Relation("behind", Target("toolbox", "toolbox")),))
    t = Target("lamp", "lamp", (), (Relation("by", Target("sofa", "sofa", (), (Relation("near", inner),))),
                                    Relation("above", Target("mini-fridge", "mini-fridge"))))
    rng = np.random.default_rng(5)
    for _ in range(150):
        text = W.render_goal_w(rng, Subgoal(0, t, room="nursery"))
        assert max(_depths(text)) <= 1 and re.search(r"drums, which in turn are [a-z ]+ the toolbox", text), text
        check_goal(text, Subgoal(0, t, room="nursery"), W_REL_WORDS, "{}")
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "nursery", text


def test_every_relation_word_is_used_and_read():
    rng = np.random.default_rng(7)
    for rtype in W.REL_WORDS:
        sg = Subgoal(0, Target("lamp", "lamp", (), (Relation(rtype, Target("sofa", "sofa")),)))
        seen = set()
        for _ in range(120):
            text = W.render_goal_w(rng, sg)
            assert read_goal(text)[0]["relations"][0][0] == rtype, text
            seen.add(text[len("the lamp "): -len(" the sofa")].removeprefix("to be found "))
        assert seen == set(W_REL_WORDS[rtype]), rtype


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own

_DIGIT = {w: str(i) for i, w in enumerate(("nought", "one", "two", "three", "four", "five", "six", "seven", "eight",
                                           "nine"))}




def numbers_in(text: str) -> list[float]:
    """Every number: '-4', '−4', '.65', '0,65', '22,5', '65/100', 'minus 4', 'minus four', 'one hundred and five',
    'twenty-two and a half', '22 and a half', 'nought point six five', 'four degrees below zero'."""
    t = text.lower().replace("\u2212", "-").replace("℃", " c").replace("°c", " c")
    t = re.sub(r"(\d),(\d)", r"\1.\2", t)
    t = re.sub(r"\b(\d+)/100\b", lambda m: f"{int(m.group(1)) / 100:g}", t)
    t = t.replace("parts in the hundred", "pct")
    t = re.sub(r"\bnought point ((?:nought|one|two|three|four|five|six|seven|eight|nine)(?: (?:nought|one|two|three|"
               r"four|five|six|seven|eight|nine))*)\b",
               lambda m: "0." + "".join(_DIGIT[w] for w in m.group(1).split()), t)
    t = re.sub(r"\b(minus )?(\d+|[a-z]+(?:-[a-z]+)?) and a half\b",
               lambda m: f"{(-1 if m.group(1) else 1) * (word_number(m.group(2)) + 0.5):g}", t)
    t = re.sub(r"\b(\d+|[a-z]+(?:-[a-z]+)?) degrees? below zero\b", r"minus \1 degrees", t)
    return spoken_numbers(re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)*", t))


def comparator_of(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"hovers round|hovering round|in the region of|or thereabouts", "approx"),
                  (r"not more than|tops out at|topping out at|capped at", "le"),
                  (r"not less than|or upwards|at a minimum", "ge"),
                  (r"falls short of|falling short of|shy of|comes in under|coming in under", "lt"),
                  (r"\btops\b|\btopping\b|in excess of|runs past|running past", "gt")):
        if re.search(rx, t):
            return c
    return "?"


def reading_of(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|verdant|flourishing|perkiest|droopiest|wilted|ailing", t):
        return "ndvi"
    if re.search(r"humid|muggiest|clammiest|soggiest|parched|\barid\b|bone-dry|%|per centum|percent|parts in the", t):
        return "humidity_pct"
    if re.search(r"temperature|toastiest|sweltering|blistering|frostiest|nippiest|glacial|°|℃|deg c|degree|celsius",
                 t):
        return "temperature_c"
    return "?"


_LOW = r"frostiest|nippiest|glacial|droopiest|wilted|ailing|parched|\barid\b|bone-dry|props up|lower than all|lowest"
_UNIT_C = r"°c|℃|deg c|degree|celsius"
_UNIT_PCT = r"%|per centum|percent|parts in the hundred"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = W.render_sensor_w(np.random.default_rng(seed), c)
    check_sensor(rendered, c, comparator_of, _LOW, _UNIT_C, _UNIT_PCT, numbers_in, reading_of)
    text = (rendered[0] + " " + rendered[1]).strip()
    assert "(" not in text and "  " not in text, text
    if "below zero" in text:
        assert c.comparator == "approx" and rendered[2].value < 0 and rendered[2].unit == "c", text
        assert re.search(r"\b(\d+|[a-z]+(-[a-z]+)?) degrees? below zero\b", text) and "minus" not in text, text
    if not rendered[2].unit and not c.is_superlative:  # a unitless number always has its reading named
        assert re.search(r"^(where the (temperature|humidity|ndvi)|with an? (temperature|humidity|ndvi)) ",
                         text.lower()), text
    if c.reading == "ndvi":  # an NDVI is always named
        assert rendered[2].unit == "" and (c.is_superlative or not text.startswith("that ")), text


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase_after_the_head(c, sg, seed):
    check_sensor_goal(W.render_sensor_w, W.render_goal_w, c, sg, seed, numbers_in)


def _tidy_cut(s: str) -> str:
    return tidy_commas(s)


@SETTINGS
@given(c=constraints(), sg=subgoals(), x=st.floats(-20, 40).map(lambda v: round(v, 1)),
       y=st.floats(-20, 40).map(lambda v: round(v, 1)), seed=st.integers(0, 2**31))
def test_a_goal_with_sensor_and_hint_ends_on_the_coordinates(c, sg, x, y, seed):
    """The hint's numbers come last in the goal (after any number of the sensor phrase), and brackets never stack."""
    rng = np.random.default_rng(seed)
    prefix, tail, _ = W.render_sensor_w(rng, c)
    hint = W.hint_text_w(rng, f"{x:.1f}", f"{y:.1f}")
    text = W.render_goal_w(rng, sg, prefix=prefix, tail=tail, hint=hint)
    nums = numbers_in(text)
    assert nums[-2:] == [pytest.approx(x), pytest.approx(y)], text
    assert len(nums) == 2 + (not c.is_superlative), text
    assert ") (" not in text and max(_depths(text), default=0) <= 1 and text.count("(") == text.count(")"), text
    check_goal_layout(text, sg, W_REL_WORDS)
    # the reader still finds head, attributes, states and room once the sensor phrase and hint are cut out
    cut = text.replace(hint, " ")
    if tail:
        cut = cut.replace(tail, " ")
    if prefix:
        cut = cut.replace(f"the {prefix} ", "the ", 1)
    got, room = read_goal(_tidy_cut(cut))
    assert reading_norm(got) == target_truth(sg.target), (text, cut)
    assert room == sg.room, text


@SETTINGS
@given(v=st.integers(-30, -1).map(float) | st.sampled_from([-0.5, -2.5, -12.5]), cmp=st.sampled_from(("approx", "lt")),
       seed=st.integers(0, 2**31))
def test_temperatures_below_zero_keep_their_sign(v, cmp, seed):
    """'4 degrees below zero', 'minus 4', '−4', '-4', 'minus four', 'minus two and a half' all write a value below
    zero, in °C."""
    prefix, tail, written = W.render_sensor_w(np.random.default_rng(seed), SensorConstraint("temperature_c", cmp, v))
    assert not prefix and written == SensorConstraint("temperature_c", cmp, v, written.unit), tail
    assert numbers_in(tail) == [v] and comparator_of(tail) == cmp, tail
    assert written.unit == ("c" if re.search(_UNIT_C, tail.lower()) else ""), tail


def test_number_formats_frames_and_superlatives_vary():
    rng = np.random.default_rng(3)
    cold = {W.render_sensor_w(rng, SensorConstraint("temperature_c", "approx", -4.0))[1] for _ in range(400)}
    for rx in (r"minus four", r"minus 4\b", r"\b4 degrees below zero\b", r"\bfour degrees below zero\b",
               r"(?<![\w−])-4\b", r"−4\b", r"^that ", r"^where the temperature ", r"^with a temperature ", r"°C",
               r"\d °C", r"deg C", r"degrees C", r"℃", r"Celsius", r"hovers round", r"hovering round",
               r"in the region of", r"or thereabouts"):
        assert any(re.search(rx, t) for t in cold), rx
    assert all(numbers_in(t) == [-4.0] for t in cold)
    half = {W.render_sensor_w(rng, SensorConstraint("temperature_c", "lt", 22.5))[1] for _ in range(300)}
    for rx in (r"twenty-two and a half degrees", r"\b22 and a half degrees", r"22\.5", r"22,5"):
        assert any(re.search(rx, t) for t in half), rx
    assert all(numbers_in(t) == [22.5] for t in half)
    neg = {W.render_sensor_w(rng, SensorConstraint("temperature_c", "ge", -2.5))[1] for _ in range(300)}
    for rx in (r"minus two and a half", r"minus 2 and a half", r"(?<!\w)-2\.5", r"(?<!\w)-2,5"):
        assert any(re.search(rx, t) for t in neg), rx
    assert all(numbers_in(t) == [-2.5] for t in neg)
    hot = {W.render_sensor_w(rng, SensorConstraint("temperature_c", "gt", 105.0))[1] for _ in range(100)}
    assert any("one hundred and five" in t for t in hot) and all(numbers_in(t) == [105.0] for t in hot)
    damp = {W.render_sensor_w(rng, SensorConstraint("humidity_pct", "le", 40.0))[1] for _ in range(300)}
    for rx in (r"\d%", r"\d % RH", r"per centum", r"forty percent", r"parts in the hundred", r"forty",
               r"not more than", r"tops out at", r"topping out at", r"capped at"):
        assert any(re.search(rx, t) for t in damp), rx
    assert all(numbers_in(t) == [40.0] for t in damp)
    ndvi = {W.render_sensor_w(rng, SensorConstraint("ndvi", "gt", 0.65))[1] for _ in range(300)}
    for rx in (r"(?<![\d,])\.65\b", r"0\.65\b", r"0,65", r"\b65/100\b", r"nought point six five",
               r"^where the NDVI", r"^with an NDVI", r"\btops\b", r"in excess of", r"runs past", r"topping",
               r"running past"):
        assert any(re.search(rx, t) for t in ndvi), rx
    assert all(numbers_in(t) == [0.65] for t in ndvi)
    for v, words in ((0.6, "nought point six"), (0.05, "nought point nought five"), (0.05, "5/100")):
        got = {W.render_sensor_w(rng, SensorConstraint("ndvi", "le", v))[1] for _ in range(150)}
        assert any(t.endswith(words) for t in got) and all(numbers_in(t) == [v] for t in got), got
    for name, rd in (("humidity", "humidity_pct"), ("NDVI", "ndvi"), ("temperature", "temperature_c")):
        art = "an" if name == "NDVI" else "a"
        sup = {W.render_sensor_w(rng, SensorConstraint(rd, "max")) for _ in range(200)}
        assert {f"that tops the league for {name}", f"with {art} {name} second to none",
                f"whose {name} is the highest on record"} == {t for _, t, _ in sup if t}
        low = {W.render_sensor_w(rng, SensorConstraint(rd, "min")) for _ in range(200)}
        assert {f"that props up the league for {name}", f"with {art} {name} lower than all the rest",
                f"whose {name} is the lowest on record"} == {t for _, t, _ in low if t}
    adjectives = {p for rd in ("humidity_pct", "ndvi", "temperature_c") for cmp in ("max", "min")
                  for p, _, _ in (W.render_sensor_w(rng, SensorConstraint(rd, cmp)) for _ in range(60)) if p}
    assert adjectives == {"toastiest", "most sweltering", "most blistering", "frostiest", "nippiest", "most glacial",
                          "most verdant", "most flourishing", "perkiest", "droopiest", "most wilted", "most ailing",
                          "muggiest", "clammiest", "soggiest", "most parched", "most arid", "most bone-dry"}
    for cmp in ("gt", "ge", "lt", "le", "approx"):
        seen = {comparator_of(W.render_sensor_w(rng, SensorConstraint("temperature_c", cmp, 30.0))[1])
                for _ in range(60)}
        assert seen == {cmp}, (cmp, seen)


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(W.hint_text_w, W.render_goal_w, W.render_instruction_w, x, y, seed)


def _read_hint(hint: str) -> tuple[float, float]:
    """x then y from every form, by its own labels: '(x, y) = (a, b)', 'posn aE bN', 'a along and b up', 'an x of a
    and a y of b', 'easting a, northing b'."""
    n = r"(-?\d+(?:\.\d+)?)"
    for rx in (rf"the point \(x, y\) = \({n}, {n}\)", rf"posn {n}E {n}N", rf"at {n} along and {n} up",
               rf"an x of {n} and a y of {n}", rf"easting {n}, northing {n}"):
        if m := re.search(rx, hint):
            return float(m.group(1)), float(m.group(2))
    raise AssertionError(hint)


def test_every_coordinate_form_is_used_and_labels_x_and_y():
    rng = np.random.default_rng(4)
    hints = {W.hint_text_w(rng, "-3.5", "2.0") for _ in range(100)}
    assert hints == {"at the point (x, y) = (-3.5, 2.0)", "at posn -3.5E 2.0N", "at -3.5 along and 2.0 up",
                     "with an x of -3.5 and a y of 2.0", "at easting -3.5, northing 2.0"}
    assert {_read_hint(h) for h in hints} == {(-3.5, 2.0)}
    goal = W.render_goal_w(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(-3.5, 2.0)),
                           hint="at posn -3.5E 2.0N")
    assert goal == "the guitar at posn -3.5E 2.0N"


STRICT_CUES = r"in the order they're written|skip ahead and the whole thing curdles|no shuffling the steps about|" \
              r"one after the other, just like a soufflé|in the order logged|each only after the one above it|" \
              r"in the order given|none taken early|in the following sequence|" \
              r"no station shall be attended before every station preceding it|" \
              r"time is of the essence as to sequence|only upon completion of the attendance preceding it|" \
              r"touch by touch|every touch in its proper turn|in that sequence, pass after pass|" \
              r"the whole move breaks down"
FREE_CUES = r"any which way|whichever order suits you|it all comes together in the end|" \
            r"doesn't matter which you tackle first|comes out in the gravy|sequence at keeper's discretion|" \
            r"as tide and weather allow|sequence immaterial|whichever comes to hand first|no order laid down|" \
            r"in such order as the robot may in its sole discretion determine|" \
            r"no station shall take precedence over any other|in any sequence whatsoever|of no consequence|" \
            r"take your pick|any of them could go first|isn't fussed about the running order|" \
            r"pick them off however he likes|couldn't care less which comes first"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_stay_whole_in_order(sgs, seed, strict):
    check_order(W.render_goal_w, W.render_instruction_w, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [W.render_goal_w(rng, sg) for sg in sgs]
    low = W.render_instruction_w(rng, res, "strict" if strict else "free").lower()
    if strict:
        assert re.search(STRICT_CUES, low), low
    at = 0
    for r in res:
        at = low.find(r.lower(), at)
        assert at >= 0, (r, low)
        at += len(r)


def test_goals_with_relations_are_never_run_together_with_a_bare_and():
    """In a running list a goal that has words after its noun is closed off (', and also', or semicolons), so the
    next goal cannot be read as one more anchor."""
    res = ["the lamp next to the sofa", "the kiln", "the guitar"]
    for seed in range(200):
        text = W.render_instruction_w(np.random.default_rng(seed), res, "free")
        if "\n" not in text:
            assert "the sofa, the kiln, and also the guitar" in text, text


_OWN_HEADS = ("guitar", "harp", "kiln", "crib", "easel", "cello", "lectern", "jukebox")
_WORDS = {w: i for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight"))}
_TERMS = ("First", "Second", "Third", "Fourth", "Fifth", "Sixth", "Seventh")
_ROMANS = ("i", "ii", "iii", "iv", "v", "vi", "vii", "viii")


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
    text = W.render_instruction_w(np.random.default_rng(seed), res, "strict" if strict else "free")
    counted = r"(?:recipe in|following|–) (\w+) (steps|bits to get ready|stations to visit|premises|runners)\b"
    for m in re.finditer(counted, text):
        assert _WORDS[m.group(1)] == n, text
    lines = text.split("\n")
    goal_lines = [ln for ln in lines if re.search(r"\bthe (" + "|".join(_OWN_HEADS[:n]) + r")\b", ln)]
    if len(goal_lines) > 1:
        assert len(goal_lines) == n, text
        steps = [_WORDS[m.group(1)] for ln in goal_lines if (m := re.match(r"Step (\w+)[:,] ", ln))]
        if steps:
            assert steps == list(range(1, n + 1)) and goal_lines[-1].startswith(f"Step {_ref(n)}, to serve: "), text
        stamps = [int(m.group(1)) * 60 + int(m.group(2)) for ln in goal_lines if (m := re.match(r"(\d\d)(\d\d) ", ln))]
        if stamps:
            assert len(stamps) == n and stamps == sorted(set(stamps)) and stamps[-1] < 24 * 60, text
            assert re.match(r"\d{4} Rounds begin\. Make for ", goal_lines[0]), text
            assert goal_lines[-1].endswith(". Rounds complete."), text
        letters = [m.group(1) for ln in goal_lines if (m := re.match(r"\(([a-h])\) ", ln))]
        if letters:
            assert letters == list("abcdefgh"[:n]), text
            terms = [m.group(1) for ln in goal_lines if (m := re.search(r"the “(\w+) Station”", ln))]
            assert terms == [*_TERMS[: n - 1], "Final"], text
        romans = [m.group(1) for ln in goal_lines if (m := re.match(r"\(([ivx]+)\) ", ln))]
        if romans:
            assert romans == list(_ROMANS[:n]) and goal_lines[-1].endswith("."), text
        touches = [m.group(1) for ln in goal_lines if (m := re.match(r"(First touch|Touch number \w+|And the finish)", ln))]
        if touches:
            assert touches == ["First touch", *(f"Touch number {_ref(k)}" for k in range(2, n)), "And the finish"]
    at = 0
    for r in res:  # every goal once, in order, never run into the next word
        m = re.compile(re.escape(r) + r"(?![\w-])").search(text, at)
        assert m, (r, text)
        at = m.end()


def _ref(k: int) -> str:
    return next(w for w, i in _WORDS.items() if i == k)


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_and_keeps_the_goal(sg, seed):
    rng = np.random.default_rng(seed)
    goal = W.render_goal_w(rng, sg)
    text = W.render_instruction_w(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text), text
    assert not re.search(FREE_CUES, text.lower()) and not re.search(STRICT_CUES, text.lower()), text


def test_every_author_is_used_and_a_seed_repeats():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the guitar", "the kiln"]
    texts = [W.render_instruction_w(rng, res, order) for order in ("strict", "free") for _ in range(160)]
    for m in (r"lovely people|recipe|mise en place|baking|soufflé", r"keeper|log|watch|tide|make for",
              r"the robot shall|the robot may|station|premises", r"touch|he's|the gaffer|goal!|runners"):
        assert any(re.search(m, t.lower()) for t in texts), m
    for some, cues in ((texts[:160], STRICT_CUES), (texts[160:], FREE_CUES)):  # every cue of each order is written
        got = {c for t in some for c in re.findall(cues, t.lower())}
        assert got == set(cues.split("|")), set(cues.split("|")) - got
    assert any("\n" in t for t in texts) and any("\n" not in t for t in texts)
    assert len(set(texts)) > 60
    singles = [W.render_instruction_w(rng, res[:1], "strict") for _ in range(100)]
    for m in (r"just the one thing on today's menu|quickest recipe in the book", r"one duty only|single errand logged",
              r"upon no other premises|sole obligation", r"one-man show|just the one chance"):
        assert any(re.search(m, t.lower()) for t in singles), m
    again = [W.render_instruction_w(np.random.default_rng(9), res, "free") for _ in range(2)]
    assert again[0] == again[1]


def test_unseen_w_sensor_numbers_are_the_constraints():
    """The written number of a reading is the constraint's, in the goal's own text; a hint is x then y."""
    from test_heldout_sets import SMALL

    from ragnav_jax.config import load_config
    from ragnav_jax.language.episodes import generate_episodes
    from ragnav_jax.world.generator import generate_scene

    scene = generate_scene(load_config(None, SMALL).world, 5, 0)
    eps = generate_episodes([scene], load_config(None, [*SMALL, "episodes.split=unseen_w"]).episodes, seed=3)
    assert eps
    for p in eps:
        for sg in p.truth.subgoals:
            numbers = numbers_in(sg.text)
            for c in sg.sensors:
                if not c.is_superlative:
                    assert pytest.approx(c.value, abs=0.006) in numbers, sg.text
            if sg.location is not None:
                assert numbers[-2:] == [pytest.approx(sg.location.x), pytest.approx(sg.location.y)], sg.text
                assert _read_hint(sg.text) == (pytest.approx(sg.location.x), pytest.approx(sg.location.y)), sg.text
