"""Perception phase: the candidate nodes of every subgoal of every episode, per method (`retrieve_candidates`).

The instruction is parsed and grounded (`grounder`), then ranked by the method's retrieval: RAGNav's kernel
(`_kernel_ranked`: `candidate_order`, distinct instances, the pre-check `ruled_out` on the memory's records,
the `closest_view` of each instance), a text-retrieval baseline over the memory's captions (`_text_ranked`) or
the true goals' nodes (`_truth_ranked`, the Oracle). RAGNav scores every subgoal in one batched kernel call.
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections import defaultdict
from collections.abc import Sequence

import jax
import numpy as np

from ragnav_jax.config import Config
from ragnav_jax.evaluation.grounding import MemoryGrounder, RelationWords, SensorReading, TaggedReading
from ragnav_jax.evaluation.methods import MethodSpec
from ragnav_jax.evaluation.verify import Verifier, recorded, vocabulary
from ragnav_jax.language.episodes import Episode
from ragnav_jax.language.sensor_reader import load_reader
from ragnav_jax.language.tagger import ADD_CONF, load_tagger
from ragnav_jax.language.types import Subgoal
from ragnav_jax.memory.names import name_classes
from ragnav_jax.memory.types import MemoryBank
from ragnav_jax.pytrees import take
from ragnav_jax.retrieval import kernels as K
from ragnav_jax.retrieval.baselines import BASELINES, TextMemory
from ragnav_jax.retrieval.evaluate import goal_items, prepare_batch, scored_batch
from ragnav_jax.retrieval.index import node_slots
from ragnav_jax.retrieval.params import ablation_params, params_from_config
from ragnav_jax.retrieval.score import score_subgoal
from ragnav_jax.world.scene import Scene

CANDIDATE_DEPTH = 8  # ranked nodes per candidate slot searched for distinct instances


def ruled_out(verifier, sg: Subgoal | None, names, texts, vocab, classes, est: np.ndarray,
              location_radius: float) -> bool:
    """RAGNav's pre-check of a candidate instance on what the memory holds: its recorded names and
    descriptions contradict the target (Verifier.contradicts), or its estimated position lies beyond the
    coordinate hint's radius."""
    if sg is None:
        return False
    if sg.location is not None and math.dist(est, (sg.location.x, sg.location.y)) > location_radius:
        return True
    return verifier.contradicts(sg, names, texts, vocab, classes)


@dataclasses.dataclass
class Candidates:
    subgoals: list  # per episode: tuple of Subgoal, or None (parse failure)
    nodes: list  # per episode: list (per goal) of candidate node lists, best first
    timing: dict
    est: list | None = None  # per episode, per goal, per candidate: (2,) estimated target position or None
    top: list = dataclasses.field(default_factory=list)  # per episode, per goal: the retrieval's top-1 node or None
    scores: list = dataclasses.field(default_factory=list)  # per episode, per goal, per candidate: retrieval score
    # (RAGNav: the relaxed one for candidates the hard constraints dropped) or None (Oracle)
    ungrounded: dict = dataclasses.field(default_factory=dict)  # episode id -> parsed goal phrases naming nothing
    # the memory knows, dropped before retrieval (evaluation/grounding.py), or remarks the tagger dropped
    tagged: dict = dataclasses.field(default_factory=dict)  # episode id -> goal phrases the tagger added (eval.tagger)
    revised: dict = dataclasses.field(default_factory=dict)  # episode id -> goals whose sensor comparison the sensor
    # reader changed, each "text: before -> after" (eval.sensor_reader)


@jax.jit
def _ranked_terms(index, queries, params):
    """What candidate_order ranks by, for every (scene, subgoal slot, node), each (B, Q, N): the final
    score, the relaxed score, category match, and the node's best-matching observation slot (int32)."""
    s, ex = scored_batch(index, queries, params)
    return s, ex["relaxed"], ex["category"], ex["instance"]


