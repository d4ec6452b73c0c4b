"""Order solvers against an itertools reference: exact agreement, padding, jit/vmap, tracing, unreachable goals."""

from __future__ import annotations

import itertools
import math

import jax
import jax.numpy as jnp
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ragnav_jax.planning import (
    INFEASIBLE,
    NONE_REACHABLE,
    OK,
    SOME_UNREACHABLE,
    brute_force,
    held_karp,
    local_search,
    order_problem,
    solve,
)
from ragnav_jax.planning import order as order_mod

JIT = {
    name: jax.jit(f)
    for name, f in [("brute_force", brute_force), ("held_karp", held_karp), ("local_search", local_search)]
}


def reference(start_cost, cost, rank, lam, unary=None):
    """Best objective over all permutations (and candidates) by plain itertools; K = unary.shape[1]."""
    start_cost, cost = np.asarray(start_cost, np.float64), np.asarray(cost, np.float64)
    n = len(rank)
    if n == 0:
        return 0.0
    K = 1 if unary is None else unary.shape[1]
    best = math.inf
    for perm in itertools.permutations(range(n)):
        inv = sum(1 for a in range(n) for b in range(a + 1, n) if rank[perm[a]] > rank[perm[b]])
        pen = lam * inv if inv else 0.0
        for cand in itertools.product(range(K), repeat=n):
            if K == 1:
                travel = start_cost[perm[0]] + sum(cost[perm[t], perm[t + 1]] for t in range(n - 1))
                un = 0.0
            else:
                ch = dict(zip(perm, cand))
                travel = start_cost[perm[0], ch[perm[0]]] + sum(
                    cost[perm[t], ch[perm[t]], perm[t + 1], ch[perm[t + 1]]] for t in range(n - 1)
                )
                un = sum(unary[g, ch[g]] for g in range(n))
            best = min(best, travel + un + pen)
    return best


def random_instance(rng, G, n, N=12, metric=True):
    """A random map cost matrix (N, N), start node 0, n real goals padded to G."""
    if metric:
        pts = rng.uniform(0, 10, (N, 2))
        dist = np.linalg.norm(pts[:, None] - pts[None], axis=-1)
    else:  # asymmetric, no triangle inequality: harder for heuristics, same for exact solvers
        dist = rng.uniform(0.5, 10, (N, N))
        np.fill_diagonal(dist, 0.0)
    targets = np.full(G, -1, np.int32)
    targets[:n] = rng.choice(np.arange(1, N), n, replace=False)
    rank = np.full(G, 0, np.int32)
    rank[:n] = rng.integers(0, max(n, 1), n)  # ties: some pairs unordered
    return dist.astype(np.float32), targets, rank


def _check(result, dist, targets, rank, lam, expect):
    n = int((targets >= 0).sum())
    order = np.asarray(result.order)
    planned = order[order >= 0]
    assert sorted(planned.tolist()) == list(range(n))  # real goals sit first here
    assert np.all(order[len(planned) :] == -1)
    tg = targets[planned]
    # The reported objective is the exact cost of the reported order ...
    travel = (dist[0, tg[0]] + sum(dist[tg[t], tg[t + 1]] for t in range(len(tg) - 1))) if n else 0.0
    inv = sum(1 for a in range(n) for b in range(a + 1, n) if rank[planned[a]] > rank[planned[b]])
    assert int(result.inversions) == inv
    assert float(result.travel) == pytest.approx(travel, rel=1e-5, abs=1e-5)
    assert float(result.objective) == pytest.approx(travel + (lam * inv if inv else 0.0), rel=1e-5, abs=1e-5)
    # ... and that cost is the optimum.
    assert float(result.objective) == pytest.approx(expect, rel=1e-5, abs=1e-4)
    assert int(result.status) == OK
    assert np.array_equal(np.asarray(result.visit_nodes)[: len(tg)], tg)


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    G=st.sampled_from([0, 1, 3, 6]),
    data=st.data(),
    lam=st.sampled_from([0.0, 0.7, 4.0, 1e4]),
    metric=st.booleans(),
    seed=st.integers(0, 2**31 - 1),
)
def test_exact_solvers_match_itertools(G, data, lam, metric, seed):
    n = data.draw(st.integers(0, G))
    rng = np.random.default_rng(seed)
    dist, targets, rank = random_instance(rng, G, n, metric=metric)
    p = order_problem(dist, 0, targets, rank=rank)
    tg = targets[:n]
    expect = reference(dist[0, tg], dist[np.ix_(tg, tg)], rank[:n], lam)
    for name in ("brute_force", "held_karp"):
        _check(JIT[name](p, jnp.float32(lam)), dist, targets, rank, lam, expect)
    ls = JIT["local_search"](p, jnp.float32(lam))
    assert float(ls.objective) >= expect - 1e-4 * (1 + abs(expect))
    assert sorted(np.asarray(ls.order)[:n].tolist()) == list(range(n))


