"""Fourth development phrasings (episodes.split=unseen_dev4): deterministic; every head noun, attribute, state, room and
anchor written; relations and superlative scopes kept; numbers and coordinates read back by an independent reader;
strict/free wording told apart; punctuation clean in each of the three typing styles (proper sentences, no final
stop, all lower case)."""

import re

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from phrasing_fixtures import SENSORS as _sensors
from phrasing_fixtures import STATES, T, gen
from phrasing_fixtures import phrases as _phrases
from phrasing_fixtures import word as _word

from ragnav_jax.language.phrasings_dev4 import (
    hint_text_dev4,
    render_goal_dev4,
    render_instruction_dev4,
    render_sensor_dev4,
)
from ragnav_jax.language.types import RELATION_TYPES, SensorConstraint, Subgoal

HEADS = ("lamp", "sofa", "kettle", "fern", "coffee machine", "hi-fi speaker", "heater", "drums", "night-light")
MODS = ("red", "oak", "gold-framed", "grey fabric", "king-size", "teal")
ROOMS = ("kitchen", "living room", "games room", "pantry")


# ----------------------------------------------------------------------------------------------------
# An independent reader of amounts: "-18", "50.0", ".6", "minus 18", "negative 0.2", "fifty-five",
# "18 degrees below zero", "3.5m".

_W = {w: i for i, w in enumerate(
    "zero one two three four five six seven eight nine ten eleven twelve thirteen fourteen fifteen sixteen "
    "seventeen eighteen nineteen".split())}
_W.update({w: 10 * k for k, w in enumerate("twenty thirty forty fifty sixty seventy eighty ninety".split(), 2)})
_NW = "|".join(sorted(_W, key=len, reverse=True))
_NUMBER = re.compile(rf"(?<![\w.])(?P<sign>minus |negative |-)?(?P<n>\d+(?:\.\d+)?|\.\d+|(?:{_NW})(?:-(?:{_NW}))?)"
                     rf"(?![\d]|\.\d|[a-ln-z-])(?P<below> degrees below zero)?")


def read_numbers(text):
    text = re.sub(r"\bthe ones?\b", "the", text)  # "(the one that's over 50 degrees)" is not a number
    out = []
    for m in _NUMBER.finditer(text):
        n = m.group("n")
        v = float(n) if n[0].isdigit() or n[0] == "." else float(sum(_W[p] for p in n.split("-")))
        out.append(-v if (m.group("sign") or m.group("below")) else v)
    return out


def test_reader_itself():
    assert read_numbers("minus 18 C and negative 0.25, -3") == [-18.0, -0.25, -3.0]
    assert read_numbers("fifty-five degrees, .6 and 0.60, 50.0°C") == [55.0, 0.6, 0.6, 50.0]
    assert read_numbers("colder than 18 degrees below zero, at x 3.5m, y -2m") == [-18.0, 3.5, -2.0]
    assert read_numbers("the heater in the pantry (the one that's over 30% humidity)") == [30.0]


# Comparator cues, written down independently of the renderer's tables.
_CUES = {"gt": ("over", "above", "more than", "higher than", "greater than", "hotter than", "warmer than", ">"),
         "ge": ("at least", "or more", "or higher", "or above", "no less than", "not below", "or hotter", "or warmer",
                "no cooler than", ">="),
         "lt": ("under", "below", "less than", "lower than", "colder than", "cooler than", "<"),
         "le": ("at most", "or less", "or lower", "or below", "no more than", "not above", "or colder", "or cooler",
                "no warmer than", "<="),
         "approx": ("about", "around", "roughly", "approximately", "or so", "~")}
_CUE_RE = re.compile("|".join(rf"(?<!\w){re.escape(c)}(?!\w)" if c[0].isalpha() else re.escape(c)
                              for c in sorted((c for cs in _CUES.values() for c in cs), key=len, reverse=True)))
_CUE_OF = {c: k for k, cs in _CUES.items() for c in cs}


