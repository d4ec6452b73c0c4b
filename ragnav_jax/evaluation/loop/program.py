"""The closed loop as one device program: every episode of a batch, every leg, one jitted `lax.while_loop`.

    run_device(loop, states, cfg)   # evaluation/navigate.py hands over its host EpisodeStates

Host Python runs before the loop (the padded `World` and `Inputs` from what `evaluate_navigation` computed:
candidates, verdict and search tables, the memory's paths, occupancy grids and local plans of map edges)
and after it (the final `State` written back into the host EpisodeStates, from which `metrics.episode_row`
makes the rows). In between, each iteration of the while_loop reflects on the episodes whose leg ended
(look-around with MJX camera visibility -> `step.after_leg` -> budget -> a lane whose episode ended takes the
next queued one -> `step.next_leg` -> waypoints, on a share `eval.refill` of the lanes gathered from the
batch: vmapped and masked, or on a CPU one lane after another, `eval.reflections`) and then drives
(`Executor.advance`, a while_loop over MJX control steps) until that many lanes need a reflection again, so
short legs do not wait for the batch's longest. eval.batch_size lanes run
at once; a call queues several batches. The method is data (`Inputs`), the settings static `Flags`, the order
penalty lambda an array: a sweep over it, and every method, reuse one compilation.

What differs from the host loop is in the README ("The device loop"). The ETPNav-style baseline
(exploration replay), traces and record_legs run on the host loop only.
"""

from __future__ import annotations

import functools
import math

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.config import Config
from ragnav_jax.evaluation.execute import Driving
from ragnav_jax.evaluation.loop import geometry as geo
from ragnav_jax.evaluation.loop import step
from ragnav_jax.evaluation.loop.state import (
    CLOSER,
    FAILED,
    NAV,
    NONE,
    REASON_NAMES,
    SEARCH,
    STATUS_NAMES,
    Flags,
    Inputs,
    State,
    World,
)
from ragnav_jax.memory.topomap import obstacles_numpy
from ragnav_jax.world.arrays import pad_sizes

PLAN_POINTS = 24  # waypoints a map edge's local plan may have


def flags_of(cfg: Config, look_cost: int) -> Flags:
    from ragnav_jax.evaluation.clearance import GRID_MARGIN_M, TIGHT_GAP_M

    ev, sim = cfg.eval, cfg.sim
    return Flags(retries=ev.retries, max_steps=ev.max_steps, leg_max_steps=ev.leg_max_steps, look_cost=look_cost,
                 found_radius=ev.found_radius, approach_gap=ev.approach_gap, robot_radius=sim.robot_radius,
                 need=sim.robot_radius + GRID_MARGIN_M, tight=sim.robot_radius + TIGHT_GAP_M,
                 solver=cfg.planning.solver, search_iters=cfg.planning.local_search_iters, path_points=ev.path_points,
                 refill=ev.refill, serial=ev.reflections == "serial" or (ev.reflections == "auto"
                                                                          and jax.default_backend() == "cpu"))


# ----------------------------------------------------------------------------------------------------
# Host tables