def candidate_order(score: np.ndarray, relaxed: np.ndarray, category: np.ndarray, live: np.ndarray,
                    widen: bool) -> np.ndarray:
    """Node indices, best first, that the reflection may try for one subgoal; all inputs (N,).

    Without `widen`: the nodes the retrieval kept (score > K.NEG / 2), by score, as top-k retrieval.
    With it (RAGNav's reflection, ours): the retrieval's top-1 first (so the retrieval accuracy is the
    kernel's), then four tiers, each by score: kept nodes whose instance is of the target's category;
    the category matches the hard constraints (the forest's region lock, anchor validation) dropped, by
    their relaxed score; the other kept nodes; the rest. A hard constraint that chose the wrong region
    then costs a rejected candidate, not the goal.
    """
    kept = live & (score > K.NEG / 2)
    idx = np.flatnonzero(kept)
    idx = idx[np.argsort(-score[idx], kind="stable")]
    if not widen or not len(idx):
        return idx
    rest = np.flatnonzero((kept | (live & (relaxed > K.NEG / 2))) & (np.arange(len(score)) != idx[0]))
    tier = np.where(category, 0, 2) + np.where(kept, 0, 1)
    key = np.where(kept, score, relaxed)
    return np.concatenate([idx[:1], rest[np.lexsort((-key[rest], tier[rest]))]])


_score_single = jax.jit(score_subgoal)


def distinct_instances(inst: Sequence[int], k: int) -> list[int]:
    """Positions of the first k ranked candidates whose matched instances differ (-1: no instance, always
    distinct); topped up with the best remaining ones when fewer than k instances are ranked. A rejected
    candidate then hands over to another object, not to another view of the same one."""
    pick, seen = [], set()
    for j, c in enumerate(inst):
        if len(pick) == k:
            break
        if c < 0 or c not in seen:
            pick.append(j)
            seen.add(c)
    rest = [j for j in range(len(inst)) if j not in pick]
    return pick + rest[: k - len(pick)]


def closest_view(slot_inst: np.ndarray, node_pos: np.ndarray, node_live: np.ndarray, est: np.ndarray, inst: int,
                 default: int) -> int:
    """The live key pose, among those that recorded instance `inst`, nearest to its estimated position `est`.

    slot_inst (N, S) instance of each node's slots; node_pos (N, 2); node_live (N,); est (2,). The best-scoring
    node describes the instance best, but may have seen it from across the room; the leg ends where the
    memory saw it from closest (the Oracle's rule, on the memory's own estimates). `default` if none did.
    """
    saw = (slot_inst == inst).any(-1) & node_live
    if not saw.any():
        return default
    d = np.linalg.norm(node_pos - est[None], axis=-1)
    return int(np.argmin(np.where(saw, d, np.inf)))


def view_nodes(nodes: Sequence[int], insts: Sequence[int], slot_inst: np.ndarray, node_pos: np.ndarray,
               node_live: np.ndarray, inst_pos: np.ndarray) -> list[int]:
    """Where each candidate's leg ends: the first candidate of an instance at its `closest_view`; a later
    candidate of the same instance (or one without an instance, -1) keeps its own node, so a retry sees
    the instance from elsewhere. inst_pos (I, 2)."""
    out, first = list(nodes), set()
    for c, i in enumerate(insts):
        if i >= 0 and i not in first:
            first.add(i)
            out[c] = closest_view(slot_inst, node_pos, node_live, inst_pos[i], i, out[c])
    return out


def _oracle_node(bank: MemoryBank, b: int, gidx: int) -> int:
    """The key pose that observed scene object `gidx` from closest (ground truth: the Oracle); -1 if none did."""
    obs = np.asarray(bank.memory.obs_object[b])
    dist = np.asarray(bank.memory.obs_distance[b])
    hit = obs == gidx
    if hit.any():
        d = np.where(hit, dist, np.inf).min(1)
        return int(np.argmin(d))
    return -1