def comparators(text):
    return [_CUE_OF[m.group(0)] for m in _CUE_RE.finditer(text.replace("degrees below zero", "degrees"))]


_DEGREE = re.compile(r"°|\bdegrees?\b|Celsius|\d ?C\b")
_HIGH = ("highest", "hottest", "warmest", "most humid", "dampest", "healthiest", "greenest")
_LOW = ("lowest", "coldest", "coolest", "driest", "least humid", "least healthy", "unhealthiest")


@pytest.mark.parametrize("reading,values", [
    ("temperature_c", [-24.0, -18.0, 0.0, 7.0, 20.0, 57.5, 60.0, 65.0, 99.0, 120.0, 950.0]),
    ("humidity_pct", [5.0, 30.0, 65.0, 100.0]),
    ("ndvi", [-0.25, -0.2, 0.0, 0.05, 0.2, 0.6, 0.65, 1.0]),
])
def test_sensor_text_denotes_the_written_constraint(reading, values):
    rng = gen(1)
    frames = set()
    for v in values:
        for cmp_ in ("gt", "ge", "lt", "le", "approx"):
            for _ in range(16):
                prefix, tail, w = render_sensor_dev4(rng, SensorConstraint(reading, cmp_, v))
                assert prefix == "" and (w.reading, w.comparator, w.value) == (reading, cmp_, v), tail
                assert read_numbers(tail) == [v], tail
                assert comparators(tail) == [cmp_], tail
                assert tail.startswith(("that's ", "with ", "whose ")), tail
                frames.add(tail.split()[0])
                if reading == "temperature_c":
                    named = re.search(r"\btemp(erature)?\b|hotter|warmer|colder|cooler", tail)
                    assert w.unit in ("c", "") and (w.unit == "c") == bool(_DEGREE.search(tail)), tail
                    assert named or w.unit == "c", tail  # the reading is named or the unit says it
                elif reading == "humidity_pct":
                    assert w.unit == "%" and re.search(r"%|percent|per cent", tail) and "humidity" in tail, tail
                else:
                    assert w.unit == "" and "NDVI" in tail and not re.search(r"%|degree|°", tail), tail
    assert frames == {"that's", "with", "whose"} or (reading != "temperature_c" and frames == {"with", "whose"})
    for cmp_ in ("max", "min"):
        seen = set()
        for _ in range(80):
            prefix, tail, w = render_sensor_dev4(rng, SensorConstraint(reading, cmp_))
            assert w == SensorConstraint(reading, cmp_) and bool(prefix) != bool(tail)
            seen.add("prefix" if prefix else tail.split()[0])
            text = f" {prefix}{tail} "
            assert any(re.search(_word(e), text) for e in (_HIGH if cmp_ == "max" else _LOW)), text
            assert not any(re.search(_word(e), text) for e in (_LOW if cmp_ == "max" else _HIGH)), text
        assert seen == {"prefix", "whichever", "with", "whose", "that's"}


