"""One episode's reflection and planning on the device: `next_leg` before a leg, `after_leg` after it.

Both are kernels for one episode (vmap from outside, `program.py`); every transition of the host loop
(`evaluation/host_loop.py: Loop`) is an array operation here: the visiting order is re-solved with
`planning/order.py`'s solvers, paths come from the memory's predecessor matrix, a goal's candidates,
rejections, skipped objects and fallback live in padded arrays. In this module `st`, `inp` are one
episode's `State` / `Inputs` (leading axis removed) and `w` the whole `World` (indexed by the episode's
scene `inp.b` at each use, so no per-episode copy of a scene's arrays is made).
"""

from __future__ import annotations

import jax
import jax.numpy as jnp

from ragnav_jax.evaluation.clearance import CLOSER_GAP_M, SAME_INSTANCE_M
from ragnav_jax.evaluation.loop import geometry as geo
from ragnav_jax.evaluation.loop.state import APPROACH, CLOSER, FAILED, FOUND, NAV, NONE, SEARCH, WRONG, Flags
from ragnav_jax.planning.costs import order_problem
from ragnav_jax.planning.order import SOLVERS, pick_solver

ROUTE_POINTS = 16  # waypoints a grid route keeps
_INF = jnp.inf


def _obs(w, b) -> dict:
    return {k: v[b] for k, v in w.obstacles.items()}


def box_distance(c, half, xy):
    """Planar metres from xy (2,) to footprints (..., 2) centred c with half sizes `half` (0 inside)."""
    d = jnp.maximum(jnp.abs(jnp.broadcast_to(xy, c.shape) - c) - half, 0.0)
    return jnp.linalg.norm(d, axis=-1)


# ----------------------------------------------------------------------------------------------------
# The remaining goals (an ordered list in a padded array)


def _remove(st, g):
    """Drops goal g from the remaining order."""
    G = st.order.shape[0]
    i = jnp.arange(G)
    at = jnp.argmax((st.order == g) & (i < st.n_left))
    hit = jnp.any((st.order == g) & (i < st.n_left))
    shifted = jnp.where(i >= at, st.order[jnp.minimum(i + 1, G - 1)], st.order)
    return st.replace(order=jnp.where(hit, shifted, st.order), n_left=st.n_left - hit.astype(jnp.int32))


def _left_mask(st):
    G = st.order.shape[0]
    live = jnp.arange(G) < st.n_left
    return jnp.any((st.order[None, :] == jnp.arange(G)[:, None]) & live[None, :], axis=1)


def current(st, inp, g, fl: Flags):
    """The goal's current candidate key pose, or -1 (retries spent or candidates run out)."""
    C = inp.cands.shape[1]
    c = inp.cands[g, jnp.minimum(st.cptr[g], C - 1)]
    ok = (st.rejected[g] <= fl.retries) & (st.cptr[g] < C) & (c >= 0)
    return jnp.where(ok, c, -1)


def estimate(st, inp, g):
    """((2,) estimated position of the current candidate's instance, whether there is one)."""
    C = inp.cands.shape[1]
    j = jnp.minimum(st.cptr[g], C - 1)
    return inp.est[g, j], inp.has_est[g, j] & (st.cptr[g] < C)


def order_cost(w, inp, i, j):
    """Order-planning cost between key poses (map paths, or straight lines for methods without the map)."""
    return jnp.where(inp.straight, w.euclid[inp.b, i, j], w.path_cost[inp.b, i, j])


def search_next(st, inp, w, g, fl: Flags):
    """The nearest key pose still to search for goal g (by the order cost from the robot's node), or -1."""
    nodes = inp.search[g]
    left = (nodes >= 0) & ~st.looked[g, jnp.maximum(nodes, 0)]
    cost = jnp.where(left, order_cost(w, inp, st.node, jnp.maximum(nodes, 0)), _INF)
    k = jnp.argmin(cost)
    return jnp.where(inp.searches & left.any(), nodes[k], -1)