@dataclasses.dataclass
class _Ranked:
    """What a retrieval gives per (episode id, subgoal index): candidate nodes, best first, and per candidate the
    instance's estimated position (RAGNav) and score; the kernel's top-1 before any pre-check; timings."""

    nodes: dict = dataclasses.field(default_factory=dict)
    est: dict = dataclasses.field(default_factory=dict)
    top: dict = dataclasses.field(default_factory=dict)
    score: dict = dataclasses.field(default_factory=dict)
    timing: dict = dataclasses.field(default_factory=lambda: {"retrieval_ms_single": 0.0, "retrieval_ms_batched": 0.0,
                                                              "embed_ms": 0.0})


def _kernel_ranked(spec: MethodSpec, bank: MemoryBank, scenes, episodes, embedder, cfg: Config, verifier, ground
                   ) -> _Ranked:
    """RAGNav and its ablations (spec.variant): the retrieval kernel's ranking, distinct instances, the
    pre-check on the memory's records and the closest view."""
    k, out = cfg.eval.candidates, _Ranked()
    by_name = {s.name: s for s in scenes}
    p = ablation_params(params_from_config(cfg.retrieval), spec.variant)
    batch, bmeta = prepare_batch(bank, scenes, episodes, embedder, ground=ground, every_subgoal=True, bucket_slots=True)
    out.timing["embed_ms"] = bmeta.embed_ms
    if batch is None:
        return out
    rec = [recorded(m, by_name[m.scene]) if m.scene in by_name else ({}, {}) for m in bank.metas]
    name_of = [r[1] for r in rec]  # per scene: caption phrase -> the name it used
    classes = [name_classes(r[0])[0] for r in rec]  # per scene: name -> its aliases
    vocab = [vocabulary(r[0]) for r in rec]  # per scene: every name
    jax.block_until_ready(_ranked_terms(batch.index, batch.queries, p))
    t0 = time.perf_counter()
    terms = jax.block_until_ready(_ranked_terms(batch.index, batch.queries, p))
    live = sum(sl is not None for sl in bmeta.slots)
    out.timing["retrieval_ms_batched"] = 1e3 * (time.perf_counter() - t0) / max(live, 1)
    score, relaxed, category, slot_best = map(np.asarray, terms)  # each (B, Q, N)
    node_live = np.asarray(batch.index.node_mask)  # (B, N)
    b0, s0 = next(sl for sl in bmeta.slots if sl is not None)
    idx0 = take(batch.index, b0)
    q0 = take(batch.queries, (b0, s0))
    jax.block_until_ready(_score_single(idx0, q0, p))
    ts = []
    for _ in range(5):
        t0 = time.perf_counter()
        jax.block_until_ready(_score_single(idx0, q0, p))
        ts.append(time.perf_counter() - t0)
    out.timing["retrieval_ms_single"] = 1e3 * float(np.median(ts))
    # Where each candidate node's best-matching instance is (the index associates detections into
    # instances with estimated positions): the reflection looks for the target there.
    slot_inst = np.asarray(batch.index.slot_inst)  # (B, N, S)
    inst_pos = np.asarray(batch.index.inst_pos)[..., :2]  # (B, I, 2)
    node_pos = np.asarray(batch.index.node_pos)[..., :2]  # (B, N, 2)
    for (ep, kk, _goal, sg), sl in zip(bmeta.items, bmeta.slots):
        if sl is None:
            continue
        b_, q_ = sl
        ranked = candidate_order(score[sl], relaxed[sl], category[sl], node_live[b_], cfg.eval.widen)
        ranked = [int(n) for n in ranked[: k * CANDIDATE_DEPTH]]
        out.top[(ep.id, kk)] = ranked[0] if ranked else None
        inst = [int(slot_inst[b_, n, slot_best[b_, q_, n]]) for n in ranked]
        pick = distinct_instances(inst, len(inst))
        if cfg.eval.precheck and verifier is not None:  # on the memory's own records (no driving)
            texts = [bmeta.imetas[b_].instance_phrases[inst[j]] if inst[j] >= 0 else () for j in pick]
            kept = [j for j, ts in zip(pick, texts) if inst[j] < 0 or not ruled_out(
                verifier, sg, [name_of[b_].get(t, t) for t in ts], ts, vocab[b_], classes[b_],
                inst_pos[b_, inst[j]], cfg.episodes.location_radius)]
            pick = kept or pick  # everything ruled out: the check, not the memory, is likely wrong
        pick = pick[:k]
        nodes = [ranked[j] for j in pick]
        if cfg.eval.closest_view:  # drive to the key pose that saw the instance from closest
            nodes = view_nodes(nodes, [inst[j] for j in pick], slot_inst[b_], node_pos[b_], node_live[b_], inst_pos[b_])
        out.nodes[(ep.id, kk)] = nodes
        out.est[(ep.id, kk)] = [inst_pos[b_, inst[j]].copy() if inst[j] >= 0 else None for j in pick]
        s_, r_ = score[sl], relaxed[sl]
        out.score[(ep.id, kk)] = [float(s_[n] if s_[n] > K.NEG / 2 else r_[n]) for n in (ranked[j] for j in pick)]
    return out


