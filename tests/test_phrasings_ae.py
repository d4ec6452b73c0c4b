"""Set AE's own wording (ragnav_jax/language/phrasings_ae.py): the same seed writes the same text, and a small reader
written here from set AE's templates (not the project's parser) recovers from each goal, sensor phrase, coordinate
hint and instruction exactly what its arguments mean."""

from __future__ import annotations

import re

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ragnav_jax.language import phrasings_ae as ae
from ragnav_jax.language.template_text import ONES, TENS, hyphenated
from ragnav_jax.language.types import RELATION_TYPES, Relation, SensorConstraint, Subgoal, Target

HEADS = ("lamp", "sofa", "record player", "drums", "toy chest", "fern", "dehumidifier")
PRE = ("teal", "oak", "black metal", "vintage", "glossy", "white-painted")
STATES = ("switched on", "switched off", "open", "closed", "empty", "full")
ROOMS = ("kitchen", "living room", "bathroom", "study", "nursery")
FAST = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def make_target(head: str, pre: list[str], states: list[str], rels: tuple[Relation, ...] = ()) -> Target:
    return Target(" ".join([*pre, head]), head, (*pre, *states), rels)


@st.composite
def targets(draw, depth: int = 0) -> Target:
    head = draw(st.sampled_from(HEADS))
    pre = draw(st.lists(st.sampled_from(PRE), max_size=2, unique=True))
    states = draw(st.lists(st.sampled_from(STATES), max_size=1))
    rels: tuple[Relation, ...] = ()
    if depth < 2:
        n = draw(st.integers(0, 2 if depth == 0 else 1))
        rels = tuple(Relation(draw(st.sampled_from(RELATION_TYPES)), draw(targets(depth + 1))) for _ in range(n))
    return make_target(head, pre, states, rels)


@st.composite
def subgoals(draw) -> Subgoal:
    return Subgoal(0, draw(targets()), room=draw(st.none() | st.sampled_from(ROOMS)))


# ----------------------------------------------------------------------------------------------------
# The small reader


def says_np(text: str, t: Target) -> int:
    """Checks the noun phrase of t is in text (head, every attribute, every state); returns where the head is."""
    low = text.lower()
    i = low.find(t.head)
    assert i >= 0, (t.head, text)
    for a in t.attributes:
        assert a in low or hyphenated([a]) in low, (a, text)
    return i


def rel_starts(text: str, kind: str) -> list[int]:
    """Where set AE's words for a relation kind stand in text (the word's end, where its anchor begins)."""
    words = [*ae.REL_WORDS[kind], *(("that has",) if kind == "with" else ())]
    return [m.end() for w in words for m in re.finditer(r"(?<![\w-])" + re.escape(w) + r" the\b", text)]


def says_relations(text: str, t: Target) -> None:
    """Every relation of t: one of its kind's words, then (after it) the anchor, itself said in full."""
    for r in t.relations:
        starts = rel_starts(text, r.type)
        assert starts, (r.type, text)
        assert any(text.find(r.anchor.head, s) >= 0 for s in starts), (r, text)
        says_np(text, r.anchor)
        says_relations(text, r.anchor)


_WORDS = {w: i for i, w in enumerate(ONES)} | {w: 10 * i for i, w in enumerate(TENS) if w}
_DIGIT = {w: i for i, w in enumerate(ae._DIGIT_WORDS)}


def read_number(text: str) -> tuple[float, bool]:
    """(the one number a sensor phrase writes, in its own unit; whether that unit is Fahrenheit)."""
    t = text.lower().replace("°", " ")
    t = re.sub(r"(?<=[a-z])-(?=[a-z])", " ", t)
    toks = re.findall(r"-?\d*\.\d+|-?\d+|[a-z]+", t)
    numeric = lambda w: bool(re.fullmatch(r"-?\d*\.?\d+", w)) or w in _WORDS or w in ("minus", "nought")  # noqa: E731
    i = next(k for k, w in enumerate(toks) if numeric(w))
    sign = 1.0
    if toks[i] == "minus":
        sign, i = -1.0, i + 1
    if toks[i] == "nought":
        assert toks[i + 1] == "point"
        i += 2
        digits = ""
        while i < len(toks) and toks[i] in _DIGIT:
            digits += str(_DIGIT[toks[i]])
            i += 1
        val = float("0." + digits)
    elif re.fullmatch(r"-?\d*\.?\d+", toks[i]):
        val = float(toks[i])
        i += 1
    else:
        val = 0.0
        while i < len(toks):
            w = toks[i]
            if w in _WORDS:
                val += _WORDS[w]
            elif w == "hundred":
                val *= 100
            elif w == "and" and i + 1 < len(toks) and toks[i + 1] in _WORDS and toks[i + 2:i + 3] != ["quarters"]:
                pass
            else:
                break
            i += 1
    rest = toks[i:]
    if rest[:3] == ["and", "a", "half"]:
        val += 0.5
    elif rest[:3] == ["and", "a", "quarter"]:
        val += 0.25
    elif rest[:3] == ["and", "three", "quarters"]:
        val += 0.75
    val *= sign
    if "celsius below zero" in t:
        val = -val
    fahrenheit = "fahrenheit" in t or bool(re.search(r"\d\s*f\b", t))
    return val, fahrenheit


