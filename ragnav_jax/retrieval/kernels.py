"""Retrieval kernels: pure JAX functions for one query over one scene's memory; callers vmap.

Equation references are to the RAGNav paper (ragnav_paper.tex):
- S_spatial(v_i | v_B) = sim(phi(Q_A), psi(v_i)) * exp(-||p_i - p_B||^2 / (2 sigma^2))   (task decomposition)
- S_combo(v_A, v_B) = 1 / (1 + d(v_A, v_B))                                              (anchor-guided retrieval)
- S_boost = S_sem * (1 + eta * mean relevant-neighbour score)                              (neighbour boosting)

Graphs are padded neighbour lists (N, Dmax) int32 with -1 padding, so the same kernels serve an
80-node house and a 100k-node benchmark. Masked-out nodes score NEG. Every hyperparameter that a sweep
varies is an array argument; only array *sizes* (max K, max hops, forest levels) are static.
"""

from __future__ import annotations

import jax
import jax.numpy as jnp

NEG = -1e9  # score of masked / pruned nodes: finite, so sums and softmaxes stay NaN-free

# Sensor comparators (TaskChain sensor constraints, encoded as integers for arrays).
OP_NONE, OP_GT, OP_LT, OP_APPROX, OP_MAX, OP_MIN = range(6)


def cosine_scores(q: jax.Array, emb: jax.Array, mask: jax.Array) -> jax.Array:
    """Cosine similarity of one query with N rows.

    q: (D,); emb: (N, D); mask: (N,) bool. Returns (N,), NEG where masked.
    """
    qn = q / jnp.maximum(jnp.linalg.norm(q), 1e-12)
    en = emb / jnp.maximum(jnp.linalg.norm(emb, axis=-1, keepdims=True), 1e-12)
    return jnp.where(mask, en @ qn, NEG)


def gate(x: jax.Array, threshold: jax.Array, tau: jax.Array | None = None) -> jax.Array:
    """1.0 where x >= threshold, else 0.0 (float, x's shape).

    With tau (an array, the tuning surrogate's gate softness) the forward value is unchanged but the
    gradient is that of sigmoid((x - threshold) / tau) (straight-through), so a threshold gets a
    gradient while the scores stay exactly those of the hard kernel.
    """
    hard = (x >= threshold).astype(jnp.float32)
    if tau is None:
        return hard
    soft = jax.nn.sigmoid((x - threshold) / tau)
    return hard + (soft - jax.lax.stop_gradient(soft))


def gaussian(dist2: jax.Array, sigma: jax.Array) -> jax.Array:
    """exp(-d^2 / (2 sigma^2)) for squared distances (any shape) and a scalar width."""
    return jnp.exp(-dist2 / (2.0 * sigma * sigma))


def spatial_score(sem: jax.Array, pos: jax.Array, anchor_pos: jax.Array, sigma: jax.Array) -> jax.Array:
    """Paper's S_spatial: semantic score times a Gaussian of the distance to the anchor.

    sem: (N,); pos: (N, 3); anchor_pos: (3,) or (N, 3) (a per-node anchor). Returns (N,).
    """
    d2 = jnp.sum((pos - jnp.broadcast_to(anchor_pos, pos.shape)) ** 2, axis=-1)
    return sem * gaussian(d2, sigma)


def combo_score(pos_a: jax.Array, pos_b: jax.Array) -> jax.Array:
    """Paper's S_combo = 1 / (1 + ||p_a - p_b||); broadcasts over leading axes of (..., 3) inputs."""
    pos_a, pos_b = jnp.broadcast_arrays(pos_a, pos_b)
    return 1.0 / (1.0 + jnp.linalg.norm(pos_a - pos_b, axis=-1))


def expand(reach: jax.Array, nbr: jax.Array, nbr_mask: jax.Array) -> jax.Array:
    """One hop of breadth-first expansion of node sets.

    reach: (M, N) bool sets; nbr: (N, Dmax) int32; nbr_mask: (N, Dmax) bool. Returns (M, N) bool.
    """
    gathered = jnp.take(reach, jnp.maximum(nbr, 0), axis=1)  # (M, N, Dmax): is neighbour d of node j in the set
    return reach | jnp.any(gathered & nbr_mask[None], axis=-1)


