"""Each retrieval kernel equals a plain NumPy reference on random inputs, under jit and vmap."""

import jax
import jax.numpy as jnp
import numpy as np
import retrieval_reference as ref
from hypothesis import given, settings
from hypothesis import strategies as st

from ragnav_jax.retrieval import kernels as K

ATOL = 1e-5


def random_graph(rng, n, dmax, p=0.3):
    """Symmetric random neighbour lists (N, Dmax) with -1 padding."""
    nbr = np.full((n, dmax), -1, np.int32)
    pos = rng.uniform(0, 10, (n, 3)).astype(np.float32)
    pos[:, 2] = 0
    deg = np.zeros(n, int)
    for i in range(n):
        for j in range(i + 1, n):
            if rng.uniform() < p and deg[i] < dmax and deg[j] < dmax:
                nbr[i, deg[i]], nbr[j, deg[j]] = j, i
                deg[i] += 1
                deg[j] += 1
    return nbr, nbr >= 0, pos


def tie_free(rng, n):
    """Scores with distinct values (ties make argmax/top-k choices reference-dependent)."""
    return (rng.permutation(n) / n + rng.uniform(0, 1e-3, n)).astype(np.float32)


seeds = st.integers(0, 2**31 - 1)
sizes = st.sampled_from([1, 5, 12])  # a few shapes only: each new shape is a new compile


@settings(max_examples=25, deadline=None)
@given(seed=seeds, n=sizes, d=st.sampled_from([1, 8]))
def test_cosine(seed, n, d):
    rng = np.random.default_rng(seed)
    q, emb = rng.normal(size=d).astype(np.float32), rng.normal(size=(n, d)).astype(np.float32)
    mask = rng.uniform(size=n) < 0.8
    np.testing.assert_allclose(jax.jit(K.cosine_scores)(q, emb, mask), ref.cosine(q, emb, mask), atol=ATOL)


@settings(max_examples=25, deadline=None)
@given(seed=seeds, n=sizes, sigma=st.floats(0.3, 5.0))
def test_spatial_and_combo(seed, n, sigma):
    rng = np.random.default_rng(seed)
    sem, pos, pb = rng.uniform(size=n).astype(np.float32), rng.uniform(0, 8, (n, 3)).astype(np.float32), rng.uniform(0, 8, 3).astype(np.float32)
    expect = sem * np.exp(-np.sum((pos - pb) ** 2, -1) / (2 * sigma**2))
    np.testing.assert_allclose(K.spatial_score(sem, pos, pb, jnp.float32(sigma)), expect, atol=ATOL)
    np.testing.assert_allclose(K.combo_score(pos, pb), 1 / (1 + np.linalg.norm(pos - pb, axis=-1)), atol=ATOL)


@settings(max_examples=30, deadline=None)
@given(seed=seeds, n=sizes, top_k=st.integers(1, 6), hops=st.integers(0, 3),
       thr=st.floats(0.0, 0.9), sigma=st.floats(0.5, 4.0))
def test_anchor_guided(seed, n, top_k, hops, thr, sigma):
    rng = np.random.default_rng(seed)
    nbr, nm, pos = random_graph(rng, n, 4)
    sem_a, sem_b = tie_free(rng, n), tie_free(rng, n)
    pos_b = pos + rng.uniform(-0.5, 0.5, pos.shape).astype(np.float32)  # where each node's B instance lies
    f = jax.jit(K.anchor_guided, static_argnames=("max_k", "max_hops"))
    s, a, has = f(sem_a, sem_b, pos, nbr, nm, jnp.int32(top_k), jnp.int32(hops), jnp.float32(thr),
                  jnp.float32(sigma), max_k=min(6, n), max_hops=3, pos_b=pos_b)
    rs, ra = ref.anchor_guided(sem_a, sem_b, pos, nbr, nm, top_k, hops, thr, sigma, pos_b)
    np.testing.assert_allclose(np.asarray(s), rs, atol=ATOL)
    np.testing.assert_array_equal(np.asarray(a), ra)
    np.testing.assert_array_equal(np.asarray(has), ra >= 0)


