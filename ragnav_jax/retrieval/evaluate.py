"""Retrieval evaluation over an episodes file: top-1, instance-level accuracy per modality and timing.

Accuracy rule (instance-level, top-1): subgoal k of an episode is correct when the single best node
returned for it *observes the ground-truth object instance* goal k, i.e. that instance is among the
objects visible from the node's key pose (memory.obs_object). Another object of the same category
does not count. Subgoals are matched to goals by position; an instruction that fails to parse, or
parses into fewer subgoals than it has goals, scores its unmatched goals as wrong. RAGNav's rows also say whether
the instance the best node's score came from is the goal's object (`instance_correct`, summary
`instance_accuracy`): a key pose that sees two mugs observes both, and time-indexed queries ask which of them.

Timing: `retrieval_ms_batched` is the wall time of the one jitted call scoring every subgoal of every
scene, divided by the number of subgoals (kernels only; queries already embedded);
`retrieval_ms_single` is the warm latency of scoring one subgoal in one scene (kernels only, median
of repeats); `embed_ms` is the host time to embed the query texts, per subgoal. Compilation is
reported apart (`compile_s`).
"""

from __future__ import annotations

import dataclasses
import functools
import time
from collections import defaultdict
from collections.abc import Callable, Sequence

import jax
import jax.numpy as jnp
import numpy as np
from flax import struct

from ragnav_jax.language.episodes import Episode
from ragnav_jax.language.parser import parse_instruction
from ragnav_jax.language.types import ParseError, Subgoal, TaskChain
from ragnav_jax.memory.types import MemoryBank
from ragnav_jax.pytrees import take as take_leaves
from ragnav_jax.retrieval.baselines import BASELINES, TextMemory
from ragnav_jax.retrieval.index import IndexMeta, build_bank_index, node_slots
from ragnav_jax.retrieval.params import ABLATIONS, RetrievalParams, ablation_params
from ragnav_jax.retrieval.query import QueryArrays, encode_subgoals
from ragnav_jax.retrieval.score import RetrievalIndex, score_subgoal
from ragnav_jax.world.scene import Scene

METHODS = tuple(f"ragnav:{a}" if a != "ragnav" else "ragnav" for a in ABLATIONS) + tuple(BASELINES)


def _median_time(fn, repeats: int = 7) -> float:
    ts = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        jax.block_until_ready(fn())
        ts.append(time.perf_counter() - t0)
    return float(np.median(ts))


def scored_batch(index: RetrievalIndex, queries: QueryArrays, params: RetrievalParams, gate_tau=None):
    """score_subgoal for every (scene, query slot): index (B, ...), queries (B, Q, ...) -> scores (B, Q, N)
    and the explanation dict, each entry (B, Q, N). The one batched scoring path: evaluation, the closed
    loop's candidate ranking, sweeps (vmapped over a grid of params) and the tuning surrogate (with
    gate_tau) all go through it; under jit, explanation entries nobody reads are not computed."""

    def one_scene(idx, qs):
        return jax.vmap(lambda q: score_subgoal(idx, q, params, gate_tau))(qs)

    return jax.vmap(one_scene)(index, queries)


def node_scores(index: RetrievalIndex, queries: QueryArrays, params: RetrievalParams, gate_tau=None) -> jax.Array:
    """Scores of every node for every (scene, query slot): (B, Q, N) (scored_batch without the explanation)."""
    return scored_batch(index, queries, params, gate_tau)[0]


def best_nodes(index: RetrievalIndex, queries: QueryArrays, qmask: jax.Array, params: RetrievalParams):
    """Top-1 node (B, Q) int32 (-1 where qmask is False) and its score (B, Q)."""
    s = node_scores(index, queries, params)
    best = jnp.argmax(s, axis=-1).astype(jnp.int32)
    return jnp.where(qmask, best, -1), jnp.max(s, axis=-1)


score_bank = jax.jit(best_nodes)
score_bank.__doc__ = "Jitted best_nodes: (index (B, ...), queries (B, Q, ...), qmask (B, Q), params) -> (best, top)."
# each node's best instance slot (B, Q, N): the instance rule of RAGNav's rows, compiled once per shape
_best_instances = jax.jit(lambda index, queries, params: scored_batch(index, queries, params)[1]["instance"])


@struct.dataclass
class RetrievalBatch:
    """Every parsed subgoal of an episodes file grouped by scene (padded), with what accuracy needs."""

    index: RetrievalIndex  # (B, ...) one per scene of the bank
    queries: QueryArrays  # (B, Q, ...) the subgoals of each scene, padded
    qmask: jax.Array  # (B, Q) bool, real subgoal slots
    truth: jax.Array  # (B, Q, N) bool: node observes the slot's ground-truth goal instance
    group: jax.Array  # (B, Q, G) bool: one-hot modality (BatchMeta.modalities) of the slot's episode


