"""The `unseen_train2` training templates (set Train2: an estate agent and a texting teenager): every piece of the
ground truth is written down, the split is wired, and a seed repeats its text.

Checked with small readers of their own (a goal reader that recovers head, attributes, states, room and nested
relations; phrase lists for comparators, superlatives, readings, units, numbers, coordinates and order cues) that
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
from ragnav_jax.language import phrasings_train2 as T
from ragnav_jax.language.episodes import UNSEEN_TEMPLATES, _renderer
from ragnav_jax.language.types import Relation, SensorConstraint, Subgoal, Target

SETTINGS = settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# ----------------------------------------------------------------------------------------------------
# A reader of the set's goals (its phrase list is written apart from the templates)

REL_PHRASES = {
    "near": "near", "moments from": "near", "within easy reach of": "near", "rly close to": "near",
    "kinda near": "near",
    "next to": "next_to", "immediately alongside": "next_to", "sat neatly next to": "next_to",
    "right nxt to": "next_to", "nxt to": "next_to",
    "beside": "beside", "sited beside": "beside", "placed handsomely beside": "beside", "literally beside": "beside",
    "by": "by", "handily placed by": "by", "set by": "by", "chillin by": "by",
    "on": "on", "resting on": "on", "showcased on": "on", "sittin on": "on", "chillin on": "on",
    "under": "under", "set neatly beneath": "under", "beneath": "under", "undr": "under", "jammed under": "under",
    "above": "above", "elevated above": "above", "commanding views over": "above", "abv": "above",
    "hangin above": "above",
    "in": "in", "enclosed in": "in", "fitted into": "in", "inside of": "in", "stuck in": "in",
    "with": "with", "complemented by": "with", "benefitting from": "with", "w": "with", "rockin": "with",
    "in the same room as": "in_room_with", "in a room also home to": "in_room_with",
    "in the same space as": "in_room_with", "in the same rm as": "in_room_with", "in the room w": "in_room_with",
    "in front of": "in_front_of", "in pride of place in front of": "in_front_of",
    "taking centre stage in front of": "in_front_of", "right in front of": "in_front_of", "infront of": "in_front_of",
    "behind": "behind", "discreetly set behind": "behind", "set back behind": "behind", "bhind": "behind",
    "round behind": "behind",
    "opposite": "opposite", "with views across to": "opposite", "directly facing": "opposite",
    "on the other side from": "opposite", "across from": "opposite",
    "to the left of": "left_of", "set to the left of": "left_of", "sited to the left of": "left_of",
    "left of": "left_of", "lil bit left of": "left_of",
    "to the right of": "right_of", "set to the right of": "right_of", "sited to the right of": "right_of",
    "right of": "right_of", "lil bit right of": "right_of",
}
_BY_LENGTH = sorted(REL_PHRASES, key=len, reverse=True)
REL_WORDS: dict[str, tuple[str, ...]] = {}
for _p, _t in REL_PHRASES.items():
    REL_WORDS[_t] = (*REL_WORDS.get(_t, ()), _p)
_ROOM_RX = re.compile(r"\b(?:in the (?:well-appointed |light-filled )?|within the |inside the )("
                      + "|".join(sorted(ROOMS, key=len, reverse=True)) + r")\b")
_LIST = re.compile(r" and | n ")


def _relations_at_top(text: str) -> list[tuple[int, int, str]]:
    depth, out, i = _depths(text), [], 0
    while i < len(text):
        if depth[i] == 0 and (i == 0 or text[i - 1] == " "):
            for p in _BY_LENGTH:
                if text.startswith(p + " the ", i):
                    out.append((i, i + len(p), REL_PHRASES[p]))
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
        seg = re.sub(r"(, whilst also|, and indeed| and| n also| n)\s*$", "", text[end:stop].strip())
        out.append((rtype, _read_np(seg.strip())))
    return out


def _read_np(seg: str) -> dict:
    """'the switched-on teal lamp (the very one next to the sofa)', 'the lamp (a charming teal and wool specimen),
    which the vendors keep open', 'the lamp (open atm), the teal n wool one', 'the shelves (empty rn)'."""
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
        if m := re.fullmatch(r"(?:the very one|which is to say, the one|like the one) (.+)", body):
            got["relations"] += _read_chain(m.group(1))
        elif m := re.fullmatch(r"the one (.+) obvs", body):
            got["relations"] += _read_chain(m.group(1))
        elif m := re.fullmatch(r"left (.+?)(?: for viewings)?|(.+) (?:rn|atm)", body):
            got["states"] += _LIST.split(m.group(1) or m.group(2))
        elif m := re.fullmatch(r"a charming (.+) specimen|(.+), u cant miss it", body):
            got["after"] += _LIST.split(m.group(1) or m.group(2))
        else:
            raise AssertionError(f"unknown bracket {body!r} in {seg!r}")
    parts = [p.strip() for p in plain.split(",") if p.strip()]
    for p in parts[1:]:
        if m := re.fullmatch(r"which the vendors keep (.+)|thats (.+) rn", p):
            got["states"] += _LIST.split(m.group(1) or m.group(2))
        else:
            m = re.fullmatch(r"(.+) no less|the (.+) one", p)
            assert m, (p, seg)
            got["after"] += _LIST.split(m.group(1) or m.group(2))
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
    room = None
    depth = _depths(text)
    rooms = [m for m in _ROOM_RX.finditer(text) if depth[m.start()] == 0]
    if rooms:
        assert len(rooms) == 1, text
        room = rooms[0].group(1)
        text = text[: rooms[0].start()] + text[rooms[0].end():]
        text = " ".join(text.split())
    rels = _relations_at_top(text)
    main = text[: rels[0][0]] if rels else text
    got = _read_np(main.strip().rstrip(","))
    if rels:
        got["relations"] += _read_chain(text[rels[0][0]:])
    return got, room