def _text_ranked(spec: MethodSpec, bank: MemoryBank, scenes, items, embedder, cfg: Config) -> _Ranked:
    """A text-retrieval baseline (spec.variant, BASELINES) over the memory's captions, each subgoal's text as the
    query; spec.positions adds ReMEmbR's position term."""
    k, out = cfg.eval.candidates, _Ranked()
    by_name = {s.name: s for s in scenes}
    t_total, n_total = 0.0, 0
    for b, meta in enumerate(bank.metas):
        mine = [it for it in items if it[0].scene == meta.scene and it[3] is not None]
        if not mine or meta.num_nodes == 0:
            continue
        objs, phrases = node_slots(meta, by_name[meta.scene])
        mem = TextMemory(tuple(meta.captions), tuple(tuple(p) for p in phrases))
        model = BASELINES[spec.variant](mem, embedder)
        t0 = time.perf_counter()
        s = np.asarray(model.scores([it[3].text or it[0].instruction for it in mine]))[:, : meta.num_nodes]
        if spec.positions:  # ReMEmbR's memory keeps positions: a position query adds a term
            pos = np.asarray(bank.memory.position[b, : meta.num_nodes, :2])
            for q, it in enumerate(mine):
                if it[3].location is not None:
                    d2 = np.sum((pos - [it[3].location.x, it[3].location.y]) ** 2, 1)
                    s[q] += np.exp(-d2 / (2 * cfg.retrieval.sigma_loc**2))
        t_total += time.perf_counter() - t0
        n_total += len(mine)
        for it, row in zip(mine, s):
            out.nodes[(it[0].id, it[1])] = [int(x) for x in np.argsort(-row, kind="stable")[:k]]
            out.score[(it[0].id, it[1])] = [float(row[x]) for x in out.nodes[(it[0].id, it[1])]]
    out.timing["retrieval_ms_single"] = out.timing["retrieval_ms_batched"] = 1e3 * t_total / max(n_total, 1)
    return out


def _truth_ranked(bank: MemoryBank, scenes, items, memory_scenes=None) -> _Ranked:
    """The Oracle: each true goal's node: the key pose that observed it from closest, or, for an object that moved
    or appeared since the memory was built (`scenes` against `memory_scenes`), the live key pose nearest where
    it stands now."""
    out, names = _Ranked(), list(bank.names)
    by_name = {s.name: s for s in scenes}
    before = {s.name: s for s in memory_scenes or scenes}
    for ep, kk, goal, _sg in items:
        if goal is None:
            continue
        objs, old = by_name[ep.scene].objects, before[ep.scene].objects
        gidx = next((j for j, o in enumerate(objs) if o.id == goal), -1)
        b = names.index(ep.scene)
        if gidx >= len(old) or (gidx >= 0 and old[gidx].position != objs[gidx].position):
            pos = np.asarray(bank.memory.position[b])[:, :2]
            d = np.where(np.asarray(bank.memory.node_mask[b]), np.linalg.norm(pos - objs[gidx].position[:2], axis=1),
                         np.inf)
            node = int(np.argmin(d))
        else:
            node = _oracle_node(bank, b, gidx)
        out.nodes[(ep.id, kk)] = [node] if node >= 0 else []
    return out


