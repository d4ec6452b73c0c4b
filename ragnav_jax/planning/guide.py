"""The structured navigation guide (paper: "target markers, relevance explanations, navigation cues").

Host-side and pure: `build_guide` turns one episode's OrderResult plus the memory's arrays and host
metadata into a JSON-ready dict; `guide_text` renders it for people; `draw_route` puts it on a
floor plan. Nothing here reads files or the memory, so the `ragnav plan` command and notebooks can
call it with whatever memory and retrieval produced.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path as FilePath

import numpy as np

from ragnav_jax.io import save_figure
from ragnav_jax.planning.paths import edge_lengths, path_list
from ragnav_jax.planning.types import STATUS_NAMES, OrderResult

GUIDE_SCHEMA = "ragnav-guide/1"


def _num(x: float) -> float | None:
    """JSON-safe float: rounded, None for inf/nan."""
    x = float(x)
    return round(x, 4) if math.isfinite(x) else None


def _turn(prev: np.ndarray, nxt: np.ndarray) -> float:
    """Signed heading change in degrees from direction `prev` to `nxt` (positive = left, y up)."""
    cross = prev[0] * nxt[1] - prev[1] * nxt[0]
    return math.degrees(math.atan2(cross, float(prev @ nxt)))


def leg_cues(
    nodes: Sequence[int],
    xy: np.ndarray,
    heading: float | None = None,
    node_rooms: Sequence[str | None] | None = None,
    node_objects: Sequence[Sequence[str]] | None = None,
    turn_threshold_deg: float = 30.0,
) -> list[dict]:
    """Navigation cues along one leg: turns (left / right / around), rooms entered, landmarks passed.

    Args:
      nodes: the leg's node ids, source first.
      xy: (N, 2) node coordinates.
      heading: direction of travel (radians) on arrival at the first node, None if unknown.
      node_rooms: per node, its room label (None if unknown).
      node_objects: per node, the objects seen there (landmarks).
    """
    cues: list[dict] = []
    seen: set[str] = set()
    dirs = [xy[b] - xy[a] for a, b in zip(nodes[:-1], nodes[1:])]
    prev = None if heading is None else np.array([math.cos(heading), math.sin(heading)])
    for i, v in enumerate(nodes):
        v = int(v)
        if i > 0 and node_rooms is not None:
            room, before = node_rooms[v], node_rooms[int(nodes[i - 1])]
            if room is not None and room != before:
                cues.append({"type": "enter", "node": v, "room": room})
        if i < len(dirs) and np.linalg.norm(dirs[i]) > 1e-9:
            if prev is not None:
                angle = _turn(prev, dirs[i])
                if abs(angle) >= 150.0:
                    cues.append({"type": "turn", "node": v, "direction": "around", "angle_deg": round(angle, 1)})
                elif abs(angle) >= turn_threshold_deg:
                    side = "left" if angle > 0 else "right"
                    cues.append({"type": "turn", "node": v, "direction": side, "angle_deg": round(angle, 1)})
            prev = dirs[i]
        if node_objects is not None and 0 < i < len(nodes) - 1:
            new = [o for o in node_objects[v] if o not in seen]
            seen.update(new)
            if new:
                cues.append({"type": "pass", "node": v, "landmarks": new})
    if len(nodes) > 0:
        end = int(nodes[-1])
        arrive = {"type": "arrive", "node": end}
        if node_rooms is not None and node_rooms[end] is not None:
            arrive["room"] = node_rooms[end]
        if node_objects is not None and node_objects[end]:
            arrive["landmarks"] = list(node_objects[end])
        cues.append(arrive)
    return cues


def build_guide(
    result: OrderResult,
    *,
    start: int,
    positions: np.ndarray,
    pred: np.ndarray,
    weights: np.ndarray,
    goal_names: Sequence[str],
    has_distance: np.ndarray | None = None,
    rank: Sequence[int] | None = None,
    explanations: Sequence[dict | None] | None = None,
    node_rooms: Sequence[str | None] | None = None,
    node_objects: Sequence[Sequence[str]] | None = None,
    start_heading: float | None = None,
    turn_threshold_deg: float = 30.0,
) -> dict:
    """The guide of one episode as a JSON-ready dict (schema "ragnav-guide/1").

    Args:
      result: one episode's OrderResult (fields of shape (G,) and ()).
      start: start node; positions: (N, 3) node coordinates; pred: (N, N) predecessor matrix;
      weights: (N, N) edge distances (Rule 1), has_distance: (N, N) bool (default weights > 0).
      goal_names: (G,) names of the goals as the instruction says them (padding may be omitted).
      rank: (G,) instruction position of each goal (default: goal index).
      explanations: per goal, why its marker was chosen (e.g. retrieval scores and matched terms).
      node_rooms, node_objects: per node, its room label and the objects seen there.
      start_heading: the robot's yaw (radians) at the start, for the first turn cue.
    """
    r = OrderResult(*(np.asarray(x) for x in result))
    positions = np.asarray(positions, np.float64)
    xy = positions[:, :2]
    weights = np.asarray(weights, np.float32)
    if has_distance is None:
        has_distance = np.isfinite(weights) & (weights > 0)
    G = len(r.order)
    rank = list(range(G)) if rank is None else [int(x) for x in rank]

    def marker(node: int) -> dict:
        m = {"node": int(node), "position": [_num(c) for c in positions[node]]}
        if node_rooms is not None and node_rooms[node] is not None:
            m["room"] = node_rooms[node]
        return m

    targets, total, rules = [], 0.0, set()
    here, heading = int(start), start_heading
    for step, g in enumerate(int(x) for x in r.order if x >= 0):
        node = int(r.visit_nodes[step])
        nodes = path_list(pred, here, node)
        entry = {
            "step": step + 1,
            "goal": g,
            "name": goal_names[g] if g < len(goal_names) else f"goal {g}",
            "instruction_rank": rank[g],
            "candidate": int(r.choice[g]),
            "marker": marker(node),
            "why": dict(explanations[g]) if explanations is not None and explanations[g] is not None else {},
        }
        if nodes is None:  # the planner's costs said reachable but the predecessors disagree
            entry["leg"] = {"nodes": [], "distance_m": None, "cues": [], "error": "no path in predecessor matrix"}
            targets.append(entry)
            continue
        arr = np.array(nodes, np.int32)
        lengths, rule2 = (
            np.asarray(x) for x in edge_lengths(arr, np.ones(len(arr), bool), positions, weights, has_distance)
        )
        dist = float(lengths.sum())
        total += dist
        rules.update(["rule2" if f else "rule1" for f in rule2.tolist()])
        entry["leg"] = {
            "nodes": nodes,
            "points": [[_num(x), _num(y)] for x, y in xy[arr]],
            "distance_m": _num(dist),
            "cues": leg_cues(nodes, xy, heading, node_rooms, node_objects, turn_threshold_deg),
        }
        if len(nodes) > 1:
            d = xy[nodes[-1]] - xy[nodes[-2]]
            heading = math.atan2(d[1], d[0])
        here = node
        targets.append(entry)

    unreachable = [
        {
            "goal": g,
            "name": goal_names[g] if g < len(goal_names) else f"goal {g}",
            "instruction_rank": rank[g],
            "reason": "no path from the start in the map",
        }
        for g in range(G)
        if g < len(goal_names) and not bool(r.reachable[g]) and goal_names[g]
    ]
    rule = "rule1" if rules <= {"rule1"} else ("rule2" if rules == {"rule2"} else "mixed")
    return {
        "schema": GUIDE_SCHEMA,
        "status": STATUS_NAMES[int(r.status)],
        "start": marker(int(start)),
        "order": [int(x) for x in r.order if x >= 0],
        "inversions": int(r.inversions),
        "instruction_order_kept": int(r.inversions) == 0,
        "planned_cost": _num(r.travel),
        "objective": _num(r.objective),
        "distance_m": _num(total),
        "distance_rule": rule,
        "targets": targets,
        "unreachable": unreachable,
    }


_CUE_TEXT = {
    "enter": lambda c: f"enter the {c['room']}",
    "turn": lambda c: (
        "turn around" if c["direction"] == "around" else f"turn {c['direction']} ({abs(c['angle_deg']):.0f} deg)"
    ),
    "pass": lambda c: "pass " + ", ".join(c["landmarks"]),
    "arrive": lambda c: (
        "arrive"
        + (f" in the {c['room']}" if "room" in c else "")
        + (f" by {', '.join(c['landmarks'])}" if c.get("landmarks") else "")
    ),
}


def guide_text(guide: dict) -> str:
    """A readable rendering of a guide dict."""
    rule = {
        "rule1": "edge distances, Rule 1",
        "rule2": "straight lines between nodes, Rule 2",
        "mixed": "Rule 1 with Rule 2 where edges lack a distance",
    }[guide["distance_rule"]]
    names = [t["name"] for t in guide["targets"]]
    kept = "instruction order kept" if guide["instruction_order_kept"] else f"{guide['inversions']} pair(s) reordered"
    dist = guide["distance_m"]
    lines = [
        f"Plan ({guide['status']}): {len(names)} target(s): " + (" -> ".join(names) if names else "none"),
        f"  {kept}; distance {dist:.2f} m ({rule})" if dist is not None else f"  {kept}",
    ]
    for t in guide["targets"]:
        m = t["marker"]
        where = f"node {m['node']} at ({m['position'][0]:.2f}, {m['position'][1]:.2f})"
        room = f" in the {m['room']}" if "room" in m else ""
        lines.append(f"{t['step']}. {t['name']} (instruction #{t['instruction_rank'] + 1}): {where}{room}")
        if t["why"]:
            why = "; ".join(f"{k}: {v:.3g}" if isinstance(v, float) else f"{k}: {v}" for k, v in t["why"].items())
            lines.append(f"   why: {why}")
        leg = t["leg"]
        if leg.get("error"):
            lines.append(f"   route: {leg['error']}")
            continue
        cues = "; ".join(_CUE_TEXT[c["type"]](c) for c in leg["cues"])
        d = leg["distance_m"]
        lines.append(
            f"   route: {d:.2f} m, {len(leg['nodes'])} nodes: {cues}" if d is not None else f"   route: {cues}"
        )
    for u in guide["unreachable"]:
        lines.append(f"unreachable: {u['name']} (instruction #{u['instruction_rank'] + 1}): {u['reason']}")
    return "\n".join(lines)


def draw_route(ax, guide: dict, color_map: str = "viridis"):
    """Draws a guide's route (one colour per leg) and numbered target markers on a matplotlib axis."""
    import matplotlib.pyplot as plt

    cmap = plt.get_cmap(color_map)
    n = max(len(guide["targets"]), 1)
    s = guide["start"]["position"]
    ax.plot(s[0], s[1], marker="s", color="#e63946", ms=6, zorder=5)
    for i, t in enumerate(guide["targets"]):
        pts = np.array(t["leg"].get("points") or [], float).reshape(-1, 2)
        c = cmap(i / max(n - 1, 1) * 0.85)
        if len(pts):
            ax.plot(pts[:, 0], pts[:, 1], "-", color=c, lw=2.2, alpha=0.9, zorder=4)
            ax.plot(pts[:, 0], pts[:, 1], ".", color=c, ms=4, zorder=4)
        p = t["marker"]["position"]
        ax.plot(p[0], p[1], marker="o", ms=13, color=c, mec="black", zorder=6)
        ax.text(
            p[0], p[1], str(t["step"]), ha="center", va="center", fontsize=7, color="white", weight="bold", zorder=7
        )
        ax.annotate(
            t["name"],
            (p[0], p[1]),
            xytext=(6, 6),
            textcoords="offset points",
            fontsize=7,
            zorder=7,
            bbox=dict(boxstyle="round,pad=0.15", fc="white", ec=c, alpha=0.85),
        )
    return ax


def save_route_picture(scene, guide: dict, out: str | FilePath, dpi: int = 150) -> FilePath:
    """Saves the floor plan of `scene` (ragnav_jax.world.scene.Scene) with the guide's route on it."""
    import matplotlib.pyplot as plt

    from ragnav_jax.world.plot import draw_floor_plan

    out = FilePath(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    ax = draw_floor_plan(scene, labels=True)
    draw_route(ax, guide)
    names = " -> ".join(t["name"] for t in guide["targets"]) or "no reachable target"
    ax.set_title(f"{scene.name}: {names} ({guide['distance_m'] or 0:.1f} m)")
    ax.figure.tight_layout()
    save_figure(ax.figure, out, dpi=dpi)
    plt.close(ax.figure)
    return out
