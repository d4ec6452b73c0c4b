"""Semantic forest T_s: agglomerative clustering over the hybrid similarity, cut into levels.

Paper, "Task-Driven Dual-Basis Memory Construction":
  S_ij = omega * Phi_spatial(i, j) + (1 - omega) * Psi_semantic(i, j)               (hybrid similarity)
  F_i  = alpha * Norm(f_i^spa) + (1 - alpha) * Norm(f_i^sem)                          (fused feature)
with Phi_spatial = exp(-d_ij / spatial_scale) (d_ij Euclidean, or beyond the paper the geodesic distance over
G_t so clusters do not leak through walls) and Psi_semantic the cosine of fingerprint embeddings. The
clustering distance is 1 - S_ij (`metric="hybrid"`) or ||F_i - F_j|| (`metric="fused"`; F_i lives in the
direct sum of the spatial and semantic spaces, i.e. the concatenation of the two weighted blocks).

Everything is written for one scene with padded node count N and a mask; `build_forest_batched` vmaps over
scenes. The merge sequence equals `scipy.cluster.hierarchy.linkage` on tie-free inputs (tests).

Forest layout: L = 1 + len(level_sizes) levels, slot l * N + k holds cluster k of level l (level 0: the
leaves, i.e. the map nodes; the top level's clusters are the forest's roots).
"""

from __future__ import annotations

import functools
from typing import NamedTuple

import jax
import jax.numpy as jnp

LINKAGES = ("single", "complete", "average", "weighted", "ward")


class Dendrogram(NamedTuple):
    merges: jnp.ndarray  # (N-1, 2) int32 scipy-style cluster ids (leaves 0..n-1, step s creates n+s); -1 unused
    heights: jnp.ndarray  # (N-1,) float32 merge distance; inf for unused steps
    sizes: jnp.ndarray  # (N-1,) int32 leaves in the merged cluster; 0 for unused steps
    history: jnp.ndarray  # (N, N) int32: history[s, i] = representative slot of leaf i after s merges


class Forest(NamedTuple):
    parent: jnp.ndarray  # (M,) int32 slot of the parent cluster, -1 for roots and padding
    children: jnp.ndarray  # (M, N) int32 child slots ascending, -1 padded
    level: jnp.ndarray  # (M,) int32
    mask: jnp.ndarray  # (M,) bool
    members: jnp.ndarray  # (M, N) bool leaves under each slot
    size: jnp.ndarray  # (M,) int32 number of leaves
    embedding: jnp.ndarray  # (M, D) float32 unit rows (parents: normalised mean of children)
    position: jnp.ndarray  # (M, 3) float32 centroid of the leaves
    leaf_cluster: jnp.ndarray  # (L, N) int32 cluster (within level) of every leaf, -1 for padding


def _normalise(x: jnp.ndarray) -> jnp.ndarray:
    n = jnp.linalg.norm(x, axis=-1, keepdims=True)
    return x / jnp.maximum(n, 1e-12)


def fused_features(positions, embeddings, mask, alpha) -> jnp.ndarray:
    """F_i (N, 3 + D): [alpha * Norm(f_spa), (1 - alpha) * Norm(f_sem)].

    Norm(f_spa): positions centred on the nodes' mean and divided by their RMS spread (one scalar, so the
    layout is not distorted; unit average norm). Norm(f_sem): L2-normalised embedding.
    """
    m = mask[:, None].astype(jnp.float32)
    n = jnp.maximum(m.sum(), 1.0)
    centre = (positions * m).sum(0, keepdims=True) / n
    c = (positions - centre) * m
    rms = jnp.sqrt(jnp.maximum((c**2).sum() / n, 1e-12))
    spa = c / rms
    sem = _normalise(embeddings) * m
    return jnp.concatenate([alpha * spa, (1.0 - alpha) * sem], axis=-1)


def hybrid_similarity(spatial_distance, embeddings, omega, spatial_scale) -> jnp.ndarray:
    """S (N, N): omega * exp(-d / spatial_scale) + (1 - omega) * cos(e_i, e_j); d may hold inf (Phi = 0)."""
    phi = jnp.exp(-spatial_distance / spatial_scale)
    e = _normalise(embeddings)
    psi = e @ e.T
    return omega * phi + (1.0 - omega) * psi


def clustering_distance(positions, embeddings, mask, geodesic, omega, alpha, spatial_scale, *, metric: str,
                        spatial: str) -> jnp.ndarray:
    """The (N, N) distance the forest clusters on: 1 - S_ij (hybrid) or ||F_i - F_j|| (fused); 0 diagonal."""
    if metric == "fused":
        f = fused_features(positions, embeddings, mask, alpha)
        d = jnp.sqrt(jnp.maximum(((f[:, None, :] - f[None, :, :]) ** 2).sum(-1), 0.0))
    else:
        diff = positions[:, None, :] - positions[None, :, :]
        euclid = jnp.sqrt(jnp.maximum((diff**2).sum(-1), 0.0))
        d_spa = geodesic if spatial == "geodesic" else euclid
        d = jnp.maximum(1.0 - hybrid_similarity(d_spa, embeddings, omega, spatial_scale), 0.0)
    return jnp.where(jnp.eye(d.shape[0], dtype=bool), 0.0, d)


