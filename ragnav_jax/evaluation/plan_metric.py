"""Plan success as a sweep metric: retrieval (sigma, eta, ...) and order planning (lambda) in one grid.

Retrieval accuracy does not depend on the planning lambda; the plan built on the retrieved nodes does.
For every grid point this metric retrieves the top-1 node of every subgoal (the same kernel as
retrieval accuracy), plans each episode's visiting order over the memory's shortest-path costs with
that point's lambda (exact brute force over permutations, `planning.order`), and counts an episode as
planned right when every goal's node is a ground-truth node of its target and, for strict episodes,
the order keeps the instruction's (no inversion). Free-order episodes take the shortest order whatever
lambda is, so lambda trades route length against order fidelity on strict ones only.

    metric = plan_metric(batch, meta, bank, scenes, grid)
    run_sweep(cfg, batch, meta, extra_metrics=[metric])   # sweep.axes.lam now allowed

Sums are per modality over episodes (totals: episodes per modality, unparsed ones included as misses).
"""

from __future__ import annotations

import dataclasses
import functools
from collections.abc import Sequence

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.evaluation.sweep import Grid, GridMetric, _digest, _in_axes
from ragnav_jax.planning.order import MAX_BRUTE_FORCE_GOALS, MAX_HELD_KARP_GOALS, brute_force, held_karp, local_search
from ragnav_jax.planning.types import OK, OrderProblem
from ragnav_jax.retrieval.evaluate import BatchMeta, RetrievalBatch, best_nodes


@jax.tree_util.register_dataclass
@dataclasses.dataclass(frozen=True)
class PlanEpisodes:
    """Episodes whose every goal has a retrieval slot, padded to G goals (device arrays)."""

    scene: jax.Array  # (E,) int32 scene index b of the batch
    slot: jax.Array  # (E, G) int32 query slot of each goal in its scene, 0 for padding
    goal_mask: jax.Array  # (E, G) bool
    rank: jax.Array  # (E, G) int32: 0..n-1 for strict episodes, all 0 for free ones
    strict: jax.Array  # (E,) bool
    start: jax.Array  # (E,) int32 map node nearest the scene's start pose
    group: jax.Array  # (E, M) bool one-hot modality
    cost: jax.Array  # (B, N, N) float32 shortest-path costs of every scene's map (inf: unreachable)


def plan_episodes(batch: RetrievalBatch, meta: BatchMeta, bank, scenes: Sequence) -> tuple[PlanEpisodes, np.ndarray]:
    """(PlanEpisodes, totals (M,) episodes per modality) from a retrieval batch and its memory bank."""
    by_ep: dict[str, list] = {}
    for it, sl in zip(meta.items, meta.slots):
        by_ep.setdefault(it[0].id, []).append((it, sl))
    mods = meta.modalities
    totals = np.zeros(len(mods), np.int64)
    rows = []
    for goals in by_ep.values():
        ep = goals[0][0][0]
        totals[mods.index(ep.modality)] += 1
        if any(sl is None for _, sl in goals):
            continue  # an instruction that did not yield every subgoal cannot be planned right
        rows.append((ep, [sl for _, sl in goals]))
    G = max([len(s) for _, s in rows], default=1)
    E = max(len(rows), 1)
    scene = np.zeros(E, np.int32)
    slot = np.zeros((E, G), np.int32)
    gmask = np.zeros((E, G), bool)
    rank = np.zeros((E, G), np.int32)
    strict = np.zeros(E, bool)
    start = np.zeros(E, np.int32)
    group = np.zeros((E, len(mods)), bool)
    pos = np.asarray(bank.memory.position)[..., :2]
    nmask = np.asarray(bank.memory.node_mask)
    by_name = {s.name: s for s in scenes}
    for e, (ep, sl) in enumerate(rows):
        b = sl[0][0]
        scene[e] = b
        slot[e, : len(sl)] = [q for _, q in sl]
        gmask[e, : len(sl)] = True
        strict[e] = ep.order == "strict"
        rank[e, : len(sl)] = np.arange(len(sl)) if strict[e] else 0
        d = np.linalg.norm(pos[b] - np.asarray(by_name[ep.scene].start.position[:2])[None], axis=1)
        start[e] = int(np.argmin(np.where(nmask[b], d, np.inf)))
        group[e, mods.index(ep.modality)] = True
    pe = PlanEpisodes(jnp.asarray(scene), jnp.asarray(slot), jnp.asarray(gmask), jnp.asarray(rank),
                      jnp.asarray(strict), jnp.asarray(start), jnp.asarray(group),
                      jnp.asarray(np.asarray(bank.memory.path_cost), jnp.float32))
    return pe, totals


def plan_hits(batch: RetrievalBatch, pe: PlanEpisodes, params, lam: jax.Array) -> jax.Array:
    """Episodes planned right per modality (M,) int32 for one parameter set and planning lambda."""
    best, _ = best_nodes(batch.index, batch.queries, batch.qmask, params)  # (B, Q)
    nodes = best[pe.scene[:, None], pe.slot]  # (E, G)
    truth = batch.truth[pe.scene[:, None], pe.slot, jnp.maximum(nodes, 0)]  # (E, G)
    all_hit = jnp.all(truth | ~pe.goal_mask, axis=1)
    G = pe.slot.shape[1]
    solver = brute_force if G <= MAX_BRUTE_FORCE_GOALS else held_karp if G <= MAX_HELD_KARP_GOALS else local_search

    def one(b, start, ns, gm, rk):
        c = pe.cost[b]
        ok = gm & (ns >= 0)
        safe = jnp.maximum(ns, 0)
        sc = jnp.where(ok, c[start, safe], jnp.inf)[:, None]
        pair = jnp.where(ok[:, None] & ok[None, :], c[safe[:, None], safe[None, :]], jnp.inf)[:, None, :, None]
        prob = OrderProblem(sc, pair, jnp.zeros_like(sc), jnp.where(ok, ns, -1)[:, None], ok[:, None], rk, gm)
        return solver(prob, lam)

    res = jax.vmap(one)(pe.scene, pe.start, nodes, pe.goal_mask, pe.rank)
    ordered = (res.inversions == 0) | ~pe.strict
    right = all_hit & ordered & (res.status == OK)
    return jnp.sum(pe.group & right[:, None], axis=0).astype(jnp.int32)


@functools.cache
def _grid_plan(outer: tuple[str, ...], inner: tuple[str, ...]):
    f = jax.vmap(plan_hits, in_axes=(None, None, _in_axes(inner), 0))  # (C, M): inner fields and lam per point
    if outer:
        f = jax.vmap(f, in_axes=(None, None, _in_axes(outer), None))  # (V, C, M)
    else:
        f = (lambda g: lambda b, e, p, lam: g(b, e, p, lam)[None])(f)
    return jax.jit(f)


def plan_metric(batch: RetrievalBatch, meta: BatchMeta, bank, scenes: Sequence, grid: Grid) -> GridMetric:
    """`plan_success` of every grid point (sigma, eta, ... and lambda) as a GridMetric of run_sweep."""
    pe, totals = plan_episodes(batch, meta, bank, scenes)
    fp = _digest((batch, pe))
    fn = _grid_plan(tuple(grid.outer), tuple(grid.inner))
    return GridMetric("plan_success", lambda params, lam, real: fn(batch, pe, params, lam), totals, meta.modalities, fp,
                      uses_lam=True)
