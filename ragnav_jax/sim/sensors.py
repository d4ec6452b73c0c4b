"""Robot sensors in JAX: 2-D lidar and a forward camera's object visibility (MJX ray casting), odometry.

All functions take one scene's MJX model and data (vmap from outside); rays ignore the robot's own
body. Rays see every geom of the scene: walls, objects and the floor (which a horizontal lidar never
meets); parked slots sit far below the house where no ray goes.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import jax
import jax.numpy as jnp
import numpy as np
from mujoco import mjx

from ragnav_jax.config import SimConfig
from ragnav_jax.sim.model import mjx_ray

SIDE_POINTS = 0.35  # camera targets on an object's top face: the middle and +-35% of its longer extent


def lidar_angles(sim: SimConfig) -> np.ndarray:
    """(L,) float32 ray angles relative to the heading: a full circle, or a fan centred on the heading."""
    L = sim.lidar_rays
    if sim.lidar_fov_deg >= 360.0:
        return (-math.pi + 2 * math.pi * np.arange(L) / L).astype(np.float32)
    half = math.radians(sim.lidar_fov_deg) / 2
    return np.linspace(-half, half, L).astype(np.float32)


def wrap_angle(a: jax.Array) -> jax.Array:
    """Angles wrapped to (-pi, pi]."""
    return jnp.arctan2(jnp.sin(a), jnp.cos(a))


def pose_of(d: mjx.Data) -> jax.Array:
    """(3,) x, y, yaw of the planar robot (its three joints)."""
    return d.qpos[:3]


def lidar_scan(m: mjx.Model, d: mjx.Data, angles: jax.Array, height: float, max_range: float, robot_body: int) -> jax.Array:
    """(L,) ranges in metres from the robot's centre at `height`; max_range where nothing is hit within it."""
    x, y, yaw = pose_of(d)
    pnt = jnp.stack([x, y, jnp.asarray(height, jnp.float32)])
    theta = yaw + angles
    vec = jnp.stack([jnp.cos(theta), jnp.sin(theta), jnp.zeros_like(theta)], -1)
    dist, _ = jax.vmap(lambda v: mjx_ray(m, d, pnt, v, bodyexclude=robot_body))(vec)
    return jnp.where((dist < 0) | (dist > max_range), max_range, dist).astype(jnp.float32)


class Visibility(NamedTuple):
    visible: jax.Array  # (O,) bool: inside the field of view and range, line of sight clear
    distance: jax.Array  # (O,) float32 planar metres from the camera to the object's centre
    bearing: jax.Array  # (O,) float32 radians of the centre relative to the heading, in (-pi, pi]


def camera_visibility(
    m: mjx.Model, d: mjx.Data, obj_pos: jax.Array, obj_size: jax.Array, obj_mask: jax.Array, obj_geom: jax.Array,
    sim: SimConfig, robot_body: int,
) -> Visibility:
    """Which objects the forward camera sees.

    obj_pos, obj_size: (O, 3) box centre and full extents; obj_mask: (O,) bool; obj_geom: (O,) int32
    geom ids. An object in the field of view (horizontal, camera_fov_deg) and within camera_range is
    visible when a ray from the camera to one of four points first meets the object itself: three on
    its top face (the middle, and SIDE_POINTS of its longer extent either side of it) and the middle of
    the side facing the camera.
    """
    x, y, yaw = pose_of(d)
    in_view, distance, bearing = _in_view(x, y, yaw, obj_pos, obj_mask, sim)
    los = _line_of_sight(m, d, obj_pos, obj_size, obj_geom, sim, robot_body)
    return Visibility(in_view & los, distance, bearing)