def order_inputs(st, inp, w, lam, fl: Flags):
    """The re-plan's order problem: the goals left that have a candidate ("live"), by index, as the solver's
    targets 1..n_live after the robot's node 0, with their instruction ranks (strict) and lambda."""
    G = st.order.shape[0]
    ids = jnp.arange(G, dtype=jnp.int32)
    left = _left_mask(st)
    cur = jax.vmap(lambda g: current(st, inp, g, fl))(ids)
    live = left & (cur >= 0)
    n_live = live.sum().astype(jnp.int32)
    lidx = jnp.argsort(jnp.where(live, ids, G + ids)).astype(jnp.int32)  # live goals first, by index
    P = max(G, 2)  # the batch's goal count (the host pads to PAD_GOALS; exact solvers give the same order)
    slot = jnp.arange(P)
    goal_of = jnp.where(slot < n_live, lidx[jnp.minimum(slot, G - 1)], 0)
    nodes = jnp.concatenate([st.node[None], jnp.where(slot < n_live, cur[goal_of], 0)])
    valid = jnp.concatenate([jnp.ones(1, bool), slot < n_live])
    sub = order_cost(w, inp, nodes[:, None], nodes[None, :])
    sub = jnp.where(valid[:, None] & valid[None, :], sub, _INF).astype(jnp.float32)
    targets = jnp.where(slot < n_live, slot + 1, -1).astype(jnp.int32)
    ranks = jnp.where((slot < n_live) & inp.strict, goal_of, 0).astype(jnp.int32)
    return dict(left=left, live=live, n_live=n_live, goal_of=goal_of, sub=sub, targets=targets, ranks=ranks,
                lam=jnp.where(inp.strict, lam, 0.0))


def solve_order(q, fl: Flags):
    """The order planner (`planning.order`, `planning.solver`) on `order_inputs`: (P,) slots in visiting order."""
    P = q["goal_of"].shape[0]
    method = pick_solver(P) if fl.solver == "auto" else fl.solver
    kw = {"max_iters": fl.search_iters} if method == "local_search" else {}
    return SOLVERS[method](order_problem(q["sub"], jnp.int32(0), q["targets"], rank=q["ranks"]), q["lam"], **kw).order


def visit_sequence(q, k, strict):
    """(G,) goals in visiting order from the solved slots k, then the goals left without a candidate at their
    instruction place (free: at the end); and the count of goals in it."""
    G, P = q["left"].shape[0], q["goal_of"].shape[0]
    ids, slot = jnp.arange(G, dtype=jnp.int32), jnp.arange(P)
    n_live, goal_of, left, live = q["n_live"], q["goal_of"], q["left"], q["live"]
    # pos[s]: where slot s is visited (3P: not in k). A comparison, not a scatter: XLA's GPU scatter with
    # out-of-range (dropped) indices under vmap put goal 0 at the wrong place (H100, JAX 0.11.2).
    hit = (k[None, :] == slot[:, None]) & (k[None, :] < n_live)
    pos = jnp.min(jnp.where(hit, slot[None, :], 3 * P), axis=1).astype(jnp.int32)
    key = jnp.where(slot < n_live, jnp.where(pos < 3 * P, pos, P + slot), 3 * P + slot)
    key = jnp.where(n_live <= 1, slot, key)  # one goal: nothing to solve (host_loop.plan_order)
    seq = goal_of[jnp.argsort(key)][:G]
    seq = jnp.where(ids < n_live, seq, 0)

    def insert(d, carry):  # goals with no candidate left keep their instruction place
        seq, m = carry
        dead = left[d] & ~live[d]
        before = (ids < m) & (seq < d)
        at = jnp.where(strict, jnp.max(jnp.where(before, ids + 1, 0)), m)
        new = jnp.where(ids < at, seq, jnp.where(ids == at, d, seq[jnp.maximum(ids - 1, 0)]))
        return jnp.where(dead, new, seq), m + dead.astype(jnp.int32)

    return jax.lax.fori_loop(0, G, insert, (seq.astype(jnp.int32), n_live))


