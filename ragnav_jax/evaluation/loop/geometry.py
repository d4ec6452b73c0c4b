"""The closed loop's geometry on the device: key-pose paths, attaching to the map, densified waypoints, the local
planner's reachability test, approach stops and driven routes (jax.numpy, jit- and vmap-safe, static shapes).

Each kernel is for one episode (vmap from outside) and is the device twin of host code it must agree with:
`memory.paths.reconstruct_path`, `execute.densify` / `pad_points` and the `host_loop.Loop` methods named in each
docstring. The host builders `scene_grid`, `stack_grids` and `edge_plans` precompute what depends on a scene
alone (the occupancy grid, its connected regions, every map edge's local plan), once, outside any trace.
"""

from __future__ import annotations

import functools
import math

import jax
import jax.numpy as jnp
import numpy as np
from jax import lax

from ragnav_jax.evaluation.clearance import ESCAPE_M, GRID_M, TIGHT_GAP_M
from ragnav_jax.memory.topomap import segment_clearance as _segment_clearance

ATTACH_NEAREST = 8  # key poses `attach` tries, nearest first (Loop.attach)
_PW_BLOCK = 128  # NumPy's pairwise-summation block (PW_BLOCKSIZE)


def norm(v: jax.Array) -> jax.Array:
    """(...) Euclidean norm of planar vectors v (..., 2), rounded as NumPy's: the select between the squares and
    their sum keeps XLA from fusing them into a multiply-add (one ulp off, which flips ceil() and ties)."""
    sq = v * v
    sq = jnp.where(jnp.isnan(sq), 0.0, sq)
    return jnp.sqrt(sq[..., 0] + sq[..., 1])


def segment_clearance(p: jax.Array, q: jax.Array, obs: dict) -> jax.Array:
    """(P,) clearance of segments p-q (P, 2) to a scene's walls and blocking objects (`topomap.segment_clearance`)."""
    return _segment_clearance(p, q, obs, jnp)


# ----------------------------------------------------------------------------------------------------
# Paths over the key-pose map


def path_nodes(pred: jax.Array, i, j, L: int) -> tuple[jax.Array, jax.Array]:
    """The shortest path i ... j (`memory.paths.reconstruct_path`) as a padded node list.

    pred (N, N) int32 predecessors (-1: none); i, j int32 nodes; L static length (N: no path repeats a node).
    Returns nodes (L,) int32 padded with j, and their count n: 1 where i == j, 0 (nodes all i) where j is
    unreachable from i.
    """
    i, j = jnp.asarray(i, jnp.int32), jnp.asarray(j, jnp.int32)

    def back(cur, _):
        nxt = jnp.where((cur == i) | (cur < 0), cur, pred[i, jnp.maximum(cur, 0)])
        return nxt, cur

    _, rev = lax.scan(back, j, None, length=L)  # j, pred(j), ..., i, i, ...
    at_i = rev == i
    n = jnp.where(((i == j) | (pred[i, j] >= 0)) & at_i.any(), jnp.argmax(at_i) + 1, 0).astype(jnp.int32)
    nodes = rev[jnp.clip(n - 1 - jnp.arange(L), 0, L - 1)]  # reversed; slots past the end repeat j
    return jnp.where(n > 0, nodes, i).astype(jnp.int32), n


def attach(pos: jax.Array, mask: jax.Array, obs: dict, xy: jax.Array, radius) -> jax.Array:
    """The nearest key pose the robot can drive to in a straight line from xy, else the nearest (`Loop.attach`).

    pos (N, 2) key poses, mask (N,) bool live ones, obs the scene's obstacle arrays (`topomap.obstacles_numpy`,
    padded), xy (2,), radius: clearance the segment must exceed. Of the ATTACH_NEAREST nearest live poses the
    first whose segment clears. Returns int32.
    """
    xy = jnp.asarray(xy, pos.dtype)
    d = jnp.where(mask, norm(pos - xy[None]), jnp.inf)
    near = jnp.argsort(d)[: min(ATTACH_NEAREST, pos.shape[0])]
    clear = segment_clearance(jnp.broadcast_to(xy, (near.shape[0], 2)), pos[near], obs)
    ok = jnp.isfinite(d[near]) & (clear > radius)
    return jnp.where(ok.any(), near[jnp.argmax(ok)], jnp.argmin(d)).astype(jnp.int32)


# ----------------------------------------------------------------------------------------------------
# Waypoints