@pytest.mark.parametrize("head", ["heater", "appliance", "drums"])
def test_superlatives_keep_their_scope(head):
    """The room (and any anchor) is always inside what the extreme ranges over: 'the hottest heater in the
    pantry', 'whichever heater in the pantry has the highest temp', never 'the heater in the pantry with the
    highest temp' (the pantry's?) nor 'the heater in the pantry that's the hottest'."""
    rng = gen(5)
    forms = set()
    for k in range(300):
        room = ROOMS[k % 4] if k % 3 else None
        rels = [("next_to", T("sofa", ("teal",)))] if k % 5 == 0 else []
        c = SensorConstraint(("temperature_c", "ndvi", "humidity_pct")[k % 3], ("max", "min")[k % 2])
        prefix, tail, _ = render_sensor_dev4(rng, c)
        g = render_goal_dev4(rng, Subgoal(0, T(head, (), rels), room=room), prefix, tail)
        assert re.search(_word(head), g), g
        assert any(re.search(_word(e), g) for e in (_HIGH if c.comparator == "max" else _LOW)), g
        assert not any(re.search(_word(e), g) for e in (_LOW if c.comparator == "max" else _HIGH)), g
        restricted = room or rels
        if room:
            assert f"in the {room}" in g, g
            assert not re.search(rf"{room} (that|which|whose|with)\b", g), g
        if restricted:
            sup = r"(hottest|warmest|coldest|coolest|most humid|dampest|driest|least humid|healthiest|greenest|" \
                  r"least healthy|unhealthiest)"
            ok = (re.match(rf"the {sup} {head}\b", g)
                  or re.match(rf"whichever {head} .* (is|are) (the )?{sup}$", g)
                  or re.match(rf"whichever {head} .* (has|have) the (highest|lowest) \w+", g))
            assert ok, g
        if head == "drums":  # agreement: "whichever drums ... are hottest", "the drums that are the hottest"
            assert not re.search(r"drums (that |which )?(is|has)\b|drums that's", g), g
            assert not (g.startswith("whichever") and re.search(r" (is|has) (the )?[\w ]+$", g)), g
        forms.add("whichever" if g.startswith("whichever") else "adj" if re.match(r"the (\w+est|most|least)", g)
                  else "tail")
    assert forms == {"whichever", "adj", "tail"}


def test_hints_carry_the_given_numbers():
    rng = gen(2)
    for x, y in (("3.5", "2"), ("-1.2", "0.0"), ("10", "-4.25"), ("17.1", "9.8"), ("0.5", "-3")):
        forms = set()
        for _ in range(80):
            h = hint_text_dev4(rng, x, y)
            assert read_numbers(h) == [float(x), float(y)], h
            assert re.findall(r"\b[xy]\b", h) in ([], ["x", "y"]), h  # named axes come x first, like the numbers
            assert h.split()[0] in ("at", "around"), h
            forms.add(_NUMBER.sub("#", h))
        assert len(forms) >= 8, forms


# ----------------------------------------------------------------------------------------------------
# Goals: every piece of the ground truth is written


@pytest.mark.parametrize("state", STATES)
def test_goals_write_every_attribute_state_and_room(state):
    forms = set()
    for seed in range(40):
        rng = gen(seed)
        head = HEADS[seed % len(HEADS)]
        mods = (MODS[seed % len(MODS)],) if seed % 3 else ()
        rels = [("near", T("sofa", ("teal",)))] if seed % 4 == 1 else []
        room = ROOMS[seed % 4] if seed % 2 else None
        sg = Subgoal(0, T(head, (*mods, state), rels), room=room)
        g = render_goal_dev4(rng, sg)
        assert g.startswith("the "), g
        assert re.search(_word(head), g) and re.search(_word(state), g), g
        assert all(re.search(_word(m), g) for m in mods) and (room is None or f"in the {room}" in g), g
        if rels:
            assert "the teal sofa" in g and g.index("the teal sofa") > g.index(head), g  # the anchor comes after
        if room:  # nothing after the room can be read as the room's ("the pantry that's empty")
            assert not re.search(rf"{room} (that|which|whose)\b", g), g
        forms.add("before" if g.index(state) < g.index(head) else "after")
    assert forms == {"before", "after"} or state.startswith("switched")


# What each relation may be called, independently of the renderer; "{a}" the anchor.
_REL_WORDS = {
    "near": [r"(near|close to|not far from) {a}"],
    "next_to": [r"next to {a}"],
    "beside": [r"beside {a}"],
    "by": [r"\bby {a}"],
    "on": [r"\b(on|on top of) {a}"],
    "under": [r"(under|underneath|beneath) {a}"],
    "above": [r"above {a}"],
    "in": [r"\b(in|inside) {a}"],
    "with": [r"with {a}", r"{a} on (it|them) or near", r"{a} on or near (it|them)", r"on or near (it|them) {a}"],
    "in_room_with": [r"in the same room as {a}", r"in the room with {a}", r"in the room where {a} (is|are)\b"],
    "in_front_of": [r"in front of {a}"],
    "behind": [r"behind {a}"],
    "opposite": [r"(opposite|across from|facing) {a}"],
    "left_of": [r"(to|on) the left of {a}"],
    "right_of": [r"(to|on) the right of {a}"],
}


