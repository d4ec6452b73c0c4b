"""Frontier exploration of many scenes at once: one jitted while_loop over control steps, vmapped over scenes.

Each control step runs three phases over the batch, each a per-scene kernel under `vmap`:
  sense  (every `scan_every` steps): lidar scan + camera visibility, map update, stream record;
  plan   (only when some scene needs a new target): frontier regions, greedy target, grid path;
  act    : waypoint controller, `substeps` MJX physics steps.
The loop counter is not batched, so the phase conditions are real `lax.cond`s (skipped work is not done),
and a finished scene just stands still (its later records are marked inactive), so a scene's results
do not depend on the rest of its batch. Nothing runs on the host per step.

Host side (`explore_scenes`): pads a scene set once (one compilation for every batch), runs the batches
with a progress bar, and cuts each scene's outputs into an ExplorationStream plus its map and trajectory.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import zlib
from collections.abc import Sequence

import jax
import jax.numpy as jnp
import numpy as np
from flax import struct
from mujoco import mjx

from ragnav_jax.config import Config, ExploreConfig, SimConfig
from ragnav_jax.sim import grid as G
from ragnav_jax.sim.controller import Path, follow, physics
from ragnav_jax.sim.model import (
    SceneGeometry,
    SimModel,
    batch_model,
    build_template,
    initial_data,
    scene_geometry,
    slot_counts,
)
from ragnav_jax.sim.sensors import camera_visibility, lidar_angles, lidar_scan, odometry
from ragnav_jax.sim.stream import ExplorationStream
from ragnav_jax.world.scene import Scene


@struct.dataclass
class SceneInputs:
    """Per-scene inputs of the explorer (leading batch axis B when batched)."""

    geometry: SceneGeometry  # (G, ...) geom fields
    start: jax.Array  # (3,) float32 x, y, yaw
    origin: jax.Array  # (2,) float32 map origin
    inside: jax.Array  # (H, W) bool map cells within the scene's padded bounds
    obj_pos: jax.Array  # (n_obj, 3) float32 box centres
    obj_size: jax.Array  # (n_obj, 3) float32 full extents
    obj_mask: jax.Array  # (n_obj,) bool
    key: jax.Array  # (2,) uint32 PRNG key of the scene (odometry noise)


@struct.dataclass
class ExploreState:
    """Per-scene state of the exploration loop."""

    d: mjx.Data
    seen: jax.Array  # (H, W) bool
    hit: jax.Array  # (H, W) bool
    viewed: jax.Array  # (H, W) bool cells the camera looked at
    frontier: jax.Array  # (H, W) bool targets as of the last scan: lidar frontier (+ unviewed free cells)
    scan: jax.Array  # (L,) float32 the last lidar ranges
    blocked: jax.Array  # (Hc, Wc) bool exploration cells whose targets were given up
    path: Path
    goal: jax.Array  # (2,) int32 map cell of the current target's representative frontier cell
    has_goal: jax.Array  # () bool
    goal_steps: jax.Array  # () int32 control steps since the target was chosen
    goal_budget: jax.Array  # () int32 control steps allowed to reach it
    stall: jax.Array  # () int32 consecutive control steps without progress
    done: jax.Array  # () bool
    finished: jax.Array  # () bool: stopped because no frontier was left (not the step budget)
    steps: jax.Array  # () int32 control steps taken while active
    path_length: jax.Array  # () float32 metres driven
    max_penetration: jax.Array  # () float32 deepest contact penetration seen, metres
    plans: jax.Array  # () int32 targets chosen
    given_up: jax.Array  # () int32 targets given up (timeout, no path, or frontier left after arrival)
    rec_t: jax.Array  # (T,) int32 control step of each record
    rec_active: jax.Array  # (T,) bool record taken while the scene was still exploring
    rec_pose: jax.Array  # (T, 4) float32 odometry x, y, z, yaw
    rec_true: jax.Array  # (T, 3) float32 true x, y, yaw
    rec_lidar: jax.Array  # (T, L) float32
    rec_visible: jax.Array  # (T, n_obj) bool
    rec_distance: jax.Array  # (T, n_obj) float32
    rec_bearing: jax.Array  # (T, n_obj) float32


@dataclasses.dataclass(frozen=True)
class Explorer:
    """A compiled-once exploration function for scenes that fit its template and grid."""

    model: SimModel
    spec: G.GridSpec
    sim: SimConfig
    cfg: ExploreConfig
    records: int  # T
    path_len: int  # P
    run: object  # jitted (SceneInputs batch) -> ExploreState batch


def make_explorer(model: SimModel, spec: G.GridSpec, sim: SimConfig, cfg: ExploreConfig) -> Explorer:
    """Builds the jitted batched exploration loop for a template and a grid spec."""
    layout = model.layout
    n_obj = layout.objects
    H, W = spec.shape
    Hc, Wc = spec.coarse_shape
    k = spec.k
    T = -(-cfg.max_steps // cfg.scan_every)
    P = 4 * (H + W)
    np_angles = lidar_angles(sim)
    angles = jnp.asarray(np_angles)
    L = angles.shape[0]
    obj_geom = jnp.arange(layout.obj_geom0, layout.obj_geom0 + n_obj, dtype=jnp.int32)
    control_dt = sim.timestep * sim.substeps
    sweep = math.radians(cfg.look_sweep_deg)
    sweep_steps = max(cfg.look_period / control_dt, 1.0)
    rb = layout.robot_body

    def init(m, inp: SceneInputs) -> ExploreState:
        d = initial_data(m, inp.start)
        f32, b = jnp.float32, jnp.bool_
        return ExploreState(
            d=d, seen=jnp.zeros((H, W), b), hit=jnp.zeros((H, W), b), viewed=jnp.zeros((H, W), b),
            frontier=jnp.zeros((H, W), b),
            scan=jnp.full((L,), sim.lidar_range, f32),
            blocked=jnp.zeros((Hc, Wc), b), path=Path.empty(P), goal=jnp.zeros(2, jnp.int32),
            has_goal=jnp.array(False), goal_steps=jnp.int32(0), goal_budget=jnp.int32(0), stall=jnp.int32(0), done=jnp.array(False),
            finished=jnp.array(False), steps=jnp.int32(0), path_length=f32(0), max_penetration=f32(0),
            plans=jnp.int32(0), given_up=jnp.int32(0),
            rec_t=jnp.zeros(T, jnp.int32), rec_active=jnp.zeros(T, b), rec_pose=jnp.zeros((T, 4), f32),
            rec_true=jnp.zeros((T, 3), f32), rec_lidar=jnp.zeros((T, L), f32), rec_visible=jnp.zeros((T, n_obj), b),
            rec_distance=jnp.zeros((T, n_obj), f32), rec_bearing=jnp.zeros((T, n_obj), f32),
        )

    def sense(m, inp: SceneInputs, s: ExploreState, t) -> ExploreState:
        pose = s.d.qpos[:3]
        ranges = lidar_scan(m, s.d, angles, sim.lidar_height, sim.lidar_range, rb)
        vis = camera_visibility(m, s.d, inp.obj_pos, inp.obj_size, inp.obj_mask, obj_geom, sim, rb)
        seen, hit = G.update_map(spec, inp.origin, s.seen, s.hit, pose, ranges, angles, sim.lidar_range)
        viewed = G.update_viewed(
            spec, inp.origin, s.viewed, pose, ranges, np_angles, math.radians(sim.camera_fov_deg), sim.camera_range
        )
        free, _, frontier = G.classify(seen, hit, inp.inside)
        if cfg.camera_frontiers:  # free space the camera has not looked at is worth a visit too
            frontier = frontier | (free & ~viewed)
        i = t // cfg.scan_every
        odo = odometry(pose, sim.robot_height, jax.random.fold_in(inp.key, t), sim.odom_noise)
        return s.replace(
            seen=seen, hit=hit, viewed=viewed, frontier=frontier, scan=ranges,
            rec_t=s.rec_t.at[i].set(t), rec_active=s.rec_active.at[i].set(~s.done), rec_pose=s.rec_pose.at[i].set(odo),
            rec_true=s.rec_true.at[i].set(pose), rec_lidar=s.rec_lidar.at[i].set(ranges),
            rec_visible=s.rec_visible.at[i].set(vis.visible), rec_distance=s.rec_distance.at[i].set(vis.distance),
            rec_bearing=s.rec_bearing.at[i].set(vis.bearing),
        )

    def status(inp: SceneInputs, s: ExploreState):
        """(arrived, timed_out, vanished, path_blocked) of the current target."""
        pose = s.d.qpos[:3]
        end = s.path.points[jnp.maximum(s.path.n - 1, 0)]
        arrived = s.has_goal & (jnp.linalg.norm(pose[:2] - end) < cfg.arrive_tol)
        timed_out = s.has_goal & ((s.goal_steps > s.goal_budget) | (s.stall > cfg.stall_steps))
        coarse_frontier = s.frontier.reshape(Hc, k, Wc, k).any((1, 3))
        vanished = s.has_goal & ~coarse_frontier[s.goal[0] // k, s.goal[1] // k]
        cells = G.cell_of(spec, inp.origin, s.path.points)
        ids = jnp.arange(P)
        on_path = (ids >= s.path.index) & (ids < s.path.n)
        occupied = s.hit[jnp.clip(cells[:, 0], 0, H - 1), jnp.clip(cells[:, 1], 0, W - 1)]
        path_blocked = s.has_goal & jnp.any(on_path & occupied)
        return arrived, timed_out, vanished, path_blocked

    def needs_plan(inp, s):
        arrived, timed_out, vanished, path_blocked = status(inp, s)
        return ~s.done & (~s.has_goal | arrived | timed_out | vanished | path_blocked)

    def plan(m, inp: SceneInputs, s: ExploreState) -> ExploreState:
        arrived, timed_out, vanished, _ = status(inp, s)
        give_up = (arrived | timed_out) & ~vanished
        gc = s.goal // k
        blocked = s.blocked.at[gc[0], gc[1]].set(s.blocked[gc[0], gc[1]] | give_up)
        pose = s.d.qpos[:3]
        free, _, _ = G.classify(s.seen, s.hit, inp.inside)
        cost = G.cell_costs(spec, free, s.hit, inp.inside)
        src = G.cell_of(spec, inp.origin, pose[:2])
        dist = G.distance_field(spec, cost, src)
        reg = G.frontier_regions(spec, inp.origin, s.frontier, dist, blocked, cfg.min_frontier_cells)
        if cfg.target_rule == "euclidean":  # the paper: f_next = argmin_f ||p_current - f||
            score = jnp.linalg.norm(reg.center - pose[None, :2], axis=-1)
        else:  # shortest path through the explored free space
            score = reg.path_cost
        score = jnp.where(reg.valid, score, jnp.inf)
        r = jnp.argmin(score)
        any_valid = jnp.any(reg.valid)
        cells, n, ok = G.extract_path(dist, reg.target[r], P)
        centers = G.cell_centers(spec, inp.origin)
        points = centers[cells[:, 0], cells[:, 1]]
        good = any_valid & ok
        # A target without a path is given up at once.
        bc = reg.rep[r] // k
        blocked = blocked.at[bc[0], bc[1]].set(blocked[bc[0], bc[1]] | (any_valid & ~ok))
        drive = n.astype(jnp.float32) * spec.res / (sim.max_speed * control_dt)  # nominal steps along the path
        budget = cfg.goal_timeout + jnp.ceil(3.0 * drive).astype(jnp.int32)
        new_path = Path.of(points, jnp.where(good, n, 0))
        return s.replace(
            blocked=blocked, path=new_path, goal=reg.rep[r].astype(jnp.int32), has_goal=good,
            goal_steps=jnp.int32(0), goal_budget=jnp.where(good, budget, 0), stall=jnp.int32(0),
            done=~any_valid, finished=~any_valid, plans=s.plans + good,
            given_up=s.given_up + give_up.astype(jnp.int32) + (any_valid & ~ok).astype(jnp.int32),
        )

    def act(m, inp: SceneInputs, s: ExploreState) -> ExploreState:
        pose = s.d.qpos[:3]
        look = sweep * jnp.sin(2 * jnp.pi * s.steps.astype(jnp.float32) / sweep_steps)
        cmd, path = follow(
            s.path, pose, cfg.lookahead, sim.max_speed, sim.max_yaw_rate, scan=(s.scan, angles),
            robot_radius=sim.robot_radius, look=look,
        )
        cmd = jnp.where(s.done, 0.0, cmd)
        d, pen = physics(m, s.d, cmd, sim.substeps)
        moved = jnp.linalg.norm(d.qpos[:2] - pose[:2])
        active = ~s.done
        return s.replace(
            d=d, path=path, goal_steps=s.goal_steps + 1, steps=s.steps + active.astype(jnp.int32),
            stall=jnp.where(moved < 0.002, s.stall + 1, 0),
            path_length=s.path_length + jnp.where(active, moved, 0.0),
            max_penetration=jnp.maximum(s.max_penetration, pen),
        )

    def select(mask, a, b):
        return jax.tree.map(lambda x, y: jnp.where(mask.reshape(mask.shape + (1,) * (x.ndim - 1)), x, y), a, b)

    @jax.jit
    def run(inputs: SceneInputs) -> ExploreState:
        m, m_axes = batch_model(model.mx, inputs.geometry)
        vm = lambda f: jax.vmap(f, in_axes=(m_axes, 0, 0))  # noqa: E731
        s0 = jax.vmap(init, in_axes=(m_axes, 0))(m, inputs)

        def body(c):
            t, s = c
            s = jax.lax.cond(
                t % cfg.scan_every == 0,
                lambda s: jax.vmap(sense, in_axes=(m_axes, 0, 0, None))(m, inputs, s, t),
                lambda s: s,
                s,
            )
            need = jax.vmap(needs_plan)(inputs, s)
            s = jax.lax.cond(jnp.any(need), lambda s: select(need, vm(plan)(m, inputs, s), s), lambda s: s, s)
            s = vm(act)(m, inputs, s)
            return t + 1, s

        def cond(c):
            t, s = c
            return (t < cfg.max_steps) & ~jnp.all(s.done)

        _, s = jax.lax.while_loop(cond, body, (jnp.int32(0), s0))
        return s

    return Explorer(model=model, spec=spec, sim=sim, cfg=cfg, records=T, path_len=P, run=run)


# ----------------------------------------------------------------------------------------------------
# Host side


def scene_key(seed: int, name: str) -> np.ndarray:
    """A PRNG key that depends on the seed and the scene's name only (not on its batch)."""
    return np.asarray(jax.random.fold_in(jax.random.PRNGKey(seed), zlib.crc32(name.encode()) & 0x7FFFFFFF))