def densify(points: jax.Array, n, P: int, spacing: float = 0.25) -> tuple[jax.Array, jax.Array]:
    """`execute.pad_points(execute.densify(points[:n], P, spacing), P)`: the executor's waypoint buffer.

    points (L, 2) float32 (L static, may exceed P), n valid count, P static. A waypoint every `spacing` metres
    along the polyline (every vertex kept; the spacing grows for long polylines); the polyline itself where
    that would exceed P points, thinned evenly to P (ends kept) where it is longer than P. Returns out (P, 2)
    padded with its last point and the count m (int32).
    """
    L = points.shape[0]
    points = points.astype(jnp.float32)
    n = jnp.asarray(n, jnp.int32)
    q = jnp.arange(P)
    idx = jnp.minimum(q, jnp.maximum(n - 1, 0))
    if L > P:
        idx = jnp.where(n > P, _thin_index(n, P, L), idx)
    raw = jnp.where(n > 0, points[idx], 0.0)
    S = min(L, P) - 1  # segments of a polyline short enough to be densified (n < P)
    if S < 1:
        return raw, jnp.minimum(n, P)
    a, ab = points[:S], points[1 : S + 1] - points[:S]
    seg = norm(ab)
    live = jnp.arange(S) < n - 1
    total = _np_sum(jnp.where(live, seg, 0.0), n - 1)
    step = jnp.maximum(jnp.asarray(spacing, jnp.float32), total / jnp.maximum(P - n, 1).astype(jnp.float32))
    k = jnp.where(live, jnp.maximum(jnp.ceil(seg / step).astype(jnp.int32), 1), 0)  # points per segment
    end = jnp.cumsum(k)  # dense index of each segment's last point
    count = 1 + end[-1]
    qe = jnp.minimum(q, count - 1)
    s = jnp.minimum(jnp.sum(end[None, :] < qe[:, None], axis=1), S - 1)
    t = (qe - end[s] + k[s]).astype(jnp.float32) / jnp.maximum(k[s], 1).astype(jnp.float32)
    dense = jnp.where((qe == 0)[:, None], points[:1], a[s] + ab[s] * t[:, None])
    use = (n >= 2) & (n < P) & (count <= P)
    return jnp.where(use, dense, raw), jnp.where(use, count, jnp.minimum(n, P)).astype(jnp.int32)


def _thin_index(n, P: int, L: int) -> jax.Array:
    """(P,) `np.round(np.linspace(0, n - 1, P))` for P < n <= L (P distinct indices: pad_points' thinning)."""
    i = jnp.arange(P)
    den = max(P - 1, 1)
    num = i * (n - 1)
    base, r = num // den, num % den
    idx = base + ((2 * r > den) | ((2 * r == den) & (base % 2 == 1)))  # the exact value, half to even
    fn, fi, fd = _thin_flips(P, L)
    if len(fn):  # exact halves NumPy's float64 linspace puts off the half
        hit = (jnp.asarray(fn)[None] == n) & (jnp.asarray(fi)[None] == i[:, None])
        idx = idx + jnp.sum(jnp.where(hit, jnp.asarray(fd)[None], 0), axis=1)
    return idx


@functools.lru_cache(maxsize=64)
def _thin_flips(P: int, L: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(n, slot, correction) where NumPy's rounded linspace differs from the exact half-to-even index (only where
    P - 1 is even: an exact half needs it)."""
    out = []
    if P > 1 and (P - 1) % 2 == 0:
        i = np.arange(P)
        for n in range(P + 1, L + 1):
            base, r = divmod(i * (n - 1), P - 1)
            exact = base + ((2 * r > P - 1) | ((2 * r == P - 1) & (base % 2 == 1)))
            ref = np.round(np.linspace(0, n - 1, P)).astype(int)
            out += [(n, k, ref[k] - exact[k]) for k in np.flatnonzero(ref != exact)]
    return tuple(np.asarray([o[c] for o in out], np.int32) for c in range(3))


def _np_sum(x: jax.Array, m) -> jax.Array:
    """NumPy's float32 `x[:m].sum()` bit for bit (its pairwise order); x (S,) zero beyond m. The spacing it sets
    decides the ceil()ed point counts, which must be the host's."""
    S = x.shape[0]
    if S <= _PW_BLOCK:
        return _np_block(x, m)
    half = m // 2 - (m // 2) % 8
    H = (S + 1) // 2 + 8  # bounds either half
    left = _np_sum(jnp.where(jnp.arange(S) < half, x, 0.0)[:H], half)
    right = _np_sum(lax.dynamic_slice(jnp.pad(x, (0, H)), (half,), (H,)), m - half)
    return jnp.where(m <= _PW_BLOCK, _np_block(x[:_PW_BLOCK], m), left + right)


