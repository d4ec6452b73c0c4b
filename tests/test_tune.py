"""Gradient tuning: the surrogate shares the scoring path, its gradients flow, tuning lowers the training loss,
and the result loads back as a config and as an orbax checkpoint."""

import json

import jax
import jax.numpy as jnp
import numpy as np
import pytest
import sweep_fixtures
from sweep_fixtures import SMALL

from ragnav_jax.cli import main
from ragnav_jax.config import load_config
from ragnav_jax.evaluation import tune as T
from ragnav_jax.language.episodes import load_episodes
from ragnav_jax.retrieval.evaluate import node_scores, prepare_batch
from ragnav_jax.retrieval.params import params_from_config

tiny_run = sweep_fixtures.tiny_run  # the session fixture


@pytest.fixture(scope="module")
def batch(tiny_run, apartment):
    run, episodes, cfg, bank, emb = tiny_run
    b, _ = prepare_batch(bank, [apartment], load_episodes(episodes, [apartment]), emb)
    return b, params_from_config(cfg.retrieval), cfg


def test_gates_leave_scores_unchanged(batch):
    b, p, _ = batch
    hard = jax.jit(node_scores)(b.index, b.queries, p)
    soft = jax.jit(node_scores)(b.index, b.queries, p, jnp.float32(0.05))
    np.testing.assert_array_equal(np.asarray(hard), np.asarray(soft))


def test_surrogate_gradients_are_finite_and_reach_the_continuous_terms(batch):
    b, p, cfg = batch
    free = T.to_free(p, cfg.tune.params)
    loss, g = jax.jit(jax.value_and_grad(T.surrogate_loss))(free, jnp.log(0.05), b, p, jnp.float32(0.05))
    assert np.isfinite(float(loss)) and float(loss) > 0
    assert all(np.isfinite(float(v)) for v in g.values()), g
    assert sum(abs(float(g[k])) > 0 for k in ("sigma", "eta", "w_slot", "w_loc", "boost_threshold")) >= 3, g


def test_free_space_round_trip(batch):
    _, p, cfg = batch
    back = T.from_free(T.to_free(p, cfg.tune.params), p)
    for k in cfg.tune.params:
        assert float(getattr(back, k)) == pytest.approx(float(getattr(p, k)), rel=1e-5, abs=1e-4)


def test_split_is_deterministic_and_disjoint(tiny_run, apartment):
    eps = load_episodes(tiny_run[1], [apartment])
    a, b = T.split_episodes(eps, 0.5, seed=3)
    assert T.split_episodes(eps, 0.5, seed=3) == (a, b)
    assert {e.id for e in a}.isdisjoint({e.id for e in b}) and len(a) + len(b) == len(eps)
    assert {e.modality for e in a} == {e.modality for e in b} == {e.modality for e in eps}


def test_tune_cli_lowers_training_loss_and_result_loads_as_config(tiny_run, tmp_path):
    run, episodes, _, _, _ = tiny_run
    out = tmp_path / "tune"
    assert main(["tune", "--run", str(run), "--episodes", str(episodes), "--out", str(out), "--quiet", *SMALL]) == 0
    s = json.loads((out / "summary.json").read_text())
    assert s["loss_last"] < s["loss_first"]
    assert set(s["held_out"]) == {"config", "grid_best", "tuned"} and 0 <= s["held_out"]["tuned"] <= 1
    assert s["train"]["tuned"] >= s["train"]["grid_best"]  # the returned iterate is the best on train
    assert (out / "tune.md").exists() and (out / "loss.png").exists()
    cfg = load_config(out / "tuned.yaml")
    restored, temp = T.load_tuned(out / "tuned")
    from_yaml = params_from_config(cfg.retrieval)
    for k in T.params_dict(restored):
        assert np.float32(getattr(from_yaml, k)) == np.float32(getattr(restored, k)), k
    assert temp > 0 and cfg.retrieval.sigma == pytest.approx(s["tuned_params"]["sigma"])