def world_of(loop) -> World:
    """The `World` of a host `host_loop.Loop` (its bank's scenes; cached on the executor)."""
    key = ("device_world", tuple(loop.bank.names), loop._need())  # the executor's scenes are fixed
    if key in loop.ex.cache:
        return loop.ex.cache[key]
    bank = loop.bank
    B, N = loop.pos.shape[:2]
    O = loop.ex.model.layout.objects
    scenes = [loop.scenes.get(m.scene) if m.scene in loop.ex.names else None for m in bank.metas]  # the executor's
    sizes = pad_sizes([s for s in scenes if s is not None])
    obs = [obstacles_numpy(s, sizes) if s is not None else None for s in scenes]
    proto = next(o for o in obs if o is not None)
    obs = [o if o is not None else {k: np.zeros_like(v) for k, v in proto.items()} for o in obs]
    obstacles = {k: jnp.asarray(np.stack([o[k] for o in obs])) for k in proto}
    grids = [geo.scene_grid(loop, b) if s is not None and loop.bank.metas[b].num_nodes else None
             for b, s in enumerate(scenes)]
    empty = (np.zeros(2, np.float32), np.zeros((1, 1), np.float32), np.zeros((1, 1), np.int32))
    g = geo.stack_grids([x if x is not None else empty for x in grids])
    plans = [geo.edge_plans(loop, b, PLAN_POINTS) if grids[b] is not None else None for b in range(B)]
    M = max([1] + [len(p[1]) for p in plans if p is not None])
    plan_idx = np.full((B, N, N), -1, np.int32)
    plan_pts = np.zeros((B, M, PLAN_POINTS, 2), np.float32)
    plan_cnt = np.zeros((B, M), np.int32)
    for b, p in enumerate(plans):
        if p is not None:
            plan_idx[b], plan_pts[b, : len(p[1])], plan_cnt[b, : len(p[2])] = p
    known = np.zeros((B, O), bool)
    center = np.zeros((B, O, 2), np.float32)
    half = np.full((B, O, 2), 0.005, np.float32)
    for b, s in enumerate(scenes):
        known[b, [o for o in loop.known[b] if o < O]] = True
        for j, o in enumerate(s.objects if s is not None else ()):
            center[b, j], half[b, j] = o.position[:2], np.asarray(o.size[:2]) / 2
    world = World(jnp.asarray(loop.pos, jnp.float32), jnp.asarray(loop.mask), jnp.asarray(loop.cost, jnp.float32),
                  jnp.asarray(loop.euclid, jnp.float32),
                  jnp.asarray(loop.drive_pred, jnp.int32), obstacles, jnp.asarray(g["origin"]),
                  jnp.asarray(g["clear"]), jnp.asarray(g["labels"]), jnp.asarray(g["shape"], jnp.int32), jnp.asarray(plan_idx), jnp.asarray(plan_pts),
                  jnp.asarray(plan_cnt), jnp.asarray(known), jnp.asarray(center), jnp.asarray(half))
    loop.ex.cache[key] = world
    return world


def inputs_of(loop, states, G: int, C: int, S: int, T: int) -> Inputs:
    """The padded `Inputs` of host EpisodeStates (as evaluate_navigation made them, before any leg)."""
    from ragnav_jax.evaluation.host_loop import REVISIT

    E, O = len(states), loop.ex.model.layout.objects
    z = lambda shape, v, t: np.full(shape, v, t)  # noqa: E731
    b, start, ng, pf, strict = z(E, 0, np.int32), z(E, 0, np.int32), z(E, 0, np.int32), z(E, False, bool), z(E, False, bool)
    cands, est, has = z((E, G, C), -1, np.int32), z((E, G, C, 2), 0.0, np.float32), z((E, G, C), False, bool)
    verdict, misfit = z((E, G, O), False, bool), z((E, G, O), np.inf, np.float32)
    search, revisit, truth = z((E, G, S), -1, np.int32), z((E, G), False, bool), z((E, T), -1, np.int32)
    for e, st in enumerate(states):
        sc = loop.scenes[st.ep.scene]
        ids = {o.id: j for j, o in enumerate(sc.objects)}
        b[e], start[e], ng[e], strict[e] = st.b, st.node, len(st.status), st.strict
        pf[e] = loop.spec.reads and st.subgoals is None
        for t, oid in enumerate(st.ep.goals):
            truth[e, t] = ids.get(oid, -1)
        for g in range(len(st.status)):
            cs = st.cands[g][:C]
            cands[e, g, : len(cs)] = cs
            for j, x in enumerate(st.ests[g][:C]):
                if x is not None:
                    est[e, g, j], has[e, g, j] = x, True
            if not loop.spec.reads:
                if truth[e, g] >= 0:
                    verdict[e, g, truth[e, g]] = True
            elif st.subgoals is not None:
                v = np.asarray(loop.verdicts[st.e][g])
                verdict[e, g, : len(v)] = v[:O]
                if loop.cfg.eval.fallback and loop.misfits:
                    m = np.asarray(loop.misfits[st.e][g], np.float32)
                    misfit[e, g, : len(m)] = np.where(np.isfinite(m), m, np.inf)[:O]
                revisit[e, g] = bool(REVISIT.search(st.subgoals[g].text))
            if loop.search and st.e < len(loop.search) and g < len(loop.search[st.e]):
                s = list(loop.search[st.e][g])[:S]
                search[e, g, : len(s)] = s
    spec, ev = loop.spec, loop.cfg.eval
    method = [np.full(E, x, bool) for x in (spec.straight, spec.optimal_order, spec.search and ev.search_nodes > 0,
                                            spec.reads, ev.fallback, ev.look_closer)]
    return Inputs(*map(jnp.asarray, (b, start, ng, pf, strict, cands, est, has, verdict, misfit, search, revisit, truth,
                                     *method)))


