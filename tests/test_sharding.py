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
    four = json.loads((tmp_path / "four" / "summary.json").read_text())
    one = json.loads((tmp_path / "one" / "summary.json").read_text())
    assert (four["devices"], one["devices"]) == (4, 1)
    # sweep.chunk_size=12 is per device: 4 of the 6 combinations a chunk on one device (2 chunks), all 6 (padded
    # to 8) in one chunk on four
    assert (one["chunks"], one["combos_per_chunk"], four["chunks"], four["combos_per_chunk"]) == (2, 4, 1, 8)
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


_LOOP_RUNS = r"""
import json
import jax, jax.numpy as jnp, numpy as np
from ragnav_jax.evaluation.loop.sweep_metric import LoopRuns

def fn(le, run_e, cands, est, has, lam, count):  # a stand-in queue: each run's outcome from its inputs alone
    got = jnp.stack([run_e * le["w"] + lam, cands.sum((1, 2)) * 1.0, est.sum((1, 2, 3)), has.sum((1, 2)) * 1.0], -1)
    return jnp.where((jnp.arange(run_e.shape[0]) < count[0])[:, None], got, jnp.nan)  # padding: NaN

rng = np.random.default_rng(0)
V, C, E, G, k = 1, 5, 7, 2, 3
cands = rng.integers(0, 3, (V, C, E, G, k)).astype(np.int32)
cands[:, 3] = cands[:, 0]  # point 3 ranks every episode like point 0
est = rng.normal(size=(V, C, E, G, k, 2)).astype(np.float32) * (cands[..., None] > 0)
est[:, 3] = est[:, 0]
has = cands > 0
lam = np.asarray([0, 0, 1e4, 0, 0], np.float32)
devices = jax.devices() if jax.device_count() > 1 else None
runs = LoopRuns(jax.jit(fn), {"w": jnp.float32(10.0)}, lanes=2, devices=devices)
a = runs(cands, est, has, lam)
b = runs(cands[:, :2], est[:, :2], has[:, :2], lam[:2])  # a later chunk of points already met
c = runs(cands[:, :3], est[:, :3], has[:, :3], np.asarray([5, 6, 7], np.float32), 1)  # one point, two of padding
print(json.dumps({"devices": jax.device_count(), "a": a.tolist(), "b": b.tolist(), "c": c.tolist(), **runs.stats}))
"""


def test_loop_runs_deal_runs_over_four_devices_and_run_each_once():
    """LoopRuns (the closed-loop sweep's runs) on 4 forced CPU devices, a queue each, with a stand-in queue
    program: every run's outcome as on one device, the queue's padding never read, a run met again (an equal
    point, a later chunk) not run again, and a chunk's padded points neither run nor counted."""
    import subprocess
    import sys

    def go(devices):
        env = {**__import__("os").environ, "JAX_PLATFORMS": "cpu",
               "XLA_FLAGS": f"--xla_force_host_platform_device_count={devices}"}
        out = subprocess.run([sys.executable, "-c", _LOOP_RUNS], env=env, capture_output=True, text=True, timeout=300)
        assert out.returncode == 0, out.stderr[-2000:]
        return json.loads(out.stdout.strip().splitlines()[-1])

    one, four = go(1), go(4)
    assert (one["devices"], four["devices"]) == (1, 4) and (one["loop_devices"], four["loop_devices"]) == (1, 4)
    a = np.asarray(four["a"])
    assert a.shape == (1, 5, 7, 4) and np.isfinite(a).all()
    np.testing.assert_array_equal(a, np.asarray(one["a"]))
    np.testing.assert_array_equal(np.asarray(four["b"]), a[:, :2])
    c = np.asarray(four["c"])
    assert c.shape == (1, 1, 7, 4)
    np.testing.assert_array_equal(c[0, 0, :, 0], np.arange(7) * 10.0 + 5)
    assert four["episode_runs"] == one["episode_runs"] == 5 * 7 + 2 * 7 + 7
    assert four["loop_runs"] == one["loop_runs"] == 4 * 7 + 7  # point 3 repeats 0; the later chunk, 0 and 1
    np.testing.assert_array_equal(a[0, :, :, 0], np.arange(7)[None] * 10.0 + np.asarray([0, 0, 1e4, 0, 0])[:, None])