def _voice_of(text: str) -> str:
    """'teen' for a text written all in lower case with a texting word; 'agent' for one that has none."""
    if re.search(r"\b(rn|tbh|ngl|lowkey|obvs|atm|u|w|nxt|undr|abv|bhind|rly|kinda|lil|chillin|sittin|hangin|rockin|"
                 r"em|thats|doesnt|cant|isnt|tho|pls|hey|ok)\b", text):
        return "teen"
    return "agent"


# ----------------------------------------------------------------------------------------------------
# Wiring and determinism


def test_split_is_wired():
    assert "unseen_train2" in EPISODE_SPLITS
    assert UNSEEN_TEMPLATES["unseen_train2"] == ("phrasings_train2", "train2")
    assert _renderer("unseen_train2", "goal") is T.render_goal_train2
    assert _renderer("unseen_train2", "sensor") is T.render_sensor_train2
    assert _renderer("unseen_train2", "hint") is T.hint_text_train2
    assert _renderer("unseen_train2", "instruction") is T.render_instruction_train2


def _episode(seed: int, sgs, strict: bool, c: SensorConstraint):
    rng = np.random.default_rng(seed)
    prefix, tail, _ = T.render_sensor_train2(rng, c)
    hint = T.hint_text_train2(rng, "3.5", "-2.0")
    res = [T.render_goal_train2(rng, sgs[0], prefix=prefix, tail=tail, hint=hint)]
    res += [T.render_goal_train2(rng, sg) for sg in sgs[1:]]
    return res, T.render_instruction_train2(rng, res, "strict" if strict else "free")


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=1, max_size=4), seed=st.integers(0, 2**31), strict=st.booleans(),
       c=constraints())
def test_same_seed_same_text_in_one_voice(sgs, seed, strict, c):
    res, text = _episode(seed, sgs, strict, c)
    assert (res, text) == _episode(seed, sgs, strict, c)
    voice = _voice_of(text)
    if voice == "teen":  # the teenager never capitalises, and every goal is in the teenager's words
        assert text == text.lower(), text
    else:
        assert text[:1].isupper(), text
    for r in res:
        assert _voice_of(r) == voice or (voice == "teen" and r == r.lower()), (r, text)


# ----------------------------------------------------------------------------------------------------
# Goals


@SETTINGS
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_goal_writes_every_piece_and_reads_back_exactly(sg, seed):
    text = T.render_goal_train2(np.random.default_rng(seed), sg)
    check_goal_layout(text, sg, REL_WORDS)
    assert ") (" not in text and max(_depths(text), default=0) <= 1, text
    got, room = read_goal(text)
    assert reading_norm(got) == target_truth(sg.target), text
    assert room == sg.room, text


