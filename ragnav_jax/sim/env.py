"""A brax environment on the padded MJX template: point-goal navigation in a set of scenes.

`NavEnv` implements `brax.envs.Env`, so brax's wrappers (vmap, episode, auto-reset, domain
randomisation of the vmapped kind) and trainers work on it; a trainer could learn a local policy.
Each reset picks a scene, a start and a goal among the scene's reachable cells; the scene's geometry
lives in `state.info` and is swapped into the template model at every step (no recompilation for
another scene). Every step runs `substeps` physics steps, a lidar scan (the observation) and the
camera's visibility check (a metric), i.e. a full sensing step of the robot.

Observation (size L + 5): lidar ranges / range (L), goal in the robot frame / 10 m (2), base velocity
(vx, vy in the robot frame, yaw rate) (3). Action (3,) in [-1, 1]: forward and sideways speed as a
share of max_speed, yaw rate as a share of max_yaw_rate.
"""

from __future__ import annotations

from collections.abc import Sequence

import jax
import jax.numpy as jnp
import numpy as np
from brax.envs.base import Env, State
from mujoco import mjx

from ragnav_jax.config import SimConfig
from ragnav_jax.sim.controller import physics
from ragnav_jax.sim.model import GEOMETRY_FIELDS, build_template, initial_data, scene_geometry, slot_counts
from ragnav_jax.sim.sensors import camera_visibility, lidar_angles, lidar_scan
from ragnav_jax.world import geometry as world_geometry
from ragnav_jax.world.scene import Scene

GOAL_RADIUS = 0.3  # metres: an episode succeeds when the robot's centre is this close to the goal
CANDIDATES = 256  # start/goal candidate cells kept per scene


def reachable_points(scene: Scene, robot_radius: float, k: int = CANDIDATES, seed: int = 0) -> np.ndarray:
    """(k, 2) float32 cell centres reachable from the scene's start (drawn with repetition when fewer)."""
    grid = world_geometry.make_grid(scene, 0.1)
    reach = world_geometry.reachable_mask(scene, grid, robot_radius + 0.05)
    xs, ys = grid.centers()
    pts = np.stack([xs[reach], ys[reach]], -1)
    if len(pts) == 0:
        pts = np.array([scene.start.position])
    rng = np.random.default_rng(seed)
    return pts[rng.choice(len(pts), size=k, replace=len(pts) < k)].astype(np.float32)


