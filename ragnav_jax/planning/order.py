"""Order-aware multi-goal planning: the paper's Pi* objective solved exactly or heuristically.

    Pi* = argmin_pi  c(start, p_pi(1)) + sum_j D(p_pi(j), p_pi(j+1)) + lambda * L(pi, S)

(paper, "Route Planning and Sequential Navigation"), where D is the memory's shortest-path cost and
L(pi, S) counts goal pairs visited in the opposite order to the instruction (Kendall tau distance;
goals of equal rank are unordered). lambda = 0 is free order; strict order is the limit of large
lambda, and lambda = inf gives it exactly (an inversion-free order always exists).

Every solver is a kernel for one episode, `solver(problem, lam) -> OrderResult`, with `lam` a ()
float32 array; `solve` jits one of them and vmaps it over lambdas and episodes. Goals unreachable
from the start are dropped from the plan and reported (`OrderResult.reachable`, `.status`).

- brute_force: every permutation of the padded goal count G (G <= 8), scored by two matmuls.
- held_karp: dynamic programming over goal subsets with the inversion penalty carried exactly
  (appending goal j after visited set S adds |S & goals that should follow j|), G <= 16; with K > 1
  candidates per goal it chooses candidates and order jointly.
- local_search: 2-opt, swap and or-opt moves from the instruction order and a greedy order, any G.
"""

from __future__ import annotations

import functools
import itertools
import math

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.planning.costs import order_problem, precedence, reachable_candidates
from ragnav_jax.planning.types import (
    INFEASIBLE,
    NONE_REACHABLE,
    OK,
    SOME_UNREACHABLE,
    Array,
    OrderProblem,
    OrderResult,
)

MAX_BRUTE_FORCE_GOALS = 8
MAX_HELD_KARP_GOALS = 16
_BIG = 1.0e9  # finite stand-in for inf inside matmuls (0 * inf would be nan); never reported
_HIGHEST = jax.lax.Precision.HIGHEST


# ----------------------------------------------------------------------------------------------------
# Shared pieces


def penalty(inversions: Array, lam: Array) -> Array:
    """lambda * inversions, with 0 * inf = 0 so that lambda = inf means strict order."""
    return jnp.where(inversions > 0, lam * inversions, 0.0)


def count_inversions(order: Array, n: Array, after: Array) -> Array:
    """Goal pairs visited against the instruction. order: (G,) full permutation, first n planned."""
    G = order.shape[0]
    pos = jnp.zeros((G,), jnp.int32).at[order].set(jnp.arange(G, dtype=jnp.int32))
    live = pos < n
    bad = after & (pos[None, :] < pos[:, None]) & live[:, None] & live[None, :]
    return jnp.sum(bad, dtype=jnp.int32)


def _travel(order: Array, n: Array, start_cost: Array, cost: Array) -> Array:
    """Travel cost of the first n goals of `order` (G,) with per-goal costs (G,), (G, G)."""
    G = order.shape[0]
    first = jnp.where(n > 0, start_cost[order[0]], 0.0)
    legs = cost[order[:-1], order[1:]]
    live = jnp.arange(1, G) < n
    return first + jnp.sum(jnp.where(live, legs, 0.0))


def _chosen_costs(problem: OrderProblem, choice: Array) -> tuple[Array, Array, Array]:
    """Per-goal start costs (G,), pair costs (G, G) and unary costs (G,) of chosen candidates."""
    G = choice.shape[0]
    c = jnp.clip(choice, 0, problem.cand_mask.shape[1] - 1)
    g = jnp.arange(G)
    start = problem.start_cost[g, c]
    pair = problem.cost[g[:, None], c[:, None], g[None, :], c[None, :]]
    return start, pair, problem.unary[g, c]


def _actives_first(active: Array, key: Array) -> Array:
    """(G,) permutation: active goals sorted by `key` (stable), then the inactive ones."""
    big = jnp.iinfo(jnp.int32).max
    return jnp.argsort(jnp.where(active, key, big), stable=True).astype(jnp.int32)