def neighbourhood(seeds: jax.Array, n: int, nbr, nbr_mask, hops: jax.Array, max_hops: int) -> jax.Array:
    """Nodes within `hops` (<= max_hops, static) hops of each seed, the seed included.

    seeds: (M,) int32 node indices; returns (M, n) bool.
    """
    reach = jax.nn.one_hot(seeds, n, dtype=jnp.bool_)

    def body(h, r):
        return jnp.where(h < hops, expand(r, nbr, nbr_mask), r)

    return jax.lax.fori_loop(0, max_hops, body, reach)


def topk_mask(scores: jax.Array, k: jax.Array, max_k: int) -> tuple[jax.Array, jax.Array]:
    """Indices of the max_k best scores and a mask keeping the first k of them (k an array <= max_k).

    Returns idx: (max_k,) int32, keep: (max_k,) bool.
    """
    _, idx = jax.lax.top_k(scores, max_k)
    keep = (jnp.arange(max_k) < k) & (scores[idx] > NEG / 2)
    return idx.astype(jnp.int32), keep


def anchor_guided(
    sem_a: jax.Array,
    sem_b: jax.Array,
    pos: jax.Array,
    nbr: jax.Array,
    nbr_mask: jax.Array,
    top_k: jax.Array,
    hops: jax.Array,
    anchor_threshold: jax.Array,
    sigma: jax.Array,
    max_k: int = 16,
    max_hops: int = 3,
    gate_tau: jax.Array | None = None,
    pos_b: jax.Array | None = None,
) -> tuple[jax.Array, jax.Array, jax.Array]:
    """Two-stage anchor-guided retrieval for "A near B".

    Stage 1 recalls the top-K nodes for A. Stage 2 keeps a candidate only if its h-hop neighbourhood
    (itself included: one key pose often sees both objects) holds a node matching B
    (sem_b >= anchor_threshold); the anchor is the match maximising sem_b * S_combo, and the
    candidate's score is S_spatial(v_i | v_B) with that anchor. Pruned and non-candidate nodes get NEG.
    gate_tau: see `gate` (the validated score is multiplied by the anchor's gate, 1.0 in the forward pass).

    Distances are between `pos` (where node i's A lies) and `pos_b` (where node j's B lies; default
    `pos`): the key poses themselves in the paper, the matched object instances in our index.
    sem_a, sem_b: (N,); pos, pos_b: (N, 3); nbr, nbr_mask: (N, Dmax). Returns (scores (N,), anchor (N,) int32
    with -1 where none, has_anchor (N,) bool).
    """
    sem_a, sem_b, pos, nbr, nbr_mask = map(jnp.asarray, (sem_a, sem_b, pos, nbr, nbr_mask))
    pos_b = pos if pos_b is None else jnp.asarray(pos_b)
    n = sem_a.shape[0]
    cand, keep = topk_mask(sem_a, top_k, max_k)
    reach = neighbourhood(cand, n, nbr, nbr_mask, hops, max_hops)  # (K, N)
    ok = reach & (sem_b >= anchor_threshold)[None]
    pair = jnp.where(ok, sem_b[None] * combo_score(pos[cand][:, None], pos_b[None]), NEG)
    best = jnp.argmax(pair, axis=1)
    has = jnp.any(ok, axis=1) & keep
    s = spatial_score(sem_a[cand], pos[cand], pos_b[best], sigma) * gate(sem_b[best], anchor_threshold, gate_tau)
    scores = jnp.full((n,), NEG).at[cand].set(jnp.where(has, s, NEG))
    anchor = jnp.full((n,), -1, jnp.int32).at[cand].set(jnp.where(has, best, -1).astype(jnp.int32))
    has_anchor = jnp.zeros((n,), bool).at[cand].set(has)
    return scores, anchor, has_anchor


