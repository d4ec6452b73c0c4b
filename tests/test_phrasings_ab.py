"""The `unseen_ab` held-out templates (set AB): every piece of the ground truth is written down.

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

from ragnav_jax.language import phrasings_ab as AB
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# The whole phrases a reader of AB's goals splits on, each with its relation type (written apart from the templates)
AB_REL_PHRASES = {
    "near": "near", "not far from": "near", "a short hop from": "near", "within easy reach of": "near",
    "next to": "next_to", "snug up against": "next_to", "immediately adjoining": "next_to",
    "rubbing elbows with": "next_to",
    "beside": "beside", "at the side of": "beside", "pulled up beside": "beside", "set down beside": "beside",
    "by": "by", "right by": "by", "close by": "by", "stood by": "by",
    "on": "on", "sitting up on": "on", "balanced on": "on", "laid on": "on",
    "under": "under", "underneath": "under", "lurking beneath": "under", "slid under": "under",
    "above": "above", "suspended above": "above", "hanging over": "above", "high above": "above",
    "in": "in", "inside": "in", "packed inside": "in", "held within": "in",
    "with": "with", "carrying": "with", "kitted out with": "with", "bearing": "with",
    "in the same room as": "in_room_with", "under the same ceiling as": "in_room_with",
    "in the room that also holds": "in_room_with",
    "in front of": "in_front_of", "out in front of": "in_front_of", "to the fore of": "in_front_of",
    "behind": "behind", "round the back of": "behind", "hidden behind": "behind", "in back of": "behind",
    "opposite": "opposite", "directly across from": "opposite", "staring across at": "opposite",
    "to the left of": "left_of", "off to the left of": "left_of", "leftward of": "left_of",
    "to the right of": "right_of", "off to the right of": "right_of", "rightward of": "right_of",
}
_BY_LENGTH = sorted(AB_REL_PHRASES, key=len, reverse=True)
AB_REL_WORDS: dict[str, tuple[str, ...]] = {}
for _p, _t in AB_REL_PHRASES.items():
    AB_REL_WORDS[_t] = (*AB_REL_WORDS.get(_t, ()), _p)

# ----------------------------------------------------------------------------------------------------
# A reader of AB's goals


def _undash(text: str) -> str:
    """'the cactus — which for its part is on the shelves — and ...' read as 'the cactus (which for its part is on
    the shelves) and ...'."""
    return re.sub(r" — (which for (?:its|their) part (?:is|are) [^—]+?) —", r" (\1)", text)


def _relations_at_top(text: str) -> list[tuple[int, int, str]]:
    """(start, end, type) of every relation phrase outside brackets, followed by 'the' (longest phrase first)."""
    depth, out, i = _depths(text), [], 0
    while i < len(text):
        if depth[i] == 0 and (i == 0 or text[i - 1] == " "):
            for p in _BY_LENGTH:
                if text.startswith(p + " the ", i):
                    out.append((i, i + len(p), AB_REL_PHRASES[p]))
                    i += len(p)
                    break
        i += 1
    return out


_JOIN_AT_END = re.compile(r"(?:,? and also|,? and)\s*$")


