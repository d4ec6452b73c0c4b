"""Online memory updates (memory/update.py): after random key-pose insertions, new edges and removed edges the
incrementally repaired shortest paths equal networkx's on the same graph, predecessors trace paths of that
length, components equal scipy's; the forest stays consistent, and a key pose inserted where one already is
joins that one's clusters, as a rebuild puts it."""

import jax
import jax.numpy as jnp
import networkx as nx
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from test_memory_streams import synthetic_stream

from ragnav_jax.config import load_config
from ragnav_jax.memory.build import build_bank
from ragnav_jax.memory.encoder import HashingEmbedder
from ragnav_jax.memory.forest import build_forest
from ragnav_jax.memory.paths import connected_components, reconstruct_path
from ragnav_jax.memory.update import add_edge, free_slots, grow, insert_node, remove_edge, retire_objects
from ragnav_jax.pytrees import take

EXTRA = 6


@pytest.fixture(scope="module")
def base(apartment):
    cfg = load_config(None, ["memory.embedder=hashing"])
    bank, _ = build_bank([apartment], [synthetic_stream(apartment)], cfg, embedder=HashingEmbedder(cfg.memory.hashing_dim))
    return cfg, take(bank.memory, 0)


jit_insert = jax.jit(insert_node)
jit_add = jax.jit(add_edge)
jit_remove = jax.jit(remove_edge)


def check_paths(mem):
    """cost against networkx (Dijkstra over adjacency weighted by distance), pred traces, components."""
    mask = np.asarray(mem.node_mask)
    adj, dist = np.asarray(mem.adjacency), np.asarray(mem.distance)
    cost, pred = np.asarray(mem.path_cost), np.asarray(mem.path_pred)
    g = nx.Graph()
    live = np.flatnonzero(mask)
    g.add_nodes_from(live.tolist())
    for i, j in zip(*np.nonzero(np.triu(adj))):
        g.add_edge(int(i), int(j), weight=float(dist[i, j]))
    ref = dict(nx.all_pairs_dijkstra_path_length(g))
    for i in live:
        for j in live:
            want = ref[i].get(j, np.inf)
            assert np.isclose(cost[i, j], want, rtol=1e-5, atol=1e-4) or (np.isinf(want) and np.isinf(cost[i, j])), (i, j)
            if np.isfinite(want) and i != j:
                path = reconstruct_path(pred, int(i), int(j))
                assert path[0] == i and path[-1] == j
                assert all(adj[a, b] for a, b in zip(path[:-1], path[1:]))
                assert np.isclose(sum(dist[a, b] for a, b in zip(path[:-1], path[1:])), want, rtol=1e-5, atol=1e-4)
    assert (np.asarray(mem.component) == connected_components(adj, mask)).all()