# comparator words of set AE, each with the comparator it says (the longest one in a phrase wins)
CMP_READ = {f.replace("{v}", "").replace(",", "").strip(): c for c, fs in ae.CMP_FRAMES.items() for f in fs}
CMP_READ |= {f" {s} ": c for c, s in ae.CMP_SYMBOLS.items()}
for _rd, (_up, _down) in ae.COMPARATIVES.items():
    CMP_READ |= {f"{_up} than": "gt", f"or {_up}": "ge", f"{_down} than": "lt", f"or {_down}": "le"}


def read_comparator(text: str) -> str:
    t = text.replace("Celsius below zero", "Celsius")  # set AE's negative temperatures: '5 degrees Celsius below zero'
    found = [p for p in CMP_READ if p in t]
    assert found, text
    return CMP_READ[max(found, key=len)]


def read_superlative(prefix: str, tail: str) -> str:
    if prefix:
        return next(c for (_, c), adjs in ae.SUPER_ADJ.items() if prefix in adjs)
    up = any(w in tail for w in ("highest", "higher than any", " top "))
    down = any(w in tail for w in ("lowest", "lower than any", " bottom "))
    assert up != down, tail
    return "max" if up else "min"


def read_reading(text: str) -> str:
    t = text.lower()
    hits = {rd for rd, names in ae.NAMES.items() for n in names if re.search(r"(?<!\w)" + re.escape(n.lower()) + r"(?!\w)", t)}
    hits |= {rd for rd, dev in ae.DEVICES.items() if dev.lower() in t}
    hits |= {rd for rd, words in ae.COMPARATIVES.items() if any(re.search(rf"\b{w}\b", t) for w in words)}
    assert len(hits) == 1, text
    return hits.pop()


def read_unit(text: str) -> str:
    t = text.replace("°", " ")
    if "fahrenheit" in t.lower() or re.search(r"\d\s*F\b", t):
        return "f"
    if re.search(r"celsius|centigrade|\d\s*C\b|deg C|degrees C", t):
        return "c"
    if "%" in t or "per cent" in t or "percent" in t:
        return "%"
    return ""


ALL_CUES = [(c, "strict") for cs in ae.STRICT_CUES.values() for c in cs] + [
    (c, "free") for cs in ae.FREE_CUES.values() for c in cs]


def read_order(text: str) -> str | None:
    said = {o for c, o in ALL_CUES if c.lower() in text.lower()}
    assert len(said) <= 1, text
    return said.pop() if said else None


# ----------------------------------------------------------------------------------------------------
# Tests


@FAST
@given(sgs=st.lists(subgoals(), min_size=1, max_size=4), seed=st.integers(0, 2**31), strict=st.booleans())
def test_same_seed_same_text(sgs, seed, strict):
    def run():
        rng = np.random.default_rng(seed)
        res = [ae.render_goal_ae(rng, sg, hint=ae.hint_text_ae(rng, "3.5", "-2")) for sg in sgs]
        sensors = [ae.render_sensor_ae(rng, SensorConstraint("temperature_c", "ge", 40.0)) for _ in range(3)]
        return res, sensors, ae.render_instruction_ae(rng, res, "strict" if strict else "free")

    assert run() == run()


@FAST
@given(sg=subgoals(), seed=st.integers(0, 2**31))
def test_a_goal_says_its_target_room_and_relations(sg, seed):
    text = ae.render_goal_ae(np.random.default_rng(seed), sg)
    assert text.startswith("the ") and text == " ".join(text.split()) and not text.endswith(",")
    says_np(text, sg.target)
    says_relations(text, sg.target)
    if sg.room:
        assert any(f.format(sg.room) in text for f in ae.ROOM_FRAMES), text
    assert not re.search(r"\d", text)
    assert text.count("(") == text.count(")")


def test_nested_anchor_relations_stay_in_brackets():
    table = make_target("table", ["oak"], [])
    rug = make_target("rug", [], ["empty"], (Relation("under", table),))
    lamp = make_target("lamp", ["teal"], ["switched on"], (Relation("next_to", rug), Relation("left_of", table)))
    for seed in range(40):
        text = ae.render_goal_ae(np.random.default_rng(seed), Subgoal(0, lamp, room="study"))
        says_relations(text, lamp)
        # the rug's own relation (under the table) is inside the brackets that follow the rug
        inner = text[text.index("rug"):]
        assert re.search(r"\((the one|which is) (" + "|".join(ae.REL_WORDS["under"]) + r") the", inner), text


VALUES = st.one_of(st.integers(-30, 400).map(float), st.integers(-20, 300).map(lambda n: n + 0.5),
                   st.integers(1, 60).map(lambda n: n + 0.25), st.integers(1, 19).map(lambda n: round(n * 0.05, 2)),
                   st.integers(10, 9000).map(lambda n: n / 100))
