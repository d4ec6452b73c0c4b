"""Waypoint-following controller (the local planner of exploration now and of navigation later) and the
control step that runs several physics steps per command.

The controller is pure pursuit on a padded waypoint list: it aims at the first waypoint at least
`lookahead` metres away (never going back along the list, skipping ahead at most SKIP_WINDOW points), drives straight at it in the world frame
(the base is holonomic: slide x, slide y, hinge yaw), turns the heading toward the motion so the
forward camera looks where the robot goes, and slows near the last waypoint. Waypoints come from grid
paths with clearance from mapped obstacles; aiming at most `lookahead` ahead keeps the chord close to
the path around corners, so the robot does not cut through walls, and contacts (with the scan-aware
slow-down) keep it out of anything the map missed.
"""

from __future__ import annotations

import jax
import jax.numpy as jnp
from flax import struct
from mujoco import mjx

from ragnav_jax.sim.model import mjx_step
from ragnav_jax.sim.sensors import wrap_angle

SKIP_WINDOW = 6  # waypoints ahead of the current one searched for the nearest (a short stretch of path)
SLOW_GAP = 0.4  # metres of free space ahead below which the scan-aware controller slows down


@struct.dataclass
class Path:
    """A padded waypoint list and the controller's progress along it."""

    points: jax.Array  # (P, 2) float32 world x, y; entries past n repeat the last point
    n: jax.Array  # () int32 number of waypoints (0: no path, stand still)
    index: jax.Array  # () int32 waypoint currently aimed at

    @staticmethod
    def empty(max_len: int) -> Path:
        return Path(jnp.zeros((max_len, 2), jnp.float32), jnp.int32(0), jnp.int32(0))

    @staticmethod
    def of(points: jax.Array, n: jax.Array) -> Path:
        return Path(points.astype(jnp.float32), jnp.asarray(n, jnp.int32), jnp.int32(0))


def follow(
    path: Path, pose: jax.Array, lookahead: float, max_speed: float, max_yaw_rate: float, slow_radius: float = 0.5,
    scan: tuple[jax.Array, jax.Array] | None = None, robot_radius: float = 0.0, look: jax.Array | float = 0.0,
) -> tuple[jax.Array, Path]:
    """One control decision: ((3,) velocity command vx, vy, yaw rate in the world frame; updated path).

    pose: (3,) x, y, yaw. scan: optional (ranges (L,), angles (L,)) of the latest lidar scan; with it
    the robot slows down when something lies close ahead of its motion (so bumping into what the map
    missed stays gentle). Plain path following passes no scan and casts no rays. look: heading offset
    from the direction of motion in radians (the holonomic base can look sideways while it drives).
    """
    P = path.points.shape[0]
    ids = jnp.arange(P)
    last = jnp.maximum(path.n - 1, 0)
    d = jnp.linalg.norm(path.points - pose[None, :2], axis=-1)
    # Skip to the nearest waypoint a little way ahead (the robot may have been pushed past some), then
    # aim at the first one at least `lookahead` away.
    window = (ids >= path.index) & (ids <= jnp.minimum(path.index + SKIP_WINDOW, last))
    start = jnp.argmin(jnp.where(window, d, jnp.inf)).astype(jnp.int32)
    beyond = (ids >= start) & (ids <= last) & (d >= lookahead)
    index = jnp.where(jnp.any(beyond), jnp.argmax(beyond), last).astype(jnp.int32)
    target = path.points[index]
    e = target - pose[:2]
    dist = jnp.linalg.norm(e)
    heading_err = wrap_angle(jnp.arctan2(e[1], e[0]) + look - pose[2])
    # Full speed when facing the motion, a crawl when facing away (turn mostly in place).
    align = 0.2 + 0.8 * jnp.maximum(jnp.cos(heading_err), 0.0)
    speed = max_speed * align * jnp.where(index >= last, jnp.minimum(dist / slow_radius, 1.0), 1.0)
    if scan is not None:
        ranges, angles = scan
        motion = jnp.arctan2(e[1], e[0]) - pose[2]
        ahead = jnp.cos(angles - motion) > 0.5  # rays within 60 degrees of the motion
        gap = jnp.min(jnp.where(ahead, ranges, jnp.inf)) - robot_radius
        speed = speed * jnp.clip(gap / SLOW_GAP, 0.25, 1.0)
    v = e / jnp.maximum(dist, 1e-6) * speed
    wz = jnp.clip(3.0 * heading_err, -max_yaw_rate, max_yaw_rate) * (dist > 0.05)
    cmd = jnp.where(path.n > 0, jnp.stack([v[0], v[1], wz]), jnp.zeros(3))
    return cmd.astype(jnp.float32), path.replace(index=index)


def physics(m: mjx.Model, d: mjx.Data, ctrl: jax.Array, substeps: int) -> tuple[mjx.Data, jax.Array]:
    """Applies a velocity command for `substeps` physics steps: (data, deepest penetration in metres)."""

    def body(_, c):
        d, pen = c
        d = mjx_step(m, d)
        dist = d._impl.contact.dist
        pen = jnp.maximum(pen, -jnp.min(dist, initial=0.0)) if dist.size else pen
        return d, pen

    return jax.lax.fori_loop(0, substeps, body, (d.replace(ctrl=ctrl), jnp.float32(0.0)))
