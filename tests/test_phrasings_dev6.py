"""Sixth development phrasings (episodes.split=unseen_dev6: written task notes and formal requests): deterministic;
every head noun, attribute, state, room and anchor written; relations and superlative scopes kept; numbers with
formal units and coordinates read back by an independent reader; strict/free wording told apart; goals written
verbatim and in visiting order."""

import re

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from phrasing_fixtures import SENSORS as _sensors
from phrasing_fixtures import STATES, T, gen, target_strategy
from phrasing_fixtures import phrases as _phrases
from phrasing_fixtures import word as _word

from ragnav_jax.language.phrasings_dev6 import (
    hint_text_dev6,
    render_goal_dev6,
    render_instruction_dev6,
    render_sensor_dev6,
)
from ragnav_jax.language.types import RELATION_TYPES, SensorConstraint, Subgoal

HEADS = ("lamp", "sofa", "amplifier", "snake plant", "coffee machine", "hi-fi speaker", "heater", "drums",
         "night-light", "ping-pong table")
MODS = ("red", "oak", "gold-framed", "grey fabric", "king-size", "teal", "lacquered")
ROOMS = ("kitchen", "living room", "games room", "pantry", "laundry room")


# ----------------------------------------------------------------------------------------------------
# An independent reader of numbers as a formal note writes them: digits with an optional sign and decimals
# ("22.5 °C", "40 %", "0.30", "x = -1.20 m", "(3.5 m, 2.0 m)"); list markers "(1)" / "1." are not amounts.

_NUMBER = re.compile(r"(?<![\w.\d-])-?\d+(?:\.\d+)?")
_MARKER = re.compile(r"\(\d\)|(?:(?<=^)|(?<=\): )|(?<=\. ))\d\. ")


def read_numbers(text):
    return [float(m) for m in _NUMBER.findall(_MARKER.sub(" ", text))]


def test_reader_itself():
    assert read_numbers("a temperature of 22.5 °C, a relative humidity of 40 % and 40.0%") == [22.5, 40.0, 40.0]
    assert read_numbers("at coordinates x = -1.20 m, y = 2.00 m; at position (3.5 m, 0 m).") == [-1.2, 2.0, 3.5, 0.0]
    assert read_numbers("an NDVI value of -0.25 and 0.30; below -18 °C") == [-0.25, 0.3, -18.0]
    text = "Task list (in the order given): 1. Inspect the hi-fi speaker. 2. Visit (1) the lamp; (2) the heater at x: 3.5, y: 2."
    assert read_numbers(text) == [3.5, 2.0]


# Comparator cues, written down independently of the renderer's tables (longest first, so "not exceeding" is
# not read as "exceeding").
_CUES = {"gt": ("greater than", "in excess of", "exceeding", "exceeds", "above", "higher than", "more than"),
         "ge": ("at least", "no less than", "not less than", "or more", "not below", "does not fall below",
                "no lower than"),
         "lt": ("below", "less than", "lower than", "does not reach"),
         "le": ("not exceeding", "does not exceed", "at most", "no more than", "no greater than", "or less"),
         "approx": ("approximately", "about", "around", "roughly", "in the region of", "circa")}
_CUE_RE = re.compile("|".join(rf"(?<!\w){re.escape(c)}(?!\w)"
                              for c in sorted((c for cs in _CUES.values() for c in cs), key=len, reverse=True)))
_CUE_OF = {c: k for k, cs in _CUES.items() for c in cs}


def comparators(text):
    return [_CUE_OF[m.group(0)] for m in _CUE_RE.finditer(text)]


_HIGH = ("highest", "hottest", "warmest", "most humid")
_LOW = ("lowest", "coldest", "coolest", "driest", "least humid")
_LEADS = ("with ", "exhibiting ", "registering ", "showing ", "whose ")


