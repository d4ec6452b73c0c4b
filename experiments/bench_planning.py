"""Benchmark: batched JAX order solvers vs a plain Python loop, and the local-search gap.

    python experiments/bench_planning.py --out runs/bench_planning [--episodes 10000 --repeats 3]

Brute force (n = 8) and Held-Karp (n = 12) solve `--episodes` random episodes in one batched, jitted
call each; the Python baselines (itertools permutations for n = 8, textbook Held-Karp with itertools
combinations for n = 12) run on a subsample and are extrapolated linearly to all episodes, which the
JSON says (`python_extrapolated`). Compile time is measured apart (lower + compile); run times are the
median of `--repeats` calls after one warm-up call; ratios are taken from this one run. The local
search's gap to the exact Held-Karp optimum is measured on the same episodes. Writes
OUT/bench_planning.json next to the run's config and provenance.
"""

from __future__ import annotations

import argparse
import itertools
import json
import math
import statistics
import sys
import time
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.config import load_config
from ragnav_jax.planning import order as order_mod
from ragnav_jax.planning import order_problem
from ragnav_jax.runs import init_run


def make_episodes(rng: np.random.Generator, episodes: int, n: int):
    """Episodes of n goals scattered in a 20 m house, start at the origin; returns costs and problems."""
    pts = rng.uniform(0, 20, (episodes, n + 1, 2)).astype(np.float32)
    dist = np.linalg.norm(pts[:, :, None] - pts[:, None, :], axis=-1).astype(np.float32)  # (E, n+1, n+1)
    targets = jnp.arange(1, n + 1, dtype=jnp.int32)
    problems = jax.jit(jax.vmap(lambda d: order_problem(d, 0, targets)))(jnp.asarray(dist))
    return dist, problems


# ----------------------------------------------------------------------------------------------------
# Plain Python baselines (lists, no NumPy inside the loops)


def python_brute_force(d: list[list[float]], lam: float) -> float:
    """Best objective over itertools.permutations; node 0 is the start, goals 1..n in instruction order."""
    n = len(d) - 1
    best = math.inf
    for perm in itertools.permutations(range(1, n + 1)):
        cost = d[0][perm[0]]
        for a, b in zip(perm, perm[1:]):
            cost += d[a][b]
        inv = sum(1 for i in range(n) for j in range(i + 1, n) if perm[i] > perm[j])
        best = min(best, cost + lam * inv)
    return best


def python_held_karp(d: list[list[float]], lam: float) -> float:
    """Textbook Held-Karp over itertools.combinations, with the exact inversion penalty."""
    n = len(d) - 1
    dp = {(1 << j, j): d[0][j + 1] for j in range(n)}
    for size in range(2, n + 1):
        for subset in itertools.combinations(range(n), size):
            bits = sum(1 << k for k in subset)
            for j in subset:
                prev = bits ^ (1 << j)
                pen = lam * sum(1 for k in subset if k > j)  # goals visited before j that should follow it
                dp[(bits, j)] = min(dp[(prev, i)] + d[i + 1][j + 1] for i in subset if i != j) + pen
    full = (1 << n) - 1
    return min(dp[(full, j)] for j in range(n)) if n else 0.0


# ----------------------------------------------------------------------------------------------------


