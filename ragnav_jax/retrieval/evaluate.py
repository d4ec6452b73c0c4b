"""Retrieval evaluation over an episodes file: top-1, instance-level accuracy per modality and timing.

Accuracy rule (instance-level, top-1): subgoal k of an episode is correct when the single best node
returned for it *observes the ground-truth object instance* goal k, i.e. that instance is among the
objects visible from the node's key pose (memory.obs_object). Another object of the same category
does not count. Subgoals are matched to goals by position; an instruction that fails to parse, or
parses into fewer subgoals than it has goals, scores its unmatched goals as wrong.

Timing: `retrieval_ms_batched` is the wall time of the one jitted call scoring every subgoal of every
scene, divided by the number of subgoals (kernels only; queries already embedded);
`retrieval_ms_single` is the warm latency of scoring one subgoal in one scene (kernels only, median
of repeats); `embed_ms` is the host time to embed the query texts, per subgoal. Compilation is
reported apart (`compile_s`).
"""

from __future__ import annotations

import time
from collections import defaultdict
from typing import Sequence

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.language.episodes import Episode
from ragnav_jax.language.parser import parse_instruction
from ragnav_jax.language.types import ParseError, Subgoal
from ragnav_jax.memory.types import MemoryBank
from ragnav_jax.retrieval.baselines import BASELINES, TextMemory
from ragnav_jax.retrieval.index import build_bank_index, node_slots
from ragnav_jax.retrieval.params import ABLATIONS, RetrievalParams, ablation_params
from ragnav_jax.retrieval.query import encode_subgoals
from ragnav_jax.retrieval.score import score_subgoal
from ragnav_jax.world.scene import Scene

METHODS = tuple(f"ragnav:{a}" if a != "ragnav" else "ragnav" for a in ABLATIONS) + tuple(BASELINES)


def _median_time(fn, repeats: int = 7) -> float:
    ts = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        jax.block_until_ready(fn())
        ts.append(time.perf_counter() - t0)
    return float(np.median(ts))


@jax.jit
def score_bank(index, queries, qmask, params):
    """Scores for every (scene, query slot): index (B, ...), queries (B, Q, ...), qmask (B, Q).

    Returns best node (B, Q) int32 and its score (B, Q)."""

    def one_scene(idx, qs):
        s, _ = jax.vmap(score_subgoal, (None, 0, None))(idx, qs, params)
        return jnp.argmax(s, axis=-1).astype(jnp.int32), jnp.max(s, axis=-1)

    best, top = jax.vmap(one_scene)(index, queries)
    return jnp.where(qmask, best, -1), top


def parse_all(episodes: Sequence[Episode]) -> list[tuple[Subgoal, ...] | None]:
    out = []
    for ep in episodes:
        try:
            out.append(parse_instruction(ep.instruction).subgoals)
        except ParseError:
            out.append(None)
    return out


