"""Synthetic exploration streams for memory tests (no simulator): a path through every room on the free-space
grid, poses every ~0.1 m, a look-around at each room centre, visibility from a NumPy field-of-view + wall
line-of-sight check. Also a sanity test of the helper itself."""

from __future__ import annotations

import math
from collections import deque

import numpy as np

from ragnav_jax.sim.stream import ExplorationStream
from ragnav_jax.world import geometry
from ragnav_jax.world.scene import Scene

FOV = math.radians(90.0)
RANGE = 6.0


def _bfs(free: np.ndarray, start: tuple[int, int], goal: tuple[int, int]) -> list[tuple[int, int]]:
    prev = {start: None}
    q = deque([start])
    while q:
        c = q.popleft()
        if c == goal:
            break
        for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            n = (c[0] + di, c[1] + dj)
            if 0 <= n[0] < free.shape[0] and 0 <= n[1] < free.shape[1] and free[n] and n not in prev:
                prev[n] = c
                q.append(n)
    if goal not in prev:
        return []
    path, c = [], goal
    while c is not None:
        path.append(c)
        c = prev[c]
    return path[::-1]


def line_of_sight(scene: Scene, p, q, step: float = 0.02) -> bool:
    """No wall between p and q (points sampled along the segment)."""
    n = max(2, int(math.dist(p, q) / step))
    t = np.linspace(0.0, 1.0, n)[:, None]
    xs, ys = p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])  # (n, 1)
    a, b, half = _wall_arrays(scene)
    dx, dy = b[:, 0] - a[:, 0], b[:, 1] - a[:, 1]  # (W,)
    u = np.clip(((xs - a[:, 0]) * dx + (ys - a[:, 1]) * dy) / np.maximum(dx * dx + dy * dy, 1e-12), 0.0, 1.0)
    d = np.hypot(xs - (a[:, 0] + u * dx), ys - (a[:, 1] + u * dy))  # (n, W)
    return not (d <= half).any()


_WALLS: dict[int, tuple] = {}


def _wall_arrays(scene: Scene):
    key = id(scene)
    if key not in _WALLS:
        _WALLS[key] = (np.array([w.a for w in scene.walls], float).reshape(-1, 2),
                       np.array([w.b for w in scene.walls], float).reshape(-1, 2),
                       np.array([w.thickness / 2 for w in scene.walls], float))
    return _WALLS[key]


def synthetic_stream(scene: Scene, res: float = 0.1, spin_steps: int = 8) -> ExplorationStream:
    grid = geometry.make_grid(scene, res)
    reach = geometry.reachable_mask(scene, grid, 0.25)
    xs, ys = grid.centers()
    cells = np.argwhere(reach)

    def nearest_cell(x, y):
        d = (xs[reach] - x) ** 2 + (ys[reach] - y) ** 2
        return tuple(int(v) for v in cells[int(np.argmin(d))])

    cur = grid.cell_of(*scene.start.position)
    cur = nearest_cell(*scene.start.position) if not reach[cur] else cur
    todo = sorted(scene.rooms, key=lambda r: r.id)
    poses = []
    while todo:
        # greedy: nearest unvisited room centre
        todo.sort(key=lambda r: math.dist(r.center, (xs[cur], ys[cur])))
        room = todo.pop(0)
        goal = nearest_cell(*room.center)
        path = _bfs(reach, cur, goal)
        for a, b in zip(path, path[1:]):
            yaw = math.atan2(b[0] - a[0], b[1] - a[1])
            poses.append((xs[b], ys[b], yaw))
        cur = goal
        yaw0 = poses[-1][2] if poses else scene.start.yaw
        for k in range(spin_steps):
            poses.append((xs[cur], ys[cur], yaw0 + 2 * math.pi * (k + 1) / spin_steps))
    poses = poses[::1] or [(scene.start.position[0], scene.start.position[1], scene.start.yaw)]
    T, n_obj = len(poses), len(scene.objects)
    vis = np.zeros((T, n_obj), bool)
    dist = np.zeros((T, n_obj), np.float32)
    bear = np.zeros((T, n_obj), np.float32)
    for t, (x, y, yaw) in enumerate(poses):
        for o_i, o in enumerate(scene.objects):
            dx, dy = o.position[0] - x, o.position[1] - y
            d = math.hypot(dx, dy)
            b = (math.atan2(dy, dx) - yaw + math.pi) % (2 * math.pi) - math.pi
            dist[t, o_i], bear[t, o_i] = d, b
            vis[t, o_i] = d < RANGE and abs(b) < FOV / 2 and line_of_sight(scene, (x, y), o.position[:2])
    pose = np.array([(x, y, 0.1, yaw) for x, y, yaw in poses], np.float32)
    return ExplorationStream(
        scene=scene.name, t=np.arange(T, dtype=np.int32), pose=pose, lidar=np.full((T, 4), 8.0, np.float32),
        lidar_angles=np.linspace(-math.pi, math.pi, 4, endpoint=False).astype(np.float32), visible=vis,
        distance=dist, bearing=bear, object_ids=tuple(o.id for o in scene.objects),
    )


def test_synthetic_stream_sees_through_doors_not_walls(apartment):
    s = synthetic_stream(apartment)
    assert s.visible.any(axis=0).mean() > 0.8  # the tour sees most objects
    x, y = s.pose[0, :2]
    for o_i in np.flatnonzero(s.visible[0]):
        assert line_of_sight(apartment, (x, y), apartment.objects[o_i].position[:2])