@pytest.mark.parametrize("reading,values", [
    ("temperature_c", [-24.0, -18.0, 0.0, 7.0, 20.0, 22.5, 57.5, 60.0, 99.0, 120.0, 380.0, 950.0]),
    ("humidity_pct", [5.0, 30.0, 65.0, 100.0]),
    ("ndvi", [-0.25, -0.2, 0.0, 0.05, 0.2, 0.3, 0.6, 0.65, 1.0]),
])
def test_sensor_text_denotes_the_written_constraint(reading, values):
    rng = gen(1)
    forms = set()
    for v in values:
        for cmp_ in ("gt", "ge", "lt", "le", "approx"):
            for _ in range(16):
                prefix, tail, w = render_sensor_dev6(rng, SensorConstraint(reading, cmp_, v))
                assert prefix == "" and (w.reading, w.comparator, w.value) == (reading, cmp_, v), tail
                assert read_numbers(tail) == [v], tail
                assert comparators(tail) == [cmp_], tail
                assert tail.startswith(_LEADS) and not re.search(r"[;]|  ", tail), tail
                forms.add(tail.split()[0])
                if reading == "temperature_c":
                    assert w.unit == "c" and re.search(r"\d ?°C|\d degrees Celsius", tail), tail
                    assert "temperature" in tail, tail
                elif reading == "humidity_pct":
                    assert w.unit == "%" and re.search(r"\d ?%|\d per ?cent", tail) and "humidity" in tail, tail
                else:
                    assert w.unit == "" and "NDVI" in tail and not re.search(r"%|degree|°|per ?cent", tail), tail
    assert forms == {w.strip() for w in _LEADS}
    for cmp_ in ("max", "min"):
        seen = set()
        for _ in range(120):
            prefix, tail, w = render_sensor_dev6(rng, SensorConstraint(reading, cmp_))
            assert w == SensorConstraint(reading, cmp_) and bool(prefix) != bool(tail)
            assert read_numbers(prefix + tail) == [], tail
            seen.add("prefix" if prefix else tail.split()[0])
            text = f" {prefix}{tail} "
            assert any(re.search(_word(e), text) for e in (_HIGH if cmp_ == "max" else _LOW)), text
            assert not any(re.search(_word(e), text) for e in (_LOW if cmp_ == "max" else _HIGH)), text
        want = {"exhibiting", "with", "registering", "whose"} | ({"prefix"} if reading != "ndvi" else set())
        assert seen == want, seen


@pytest.mark.parametrize("head", ["heater", "appliance", "drums"])
def test_superlatives_keep_their_scope(head):
    """Room, states, coordinates and anchors are inside what the extreme ranges over: 'the warmest heater in the
    pantry' or 'the heater exhibiting the highest temperature among those in the pantry', never 'the heater in the
    pantry, which has the highest temperature'."""
    rng = gen(5)
    forms = set()
    for k in range(300):
        room = ROOMS[k % 4] if k % 3 else None
        rels = [("next_to", T("sofa", ("teal",)))] if k % 5 == 0 else []
        attrs = ("switched on",) if k % 7 == 0 else ()
        c = SensorConstraint(("temperature_c", "ndvi", "humidity_pct")[k % 3], ("max", "min")[k % 2])
        prefix, tail, _ = render_sensor_dev6(rng, c)
        g = render_goal_dev6(rng, Subgoal(0, T(head, attrs, rels), room=room), prefix, tail)
        assert re.search(_word(head), g), g
        assert any(re.search(_word(e), g) for e in (_HIGH if c.comparator == "max" else _LOW)), g
        assert not any(re.search(_word(e), g) for e in (_LOW if c.comparator == "max" else _HIGH)), g
        assert not re.search(r", (namely|which|that|whose)\b|\(", g), g  # no apposition or bracket: unclear scope
        restricted = room or rels or attrs
        if prefix:
            assert g.startswith(f"the {prefix} {head}"), g
            forms.add("adj")
        elif restricted:
            assert g.startswith(f"the {head} {tail} among those "), g
            after = g.split(" among those ", 1)[1]
            assert (room is None or f"in the {room}" in after) and (not rels or "the teal sofa" in after), g
            assert not attrs or "switched on" in after, g
            forms.add("among")
        else:
            assert g == f"the {head} {tail}", g
            forms.add("tail")
    assert forms == {"adj", "among", "tail"}


