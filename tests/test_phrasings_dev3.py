"""Third development phrasings (unseen_dev3): deterministic, every head noun, attribute, room and anchor written, relations kept,
numbers that denote the written constraint and coordinates read back by an independent reader,
strict/free wording told apart, clean punctuation."""

import re

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from phrasing_fixtures import SENSORS as _sensors
from phrasing_fixtures import gen
from phrasing_fixtures import phrases as _phrases
from phrasing_fixtures import word as _word

from ragnav_jax.language.phrasings import STATE_VALUES
from ragnav_jax.language.phrasings_dev3 import (
    hint_text_dev3,
    render_goal_dev3,
    render_instruction_dev3,
    render_sensor_dev3,
)
from ragnav_jax.language.types import RELATION_TYPES, Relation, SensorConstraint, Subgoal, Target

HEADS = ("lamp", "sofa", "kettle", "fern", "coffee machine", "hi-fi speaker", "heater", "drums", "night-light")
MODS = ("red", "oak", "gold-framed", "grey fabric", "king-size", "teal")
ROOMS = ("kitchen", "living room", "games room", "pantry")


def T(head, attrs=(), rels=()):
    return Target(" ".join(a for a in (*attrs, head)), head, tuple(attrs), tuple(Relation(t, a) for t, a in rels))


# ----------------------------------------------------------------------------------------------------
# An independent reader of amounts: "-18", "60.0", "minus 18", "negative 0.25", "sixty-five", "one hundred and
# twenty", "zero point six five", "point six", "18 degrees below zero", "sixty-ish", "the 60-degree mark".

_W = {w: i for i, w in enumerate(
    "zero one two three four five six seven eight nine ten eleven twelve thirteen fourteen fifteen sixteen "
    "seventeen eighteen nineteen".split())}
_W.update({w: 10 * k for k, w in enumerate("twenty thirty forty fifty sixty seventy eighty ninety".split(), 2)})
_NUM_WORD = r"(?:" + "|".join(sorted(_W, key=len, reverse=True)) + r")"
_SPOKEN = (rf"(?:{_NUM_WORD} hundred(?: and {_NUM_WORD}(?:-{_NUM_WORD})?)?|{_NUM_WORD}(?:-{_NUM_WORD})?)"
           rf"(?: point(?: {_NUM_WORD})+)?|point(?: {_NUM_WORD})+")
_NUMBER = re.compile(rf"(?<![\w.])(?P<sign>minus |negative |-)?(?P<n>\d+(?:\.\d+)?|{_SPOKEN})(?!\.\d)(?![a-z0-9_-])"
                     rf"(?P<below> degrees below zero)?")


def _spoken_value(s):
    whole, _, frac = s.partition("point")
    whole = whole.strip()
    v = 0.0
    if whole:
        if " hundred" in whole:
            h, _, rest = whole.partition(" hundred")
            v = 100 * _W[h] + sum(_W[p] for p in rest.replace(" and ", "").strip().split("-") if p)
        else:
            v = sum(_W[p] for p in whole.split("-"))
    if frac:
        v += float("0." + "".join(str(_W[d]) for d in frac.split()))
    return v


def _prepare(text):
    """'any other one', '(the pantry one)' are not numbers; '60-ish', 'the 60-degree mark' are."""
    text = re.sub(r"\b(other|room|the \w+) one\b", r"\1", text)
    return text.replace("-ish", " ").replace("-degree", " degree")


def read_numbers(text):
    out = []
    for m in _NUMBER.finditer(_prepare(text)):
        n = m.group("n")
        v = float(n) if n[0].isdigit() else _spoken_value(n)
        if m.group("sign") or m.group("below"):
            v = -v
        out.append(v)
    return out


