"""Topological map G_t = (V_t, E_t): Euclidean distances, edges D_ij < delta_spatial whose straight segment is
free of walls and blocking objects (beyond the paper: no edge, hence no path, through a wall), connected
components.

The clearance geometry is written once against an array namespace (`xp` = numpy or jax.numpy): the host
key-pose selector uses it with NumPy, the batched edge kernel with jax.numpy under jit and vmap.
"""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.world.geometry import FLAT_HEIGHT


def _cross(ax, ay, bx, by):
    return ax * by - ay * bx


def _point_segment(px, py, ax, ay, bx, by, xp):
    dx, dy = bx - ax, by - ay
    denom = xp.maximum(dx * dx + dy * dy, 1e-12)
    t = xp.clip(((px - ax) * dx + (py - ay) * dy) / denom, 0.0, 1.0)
    return xp.hypot(px - (ax + t * dx), py - (ay + t * dy))


def segment_segment_distance(p, q, a, b, xp=np):
    """Distance between segments p-q and a-b; all arguments (..., 2) of equal rank, broadcast. q None: the points
    p, the value of q = p bit for bit (no crossing, and a point's distance from a or b is a plain hypot)."""
    ax, ay, bx, by = a[..., 0], a[..., 1], b[..., 0], b[..., 1]
    if q is None:
        px, py = p[..., 0], p[..., 1]
        return xp.minimum(_point_segment(px, py, ax, ay, bx, by, xp),
                          xp.minimum(xp.hypot(ax - px, ay - py), xp.hypot(bx - px, by - py)))
    px, py, qx, qy = p[..., 0], p[..., 1], q[..., 0], q[..., 1]
    d1 = _cross(qx - px, qy - py, ax - px, ay - py)
    d2 = _cross(qx - px, qy - py, bx - px, by - py)
    d3 = _cross(bx - ax, by - ay, px - ax, py - ay)
    d4 = _cross(bx - ax, by - ay, qx - ax, qy - ay)
    crossing = (d1 * d2 < 0) & (d3 * d4 < 0)
    d = xp.minimum(
        xp.minimum(_point_segment(px, py, ax, ay, bx, by, xp), _point_segment(qx, qy, ax, ay, bx, by, xp)),
        xp.minimum(_point_segment(ax, ay, px, py, qx, qy, xp), _point_segment(bx, by, px, py, qx, qy, xp)),
    )
    return xp.where(crossing, 0.0, d)


def segment_box_distance(p, q, center, half, xp=np):
    """Distance between segment p-q and axis-aligned boxes (centre, half extents); (..., 2) broadcast, 0 if touching;
    q None: points."""
    lo, hi = center - half, center + half
    corners = [
        xp.stack([lo[..., 0], lo[..., 1]], -1), xp.stack([hi[..., 0], lo[..., 1]], -1),
        xp.stack([hi[..., 0], hi[..., 1]], -1), xp.stack([lo[..., 0], hi[..., 1]], -1),
    ]
    d = segment_segment_distance(p, q, corners[0], corners[1], xp)
    for k in range(1, 4):
        d = xp.minimum(d, segment_segment_distance(p, q, corners[k], corners[(k + 1) % 4], xp))
    inside = (xp.abs(p[..., 0] - center[..., 0]) <= half[..., 0]) & (xp.abs(p[..., 1] - center[..., 1]) <= half[..., 1])
    return xp.where(inside, 0.0, d)


def obstacles_numpy(scene, sizes=None) -> dict:
    """The obstacle arrays of one scene for `segment_clearance` (walls and floor-standing objects)."""
    from ragnav_jax.world.arrays import pad_sizes, scene_to_numpy

    sizes = sizes or pad_sizes([scene])
    cats = sorted({o.category for o in scene.objects})
    sens = sorted({k for o in scene.objects for k, _ in o.sensors})
    a = scene_to_numpy(scene, sizes, cats, sens)
    return obstacles_from_arrays(a, np)


def obstacles_from_arrays(a, xp=np) -> dict:
    """Obstacles from SceneArrays fields (a dict or the pytree): walls with half thickness, blocking boxes."""
    get = a.__getitem__ if isinstance(a, dict) else lambda k: getattr(a, k)
    pos, size = get("obj_pos"), get("obj_size")
    blocking = get("obj_mask") & (size[..., 2] > FLAT_HEIGHT) & (pos[..., 2] - size[..., 2] / 2 < 0.3)
    return {
        "wall_a": get("wall_a"), "wall_b": get("wall_b"), "wall_half": get("wall_thickness") / 2,
        "wall_mask": get("wall_mask"), "box_center": pos[..., :2], "box_half": size[..., :2] / 2, "box_mask": blocking,
    }


def segment_clearance(p, q, obs: dict, xp=np):
    """Free clearance (metres) of segments p-q (P, 2) to walls and blocking objects: (P,), +inf when none; q None:
    of the points p (equal to q = p, in about half the work)."""
    wa, wb = obs["wall_a"][None], obs["wall_b"][None]
    q = None if q is None else q[:, None, :]
    dw = segment_segment_distance(p[:, None, :], q, wa, wb, xp) - obs["wall_half"][None]
    dw = xp.where(obs["wall_mask"][None], dw, xp.inf)
    db = segment_box_distance(p[:, None, :], q, obs["box_center"][None], obs["box_half"][None], xp)
    db = xp.where(obs["box_mask"][None], db, xp.inf)
    inf = xp.full(p.shape[:1], xp.inf)
    mw = xp.min(dw, axis=1) if dw.shape[1] else inf
    mb = xp.min(db, axis=1) if db.shape[1] else inf
    return xp.minimum(mw, mb)


def build_edges(positions, mask, obs: dict, delta: float | jnp.ndarray, clearance: float | jnp.ndarray):
    """Edges of one scene (jax.numpy): D_ij < delta and the segment i-j clears obstacles by > clearance.

    Args:
      positions: (N, 3) float32 node positions; mask (N,) bool.
      obs: obstacle arrays of the scene (`obstacles_from_arrays`), padded.
    Returns:
      distance (N, N) float32 Euclidean (planar x, y, z) and adjacency (N, N) bool (symmetric, no self loops).
    """
    n = positions.shape[0]
    diff = positions[:, None, :] - positions[None, :, :]
    dist = jnp.sqrt(jnp.maximum((diff**2).sum(-1), 0.0))
    xy = positions[:, :2]
    p = jnp.broadcast_to(xy[:, None, :], (n, n, 2)).reshape(n * n, 2)
    q = jnp.broadcast_to(xy[None, :, :], (n, n, 2)).reshape(n * n, 2)
    clear = segment_clearance(p, q, obs, jnp).reshape(n, n)
    clear = jnp.minimum(clear, clear.T)  # exact symmetry despite rounding
    adj = (dist < delta) & (clear > clearance) & mask[:, None] & mask[None, :] & ~jnp.eye(n, dtype=bool)
    return dist.astype(jnp.float32), adj


@jax.jit
def batched_edges(positions, mask, obs: dict, delta, clearance):
    """`build_edges` over scenes (leading axis B); a sequential map keeps the (N*N, walls) temporaries small."""
    return jax.lax.map(lambda a: build_edges(a[0], a[1], a[2], delta, clearance), (positions, mask, obs))
