"""Node paths from the memory's predecessor matrix, and travel distance by the paper's Rules 1 and 2.

Predecessor convention (scipy's `shortest_path(return_predecessors=True)`, with -1 for none):
`pred[s, v]` is the node before v on a shortest path from s to v; -1 where v == s or unreachable.
"""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.planning.types import Array, Path


def path_nodes(pred: Array, src: Array, dst: Array, max_len: int) -> Path:
    """Shortest path src -> dst as a fixed-length node array (jittable; vmap over pairs).

    Args:
      pred: (N, N) int32 predecessor matrix.
      src, dst: () int32 nodes.
      max_len: static P, the most nodes a path may hold (source and destination included).
    Returns Path(nodes (P,), mask (P,), found ()); `found` is False when dst is unreachable, or the
    path is longer than P nodes (then `nodes` is all -1).
    """
    pred = jnp.asarray(pred, jnp.int32)
    src, dst = jnp.asarray(src, jnp.int32), jnp.asarray(dst, jnp.int32)

    def step(t, carry):
        cur, length, done, back = carry
        back = back.at[t].set(jnp.where(done, -1, cur))
        length = length + jnp.where(done, 0, 1)
        reached = done | (cur == src)
        nxt = jnp.where(reached, cur, pred[src, jnp.maximum(cur, 0)])
        return jnp.where(nxt < 0, cur, nxt), length, reached | (nxt < 0), back

    init = (dst, jnp.int32(0), jnp.bool_(False), jnp.full((max_len,), -1, jnp.int32))
    _, length, _, back = jax.lax.fori_loop(0, max_len, step, init)
    found = (length > 0) & (back[jnp.maximum(length - 1, 0)] == src)
    t = jnp.arange(max_len)
    nodes = jnp.where(found & (t < length), back[jnp.clip(length - 1 - t, 0, max_len - 1)], -1)
    return Path(nodes=nodes.astype(jnp.int32), mask=nodes >= 0, found=found)


def route_paths(pred: Array, start: Array, visit_nodes: Array, max_len: int) -> Path:
    """The legs of a plan: start -> first goal -> ... as Path with fields (G, P), (G, P), (G,).

    visit_nodes: (G,) int32 nodes in visiting order, -1 after the last (OrderResult.visit_nodes);
    legs past the last goal are empty with found = True.
    """
    visit_nodes = jnp.asarray(visit_nodes, jnp.int32)
    live = visit_nodes >= 0
    srcs = jnp.concatenate([jnp.reshape(jnp.asarray(start, jnp.int32), (1,)), visit_nodes[:-1]])
    legs = jax.vmap(lambda s, d: path_nodes(pred, s, d, max_len))(jnp.maximum(srcs, 0), jnp.maximum(visit_nodes, 0))
    return Path(
        nodes=jnp.where(live[:, None], legs.nodes, -1),
        mask=live[:, None] & legs.mask,
        found=~live | legs.found,
    )


def edge_lengths(nodes: Array, mask: Array, positions: Array, weights: Array, has_distance: Array | None = None):
    """Per-edge lengths of a node path by Rule 1 (edge distance) with the Rule 2 fallback.

    Rule 1: the edge's own distance attribute `weights[a, b]` where it has one; Rule 2: the Euclidean
    distance between the node coordinates in the floor plane (x, y), as the paper's formula writes.
    The fallback is per edge, so a map with every distance present is pure Rule 1 and one with none
    is pure Rule 2.

    Args:
      nodes, mask: (P,) path (Path.nodes / Path.mask).
      positions: (N, 3) or (N, 2) node coordinates.
      weights: (N, N) edge distances.
      has_distance: (N, N) bool, default: weights finite and > 0.
    Returns (lengths (P-1,) float32 with 0 on padding, rule2 (P-1,) bool: edge used the fallback).
    """
    weights = jnp.asarray(weights, jnp.float32)
    has_distance = jnp.isfinite(weights) & (weights > 0) if has_distance is None else jnp.asarray(has_distance, bool)
    nodes, mask = jnp.asarray(nodes), jnp.asarray(mask)
    a, b = jnp.maximum(nodes[:-1], 0), jnp.maximum(nodes[1:], 0)
    live = mask[:-1] & mask[1:]
    xy = jnp.asarray(positions, jnp.float32)[:, :2]
    euclid = jnp.linalg.norm(xy[b] - xy[a], axis=-1)
    rule1 = has_distance[a, b]
    length = jnp.where(rule1, weights[a, b], euclid)
    return jnp.where(live, length, 0.0), live & ~rule1


def path_length(nodes: Array, mask: Array, positions: Array, weights: Array, has_distance: Array | None = None):
    """Travel distance D_total of a path (Rule 1 with Rule 2 fallback); () float32. Jittable."""
    return jnp.sum(edge_lengths(nodes, mask, positions, weights, has_distance)[0])


# ----------------------------------------------------------------------------------------------------
# Host helpers


def path_list(pred: np.ndarray, src: int, dst: int) -> list[int] | None:
    """Shortest path src -> dst as a Python list (host), None when dst is unreachable."""
    pred = np.asarray(pred)
    out = [int(dst)]
    while out[-1] != src:
        p = int(pred[src, out[-1]])
        if p < 0 or len(out) > pred.shape[0]:
            return None
        out.append(p)
    return out[::-1]


def route_list(legs: Path) -> list[int]:
    """One node list for a whole route from route_paths' legs (host), joints not repeated."""
    nodes, mask = np.asarray(legs.nodes), np.asarray(legs.mask)
    route: list[int] = []
    for leg, m in zip(nodes, mask):
        for v in leg[m].tolist():
            if not route or route[-1] != v:
                route.append(int(v))
    return route