def test_reader_itself():
    assert read_numbers("minus 18 C and negative 0.25") == [-18.0, -0.25]
    assert read_numbers("one hundred and twenty degrees, sixty-five percent") == [120.0, 65.0]
    assert read_numbers("zero point six five, point three, eighteen degrees below zero") == [0.65, 0.3, -18.0]
    assert read_numbers("the sixty-degree mark, 40-ish percent, (x, y) = (3.5, -2)") == [60.0, 40.0, 3.5, -2.0]


# Comparator cues, written down independently of the renderer's tables.
_CUES = {"gt": ("north of", " past ", "above the", " > "), "ge": ("or greater", "and up", "at the very least", "≥", ">="),
         "lt": ("south of", "below the", " < "), "le": ("or under", "and under", "up to", "≤", "<="),
         "approx": ("give or take", "ballpark", "more or less", "-ish", "≈", "~")}
_NAMES = {"temperature_c": ("temp", "temperature"), "humidity_pct": ("humidity", "RH"), "ndvi": ("NDVI",)}
_DEGREE = ("C", "degC", "°", "degree", "degrees", "Celsius")
_HIGH = ("highest", "top", "warmest", "hottest", "greenest", "healthiest", "most humid", "dampest", "warmer",
         "hotter", "greener", "healthier", "more humid", "damper")
_LOW = ("lowest", "coldest", "coolest", "least healthy", "least green", "driest", "least humid", "colder", "cooler",
        "less healthy", "less green", "drier", "less humid")


def _cmp_of(text):
    t = f" {text} "
    t = t.replace("(", " ").replace(")", " ")
    return [c for c, cues in _CUES.items() if any(q in t for q in cues)]


@pytest.mark.parametrize("reading,values", [
    ("temperature_c", [-24.0, -18.0, 0.0, 7.0, 20.0, 57.5, 60.0, 65.0, 99.0, 120.0, 140.0, 950.0]),
    ("humidity_pct", [5.0, 30.0, 65.0, 70.0, 100.0]),
    ("ndvi", [-0.25, 0.0, 0.05, 0.2, 0.65, 0.7, 1.0]),
])
def test_sensor_text_denotes_the_written_constraint(reading, values):
    rng = gen(1)
    for v in values:
        for cmp_ in ("gt", "ge", "lt", "le", "approx"):
            for _ in range(16):
                prefix, tail, w = render_sensor_dev3(rng, SensorConstraint(reading, cmp_, v))
                assert prefix == "" and (w.reading, w.comparator, w.value) == (reading, cmp_, v), tail
                assert read_numbers(tail) == [v], tail
                assert _cmp_of(tail) == [cmp_], tail
                assert any(re.search(_word(n), tail) for n in _NAMES[reading]), tail
                words = re.findall(r"[A-Za-z°]+", tail)
                if reading == "temperature_c":
                    assert w.unit in ("c", "") and (w.unit == "c") == any(u in words or "°" in tail for u in _DEGREE), tail
                elif reading == "humidity_pct":
                    assert w.unit == "%" and ("%" in tail or "percent" in tail), tail
                else:
                    assert w.unit == "" and "%" not in tail and "degree" not in tail, tail
    for cmp_ in ("max", "min"):
        seen = set()
        for _ in range(80):
            prefix, tail, w = render_sensor_dev3(rng, SensorConstraint(reading, cmp_))
            assert w == SensorConstraint(reading, cmp_) and bool(prefix) != bool(tail)
            seen.add("prefix" if prefix else tail.split()[0])
            text = f" {prefix}{tail} "
            assert any(re.search(_word(e), text) for e in (_HIGH if cmp_ == "max" else _LOW)), text
            assert not any(re.search(_word(e), text) for e in (_LOW if cmp_ == "max" else _HIGH)), text
        assert seen >= {"prefix", "whichever", "that", "with", "whose"}


