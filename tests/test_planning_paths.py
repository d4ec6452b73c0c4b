"""Paths from predecessor matrices against networkx; Rule 1 / Rule 2 travel distance."""

from __future__ import annotations

import jax
import jax.numpy as jnp
import networkx as nx
import numpy as np
import pytest
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import shortest_path

from ragnav_jax.planning import edge_lengths, path_length, path_list, path_nodes, route_list, route_paths


def random_map(seed: int, N: int = 14, pad: int = 3):
    """A random geometric graph with two components and padded nodes; reference matrices by scipy."""
    rng = np.random.default_rng(seed)
    pos = rng.uniform(0, 10, (N + pad, 3))
    g = nx.Graph()
    g.add_nodes_from(range(N))
    half = N // 2 + 1
    for comp in (range(half), range(half, N)):  # two components
        comp = list(comp)
        for a, b in zip(comp[:-1], comp[1:]):  # a chain keeps each component connected
            g.add_edge(a, b)
        for _ in range(len(comp)):
            a, b = rng.choice(comp, 2, replace=False)
            g.add_edge(int(a), int(b))
    M = N + pad
    w = np.zeros((M, M), np.float32)
    for a, b in g.edges:
        d = float(np.linalg.norm(pos[a, :2] - pos[b, :2])) * rng.uniform(1.0, 1.3)  # detours: not pure Euclid
        g[a][b]["weight"] = d
        w[a, b] = w[b, a] = d
    dist, pred = shortest_path(csr_matrix(w.astype(np.float64)), directed=False, return_predecessors=True)
    pred = np.where(pred < 0, -1, pred).astype(np.int32)
    return g, pos.astype(np.float32), w, dist.astype(np.float32), pred


@pytest.mark.parametrize("seed", [0, 1])
def test_paths_match_networkx(seed):
    g, pos, w, dist, pred = random_map(seed)
    M = pos.shape[0]
    P = 16
    src, dst = np.meshgrid(np.arange(M), np.arange(M), indexing="ij")
    paths = jax.jit(jax.vmap(lambda s, d: path_nodes(pred, s, d, P)))(src.ravel(), dst.ravel())
    lengths = jax.jit(jax.vmap(lambda n, m: path_length(n, m, pos, w)))(paths.nodes, paths.mask)
    for k, (s, d) in enumerate(zip(src.ravel(), dst.ravel())):
        s, d = int(s), int(d)
        nodes = np.asarray(paths.nodes[k])[np.asarray(paths.mask[k])].tolist()
        host = path_list(pred, s, d)
        if s in g and d in g and nx.has_path(g, s, d):
            ref = nx.shortest_path(g, s, d, weight="weight")
            assert bool(paths.found[k]) and nodes == ref == host
            assert float(lengths[k]) == pytest.approx(
                nx.shortest_path_length(g, s, d, weight="weight"), rel=1e-5, abs=1e-5
            )
            assert float(lengths[k]) == pytest.approx(float(dist[s, d]), rel=1e-5, abs=1e-5)
        elif s == d:  # a padded node is its own (empty) path
            assert nodes == [s] and host == [s]
        else:
            assert not bool(paths.found[k]) and nodes == [] and host is None


def test_path_longer_than_buffer_is_not_found():
    N = 6
    pred = np.full((N, N), -1, np.int32)
    for s in range(N):  # a line 0-1-2-3-4-5
        for d in range(N):
            if d > s:
                pred[s, d] = d - 1
            elif d < s:
                pred[s, d] = d + 1
    find = jax.jit(path_nodes, static_argnums=3)
    full = find(pred, 0, 5, 6)
    assert bool(full.found) and np.asarray(full.nodes).tolist() == [0, 1, 2, 3, 4, 5]
    short = find(pred, 0, 5, 4)
    assert not bool(short.found) and np.all(np.asarray(short.nodes) == -1)
    back = find(pred, 4, 1, 4)
    assert np.asarray(back.nodes).tolist() == [4, 3, 2, 1]


def test_route_legs_and_host_route():
    g, pos, w, dist, pred = random_map(3)
    visit = np.array([5, 2, 7, -1, -1], np.int32)
    legs = jax.jit(lambda v: route_paths(pred, 0, v, 16))(visit)
    assert legs.nodes.shape == (5, 16) and np.asarray(legs.found).all()
    expect = [0]
    for a, b in zip([0, 5, 2], [5, 2, 7]):
        expect += nx.shortest_path(g, a, b, weight="weight")[1:]
    assert route_list(legs) == expect


def test_rule1_with_rule2_fallback():
    pos = np.array([[0, 0, 0], [3, 4, 9], [3, 0, 0]], np.float32)  # z is ignored, as in the paper's Rule 2
    nodes, mask = jnp.array([0, 1, 2, -1]), jnp.array([True, True, True, False])
    w = np.array([[0, 7.0, 0], [7.0, 0, 2.0], [0, 2.0, 0]], np.float32)
    assert float(path_length(nodes, mask, pos, w)) == pytest.approx(9.0)  # Rule 1: 7 + 2
    none = np.full((3, 3), np.nan, np.float32)
    assert float(path_length(nodes, mask, pos, none)) == pytest.approx(5.0 + 4.0)  # Rule 2: Euclid in (x, y)
    mixed = w.copy()
    mixed[1, 2] = mixed[2, 1] = np.nan
    lengths, rule2 = edge_lengths(nodes, mask, pos, mixed)
    assert np.asarray(lengths).tolist() == pytest.approx([7.0, 4.0, 0.0])
    assert np.asarray(rule2).tolist() == [False, True, False]