def _read_chain(text: str) -> list[tuple[str, dict]]:
    # ', which for its part is ...' hangs the rest of the text on the anchor before it
    depth = _depths(text)
    at = next((m for m in re.finditer(r", which for (?:its|their) part (?:is|are) ", text) if depth[m.start()] == 0),
              None)
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
    """'the switched-on teal lamp (which is next to the sofa)', 'the lamp [teal, wool], currently open,', 'the lamp
    described as teal and wool that stands switched on', 'the shelves (empty at present)', 'the lamp (open at the
    moment)', 'the cactus (that is near the drums, which for its part is on the shelves)'."""
    got = {"attrs": [], "after": [], "states": [], "relations": []}
    depth, plain, i = _depths(seg), "", 0
    while i < len(seg):
        if seg[i] == "(" and depth[i] == 1:
            j = i
            while not (seg[j] == ")" and depth[j] == 1):
                j += 1
            body = seg[i + 1 : j]
            if m := re.fullmatch(r"(?:which|that)(?: for (?:its|their) part)? (?:is|are) (.+)", body):
                got["relations"] += _read_chain(m.group(1))
            elif m := re.fullmatch(r"(.+) at (?:the moment|present)", body):
                got["states"] += m.group(1).split(" and ")
            else:
                raise AssertionError(f"unknown bracket {body!r} in {seg!r}")
            i = j + 1
            continue
        plain += seg[i]
        i += 1
    for m in re.finditer(r" \[([^\]]+)\]", plain):
        got["after"] += m.group(1).split(", ")
    plain = re.sub(r" \[[^\]]+\]", "", plain)
    parts = [p.strip() for p in plain.split(",") if p.strip()]
    for p in parts[1:]:
        m = re.fullmatch(r"currently (.+)", p)
        assert m, (p, seg)
        got["states"] += m.group(1).split(" and ")
    words = " ".join(parts[0].split())
    if m := re.search(r" that stands? (.+)$", words):
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


_ROOM_RX = re.compile(r"(?:, )?\b(?:(?:out |up )?in the|from the|belonging to the|that lives? in the) ("
                      + "|".join(sorted(ROOMS, key=len, reverse=True)) + r")\b,?")


def read_goal(text: str) -> tuple[dict, str | None]:
    room = None
    m = _ROOM_RX.search(text)
    if m:
        room = m.group(1)  # a comma around the room stays, so 'switched off, off to the left of' keeps its comma
        text = text[: m.start()] + ("," if "," in m.group(0) else "") + " " + text[m.end():]
    text = _undash(tidy_commas(text))
    rels = _relations_at_top(text)
    main = text[: rels[0][0]] if rels else text
    got = _read_np(tidy_commas(main))
    if rels:
        got["relations"] += _read_chain(text[rels[0][0]:])
    return got, room


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece_and_reads_back_exactly(sg, seed):
    text = AB.render_goal_ab(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, AB_REL_WORDS)
    assert ") (" not in text and max(_depths(text), default=0) <= 1, text
    got, room = read_goal(text)
    assert reading_norm(got) == target_truth(sg.target), text
    assert room == sg.room, text


def test_nested_goal_and_every_attribute_state_and_room_form():
    t = Target("teal wool lamp", "lamp", ("teal", "wool", "switched on"), (
        Relation("next_to", Target("sofa", "sofa", ("open",), (Relation("with", Target("drums", "drums")),))),
        Relation("under", Target("shelves", "shelves", ("empty",)))))
    rng = np.random.default_rng(0)
    texts = [AB.render_goal_ab(rng, Subgoal(0, t, room="music room")) for _ in range(400)]
    for text in texts:
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "music room", text
        assert text.index("music room") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
    for rx in (r"^the teal wool lamp", r"^the lamp described as teal and wool", r"^the lamp \[teal, wool\]",
               r"^the switched-on", r", currently switched on,", r" that stands switched on", r"\(switched on at the "
               r"moment\)", r" in the music room ", r" out in the music room ", r" up in the music room ",
               r" from the music room ", r" belonging to the music room ", r" that lives in the music room, ",
               r"\((which|that) is [a-z ]+ the drums\)", r"the shelves \(empty at present\)", r"the empty shelves",
               r"\) and also ", r"\), and ", r"\) and ", r"the open sofa"):
        assert any(re.search(rx, x) for x in texts), rx
    # never two clauses on end ('that stands switched on that lives in'), and never a clause after 'described as'
    assert not any(re.search(r"that stands switched on that", x) for x in texts)
    assert not any(re.search(r"described as [a-z ]+ that stands", x) for x in texts)


