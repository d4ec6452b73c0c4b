"""Order problems from the memory's shortest-path cost matrix (one episode; vmap for many)."""

from __future__ import annotations

import jax.numpy as jnp

from ragnav_jax.planning.types import Array, OrderProblem


def order_problem(
    dist: Array,
    start: Array,
    targets: Array,
    goal_mask: Array | None = None,
    rank: Array | None = None,
    reachable: Array | None = None,
    cand_mask: Array | None = None,
    unary: Array | None = None,
) -> OrderProblem:
    """Builds an OrderProblem from all-pairs shortest-path costs.

    Args:
      dist: (N, N) shortest-path cost; `inf` (or any value, with `reachable`) where no path exists.
      start: () int32 start node.
      targets: (G,) or (G, K) int32 target nodes (K candidates per goal); -1 marks padding.
      goal_mask: (G,) bool, default: goals with at least one candidate >= 0.
      rank: (G,) int32 position of each goal in the instruction, default 0..G-1 (strict order);
        equal ranks leave those goals unordered ("find A and B" gives both the same rank).
      reachable: (N, N) bool, for memories that mark unreachable pairs with a finite sentinel.
      cand_mask: (G, K) bool, default `targets >= 0`.
      unary: (G, K) float32 extra cost per candidate (e.g. weight * (1 - retrieval score)).
    Returns the OrderProblem; unreachable pairs carry `+inf` costs, which every solver turns into
    an explicit status (never a silent infinite objective).
    """
    targets = jnp.asarray(targets, jnp.int32)
    if targets.ndim == 1:
        targets = targets[:, None]
    G, K = targets.shape
    dist = jnp.asarray(dist, jnp.float32)
    ok = jnp.isfinite(dist) if reachable is None else jnp.asarray(reachable, bool) & ~jnp.isnan(dist)
    dist = jnp.where(ok, dist, jnp.inf)
    cmask = targets >= 0 if cand_mask is None else jnp.asarray(cand_mask, bool) & (targets >= 0)
    gmask = jnp.any(cmask, axis=1) if goal_mask is None else jnp.asarray(goal_mask, bool) & jnp.any(cmask, axis=1)
    cmask = cmask & gmask[:, None]
    safe = jnp.clip(targets, 0, dist.shape[0] - 1)
    start_cost = jnp.where(cmask, dist[start][safe], jnp.inf)
    pair = dist[safe[:, :, None, None], safe[None, None, :, :]]  # (G, K, G, K)
    pair = jnp.where(cmask[:, :, None, None] & cmask[None, None, :, :], pair, jnp.inf)
    rank = jnp.arange(G, dtype=jnp.int32) if rank is None else jnp.asarray(rank, jnp.int32)
    unary = jnp.zeros((G, K), jnp.float32) if unary is None else jnp.asarray(unary, jnp.float32)
    return OrderProblem(
        start_cost=start_cost,
        cost=pair,
        unary=jnp.where(cmask, unary, 0.0),
        nodes=jnp.where(cmask, targets, -1),
        cand_mask=cmask,
        rank=rank,
        mask=gmask,
    )


def precedence(rank: Array, active: Array) -> Array:
    """(G, G) bool `after[i, j]`: goal j should be visited after goal i (both active)."""
    return active[:, None] & active[None, :] & (rank[:, None] < rank[None, :])


def reachable_candidates(problem: OrderProblem) -> tuple[Array, Array]:
    """Candidates reachable from the start (G, K) bool, and goals with any such candidate (G,) bool."""
    cand_ok = problem.cand_mask & jnp.isfinite(problem.start_cost)
    return cand_ok, problem.mask & jnp.any(cand_ok, axis=1)


def candidate_unary(scores: Array, weight: Array, cand_mask: Array | None = None) -> Array:
    """(G, K) unary costs for a joint candidate choice: weight * (best score of the goal - candidate score).

    scores: (G, K) retrieval scores of each goal's top-k candidates; weight: metres per unit of score
    (PlanningConfig.candidate_weight). The top candidate costs nothing, so weight = 0 picks candidates
    by travel alone and a large weight keeps the top-1 retrieval.
    """
    scores = jnp.asarray(scores, jnp.float32)
    ok = jnp.ones(scores.shape, bool) if cand_mask is None else jnp.asarray(cand_mask, bool)
    best = jnp.max(jnp.where(ok, scores, -jnp.inf), axis=1, keepdims=True)
    return jnp.where(ok, weight * (best - scores), 0.0)
