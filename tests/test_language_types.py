"""TaskChain pieces: frozen, JSON round trip, schema checks; the `ragnav parse` command."""

import dataclasses
import json
import subprocess
import sys

import pytest

from ragnav_jax.cli import main
from ragnav_jax.language.types import (
    TASKCHAIN_SCHEMA,
    Location,
    ParseError,
    Relation,
    SensorConstraint,
    Subgoal,
    Target,
    TaskChain,
    derive_dependencies,
)


def _chain():
    sink = Target("steel sink", "sink", ("steel",), (Relation("next_to", Target("table", "table", (),
                                                              (Relation("with", Target("monitor", "monitor")),))),))
    subs = (Subgoal(0, sink, room="kitchen"),
            Subgoal(1, Target("fern", "fern"), location=Location(3.5, 2.0),
                    sensors=(SensorConstraint("ndvi", "gt", 0.6), SensorConstraint("temperature_c", "max"))),
            Subgoal(2, Target("lamp", "lamp", (), (Relation("near", Target("fern", "fern")),))))
    return TaskChain("i", subs, "strict", derive_dependencies(subs, "strict"))


def test_pieces_are_frozen_and_round_trip():
    c = _chain()
    with pytest.raises(dataclasses.FrozenInstanceError):
        c.order = "free"  # type: ignore[misc]
    d = json.loads(json.dumps(c.to_dict()))
    assert d["format"] == "ragnav-taskchain/1" and TaskChain.from_dict(d) == c
    deps = {(x.type, x.subgoal, x.on, x.anchor, x.relation) for x in c.dependencies}
    assert deps == {("temporal", 1, 0, None, None), ("temporal", 2, 1, None, None),
                    ("spatial", 0, None, "table", "next_to"), ("spatial", 2, 1, "fern", "near")}
    assert TASKCHAIN_SCHEMA["$defs"]["relation"]["properties"]["anchor"] == {"$ref": "#/$defs/target"}


@pytest.mark.parametrize(
    "mutate, fragment",
    [
        (lambda d: d.update(subgoals=[]), "schema"),
        (lambda d: d.update(order="whenever"), "schema"),
        (lambda d: d["subgoals"][0]["target"].update(head=""), "schema"),
        (lambda d: d["subgoals"][0].update(index=5), "index"),
        (lambda d: d["subgoals"][1]["sensors"][0].update(value=None), "needs a finite value"),
        (lambda d: d["subgoals"][1]["sensors"][1].update(value=3.0), "needs no value"),
        (lambda d: d["subgoals"][1]["sensors"][0].update(reading="lux"), "schema"),
        (lambda d: d["subgoals"][0]["target"]["relations"][0].update(type="telepathically"), "schema"),
        (lambda d: d["dependencies"].append({"type": "temporal", "subgoal": 9, "on": 0}), "only 3"),
        (lambda d: d.update(code="rm -rf /"), "schema"),
    ],
)
def test_invalid_chain_dicts_raise_parse_error(mutate, fragment):
    d = _chain().to_dict()
    mutate(d)
    with pytest.raises(ParseError, match=fragment):
        TaskChain.from_dict(d)


def test_cli_parse_prints_text_and_json(capsys):
    assert main(["parse", "Go to the fern at x=3.5, y=2, then the warmest appliance in the kitchen."]) == 0
    out = capsys.readouterr().out
    text, js = out.split("\n\n", 1)
    assert "location hint: (3.5, 2)" in text and "highest temperature_c" in text and "room: kitchen" in text
    chain = TaskChain.from_dict(json.loads(js))
    assert [s.target.head for s in chain.subgoals] == ["fern", "appliance"]
    assert main(["parse", "--json", "visit", "the", "sofa"]) == 0
    assert json.loads(capsys.readouterr().out)["subgoals"][0]["target"]["head"] == "sofa"


@pytest.mark.parametrize("argv", [["parse", "   "], ["parse", "please"], ["parse", "go to (1, zz)"],
                                  ["parse", "--set", "llm.bogus=1", "go to the sofa"]])
def test_cli_parse_errors_exit_2_with_a_message(argv):
    proc = subprocess.run([sys.executable, "-m", "ragnav_jax.cli", *argv], capture_output=True, text=True)
    assert proc.returncode == 2, proc.stderr
    assert proc.stderr.startswith("ragnav: error:") and "Traceback" not in proc.stderr
