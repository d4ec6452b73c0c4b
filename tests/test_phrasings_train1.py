"""The `unseen_train1` training templates (set T1): wired, deterministic, and every piece of the ground truth is
written down.

Checked with small readers of their own (a goal reader that recovers head, attributes, states, room and nested
relations; words for comparators, readings, units, numbers, superlative direction, coordinates and order cues) that
share no code with the templates, over random subgoals drawn by hypothesis.
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

from ragnav_jax.config import EPISODE_SPLITS
from ragnav_jax.language import phrasings_train1 as T
from ragnav_jax.language.episodes import UNSEEN_TEMPLATES, _renderer
from ragnav_jax.language.types import Location, Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# The whole phrases a reader of T1's goals splits on, each with its relation type (written apart from the templates)
T1_REL_PHRASES = {
    "near": "near", "within a cable's length of": "near", "lying close aboard": "near", "a few stitches from": "near",
    "next to": "next_to", "made fast next to": "next_to", "seamed up next to": "next_to",
    "beside": "beside", "hove to beside": "beside", "stitched in beside": "beside",
    "by": "by", "riding at anchor by": "by", "lying by": "by",
    "on": "on", "lashed on": "on", "battened down on": "on",
    "under": "under", "slung under": "under", "battened under": "under",
    "above": "above", "masthead-high over": "above", "rigged above": "above",
    "in": "in", "in the hold of": "in", "shipped inside": "in",
    "with": "with", "crewed by": "with", "trimmed with": "with",
    "in the same room as": "in_room_with", "in the same cabin as": "in_room_with",
    "sharing a cabin with": "in_room_with",
    "in front of": "in_front_of", "dead ahead of": "in_front_of", "forward of": "in_front_of",
    "behind": "behind", "astern of": "behind", "abaft": "behind",
    "opposite": "opposite", "bows-on to": "opposite", "dead across from": "opposite",
    "to the left of": "left_of", "to port of": "left_of", "off the port bow of": "left_of",
    "to the right of": "right_of", "to starboard of": "right_of", "off the starboard bow of": "right_of",
}
_BY_LENGTH = sorted(T1_REL_PHRASES, key=len, reverse=True)
T1_REL_WORDS: dict[str, tuple[str, ...]] = {}
for _p, _t in T1_REL_PHRASES.items():
    T1_REL_WORDS[_t] = (*T1_REL_WORDS.get(_t, ()), _p)


# ----------------------------------------------------------------------------------------------------
# Wiring and determinism


def test_split_is_wired():
    assert "unseen_train1" in EPISODE_SPLITS
    assert UNSEEN_TEMPLATES["unseen_train1"] == ("phrasings_train1", "train1")
    assert _renderer("unseen_train1", "goal") is T.render_goal_train1
    assert _renderer("unseen_train1", "sensor") is T.render_sensor_train1
    assert _renderer("unseen_train1", "hint") is T.hint_text_train1
    assert _renderer("unseen_train1", "instruction") is T.render_instruction_train1


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=4), c=constraints(), seed=st.integers(0, 2**31),
       strict=st.booleans())
def test_same_seed_same_text(sgs, c, seed, strict):
    def run():
        rng = np.random.default_rng(seed)
        prefix, tail, _ = T.render_sensor_train1(rng, c)
        res = [T.render_goal_train1(rng, sg, prefix=prefix, tail=tail, hint=T.hint_text_train1(rng, "3.5", "2"))
               for sg in sgs]
        return res, T.render_instruction_train1(rng, res, "strict" if strict else "free")

    assert run() == run()


# ----------------------------------------------------------------------------------------------------
# A reader of T1's goals


def _relations_at_top(text: str) -> list[tuple[int, int, str]]:
    depth, out, i = _depths(text), [], 0
    while i < len(text):
        if depth[i] == 0 and (i == 0 or text[i - 1] == " "):
            for p in _BY_LENGTH:
                if text.startswith(p + " the ", i):
                    out.append((i, i + len(p), T1_REL_PHRASES[p]))
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
        seg = re.sub(r"(, and moreover|, and further| and)\s*$", "", text[end:stop].strip())
        out.append((rtype, _read_np(seg.strip())))
    return out


def _read_np(seg: str) -> dict:
    """'the switched-on teal lamp (to wit, the one next to the sofa)', 'the lamp (open at last muster), by
    description teal and wool, logged as full'."""
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
        if m := re.fullmatch(r"(?:to wit,|that's to say) the one (.+)", body):
            got["relations"] += _read_chain(m.group(1))
        elif m := re.fullmatch(r"(.+) at last muster", body):
            got["states"] += m.group(1).split(" and ")
        elif m := re.fullmatch(r"marks to look for: (.+)", body):
            got["after"] += m.group(1).split(" and ")
        else:
            raise AssertionError(f"unknown bracket {body!r} in {seg!r}")
    parts = [p.strip() for p in plain.split(",") if p.strip()]
    for p in parts[1:]:
        if m := re.fullmatch(r"logged as (.+)", p):
            got["states"] += m.group(1).split(" and ")
        else:
            m = re.fullmatch(r"by description (.+)", p)
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


