"""Per-episode navigation metrics and their summary.

Definitions (per episode; the summary averages over episodes, and over each modality in `by_modality`):
- success: every true goal declared FOUND within `eval.found_radius` of its box on the simulated
  trajectory, in the episode's order for strict episodes, within the step budget, and no FOUND declared at
  anything else (the loop runs the subgoals it read: a declaration counts for the true goal it was made at).
- progress (MultiON): share of goals found; strict episodes count only the in-order prefix.
- travel_distance_m: length of the simulated trajectory (MJX robot positions per control step).
- planned_rule1_m / planned_rule2_m: the first plan's route over the map, Rule 1 (edge distances) and
  Rule 2 (Euclidean between consecutive node coordinates); straight-line planners: the straight segments.
- success_ci95: Wilson 95% interval of the success rate over the block's episodes (`wilson_interval`).
- oracle_m: the oracle's shortest route (true goal nodes, optimal allowed order, Rule 1 from the start node).
- spl = success * oracle_m / max(travel, oracle_m); ppl = progress * oracle_m / max(travel, oracle_m).
- retrieval_accuracy: top-1 candidate observes the goal's instance (instance-level rule of
  retrieval/evaluate.py); null for methods without retrieval (etpnav).
- sim_time_s: control steps (driving plus the look-arounds' turns in place) x control period.
- task_time_s: host wall clock from instructions to plans (parsing, query embedding, retrieval kernels,
  order solving), measured over the whole batch and divided by the number of episodes.
- total_time_s = task_time_s + sim_time_s (the paper's "Total Time" covers both).
"""

from __future__ import annotations

import math
from collections import Counter, defaultdict
from collections.abc import Sequence

import numpy as np

from ragnav_jax.memory.paths import reconstruct_path


def _route(loop, b: int, start: int, nodes: list[int]) -> tuple[float, float]:
    """(Rule 1, Rule 2) lengths of the node route start -> nodes[0] -> ... over the map."""
    r1 = r2 = 0.0
    cur = start
    for n in nodes:
        if n is None or n < 0:
            continue
        if loop.spec.straight:
            seg = float(np.linalg.norm(loop.pos[b][n] - loop.pos[b][cur]))
            r1 += seg
            r2 += seg
        else:
            path = reconstruct_path(loop.pred[b], cur, n)
            if not path:
                continue
            r1 += float(loop.cost[b][cur, n])
            r2 += float(sum(np.linalg.norm(loop.pos[b][path[i + 1]] - loop.pos[b][path[i]]) for i in range(len(path) - 1)))
        cur = n
    return r1, r2


def oracle_lengths(loop, states: Sequence, oracle_nodes: Sequence[list]) -> list[float]:
    """The SPL reference of each state's episode: the memory-path length of Pi* over its true goals' nodes
    (`oracle_nodes[i]`: state i's per-goal candidate lists, the first the true one) from the start, goals the
    start cannot reach left out; one solver call for all (`plan_orders`)."""
    from ragnav_jax.evaluation.host_loop import plan_orders

    problems, walks = [], []
    for st, nodes in zip(states, oracle_nodes):
        b = st.b
        start = loop.nearest(b, loop.scenes[st.ep.scene].start.position[:2])
        goals = [g for g, c in enumerate(nodes) if c and np.isfinite(loop.cost[b][start, c[0]])]
        problems.append((loop.cost[b], start, [nodes[g][0] for g in goals], goals, st.ep.order == "strict",
                         loop.cfg.eval.strict_lam))
        walks.append((b, start, nodes))
    lengths = []
    for (b, cur, nodes), order in zip(walks, plan_orders(problems, loop.cfg.planning.solver,
                                                         loop.cfg.planning.local_search_iters)):
        c = 0.0
        for g in order:
            c += float(loop.cost[b][cur, nodes[g][0]])
            cur = nodes[g][0]
        lengths.append(c)
    return lengths


