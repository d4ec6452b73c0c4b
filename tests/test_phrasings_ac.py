"""The `unseen_ac` held-out templates (set AC): every piece of the ground truth is written down.

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
from test_phrasings_dev8 import HEADS, MODS, ROOMS, STATES, constraints, subgoals

from ragnav_jax.language import phrasings_ac as AC
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# The whole phrases a reader of AC's goals splits on, each with its relation type (written apart from the templates)
AC_REL_PHRASES = {
    "near": "near", "not far from": "near", "within reach of": "near", "a short hop from": "near",
    "next to": "next_to", "right alongside": "next_to", "snug against": "next_to", "hard up against": "next_to",
    "beside": "beside", "at the side of": "beside", "standing beside": "beside",
    "by": "by", "over by": "by", "just by": "by",
    "on": "on", "lying on": "on", "set upon": "on", "propped on": "on",
    "under": "under", "underneath": "under", "slung under": "under", "lurking under": "under",
    "above": "above", "high above": "above", "hung above": "above", "up above": "above",
    "in": "in", "inside": "in", "housed in": "in", "sitting inside": "in",
    "with": "with", "having": "with", "bearing": "with", "fitted with": "with",
    "in the same room as": "in_room_with", "in the room that also holds": "in_room_with",
    "in a room together with": "in_room_with",
    "in front of": "in_front_of", "right in front of": "in_front_of", "just in front of": "in_front_of",
    "out in front of": "in_front_of",
    "behind": "behind", "round the back of": "behind", "tucked behind": "behind", "in back of": "behind",
    "opposite": "opposite", "directly across from": "opposite", "straight across from": "opposite",
    "vis-a-vis": "opposite",
    "to the left of": "left_of", "just left of": "left_of", "off to the left of": "left_of",
    "to the right of": "right_of", "just right of": "right_of", "off to the right of": "right_of",
}
_BY_LENGTH = sorted(AC_REL_PHRASES, key=len, reverse=True)
AC_REL_WORDS: dict[str, tuple[str, ...]] = {}
for _p, _t in AC_REL_PHRASES.items():
    AC_REL_WORDS[_t] = (*AC_REL_WORDS.get(_t, ()), _p)
# after 'which' / 'that' an anchor's 'with' is written 'has' / 'have'
_WITH_VERB = {"has", "have"}

# ----------------------------------------------------------------------------------------------------
# A reader of AC's goals


def _depths(text: str) -> list[int]:
    """Per character, how many brackets, round or square, are open there (a bracket's own characters inside)."""
    out, d = [], 0
    for ch in text:
        if ch in "([":
            d += 1
        out.append(d)
        if ch in ")]":
            d -= 1
    return out


def _top(text: str, rx: str) -> re.Match | None:
    """The first match of rx outside every bracket."""
    depth = _depths(text)
    return next((m for m in re.finditer(rx, text) if depth[m.start()] == 0), None)


def _relations_at_top(text: str) -> list[tuple[int, int, str]]:
    """(start, end, type) of every relation phrase outside brackets, followed by 'the' (longest phrase first)."""
    depth, out, i = _depths(text), [], 0
    while i < len(text):
        if depth[i] == 0 and (i == 0 or text[i - 1] == " "):
            for p in _BY_LENGTH:
                if text.startswith(p + " the ", i):
                    out.append((i, i + len(p), AC_REL_PHRASES[p]))
                    i += len(p)
                    break
        i += 1
    return out


_JOIN_AT_END = re.compile(r"(?:, plus| and also| and)\s*$")


def _read_chain(text: str) -> list[tuple[str, dict]]:
    """'next to the sofa (the one with the drums) and also under the shelves that are by the kiln'."""
    at = _top(text, r" that (?:is|are|has|have) ")
    if at is not None:  # a relative clause hangs the rest of the text on the anchor before it
        chain = _read_chain(text[: at.start()])
        chain[-1][1]["relations"] += _read_preds(text[at.start() + len(" that "):])
        return chain
    rels = _relations_at_top(text)
    assert rels and text[: rels[0][0]].strip() == "", text
    out = []
    for k, (_, end, rtype) in enumerate(rels):
        stop = rels[k + 1][0] if k + 1 < len(rels) else len(text)
        seg = _JOIN_AT_END.sub("", text[end:stop].strip())
        out.append((rtype, _read_np(seg.strip().rstrip(","))))
    return out


def _read_preds(text: str) -> list[tuple[str, dict]]:
    """'is next to the drums and also has the kiln', 'are lying on the shelves [that is by the sofa] plus ...'."""
    at = _top(text, r" that (?:is|are|has|have) ")
    if at is not None:
        preds = _read_preds(text[: at.start()])
        preds[-1][1]["relations"] += _read_preds(text[at.start() + len(" that "):])
        return preds
    depth, starts, i = _depths(text), [], 0
    while i < len(text):
        if depth[i] == 0 and (i == 0 or text[i - 1] == " "):
            if m := re.match(r"(has|have) the ", text[i:]):
                starts.append((i, i + len(m.group(1)), "with"))
                i += len(m.group(1))
            elif m := re.match(r"(?:is|are) ", text[i:]):
                p = next(p for p in _BY_LENGTH if text.startswith(p + " the ", i + m.end()))
                starts.append((i, i + m.end() + len(p), AC_REL_PHRASES[p]))
                i += m.end() + len(p)
        i += 1
    assert starts and starts[0][0] == 0, text
    out = []
    for k, (_, end, rtype) in enumerate(starts):
        stop = starts[k + 1][0] if k + 1 < len(starts) else len(text)
        seg = _JOIN_AT_END.sub("", text[end:stop].strip())
        out.append((rtype, _read_np(seg.strip().rstrip(","))))
    return out


def _read_np(seg: str) -> dict:
    """'the switched-on teal lamp (the one next to the sofa)', 'the lamp (tagged teal & wool), currently open', 'the
    lamp described as teal and wool which is switched on', 'the shelves (empty at last look)', 'the sofa (which has
    the drums)', 'the sofa [that is by the door]'."""
    got = {"attrs": [], "after": [], "states": [], "relations": []}
    depth, plain, i = _depths(seg), "", 0
    while i < len(seg):
        if seg[i] in "([" and depth[i] == 1:
            close = ")" if seg[i] == "(" else "]"
            j = i
            while not (seg[j] == close and depth[j] == 1):
                j += 1
            body = seg[i + 1 : j]
            if close == "]":
                m = re.fullmatch(r"that (.+)", body)
                assert m, (body, seg)
                got["relations"] += _read_preds(m.group(1))
            elif m := re.fullmatch(r"the ones? (.+)", body):
                got["relations"] += _read_chain(m.group(1))
            elif m := re.fullmatch(r"which (.+)", body):
                got["relations"] += _read_preds(m.group(1))
            elif m := re.fullmatch(r"(.+) at last look", body):
                got["states"] += m.group(1).split(" and ")
            elif m := re.fullmatch(r"tagged (.+)", body):
                got["after"] += m.group(1).split(" & ")
            else:
                raise AssertionError(f"unknown bracket {body!r} in {seg!r}")
            i = j + 1
            continue
        plain += seg[i]
        i += 1
    parts = [p.strip() for p in plain.split(",") if p.strip()]
    for p in parts[1:]:
        m = re.fullmatch(r"currently (.+)", p)
        assert m, (p, seg)
        got["states"] += m.group(1).split(" and ")
    words = " ".join(parts[0].split())
    if m := re.search(r" which (?:is|are) (.+)$", words):
        got["states"] += m.group(1).split(" and ")
        words = words[: m.start()]
    if m := re.search(r" described as (.+)$", words):
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


_ROOM_NAMES = "|".join(sorted(ROOMS, key=len, reverse=True))
_ROOM_RX = re.compile(r"(?:, )?(?:\(room: (" + _ROOM_NAMES + r")\)|\b(?:(?:through |out )?in the|that lives? in the) ("
                      + _ROOM_NAMES + r")\b),?")
_IE = re.compile(r",? i\.e\. the ones? $")


def read_goal(text: str) -> tuple[dict, str | None]:
    room = None
    m = _ROOM_RX.search(text)
    if m:
        room = m.group(1) or m.group(2)
        text = text[: m.start()] + " , " + text[m.end():]  # keep the break the room's commas made
    text = tidy_commas(text)
    rels = _relations_at_top(text)
    main = text[: rels[0][0]] if rels else text
    main = _IE.sub("", main)
    got = _read_np(tidy_commas(main))
    if rels:
        got["relations"] += _read_chain(text[rels[0][0]:])
    return got, room


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece_and_reads_back_exactly(sg, seed):
    text = AC.render_goal_ac(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, AC_REL_WORDS | {"with": AC_REL_WORDS["with"] + ("has", "have")})
    assert ") (" not in text and "](" not in text, text
    got, room = read_goal(text)
    assert reading_norm(got) == target_truth(sg.target), text
    assert room == sg.room, text


def test_nested_goal_and_every_attribute_state_and_room_form():
    t = Target("teal wool lamp", "lamp", ("teal", "wool", "switched on"), (
        Relation("next_to", Target("sofa", "sofa", ("open",), (Relation("with", Target("drums", "drums")),))),
        Relation("under", Target("shelves", "shelves", ("empty",)))))
    rng = np.random.default_rng(0)
    texts = [AC.render_goal_ac(rng, Subgoal(0, t, room="music room")) for _ in range(400)]
    for text in texts:
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "music room", text
        assert text.index("music room") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
    for rx in (r"^the teal wool lamp", r"^the lamp described as teal and wool", r"^the lamp \(tagged teal & wool\)",
               r"^the switched-on teal wool lamp", r" which is switched on, ", r", currently switched on,",
               r"\(switched on at last look\)", r" in the music room, ", r" through in the music room, ",
               r" out in the music room, ", r" that lives in the music room, ", r" \(room: music room\) ",
               r"\(the one (?:with|having|bearing|fitted with) the drums\)", r"\(which has the drums\)",
               r"the shelves \(empty at last look\)", r"the empty shelves", r" and also ", r", plus ",
               r"the open sofa", r", i\.e\. the one "):
        assert any(re.search(rx, x) for x in texts), rx
    # never two relative clauses on end, and never two brackets on one noun
    assert not any(re.search(r"(which is switched on|described as teal and wool),? that lives", x) for x in texts)
    assert all(re.search(r"described as teal and wool(,| \(|$)", x) for x in texts if "described" in x)
    assert not any(re.search(r"\(tagged [a-z &-]+\) \(", x) for x in texts)


def test_last_anchor_takes_a_relative_clause_and_plurals_agree():
    t = Target("lamp", "lamp", (), (Relation("by", Target("drums", "drums", (), (
        Relation("near", Target("cactus", "cactus", (), (Relation("on", Target("shelves", "shelves")),))),))),))
    rng = np.random.default_rng(2)
    texts = {AC.render_goal_ac(rng, Subgoal(0, t)) for _ in range(150)}
    for text in texts:
        assert reading_norm(read_goal(text)[0]) == target_truth(t), text
    assert any(re.search(r"the drums that are [a-z -]+ the cactus that is [a-z ]+ the shelves$", x) for x in texts)
    assert any(re.search(r"the drums \(the ones [a-z -]+ the cactus that is ", x) for x in texts)
    assert any(re.search(r"the drums \(which are [a-z -]+ the cactus that is ", x) for x in texts)
    assert not any(re.search(r"drums (?:that|\(which) is|cactus that are", x) for x in texts)
    have = Target("lamp", "lamp", (), (Relation("by", Target("drums", "drums", (), (
        Relation("with", Target("cactus", "cactus")),))),))
    texts = {AC.render_goal_ac(rng, Subgoal(0, have)) for _ in range(60)}
    assert any("the drums that have the cactus" in x for x in texts) and not any(" has the cactus" in x for x in texts)
    assert all(reading_norm(read_goal(x)[0]) == target_truth(have) for x in texts)


def test_a_relative_clause_only_closes_the_last_relation():
    """An anchor with relations of its own keeps them in a bracket while more of the goal follows."""
    sofa = Target("sofa", "sofa", (), (Relation("with", Target("drums", "drums")),))
    t = Target("lamp", "lamp", (), (Relation("by", sofa), Relation("above", Target("mini-fridge", "mini-fridge"))))
    rng = np.random.default_rng(5)
    for _ in range(150):
        text = AC.render_goal_ac(rng, Subgoal(0, t, room="nursery"))
        assert re.search(r"sofa \((the one|which) ", text), text
        check_goal(text, Subgoal(0, t, room="nursery"), AC_REL_WORDS | {"with": ("has",) + AC_REL_WORDS["with"]}, "{}")
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "nursery", text


def test_deeper_anchors_with_more_following_go_in_square_brackets():
    inner = Target("drums", "drums", ("switched on",), (Relation("behind", Target("toolbox", "toolbox")),))
    t = Target("lamp", "lamp", (), (Relation("by", Target("sofa", "sofa", (), (
        Relation("near", inner), Relation("on", Target("shelves", "shelves"))))),))
    rng = np.random.default_rng(6)
    texts = {AC.render_goal_ac(rng, Subgoal(0, t)) for _ in range(100)}
    for text in texts:
        assert re.search(r"drums \[that are [a-z ]+ the toolbox\]", text), text
        assert reading_norm(read_goal(text)[0]) == target_truth(t), text


def test_a_phrase_of_another_shape_keeps_every_attribute():
    """A phrase that does not end on its head is written as given; attributes it lacks follow it."""
    t = Target("bean bag chair", "bean bag", ("teal", "corduroy", "bean"))
    rng = np.random.default_rng(11)
    plain = {AC.render_goal_ac(rng, Subgoal(0, t, room="nursery")) for _ in range(60)}
    for text in plain:
        assert re.match(r"the bean bag chair (described as teal and corduroy(, (through |out )?in the nursery| \(room: "
                        r"nursery\))|\(tagged teal & corduroy\) ((through |out )?in the nursery|that lives in the "
                        r"nursery))$", text), text
    assert AC.render_goal_ac(rng, Subgoal(0, Target("bean bag chair", "bean bag", ("bean",)))) == "the bean bag chair"


def test_every_relation_word_is_used_and_read():
    rng = np.random.default_rng(7)
    for rtype in AC.REL_WORDS:
        sg = Subgoal(0, Target("lamp", "lamp", (), (Relation(rtype, Target("sofa", "sofa")),)))
        seen = set()
        for _ in range(120):
            text = AC.render_goal_ac(rng, sg)
            assert read_goal(text)[0]["relations"][0][0] == rtype, text
            seen.add(re.sub(r"^the lamp(, i\.e\. the one)? ", "", text)[: -len(" the sofa")])
        assert seen == set(AC_REL_WORDS[rtype]), rtype


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own

_DIGIT = {w: str(i) for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight",
                                           "nine"))}