def check_forest(mem):
    """Every cluster holds the leaves of its children; sizes, centroids and embeddings follow."""
    mask, members = np.asarray(mem.tree_mask), np.asarray(mem.tree_members)
    kids, emb, pos = np.asarray(mem.tree_children), np.asarray(mem.tree_embedding), np.asarray(mem.tree_position)
    N = np.asarray(mem.node_mask).shape[0]
    assert (members[:N][mask[:N]] == np.eye(N, dtype=bool)[mask[:N]]).all()
    for s in np.flatnonzero(mask[N:]) + N:
        k = kids[s][kids[s] >= 0]
        assert len(k) and (members[s] == members[k].any(0)).all()
        assert np.asarray(mem.tree_size)[s] == members[s].sum()
        mean = emb[k].sum(0)
        assert np.allclose(emb[s], mean / np.linalg.norm(mean), atol=1e-5)
        assert np.allclose(pos[s], np.asarray(mem.position)[members[s]].mean(0), atol=1e-4)
    for lvl in range(mask.shape[0] // N):  # every level covers every key pose, once
        blk = members[lvl * N : (lvl + 1) * N][mask[lvl * N : (lvl + 1) * N]]
        assert (blk.sum(0) == np.asarray(mem.node_mask)).all()


def test_grow_keeps_everything_and_frees_slots(base):
    _, mem = base
    g = grow(mem, EXTRA)
    N = mem.node_mask.shape[0]
    assert int(free_slots(g)) == int(free_slots(mem)) + EXTRA
    for k in ("node_mask", "position", "embedding", "obs_object", "component"):
        assert (np.asarray(getattr(g, k))[:N] == np.asarray(getattr(mem, k))).all(), k
    assert (np.asarray(g.path_cost)[:N, :N] == np.asarray(mem.path_cost)).all()
    check_paths(g)
    check_forest(g)


def _slot(mem):
    return int(np.flatnonzero(~np.asarray(mem.node_mask))[0])


@settings(max_examples=6, deadline=None)
@given(data=st.data())
def test_incremental_paths_match_networkx_after_random_changes(base, data):
    _, mem = base
    mem = grow(mem, EXTRA)
    D = mem.embedding.shape[1]
    rng = np.random.default_rng(data.draw(st.integers(0, 2**31 - 1)))
    for _ in range(data.draw(st.integers(3, 7))):
        op = data.draw(st.sampled_from(["insert", "add", "remove"]))
        live = np.flatnonzero(np.asarray(mem.node_mask))
        if op == "insert" and int(free_slots(mem)):
            # between two to three key poses, often far apart along the map: a shortcut for many pairs
            ends = rng.choice(live, size=rng.integers(0, 4), replace=False)
            p = (np.asarray(mem.position)[ends].mean(0) if len(ends) else rng.uniform(0, 10, 3)) + rng.normal(0, 0.3, 3)
            p = p.astype(np.float32)
            links = np.zeros(mem.node_mask.shape[0], bool)
            links[ends] = True
            e = rng.normal(size=D).astype(np.float32)
            objs = np.full(mem.obs_object.shape[1], -1, np.int32)
            objs[:2] = [3, 5]
            mem = jit_insert(mem, _slot(mem), p, 0.0, e / np.linalg.norm(e), jnp.zeros(mem.sensors.shape[1]),
                             jnp.zeros(mem.sensors.shape[1], bool), objs, np.full(objs.shape, 1.5, np.float32), links)
        elif op == "add":
            u, v = rng.choice(live, 2, replace=False)
            mem = jit_add(mem, int(u), int(v))
        else:
            edges = np.argwhere(np.triu(np.asarray(mem.adjacency)))
            if len(edges):
                u, v = edges[rng.integers(len(edges))]
                mem = jit_remove(mem, int(u), int(v))
        check_paths(mem)
    check_forest(mem)


def test_a_key_pose_where_one_already_is_joins_its_clusters_as_a_rebuild_does(base):
    cfg, mem = base
    mem = grow(mem, 1)
    v, twin = _slot(mem), 4
    links = np.asarray(mem.adjacency[twin]).copy()
    new = insert_node(mem, v, mem.position[twin], mem.yaw[twin], mem.embedding[twin], mem.sensors[twin],
                      mem.sensor_mask[twin], mem.obs_object[twin], mem.obs_distance[twin], links)
    check_forest(new)
    parent = np.asarray(new.tree_parent)
    assert parent[v] == parent[twin]
    m = cfg.memory
    _, forest = build_forest(new.position, new.embedding, new.node_mask, new.path_cost, jnp.float32(m.omega),
                             jnp.float32(m.alpha), jnp.float32(m.spatial_scale), metric=m.forest_metric,
                             spatial=m.spatial_distance, linkage=m.linkage, level_sizes=tuple(m.level_sizes))
    rebuilt = np.asarray(forest.parent)
    assert rebuilt[v] == rebuilt[twin]  # the rebuild puts the twin with its original too


def test_retired_observations_leave_the_lists_nearest_first(base):
    _, mem = base
    obs = np.asarray(mem.obs_object)
    gone = np.zeros(int(obs.max()) + 1, bool)
    gone[obs[0, 0]] = True
    out = retire_objects(mem, jnp.asarray(gone))
    o, d = np.asarray(out.obs_object), np.asarray(out.obs_distance)
    assert not np.isin(o, np.flatnonzero(gone)).any()
    assert (np.diff(np.where(np.isinf(d), 1e9, d), axis=1) >= 0).all() and ((o >= 0) == np.isfinite(d)).all()
    kept = obs[(obs >= 0) & ~gone[np.clip(obs, 0, None)]]
    assert sorted(o[o >= 0].tolist()) == sorted(kept.tolist())
