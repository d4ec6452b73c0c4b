"""All-pairs shortest paths: against networkx, under jit and vmap, sizes 0 and 1, unreachable pairs."""

from __future__ import annotations

import jax
import jax.numpy as jnp
import networkx as nx
import numpy as np
import pytest

from ragnav_jax.memory.paths import (
    all_pairs_shortest_paths,
    batched_shortest_paths,
    chunked_shortest_paths,
    connected_components,
    reconstruct_path,
    shortest_paths,
)


def random_graph(rng, n: int, N: int, p: float = 0.25):
    """Padded (N, N) weights (inf = no edge) with n real nodes, often disconnected."""
    w = np.full((N, N), np.inf, np.float32)
    for i in range(n):
        for j in range(i + 1, n):
            if rng.uniform() < p:
                w[i, j] = w[j, i] = rng.uniform(0.1, 2.0)
    return w, np.arange(N) < n


def check_against_networkx(w, mask, cost, pred):
    n = int(mask.sum())
    g = nx.Graph()
    g.add_nodes_from(range(n))
    for i in range(n):
        for j in range(i + 1, n):
            if np.isfinite(w[i, j]):
                g.add_edge(i, j, weight=float(w[i, j]))
    want = dict(nx.all_pairs_dijkstra_path_length(g))
    N = mask.shape[0]
    for i in range(N):
        for j in range(N):
            if i < n and j < n and j in want[i]:
                assert cost[i, j] == pytest.approx(want[i][j], rel=1e-5, abs=1e-5)
                path = reconstruct_path(pred, i, j)
                assert path[0] == i and path[-1] == j
                length = sum(w[a, b] for a, b in zip(path, path[1:]))
                assert length == pytest.approx(want[i][j], rel=1e-5, abs=1e-5)
                assert (pred[i, j] == -1) == (i == j)
            else:
                assert np.isinf(cost[i, j]) and pred[i, j] == -1
                assert reconstruct_path(pred, i, j) == ([i] if i == j else [])


@pytest.mark.parametrize("n,N", [(0, 1), (1, 1), (1, 4), (2, 4), (9, 16), (24, 32)])
def test_apsp_matches_networkx(n, N):
    rng = np.random.default_rng(n * 100 + N)
    w, mask = random_graph(rng, n, N)
    cost, pred = shortest_paths(jnp.asarray(w), jnp.asarray(mask))
    assert cost.dtype == jnp.float32 and pred.dtype == jnp.int32
    check_against_networkx(w, mask, np.asarray(cost), np.asarray(pred))


def test_apsp_batched_equals_single_and_traces_once():
    rng = np.random.default_rng(7)
    graphs = [random_graph(rng, n, 16, 0.3) for n in (16, 5, 0, 11)]
    W = jnp.asarray(np.stack([g[0] for g in graphs]))
    M = jnp.asarray(np.stack([g[1] for g in graphs]))
    cost, pred = batched_shortest_paths(W, M)
    for b, (w, m) in enumerate(graphs):
        c1, p1 = all_pairs_shortest_paths(jnp.asarray(w), jnp.asarray(m))  # eager, no jit
        np.testing.assert_array_equal(np.asarray(cost[b]), np.asarray(c1))
        np.testing.assert_array_equal(np.asarray(pred[b]), np.asarray(p1))
        check_against_networkx(w, m, np.asarray(cost[b]), np.asarray(pred[b]))
    before = batched_shortest_paths._cache_size()
    batched_shortest_paths(W * 2.0, M[::-1])  # new values, same shapes: no retrace
    assert batched_shortest_paths._cache_size() == before


def test_chunked_apsp_equals_batched():
    # 7 graphs in blocks of 3: two full blocks and a remainder, one compiled call.
    rng = np.random.default_rng(11)
    graphs = [random_graph(rng, n, 12, 0.35) for n in (12, 3, 0, 9, 12, 7, 1)]
    W = jnp.asarray(np.stack([g[0] for g in graphs]))
    M = jnp.asarray(np.stack([g[1] for g in graphs]))
    cost, pred = batched_shortest_paths(W, M)
    c2, p2 = chunked_shortest_paths(W, M, chunk=3)
    np.testing.assert_array_equal(np.asarray(c2), np.asarray(cost))
    np.testing.assert_array_equal(np.asarray(p2), np.asarray(pred))
    for b, (w, m) in enumerate(graphs):
        check_against_networkx(w, m, np.asarray(c2[b]), np.asarray(p2[b]))


def test_components():
    adj = np.zeros((6, 6), bool)
    adj[0, 1] = adj[1, 0] = adj[3, 4] = adj[4, 3] = True
    mask = np.array([1, 1, 1, 1, 1, 0], bool)
    np.testing.assert_array_equal(connected_components(adj, mask), [0, 0, 1, 2, 2, -1])
    assert (connected_components(adj, np.zeros(6, bool)) == -1).all()


def test_reconstruct_path_rejects_cycles():
    pred = np.array([[-1, 2, 1], [-1, -1, -1], [-1, -1, -1]])
    with pytest.raises(ValueError):
        reconstruct_path(pred, 0, 1)


def test_apsp_under_vmap_of_jit():
    w, m = random_graph(np.random.default_rng(1), 6, 8, 0.5)
    f = jax.vmap(jax.jit(all_pairs_shortest_paths))
    c, p = f(jnp.asarray(w)[None], jnp.asarray(m)[None])
    check_against_networkx(w, m, np.asarray(c[0]), np.asarray(p[0]))