def test_plural_heads_agree():
    t = Target("lamp", "lamp", (), (Relation("by", Target("drums", "drums", (), (
        Relation("near", Target("cactus", "cactus", (), (Relation("on", Target("shelves", "shelves")),))),))),))
    rng = np.random.default_rng(2)
    texts = {AB.render_goal_ab(rng, Subgoal(0, t)) for _ in range(100)}
    assert any("drums (which are " in x for x in texts) and any("drums (that are " in x for x in texts), texts
    assert all("cactus, which for its part is " in x for x in texts), texts
    assert not any("drums (which is" in x or "drums (that is" in x for x in texts)
    drums = Target("drums", "drums", ("full",))
    plural = {AB.render_goal_ab(rng, Subgoal(0, drums, room="nursery")) for _ in range(200)}
    assert any(" that stand full" in x for x in plural) and any(" that live in the nursery" in x for x in plural)
    assert not any(re.search(r" that (stands|lives) ", x) for x in plural), plural


def test_a_phrase_of_another_shape_keeps_every_attribute():
    """A phrase that does not end on its head is written as given; attributes it lacks follow it."""
    t = Target("bean bag chair", "bean bag", ("teal", "corduroy", "bean"))
    rng = np.random.default_rng(11)
    plain = {AB.render_goal_ab(rng, Subgoal(0, t, room="nursery")) for _ in range(60)}
    for text in plain:
        assert re.match(r"the bean bag chair (described as teal and corduroy|\[teal, corduroy\]) "
                        r"((out |up )?in the|from the|belonging to the|that lives in the) nursery$", text), text
    assert AB.render_goal_ab(rng, Subgoal(0, Target("bean bag chair", "bean bag", ("bean",)))) == "the bean bag chair"


def test_deeper_anchors_hang_on_their_own_noun():
    """Below the first bracket an anchor's own relations follow ', which for its part is' when nothing of the bracket
    follows, else they stand between dashes; nothing nests a second bracket."""
    inner = Target("drums", "drums", ("switched on",), (Relation("behind", Target("toolbox", "toolbox")),))
    t = Target("lamp", "lamp", (), (Relation("by", Target("sofa", "sofa", (), (
        Relation("near", inner), Relation("on", Target("shelves", "shelves"))))),
        Relation("above", Target("mini-fridge", "mini-fridge"))))
    rng = np.random.default_rng(5)
    for _ in range(150):
        text = AB.render_goal_ab(rng, Subgoal(0, t, room="nursery"))
        assert max(_depths(text)) <= 1, text
        dashed = r"drums — which for their part are [a-z ]+ the toolbox — and [a-z ]+ the shelves\)"
        assert re.search(dashed, text), text
        check_goal(text, Subgoal(0, t, room="nursery"), AB_REL_WORDS, "{}")
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "nursery", text


def test_every_relation_word_is_used_and_read():
    rng = np.random.default_rng(7)
    for rtype in AB.REL_WORDS:
        sg = Subgoal(0, Target("lamp", "lamp", (), (Relation(rtype, Target("sofa", "sofa")),)))
        seen = set()
        for _ in range(120):
            text = AB.render_goal_ab(rng, sg)
            assert read_goal(text)[0]["relations"][0][0] == rtype, text
            seen.add(text[len("the lamp "): -len(" the sofa")])
        assert seen == set(AB_REL_WORDS[rtype]), rtype


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own

_DIGIT = {w: str(i) for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight",
                                           "nine"))}
_DIGIT_RX = "|".join(_DIGIT)
_SMALL = "|".join(("zero|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|thirteen|fourteen|fifteen",
                   "sixteen|seventeen|eighteen|nineteen"))
_WORD = rf"\d+|(?:twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety)(?:-(?:{_DIGIT_RX}))?|{_SMALL}"