def neighbour_mean(ctx: jax.Array, relevant: jax.Array, reach: jax.Array) -> jax.Array:
    """Mean of ctx over relevant nodes in each node's neighbourhood (0 where none).

    ctx, relevant: (N,) (relevant bool, or float 0/1 gates); reach: (N, N) bool with reach[i, j] = j is a
    neighbour of i (i itself excluded).
    """
    w = reach * jnp.asarray(relevant, jnp.float32)[None]
    cnt = jnp.sum(w, axis=1)
    vals = w * jnp.where(ctx > NEG / 2, ctx, 0.0)[None]
    return jnp.where(cnt > 0, jnp.sum(vals, axis=1) / jnp.maximum(cnt, 1), 0.0)


def neighbour_boost(
    sem: jax.Array,
    ctx: jax.Array,
    nbr: jax.Array,
    nbr_mask: jax.Array,
    node_mask: jax.Array,
    eta: jax.Array,
    threshold: jax.Array,
    hops: jax.Array,
    max_hops: int = 1,
    gate_tau: jax.Array | None = None,
) -> tuple[jax.Array, jax.Array]:
    """Paper's S_boost = S_sem * (1 + eta * mean score of relevant neighbours).

    ctx (N,) is the relevance score of each node (the anchor phrase's score for "A near B", else the
    target's own score: true detections have supporting neighbours, isolated noise does not); a
    neighbour is relevant when ctx >= threshold. With max_hops == 1 (static) this gathers over the
    neighbour lists (memory O(N Dmax)); otherwise it builds (N, N) neighbourhoods within `hops`.
    gate_tau: see `gate` (relevance as straight-through gates, so the threshold gets a gradient).
    Returns (boosted (N,), neighbour mean (N,)).
    """
    sem, ctx, nbr, nbr_mask, node_mask = map(jnp.asarray, (sem, ctx, nbr, nbr_mask, node_mask))
    n = sem.shape[0]
    relevant = gate(ctx, threshold, gate_tau) * node_mask  # (N,) 0/1 in the forward pass
    if max_hops == 1:
        valid = nbr_mask & (nbr >= 0)
        w = valid * relevant[jnp.maximum(nbr, 0)]
        vals = w * jnp.where(ctx > NEG / 2, ctx, 0.0)[jnp.maximum(nbr, 0)]
        cnt = jnp.sum(w, axis=1)
        mean = jnp.where(cnt > 0, jnp.sum(vals, axis=1) / jnp.maximum(cnt, 1), 0.0)
        mean = jnp.where(hops >= 1, mean, 0.0)
    else:
        reach = neighbourhood(jnp.arange(n), n, nbr, nbr_mask, hops, max_hops) & ~jnp.eye(n, dtype=bool)
        mean = neighbour_mean(ctx, relevant, reach)
    mean = jnp.where(node_mask, mean, 0.0)
    boosted = jnp.where(node_mask, sem * (1.0 + eta * mean), NEG)
    return boosted, mean


def location_term(obj_pos: jax.Array, hint: jax.Array, sigma_loc: jax.Array) -> jax.Array:
    """Gaussian of the planar distance from (estimated) object positions to a hinted point.

    obj_pos: (..., 3); hint: (2,). Returns (...,) in (0, 1].
    """
    xy = obj_pos[..., :2]
    d2 = jnp.sum((xy - jnp.broadcast_to(hint, xy.shape)) ** 2, axis=-1)
    return gaussian(d2, sigma_loc)


def sensor_term(
    readings: jax.Array,
    present: jax.Array,
    match: jax.Array,
    channel: jax.Array,
    op: jax.Array,
    value: jax.Array,
    scale: jax.Array,
    missing: float = 0.1,
) -> jax.Array:
    """Soft match of readings to a sensor constraint, for M observed object instances.

    readings: (M, S); present: (M, S) bool; match: (M,) bool instances that match the target phrase
    (superlatives rank among these); channel, op: () int32 (OP_*); value: () float; scale: () float,
    the channel's natural unit of softness (e.g. 3 degrees, 0.05 NDVI). Returns (M,) in (0, 1]:
    gt/lt a sigmoid, approx a Gaussian, max/min exp(-gap/scale) from the best matching instance;
    a missing reading scores `missing`; OP_NONE scores 1.
    """
    x = readings[:, channel]
    has = present[:, channel]
    big = 1e9
    top = jnp.max(jnp.where(match & has, x, -big))
    bottom = jnp.min(jnp.where(match & has, x, big))
    s = scale
    terms = jnp.stack(
        [
            jnp.ones_like(x),
            jax.nn.sigmoid((x - value) / s),
            jax.nn.sigmoid((value - x) / s),
            jnp.exp(-((x - value) ** 2) / (2 * s * s)),
            jnp.exp(-jnp.clip(top - x, 0.0, big) / s),
            jnp.exp(-jnp.clip(x - bottom, 0.0, big) / s),
        ]
    )
    t = terms[op]
    return jnp.where(op == OP_NONE, 1.0, jnp.where(has, t, missing))


