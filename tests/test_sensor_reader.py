"""The learned reader of sensor comparisons (language/sensor_reader.py): its labels, what `revise` may change,
fitting (deterministic, the file round-trips) and the shipped reader. That its training reads no held-out template
set and seen-split houses only is checked beside the tagger's (tests/test_tagger.py)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ragnav_jax.config import Config, load_config
from ragnav_jax.errors import UserError
from ragnav_jax.language.parser import parse_instruction
from ragnav_jax.language.sensor_reader import (
    ABOVE,
    APPROX,
    BELOW,
    HELD_OUT,
    MAX,
    MIN,
    NONE,
    READINGS,
    WAYS,
    label,
    revise,
    training_examples,
)
from ragnav_jax.language.types import Location, SensorConstraint, Subgoal, Target


def sure(way: int, reading: str = "temperature_c", p: float = 0.99) -> tuple[np.ndarray, np.ndarray]:
    """(p_reading, p_way) of a classifier `p` sure of a way and a reading."""
    pw = np.full(len(WAYS), (1 - p) / (len(WAYS) - 1), np.float32)
    pw[way] = p
    pr = np.full(len(READINGS), 0.01, np.float32)
    pr[READINGS.index(reading)] = 0.98
    return pr, pw


def goal(text: str) -> Subgoal:
    return parse_instruction("Go to " + text).subgoals[0]


def test_a_comparison_read_the_other_way_turns_and_keeps_its_value():
    sg = goal("the freezer with a temperature under -10 degrees")
    assert sg.sensors == (SensorConstraint("temperature_c", "lt", -10.0, "c"),)
    got = revise(sg, *sure(ABOVE), conf=0.9)
    assert got.sensors == (SensorConstraint("temperature_c", "gt", -10.0, "c"),)
    assert dataclasses.replace(got, sensors=sg.sensors) == sg  # nothing else changes


def test_a_bound_the_same_way_keeps_its_comparator():
    sg = goal("the heater at least 40 degrees")
    assert sg.sensors[0].comparator == "ge"
    assert revise(sg, *sure(ABOVE), conf=0.9) == sg


@pytest.mark.parametrize("p, way", [(0.6, ABOVE), (0.99, NONE)])
def test_an_unsure_reader_or_no_comparison_leaves_the_parse(p, way):
    sg = goal("the freezer with a temperature under -10 degrees")
    assert revise(sg, *sure(way, p=p), conf=0.9) == sg


def test_a_missed_superlative_is_added_and_leaves_the_name():
    sg = goal("the toastiest tool in the workshop")
    assert sg.sensors == () and sg.target.head == "toastiest tool"
    got = revise(sg, *sure(MAX), conf=0.9)
    assert got.sensors == (SensorConstraint("temperature_c", "max"),)
    assert got.target.head == "tool" and got.room == "workshop"
    got = revise(goal("the most withered spider plant"), *sure(MIN, "ndvi"), conf=0.9)
    assert got.sensors == (SensorConstraint("ndvi", "min"),) and got.target.head == "spider plant"


def test_a_name_that_only_ends_like_a_superlative_stays_a_name():
    got = revise(goal("the chest"), *sure(MAX), conf=0.9)
    assert got.target.head == "chest" and got.sensors == (SensorConstraint("temperature_c", "max"),)
    sg = Subgoal(0, Target("chest freezer", "chest freezer"), text="the chest freezer that trails every other on temperature")
    assert revise(sg, *sure(MIN), conf=0.9).target.head == "chest freezer"
    sg = Subgoal(0, Target("largest freezer", "largest freezer"), text="the largest freezer")
    assert revise(sg, *sure(MIN), conf=0.9).target.head == "freezer"
    assert revise(sg, *sure(MIN), conf=0.9, known=("largest freezer",)).target.head == "largest freezer"


def test_a_missed_bound_takes_the_goals_one_number():
    sg = Subgoal(0, Target("dehumidifier", "dehumidifier"), text="the dehumidifier whose humidity never climbs above 40 per cent")
    got = revise(sg, *sure(BELOW, "humidity_pct"), conf=0.9)
    assert got.sensors == (SensorConstraint("humidity_pct", "lt", 40.0, "%"),)
    # a coordinate hint's numbers are no reading; with none left there is nothing to bound by
    sg = Subgoal(0, Target("lamp", "lamp"), location=Location(3.5, 2.0), text="the lamp at 3.5, 2 at about 20 degrees")
    assert revise(sg, *sure(APPROX), conf=0.9).sensors == (SensorConstraint("temperature_c", "approx", 20.0, "c"),)
    sg = Subgoal(0, Target("lamp", "lamp"), location=Location(3.5, 2.0), text="the lamp at 3.5, 2")
    assert revise(sg, *sure(APPROX), conf=0.9) == sg


def test_a_reading_the_reader_does_not_know_is_never_touched():
    sg = Subgoal(0, Target("plant", "plant"), sensors=(SensorConstraint("co2_ppm", "gt", 900.0, "ppm"),),
                 text="the plant where CO2 is over 900 ppm")
    assert revise(sg, *sure(BELOW), conf=0.5) == sg


TEXTS = ["the freezer with a temperature under -10 degrees", "the toastiest tool in the workshop", "the sofa",
         "the heater at least 40 degrees", "the fern whose NDVI is about 0.6", "the coldest fridge",
         "the most withered spider plant near the sofa"]


@settings(max_examples=80, deadline=None)
@given(text=st.sampled_from(TEXTS), way=st.integers(0, len(WAYS) - 1), reading=st.sampled_from(READINGS),
       p=st.floats(0.3, 1.0), conf=st.sampled_from([0.5, 0.9]))
def test_revise_changes_only_the_comparison_and_a_superlative_word_and_is_idempotent(text, way, reading, p, conf):
    sg = goal(text)
    pr, pw = sure(way, reading, p)
    got = revise(sg, pr, pw, conf)
    if way == NONE or p < conf:
        assert got == sg
    assert (got.index, got.room, got.location, got.text, got.target.relations) == (
        sg.index, sg.room, sg.location, sg.text, sg.target.relations)
    assert sg.target.head.endswith(got.target.head) and set(got.target.attributes) <= set(sg.target.attributes)
    if got != sg and way != NONE:
        assert label(got)[1] == way
    assert revise(got, pr, pw, conf) == got


def test_labels_are_the_truths_first_comparison():
    assert label(Subgoal(0, Target("x", "x"))) == (0, NONE)
    assert label(Subgoal(0, Target("x", "x"), sensors=(SensorConstraint("co2_ppm", "gt", 1.0),
                                                       SensorConstraint("ndvi", "le", 0.5)))) == (2, BELOW)


def test_training_examples_are_labelled_as_the_rule_parser_reads_the_seen_templates():
    """The rule parser reads the seen templates exactly (it was written beside them): every example, rewritten
    ones included, is labelled with what it reads."""
    ex = training_examples(Config(), 1, 3, ("seen",))
    assert ex == training_examples(Config(), 1, 3, ("seen",))
    ways = {w for _, _, w in ex}
    assert {NONE, ABOVE, BELOW} <= ways and ways & {MAX, MIN}
    for text, r, w in ex:
        sg = parse_instruction("Go to " + text).subgoals[0]
        assert label(sg)[1] == w and (w == NONE or label(sg)[0] == r), text


def test_a_bad_confidence_is_a_config_error():
    with pytest.raises(UserError, match="eval.sensor_reader_conf"):
        load_config(None, ["eval.sensor_reader_conf=0.3"])


class FakeReader:
    def __init__(self, way, reading="temperature_c"):
        self.way, self.reading, self.calls = way, reading, []

    def probs(self, texts):
        self.calls.append(list(texts))
        pr, pw = sure(self.way, self.reading)
        return np.tile(pr, (len(texts), 1)), np.tile(pw, (len(texts), 1))


def test_sensor_reading_revises_what_grounding_keeps():
    from ragnav_jax.evaluation.grounding import SensorReading
    from ragnav_jax.language.episodes import Episode

    class Inner:  # the tagger and grounder: drops the remark, reads an unparsable instruction as one goal
        vocab, dropped, added = {"h": ("chest freezer",)}, {"e": ("sampling points",)}, {"e": ("tool",)}

        def __call__(self, ep, sgs):
            return tuple(sg for sg in sgs if "sampling" not in sg.text)

        def read_unparsed(self, ep):
            return (Subgoal(0, Target("chest freezer", "chest freezer"), text="the chest freezer, nippiest"),)

    reader = FakeReader(MAX)
    hook = SensorReading(reader, 0.9, inner=Inner())
    ep = Episode("e", "h", "The sampling points below may be visited in any order: the toastiest tool.", ())
    out = hook(ep, parse_instruction(ep.instruction).subgoals)
    assert [sg.target.head for sg in out] == ["tool"] and out[0].sensors[0].comparator == "max"
    assert reader.calls == [["the toastiest tool"]]  # the remark grounding dropped is never read
    assert hook.revised["e"] == ("the toastiest tool: toastiest tool -> tool, temperature_c max",)
    assert hook.dropped == {"e": ("sampling points",)} and hook.added == {"e": ("tool",)}
    got = hook.read_unparsed(ep)  # a name the house uses keeps its first word
    assert got[0].target.head == "chest freezer" and got[0].sensors[0].comparator == "max"
    assert SensorReading(FakeReader(NONE), 0.9)(ep, out) == out


def test_fitting_is_deterministic_and_the_file_round_trips(tmp_path):
    from ragnav_jax.language.sensor_reader import FitSettings, SensorReader, fit_reader, load_reader_file, save_reader

    s = FitSettings(scenes=1, epochs=1, batch=8, lora=2, rewrite=0.2)
    a, meta = fit_reader(Config(), s, ("seen",))
    b, _ = fit_reader(Config(), s, ("seen",))
    assert a.keys() == b.keys() and all(np.array_equal(a[k], b[k]) for k in a)
    assert all(k[0] in ("reading", "way") or "_lora_" in k[-2] for k in a)  # only adapters and heads are fitted
    save_reader(a, meta, tmp_path / "r.npz")
    trained, meta2 = load_reader_file(tmp_path / "r.npz")
    assert meta2 == meta and meta["fitted_on"]["template_sets"] == ["seen"]
    texts = ["the coldest fridge", "the sofa"]
    pa, pb = SensorReader(a, meta).probs(texts), SensorReader(trained, meta2).probs(texts)
    for x, y in zip(pa, pb):
        np.testing.assert_array_equal(x, y)
        np.testing.assert_allclose(x.sum(1), 1.0, rtol=1e-5)


def test_a_file_that_is_no_reader_is_a_user_error(tmp_path):
    from ragnav_jax.language.sensor_reader import load_reader_file

    bad = tmp_path / "r.npz"
    bad.write_text("not an archive")
    with pytest.raises(UserError, match="r.npz: not a sensor reader file"):
        load_reader_file(bad)


def test_the_shipped_reader_learnt_from_no_held_out_set_and_reads_comparisons_no_template_writes():
    from ragnav_jax.language.sensor_reader import load_reader

    reader = load_reader("")
    sets = reader.meta["fitted_on"]["template_sets"]
    assert reader.meta["fitted_on"]["world_split"] == "seen" and not set(sets) & set(HELD_OUT)
    texts = ["the sofa", "the greenhouse fan that is running hotter than 30 degrees",
             "the boiler whose temperature beats every other"]
    pr, pw = reader.probs(texts)
    assert [WAYS[i] for i in pw.argmax(1)] == ["none", "above", "max"]
    assert READINGS[pr[2].argmax()] == "temperature_c"