def agglomerate(dist: jnp.ndarray, mask: jnp.ndarray, method: str = "average") -> Dendrogram:
    """Greedy agglomerative clustering with Lance-Williams updates on an (N, N) distance matrix.

    Args:
      dist: (N, N) float32 symmetric distances (entries of padded nodes are ignored).
      mask: (N,) bool real nodes; n = mask.sum() of them give n - 1 merges.
      method: single | complete | average | weighted | ward (static).
    """
    if method not in LINKAGES:
        raise ValueError(f"unknown linkage {method!r}")
    N = dist.shape[0]
    n = mask.sum().astype(jnp.int32)
    idx = jnp.arange(N, dtype=jnp.int32)
    off = ~jnp.eye(N, dtype=bool)
    D = jnp.where(mask[:, None] & mask[None, :] & off, dist.astype(jnp.float32), jnp.inf)
    steps = max(N - 1, 0)
    init = dict(
        D=D, active=mask, size=mask.astype(jnp.float32), cid=idx, assign=idx,
        history=jnp.broadcast_to(idx, (N, N)),
        merges=jnp.full((steps, 2), -1, jnp.int32), heights=jnp.full((steps,), jnp.inf, jnp.float32),
        sizes=jnp.zeros((steps,), jnp.int32),
    )

    def step(s, st):
        D = st["D"]
        flat = jnp.argmin(D.reshape(-1))
        i, j = flat // N, flat % N
        a, b = jnp.minimum(i, j), jnp.maximum(i, j)
        h = D[a, b]
        na, nb, nk = st["size"][a], st["size"][b], st["size"]
        da, db = D[a], D[b]
        if method == "single":
            new = jnp.minimum(da, db)
        elif method == "complete":
            new = jnp.maximum(da, db)
        elif method == "average":
            new = (na * da + nb * db) / (na + nb)
        elif method == "weighted":
            new = 0.5 * (da + db)
        else:  # ward
            t = nk + na + nb
            new = jnp.sqrt(jnp.maximum(((nk + na) * da**2 + (nk + nb) * db**2 - nk * h**2) / t, 0.0))
        live = st["active"] & (idx != a) & (idx != b)
        new = jnp.where(live, new, jnp.inf)
        D2 = D.at[a, :].set(new).at[:, a].set(new)
        D2 = D2.at[b, :].set(jnp.inf).at[:, b].set(jnp.inf)
        ca, cb = st["cid"][a], st["cid"][b]
        assign2 = jnp.where(st["assign"] == b, a, st["assign"])
        ok = s < n - 1
        pick = lambda x, y: jax.tree.map(lambda u, v: jnp.where(ok, u, v), x, y)  # noqa: E731
        upd = dict(
            D=D2, active=st["active"].at[b].set(False), size=st["size"].at[a].add(nb).at[b].set(0.0),
            cid=st["cid"].at[a].set(n + s), assign=assign2,
        )
        out = pick(upd, {k: st[k] for k in upd})
        out["history"] = st["history"].at[s + 1].set(out["assign"])
        out["merges"] = st["merges"].at[s].set(jnp.where(ok, jnp.stack([jnp.minimum(ca, cb), jnp.maximum(ca, cb)]), -1))
        out["heights"] = st["heights"].at[s].set(jnp.where(ok, h, jnp.inf))
        out["sizes"] = st["sizes"].at[s].set(jnp.where(ok, (na + nb).astype(jnp.int32), 0))
        return out

    st = jax.lax.fori_loop(0, steps, step, init) if steps else init
    return Dendrogram(st["merges"], st["heights"], st["sizes"], st["history"])


def level_counts(n, level_sizes) -> jnp.ndarray:
    """Clusters per level above the leaves: ceil(n / size), at least 1, never more than the level below."""
    sizes = jnp.asarray(level_sizes, jnp.float32)
    c = jnp.clip(jnp.ceil(n.astype(jnp.float32) / sizes).astype(jnp.int32), jnp.minimum(n, 1), n)
    return jax.lax.cummin(c)


