"""The device closed loop (evaluation/loop/): the same outcomes as the host loop on the apartment, one
trace per batch shape, and the configured order planner changes what it drives."""

import dataclasses

import jax
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from test_memory_streams import synthetic_stream

from ragnav_jax.config import load_config
from ragnav_jax.evaluation.execute import make_executor
from ragnav_jax.evaluation.loop import program
from ragnav_jax.evaluation.navigate import evaluate_navigation
from ragnav_jax.evaluation.verify import Verifier
from ragnav_jax.language.episodes import Episode, load_episodes
from ragnav_jax.memory.build import build_bank
from ragnav_jax.memory.encoder import HashingEmbedder
from ragnav_jax.world.scene import example_scene_path

EPISODES = example_scene_path().parent / "episodes.jsonl"


def _with(cfg, **kw):
    return dataclasses.replace(cfg, eval=dataclasses.replace(cfg.eval, **kw))


@pytest.fixture(scope="module")
def setup(apartment):
    # 6 episodes on 4 lanes (2 queue), each reflection serving 2 lanes gathered from the 4 (eval.refill)
    cfg = load_config(None, ["memory.embedder=hashing", "eval.batch_size=4", "eval.refill=0.5"])
    stream = synthetic_stream(apartment)
    emb = HashingEmbedder(dim=cfg.memory.hashing_dim)
    bank, _ = build_bank([apartment], [stream], cfg, embedder=emb)
    ex = make_executor([apartment], cfg)
    return cfg, bank, emb, ex, Verifier.build(emb, cfg)


def _rows(setup, apartment, method, engine, episodes=None, **kw):
    cfg, bank, emb, ex, ver = setup
    cfg = _with(cfg, engine=engine, **kw)
    episodes = episodes or load_episodes(EPISODES, [apartment])
    rows, summary = evaluate_navigation(bank, [apartment], episodes, emb, cfg, method, executor=ex, verifier=ver)
    return rows, summary


METHODS = ("oracle", "ragnav", "remembr", "ragnav:no_topology")


@pytest.fixture(scope="module")
def both(setup, apartment):
    """Rows of every method on the apartment from each engine; the device program is compiled once for all."""
    cfg, bank, emb, ex, ver = setup
    before = dict(ex.traces)
    out = {eng: {m: _rows(setup, apartment, m, eng)[0] for m in METHODS} for eng in ("host", "device")}
    return out, before


def test_device_loop_matches_host_loop(setup, both):
    (out, _), max_steps = both, setup[0].eval.max_steps
    pairs = [(m, h, d) for m in METHODS for h, d in zip(out["host"][m], out["device"][m])]
    same = [h["success"] == d["success"] and h["goal_status"] == d["goal_status"] for _, h, d in pairs]
    assert np.mean(same) >= 0.8, [(m, h["episode"], h["goal_status"], d["goal_status"]) for (m, h, d), s in
                                  zip(pairs, same) if not s]
    for m in ("oracle", "ragnav"):
        assert sum(r["success"] for r in out["device"][m]) >= sum(r["success"] for r in out["host"][m]) - 1
    for _, h, d in pairs:
        assert d["steps"] <= max_steps + 200
        if h["success"] and d["success"] and h["rejected_candidates"] == d["rejected_candidates"]:
            assert d["travel_distance_m"] == pytest.approx(h["travel_distance_m"], rel=0.35, abs=1.5)  # same legs


def test_one_compilation_serves_every_method_and_batch(setup, both):
    """Four methods, two batches each: the device program was traced once."""
    progs = [v for k, v in setup[3].cache.items() if k[0] == "device_program"]
    assert len(progs) == 1 and progs[0]._cache_size() == 1


def _longest_written_order(bank, apartment, k=3):
    """Object ids of k goals, written in the order whose route from the start is longest over the map."""
    import itertools

    from ragnav_jax.evaluation.ranking import _oracle_node

    cost = np.asarray(bank.memory.path_cost[0])
    pos = np.asarray(bank.memory.position[0, :, :2])
    start = int(np.argmin(np.linalg.norm(pos - np.asarray(apartment.start.position[:2]), axis=1)))
    nodes = {o.id: _oracle_node(bank, 0, j) for j, o in enumerate(apartment.objects)}
    ids = [i for i, n in nodes.items() if n >= 0 and np.isfinite(cost[start, n])]
    rng = np.random.default_rng(0)
    pick = list(rng.choice(ids, k, replace=False))

    def route(order):
        c, cur = 0.0, start
        for i in order:
            c, cur = c + cost[cur, nodes[i]], nodes[i]
        return c

    return max(itertools.permutations(pick), key=route)