def initial_state(inp: Inputs, lam, world: World, fl: Flags, N: int, O: int) -> State:
    """Every goal remaining, the first plan solved from the start node."""
    E, G = inp.cands.shape[:2]
    T = inp.truth.shape[1]
    zi = lambda *s: jnp.zeros(s, jnp.int32)  # noqa: E731
    zb = lambda *s: jnp.zeros(s, bool)  # noqa: E731
    st = State(
        order=jnp.broadcast_to(jnp.arange(G, dtype=jnp.int32), (E, G)), n_left=inp.num_goals.astype(jnp.int32),
        planned=zi(E, G), n_planned=zi(E), cptr=zi(E, G), rejected=zi(E, G), status=zi(E, G), found=zb(E, T),
        skip=zb(E, G, O), looked=zb(E, G, N), backup=jnp.full((E, G), -1, jnp.int32),
        backup_misfit=jnp.full((E, G), jnp.inf, jnp.float32), fell_back=zb(E, G), node=inp.start_node.astype(jnp.int32),
        steps=zi(E), look_steps=zi(E), length=jnp.zeros(E, jnp.float32), penetration=jnp.zeros(E, jnp.float32),
        leg_kind=zi(E), leg_goal=zi(E), leg_target=zi(E), leg_xy=jnp.zeros((E, 2), jnp.float32), done=zb(E),
        reason=zi(E), decl_goal=zi(E, G), decl_truth=zi(E, G), decl_obj=zi(E, G), decl_step=zi(E, G),
        decl_xy=jnp.zeros((E, G, 2), jnp.float32), decl_fallback=zb(E, G), n_decl=zi(E), legs=zi(E))
    st = jax.vmap(lambda s, i, lm: step.replan(s, i, world, lm, fl))(st, inp, lam)
    return st.replace(planned=st.order, n_planned=st.n_left)


# ----------------------------------------------------------------------------------------------------
# The program


def _select(mask, a, b):
    return jax.tree.map(lambda x, y: jnp.where(mask.reshape(mask.shape + (1,) * (x.ndim - 1)), x, y), a, b)


def _take(tree, idx):
    return jax.tree.map(lambda x: x[idx], tree)


def _put(tree, idx, sub):
    """tree with rows idx (distinct) replaced by sub's."""
    return jax.tree.map(lambda x, y: x.at[idx].set(y, unique_indices=True), tree, sub)


def _lanewise(f, in_axes, serial: bool, when=None, otherwise=None):
    """jax.vmap(f, in_axes) over a batch of lanes; with `serial` (static), f on one lane after another
    (lax.map), so its lax.cond / switch run one branch and its while_loops stop when that lane is done, and a
    lane where `when` (bool, leading axis) is False runs `otherwise` (same arguments, same output structure:
    a value the caller discards) instead of f."""
    if not serial:
        return jax.vmap(f, in_axes=in_axes)

    def mapped(*args):
        batched = [a for a, ax in zip(args, in_axes) if ax is not None]
        go = jnp.ones(jax.tree.leaves(batched)[0].shape[0], bool) if when is None else when

        def one(lane):
            run, it = lane[0], iter(lane[1:])
            lane_args = [a if ax is None else next(it) for a, ax in zip(args, in_axes)]
            return f(*lane_args) if when is None else jax.lax.cond(run, f, otherwise, *lane_args)

        return jax.lax.map(one, [go, *batched])

    return mapped