def _finish(problem: OrderProblem, order: Array, choice: Array, active: Array, lam: Array) -> OrderResult:
    """Scores a full permutation `order` (active goals first) exactly and sets the status."""
    G = order.shape[0]
    n = jnp.sum(active, dtype=jnp.int32)
    start, pair, unary = _chosen_costs(problem, choice)
    after = precedence(problem.rank, active)
    travel = _travel(order, n, start, pair)
    inv = count_inversions(order, n, after)
    objective = travel + jnp.sum(jnp.where(active, unary, 0.0)) + penalty(inv, lam)
    live = jnp.arange(G) < n
    node = problem.nodes[order, jnp.clip(choice[order], 0, None)]
    n_goals = jnp.sum(problem.mask, dtype=jnp.int32)
    status = jnp.where(n < n_goals, jnp.where(n == 0, NONE_REACHABLE, SOME_UNREACHABLE), OK)
    status = jnp.where(jnp.isfinite(travel), status, INFEASIBLE).astype(jnp.int32)
    return OrderResult(
        order=jnp.where(live, order, -1).astype(jnp.int32),
        choice=jnp.where(active, choice, -1).astype(jnp.int32),
        visit_nodes=jnp.where(live, node, -1).astype(jnp.int32),
        travel=travel.astype(jnp.float32),
        inversions=inv,
        objective=objective.astype(jnp.float32),
        reachable=active,
        status=status,
    )


def _empty_result(problem: OrderProblem) -> OrderResult:
    f = jnp.zeros((), jnp.float32)
    e = jnp.zeros((0,), jnp.int32)
    return OrderResult(e, e, e, f, jnp.zeros((), jnp.int32), f, jnp.zeros((0,), bool), jnp.zeros((), jnp.int32))


def _single_candidate(problem: OrderProblem, solver: str) -> None:
    if problem.cand_mask.shape[1] != 1:
        raise ValueError(f"{solver} takes one candidate per goal (K = 1); use held_karp for joint choice")


# ----------------------------------------------------------------------------------------------------
# Brute force


