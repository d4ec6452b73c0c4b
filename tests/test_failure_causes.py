"""experiments/failure_causes.py names why each goal of an eval run failed: a goal whose instruction names
another object than its target fails because the check rejects the target by name; found goals get no row."""

import importlib.util
import json
from pathlib import Path

import pytest
import sweep_fixtures

from ragnav_jax.cli import main

tiny_run = sweep_fixtures.tiny_run  # the session fixture
SCRIPT = Path(__file__).resolve().parents[1] / "experiments" / "failure_causes.py"


def load_script():
    spec = importlib.util.spec_from_file_location("failure_causes", SCRIPT)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


@pytest.fixture(scope="module")
def eval_run(tiny_run, tmp_path_factory):
    run, *_ = tiny_run
    d = tmp_path_factory.mktemp("causes")
    episodes = d / "episodes.jsonl"
    rows = [  # the first asks for the fridge but its goal is the desk: no check may confirm the desk as a fridge
        {"id": "misnamed", "scene": "apartment", "instruction": "Go to the fridge.", "modality": "text",
         "goals": [{"object_id": "desk_1"}], "order": "strict"},
        {"id": "plain", "scene": "apartment", "instruction": "Go to the fridge.", "modality": "text",
         "goals": [{"object_id": "fridge_1"}], "order": "strict"},
    ]
    episodes.write_text("".join(json.dumps(r) + "\n" for r in rows))
    out = d / "ev"
    assert main(["eval", "--scenes", str(run), "--episodes", str(episodes), "--method", "ragnav", "--out", str(out),
                 "--quiet", "memory.embedder=hashing"]) == 0
    return out


def test_a_misnamed_target_is_rejected_by_the_check(eval_run):
    recorded = {json.loads(x)["episode"]: json.loads(x) for x in (eval_run / "eval" / "ragnav" / "episodes.jsonl").read_text().splitlines()}
    assert recorded["plain"]["goal_status"] == ["found"]
    assert recorded["misnamed"]["goal_status"] != ["found"]
    rows = load_script().causes(eval_run, "ragnav")
    assert [(r["episode"], r["goal"], r["target"]) for r in rows] == [("misnamed", 0, "desk_1")]
    assert rows[0]["cause"] == "check_rejects_target" and "name" in rows[0]["detail"].split("+")
