"""The navigation guide: markers, explanations, cues (turns, rooms, landmarks), unreachable goals, picture."""

from __future__ import annotations

import json

import jax
import jax.numpy as jnp
import numpy as np
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import shortest_path

from ragnav_jax.planning import build_guide, guide_text, held_karp, leg_cues, order_problem, save_route_picture

#   4 (0,3) bedroom          2 (2,2) kitchen -- 3 (4,2) kitchen
#   |                        |
#   0 (0,0) hallway -------- 1 (2,0) hallway           5 (9,9) greenhouse, disconnected
POS = np.array([[0, 0, 0], [2, 0, 0], [2, 2, 0], [4, 2, 0], [0, 3, 0], [9, 9, 0]], np.float32)
EDGES = [(0, 1), (1, 2), (2, 3), (0, 4)]
ROOMS = ["hallway", "hallway", "kitchen", "kitchen", "bedroom", "greenhouse"]
OBJECTS = [[], ["door"], ["fridge", "table"], ["mug"], ["bed"], ["plant"]]


def small_map():
    w = np.zeros((6, 6), np.float32)
    for a, b in EDGES:
        w[a, b] = w[b, a] = np.linalg.norm(POS[a, :2] - POS[b, :2])
    dist, pred = shortest_path(csr_matrix(w.astype(np.float64)), directed=False, return_predecessors=True)
    return w, dist.astype(np.float32), np.where(pred < 0, -1, pred).astype(np.int32)


def test_leg_cues_turns_rooms_landmarks():
    xy = POS[:, :2]
    cues = leg_cues([0, 1, 2, 3], xy, heading=0.0, node_rooms=ROOMS, node_objects=OBJECTS)
    kinds = [(c["type"], c.get("direction") or c.get("room") or c.get("landmarks")) for c in cues]
    assert kinds == [
        ("turn", "left"),  # at node 1: east -> north
        ("pass", ["door"]),
        ("enter", "kitchen"),
        ("turn", "right"),  # at node 2: north -> east
        ("pass", ["fridge", "table"]),
        ("arrive", "kitchen"),
    ]
    back = leg_cues([3, 2], xy, heading=0.0)
    assert back[0]["direction"] == "around"


def test_guide_json_and_text_with_unreachable_goal(tmp_path, apartment):
    w, dist, pred = small_map()
    names = ["mug", "bed", "plant"]
    p = order_problem(dist, 0, np.array([3, 4, 5], np.int32), rank=np.array([0, 1, 2], np.int32))
    result = jax.jit(held_karp)(p, jnp.float32(100.0))  # strict enough: mug, then bed
    why = [{"score": 0.91, "matched": "mug on the kitchen counter"}, {"score": 0.7}, {"score": 0.4}]
    guide = build_guide(
        result,
        start=0,
        positions=POS,
        pred=pred,
        weights=w,
        goal_names=names,
        explanations=why,
        node_rooms=ROOMS,
        node_objects=OBJECTS,
        start_heading=0.0,
    )
    json.loads(json.dumps(guide))  # JSON-ready, no inf / numpy scalars
    assert guide["status"] == "some_unreachable"
    assert [t["name"] for t in guide["targets"]] == ["mug", "bed"]
    assert guide["unreachable"] == [
        {"goal": 2, "name": "plant", "instruction_rank": 2, "reason": "no path from the start in the map"}
    ]
    mug, bed = guide["targets"]
    assert mug["marker"] == {"node": 3, "position": [4.0, 2.0, 0.0], "room": "kitchen"}
    assert mug["why"]["matched"] == "mug on the kitchen counter"
    assert mug["leg"]["nodes"] == [0, 1, 2, 3] and bed["leg"]["nodes"] == [3, 2, 1, 0, 4]
    assert guide["distance_m"] == 6.0 + 9.0 and guide["distance_rule"] == "rule1"
    assert guide["instruction_order_kept"]
    # arriving at node 3 heading east, the way back starts with a U-turn
    assert bed["leg"]["cues"][0]["direction"] == "around"
    text = guide_text(guide)
    assert "mug -> bed" in text and "enter the kitchen" in text and "unreachable: plant" in text
    out = save_route_picture(apartment, guide, tmp_path / "route.png", dpi=50)
    assert out.exists() and out.stat().st_size > 1000


def test_guide_rule2_when_edges_have_no_distance():
    w, dist, pred = small_map()
    p = order_problem(dist, 0, np.array([3], np.int32))
    result = jax.jit(held_karp)(p, jnp.float32(0.0))
    nan_w = np.where(w > 0, np.nan, 0).astype(np.float32)
    guide = build_guide(result, start=0, positions=POS, pred=pred, weights=nan_w, goal_names=["mug"])
    assert guide["distance_rule"] == "rule2" and guide["distance_m"] == 6.0
    assert guide["status"] == "ok" and guide["unreachable"] == []