def test_every_form_of_attribute_state_room_and_relation_is_used_and_read():
    t = Target("teal wool lamp", "lamp", ("teal", "wool", "switched on"), (
        Relation("next_to", Target("sofa", "sofa", ("open",), (Relation("with", Target("drums", "drums")),))),
        Relation("under", Target("shelves", "shelves", ("empty",)))))
    texts = [T.render_goal_train2(np.random.default_rng(s), Subgoal(0, t, room="music room")) for s in range(300)]
    for text in texts:
        got, room = read_goal(text)
        assert reading_norm(got) == target_truth(t) and room == "music room", text
        assert text.index("music room") < text.index("sofa") < text.index("drums") < text.index("shelves"), text
    for rx in (r"^the teal wool lamp", r"^the lamp \(a charming teal and wool specimen\)", r"^the lamp, teal and wool "
               r"no less,", r"^the lamp \(teal n wool, u cant miss it\)", r"^the lamp, the teal n wool one,",
               r"^the switched-on ", r"\(left switched on for viewings\)", r", which the vendors keep switched on,",
               r", thats switched on rn,", r"\(switched on atm\)", r"in the well-appointed music room",
               r"in the light-filled music room", r"within the music room", r"inside the music room",
               r"\(the very one ", r"\(which is to say, the one ", r"\(the one .* obvs\)", r"\(like the one ",
               r"the shelves \(left empty\)", r"the shelves \(empty rn\)", r", whilst also ", r", and indeed ",
               r"\) n (also )?\w"):
        assert any(re.search(rx, x) for x in texts), rx
    for rtype in REL_WORDS:
        sg = Subgoal(0, Target("lamp", "lamp", (), (Relation(rtype, Target("sofa", "sofa")),)))
        seen = set()
        for s in range(60):
            text = T.render_goal_train2(np.random.default_rng(s), sg)
            assert read_goal(text)[0]["relations"][0][0] == rtype, text
            seen.add(text[len("the lamp "): -len(" the sofa")])
        assert seen == set(REL_WORDS[rtype]), (rtype, set(REL_WORDS[rtype]) - seen)


# ----------------------------------------------------------------------------------------------------
# Sensor phrases, read back by a reader of our own

_WORD = r"[a-z]+(?:-[a-z]+)?"


def numbers_in(text: str) -> list[float]:
    """Every number: '-4', '.65', '30c', '30c+', 'minus 4', 'neg 4', 'minus four', '20 and a half', 'twenty and a
    half' ('one' only counts before a unit: 'the teal one' and 'every other one' are no numbers)."""
    t = text.lower().replace("°c", " c").replace("+", " ")
    t = re.sub(r"(\d)(c|°)(?![a-z])", r"\1 \2", t)
    t = re.sub(r"\bneg\b", "minus", t)
    t = re.sub(r"\bone\b(?! (?:degree|deg|per ?cent|pct|hundred))", "ONE", t)

    def half(m: re.Match) -> str:
        k = spoken_numbers([m.group(1)])
        assert len(k) == 1, m.group(0)
        return f"{k[0] + 0.5:g}"

    t = re.sub(r"(\d+|" + _WORD + r") and a half\b", half, t)
    return spoken_numbers(re.findall(r"-?\d*\.?\d+|[a-z]+(?:-[a-z]+)*", t))


_COMPARATORS = (  # checked in this order: the first that matches names the comparator
    (r"in the order of|stone's throw either side|somewhere near|\bbout\b|close-ish|somewhere round", "approx"),
    (r"upwards|or higher|slips beneath|\+|isnt under|or more", "ge"),
    (r"stops at|rises beyond|or below|\bmax\b|doesnt go over|or lower", "le"),
    (r"streets ahead|step up|clears .* with room to spare|higher than|goes over|smashes|above", "gt"),
    (r"never quite reaches|held beneath|step down|doesnt even hit|\bsub\b|lower than|cant even reach", "lt"),
)


def comparator_of(text: str) -> str:
    t = text.lower()
    for rx, c in _COMPARATORS:
        if re.search(rx, t):
            return c
    return "?"