def test_hints_carry_the_given_numbers():
    rng = gen(2)
    for x, y in (("3.5", "2"), ("-1.2", "0.0"), ("10", "-4.25"), ("17.1", "9.8"), ("0.5", "-3"), ("14.1", "0")):
        forms = set()
        for _ in range(100):
            h = hint_text_dev6(rng, x, y)
            assert read_numbers(h) == [float(x), float(y)], h
            axes = re.findall(r"\b[xy]\b", h)
            assert axes in ([], ["x", "y"], ["x", "y", "x", "y"]), h  # named axes come x first, like the numbers
            assert h.startswith("at ") and h == h.strip() and ";" not in h, h
            assert re.search(r"\d( m)?(, | and )", h), h  # the two numbers are always kept apart
            forms.add(re.sub(r"-?[\d.]+", "#", h))
        assert len(forms) >= 12, forms


# ----------------------------------------------------------------------------------------------------
# Goals: every piece of the ground truth is written


@pytest.mark.parametrize("state", STATES)
def test_goals_write_every_attribute_state_and_room(state):
    forms = set()
    for seed in range(80):
        rng = gen(seed)
        head = HEADS[seed % len(HEADS)]
        mods = (MODS[seed % len(MODS)],) if seed % 3 else ()
        rels = [("near", T("sofa", ("teal",)))] if seed % 4 == 1 else []
        room = ROOMS[seed % 4] if seed % 2 else None
        sg = Subgoal(0, T(head, (*mods, state), rels), room=room)
        g = render_goal_dev6(rng, sg)
        assert g.startswith("the ") and g == g.lower() and ";" not in g, g
        assert re.search(_word(head), g) and re.search(_word(state), g), g
        assert all(re.search(_word(m), g) for m in mods) and (room is None or f"in the {room}" in g), g
        if rels:
            assert "the teal sofa" in g and g.rindex("the teal sofa") > g.index(head), g  # the anchor comes after
            assert g.rstrip(")").endswith("the teal sofa"), g  # nothing after an anchor can be read as its
        if room:
            assert not re.search(rf"{room},? (and )?(that|which|whose)\b", g), g
        forms.add("before" if g.index(state) < g.index(head) else "after")
    assert forms == {"before", "after"} or state.startswith("switched")


# What each relation may be called, independently of the renderer; "{a}" the anchor.
_REL_WORDS = {
    "near": [r"\b(near|close to|in the vicinity of|in close proximity to) {a}"],
    "next_to": [r"\b(next to|alongside) {a}"],
    "beside": [r"\bbeside {a}"],
    "by": [r"\bby {a}"],
    "on": [r"\b(on|on top of|rests on|resting on|placed on|sits on|sitting on) {a}"],
    "under": [r"\b(under|underneath|beneath|below) {a}"],
    "above": [r"\babove {a}"],
    "in": [r"\b(in|inside|contained in) {a}"],
    "with": [r"\bwith {a}"],
    "in_room_with": [r"\bin the same room as {a}", r"\bin the room with {a}",
                     r"\bin the room where {a} (stands?|(is|are) (located|situated))$"],
    "in_front_of": [r"\bin front of {a}"],
    "behind": [r"\bbehind {a}"],
    "opposite": [r"\b(opposite|across from|facing|faces?) {a}"],
    "left_of": [r"\b(to|on) the left(-hand side)? of {a}"],
    "right_of": [r"\b(to|on) the right(-hand side)? of {a}"],
}


@pytest.mark.parametrize("rtype", RELATION_TYPES)
def test_relations_keep_their_meaning(rtype):
    forms = set()
    for seed in range(120):
        rng = gen(seed)
        nested = seed % 3 == 0
        anchor = T("sofa", ("grey fabric",), [("on", T("rug"))] if nested else [])
        a = r"the grey fabric sofa (that|which) (is on|is on top of|rests on|is placed on|sits on) the rug" \
            if nested else "the grey fabric sofa"
        head = ("lamp", "drums")[seed % 2]
        room = "pantry" if seed % 4 == 1 else None
        g = render_goal_dev6(rng, Subgoal(0, T(head, (), [(rtype, anchor)]), room=room))
        hits = [p for p in _REL_WORDS[rtype] if re.search(p.format(a=a), g.rstrip(")"))]
        assert hits, g
        forms.add(hits[0])
        if nested:  # the anchor's own relation closes the goal: nothing can follow it
            assert g.rstrip(")").endswith("the rug"), g
        if head == "drums":  # agreement: a plural head takes plural verbs
            assert not re.search(r"drums (that |which )?(is|has|stands|rests|sits|faces)\b", g), g
    assert len(forms) == len(_REL_WORDS[rtype])