def numbers_in(text: str) -> list[float]:
    """Every number: '-4', 'minus 4', 'negative 4', 'minus four', 'negative four', 'one hundred and five', '22½',
    '-2½', '22 point 5', 'twenty-two point five', 'point six five', 'zero point six five', 'sixty-five hundredths',
    'six tenths', '40C', 'X3.5 Y2'."""
    t = text.lower().replace("negative", "minus")
    t = re.sub(r"(\d+)½", r"\1.5", t)
    t = re.sub(rf"\b({_WORD}) point ((?:{_DIGIT_RX}|\d)(?: (?:{_DIGIT_RX}))*)\b",
               lambda m: f"{int(word_number(m.group(1)))}." + "".join(_DIGIT.get(w, w) for w in m.group(2).split()), t)
    t = re.sub(rf"\bpoint ((?:{_DIGIT_RX})(?: (?:{_DIGIT_RX}))*)\b",
               lambda m: "0." + "".join(_DIGIT[w] for w in m.group(1).split()), t)
    t = re.sub(rf"\b({_WORD}) (tenth|hundredth)s?\b",
               lambda m: f"{word_number(m.group(1)) / (10 if m.group(2) == 'tenth' else 100):g}", t)
    t = t.replace("°", " ")
    return spoken_numbers(re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)*", t))


def comparator_of(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"circa|give or take|within a whisker of", "approx"),
                  (r"no higher than|or under\b|never climbs past|never climbing past", "le"),
                  (r"no lower than|or over\b|never dips below|never dipping below", "ge"),
                  (r"stays beneath|staying beneath|doesn't reach|not reaching|south of", "lt"),
                  (r"\bclears\b|\bclearing\b|higher than|north of", "gt")):
        if re.search(rx, t):
            return c
    return "?"