_ROOM_RX = re.compile(r"(?:berthed )?in the (" + "|".join(sorted(ROOMS, key=len, reverse=True)) + r")( compartment)?\b")


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
    text = T.render_goal_train1(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, T1_REL_WORDS)
    assert ") (" not in text and max(_depths(text), default=0) <= 1, text
    got, room = read_goal(text)
    assert reading_norm(got) == target_truth(sg.target), text
    assert room == sg.room, text


def test_every_attribute_state_room_and_relation_form_is_used_and_read():
    t = Target("teal wool lamp", "lamp", ("teal", "wool", "switched on"), (
        Relation("next_to", Target("sofa", "sofa", ("open",), (Relation("with", Target("drums", "drums")),))),
        Relation("under", Target("shelves", "shelves", ("empty",)))))
    rng = np.random.default_rng(0)
    texts = [T.render_goal_train1(rng, Subgoal(0, t, room="music room")) for _ in range(200)]
    for text in texts:
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "music room", text
        assert text.index("music room") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
    for rx in (r"^the teal wool lamp", r"^the lamp \(marks to look for: teal and wool\)", r", by description teal and "
               r"wool,", r"^the switched-on ", r"^the lamp \(switched on at last muster\)", r", logged as switched on,",
               r"in the music room compartment", r"berthed in the music room", r"\(to wit, the one ",
               r"\(that's to say the one ", r"the shelves \(empty at last muster\)", r"the empty shelves",
               r", and moreover ", r", and further "):
        assert any(re.search(rx, x) for x in texts), rx
    for rtype in T.REL_WORDS:
        sg = Subgoal(0, Target("lamp", "lamp", (), (Relation(rtype, Target("sofa", "sofa")),)))
        seen = set()
        for _ in range(60):
            text = T.render_goal_train1(rng, sg)
            assert read_goal(text)[0]["relations"][0][0] == rtype, text
            seen.add(text[len("the lamp "): -len(" the sofa")])
        assert seen == set(T1_REL_WORDS[rtype]), rtype


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own

_DIGIT_WORDS = {w: i for i, w in enumerate(("nought", "one", "two", "three", "four", "five", "six", "seven", "eight",
                                            "nine"))}
_DIGIT_WORDS["zero"] = 0


def numbers_in(text: str) -> list[float]:
    """Every number: '-4', '.65', 'minus 4', 'minus four', 'twenty-two point five', 'point six five', 'nought point
    six five', 'four degrees of frost', 'two hundred and fifty' ('the one' is no number)."""
    t = text.lower().replace("°c", " c")
    t = re.sub(r"(?<=the )one\b", "ONE", t)
    t = re.sub(r"(\S+) degrees of frost", r"minus \1 degrees", t)
    t = re.sub(r"minus minus ", "minus ", t)

    def spoken_decimal(m: re.Match) -> str:
        before, digits = m.group(1), m.group(2).split()
        frac = float("0." + "".join(str(_DIGIT_WORDS[d]) for d in digits))
        whole = spoken_numbers([before]) if before and before != "nought" else []
        if before and before != "nought" and not whole:
            return f"{before} {frac}"
        return f"{(whole[0] if whole else 0) + frac:g}"

    t = re.sub(r"(?:\b([a-z]+(?:-[a-z]+)?) )?point((?: (?:" + "|".join(_DIGIT_WORDS) + r")\b)+)", spoken_decimal, t)
    return spoken_numbers(re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)*", t))


def comparator_of(text: str) -> str:
    t = text.lower()
    for rx, c in ((r"nigh on|hair's breadth|dead reckoning|abreast of|shade either side", "approx"),
                  (r"sinks under|or above it|minimum|or more on the gauge|low-water mark|or (hotter|damper|greener)",
                   "ge"),
                  (r"creeps over|or under it|maximum|or less on the gauge|high-water mark|or (colder|drier|less green)",
                   "le"),
                  (r"proud of|rides higher|risen clear|overtops|is not .+ or under$|(hotter|damper|greener) than",
                   "gt"),
                  (r"rides lower|falls away below|dropped clear below|is not .+ or over$|"
                   r"(cooler|drier|less green) than", "lt")):
        if re.search(rx, t):
            return c
    return "?"


