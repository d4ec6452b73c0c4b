"""RAGNav's candidate list of one subgoal slot from the retrieval kernel's terms, on the device.

The jittable form of `ranking._kernel_ranked`'s per-slot body (`candidate_order`, `distinct_instances`, the
pre-check, `view_nodes`), node for node: every Python loop there is a sort with explicit tie keys here.

    r = jax.jit(rank_all, static_argnames=("k", "depth", "widen", "closest_view"))(
        score, relaxed, category, slot_best, node_live, slot_inst, inst_pos, node_pos, ruled, b, q,
        k=4, depth=8, widen=True, closest_view=True)
"""

from __future__ import annotations

import functools

import jax
import jax.numpy as jnp
from flax import struct
from jax import lax

from ragnav_jax.retrieval import kernels as K


@struct.dataclass
class Ranked:
    """One slot's candidates, best first (rank_all adds a leading slot axis M)."""

    nodes: jax.Array  # (k,) int32 node each candidate's leg ends at, -1 padded
    est: jax.Array  # (k, 2) float32 the matched instance's estimated position (0 where has_est is False)
    has_est: jax.Array  # (k,) bool the candidate matched an instance (inst >= 0)
    inst: jax.Array  # (k,) int32 matched instance; -1: none, or padding
    n: jax.Array  # () int32 candidates (<= k)
    top: jax.Array  # () int32 the ranking's first node, before the pre-check; -1 if none


def _earlier_same(x: jax.Array) -> jax.Array:
    """(L,) -> (L,) bool: an earlier entry holds the same value."""
    i = jnp.arange(x.shape[0])
    return ((x[:, None] == x[None, :]) & (i[None, :] < i[:, None])).any(1)


def _order(score, relaxed, category, live, widen: bool):
    """`candidate_order` as a permutation of all N nodes, its first `m` entries the ranking: ((N,) int32, () int32)."""
    iota = jnp.arange(score.shape[0], dtype=jnp.int32)
    kept = live & (score > K.NEG / 2)
    # Kept nodes by descending score; the index as the last key is argsort's stable tie rule.
    _, _, by_score = lax.sort((jnp.where(kept, 0, 1), -jnp.where(kept, score, 0.0), iota), num_keys=3)
    m = kept.sum(dtype=jnp.int32)
    if not widen:
        return by_score, m
    first = by_score[0]
    rest = (kept | (live & (relaxed > K.NEG / 2))) & (iota != first)
    group = jnp.where(m > 0, jnp.where(iota == first, 0, jnp.where(rest, 1, 2)), 2)  # top-1, the tiers, excluded
    tier = jnp.where(category, 0, 2) + jnp.where(kept, 0, 1)
    key = jnp.where(group == 1, -jnp.where(kept, score, relaxed), 0.0)
    *_, order = lax.sort((group, tier, key, iota), num_keys=4)  # lexsort((-key, tier)) after the top-1
    return order, jnp.where(m > 0, 1 + rest.sum(dtype=jnp.int32), 0)