_LOW = (r"bracing|ice-cold|neglected|tired-looking|least damp-prone|moisture-free|freezing|frozen|deadest|dyin|"
        r"dried out|least swampy|bottom of the listings|last of all|on the books outranks|bottom tier|lowest|loses to")
_HIGH = (r"piping-hot|tropical|well-tended|blooming|most damp-prone|condensation-prone|boiling|heated|most alive|"
         r"healthiest|swampiest|sweatiest|heads the listings|first of all|outranks every other|top tier|highest|"
         r"beats every other")


def reading_of(text: str) -> str:
    t = text.lower()
    if re.search(r"ndvi|well-tended|blooming|neglected|tired-looking|alive|healthiest|deadest|dyin", t):
        return "ndvi"
    if re.search(r"humid|damp|condensation|moisture|swamp|sweat|dried out|%|per ?cent|pct", t):
        return "humidity_pct"
    if re.search(r"temp|piping|tropical|bracing|ice-cold|boiling|heated|freezing|frozen|°|deg|\dc\b", t):
        return "temperature_c"
    return "?"


@SETTINGS
@given(c=constraints(), seed=st.integers(0, 2**31))
def test_sensor_phrase_denotes_the_written_constraint(c, seed):
    rendered = T.render_sensor_train2(np.random.default_rng(seed), c)
    check_sensor(rendered, c, comparator_of, _LOW, r"°|degree|\bdegs?\b|\dc\b", r"%|per ?cent|pct", numbers_in,
                 reading_of)
    text = (rendered[0] + " " + rendered[1]).strip()
    assert "(" not in text and "  " not in text, text
    if c.is_superlative:
        assert bool(re.search(_HIGH, text)) == (c.comparator == "max"), text
    elif not rendered[2].unit:  # a number without a unit always has its reading named
        assert re.search(r"temp|humidity|ndvi", text.lower()), text


