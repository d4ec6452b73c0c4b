"""Batched MJX execution of navigation legs: every episode drives its current leg in one jitted call.

A *leg* is a padded waypoint list (the topological path to a retrieved node, a straight line, or an
approach to a seen object). `Executor.run` drives all episodes' legs together: one `lax.while_loop`
over control steps whose body is the per-episode kernel (waypoint controller `sim.controller.follow`,
`substeps` MJX physics steps) vmapped over episodes, each with its scene's geometry swapped into the
one padded template (`sim.model.batch_model`). The loop stops when every leg has arrived, stalled or
spent its step allowance; nothing runs on the host per step. `Executor.look` is the look-around on
arrival: camera visibility at `look_headings` headings from the robot's simulated position.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Sequence

import jax
import jax.numpy as jnp
import numpy as np
from flax import struct

from ragnav_jax.config import Config
from ragnav_jax.sim import mjx  # imported without MJX's Warp notice
from ragnav_jax.sim.controller import Path, follow, physics
from ragnav_jax.sim.model import SimModel, batch_model, build_template, initial_data, scene_geometry, slot_counts
from ragnav_jax.sim.sensors import camera_visibility, look_around
from ragnav_jax.world.scene import Scene

PROGRESS_EPS = 0.002  # metres per control step below which a step counts as no progress
STATE_FIELDS = ("qpos", "qvel", "act", "qacc_warmstart", "time")  # what a physics step reads of mjx.Data


@struct.dataclass
class SceneTables:
    """Per-scene arrays of a scene set (leading axis S)."""

    geometry: object  # SceneGeometry (S, G, ...)
    obj_pos: jax.Array  # (S, O, 3) float32 box centres
    obj_size: jax.Array  # (S, O, 3) float32 full extents
    obj_mask: jax.Array  # (S, O) bool


@struct.dataclass
class LegResult:
    """Outcome of one batch of legs (leading axis E)."""

    d: mjx.Data
    arrived: jax.Array  # (E,) bool within arrive_tol of the last waypoint
    steps: jax.Array  # (E,) int32 control steps driven
    length: jax.Array  # (E,) float32 metres driven (simulated trajectory)
    penetration: jax.Array  # (E,) float32 deepest contact penetration


@struct.dataclass
class Driving:
    """Legs in progress (leading axis E): what `Executor.advance` carries from one call to the next, so a
    caller can stop driving once some legs end, start new legs on those lanes and drive on."""

    d: mjx.Data
    paths: Path  # the legs' waypoints and the controller's progress along them
    allowance: jax.Array  # (E,) int32 control steps the leg may take
    steps: jax.Array  # (E,) int32 control steps driven on the leg
    length: jax.Array  # (E,) float32 metres driven on the leg
    stall: jax.Array  # (E,) int32 consecutive steps without progress
    pen: jax.Array  # (E,) float32 deepest contact on the leg

    @staticmethod
    def start(d: mjx.Data, points: jax.Array, n: jax.Array, allowance: jax.Array) -> Driving:
        """New legs from d: points (E, P, 2), n (E,) (0: no leg), allowance (E,)."""
        E = n.shape[0]
        zi, zf = jnp.zeros(E, jnp.int32), jnp.zeros(E, jnp.float32)
        return Driving(d, jax.vmap(Path.of)(points, n), jnp.asarray(allowance, jnp.int32), zi, zf, zi, zf)


@dataclasses.dataclass(frozen=True)
class Executor:
    """Compiled-once leg runner and look-around for scenes that fit its template."""

    model: SimModel
    tables: SceneTables
    names: tuple[str, ...]
    path_points: int
    control_dt: float
    run: object  # jitted (scene_idx (E,), d, points (E,P,2), n (E,), allowance (E,)) -> LegResult
    run_traced: object  # as run, -> (LegResult, poses (E, leg_max_steps, 3) per control step); compiled on first use
    look: object  # jitted (scene_idx (E,), d) -> (visible (E, O) bool, distance (E, O) float32)
    see: object  # jitted (scene_idx (E,), poses (E, T, 3) x, y, yaw) -> what the forward camera sees from each pose:
    # (visible (E, T, O) bool, distance (E, T, O), bearing (E, T, O) float32)
    init: object  # jitted (scene_idx (E,), start (E, 3)) -> mjx.Data batch
    traces: dict  # times each of run / look / init was traced (a recompile guard for tests)
    cache: dict  # host work that depends on these scenes alone (occupancy grids, local plans), shared by methods
    advance: object  # unjitted (scene_idx (E,), Driving, keep ()) -> (Driving, arrived (E,), driving (E,)): drives
    # until at most `keep` legs are still going (0: every leg ends), for callers that trace it into a larger
    # program (evaluation/loop)
    look_fn: object  # look unjitted, likewise
    leg_status: object  # unjitted (Driving) -> (arrived (E,), still driving (E,)), likewise


def make_executor(scenes: Sequence[Scene], cfg: Config) -> Executor:
    walls, objects = slot_counts(scenes)
    return _executor(tuple(scenes), walls, objects, cfg)


def _executor(scenes: tuple, walls: int, objects: int, cfg: Config) -> Executor:
    sim, ev = cfg.sim, cfg.eval
    model = build_template(walls, objects, sim)
    O = model.layout.objects
    geo = scene_geometry(scenes, model)
    pos = np.zeros((len(scenes), O, 3), np.float32)
    size = np.full((len(scenes), O, 3), 0.01, np.float32)
    mask = np.zeros((len(scenes), O), bool)
    for s, sc in enumerate(scenes):
        for j, o in enumerate(sc.objects):
            pos[s, j], size[s, j], mask[s, j] = o.position, o.size, o.id not in sc.absent
    tables = SceneTables(geo, jnp.asarray(pos), jnp.asarray(size), jnp.asarray(mask))
    obj_geom = jnp.arange(model.layout.obj_geom0, model.layout.obj_geom0 + O, dtype=jnp.int32)
    rb = model.layout.robot_body
    lookahead, tol, stall_max = cfg.explore.lookahead, ev.arrive_tol, ev.stall_steps
    headings = jnp.asarray(np.arange(ev.look_headings) * 2 * math.pi / ev.look_headings, jnp.float32)
    traces = {"run": 0, "look": 0, "init": 0}  # bumped by Python at trace time only (run_traced: once used)

    def models(scene_idx):
        g = jax.tree.map(lambda x: x[scene_idx], tables.geometry)
        return batch_model(model.mx, g)

    def one_step(m, d, path, active, steps, length, stall, pen):
        pose = d.qpos[:3]
        cmd, path2 = follow(path, pose, lookahead, sim.max_speed, sim.max_yaw_rate)
        d2, p = physics(m, d, cmd, sim.substeps)
        moved = jnp.linalg.norm(d2.qpos[:2] - pose[:2])
        keep = lambda a, b: jax.tree.map(lambda x, y: jnp.where(active, x, y), a, b)  # noqa: E731
        # a leg that ended keeps its state; d2's other fields are recomputed from the state by the next step
        d = d2.replace(**keep({k: getattr(d2, k) for k in STATE_FIELDS}, {k: getattr(d, k) for k in STATE_FIELDS}))
        path = keep(path2, path)
        steps = steps + active.astype(jnp.int32)
        length = length + jnp.where(active, moved, 0.0)
        stall = jnp.where(active & (moved < PROGRESS_EPS), stall + 1, jnp.where(active, 0, stall))
        pen = jnp.maximum(pen, jnp.where(active, p, 0.0))
        return d, path, steps, length, stall, pen

    def arrived_of(d, path):
        last = path.points[jnp.maximum(path.n - 1, 0)]
        return (path.n == 0) | (jnp.linalg.norm(d.qpos[:2] - last) < tol)

    def status(c: Driving):
        """((E,) arrived, (E,) still driving)."""
        arrived = jax.vmap(arrived_of)(c.d, c.paths)
        return arrived, ~arrived & (c.steps < c.allowance) & (c.stall < stall_max)

    def advance(scene_idx, c: Driving, keep, record: bool = False):
        """Drives the legs of c until at most `keep` are still going: one while_loop over control steps whose
        body is the per-episode step vmapped over episodes (legs that ended stay as they are). With `record`,
        also every episode's pose after each of its control steps (row t of an episode's (leg_max_steps, 3)
        buffer for its step t + 1 of this call, valid for t < steps)."""
        key = "run_traced" if record else "run"
        traces[key] = traces.get(key, 0) + 1
        m, in_axes = models(scene_idx)
        E = scene_idx.shape[0]
        buf = jnp.zeros((E, ev.leg_max_steps if record else 0, 3), jnp.float32)

        def cond(x):
            return jnp.sum(x[3]) > keep

        def body(x):
            t, c, buf, active = x
            out = jax.vmap(one_step, in_axes=(in_axes, 0, 0, 0, 0, 0, 0, 0))(
                m, c.d, c.paths, active, c.steps, c.length, c.stall, c.pen)
            if record:  # an episode is active for its first `steps` iterations, so row t is its step t + 1
                buf = jax.lax.dynamic_update_slice_in_dim(buf, out[0].qpos[:, None, :3], t, axis=1)
            d, paths, steps, length, stall, pen = out
            c = c.replace(d=d, paths=paths, steps=steps, length=length, stall=stall, pen=pen)
            return t + 1, c, buf, status(c)[1]

        _, c, buf, _ = jax.lax.while_loop(cond, body, (jnp.int32(0), c, buf, status(c)[1]))
        arrived, going = status(c)
        return c, arrived, going, buf

    def drive(scene_idx, d, points, n, allowance, record: bool):
        """Every leg to its end (arrived, stalled or out of allowance); with `record`, the poses (`advance`)."""
        c, arrived, _, buf = advance(scene_idx, Driving.start(d, points, n, allowance), 0, record)
        res = LegResult(c.d, arrived, c.steps, c.length, c.pen)
        return (res, buf) if record else res

    run = jax.jit(functools.partial(drive, record=False))
    run_traced = jax.jit(functools.partial(drive, record=True))

    def look_fn(scene_idx, d):
        traces["look"] += 1
        m, in_axes = models(scene_idx)

        def one(m, d, op, osz, om):
            return look_around(m, d, op, osz, om, obj_geom, sim, rb, headings)

        return jax.vmap(one, in_axes=(in_axes, 0, 0, 0, 0))(
            m, d, tables.obj_pos[scene_idx], tables.obj_size[scene_idx], tables.obj_mask[scene_idx])

    look = jax.jit(look_fn)

    @jax.jit
    def see(scene_idx, poses):
        traces["see"] = traces.get("see", 0) + 1
        m, in_axes = models(scene_idx)

        def lane(m, poses, op, osz, om):
            def one(p):
                v = camera_visibility(m, initial_data(m, p), op, osz, om, obj_geom, sim, rb)
                return v.visible, v.distance, v.bearing

            return jax.vmap(one)(poses)

        return jax.vmap(lane, in_axes=(in_axes, 0, 0, 0, 0))(
            m, poses, tables.obj_pos[scene_idx], tables.obj_size[scene_idx], tables.obj_mask[scene_idx])

    @jax.jit
    def init(scene_idx, start):
        traces["init"] += 1
        m, in_axes = models(scene_idx)
        return jax.vmap(initial_data, in_axes=(in_axes, 0))(m, start)

    return Executor(model, tables, tuple(s.name for s in scenes), ev.path_points, sim.timestep * sim.substeps,
                    run, run_traced, look, see, init, traces, {}, lambda i, c, keep: advance(i, c, keep)[:3], look_fn,
                    status)


def densify(points: np.ndarray, P: int, spacing: float = 0.25) -> np.ndarray:
    """Waypoints every `spacing` metres along the polyline (every vertex kept, at most P in all; the spacing
    grows for long paths), so the pure-pursuit controller follows the map's edges instead of cutting
    the corners between key poses by up to its lookahead."""
    points = np.asarray(points, np.float32).reshape(-1, 2)
    if len(points) < 2:
        return points
    seg = np.linalg.norm(np.diff(points, axis=0), axis=1)
    if len(points) >= P:
        return points
    spacing = max(spacing, float(seg.sum()) / max(P - len(points), 1))
    out = [points[:1]]
    for a, b, L in zip(points[:-1], points[1:], seg):
        k = max(int(np.ceil(L / spacing)), 1)
        t = np.arange(1, k + 1, dtype=np.float32)[:, None] / k
        out.append(a + (b - a) * t)
    dense = np.concatenate(out)
    return dense if len(dense) <= P else points


def pad_points(points: np.ndarray, P: int) -> tuple[np.ndarray, int]:
    """(P, 2) waypoints (the last repeated) and the count; longer lists are thinned evenly, ends kept."""
    points = np.asarray(points, np.float32).reshape(-1, 2)
    n = len(points)
    if n == 0:
        return np.zeros((P, 2), np.float32), 0
    if n > P:
        keep = np.unique(np.round(np.linspace(0, n - 1, P)).astype(int))
        points, n = points[keep], len(keep)
    out = np.repeat(points[-1:], P, 0)
    out[:n] = points
    return out, n


@functools.lru_cache(maxsize=4)
def _cached(scenes: tuple, walls: int, objects: int, cfg: Config) -> Executor:
    return _executor(scenes, walls, objects, cfg)