@settings(max_examples=30, deadline=None)
@given(seed=seeds, n=sizes, hops=st.integers(0, 3), eta=st.floats(0.0, 2.0), thr=st.floats(0.0, 0.9))
def test_neighbour_boost(seed, n, hops, eta, thr):
    rng = np.random.default_rng(seed)
    nbr, nm, _ = random_graph(rng, n, 4)
    sem, ctx = rng.uniform(size=n).astype(np.float32), rng.uniform(size=n).astype(np.float32)
    mask = rng.uniform(size=n) < 0.85
    rb, rm = ref.boost(sem, ctx, nbr, nm, mask, eta, thr, hops)
    for max_hops in ((1,) if hops <= 1 else ()) + (3,):
        b, m = jax.jit(K.neighbour_boost, static_argnames="max_hops")(
            sem, ctx, nbr, nm, mask, jnp.float32(eta), jnp.float32(thr), jnp.int32(hops), max_hops=max_hops)
        np.testing.assert_allclose(np.asarray(b), rb, atol=ATOL, rtol=1e-5)
        np.testing.assert_allclose(np.asarray(m), rm, atol=ATOL)


@settings(max_examples=40, deadline=None)
@given(seed=seeds, m=st.sampled_from([1, 4, 8]), op=st.integers(0, 5), value=st.floats(-5, 80), scale=st.floats(0.05, 5.0))
def test_sensor_term(seed, m, op, value, scale):
    rng = np.random.default_rng(seed)
    readings = rng.uniform(-5, 80, (m, 3)).astype(np.float32)
    present, match = rng.uniform(size=(m, 3)) < 0.7, rng.uniform(size=m) < 0.7
    ch = int(rng.integers(3))
    got = K.sensor_term(readings, present, match, jnp.int32(ch), jnp.int32(op), jnp.float32(value), jnp.float32(scale))
    np.testing.assert_allclose(np.asarray(got), ref.sensor(readings, present, match, ch, op, value, scale), atol=1e-5, rtol=1e-4)


def test_location_term():
    pos = np.array([[1.0, 2.0, 0.5], [4.0, 6.0, 0.0]], np.float32)
    got = K.location_term(pos, jnp.array([1.0, 2.0]), jnp.float32(1.0))
    np.testing.assert_allclose(got, [1.0, np.exp(-25 / 2)], atol=1e-6)


@settings(max_examples=30, deadline=None)
@given(seed=seeds, n=sizes, width=st.integers(1, 4))
def test_beam_prune(seed, n, width):
    rng = np.random.default_rng(seed)
    L, C, D = 3, 6, 5
    # A random hierarchy: level-0 clusters over leaves, parents one level up.
    c0 = rng.integers(0, C, n)
    parent0 = rng.integers(0, 4, C)
    parent1 = rng.integers(0, 2, C)
    mask = np.zeros((L, C), bool)
    mask[0, np.unique(c0)] = True
    mask[1, np.unique(parent0[mask[0]])] = True
    mask[2, np.unique(parent1[mask[1]])] = True
    leaf_cluster = np.stack([c0, parent0[c0], parent1[parent0[c0]]], 1).astype(np.int32)
    cluster_parent = np.stack([np.where(mask[0], parent0, -1), np.where(mask[1], parent1, -1), np.full(C, -1)]).astype(np.int32)
    emb = rng.normal(size=(L, C, D)).astype(np.float32)
    q = rng.normal(size=D).astype(np.float32)
    allowed, kept = jax.jit(K.beam_prune, static_argnames="max_beam")(q, emb, mask, cluster_parent, leaf_cluster, jnp.int32(width), max_beam=4)
    ra, rk = ref.beam(q, emb, mask, cluster_parent, leaf_cluster, width)
    np.testing.assert_array_equal(np.asarray(kept), rk)
    np.testing.assert_array_equal(np.asarray(allowed), ra)
    assert np.asarray(allowed).any()  # the beam always keeps at least one populated branch


def test_sigma_eta_grid_vmap_equals_loop():
    rng = np.random.default_rng(0)
    n = 10
    nbr, nm, pos = random_graph(rng, n, 4)
    sem_a, sem_b = tie_free(rng, n), tie_free(rng, n)
    mask = np.ones(n, bool)

    def score(sigma, eta):
        s, _, _ = K.anchor_guided(sem_a, sem_b, pos, nbr, nm, jnp.int32(5), jnp.int32(2), jnp.float32(0.3), sigma, max_k=6)
        b, _ = K.neighbour_boost(jnp.maximum(s, 0), sem_b, nbr, nm, mask, eta, jnp.float32(0.5), jnp.int32(1))
        return b

    sigmas = jnp.array([0.5, 1.0, 2.0, 4.0], jnp.float32)
    etas = jnp.array([0.0, 0.5, 1.0], jnp.float32)
    grid = jax.jit(jax.vmap(jax.vmap(score, (None, 0)), (0, None)))(sigmas, etas)
    for i, s in enumerate(sigmas):
        for j, e in enumerate(etas):
            np.testing.assert_allclose(grid[i, j], score(s, e), atol=1e-6)
