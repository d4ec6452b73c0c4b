"""Occupancy map, frontiers and grid paths of one scene, in JAX with static shapes (vmap from outside).

Two grids share one frame. The map raster (resolution `map_resolution`, shape (H, W)) holds what the
lidar saw: `seen` (a ray passed through the cell) and `hit` (a ray ended in it). Cells outside the
scene's padded bounds (`inside` False) count as obstacles, so a padded batch behaves like each scene
alone. The paper's exploration grid (resolution `grid_resolution` = k map cells, shape (Hc, Wc))
clusters frontier cells into regions.

Definitions (paper, section "Embodied Data Acquisition and Autonomous Exploration"):
- free = seen and not hit; unknown = inside, not seen, not hit; occupied = hit or outside.
- frontier cell: a free map cell 4-connected to an unknown one.
- frontier region: a 4-connected component of exploration-grid cells holding reachable frontier cells
  (breadth-first clustering); regions with fewer than `min_cells` frontier cells are noise.
- frontier point f_i: the region's geometric centre (mean of its frontier cells); the robot drives to
  the region's reachable frontier cell nearest to it.
Paths run through free cells only: cells with `radius` cells of clearance from occupied ones cost 1 per
cell, other free cells `TIGHT_COST` (so the robot can leave a tight spot but prefers clearance).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import NamedTuple

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.world.scene import Scene

TIGHT_COST = 10.0
BIG = 1e9  # "infinite" distance, kept finite so arithmetic stays NaN-free
GRID_PAD = 0.5  # metres of map around a scene's bounds


class GridSpec(NamedTuple):
    """Static grid facts of a batch."""

    res: float  # metres per map cell
    shape: tuple[int, int]  # (H, W) map cells, multiples of k
    k: int  # map cells per exploration-grid cell along each axis
    radius: float  # clearance radius in map cells (robot radius + clearance) / res

    @property
    def coarse_shape(self) -> tuple[int, int]:
        return (self.shape[0] // self.k, self.shape[1] // self.k)


def grid_spec(scenes: Sequence[Scene], map_res: float, grid_res: float, clearance_m: float) -> GridSpec:
    """The smallest map that holds every scene's bounds plus GRID_PAD, in whole exploration cells."""
    k = int(round(grid_res / map_res))
    H = W = k
    for s in scenes:
        xmin, ymin, xmax, ymax = s.bounds
        W = max(W, math.ceil((xmax - xmin + 2 * GRID_PAD) / map_res - 1e-6))
        H = max(H, math.ceil((ymax - ymin + 2 * GRID_PAD) / map_res - 1e-6))
    H, W = -(-H // k) * k, -(-W // k) * k
    return GridSpec(float(map_res), (H, W), k, clearance_m / map_res)


def scene_frame(scene: Scene, spec: GridSpec) -> tuple[np.ndarray, np.ndarray]:
    """(origin (2,), inside (H, W) bool) of one scene's map; depends on the scene only, not the batch."""
    xmin, ymin, xmax, ymax = scene.bounds
    origin = np.array([xmin - GRID_PAD, ymin - GRID_PAD], np.float32)
    w = math.ceil((xmax - xmin + 2 * GRID_PAD) / spec.res - 1e-6)
    h = math.ceil((ymax - ymin + 2 * GRID_PAD) / spec.res - 1e-6)
    inside = np.zeros(spec.shape, bool)
    inside[:h, :w] = True
    return origin, inside


def cell_centers(spec: GridSpec, origin: jax.Array) -> jax.Array:
    """(H, W, 2) world x, y of map cell centres."""
    H, W = spec.shape
    xs = origin[0] + (jnp.arange(W, dtype=jnp.float32) + 0.5) * spec.res
    ys = origin[1] + (jnp.arange(H, dtype=jnp.float32) + 0.5) * spec.res
    return jnp.stack(jnp.meshgrid(xs, ys), axis=-1)


def cell_of(spec: GridSpec, origin: jax.Array, xy: jax.Array) -> jax.Array:
    """(..., 2) int32 (i = row/y, j = col/x) of points (..., 2); may lie outside the grid."""
    o = jnp.reshape(origin, (1,) * (xy.ndim - 1) + (2,))
    ij = jnp.floor((xy - o) / spec.res).astype(jnp.int32)
    return ij[..., ::-1]


def _shift(x: jax.Array, di: int, dj: int, fill) -> jax.Array:
    """y[i, j] = x[i + di, j + dj], `fill` where that falls outside."""
    H, W = x.shape
    p = max(abs(di), abs(dj))
    if p == 0:
        return x
    xp = jnp.pad(x, p, constant_values=fill)
    return jax.lax.dynamic_slice(xp, (p + di, p + dj), (H, W))


NEIGHBORS4 = ((-1, 0), (1, 0), (0, -1), (0, 1))
NEIGHBORS8 = NEIGHBORS4 + ((-1, -1), (-1, 1), (1, -1), (1, 1))


def disc_offsets(radius: float) -> list[tuple[int, int]]:
    r = int(math.floor(radius))
    return [(di, dj) for di in range(-r, r + 1) for dj in range(-r, r + 1) if di * di + dj * dj <= radius * radius + 1e-9]


def update_map(
    spec: GridSpec, origin: jax.Array, seen: jax.Array, hit: jax.Array, pose: jax.Array, ranges: jax.Array,
    angles: jax.Array, max_range: float,
) -> tuple[jax.Array, jax.Array]:
    """Marks the cells a lidar scan passed through (seen) and ended in (hit).

    pose: (3,) x, y, yaw; ranges: (L,) metres (max_range where nothing was hit); angles: (L,) relative
    to the heading. Samples every half cell along each ray, stopping half a cell short of the hit.
    """
    H, W = spec.shape
    step = spec.res / 2
    S = int(math.ceil(max_range / step))
    s = (jnp.arange(S, dtype=jnp.float32) + 0.5) * step  # (S,)
    theta = pose[2] + angles  # (L,)
    u = jnp.stack([jnp.cos(theta), jnp.sin(theta)], -1)  # (L, 2)
    pts = pose[None, None, :2] + s[None, :, None] * u[:, None, :]  # (L, S, 2)
    free = s[None, :] < ranges[:, None] - step / 2  # (L, S)

    def flat(ij, valid):
        ok = valid & (ij[..., 0] >= 0) & (ij[..., 0] < H) & (ij[..., 1] >= 0) & (ij[..., 1] < W)
        return jnp.where(ok, ij[..., 0] * W + ij[..., 1], H * W).ravel()

    idx_free = flat(cell_of(spec, origin, pts), free)
    end = pose[None, :2] + ranges[:, None] * u
    is_hit = ranges < max_range - 1e-3
    idx_hit = flat(cell_of(spec, origin, end), is_hit)
    seen = seen.ravel().at[idx_free].set(True, mode="drop").at[idx_hit].set(True, mode="drop").reshape(H, W)
    hit = hit.ravel().at[idx_hit].set(True, mode="drop").reshape(H, W)
    return seen, hit


def update_viewed(
    spec: GridSpec, origin: jax.Array, viewed: jax.Array, pose: jax.Array, ranges: jax.Array, angles: np.ndarray,
    fov: float, max_range: float,
) -> jax.Array:
    """Marks the cells the forward camera looked at: inside its horizontal field of view `fov` (radians),
    within `max_range`, and no farther than the lidar ray of that bearing reached (line of sight).

    angles: (L,) evenly spaced lidar angles (static NumPy); ranges: (L,) the scan at the same pose.
    """
    L = angles.shape[0]
    step = float(angles[1] - angles[0]) if L > 1 else 1.0
    full = L > 1 and abs(step * L - 2 * math.pi) < 1e-4
    xy = cell_centers(spec, origin)
    rel = xy - pose[None, None, :2]
    dist = jnp.linalg.norm(rel, axis=-1)
    heading = jnp.arctan2(rel[..., 1], rel[..., 0]) - pose[2]
    bearing = jnp.arctan2(jnp.sin(heading), jnp.cos(heading))
    i = jnp.round((bearing - float(angles[0])) / step).astype(jnp.int32)
    i = jnp.mod(i, L) if full else jnp.clip(i, 0, L - 1)
    reach = ranges[i] + spec.res / 2
    return viewed | ((jnp.abs(bearing) <= fov / 2) & (dist <= max_range) & (dist <= reach))


def classify(seen: jax.Array, hit: jax.Array, inside: jax.Array) -> tuple[jax.Array, jax.Array, jax.Array]:
    """(free, unknown, frontier), each (H, W) bool."""
    free = seen & ~hit & inside
    unknown = ~seen & ~hit & inside
    near_unknown = jnp.zeros_like(free)
    for di, dj in NEIGHBORS4:
        near_unknown = near_unknown | _shift(unknown, di, dj, False)
    return free, unknown, free & near_unknown


def cell_costs(spec: GridSpec, free: jax.Array, hit: jax.Array, inside: jax.Array) -> jax.Array:
    """(H, W) cost of entering each cell: 1 with clearance, TIGHT_COST without, BIG if not free."""
    occ = hit | ~inside
    near = jnp.zeros_like(occ)
    for di, dj in disc_offsets(spec.radius):
        near = near | _shift(occ, di, dj, True)
    return jnp.where(free, jnp.where(near, TIGHT_COST, 1.0), BIG)


def distance_field(spec: GridSpec, cost: jax.Array, source: jax.Array, max_iters: int | None = None) -> jax.Array:
    """(H, W) path length in metres from `source` (2,) int32 cell over 8-connected cells (Bellman-Ford
    relaxation in a while_loop until nothing changes); BIG where unreachable. The source is always
    passable, so a robot in a tight or unmapped cell can still leave it."""
    H, W = spec.shape
    max_iters = max_iters or 4 * (H + W)
    si = jnp.clip(source[0], 0, H - 1)
    sj = jnp.clip(source[1], 0, W - 1)
    d0 = jnp.full((H, W), BIG, jnp.float32).at[si, sj].set(0.0)
    passable = cost < BIG
    step_cost = cost * spec.res

    def relax(d):
        best = d
        for di, dj in NEIGHBORS8:
            w = math.sqrt(2.0) if di and dj else 1.0
            best = jnp.minimum(best, _shift(d, di, dj, BIG) + w * step_cost)
        return jnp.where(passable, jnp.minimum(best, BIG), d)

    def body(c):
        d, _, it = c
        nd = relax(d)
        return nd, jnp.any(nd < d), it + 1

    d, _, _ = jax.lax.while_loop(lambda c: c[1] & (c[2] < max_iters), body, (d0, jnp.array(True), jnp.int32(0)))
    return d


def _min_filter(x: jax.Array, r: int, fill) -> jax.Array:
    out = x
    for di in range(-r, r + 1):
        for dj in range(-r, r + 1):
            out = jnp.minimum(out, _shift(x, di, dj, fill))
    return out


class Regions(NamedTuple):
    """Frontier regions keyed by exploration-grid cell id (Hc * Wc slots; a region lives at its root)."""

    valid: jax.Array  # (N,) bool: a region with >= min_cells reachable frontier cells
    count: jax.Array  # (N,) int32 frontier cells
    center: jax.Array  # (N, 2) float32 frontier point f_i (mean of the region's frontier cells)
    target: jax.Array  # (N, 2) int32 map cell the robot drives to (a traversable cell next to rep)
    rep: jax.Array  # (N, 2) int32 the region's reachable frontier cell nearest to its centre
    path_cost: jax.Array  # (N,) float32 metres from the robot to `target`
    labels: jax.Array  # (Hc, Wc) int32 region root of each exploration cell (-1: none)


def frontier_regions(
    spec: GridSpec, origin: jax.Array, frontier: jax.Array, dist: jax.Array, blocked: jax.Array, min_cells: int
) -> Regions:
    """Clusters reachable frontier cells into regions on the exploration grid.

    frontier: (H, W) bool; dist: (H, W) distance field from the robot; blocked: (Hc, Wc) bool cells
    whose targets were given up.
    """
    H, W = spec.shape
    k = spec.k
    Hc, Wc = spec.coarse_shape
    N = Hc * Wc
    r = int(math.ceil(spec.radius))
    # A frontier cell is reachable when a cell within r (Chebyshev) has a finite path: the robot can get
    # next to it. r never reaches across an occupied cell that made those cells tight.
    reach = _min_filter(dist, r, BIG)
    cblocked = jnp.repeat(jnp.repeat(blocked, k, 0), k, 1)
    fr = frontier & (reach < BIG / 2) & ~cblocked
    coarse_count = fr.reshape(Hc, k, Wc, k).sum((1, 3))
    cf = coarse_count > 0
    ids = jnp.arange(N, dtype=jnp.int32).reshape(Hc, Wc)
    lab0 = jnp.where(cf, ids, N)

    def body(c):
        lab, _ = c
        nl = lab
        for di, dj in NEIGHBORS4:
            nl = jnp.minimum(nl, _shift(lab, di, dj, N))
        nl = jnp.where(cf, nl, N)
        return nl, jnp.any(nl != lab)

    labels, _ = jax.lax.while_loop(lambda c: c[1], body, (lab0, jnp.array(True)))
    cell_label = jnp.repeat(jnp.repeat(labels, k, 0), k, 1)  # (H, W) region of each map cell
    seg = jnp.where(fr, cell_label, N).ravel()
    xy = cell_centers(spec, origin).reshape(-1, 2)
    count = jax.ops.segment_sum(fr.ravel().astype(jnp.int32), seg, N + 1)[:N]
    sums = jax.ops.segment_sum(jnp.where(fr.ravel()[:, None], xy, 0.0), seg, N + 1)[:N]
    center = sums / jnp.maximum(count, 1)[:, None]
    # Representative: the region's frontier cell nearest to the centre (lowest index on ties).
    dc = jnp.linalg.norm(xy - center[jnp.minimum(seg, N - 1)], axis=-1)
    dc = jnp.where(seg < N, dc, BIG)
    best = jax.ops.segment_min(dc, seg, N + 1)[:N]
    flat = jnp.arange(H * W, dtype=jnp.int32)
    is_best = (seg < N) & (dc <= best[jnp.minimum(seg, N - 1)])
    rep_flat = jax.ops.segment_min(jnp.where(is_best, flat, H * W), seg, N + 1)[:N]
    rep_flat = jnp.minimum(rep_flat, H * W - 1)
    rep = jnp.stack([rep_flat // W, rep_flat % W], -1)
    # Target: the cell next to rep (within r) with the shortest path.
    offs = jnp.array([(di, dj) for di in range(-r, r + 1) for dj in range(-r, r + 1)], jnp.int32)  # (M, 2)
    cand = rep[:, None, :] + offs[None]  # (N, M, 2)
    ok = (cand[..., 0] >= 0) & (cand[..., 0] < H) & (cand[..., 1] >= 0) & (cand[..., 1] < W)
    cd = jnp.where(ok, dist[jnp.clip(cand[..., 0], 0, H - 1), jnp.clip(cand[..., 1], 0, W - 1)], BIG)
    m = jnp.argmin(cd, axis=1)
    target = jnp.take_along_axis(cand, m[:, None, None], axis=1)[:, 0]
    path_cost = jnp.min(cd, axis=1)
    valid = (count >= min_cells) & (path_cost < BIG / 2)
    return Regions(valid, count, center, target, rep, path_cost, jnp.where(cf, labels, -1))


def extract_path(dist: jax.Array, goal: jax.Array, max_len: int) -> tuple[jax.Array, jax.Array, jax.Array]:
    """Steepest descent of `dist` from `goal` to the source: ((max_len, 2) int32 cells from the source
    to the goal, padded with the goal; number of cells n; whether the source was reached in max_len)."""
    H, W = dist.shape
    offs = jnp.array(NEIGHBORS8, jnp.int32)

    def step(cell, _):
        nb = cell[None] + offs
        ok = (nb[:, 0] >= 0) & (nb[:, 0] < H) & (nb[:, 1] >= 0) & (nb[:, 1] < W)
        dn = jnp.where(ok, dist[jnp.clip(nb[:, 0], 0, H - 1), jnp.clip(nb[:, 1], 0, W - 1)], BIG)
        i = jnp.argmin(dn)
        here = dist[cell[0], cell[1]]
        nxt = jnp.where((dn[i] < here) & (here > 0), nb[i], cell)
        return nxt, cell

    _, cells = jax.lax.scan(step, goal.astype(jnp.int32), None, length=max_len)  # goal ... source, source, ...
    at_source = dist[cells[:, 0], cells[:, 1]] <= 0
    n = jnp.where(jnp.any(at_source), jnp.argmax(at_source) + 1, max_len).astype(jnp.int32)
    # Reverse the first n cells (source first); pad with the goal.
    idx = n - 1 - jnp.arange(max_len)
    path = jnp.where((idx >= 0)[:, None], cells[jnp.clip(idx, 0, max_len - 1)], goal[None].astype(jnp.int32))
    return path, n, jnp.any(at_source)
