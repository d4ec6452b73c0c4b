"""Key poses from the exploration stream, and what each one observed.

Host-side (NumPy), one pass over the stream's records. Rules (`memory.keyframe_rule`):
- spacing: a record becomes a key pose when no earlier key pose within `keyframe_spacing` metres has a
  clear line of sight to it (coverage, so revisits do not duplicate nodes);
- novelty: a record at least `keyframe_min_spacing` from every key pose becomes one when at least a fraction
  `novelty_threshold` of the objects it sees were never seen from any key pose (new view of the world);
- both (default): either rule.
Whatever the rule, the map stays connected where exploration connected it: the robot is always linked to
an "anchor" key pose (the last one, or the nearest visible one on a revisit); when the next record could no
longer be linked to it (farther than delta_spatial or behind a wall/object), the previous record becomes a
key pose. Consecutive links therefore satisfy the edge rule of `topomap.build_edges`.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ragnav_jax.memory.topomap import segment_segment_distance
from ragnav_jax.sim.stream import ExplorationStream
from ragnav_jax.world.scene import Scene

LINK_MARGIN = 0.05  # metres kept inside the edge thresholds so float32 edges agree with host links
MIN_MOVE = 0.05  # metres: records closer than this to the last considered one, and ...
MIN_TURN = 0.15  # ... turned less than this (radians), add nothing new and are skipped


@dataclasses.dataclass(frozen=True)
class NodeObservation:
    """What one key pose observed (host record)."""

    record: int  # index into the stream's records
    position: tuple[float, float, float]  # x, y, z
    yaw: float
    objects: tuple[int, ...]  # indices into scene.objects, nearest first
    distances: tuple[float, ...]  # metres, same order
    bearings: tuple[float, ...]  # radians relative to the heading, same order


@dataclasses.dataclass(frozen=True)
class KeyframeRule:
    rule: str = "both"  # spacing | novelty | both
    spacing: float = 1.5
    min_spacing: float = 0.5
    novelty: float = 0.5
    link_distance: float = 2.0  # delta_spatial
    link_clearance: float = 0.05  # edge clearance
    window: int = 0  # records either side merged into a node's observation


def select_key_poses(stream: ExplorationStream, obstacles: dict, rule: KeyframeRule) -> np.ndarray:
    """Indices (K,) int64 of the records that become key poses, increasing."""
    T = stream.pose.shape[0]
    if T == 0:
        return np.zeros((0,), np.int64)
    if rule.rule not in ("spacing", "novelty", "both"):
        raise ValueError(f"unknown keyframe rule {rule.rule!r}")
    xy = stream.pose[:, :2].astype(np.float64)
    vis = stream.visible
    use_spacing = rule.rule in ("spacing", "both")
    use_novelty = rule.rule in ("novelty", "both")
    link_d = rule.link_distance - LINK_MARGIN
    link_c = rule.link_clearance + LINK_MARGIN

    segs = obstacle_segments(obstacles)

    def clear(a: np.ndarray, b: np.ndarray) -> np.ndarray:  # a (P, 2), b (P, 2) -> (P,) bool
        return segments_clearance(a, b, segs) > link_c

    keys = [0]
    key_xy = [xy[0]]
    seen = vis[0].copy()
    anchor = 0
    yaw = stream.pose[:, 3].astype(np.float64)
    last = 0  # last record considered
    for t in range(1, T):
        p = xy[t]
        turn = abs((yaw[t] - yaw[last] + np.pi) % (2 * np.pi) - np.pi)
        if t < T - 1 and np.hypot(*(p - xy[last])) < MIN_MOVE and turn < MIN_TURN and not (vis[t] & ~seen).any():
            continue
        K = np.asarray(key_xy)
        d = np.hypot(K[:, 0] - p[0], K[:, 1] - p[1])
        # Revisits: re-anchor on the nearest key pose in sight when it is closer than the anchor.
        near = int(np.argmin(d))
        if near != anchor and d[near] < d[anchor] and clear(K[near][None], p[None])[0]:
            anchor = near
        if not (d[anchor] < link_d and clear(K[anchor][None], p[None])[0]):
            prev = last
            if keys[-1] != prev:
                keys.append(prev)
                key_xy.append(xy[prev])
                seen |= vis[prev]
            anchor = len(keys) - 1
            K = np.asarray(key_xy)
            d = np.hypot(K[:, 0] - p[0], K[:, 1] - p[1])
        new = False
        if use_spacing:
            close = np.flatnonzero(d < rule.spacing)
            covered = close.size > 0 and bool(clear(K[close], np.broadcast_to(p, (close.size, 2))).any())
            new = not covered
        if not new and use_novelty and d.min() >= rule.min_spacing and vis[t].any():
            frac = (vis[t] & ~seen).sum() / vis[t].sum()
            new = frac >= rule.novelty
        if new:
            keys.append(t)
            key_xy.append(p)
            seen |= vis[t]
            anchor = len(keys) - 1
        last = t
    return np.asarray(keys, np.int64)


def obstacle_segments(obs: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Walls and the four sides of every blocking box as one segment list: a (G, 2), b (G, 2), half width (G,)."""
    wm = np.asarray(obs["wall_mask"], bool)
    a, b, h = [np.asarray(obs["wall_a"])[wm]], [np.asarray(obs["wall_b"])[wm]], [np.asarray(obs["wall_half"])[wm]]
    bm = np.asarray(obs["box_mask"], bool)
    c, hb = np.asarray(obs["box_center"])[bm], np.asarray(obs["box_half"])[bm]
    corners = [c + hb * np.array(s) for s in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    for k in range(4):
        a.append(corners[k])
        b.append(corners[(k + 1) % 4])
        h.append(np.zeros(len(c)))
    return np.concatenate(a).astype(np.float64), np.concatenate(b).astype(np.float64), np.concatenate(h)


def segments_clearance(p: np.ndarray, q: np.ndarray, segs) -> np.ndarray:
    """Host clearance of segments p-q (P, 2) to obstacle segments (boxes as their sides; a segment wholly
    inside a box is impossible here because both ends are robot positions)."""
    a, b, h = segs
    if len(a) == 0:
        return np.full(p.shape[0], np.inf)
    d = segment_segment_distance(p[:, None, :], q[:, None, :], a[None], b[None], np) - h[None]
    return d.min(axis=1)


def observe(stream: ExplorationStream, records: np.ndarray, window: int = 0) -> list[NodeObservation]:
    """Objects seen at each key record (union over +-window records; nearest distance kept)."""
    T = stream.pose.shape[0]
    out = []
    for r in records:
        lo, hi = max(0, int(r) - window), min(T, int(r) + window + 1)
        vis = stream.visible[lo:hi]
        dist = np.where(vis, stream.distance[lo:hi], np.inf)
        best = dist.min(axis=0)
        rows = dist.argmin(axis=0)
        idx = np.flatnonzero(np.isfinite(best))
        idx = idx[np.argsort(best[idx], kind="stable")]
        bearing = stream.bearing[lo:hi][rows[idx], idx]
        x, y, z, yaw = (float(v) for v in stream.pose[r])
        out.append(NodeObservation(
            record=int(r), position=(x, y, z), yaw=yaw, objects=tuple(int(i) for i in idx),
            distances=tuple(float(best[i]) for i in idx), bearings=tuple(float(b) for b in bearing),
        ))
    return out


def node_sensors(scene: Scene, obs: NodeObservation, sensor_names: tuple[str, ...]) -> tuple[np.ndarray, np.ndarray]:
    """Aggregated readings (S,) float32 (mean over the seen objects reporting each channel) and mask (S,) bool."""
    total = np.zeros(len(sensor_names), np.float64)
    count = np.zeros(len(sensor_names), np.int64)
    col = {k: i for i, k in enumerate(sensor_names)}
    for o in obs.objects:
        for k, v in scene.objects[o].sensors:
            if k in col:
                total[col[k]] += v
                count[col[k]] += 1
    mean = np.where(count > 0, total / np.maximum(count, 1), 0.0)
    return mean.astype(np.float32), count > 0