@pytest.mark.parametrize("head", ["heater", "appliance", "drums"])
def test_superlatives_keep_their_scope(head):
    rng = gen(5)
    forms = set()
    for k in range(200):
        room = ROOMS[k % 4] if k % 3 else None
        c = SensorConstraint(("temperature_c", "ndvi", "humidity_pct")[k % 3], ("max", "min")[k % 2])
        prefix, tail, _ = render_sensor_dev3(rng, c)
        g = render_goal_dev3(rng, Subgoal(0, T(head), room=room), prefix, tail)
        assert re.search(_word(head), g), g
        assert any(re.search(_word(e), g) for e in (_HIGH if c.comparator == "max" else _LOW)), g
        assert not any(re.search(_word(e), g) for e in (_LOW if c.comparator == "max" else _HIGH)), g
        if room:  # the room is always part of what the extreme ranges over, never an afterthought
            assert room in g, g
            assert re.search(rf"{room}'s|in the {room}|in there", g), g
        if g.startswith("whichever"):
            assert g.endswith(("est", "healthy", "green", "humid")) and (" are " in g) == (head == "drums"), g
        forms.add(g.split()[0] if g.startswith("whichever") else "poss" if "'s" in g else
                  "cmp" if "than any other" in g else "tail" if re.search(r"with the|whose", g) else "adj")
    assert forms >= {"whichever", "tail", "adj"} | ({"cmp"} if head != "drums" else set())


def test_hints_carry_the_given_numbers():
    rng = gen(2)
    for x, y in (("3.5", "2"), ("-1.2", "0.0"), ("10", "-4.25"), ("17.1", "9.8"), ("0.5", "-3")):
        forms = set()
        for _ in range(80):
            h = hint_text_dev3(rng, x, y)
            assert read_numbers(h) == [float(x), float(y)], h
            assert re.findall(r"\b[xy]\b", h) in ([], ["x", "y"]), h  # named axes come x first, like the numbers
            forms.add(_NUMBER.sub("#", h))
        assert len(forms) >= 6, forms


# ----------------------------------------------------------------------------------------------------
# Goals: every piece of the ground truth is written

@pytest.mark.parametrize("state", STATE_VALUES)
def test_goals_write_every_attribute_state_and_room(state):
    for seed in range(20):
        rng = gen(seed)
        head = HEADS[seed % len(HEADS)]
        mods = (MODS[seed % len(MODS)],) if seed % 3 else ()
        rels = [("near", T("sofa", ("teal",)))] if seed % 4 == 1 else []
        room = ROOMS[seed % 4] if seed % 2 else None
        sg = Subgoal(0, T(head, (*mods, state), rels), room=room)
        g = render_goal_dev3(rng, sg)
        assert re.search(_word(head), g) and re.search(_word(state), g), g
        assert all(re.search(_word(m), g) for m in mods) and (room is None or f"the {room}" in g or f"{room}'s" in g), g
        if rels:
            assert "the teal sofa" in g and g.index("the teal sofa") > g.index(head), g  # the anchor comes after


# What each relation may be called, independently of the renderer; "{a}" the anchor.
_REL_WORDS = {
    "near": [r"(a few steps from|a stone's throw from|near to) {a}"],
    "next_to": [r"(alongside|side by side with|directly next to) {a}"],
    "beside": [r"(at the side of|immediately beside) {a}"],
    "by": [r"(down by|just by) {a}"],
    "on": [r"(perched on|on top of|up on|stands? on) {a}"],
    "under": [r"(tucked under|below) {a}"],
    "above": [r"(up above|over) {a}"],
    "in": [r"(tucked inside|sitting in|sits within|within) {a}"],
    "with": [r"{a} (is|are) on or near", r"{a} rests? on or stands? near", r"{a} sits? on or close to",
             r"supports? or stands? near {a}"],
    "in_room_with": [r"in (whichever room|the room) {a} (is|are) in", r"in the room where you'll find {a}"],
    "in_front_of": [r"in front of {a}"],
    "behind": [r"(directly|tucked) behind {a}"],
    "opposite": [r"(directly opposite|straight across from) {a}"],
    "left_of": [r"(just left of|on the left of) {a}", r"to {a}'s left"],
    "right_of": [r"(just right of|on the right of) {a}", r"to {a}'s right"],
}


