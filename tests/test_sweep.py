"""Sweeps: the grid call equals points one by one, one compile per sweep, tidy table and heatmaps, resume."""

import json
import signal
import time
from types import SimpleNamespace

import jax
import numpy as np
import pandas as pd
import pytest
import sweep_fixtures
from sweep_fixtures import SMALL, ragnav_subprocess

from ragnav_jax.cli import main
from ragnav_jax.config import load_config
from ragnav_jax.evaluation import sweep as S
from ragnav_jax.language.episodes import load_episodes
from ragnav_jax.retrieval.evaluate import correct_counts, evaluate_retrieval, prepare_batch
from ragnav_jax.retrieval.params import params_from_config

tiny_run = sweep_fixtures.tiny_run  # the session fixture


@pytest.fixture(scope="module")
def batch(tiny_run, apartment):
    run, episodes, cfg, bank, emb = tiny_run
    eps = load_episodes(episodes, [apartment])
    b, meta = prepare_batch(bank, [apartment], eps, emb)
    return b, meta, eps


ONE = jax.jit(correct_counts)


@pytest.mark.parametrize("chunk", [1, 4])  # combinations per call: 6 chunks, or 2 with the last padded
def test_grid_equals_points_one_by_one(tiny_run, batch, chunk):
    _, _, cfg, _, _ = tiny_run
    b, meta, _ = batch
    grid = S.make_grid(cfg.sweep, params_from_config(cfg.retrieval))
    assert grid.size == 3 * 6 and grid.outer == ("use_forest", "use_boost") and grid.inner == ("sigma", "eta")
    sums, stats = S.evaluate_grid([S.retrieval_metric(b, meta, grid)], grid, chunk * 3)
    for p in range(grid.size):
        ref = np.asarray(ONE(b, jax.tree.map(lambda x, p=p: x[p], grid.params)))
        np.testing.assert_array_equal(sums["retrieval_accuracy"][p], ref, err_msg=f"point {p}: {grid.points[p]}")
    assert stats["chunks"] == -(-6 // chunk) and stats["combos_per_chunk"] == chunk


@pytest.mark.parametrize("devices", [1, 2, 4])
def test_chunk_holds_a_one_device_chunk_per_device(devices):
    """sweep.chunk_size is per device: n devices take n one-device chunks per call, never more than the grid,
    always a multiple of the devices."""
    grid, mesh = SimpleNamespace(variants=("a", "b"), num_combos=50), SimpleNamespace(size=devices)
    assert S.chunk_shape(grid, 8, mesh) == 4 * devices
    assert S.chunk_shape(grid, 1, mesh) == devices  # at least one combination a device
    big = S.chunk_shape(grid, 200, mesh)
    assert big % devices == 0 and 50 <= big < 50 + devices


def test_grid_agrees_with_evaluate_retrieval(tiny_run, batch, apartment):
    """The sweep's accuracy of a point is what `ragnav retrieve` reports for the same method and values."""
    _, _, cfg, bank, emb = tiny_run
    b, meta, eps = batch
    grid = S.make_grid(cfg.sweep, params_from_config(cfg.retrieval))
    rows = S.sweep_rows(grid, [S.retrieval_metric(b, meta, grid)],
                        S.evaluate_grid([S.retrieval_metric(b, meta, grid)], grid, 18)[0])
    for p in (1, 10):  # a ragnav point and a no_boost point
        pt = grid.points[p]
        base = params_from_config(cfg.retrieval).replace(sigma=np.float32(pt["sigma"]), eta=np.float32(pt["eta"]))
        method = "ragnav" if pt["variant"] == "ragnav" else f"ragnav:{pt['variant']}"
        _, summary = evaluate_retrieval(bank, [apartment], eps, emb, method, base)
        mine = {r["modality"]: r["retrieval_accuracy"] for r in rows if r["point"] == p}
        assert mine["all"] == pytest.approx(summary["retrieval_accuracy"], abs=1e-6)
        for m, v in summary["by_modality"].items():
            assert mine[m] == pytest.approx(v["retrieval_accuracy"], abs=1e-6)


def test_chunks_compile_once(tiny_run, batch):
    _, _, cfg, _, _ = tiny_run
    b, meta, _ = batch
    grid = S.make_grid(cfg.sweep, params_from_config(cfg.retrieval))
    fn = S._grid_correct(grid.outer, grid.inner)
    before = fn._cache_size()
    for _ in range(2):  # 2 chunks each, the last padded: one compile for all four calls
        _, stats = S.evaluate_grid([S.retrieval_metric(b, meta, grid)], grid, 3 * 4)
    assert stats["chunks_computed"] == 2 and fn._cache_size() - before <= 1


def test_grid_sizes_zero_and_one_axes(tiny_run, batch):
    _, _, cfg, _, _ = tiny_run
    b, meta, _ = batch
    one = load_config(None, ["sweep.variants=[ragnav]"])  # no axis varied: one point
    grid = S.make_grid(one.sweep, params_from_config(cfg.retrieval))
    sums, _ = S.evaluate_grid([S.retrieval_metric(b, meta, grid)], grid, 4)
    assert grid.size == 1
    np.testing.assert_array_equal(sums["retrieval_accuracy"][0], ONE(b, params_from_config(cfg.retrieval)))


def _sweep_args(run, episodes, out, *extra):
    return ["sweep", "--run", str(run), "--episodes", str(episodes), "--out", str(out), "--quiet", *SMALL, *extra]


def test_sweep_cli_table_heatmaps_and_resume(tiny_run, tmp_path):
    run, episodes, _, _, _ = tiny_run
    out = tmp_path / "sw"
    assert main(_sweep_args(run, episodes, out)) == 0
    df = pd.read_csv(out / "sweep.csv")
    assert len(df) == 18 * 4 and set(df["modality"]) == {"text", "text+location", "text+location+sensor", "all"}
    assert {"point", "variant", "sigma", "eta", "retrieval_accuracy", "retrieval_accuracy_n"} <= set(df.columns)
    assert (out / "sweep.md").exists() and len(list((out / "heatmaps").glob("*.png"))) == 3
    s1 = json.loads((out / "summary.json").read_text())
    assert s1["chunks_computed"] == s1["chunks"] == 2 and set(s1["best"]) == {"ragnav", "no_boost", "no_forest"}
    # Started again on the same folder: everything comes from the checkpoints, same table.
    assert main(_sweep_args(run, episodes, out)) == 0
    s2 = json.loads((out / "summary.json").read_text())
    assert s2["chunks_resumed"] == 2 and s2["chunks_computed"] == 0
    pd.testing.assert_frame_equal(df, pd.read_csv(out / "sweep.csv"))
    # Another grid in the same folder is refused unless --fresh.
    assert main(_sweep_args(run, episodes, out, "sweep.axes.eta=[0.0,0.5]")) == 2
    assert main(_sweep_args(run, episodes, out, "sweep.axes.eta=[0.0,0.5]", "--fresh")) == 0
    # Unknown variants are config errors (the lambda axis: test_plan_metric.py).
    assert main(_sweep_args(run, episodes, tmp_path / "v", "sweep.variants=[nope]")) == 2


def test_kill_and_resume_matches_uninterrupted(tiny_run, tmp_path):
    """A real `ragnav sweep` killed with SIGKILL after some chunks, then restarted, equals an uninterrupted run."""
    run, episodes, _, _, _ = tiny_run
    small = ["sweep.chunk_size=3"]  # 6 chunks of one combination x 3 variants
    ref = tmp_path / "ref"
    assert main(_sweep_args(run, episodes, ref, *small, "sweep.checkpoint=false")) == 0
    out = tmp_path / "killed"
    cache = tmp_path / "jax_cache"
    proc = ragnav_subprocess(_sweep_args(run, episodes, out, *small, "sweep.pause_s=1.0"), cache=cache)
    chunks = out / "checkpoints" / "chunks"
    deadline = time.time() + 120
    while time.time() < deadline and proc.poll() is None:
        if chunks.is_dir() and sum(p.name.isdigit() for p in chunks.iterdir()) >= 2:
            break
        time.sleep(0.05)
    assert proc.poll() is None, "the sweep finished before it could be killed:\n" + proc.stdout.read()
    proc.send_signal(signal.SIGKILL)
    proc.wait(30)
    proc.stdout.close()
    done = sorted(int(p.name) for p in chunks.iterdir() if p.name.isdigit())
    assert 2 <= len(done) < 6
    proc = ragnav_subprocess(_sweep_args(run, episodes, out, *small), cache=cache)
    text, _ = proc.communicate(timeout=300)
    assert proc.returncode == 0, text
    assert f"resuming: {len(done)} of 6 chunks" in text
    s = json.loads((out / "summary.json").read_text())
    assert s["chunks_resumed"] == len(done) and s["chunks_computed"] == 6 - len(done)
    pd.testing.assert_frame_equal(pd.read_csv(ref / "sweep.csv"), pd.read_csv(out / "sweep.csv"))
