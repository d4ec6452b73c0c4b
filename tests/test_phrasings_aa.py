"""The `unseen_aa` held-out templates (set AA): every piece of the ground truth is written down.

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

from ragnav_jax.language import phrasings_aa as AA
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# The whole phrases a reader of AA's goals splits on, each with its relation type (written apart from the templates)
AA_REL_PHRASES = {
    "near": "near", "a short hop from": "near", "within easy reach of": "near", "neighbouring": "near",
    "next to": "next_to", "right up against": "next_to", "rubbing elbows with": "next_to",
    "immediately adjoining": "next_to",
    "beside": "beside", "at the side of": "beside", "huddled beside": "beside",
    "by": "by", "just by": "by", "stationed by": "by",
    "on": "on", "balanced on": "on", "sitting on top of": "on", "laid on": "on",
    "under": "under", "underneath": "under", "stashed below": "under", "lurking beneath": "under",
    "above": "above", "overhanging": "above", "up above": "above", "suspended over": "above",
    "in": "in", "inside": "in", "contained in": "in", "held within": "in",
    "with": "with", "paired with": "with", "accompanied by": "with",
    "in the same room as": "in_room_with", "in one room with": "in_room_with",
    "sharing quarters with": "in_room_with",
    "in front of": "in_front_of", "out in front of": "in_front_of", "standing before": "in_front_of",
    "just ahead of": "in_front_of",
    "behind": "behind", "round the back of": "behind", "hidden behind": "behind",
    "opposite": "opposite", "across from": "opposite", "facing": "opposite", "vis-a-vis": "opposite",
    "left of": "left_of", "off to the left of": "left_of", "just left of": "left_of",
    "right of": "right_of", "off to the right of": "right_of", "just right of": "right_of",
}
_BY_LENGTH = sorted(AA_REL_PHRASES, key=len, reverse=True)
AA_REL_WORDS: dict[str, tuple[str, ...]] = {}
for _p, _t in AA_REL_PHRASES.items():
    AA_REL_WORDS[_t] = (*AA_REL_WORDS.get(_t, ()), _p)

# ----------------------------------------------------------------------------------------------------
# A reader of AA's goals


def _levels(text: str) -> list[int]:
    """Per character, how many round or square brackets are open there (a bracket's own characters inside it)."""
    out, d = [], 0
    for ch in text:
        if ch in "([":
            d += 1
        out.append(d)
        if ch in ")]":
            d -= 1
    return out


def _undash(text: str) -> str:
    """'the sofa — the one next to the drums — and ...' read as 'the sofa (the one next to the drums) and ...'."""
    return re.sub(r" — (the ones? [^—]+?) —", r" (\1)", text)


def _relations_at_top(text: str) -> list[tuple[int, int, str]]:
    """(start, end, type) of every relation phrase outside brackets, followed by 'the' (longest phrase first)."""
    level, out, i = _levels(text), [], 0
    while i < len(text):
        if level[i] == 0 and (i == 0 or text[i - 1] == " "):
            for p in _BY_LENGTH:
                if text.startswith(p + " the ", i):
                    out.append((i, i + len(p), AA_REL_PHRASES[p]))
                    i += len(p)
                    break
        i += 1
    return out


_JOIN_AT_END = re.compile(r"(?: and also|, plus| and)\s*$")


def _read_chain(text: str) -> list[tuple[str, dict]]:
    # ', the latter ...' hangs the rest of the text on the last anchor before it
    level = _levels(text)
    at = next((m for m in re.finditer(r", the latter ", text) if level[m.start()] == 0), None)
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
    """'the switched-on teal sofa (the one next to the drums)', 'the lamp (the teal wool variety), currently open',
    'the lamp described as teal and wool that happens to be open', 'the lamp in a switched-on state', 'the shelves
    (currently empty)', 'the drums [the ones behind the toolbox]'."""
    got = {"attrs": [], "after": [], "states": [], "relations": []}
    level, plain, i = _levels(seg), "", 0
    while i < len(seg):
        if seg[i] in "([" and level[i] == 1:
            close = ")" if seg[i] == "(" else "]"
            j = i
            while not (seg[j] == close and level[j] == 1):
                j += 1
            body = seg[i + 1 : j]
            if m := re.fullmatch(r"(?:that is, )?the ones? (.+)", body):
                got["relations"] += _read_chain(m.group(1))
            elif m := re.fullmatch(r"currently (.+)", body):
                got["states"] += m.group(1).split(" and ")
            elif m := re.fullmatch(r"the (.+) variety", body):
                got["after"] += m.group(1).split()
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
    if m := re.search(r" that happens? to be (.+)$", words):
        got["states"] += m.group(1).split(" and ")
        words = words[: m.start()]
    if m := re.search(r" in an? (.+) state$", words):
        got["states"] += [s.replace("-", " ") for s in m.group(1).split(" and ")]
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


_ROOM_RX = re.compile(r"(?:, )?\b(?:in the room known as|somewhere in|kept in|within|in) the ("
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
    main = re.sub(r",?\s*located\s*$", "", main.strip())
    got = _read_np(tidy_commas(main))
    if rels:
        got["relations"] += _read_chain(text[rels[0][0]:])
    return got, room


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece_and_reads_back_exactly(sg, seed):
    text = AA.render_goal_aa(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, AA_REL_WORDS)
    assert ") (" not in text and text.count("[") == text.count("]"), text
    got, room = read_goal(text)
    assert reading_norm(got) == target_truth(sg.target), text
    assert room == sg.room, text


def test_nested_goal_and_every_attribute_state_and_room_form():
    t = Target("teal wool lamp", "lamp", ("teal", "wool", "switched on"), (
        Relation("next_to", Target("sofa", "sofa", ("open",), (Relation("with", Target("drums", "drums")),))),
        Relation("under", Target("shelves", "shelves", ("empty",)))))
    rng = np.random.default_rng(0)
    texts = [AA.render_goal_aa(rng, Subgoal(0, t, room="music room")) for _ in range(500)]
    for text in texts:
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "music room", text
        assert text.index("music room") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
    for rx in (r"^the teal wool lamp", r"^the lamp \(the teal wool variety\)", r"^the lamp described as teal and wool",
               r", currently switched on,", r" that happens to be switched on ", r" in a switched-on state ",
               r" in the music room ", r" somewhere in the music room", r" kept in the music room",
               r" within the music room", r" in the room known as the music room", r"music room, [a-z]",
               r", located ", r"\(the one (with|paired with|accompanied by) the drums\)",
               r"\(that is, the one [a-z ]+ the drums\)", r" — the one [a-z ]+ the drums — ",
               r"the shelves \(currently empty\)", r"the empty shelves", r" and also ", r", plus ", r"the open sofa"):
        assert any(re.search(rx, x) for x in texts), rx
    # no state before the goal's own noun, never two relative clauses on end, never two brackets on one noun
    assert not any(x.startswith("the switched-on") for x in texts)
    assert not any(re.search(r"\) \(", x) for x in texts)


def test_plural_anchors_agree():
    t = Target("lamp", "lamp", (), (Relation("by", Target("drums", "drums", (), (
        Relation("near", Target("cactus", "cactus", (), (Relation("on", Target("shelves", "shelves")),))),))),))
    rng = np.random.default_rng(2)
    texts = {AA.render_goal_aa(rng, Subgoal(0, t)) for _ in range(100)}
    assert any("(the ones near the cactus, the latter " in x for x in texts), texts
    assert any("(that is, the ones near the cactus, the latter " in x for x in texts)
    assert not any("drums (the one " in x or "drums (that is, the one " in x for x in texts)
    plural = {AA.render_goal_aa(rng, Subgoal(0, Target("shelves", "shelves", ("open",)))) for _ in range(60)}
    assert "the shelves that happen to be open" in plural and "the shelves that happens to be open" not in plural


def test_a_phrase_of_another_shape_keeps_every_attribute():
    """A phrase that does not end on its head is written as given; attributes it lacks follow it."""
    t = Target("bean bag chair", "bean bag", ("teal", "corduroy", "bean"))
    rng = np.random.default_rng(11)
    plain = {AA.render_goal_aa(rng, Subgoal(0, t, room="nursery")) for _ in range(60)}
    for text in plain:
        assert re.match(r"the bean bag chair (described as teal and corduroy|\(the teal corduroy variety\)) "
                        r"(in the|somewhere in the|kept in the|within the|in the room known as the) nursery$", text), text
    assert AA.render_goal_aa(rng, Subgoal(0, Target("bean bag chair", "bean bag", ("bean",)))) == "the bean bag chair"


def test_deeper_anchors_hang_on_their_own_noun():
    """Below the first bracket an anchor's own relations follow ', the latter' when nothing else follows in the
    bracket, else they go in square brackets, so every relation stays with its own noun."""
    inner = Target("drums", "drums", ("switched on",), (Relation("behind", Target("toolbox", "toolbox")),))
    last = Target("lamp", "lamp", (), (Relation("by", Target("sofa", "sofa", (), (Relation("near", inner),))),
                                       Relation("above", Target("mini-fridge", "mini-fridge"))))
    mid = Target("lamp", "lamp", (), (Relation("by", Target("sofa", "sofa", (), (
        Relation("near", inner), Relation("on", Target("shelves", "shelves", ("empty",)))))),))
    rng = np.random.default_rng(5)
    for t, rx in ((last, r"the switched-on drums, the latter [a-z ]+ the toolbox"),
                  (mid, r"the switched-on drums \[the ones [a-z ]+ the toolbox\](?: and|, plus| and also) [a-z ]+ "
                        r"the empty shelves")):
        for _ in range(150):
            text = AA.render_goal_aa(rng, Subgoal(0, t, room="nursery"))
            assert re.search(rx, text), text
            check_goal(text, Subgoal(0, t, room="nursery"), AA_REL_WORDS, "{}")
            got, room = read_goal(text)
            assert reading_norm(got) == target_truth(t) and room == "nursery", text


def test_every_relation_word_is_used_and_read():
    rng = np.random.default_rng(7)
    for rtype in AA.REL_WORDS:
        sg = Subgoal(0, Target("lamp", "lamp", (), (Relation(rtype, Target("sofa", "sofa")),)))
        seen = set()
        for _ in range(150):
            text = AA.render_goal_aa(rng, sg)
            assert read_goal(text)[0]["relations"][0][0] == rtype, text
            m = re.fullmatch(r"the lamp(?:, located)? (.+) the sofa", text)
            assert m, text
            seen.add(m.group(1))
        assert seen == set(AA_REL_WORDS[rtype]), rtype


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own

_DIGIT = {w: str(i) for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight",
                                           "nine"))}