def grounder(spec: MethodSpec, bank: MemoryBank, scenes, episodes, cfg: Config, verifier: Verifier | None):
    """What turns a parse into the subgoals run (evaluation/grounding.py: the tagger, the memory grounder, then
    the sensor reader), or None."""
    ground = (MemoryGrounder(verifier, bank, scenes, cfg.eval.ground_described)
              if cfg.eval.ground and verifier is not None else None)
    if cfg.eval.tagger and spec.reads:
        tagger = load_tagger(cfg.eval.tagger_file)
        conf = cfg.eval.tagger_conf or tagger.meta["reconcile"]["conf"]
        relations = RelationWords(verifier) if cfg.eval.clause_anchors and verifier is not None else None
        ground = TaggedReading(tagger, episodes, conf, then=ground, clauses=cfg.eval.tagger_clauses,
                               anchors=cfg.eval.tagger_anchors, relation_of=relations,
                               anchor_conf=ADD_CONF if cfg.eval.likely_anchors else None,
                               regroup=cfg.eval.tagger_regroup)
    if cfg.eval.sensor_reader and spec.reads:
        reader = load_reader(cfg.eval.sensor_reader_file)
        ground = SensorReading(reader, cfg.eval.sensor_reader_conf or reader.meta["revise"]["conf"], inner=ground)
    return ground


def retrieve_candidates(spec: MethodSpec, bank: MemoryBank, scenes: Sequence[Scene], episodes: Sequence[Episode],
                        embedder, cfg: Config, verifier: Verifier | None = None,
                        memory_scenes: Sequence[Scene] | None = None) -> Candidates:
    """Top-k candidate nodes per subgoal for a method (spec.retrieval); timings of the retrieval kernels.
    RAGNav's pre-check (`eval.precheck`) needs the verifier. The Oracle reads the world (`scenes`), where it
    changed since the memory was built (`memory_scenes`)."""
    ground = grounder(spec, bank, scenes, episodes, cfg, verifier)
    items = goal_items(episodes, ground, every_subgoal=True)
    subgoals: dict[str, object] = {}
    for ep, _kk, _goal, sg in items:
        subgoals.setdefault(ep.id, None)
        if sg is not None:
            subgoals[ep.id] = (subgoals[ep.id] or ()) + (sg,)
    r = {"kernel": lambda: _kernel_ranked(spec, bank, scenes, episodes, embedder, cfg, verifier, ground),
         "text": lambda: _text_ranked(spec, bank, scenes, items, embedder, cfg),
         "truth": lambda: _truth_ranked(bank, scenes, items, memory_scenes),
         "none": _Ranked}[spec.retrieval]()
    per_ep: dict[str, list] = defaultdict(list)
    est_ep: dict[str, list] = defaultdict(list)
    for ep, kk, _goal, _sg in items:
        per_ep[ep.id].append(r.nodes.get((ep.id, kk), []))
        est_ep[ep.id].append(r.est.get((ep.id, kk), [None] * len(r.nodes.get((ep.id, kk), []))))
    top = [[r.top[(ep.id, kk)] if (ep.id, kk) in r.top else (c[0] if c else None)
            for kk, c in enumerate(per_ep[ep.id])] for ep in episodes]
    scores = [[r.score.get((ep.id, kk), [None] * len(c)) for kk, c in enumerate(per_ep[ep.id])] for ep in episodes]
    return Candidates([subgoals[ep.id] for ep in episodes], [per_ep[ep.id] for ep in episodes], r.timing,
                      [est_ep[ep.id] for ep in episodes], top, scores, ground.dropped if ground else {},
                      getattr(ground, "added", {}), getattr(ground, "revised", {}))