@SETTINGS
@given(c=constraints(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_sensor_goal_keeps_the_phrase_after_the_head(c, sg, seed):
    check_sensor_goal(T.render_sensor_train2, T.render_goal_train2, c, sg, seed, numbers_in)


@SETTINGS
@given(c=constraints(), sg=subgoals(), x=st.floats(-20, 40).map(lambda v: round(v, 1)),
       y=st.floats(-20, 40).map(lambda v: round(v, 1)), seed=st.integers(0, 2**31))
def test_a_goal_with_sensor_and_hint_ends_on_the_coordinates(c, sg, x, y, seed):
    rng = np.random.default_rng(seed)
    prefix, tail, _ = T.render_sensor_train2(rng, c)
    hint = T.hint_text_train2(rng, f"{x:.1f}", f"{y:.1f}")
    text = T.render_goal_train2(rng, sg, prefix=prefix, tail=tail, hint=hint)
    nums = numbers_in(text)
    assert nums[-2:] == [pytest.approx(x), pytest.approx(y)] and len(nums) == 2 + (not c.is_superlative), text
    assert ") (" not in text and max(_depths(text), default=0) <= 1 and text.count("(") == text.count(")"), text


def _many(c: SensorConstraint, n: int) -> list[tuple[str, str, SensorConstraint]]:
    """A phrase for each of n fresh generators (one generator keeps one voice until an instruction is written)."""
    return [T.render_sensor_train2(np.random.default_rng(s), c) for s in range(n)]


def test_every_comparator_idiom_number_and_unit_form_is_used():
    for cmp in ("gt", "ge", "lt", "le", "approx"):
        for rd, v in (("temperature_c", -4.0), ("humidity_pct", 40.0), ("ndvi", 0.65), ("temperature_c", 20.5)):
            texts = {t for _, t, _ in _many(SensorConstraint(rd, cmp, v), 150)}
            assert {comparator_of(t) for t in texts} == {cmp}, (cmp, texts)
            assert all(numbers_in(t) == [pytest.approx(v)] for t in texts), texts
            assert len(texts) > 8, texts
    cold = {t for _, t, _ in _many(SensorConstraint("temperature_c", "ge", -4.0), 300)}
    for rx in (r"minus four", r"minus 4\b", r"neg 4\b", r"(?<!\w)-4\b", r"°C", r"degrees Celsius", r" degs\b",
               r"\d°", r"4c\b", r"4c\+", r"whose temperature", r"w temp"):
        assert any(re.search(rx, t) for t in cold), rx
    half = {t for _, t, _ in _many(SensorConstraint("temperature_c", "lt", 20.5), 200)}
    assert any("twenty and a half" in t for t in half) and any("20 and a half" in t for t in half)
    pct = {t for _, t, _ in _many(SensorConstraint("humidity_pct", "le", 40.0), 200)}
    for rx in (r"%", r" per cent", r" percent", r" pct"):
        assert any(rx in t for t in pct), rx
    ndvi = {t for _, t, _ in _many(SensorConstraint("ndvi", "approx", 0.65), 100)}
    assert any(re.search(r"(?<!\d)\.65", t) for t in ndvi) and any("0.65" in t for t in ndvi)
    for rd in ("temperature_c", "humidity_pct", "ndvi"):
        for cmp in ("max", "min"):
            sup = _many(SensorConstraint(rd, cmp), 200)
            assert len({p for p, _, _ in sup if p}) == 4 and len({t for _, t, _ in sup if t}) == 6, (rd, cmp)
            assert all(reading_of(p + " " + t) == rd for p, t, _ in sup), (rd, cmp)


# ----------------------------------------------------------------------------------------------------
# Coordinates and whole instructions


@SETTINGS
@given(x=st.floats(-20, 40).map(lambda v: round(v, 1)), y=st.floats(-20, 40).map(lambda v: round(v, 1)),
       seed=st.integers(0, 2**31))
def test_coordinates_read_back_x_then_y(x, y, seed):
    check_coordinates(T.hint_text_train2, T.render_goal_train2, T.render_instruction_train2, x, y, seed)


STRICT_CUES = r"strictly in the order listed|in the order set out|that exact order|mix up the order"
FREE_CUES = r"whichever sequence you prefer|any particular order|whatever order|order doesnt matter"


@SETTINGS
@given(sgs=st.lists(subgoals(), min_size=2, max_size=5, unique_by=lambda s: s.target.head),
       seed=st.integers(0, 2**31), strict=st.booleans())
def test_strict_and_free_are_told_apart_and_goals_stay_whole_in_order(sgs, seed, strict):
    check_order(T.render_goal_train2, T.render_instruction_train2, sgs, seed, strict, STRICT_CUES, FREE_CUES)
    rng = np.random.default_rng(seed)
    res = [T.render_goal_train2(rng, sg) for sg in sgs]
    text = T.render_instruction_train2(rng, res, "strict" if strict else "free")
    assert re.search(STRICT_CUES if strict else FREE_CUES, text.lower()), text
    at = 0
    for r in res:  # every goal once, whole, in visiting order
        m = re.compile(re.escape(r) + r"(?![\w-])").search(text, at)
        assert m, (r, text)
        at = m.end()


def test_both_voices_every_frame_and_a_single_goal():
    res = ["the teal bean bag in the nursery", "the kettle", "the toaster"]
    texts = {order: [T.render_instruction_train2(np.random.default_rng(s), res, order) for s in range(120)]
             for order in ("strict", "free")}
    for order, cues in (("strict", STRICT_CUES), ("free", FREE_CUES)):
        got = {c for t in texts[order] for c in re.findall(cues, t.lower())}
        assert got == set(cues.split("|")), set(cues.split("|")) - got
    every = texts["strict"] + texts["free"]
    for rx in (r"^VIEWING ITINERARY", r"step through to", r"^KEY FEATURES", r"open house", r"^ok so\nfirst: ",
               r"^hey can u go to", r"^stuff to check rn:\n- ", r"^can u hit"):
        assert any(re.search(rx, t) for t in every), rx
    singles = [T.render_instruction_train2(np.random.default_rng(s), res[:1], "strict") for s in range(60)]
    for rx in (r"single-feature viewing", r"just the one to show you", r"^just go to", r"^only need u at"):
        assert any(re.search(rx, t.lower()) for t in singles), rx
    assert not any(re.search(STRICT_CUES + "|" + FREE_CUES, t.lower()) or re.search(r"\d", t) for t in singles)
