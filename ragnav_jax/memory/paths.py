"""All-pairs shortest paths over the topological map G_t (Floyd-Warshall), jitted and batched over scenes.

Conventions (shared with the planning stage):
- `cost[i, j]`: length of the shortest path from node i to node j; `inf` where j is unreachable from i or
  either node is padding; `cost[i, i] = 0` for real nodes.
- `pred[i, j]`: the node just before j on a shortest path from i to j (int32); -1 where unreachable, on
  the diagonal and for padding. The path i -> j is j, pred[i, j], pred[i, pred[i, j]], ... until i.
- `reachable = isfinite(cost)`.
"""

from __future__ import annotations

import functools

import jax
import jax.numpy as jnp
import numpy as np


def edge_weights(adjacency: jnp.ndarray, distance: jnp.ndarray) -> jnp.ndarray:
    """(N, N) float32 edge weights: D_ij where an edge exists, inf elsewhere."""
    return jnp.where(adjacency, distance, jnp.inf).astype(jnp.float32)


def all_pairs_shortest_paths(weights: jnp.ndarray, mask: jnp.ndarray) -> tuple[jnp.ndarray, jnp.ndarray]:
    """Floyd-Warshall with predecessors for one scene.

    Args:
      weights: (N, N) float32 non-negative edge weights, inf where there is no edge.
      mask: (N,) bool, real (not padding) nodes.
    Returns:
      cost (N, N) float32 and pred (N, N) int32 (conventions in the module docstring).
    """
    n = weights.shape[0]
    idx = jnp.arange(n, dtype=jnp.int32)
    valid = mask[:, None] & mask[None, :]
    eye = jnp.eye(n, dtype=bool)
    w = jnp.where(valid & ~eye, weights.astype(jnp.float32), jnp.inf)
    cost = jnp.where(eye & mask[:, None], 0.0, w)
    pred = jnp.where(jnp.isfinite(w), idx[:, None], -1).astype(jnp.int32)

    def relax(k, carry):
        cost, pred = carry
        via = cost[:, k, None] + cost[None, k, :]
        better = via < cost
        return jnp.where(better, via, cost), jnp.where(better, pred[k][None, :], pred)

    if n == 0:
        return cost, pred
    return jax.lax.fori_loop(0, n, relax, (cost, pred))


# Scenes with the same padded node count in one call: (B, N, N), (B, N) -> (B, N, N) x2.
batched_shortest_paths = jax.jit(jax.vmap(all_pairs_shortest_paths))
shortest_paths = jax.jit(all_pairs_shortest_paths)


@functools.partial(jax.jit, static_argnames="chunk")
def chunked_shortest_paths(weights: jnp.ndarray, mask: jnp.ndarray, chunk: int) -> tuple[jnp.ndarray, jnp.ndarray]:
    """`batched_shortest_paths` with at most `chunk` graphs in flight: one compiled call that maps over
    blocks of `chunk` vmapped graphs (lax.map), so the relaxation temporaries of B graphs never have to
    fit in device memory at once (16384 graphs of 500 nodes on one GPU). Same results, same shapes.
    """
    return jax.lax.map(lambda wm: all_pairs_shortest_paths(*wm), (weights, mask), batch_size=chunk)


def reconstruct_path(pred: np.ndarray, i: int, j: int) -> list[int]:
    """Host-side node list i ... j from a predecessor matrix; [] when j is unreachable from i."""
    pred = np.asarray(pred)
    if i == j:
        return [i]
    if pred[i, j] < 0:
        return []
    path = [j]
    while path[-1] != i:
        path.append(int(pred[i, path[-1]]))
        if len(path) > pred.shape[0]:  # a malformed matrix must not loop forever
            raise ValueError("predecessor matrix has a cycle")
    return path[::-1]


def connected_components(adjacency: np.ndarray, mask: np.ndarray) -> np.ndarray:
    """(N,) int32 component label per real node (0, 1, ... by first node), -1 for padding."""
    from scipy.sparse import csr_matrix
    from scipy.sparse.csgraph import connected_components as cc

    mask = np.asarray(mask, bool)
    n = int(mask.sum())
    labels = np.full(mask.shape[0], -1, np.int32)
    if n == 0:
        return labels
    idx = np.flatnonzero(mask)
    sub = np.asarray(adjacency, bool)[np.ix_(idx, idx)]
    _, lab = cc(csr_matrix(sub), directed=False)
    # Relabel by first appearance so labels are stable.
    order = {}
    labels[idx] = [order.setdefault(int(x), len(order)) for x in lab]
    return labels
