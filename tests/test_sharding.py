"""Sharding: a sweep split over 4 (forced CPU) devices in a subprocess gives the single-device table."""

import json

import jax
import numpy as np
import pandas as pd
import pytest
import sweep_fixtures
from sweep_fixtures import SMALL, ragnav_subprocess

from ragnav_jax.cli import main
from ragnav_jax.evaluation import sharding

tiny_run = sweep_fixtures.tiny_run  # the session fixture


def test_pad_and_shard_helpers_on_one_device():
    mesh = sharding.batch_mesh()
    x = {"a": np.arange(5, dtype=np.float32), "b": np.ones((5, 2), np.int32)}
    padded = sharding.pad_leading(x, 4)
    assert padded["a"].shape == (8,) and padded["a"][-1] == 4 and padded["b"].shape == (8, 2)
    assert sharding.pad_leading(np.arange(4), 4).shape == (4,)
    y = sharding.shard_leading(sharding.pad_leading(x, mesh.size), mesh)
    np.testing.assert_array_equal(sharding.to_host(y["a"]), x["a"])
    assert jax.tree.leaves(sharding.replicate(np.float32(3.0), mesh))[0].shape == ()


def test_sweep_on_four_devices_equals_one_device(tiny_run, tmp_path):
    run, episodes, _, _, _ = tiny_run
    args = ["sweep", "--run", str(run), "--episodes", str(episodes), "--quiet", *SMALL, "sweep.checkpoint=false"]
    assert main([*args, "--out", str(tmp_path / "one")]) == 0
    proc = ragnav_subprocess([*args, "--out", str(tmp_path / "four")],
                             env={"XLA_FLAGS": "--xla_force_host_platform_device_count=4"})
    text, _ = proc.communicate(timeout=300)
    assert proc.returncode == 0, text
    assert json.loads((tmp_path / "four" / "summary.json").read_text())["devices"] == 4
    assert json.loads((tmp_path / "one" / "summary.json").read_text())["devices"] == 1
    pd.testing.assert_frame_equal(pd.read_csv(tmp_path / "one" / "sweep.csv"), pd.read_csv(tmp_path / "four" / "sweep.csv"))


def test_init_distributed_reads_its_variables(monkeypatch):
    import jax

    from ragnav_jax.errors import UserError
    from ragnav_jax.evaluation.sharding import init_distributed

    calls = []
    monkeypatch.setattr(jax.distributed, "initialize", lambda **kw: calls.append(kw))
    assert not init_distributed({}) and not init_distributed({"RAGNAV_DISTRIBUTED": "0"}) and calls == []
    assert init_distributed({"RAGNAV_DISTRIBUTED": "1", "RAGNAV_COORDINATOR": "h0:1234", "RAGNAV_NUM_PROCESSES": "2",
                             "RAGNAV_PROCESS_ID": "1"})
    assert calls == [{"coordinator_address": "h0:1234", "num_processes": 2, "process_id": 1}]
    assert init_distributed({"RAGNAV_DISTRIBUTED": "1"}) and calls[-1] == {}  # cluster auto-detection
    with pytest.raises(UserError, match="RAGNAV_PROCESS_ID"):
        init_distributed({"RAGNAV_DISTRIBUTED": "1", "RAGNAV_PROCESS_ID": "one"})
