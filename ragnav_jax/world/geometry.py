"""Host-side (NumPy) floor-plan geometry: occupancy rasters and reachability.

Used by the generator to guarantee reachable layouts and by tests and the explorer's coverage metric
as the ground truth of the reachable free area. The JAX side works on padded arrays (`arrays.py`).
"""

from __future__ import annotations

import dataclasses

import numpy as np
from scipy import ndimage

from ragnav_jax.world.scene import Scene

FLAT_HEIGHT = 0.05  # objects at most this tall (rugs, mats) do not block the robot


@dataclasses.dataclass(frozen=True)
class Grid:
    """A raster over the scene's bounds. Cell (i, j) has centre (x0 + (j + .5) r, y0 + (i + .5) r)."""

    origin: tuple[float, float]  # (x0, y0) of the lower-left corner
    resolution: float  # metres per cell
    shape: tuple[int, int]  # (rows = y, cols = x)

    def centers(self) -> tuple[np.ndarray, np.ndarray]:
        """(xs, ys) of cell centres, each (rows, cols)."""
        r = self.resolution
        xs = self.origin[0] + (np.arange(self.shape[1]) + 0.5) * r
        ys = self.origin[1] + (np.arange(self.shape[0]) + 0.5) * r
        return np.meshgrid(xs, ys)

    def cell_of(self, x: float, y: float) -> tuple[int, int]:
        j = int(np.floor((x - self.origin[0]) / self.resolution))
        i = int(np.floor((y - self.origin[1]) / self.resolution))
        return i, j


def make_grid(scene: Scene, resolution: float, pad: float = 0.5) -> Grid:
    xmin, ymin, xmax, ymax = scene.bounds
    x0, y0 = xmin - pad, ymin - pad
    cols = int(np.ceil((xmax + pad - x0) / resolution))
    rows = int(np.ceil((ymax + pad - y0) / resolution))
    return Grid((x0, y0), resolution, (rows, cols))


def segment_distance(px: np.ndarray, py: np.ndarray, a, b) -> np.ndarray:
    """Distance of points (any shape) to segment a-b."""
    ax, ay = a
    dx, dy = b[0] - ax, b[1] - ay
    denom = dx * dx + dy * dy
    t = np.clip(((px - ax) * dx + (py - ay) * dy) / max(denom, 1e-12), 0.0, 1.0)
    return np.hypot(px - (ax + t * dx), py - (ay + t * dy))


def inside_rooms(scene: Scene, xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
    inside = np.zeros(xs.shape, bool)
    for r in scene.rooms:
        inside |= (xs >= r.min[0]) & (xs <= r.max[0]) & (ys >= r.min[1]) & (ys <= r.max[1])
    return inside


def blocking_objects(scene: Scene):
    return [o for o in scene.objects if o.size[2] > FLAT_HEIGHT and o.position[2] - o.size[2] / 2 < 0.3]


def free_mask(scene: Scene, grid: Grid, inflate: float = 0.0, objects=None) -> np.ndarray:
    """Boolean (rows, cols): cell centre inside a room and at least `inflate` metres clear of every wall
    and every blocking object (flat things such as rugs, and things resting on others, do not block)."""
    xs, ys = grid.centers()
    free = inside_rooms(scene, xs, ys)
    for w in scene.walls:
        free &= segment_distance(xs, ys, w.a, w.b) > w.thickness / 2 + inflate
    for o in blocking_objects(scene) if objects is None else objects:
        hx, hy = o.size[0] / 2 + inflate, o.size[1] / 2 + inflate
        free &= ~((np.abs(xs - o.position[0]) <= hx) & (np.abs(ys - o.position[1]) <= hy))
    return free


def reachable_mask(scene: Scene, grid: Grid, inflate: float = 0.2, free: np.ndarray | None = None) -> np.ndarray:
    """Free cells 4-connected to the start cell (robot of radius `inflate`)."""
    if free is None:
        free = free_mask(scene, grid, inflate)
    labels, _ = ndimage.label(free)
    i, j = grid.cell_of(*scene.start.position)
    if not (0 <= i < grid.shape[0] and 0 <= j < grid.shape[1]) or labels[i, j] == 0:
        return np.zeros_like(free)
    return labels == labels[i, j]


def object_box_distance(o, xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
    """Planar distance from points to an object's footprint rectangle (0 inside)."""
    dx = np.maximum(np.abs(xs - o.position[0]) - o.size[0] / 2, 0.0)
    dy = np.maximum(np.abs(ys - o.position[1]) - o.size[1] / 2, 0.0)
    return np.hypot(dx, dy)


@dataclasses.dataclass(frozen=True)
class Reachability:
    rooms_reachable: dict[str, bool]  # room id -> some reachable free cell lies inside it
    objects_reachable: dict[str, bool]  # object id -> a reachable cell within `success_radius` of its box
    reachable_area: float  # m^2 of reachable free space (robot-centre cells)

    @property
    def all_ok(self) -> bool:
        return all(self.rooms_reachable.values()) and all(self.objects_reachable.values())


def reachability(
    scene: Scene, resolution: float = 0.1, robot_radius: float = 0.2, success_radius: float = 1.0
) -> Reachability:
    """Which rooms and objects the robot can reach from its start pose."""
    grid = make_grid(scene, resolution)
    reach = reachable_mask(scene, grid, robot_radius)
    xs, ys = grid.centers()
    rooms = {}
    for r in scene.rooms:
        inside = (xs > r.min[0]) & (xs < r.max[0]) & (ys > r.min[1]) & (ys < r.max[1])
        rooms[r.id] = bool((reach & inside).any())
    objs = {}
    rx, ry = xs[reach], ys[reach]
    for o in scene.objects:
        objs[o.id] = bool(rx.size and (object_box_distance(o, rx, ry) <= success_radius).any())
    return Reachability(rooms, objs, float(reach.sum()) * resolution**2)