_DIGIT_RUN = r"(?:zero|one|two|three|four|five|six|seven|eight|nine)(?: (?:zero|one|two|three|four|five|six|seven|" \
             r"eight|nine))*"
_UNITS = "zero|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|thirteen|fourteen|fifteen|sixteen|" \
         "seventeen|eighteen|nineteen"
_NUMWORD = rf"(?:(?:twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety)(?:-(?:{_UNITS}))?|{_UNITS})"
_SPOKEN = rf"(?:\d+|{_NUMWORD}(?: hundred(?: and {_NUMWORD})?)?)"


def _whole(words: str) -> float:
    got = spoken_numbers(words.split())
    assert len(got) == 1, words
    return got[0]


_THE_ONE = re.compile(r"\bthe ones? (?=(?:" + "|".join(map(re.escape, _BY_LENGTH)) + r") the )")


def _point(m: re.Match) -> str:
    """'thirty-seven point five' -> '37.5', 'point six five' -> '0.65'."""
    whole = _whole(m.group(1)) if m.group(1) else 0
    return f"{whole + float('0.' + ''.join(_DIGIT[w] for w in m.group(2).split())):g}"


def numbers_in(text: str) -> list[float]:
    """Every number: '-4', '22½', '-2½', '.65', '65 hundredths', 'six tenths', 'minus 4', 'negative four', 'one
    hundred and five', 'twenty-two point five', 'point six five', 'zero point six five' ('the one' is no number)."""
    t = text.lower().replace("°c", " c").replace("½", ".5")
    t = _THE_ONE.sub("the ", t)
    t = re.sub(r"\bnegative\b", "minus", t)
    t = re.sub(r"\b(\d+|[a-z]+(?:-[a-z]+)?) (hundredths|tenths)\b",
               lambda m: f"{word_number(m.group(1)) / (100 if m.group(2) == 'hundredths' else 10):g}", t)
    t = re.sub(rf"\b(?:({_SPOKEN}) )?point ({_DIGIT_RUN})\b", _point, t)
    return spoken_numbers(re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)*", t))