@functools.cache
def _perm_tables(G: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """All permutations of G goals (P, G) and their matmul features.

    travel features (P, G*G + G): 1 where goal j directly follows goal i, then one-hot first goal;
    order features (P, G*G): 1 where goal j is visited before goal i (pair i, j in that order).
    """
    perms = np.array(list(itertools.permutations(range(G))), np.int32).reshape(-1, G)
    P = perms.shape[0]
    follow = np.zeros((P, G * G), np.float32)
    rows = np.repeat(np.arange(P), max(G - 1, 0))
    follow[rows, (perms[:, :-1] * G + perms[:, 1:]).ravel()] = 1.0
    first = np.zeros((P, G), np.float32)
    first[np.arange(P), perms[:, 0]] = 1.0
    pos = np.argsort(perms, axis=1)
    before = (pos[:, None, :] < pos[:, :, None]).reshape(P, G * G).astype(np.float32)
    return perms, np.concatenate([follow, first], axis=1), before


def brute_force(problem: OrderProblem, lam: Array) -> OrderResult:
    """Exact order by scoring all G! permutations of the padded goal count (G <= 8, K = 1).

    Inactive goals (padding, unreachable) are pushed to the end of every scored permutation by
    charging a sentinel for leaving them, so one kernel serves every goal count up to G.
    """
    G = problem.mask.shape[0]
    _single_candidate(problem, "brute_force")
    if G > MAX_BRUTE_FORCE_GOALS:
        raise ValueError(f"brute_force handles at most {MAX_BRUTE_FORCE_GOALS} goals, got G = {G}")
    if G == 0:
        return _empty_result(problem)
    _, active = reachable_candidates(problem)
    start, cost = problem.start_cost[:, 0], problem.cost[:, 0, :, 0]
    pad = ~active
    cost = jnp.where(jnp.isfinite(cost), cost, _BIG)
    cost = jnp.where(pad[None, :], 0.0, jnp.where(pad[:, None], _BIG, cost))
    start = jnp.where(pad, 0.0, jnp.where(jnp.isfinite(start), start, _BIG))
    after = precedence(problem.rank, active)
    perms, travel_feat, before_feat = (jnp.asarray(t) for t in _perm_tables(G))
    # The barrier keeps XLA from fusing these small producers into the big matmuls (measured slower).
    vec, pairs = jax.lax.optimization_barrier(
        (jnp.concatenate([cost.ravel(), start]), after.ravel().astype(jnp.float32))
    )
    travel = jnp.dot(travel_feat, vec, precision=_HIGHEST)
    inv = jnp.dot(before_feat, pairs, precision=_HIGHEST)
    best = jnp.argmin(travel + penalty(inv, lam))
    return _finish(problem, perms[best], jnp.zeros((G,), jnp.int32), active, lam)


# ----------------------------------------------------------------------------------------------------
# Held-Karp


@functools.cache
def _subset_layers(G: int) -> tuple[np.ndarray, ...]:
    """Subsets of G goals as bitmasks, grouped by size: layers[k] (C(G, k),) int32."""
    masks = np.arange(1 << G, dtype=np.int64)
    sizes = np.array([bin(m).count("1") for m in range(1 << G)])
    return tuple(masks[sizes == k].astype(np.int32) for k in range(G + 1))


def held_karp(problem: OrderProblem, lam: Array) -> OrderResult:
    """Exact order (and candidate choice when K > 1) by dynamic programming over goal subsets.

    dp[S, j, c] is the cheapest way to visit goal set S ending at candidate c of goal j:
      dp[S, j, c] = min_{i, c'} dp[S - j, i, c'] + D(c'_i, c_j) + unary(j, c) + lambda * |(S - j) & after(j)|
    which carries the inversion penalty exactly. Subset layers of equal size are processed together
    (a static loop of G steps, each a batched gather-min), G <= 16; O(2^G G^2 K^2) work.
    """
    G, K = problem.cand_mask.shape
    if G > MAX_HELD_KARP_GOALS:
        raise ValueError(f"held_karp handles at most {MAX_HELD_KARP_GOALS} goals, got G = {G}")
    if G == 0:
        return _empty_result(problem)
    cand_ok, active = reachable_candidates(problem)
    after = precedence(problem.rank, active)
    M = 1 << G
    goal_bit = 1 << np.arange(G, dtype=np.int32)
    bits = (jnp.arange(M, dtype=jnp.int32)[:, None] & jnp.asarray(goal_bit)[None, :]) > 0  # (M, G)
    # pen[T, j]: goals in T that the instruction puts after j.
    pen = jnp.dot(bits.astype(jnp.float32), after.T.astype(jnp.float32), precision=_HIGHEST)
    lam_pen = penalty(pen, lam)  # (M, G)
    unary = jnp.where(cand_ok, problem.unary, jnp.inf)  # (G, K)
    start = jnp.where(cand_ok, problem.start_cost, jnp.inf)
    arrive = jnp.transpose(problem.cost, (2, 3, 0, 1)).reshape(G, K, G * K)  # [j, c, (i, c')]

    dp = jnp.full((M, G, K), jnp.inf, jnp.float32)
    dp = dp.at[goal_bit, np.arange(G)].set(start + unary)
    layers = _subset_layers(G)
    for k in range(2, G + 1):  # static: one batched step per subset size
        rows = layers[k]
        prev = rows[:, None] ^ goal_bit[None, :]  # (Mk, G): S - j (garbage where j not in S)
        in_row = (rows[:, None] & goal_bit[None, :]) > 0
        cand = dp[prev].reshape(len(rows), G, 1, G * K) + arrive[None]  # (Mk, Gj, Kc, G*K)
        val = jnp.min(cand, axis=-1) + lam_pen[prev, np.arange(G)[None, :]][..., None] + unary[None]
        dp = dp.at[rows].set(jnp.where(in_row[:, :, None], val, jnp.inf))

    n = jnp.sum(active, dtype=jnp.int32)
    full = jnp.sum(jnp.where(active, goal_bit, 0))
    last = dp[full].ravel()
    best = jnp.argmin(last)
    feasible = jnp.isfinite(last[best])
    fallback = _actives_first(active, problem.rank)

    def back(t, carry):
        S, j, c, order, choice = carry
        pos = n - 1 - t
        live = pos >= 0
        at = jnp.maximum(pos, 0)
        order = order.at[at].set(jnp.where(live, j, order[at]))
        choice = choice.at[j].set(jnp.where(live, c, choice[j]))
        # Recompute the argmin of this one step instead of storing parents (min is cheaper than argmin).
        par = jnp.argmin(dp[S ^ (1 << j)].ravel() + arrive[j, c])
        nxt = (S ^ (1 << j), par // K, par % K)
        S, j, c = (jnp.where(live, a, b) for a, b in zip(nxt, (S, j, c)))
        return S, j, c, order, choice

    init = (full, (best // K).astype(jnp.int32), (best % K).astype(jnp.int32), fallback, jnp.zeros((G,), jnp.int32))
    _, _, _, order, choice = jax.lax.fori_loop(0, G, back, init)
    first_ok = jnp.argmax(cand_ok, axis=1).astype(jnp.int32)
    order = jnp.where(feasible, order, fallback)
    choice = jnp.where(feasible, choice, first_ok)
    return _finish(problem, order, choice, active, lam)


# ----------------------------------------------------------------------------------------------------
# Local search


@functools.cache
def _move_tables(G: int, max_segment: int = 3) -> tuple[np.ndarray, np.ndarray]:
    """Neighbourhood of an order as position permutations: new = order[sigma].

    Returns sigma (M, G) int32 and reach (M,) int32, the last position a move touches (a move is
    allowed when reach < number of planned goals, so padding stays at the end). Moves: 2-opt
    (reverse a segment), swap two goals, or-opt (move a segment of 1..max_segment goals elsewhere).
    """
    ident = list(range(G))
    moves = {}
    for i in range(G):
        for j in range(i + 1, G):
            rev = ident[:i] + ident[i : j + 1][::-1] + ident[j + 1 :]
            moves.setdefault(tuple(rev), j)
            sw = list(ident)
            sw[i], sw[j] = sw[j], sw[i]
            moves.setdefault(tuple(sw), j)
    for length in range(1, max_segment + 1):
        for i in range(G - length + 1):
            seg, rest = ident[i : i + length], ident[:i] + ident[i + length :]
            for q in range(len(rest) + 1):
                new = rest[:q] + seg + rest[q:]
                if new != ident:
                    moves.setdefault(tuple(new), max(i + length - 1, q + length - 1))
    if not moves:
        return np.zeros((0, G), np.int32), np.zeros((0,), np.int32)
    sigma = np.array(list(moves.keys()), np.int32).reshape(-1, G)
    return sigma, np.array(list(moves.values()), np.int32)


def greedy_order(problem: OrderProblem, lam: Array) -> Array:
    """(G,) full permutation: repeatedly the goal with the cheapest leg plus penalty increment (K = 1)."""
    G = problem.mask.shape[0]
    _, active = reachable_candidates(problem)
    after = precedence(problem.rank, active)
    start, cost = problem.start_cost[:, 0], problem.cost[:, 0, :, 0]

    def step(t, carry):
        visited, last, order = carry
        leg = jnp.where(t == 0, start, cost[jnp.maximum(last, 0)])
        inc = jnp.sum(after & visited[None, :], axis=1)  # visited goals that should follow j
        score = jnp.nan_to_num(leg, posinf=_BIG) + penalty(inc, lam)
        open_active = active & ~visited
        score = jnp.where(open_active, score, jnp.inf)
        pick = jnp.where(jnp.any(open_active), jnp.argmin(score), jnp.argmin(visited)).astype(jnp.int32)
        return visited.at[pick].set(True), pick, order.at[t].set(pick)

    init = (jnp.zeros((G,), bool), jnp.int32(-1), jnp.zeros((G,), jnp.int32))
    return jax.lax.fori_loop(0, G, step, init)[2]


def local_search(problem: OrderProblem, lam: Array, max_iters: int = 100) -> OrderResult:
    """Best-improvement local search (2-opt, swap, or-opt) from the instruction and greedy orders (K = 1).

    Stops at a local optimum or after `max_iters` moves per start; any G. Each iteration scores the
    whole neighbourhood as one batch (O(M G^2), M ~ 3 G^2 moves).
    """
    G = problem.mask.shape[0]
    _single_candidate(problem, "local_search")
    if G == 0:
        return _empty_result(problem)
    _, active = reachable_candidates(problem)
    after = precedence(problem.rank, active)
    n = jnp.sum(active, dtype=jnp.int32)
    start, cost = problem.start_cost[:, 0], problem.cost[:, 0, :, 0]
    sigma, reach = _move_tables(G)
    sigma, allowed = jnp.asarray(sigma), jnp.asarray(reach) < n

    def objective(order):
        return _travel(order, n, start, cost) + penalty(count_inversions(order, n, after), lam)

    def descend(order):
        def cond(s):
            it, _, _, improved = s
            return improved & (it < max_iters)

        def body(s):
            it, order, val, _ = s
            cands = order[sigma]
            vals = jnp.where(allowed, jax.vmap(objective)(cands), jnp.inf)
            b = jnp.argmin(vals)
            better = vals[b] < val
            return it + 1, jnp.where(better, cands[b], order), jnp.where(better, vals[b], val), better

        if sigma.shape[0] == 0:
            return order, objective(order)
        _, order, val, _ = jax.lax.while_loop(cond, body, (jnp.int32(0), order, objective(order), jnp.bool_(True)))
        return order, val

    inits = jnp.stack([_actives_first(active, problem.rank), greedy_order(problem, lam)])
    orders, vals = jax.vmap(descend)(inits)
    order = orders[jnp.argmin(vals)]
    return _finish(problem, order, jnp.zeros((G,), jnp.int32), active, lam)


# ----------------------------------------------------------------------------------------------------
# Batched entry point

SOLVERS = {"brute_force": brute_force, "held_karp": held_karp, "local_search": local_search}


def pick_solver(num_goals: int, candidates: int = 1) -> str:
    """The default solver for a padded goal count: exact Held-Karp up to 16 goals, else local search."""
    if num_goals <= MAX_HELD_KARP_GOALS or candidates > 1:
        return "held_karp"
    return "local_search"


def _episode_bytes(method: str, G: int, K: int) -> int:
    """Rough peak memory of one episode's kernel, to size the vmapped chunks."""
    if method == "brute_force":
        return 4 * math.factorial(G) * 4
    if method == "held_karp":
        widest = math.comb(G, G // 2) if G else 1
        return 4 * (widest * G * K * G * K * 3 + (1 << G) * G * K * 2)
    return 4 * (3 * G * G) * G * G * 4


@functools.partial(jax.jit, static_argnames=("method", "batch_size", "max_iters"))
def _solve(problems: OrderProblem, lams: Array, method: str, batch_size: int, max_iters: int) -> OrderResult:
    kernel = SOLVERS[method]
    if method == "local_search":
        kernel = functools.partial(kernel, max_iters=max_iters)

    def over_episodes(lam):
        return jax.lax.map(lambda p: kernel(p, lam), problems, batch_size=batch_size)

    return jax.vmap(over_episodes)(lams)


def solve(
    problems: OrderProblem,
    lams: Array,
    method: str = "auto",
    batch_size: int | None = None,
    max_iters: int = 100,
    memory_budget: int = 1 << 28,
) -> OrderResult:
    """Solves a batch of episodes for every lambda in one jitted call.

    Args:
      problems: OrderProblem with a leading episode axis E (stack with `jax.tree.map(jnp.stack, ...)`).
      lams: (L,) order-penalty weights (0 = free order, inf = strict), an array so one compilation
        serves every value.
      method: "brute_force", "held_karp", "local_search" or "auto" (pick_solver).
      batch_size: episodes vmapped at once inside the call (default: sized from `memory_budget` bytes).
    Returns OrderResult with leading axes (L, E).
    """
    E, G, K = problems.cand_mask.shape
    if method == "auto":
        method = pick_solver(G, K)
    if method not in SOLVERS:
        raise ValueError(f"unknown solver '{method}' (known: auto, {', '.join(SOLVERS)})")
    lams = jnp.asarray(lams, jnp.float32).reshape(-1)
    if batch_size is None:
        per = max(1, _episode_bytes(method, G, K) * lams.shape[0])
        batch_size = int(max(1, min(E, memory_budget // per)))
    return _solve(problems, lams, method=method, batch_size=min(batch_size, max(E, 1)), max_iters=max_iters)


_problems = jax.jit(jax.vmap(lambda d, s, t, r: order_problem(d, s, t, rank=r)))  # (E, ...) host problems, one call

PAD_GOALS = 8  # goals of one host-side problem are padded to this, so one compilation serves every episode


def order_of(cost: np.ndarray, start: int, nodes: list[int], rank: list[int], lam: float, method: str = "auto",
             max_iters: int = 100) -> list[int]:
    """Pi* for one episode from the host (`orders_of` of one problem): indices into `nodes` in visiting order,
    goals unreachable from the start after the planned ones (in their given order).

    cost: (N, N) shortest-path costs (inf where no path); start: the robot's node; nodes: each goal's target
    node; rank: each goal's place in the instruction (equal ranks are unordered); lam: the order penalty."""
    return orders_of([(cost, start, nodes, rank, lam)], method, max_iters)[0]


def orders_of(problems: list[tuple], method: str = "auto", max_iters: int = 100) -> list[list[int]]:
    """Pi* for many episodes from the host in one solver call: `order_of` of each (cost, start, nodes, rank, lam).

    Each problem is cut to the (G + 1) nodes it needs and padded to PAD_GOALS goals, the episodes to a power of
    two (jit-stable shapes: a handful of compilations for a whole evaluation); every distinct lam is solved for
    every episode and each episode reads its own."""
    out = [list(range(len(p[2]))) for p in problems]
    todo = [i for i, p in enumerate(problems) if len(p[2]) > 1]
    if not todo:
        return out
    P = max(PAD_GOALS, max(len(problems[i][2]) for i in todo))
    E = 1 << (len(todo) - 1).bit_length()
    sub = np.full((E, P + 1, P + 1), np.inf, np.float32)
    targets = np.full((E, P), -1, np.int32)
    ranks = np.zeros((E, P), np.int32)
    lam = np.zeros(E, np.float32)
    for k, i in enumerate(todo):
        cost, start, nodes, rank, lam[k] = problems[i]
        G, idx = len(nodes), [start, *nodes]
        sub[k, : G + 1, : G + 1] = np.asarray(cost, np.float32)[np.ix_(idx, idx)]
        targets[k, :G] = np.arange(1, G + 1)
        ranks[k, :G] = rank
    sub[len(todo) :], targets[len(todo) :] = sub[0], targets[0]  # padding: copies of the first, never read
    lams, which = np.unique(lam, return_inverse=True)
    problem = _problems(sub, np.zeros(E, np.int32), targets, ranks)
    order = np.asarray(solve(problem, lams, method=method, max_iters=max_iters).order)[which.reshape(-1), np.arange(E)]
    for k, i in enumerate(todo):
        G = len(problems[i][2])
        planned = [int(x) for x in order[k] if 0 <= x < G]
        out[i] = planned + [x for x in range(G) if x not in planned]
    return out
