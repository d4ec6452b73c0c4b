"""The sections of `ragnav bench`: each takes a Profile and returns a JSON-ready dict with its rows and
its peer comparisons (`comparison` records). Retrieval, planning and simulation call the benchmark
functions of experiments/bench_{retrieval,planning,sim}.py (loaded from the source tree), so the
scripts and the suite share one implementation.
"""

from __future__ import annotations

import contextlib
import copy
import dataclasses
import functools
import importlib.util
import math
import sys
import time
import types
from collections.abc import Callable, Sequence
from pathlib import Path

import numpy as np

from ragnav_jax.bench.profiles import Profile
from ragnav_jax.bench.timing import stage_clock, stats

REPO = Path(__file__).resolve().parents[2]
PAPER_MS = (185.0, 195.0)  # the paper's retrieval latency per query


# Set by the suite while a section runs: called with the section's figures so far, which it saves as a
# 'partial' section, so a run killed mid-section (a time-limited command) keeps what it measured.
partial_hook: Callable[[dict], None] | None = None


def _partial(res: dict) -> None:
    if partial_hook is not None:
        partial_hook(res)


class Unavailable(RuntimeError):
    """A section or stage whose code is not in this tree (recorded as 'not available')."""


def experiment(name: str) -> types.ModuleType:
    """experiments/<name>.py of the source tree, imported as a module (its functions, not its CLI)."""
    path = REPO / "experiments" / f"{name}.py"
    if not path.is_file():
        raise Unavailable(f"{path} not found (the suite needs a source checkout)")
    key = f"ragnav_experiments_{name}"
    if key not in sys.modules:
        spec = importlib.util.spec_from_file_location(key, path)
        mod = importlib.util.module_from_spec(spec)
        sys.modules[key] = mod
        try:
            spec.loader.exec_module(mod)
        except Exception:
            del sys.modules[key]
            raise
    return sys.modules[key]


def comparison(section: str, name: str, ours: dict, peer: dict, peer_name: str, unit: str, **extra) -> dict:
    """Ours vs a peer on the same work: seconds per `unit` (median, min, max); ratio = peer / ours
    (> 1: ours is faster), with the range from the extremes (peer min / ours max .. peer max / ours min)."""
    return {
        "section": section, "name": name, "unit": unit, "ours": ours, "peer": {"name": peer_name, **peer},
        "ratio": peer["median_s"] / ours["median_s"],
        "ratio_range": [peer["min_s"] / ours["max_s"], peer["max_s"] / ours["min_s"]],
        **extra,
    }


def _per(s: dict, k: float) -> dict:
    return {**s, "median_s": s["median_s"] / k, "min_s": s["min_s"] / k, "max_s": s["max_s"] / k}


# ----------------------------------------------------------------------------------------------------