def reading_of(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|vegetation index|lushest|thriving|vigorous|sickliest|withered|bedraggled", t):
        return "ndvi"
    if re.search(r"humid|\brh\b|steamiest|dankest|stickiest|desiccated|least damp|dried-out|%|per cent|\bpct\b", t):
        return "humidity_pct"
    if re.search(r"temp|balmiest|scorching|baking|chilliest|iciest|wintry|°|centigrade|degc|degree|[\d½]c\b", t):
        return "temperature_c"
    return "?"


_LOW = r"chilliest|iciest|wintry|sickliest|withered|bedraggled|desiccated|least damp|dried-out|lower than all|" \
       r"undercut|bottom"
_UNIT_C = r"°|centigrade|degc|degree|[\d½]c\b"
_UNIT_PCT = r"%|per cent|\bpct\b"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = AB.render_sensor_ab(np.random.default_rng(seed), c)
    check_sensor(rendered, c, comparator_of, _LOW, _UNIT_C, _UNIT_PCT, numbers_in, reading_of)
    text = (rendered[0] + " " + rendered[1]).strip()
    assert "(" not in text and "  " not in text and not text.startswith("that "), text
    if not rendered[2].unit and not c.is_superlative:  # a unitless number always has its reading named
        assert re.search(r"^(whose|with an?|showing an?) (temp|temperature|humidity|relative humidity|rh|ndvi|ndvi "
                         r"score|vegetation index) ", text.lower()), text
    if c.reading == "ndvi":  # an NDVI is always named
        assert rendered[2].unit == "" and (c.is_superlative or text.startswith(("whose ", "with ", "showing "))), text


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase_after_the_head(c, sg, seed):
    check_sensor_goal(AB.render_sensor_ab, AB.render_goal_ab, c, sg, seed, numbers_in)


@SETTINGS
@given(c=constraints(), sg=subgoals(), x=st.floats(-20, 40).map(lambda v: round(v, 1)),
       y=st.floats(-20, 40).map(lambda v: round(v, 1)), seed=st.integers(0, 2**31))
def test_a_goal_with_sensor_and_hint_ends_on_the_coordinates(c, sg, x, y, seed):
    """The hint's numbers come last in the goal (after any number of the sensor phrase), and brackets never stack."""
    rng = np.random.default_rng(seed)
    prefix, tail, _ = AB.render_sensor_ab(rng, c)
    hint = AB.hint_text_ab(rng, f"{x:.1f}", f"{y:.1f}")
    text = AB.render_goal_ab(rng, sg, prefix=prefix, tail=tail, hint=hint)
    nums = numbers_in(text)
    assert nums[-2:] == [pytest.approx(x), pytest.approx(y)], text
    assert len(nums) == 2 + (not c.is_superlative), text
    assert ") (" not in text and max(_depths(text), default=0) <= 1 and text.count("(") == text.count(")"), text
    check_goal_layout(text, sg, AB_REL_WORDS)
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
@given(v=st.integers(-30, -1).map(float) | st.sampled_from([-0.5, -2.5, -12.5]),
       cmp=st.sampled_from(("approx", "lt", "ge")), seed=st.integers(0, 2**31))
def test_temperatures_below_zero_keep_their_sign(v, cmp, seed):
    """'minus 4', 'negative 4', '-4', 'minus four', 'negative four', '-2½', 'minus two point five' all write a value
    below zero, in °C."""
    prefix, tail, written = AB.render_sensor_ab(np.random.default_rng(seed), SensorConstraint("temperature_c", cmp, v))
    assert not prefix and written == SensorConstraint("temperature_c", cmp, v, written.unit), tail
    assert numbers_in(tail) == [v] and comparator_of(tail) == cmp, tail
    assert written.unit == ("c" if re.search(_UNIT_C, tail.lower()) else ""), tail


def test_number_formats_frames_and_superlatives_vary():
    rng = np.random.default_rng(3)
    cold = {AB.render_sensor_ab(rng, SensorConstraint("temperature_c", "approx", -4.0))[1] for _ in range(400)}
    for rx in (r"minus four", r"negative four", r"minus 4\b", r"negative 4\b", r"(?<![\w])-4\b", r"^reading ",
               r"^running ", r"^sitting ", r"^whose temperature ", r"^whose temp ", r"^with a temperature ",
               r"^showing a temp ", r"-4C\b", r"4°", r"degC", r"degrees centigrade", r"\d centigrade",
               r"four degrees$",
               r"circa", r"give or take", r"within a whisker of"):
        assert any(re.search(rx, t) for t in cold), rx
    assert all(numbers_in(t) == [-4.0] for t in cold)
    half = {AB.render_sensor_ab(rng, SensorConstraint("temperature_c", "lt", 22.5))[1] for _ in range(300)}
    for rx in (r"twenty-two point five", r"\b22 point 5\b", r"22\.5", r"22½"):
        assert any(re.search(rx, t) for t in half), rx
    assert all(numbers_in(t) == [22.5] for t in half)
    neg = {AB.render_sensor_ab(rng, SensorConstraint("temperature_c", "ge", -2.5))[1] for _ in range(300)}
    for rx in (r"minus two point five", r"negative two point five", r"minus 2 point 5", r"(?<!\w)-2\.5", r"-2½",
               r"minus 2½|negative 2½"):
        assert any(re.search(rx, t) for t in neg), rx
    assert all(numbers_in(t) == [-2.5] for t in neg)
    hot = {AB.render_sensor_ab(rng, SensorConstraint("temperature_c", "gt", 105.0))[1] for _ in range(100)}
    assert any("one hundred and five" in t for t in hot) and all(numbers_in(t) == [105.0] for t in hot)
    one = {AB.render_sensor_ab(rng, SensorConstraint("temperature_c", "gt", 1.0))[1] for _ in range(200)}
    assert any("one degree" in t for t in one) and not any(re.search(r"\b(one|1) degrees", t) for t in one)
    damp = {AB.render_sensor_ab(rng, SensorConstraint("humidity_pct", "le", 40.0))[1] for _ in range(300)}
    for rx in (r"\d%", r"\d per cent", r"\d pct", r"forty per cent", r"^whose relative humidity ", r"^with an RH ",
               r"^showing a humidity ", r"no higher than", r"or under", r"never climbs past", r"never climbing past",
               r"^reading no higher than", r"^reading 40% or under"):
        assert any(re.search(rx, t) for t in damp), rx
    assert all(numbers_in(t) == [40.0] for t in damp)
    ndvi = {AB.render_sensor_ab(rng, SensorConstraint("ndvi", "gt", 0.65))[1] for _ in range(300)}
    for rx in (r"0\.65\b", r"(?<!zero )point six five", r"zero point six five", r"sixty-five hundredths",
               r"^whose NDVI ", r"^whose NDVI score ", r"^with a vegetation index ", r"^showing an NDVI ",
               r"\bclears\b", r"reads higher than", r"sits north of", r"clearing", r"reading higher than",
               r" north of"):
        assert any(re.search(rx, t) for t in ndvi), rx
    assert all(numbers_in(t) == [0.65] for t in ndvi)
    for v, words in ((0.6, "six tenths"), (0.05, "five hundredths"), (0.05, "point zero five"), (0.1, "one tenth")):
        got = {AB.render_sensor_ab(rng, SensorConstraint("ndvi", "le", v))[1] for _ in range(150)}
        assert any(t.endswith(words) for t in got) and all(numbers_in(t) == [v] for t in got), got
    for name, rd in (("humidity", "humidity_pct"), ("NDVI", "ndvi"), ("temperature", "temperature_c")):
        art = "an" if name == "NDVI" else "a"
        sup = {AB.render_sensor_ab(rng, SensorConstraint(rd, "max")) for _ in range(300)}
        assert {f"whose {name} beats all the others", f"with {art} {name} nobody else can match",
                f"coming out top on {name}"} <= {t for _, t, _ in sup if t}
        low = {AB.render_sensor_ab(rng, SensorConstraint(rd, "min")) for _ in range(300)}
        assert {f"whose {name} is lower than all the others", f"with {art} {name} nobody else can undercut",
                f"coming out bottom on {name}"} <= {t for _, t, _ in low if t}
    adjectives = {p for rd in ("humidity_pct", "ndvi", "temperature_c") for cmp in ("max", "min")
                  for p, _, _ in (AB.render_sensor_ab(rng, SensorConstraint(rd, cmp)) for _ in range(60)) if p}
    assert adjectives == {"balmiest", "most scorching", "most baking", "chilliest", "iciest", "most wintry",
                          "lushest", "most thriving", "most vigorous", "sickliest", "most withered", "most bedraggled",
                          "steamiest", "dankest", "stickiest", "most desiccated", "least damp", "most dried-out"}
    for cmp in ("gt", "ge", "lt", "le", "approx"):
        seen = {comparator_of(AB.render_sensor_ab(rng, SensorConstraint("temperature_c", cmp, 30.0))[1])
                for _ in range(60)}
        assert seen == {cmp}, (cmp, seen)


def test_plural_heads_take_no_verb_that_agrees():
    """A sensor tail straight after the noun has no finite verb, so 'the drums' read as well as 'the lamp'."""
    rng = np.random.default_rng(8)
    for cmp in ("gt", "ge", "lt", "le", "approx", "max", "min"):
        for _ in range(40):
            c = SensorConstraint("humidity_pct", cmp, None if cmp in ("max", "min") else 40.0)
            _, tail, _ = AB.render_sensor_ab(rng, c)
            assert not re.match(r"(that|which) ", tail), tail


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(AB.hint_text_ab, AB.render_goal_ab, AB.render_instruction_ab, x, y, seed)


def _read_hint(hint: str) -> tuple[float, float]:
    """x then y from every form, by its own labels: 'x is a and y is b', 'Xa Yb', 'marked x a, y b', '[x a | y b]',
    'x-axis a, y-axis b'."""
    n = r"(-?\d+(?:\.\d+)?)"
    for rx in (rf"where x is {n} and y is {n}", rf"at X{n} Y{n}", rf"the spot marked x {n}, y {n}",
               rf"\[x {n} \| y {n}\]", rf"x-axis {n}, y-axis {n}"):
        if m := re.search(rx, hint):
            return float(m.group(1)), float(m.group(2))
    raise AssertionError(hint)


def test_every_coordinate_form_is_used_and_labels_x_and_y():
    rng = np.random.default_rng(4)
    hints = {AB.hint_text_ab(rng, "-3.5", "2.0") for _ in range(100)}
    assert hints == {"where x is -3.5 and y is 2.0", "at X-3.5 Y2.0", "at the spot marked x -3.5, y 2.0",
                     "at [x -3.5 | y 2.0]", "at x-axis -3.5, y-axis 2.0"}
    assert {_read_hint(h) for h in hints} == {(-3.5, 2.0)}
    goal = AB.render_goal_ab(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(-3.5, 2.0)),
                             hint="at X-3.5 Y2.0")
    assert goal == "the guitar at X-3.5 Y2.0"