def test_order_penalty_reaches_the_device_loop(setup, apartment):
    """A strict instruction written in its longest order: lambda = 0 lets the planner take a shorter order (the
    strict episode then fails on order), a large lambda drives the written one."""
    cfg, bank, emb, ex, ver = setup
    goals = _longest_written_order(bank, apartment)
    ep = Episode("lam-0", apartment.name, "visit them in order", tuple(goals), "text", "strict")
    episodes = [ep, *load_episodes(EPISODES, [apartment])[:5]]  # the module's queue shape: no new compilation
    out = {}
    for lam in (0.0, 1.0e4):
        c = dataclasses.replace(cfg, planning=dataclasses.replace(cfg.planning, lam=lam))
        rows, _ = evaluate_navigation(bank, [apartment], episodes, emb, _with(c, engine="device"), "oracle",
                                      executor=ex, verifier=ver)
        out[lam] = rows[0]
    assert out[1.0e4]["success"] and not out[0.0]["success"]
    assert out[0.0]["reason"] == "order"
    assert out[0.0]["travel_distance_m"] < out[1.0e4]["travel_distance_m"]


def test_unknown_engine_or_reflections_is_a_config_error():
    from ragnav_jax.errors import UserError

    with pytest.raises(UserError, match="eval.engine"):
        load_config(None, ["eval.engine=gpu"])
    with pytest.raises(UserError, match="eval.reflections"):
        load_config(None, ["eval.reflections=parallel"])
    flags = [program.flags_of(load_config(None, [f"eval.reflections={r}"]), 8).serial for r in ("serial", "batched")]
    assert flags == [True, False]


def test_device_loop_refuses_etpnav_directly(setup, apartment):
    from ragnav_jax.errors import UserError
    from ragnav_jax.evaluation.host_loop import Loop
    from ragnav_jax.evaluation.methods import method_spec

    cfg, bank, emb, ex, ver = setup
    loop = Loop(method_spec("etpnav"), bank, [apartment], cfg, ex, {})
    with pytest.raises(UserError, match="etpnav"):
        program.run_device(loop, [object()], cfg)


def test_closed_loop_sweep_matches_the_device_eval(setup, apartment, both):
    """The sweep's closed-loop metric at the configured point (device candidate ranking, device judging) counts
    the successes that `ragnav eval`'s device engine (host ranking, host rows) gets, with its compiled loop;
    lambda is a grid axis. A point that ranks every candidate alike (here a sigma 0.01% away, in a later chunk)
    reads the runs it shares instead of running them again; the later chunk's padding is neither run nor counted."""
    from ragnav_jax.config import SweepAxes
    from ragnav_jax.evaluation.loop.sweep_metric import closed_loop_metrics
    from ragnav_jax.evaluation.sweep import evaluate_grid, make_grid
    from ragnav_jax.retrieval.params import params_from_config

    cfg, bank, emb, ex, ver = setup
    episodes = load_episodes(EPISODES, [apartment])
    mods = tuple(sorted({e.modality for e in episodes}))
    sigma = cfg.retrieval.sigma
    sweep = dataclasses.replace(cfg.sweep, axes=SweepAxes(sigma=(sigma, 0.25 * sigma, 1.0001 * sigma), lam=(cfg.planning.lam,)),
                                variants=("ragnav",), chunk_size=2)
    c = dataclasses.replace(cfg, sweep=sweep)
    grid = make_grid(c.sweep, params_from_config(c.retrieval), c.planning.lam)
    metrics = closed_loop_metrics(c, bank, [apartment], episodes, emb, grid, mods, executor=ex, verifier=ver)
    progs = [v for k, v in ex.cache.items() if k[0] == "device_program"]
    before = sum(p._cache_size() for p in progs)
    sums, stats = evaluate_grid(metrics, grid, chunk_size=2)
    assert stats["chunks_computed"] == 2
    rows, _ = _rows(setup, apartment, "ragnav", "device", episodes)
    want = [sum(r["success"] for r in rows if r["modality"] == m) for m in mods]
    assert sums["nav_success"][0].tolist() == want
    assert 0.0 <= sums["nav_spl"][0].sum() <= sums["nav_success"][0].sum() + 1e-6
    assert sums["nav_travel_m"][0].sum() == pytest.approx(sum(r["travel_distance_m"] for r in rows), rel=1e-3)
    for name in sums:
        np.testing.assert_array_equal(sums[name][2], sums[name][0])
    runs = metrics[0].stats
    assert runs["episode_runs"] == 3 * len(episodes) and len(episodes) <= runs["loop_runs"] <= 2 * len(episodes)
    assert runs["loop_calls"] <= 2  # the third point's runs are the first's
    assert sum(p._cache_size() for p in progs) == before  # the device eval's compiled loop ran the sweep