READINGS = ("temperature_c", "humidity_pct", "ndvi")


@FAST
@given(rd=st.sampled_from(READINGS), cmp=st.sampled_from(("gt", "ge", "lt", "le", "approx")), v=VALUES,
       seed=st.integers(0, 2**31))
def test_a_threshold_says_reading_comparator_and_value(rd, cmp, v, seed):
    prefix, tail, written = ae.render_sensor_ae(np.random.default_rng(seed), SensorConstraint(rd, cmp, v))
    assert prefix == "" and tail
    assert (written.reading, written.comparator, written.value) == (rd, cmp, v)
    assert read_reading(tail) == rd
    assert read_comparator(tail) == cmp, tail
    val, fahrenheit = read_number(tail)
    assert (written.unit == "f") == fahrenheit and read_unit(tail) == written.unit, (tail, written)
    if fahrenheit:
        val = (val - 32) * 5 / 9
    assert abs(val - v) < 1e-6, (tail, val, v)


@FAST
@given(rd=st.sampled_from(READINGS), cmp=st.sampled_from(("max", "min")), seed=st.integers(0, 2**31))
def test_a_superlative_says_its_direction(rd, cmp, seed):
    prefix, tail, written = ae.render_sensor_ae(np.random.default_rng(seed), SensorConstraint(rd, cmp))
    assert written == SensorConstraint(rd, cmp, None, "") and bool(prefix) != bool(tail)
    assert read_superlative(prefix, tail) == cmp
    if tail:
        assert read_reading(tail) == rd and not re.search(r"\d", tail)
    else:
        assert (rd, cmp) in ae.SUPER_ADJ


@FAST
@given(sg=subgoals(), rd=st.sampled_from(READINGS), cmp=st.sampled_from(("ge", "lt", "approx", "max", "min")),
       seed=st.integers(0, 2**31))
def test_a_sensor_goal_carries_its_phrase(sg, rd, cmp, seed):
    rng = np.random.default_rng(seed)
    prefix, tail, _ = ae.render_sensor_ae(rng, SensorConstraint(rd, cmp, None if cmp in ("max", "min") else 21.5))
    text = ae.render_goal_ae(rng, sg, prefix=prefix, tail=tail)
    says_np(text, sg.target)
    says_relations(text, sg.target)
    if prefix:
        assert re.search(re.escape(prefix) + r" (\S+ )*?" + re.escape(sg.target.head), text), text
    assert tail in text


def _coord():
    return st.one_of(st.integers(-99, 99).map(lambda n: f"{n / 10:.1f}"), st.integers(-99, 99).map(lambda n: f"{n / 10:g}"))


@FAST
@given(x=_coord(), y=_coord(), sg=subgoals(), seed=st.integers(0, 2**31))
def test_a_hint_gives_x_then_y_last(x, y, sg, seed):
    rng = np.random.default_rng(seed)
    hint = ae.hint_text_ae(rng, x, y)
    assert [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", hint)] == [float(x), float(y)], hint
    assert hint.lower().index("x") < hint.lower().index("y")
    text = ae.render_goal_ae(rng, sg, hint=hint)
    assert hint in text
    assert [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", text)][-2:] == [float(x), float(y)], text


@FAST
@given(sgs=st.lists(subgoals(), min_size=1, max_size=5), seed=st.integers(0, 2**31), strict=st.booleans())
def test_an_instruction_keeps_every_goal_in_order_and_says_the_order(sgs, seed, strict):
    rng = np.random.default_rng(seed)
    res = [ae.render_goal_ae(rng, sg) for sg in sgs]
    order = "strict" if strict else "free"
    text = ae.render_instruction_ae(rng, res, order)
    at = 0
    for r in res:
        i = text.lower().find(r.lower(), at)
        assert i >= 0, (r, text)
        at = i + len(r)
    frame = text
    for r in res:
        frame = frame.replace(r, " ", 1)
    if len(res) == 1:
        assert read_order(frame) is None and not re.search(r"\d", frame), text
    else:
        assert read_order(frame) == order, text


def test_every_voice_speaks_for_every_order():
    res = ["the lamp in the kitchen", "the teal sofa (state: open)", "the fern, found empty, not far from the rug"]
    for who, voice in ae.VOICES.items():
        for order, cues in (("strict", ae.STRICT_CUES), ("free", ae.FREE_CUES)):
            texts = {voice(np.random.default_rng(s), res, order) for s in range(30)}
            assert len(texts) >= 2, who
            for t in texts:
                assert any(c.lower() in t.lower() for c in cues[who]) and read_order(t) == order, t
        singles = {voice(np.random.default_rng(s), res[:1], "strict") for s in range(30)}
        assert len(singles) >= 2 and all(read_order(t) is None for t in singles)


def test_number_forms_are_exact():
    for v in (40.0, -5.0, 22.5, -2.5, 13.25, 7.75, 0.65, 0.5, 0.0, 305.0):
        for f in ae.number_forms(v):
            got, _ = read_number(f)
            assert abs(got - v) < 1e-9, (f, v)