def comparator_of(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"\bor so\b|in the ballpark of|close on|circa", "approx"),
                  (r"no higher than|or below|maxes out at|maxing out at|doesn't go over|not going over", "le"),
                  (r"no lower than|or above|or more", "ge"),
                  (r"beneath|doesn't reach|not reaching|under the .+ mark", "lt"),
                  (r"clears|clearing|beats|beating|beyond|over the .+ mark", "gt")):
        if re.search(rx, t):
            return c
    return "?"


def reading_of(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|vegetation|lushest|thriving|vigorous|sickliest|withered|feeblest", t):
        return "ndvi"
    if re.search(r"humid|dankest|sodden|moistest|desiccated|muggy|damp|%|per ?cent|\bpc\b", t):
        return "humidity_pct"
    if re.search(r"temp|balmiest|scorching|roasting|chilliest|iciest|frigid|°|centigrade|celsius|degree|[\d½]c\b", t):
        return "temperature_c"
    return "?"


_LOW = r"chilliest|iciest|frigid|sickliest|withered|feeblest|desiccated|least muggy|least damp|bottom|undercuts|" \
       r"lowest"
_UNIT_C = r"°c|centigrade|celsius|degree|[\d½]c\b"
_UNIT_PCT = r"%|per ?cent|\bpc\b"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = AC.render_sensor_ac(np.random.default_rng(seed), c)
    check_sensor(rendered, c, comparator_of, _LOW, _UNIT_C, _UNIT_PCT, numbers_in, reading_of)
    text = (rendered[0] + " " + rendered[1]).strip()
    assert "(" not in text and "  " not in text, text
    if not rendered[2].unit and not c.is_superlative:  # a unitless number always has its reading named
        assert re.search(r"^(with its|whose|with an? [a-z ]+ reading) ", text.lower()), text
    if c.reading == "ndvi":  # an NDVI is always named
        assert rendered[2].unit == "" and (c.is_superlative or not text.startswith("that ")), text


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase_after_the_head(c, sg, seed):
    check_sensor_goal(AC.render_sensor_ac, AC.render_goal_ac, c, sg, seed, numbers_in)


@SETTINGS
@given(c=constraints(), sg=subgoals(), x=st.floats(-20, 40).map(lambda v: round(v, 1)),
       y=st.floats(-20, 40).map(lambda v: round(v, 1)), seed=st.integers(0, 2**31))
def test_a_goal_with_sensor_and_hint_ends_on_the_coordinates(c, sg, x, y, seed):
    """The hint's numbers come last in the goal (after any number of the sensor phrase)."""
    rng = np.random.default_rng(seed)
    prefix, tail, _ = AC.render_sensor_ac(rng, c)
    hint = AC.hint_text_ac(rng, f"{x:.1f}", f"{y:.1f}")
    text = AC.render_goal_ac(rng, sg, prefix=prefix, tail=tail, hint=hint)
    nums = numbers_in(text)
    assert nums[-2:] == [pytest.approx(x), pytest.approx(y)], text
    assert len(nums) == 2 + (not c.is_superlative), text
    assert ") (" not in text and text.count("(") == text.count(")"), text
    check_goal_layout(text, sg, AC_REL_WORDS | {"with": AC_REL_WORDS["with"] + ("has", "have")})
    # the reader still finds head, attributes, states and room once the sensor phrase and hint are cut out
    cut = text.replace(hint, " ")
    if tail:
        cut = cut.replace(tail, " ")
    if prefix:
        cut = cut.replace(f"the {prefix} ", "the ", 1)
    got, room = read_goal(tidy_commas(cut))
    assert reading_norm(got) == target_truth(sg.target), (text, cut)
    assert room == sg.room, text


@SETTINGS
@given(v=st.integers(-30, -1).map(float) | st.sampled_from([-0.5, -2.5, -12.5]), cmp=st.sampled_from(("approx", "lt")),
       seed=st.integers(0, 2**31))
def test_temperatures_below_zero_keep_their_sign(v, cmp, seed):
    """'-4', 'minus 4', 'negative 4', 'minus four', 'negative two point five', '-2½' all write a value below zero."""
    prefix, tail, written = AC.render_sensor_ac(np.random.default_rng(seed), SensorConstraint("temperature_c", cmp, v))
    assert not prefix and written == SensorConstraint("temperature_c", cmp, v, written.unit), tail
    assert numbers_in(tail) == [v] and comparator_of(tail) == cmp, tail
    assert written.unit == ("c" if re.search(_UNIT_C, tail.lower()) else ""), tail


def test_number_formats_frames_and_superlatives_vary():
    rng = np.random.default_rng(3)
    cold = {AC.render_sensor_ac(rng, SensorConstraint("temperature_c", "approx", -4.0))[1] for _ in range(400)}
    for rx in (r"minus four", r"negative four", r"minus 4\b", r"negative 4\b", r"(?<!\w)-4\b", r"^that ",
               r"^with its temperature ", r"^with its temp ", r"^whose temperature reading ", r"^with a temp reading ",
               r"\d°C", r"\d °C", r"\dC\b", r" centigrade", r"degrees centigrade", r"degrees Celsius", r"\bor so\b",
               r"in the ballpark of", r"close on", r"circa"):
        assert any(re.search(rx, t) for t in cold), rx
    assert all(numbers_in(t) == [-4.0] for t in cold)
    half = {AC.render_sensor_ac(rng, SensorConstraint("temperature_c", "lt", 22.5))[1] for _ in range(300)}
    for rx in (r"twenty-two point five degrees", r"\b22½", r"22\.5", r"beneath", r"doesn't reach", r"not reaching",
               r"under the .+ mark"):
        assert any(re.search(rx, t) for t in half), rx
    assert all(numbers_in(t) == [22.5] for t in half)
    neg = {AC.render_sensor_ac(rng, SensorConstraint("temperature_c", "ge", -2.5))[1] for _ in range(300)}
    for rx in (r"minus two point five", r"negative two point five", r"(?<!\w)-2½", r"minus 2½", r"(?<!\w)-2\.5"):
        assert any(re.search(rx, t) for t in neg), rx
    assert all(numbers_in(t) == [-2.5] for t in neg)
    hot = {AC.render_sensor_ac(rng, SensorConstraint("temperature_c", "gt", 105.0))[1] for _ in range(100)}
    assert any("one hundred and five" in t for t in hot) and all(numbers_in(t) == [105.0] for t in hot)
    damp = {AC.render_sensor_ac(rng, SensorConstraint("humidity_pct", "le", 40.0))[1] for _ in range(300)}
    for rx in (r"\d%", r"\d per cent", r"\d percent", r"\d pc\b", r"forty per cent", r"forty percent",
               r"relative humidity", r"no higher than", r"or below", r"maxes out at", r"maxing out at",
               r"doesn't go over", r"not going over"):
        assert any(re.search(rx, t) for t in damp), rx
    assert all(numbers_in(t) == [40.0] for t in damp)
    ndvi = {AC.render_sensor_ac(rng, SensorConstraint("ndvi", "gt", 0.65))[1] for _ in range(300)}
    for rx in (r"(?<![\d])\.65\b", r"0\.65\b", r"\b65 hundredths", r"sixty-five hundredths", r"zero point six five",
               r"(?<!zero )point six five", r"^whose NDVI reading", r"^with its vegetation index",
               r"^with an NDVI reading",
               r"clears", r"beats", r"goes beyond", r"over the .+ mark", r"clearing", r"beating", r"beyond"):
        assert any(re.search(rx, t) for t in ndvi), rx
    assert all(numbers_in(t) == [0.65] for t in ndvi)
    for v, words in ((0.6, "six tenths"), (0.05, "zero point zero five"), (0.05, "5 hundredths")):
        got = {AC.render_sensor_ac(rng, SensorConstraint("ndvi", "le", v))[1] for _ in range(150)}
        assert any(words in t for t in got) and all(numbers_in(t) == [v] for t in got), got
    for names, rd in ((("humidity", "relative humidity"), "humidity_pct"), (("NDVI", "vegetation index"), "ndvi"),
                      (("temperature", "temp"), "temperature_c")):
        sup = {AC.render_sensor_ac(rng, SensorConstraint(rd, "max")) for _ in range(300)}
        assert {form.format(n) for n in names for form in ("with the top {} reading", "whose {} beats every other",
                                                            "that reads highest for {}")} == {t for _, t, _ in sup if t}
        low = {AC.render_sensor_ac(rng, SensorConstraint(rd, "min")) for _ in range(300)}
        assert {form.format(n) for n in names for form in ("with the bottom {} reading",
                                                            "whose {} undercuts every other",
                                                            "that reads lowest for {}")} == {t for _, t, _ in low if t}
    adjectives = {p for rd in ("humidity_pct", "ndvi", "temperature_c") for cmp in ("max", "min")
                  for p, _, _ in (AC.render_sensor_ac(rng, SensorConstraint(rd, cmp)) for _ in range(60)) if p}
    assert adjectives == {"balmiest", "most scorching", "most roasting", "chilliest", "iciest", "most frigid",
                          "lushest", "most thriving", "most vigorous", "sickliest", "most withered", "feeblest",
                          "dankest", "most sodden", "moistest", "most desiccated", "least muggy", "least damp"}
    for cmp in ("gt", "ge", "lt", "le", "approx"):
        seen = {comparator_of(AC.render_sensor_ac(rng, SensorConstraint("temperature_c", cmp, 30.0))[1])
                for _ in range(60)}
        assert seen == {cmp}, (cmp, seen)


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(AC.hint_text_ac, AC.render_goal_ac, AC.render_instruction_ac, x, y, seed)


def _read_hint(hint: str) -> tuple[float, float]:
    """x then y from every form, by its own labels or layout: 'map ref a/b', 'x reads a and y reads b', 'a m east
    and b m north', 'the pin [a | b]', 'x a / y b'."""
    n = r"(-?\d+(?:\.\d+)?)"
    for rx in (rf"map ref {n}/{n}", rf"where x reads {n} and y reads {n}", rf"{n} m east and {n} m north",
               rf"the pin \[{n} \| {n}\]", rf"the spot marked x {n} / y {n}"):
        if m := re.search(rx, hint):
            return float(m.group(1)), float(m.group(2))
    raise AssertionError(hint)


def test_every_coordinate_form_is_used_and_labels_x_and_y():
    rng = np.random.default_rng(4)
    hints = {AC.hint_text_ac(rng, "-3.5", "2.0") for _ in range(100)}
    assert hints == {"at map ref -3.5/2.0", "where x reads -3.5 and y reads 2.0",
                     "at a point -3.5 m east and 2.0 m north of the origin", "at the pin [-3.5 | 2.0]",
                     "at the spot marked x -3.5 / y 2.0"}
    assert {_read_hint(h) for h in hints} == {(-3.5, 2.0)}
    goal = AC.render_goal_ac(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(-3.5, 2.0)),
                             hint="at map ref -3.5/2.0")
    assert goal == "the guitar at map ref -3.5/2.0"


