"""Exploration coverage, measured on the host against the scene's ground truth (independent of the
explorer's own map): the share of the reachable free area that some lidar scan covered.

Reachable free area: `world.geometry.reachable_mask` at 0.1 m for a robot of the simulated radius (cells
its centre can reach from the start). A cell counts as covered by a scan when it lies within the scan's
field of view and no farther from the sensor than the shorter of the two rays that bracket its bearing
(a conservative fill of the scan polygon).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ragnav_jax.world import geometry
from ragnav_jax.world.scene import Scene

COVERAGE_RES = 0.1  # metres per ground-truth cell


@dataclasses.dataclass(frozen=True)
class Coverage:
    reachable: np.ndarray  # (rows, cols) bool ground-truth reachable free cells
    covered: np.ndarray  # (rows, cols) bool cells some scan covered
    grid: geometry.Grid

    @property
    def reachable_area(self) -> float:
        return float(self.reachable.sum()) * self.grid.resolution**2

    @property
    def covered_area(self) -> float:
        return float((self.covered & self.reachable).sum()) * self.grid.resolution**2

    @property
    def fraction(self) -> float:
        n = int(self.reachable.sum())
        return float((self.covered & self.reachable).sum()) / n if n else 1.0


def scan_cover(
    xs: np.ndarray, ys: np.ndarray, pose: np.ndarray, ranges: np.ndarray, angles: np.ndarray, chunk: int = 64
) -> np.ndarray:
    """(N,) bool: which points (xs, ys: (N,)) lie inside at least one scan.

    pose: (T, 3) sensor x, y, yaw; ranges: (T, L) metres; angles: (L,) increasing ray angles relative to
    the heading (a full circle when they are evenly spaced over 2 pi).
    """
    L = angles.shape[0]
    full = L > 1 and np.isclose((angles[1] - angles[0]) * L, 2 * np.pi, atol=1e-4)
    step = (angles[1] - angles[0]) if L > 1 else 1.0
    out = np.zeros(xs.shape, bool)
    for s in range(0, pose.shape[0], chunk):
        p, r = pose[s : s + chunk], ranges[s : s + chunk]
        dx = xs[None, :] - p[:, 0:1]
        dy = ys[None, :] - p[:, 1:2]
        dist = np.hypot(dx, dy)
        rel = np.arctan2(dy, dx) - p[:, 2:3] - angles[0]  # bearing measured from the first ray
        if full:
            rel = np.mod(rel, 2 * np.pi)
            i0 = np.floor(rel / step).astype(int) % L
            i1 = (i0 + 1) % L
            inside_fov = np.ones_like(rel, bool)
        else:
            rel = np.mod(rel + np.pi, 2 * np.pi) - np.pi
            i0 = np.clip(np.floor(rel / step).astype(int), 0, L - 1)
            i1 = np.clip(i0 + 1, 0, L - 1)
            inside_fov = (rel >= 0) & (rel <= angles[-1] - angles[0])
        rows = np.arange(p.shape[0])[:, None]
        limit = np.minimum(r[rows, i0], r[rows, i1])
        out |= np.any(inside_fov & (dist <= limit), axis=0)
    return out


def coverage(scene: Scene, pose: np.ndarray, ranges: np.ndarray, angles: np.ndarray, robot_radius: float) -> Coverage:
    """Coverage of one scene by its scans (true poses (T, 3), ranges (T, L))."""
    grid = geometry.make_grid(scene, COVERAGE_RES)
    reach = geometry.reachable_mask(scene, grid, robot_radius)
    xs, ys = grid.centers()
    covered = np.zeros(grid.shape, bool)
    if pose.shape[0]:
        covered[reach] = scan_cover(xs[reach], ys[reach], pose, ranges, angles)
    return Coverage(reachable=reach, covered=covered, grid=grid)


# ----------------------------------------------------------------------------------------------------
# Rooms entered and rooms whose objects were seen: lidar coverage can read 1.0 while rooms were only
# scanned through their doorways, so the summary reports both next to it.


def densify(xy: np.ndarray, step: float) -> np.ndarray:
    """(M, 2) points along the polyline xy (T, 2), consecutive ones at most `step` metres apart; the
    vertices are kept (M = T when T < 2)."""
    xy = np.asarray(xy, float)[:, :2]
    if xy.shape[0] < 2:
        return xy
    seg = np.diff(xy, axis=0)  # (T-1, 2)
    n = np.maximum(np.ceil(np.hypot(seg[:, 0], seg[:, 1]) / step).astype(int), 1)  # samples per segment
    idx = np.repeat(np.arange(seg.shape[0]), n)
    frac = (np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)) / np.repeat(n, n)
    return np.concatenate([xy[idx] + frac[:, None] * seg[idx], xy[-1:]])


def rooms_entered(scene: Scene, pose: np.ndarray, margin: float = 0.0, step: float = 0.05) -> np.ndarray:
    """(R,) bool in `scene.rooms` order: the true trajectory passed at least `margin` metres inside room r.

    pose: (T, 2+) true x, y (further columns such as yaw are ignored) of consecutive records; the
    straight path between two records is sampled every `step` metres, so a room crossed between
    records counts as entered.
    """
    pts = densify(pose, step)  # (M, 2)
    out = np.zeros(len(scene.rooms), bool)
    for r, room in enumerate(scene.rooms):
        inside = (pts[:, 0] >= room.min[0] + margin) & (pts[:, 0] <= room.max[0] - margin)
        inside &= (pts[:, 1] >= room.min[1] + margin) & (pts[:, 1] <= room.max[1] - margin)
        out[r] = bool(inside.any())
    return out


def room_objects_unseen(scene: Scene, visible: np.ndarray) -> np.ndarray:
    """(R,) bool in `scene.rooms` order: room r holds objects and the camera saw none of them.

    visible: (T, O) bool camera visibility per record, columns in `scene.objects` order.
    """
    R, O = len(scene.rooms), len(scene.objects)
    seen = np.asarray(visible, bool).reshape(-1, O).any(0)  # (O,)
    held = np.array([[o.room == r.id for o in scene.objects] for r in scene.rooms], bool).reshape(R, O)
    return held.any(1) & ~(held & seen[None, :]).any(1)