_DIGIT_RX = "(?:" + "|".join(_DIGIT) + ")"
_TEEN_RX = "(?:zero|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|thirteen|fourteen|fifteen|" \
           "sixteen|seventeen|eighteen|nineteen)"
_NUMWORD_RX = rf"(?:(?:twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety)(?:-{_DIGIT_RX})?|{_TEEN_RX})"




def numbers_in(text: str) -> list[float]:
    """Every number: '-4', 'negative 4', 'negative four', '40.0', '22½', 'twenty-two point five', 'a hundred and
    five', '0.650', 'zero point six five', 'point six five', 'sixty-five hundredths', 'six tenths'; 'the one(s)'
    before a relation and 'in one room' name no number."""
    t = text.lower().replace("negative ", "minus ")
    t = re.sub(r"\bthe ones? (?=(?:" + "|".join(map(re.escape, _BY_LENGTH)) + r") the\b)", "the ", t)
    t = re.sub(r"\bin one room\b", "in a room", t)
    t = re.sub(r"\ba hundred\b", "one hundred", t)
    t = re.sub(r"(\d+)½", r"\1.5", t)
    t = re.sub(r"\b(minus )?(" + _NUMWORD_RX + r") point five\b(?! " + _DIGIT_RX + r"\b)",
               lambda m: f"{(-1 if m.group(1) else 1) * (word_number(m.group(2)) + 0.5):g}", t)
    t = re.sub(r"\b(?:zero )?point (" + _DIGIT_RX + r"(?: " + _DIGIT_RX + r")*)\b",
               lambda m: "0." + "".join(_DIGIT[w] for w in m.group(1).split()), t)
    t = re.sub(r"\b(" + _NUMWORD_RX + r") (tenths?|hundredths?)\b",
               lambda m: f"{word_number(m.group(1)) / (10 if m.group(2).startswith('tenth') else 100):g}", t)
    return spoken_numbers(re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)*", t))