def test_refill_and_reflections_change_speed_not_rows(setup, apartment, both):
    """eval.refill 1.0 (every lane reflects at once, after every leg of the batch has ended) with batched
    reflections (vmapped: every branch and grid search computed for every lane, as on a GPU) gives the same rows
    as the module's reflections of 2 lanes gathered from the 4 while the other 2 drive on, one lane after another
    (serial, the CPU's default): a second program."""
    out, _ = both
    assert setup[0].eval.reflections == "auto" and jax.default_backend() == "cpu"  # the module's: serial
    rows, _ = _rows(setup, apartment, "ragnav", "device", refill=1.0, reflections="batched")
    keys = ("success", "goal_status", "steps", "travel_distance_m", "declarations")
    assert [{k: r[k] for k in keys} for r in rows] == [{k: r[k] for k in keys} for r in out["device"]["ragnav"]]
    progs = [v for k, v in setup[3].cache.items() if k[0] == "device_program"]
    assert len(progs) == 2  # the share is static: the lanes a reflection gathers are an array shape


def test_an_episode_does_not_depend_on_its_lane_or_queue_place(setup, apartment, both):
    """4 lanes, 6 episodes: two wait in the queue for a lane. In reverse order the first ones wait instead, and
    every episode's row is the same, from the same compiled program."""
    out, _ = both
    progs = [v for k, v in setup[3].cache.items() if k[0] == "device_program"]
    before = sum(p._cache_size() for p in progs)
    episodes = load_episodes(EPISODES, [apartment])
    rows, _ = _rows(setup, apartment, "ragnav", "device", episodes[::-1])
    keys = ("episode", "success", "goal_status", "steps", "travel_distance_m", "declarations")
    assert [{k: r[k] for k in keys} for r in rows[::-1]] == [{k: r[k] for k in keys} for r in out["device"]["ragnav"]]
    assert sum(p._cache_size() for p in progs) == before


def test_tune_checks_its_values_by_closed_loop_success_on_held_out_episodes(setup, apartment, both):
    """tune.closed_loop: RAGNav's held-out success with the config's, the best grid point's and the tuned retrieval
    values, on the module's executor (retrieval values do not recompile the loop); the config's is what `ragnav
    eval` gets on the held-out episodes."""
    from ragnav_jax.config import SweepAxes
    from ragnav_jax.evaluation.tune import run_tune, split_episodes

    cfg, bank, emb, ex, ver = setup
    eps = load_episodes(EPISODES, [apartment])
    eps = eps + [dataclasses.replace(e, id=e.id + "-again") for e in eps]  # 12: two episodes of each kind held out
    sigma = cfg.retrieval.sigma
    c = dataclasses.replace(cfg, tune=dataclasses.replace(cfg.tune, closed_loop=True, steps=4, eval_every=2),
                            sweep=dataclasses.replace(cfg.sweep, axes=SweepAxes(sigma=(sigma, 2 * sigma)), checkpoint=False))
    held = split_episodes(eps, c.tune.train_fraction, c.tune.split_seed)[1]
    assert 4 < len(held) <= 8  # the module's queue shape (8 on 4 lanes)
    progs = [v for k, v in ex.cache.items() if k[0] == "device_program"]
    before = sum(p._cache_size() for p in progs)
    summary, _ = run_tune(c, bank, [apartment], eps, emb, executor=ex, verifier=ver)
    nav = summary["held_out_success"]
    assert set(nav) == {"config", "grid_best", "tuned"} and all(0.0 <= v <= 1.0 for v in nav.values())
    rows, _ = _rows(setup, apartment, "ragnav", "device", held)
    assert nav["config"] == pytest.approx(np.mean([r["success"] for r in rows]))
    assert sum(p._cache_size() for p in progs) == before


@settings(max_examples=30, deadline=None)
@given(st.integers(0, 2**31 - 1))
def test_visit_sequence_follows_the_solved_slots_and_keeps_dead_goals_in_place(seed):
    """The goals in the solver's slot order (NumPy), then each goal left without a candidate: at its written
    place when strict, at the end when free."""
    from ragnav_jax.evaluation.loop import step

    rng = np.random.default_rng(seed)
    G = 5
    left = rng.random(G) < 0.8
    live = left & (rng.random(G) < 0.8)
    goal_of = np.flatnonzero(live)
    n = len(goal_of)
    k = np.full(G, -1)
    k[:n] = rng.permutation(n)
    strict = bool(rng.integers(2))
    q = {"left": left, "live": live, "n_live": np.int32(n), "goal_of": np.pad(goal_of, (0, G - n)).astype(np.int32)}
    seq, m = jax.jit(step.visit_sequence)(q, k.astype(np.int32), strict)
    want = [int(goal_of[s]) for s in k[:n]] if n > 1 else list(goal_of)
    for d in np.flatnonzero(left & ~live):
        at = max([i + 1 for i, g in enumerate(want) if g < d], default=0) if strict else len(want)
        want.insert(at, int(d))
    assert int(m) == len(want) and np.asarray(seq)[: len(want)].tolist() == want