def replan(st, inp, w, lam, fl: Flags):
    """Re-solves the order of the remaining goals from the robot's node with their current candidates
    (`host_loop.Loop.replan`): the order planner over the goals that have one (strict instructions with the
    order penalty `lam`), then each goal without one at its instruction place (free: at the end)."""
    q = order_inputs(st, inp, w, lam, fl)
    seq, m = visit_sequence(q, solve_order(q, fl), inp.strict)
    ids = jnp.arange(seq.shape[0], dtype=jnp.int32)
    written = jnp.argsort(jnp.where(q["left"], ids, seq.shape[0] + ids)).astype(jnp.int32)  # the instruction's order
    return st.replace(order=jnp.where(inp.optimal_order, seq, written), n_left=jnp.where(inp.optimal_order, m, st.n_left))


def reject(st, inp, w, g, why: int, lam, fl: Flags):
    """The current candidate of goal g failed: take the next one and give the goal up when nothing is left
    to try. The caller re-plans (`_replanned`: once per step, so the solver is traced once)."""
    st = st.replace(cptr=st.cptr.at[g].add(1), rejected=st.rejected.at[g].add(1))
    out = (current(st, inp, g, fl) < 0) & (search_next(st, inp, w, g, fl) < 0) & (st.backup[g] < 0)
    return jax.lax.cond(out, lambda s: _remove(s.replace(status=s.status.at[g].set(why)), g), lambda s: s, st)


def _replanned(before, st, inp, w, lam, fl: Flags):
    """st re-planned where a candidate was rejected since `before`."""
    return jax.lax.cond(jnp.sum(st.rejected) > jnp.sum(before.rejected), lambda s: replan(s, inp, w, lam, fl),
                        lambda s: s, st)


# ----------------------------------------------------------------------------------------------------
# Before a leg


def approach_stop(st, inp, w, o, pose, fl: Flags):
    """(2,) where to stop by object o (`host_loop.Loop.approach_points`)."""
    b = inp.b
    return geo.approach_stop(w.obj_center[b, o], w.obj_half[b, o], pose[:2], fl.approach_gap + fl.robot_radius,
                             fl.need, _obs(w, b), w.grid_origin[b], w.grid_clear[b], w.grid_labels[b], fl.tight,
                             shape=w.grid_shape[b])


def next_leg(st, inp, w, pose, lam, fl: Flags):
    """Decides the episode's next leg (`host_loop.Loop.next_leg`): sets leg_kind / leg_goal / leg_target, or
    done. Goals that cannot be tried are given up on the way, as on the host."""

    def cond(c):
        st, resolved = c
        return ~resolved & ~st.done

    def body(c):
        st, _ = c
        pending = (st.leg_kind == APPROACH) | (st.leg_kind == CLOSER)  # issued by the reflection

        def empty(st):
            return st.replace(done=True, reason=jnp.where(st.reason == 0, 1, st.reason)), True

        def head(st):
            g = st.order[0]

            def parse_fail(st):
                return _remove(st.replace(status=st.status.at[g].set(FAILED["parse"])), g), False

            def choose(st):
                node = current(st, inp, g, fl)
                snode = search_next(st, inp, w, g, fl)
                kind = jnp.where(node >= 0, NAV, jnp.where(snode >= 0, SEARCH, NONE))
                node = jnp.where(node >= 0, node, snode)
                fall = (node < 0) & (st.backup[g] >= 0)

                def fallback(st):
                    o = st.backup[g]
                    st = st.replace(backup=st.backup.at[g].set(-1), fell_back=st.fell_back.at[g].set(True))
                    st = st.replace(leg_kind=jnp.int32(APPROACH), leg_goal=g, leg_target=o)
                    return st, True

                def give_up(st):
                    why = jnp.where(st.looked[g].any(), FAILED["searched"], FAILED["no_candidate"])
                    return _remove(st.replace(status=st.status.at[g].set(why)), g), False

                def go(st):
                    ok = inp.straight | (node == st.node) | (w.drive_pred[inp.b, st.node, node] >= 0)

                    def leg(st):
                        return st.replace(leg_kind=kind.astype(jnp.int32), leg_goal=g, leg_target=node), True

                    def unreachable(st):
                        st = jax.lax.cond(kind == SEARCH, lambda s: s.replace(looked=s.looked.at[g, node].set(True)),
                                          lambda s: reject(s, inp, w, g, FAILED["unreachable"], lam, fl), st)
                        return st, False

                    return jax.lax.cond(ok, leg, unreachable, st)

                return jax.lax.switch(jnp.where(node >= 0, 2, jnp.where(fall, 0, 1)), [fallback, give_up, go], st)

            return jax.lax.cond(inp.reads & inp.parse_failed, parse_fail, choose, st)

        before = st
        st, resolved = jax.lax.cond(pending, lambda s: (s, True),
                                    lambda s: jax.lax.cond(s.n_left == 0, empty, head, s), st)
        return _replanned(before, st, inp, w, lam, fl), jnp.asarray(resolved)

    st, _ = jax.lax.while_loop(cond, body, (st, jnp.asarray(False)))
    return st


