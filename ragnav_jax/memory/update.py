"""Online updates of one scene's memory (issue 22): key poses inserted into free slots, edges added or removed,
observations retired, with the shortest paths repaired incrementally instead of by a new Floyd-Warshall, and
the new key pose placed in the forest (its nearest key pose's clusters, whose sizes, centroids and embeddings
follow).

    mem = grow(mem, 16)                                                 # 16 free node slots (host, once)
    mem = insert_node(mem, slot, position, yaw, embedding, sensors, sensor_mask, objects, distances, links)
    mem = add_edge(mem, u, v)                                           # a way found between two key poses
    mem = remove_edge(mem, u, v)                                        # a door found closed
    mem = retire_objects(mem, gone)                                     # observations found wrong

Every function but `grow` takes and returns one scene's `DualBasisMemory` (no leading axis) and is jittable:
vmap over episodes from outside, each episode its own copy. Paths keep `memory/paths.py`'s conventions.

Incremental shortest paths. A new node v with edges of weight w_a to nodes a: cost[v, j] = min_a w_a + cost[a, j],
then every pair (i, j) may pass through v: cost[i, v] + cost[v, j] (O(N^2)). A new edge (u, v, w): every pair may
use it once, i ~> u -> v ~> j or i ~> v -> u ~> j, over the old shortest paths (O(N^2)). A removed edge: the pairs
whose shortest length the edge could carry are reset to the edges left and repaired by min-plus squaring of their
rows against the whole matrix (O(R N^2) per pass, R rows touched, a few passes: each doubles the hops), the rest
kept. The forest keeps its cut: a new leaf joins the
level-1 cluster of the live key pose nearest it in the clustering's hybrid distance, and the clusters above it
follow; a rebuild may cut the dendrogram elsewhere (tests/test_memory_update.py states the bound).
"""

from __future__ import annotations

import functools

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.memory.types import DualBasisMemory

_EPS = 1e-5  # metres: a path this much shorter is shorter (float32 sums)


# ----------------------------------------------------------------------------------------------------
# Free slots


