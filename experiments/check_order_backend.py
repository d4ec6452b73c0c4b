"""The batched order solvers on this machine's JAX backend against an itertools brute force (the trusted peer).

    python experiments/check_order_backend.py --batch 16384 --goals 5 --out OUT.json

Builds order problems the way the device loop's re-plan does (a start node then G goal nodes, map costs
with unreachable pairs, strict instructions with lambda = 1e4 and free ones with lambda = 0), solves them
with every exact solver under one jit(vmap), and scores each returned order with NumPy. An order is right
when its objective (travel + lambda x inversions) equals the itertools optimum; the report counts the
problems where it is not, per solver and lambda, and keeps the first few for reading.
"""

from __future__ import annotations

import argparse
import functools
import itertools
import json
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.planning.costs import order_problem
from ragnav_jax.planning.order import SOLVERS


def problems(rng: np.random.Generator, batch: int, G: int, unreachable: float):
    """Costs (B, G+1, G+1) between the start (0) and the goals (1..G), ranks (B, G) and goal counts (B,)."""
    xy = rng.uniform(0.0, 20.0, (batch, G + 1, 2))
    cost = np.linalg.norm(xy[:, :, None] - xy[:, None, :], axis=-1) * rng.uniform(1.0, 1.5, (batch, 1, 1))
    cut = rng.uniform(size=(batch, G + 1, G + 1)) < unreachable
    cut = cut | np.swapaxes(cut, 1, 2)
    cost = np.where(cut & ~np.eye(G + 1, dtype=bool), np.inf, cost).astype(np.float32)
    n = rng.integers(1, G + 1, batch)
    rank = np.stack([rng.permutation(G) for _ in range(batch)]).astype(np.int32)
    return cost, rank, n


def objective(cost, start_costs, order, rank, lam) -> float:
    """travel + lam x inversions of a visiting order (goal indices), NumPy."""
    travel = start_costs[order[0]] + sum(cost[a, b] for a, b in zip(order[:-1], order[1:]))
    inv = sum(1 for i in range(len(order)) for j in range(i + 1, len(order)) if rank[order[i]] > rank[order[j]])
    return float(travel) + (lam * inv if inv else 0.0)


def brute(cost, rank, n, lam) -> float:
    """The itertools optimum over the n live goals whose start cost is finite."""
    goals = [g for g in range(n) if np.isfinite(cost[0, g + 1])]
    if not goals:
        return 0.0
    best = min(objective(cost[1:, 1:], cost[0, 1:], p, rank, lam) for p in itertools.permutations(goals))
    return best


@functools.partial(jax.jit, static_argnums=0)
def _solve(method: str, cost, targets, rank, lam):
    """One solver over every problem (vmapped), as the device loop's re-plan calls it."""
    return jax.vmap(lambda c, t, r: SOLVERS[method](order_problem(c, jnp.int32(0), t, rank=r), lam))(cost, targets, rank)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--batch", type=int, default=4096)
    ap.add_argument("--goals", type=int, default=5)
    ap.add_argument("--unreachable", type=float, default=0.05)
    ap.add_argument("--check", type=int, default=3000, help="problems checked against itertools per run")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--out", type=Path, required=True)
    a = ap.parse_args(argv)
    rng = np.random.default_rng(a.seed)
    cost, rank, n = problems(rng, a.batch, a.goals, a.unreachable)
    G = a.goals
    slot = np.arange(G)
    targets = np.where(slot[None] < n[:, None], slot[None] + 1, -1).astype(np.int32)

    report = {"backend": jax.default_backend(), "devices": [str(d) for d in jax.devices()], "batch": a.batch,
              "goals": G, "runs": []}
    for method in ("held_karp", "brute_force"):
        for lam in (0.0, 1.0e4):
            res = jax.device_get(_solve(method, cost, targets, rank, np.float32(lam)))
            wrong, infeasible, examples = 0, 0, []
            for b in range(min(a.check, a.batch)):
                order = [int(k) for k in res.order[b] if k >= 0]
                want = brute(cost[b], rank[b], int(n[b]), lam)
                if not np.isfinite(want):  # no order reaches every goal: the solvers only report a status
                    infeasible += 1
                    continue
                got = objective(cost[b, 1:, 1:], cost[b, 0, 1:], order, rank[b], lam) if order else 0.0
                if not np.isclose(got, want, rtol=1e-5, atol=1e-3):
                    wrong += 1
                    if len(examples) < 5:
                        examples.append({"b": b, "n": int(n[b]), "rank": rank[b].tolist(), "order": order,
                                         "got": got, "want": want, "inversions": int(res.inversions[b]),
                                         "objective": float(res.objective[b])})
            checked = min(a.check, a.batch) - infeasible
            report["runs"].append({"method": method, "lam": lam, "checked": checked, "infeasible": infeasible,
                                   "wrong": wrong, "examples": examples})
            print(method, lam, "wrong", wrong, "of", checked, flush=True)
    a.out.parent.mkdir(parents=True, exist_ok=True)
    a.out.write_text(json.dumps(report, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