@dataclasses.dataclass(frozen=True)
class BatchMeta:
    """Host-side bookkeeping of a RetrievalBatch."""

    items: tuple  # (episode, goal k, goal object id, Subgoal or None) for every goal of every episode
    slots: tuple  # (scene b, query slot) of each item, None where the instruction did not yield its subgoal
    modalities: tuple[str, ...]  # G modality names
    totals: np.ndarray  # (G,) goals per modality, parse failures included (the accuracy denominators)
    imetas: tuple[IndexMeta, ...]  # per scene of the bank
    embed_ms: float  # host time to embed the query texts, per subgoal


def correct_counts(batch: RetrievalBatch, params: RetrievalParams) -> jax.Array:
    """Top-1 instance-level hits per modality (G,) int32 for one parameter set; vmap it over a grid."""
    best, _ = best_nodes(batch.index, batch.queries, batch.qmask, params)
    hit = jnp.take_along_axis(batch.truth, jnp.maximum(best, 0)[..., None], axis=-1)[..., 0] & batch.qmask
    return jnp.sum(batch.group & hit[..., None], axis=(0, 1)).astype(jnp.int32)


def goal_items(episodes: Sequence[Episode], ground: Callable | None = None, every_subgoal: bool = False) -> list[tuple]:
    """(episode, goal k, goal object id, Subgoal or None) for every goal of every episode, in order: the k-th
    parsed subgoal beside the k-th true goal, as retrieval is scored. ground: (episode, subgoals) -> subgoals,
    applied to each parse (evaluation/grounding.py). every_subgoal: also the parsed subgoals past the last true
    goal (goal id None), as the closed loop runs every subgoal it read."""
    items = []
    for ep, sgs in zip(episodes, parse_all(episodes, ground)):
        n = max(len(ep.goals), len(sgs)) if every_subgoal and sgs is not None else len(ep.goals)
        for k in range(n):
            items.append((ep, k, ep.goals[k] if k < len(ep.goals) else None,
                          sgs[k] if sgs is not None and k < len(sgs) else None))
    return items


def prepare_batch(
    bank: MemoryBank, scenes: Sequence[Scene], episodes: Sequence[Episode], embedder,
    index_and_metas: tuple | None = None, modalities: Sequence[str] | None = None, ground: Callable | None = None,
    every_subgoal: bool = False, bucket_slots: bool = False,
) -> tuple[RetrievalBatch | None, BatchMeta]:
    """Parses, embeds and groups the episodes' subgoals by scene (host side, once per episodes file).

    index_and_metas: a prebuilt build_bank_index(bank, scenes, embedder) to reuse. ground, every_subgoal: as in
    goal_items. bucket_slots: pad the subgoal slots per scene (Q) to a power of two (masked), so evaluations
    of different episode counts share the scoring kernel's compilation.
    Returns (None, meta) when no instruction yields a subgoal.
    """
    names = list(bank.names)
    unknown = sorted({ep.scene for ep in episodes} - set(names))
    if unknown:
        from ragnav_jax.errors import UserError

        raise UserError(f"episodes refer to scenes without memory: {', '.join(unknown)}")
    index, imetas = index_and_metas or build_bank_index(bank, scenes, embedder)
    items = goal_items(episodes, ground, every_subgoal)
    mods = tuple(modalities) if modalities is not None else tuple(sorted({ep.modality for ep in episodes}))
    totals = np.zeros(len(mods), np.int64)
    for it in items:
        totals[mods.index(it[0].modality)] += it[2] is not None  # true goals only
    live = [(i, it) for i, it in enumerate(items) if it[3] is not None]
    slots: list = [None] * len(items)
    if not live:
        return None, BatchMeta(tuple(items), tuple(slots), mods, totals, tuple(imetas), 0.0)
    sensor_names = list(bank.metas[0].sensor_names)
    t0 = time.perf_counter()
    q_all = encode_subgoals([it[3] for _, it in live], embedder, sensor_names)
    embed_ms = 1e3 * (time.perf_counter() - t0) / len(live)
    per_scene = defaultdict(list)
    for pos, (i, it) in enumerate(live):
        per_scene[names.index(it[0].scene)].append((pos, i))
    B, Q, N = len(names), max(len(v) for v in per_scene.values()), int(index.node_mask.shape[1])
    if bucket_slots:
        Q = 1 << (Q - 1).bit_length()
    take = np.zeros((B, Q), np.int32)
    qmask = np.zeros((B, Q), bool)
    truth = np.zeros((B, Q, N), bool)
    group = np.zeros((B, Q, len(mods)), bool)
    objects = {s.name: {o.id: j for j, o in enumerate(s.objects)} for s in scenes}
    for b, lst in per_scene.items():
        observed = imetas[b].observed
        for slot, (pos, i) in enumerate(lst):
            ep, _, goal, _ = items[i]
            take[b, slot], qmask[b, slot], slots[i] = pos, True, (b, slot)
            gidx = objects[ep.scene].get(goal, -1)
            truth[b, slot, : len(observed)] = [gidx in o for o in observed]
            group[b, slot, mods.index(ep.modality)] = True
    queries = take_leaves(q_all, take)
    batch = RetrievalBatch(index=index, queries=queries, qmask=jnp.asarray(qmask), truth=jnp.asarray(truth),
                           group=jnp.asarray(group))
    return batch, BatchMeta(tuple(items), tuple(slots), mods, totals, tuple(imetas), embed_ms)