def grow(mem: DualBasisMemory, extra: int) -> DualBasisMemory:
    """`mem` with `extra` more node slots (padding, free for `insert_node`), every (N, ...) array padded and the
    forest's (L * N) slot layout, its slot indices and the dendrogram's ids moved to N + extra. Host side."""
    a = {k: np.asarray(getattr(mem, k)) for k in mem.__dataclass_fields__}
    N = a["node_mask"].shape[0]
    L = a["tree_level"].shape[0] // max(N, 1)
    M2 = N + extra

    def pad(x, axes, value):
        return np.pad(x, [(0, extra if i in axes else 0) for i in range(x.ndim)], constant_values=value)

    def slot(x):  # forest slot lvl * N + c -> lvl * M2 + c (negative: none)
        return np.where(x >= 0, (x // max(N, 1)) * M2 + x % max(N, 1), x).astype(x.dtype)

    def levels(x, value):  # (L * N, ...) -> (L * M2, ...)
        x = x.reshape(L, N, *x.shape[1:])
        return pad(x, (1,), value).reshape(L * M2, *x.shape[2:])

    out = dict(a)
    for k, v in {"node_mask": False, "position": 0.0, "yaw": 0.0, "record": -1, "embedding": 0.0, "sensors": 0.0,
                 "sensor_mask": False, "obs_object": -1, "obs_distance": np.inf, "component": -1}.items():
        out[k] = pad(a[k], (0,), v)
    out["distance"] = pad(a["distance"], (0, 1), 0.0)
    out["adjacency"] = pad(a["adjacency"], (0, 1), False)
    out["path_cost"] = pad(a["path_cost"], (0, 1), np.inf)
    out["path_pred"] = pad(a["path_pred"], (0, 1), -1)
    merges = np.where(a["merges"] >= N, a["merges"] + extra, a["merges"])
    out["merges"] = pad(merges, (0,), -1)
    out["merge_height"] = pad(a["merge_height"], (0,), np.inf)
    out["merge_size"] = pad(a["merge_size"], (0,), 0)
    out["tree_parent"] = levels(slot(a["tree_parent"]), -1)
    out["tree_children"] = pad(levels(slot(a["tree_children"]), -1), (1,), -1)
    out["tree_level"] = np.repeat(np.arange(L, dtype=np.int32), M2)
    out["tree_mask"] = levels(a["tree_mask"], False)
    out["tree_members"] = pad(levels(a["tree_members"], False), (1,), False)
    out["tree_size"] = levels(a["tree_size"], 0)
    out["tree_embedding"] = levels(a["tree_embedding"], 0.0)
    out["tree_position"] = levels(a["tree_position"], 0.0)
    return DualBasisMemory(**{k: jnp.asarray(v) for k, v in out.items()})


def free_slots(mem: DualBasisMemory) -> jax.Array:
    """() int32: free node slots left."""
    return jnp.sum(~mem.node_mask).astype(jnp.int32)


# ----------------------------------------------------------------------------------------------------
# Shortest paths, repaired


def _components(cost: jax.Array, mask: jax.Array) -> jax.Array:
    """(N,) int32 component labels from reachability (0, 1, ... by first node, as `paths.connected_components`),
    -1 for padding."""
    N = mask.shape[0]
    idx = jnp.arange(N, dtype=jnp.int32)
    reach = jnp.isfinite(cost) & mask[:, None] & mask[None, :]
    first = jnp.argmax(reach, axis=1).astype(jnp.int32)  # smallest node reachable from each (itself at worst)
    root = mask & (first == idx)
    label = jnp.sum(root[None, :] & (idx[None, :] < first[:, None]), axis=1).astype(jnp.int32)
    return jnp.where(mask, label, -1)


def _through(cost, pred, v):
    """Every pair's path may pass through node v (whose row and column are exact): the Floyd-Warshall step of v."""
    via = cost[:, v, None] + cost[None, v, :]
    better = via < cost - _EPS
    return jnp.where(better, via, cost), jnp.where(better, pred[v][None, :], pred)


def insert_node(mem: DualBasisMemory, slot, position, yaw, embedding, sensors, sensor_mask, objects, distances,
                links) -> DualBasisMemory:
    """`mem` with a key pose in free slot `slot` (() int32): position (3,), yaw (), embedding (D,) unit,
    sensors (S,) / sensor_mask (S,) the mean reading of what it saw, objects (K,) int32 scene objects seen,
    nearest first (-1 padded) at distances (K,), and edges to the live nodes of links (N,) bool (weights: the
    Euclidean distance). Paths, components and the forest follow (module docstring)."""
    N = mem.node_mask.shape[0]
    idx = jnp.arange(N, dtype=jnp.int32)
    live = mem.node_mask
    d = jnp.linalg.norm(mem.position - position[None], axis=-1).astype(jnp.float32)
    d = d.at[slot].set(0.0)
    links = links & live & (idx != slot)
    m = mem.replace(
        node_mask=live.at[slot].set(True), position=mem.position.at[slot].set(position),
        yaw=mem.yaw.at[slot].set(yaw), record=mem.record.at[slot].set(-1),
        embedding=mem.embedding.at[slot].set(embedding), sensors=mem.sensors.at[slot].set(sensors),
        sensor_mask=mem.sensor_mask.at[slot].set(sensor_mask), obs_object=mem.obs_object.at[slot].set(objects),
        obs_distance=mem.obs_distance.at[slot].set(jnp.where(objects >= 0, distances, jnp.inf)),
        distance=mem.distance.at[slot].set(d).at[:, slot].set(d),
        adjacency=mem.adjacency.at[slot].set(links).at[:, slot].set(links))
    # the new row: the best neighbour a for every target j
    w = jnp.where(links, d, jnp.inf)
    via = w[:, None] + mem.path_cost  # (a, j)
    a = jnp.argmin(via, axis=0).astype(jnp.int32)
    row = jnp.min(via, axis=0)
    row_pred = jnp.where(a == idx, slot, mem.path_pred[a, idx])
    row = row.at[slot].set(0.0)
    row_pred = jnp.where(jnp.isfinite(row), row_pred, -1).at[slot].set(-1)
    cost = mem.path_cost.at[slot].set(row).at[:, slot].set(row)
    col_pred = jnp.where(jnp.isfinite(row), a, -1).at[slot].set(-1)  # before v on i -> v: i's best neighbour of v
    pred = mem.path_pred.at[slot].set(row_pred).at[:, slot].set(col_pred)
    cost, pred = _through(cost, pred, slot)
    m = m.replace(path_cost=cost, path_pred=pred, component=_components(cost, m.node_mask))
    return _forest_insert(m, slot)


def add_edge(mem: DualBasisMemory, u, v) -> DualBasisMemory:
    """`mem` with the edge u - v (weight: their distance) and every shortest path that it shortens."""
    w = mem.distance[u, v]
    cost, pred = mem.path_cost, mem.path_pred
    idx = jnp.arange(cost.shape[0], dtype=jnp.int32)
    via_uv = cost[:, u, None] + w + cost[None, v, :]  # i ~> u -> v ~> j
    via_vu = cost[:, v, None] + w + cost[None, u, :]  # i ~> v -> u ~> j
    p_uv = jnp.where(idx == v, u, pred[v])[None, :]
    p_vu = jnp.where(idx == u, v, pred[u])[None, :]
    first = via_uv <= via_vu
    via, p = jnp.where(first, via_uv, via_vu), jnp.where(first, p_uv, p_vu)
    better = via < cost - _EPS
    cost, pred = jnp.where(better, via, cost), jnp.where(better, p, pred)
    adj = mem.adjacency.at[u, v].set(True).at[v, u].set(True)
    return mem.replace(adjacency=adj, path_cost=cost, path_pred=pred, component=_components(cost, mem.node_mask))


@functools.partial(jax.jit, static_argnames="rows")
def _repair_rows(cost, pred, todo, rows: int):
    """Min-plus squaring of the rows marked `todo` (N,) against the whole matrix, `rows` of them per block,
    until nothing changes: each pass doubles the hops of the paths found, so a few passes repair every row
    (the rows not marked are exact and stay)."""
    N = cost.shape[0]
    order = jnp.argsort(~todo, stable=True)  # the rows to repair first
    starts = jnp.arange(0, N, rows, dtype=jnp.int32)

    def one_block(carry, start):
        cost, pred, changed = carry
        r = jax.lax.dynamic_slice_in_dim(order, start, rows)
        ok = jax.lax.dynamic_slice_in_dim(todo[order], start, rows)
        via = cost[r][:, :, None] + cost[None, :, :]  # (R, k, j): i ~> k ~> j
        k = jnp.argmin(via, axis=1).astype(jnp.int32)
        best = jnp.min(via, axis=1)
        better = ok[:, None] & (best < cost[r] - _EPS)
        p = jnp.where(better, pred[k, jnp.arange(N)[None, :]], pred[r])  # j's predecessor on the k ~> j path
        cost = cost.at[r].set(jnp.where(better, best, cost[r]))
        return (cost, pred.at[r].set(p), changed | jnp.any(better)), None

    def cond(x):
        return x[2]

    def body(x):
        cost, pred, _ = x
        (cost, pred, changed), _ = jax.lax.scan(one_block, (cost, pred, False), starts)
        return cost, pred, changed

    cost, pred, _ = jax.lax.while_loop(cond, body, (cost, pred, jnp.any(todo)))
    return cost, pred


def remove_edge(mem: DualBasisMemory, u, v, rows: int = 32) -> DualBasisMemory:
    """`mem` without the edge u - v: the pairs whose shortest length it could carry are reset to the edges left
    and repaired by min-plus squaring of their rows (`_repair_rows`, `rows` rows a block); the rest keep their
    paths."""
    N = mem.node_mask.shape[0]
    idx = jnp.arange(N, dtype=jnp.int32)
    w = mem.distance[u, v]
    cost, pred = mem.path_cost, mem.path_pred
    tol = 1e-4 * (1.0 + cost)
    carried = (jnp.abs(cost[:, u, None] + w + cost[None, v, :] - cost) <= tol) | (
        jnp.abs(cost[:, v, None] + w + cost[None, u, :] - cost) <= tol)
    carried &= mem.adjacency[u, v] & ~jnp.eye(N, dtype=bool)
    adj = mem.adjacency.at[u, v].set(False).at[v, u].set(False)
    weights = jnp.where(adj, mem.distance, jnp.inf)
    cost = jnp.where(carried, weights, cost)  # a reset pair keeps its direct edge, if it has one
    pred = jnp.where(carried, jnp.where(jnp.isfinite(weights), idx[:, None], -1), pred)
    cost, pred = _repair_rows(cost, pred, jnp.any(carried, axis=1), min(rows, N))
    return mem.replace(adjacency=adj, path_cost=cost, path_pred=pred, component=_components(cost, mem.node_mask))


def retire_objects(mem: DualBasisMemory, gone) -> DualBasisMemory:
    """`mem` without the observations of the scene objects marked gone ((O,) bool: not where the memory saw
    them), each node's remaining observations kept nearest first."""
    hit = (mem.obs_object >= 0) & gone[jnp.clip(mem.obs_object, 0, gone.shape[0] - 1)]
    obj = jnp.where(hit, -1, mem.obs_object)
    dist = jnp.where(hit, jnp.inf, mem.obs_distance)
    order = jnp.argsort(dist, axis=1, stable=True)
    return mem.replace(obs_object=jnp.take_along_axis(obj, order, 1), obs_distance=jnp.take_along_axis(dist, order, 1))


# ----------------------------------------------------------------------------------------------------
# The forest


def _forest_insert(mem: DualBasisMemory, v) -> DualBasisMemory:
    """Leaf slot v joins the clusters of the live key pose nearest it (planar metres along the map where it is
    reachable, straight otherwise, plus the embedding's cosine distance, as the clustering's hybrid metric):
    its level-1 cluster and every cluster above gain the leaf, their sizes, centroids and (normalised mean
    of the children) embeddings recomputed."""
    N = mem.node_mask.shape[0]
    L = mem.tree_level.shape[0] // N
    idx = jnp.arange(N, dtype=jnp.int32)
    others = mem.node_mask & (idx != v)
    geo = jnp.where(jnp.isfinite(mem.path_cost[v]), mem.path_cost[v], mem.distance[v])
    cosd = 1.0 - mem.embedding @ mem.embedding[v]
    near = jnp.argmin(jnp.where(others, geo + cosd, jnp.inf)).astype(jnp.int32)
    parent = mem.tree_parent.at[v].set(jnp.where(others.any(), mem.tree_parent[near], -1))
    t = mem.replace(tree_parent=parent, tree_mask=mem.tree_mask.at[v].set(True),
                    tree_members=mem.tree_members.at[v].set(idx == v), tree_size=mem.tree_size.at[v].set(1),
                    tree_embedding=mem.tree_embedding.at[v].set(mem.embedding[v]),
                    tree_position=mem.tree_position.at[v].set(mem.position[v]))
    # climb: each ancestor gains the leaf and the child below it (sorted), then its figures follow
    child = v
    for _ in range(L - 1):
        c = t.tree_parent[child]
        ok = c >= 0
        cs = jnp.where(ok, c, 0)
        kids = t.tree_children[cs]
        kids = jnp.where(ok & ~jnp.any(kids == child), jnp.sort(jnp.where(kids < 0, jnp.iinfo(jnp.int32).max,
                                                                           kids).at[-1].set(child)), kids)
        kids = jnp.where(kids == jnp.iinfo(jnp.int32).max, -1, kids)
        members = t.tree_members[cs] | (idx == v)
        live = kids >= 0
        emb = jnp.sum(jnp.where(live[:, None], t.tree_embedding[jnp.clip(kids, 0)], 0.0), 0)
        emb = emb / jnp.maximum(jnp.linalg.norm(emb), 1e-12)
        mf = members.astype(jnp.float32)
        pos = (mf @ t.position) / jnp.maximum(mf.sum(), 1.0)
        t = t.replace(tree_children=t.tree_children.at[cs].set(jnp.where(ok, kids, t.tree_children[cs])),
                      tree_members=t.tree_members.at[cs].set(jnp.where(ok, members, t.tree_members[cs])),
                      tree_size=t.tree_size.at[cs].set(jnp.where(ok, members.sum(), t.tree_size[cs])),
                      tree_embedding=t.tree_embedding.at[cs].set(jnp.where(ok, emb, t.tree_embedding[cs])),
                      tree_position=t.tree_position.at[cs].set(jnp.where(ok, pos, t.tree_position[cs])))
        child = jnp.where(ok, c, child)
    return t