def comparator_of(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"\bcirca\b|give or take|in the ballpark of|\bor so\b", "approx"),
                  (r"never goes above|never going above|\bor under\b|ceiling of|at the outside", "le"),
                  (r"\band up\b|doesn't dip below|not dipping below|floor of|floored at", "ge"),
                  (r"south of|stays beneath|staying beneath|under the .+ mark", "lt"),
                  (r"\bclears\b|\bclearing\b|north of|\bbeyond\b", "gt")):
        if re.search(rx, t):
            return c
    return "?"


def reading_of(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|thriving|vigorous|luxuriant|languishing|feeblest|poorly", t):
        return "ndvi"
    if re.search(r"humid|dankest|sodden|dewiest|desiccated|dewy|moisture-starved|%|per cent|percent|\bpct\b", t):
        return "humidity_pct"
    if re.search(r"\btemp|balmiest|scorching|roasting|iciest|wintry|arctic|º|°|degc|centigrade|celsius", t):
        return "temperature_c"
    return "?"


_LOW = r"iciest|wintry|arctic|languishing|feeblest|poorly|desiccated|least dewy|moisture-starved|lowest|bottom|trails"
_UNIT_C = r"ºc|°|degc|centigrade|celsius"
_UNIT_PCT = r"%|per cent|percent|\bpct\b"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = AA.render_sensor_aa(np.random.default_rng(seed), c)
    check_sensor(rendered, c, comparator_of, _LOW, _UNIT_C, _UNIT_PCT, numbers_in, reading_of)
    text = (rendered[0] + " " + rendered[1]).strip()
    assert "  " not in text and text.count("(") == text.count(")"), text
    if not rendered[2].unit and not c.is_superlative:  # a unitless number always has its reading named
        assert re.search(r"^(whose (temperature|temp|humidity|relative humidity|ndvi)|logging an? (temperature|temp|"
                         r"humidity|relative humidity|ndvi)|\((temperature|temp|humidity|relative humidity|ndvi)"
                         r"[a-z ]*:)", text.lower()), text
    if c.reading != "temperature_c":  # only a temperature may go unnamed (after 'that', with its unit)
        assert not text.startswith("that ") or c.is_superlative, text
    if text.startswith("that ") and not c.is_superlative:
        assert rendered[2].unit == "c", text


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase_after_the_head(c, sg, seed):
    check_sensor_goal(AA.render_sensor_aa, AA.render_goal_aa, c, sg, seed, numbers_in)


@SETTINGS
@given(c=constraints(), sg=subgoals(), x=st.floats(-20, 40).map(lambda v: round(v, 1)),
       y=st.floats(-20, 40).map(lambda v: round(v, 1)), seed=st.integers(0, 2**31))
def test_a_goal_with_sensor_and_hint_ends_on_the_coordinates(c, sg, x, y, seed):
    """The hint's numbers come last in the goal (after any number of the sensor phrase), and brackets never stack."""
    rng = np.random.default_rng(seed)
    prefix, tail, _ = AA.render_sensor_aa(rng, c)
    hint = AA.hint_text_aa(rng, f"{x:.1f}", f"{y:.1f}")
    text = AA.render_goal_aa(rng, sg, prefix=prefix, tail=tail, hint=hint)
    nums = numbers_in(text)
    assert nums[-2:] == [pytest.approx(x), pytest.approx(y)], text
    assert len(nums) == 2 + (not c.is_superlative), text
    assert ") (" not in text and text.count("(") == text.count(")"), text
    check_goal_layout(text, sg, AA_REL_WORDS)
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
    """'negative 4', 'negative four', 'minus four', '-4', '-2½', 'minus two point five' all write a value below zero."""
    prefix, tail, written = AA.render_sensor_aa(np.random.default_rng(seed), SensorConstraint("temperature_c", cmp, v))
    assert not prefix and written == SensorConstraint("temperature_c", cmp, v, written.unit), tail
    assert numbers_in(tail) == [v] and comparator_of(tail) == cmp, tail
    assert written.unit == ("c" if re.search(_UNIT_C, tail.lower()) else ""), tail


def test_number_formats_frames_and_superlatives_vary():
    rng = np.random.default_rng(3)
    cold = {AA.render_sensor_aa(rng, SensorConstraint("temperature_c", "approx", -4.0))[1] for _ in range(400)}
    for rx in (r"negative four", r"minus four", r"negative 4\b", r"(?<![\w-])-4\b", r"-4\.0\b", r"^that ",
               r"^whose temperature ", r"^whose temp ", r"^logging a temperature ", r"^logging a temp ",
               r"^\(temperature: ", r"^\(temp: ", r"\d degC", r"ºC", r"° Celsius", r"\d°( |,|\)|$)", r"\d centigrade",
               r"degrees centigrade", r"is circa", r"of circa", r"give or take", r"in the ballpark of", r"or so\b"):
        assert any(re.search(rx, t) for t in cold), rx
    assert all(numbers_in(t) == [-4.0] for t in cold)
    half = {AA.render_sensor_aa(rng, SensorConstraint("temperature_c", "lt", 22.5))[1] for _ in range(300)}
    for rx in (r"twenty-two point five", r"\b22½", r"22\.5"):
        assert any(re.search(rx, t) for t in half), rx
    assert all(numbers_in(t) == [22.5] for t in half)
    neg = {AA.render_sensor_aa(rng, SensorConstraint("temperature_c", "ge", -2.5))[1] for _ in range(300)}
    for rx in (r"(negative|minus) two point five", r"(?<!\w)-2½", r"negative 2\.5", r"(?<!\w)-2\.5"):
        assert any(re.search(rx, t) for t in neg), rx
    assert all(numbers_in(t) == [-2.5] for t in neg)
    hot = {AA.render_sensor_aa(rng, SensorConstraint("temperature_c", "gt", 105.0))[1] for _ in range(200)}
    for rx in (r"\bone hundred and five\b", r"\ba hundred and five\b", r"\b105\b", r"\b105\.0\b"):
        assert any(re.search(rx, t) for t in hot), rx
    assert all(numbers_in(t) == [105.0] for t in hot)
    damp = {AA.render_sensor_aa(rng, SensorConstraint("humidity_pct", "le", 40.0))[1] for _ in range(300)}
    for rx in (r"\d%", r"\d per cent", r"\d pct", r"forty per cent", r"forty percent", r"never goes above",
               r"never going above", r"or under", r"ceiling of", r"at the outside", r"relative humidity"):
        assert any(re.search(rx, t) for t in damp), rx
    assert all(numbers_in(t) == [40.0] for t in damp)
    ndvi = {AA.render_sensor_aa(rng, SensorConstraint("ndvi", "gt", 0.65))[1] for _ in range(300)}
    for rx in (r"0\.65\b", r"0\.650\b", r"zero point six five", r"(?<!zero )point six five",
               r"sixty-five hundredths", r"^whose NDVI ", r"^logging an NDVI value ", r"^\(NDVI score: ",
               r"\bclears\b", r"north of", r"goes beyond", r"clearing", r"\bbeyond\b"):
        assert any(re.search(rx, t) for t in ndvi), rx
    assert all(numbers_in(t) == [0.65] for t in ndvi)
    for v, words in ((0.6, "six tenths"), (0.1, "one tenth"), (0.05, "five hundredths"), (0.6, "zero point six"),
                     (0.05, "point zero five"), (0.6, "0.600")):
        got = {AA.render_sensor_aa(rng, SensorConstraint("ndvi", "le", v))[1] for _ in range(200)}
        assert any(words in t for t in got) and all(numbers_in(t) == [v] for t in got), (words, got)
    for name, rd in (("humidity", "humidity_pct"), ("NDVI", "ndvi"), ("temperature", "temperature_c")):
        sup = {t for _, t, _ in (AA.render_sensor_aa(rng, SensorConstraint(rd, "max")) for _ in range(300)) if t}
        assert {f"whose {name} beats all comers", f"with the top {name} of the lot",
                f"that outdoes every rival on {name}"} <= sup, sup
        low = {t for _, t, _ in (AA.render_sensor_aa(rng, SensorConstraint(rd, "min")) for _ in range(300)) if t}
        assert {f"whose {name} is the lowest of the bunch", f"with the bottom {name} of the lot",
                f"that trails every rival on {name}"} <= low, low
    adjectives = {p for rd in ("humidity_pct", "ndvi", "temperature_c") for cmp in ("max", "min")
                  for p, _, _ in (AA.render_sensor_aa(rng, SensorConstraint(rd, cmp)) for _ in range(60)) if p}
    assert adjectives == {"balmiest", "most scorching", "most roasting", "iciest", "most wintry", "most arctic",
                          "most thriving", "most vigorous", "most luxuriant", "most languishing", "feeblest",
                          "most poorly", "dankest", "most sodden", "dewiest", "most desiccated", "least dewy",
                          "most moisture-starved"}
    for cmp in ("gt", "ge", "lt", "le", "approx"):
        seen = {comparator_of(AA.render_sensor_aa(rng, SensorConstraint("temperature_c", cmp, 30.0))[1])
                for _ in range(80)}
        assert seen == {cmp}, (cmp, seen)


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(AA.hint_text_aa, AA.render_goal_aa, AA.render_instruction_aa, x, y, seed)


def _read_hint(hint: str) -> tuple[float, float]:
    """x then y from every form, by its own labels: 'x:a / y:b', 'x reads a and y reads b', 'a m along the x-axis
    and b m along the y-axis', '[x a | y b]', 'a/b (x/y)'."""
    n = r"(-?\d+(?:\.\d+)?)"
    for rx in (rf"x:{n} / y:{n}", rf"x reads {n} and y reads {n}", rf"{n} m along the x-axis and {n} m along the y-axis",
               rf"\[x {n} \| y {n}\]", rf"{n}/{n} \(x/y\)"):
        if m := re.search(rx, hint):
            return float(m.group(1)), float(m.group(2))
    raise AssertionError(hint)


def test_every_coordinate_form_is_used_and_labels_x_and_y():
    rng = np.random.default_rng(4)
    hints = {AA.hint_text_aa(rng, "-3.5", "2.0") for _ in range(100)}
    assert hints == {"pinned at x:-3.5 / y:2.0", "where x reads -3.5 and y reads 2.0",
                     "at -3.5 m along the x-axis and 2.0 m along the y-axis", "at grid square [x -3.5 | y 2.0]",
                     "at -3.5/2.0 (x/y)"}
    assert {_read_hint(h) for h in hints} == {(-3.5, 2.0)}
    goal = AA.render_goal_aa(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(-3.5, 2.0)),
                             hint="pinned at x:-3.5 / y:2.0")
    assert goal == "the guitar pinned at x:-3.5 / y:2.0"