@pytest.mark.parametrize("rtype", RELATION_TYPES)
def test_relations_keep_their_meaning(rtype):
    forms = set()
    for seed in range(60):
        rng = gen(seed)
        nested = seed % 3 == 0
        anchor = T("sofa", ("grey fabric",), [("on", T("rug"))] if nested else [])
        a = r"whichever grey fabric sofa (is|sits|stands) (on|on top of|sitting on) the rug" if nested \
            else "the grey fabric sofa"
        head = ("lamp", "drums")[seed % 2]
        room = "pantry" if seed % 4 == 1 else None
        g = render_goal_dev4(rng, Subgoal(0, T(head, (), [(rtype, anchor)]), room=room))
        hits = [p for p in _REL_WORDS[rtype] if re.search(p.format(a=a), g)]
        assert hits, g
        forms.add(hits[0])
        if nested:  # the anchor's own relation is closed off inside "whichever ..." and comes last
            assert g.endswith("the rug"), g
        if head == "drums":  # agreement: a plural head takes plural verbs
            assert not re.search(r"drums (that |which )?(is|has|sits|stands)\b|drums that's", g), g
    assert len(forms) == len(_REL_WORDS[rtype])


def test_room_and_readings_never_share_a_phrase():
    """A reading after a room is in a coordinated clause of the goal ('that's in the pantry and over 50 degrees')
    or an apposition '(the one ...)': never 'the pantry whose humidity ...' (the reading would be the room's)."""
    rng = gen(9)
    forms = set()
    for k in range(300):
        room = ROOMS[k % 4]
        c = SensorConstraint(("temperature_c", "humidity_pct", "ndvi")[k % 3], ("gt", "ge", "lt", "le", "approx")[k % 5],
                             (40.0, 55.0, 0.6)[k % 3])
        prefix, tail, w = render_sensor_dev4(rng, c)
        g = render_goal_dev4(rng, Subgoal(0, T("heater"), room=room), prefix, tail)
        assert not re.search(rf"{room} (that|which|whose|with|\d)", g), g
        assert read_numbers(g) == [w.value], g
        forms.add("paren" if "(the one" in g else "clause")
    assert forms == {"paren", "clause"}


# ----------------------------------------------------------------------------------------------------
# Instructions

_STRICT = (" then", "first", "after that", "once you're done", "when that's done", "in order", "in this order",
           "before you", "finally", "lastly", "end up at")
_FREE = ("any order", "order doesn't matter", "what order", "whatever order", "which order", "no particular order",
         "whichever order", "order's up to you")


def _clean(text):
    bad = ("  ", ",,", ", ,", "()", "( ", " )", " ,", ",.", ",;", ";;", ",?", " ;", " ?", "..", "?.", ".?",
           ";,", "!.", ":,")
    return not any(b in text for b in bad) and not re.search(r" \.(\s|$)", text) and text == text.strip()


def _style_ok(text):
    """Proper sentences, sentences without the final stop, or all lower case: never a lower-case sentence start
    in a text that uses capitals."""
    if text == text.lower():
        return True
    return text[0].isupper() and not re.search(r"[.?!] [a-z]", text)