def time_jax(method: str, problems, lams, repeats: int, **kw) -> tuple[dict, object]:
    """Compile time, then the median of `repeats` timed calls after a warm-up (host timing, outside jit)."""
    E, G, K = problems.cand_mask.shape
    batch = kw.pop("batch_size", None)
    if batch is None:
        per = order_mod._episode_bytes(method, G, K) * lams.shape[0]
        batch = int(max(1, min(E, (1 << 28) // per)))
    t = time.perf_counter()
    compiled = order_mod._solve.lower(
        problems, lams, method=method, batch_size=batch, max_iters=kw.get("max_iters", 100)
    ).compile()
    compile_s = time.perf_counter() - t
    out = jax.block_until_ready(compiled(problems, lams))  # warm-up
    runs = []
    for _ in range(repeats):
        t = time.perf_counter()
        out = jax.block_until_ready(compiled(problems, lams))
        runs.append(time.perf_counter() - t)
    return {
        "compile_s": compile_s,
        "run_s_median": statistics.median(runs),
        "run_s_all": runs,
        "batch_size": batch,
    }, out


def time_python(fn, dist: np.ndarray, lam: float, sample: int, episodes: int, repeats: int = 1) -> tuple[dict, list[float]]:
    """Median (min, max) of `repeats` timed passes over `sample` episodes, extrapolated to `episodes`."""
    lists = [d.astype(float).tolist() for d in dist[:sample]]
    runs = []
    for _ in range(max(1, repeats)):
        t = time.perf_counter()
        values = [fn(d, lam) for d in lists]
        runs.append(time.perf_counter() - t)
    elapsed = statistics.median(runs)
    return {
        "python_episodes_timed": sample,
        "python_s_timed": elapsed,
        "python_s_timed_all": runs,
        "python_s_per_episode": elapsed / sample,
        "python_s_all_episodes": elapsed / sample * episodes,
        "python_extrapolated": sample < episodes,
    }, values


def bench_case(name, method, n, fn, args, rng) -> tuple[dict, object, np.ndarray]:
    dist, problems = make_episodes(rng, args.episodes, n)
    lams = jnp.array([args.lam], jnp.float32)
    jx, out = time_jax(method, problems, lams, args.repeats)
    sample = args.python_sample_bf if method == "brute_force" else args.python_sample_hk
    py, values = time_python(fn, dist, args.lam, min(sample, args.episodes), args.episodes,
                             getattr(args, "python_repeats", 1))
    got = np.asarray(out.objective[0, : len(values)])
    agree = bool(np.allclose(got, np.array(values), rtol=1e-4, atol=1e-3))
    row = {
        "case": name,
        "method": method,
        "goals": n,
        "episodes": args.episodes,
        "lambda": args.lam,
        **jx,
        **py,
        "jax_episodes_per_s": args.episodes / jx["run_s_median"],
        "speedup_vs_python": py["python_s_all_episodes"] / jx["run_s_median"],
        "speedup_vs_python_incl_compile": py["python_s_all_episodes"] / (jx["run_s_median"] + jx["compile_s"]),
        "agrees_with_python": agree,
    }
    print(
        f"{name}: jax {jx['run_s_median']:.2f} s (compile {jx['compile_s']:.1f} s), python "
        f"{py['python_s_all_episodes']:.0f} s{' (extrapolated)' if py['python_extrapolated'] else ''}, "
        f"x{row['speedup_vs_python']:.0f}, agree={agree}",
        flush=True,
    )
    return row, out, dist


def gap_case(n: int, episodes: int, lam: float, rng, repeats: int) -> dict:
    """Local search vs the exact Held-Karp optimum on the same episodes."""
    _, problems = make_episodes(rng, episodes, n)
    lams = jnp.array([lam], jnp.float32)
    t_hk, exact = time_jax("held_karp", problems, lams, 1)
    t_ls, ls = time_jax("local_search", problems, lams, repeats)
    best, heur = np.asarray(exact.objective[0], np.float64), np.asarray(ls.objective[0], np.float64)
    gap = (heur - best) / np.maximum(best, 1e-9)
    row = {
        "goals": n,
        "episodes": episodes,
        "lambda": lam,
        "gap_mean_pct": 100 * float(gap.mean()),
        "gap_p95_pct": 100 * float(np.percentile(gap, 95)),
        "gap_max_pct": 100 * float(gap.max()),
        "optimal_fraction": float(np.mean(gap <= 1e-6)),
        "never_better_than_exact": bool(np.all(gap >= -1e-5)),
        "local_search_run_s": t_ls["run_s_median"],
        "held_karp_run_s": t_hk["run_s_median"],
    }
    print(
        f"local search n={n} lambda={lam}: mean gap {row['gap_mean_pct']:.3f}%, max {row['gap_max_pct']:.2f}%, "
        f"optimal {100 * row['optimal_fraction']:.1f}%",
        flush=True,
    )
    return row


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", required=True, help="run folder for bench_planning.json")
    ap.add_argument("--episodes", type=int, default=10_000)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--lam", type=float, default=5.0, help="order penalty (metres per inverted pair)")
    ap.add_argument("--python-sample-bf", type=int, default=50, help="episodes timed in Python, n = 8")
    ap.add_argument("--python-sample-hk", type=int, default=10, help="episodes timed in Python, n = 12")
    ap.add_argument("--python-repeats", type=int, default=1, help="timed passes over the Python sample (median)")
    ap.add_argument("--gap-episodes", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    out = init_run(args.out, load_config(), "bench_planning", argv=sys.argv if argv is None else argv)
    rng = np.random.default_rng(args.seed)

    cases = []
    bf, _, _ = bench_case("brute_force_n8", "brute_force", 8, python_brute_force, args, rng)
    cases.append(bf)
    hk, _, _ = bench_case("held_karp_n12", "held_karp", 12, python_held_karp, args, rng)
    cases.append(hk)
    # Order of magnitude only: the itertools permutation loop at n = 12, from its per-permutation time at n = 8.
    per_perm = bf["python_s_per_episode"] / math.factorial(8)
    hk["python_itertools_permutations_estimate_s"] = per_perm * math.factorial(12) * (12 * 11 / (8 * 7)) * args.episodes

    gaps = [gap_case(n, args.gap_episodes, lam, rng, args.repeats) for n in (10, 12) for lam in (0.0, args.lam)]
    result = {
        "benchmark": "planning",
        "device": str(jax.devices()[0]),
        "jax_version": jax.__version__,
        "note": "python_s_all_episodes is extrapolated linearly from python_episodes_timed where python_extrapolated "
        "is true; run times are medians after a warm-up call; compile time is measured apart.",
        "cases": cases,
        "local_search_gap": gaps,
    }
    path = Path(out) / "bench_planning.json"
    path.write_text(json.dumps(result, indent=1) + "\n")
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