@functools.lru_cache(maxsize=1 << 16)
def _chain(instruction: str) -> TaskChain | None:
    try:
        return parse_instruction(instruction)
    except ParseError:
        return None


def _subgoals(instruction: str) -> tuple[Subgoal, ...] | None:
    chain = _chain(instruction)
    return None if chain is None else chain.subgoals


def parsed_order(instruction: str) -> str | None:
    """The order the parser reads in an instruction ('strict' | 'free'), None where it cannot read it."""
    chain = _chain(instruction)
    return None if chain is None else chain.order


def parse_all(episodes: Sequence[Episode], ground: Callable | None = None) -> list[tuple[Subgoal, ...] | None]:
    """Each episode's parsed subgoals, None where the parser cannot read the instruction (cached per text:
    a batch command checks for unreadable instructions before it scores them); ground: as in goal_items. A
    hook with a `read_unparsed(episode)` method (the instruction tagger's) reads the instructions the parser
    cannot (None where it reads no goal either)."""
    sgs = [_subgoals(ep.instruction) for ep in episodes]
    if ground is None:
        return sgs
    alone = getattr(ground, "read_unparsed", lambda ep: None)
    return [alone(ep) if s is None else ground(ep, s) for ep, s in zip(episodes, sgs)]


def unparsed(episodes: Sequence[Episode]) -> list[str]:
    """Ids of the episodes whose instruction the parser cannot read."""
    return [ep.id for ep, sgs in zip(episodes, parse_all(episodes)) if sgs is None]


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
    timing: dict = {}
    if method.startswith("ragnav"):
        variant = method.split(":", 1)[1] if ":" in method else "ragnav"
        p = ablation_params(params or RetrievalParams.create(), variant)
        batch, bmeta = prepare_batch(bank, scenes, episodes, embedder)
        items = list(bmeta.items)
        live = [i for i, sl in enumerate(bmeta.slots) if sl is not None]
        best_node = np.full(len(items), -1)
        grounded = np.full(len(items), -1)  # the scene object of the best node's best instance
        timing["embed_ms"] = bmeta.embed_ms
        if batch is not None:
            index, queries, qmask = batch.index, batch.queries, batch.qmask
            t0 = time.perf_counter()
            jax.block_until_ready(score_bank(index, queries, qmask, p))
            timing["compile_s"] = time.perf_counter() - t0
            run = lambda: score_bank(index, queries, qmask, p)  # noqa: E731
            timing["retrieval_ms_batched"] = 1e3 * _median_time(run, 3) / len(live)
            best = np.asarray(run()[0])
            which = np.asarray(_best_instances(index, queries, p))  # (B, Q, N) each node's best slot
            for i in live:
                best_node[i] = best[bmeta.slots[i]]
                b, q = bmeta.slots[i]
                slots = bmeta.imetas[b].slot_objects[best_node[i]] if best_node[i] < bmeta.imetas[b].num_nodes else ()
                j = int(which[b, q, best_node[i]])
                grounded[i] = int(slots[j]) if j < len(slots) else -1
            # Warm single-query latency: one subgoal, one scene.
            b0, s0 = bmeta.slots[live[0]]
            idx0 = take_leaves(index, b0)
            q0 = take_leaves(queries, (b0, s0))
            single = jax.jit(score_subgoal)
            jax.block_until_ready(single(idx0, q0, p))
            timing["retrieval_ms_single"] = 1e3 * _median_time(lambda: single(idx0, q0, p))
        observed = {im.scene: im.observed for im in bmeta.imetas}
    else:
        items = goal_items(episodes)
        live = [(i, it) for i, it in enumerate(items) if it[3] is not None]
        best_node = np.full(len(items), -1)
        grounded = None  # the baselines rank nodes, not instances
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
        if grounded is not None:  # stricter: the instance the node's score came from is the goal's object
            rows[-1]["instance_correct"] = bool(ok and grounded[i] == gidx)
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
        **({"instance_accuracy": float(np.mean([r["instance_correct"] for r in rows]))} if grounded is not None and rows
           else {}),
        **{k: round(v, 4) for k, v in timing.items()},
    }
    return rows, summary