class NavEnv(Env):
    """Point-goal navigation over a scene set (see the module docstring)."""

    def __init__(self, scenes: Sequence[Scene], sim: SimConfig, with_camera: bool = True):
        if not scenes:
            raise ValueError("NavEnv needs at least one scene")
        self.sim = sim
        self.with_camera = with_camera
        self.model = build_template(*slot_counts(scenes), sim)
        self.geometry = scene_geometry(scenes, self.model)  # (S, G, ...)
        self.points = jnp.asarray(np.stack([reachable_points(s, sim.robot_radius) for s in scenes]))  # (S, K, 2)
        n_obj = self.model.layout.objects
        pos = np.zeros((len(scenes), n_obj, 3), np.float32)
        size = np.zeros((len(scenes), n_obj, 3), np.float32)
        mask = np.zeros((len(scenes), n_obj), bool)
        for b, s in enumerate(scenes):
            for i, o in enumerate(s.objects):
                pos[b, i], size[b, i], mask[b, i] = o.position, o.size, True
        self.obj_pos, self.obj_size, self.obj_mask = jnp.asarray(pos), jnp.asarray(size), jnp.asarray(mask)
        self.obj_geom = jnp.arange(self.model.layout.obj_geom0, self.model.layout.obj_geom0 + n_obj, dtype=jnp.int32)
        self.angles = jnp.asarray(lidar_angles(sim))
        self.num_scenes = len(scenes)

    # -- brax interface -------------------------------------------------------------------------------
    @property
    def observation_size(self) -> int:  # fixed: brax's default would run an un-jitted reset
        return int(self.angles.shape[0]) + 5

    @property
    def action_size(self) -> int:
        return 3

    @property
    def backend(self) -> str:
        return "mjx"

    @property
    def dt(self) -> float:
        return self.sim.timestep * self.sim.substeps

    def scene_model(self, scene: jax.Array) -> mjx.Model:
        """The template with scene `scene`'s geometry (traced index; batched under vmap)."""
        return self.model.mx.tree_replace({k: getattr(self.geometry, k)[scene] for k in GEOMETRY_FIELDS})

    def reset(self, rng: jax.Array) -> State:
        k_scene, k_start, k_goal = jax.random.split(rng, 3)
        scene = jax.random.randint(k_scene, (), 0, self.num_scenes)
        K = self.points.shape[1]
        start = self.points[scene, jax.random.randint(k_start, (), 0, K)]
        goal = self.points[scene, jax.random.randint(k_goal, (), 0, K)]
        yaw = jax.random.uniform(k_start, (), minval=-jnp.pi, maxval=jnp.pi)
        m = self.scene_model(scene)
        d = initial_data(m, jnp.stack([start[0], start[1], yaw]))
        info = {"scene": scene, "goal": goal}
        obs, dist, visible = self._observe(m, d, scene, goal)
        zero = jnp.float32(0.0)
        metrics = {"distance": dist, "visible_objects": visible, "penetration": zero, "success": zero}
        return State(pipeline_state=d, obs=obs, reward=zero, done=zero, metrics=metrics, info=info)

    def step(self, state: State, action: jax.Array) -> State:
        scene, goal = state.info["scene"], state.info["goal"]
        m = self.scene_model(scene)
        d = state.pipeline_state
        yaw = d.qpos[2]
        a = jnp.clip(action, -1.0, 1.0)
        c, s = jnp.cos(yaw), jnp.sin(yaw)
        v = self.sim.max_speed * a[:2]
        ctrl = jnp.stack([c * v[0] - s * v[1], s * v[0] + c * v[1], self.sim.max_yaw_rate * a[2]])
        prev = jnp.linalg.norm(d.qpos[:2] - goal)
        d, pen = physics(m, d, ctrl, self.sim.substeps)
        obs, dist, visible = self._observe(m, d, scene, goal)
        success = dist < GOAL_RADIUS
        reward = (prev - dist) - 10.0 * pen + success.astype(jnp.float32)
        metrics = dict(state.metrics)  # keep the incoming keys: brax's wrappers scan over them
        metrics.update(distance=dist, visible_objects=visible, penetration=pen, success=success.astype(jnp.float32))
        return state.replace(
            pipeline_state=d, obs=obs, reward=reward.astype(jnp.float32), done=success.astype(jnp.float32),
            metrics=metrics,
        )

    # -- helpers --------------------------------------------------------------------------------------
    def _observe(self, m: mjx.Model, d: mjx.Data, scene: jax.Array, goal: jax.Array):
        sim = self.sim
        rb = self.model.layout.robot_body
        ranges = lidar_scan(m, d, self.angles, sim.lidar_height, sim.lidar_range, rb)
        x, y, yaw = d.qpos[0], d.qpos[1], d.qpos[2]
        c, s = jnp.cos(yaw), jnp.sin(yaw)
        rel = goal - jnp.stack([x, y])
        goal_body = jnp.stack([c * rel[0] + s * rel[1], -s * rel[0] + c * rel[1]])
        vel = jnp.stack([c * d.qvel[0] + s * d.qvel[1], -s * d.qvel[0] + c * d.qvel[1], d.qvel[2]])
        obs = jnp.concatenate([ranges / sim.lidar_range, goal_body / 10.0, vel]).astype(jnp.float32)
        if self.with_camera:
            vis = camera_visibility(
                m, d, self.obj_pos[scene], self.obj_size[scene], self.obj_mask[scene], self.obj_geom, sim, rb
            )
            visible = jnp.sum(vis.visible).astype(jnp.float32)
        else:
            visible = jnp.float32(0.0)
        return obs, jnp.linalg.norm(rel).astype(jnp.float32), visible