STRICT_CUES = r"strictly in the numbered sequence|no item is to be approached before the item preceding it|" \
              r"the sequence is to be observed strictly|no deviation from it is permitted|in order, no skipping|" \
              r"skip one and you're back to the start|in that order, people|one after the other|" \
              r"to be undertaken in the order here set down|" \
              r"let no trial be attempted ere the one before it be fulfilled|in that exact order|" \
              r"don't like mix up the order"
FREE_CUES = r"sequence at the examiner's discretion|the order of inspection is immaterial|in no prescribed sequence|" \
            r"in whatever sequence proves convenient|in any order you fancy|i'm not fussed which one you tag first|" \
            r"whichever you reach first|nobody's keeping track of the order|" \
            r"the order of their finding mattereth not|in whatsoever order thou wilt|" \
            r"no relic taketh precedence over another|as fortune guideth|whatever order honestly|" \
            r"literally doesn't matter which one you do first|i genuinely do not care"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_stay_whole_in_order(sgs, seed, strict):
    check_order(AA.render_goal_aa, AA.render_instruction_aa, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [AA.render_goal_aa(rng, sg) for sg in sgs]
    text = AA.render_instruction_aa(rng, res, "strict" if strict else "free")
    if strict:
        assert re.search(STRICT_CUES, text.lower()), text
    at = 0
    for r in res:  # each goal exactly as rendered (case and all), in visiting order
        at = text.find(r, at)
        assert at >= 0, (r, text)
        at += len(r)


def test_goals_with_relations_are_never_run_together_with_a_bare_and():
    """In a running list a goal that has words after its noun is closed off (a semicolon, 'then', 'oh and' or a
    line of its own), so the next goal cannot be read as one more anchor."""
    res = ["the lamp next to the sofa", "the kiln", "the guitar"]
    for seed in range(300):
        for order in ("strict", "free"):
            text = AA.render_instruction_aa(np.random.default_rng(seed), res, order)
            assert "the sofa and the kiln" not in text and "the sofa, the kiln" not in text, text
            assert re.search(r"the sofa(\n|[;!.]\s| and then | oh and |,? THEN | first and then |, before anything "
                             r"else|, (when that is done|thence|and after),? )", text + " "), text


_OWN_HEADS = ("guitar", "harp", "kiln", "crib", "easel", "cello", "lectern", "jukebox")
_WORDS = {w: i for i, w in enumerate(("zero", "one", "two", "three", "four", "five", "six", "seven", "eight"))}
_ORDS = ("First", "Second", "Third", "Fourth", "Fifth", "Sixth", "Seventh")


@SETTINGS
@given(n=st.integers(2, 8), seed=st.integers(0, 2**31), strict=st.booleans())
def test_counts_numbers_and_ordinals_agree_with_the_goals(n, seed, strict):
    _check_counts(n, seed, strict)


def test_counts_agree_over_a_sweep_of_seeds():
    for n in range(2, 9):
        for seed in range(40):
            _check_counts(n, seed, seed % 2 == 0)


def _check_counts(n: int, seed: int, strict: bool) -> None:
    res = [f"the {h}" for h in _OWN_HEADS[:n]]
    text = AA.render_instruction_aa(np.random.default_rng(seed), res, "strict" if strict else "free")
    counted = r"\b(\w+) (stations, in order|cones, hit them|relics, and|in total;)"
    for m in re.finditer(counted, text.lower()):
        assert _WORDS[m.group(1)] == n, text
    lines = text.split("\n")
    goal_lines = [ln for ln in lines if re.search(r"\bthe (" + "|".join(_OWN_HEADS[:n]) + r")\b", ln)]
    if len(goal_lines) > 1:
        assert len(goal_lines) == n, text
        numbered = [int(m.group(1)) for ln in goal_lines if (m := re.match(r"(\d+)\. ", ln))]
        if numbered:
            assert numbered == list(range(1, n + 1)), text
            assert goal_lines[0].endswith(", before anything else.") and "last of all" in goal_lines[-1], text
        stations = [m.group(1) for ln in goal_lines if (m := re.match(r"(STATION \w+|FINAL STATION): ", ln))]
        if stations:
            assert stations == [*(f"STATION {_ref(k).upper()}" for k in range(1, n)), "FINAL STATION"], text
        trials = [m.group(1) for ln in goal_lines if (m := re.match(r"The (\w+) Trial: ", ln))]
        if trials:
            assert trials == [*_ORDS[: n - 1], "Last"], text
        bullets = {ln[0] for ln in goal_lines}
        assert len(bullets) == 1 or numbered or stations or trials, text
    at = 0
    for r in res:  # every goal once, in order, never run into the next word
        m = re.compile(re.escape(r) + r"(?![\w-])").search(text, at)
        assert m, (r, text)
        at = m.end()
    assert all(len(re.findall(re.escape(r) + r"(?![\w-])", text)) == 1 for r in res), text


def _ref(k: int) -> str:
    return next(w for w, i in _WORDS.items() if i == k)


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_and_keeps_the_goal(sg, seed):
    rng = np.random.default_rng(seed)
    goal = AA.render_goal_aa(rng, sg)
    text = AA.render_instruction_aa(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text), text
    assert not re.search(FREE_CUES, text.lower()) and not re.search(STRICT_CUES, text.lower()), text


def test_every_author_is_used_and_a_seed_repeats():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the guitar", "the kiln"]
    texts = [AA.render_instruction_aa(rng, res, order) for order in ("strict", "free") for _ in range(200)]
    for m in (r"condition|examin|n\.b\.|viz\.|cf\.", r"phw|pheep|station|cones|team|people",
              r"traveller|trial|relic|oracle|thou|thy", r"voice memo|like|literally|honestly"):
        assert any(re.search(m, t.lower()) for t in texts), m
    for some, cues in ((texts[:200], STRICT_CUES), (texts[200:], FREE_CUES)):  # every cue of each order is written
        got = {c for t in some for c in re.findall(cues, t.lower())}
        assert got == set(cues.split("|")), set(cues.split("|")) - got
    assert any("\n" in t for t in texts) and any("\n" not in t for t in texts)
    assert len(set(texts)) >= 16
    teen = [t for t in texts if t.startswith("[voice memo")]
    assert teen and all(t == t.lower() for t in teen)
    shout = [t for t in texts if "PH" in t or "OI!" in t or "FREE-FOR-ALL" in t]
    assert shout and all(re.search(r"\b[A-Z]{2,}(?: [A-Z'!.]+){2,}", t) for t in shout)
    singles = [AA.render_instruction_aa(rng, res[:1], "strict") for _ in range(120)]
    for m in (r"single object|object for examination", r"one job and one job only|that's the session",
              r"a single quest remaineth|speaketh of but one relic", r"literally all you have to do|can you go to"):
        assert any(re.search(m, t.lower()) for t in singles), m
    again = [AA.render_instruction_aa(np.random.default_rng(9), res, "free") for _ in range(2)]
    assert again[0] == again[1]


def test_unseen_aa_sensor_numbers_are_the_constraints():
    """The written number of a reading is the constraint's, in the goal's own text; a hint is x then y."""
    from test_heldout_sets import SMALL

    from ragnav_jax.config import load_config
    from ragnav_jax.language.episodes import generate_episodes
    from ragnav_jax.world.generator import generate_scene

    scene = generate_scene(load_config(None, SMALL).world, 5, 0)
    eps = generate_episodes([scene], load_config(None, [*SMALL, "episodes.split=unseen_aa"]).episodes, seed=3)
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