STRICT_CUES = r"objectives, in sequence|in the order listed|do not advance until the previous obj is secured|" \
              r"in that order – no skipping, no freelancing|in this order and no other|" \
              r"nor seek the latter ere the former be done|each in its turn, and none before its time|" \
              r"then, and only then|the route never varies|each stop must come before the next|" \
              r"always in this order|there is no skipping ahead|ride 'em in that order|" \
              r"don't go jumpin' ahead of the herd|in that order, mind|no cuttin' corners"
FREE_CUES = r"order of attack at your discretion|in any order you see fit|i don't care which you hit first|" \
            r"in what order thou wilt|'tis all one to me which thou seekest first|as it please thee|" \
            r"matters not a whit|it seems not to matter in the slightest|as the fancy takes it|" \
            r"in no particular order|in whatever order it pleases|in whatever order suits ya|" \
            r"don't matter none which one ya hit first|ain't no never-mind which ya do first"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_stay_whole_in_order(sgs, seed, strict):
    check_order(AC.render_goal_ac, AC.render_instruction_ac, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [AC.render_goal_ac(rng, sg) for sg in sgs]
    low = AC.render_instruction_ac(rng, res, "strict" if strict else "free").lower()
    if strict:
        assert re.search(STRICT_CUES, low), low
    at = 0
    for r in res:
        at = low.find(r.lower(), at)
        assert at >= 0, (r, low)
        at += len(r)


def test_goals_with_words_after_the_noun_are_kept_apart_in_a_running_list():
    """In a running list a goal that has words after its noun is closed off by semicolons, so the next goal cannot
    be read as one more anchor; bare goals take commas."""
    res = ["the lamp next to the sofa", "the kiln", "the guitar"]
    for seed in range(200):
        text = AC.render_instruction_ac(np.random.default_rng(seed), res, "free")
        if "\n" not in text:
            assert "the sofa; the kiln; and the guitar" in text, text
        two = AC.render_instruction_ac(np.random.default_rng(seed), res[:2], "free")
        if "\n" not in two:
            assert "the sofa; and also the kiln" in two, two
        bare = AC.render_instruction_ac(np.random.default_rng(seed), res[1:], "free")
        if "\n" not in bare:
            assert "the kiln and the guitar" in bare, bare


_OWN_HEADS = ("guitar", "harp", "kiln", "crib", "easel", "cello", "lectern", "jukebox")
_WORDS = {w: i for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight"))}
_NATO = ("ALPHA", "BRAVO", "CHARLIE", "DELTA", "ECHO", "FOXTROT", "GOLF", "HOTEL")


@SETTINGS
@given(n=st.integers(2, 8), seed=st.integers(0, 2**31), strict=st.booleans())
def test_counts_and_labels_agree_with_the_goals(n, seed, strict):
    _check_counts(n, seed, strict)


def test_counts_agree_over_a_sweep_of_seeds():
    for n in range(2, 9):
        for seed in range(40):
            _check_counts(n, seed, seed % 2 == 0)


def _check_counts(n: int, seed: int, strict: bool) -> None:
    res = [f"the {h}" for h in _OWN_HEADS[:n]]
    text = AC.render_instruction_ac(np.random.default_rng(seed), res, "strict" if strict else "free")
    counted = r"(?:secure|here be|in|has|–) (\w+) (objectives|places|stages|spots)\b|^(\w+) objectives, order"
    for m in re.finditer(counted, text, flags=re.M | re.I):
        assert _WORDS[(m.group(1) or m.group(3)).lower()] == n, text
    goal_lines = [ln for ln in text.split("\n") if re.search(r"\bthe (" + "|".join(_OWN_HEADS[:n]) + r")\b", ln)]
    if len(goal_lines) > 1:
        assert len(goal_lines) == n, text
        objs = [m.group(1) for ln in goal_lines if (m := re.match(r"OBJ (\w+) – ", ln))]
        if objs:
            assert objs == list(_NATO[:n]), text
        if goal_lines[0].startswith("First, hie thee unto "):
            assert goal_lines[-1].startswith("And last of all, unto ") and goal_lines[-1].endswith("."), text
            assert all(ln.endswith(";") for ln in goal_lines[:-1]), text
        if goal_lines[0].startswith("— first, "):
            assert goal_lines[-1].startswith("— and finally, ") and all(ln.startswith("— then ")
                                                                        for ln in goal_lines[1:-1]), text
        if goal_lines[0].startswith("First stop – "):
            assert goal_lines[-1].startswith("Last stop, end o' the trail – "), text
            assert all(ln.startswith("Next stop – ") for ln in goal_lines[1:-1]), text
    at = 0
    for r in res:  # every goal once, in order, never run into the next word
        m = re.compile(re.escape(r) + r"(?![\w-])").search(text, at)
        assert m, (r, text)
        at = m.end()


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_and_keeps_the_goal(sg, seed):
    rng = np.random.default_rng(seed)
    goal = AC.render_goal_ac(rng, sg)
    text = AC.render_instruction_ac(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text), text
    assert not re.search(FREE_CUES, text.lower()) and not re.search(STRICT_CUES, text.lower()), text


def test_every_author_is_used_and_a_seed_repeats():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the guitar", "the lamp next to the sofa", "the kiln"]
    texts = [AC.render_instruction_ac(rng, res, order) for order in ("strict", "free") for _ in range(160)]
    for m in (r"operation|\bobj\b|soldier|maggot|tin can", r"thee|thou|prithee|hark|'tis",
              r"the robot|…|journey|foraging", r"partner|y'hear|mosey|reckon|ya\b"):
        assert any(re.search(m, t.lower()) for t in texts), m
    for some, cues in ((texts[:160], STRICT_CUES), (texts[160:], FREE_CUES)):  # every cue of each order is written
        got = {c for t in some for c in re.findall(cues, t.lower())}
        assert got == set(cues.split("|")), set(cues.split("|")) - got
    assert any("\n" in t for t in texts) and any("\n" not in t for t in texts)
    assert len(set(texts)) > 40
    singles = [AC.render_instruction_ac(rng, res[:1], "strict") for _ in range(100)]
    for m in (r"single objective, soldier|your mission today is", r"one errand only|away, good engine",
              r"single destination|but one goal", r"just the one job today|only errand on the trail"):
        assert any(re.search(m, t.lower()) for t in singles), m
    again = [AC.render_instruction_ac(np.random.default_rng(9), res, "free") for _ in range(2)]
    assert again[0] == again[1]
    assert len({AC.render_instruction_ac(np.random.default_rng(s), res, "free") for s in range(20)}) > 5


def test_unseen_ac_sensor_numbers_are_the_constraints():
    """The written number of a reading is the constraint's, in the goal's own text; a hint is x then y."""
    from test_heldout_sets import SMALL

    from ragnav_jax.config import load_config
    from ragnav_jax.language.episodes import generate_episodes
    from ragnav_jax.world.generator import generate_scene

    scene = generate_scene(load_config(None, SMALL).world, 5, 0)
    eps = generate_episodes([scene], load_config(None, [*SMALL, "episodes.split=unseen_ac"]).episodes, seed=3)
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