def episode_row(st, loop, oracle_length: float, cands, cfg, method: str) -> dict:
    """One episode's outcome against its true goals. The loop ran the subgoals it read; a declaration counts
    for the true goal it was made at (`truth`), and one made at no true goal is a wrong declaration, which
    fails the episode. `goal_status` is per true goal (found, else what became of the subgoal read in its
    place, or `missed`); `subgoal_status` per subgoal run."""
    ep = st.ep
    G = len(ep.goals)
    found = list(st.found)
    seq = [d["truth"] for d in st.declarations if d["correct"]]
    in_order = seq == sorted(seq)
    wrong = any(not d["correct"] for d in st.declarations)
    strict = ep.order == "strict"
    if strict:
        prefix = 0
        for g in range(G):
            if found[g] and (g == 0 or prefix == g):
                prefix += 1
            else:
                break
        progress = prefix / G if in_order else sum(1 for i, g in enumerate(seq) if g == i) / G
    else:
        progress = sum(found) / G
    budget_ok = st.steps + st.look_steps <= cfg.eval.max_steps
    success = all(found) and (in_order or not strict) and budget_ok and not wrong
    L = st.length
    Ls = oracle_length
    ratio = 1.0 if Ls <= 0 and L <= 0 else Ls / max(L, Ls, 1e-9)
    sc = loop.scenes[ep.scene]
    obs = np.asarray(loop.bank.memory.obs_object[st.b])
    ids = [o.id for o in sc.objects]
    top1 = []
    if loop.spec.explores:
        top1 = [None] * G
    else:
        for g in range(G):
            t = cands.top[st.e][g] if g < len(cands.top[st.e]) else None  # the retrieval's top-1 node
            gidx = ids.index(ep.goals[g]) if ep.goals[g] in ids else -1
            top1.append(t is not None and gidx >= 0 and gidx in set(obs[t].tolist()))
    first = [cands.nodes[st.e][g][0] if g < len(cands.nodes[st.e]) and cands.nodes[st.e][g] else None for g in st.planned]
    start = loop.nearest(st.b, sc.start.position[:2])
    r1, r2 = _route(loop, st.b, start, first) if not loop.spec.explores else (float("nan"), float("nan"))
    fails = [s.split(":", 1)[1] for s in st.status if s.startswith("failed")]
    reason = "success" if success else (
        "wrong_declaration" if wrong else
        (fails[0] if fails else ("order" if not in_order else st.reason or "incomplete")))
    return {
        "episode": ep.id, "scene": ep.scene, "modality": ep.modality, "order": ep.order, "method": method,
        "goals": G, "goal_ids": list(ep.goals), "success": bool(success), "progress": round(progress, 4),
        "spl": round(float(success) * ratio, 4), "ppl": round(progress * ratio, 4),
        "travel_distance_m": round(L, 3), "oracle_m": round(Ls, 3),
        "planned_rule1_m": None if math.isnan(r1) else round(r1, 3),
        "planned_rule2_m": None if math.isnan(r2) else round(r2, 3),
        "sim_time_s": round((st.steps + st.look_steps) * loop.ex.control_dt, 2), "steps": st.steps + st.look_steps,
        "retrieval_top1": top1, "declarations": st.declarations, "subgoal_status": list(st.status),
        "goal_status": ["found" if found[j] else (st.status[j] if j < len(st.status) and st.status[j] != "found"
                                                   else "missed") for j in range(G)],
        "wrong_declarations": sum(not d["correct"] for d in st.declarations),
        "rejected_candidates": int(sum(st.rejected)), "max_penetration_m": round(st.penetration, 4),
        "reason": reason, "ungrounded": list(cands.ungrounded.get(ep.id, ())),
        "tagged": list(cands.tagged.get(ep.id, ())),
        "revised": list(cands.revised.get(ep.id, ())),
        **({"legs": st.legs} if st.legs else {}),
    }


def _mean(xs) -> float | None:
    xs = [x for x in xs if x is not None and not (isinstance(x, float) and math.isnan(x))]
    return round(float(np.mean(xs)), 4) if xs else None