def closed_loop(world: World, inp: Inputs, scene_idx, start_pose, lam, count=None, *, fl: Flags, init,
                advance, look, status, lanes: int | None = None) -> State:
    """Runs every episode of a queue to its end on `lanes` lanes. inp, scene_idx (Q,) executor scene, start_pose
    (Q, 3) and lam (Q,) order penalty (a sweep's grid points are episodes too) have the queue's leading axis Q;
    count () episodes of the queue to run (the rest is padding; default Q); lanes (static) episodes run at once
    (default Q). Returns the final State of every queued episode (Q leading).

    Each iteration reflects on K = ceil(fl.refill * lanes) lanes that need it, gathered into a batch of K: the
    end of a lane's leg (look-around, `step.after_leg`, the budget), the next episode of the queue where its
    episode ended (its first plan and MJX state), its next leg (`step.next_leg`, waypoints). Then it drives
    (`advance`) until K lanes need a reflection, or every leg has ended: lanes do not wait for the batch's
    longest leg (refill 1.0: every leg ends first), nor for its longest episode while the queue lasts. A
    reflection costs its K lanes however few of them need it, so K counts lanes, not the legs going. Once no
    more than K legs are going (the batch's tail), the drive too runs on K lanes gathered from the batch. An
    episode's legs and steps do not depend on its lane, on when it was loaded or on K."""
    N, O = world.pos.shape[1], world.known.shape[1]
    Q = inp.b.shape[0]
    L = Q if lanes is None else min(lanes, Q)
    K = max(1, min(L, math.ceil(fl.refill * L)))  # lanes one reflection serves
    lanewise = functools.partial(_lanewise, serial=fl.serial)
    count = jnp.int32(Q) if count is None else jnp.asarray(count, jnp.int32)
    first = initial_state(inp, lam, world, fl, N, O)  # (Q) every queued episode's first plan
    start_d = init(scene_idx, start_pose)  # (Q) and its MJX state at the start pose
    ep = jnp.arange(L, dtype=jnp.int32)  # each lane's episode
    lane = jnp.arange(L, dtype=jnp.int32)
    st = _take(first, ep)
    st = st.replace(done=st.done | (ep >= count))
    d = _take(start_d, ep)
    P = fl.path_points
    drv = Driving.start(d, jnp.zeros((L, P, 2), jnp.float32), jnp.zeros(L, jnp.int32), jnp.zeros(L, jnp.int32))
    out = jax.tree.map(lambda x: jnp.zeros((Q + L, *x.shape[1:]), x.dtype), st)  # row Q + lane: a lane's scratch
    in_ep = (0, 0, None, 0, 0)

    def write(out, st, ep, lane):
        """Every ended episode's state into its queue row (each lane writes a row of its own: no collisions)."""
        row = jnp.where(st.done, ep, Q + lane)
        return jax.tree.map(lambda o, x: o.at[row].set(x, unique_indices=True), out, st)

    def load(args):
        """Lanes whose episode ended take the next ones of the queue, in lane order (their MJX state: `took`)."""
        st, ep, nxt, _ = args
        new = nxt + jnp.cumsum(st.done) - 1
        take = st.done & (new < count)
        ep = jnp.where(take, new, ep)
        st = _select(take, _take(first, ep), st)
        return st, ep, nxt + jnp.sum(take), take

    def reflect(st, drv, pose, lane_d, arrived, going, pending, ep, nxt, out, lane):
        """Lanes not driving: the end of their leg (`pending`), a new episode where theirs ended, then their next
        leg; every argument but lane_d, nxt and out has the reflected lanes' leading axis, `lane` their lane
        numbers. drv is their Driving without its MJX state (d=None: gathering and scattering mjx.Data's 84
        arrays costs more than a reflection on a CPU), pose (K, 3) theirs, lane_d() gathers their mjx.Data for
        the look-around. Returns (st, drv, pending, ep, nxt, out, took: lanes that took a new episode)."""
        li, sidx, lm = _take(inp, ep), scene_idx[ep], lam[ep]
        ended = pending & ~going
        # the look-around where a leg to a key pose or a search ended (after_leg reads it there alone)
        looks = ended & ((st.leg_kind == NAV) | (st.leg_kind == SEARCH) | (st.leg_kind == CLOSER))
        visible = jax.lax.cond(jnp.any(looks), lambda: look(sidx, lane_d())[0],
                               lambda: jnp.zeros((looks.shape[0], world.known.shape[1]), bool))
        st = _select(ended, st.replace(steps=st.steps + drv.steps, length=st.length + drv.length,
                                       penetration=jnp.maximum(st.penetration, drv.pen), legs=st.legs + 1), st)
        after = lanewise(lambda s, i, w, p, a, v, lm: step.after_leg(s, i, w, p, a, v, lm, fl), (0, 0, None, 0, 0, 0, 0),
                         when=ended, otherwise=lambda s, *_: s)(st, li, world, pose, arrived, visible, lm)
        st = _select(ended, after, st)
        free = ~going & ~st.done
        over = free & (st.steps + st.look_steps >= fl.max_steps)
        left = lanewise(step._left_mask, (0,))(st)
        st = st.replace(done=st.done | over, reason=jnp.where(over, 2, st.reason), n_left=jnp.where(over, 0, st.n_left),
                        status=jnp.where(over[:, None] & left, FAILED["budget"], st.status),
                        leg_kind=jnp.where(over, NONE, st.leg_kind))
        out = write(out, st, ep, lane)
        st, ep, nxt, took = jax.lax.cond(jnp.any(st.done) & (nxt < count), load, lambda a: a,
                                         (st, ep, nxt, jnp.zeros_like(st.done)))
        li, lm = _take(inp, ep), lam[ep]
        pose = jnp.where(took[:, None], start_d.qpos[ep, :3], pose)
        free = ~going & ~st.done
        nxt_leg = lanewise(lambda s, i, w, p, lm: step.next_leg(s, i, w, p, lm, fl), in_ep, when=free,
                           otherwise=lambda s, *_: s)(st, li, world, pose, lm)
        st = _select(free, nxt_leg, st)
        start = free & ~st.done & (st.leg_kind != NONE)
        pts, n = lanewise(lambda s, i, w, p: step.leg_waypoints(s, i, w, p, fl), in_ep[:4], when=start,
                          otherwise=lambda *_: (jnp.zeros((fl.path_points, 2), jnp.float32), jnp.int32(0)))(
            st, li, world, pose)
        allow = jnp.clip(jnp.minimum(fl.leg_max_steps, fl.max_steps - st.steps - st.look_steps), 0, None)
        new = Driving.start(None, pts, jnp.where(start, n, 0), jnp.where(start, allow, 0).astype(jnp.int32))
        return st, _select(start, new, drv), start | (pending & going), ep, nxt, out, took

    def cond(c):
        return jnp.any(~c[0].done) | (c[6] < count)

    def body(c):
        st, drv, arrived, going, pending, ep, nxt, out, it = c
        # K lanes that need a reflection, gathered into a batch of K (a reflection costs K lanes, not L; a lane
        # chosen that needs none is left as it is), round robin among those that need one so none waits for ever
        needs = ~going & (pending | ~st.done | (nxt < count))
        idx = jnp.argsort(jnp.where(needs, 0, L) + (lane - it * K) % L)[:K]
        meta = drv.replace(d=None)
        sub = reflect(_take(st, idx), _take(meta, idx), drv.d.qpos[idx, :3], lambda: _take(drv.d, idx),
                      *_take((arrived, going, pending, ep), idx), nxt, out, idx)
        (st, meta, pending, ep), nxt, out, took = _put((st, meta, pending, ep), idx, sub[:4]), sub[4], sub[5], sub[6]
        # lanes that took a new episode start from its MJX state
        d = jax.lax.cond(jnp.any(took), lambda d: _put(d, idx, _select(took, _take(start_d, ep[idx]), _take(d, idx))),
                         lambda d: d, drv.d)
        drv = meta.replace(d=d)
        unserved = needs.at[idx].set(False, unique_indices=True)
        # drive until K lanes need a reflection: legs in progress end, joining those still unserved. Once no more
        # than K legs are going (the batch's last ones), on K lanes gathered from the batch: a control step then
        # costs K lanes, not L
        keep = jnp.maximum(jnp.sum(pending & ~unserved) + jnp.sum(unserved) - K, 0)
        sidx, going_now = scene_idx[ep], status(drv)[1]

        def drive_all(drv):
            return advance(sidx, drv, keep)[0]

        def drive_few(drv):
            few = jnp.argsort(jnp.where(going_now, 0, 1))[:K]  # every lane going, then others (left as they are)
            return _put(drv, few, advance(sidx[few], _take(drv, few), keep)[0])

        drv = drive_all(drv) if K == L else jax.lax.cond(jnp.sum(going_now) <= K, drive_few, drive_all, drv)
        arrived, going = status(drv)
        return st, drv, arrived, going, pending, ep, nxt, out, it + 1

    z = jnp.zeros(L, bool)
    c = (st, drv, jnp.ones(L, bool), z, z, ep, jnp.minimum(jnp.int32(L), count), out, jnp.int32(0))
    st, _, _, _, _, ep, _, out, _ = jax.lax.while_loop(cond, body, c)
    return jax.tree.map(lambda x: x[:Q], write(out, st, ep, lane))


