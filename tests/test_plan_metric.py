"""plan_success of the sweep (sigma x eta x lambda) against a NumPy + itertools reference."""

import itertools

import jax
import numpy as np
import pytest
import sweep_fixtures
from sweep_fixtures import SMALL

from ragnav_jax.config import load_config
from ragnav_jax.evaluation import sweep as S
from ragnav_jax.evaluation.plan_metric import plan_episodes, plan_metric
from ragnav_jax.language.episodes import load_episodes
from ragnav_jax.retrieval.evaluate import prepare_batch, score_bank
from ragnav_jax.retrieval.params import params_from_config

tiny_run = sweep_fixtures.tiny_run  # the session fixture
LAM = ["sweep.axes.lam=[0.5,100.0]", "sweep.variants=[ragnav,no_boost]"]


@pytest.fixture(scope="module")
def setup(tiny_run, apartment):
    run, episodes, _, bank, emb = tiny_run
    cfg = load_config(None, SMALL + LAM)
    eps = load_episodes(episodes, [apartment])
    b, meta = prepare_batch(bank, [apartment], eps, emb)
    return cfg, bank, b, meta, eps


def _reference(bank, b, meta, apartment, params, lam: float) -> np.ndarray:
    """Episodes planned right per modality: argmin over itertools permutations of travel + lam * inversions."""
    best = np.asarray(score_bank(b.index, b.queries, b.qmask, params)[0])
    truth = np.asarray(b.truth)
    cost = np.asarray(bank.memory.path_cost)[0]
    pos, mask = np.asarray(bank.memory.position)[0, :, :2], np.asarray(bank.memory.node_mask)[0]
    d = np.where(mask, np.linalg.norm(pos - np.asarray(apartment.start.position[:2]), axis=1), np.inf)
    start = int(np.argmin(d))
    by_ep: dict = {}
    for it, sl in zip(meta.items, meta.slots):
        by_ep.setdefault(it[0].id, (it[0], []))[1].append(sl)
    out = np.zeros(len(meta.modalities), np.int64)
    for ep, slots in by_ep.values():
        if any(sl is None for sl in slots):
            continue
        nodes = [int(best[0, q]) for _, q in slots]
        if not all(truth[0, q, n] for (_, q), n in zip(slots, nodes)):
            continue
        strict = ep.order == "strict"
        scored = []
        for perm in itertools.permutations(range(len(nodes))):
            seq = [start] + [nodes[i] for i in perm]
            travel = sum(cost[a, c] for a, c in zip(seq, seq[1:]))
            inv = sum(perm[i] > perm[j] for i in range(len(perm)) for j in range(i + 1, len(perm))) if strict else 0
            scored.append((travel + lam * inv, inv, travel))
        if not np.isfinite(min(s[2] for s in scored)):
            continue
        _, inv, _ = min(scored)
        out[meta.modalities.index(ep.modality)] += inv == 0
    return out


def test_plan_success_matches_itertools_reference(setup, apartment):
    cfg, bank, b, meta, _ = setup
    grid = S.make_grid(cfg.sweep, params_from_config(cfg.retrieval), cfg.planning.lam)
    metric = plan_metric(b, meta, bank, [apartment], grid)
    sums, _ = S.evaluate_grid([S.retrieval_metric(b, meta, grid), metric], grid, 2 * 4)
    assert grid.size == 2 * 3 * 2 * 2
    _, totals = plan_episodes(b, meta, bank, [apartment])
    np.testing.assert_array_equal(metric.totals, totals)
    for p in range(grid.size):
        params = jax.tree.map(lambda x, p=p: x[p], grid.params)
        ref = _reference(bank, b, meta, apartment, params, float(grid.lam[p]))
        np.testing.assert_array_equal(sums["plan_success"][p], ref, err_msg=f"point {p}: {grid.points[p]}")


def test_lambda_trades_order_for_travel(setup, apartment):
    """Large lambda keeps every strict episode's order: success is then 'all goals retrieved right'; a
    smaller lambda can only lose strict episodes, never gain any."""
    cfg, bank, b, meta, _ = setup
    grid = S.make_grid(cfg.sweep, params_from_config(cfg.retrieval), cfg.planning.lam)
    sums, _ = S.evaluate_grid([plan_metric(b, meta, bank, [apartment], grid)], grid, 4)
    ps = sums["plan_success"]
    for p, pt in enumerate(grid.points):
        if pt["lam"] == 0.5:
            q = next(i for i, o in enumerate(grid.points) if o == {**pt, "lam": 100.0})
            assert np.all(ps[p] <= ps[q])
    assert ps.sum() > 0


def test_sweep_cli_with_lambda_axis(tiny_run, tmp_path):
    import json

    import pandas as pd

    from ragnav_jax.cli import main

    run, episodes, _, _, _ = tiny_run
    out = tmp_path / "lam"
    args = ["sweep", "--run", str(run), "--episodes", str(episodes), "--out", str(out), "--quiet", *SMALL, *LAM]
    assert main(args) == 0
    df = pd.read_csv(out / "sweep.csv")
    assert {"lam", "plan_success", "plan_success_n", "retrieval_accuracy"} <= set(df.columns)
    assert len(df) == 24 * 4
    s = json.loads((out / "summary.json").read_text())
    assert set(s["best_plan"]) == {"ragnav", "no_boost"} and "plan_success" in s["metrics"]
    # Retrieval accuracy does not depend on lambda; plan success can.
    acc = df[df.modality == "all"].groupby(["variant", "sigma", "eta"])["retrieval_accuracy"].nunique()
    assert (acc == 1).all()