@pytest.mark.parametrize("rtype", RELATION_TYPES)
def test_relations_keep_their_meaning(rtype):
    forms = set()
    for seed in range(40):
        rng = gen(seed)
        nested = seed % 3 == 0
        anchor = T("sofa", ("grey fabric",), [("on", T("rug"))] if nested else [])
        head = ("lamp", "drums")[seed % 2]
        g = render_goal_dev3(rng, Subgoal(0, T(head, (), [(rtype, anchor)])))
        hits = [p for p in _REL_WORDS[rtype] if re.search(p.format(a="the grey fabric sofa"), g)]
        assert hits, g
        forms.add(hits[0])
        if nested:
            assert re.search(r"\brug\b", g) and g.index("rug") > g.index("sofa"), g
        # agreement: a plural head takes plural verbs
        if head == "drums":
            assert not re.search(r"drums (that |which )?(is|has|sits|stands|lives)\b", g), g
    assert len(forms) == len(_REL_WORDS[rtype]) or rtype == "with"


def test_room_and_readings_never_share_a_phrase():
    """A room before a sensor clause is a possessive or a clause of its own: 'the pantry that has a humidity
    ...' never occurs (the reading would be the room's)."""
    rng = gen(9)
    for k in range(300):
        room = ROOMS[k % 4]
        c = SensorConstraint(("temperature_c", "humidity_pct", "ndvi")[k % 3], ("gt", "ge", "lt", "le", "approx")[k % 5],
                             (40.0, 55.0, 0.6)[k % 3])
        prefix, tail, _ = render_sensor_dev3(rng, c)
        g = render_goal_dev3(rng, Subgoal(0, T("heater"), room=room), prefix, tail)
        assert not re.search(rf"{room} (that|which|whose|\()", g), g
        assert read_numbers(g) == [c.value], g
    for _ in range(200):  # states after a room in a clause: "the freezer in the pantry that's open" never occurs
        g = render_goal_dev3(rng, Subgoal(0, T("freezer", ("open",)), room="pantry"))
        assert not re.search(r"pantry (that|which)", g), g


# ----------------------------------------------------------------------------------------------------
# Instructions

_STRICT = (" first", " second", "start with", "finish with", "in the order listed", "in the order given",
           "keeping to this order", "step one", "next stop", "before you", "before ", "not until", "only then",
           "afterwards", "to begin with", "as listed")
_FREE = ("not fussed", "makes no difference", "no need to stick", "isn't important", "no special order",
         "flexible", "either one can come first", "shuffle the order", "free to choose")


@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_strict_and_free_wording(n):
    rng = gen(n)
    goals = [render_goal_dev3(rng, Subgoal(0, T(h, ("teal", "switched off")), room="pantry")) for h in HEADS[:n]]
    strict_forms, free_forms = set(), set()
    for _ in range(80):
        for order in ("strict", "free"):
            text = render_instruction_dev3(rng, goals, order)
            low = text.lower()
            assert all(g.lower() in low for g in goals), text
            assert text[0].isupper() and text[-1] in ".?", text
            if n == 1:
                rest = low.replace(goals[0].lower(), "")
                assert rest.count(".") + rest.count("?") == 1, text
                continue
            pos = [low.index(g.lower()) for g in goals]
            if order == "strict":
                assert any(c in low for c in _STRICT) and not any(c in low for c in _FREE), text
                if low.startswith("before") or "not until" in low:
                    assert n == 2, text  # the two reversed mentions (see below)
                else:
                    assert pos == sorted(pos), text  # the goals are written in visiting order
                strict_forms.add(next(c for c in _STRICT if c in low))
            else:
                assert sum(c in low for c in _FREE) == 1, text
                free_forms.add(next(c for c in _FREE if c in low))
    if n > 1:
        assert len(strict_forms) >= 6 and len(free_forms) >= 7