STRICT_CUES = r"keep to this order|order as cabled|no call out of turn|in strict sequence|" \
              r"do not rpt not alter order|in the order shown|waypoint order is locked|" \
              r"the route must be followed in this sequence|each in its due turn|in that order and no other|" \
              r"in order as here cried|let none be visited out of turn|in exactly this order|strictly that order|" \
              r"in that order, mind|don't jumble them up"
FREE_CUES = r"any order will do|order of calls your choice|order optional|sequence yours to choose|order unset|" \
            r"may be reached in any sequence|the route will be optimised|visiting order: flexible|" \
            r"the fastest route will be chosen for you|in what order it please|no order is decreed|in no set order|" \
            r"as the fancy takes it|no particular order|whichever way round you fancy|in any old order|" \
            r"it really doesn't matter"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_stay_whole_in_order(sgs, seed, strict):
    check_order(AB.render_goal_ab, AB.render_instruction_ab, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [AB.render_goal_ab(rng, sg) for sg in sgs]
    low = AB.render_instruction_ab(rng, res, "strict" if strict else "free").lower()
    if strict:
        assert re.search(STRICT_CUES, low), low
    at = 0
    for r in res:
        at = low.find(r.lower(), at)
        assert at >= 0, (r, low)
        at += len(r)


def test_goals_with_relations_are_never_run_together_with_a_bare_and():
    """In a running list a goal that has words after its noun is closed off (semicolons, STOP or a full stop), so
    the next goal cannot be read as one more anchor."""
    res = ["the lamp next to the sofa", "the kiln", "the guitar"]
    for seed in range(200):
        text = AB.render_instruction_ab(np.random.default_rng(seed), res, "free")
        assert "the sofa and the kiln" not in text and "the sofa, the kiln" not in text, text
        if "\n" not in text and "STOP" not in text:
            assert "the sofa; the kiln; and the guitar" in text, text


_OWN_HEADS = ("guitar", "harp", "kiln", "crib", "easel", "cello", "lectern", "jukebox")
_WORDS = {w: i for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight"))}
_ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth", "seventh")


@SETTINGS
@given(n=st.integers(2, 8), seed=st.integers(0, 2**31), strict=st.booleans())
def test_counts_numbers_and_items_agree_with_the_goals(n, seed, strict):
    _check_counts(n, seed, strict)


def test_counts_agree_over_a_sweep_of_seeds():
    for n in range(2, 9):
        for seed in range(40):
            _check_counts(n, seed, seed % 2 == 0)


def _check_counts(n: int, seed: int, strict: bool) -> None:
    res = [f"the {h}" for h in _OWN_HEADS[:n]]
    text = AB.render_instruction_ab(np.random.default_rng(seed), res, "strict" if strict else "free")
    for m in re.finditer(r"\b(\w+) (CALLS IN STRICT SEQUENCE|CALLS REQUIRED|waypoints[.,]|visits,|calls to pay)", text):
        assert word_number(m.group(1).lower()) == n, text
    lines = text.split("\n")
    goal_lines = [ln for ln in lines if re.search(r"\bthe (" + "|".join(_OWN_HEADS[:n]) + r")\b", ln)]
    if len(goal_lines) > 1:
        assert len(goal_lines) == n, text
        numbered = [m.group(1) for ln in goal_lines if (m := re.match(r"([A-Z]+): the ", ln))]
        if numbered:
            assert [_WORDS[w.lower()] for w in numbered] == list(range(1, n + 1)), text
            assert all(ln.endswith(" STOP") for ln in goal_lines), text
        ways = [(int(m.group(1)), int(m.group(2))) for ln in goal_lines if (m := re.match(r"Waypoint (\d+) of (\d+): ",
                                                                                          ln))]
        if ways:
            assert ways == [(k, n) for k in range(1, n)] and goal_lines[-1].startswith("Destination: "), text
        items = [m.group(1) for ln in goal_lines if (m := re.match(r"Item the (\w+): ", ln))]
        if items:
            assert items == [*_ORDINALS[: n - 1], "last"], text
        postcard = [int(m.group(1)) for ln in goal_lines if (m := re.match(r"(\d+)\) ", ln))]
        if postcard:
            assert postcard == list(range(1, n + 1)), text
    at = 0
    for r in res:  # every goal once, in order, never run into the next word
        m = re.compile(re.escape(r) + r"(?![\w-])").search(text, at)
        assert m, (r, text)
        at = m.end()


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_and_keeps_the_goal(sg, seed):
    rng = np.random.default_rng(seed)
    goal = AB.render_goal_ab(rng, sg)
    text = AB.render_instruction_ab(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text), text
    assert not re.search(FREE_CUES, text.lower()) and not re.search(STRICT_CUES, text.lower()), text


def test_every_voice_is_used_and_a_seed_repeats():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the guitar", "the kiln"]
    texts = [AB.render_instruction_ab(rng, res, order) for order in ("strict", "free") for _ in range(160)]
    for m in (r"\bSTOP\b", r"waypoint|route", r"Oyez|Hear ye|PROCLAMATION", r"Love, .+ xx$"):
        assert any(re.search(m, t) for t in texts), m
    for some, cues in ((texts[:160], STRICT_CUES), (texts[160:], FREE_CUES)):  # every cue of each order is written
        got = {c for t in some for c in re.findall(cues, t.lower())}
        assert got == set(cues.split("|")), set(cues.split("|")) - got
    assert any("\n" in t for t in texts) and any("\n" not in t for t in texts)
    assert len(set(texts)) > 60
    singles = [AB.render_instruction_ab(rng, res[:1], "strict") for _ in range(100)]
    for m in (r"ONE CALL ONLY|PLS CALL AT", r"Destination set|Navigating to", r"nowhere else this day|betake itself",
              r"only one little favour|just the one job"):
        assert any(re.search(m, t, re.IGNORECASE) for t in singles), m
    again = [AB.render_instruction_ab(np.random.default_rng(9), res, "free") for _ in range(2)]
    assert again[0] == again[1]
    differ = {AB.render_instruction_ab(np.random.default_rng(s), res, "free") for s in range(20)}
    assert len(differ) > 10


def test_unseen_ab_sensor_numbers_are_the_constraints():
    """The written number of a reading is the constraint's, in the goal's own text; a hint is x then y."""
    from test_heldout_sets import SMALL

    from ragnav_jax.config import load_config
    from ragnav_jax.language.episodes import generate_episodes
    from ragnav_jax.world.generator import generate_scene

    scene = generate_scene(load_config(None, SMALL).world, 5, 0)
    eps = generate_episodes([scene], load_config(None, [*SMALL, "episodes.split=unseen_ab"]).episodes, seed=3)
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