def scene_inputs(scenes: Sequence[Scene], explorer: Explorer, seed: int) -> SceneInputs:
    """Stacked (B, ...) explorer inputs of scenes."""
    n_obj = explorer.model.layout.objects
    frames = [G.scene_frame(s, explorer.spec) for s in scenes]
    obj_pos = np.zeros((len(scenes), n_obj, 3), np.float32)
    obj_size = np.zeros((len(scenes), n_obj, 3), np.float32)
    obj_mask = np.zeros((len(scenes), n_obj), bool)
    for b, s in enumerate(scenes):
        for i, o in enumerate(s.objects):
            obj_pos[b, i], obj_size[b, i], obj_mask[b, i] = o.position, o.size, True
    return SceneInputs(
        geometry=scene_geometry(scenes, explorer.model),
        start=jnp.asarray([[*s.start.position, s.start.yaw] for s in scenes], jnp.float32),
        origin=jnp.asarray(np.stack([f[0] for f in frames])),
        inside=jnp.asarray(np.stack([f[1] for f in frames])),
        obj_pos=jnp.asarray(obj_pos), obj_size=jnp.asarray(obj_size), obj_mask=jnp.asarray(obj_mask),
        key=jnp.asarray(np.stack([scene_key(seed, s.name) for s in scenes])),
    )