def test_brute_force_and_held_karp_agree_at_eight_goals_batched():
    """Padding inside a batch (2..8 goals in G = 8), vmapped over episodes and three lambdas."""
    rng = np.random.default_rng(1)
    inst = [random_instance(rng, 8, n, N=16, metric=bool(n % 2)) for n in (8, 7, 2, 5, 8, 0)]
    probs = jax.tree.map(lambda *x: jnp.stack(x), *[order_problem(d, 0, t, rank=r) for d, t, r in inst])
    lams = jnp.array([0.0, 2.5, jnp.inf], jnp.float32)
    bf = solve(probs, lams, method="brute_force", batch_size=4)
    hk = solve(probs, lams, method="held_karp")
    assert bf.order.shape == (3, 6, 8)
    np.testing.assert_allclose(np.asarray(bf.objective)[:2], np.asarray(hk.objective)[:2], rtol=1e-5, atol=1e-4)
    for e, (dist, targets, rank) in enumerate(inst):
        n = int((targets >= 0).sum())
        if n <= 6:  # itertools reference only where it is quick
            tg = targets[:n]
            for li, lam in enumerate([0.0, 2.5]):
                expect = reference(dist[0, tg], dist[np.ix_(tg, tg)], rank[:n], lam)
                assert float(hk.objective[li, e]) == pytest.approx(expect, rel=1e-5, abs=1e-4)
    # strict order: no inversions, and the travel of the best inversion-free order
    assert np.all(np.asarray(bf.inversions[2]) == 0) and np.all(np.asarray(hk.inversions[2]) == 0)
    np.testing.assert_allclose(np.asarray(bf.travel[2]), np.asarray(hk.travel[2]), rtol=1e-5)


def test_free_and_strict_limits():
    rng = np.random.default_rng(2)
    dist, targets, _ = random_instance(rng, 5, 5)
    rank = np.arange(5, dtype=np.int32)
    p = order_problem(dist, 0, targets, rank=rank)
    strict = JIT["held_karp"](p, jnp.float32(jnp.inf))
    assert np.array_equal(np.asarray(strict.order), np.arange(5))  # the instruction order itself
    free = JIT["held_karp"](p, jnp.float32(0.0))
    tg = targets
    assert float(free.travel) == pytest.approx(reference(dist[0, tg], dist[np.ix_(tg, tg)], rank, 0.0), rel=1e-5)
    big = JIT["held_karp"](p, jnp.float32(1e5))
    assert int(big.inversions) == 0


def test_joint_candidate_choice_matches_itertools():
    rng = np.random.default_rng(3)
    for n, K in [(3, 2), (4, 3), (1, 3)]:
        G = 4
        pts = rng.uniform(0, 10, (20, 2))
        dist = np.linalg.norm(pts[:, None] - pts[None], axis=-1).astype(np.float32)
        cands = np.full((G, K), -1, np.int32)
        cands[:n] = rng.choice(np.arange(1, 20), (n, K), replace=False)
        cands[0, K - 1] = -1  # goal 0 has one candidate fewer
        unary = rng.uniform(0, 2, (G, K)).astype(np.float32)
        rank = np.arange(G, dtype=np.int32)
        p = order_problem(dist, 0, cands, rank=rank, unary=unary)
        for lam in (0.0, 3.0):
            r = JIT["held_karp"](p, jnp.float32(lam))
            cm = np.asarray(p.cand_mask)
            sc = np.where(cm, np.asarray(p.start_cost), np.inf)[:n]
            cc = np.asarray(p.cost)[:n, :, :n, :]
            un = np.where(cm, unary, np.inf)[:n]
            expect = reference(sc, cc, rank[:n], lam, un)
            assert float(r.objective) == pytest.approx(expect, rel=1e-5, abs=1e-4)
            ch = np.asarray(r.choice)[:n]
            assert np.all(cm[np.arange(n), ch])
            assert np.array_equal(
                np.asarray(r.visit_nodes)[:n], cands[np.asarray(r.order)[:n], ch[np.asarray(r.order)[:n]]]
            )


def test_local_search_beyond_exact_sizes():
    rng = np.random.default_rng(4)
    dist, targets, rank = random_instance(rng, 20, 18, N=30)
    p = order_problem(dist, 0, targets, rank=rank)
    r = JIT["local_search"](p, jnp.float32(1.0))
    order = np.asarray(r.order)
    assert sorted(order[:18].tolist()) == list(range(18)) and np.all(order[18:] == -1)
    assert int(r.status) == OK and np.isfinite(float(r.objective))
    with pytest.raises(ValueError, match="at most 16"):
        held_karp(p, jnp.float32(1.0))
    with pytest.raises(ValueError, match="at most 8"):
        brute_force(p, jnp.float32(1.0))