def evaluate_retrieval(
    bank: MemoryBank, scenes: Sequence[Scene], episodes: Sequence[Episode], embedder, method: str = "ragnav",
    params: RetrievalParams | None = None,
) -> tuple[list[dict], dict]:
    """Runs one method over all episodes; returns per-subgoal rows and a summary dict."""
    if method not in METHODS:
        from ragnav_jax.errors import UserError

        raise UserError(f"unknown retrieval method '{method}' (known: {', '.join(METHODS)})")
    names = list(bank.names)
    by_scene = {s.name: s for s in scenes}
    unknown = sorted({ep.scene for ep in episodes} - set(names))
    if unknown:
        from ragnav_jax.errors import UserError

        raise UserError(f"episodes refer to scenes without memory: {', '.join(unknown)}")
    parsed = parse_all(episodes)
    # Flat list of (episode, goal k, subgoal or None).
    items = []
    for ep, sgs in zip(episodes, parsed):
        for k, goal in enumerate(ep.goals):
            items.append((ep, k, goal, sgs[k] if sgs is not None and k < len(sgs) else None))
    live = [(i, it) for i, it in enumerate(items) if it[3] is not None]
    best_node = np.full(len(items), -1)
    timing: dict = {}
    if method.startswith("ragnav"):
        variant = method.split(":", 1)[1] if ":" in method else "ragnav"
        p = ablation_params(params or RetrievalParams.create(), variant)
        index, imetas = build_bank_index(bank, scenes, embedder)
        sensor_names = list(bank.metas[0].sensor_names)
        t0 = time.perf_counter()
        q_all = encode_subgoals([it[3] for _, it in live], embedder, sensor_names) if live else None
        timing["embed_ms"] = 1e3 * (time.perf_counter() - t0) / max(len(live), 1)
        if live:
            per_scene = defaultdict(list)
            for pos, (i, it) in enumerate(live):
                per_scene[names.index(it[0].scene)].append((pos, i))
            qmax = max(len(v) for v in per_scene.values())
            B = len(names)
            take = np.zeros((B, qmax), np.int32)
            qmask = np.zeros((B, qmax), bool)
            for b, lst in per_scene.items():
                take[b, : len(lst)] = [pos for pos, _ in lst]
                qmask[b, : len(lst)] = True
            queries = jax.tree.map(lambda x: x[jnp.asarray(take)], q_all)
            t0 = time.perf_counter()
            jax.block_until_ready(score_bank(index, queries, jnp.asarray(qmask), p))
            timing["compile_s"] = time.perf_counter() - t0
            run = lambda: score_bank(index, queries, jnp.asarray(qmask), p)  # noqa: E731
            timing["retrieval_ms_batched"] = 1e3 * _median_time(run, 3) / len(live)
            best, _ = run()
            best = np.asarray(best)
            for b, lst in per_scene.items():
                for slot, (pos, i) in enumerate(lst):
                    best_node[i] = best[b, slot]
            # Warm single-query latency: one subgoal, one scene.
            b0 = next(iter(per_scene))
            idx0 = jax.tree.map(lambda x: x[b0], index)
            q0 = jax.tree.map(lambda x: x[per_scene[b0][0][0]], q_all)
            single = jax.jit(score_subgoal)
            jax.block_until_ready(single(idx0, q0, p))
            timing["retrieval_ms_single"] = 1e3 * _median_time(lambda: single(idx0, q0, p))
        observed = {im.scene: im.observed for im in imetas}
    else:
        cls = BASELINES[method]
        observed = {}
        t_total, n_total = 0.0, 0
        for b, meta in enumerate(bank.metas):
            scene = by_scene[meta.scene]
            objs, phrases = node_slots(meta, scene)
            mem = TextMemory(tuple(meta.captions), tuple(tuple(p) for p in phrases))
            observed[meta.scene] = tuple(
                frozenset(int(x) for x in np.asarray(bank.memory.obs_object[b, i]) if x >= 0) for i in range(meta.num_nodes)
            )
            mine = [(i, it) for i, it in live if it[0].scene == meta.scene]
            if not mine or meta.num_nodes == 0:
                continue
            model = cls(mem, embedder)
            t0 = time.perf_counter()
            s = model.scores([it[3].text or it[0].instruction for _, it in mine])
            t_total += time.perf_counter() - t0
            n_total += len(mine)
            for (i, _), row in zip(mine, s):
                best_node[i] = int(np.argmax(row[: meta.num_nodes]))
        timing["retrieval_ms_single"] = timing["retrieval_ms_batched"] = 1e3 * t_total / max(n_total, 1)
        timing["embed_ms"] = 0.0  # included in the baselines' scoring time
        timing["compile_s"] = 0.0
    rows = []
    for i, (ep, k, goal, sg) in enumerate(items):
        scene = by_scene[ep.scene]
        gidx = next((j for j, o in enumerate(scene.objects) if o.id == goal), -1)
        node = int(best_node[i])
        ok = sg is not None and node >= 0 and gidx in observed[ep.scene][node]
        rows.append({
            "episode": ep.id, "scene": ep.scene, "modality": ep.modality, "goal_index": k, "goal": goal,
            "subgoal": sg.target.phrase if sg is not None else None, "node": node, "correct": bool(ok),
            "failure": None if ok else ("parse" if sg is None else "wrong_node"),
        })
    acc = float(np.mean([r["correct"] for r in rows])) if rows else 0.0
    by_mod = defaultdict(list)
    for r in rows:
        by_mod[r["modality"]].append(r["correct"])
    summary = {
        "method": method,
        "retrieval_accuracy": acc,
        "by_modality": {m: {"retrieval_accuracy": float(np.mean(v)), "queries": len(v)} for m, v in sorted(by_mod.items())},
        "queries": len(rows),
        "episodes": len(episodes),
        "parse_failures": sum(r["failure"] == "parse" for r in rows),
        **{k: round(v, 4) for k, v in timing.items()},
    }
    return rows, summary