def rank_candidates(score: jax.Array, relaxed: jax.Array, category: jax.Array, slot_best: jax.Array,
                    node_live: jax.Array, slot_inst: jax.Array, inst_pos: jax.Array, node_pos: jax.Array,
                    ruled: jax.Array, k: int, depth: int, widen: bool, closest_view: bool) -> Ranked:
    """One subgoal slot's candidates, as `ranking._kernel_ranked` lists them.

    score, relaxed: (N,) float32 final and relaxed retrieval scores (K.NEG: dropped); category: (N,) bool;
    slot_best: (N,) int32 each node's best-matching observation slot; node_live: (N,) bool;
    slot_inst: (N, S) int32 instance of each slot (-1: none); inst_pos: (I, 2); node_pos: (N, 2);
    ruled: (I,) bool the pre-check rules the instance out (all False: no pre-check).
    Static: k candidates, `depth` ranked nodes per candidate searched for distinct instances (CANDIDATE_DEPTH),
    widen (candidate_order's tiers), closest_view (an instance's first candidate ends at its closest view).
    """
    N, R = score.shape[0], min(score.shape[0], k * depth)
    if N == 0:  # no nodes: no candidates
        none = jnp.full((k,), -1, jnp.int32)
        return Ranked(nodes=none, est=jnp.zeros((k, 2), jnp.float32), has_est=none >= 0, inst=none, n=jnp.int32(0),
                      top=jnp.int32(-1))
    if inst_pos.shape[0] == 0:  # no instances (slot_inst all -1): one never-read row keeps the gathers valid
        inst_pos, ruled = jnp.zeros((1, 2), jnp.float32), jnp.zeros((1,), bool)
    order, m = _order(score, relaxed, category, node_live, widen)
    ranked = order[:R]  # (R,)
    valid = jnp.arange(R) < jnp.minimum(m, k * depth)
    inst = jnp.where(valid, slot_inst[ranked, slot_best[ranked]], -1)
    first = (inst < 0) | ~_earlier_same(inst)  # distinct_instances: first of each instance, then the others
    ok = (inst < 0) | ~ruled[jnp.maximum(inst, 0)]
    chosen = valid & (ok | ~(valid & ok).any())  # everything ruled out: keep all
    *_, pick = lax.sort((jnp.where(chosen, jnp.where(first, 0, 1), 2), jnp.arange(R, dtype=jnp.int32)), num_keys=2)
    pick = jnp.pad(pick[:k], (0, max(k - R, 0)))  # (k,)
    n = jnp.minimum(chosen.sum(dtype=jnp.int32), k)
    live = jnp.arange(k) < n
    c_inst = jnp.where(live, inst[pick], -1)
    c_node = jnp.where(live, ranked[pick], -1)
    has = c_inst >= 0
    est = jnp.where(has[:, None], inst_pos[jnp.maximum(c_inst, 0)], 0.0).astype(jnp.float32)
    if closest_view:
        def view(i, e):  # closest_view: the live node that recorded instance i nearest its estimate, if any
            saw = (slot_inst == i).any(-1) & node_live
            diff = node_pos - e[None]
            d = jnp.sqrt(jnp.sum(diff * diff, -1))  # as np.linalg.norm, so ties break alike
            return saw.any(), jnp.argmin(jnp.where(saw, d, jnp.inf)).astype(jnp.int32)

        seen, best = jax.vmap(view)(c_inst, est)
        c_node = jnp.where(has & ~_earlier_same(c_inst) & seen, best, c_node)
    return Ranked(nodes=c_node.astype(jnp.int32), est=est, has_est=has, inst=c_inst.astype(jnp.int32), n=n,
                  top=jnp.where(m > 0, order[0], -1).astype(jnp.int32))


def rank_all(score: jax.Array, relaxed: jax.Array, category: jax.Array, slot_best: jax.Array, node_live: jax.Array,
             slot_inst: jax.Array, inst_pos: jax.Array, node_pos: jax.Array, ruled: jax.Array, b: jax.Array,
             q: jax.Array, k: int, depth: int, widen: bool, closest_view: bool) -> Ranked:
    """rank_candidates for M slots at once, each reading its scene's arrays.

    score, relaxed, category, slot_best: (B, Q, N) as `_ranked_terms` gives them; node_live: (B, N);
    slot_inst: (B, N, S); inst_pos: (B, I, 2); node_pos: (B, N, 2); ruled: (M, I) per slot;
    b, q: (M,) int32 each slot's scene and subgoal slot. Returns Ranked with a leading axis M.
    """
    one = functools.partial(rank_candidates, k=k, depth=depth, widen=widen, closest_view=closest_view)
    score, relaxed, category, slot_best, node_live, slot_inst, inst_pos, node_pos = map(
        jnp.asarray, (score, relaxed, category, slot_best, node_live, slot_inst, inst_pos, node_pos))  # host arrays

    def slot(b_, q_, r):
        return one(score[b_, q_], relaxed[b_, q_], category[b_, q_], slot_best[b_, q_], node_live[b_],
                   slot_inst[b_], inst_pos[b_], node_pos[b_], r)

    return jax.vmap(slot)(b, q, ruled)