def test_two_clause_bearing_anchors_are_enumerated():
    """'the lamp which (i) stands next to the sofa that is on the rug and (ii) is under the shelf that is by the
    door': the second anchor cannot be read as the rug's or the sofa's."""
    rng = gen(3)
    for _ in range(40):
        t = T("lamp", (), [("next_to", T("sofa", (), [("on", T("rug"))])),
                           ("under", T("shelf", (), [("by", T("door"))]))])
        g = render_goal_dev6(rng, Subgoal(0, t, room="pantry"))
        assert re.search(r"\(i\) .*the rug,? and \(ii\) .*the door$|\(ii\) .*the rug,? and \(iii\) .*the door$", g), g
        assert g.index("pantry") < g.index("sofa"), g


def test_room_and_readings_never_share_a_phrase():
    """A threshold after a room is a coordinated predicate of the goal ('which is located in the pantry and has a
    temperature greater than 50 °C') or said first ('whose temperature exceeds 50 °C and which is in the pantry'):
    never 'the pantry whose ...' (the reading would be the room's)."""
    rng = gen(9)
    forms = set()
    for k in range(300):
        room = ROOMS[k % 4]
        c = SensorConstraint(("temperature_c", "humidity_pct", "ndvi")[k % 3],
                             ("gt", "ge", "lt", "le", "approx")[k % 5], (40.0, 55.0, 0.6)[k % 3])
        prefix, tail, w = render_sensor_dev6(rng, c)
        g = render_goal_dev6(rng, Subgoal(0, T("heater"), room=room), prefix, tail)
        assert not re.search(rf"{room},? (and )?(that|which|whose|with|exhibiting|registering|showing)\b", g), g
        assert read_numbers(g) == [w.value] and comparators(g) == [c.comparator], g
        forms.add(("whose" if "whose" in g else "") + ("which" if re.search(r"\b(which|that)\b", g) else ""))
    assert forms == {"which", "whosewhich"}


# ----------------------------------------------------------------------------------------------------
# Instructions

_STRICT = ("firstly", "secondly", "finally", "lastly", "subsequently", "thereafter", "upon completion", "prior to",
           "in the order given", "in the sequence listed", "in the following order", "in the first instance",
           "first")
_FREE = ("in an order of its choosing", "at the robot's discretion", "not prescribed", "in no prescribed order",
         "immaterial", "no particular sequence", "in whatever sequence", "left to the robot")
_PURPOSE = re.compile(r", (in order to|for|so that) [^;.()]*|\((for|this forms|no intervention)[^()]*\)")


def _has(text, cues):
    return [c for c in cues if re.search(rf"(?<![\w']){re.escape(c)}(?![\w'])", text)]


def _style(text):
    """A written note: capitalised, ends with a stop, sentences capitalised, tidy spacing."""
    assert text[0].isupper() and text.endswith(".") and not re.search(r"\. [a-z]", text), text
    assert not re.search(r"  |,,| ,| ;|;;|\.\.|;\.", text), text


@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_strict_and_free_wording(n):
    rng = gen(n)
    subs = [Subgoal(0, T(h, ("teal", "switched off")), room="pantry") for h in HEADS[:n]]
    strict_forms, free_forms = set(), set()
    for _ in range(200):
        goals = [render_goal_dev6(rng, s) for s in subs]
        for order in ("strict", "free"):
            text = render_instruction_dev6(rng, goals, order)
            low = text.lower()
            _style(text)
            assert all(g in text for g in goals), text  # verbatim: no goal begins a sentence
            rest = low
            for g in goals:
                rest = rest.replace(g, " # ")
            assert rest.count("#") == n, text
            cues_text = _PURPOSE.sub(" ", rest)
            if n == 1:
                assert not _has(cues_text, _FREE), text
                continue
            pos = [text.index(g) for g in goals]
            assert pos == sorted(pos), text  # the goals are always written in visiting order
            if order == "strict":
                assert _has(cues_text, _STRICT) and not _has(cues_text, _FREE), text
                strict_forms |= set(_has(cues_text, _STRICT))
            else:
                assert _has(cues_text, _FREE) and not _has(cues_text, _STRICT), text
                free_forms |= set(_has(cues_text, _FREE))
    if n > 1:
        assert len(strict_forms) >= 8 and len(free_forms) >= 6, (strict_forms, free_forms)