def look_around(
    m: mjx.Model, d: mjx.Data, obj_pos: jax.Array, obj_size: jax.Array, obj_mask: jax.Array, obj_geom: jax.Array,
    sim: SimConfig, robot_body: int, headings: jax.Array,
) -> tuple[jax.Array, jax.Array]:
    """`camera_visibility` at each of `headings` (H,) yaws from the robot's position in d, a turn in place:
    ((O,) bool seen at some heading, (O,) float32 distance). The camera's position does not turn with it, so
    each line of sight is cast once for all headings."""
    x, y, _ = pose_of(d)
    in_view, distance, _ = jax.vmap(lambda h: _in_view(x, y, h, obj_pos, obj_mask, sim))(headings)
    los = _line_of_sight(m, d, obj_pos, obj_size, obj_geom, sim, robot_body)
    return jnp.any(in_view, 0) & los, distance[0]


def _in_view(x, y, yaw, obj_pos: jax.Array, obj_mask: jax.Array, sim: SimConfig):
    """((O,) in the field of view and range, (O,) planar distance, (O,) bearing) of the camera at x, y, yaw."""
    rel = obj_pos[:, :2] - jnp.stack([x, y])[None]
    distance = jnp.linalg.norm(rel, axis=-1)
    bearing = wrap_angle(jnp.arctan2(rel[:, 1], rel[:, 0]) - yaw)
    in_view = obj_mask & (distance <= sim.camera_range) & (jnp.abs(bearing) <= math.radians(sim.camera_fov_deg) / 2)
    return in_view, distance.astype(jnp.float32), bearing


def _line_of_sight(m: mjx.Model, d: mjx.Data, obj_pos: jax.Array, obj_size: jax.Array, obj_geom: jax.Array,
                   sim: SimConfig, robot_body: int) -> jax.Array:
    """(O,) bool: a ray from the camera to one of an object's four target points first meets the object."""
    x, y, _ = pose_of(d)
    cam = jnp.stack([x, y, jnp.asarray(sim.camera_height, jnp.float32)])
    # Three points on the top face: its middle and two points along its longer side.
    top = obj_pos.at[:, 2].add(obj_size[:, 2] / 2 - jnp.minimum(0.01, obj_size[:, 2] / 4))
    along = jnp.where((obj_size[:, 0] >= obj_size[:, 1])[:, None], jnp.array([1.0, 0.0, 0.0]), jnp.array([0.0, 1.0, 0.0]))
    offset = SIDE_POINTS * jnp.max(obj_size[:, :2], axis=1, keepdims=True) * along
    # ... and the middle of the side facing the camera (things on top may hide the top face).
    to_cam = cam[None, :2] - obj_pos[:, :2]
    x_side = jnp.abs(to_cam[:, 0]) * obj_size[:, 1] >= jnp.abs(to_cam[:, 1]) * obj_size[:, 0]
    half = obj_size[:, :2] / 2 - 0.01
    face = jnp.where(x_side[:, None], jnp.stack([jnp.sign(to_cam[:, 0]) * half[:, 0], 0 * half[:, 1]], -1),
                     jnp.stack([0 * half[:, 0], jnp.sign(to_cam[:, 1]) * half[:, 1]], -1))
    side = obj_pos.at[:, :2].add(face)
    targets = jnp.stack([top, top - offset, top + offset, side], 1)  # (O, 4, 3)

    def clear(target, geom):
        v = target - cam
        n = jnp.linalg.norm(v)
        dist, gid = mjx_ray(m, d, cam, v / jnp.maximum(n, 1e-6), bodyexclude=robot_body)
        return (gid == geom) | (dist < 0) | (dist >= n - 1e-3)

    return jax.vmap(jax.vmap(clear, in_axes=(0, None)))(targets, obj_geom).any(-1)


def odometry(pose: jax.Array, z: float, key: jax.Array, noise: tuple[float, float]) -> jax.Array:
    """(4,) x, y, z, yaw as recorded, with optional Gaussian noise (std noise[0] on x, y; noise[1] on yaw)."""
    n = jax.random.normal(key, (3,)) * jnp.array([noise[0], noise[0], noise[1]], jnp.float32)
    noisy = pose + n
    return jnp.stack([noisy[0], noisy[1], jnp.asarray(z, jnp.float32), noisy[2]])