def bench_retrieval(p: Profile, log: Callable[[str], None]) -> dict:
    """Warm single-query latency and batched throughput per memory size; similarity stage vs faiss."""
    mod = experiment("bench_retrieval")
    rng = np.random.default_rng(0)
    rows, comps = [], []
    for n, q in zip(p.retrieval_sizes, p.retrieval_queries):
        chunk, fq = p.retrieval_chunk, p.faiss_queries
        if p.retrieval_max_cells is not None:  # large memories: fewer queries per block, fewer timed in faiss
            cap = max(1, p.retrieval_max_cells // n)
            chunk = min(chunk or q, cap)
            fq = min(fq or q, cap)
        try:
            r = mod.bench_size(n, 384, q, p.repeats, rng, chunk=chunk, faiss_queries=fq)
        except Exception as e:  # noqa: BLE001 - one size failing (e.g. device memory) keeps the others
            rows.append({"nodes": n, "batch_queries": q, "query_chunk": chunk, "error": f"{type(e).__name__}: {e}"[:500]})
            _partial({"rows": rows, "comparisons": comps})
            log(f"retrieval N={n}: FAILED {type(e).__name__}: {str(e)[:200]}")
            continue
        r["batched_queries_per_s_range"] = [q / r["batched"]["max_s"], q / r["batched"]["min_s"]]
        rows.append(r)
        fq = r["sim_faiss_queries"]
        if r["sim_faiss"] is not None:  # faiss-cpu is a dev dependency; without it the comparison is left out
            comps.append(comparison("retrieval", f"similarity vs faiss IndexFlatIP, {n} nodes", _per(r["sim_jax"], q),
                                    _per(r["sim_faiss"], fq), "faiss-cpu IndexFlatIP", "query",
                                    nodes=n, queries=q, faiss_queries=fq, top1_agreement=r["sim_top1_agreement"]))
        paper = {"median_s": 1e-3 * sum(PAPER_MS) / 2, "min_s": 1e-3 * PAPER_MS[0], "max_s": 1e-3 * PAPER_MS[1],
                 "repeats": 0}
        comps.append(comparison("retrieval", f"single query vs paper, {n} nodes", r["single"], paper,
                                "paper (185-195 ms/query, reported)", "query", nodes=n,
                                compile_s=r["compile_single_s"]))
        _partial({"rows": rows, "comparisons": comps})
        log(f"retrieval N={n}: single {r['single_ms']:.2f} ms, batched {r['batched_queries_per_s']:.0f} q/s, "
            + (f"faiss/JAX per query {r['sim_ratio_faiss_over_jax']:.2f}" if r["sim_faiss"] else "faiss not installed"))
    return {"rows": rows, "comparisons": comps}


def random_graphs(rng: np.random.Generator, graphs: int, n: int, degree: float = 6.0):
    """Random geometric graphs like topological maps: n nodes at 1 per m^2, an edge (Euclidean length)
    between nodes closer than the radius giving about `degree` neighbours. Returns weights (G, n, n)
    float32 (inf: no edge) and mask (G, n) bool."""
    side = math.sqrt(n)
    radius = math.sqrt(degree / math.pi)
    pos = rng.uniform(0, side, (graphs, n, 2)).astype(np.float32)
    d = np.linalg.norm(pos[:, :, None] - pos[:, None, :], axis=-1)
    w = np.where((d < radius) & ~np.eye(n, dtype=bool), d, np.inf).astype(np.float32)
    return w, np.ones((graphs, n), bool)


def _networkx_all_pairs(w: np.ndarray) -> dict:
    import networkx as nx

    g = nx.Graph()
    g.add_nodes_from(range(w.shape[0]))
    i, j = np.nonzero(np.isfinite(w) & np.triu(np.ones_like(w, bool), 1))
    g.add_weighted_edges_from(zip(i.tolist(), j.tolist(), w[i, j].astype(float).tolist()))
    return g


def bench_paths(p: Profile, log: Callable[[str], None]) -> dict:
    """Batched jitted all-pairs shortest paths (memory.paths, Floyd-Warshall) vs networkx all-pairs
    Dijkstra on the same graphs; networkx runs on a sample and is extrapolated linearly (said in the row)."""
    import jax
    import networkx as nx

    from ragnav_jax.memory.paths import batched_shortest_paths, chunked_shortest_paths

    apsp = batched_shortest_paths
    if p.path_chunk is not None and p.path_chunk < p.path_graphs:
        apsp = functools.partial(chunked_shortest_paths, chunk=p.path_chunk)  # bounded device memory
    rng = np.random.default_rng(1)
    rows, comps = [], []
    for n in p.path_nodes:
        # Inputs and outputs are (G, n, n) arrays: large n gets fewer graphs so they fit (path_max_cells).
        G = p.path_graphs if p.path_max_cells is None else max(1, min(p.path_graphs, p.path_max_cells // (n * n)))
        w, mask = random_graphs(rng, G, n)
        wj, mj = jax.device_put(w), jax.device_put(mask)
        t0 = time.perf_counter()
        compiled = jax.jit(apsp).lower(wj, mj).compile()
        compile_s = time.perf_counter() - t0
        cost, _ = jax.block_until_ready(compiled(wj, mj))
        ts = []
        for _ in range(p.path_repeats or p.repeats):
            t0 = time.perf_counter()
            jax.block_until_ready(compiled(wj, mj))
            ts.append(time.perf_counter() - t0)
        ours = stats(ts)
        sample = min(p.path_nx_sample, G)
        graphs = [_networkx_all_pairs(w[g]) for g in range(sample)]  # graph construction is not timed
        nts = []
        for _ in range(max(1, min(p.repeats, 3))):
            t0 = time.perf_counter()
            res = [dict(nx.all_pairs_dijkstra_path_length(g)) for g in graphs]
            nts.append((time.perf_counter() - t0) * G / sample)
        cost = np.asarray(cost)
        ref = np.full((sample, n, n), np.inf, np.float32)
        for g, dd in enumerate(res):
            for a, row in dd.items():
                ref[g, a, list(row)] = list(row.values())
        agree = bool(np.allclose(cost[:sample], ref, rtol=1e-4, atol=1e-4))
        peer = stats(nts)
        row = {"nodes": n, "graphs": G, "graph_chunk": p.path_chunk, "compile_s": compile_s, "jax": ours, "networkx": peer,
               "networkx_graphs_timed": sample, "networkx_extrapolated": sample < G,
               "mean_degree": float(np.isfinite(w).sum(-1).mean()), "agrees_with_networkx": agree}
        rows.append(row)
        comps.append(comparison("paths", f"all-pairs shortest paths vs networkx, {G} graphs of {n} nodes",
                                _per(ours, G), _per(peer, G), "networkx all_pairs_dijkstra",
                                "graph", nodes=n, compile_s=compile_s, agrees=agree,
                                peer_extrapolated_from=sample))
        _partial({"rows": rows, "comparisons": comps})
        log(f"paths n={n}: jax {ours['median_s']:.3f} s / {G} graphs (compile {compile_s:.1f} s), "
            f"networkx {peer['median_s']:.1f} s, x{comps[-1]['ratio']:.0f}, agree={agree}")
    return {"rows": rows, "comparisons": comps}


def bench_planning(p: Profile, log: Callable[[str], None]) -> dict:
    """Brute force n=8 and Held-Karp n=12 over many episodes vs the plain Python itertools loops."""
    mod = experiment("bench_planning")
    args = types.SimpleNamespace(episodes=p.plan_episodes, lam=5.0, repeats=p.repeats, python_sample_bf=p.plan_python_bf,
                                 python_sample_hk=p.plan_python_hk, python_repeats=max(1, min(p.repeats, 3)))
    rng = np.random.default_rng(0)
    rows, comps = [], []
    for name, method, n, fn in (("brute_force_n8", "brute_force", 8, mod.python_brute_force),
                                ("held_karp_n12", "held_karp", 12, mod.python_held_karp)):
        row, _, _ = mod.bench_case(name, method, n, fn, args, rng)
        rows.append(row)
        ours = stats(row["run_s_all"])
        scale = p.plan_episodes / row["python_episodes_timed"]
        peer = stats([t * scale for t in row["python_s_timed_all"]])
        comps.append(comparison("planning", f"{method.replace('_', ' ')} n={n}, {p.plan_episodes} episodes vs Python",
                                _per(ours, p.plan_episodes), _per(peer, p.plan_episodes), "Python itertools loop",
                                "episode", goals=n, compile_s=row["compile_s"], agrees=row["agrees_with_python"],
                                peer_extrapolated_from=row["python_episodes_timed"]))
        log(f"planning {name}: x{comps[-1]['ratio']:.0f} vs Python (compile {row['compile_s']:.1f} s)")
    return {"rows": rows, "comparisons": comps}


def bench_simulation(p: Profile, log: Callable[[str], None]) -> dict:
    """Env-steps/s of the MJX NavEnv (physics + lidar + visibility) per batch size vs the MuJoCo C loop."""
    from ragnav_jax.config import load_config
    from ragnav_jax.sim.env import NavEnv
    from ragnav_jax.world.scene import example_scene_path, load_scene

    mod = experiment("bench_sim")
    cfg = load_config()
    scene = load_scene(example_scene_path())
    env = NavEnv([scene], cfg.sim)
    layout = env.model.layout
    c = mod.bench_c(scene, cfg, layout.walls, layout.objects, p.sim_c_steps, p.repeats)

    def spread(r, work):  # bench_sim reports the median call; min/max where it gives them
        med = r["median_call_s"]
        return _per({"median_s": med, "min_s": r.get("min_call_s", med), "max_s": r.get("max_call_s", med),
                     "repeats": r["repeats"]}, work)

    peer = spread(c, c["steps_per_call"])
    rows, comps = [], []
    for b in p.sim_batches:
        r = mod.bench_mjx(env, b, p.sim_steps, p.repeats)
        rows.append(r)
        comps.append(comparison("simulation", f"MJX batch {b} vs MuJoCo C, 1 thread", spread(r, b * p.sim_steps), peer,
                                "MuJoCo C loop (mj_step, mj_multiRay, mj_ray), 1 thread", "env step", batch=b,
                                compile_s=r["compile_s"], env_steps_per_s=r["env_steps_per_s"]))
        _partial({"c_engine": c, "rows": rows, "comparisons": comps})
        log(f"simulation batch {b}: {r['env_steps_per_s']:.0f} env-steps/s (C {c['env_steps_per_s']:.0f}), "
            f"compile {r['compile_s']:.1f} s")
    return {"c_engine": c, "rows": rows, "comparisons": comps, "scene": scene.name,
            "note": "min and max per call from experiments/bench_sim.py (equal to the median where it gives none)"}


# ----------------------------------------------------------------------------------------------------
# End to end on the paper preset


STAGES = ("generate", "explore", "build_memory", "episodes", "retrieve", "plan", "execute")


def paper_config(p: Profile, scenes: int, spacing: float | None = None):
    """The paper preset (configs/paper.yaml) with `scenes` scenes and the profile's embedder and explore budget."""
    from ragnav_jax.config import load_config

    path = REPO / "configs" / "paper.yaml"
    ov = [f"world.num_scenes={scenes}", f"memory.embedder={p.e2e_embedder}"]
    if p.e2e_explore_steps is not None:
        ov.append(f"explore.max_steps={p.e2e_explore_steps}")
    if p.e2e_explore_batch is not None:
        ov.append(f"explore.batch_size={p.e2e_explore_batch}")
    if spacing is not None:
        ov += [f"memory.keyframe_spacing={spacing}", f"memory.keyframe_min_spacing={min(0.3, 0.6 * spacing):.3f}"]
    return load_config(str(path) if path.is_file() else None, ov)


def execute_stage():
    """The closed-loop evaluation's entry point (evaluate_navigation), or Unavailable where it is missing."""
    try:
        from ragnav_jax.evaluation.navigate import evaluate_navigation
    except ImportError as e:
        raise Unavailable(f"closed-loop evaluation (ragnav eval, issue 8) is not in this tree ({e})") from e
    return evaluate_navigation


def run_pipeline(cfg, p: Profile, log, reuse=None, execute: bool = True, plan: bool = True) -> tuple[dict, dict]:
    """The RAGNav pipeline on cfg's scenes, each stage under stage_clock; returns (record, artifacts).

    reuse: artifacts of an earlier call (scenes and exploration results) to skip generate and explore;
    execute: run a sample of episodes through the closed loop (skipped in the nodes-per-scene runs);
    plan: plan a sample of instructions (skipped where only the artifacts are wanted).
    """
    import jax

    from ragnav_jax.language.episodes import generate_episodes
    from ragnav_jax.memory.build import build_bank, memory_summary
    from ragnav_jax.memory.encoder import make_embedder
    from ragnav_jax.planning.plan import plan_instruction
    from ragnav_jax.retrieval.evaluate import prepare_batch, score_bank
    from ragnav_jax.retrieval.params import params_from_config
    from ragnav_jax.sim.explore import explore_scenes
    from ragnav_jax.world.generator import generate_scenes

    st: dict = {}
    art = dict(reuse or {})
    if "scenes" not in art:
        with stage_clock(st.setdefault("generate", {})):
            art["scenes"] = generate_scenes(cfg.world, cfg.seed)
        with stage_clock(st.setdefault("explore", {})):
            art["explored"] = explore_scenes(art["scenes"], cfg)
        st["explore"]["control_steps"] = int(sum(r.steps for r in art["explored"]))
    scenes = art["scenes"]
    m = cfg.memory
    embedder = make_embedder(m.embedder, dim=m.hashing_dim, batch_size=m.embed_batch, buckets=m.token_buckets)
    with stage_clock(st.setdefault("build_memory", {})):
        bank, _ = build_bank(scenes, [r.stream for r in art["explored"]], cfg, embedder=embedder)
        jax.block_until_ready(bank.memory)
    with stage_clock(st.setdefault("episodes", {})):
        episodes = [g.episode for g in generate_episodes(scenes, cfg.episodes, cfg.seed)]
    with stage_clock(st.setdefault("retrieve", {})):
        batch, meta = prepare_batch(bank, scenes, episodes, embedder)
        if batch is not None:
            jax.block_until_ready(score_bank(batch.index, batch.queries, batch.qmask, params_from_config(cfg.retrieval)))
    st["retrieve"]["subgoals"] = sum(s is not None for s in meta.slots)
    by_name = {s.name: s for s in scenes}
    k = p.e2e_plan_episodes
    todo = episodes[:: max(1, len(episodes) // max(k, 1))][:k] if plan else []
    failed = 0
    with stage_clock(st.setdefault("plan", {})):
        for ep in todo:
            try:
                plan_instruction(bank, by_name[ep.scene], ep.instruction, embedder, cfg)
            except Exception:  # an instruction the parser rejects counts as a failure, not a crash
                failed += 1
    st["plan"].update({"instructions": len(todo), "failed": failed,
                       "per_instruction_s": st["plan"]["wall_s"] / max(len(todo), 1)})
    skip = ("skipped in this run (execute is timed in the scene-count runs)" if not execute else
            "skipped (e2e_execute_episodes=0)" if p.e2e_execute_episodes < 1 else None)
    try:
        if skip:
            raise Unavailable(skip)
        evaluate_navigation = execute_stage()
        runs = episodes[:: max(1, len(episodes) // max(p.e2e_execute_episodes, 1))][: p.e2e_execute_episodes]
        streams = {s.name: r.stream for s, r in zip(scenes, art["explored"])}
        with stage_clock(st.setdefault("execute", {})):
            _, summ_ex = evaluate_navigation(bank, scenes, runs, embedder, cfg, method="ragnav", streams=streams)
        st["execute"].update({"episodes": len(runs), "per_episode_s": st["execute"]["wall_s"] / max(len(runs), 1),
                              "success_rate": summ_ex.get("success_rate")})
    except Unavailable as e:
        st["execute"] = {"status": "skipped" if skip else "not available", "reason": str(e)}
    except Exception as e:  # the closed loop is another engineer's work in progress: record, go on
        st["execute"] = {"status": "failed", "reason": f"{type(e).__name__}: {e}"}
    summ = memory_summary(bank)
    art.update(bank=bank, episodes=episodes, batch=batch, meta=meta, embedder=embedder)
    rec = {"scenes": len(scenes), "episodes": len(episodes), "mean_nodes": summ["mean_nodes"], "stages": st}
    log(f"end to end, {len(scenes)} scenes ({summ['mean_nodes']:.0f} nodes/scene): " + ", ".join(
        f"{k} {v['wall_s']:.2f} s" for k, v in st.items() if "wall_s" in v))
    return rec, art


_ARTIFACTS: dict = {}  # (profile name, scenes) -> pipeline artifacts, so the sweep reuses end-to-end runs


def bench_end_to_end(p: Profile, log: Callable[[str], None]) -> dict:
    """Stage wall time, compile time and peak RSS vs scene count, then vs nodes per scene (keyframe spacing,
    on the scenes of the scene-count run of the same size, whose exploration is reused)."""
    from ragnav_jax.bench.timing import max_rss_mb

    by_scenes = []
    for n in p.e2e_scenes:
        rec, art = run_pipeline(paper_config(p, n), p, log)
        _ARTIFACTS[(p.name, n)] = art
        by_scenes.append(rec)
        _partial({"by_scenes": by_scenes})
    by_nodes = []
    art = _ARTIFACTS.get((p.name, p.e2e_spacing_scenes))
    for sp in p.e2e_spacings:
        rec, art = run_pipeline(paper_config(p, p.e2e_spacing_scenes, sp), p, log,
                                reuse=None if art is None else {k: art[k] for k in ("scenes", "explored")}, execute=False)
        rec["keyframe_spacing"] = sp
        by_nodes.append(rec)
        _partial({"by_scenes": by_scenes, "by_nodes": by_nodes})
    ex = by_scenes[0]["stages"].get("execute", {})
    return {"preset": "configs/paper.yaml", "embedder": p.e2e_embedder, "explore_max_steps": p.e2e_explore_steps,
            "explore_batch": p.e2e_explore_batch, "by_scenes": by_scenes, "by_nodes": by_nodes,
            "execute": ex if "status" in ex else {"status": "ok"}, "process_max_rss_mb": max_rss_mb(),
            "note": "wall_s = compile_s + run_s; compile_s sums JAX tracing, lowering and XLA compile events "
                    "(jax.monitoring) inside the stage; peak_rss_mb is the process's resident set (host and XLA "
                    "buffers) sampled every 10 ms during the stage. Runs after the first reuse compiled code where "
                    "padded shapes repeat; plan and execute run on a sample of the episodes (counts in the JSON)."}


def bench_sweep(p: Profile, log: Callable[[str], None]) -> dict:
    """A sigma x eta (x lambda where navigation metrics exist) grid over the paper-preset retrieval batch."""
    from ragnav_jax.config import SweepAxes
    from ragnav_jax.errors import UserError
    from ragnav_jax.evaluation.sweep import run_sweep

    base = paper_config(p, p.sweep_scenes)
    art = _ARTIFACTS.get((p.name, p.sweep_scenes))
    if art is None:
        _, art = run_pipeline(base, p, log, execute=False)
        _ARTIFACTS[(p.name, p.sweep_scenes)] = art

    def cfg_for(axes: SweepAxes):
        sweep = dataclasses.replace(base.sweep, axes=axes, checkpoint=False, variants=("ragnav",))
        return dataclasses.replace(base, sweep=sweep)

    k3 = math.ceil(p.sweep_points ** (1 / 3) - 1e-9)
    k2 = math.ceil(math.sqrt(p.sweep_points) - 1e-9)
    lin = lambda a, b, k: tuple(float(x) for x in np.round(np.linspace(a, b, k), 5))  # noqa: E731
    tries = [("sigma x eta x lambda", SweepAxes(sigma=lin(0.5, 6, k3), eta=lin(0, 1, k3), lam=lin(0, 10, k3))),
             ("sigma x eta", SweepAxes(sigma=lin(0.5, 6, k2), eta=lin(0, 1, k2)))]
    note = None
    for label, axes in tries:
        cfg = cfg_for(axes)
        try:
            first: dict = {}
            with stage_clock(first):
                _, summary = run_sweep(cfg, art["batch"], art["meta"], None, bank=art["bank"], scenes=art["scenes"])
        except UserError as e:
            note = f"{label}: {e}"
            log(f"sweep: {label} not possible here ({e}); falling back")
            continue
        ts = []
        for _ in range(max(1, min(p.repeats, 3))):
            t0 = time.perf_counter()
            run_sweep(cfg, art["batch"], art["meta"], None, bank=art["bank"], scenes=art["scenes"])
            ts.append(time.perf_counter() - t0)
        points = summary["grid_points"]
        warm = stats(ts)
        log(f"sweep {label}: {points} points, {points / warm['median_s']:.0f} points/s (first call {first['wall_s']:.1f} s)")
        return {"grid": label, "grid_points": points, "scenes": p.sweep_scenes,
                "subgoals": sum(s is not None for s in art["meta"].slots), "first_call": first, "warm": warm,
                "points_per_s": points / warm["median_s"], "note": note}
    raise Unavailable(note or "no sweep grid could run")


# ----------------------------------------------------------------------------------------------------
# Closed loop: the host engine vs the device engine (eval.engine)

# The closed loop proper of each engine, both called by evaluate_navigation as fn(loop, states, ...) after its
# preamble (parsing, retrieval, verdict tables) and before the rows are made; it looks both up in these modules
# when it calls them, so wrapping the module attributes catches every call.
LOOP_ENTRY_POINTS = (("ragnav_jax.evaluation.host_loop", "_run_chunk"),  # host engine, one batch of episodes
                     ("ragnav_jax.evaluation.loop.program", "run_device"))  # device engine, all episodes


def loop_episodes(episodes: list, n: int) -> list:
    """n episodes: evenly spaced below the list's length (as the end-to-end execute stage picks them), the
    whole list repeated above it."""
    if n <= len(episodes):
        return episodes[:: max(1, len(episodes) // max(n, 1))][:n]
    return (episodes * math.ceil(n / len(episodes)))[:n]


@contextlib.contextmanager
def _captured_loop(calls: list):
    """While active, every call of a LOOP_ENTRY_POINTS function is timed (stage_clock) and appended to `calls`
    with its arguments and a copy of its states as they were before it ran, which `_replay` runs again.
    evaluate_navigation reports no loop-only time, so the module functions are wrapped for the duration of
    one call and restored after it."""
    import importlib

    saved = []
    for modname, name in LOOP_ENTRY_POINTS:
        mod = importlib.import_module(modname)
        fn = getattr(mod, name)

        @functools.wraps(fn)
        def timed(loop, states, *rest, _fn=fn, **kw):
            t0 = time.perf_counter()
            rec = {"fn": _fn, "loop": loop, "states": states, "rest": rest, "kw": kw, "before": copy.deepcopy(states)}
            rec["copy_s"] = time.perf_counter() - t0
            with stage_clock(rec):
                out = _fn(loop, states, *rest, **kw)
            calls.append(rec)
            return out

        setattr(mod, name, timed)
        saved.append((mod, name, fn))
    try:
        yield calls
    finally:
        for mod, name, fn in reversed(saved):
            setattr(mod, name, fn)


def _replay(calls: list, n: int, traces: dict, **ev) -> tuple[dict, list]:
    """Runs the captured loop calls again on fresh copies of their starting states; where n is more than they
    held, the states of the single captured call tiled to n (each copy its own object). Returns the
    stage_clock record (copying not timed) and the final states, in order. ev: eval settings (refill,
    batch_size) of the device loop's calls (run_device(loop, states, cfg)) instead of the captured config's."""
    held = sum(len(c["before"]) for c in calls)
    if n > held:
        if len(calls) != 1:
            raise ValueError(f"tiling to {n} episodes replays one captured call, not {len(calls)}")
        src = calls[0]["before"]
        jobs = [(calls[0], [copy.deepcopy(src[i % len(src)]) for i in range(n)])]
    else:
        jobs = [(c, copy.deepcopy(c["before"])) for c in calls]
    rec: dict = {"episodes": max(n, held)}
    before = sum(traces.values())
    with stage_clock(rec):
        for c, states in jobs:
            rest = c["rest"]
            if ev:
                cfg = rest[0]
                rest = (dataclasses.replace(cfg, eval=dataclasses.replace(cfg.eval, **ev)), *rest[1:])
            c["fn"](c["loop"], states, *rest, **c["kw"])
    rec["traces"] = sum(traces.values()) - before
    return rec, [st for _, states in jobs for st in states]


def _outcome_state(st) -> tuple:
    return tuple(st.status), tuple(st.found)


def _outcome_row(row: dict) -> tuple:
    return bool(row["success"]), tuple(row["goal_status"])


def engine_runs(run: Callable[[], tuple], n: int, repeats: int, traces: dict,
                refills: Sequence[float] = (), lanes: Sequence[int] = ()) -> tuple[dict, list[dict]]:
    """One engine's figures: run() (an evaluate_navigation call -> (rows, summary)) once with its loop captured,
    then the loop alone again on copies of the captured states (tiled to n episodes where n is more than run()
    evaluated), `repeats` times after the first timed run. The first timed run is the evaluate call's loop where
    no tiling is needed (else the first replay) and includes compilation: compile_s = first - median of the
    others. Returns (record, the evaluate call's rows). `traces`: the executor's trace counters."""
    calls: list = []
    ev: dict = {}
    t0 = sum(traces.values())
    with stage_clock(ev), _captured_loop(calls):
        rows, _ = run()
    ev["traces"] = sum(traces.values()) - t0
    ev["episodes"] = len(rows)
    ev["loop_s"] = sum(c["wall_s"] for c in calls)
    ev["loop_compile_s"] = sum(c["compile_s"] for c in calls)
    ev["preamble_s"] = ev["wall_s"] - ev["loop_s"] - sum(c["copy_s"] for c in calls)  # parsing ... rows
    if not calls:
        raise RuntimeError("evaluate_navigation ran no closed loop (no call of " +
                           ", ".join(f"{m}.{f}" for m, f in LOOP_ENTRY_POINTS) + ")")
    finals = [st for c in calls for st in c["states"]]
    d = len(finals)
    tiled = n > d
    runs = [] if tiled else [{"episodes": d, "wall_s": ev["loop_s"], "compile_s": ev["loop_compile_s"],
                              "traces": ev["traces"], "source": "evaluate_navigation call"}]
    same, last = [], finals
    for _ in range(repeats + (1 if tiled else 0)):
        rec, last = _replay(calls, max(n, d), traces)
        rec["source"] = "replay"
        runs.append(rec)
        same += [_outcome_state(st) == _outcome_state(finals[i % d]) for i, st in enumerate(last)]
    warm = stats([r["wall_s"] for r in runs[1:] or runs])
    m = runs[0]["episodes"]
    variants = {"refills": [("refill", r) for r in refills], "lanes": [("batch_size", b) for b in lanes]}
    by = {}
    for group, settings in variants.items():  # the same states again with other eval settings
        by[group] = {}
        for key, v in settings:
            times = []  # a refill share or a lane count is a new compilation: its first replay is timed apart
            for _ in range(max(repeats, 1) + 1):
                rec, fin = _replay(calls, max(n, d), traces, **{key: v})
                times.append(rec["wall_s"])
                same += [_outcome_state(st) == _outcome_state(finals[i % d]) for i, st in enumerate(fin)]
            w = stats(times[1:])
            by[group][str(v)] = {"warm": w, "episodes_per_s": m / w["median_s"],
                                 "compile_s": max(times[0] - w["median_s"], 0.0)}
    return {"episodes": m, "distinct_episodes": d, "tiled": tiled, "evaluate_call": ev, "runs": runs, "warm": warm,
            "episodes_per_s": m / warm["median_s"], "episodes_per_s_range": [m / warm["max_s"], m / warm["min_s"]],
            "compile_s": max(runs[0]["wall_s"] - warm["median_s"], 0.0), "jax_compile_s_first": runs[0]["compile_s"],
            "compilations": ev["traces"] + sum(r["traces"] for r in runs if r["source"] == "replay"),
            "compilations_after_first": sum(r["traces"] for r in runs[1:]),
            "replay_agreement": float(np.mean(same)) if same else None, **by,
            "steps_per_episode": float(np.mean([st.steps + st.look_steps for st in last]))}, rows


def bench_closed_loop(p: Profile, log: Callable[[str], None]) -> dict:
    """Episodes/s of the closed loop with eval.engine=host (the host state machine, one batched MJX call per
    leg) and eval.engine=device (the whole loop of a batch as one jitted while_loop) on the same paper-preset
    episodes, executor and verifier; per-episode agreement of the two; MJX's step-only rate at the loop's batch
    (experiments/bench_sim.py) with the episodes/s it implies at the loop's steps per episode."""
    from ragnav_jax.evaluation.execute import make_executor
    from ragnav_jax.evaluation.verify import Verifier
    from ragnav_jax.sim.env import NavEnv

    evaluate_navigation = execute_stage()
    try:
        from ragnav_jax.evaluation.loop import program  # noqa: F401  the device engine
    except ImportError as e:
        raise Unavailable(f"the device closed loop (evaluation/loop) is not in this tree ({e})") from e
    base = paper_config(p, p.loop_scenes)
    if not hasattr(base.eval, "engine"):
        raise Unavailable("eval.engine is not in this tree's config")
    setup: dict = {}
    with stage_clock(setup):
        art = _ARTIFACTS.get((p.name, p.loop_scenes))
        if art is None:
            _, art = run_pipeline(base, p, log, execute=False, plan=False)
            _ARTIFACTS[(p.name, p.loop_scenes)] = art
        scenes, bank, embedder = art["scenes"], art["bank"], art["embedder"]
        distinct = loop_episodes(art["episodes"], min(p.loop_distinct or p.loop_episodes, p.loop_episodes,
                                                      len(art["episodes"])))
        n = max(p.loop_episodes, len(distinct))
        batch = p.loop_batch or base.eval.batch_size
        used = [s for s in scenes if s.name in {ep.scene for ep in distinct}]
        executor = make_executor(used, base)  # shared by both engines and both methods, as their verifier
        verifier = Verifier.build(embedder, base)
    streams = {s.name: r.stream for s, r in zip(scenes, art["explored"])}

    def runner(method: str, engine: str):
        cfg = dataclasses.replace(base, eval=dataclasses.replace(base.eval, engine=engine, batch_size=batch))
        return lambda: evaluate_navigation(bank, scenes, distinct, embedder, cfg, method, streams=streams,
                                           executor=executor, verifier=verifier)

    res = {"preset": "configs/paper.yaml", "embedder": p.e2e_embedder, "scenes": len(scenes),
           "scene_episodes": len(art["episodes"]), "distinct_episodes": len(distinct), "episodes": n,
           "batch_size": batch, "setup": setup, "methods": {}, "comparisons": []}
    for method in p.loop_methods:
        host, host_rows = engine_runs(runner(method, "host"), len(distinct), p.loop_host_repeats, executor.traces)
        _partial(res)
        dev, dev_rows = engine_runs(runner(method, "device"), n, p.loop_repeats, executor.traces, p.loop_refills,
                                     p.loop_lanes)
        dev["refill"] = base.eval.refill
        same = [_outcome_row(h) == _outcome_row(d) for h, d in zip(host_rows, dev_rows)]
        rec = {"host": host, "device": dev, "agreement": float(np.mean(same)), "agreement_episodes": len(same),
               "success_rate_host": float(np.mean([r["success"] for r in host_rows])),
               "success_rate_device": float(np.mean([r["success"] for r in dev_rows]))}
        res["methods"][method] = rec
        res["comparisons"].append(comparison(
            "closed_loop", f"device vs host closed loop, {method}, {dev['episodes']} episodes",
            _per(dev["warm"], dev["episodes"]), _per(host["warm"], host["episodes"]), "host loop (eval.engine=host)",
            "episode", method=method, compile_s=dev["compile_s"], agreement=rec["agreement"],
            episodes=dev["episodes"], peer_episodes=host["episodes"], batch_size=batch))
        _partial(res)
        log(f"closed loop {method}: host {host['episodes_per_s']:.2f} ep/s ({host['episodes']} episodes), device "
            f"{dev['episodes_per_s']:.2f} ep/s ({dev['episodes']}), x{res['comparisons'][-1]['ratio']:.2f}, device "
            f"compile {dev['compile_s']:.1f} s, agreement {rec['agreement']:.2f}")
    # MJX's step-only rate at the device loop's batch, on these scenes
    env_batch = min(batch, n)
    sim = experiment("bench_sim").bench_mjx(NavEnv(used, base.sim), env_batch, p.sim_steps, p.repeats)
    res.update(mjx=sim, env_steps_per_s=sim["env_steps_per_s"])
    for rec in res["methods"].values():
        spe = rec["device"]["steps_per_episode"]
        rec["steps_per_episode"] = spe
        rec["episodes_per_s_bound"] = sim["env_steps_per_s"] / spe if spe > 0 else None
        rec["device_over_bound"] = rec["device"]["episodes_per_s"] / rec["episodes_per_s_bound"] if spe > 0 else None
    log(f"closed loop: MJX {sim['env_steps_per_s']:.0f} env-steps/s at batch {env_batch}; at that rate " + ", ".join(
        f"{m} {r['episodes_per_s_bound']:.2f} ep/s" for m, r in res["methods"].items() if r["episodes_per_s_bound"]))
    res["note"] = (
        "Each engine runs evaluate_navigation once on the distinct episodes (its rows give agreement and success); "
        "the closed loop proper (host_loop._run_chunk batches, loop.program.run_device) is then run again on copies of "
        "the states that call handed it, so the timed runs leave out the preamble (parsing, retrieval, verdict "
        "tables; preamble_s under evaluate_call), which is host work per episode and the same for both engines. "
        + (f"The device runs tile the {len(distinct)} distinct episodes' states to {n} (the same work repeated, "
           "for throughput at a large batch); the host engine runs the distinct ones. " if n > len(distinct) else "")
        + "episodes_per_s: episodes / median seconds of the runs after the first; compile_s = first run - that "
        "median (the first run: the evaluate call's loop or, tiled, the first replay, which compiles for its batch "
        "once more); refills, lanes: the same replays at other eval.refill shares and eval.batch_size lane counts (each compiles once, in a first replay timed apart: compile_s). compilations: traces of the executor's jitted init, run and look (the device program traces "
        "run and look once each). agreement: "
        "share of distinct episodes with the same success and goal_status on both engines; replay_agreement: the "
        "same status and found on every replay as in the evaluate call. env_steps_per_s: experiments/bench_sim.py "
        "bench_mjx at the device batch on these scenes; its env step is physics + lidar + camera visibility, while "
        "a loop step is physics + pure pursuit, so episodes_per_s_bound = env_steps_per_s / steps_per_episode "
        "(steps as the rows count them, look-around turns included) is a reference, not a ceiling.")
    return res


def closed_loop_markdown(sec: dict) -> list[str]:
    """bench.md lines of the closed_loop section (none where no method was measured)."""
    if not sec.get("methods"):
        return []
    nan = float("nan")
    L = ["## Closed loop: host vs device engine", "",
         f"{sec['scenes']} paper-preset scene(s), {sec['distinct_episodes']} distinct episodes through "
         f"evaluate_navigation on both engines; device timed on {sec['episodes']}, batch {sec['batch_size']}. "
         f"MJX alone at that batch: {sec.get('env_steps_per_s', nan):.0f} env-steps/s.", "",
         "| method | host ep/s | device ep/s [range] | device / host | device compile s | compilations host / device "
         "| steps/episode | ep/s at MJX rate | agreement |", "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for m, r in sec["methods"].items():
        h, d = r["host"], r["device"]
        lo, hi = d["episodes_per_s_range"]
        L.append(f"| {m} | {h['episodes_per_s']:.2f} | {d['episodes_per_s']:.2f} [{lo:.2f}-{hi:.2f}] | "
                 f"{d['episodes_per_s'] / h['episodes_per_s']:.2f}x | {d['compile_s']:.1f} | {h['compilations']} / "
                 f"{d['compilations']} | {r.get('steps_per_episode', nan):.0f} | "
                 f"{r.get('episodes_per_s_bound') or nan:.2f} | {r['agreement']:.2f} |")
    titles = {"refills": "eval.refill (the share of the lanes one reflection serves)",
              "lanes": "eval.batch_size lanes (episodes run at once; the others queue)"}
    for group, what, conf in (("refills", "refill", "refill"), ("lanes", "lanes", "batch_size")):
        rows = [(m, r["device"]) for m, r in sec["methods"].items() if r["device"].get(group)]
        if not rows:
            continue
        keys = list(rows[0][1][group])
        L += ["", f"Device ep/s by {titles[group]}; rows do not depend on it:", "",
              "| method | " + " | ".join(f"{what} {k}" for k in keys) + f" | {what} {rows[0][1].get(conf, sec.get('batch_size'))} (run above) |",
              "|---|" + "---:|" * (len(keys) + 1)]
        for m, d in rows:
            L.append(f"| {m} | " + " | ".join(f"{v['episodes_per_s']:.2f}" for v in d[group].values()) +
                     f" | {d['episodes_per_s']:.2f} |")
    return L + ["", sec.get("note", ""), ""]


def bench_memory_update(p: Profile, log: Callable[[str], None]) -> dict:
    """Online memory updates (memory/update.py), each batched over `update_episodes` episodes that hold their own
    copy of one paper-preset scene's memory (grown by free slots): a key pose inserted (paths repaired, forest
    followed), an edge added, an edge removed; per observation (an episode's update), against rebuilding that
    scene's memory from its exploration (`build_bank`, the hashing or MiniLM embedder of the profile) and next
    to embedding one new caption with that embedder. Compile times apart."""
    import jax
    import jax.numpy as jnp

    from ragnav_jax.memory.build import build_bank
    from ragnav_jax.memory.update import add_edge, grow, insert_node, remove_edge
    from ragnav_jax.pytrees import take

    cfg = paper_config(p, 1)
    art = _ARTIFACTS.get((p.name, 1)) or run_pipeline(cfg, p, log, execute=False, plan=False)[1]
    scene, stream, emb = art["scenes"][0], art["explored"][0].stream, art["embedder"]
    times = []
    for _ in range(1 + p.repeats):  # the first call compiles
        t0 = time.perf_counter()
        bank, _ = build_bank([scene], [stream], cfg, embedder=emb)
        jax.block_until_ready(bank.memory)
        times.append(time.perf_counter() - t0)
    first, rebuild = times[0], stats(times[1:])
    E, rng = p.update_episodes, np.random.default_rng(0)
    mem = grow(take(bank.memory, 0), 16)
    live = np.flatnonzero(np.asarray(mem.node_mask))
    pos, adj = np.asarray(mem.position), np.asarray(mem.adjacency)
    near = rng.choice(live, E)  # each episode sees something new half a metre from one of its key poses
    new_pos = (pos[near] + rng.normal(0, 0.5, (E, 3)) * [1, 1, 0]).astype(np.float32)
    links = (np.linalg.norm(pos[None] - new_pos[:, None], axis=-1) < cfg.memory.delta_spatial) & np.asarray(mem.node_mask)
    links[np.arange(E), near] = True
    slot = np.full(E, int(np.flatnonzero(~np.asarray(mem.node_mask))[0]), np.int32)
    edges = np.argwhere(np.triu(adj))
    cut = edges[rng.integers(len(edges), size=E)]
    apart = np.argwhere(np.triu(~adj & np.asarray(mem.node_mask)[:, None] & np.asarray(mem.node_mask)[None], 1))
    join = apart[rng.integers(len(apart), size=E)]
    mems = jax.tree.map(lambda x: jnp.broadcast_to(x, (E, *x.shape)), mem)
    g = lambda f: jnp.asarray(np.asarray(f)[near])  # noqa: E731  the new key pose's fields, from its neighbour's
    ops = {
        "insert a key pose": (jax.vmap(insert_node), (mems, jnp.asarray(slot), jnp.asarray(new_pos), g(mem.yaw),
                                                      g(mem.embedding), g(mem.sensors), g(mem.sensor_mask),
                                                      g(mem.obs_object), g(mem.obs_distance), jnp.asarray(links))),
        "add an edge": (jax.vmap(add_edge), (mems, jnp.asarray(join[:, 0]), jnp.asarray(join[:, 1]))),
        "remove an edge": (jax.vmap(remove_edge), (mems, jnp.asarray(cut[:, 0]), jnp.asarray(cut[:, 1]))),
    }
    rows, comps = [], []
    for name, (fn, args) in ops.items():
        t0 = time.perf_counter()
        compiled = jax.jit(fn).lower(*args).compile()
        compile_s = time.perf_counter() - t0
        jax.block_until_ready(compiled(*args))
        rs = []
        for _ in range(p.repeats):
            t0 = time.perf_counter()
            jax.block_until_ready(compiled(*args))
            rs.append(time.perf_counter() - t0)
        ours = _per(stats(rs), E)
        rows.append({"update": name, "episodes": E, "nodes": int(mem.node_mask.shape[0]), "live": len(live),
                     "per_observation": ours, "compile_s": compile_s})
        comps.append(comparison("memory_update", f"{name}, batched over {E} episodes, vs rebuilding the scene's "
                                f"memory ({len(live)} key poses)", ours, rebuild, "build_bank (one scene)",
                                "observation", compile_s=compile_s, rebuild_first_call_s=first))
        log(f"memory update: {name} {1e3 * ours['median_s']:.3f} ms per observation ({E} episodes, compile "
            f"{compile_s:.1f} s); rebuild {rebuild['median_s']:.2f} s")
        _partial({"rows": rows, "comparisons": comps})
    caps = list(bank.metas[0].captions[:E]) or ["a chair"]
    es = []
    for r in range(1 + p.repeats):  # fresh texts each time: an embedder may keep what it embedded
        t0 = time.perf_counter()
        emb.embed([f"{c} ({r}.{i})" for i, c in enumerate(caps)])
        es.append((time.perf_counter() - t0) / len(caps))
    return {"rows": rows, "comparisons": comps, "rebuild": rebuild, "rebuild_first_call_s": first,
            "embed_caption": stats(es[1:]), "embedder": cfg.memory.embedder, "scene": scene.name}


def memory_update_markdown(sec: dict) -> list[str]:
    """The memory_update section's table."""
    if not sec.get("rows"):
        return []
    L = ["## Online memory updates", "", f"One paper-preset scene ({sec['scene']}); rebuilding its memory takes "
         f"{sec['rebuild']['median_s']:.2f} s (first call {sec['rebuild_first_call_s']:.1f} s); embedding one new "
         f"caption with {sec['embedder']} {1e3 * sec['embed_caption']['median_s']:.2f} ms.", "",
         "| update | episodes | node slots (live) | ms per observation (median [min-max]) | compile s | x rebuild |",
         "|---|---:|---:|---:|---:|---:|"]
    for r in sec["rows"]:
        o = r["per_observation"]
        L.append(f"| {r['update']} | {r['episodes']} | {r['nodes']} ({r['live']}) | {1e3 * o['median_s']:.3f} "
                 f"[{1e3 * o['min_s']:.3f}-{1e3 * o['max_s']:.3f}] | {r['compile_s']:.1f} | "
                 f"{sec['rebuild']['median_s'] / o['median_s']:.0f} |")
    return L + [""]


SECTION_FUNCS = {
    "retrieval": bench_retrieval, "paths": bench_paths, "planning": bench_planning, "simulation": bench_simulation,
    "end_to_end": bench_end_to_end, "sweep": bench_sweep, "closed_loop": bench_closed_loop,
    "memory_update": bench_memory_update,
}
