"""The host loop's distances and the helpers that measure them: clearance to walls and objects
(`segment_clearance_np`), the local planner's occupancy grid and gaps, the spacing of replayed exploration,
stops round an object's box (`approach_ring`) and a point's distance to one (`box_distance`). The device loop
(`evaluation/loop/`) imports the same constants.
"""

from __future__ import annotations

import math

import numpy as np

from ragnav_jax.memory.topomap import segment_clearance as _segment_clearance

THIN_M = 0.3  # metres between replayed exploration waypoints (ETPNav-style)
SAME_INSTANCE_M = 0.5  # a seen object this close to the retrieved instance's estimated position is that instance
TIGHT_PENALTY = 10.0  # driving-path cost factor of map edges that pass closer to an obstacle than the robot's radius
GRID_M = 0.05  # occupancy grid of the local planner (metres per cell)
GRID_MARGIN_M = 0.04  # clearance beyond the robot's radius the local planner keeps
GRID_WINDOW_M = 1.5  # metres around a tight segment the local planner searches first (approaches: then the whole house)
TIGHT_GAP_M = 0.0  # clearance beyond the robot's radius of the passages the local planner tries last
ESCAPE_M = 0.3  # metres around a leg's ends where the local planner may pass cells as tight as the end itself
CLOSER_GAP_M = 0.6  # extra metres (beyond approach_gap + robot radius) the look-closer leg stops short of it


def segment_clearance_np(p: np.ndarray, q: np.ndarray | None, obs: dict) -> np.ndarray:
    """(P,) clearance of segments p-q (P, 2) to a scene's walls and blocking objects (host NumPy); q None: of the
    points p."""
    return _segment_clearance(np.asarray(p, np.float32), None if q is None else np.asarray(q, np.float32), obs, np)


def approach_ring(c: np.ndarray, half: np.ndarray, gap: float, per_side: int = 5) -> np.ndarray:
    """(4 * per_side + 12, 2) stops at distance `gap` from a box footprint (centre c, half sizes): along
    each side's outward normal, and three directions round each corner."""
    t = np.linspace(-1.0, 1.0, per_side + 2)[1:-1]
    out = []
    for axis in (0, 1):
        other = 1 - axis
        for sign in (-1.0, 1.0):
            p = np.zeros((per_side, 2), np.float32)
            p[:, axis] = c[axis] + sign * (half[axis] + gap)
            p[:, other] = c[other] + t * half[other]
            out.append(p)
    for sx in (-1.0, 1.0):
        for sy in (-1.0, 1.0):
            corner = c + np.asarray([sx, sy]) * half
            for a in (0.0, math.pi / 4, math.pi / 2):
                out.append((corner + gap * np.asarray([sx * math.cos(a), sy * math.sin(a)]))[None])
    return np.concatenate(out).astype(np.float32)


def box_distance(obj, xy) -> float:
    """Planar metres from a point to an object's box footprint (0 inside)."""
    dx = max(0.0, abs(xy[0] - obj.position[0]) - obj.size[0] / 2)
    dy = max(0.0, abs(xy[1] - obj.position[1]) - obj.size[1] / 2)
    return math.hypot(dx, dy)