def test_solvers_trace_once_across_lambdas():
    rng = np.random.default_rng(5)
    inst = [random_instance(rng, 3, n) for n in (3, 1, 2)]
    probs = jax.tree.map(lambda *x: jnp.stack(x), *[order_problem(d, 0, t, rank=r) for d, t, r in inst])
    for method in ("brute_force", "held_karp", "local_search"):
        traces = []
        kernel = order_mod.SOLVERS[method]

        def counted(p, lam, kernel=kernel, traces=traces):
            traces.append(1)
            return kernel(p, lam)

        f = jax.jit(jax.vmap(counted, in_axes=(0, None)))
        for lam in (0.0, 1.5, 30.0, float("inf")):
            jax.block_until_ready(f(probs, jnp.float32(lam)))
        assert len(traces) == 1, method
        if method == "brute_force":
            continue  # the batched entry point is the same for every solver; two suffice
        before = order_mod._solve._cache_size()
        for lams in ([0.0, 1.0], [2.0, 3.0], [5.0, float("inf")]):
            jax.block_until_ready(solve(probs, jnp.array(lams), method=method, batch_size=3))
        assert order_mod._solve._cache_size() - before <= 1, method


def _two_component_map():
    """Nodes 0-4 connected (a path), nodes 5-6 a separate component."""
    N = 7
    dist = np.full((N, N), np.inf, np.float32)
    for comp in ([0, 1, 2, 3, 4], [5, 6]):
        for i in comp:
            for j in comp:
                dist[i, j] = abs(i - j)
    return dist


@pytest.mark.parametrize("method", ["brute_force", "held_karp", "local_search"])
def test_unreachable_goals_are_reported(method):
    dist = _two_component_map()
    f = JIT[method]
    lam = jnp.float32(1.0)
    # some goals unreachable: plan the others, flag these
    r = f(order_problem(dist, 0, np.array([6, 3, 5, 1, -1], np.int32)), lam)
    assert int(r.status) == SOME_UNREACHABLE
    assert np.asarray(r.reachable).tolist() == [False, True, False, True, False]
    assert np.asarray(r.order).tolist() == [3, 1, -1, -1, -1]
    assert float(r.travel) == pytest.approx(3.0) and np.isfinite(float(r.objective))
    # none reachable
    r = f(order_problem(dist, 0, np.array([6, 5, -1], np.int32)), lam)
    assert int(r.status) == NONE_REACHABLE and np.all(np.asarray(r.order) == -1) and float(r.objective) == 0.0
    # the same with a finite sentinel plus a reachability mask, as a memory may store it
    sentinel = np.where(np.isfinite(dist), dist, 1e9).astype(np.float32)
    r2 = f(order_problem(sentinel, 0, np.array([6, 3, 5, 1, -1], np.int32), reachable=np.isfinite(dist)), lam)
    assert int(r2.status) == SOME_UNREACHABLE and float(r2.travel) == pytest.approx(3.0)
    # directed map: both goals reachable from the start but not from each other
    directed = np.array([[0, 1, 1], [np.inf, 0, np.inf], [np.inf, np.inf, 0]], np.float32)
    r = f(order_problem(directed, 0, np.array([1, 2], np.int32)), lam)
    assert int(r.status) == INFEASIBLE and not np.isfinite(float(r.travel))
    assert sorted(np.asarray(r.order).tolist()) == [0, 1]


def test_candidate_unary_keeps_top_candidate_free():
    from ragnav_jax.planning import candidate_unary

    u = candidate_unary(jnp.array([[0.9, 0.5], [0.3, 0.2]]), jnp.float32(10.0), jnp.array([[True, True], [True, False]]))
    np.testing.assert_allclose(np.asarray(u), [[0.0, 4.0], [0.0, 0.0]], atol=1e-5)


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 2**31 - 1), count=st.integers(1, 7))
def test_orders_of_a_batch_is_each_problems_itertools_optimum(seed, count):
    """The host's batched call (one solver call for problems of mixed goal counts and lambdas, episodes padded
    to a power of two) returns, for each problem, an order whose objective is itertools' optimum."""
    rng = np.random.default_rng(seed)
    N = 10
    problems = []
    for _ in range(count):
        pts = rng.uniform(0, 10, (N, 2))
        cost = np.linalg.norm(pts[:, None] - pts[None], axis=-1).astype(np.float32)
        n = int(rng.integers(0, 6))
        nodes = rng.choice(np.arange(1, N), n, replace=False).tolist()
        rank = rng.integers(0, max(n, 1), n).tolist()
        problems.append((cost, int(rng.integers(0, N)), nodes, rank, float(rng.choice([0.0, 2.0, 1e4]))))
    orders = order_mod.orders_of(problems)
    for (cost, start, nodes, rank, lam), order in zip(problems, orders):
        assert sorted(order) == list(range(len(nodes)))
        if not nodes:
            continue
        seq = [nodes[k] for k in order]
        inv = sum(1 for a in range(len(order)) for b in range(a + 1, len(order)) if rank[order[a]] > rank[order[b]])
        got = cost[start, seq[0]] + sum(cost[seq[t], seq[t + 1]] for t in range(len(seq) - 1)) + lam * inv
        idx = [start, *nodes]
        want = reference(cost[start, nodes], cost[np.ix_(nodes, nodes)], rank, lam)
        assert got == pytest.approx(want, rel=1e-5, abs=1e-4), idx
        assert order == order_mod.order_of(cost, start, nodes, rank, lam)  # one problem alone: the same order