def _np_block(x: jax.Array, m) -> jax.Array:
    """NumPy's pairwise sum of at most PW_BLOCK values: sequential below 8, else 8 lanes, a tree, the rest."""
    S = x.shape[0]
    x = jnp.pad(x, (0, 8 - S if S < 8 else (-S) % 8))
    seq = lax.fori_loop(1, 8, lambda k, s: s + x[k], x[0])  # zeros beyond m add nothing
    full = m - m % 8
    blocks = x.reshape(-1, 8)
    r = lax.fori_loop(1, blocks.shape[0], lambda b, r: r + jnp.where(8 * b < full, blocks[b], 0.0), blocks[0])
    tree = ((r[0] + r[1]) + (r[2] + r[3])) + ((r[4] + r[5]) + (r[6] + r[7]))
    tree = lax.fori_loop(0, x.shape[0], lambda k, s: s + jnp.where(k >= full, x[k], 0.0), tree)
    return jnp.where(m < 8, seq, tree)


# ----------------------------------------------------------------------------------------------------
# The local planner's occupancy grid


def scene_grid(loop, b: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Host: the local planner's grid of bank scene b (`Loop._grid`) and the regions `Loop.way_exists` joins.

    Returns origin (2,) float32, clear (H, W) float32 metres from each cell to the nearest obstacle, and labels
    (H, W) int32: 8-connected regions of the cells the robot fits in (clearance >= its radius + TIGHT_GAP_M), 0
    elsewhere.
    """
    from scipy import ndimage

    lo, clear = loop._grid(b)
    tight = loop.cfg.sim.robot_radius + TIGHT_GAP_M
    labels = ndimage.label(clear >= tight, structure=np.ones((3, 3), bool))[0]
    return np.asarray(lo, np.float32), np.asarray(clear, np.float32), labels.astype(np.int32)


def stack_grids(grids) -> dict:
    """Host: `scene_grid`s of several scenes padded to one (H, W) so they batch.

    Returns origin (S, 2) float32, clear (S, H, W) float32 (padding 0.0: blocked), labels (S, H, W) int32
    (padding 0) and shape (S, 2) int32: each grid's own (H, W), which `way_exists` clips cells to.
    """
    H = max(g[1].shape[0] for g in grids)
    W = max(g[1].shape[1] for g in grids)
    pad = lambda a: np.pad(a, ((0, H - a.shape[0]), (0, W - a.shape[1])))  # noqa: E731
    return {"origin": np.stack([np.asarray(g[0], np.float32) for g in grids]),
            "clear": np.stack([pad(np.asarray(g[1], np.float32)) for g in grids]),
            "labels": np.stack([pad(np.asarray(g[2], np.int32)) for g in grids]),
            "shape": np.asarray([g[1].shape for g in grids], np.int32)}


def _regions(origin, clear, labels, p, tight, res: float, escape: float, shape) -> jax.Array:
    """(K,) region labels of the cells within `escape` of p's cell the robot may leave p by: as clear as p's cell
    or the tight threshold, whichever is less (0 for the others); K cells of the disc of int(escape / res)."""
    r = int(escape / res)  # the host's rounding (0.3 / 0.05 -> 5)
    di, dj = np.mgrid[-r : r + 1, -r : r + 1].reshape(2, -1)
    disc = di**2 + dj**2 <= r**2
    di, dj = di[disc], dj[disc]
    hw = jnp.asarray(clear.shape if shape is None else shape, jnp.int32)
    ij = jnp.clip(jnp.round((p[:2] - origin) / res).astype(jnp.int32), 0, hw - 1)
    # clipped indices only repeat cells of the disc (a coordinate moved towards the centre)
    ci, cj = jnp.clip(ij[0] + di, 0, hw[0] - 1), jnp.clip(ij[1] + dj, 0, hw[1] - 1)
    ok = clear[ci, cj] >= jnp.minimum(clear[ij[0], ij[1]], tight) - 1e-6
    return jnp.where(ok, labels[ci, cj], 0)


def way_exists(origin, clear, labels, a, c, tight, res: float = GRID_M, escape: float = ESCAPE_M,
               shape=None) -> jax.Array:
    """The local planner's grid joins a and c (`Loop.way_exists`): a region the robot may leave a by is one it may
    reach c by.

    origin (2,), clear (H, W), labels (H, W) int32 (`scene_grid`); a, c (2,); tight: the clearance of the
    regions' cells (robot radius + TIGHT_GAP_M); res, escape static; shape (2,) the grid's own (H, W) where it
    is padded (`stack_grids`), else clear.shape. Returns bool.
    """
    la = _regions(origin, clear, labels, a, tight, res, escape, shape)
    lc = _regions(origin, clear, labels, c, tight, res, escape, shape)
    return jnp.any((la[:, None] == lc[None, :]) & (la[:, None] > 0))


# ----------------------------------------------------------------------------------------------------
# Approaches


def approach_ring_jnp(c: jax.Array, half: jax.Array, gap, per_side: int = 5) -> jax.Array:
    """(4 * per_side + 12, 2) stops at distance `gap` from a box footprint (`clearance.approach_ring`, same order):
    along each side's outward normal, then three directions round each corner. c, half (2,)."""
    t = jnp.asarray(np.linspace(-1.0, 1.0, per_side + 2)[1:-1], jnp.float32)
    out = []
    for axis in (0, 1):
        for sign in (-1.0, 1.0):
            fixed = jnp.broadcast_to(c[axis] + sign * (half[axis] + gap), t.shape)
            along = c[1 - axis] + t * half[1 - axis]
            out.append(jnp.stack([fixed, along] if axis == 0 else [along, fixed], -1))
    for sx in (-1.0, 1.0):
        for sy in (-1.0, 1.0):
            corner = c + jnp.asarray([sx, sy], jnp.float32) * half
            dirs = np.asarray([[sx * math.cos(a), sy * math.sin(a)] for a in (0.0, math.pi / 4, math.pi / 2)])
            out.append(corner[None] + gap * jnp.asarray(dirs, jnp.float32))
    return jnp.concatenate(out).astype(jnp.float32)


def approach_stop(c, half, pose, gap, need, obs, origin, clear, labels, tight, res: float = GRID_M,
                  escape: float = ESCAPE_M, shape=None) -> jax.Array:
    """(2,) where to stop by a box footprint (`Loop.approach_points`' point).

    `gap` from the footprint (centre c, half sizes `half`, (2,)) on the robot's side (pose (2,) or (3,)); where
    that spot is no room for the robot (clearance < need) or the grid has no way to it from the robot
    (`way_exists`), the nearest free reachable stop of `approach_ring_jnp`, else the nearest free one; the
    robot-side spot where nothing is free; the robot's own position where it is within `gap` already.
    obs: obstacle arrays; origin, clear, labels, tight, res, escape, shape: as `way_exists`.
    """
    xy = pose[:2]
    near = jnp.clip(xy, c - half, c + half)  # closest point of the footprint
    v = xy - near
    dist = norm(v)
    goal = near + v / jnp.where(dist > 0, dist, 1.0) * gap
    cand = jnp.concatenate([goal[None], approach_ring_jnp(c, half, gap)])  # (R, 2)
    free = segment_clearance(cand, cand, obs) >= need
    d = norm(cand - xy[None]).at[0].set(0.0)  # the spot on the robot's side first
    here = _regions(origin, clear, labels, xy, tight, res, escape, shape)
    there = jax.vmap(lambda p: _regions(origin, clear, labels, p, tight, res, escape, shape))(cand)  # (R, K)
    reach = jnp.any((here[None, :, None] == there[:, None, :]) & (here[None, :, None] > 0), axis=(1, 2))
    best = jnp.argmin(jnp.where(free & reach, d, jnp.inf))
    nearest = jnp.argmin(jnp.where(free, d, jnp.inf))
    stop = jnp.where((free & reach).any(), cand[best], jnp.where(free.any(), cand[nearest], goal))
    return jnp.where(dist <= gap, xy, stop)


# ----------------------------------------------------------------------------------------------------
# Driven routes


def edge_plans(loop, b: int, K: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Host: the local plan (`Loop.local_plans`) of every directed map edge of bank scene b, for `drive_route`.

    Returns idx (N, N) int32 (plan row of edge i -> j, -1: no edge), plans (M, K, 2) float32 (each padded with
    its last point) and count (M,) int32 points per plan; M = max(edges, 1) (a zero row where there are none).
    Scenes without obstacle arrays drive every edge straight, as `Loop.drive_points` does. Raises ValueError
    when a plan has more than K points.
    """
    live = np.asarray(loop.mask[b], bool)
    pos = np.asarray(loop.pos[b], np.float32)
    adj = (np.asarray(loop.bank.memory.adjacency[b]) != 0) & live[:, None] & live[None, :]
    ii, jj = np.nonzero(adj)
    idx = np.full(adj.shape, -1, np.int32)
    plans = np.zeros((max(len(ii), 1), K, 2), np.float32)
    count = np.zeros(len(plans), np.int32)
    ways = loop.local_plans(b, pos[ii], pos[jj]) if b in loop.obstacles else [np.stack([pos[i], pos[j]])
                                                                               for i, j in zip(ii, jj)]
    for m, (i, j, way) in enumerate(zip(ii, jj, ways)):
        if len(way) > K:
            raise ValueError(f"the local plan of map edge {i} -> {j} of scene {b} has {len(way)} points (K = {K})")
        plans[m] = way[-1]
        plans[m, : len(way)] = way
        count[m], idx[i, j] = len(way), m
    return idx, plans, count


def join_plans(pts, n, plans, cnt, planned):
    """Waypoints of a polyline whose segments are replaced by their plans.

    pts (L, 2) with n valid; plans (L-1, K, 2) and cnt (L-1,) each segment's plan (first point = the
    segment's start), used where `planned` (L-1,) bool, else the straight segment. Returns ((L * K, 2)
    points, count): each segment's plan without repeating its first point."""
    L, K = pts.shape[0], plans.shape[1]
    seg_valid = jnp.arange(L - 1) < n - 1
    cnt = jnp.where(planned, cnt, 2)
    add = jnp.where(seg_valid, cnt - 1, 0)  # points each segment adds
    off = 1 + jnp.cumsum(add) - add  # where each segment's added points start
    k = jnp.arange(1, K)
    src = jnp.where(planned[:, None, None], plans[:, 1:],
                    jnp.where((k == 1)[None, :, None], pts[1:, None], 0.0))  # (L-1, K-1, 2)
    # Each output point gathers its segment's point (no scatter with dropped indices: under vmap on the GPU
    # those misplaced points, see step.visit_sequence). Segments adding nothing share the next one's offset.
    p = jnp.arange(L * K)
    seg = jnp.clip(jnp.searchsorted(off, p, side="right") - 1, 0, L - 2)
    out = src[seg, jnp.clip(p - off[seg], 0, K - 2)]
    out = jnp.where((p == 0)[:, None], pts[0], jnp.where(((p >= 1) & (p < 1 + add.sum()))[:, None], out, 0.0))
    return out.astype(jnp.float32), jnp.where(n > 0, 1 + add.sum(), 0)


def densify_or_keys(way, m, pts, n, P: int):
    """densify(way), or the polyline pts itself where the way would not fit the waypoint buffer (the host's rule)."""
    dp, dn = densify(way, m, P)
    sp, sn = densify(jnp.concatenate([pts, jnp.zeros((max(way.shape[0] - pts.shape[0], 0), 2), pts.dtype)]), n, P)
    return jnp.where(m <= P, dp, sp), jnp.where(m <= P, dn, sn)


def drive_route(nodes: jax.Array, n, pos: jax.Array, idx: jax.Array, plans: jax.Array, count: jax.Array,
                P: int) -> tuple[jax.Array, jax.Array]:
    """The waypoint buffer of a node path as driven (`Loop.drive_points(pos[nodes[:n]])`, padded as `_run_chunk`):
    `join_plans` of each pair's local plan, then `densify_or_keys`. nodes (L,) int32 and count n
    (`path_nodes`); pos (N, 2); idx, plans, count from `edge_plans` (a pair that is no edge is driven
    straight); P static. Returns ((P, 2) waypoints, count int32)."""
    key = pos[nodes].astype(jnp.float32)  # (L, 2)
    n = jnp.asarray(n, jnp.int32)
    if nodes.shape[0] < 2:
        return densify(key, n, P)
    e = idx[nodes[:-1], nodes[1:]]  # (L-1,)
    way, m = join_plans(key, n, plans[jnp.maximum(e, 0)], count[jnp.maximum(e, 0)], e >= 0)
    return densify_or_keys(way, m, key, n, P)


# ----------------------------------------------------------------------------------------------------
# The local planner


_STEPS = np.asarray([(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)], np.int32)  # (8, 2)


LOCAL_WINDOW = 128  # cells (6.4 m) of the block a segment's grid route is searched in


def local_route(a, c, obs: dict, origin, clear, shape, need, tight, anywhere: bool, window: int = LOCAL_WINDOW,
                max_points: int = 16, res: float = GRID_M, escape: float = ESCAPE_M, go=True) -> tuple[jax.Array, jax.Array]:
    """Waypoints a ... c round what is in the way (`Loop._local`): the straight segment where it clears `need`.

    a, c (2,); obs: obstacle arrays (padded); origin (2,), clear (H, W): the scene's grid padded as `stack_grids`
    (blocked beyond its own shape (2,) int32 (H, W)); need, tight: the tiers' clearances (robot radius +
    GRID_MARGIN_M, + TIGHT_GAP_M); window (a multiple of 32), max_points, res, escape static; go: bool, False
    gives the straight segment without searching (under vmap, lanes that need no route add no iterations).

    Where the segment passes closer than `need` to an obstacle (and |c - a| >= 1e-3), a breadth-first search
    from c's cell over the 8-connected cells of a window x window block centred on the segment, in the host's
    tiers: cells that clear `need`, then `tight`, in the ends' cells' bounding box grown by GRID_WINDOW_M; with
    `anywhere` (static) then the same over the whole block (the host's whole house where the block covers the
    grid, as `step._local` makes it for approaches; else routes that leave the block are not found). Within `escape` of either end a cell as clear as that end (or the
    tier) passes too, and the end cells always. One layer per `lax.while_loop` iteration (none where the
    segment is clear), until a's cell is reached or the tier's region is exhausted. Then a walk from a's cell to a neighbour one layer
    nearer c (fixed order) and string pulling: from each kept point the farthest later cell (at most `window`
    cells on) in line of sight that clears the tier's clearance * 0.999.
    The straight segment where no tier joins the ends, where an end lies outside the block (|c - a| beyond
    about window * res along an axis), where both ends share a cell (the host keeps [c]), or where the path
    has more than 4 * window cells.
    Returns points (max_points, 2) float32, a first and c last (the first max_points - 1 and c where the
    host would keep more), padded with c, and their count n (int32; 2 for the straight segment).
    """
    from ragnav_jax.evaluation.clearance import GRID_WINDOW_M

    if window % 32:
        raise ValueError(f"window must be a multiple of 32 (got {window})")
    a, c = jnp.asarray(a, jnp.float32), jnp.asarray(c, jnp.float32)
    origin = jnp.asarray(origin, jnp.float32)
    need, tight = jnp.asarray(need, jnp.float32), jnp.asarray(tight, jnp.float32)
    w = window
    clear = jnp.asarray(clear, jnp.float32)
    clear = jnp.pad(clear, ((0, max(w - clear.shape[0], 0)), (0, max(w - clear.shape[1], 0))))
    hw = jnp.asarray(shape, jnp.int32)
    straight = (segment_clearance(a[None], c[None], obs)[0] >= need) | (norm(c - a) < 1e-3)

    ia, ic = (jnp.clip(jnp.round((p - origin) / res).astype(jnp.int32), 0, hw - 1) for p in (a, c))
    top = jnp.clip((ia + ic) // 2 - w // 2, 0, jnp.asarray(clear.shape, jnp.int32) - w)  # the block's corner
    blk = lax.dynamic_slice(clear, (top[0], top[1]), (w, w))
    la, lc = ia - top, ic - top
    ends_in = jnp.all((la >= 0) & (la < w) & (lc >= 0) & (lc < w))
    la, lc = jnp.clip(la, 0, w - 1), jnp.clip(lc, 0, w - 1)
    straight_points = jnp.where(jnp.arange(max_points)[:, None] == 0, a[None], c[None]).astype(jnp.float32)
    run = ~straight & ends_in & go

    def searched():
        gi, gj = top[0] + jnp.arange(w), top[1] + jnp.arange(w)  # the block's rows and columns in the grid
        r2 = math.floor((escape / res) ** 2)  # the host compares integer squares with (escape / res) ** 2
        near = [((gi - e[0]) ** 2)[:, None] + ((gj - e[1]) ** 2)[None, :] <= r2 for e in (ia, ic)]
        pad = int(GRID_WINDOW_M / res)
        lo_ij, hi_ij = jnp.minimum(ia, ic) - pad, jnp.maximum(ia, ic) + pad
        box = ((gi >= lo_ij[0]) & (gi <= hi_ij[0]))[:, None] & ((gj >= lo_ij[1]) & (gj <= hi_ij[1]))[None, :]
        box = box & (gi < hw[0])[:, None] & (gj < hw[1])[None, :]
        ends = _one_cell(la, w) | _one_cell(lc, w)

        def passable(t, region):  # (w, w) bool: the cells of a tier
            ok = blk >= t
            for e, disc in zip((ia, ic), near):  # let a robot parked in a tight spot out
                ok = ok | (disc & (blk >= jnp.minimum(clear[e[0], e[1]], t) - 1e-6))
            return (ok & region) | ends

        whole = (gi < hw[0])[:, None] & (gj < hw[1])[None, :]
        tiers = [(need, box), (tight, box)] + ([(need, whole), (tight, whole)] if anywhere else [])
        oks = _pack(jnp.stack([passable(t, m) for t, m in tiers]))  # (T, w, w / 32)
        tier, steps, layers = _search(oks, la, lc, run)  # (under vmap: no layers where run is False)
        cap = 4 * w
        found = (tier < len(tiers)) & (steps > 0) & (steps < cap)
        cells = _descend(layers, la, steps, cap, found)  # (cap, 2) a's cell ... c's cell, padded with c's
        sight = jnp.stack([t for t, _ in tiers])[jnp.minimum(tier, len(tiers) - 1)] * 0.999
        kept, n = _string_pull(coords(cells, steps), steps, obs, sight, max_points, w, found)
        return cells, steps, found, kept, n

    def coords(cells, steps):  # (cap, 2) a, the cells' centres, c from `steps` on
        j = jnp.arange(cells.shape[0])[:, None]
        xy = (origin[None] + (cells + top[None]).astype(jnp.float32) * res).astype(jnp.float32)
        return jnp.where(j == 0, a[None], jnp.where(j >= steps, c[None], xy))

    # a conditional where it can be one (a single segment, not under vmap): a segment that needs no search
    # costs no grid work; under vmap it runs as a select, both sides computed. The points are placed after it,
    # by the same code in either case (bit for bit as before, whatever XLA fuses inside the branch)
    cells, steps, found, kept, n = lax.cond(run, searched, lambda: (
        jnp.zeros((4 * w, 2), jnp.int32), jnp.int32(0), jnp.bool_(False), jnp.zeros(max_points, jnp.int32), jnp.int32(2)))
    points = jnp.where(found, coords(cells, steps)[kept], straight_points)
    return points.astype(jnp.float32), jnp.where(found, n, 2).astype(jnp.int32)


def _pack(m: jax.Array) -> jax.Array:
    """(..., H, W / 32) uint32: the bits of m (..., H, W) bool, cell j of a row at bit j % 32 of word j // 32."""
    bits = jnp.left_shift(jnp.uint32(1), jnp.arange(32, dtype=jnp.uint32))
    m = m.reshape(*m.shape[:-1], m.shape[-1] // 32, 32)
    return jnp.sum(jnp.where(m, bits.reshape((1,) * (m.ndim - 1) + (32,)), jnp.uint32(0)), axis=-1, dtype=jnp.uint32)


def _one_cell(ij, w: int) -> jax.Array:
    """(w, w) bool: cell ij alone."""
    return (jnp.arange(w) == ij[0])[:, None] & (jnp.arange(w) == ij[1])[None, :]


def _bit(x: jax.Array, i, j) -> jax.Array:
    """bool: cell (i, j) of packed bits x (H, W / 32); False outside."""
    H, nw = x.shape
    inside = (i >= 0) & (i < H) & (j >= 0) & (j < 32 * nw)
    word = x[jnp.clip(i, 0, H - 1), jnp.clip(j, 0, 32 * nw - 1) // 32]
    return inside & ((jnp.right_shift(word, (jnp.clip(j, 0, 32 * nw - 1) % 32).astype(jnp.uint32)) & 1) == 1)


def _dilate(x: jax.Array) -> jax.Array:
    """(H, W / 32) uint32: packed cells x grown by one cell to their 8 neighbours (3 x 3, rows then columns)."""
    z = jnp.zeros_like(x[:, :1])
    prev, nxt = jnp.concatenate([z, x[:, :-1]], 1), jnp.concatenate([x[:, 1:], z], 1)
    x = x | (x << 1) | (prev >> 31) | (x >> 1) | (nxt << 31)
    z = jnp.zeros_like(x[:1])
    return x | jnp.concatenate([z, x[:-1]], 0) | jnp.concatenate([x[1:], z], 0)


def _search(oks: jax.Array, la, lc, run) -> tuple[jax.Array, jax.Array, jax.Array]:
    """Breadth-first layers from cell lc over the packed passable cells of each tier oks (T, w, w / 32), tier
    after tier until one reaches la (none while `run` is False).

    Returns the tier (T where none joins them), the number of steps la is from lc, and the cells of each layer
    modulo 3 (3, w, w / 32) (neighbours' layers differ by at most one: enough to walk back).
    """
    T = oks.shape[0]
    seed = _pack(_one_cell(lc, oks.shape[1]))
    start = jnp.stack([seed, jnp.zeros_like(seed), jnp.zeros_like(seed)])

    def layer(s):  # the unreached passable neighbours of the last layer; the next tier afresh when none
        t, it, layers, front, _ = s
        new = _dilate(front) & oks[t] & ~(layers[0] | layers[1] | layers[2])
        found = _bit(new, la[0], la[1])
        stuck = ~found & ~new.any()
        layers = layers | jnp.where(jnp.arange(3)[:, None, None] == (it + 1) % 3, new[None], jnp.uint32(0))
        return (jnp.where(stuck, t + 1, t), jnp.where(stuck, 0, it + 1), jnp.where(stuck, start, layers),
                jnp.where(stuck, seed, new), found)

    t, it, layers, _, _ = lax.while_loop(lambda s: run & ~s[4] & (s[0] < T), layer,
                                         (jnp.int32(0), jnp.int32(0), start, seed, jnp.bool_(False)))
    return jnp.where(run, t, T), it, layers


def _descend(layers: jax.Array, la, steps, cap: int, go) -> jax.Array:
    """(cap, 2) int32 cells from la (layer `steps`) to the search's seed, each to its first neighbour (`_STEPS`
    order) one layer nearer; padded with the last (none while `go` is False)."""
    moves = jnp.asarray(_STEPS)

    def down(s):
        k, cur, cells = s
        below = layers[(steps - k - 1) % 3]
        ok = jax.vmap(lambda m: _bit(below, cur[0] + m[0], cur[1] + m[1]))(moves)
        nxt = cur + moves[jnp.argmax(ok)]
        return k + 1, nxt, jnp.where(jnp.arange(cap)[:, None] > k, nxt[None], cells)

    cells = jnp.broadcast_to(la, (cap, 2))
    return lax.while_loop(lambda s: go & (s[0] < steps), down, (jnp.int32(0), la, cells))[2]


def _string_pull(xy: jax.Array, steps, obs: dict, sight, max_points: int, reach: int, go):
    """Indices into xy (cap, 2) (a, the path's cells, c at `steps`) of the points kept: from each the farthest
    later one, at most `reach` on, whose segment clears `sight` (the next where none does), up to steps; the
    first max_points - 1 and steps where there are more. Returns kept (max_points,) int32 padded with steps and
    their count (none while `go` is False)."""
    xy = jnp.pad(xy, ((0, reach), (0, 0)), mode="edge")
    ahead = jnp.arange(1, reach + 1)

    def pull(s):
        k, n, kept = s
        cand = lax.dynamic_slice(xy, (k + 1, 0), (reach, 2))
        ok = (k + ahead <= steps) & (segment_clearance(jnp.broadcast_to(xy[k], (reach, 2)), cand, obs) >= sight)
        nxt = k + jnp.where(ok.any(), jnp.max(jnp.where(ok, ahead, 0)), 1).astype(jnp.int32)
        return nxt, n + 1, kept.at[n].set(nxt)

    k, n, kept = lax.while_loop(lambda s: go & (s[0] < steps) & (s[1] < max_points - 1), pull,
                                (jnp.int32(0), jnp.int32(1), jnp.zeros((max_points,), jnp.int32)))
    kept = jnp.where(jnp.arange(max_points) < n, kept, steps)  # c closes a route cut short
    return kept, jnp.where(k < steps, n + 1, n)