def _block(rows: list[dict]) -> dict:
    top1 = [t for r in rows for t in r["retrieval_top1"] if t is not None]
    ok = [r for r in rows if r["success"]]
    return {
        "episodes": len(rows),
        "success_rate": _mean([float(r["success"]) for r in rows]),
        "success_ci95": [round(x, 4) for x in wilson_interval(len(ok), len(rows))] if rows else None,
        "retrieval_accuracy": _mean([float(t) for t in top1]) if top1 else None,
        "spl": _mean([r["spl"] for r in rows]),
        "progress": _mean([r["progress"] for r in rows]),
        "ppl": _mean([r["ppl"] for r in rows]),
        "travel_distance_m": _mean([r["travel_distance_m"] for r in rows]),
        "travel_distance_success_m": _mean([r["travel_distance_m"] for r in ok]),
        "oracle_m": _mean([r["oracle_m"] for r in rows]),
        "planned_rule1_m": _mean([r["planned_rule1_m"] for r in rows]),
        "planned_rule2_m": _mean([r["planned_rule2_m"] for r in rows]),
        "sim_time_s": _mean([r["sim_time_s"] for r in rows]),
        "wrong_declarations": int(sum(r["wrong_declarations"] for r in rows)),
        "fallback_declarations": sum(bool(d.get("fallback")) for r in rows for d in r.get("declarations", ())),
        "fallback_correct": sum(bool(d.get("fallback")) and d["correct"] for r in rows for d in r.get("declarations", ())),
    }


def summarise(rows: list[dict], timing: dict, task_time_s: float, method: str) -> dict:
    out = {"method": method, **_block(rows)}
    out["retrieval_ms"] = round(timing.get("retrieval_ms_batched", 0.0), 4)
    out["retrieval_ms_single"] = round(timing.get("retrieval_ms_single", 0.0), 4)
    out["embed_ms"] = round(timing.get("embed_ms", 0.0), 4)
    out["task_time_s"] = round(task_time_s, 4)
    out["loop_wall_s"] = round(timing.get("loop_s", 0.0), 3)  # host wall clock of the closed loop (all episodes)
    out["total_time_s"] = round(task_time_s + (out["sim_time_s"] or 0.0), 3)
    by = defaultdict(list)
    for r in rows:
        by[r["modality"]].append(r)
    out["by_modality"] = {m: _block(v) for m, v in sorted(by.items())}
    if any("changed" in r for r in rows):  # a world that changed after exploration (evaluation/worlds.py)
        out["by_change"] = {k: _block([r for r in rows if r.get("changed") == (k == "changed")])
                            for k in ("static", "changed")}
    out["reasons"] = dict(Counter(r["reason"] for r in rows))
    return out


def wilson_interval(k: int, n: int, z: float = 1.959964) -> tuple[float, float]:
    """Wilson score interval of a success proportion k / n (95% by default); (0, 1) when n = 0."""
    if n == 0:
        return 0.0, 1.0
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return max(0.0, centre - half), min(1.0, centre + half)


def sign_test_p(wins: int, losses: int) -> float:
    """Exact two-sided sign test: P(a split at least this uneven | no difference), ties dropped."""
    n = wins + losses
    if n == 0:
        return 1.0
    k = min(wins, losses)
    tail = sum(math.comb(n, i) for i in range(k + 1)) / 2.0**n
    return min(1.0, 2.0 * tail)


def paired_comparison(base: list[dict], other: list[dict]) -> dict:
    """Episode-paired comparison of two methods' rows (matched by episode id) on success and on top-1
    retrieval per goal: where only `base` succeeds (wins), only `other` (losses), and the sign test's p."""
    by = {r["episode"]: r for r in other}
    common = [(r, by[r["episode"]]) for r in base if r["episode"] in by]
    wins = sum(a["success"] and not b["success"] for a, b in common)
    losses = sum(b["success"] and not a["success"] for a, b in common)
    pairs = [(x, y) for a, b in common for x, y in zip(a["retrieval_top1"], b["retrieval_top1"])
             if x is not None and y is not None]
    r_wins = sum(x and not y for x, y in pairs)
    r_losses = sum(y and not x for x, y in pairs)
    return {"episodes": len(common), "success_wins": wins, "success_losses": losses,
            "success_p": sign_test_p(wins, losses), "goals": len(pairs), "top1_wins": r_wins,
            "top1_losses": r_losses, "top1_p": sign_test_p(r_wins, r_losses)}
