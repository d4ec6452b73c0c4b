"""`ragnav doctor` on this CPU: the JSON report, every check passing, a failing check named with exit 1."""

import json

import pytest

from ragnav_jax.cli import main
from ragnav_jax.doctor import CHECKS, REQUIRED


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    path = tmp_path_factory.mktemp("doctor") / "doctor.json"
    code = main(["doctor", "--json", str(path)])
    return code, json.loads(path.read_text())


def test_doctor_passes_on_cpu(report, capsys):
    code, doc = report
    assert code == 0, doc["failed"]
    assert set(doc) >= {"ok", "failed", "python", "platform", "versions", "backend", "devices", "checks"}
    assert doc["ok"] and doc["failed"] == []
    assert doc["backend"] == "cpu" and doc["devices"][0]["platform"] == "cpu"
    assert all(doc["versions"][n] != "not installed" for n in REQUIRED)
    assert list(doc["checks"]) == list(CHECKS) and all(c["ok"] for c in doc["checks"].values())
    mjx = doc["checks"]["mjx"]
    assert mjx["max_abs_diff"] <= mjx["tolerance"] and mjx["moved_m"] > 0.1
    assert mjx["device"] == doc["devices"][0]["name"]  # ran on the default device
    assert doc["checks"]["minilm"]["dim"] == 384


def test_doctor_text_and_stdout_json_agree(report, capsys):
    _, doc = report
    assert main(["doctor", "--only", "packages", "jax", "--json"]) == 0
    quick = json.loads(capsys.readouterr().out)
    assert list(quick["checks"]) == ["packages", "jax"] and quick["versions"] == doc["versions"]
    assert main(["doctor", "--only", "jax"]) == 0
    out = capsys.readouterr().out
    assert "ok    jax       backend cpu" in out and out.rstrip().endswith("all checks passed")


def test_doctor_names_a_failing_check(capsys):
    assert main(["doctor", "--only", "jax", "--backend", "gpu"]) == 1
    captured = capsys.readouterr()
    assert "FAIL  jax" in captured.out and "expected backend gpu" in captured.out
    assert "failed check(s): jax" in captured.err
    assert main(["doctor", "--only", "bogus"]) == 2
