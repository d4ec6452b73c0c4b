"""Instruction -> guide for one scene: parse, retrieve top-k per subgoal, plan the order, build the guide.

    guide = plan_instruction(bank, scene, "First the sofa, then the fridge", embedder, cfg)
"""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.language.parser import parse_instruction
from ragnav_jax.planning.costs import candidate_unary, order_problem
from ragnav_jax.planning.guide import build_guide
from ragnav_jax.planning.order import solve
from ragnav_jax.retrieval.index import build_scene_index
from ragnav_jax.retrieval.params import params_from_config
from ragnav_jax.retrieval.query import encode_subgoals
from ragnav_jax.retrieval.score import score_subgoal
from ragnav_jax.world.scene import room_of

# Compiled once per (subgoal count, index shape), shared by every call (a fresh jit per call recompiled).
_score_subgoals = jax.jit(jax.vmap(score_subgoal, (None, 0, None)))


def nearest_node(mem, xy) -> int:
    pos = np.asarray(mem.position)[:, :2]
    d = np.linalg.norm(pos - np.asarray(xy, np.float32), axis=1)
    d[~np.asarray(mem.node_mask)] = np.inf
    return int(np.argmin(d))


def plan_instruction(bank, scene, instruction: str, embedder, cfg) -> dict:
    """The structured guide (ragnav-guide/1 dict, plus the parsed chain) for one instruction."""
    mem, meta = bank.scene(scene.name)
    n_slots = max([len(o) for o in meta.observed_ids] + [1])
    max_deg = max(int(np.asarray(mem.adjacency).sum(-1).max()), 1)
    index, imeta = build_scene_index(mem, meta, scene, embedder, n_slots, max_deg)
    chain = parse_instruction(instruction)
    queries = encode_subgoals(chain.subgoals, embedder, list(meta.sensor_names))
    params = params_from_config(cfg.retrieval)
    scores, expl = _score_subgoals(index, queries, params)
    k = min(cfg.planning.top_k, int(mem.node_mask.shape[0]))
    top_s, top_n = jax.lax.top_k(scores, k)  # (G, k)
    valid = top_s > -1e8
    targets = jnp.where(valid, top_n, -1)
    G = len(chain.subgoals)
    rank = jnp.arange(G, dtype=jnp.int32) if chain.order == "strict" else jnp.zeros(G, jnp.int32)
    start = nearest_node(mem, scene.start.position)
    problem = order_problem(mem.path_cost, jnp.int32(start), targets, rank=rank,
                            unary=candidate_unary(top_s, cfg.planning.candidate_weight, valid))
    lam = cfg.planning.lam if chain.order == "strict" else 0.0
    result = jax.tree.map(lambda x: x[0, 0], solve(jax.tree.map(lambda x: x[None], problem), jnp.array([lam]),
                                                   method=cfg.planning.solver, max_iters=cfg.planning.local_search_iters))
    choice = np.asarray(result.choice)
    explanations = []
    e = jax.tree.map(np.asarray, expl)
    for g in range(G):
        node = int(np.asarray(targets)[g, max(int(choice[g]), 0)])
        if node < 0:
            explanations.append({"reason": "no node matches this subgoal"})
            continue
        slot = int(e["instance"][g, node])
        explanations.append({
            "subgoal": chain.subgoals[g].target.phrase, "score": round(float(scores[g, node]), 4),
            "caption": meta.captions[node],
            "matched": imeta.slot_phrases[node][slot] if slot < len(imeta.slot_phrases[node]) else None,
            "fingerprint_similarity": round(float(e["node_sem"][g, node]), 4),
            "instance_similarity": round(float(e["instance_sim"][g, node]), 4),
            "location_term": round(float(e["loc"][g, node]), 4), "sensor_term": round(float(e["sensor"][g, node]), 4),
            "time_term": round(float(e["time"][g, node]), 4),
            "anchor_node": int(e["anchor"][g, node]), "neighbour_boost": round(float(e["boost"][g, node]), 4),
        })
    pos = np.asarray(mem.position)
    n = meta.num_nodes
    rooms = [room_of(scene.rooms, float(pos[i, 0]), float(pos[i, 1])) or None for i in range(pos.shape[0])]
    room_type = {r.id: r.type for r in scene.rooms}
    node_rooms = [room_type.get(r) if r else None for r in rooms]
    node_objects = [list(meta.caption_labels[i]) if i < n else [] for i in range(pos.shape[0])]
    weights = np.where(np.asarray(mem.adjacency), np.asarray(mem.distance), 0.0)
    guide = build_guide(
        result, start=start, positions=pos, pred=np.asarray(mem.path_pred), weights=weights,
        goal_names=[sg.target.phrase for sg in chain.subgoals], rank=[int(x) for x in np.asarray(rank)],
        explanations=explanations, node_rooms=node_rooms, node_objects=node_objects,
        start_heading=scene.start.yaw, turn_threshold_deg=cfg.planning.turn_threshold_deg,
    )
    guide["instruction"] = instruction
    guide["chain"] = chain.to_dict()
    return guide