def cut_levels(dendro: Dendrogram, mask, embeddings, positions, level_sizes) -> Forest:
    """Cuts the dendrogram into levels and builds the forest arrays (see `Forest`)."""
    N = mask.shape[0]
    L = 1 + len(level_sizes)
    n = mask.sum().astype(jnp.int32)
    idx = jnp.arange(N, dtype=jnp.int32)
    counts = jnp.concatenate([n[None], level_counts(n, level_sizes)])  # (L,)
    leaf_cluster = [jnp.where(mask, idx, -1)]
    for lvl in range(1, L):
        assign = dendro.history[jnp.clip(n - counts[lvl], 0, max(N - 1, 0))] if N else idx
        is_rep = jnp.zeros((N,), bool).at[jnp.where(mask, assign, N)].set(True, mode="drop")
        rank = jnp.cumsum(is_rep) - 1
        leaf_cluster.append(jnp.where(mask, rank[assign], -1).astype(jnp.int32))
    leaf_cluster = jnp.stack(leaf_cluster)  # (L, N)
    lvl_mask = idx[None, :] < counts[:, None]  # (L, N)

    parent_local = []
    for lvl in range(L - 1):
        below, above = leaf_cluster[lvl], leaf_cluster[lvl + 1]
        p = jnp.full((N,), -1, jnp.int32).at[jnp.where(mask, below, N)].max(above, mode="drop")
        parent_local.append(jnp.where(lvl_mask[lvl], p + (lvl + 1) * N, -1))
    parent_local.append(jnp.full((N,), -1, jnp.int32))
    parent = jnp.concatenate(parent_local)  # (M,)

    members = (leaf_cluster[:, None, :] == idx[None, :, None]) & mask[None, None, :] & lvl_mask[:, :, None]
    members = members.reshape(L * N, N)
    size = members.sum(-1).astype(jnp.int32)

    children = [jnp.full((N, N), -1, jnp.int32)]
    emb = [_normalise(embeddings) * mask[:, None]]
    for lvl in range(1, L):
        p_below = parent_local[lvl - 1] - lvl * N  # (N,) local parent of each level-(lvl-1) slot, <0 if none
        is_child = (p_below[None, :] == idx[:, None]) & lvl_mask[lvl - 1][None, :]  # (N parents, N below)
        order = jnp.sort(jnp.where(is_child, idx[None, :], N), axis=-1)
        children.append(jnp.where(order < N, order + (lvl - 1) * N, -1).astype(jnp.int32))
        e = is_child.astype(jnp.float32) @ emb[-1]
        emb.append(_normalise(e) * lvl_mask[lvl][:, None])
    children = jnp.concatenate(children)
    embedding = jnp.concatenate(emb)
    mf = members.astype(jnp.float32)
    position = (mf @ positions) / jnp.maximum(mf.sum(-1, keepdims=True), 1.0)
    level = jnp.repeat(jnp.arange(L, dtype=jnp.int32), N)
    return Forest(parent, children, level, lvl_mask.reshape(-1), members, size, embedding, position, leaf_cluster)


def build_forest(positions, embeddings, mask, geodesic, omega, alpha, spatial_scale, *, metric: str = "hybrid",
                 spatial: str = "geodesic", linkage: str = "average", level_sizes=(5.0, 16.0)):
    """The whole forest of one scene: distance, dendrogram, levels. omega/alpha/spatial_scale are arrays
    (sweepable); metric/spatial/linkage/level_sizes are static."""
    dist = clustering_distance(positions, embeddings, mask, geodesic, omega, alpha, spatial_scale,
                               metric=metric, spatial=spatial)
    dendro = agglomerate(dist, mask, linkage)
    return dendro, cut_levels(dendro, mask, embeddings, positions, tuple(level_sizes))


@functools.partial(jax.jit, static_argnames=("metric", "spatial", "linkage", "level_sizes"))
def build_forest_batched(positions, embeddings, mask, geodesic, omega, alpha, spatial_scale, *, metric="hybrid",
                         spatial="geodesic", linkage="average", level_sizes=(5.0, 16.0)):
    """`build_forest` vmapped over scenes (leading axis B on the arrays; omega/alpha/scale shared)."""
    fn = functools.partial(build_forest, metric=metric, spatial=spatial, linkage=linkage, level_sizes=level_sizes)
    return jax.vmap(fn, in_axes=(0, 0, 0, 0, None, None, None))(positions, embeddings, mask, geodesic, omega, alpha,
                                                                  spatial_scale)


agglomerate_jit = jax.jit(agglomerate, static_argnames=("method",))
agglomerate_batched = jax.jit(jax.vmap(agglomerate, in_axes=(0, 0, None)), static_argnames=("method",))


def to_scipy_linkage(dendro: Dendrogram, n: int):
    """The first n - 1 merges as a scipy linkage matrix Z (n-1, 4) float64 (host)."""
    import numpy as np

    m = np.asarray(dendro.merges)[: max(n - 1, 0)]
    return np.column_stack([m.astype(np.float64), np.asarray(dendro.heights)[: len(m)], np.asarray(dendro.sizes)[: len(m)]])