@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_strict_and_free_wording(n):
    rng = gen(n)
    goals = [render_goal_dev4(rng, Subgoal(0, T(h, ("teal", "switched off")), room="pantry")) for h in HEADS[:n]]
    strict_forms, free_forms, styles = set(), set(), set()
    for _ in range(120):
        for order in ("strict", "free"):
            text = render_instruction_dev4(rng, goals, order)
            low = text.lower()
            assert all(g.lower() in low for g in goals), text
            assert _clean(text) and _style_ok(text), text
            styles.add("lower" if text == low else "stop" if text[-1] in ".?!" else "open")
            if n == 1:
                rest = low.replace(goals[0].lower(), "#")
                assert not any(c in rest for c in _FREE) and rest.count("#") == 1, text
                continue
            pos = [low.index(g.lower()) for g in goals]
            if order == "strict":
                assert any(c in low for c in _STRICT) and not any(c in low for c in _FREE), text
                if re.search(r"before you|, but .* first[.!?]?$", low):
                    assert n == 2 and pos == sorted(pos, reverse=True), text  # the two reversed mentions
                else:
                    assert pos == sorted(pos), text  # the goals are written in visiting order
                strict_forms |= {c for c in _STRICT if c in low}
            else:
                assert any(c in low for c in _FREE) and not any(c in low for c in _STRICT), text
                free_forms |= {c for c in _FREE if c in low}
    assert styles == {"lower", "stop", "open"}
    if n > 1:
        assert len(strict_forms) >= 6 and len(free_forms) >= 6


def test_reversed_mentions_keep_the_visiting_order():
    """'Before you check B, check A' and 'Check B, but check A first' mention B first: A is still the first goal."""
    rng = gen(4)
    seen = set()
    for _ in range(400):
        low = render_instruction_dev4(rng, ["the lamp", "the sofa"], "strict").lower()
        if re.search(r"before you .*the sofa, .*the lamp", low):
            seen.add("before")
        elif re.search(r"the sofa, but .*the lamp first", low):
            seen.add("but first")
        else:
            assert low.index("the lamp") < low.index("the sofa"), low
    assert seen == {"before", "but first"}


def test_busy_goals_are_listed_with_their_own_verbs():
    """In a free list, a goal with an anchor is never followed by a bare 'and the ...' (which could be read as a
    second anchor): each goal after it gets its own verb."""
    rng = gen(11)
    goals = ["the lamp next to the sofa", "the rug"]
    for _ in range(100):
        low = render_instruction_dev4(rng, goals, "free").lower()
        assert "the sofa and the rug" not in low and "the sofa, and the rug" not in low, low


_targets = st.recursive(
    st.builds(T, st.sampled_from(HEADS), st.lists(st.sampled_from(MODS + STATES), max_size=3, unique=True)),
    lambda inner: st.builds(T, st.sampled_from(HEADS), st.lists(st.sampled_from(MODS + STATES), max_size=2,
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
        prefix, tail, written = render_sensor_dev4(rng, sensor) if sensor else ("", "", None)
        x = f"{rng.uniform(-9, 9):.1f}"
        hint = hint_text_dev4(rng, x, "2") if hinted else ""
        sg = Subgoal(0, target, room=room, sensors=(written,) if written else ())
        g = render_goal_dev4(rng, sg, prefix, tail, hint)
        assert _clean(g) and g.startswith(("the ", "whichever ")) and not g.endswith((",", ";")), g
        assert all(re.search(_word(p), g) for p in _phrases(target)), g
        assert room is None or f"in the {room}" in g, g
        nums = read_numbers(g)
        want = ([written.value] if written and written.value is not None else []) + ([float(x), 2.0] if hinted else [])
        assert sorted(nums) == sorted(want), g
        texts.append(g)
    text = render_instruction_dev4(rng, texts, order)
    assert _clean(text) and _style_ok(text), text
    assert all(g.lower() in text.lower() for g in texts), text


def test_determinism():
    sg = Subgoal(0, T("lamp", ("red", "switched on"), [("next_to", T("sofa", ("grey fabric",)))]), room="pantry")
    for c in (SensorConstraint("temperature_c", "gt", 60.0), SensorConstraint("ndvi", "max")):
        for seed in range(20):
            def run(rng, c=c):
                p, t, w = render_sensor_dev4(rng, c)
                goals = [render_goal_dev4(rng, sg, p, t, hint_text_dev4(rng, "3.5", "2")) for _ in range(3)]
                return (p, t, w, goals, render_instruction_dev4(rng, goals, "strict"),
                        render_instruction_dev4(rng, goals, "free"))
            assert run(gen(seed)) == run(gen(seed))
