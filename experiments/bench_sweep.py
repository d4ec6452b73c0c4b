"""Benchmark: a 10 x 10 sigma x eta retrieval grid as one compiled call vs a Python loop over the 100 points.

    python experiments/bench_sweep.py --run RUN --episodes RUN/episodes/episodes.jsonl --out runs/bench_sweep \
        [--config configs/sweep.yaml --repeats 5]

RUN holds scenes/ and memory/bank (the paper preset: ragnav generate/explore/build-memory/episodes with
configs/paper.yaml). The grid is sweep.axes.sigma x sweep.axes.eta of the config (10 x 10 in
configs/sweep.yaml), variant "ragnav", over every subgoal of the episodes file:
- grid: evaluation/sweep.py's grid_correct, the 100 points as one jitted nested-vmap call;
- loop: a jitted single-point correct_counts (compiled once) called for each point in a Python loop,
  its result read back each time, as a loop would.
Compile time is measured apart (lower + compile) for both; run times are the median of --repeats runs
after a warm-up; both give the same hits (checked). The five-variant grid (500 points, ablations in the
same call) is timed too. Writes OUT/bench_sweep.json next to the run's config and provenance.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import statistics
import sys
import time
from pathlib import Path

import jax
import numpy as np

from ragnav_jax.config import load_config
from ragnav_jax.evaluation.commands import load_retrieval_inputs
from ragnav_jax.evaluation.sweep import _grid_correct, make_grid
from ragnav_jax.retrieval.evaluate import correct_counts, prepare_batch
from ragnav_jax.retrieval.params import params_from_config
from ragnav_jax.runs import init_run


def _median(fn, repeats: int) -> float:
    ts = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        jax.block_until_ready(fn())
        ts.append(time.perf_counter() - t0)
    return statistics.median(ts)


def bench_grid(batch, grid, repeats: int) -> tuple[dict, np.ndarray]:
    """The whole grid in one call: compile apart, then the median run time."""
    params, _ = grid.chunk(0, grid.num_combos, grid.num_combos)
    fn = _grid_correct(grid.outer, grid.inner)
    t0 = time.perf_counter()
    compiled = fn.lower(batch, params).compile()
    compile_s = time.perf_counter() - t0
    out = np.asarray(compiled(batch, params))  # warm-up
    run_s = _median(lambda: compiled(batch, params), repeats)
    return {"compile_s": compile_s, "run_s": run_s}, out.reshape(grid.size, -1)


def bench_loop(batch, grid, repeats: int) -> tuple[dict, np.ndarray]:
    """A Python loop over the points, one compiled single-point call each (compiled once)."""
    points = [jax.tree.map(lambda x, p=p: jax.numpy.asarray(x[p]), grid.params) for p in range(grid.size)]
    t0 = time.perf_counter()
    compiled = jax.jit(correct_counts).lower(batch, points[0]).compile()
    compile_s = time.perf_counter() - t0

    def loop():
        return [np.asarray(compiled(batch, p)) for p in points]

    out = np.stack(loop())  # warm-up
    run_s = _median(loop, repeats)
    return {"compile_s": compile_s, "run_s": run_s}, out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--run", required=True)
    ap.add_argument("--episodes", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--config", default=str(Path(__file__).resolve().parents[1] / "configs" / "sweep.yaml"))
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("overrides", nargs="*", default=[])
    args = ap.parse_args(argv)
    cfg = load_config(args.config, args.overrides)
    out = init_run(args.out, cfg, "bench_sweep", argv=sys.argv)
    bank, scenes, episodes, embedder = load_retrieval_inputs(args.run, args.episodes, cfg)
    batch, meta = prepare_batch(bank, scenes, episodes, embedder)
    base = params_from_config(cfg.retrieval)
    axes = dataclasses.replace(cfg.sweep.axes.__class__(), sigma=cfg.sweep.axes.sigma, eta=cfg.sweep.axes.eta)
    grid = make_grid(dataclasses.replace(cfg.sweep, axes=axes, variants=("ragnav",)), base)
    g, g_out = bench_grid(batch, grid, args.repeats)
    loop, l_out = bench_loop(batch, grid, args.repeats)
    equal = bool(np.array_equal(g_out, l_out))
    grid5 = make_grid(dataclasses.replace(cfg.sweep, axes=axes), base)
    g5, _ = bench_grid(batch, grid5, args.repeats)
    acc = g_out.sum(1) / meta.totals.sum()
    best = int(np.argmax(acc))
    res = {
        "grid_points": grid.size, "axes": {"sigma": list(axes.sigma), "eta": list(axes.eta)},
        "scenes": int(batch.qmask.shape[0]), "subgoals": int(np.asarray(batch.qmask).sum()),
        "subgoals_counted": int(meta.totals.sum()),  # accuracy denominator: subgoals incl. any whose instruction failed to parse
        "grid_run_s": round(g["run_s"], 4), "grid_compile_s": round(g["compile_s"], 3),
        "loop_run_s": round(loop["run_s"], 4), "loop_compile_s": round(loop["compile_s"], 3),
        "speedup_loop_over_grid": round(loop["run_s"] / g["run_s"], 2),
        "grid_ms_per_point": round(1e3 * g["run_s"] / grid.size, 3),
        "loop_ms_per_point": round(1e3 * loop["run_s"] / grid.size, 3),
        "same_results": equal,
        "ablation_grid_points": grid5.size, "ablation_variants": list(grid5.variants),
        "ablation_grid_run_s": round(g5["run_s"], 4), "ablation_grid_compile_s": round(g5["compile_s"], 3),
        "best_point": grid.points[best], "best_accuracy": round(float(acc[best]), 4),
        "repeats": args.repeats, "device": str(jax.devices()[0]), "devices": jax.device_count(),
        "cpu_count": os.cpu_count(), "embedder": getattr(embedder, "name", type(embedder).__name__),
        "note": "run times: median of repeats after a warm-up; compile apart (lower + compile); host-side timing",
    }
    (Path(out) / "bench_sweep.json").write_text(json.dumps(res, indent=1) + "\n")
    print(json.dumps(res, indent=1))
    return 0 if equal else 1


if __name__ == "__main__":
    sys.exit(main())