def reading_of(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|greenest|burgeon|full-leafed|sallow|peaky|wizened", t):
        return "ndvi"
    if re.search(r"humid|damp|waterlog|fog-bound|desert-dry|wrung|drier|%|per ?cent", t):
        return "humidity_pct"
    if re.search(r"temperature|torrid|fever|furnace|gelid|ice-bound|shivery|°|degree|celsius|deg c|hotter|cooler|"
                 r"colder", t):
        return "temperature_c"
    return "?"


_LOW = r"gelid|ice-bound|shivery|sallow|peaky|wizened|desert-dry|wrung-out|least|lowest|beneath all|bilges"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = T.render_sensor_train1(np.random.default_rng(seed), c)
    check_sensor(rendered, c, comparator_of, _LOW, r"°c|degree|celsius|deg c", r"(?i)%|per ?cent", numbers_in,
                 reading_of)
    text = (rendered[0] + " " + rendered[1]).strip()
    assert "(" not in text and "  " not in text, text
    if "of frost" in text:
        assert c.comparator == "approx" and rendered[2].value < 0, text
    if not rendered[2].unit and not c.is_superlative:  # a unitless number always has its reading named
        assert re.search(r"temperature|humidity|ndvi", text.lower()), text


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase_after_the_head(c, sg, seed):
    check_sensor_goal(T.render_sensor_train1, T.render_goal_train1, c, sg, seed, numbers_in)


@SETTINGS
@given(c=constraints(), sg=subgoals(), x=st.floats(-20, 40).map(lambda v: round(v, 1)),
       y=st.floats(-20, 40).map(lambda v: round(v, 1)), seed=st.integers(0, 2**31))
def test_a_goal_with_sensor_and_hint_ends_on_the_coordinates(c, sg, x, y, seed):
    """The hint's numbers come last in the goal (after any number of the sensor phrase), and brackets never stack."""
    rng = np.random.default_rng(seed)
    prefix, tail, _ = T.render_sensor_train1(rng, c)
    hint = T.hint_text_train1(rng, f"{x:.1f}", f"{y:.1f}")
    text = T.render_goal_train1(rng, sg, prefix=prefix, tail=tail, hint=hint)
    nums = numbers_in(text)
    assert nums[-2:] == [pytest.approx(x), pytest.approx(y)], text
    assert len(nums) == 2 + (not c.is_superlative), text
    assert ") (" not in text and max(_depths(text), default=0) <= 1 and text.count("(") == text.count(")"), text


def test_every_comparison_idiom_number_form_and_superlative_is_used():
    rng = np.random.default_rng(3)
    idioms_by_cmp = {
        "gt": {"stands proud of N", "rides higher than N", "has risen clear of N", "overtops N", "is not N or under",
               "runs hotter than N"},
        "ge": {"never sinks under N", "stands level with N or above it", "reads N minimum",
               "shows N or more on the gauge", "has a low-water mark of N", "is at N or hotter"},
        "lt": {"rides lower than N", "falls away below N", "has dropped clear below N", "is not N or over",
               "runs cooler than N"},
        "le": {"never creeps over N", "stands level with N or under it", "reads N maximum",
               "shows N or less on the gauge", "has a high-water mark of N", "is at N or colder"},
        "approx": {"is nigh on N", "sits within a hair's breadth of N", "reads N by dead reckoning",
                   "runs abreast of N", "is a shade either side of N"},
    }
    for cmp, idioms in idioms_by_cmp.items():
        seen = {T.render_sensor_train1(rng, SensorConstraint("temperature_c", cmp, 30.0))[1] for _ in range(300)}
        assert {comparator_of(t) for t in seen} == {cmp}, cmp
        got = {re.sub(r"^(that|whose temperature|carrying a temperature that|with a temperature that) ", "",
                      re.sub(r"(30|thirty)( ?°C| ° Celsius| degrees Celsius| deg C| degrees)?", "N", t)) for t in seen}
        assert got == idioms, (cmp, got ^ idioms)
    cold = {T.render_sensor_train1(rng, SensorConstraint("temperature_c", "approx", -4.0))[1] for _ in range(300)}
    for rx in (r"minus four", r"minus 4\b", r"\b(4|four) degrees of frost", r"-4\b", r"^that ", r"^whose ",
               r"^carrying a temperature that ", r"^with a temperature that ", r"° Celsius", r"deg C", r"°C"):
        assert any(re.search(rx, t) for t in cold), rx
    assert all(numbers_in(t) == [-4.0] for t in cold)
    half = {T.render_sensor_train1(rng, SensorConstraint("temperature_c", "lt", 22.5))[1] for _ in range(200)}
    assert any("twenty-two point five" in t for t in half) and all(numbers_in(t) == [22.5] for t in half)
    ndvi = {T.render_sensor_train1(rng, SensorConstraint("ndvi", "gt", 0.65))[1] for _ in range(200)}
    for rx in (r"(?<![\d])\.65\b", r"0\.65\b", r"(?<!nought )point six five", r"nought point six five",
               r"greener than .* on the NDVI", r"with an NDVI that"):
        assert any(re.search(rx, t) for t in ndvi), rx
    hum = {T.render_sensor_train1(rng, SensorConstraint("humidity_pct", "le", 40.0))[1] for _ in range(200)}
    for rx in (r"forty", r"% r\.h\.", r"per cent relative humidity", r"percent", r"or drier"):
        assert any(re.search(rx, t) for t in hum), rx
    sup = {T.render_sensor_train1(rng, SensorConstraint("humidity_pct", "min")) for _ in range(200)}
    assert {"most desert-dry", "most wrung-out", "least damp"} <= {p for p, _, _ in sup}
    assert {"whose humidity is the fleet's lowest", "with the humidity down in the bilges"} <= {t for _, t, _ in sup}


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(T.hint_text_train1, T.render_goal_train1, T.render_instruction_train1, x, y, seed)


def test_every_coordinate_form_is_used():
    rng = np.random.default_rng(4)
    hints = {T.hint_text_train1(rng, "-3.5", "2.0") for _ in range(100)}
    assert hints == {"at longitude -3.5, latitude 2.0 on the house chart", "(fix: x -3.5, y 2.0)",
                     "at -3.5 across, 2.0 up (x then y)", "where the chart puts x at -3.5 and y at 2.0"}
    goal = T.render_goal_train1(rng, Subgoal(0, Target("guitar", "guitar"), location=Location(-3.5, 2.0)),
                                hint="(fix: x -3.5, y 2.0)")
    assert goal == "the guitar (fix: x -3.5, y 2.0)"


STRICT_CUES = r"in the order written|leg after leg|one after another, in the order i gave them|consecutively|" \
              r"in the sequence written|out of order"
FREE_CUES = r"any rotation|no sequence|as the tide and the wind serve|left to your own judgement|in any order at all|" \
            r"makes no difference|crocheter's choice"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_stay_whole_in_order(sgs, seed, strict):
    check_order(T.render_goal_train1, T.render_instruction_train1, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [T.render_goal_train1(rng, sg) for sg in sgs]
    low = T.render_instruction_train1(rng, res, "strict" if strict else "free").lower()
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
def test_counts_rows_and_legs_agree_with_the_goals(n, seed, strict):
    res = [f"the {h}" for h in _OWN_HEADS[:n]]
    text = T.render_instruction_train1(np.random.default_rng(seed), res, "strict" if strict else "free")
    for m in re.finditer(r"\b(\w+) (landings|calls in all|squares in all)|Motifs to make \((\w+)\)", text):
        assert _WORDS[m.group(1) or m.group(3)] == n, text
    goal_lines = [ln for ln in text.split("\n") if re.search(r"\bthe (" + "|".join(_OWN_HEADS[:n]) + r")\b", ln)]
    if len(goal_lines) > 1:
        assert len(goal_lines) == n, text
        rows = [int(m.group(1)) for ln in goal_lines if (m := re.match(r"Row (\d+)\b", ln))]
        if rows:
            assert rows == list(range(1, n + 1)) and goal_lines[-1].startswith(f"Row {n} (last row)"), text
        legs = [m.group(1) for ln in goal_lines if (m := re.match(r"Leg the (\w+):", ln))]
        if legs:
            assert legs == [*_ORDS[: n - 1], "last"], text
    at = 0
    for r in res:  # every goal once, in order, never run into the next word
        m = re.compile(re.escape(r) + r"(?![\w-])").search(text, at)
        assert m, (r, text)
        at = m.end()


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_one_goal_instruction_adds_no_number_or_order_cue(sg, seed):
    rng = np.random.default_rng(seed)
    goal = T.render_goal_train1(rng, sg)
    text = T.render_instruction_train1(rng, [goal], "strict")
    assert goal in text and not re.search(r"\d", text) and numbers_in(text) == [], text
    assert not re.search(FREE_CUES, text.lower()) and not re.search(STRICT_CUES, text.lower()), text


def test_both_writers_and_every_cue_are_used():
    rng = np.random.default_rng(1)
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    texts = [T.render_instruction_train1(rng, res, order) for order in ("strict", "free") for _ in range(60)]
    for m in (r"sailing orders|hands to stations|liberty boats|jolly boat", r"row 1:|rep from \*|motif|granny square"):
        assert any(re.search(m, t.lower()) for t in texts), m
    for some, cues in ((texts[:60], STRICT_CUES), (texts[60:], FREE_CUES)):  # every cue of each order is written
        got = {c for t in some for c in re.findall(cues, t.lower())}
        assert got == set(cues.split("|")), set(cues.split("|")) - got
    assert any("\n" in t for t in texts) and any("\n" not in t for t in texts)
    singles = {T.render_instruction_train1(rng, res[:1], "strict").split(" the teal")[0] for _ in range(60)}
    assert len(singles) >= 4, singles
