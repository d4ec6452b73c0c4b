"""Semantic forest: merges equal scipy's linkage, hybrid similarity and fused features as in the paper,
level structure, parent embeddings, jit/vmap with padding."""

from __future__ import annotations

import jax.numpy as jnp
import numpy as np
import pytest
from scipy.cluster.hierarchy import linkage
from scipy.spatial.distance import pdist, squareform

from ragnav_jax.memory.forest import (
    LINKAGES,
    agglomerate_batched,
    agglomerate_jit,
    build_forest_batched,
    clustering_distance,
    fused_features,
    hybrid_similarity,
    to_scipy_linkage,
)


def padded(d: np.ndarray, N: int):
    n = d.shape[0]
    D = np.zeros((N, N), np.float32)
    D[:n, :n] = d
    return jnp.asarray(D), jnp.asarray(np.arange(N) < n)


@pytest.mark.parametrize("method", LINKAGES)
@pytest.mark.parametrize("n,N", [(2, 8), (7, 8), (13, 16)])
def test_merges_equal_scipy(method, n, N):
    rng = np.random.default_rng(n)
    X = rng.normal(size=(n, 4))  # continuous random points: tie-free distances
    D, mask = padded(squareform(pdist(X)), N)
    Z = to_scipy_linkage(agglomerate_jit(D, mask, method=method), n)
    want = linkage(pdist(X), method)
    np.testing.assert_array_equal(Z[:, :2], want[:, :2])
    np.testing.assert_allclose(Z[:, 2], want[:, 2], rtol=1e-5, atol=1e-5)
    np.testing.assert_array_equal(Z[:, 3], want[:, 3])


@pytest.mark.parametrize("n", [0, 1])
def test_tiny_inputs(n):
    D, mask = padded(np.zeros((n, n)), 4)
    dg = agglomerate_jit(D, mask, method="average")
    assert (np.asarray(dg.merges) == -1).all() and np.isinf(np.asarray(dg.heights)).all()


def test_vmapped_agglomeration_over_padded_scenes():
    rng = np.random.default_rng(3)
    sizes = (16, 9, 3)
    Xs = [rng.normal(size=(n, 3)) for n in sizes]
    D = jnp.stack([padded(squareform(pdist(X)), 16)[0] for X in Xs])
    M = jnp.stack([padded(squareform(pdist(X)), 16)[1] for X in Xs])
    dg = agglomerate_batched(D, M, "average")
    for b, X in enumerate(Xs):
        one = jax_tree_index(dg, b)
        np.testing.assert_array_equal(to_scipy_linkage(one, len(X))[:, :2], linkage(pdist(X), "average")[:, :2])


def jax_tree_index(t, b):
    return type(t)(*(np.asarray(x)[b] for x in t))


def test_hybrid_similarity_and_fused_features_follow_the_paper():
    rng = np.random.default_rng(0)
    pos = rng.normal(size=(5, 3)).astype(np.float32)
    emb = rng.normal(size=(5, 8)).astype(np.float32)
    d = squareform(pdist(pos)).astype(np.float32)
    omega, scale = 0.3, 2.0
    S = np.asarray(hybrid_similarity(jnp.asarray(d), jnp.asarray(emb), omega, scale))
    e = emb / np.linalg.norm(emb, axis=1, keepdims=True)
    np.testing.assert_allclose(S, omega * np.exp(-d / scale) + (1 - omega) * e @ e.T, atol=1e-6)
    mask = jnp.asarray(np.array([1, 1, 1, 1, 0], bool))
    F = np.asarray(fused_features(jnp.asarray(pos), jnp.asarray(emb), mask, 0.25))
    c = pos[:4] - pos[:4].mean(0)
    spa = c / np.sqrt((c**2).sum() / 4)
    np.testing.assert_allclose(F[:4, :3], 0.25 * spa, atol=1e-5)
    np.testing.assert_allclose(F[:4, 3:], 0.75 * e[:4], atol=1e-6)
    assert np.all(F[4] == 0)
    dist = np.asarray(clustering_distance(jnp.asarray(pos), jnp.asarray(emb), mask, jnp.asarray(d), omega, 0.5, scale,
                                          metric="hybrid", spatial="geodesic"))
    np.testing.assert_allclose(dist, np.where(np.eye(5, dtype=bool), 0, np.maximum(1 - S, 0)), atol=1e-6)


@pytest.mark.parametrize("metric", ["hybrid", "fused"])
def test_forest_levels_parents_and_embeddings(metric):
    rng = np.random.default_rng(5)
    B, N = 3, 32
    counts = np.array([32, 20, 1])
    pos = rng.uniform(0, 10, size=(B, N, 3)).astype(np.float32)
    emb = rng.normal(size=(B, N, 16)).astype(np.float32)
    emb /= np.linalg.norm(emb, axis=-1, keepdims=True)
    mask = np.arange(N)[None] < counts[:, None]
    geo = np.stack([squareform(pdist(p)) for p in pos]).astype(np.float32)
    level_sizes = (3.0, 8.0, 20.0)
    dg, f = build_forest_batched(jnp.asarray(pos), jnp.asarray(emb), jnp.asarray(mask), jnp.asarray(geo),
                                 jnp.float32(0.5), jnp.float32(0.5), jnp.float32(3.0), metric=metric,
                                 spatial="geodesic", level_sizes=level_sizes)
    L = 1 + len(level_sizes)
    f = type(f)(*(np.asarray(x) for x in f))
    for b, n in enumerate(counts):
        per_level = [int(f.mask[b, lv * N:(lv + 1) * N].sum()) for lv in range(L)]
        want = [n] + [max(1, int(np.ceil(n / s))) for s in level_sizes]
        want = [min(want[: k + 1]) for k in range(L)]
        assert per_level == want
        for slot in np.flatnonzero(f.mask[b]):
            lvl = f.level[b, slot]
            kids = f.children[b, slot][f.children[b, slot] >= 0]
            if lvl == 0:
                assert len(kids) == 0 and f.size[b, slot] == 1
            else:
                assert len(kids) >= 1 and (f.parent[b, kids] == slot).all() and (f.level[b, kids] == lvl - 1).all()
                # members are the union of the children's members; sizes add up
                np.testing.assert_array_equal(f.members[b, slot], f.members[b, kids].any(0))
                assert f.size[b, slot] == f.size[b, kids].sum()
                mean = f.embedding[b, kids].mean(0)
                np.testing.assert_allclose(f.embedding[b, slot], mean / np.linalg.norm(mean), atol=1e-5)
                np.testing.assert_allclose(f.position[b, slot], pos[b][f.members[b, slot]].mean(0), atol=1e-4)
            if lvl == L - 1:
                assert f.parent[b, slot] == -1
            else:
                assert f.parent[b, slot] >= (lvl + 1) * N
        # every real leaf sits in exactly one cluster per level
        assert (f.members[b].reshape(L, N, N).sum(1)[:, :n] == 1).all()
        assert not f.members[b][:, n:].any()