def compiled(ex, fl: Flags, lanes: int | None = None):
    """The jitted program of an executor, flags and lane count (one trace per queue shape), kept on the
    executor."""
    key = ("device_program", fl, lanes)
    if key not in ex.cache:
        ex.cache[key] = jax.jit(functools.partial(closed_loop, fl=fl, init=ex.init, advance=ex.advance,
                                                  look=ex.look_fn, status=ex.leg_status, lanes=lanes))
    return ex.cache[key]


def _pad(x, E: int):
    """Pads the leading axis to E by repeating the first row."""
    return jax.tree.map(lambda a: jnp.concatenate([a, jnp.repeat(a[:1], E - a.shape[0], 0)]) if a.shape[0] < E else a, x)


def batch_sizes(states: list, cfg: Config) -> tuple[int, int, int, int]:
    """(G goals, C candidates, S search nodes, T true goals) of `inputs_of`: from the episodes and the config
    alone (not the method), so every method shares one compilation."""
    T = max(len(st.ep.goals) for st in states)
    G = max(T, max(len(st.status) for st in states), 1)
    C = max([cfg.eval.candidates] + [len(c) for st in states for c in st.cands])
    return G, C, max(1, cfg.eval.search_nodes), T


QUEUE_BATCHES = 8  # a device call queues up to this many batches of episodes on its eval.batch_size lanes