def test_reversed_mentions_keep_the_visiting_order():
    """'Before you go to B, go to A' and 'Go to B, but not until you've been to A' mention B first: A is
    still the first goal."""
    rng = gen(4)
    seen = set()
    for _ in range(300):
        text = render_instruction_dev3(rng, ["the lamp", "the sofa"], "strict")
        low = text.lower()
        m = re.search(r"before (you \w+|\w+ing)", low)
        if low.startswith("before"):
            seen.add("before")
            assert low.index("the sofa") < low.index("the lamp") and m, text
        elif "not until" in low:
            seen.add("not until")
            assert re.search(r"the sofa, but not until you've been to the lamp", low), text
        else:
            assert low.index("the lamp") < low.index("the sofa"), text
    assert seen == {"before", "not until"}


def _clean(text):
    bad = ("  ", ",,", ", ,", "()", "( )", " ,", ",.", ",;", ";;", ",?", " ;", " ?", " )", "( ", "..", ";,")
    return (not any(b in text for b in bad) and not re.search(r" \.(\s|$)|[.?] [a-z]", text)
            and text == text.strip())


_targets = st.recursive(
    st.builds(T, st.sampled_from(HEADS), st.lists(st.sampled_from(MODS + STATE_VALUES), max_size=3, unique=True)),
    lambda inner: st.builds(T, st.sampled_from(HEADS), st.lists(st.sampled_from(MODS + STATE_VALUES), max_size=2,
                                                                unique=True),
                            st.lists(st.tuples(st.sampled_from(RELATION_TYPES), inner), max_size=2)),
    max_leaves=4,
)
_goals = st.tuples(_targets, st.one_of(st.none(), st.sampled_from(ROOMS)), _sensors, st.booleans())


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(_goals, min_size=1, max_size=5), st.integers(0, 2**31), st.sampled_from(("strict", "free")))
def test_renderers_never_raise_and_write_clean_text(goals, seed, order):
    rng = gen(seed)
    texts = []
    for target, room, sensor, hinted in goals:
        prefix, tail, written = render_sensor_dev3(rng, sensor) if sensor else ("", "", None)
        x = f"{rng.uniform(-9, 9):.1f}"
        hint = hint_text_dev3(rng, x, "2") if hinted else ""
        sg = Subgoal(0, target, room=room, sensors=(written,) if written else ())
        g = render_goal_dev3(rng, sg, prefix, tail, hint)
        assert _clean(g) and g.startswith(("the ", "whichever ")) and not g.endswith((",", ";")), g
        assert all(re.search(_word(p), g) for p in _phrases(target)), g
        assert room is None or room in g, g
        nums = read_numbers(g)
        want = ([written.value] if written and written.value is not None else []) + ([float(x), 2.0] if hinted else [])
        assert sorted(nums) == sorted(want), g
        texts.append(g)
    text = render_instruction_dev3(rng, texts, order)
    assert _clean(text), text
    assert all(g in text or g[0].upper() + g[1:] in text for g in texts), text


def test_determinism():
    sg = Subgoal(0, T("lamp", ("red", "switched on"), [("next_to", T("sofa", ("grey fabric",)))]), room="pantry")
    for c in (SensorConstraint("temperature_c", "gt", 60.0), SensorConstraint("ndvi", "max")):
        for seed in range(20):
            def run(rng, c=c):
                p, t, w = render_sensor_dev3(rng, c)
                goals = [render_goal_dev3(rng, sg, p, t, hint_text_dev3(rng, "3.5", "2")) for _ in range(3)]
                return (p, t, w, goals, render_instruction_dev3(rng, goals, "strict"),
                        render_instruction_dev3(rng, goals, "free"))
            assert run(gen(seed)) == run(gen(seed))