def test_goals_in_lists_are_kept_apart_and_passives_have_plain_subjects():
    """Goals are separated by semicolons, sentences or verbs, never by a bare 'and the ...' (which could read as a
    second anchor); a goal with a clause of its own is never the subject of a passive ('... that is on the rug is
    to be inspected' could read as the rug's)."""
    rng = gen(11)
    plain = ["the lamp next to the sofa", "the heater at position (3.5 m, 2.0 m)", "the rug"]
    clauses = ["the lamp next to the sofa", "the heater whose temperature exceeds 50 °C",
               "the lamp which is on the rug", "the rug"]
    passives = {"plain": 0, "clauses": 0}
    for _ in range(400):
        for name, goals in (("plain", plain), ("clauses", clauses), ("plain", plain[:1]), ("clauses", clauses[2:3])):
            for order in ("strict", "free"):
                text = render_instruction_dev6(rng, goals, order)
                assert not re.search(r"(sofa|°C|rug|\)),? and the\b", text), text
                passives[name] += any(f"{g} is to be" in text for g in goals)
    assert passives["plain"] > 20 and passives["clauses"] == 0, passives


def test_instruction_numbers_are_the_goals_numbers():
    rng = gen(4)
    goals = ["the heater with a temperature in excess of 30 °C", "the lamp at position (3.5 m, -2.0 m)",
             "the plant whose NDVI value is at least 0.30"]
    for _ in range(200):
        text = render_instruction_dev6(rng, goals, ("strict", "free")[int(rng.integers(2))])
        assert read_numbers(text) == [30.0, 3.5, -2.0, 0.3], text


_goals = st.tuples(target_strategy(HEADS, MODS), st.one_of(st.none(), st.sampled_from(ROOMS)), _sensors, st.booleans())


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(_goals, min_size=1, max_size=5), st.integers(0, 2**31), st.sampled_from(("strict", "free")))
def test_renderers_never_raise_and_write_every_piece(goals, seed, order):
    rng = gen(seed)
    texts, want_all = [], []
    for target, room, sensor, hinted in goals:
        prefix, tail, written = render_sensor_dev6(rng, sensor) if sensor else ("", "", None)
        x = f"{rng.uniform(-9, 9):.1f}"
        hint = hint_text_dev6(rng, x, "2") if hinted else ""
        sg = Subgoal(0, target, room=room, sensors=(written,) if written else ())
        g = render_goal_dev6(rng, sg, prefix, tail, hint)
        assert g.startswith("the ") and not re.search(r"  |;", g) and g == g.strip(" ,"), g
        assert all(re.search(_word(p), g) for p in _phrases(target)), g
        assert room is None or f"in the {room}" in g, g
        nums = read_numbers(g)
        want = ([written.value] if written and written.value is not None else []) + ([float(x), 2.0] if hinted else [])
        assert sorted(nums) == sorted(want), g
        if written and not written.is_superlative:
            assert comparators(tail) == [written.comparator], g
        texts.append(g)
        want_all += nums
    text = render_instruction_dev6(rng, texts, order)
    _style(text)
    assert all(g in text for g in texts), text
    assert read_numbers(text) == want_all, text


def test_determinism():
    sg = Subgoal(0, T("lamp", ("red", "switched on"), [("next_to", T("sofa", ("grey fabric",)))]), room="pantry")
    for c in (SensorConstraint("temperature_c", "gt", 60.0), SensorConstraint("ndvi", "max")):
        for seed in range(20):
            def run(rng, c=c):
                p, t, w = render_sensor_dev6(rng, c)
                goals = [render_goal_dev6(rng, sg, p, t, hint_text_dev6(rng, "3.5", "2")) for _ in range(3)]
                return (p, t, w, goals, render_instruction_dev6(rng, goals, "strict"),
                        render_instruction_dev6(rng, goals, "free"))
            assert run(gen(seed)) == run(gen(seed))