def explorer_for(scenes: Sequence[Scene], cfg: Config) -> Explorer:
    """One explorer (template + grid) that fits every scene of a set. Explorers are cached by their
    static shapes and settings, so scene sets that pad alike share one compilation in a process. Scenes
    beyond the configured sizes or the device's memory are a UserError here, before any compilation."""
    from ragnav_jax.world.limits import check_explore_fits

    check_explore_fits(scenes, cfg)
    walls, objects = slot_counts(scenes)
    spec = G.grid_spec(
        scenes, cfg.explore.map_resolution, cfg.explore.grid_resolution, cfg.sim.robot_radius + cfg.explore.clearance
    )
    return _cached_explorer(walls, objects, spec, cfg.sim, cfg.explore)


@functools.lru_cache(maxsize=8)
def _cached_explorer(walls: int, objects: int, spec: G.GridSpec, sim: SimConfig, cfg: ExploreConfig) -> Explorer:
    return make_explorer(build_template(walls, objects, sim), spec, sim, cfg)


@dataclasses.dataclass(frozen=True)
class SceneResult:
    """Everything the explorer produced for one scene, cut to its own sizes (host NumPy)."""

    stream: ExplorationStream
    true_pose: np.ndarray  # (T, 3) x, y, yaw of each record (the stream's pose may carry noise)
    origin: np.ndarray  # (2,) map origin
    resolution: float  # map metres per cell
    grid_factor: int  # map cells per exploration-grid cell
    seen: np.ndarray  # (h, w) bool
    hit: np.ndarray  # (h, w) bool
    viewed: np.ndarray  # (h, w) bool cells the camera looked at
    frontier: np.ndarray  # (h, w) bool frontier cells left at the end
    blocked: np.ndarray  # (hc, wc) bool exploration cells given up
    steps: int
    finished: bool
    path_length: float
    max_penetration: float
    plans: int
    given_up: int
    control_dt: float  # seconds per control step