def queue_size(n: int, lanes: int) -> int:
    """Episodes one device call queues for n on `lanes` lanes: 1, 2, 4 or 8 batches, as few as hold n (few
    shapes, few compilations)."""
    return lanes * min(QUEUE_BATCHES, 1 << (-(-n // lanes) - 1).bit_length())


def run_device(loop, states: list, cfg: Config, progress=None) -> None:
    """Runs `states` (host EpisodeStates, before any leg) on the device program and writes the outcome back
    into them (status, found, declarations, steps, travel, the first plan). eval.batch_size lanes run at once;
    each call queues up to QUEUE_BATCHES batches of episodes (a power of two of them, padded; the padding is not
    run)."""
    if loop.spec.explores:
        from ragnav_jax.errors import UserError

        raise UserError("the device loop does not run the etpnav baseline (eval.engine=host runs it)")
    if not states:
        return
    G, C, S, T = batch_sizes(states, cfg)
    fl = flags_of(cfg, loop.look_cost)
    world = world_of(loop)
    B = min(cfg.eval.batch_size, len(states))
    Q = queue_size(len(states), B)
    prog = compiled(loop.ex, fl, B)
    for c0 in range(0, len(states), Q):
        chunk = states[c0 : c0 + Q]
        inp = _pad(inputs_of(loop, chunk, G, C, S, T), Q)
        sidx = _pad(jnp.asarray([st.s for st in chunk], jnp.int32), Q)
        start = _pad(jnp.asarray([[*loop.scenes[st.ep.scene].start.position[:2], loop.scenes[st.ep.scene].start.yaw]
                                  for st in chunk], jnp.float32), Q)
        lam = jnp.full(Q, cfg.planning.lam, jnp.float32)
        write_back(chunk, prog(world, inp, sidx, start, lam, jnp.int32(len(chunk))),
                   loop)
        if progress is not None:
            progress(len(chunk))


def write_back(states: list, out: State, loop) -> None:
    """Copies the final device State of a batch (its first len(states) rows) into the host EpisodeStates: one
    device-to-host copy and one list conversion per field, then plain Python per episode."""
    E = len(states)
    s = {k: v[:E].tolist() for k, v in vars(jax.device_get(out)).items()}
    for i, st in enumerate(states):
        G, T = len(st.status), len(st.ep.goals)
        objs = loop.scenes[st.ep.scene].objects
        st.status = [STATUS_NAMES[x] for x in s["status"][i][:G]]
        st.found = s["found"][i][:T]
        st.rejected, st.cptr = s["rejected"][i][:G], s["cptr"][i][:G]
        st.steps, st.look_steps = s["steps"][i], s["look_steps"][i]
        st.length, st.penetration = s["length"][i], s["penetration"][i]
        st.planned = s["planned"][i][: s["n_planned"][i]]
        st.remaining = s["order"][i][: s["n_left"][i]]
        st.node, st.done, st.reason = s["node"][i], s["done"][i], REASON_NAMES[s["reason"][i]]
        st.declarations = []
        for k in range(s["n_decl"][i]):
            j = s["decl_truth"][i][k]
            st.declarations.append({"goal": s["decl_goal"][i][k], "truth": j if j >= 0 else None,
                                    "object": objs[s["decl_obj"][i][k]].id, "correct": j >= 0,
                                    "step": s["decl_step"][i][k], "xy": [round(x, 3) for x in s["decl_xy"][i][k]],
                                    **({"fallback": True} if s["decl_fallback"][i][k] else {})})
        st.fell_back = {g for g in range(G) if s["fell_back"][i][g]}