def _splice(pts, n, is_node, nodes, ends, w, b):
    """`_joined` with the World's local plan of each map edge between two key poses (is_node (L,) bool, nodes
    (L,) int32) and ends = (plans (2, K, 2), counts (2,), use (2,) bool): plans of the first and the last
    segment, used where `use`."""
    L = pts.shape[0]
    edge = is_node[:-1] & is_node[1:]
    pid = jnp.where(edge, w.plan_idx[b, jnp.maximum(nodes[:-1], 0), jnp.maximum(nodes[1:], 0)], -1)
    seg = jnp.arange(L - 1)
    end_plans, end_cnt, end_use = ends
    which = jnp.where((seg == 0) & end_use[0], 0, jnp.where((seg == n - 2) & end_use[1], 1, -1))
    plans = jnp.where((which >= 0)[:, None, None], end_plans[jnp.maximum(which, 0)], w.plans[b, jnp.maximum(pid, 0)])
    cnt = jnp.where(which >= 0, end_cnt[jnp.maximum(which, 0)], w.plan_count[b, jnp.maximum(pid, 0)])
    return geo.join_plans(pts, n, plans, cnt, (which >= 0) | (pid >= 0))


def _local(w, b, a, c, fl: Flags, anywhere: bool, go=True):
    """`geometry.local_route` on the episode's scene: ((ROUTE_POINTS, 2) points, count); the straight segment
    where `go` is False. A segment's route is searched in the LOCAL_WINDOW-cell block round it; with `anywhere`
    (approaches), where that finds none, again in a block as large as the padded grid, whose whole-block tiers
    are the host's whole house."""
    route = lambda window, anywhere, go: geo.local_route(  # noqa: E731
        a, c, _obs(w, b), w.grid_origin[b], w.grid_clear[b], w.grid_shape[b], fl.need, fl.tight, anywhere,
        window=window, max_points=ROUTE_POINTS, go=go)
    p, n = route(geo.LOCAL_WINDOW, False, go)
    if not anywhere:
        return p, n
    q, m = route(-(-max(w.grid_clear.shape[1:]) // 32) * 32, True, go & (n <= 2))
    return jnp.where(n <= 2, q, p), jnp.where(n <= 2, m, n)


def _drive_points(pts, n, is_node, nodes, raw, w, b, fl: Flags):
    """`host_loop.Loop.drive_points`: local plans where segments pass too close, then densified. Map edges take
    the plans made on the host before the loop; the first and last segment of a leg (which may end off the
    map) are planned here. `raw`: pts[:ROUTE_POINTS] is a grid route round an obstacle, whose every segment is
    planned again (as the host's drive_points does)."""
    K = w.plans.shape[2]
    last = jnp.maximum(n - 2, 0)
    use = jnp.stack([(n >= 2) & ~(is_node[0] & is_node[1]), (n >= 2) & ~(is_node[last] & is_node[last + 1])])
    route = pts[:ROUTE_POINTS]  # (the caller's buffer holds at least ROUTE_POINTS)
    seg = raw & (jnp.arange(ROUTE_POINTS - 1) < n - 1)
    # one grid search for the leg's two end segments and the route's segments (traced and compiled once)
    a = jnp.concatenate([pts[jnp.stack([0, last])], route[:-1]])
    c = jnp.concatenate([pts[jnp.stack([1, last + 1])], route[1:]])
    go = jnp.concatenate([use & ~raw, seg])
    one = lambda a, c, go: _local(w, b, a, c, fl, False, go)  # noqa: E731
    # fl.serial: one segment after another, each searched only where it needs it (lax.cond); else all at once
    local, count = jax.lax.map(lambda x: one(*x), (a, c, go)) if fl.serial else jax.vmap(one)(a, c, go)
    pad = lambda p: jnp.concatenate([p, jnp.repeat(p[:, -1:], K - p.shape[1], 1)], axis=1)  # noqa: E731
    way, m = _splice(pts, n, is_node, nodes, (pad(local[:2]), count[:2], use), w, b)
    plans, cnt = local[2:], count[2:]
    rway, rm = geo.join_plans(route, jnp.minimum(n, ROUTE_POINTS), plans, cnt, jnp.ones(ROUTE_POINTS - 1, bool))
    dp, dn = geo.densify_or_keys(way, m, pts, n, fl.path_points)
    rp, rn = geo.densify_or_keys(rway, rm, route, jnp.minimum(n, ROUTE_POINTS), fl.path_points)
    return jnp.where(raw, rp, dp), jnp.where(raw, rn, dn)


def _node_route(w, b, a, t, N):
    """(N,) key poses of the driven path a -> t (just a where none) and their count."""
    nodes, n = geo.path_nodes(w.drive_pred[b], a, t, N)
    return jnp.where(n > 0, nodes, a), jnp.maximum(n, 1)


def leg_waypoints(st, inp, w, pose, fl: Flags):
    """((P, 2) waypoints, count) of the episode's leg, as `_run_chunk` hands them to the executor."""
    b, N = inp.b, w.pos.shape[1]
    L = max(N + 2, ROUTE_POINTS)  # polyline buffer: a map path with both ends off the map, or a grid route
    ar = jnp.arange(L)
    here = pose[:2]

    def map_route(a, t, head, tail, has_head, has_tail):
        """Polyline [head] + path(a -> t) + [tail] with key-pose marks, padded to L."""
        nodes, n = _node_route(w, b, a, t, N)
        h = jnp.asarray(has_head, jnp.int32)
        idx = ar - h
        in_path = (idx >= 0) & (idx < n)
        node_at = jnp.where(in_path, nodes[jnp.clip(idx, 0, N - 1)], -1)
        pts = jnp.where(in_path[:, None], w.pos[b, jnp.maximum(node_at, 0)], 0.0)
        pts = jnp.where((ar == 0)[:, None] & has_head, head, pts)
        pts = jnp.where((ar == n + h)[:, None] & has_tail, tail, pts)
        return pts.astype(jnp.float32), (n + h + jnp.asarray(has_tail, jnp.int32)).astype(jnp.int32), in_path, node_at

    def pick(cond, x, y):
        return jax.tree.map(lambda u, v: jnp.where(cond, u, v), x, y)

    def nav():
        pts = jnp.zeros((L, 2), jnp.float32).at[0].set(w.pos[b, st.leg_target])
        line = (pts, jnp.int32(1), jnp.zeros(L, bool), jnp.full(L, -1, jnp.int32), jnp.asarray(False))
        return pick(inp.straight, line, (*map_route(st.node, st.leg_target, here, here, False, False), jnp.asarray(False)))

    def closer():
        est = st.leg_xy
        gap = fl.approach_gap + fl.robot_radius + CLOSER_GAP_M
        a = geo.attach(w.pos[b], w.node_mask[b], _obs(w, b), here, fl.robot_radius)
        t = geo.attach(w.pos[b], w.node_mask[b], _obs(w, b), est, fl.robot_radius)
        none = (jnp.zeros((L, 2), jnp.float32), jnp.int32(0), jnp.zeros(L, bool), jnp.full(L, -1, jnp.int32))
        pts, n, is_node, node_at = pick(inp.straight, none, map_route(a, t, here, here, False, False))
        last = jnp.where(inp.straight, here, pts[jnp.maximum(n - 1, 0)])
        v = last - est
        d = jnp.linalg.norm(v)
        goal = jnp.where(d <= gap, last, est + v / jnp.maximum(d, 1e-9) * gap)
        return pts.at[n].set(goal), n + 1, is_node, node_at, jnp.asarray(False)

    def approach():
        stop = approach_stop(st, inp, w, st.leg_target, pose, fl)
        direct = (jnp.zeros((L, 2), jnp.float32).at[0].set(here).at[1].set(stop), jnp.int32(2), jnp.zeros(L, bool),
                  jnp.full(L, -1, jnp.int32), jnp.asarray(False))
        clear = inp.straight | (geo.segment_clearance(here[None], stop[None], _obs(w, b))[0] >= fl.need)
        # round what is in the way on the grid; else over the map (`host_loop.Loop.approach_route`)
        ap, an = _local(w, b, here, stop, fl, True, (st.leg_kind == APPROACH) & ~clear)
        around = (jnp.zeros((L, 2), jnp.float32).at[: ap.shape[0]].set(ap), an, jnp.zeros(L, bool),
                  jnp.full(L, -1, jnp.int32), jnp.asarray(True))
        a = geo.attach(w.pos[b], w.node_mask[b], _obs(w, b), here, fl.robot_radius)
        t = geo.attach(w.pos[b], w.node_mask[b], _obs(w, b), stop, fl.robot_radius)
        pts, n, is_node, node_at = map_route(a, t, here, stop, True, True)
        single = (n == 3) & (jnp.linalg.norm(stop - here) <= jnp.linalg.norm(w.pos[b, a] - here))
        which = jnp.where(clear | (~(an > 2) & single), 0, jnp.where(an > 2, 1, 2))
        return jax.tree.map(lambda x, y, z: jnp.where(which == 0, x, jnp.where(which == 1, y, z)), direct, around,
                            (pts, n, is_node, node_at, jnp.asarray(False)))

    branches = [nav, closer, approach]
    which = jnp.where(st.leg_kind == APPROACH, 2, jnp.where(st.leg_kind == CLOSER, 1, 0))
    pts, n, is_node, node_at, raw = jax.lax.switch(which, branches)
    return _drive_points(pts, n, is_node, node_at, raw, w, b, fl)


# ----------------------------------------------------------------------------------------------------
# After a leg


def _true_goal_at(st, inp, w, o, pose, fl: Flags):
    """The true goal a FOUND for object o at the pose counts for (`Loop.true_goal_at`), or -1."""
    b = inp.b
    left = ~st.found & (inp.truth >= 0)
    here = box_distance(w.obj_center[b, o], w.obj_half[b, o], pose[:2]) <= fl.found_radius
    same = left & (inp.truth == o)
    t = jnp.maximum(inp.truth, 0)
    d = box_distance(w.obj_center[b, t], w.obj_half[b, t], pose[:2])
    near = left & (d <= fl.found_radius)
    j_same = jnp.argmax(same)
    j_near = jnp.argmin(jnp.where(near, d, _INF))
    return jnp.where(same.any() & here, j_same, jnp.where(near.any(), j_near, -1))


def _nearest_object(ok, w, b, xy):
    d = box_distance(w.obj_center[b], w.obj_half[b], xy)
    return jnp.argmin(jnp.where(ok, d, _INF)).astype(jnp.int32)


def after_leg(st, inp, w, pose, arrived, visible, lam, fl: Flags):
    """The reflection after the leg just driven (`host_loop.Loop.after_leg`); visible (O,) bool."""
    b, g, kind = inp.b, st.leg_goal, st.leg_kind

    def look(st):
        target = st.leg_target
        node = jnp.where((kind != CLOSER) & arrived & ~inp.straight, target,
                         geo.attach(w.pos[b], w.node_mask[b], _obs(w, b), pose[:2], fl.robot_radius))
        st = st.replace(node=node.astype(jnp.int32), look_steps=st.look_steps + fl.look_cost)
        seen = inp.verdict[g] & (visible | ~inp.reads)
        ok = seen & ~st.skip[g]
        st = jax.lax.cond(kind != CLOSER, lambda s: s.replace(looked=s.looked.at[g, target].set(True)), lambda s: s, st)
        est, has = estimate(st, inp, g)
        has = has & inp.reads & (kind != SEARCH)
        # eval.fallback: remember the visible object that fails fewest parts of the check
        m = jnp.where(visible & ~st.skip[g], inp.misfit[g], _INF)
        d = box_distance(w.obj_center[b], w.obj_half[b], jnp.where(has, est, pose[:2]))
        best = jnp.argmin(jnp.where(jnp.isfinite(m) & (m == m.min()), d, _INF))  # fewest parts, then nearest
        better = jnp.isfinite(m[best]) & ((st.backup[g] < 0) | (m[best] < st.backup_misfit[g]))
        take = inp.fallback & ~ok.any() & ~st.fell_back[g] & better
        st = st.replace(backup=st.backup.at[g].set(jnp.where(take, best, st.backup[g])),
                        backup_misfit=st.backup_misfit.at[g].set(jnp.where(take, m[best], st.backup_misfit[g])))

        def approach_to(st, o):  # its stop is placed from this pose when the leg is driven (leg_waypoints)
            return st.replace(leg_kind=jnp.int32(APPROACH), leg_target=o)

        def searched(st):
            o = _nearest_object(ok, w, b, pose[:2])
            return jax.lax.cond(ok.any(), lambda s: approach_to(s, o), lambda s: s.replace(leg_kind=jnp.int32(NONE)), st)

        def candidate(st):
            near = box_distance(w.obj_center[b], w.obj_half[b], est) <= SAME_INSTANCE_M
            rec = inp.verdict[g] & w.known[b] & near & ~st.skip[g]
            ok2 = jnp.where(~ok.any() & (kind == CLOSER) & has, rec, ok)
            closer = inp.look_closer & has & (kind == NAV)
            o = _nearest_object(ok2, w, b, jnp.where(has, est, pose[:2]))
            at_est = box_distance(w.obj_center[b, o], w.obj_half[b, o], est) <= SAME_INSTANCE_M
            go = ok2.any() & (~closer | at_est)
            why = jnp.where(arrived, FAILED["not_confirmed"], FAILED["stuck"])
            return jax.lax.switch(
                jnp.where(go, 0, jnp.where(closer, 1, 2)),
                [lambda s: approach_to(s, o),
                 lambda s: s.replace(leg_kind=jnp.int32(CLOSER), leg_xy=est),
                 lambda s: reject(s, inp, w, g, why, lam, fl).replace(leg_kind=jnp.int32(NONE))], st)

        return jax.lax.cond(kind == SEARCH, searched, candidate, st)

    def approached(st):
        o = st.leg_target
        st = st.replace(leg_kind=jnp.int32(NONE))
        at = box_distance(w.obj_center[b, o], w.obj_half[b, o], pose[:2]) <= fl.found_radius

        def declare(st):
            j = _true_goal_at(st, inp, w, o, pose, fl)
            k = st.n_decl
            st = st.replace(found=st.found | (jnp.arange(st.found.shape[0]) == j),
                            decl_goal=st.decl_goal.at[k].set(g), decl_truth=st.decl_truth.at[k].set(j),
                            decl_obj=st.decl_obj.at[k].set(o), decl_step=st.decl_step.at[k].set(st.steps + st.look_steps),
                            decl_xy=st.decl_xy.at[k].set(pose[:2]), decl_fallback=st.decl_fallback.at[k].set(st.fell_back[g]),
                            n_decl=k + 1, status=st.status.at[g].set(jnp.where(j >= 0, FOUND, WRONG)))
            st = _remove(st, g)
            # an object answers one goal, unless a goal goes back to it ("then back to the sofa")
            others = _left_mask(st) & ~inp.revisit
            return st.replace(skip=st.skip.at[:, o].set(st.skip[:, o] | others),
                              backup=jnp.where(others & (st.backup == o), -1, st.backup))

        def blocked(st):
            st = st.replace(skip=st.skip.at[g, o].set(True))
            return reject(st, inp, w, g, FAILED["blocked"], lam, fl)

        return jax.lax.cond(at, declare, blocked, st)

    before = st
    st = jax.lax.cond(kind == APPROACH, approached, lambda s: s, st)
    st = jax.lax.cond((kind == NAV) | (kind == SEARCH) | (kind == CLOSER), look, lambda s: s, st)
    return _replanned(before, st, inp, w, lam, fl)