def cut_results(scenes: Sequence[Scene], explorer: Explorer, s: ExploreState) -> list[SceneResult]:
    s = jax.tree.map(np.asarray, s)
    angles = lidar_angles(explorer.sim)
    out = []
    for b, scene in enumerate(scenes):
        n_obj = len(scene.objects)
        _, inside = G.scene_frame(scene, explorer.spec)
        h, w = int(inside.any(1).sum()), int(inside.any(0).sum())
        keep = s.rec_active[b]
        stream = ExplorationStream(
            scene=scene.name, t=s.rec_t[b][keep].astype(np.int32), pose=s.rec_pose[b][keep],
            lidar=s.rec_lidar[b][keep], lidar_angles=angles, visible=s.rec_visible[b][keep][:, :n_obj],
            distance=s.rec_distance[b][keep][:, :n_obj], bearing=s.rec_bearing[b][keep][:, :n_obj],
            object_ids=tuple(o.id for o in scene.objects),
        )
        k = explorer.spec.k
        out.append(SceneResult(
            stream=stream, true_pose=s.rec_true[b][keep], origin=G.scene_frame(scene, explorer.spec)[0],
            resolution=explorer.spec.res, grid_factor=k, seen=s.seen[b][:h, :w], hit=s.hit[b][:h, :w],
            viewed=s.viewed[b][:h, :w],
            frontier=s.frontier[b][:h, :w], blocked=s.blocked[b][: -(-h // k), : -(-w // k)],
            steps=int(s.steps[b]), finished=bool(s.finished[b]), path_length=float(s.path_length[b]),
            max_penetration=float(s.max_penetration[b]), plans=int(s.plans[b]), given_up=int(s.given_up[b]),
            control_dt=explorer.sim.timestep * explorer.sim.substeps,
        ))
    return out


def explore_scenes(scenes: Sequence[Scene], cfg: Config, progress: bool = False, explorer: Explorer | None = None) -> list[SceneResult]:
    """Explores every scene, `cfg.explore.batch_size` at a time (the last batch padded with repeats of
    its first scene so shapes stay static); one compilation serves all batches."""
    from tqdm import tqdm

    explorer = explorer or explorer_for(scenes, cfg)
    B = min(cfg.explore.batch_size, len(scenes))
    results: list[SceneResult] = []
    batches = [list(scenes[i : i + B]) for i in range(0, len(scenes), B)]
    for batch in tqdm(batches, desc="explore", unit="batch", disable=not progress):
        padded = batch + [batch[0]] * (B - len(batch))
        state = explorer.run(scene_inputs(padded, explorer, cfg.seed))
        n = len(batch)
        results += cut_results(batch, explorer, jax.tree.map(lambda x, n=n: x[:n], state))
    return results


def control_hz(sim: SimConfig) -> float:
    return 1.0 / (sim.timestep * sim.substeps)


__all__ = [
    "Explorer", "ExploreState", "SceneInputs", "SceneResult", "control_hz", "explore_scenes", "explorer_for",
    "make_explorer", "scene_inputs", "scene_key",
]