TIME_NONE, TIME_FIRST, TIME_LAST = 0, 1, 2


def time_term(first: jax.Array, last: jax.Array, pool: jax.Array, order: jax.Array, rank: jax.Array) -> jax.Array:
    """Soft match of when each of M instances was seen to a time-indexed query ("the second mug you saw").

    first, last: (M,) timestamps (exploration record) of the first and the latest view of each instance;
    pool: (M,) bool the instances the ranking is among (the target's kind, in its room); order: () int32
    TIME_*; rank: () int32, 1-based. An instance's rank is the number of pool instances seen strictly earlier
    (TIME_FIRST, by first view) or strictly later (TIME_LAST, by latest view), so ties share a rank.
    Returns (M,) exp(-|rank - (rank_wanted - 1)|): 1 at the asked rank, e^-1 one place off; 1 for TIME_NONE.
    """
    key = jnp.where(order == TIME_LAST, -last, first)  # smaller is "earlier in the asked direction"
    before = jnp.sum(pool[None, :] & (key[None, :] < key[:, None]), axis=1)  # (M,)
    term = jnp.exp(-jnp.abs(before - (rank - 1)).astype(jnp.float32))
    return jnp.where(order == TIME_NONE, 1.0, term)


def recency_term(last: jax.Array, mask: jax.Array, weight: jax.Array) -> jax.Array:
    """exp(-weight * age) for M instances: age = (t_latest - last) / (t_latest - t_earliest) in [0, 1] over the
    masked instances' latest views, so the memory's newest entries keep full score. (M,); 1 at weight 0."""
    hi = jnp.max(jnp.where(mask, last, -jnp.inf))
    lo = jnp.min(jnp.where(mask, last, jnp.inf))
    age = jnp.where(mask, (hi - last) / jnp.maximum(hi - lo, 1.0), 0.0)
    return jnp.exp(-weight * age)


def beam_prune(
    q: jax.Array,
    cluster_emb: jax.Array,
    cluster_mask: jax.Array,
    cluster_parent: jax.Array,
    leaf_cluster: jax.Array,
    beam: jax.Array,
    max_beam: int = 8,
) -> tuple[jax.Array, jax.Array]:
    """Coarse-to-fine beam search down the semantic forest.

    The forest is cut into L levels (0 = finest clusters above the leaves, L-1 = coarsest).
    cluster_emb: (L, C, D); cluster_mask: (L, C) bool; cluster_parent: (L, C) int32 index of the parent
    at level l+1 (-1 at the top level); leaf_cluster: (N, L) int32 cluster of each leaf at each level.
    At the top level all clusters compete; at each lower level only children of kept clusters do; the
    best `beam` (array, <= max_beam) are kept. Returns (allowed leaves (N,) bool, kept (L, C) bool).
    """
    L, C, _ = cluster_emb.shape
    kept = []
    parent_kept = jnp.ones((C,), bool)
    for level in range(L - 1, -1, -1):
        cand = cluster_mask[level]
        if level < L - 1:
            par = cluster_parent[level]
            cand = cand & (par >= 0) & parent_kept[jnp.maximum(par, 0)]
        s = cosine_scores(q, cluster_emb[level], cand)
        idx, keep = topk_mask(s, beam, min(max_beam, C))
        k = jnp.zeros((C,), bool).at[idx].set(keep)
        kept.append(k)
        parent_kept = k
    kept = jnp.stack(kept[::-1])  # (L, C), level 0 first
    allowed = kept[0][jnp.maximum(leaf_cluster[:, 0], 0)] & (leaf_cluster[:, 0] >= 0)
    return allowed, kept
