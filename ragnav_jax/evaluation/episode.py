"""The closed loop: perception (retrieval) - planning - execution (MJX) - reflection, over many episodes.

    rows, summary = evaluate_navigation(bank, scenes, episodes, embedder, cfg, method="ragnav", streams=streams)

Phases (host Python only between them; every simulation step runs inside a jitted batched call):
1. Plan: parse every instruction, retrieve the top-`eval.candidates` nodes of every subgoal in one
   batched kernel call (`retrieve_candidates`), solve each episode's visiting order.
2. Execute legs: every active episode drives its current leg together (`execute.Executor.run`:
   lax.while_loop over control steps, vmapped over episodes and their scenes' geometry).
3. Reflect on arrival (`Executor.look`: camera visibility at several headings from the simulated
   pose; the verifier's verdict table: is a visible object the subgoal's target?). Confirmed: drive up to it (an approach
   leg) and declare FOUND. Not confirmed, or the approach is blocked: reject the candidate, take the
   goal's next candidate and re-plan the remaining order, at most `eval.retries` times per goal.
The loop runs the subgoals it read, as many as it read and in the order type it read (strict: as written;
free: its own plan); it never sees the episode file's goals or order (only the Oracle does).
Judging (MultiON-style, on the simulated trajectory only): a FOUND counts for the true goal the robot
approached when it is one not found yet, else for the nearest such goal within `eval.found_radius` of the
robot's simulated position, whichever subgoal it was made for; passing near a goal without declaring does
not count; a FOUND at no true goal is a recorded wrong declaration and fails the episode. An episode
succeeds when every true goal was found (strict episodes: in the episode's order) within `eval.max_steps`.

Methods (flags of one loop, `method_spec`): RAGNav and its retrieval ablations; `ragnav:no_topology`
also plans and drives straight lines (no map); the retrieval baselines (naive_rag, graphrag, lightrag)
on RAGNav's planner; navigation baselines reimplemented *in the style of* the papers: `remembr`
(flat caption memory with positions, text retrieval plus a position term, instruction order, the same
map paths and local planner as RAGNav), `etpnav` (no prior memory: replays the robot's own frontier
exploration from the start pose until the target is seen, then approaches it; instruction order) and
`oracle` (true goal positions, optimal order, topological paths). Every method but the Oracle checks
what it sees with the same open-vocabulary verifier (`verify.py`: a verdict table computed before the loop).
"""

from __future__ import annotations

import dataclasses
import math
import re
import time
from collections import defaultdict, deque
from collections.abc import Collection, Sequence

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.config import Config
from ragnav_jax.errors import UserError
from ragnav_jax.evaluation.execute import Executor, densify, make_executor, pad_points
from ragnav_jax.evaluation.grounding import MemoryGrounder, TaggedReading
from ragnav_jax.evaluation.search import search_table
from ragnav_jax.evaluation.verify import Verifier, memory_views, name_classes, recorded, verdict_table, vocabulary
from ragnav_jax.language.episodes import Episode
from ragnav_jax.language.tagger import load_tagger
from ragnav_jax.language.types import Subgoal
from ragnav_jax.memory.paths import reconstruct_path
from ragnav_jax.memory.topomap import segment_clearance as _segment_clearance
from ragnav_jax.memory.types import MemoryBank
from ragnav_jax.planning.order import order_of
from ragnav_jax.pytrees import take
from ragnav_jax.retrieval import kernels as K
from ragnav_jax.retrieval.baselines import BASELINES, TextMemory
from ragnav_jax.retrieval.evaluate import goal_items, parsed_order, prepare_batch, scored_batch
from ragnav_jax.retrieval.index import node_slots
from ragnav_jax.retrieval.params import ablation_params, params_from_config
from ragnav_jax.retrieval.score import score_subgoal
from ragnav_jax.world.scene import Scene

NAV_METHODS = ("ragnav", "ragnav:no_forest", "ragnav:no_topology", "ragnav:no_spatial", "ragnav:no_boost",
               "naive_rag", "graphrag", "lightrag", "remembr", "etpnav", "oracle")
THIN_M = 0.3  # metres between replayed exploration waypoints (ETPNav-style)
SAME_INSTANCE_M = 0.5  # a seen object this close to the retrieved instance's estimated position is that instance
TIGHT_PENALTY = 10.0  # driving-path cost factor of map edges that pass closer to an obstacle than the robot's radius
GRID_M = 0.05  # occupancy grid of the local planner (metres per cell)
GRID_MARGIN_M = 0.04  # clearance beyond the robot's radius the local planner keeps
GRID_WINDOW_M = 1.5  # metres around a tight segment the local planner searches first (approaches: then the whole house)
TIGHT_GAP_M = 0.0  # clearance beyond the robot's radius of the passages the local planner tries last
ESCAPE_M = 0.3  # metres around a leg's ends where the local planner may pass cells as tight as the end itself
CANDIDATE_DEPTH = 8  # ranked nodes per candidate slot searched for distinct instances
REVISIT = re.compile(r"\b(?:back|again|return|returning|revisit|once\s+more)\b")  # a goal that goes back to an object
CLOSER_GAP_M = 0.6  # extra metres (beyond approach_gap + robot radius) the look-closer leg stops short of it


@dataclasses.dataclass(frozen=True)
class MethodSpec:
    name: str
    retrieval: str  # what ranks the memory's nodes: "kernel" (RAGNav's scores), "text" (a text-retrieval model),
    # "truth" (the true goals' nodes: the Oracle) or "none" (the ETPNav-style baseline explores instead)
    straight: bool  # straight-line legs and Euclidean order costs (no topological map)
    optimal_order: bool  # solve the order (False: instruction order)
    search: bool = True  # candidates run out: search the key poses where the instruction puts the goal (search.py)
    reads: bool = True  # reads the instruction and checks what it sees (False: the Oracle, which knows the goals)
    explores: bool = False  # finds goals by replaying its exploration, with no retrieval (the ETPNav-style baseline)
    variant: str = "ragnav"  # kernel: the ablation ("ragnav", "no_forest", ...); text: the model (a BASELINES name)
    positions: bool = False  # text: a position in the instruction adds a Gaussian term over node positions (ReMEmbR)


def segment_clearance_np(p: np.ndarray, q: np.ndarray, obs: dict) -> np.ndarray:
    """(P,) clearance of segments p-q (P, 2) to a scene's walls and blocking objects (host NumPy)."""
    return _segment_clearance(np.asarray(p, np.float32), np.asarray(q, np.float32), obs, np)


def method_spec(name: str) -> MethodSpec:
    if name not in NAV_METHODS:
        raise UserError(f"unknown method '{name}' (known: {', '.join(NAV_METHODS)})")
    if name.startswith("ragnav"):
        variant = name.split(":", 1)[1] if ":" in name else "ragnav"
        return MethodSpec(name, "kernel", variant == "no_topology", True, variant=variant)
    if name in BASELINES:
        return MethodSpec(name, "text", False, True, variant=name)
    # ReMEmbR hands its retrieved goal to a standard navigation stack: the same map paths and local planner as
    # RAGNav here (it once drove straight lines into walls, which measured a crippled navigator, not its memory).
    # The ETPNav-style baseline explores for itself, and the Oracle knows where every goal is: neither searches.
    return {"remembr": MethodSpec(name, "text", False, False, variant="naive_rag", positions=True),
            "etpnav": MethodSpec(name, "none", False, False, search=False, explores=True),
            "oracle": MethodSpec(name, "truth", False, True, search=False, reads=False)}[name]


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


# ----------------------------------------------------------------------------------------------------
# Perception checks


def box_distance(obj, xy) -> float:
    """Planar metres from a point to an object's box footprint (0 inside)."""
    dx = max(0.0, abs(xy[0] - obj.position[0]) - obj.size[0] / 2)
    dy = max(0.0, abs(xy[1] - obj.position[1]) - obj.size[1] / 2)
    return math.hypot(dx, dy)


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


# ----------------------------------------------------------------------------------------------------
# Perception phase: candidates for every subgoal of every episode


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


def _truth_ranked(bank: MemoryBank, scenes, items) -> _Ranked:
    """The Oracle: each true goal's node."""
    out, names = _Ranked(), list(bank.names)
    by_name = {s.name: s for s in scenes}
    for ep, kk, goal, _sg in items:
        if goal is None:
            continue
        gidx = next((j for j, o in enumerate(by_name[ep.scene].objects) if o.id == goal), -1)
        node = _oracle_node(bank, names.index(ep.scene), gidx)
        out.nodes[(ep.id, kk)] = [node] if node >= 0 else []
    return out


def grounder(spec: MethodSpec, bank: MemoryBank, scenes, episodes, cfg: Config, verifier: Verifier | None):
    """What turns a parse into the subgoals run (evaluation/grounding.py, the tagger), or None."""
    ground = MemoryGrounder(verifier, bank, scenes) if cfg.eval.ground and verifier is not None else None
    if cfg.eval.tagger and spec.reads:
        tagger = load_tagger(cfg.eval.tagger_file)
        conf = cfg.eval.tagger_conf or tagger.meta["reconcile"]["conf"]
        ground = TaggedReading(tagger, episodes, conf, then=ground)
    return ground


def retrieve_candidates(spec: MethodSpec, bank: MemoryBank, scenes: Sequence[Scene], episodes: Sequence[Episode],
                        embedder, cfg: Config, verifier: Verifier | None = None) -> Candidates:
    """Top-k candidate nodes per subgoal for a method (spec.retrieval); timings of the retrieval kernels.
    RAGNav's pre-check (`eval.precheck`) needs the verifier."""
    ground = grounder(spec, bank, scenes, episodes, cfg, verifier)
    items = goal_items(episodes, ground, every_subgoal=True)
    subgoals: dict[str, object] = {}
    for ep, _kk, _goal, sg in items:
        subgoals.setdefault(ep.id, None)
        if sg is not None:
            subgoals[ep.id] = (subgoals[ep.id] or ()) + (sg,)
    r = {"kernel": lambda: _kernel_ranked(spec, bank, scenes, episodes, embedder, cfg, verifier, ground),
         "text": lambda: _text_ranked(spec, bank, scenes, items, embedder, cfg),
         "truth": lambda: _truth_ranked(bank, scenes, items),
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
                      getattr(ground, "added", {}))


# ----------------------------------------------------------------------------------------------------
# Order planning (exact over permutations: episodes have at most a handful of goals)


def plan_order(cost: np.ndarray, start: int, nodes: Sequence[int], goals: Sequence[int], strict: bool, lam: float,
               solver: str = "auto", max_iters: int = 100) -> list[int]:
    """Visiting order of `goals` (their target nodes `nodes`) from node `start`: the paper's Pi*
    (`planning/order.py`), path cost + lam * (goal pairs visited against the instruction order) for strict
    episodes, path cost alone for free ones; goals unreachable from the start come last."""
    goals = list(goals)
    keep = order_of(cost, start, list(nodes), goals if strict else [0] * len(goals), lam if strict else 0.0,
                    solver, max_iters)
    return [goals[k] for k in keep]


# ----------------------------------------------------------------------------------------------------
# The closed loop


@dataclasses.dataclass
class EpisodeState:
    e: int
    ep: Episode
    b: int  # scene index in the bank
    s: int  # scene index in the executor
    subgoals: tuple | None
    cands: list  # per goal candidate node lists
    ests: list  # per goal, per candidate: (2,) estimated target position (retrieved instance) or None
    cptr: list  # per goal: index of the current candidate
    rejected: list  # per goal: candidates rejected so far
    remaining: list  # goals still to visit, in planned order
    node: int  # graph node the robot is at (or nearest to)
    status: list  # per goal: pending | found | wrong | failed:<reason>
    strict: bool  # visit the goals in the order written (the parser's reading; the Oracle's: the truth)
    found: list  # per true goal of the episode: a correct declaration was made at it
    declarations: list = dataclasses.field(default_factory=list)
    steps: int = 0
    look_steps: int = 0
    length: float = 0.0
    done: bool = False
    reason: str = ""
    leg: tuple | None = None  # (kind, goal, payload)
    expl_t: int = 0  # ETPNav-style: exploration record reached
    skip: set = dataclasses.field(default_factory=set)  # (goal, object) ruled out: rejected on approach, or
    # declared for another goal
    looked: set = dataclasses.field(default_factory=set)  # (goal, node): key poses looked around at for the goal
    backup: dict = dataclasses.field(default_factory=dict)  # goal -> (parts failed, object): of the objects seen
    # for the goal, the first that fails fewest parts of its check (eval.fallback)
    fell_back: set = dataclasses.field(default_factory=set)  # goals the fallback was taken for
    penetration: float = 0.0
    planned: list = dataclasses.field(default_factory=list)  # the first plan's order
    legs: list = dataclasses.field(default_factory=list)  # eval.record_legs: kind, goal, waypoints, simulated end
    trace: dict | None = None  # evaluate_navigation(trace=...): candidates and rejections; its legs are recorded
    # with every control step's pose and what the look-around saw


class Loop:
    """Host state machine of the episode loop; each phase hands one leg per episode to the executor."""

    def __init__(self, spec: MethodSpec, bank: MemoryBank, scenes: Sequence[Scene], cfg: Config, executor: Executor,
                 streams: dict | None):
        self.spec, self.bank, self.cfg, self.ex = spec, bank, cfg, executor
        self.scenes = {s.name: s for s in scenes}
        self.pos = np.asarray(bank.memory.position)[..., :2]
        self.mask = np.asarray(bank.memory.node_mask)
        self.cost = np.asarray(bank.memory.path_cost)
        self.pred = np.asarray(bank.memory.path_pred)
        self.euclid = np.asarray(bank.memory.distance)
        self.streams = streams or {}
        self._seen: dict = {}
        self.look_cost = int(math.ceil(2 * math.pi / cfg.sim.max_yaw_rate / executor.control_dt))
        self.obstacles: dict = {}
        # Occupancy grids and local plans depend on the scene alone: kept on the executor, so every method
        # evaluated with it shares them (keyed by bank index, hence the bank's scene order).
        key = (tuple(bank.names), self._need())
        self._grids = executor.cache.setdefault(("grids", *key), {})
        self._local_cache = executor.cache.setdefault(("local_plans", *key), {})
        self.drive_pred = self._drive_paths(bank)
        # Every object some key pose of the memory recorded (where a look closer may find the instance).
        obs = np.asarray(bank.memory.obs_object)
        self.known = [sorted({int(x) for x in obs[b][self.mask[b]].ravel() if x >= 0}) for b in range(obs.shape[0])]
        self.verdicts: list = []  # [e][g] -> (O,) bool: the verifier's check of every scene object (verify.py)
        self.misfits: list = []  # [e][g] -> (O,) float: parts of the check each object fails (eval.fallback)
        self.search: list = []  # [e][g] -> key poses to search when the candidates run out (search.py)

    # -- helpers
    def _drive_paths(self, bank: MemoryBank) -> np.ndarray:
        """(B, N, N) predecessors of the paths the robot drives: the map's shortest paths with edges that pass
        closer to a wall or object than the robot's radius (the map keeps edges with a thin clearance)
        made TIGHT_PENALTY times dearer, so the body fits wherever another way exists. Planning costs and
        metrics keep the map's own lengths (Rule 1)."""
        from scipy.sparse.csgraph import shortest_path

        from ragnav_jax.memory.topomap import obstacles_numpy, segment_clearance

        adj = np.asarray(bank.memory.adjacency)
        out = np.array(self.pred, copy=True)
        need = self.cfg.sim.robot_radius + 0.02
        for b, meta in enumerate(bank.metas):
            sc = self.scenes.get(meta.scene)
            if sc is None or meta.num_nodes == 0:
                continue
            obs = self.obstacles.setdefault(b, obstacles_numpy(sc))
            i, j = np.nonzero(adj[b])
            if not len(i):
                continue
            clear = segment_clearance(self.pos[b][i], self.pos[b][j], obs)
            w = np.zeros_like(self.euclid[b], dtype=np.float64)
            w[i, j] = np.maximum(self.euclid[b][i, j], 1e-6) * np.where(clear < need, TIGHT_PENALTY, 1.0)
            _, pred = shortest_path(w, method="D", directed=True, return_predecessors=True)
            out[b] = np.where(pred < 0, -1, pred)
        return out

    def attach(self, b: int, xy) -> int:
        """The nearest key pose the robot can drive to in a straight line from xy (the nearest one if none)."""
        d = np.linalg.norm(self.pos[b] - np.asarray(xy)[None], axis=1)
        d[~self.mask[b]] = np.inf
        order = [int(k) for k in np.argsort(d)[:8] if np.isfinite(d[k])]
        if b in self.obstacles and order:
            p = np.repeat(np.asarray(xy, np.float32)[None], len(order), 0)
            clear = segment_clearance_np(p, self.pos[b][order], self.obstacles[b])
            ok = [k for k, c in zip(order, clear) if c > self.cfg.sim.robot_radius]
            if ok:
                return ok[0]
        return int(np.argmin(d))

    def drive_points(self, st: EpisodeState, pts: np.ndarray) -> np.ndarray:
        """The leg's waypoints as driven: every segment that passes closer to a wall or object than the
        robot's radius (plus a margin) is replaced by a local plan on the robot's occupancy grid (the
        paper assumes a perfect local planner between key poses); then densified along the polyline."""
        pts = np.asarray(pts, np.float32).reshape(-1, 2)
        if st.b not in self.obstacles or len(pts) < 2:
            return densify(pts, self.ex.path_points)
        out = [pts[:1]]
        for a, c in zip(pts[:-1], pts[1:]):
            out.append(self._local(st.b, a, c)[1:])
        way = np.concatenate(out)
        return densify(way if len(way) <= self.ex.path_points else pts, self.ex.path_points)

    def _need(self) -> float:
        return self.cfg.sim.robot_radius + GRID_MARGIN_M

    def _grid(self, b: int):
        """(origin (2,), clearance (H, W) float): each cell's distance to the nearest wall or object."""
        if b not in self._grids:
            obs = self.obstacles[b]
            pts = np.concatenate([np.asarray(obs["wall_a"]), np.asarray(obs["wall_b"]), self.pos[b][self.mask[b]]])
            lo, hi = pts.min(0) - 0.5, pts.max(0) + 0.5
            xs, ys = np.arange(lo[0], hi[0], GRID_M), np.arange(lo[1], hi[1], GRID_M)
            cells = np.stack(np.meshgrid(xs, ys, indexing="ij"), -1).reshape(-1, 2).astype(np.float32)
            clear = np.concatenate([segment_clearance_np(c, c, obs) for c in np.array_split(cells, max(len(cells) // 4096, 1))])
            self._grids[b] = (lo.astype(np.float32), clear.reshape(len(xs), len(ys)))
        return self._grids[b]

    def _local(self, b: int, a: np.ndarray, c: np.ndarray, anywhere: bool = False) -> np.ndarray:
        """Waypoints a ... c: the straight segment when it clears the robot, else a grid path (BFS within a
        window around the segment over cells that clear the robot with a margin, then through passages it
        just fits; with `anywhere` (approaches, which go where no map edge leads), then the same over the
        whole house; shortcut by line of sight); the straight segment when none is found (a map edge the
        window finds no way along is driven as the map has it). Within ESCAPE_M of either end a cell as
        clear as that end passes too, so a robot parked in a tight spot (between a bin and a wall) can
        leave it."""
        key = (b, *np.round(a, 3), *np.round(c, 3), anywhere)
        if key in self._local_cache:
            return self._local_cache[key]
        obs, need = self.obstacles[b], self._need()
        straight = np.stack([a, c])
        if segment_clearance_np(a[None], c[None], obs)[0] >= need or np.linalg.norm(c - a) < 1e-3:
            self._local_cache[key] = straight
            return straight
        lo, clear = self._grid(b)
        H, W = clear.shape
        cell = lambda p: (int(np.clip(round((p[0] - lo[0]) / GRID_M), 0, H - 1)),  # noqa: E731
                          int(np.clip(round((p[1] - lo[1]) / GRID_M), 0, W - 1)))
        (i0, j0), (i1, j1) = cell(a), cell(c)
        ii, jj = np.ogrid[:H, :W]
        ends = [(ii - i) ** 2 + (jj - j) ** 2 <= (ESCAPE_M / GRID_M) ** 2 for i, j in ((i0, j0), (i1, j1))]
        pad = int(GRID_WINDOW_M / GRID_M)
        window = (max(min(i0, i1) - pad, 0), min(max(i0, i1) + pad, H - 1), max(min(j0, j1) - pad, 0), min(max(j0, j1) + pad, W - 1))
        prev = None
        boxes = (window, (0, H - 1, 0, W - 1)) if anywhere else (window,)
        tiers = [(t, box) for box in boxes for t in (need, self.cfg.sim.robot_radius + TIGHT_GAP_M)]
        for tight, (bi0, bi1, bj0, bj1) in tiers:
            ok = clear >= tight
            for (i, j), near in zip(((i0, j0), (i1, j1)), ends):  # the ends may sit in a tight spot: let the robot out
                ok |= near & (clear >= min(float(clear[i, j]), tight) - 1e-6)
                ok[i, j] = True
            prev = {(i0, j0): None}
            queue = deque([(i0, j0)])
            while queue and (i1, j1) not in prev:
                i, j = queue.popleft()
                for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)):
                    n = (i + di, j + dj)
                    if bi0 <= n[0] <= bi1 and bj0 <= n[1] <= bj1 and n not in prev and ok[n]:
                        prev[n] = (i, j)
                        queue.append(n)
            if (i1, j1) in prev:
                break
        if (i1, j1) not in prev:
            self._local_cache[key] = straight
            return straight
        path, n = [], (i1, j1)
        while n is not None:
            path.append(n)
            n = prev[n]
        xy = lo + np.asarray(path[::-1], np.float32) * GRID_M
        xy[0], xy[-1] = a, c
        keep = [0]  # string pulling: jump to the farthest cell still in clear line of sight
        while keep[-1] < len(xy) - 1:
            k = keep[-1]
            cand = np.arange(k + 1, len(xy))
            sight = segment_clearance_np(np.repeat(xy[k : k + 1], len(cand), 0), xy[cand], obs)
            good = cand[sight >= tight * 0.999]
            keep.append(int(good.max()) if len(good) else k + 1)
        out = xy[keep].astype(np.float32)
        self._local_cache[key] = out
        return out

    def nearest(self, b: int, xy) -> int:
        d = np.linalg.norm(self.pos[b] - np.asarray(xy)[None], axis=1)
        d[~self.mask[b]] = np.inf
        return int(np.argmin(d))

    def order_cost(self, b):
        return self.euclid[b] if self.spec.straight else self.cost[b]

    def current(self, st: EpisodeState, g: int) -> int | None:
        c = st.cands[g]
        if st.rejected[g] > self.cfg.eval.retries or st.cptr[g] >= len(c):
            return None
        return c[st.cptr[g]]

    def replan(self, st: EpisodeState) -> None:
        """Re-solves the order of the remaining goals from the robot's node with their current candidates."""
        if not self.spec.optimal_order:
            st.remaining = sorted(st.remaining)  # the instruction's order
            return
        live = [g for g in sorted(st.remaining) if self.current(st, g) is not None]
        nodes = [self.current(st, g) for g in live]
        p = self.cfg.planning
        order = plan_order(self.order_cost(st.b), st.node, nodes, live, st.strict, p.lam, p.solver, p.local_search_iters)
        for d in sorted(set(st.remaining) - set(live)):  # goals with no candidate left keep their instruction place
            order.insert(max((k + 1 for k, g in enumerate(order) if g < d), default=0) if st.strict else len(order), d)
        st.remaining = order

    def estimate(self, st: EpisodeState, g: int):
        """(2,) estimated position of the current candidate's retrieved instance, or None."""
        if st.cptr[g] >= len(st.ests[g]):
            return None
        return st.ests[g][st.cptr[g]]

    def closer_points(self, st: EpisodeState, est: np.ndarray, pose: np.ndarray) -> np.ndarray:
        """Waypoints to a spot short of the estimated target position: over the map to its nearest key pose
        (straight planners: directly), then towards it."""
        gap = self.cfg.eval.approach_gap + self.cfg.sim.robot_radius + CLOSER_GAP_M
        if self.spec.straight:
            pts, last = np.zeros((0, 2), np.float32), pose[:2]
        else:
            a, t = self.attach(st.b, pose[:2]), self.attach(st.b, est)
            path = reconstruct_path(self.drive_pred[st.b], a, t) or [a]
            pts = self.pos[st.b][path]
            last = pts[-1]
        v = np.asarray(last, np.float32) - est
        n = float(np.linalg.norm(v))
        goal = last if n <= gap else est + v / n * gap
        return np.concatenate([pts, np.asarray(goal, np.float32)[None]]).astype(np.float32)

    def passing(self, st: EpisodeState, g: int, objects) -> list[int]:
        """The objects (scene indices) that pass the verifier's check for goal g (the verdict table)."""
        v = self.verdicts[st.e][g]
        return [int(o) for o in objects if o < len(v) and v[o]]

    def keep_backup(self, st: EpisodeState, g: int, visible: np.ndarray, near: np.ndarray) -> None:
        """eval.fallback: remembers the visible object that fails fewest parts of goal g's check (the nearest to
        `near` (2,) of those), unless one seen earlier fails as few."""
        m = self.misfits[st.e][g]
        objs = self.scenes[st.ep.scene].objects
        seen = [(float(m[o]), box_distance(objs[o], near), int(o)) for o in np.flatnonzero(visible)
                if o < len(m) and np.isfinite(m[o]) and (g, int(o)) not in st.skip]
        best = min(seen, default=None)
        if best is not None and (g not in st.backup or best[0] < st.backup[g][0]):
            st.backup[g] = (best[0], best[2])

    def reject(self, st: EpisodeState, g: int, why: str) -> None:
        if st.trace is not None:
            st.trace["rejections"].append({"goal": g, "candidate": st.cptr[g], "why": why, "leg": len(st.legs) - 1})
        st.cptr[g] += 1
        st.rejected[g] += 1
        if self.current(st, g) is None and self.search_next(st, g) is None and g not in st.backup:
            st.status[g] = f"failed:{why}"
            st.remaining.remove(g)
        self.replan(st)

    def search_next(self, st: EpisodeState, g: int) -> int | None:
        """The nearest key pose still to search for goal g (none looked around at for it yet), or None."""
        if not self.spec.search or st.e >= len(self.search) or g >= len(self.search[st.e]):
            return None
        left = [n for n in self.search[st.e][g] if (g, n) not in st.looked]
        cost = self.order_cost(st.b)
        return min(left, key=lambda n: cost[st.node, n]) if left else None

    def goal_object(self, st: EpisodeState, g: int):
        """The scene object of the episode's true goal g (the Oracle's goals are the true ones)."""
        sc = self.scenes[st.ep.scene]
        oid = st.ep.goals[g]
        return next((o for o in sc.objects if o.id == oid), None)

    def true_goal_at(self, st: EpisodeState, obj, pose: np.ndarray) -> int | None:
        """The true goal a FOUND for object `obj` at the pose counts for, or None, whichever subgoal the robot
        was after (the loop runs the subgoals it read, which need not be the true ones one for one): `obj`
        itself when it is a true goal not found yet, else the nearest such goal within eval.found_radius of
        the pose."""
        r = self.cfg.eval.found_radius
        left = [j for j in range(len(st.ep.goals)) if not st.found[j]]
        same = [j for j in left if st.ep.goals[j] == obj.id]
        if same and box_distance(obj, pose[:2]) <= r:
            return same[0]
        near = [(box_distance(o, pose[:2]), j) for j in left
                if (o := self.goal_object(st, j)) is not None and box_distance(o, pose[:2]) <= r]
        return min(near)[1] if near else None

    # -- deciding the next leg
    def next_leg(self, st: EpisodeState, pose: np.ndarray) -> tuple | None:
        """(kind, goal, payload, waypoints (n, 2)) or None when the episode is over."""
        while not st.done:
            if st.leg is not None and st.leg[0] in ("approach", "explore", "closer"):
                return st.leg  # continuing multi-part legs are re-issued by the reflect step
            if not st.remaining:
                st.done, st.reason = True, st.reason or "completed"
                return None
            g = st.remaining[0]
            if self.spec.reads and (st.subgoals is None or g >= len(st.subgoals)):
                st.status[g] = "failed:parse"  # (the Oracle reads no instruction)
                st.remaining.remove(g)
                continue
            if self.spec.explores:
                return self.etp_leg(st, g, pose)
            node, kind = self.current(st, g), "nav"
            if node is None:
                node, kind = self.search_next(st, g), "search"
            if node is None and g in st.backup:  # the fallback: the object seen that fits the goal best
                o = st.backup.pop(g)[1]
                st.fell_back.add(g)
                return ("approach", g, o, self.approach_points(st, o, pose))
            if node is None:
                st.status[g] = "failed:searched" if any(k == g for k, _ in st.looked) else "failed:no_candidate"
                st.remaining.remove(g)
                continue
            if self.spec.straight:
                pts = self.pos[st.b][[node]]
            else:
                path = reconstruct_path(self.drive_pred[st.b], st.node, node)
                if not path:
                    if kind == "search":
                        st.looked.add((g, node))
                    else:
                        self.reject(st, g, "unreachable")
                    continue
                pts = self.pos[st.b][path]
            return (kind, g, node, pts)
        return None

    def etp_leg(self, st: EpisodeState, g: int, pose) -> tuple | None:
        stream = self.streams.get(st.ep.scene)
        if stream is None:
            raise UserError(f"etpnav needs the exploration stream of scene '{st.ep.scene}' (RUN/explore/streams)")
        T = len(stream.t)

        fell = g in st.fell_back
        key = (st.e, g, fell)
        if key not in self._seen:  # records where some visible object passes the check, and those objects
            table = self.verdicts[st.e][g]
            if fell:  # the fallback: the objects the exploration saw that fail fewest parts of the check
                m = np.where(stream.visible.any(0)[: len(table)], self.misfits[st.e][g], np.inf)
                table = np.isfinite(m) & (m == m.min())
            cand = np.zeros(stream.visible.shape[1], bool)
            cand[: len(table)] = table
            self._seen[key] = {int(r): [int(i) for i in np.flatnonzero(stream.visible[r] & cand)]
                               for r in np.flatnonzero(stream.visible[:, cand].any(1))}

        def seen(r):
            ok = [o for o in self._seen[key].get(r, []) if (g, o) not in st.skip]
            return ok[0] if ok else None

        # The online map already holds everything seen up to expl_t: go back there.
        for r in sorted(x for x in self._seen[key] if x <= st.expl_t):
            o = seen(r)
            if o is not None:
                a, bnode = self.nearest(st.b, pose[:2]), self.nearest(st.b, stream.pose[r, :2])
                path = reconstruct_path(self.pred[st.b], a, bnode) or [a]
                pts = np.concatenate([self.pos[st.b][path], stream.pose[r : r + 1, :2]])
                return ("goto_seen", g, o, pts)
        for r in sorted(x for x in self._seen[key] if x > st.expl_t):
            o = seen(r)
            if o is not None:
                return ("explore", g, (r, o), self.thin(stream.pose[st.expl_t : r + 1, :2]))
        if st.expl_t < T - 1:
            return ("explore", g, (T - 1, None), self.thin(stream.pose[st.expl_t :, :2]))
        if self.cfg.eval.fallback and not fell:  # everything explored: the object seen that fits the goal best
            st.fell_back.add(g)
            return self.etp_leg(st, g, pose)
        st.status[g] = "failed:not_observed"
        st.remaining.remove(g)
        return self.next_leg(st, pose)

    def thin(self, xy: np.ndarray) -> np.ndarray:
        keep, last = [0], xy[0]
        for i in range(1, len(xy)):
            if np.linalg.norm(xy[i] - last) >= THIN_M:
                keep.append(i)
                last = xy[i]
        if keep[-1] != len(xy) - 1:
            keep.append(len(xy) - 1)
        return xy[keep][: self.ex.path_points]

    def approach_points(self, st: EpisodeState, o: int, pose) -> np.ndarray:
        """(1, 2) where to stop by object o: `approach_gap` from its footprint on the robot's side; where that
        spot is no room for the robot (another object, a wall) or cannot be got to (`way_exists`: a pocket
        between furniture, the far side of a wall), the nearest such spot of a ring of stops around the
        footprint. The leg is driven with the local planner (drive_points)."""
        obj = self.scenes[st.ep.scene].objects[o]
        c = np.asarray(obj.position[:2], np.float32)
        half = np.asarray(obj.size[:2], np.float32) / 2
        near = np.clip(pose[:2], c - half, c + half)  # closest point of the footprint
        v = pose[:2] - near
        n = np.linalg.norm(v)
        gap = self.cfg.eval.approach_gap + self.cfg.sim.robot_radius
        if n <= gap:
            return np.asarray([pose[:2]], np.float32)
        goal = (near + v / n * gap).astype(np.float32)
        if st.b not in self.obstacles:
            return goal[None]
        ring = approach_ring(c, half, gap)  # (R, 2) stops at `gap` from the footprint
        cand = np.concatenate([goal[None], ring])
        free = segment_clearance_np(cand, cand, self.obstacles[st.b]) >= self._need()
        if not free.any():
            return goal[None]
        d = np.where(free, np.linalg.norm(cand - pose[None, :2], axis=1), np.inf)
        d[0] = 0.0 if free[0] else np.inf  # the spot on the robot's side first
        order = [k for k in np.argsort(d, kind="stable") if np.isfinite(d[k])]
        for k in order:  # the nearest stop the robot can get to
            if self.way_exists(st.b, pose[:2], cand[k]):
                return cand[k][None]
        return cand[order[0]][None]

    def way_exists(self, b: int, a: np.ndarray, c: np.ndarray) -> bool:
        """The local planner's grid joins a and c: some free region it lets the robot leave a by (see
        `_local`'s escape) is one it lets the robot reach c by, through passages the robot just fits."""
        from scipy import ndimage

        lo, clear = self._grid(b)
        tight = self.cfg.sim.robot_radius + TIGHT_GAP_M
        if (b, "labels") not in self._grids:
            self._grids[b, "labels"] = ndimage.label(clear >= tight, structure=np.ones((3, 3), bool))[0]
        labels, (H, W) = self._grids[b, "labels"], clear.shape
        r = int(ESCAPE_M / GRID_M)

        def regions(p) -> set:
            i, j = (int(np.clip(round((x - o) / GRID_M), 0, n - 1)) for x, o, n in zip(p, lo, (H, W)))
            win = np.ogrid[max(i - r, 0) : min(i + r + 1, H), max(j - r, 0) : min(j + r + 1, W)]
            disc = (win[0] - i) ** 2 + (win[1] - j) ** 2 <= r**2
            ok = disc & (clear[tuple(win)] >= min(float(clear[i, j]), tight) - 1e-6)
            return set(np.unique(labels[tuple(win)][ok]).tolist()) - {0}

        return bool(regions(a) & regions(c))

    def approach_route(self, st: EpisodeState, pose: np.ndarray, stop: np.ndarray) -> np.ndarray:
        """(n, 2) waypoints from the robot's position to an approach stop: straight where the segment is
        clear, else around what is in the way with the local planner, else over the map (key pose nearest
        the robot -> key pose nearest the stop -> stop)."""
        here, stop = np.asarray(pose[:2], np.float32), np.asarray(stop, np.float32)
        direct = np.stack([here, stop])
        if self.spec.straight or st.b not in self.obstacles:
            return direct
        if segment_clearance_np(here[None], stop[None], self.obstacles[st.b])[0] >= self._need():
            return direct
        around = self._local(st.b, here, stop, anywhere=True)
        if len(around) > 2:  # a grid path near the segment (a plant, a chair): no detour over the map
            return around
        a, t = self.attach(st.b, here), self.attach(st.b, stop)
        path = reconstruct_path(self.drive_pred[st.b], a, t) or [a]
        if len(path) <= 1 and np.linalg.norm(stop - here) <= np.linalg.norm(self.pos[st.b][path[0]] - here):
            return direct
        return np.concatenate([here[None], self.pos[st.b][path], stop[None]]).astype(np.float32)

    # -- after a leg
    def after_leg(self, st: EpisodeState, leg: tuple, pose: np.ndarray, arrived: bool, visible: np.ndarray) -> None:
        kind, g, payload, _ = leg
        sc = self.scenes[st.ep.scene]
        if kind in ("nav", "closer", "search"):
            if kind in ("nav", "search") and arrived and not self.spec.straight:
                st.node = payload
            else:  # stuck short of the node, or off the map: re-attach where a straight line leads
                st.node = self.attach(st.b, pose[:2])
            st.look_steps += self.look_cost
            if not self.spec.reads:  # knows the true goal position: no check needed
                gobj = self.goal_object(st, g)
                ok = [sc.objects.index(gobj)] if gobj is not None else []
            else:
                ok = self.passing(st, g, np.flatnonzero(visible))
            ok = [o for o in ok if (g, o) not in st.skip]
            if kind != "closer":
                st.looked.add((g, payload))
            est = self.estimate(st, g) if self.spec.reads and kind != "search" else None
            if not ok and self.cfg.eval.fallback and g not in st.fell_back:
                self.keep_backup(st, g, visible, pose[:2] if est is None else est)
            if kind == "search":  # the nearest object that passes, else the next key pose (next_leg)
                if ok:
                    o = min(ok, key=lambda i: box_distance(sc.objects[i], pose[:2]))
                    st.leg = ("approach", g, o, self.approach_points(st, o, pose))
                else:
                    st.leg = None
                return
            if not ok and kind == "closer" and est is not None:
                # Still out of sight from near it (occluded, or small): the memory recorded the instance,
                # so it passes the same check on the record and is approached at its estimated position.
                rec = [o for o in self.known[st.b] if box_distance(sc.objects[o], est) <= SAME_INSTANCE_M]
                ok = [o for o in self.passing(st, g, rec) if (g, o) not in st.skip]
            closer = self.cfg.eval.look_closer and est is not None and kind == "nav"
            if ok:
                if est is None:
                    o = min(ok, key=lambda i: box_distance(sc.objects[i], pose[:2]))
                else:  # the memory's instance for this candidate (chosen with the room / superlative terms)
                    o = min(ok, key=lambda i: box_distance(sc.objects[i], est))
                if not closer or box_distance(sc.objects[o], est) <= SAME_INSTANCE_M:
                    st.leg = ("approach", g, o, self.approach_points(st, o, pose))
                    return
            if closer:  # the key pose's view was merged over several records: look again near the instance
                st.leg = ("closer", g, payload, self.closer_points(st, est, pose))
                return
            self.reject(st, g, "not_confirmed" if arrived else "stuck")
            st.leg = None
        elif kind in ("explore", "goto_seen"):
            if kind == "explore":
                r, o = payload
                target = self.streams[st.ep.scene].pose[r, :2]
                if np.linalg.norm(pose[:2] - target) > 1.0 and st.steps < self.cfg.eval.max_steps:
                    # a long replay is split into buffer-sized parts: continue from the record reached
                    t_new = self._record_near(st, pose, r)
                    st.leg = None
                    if t_new <= st.expl_t:  # no headway along the replayed exploration
                        st.status[g] = "failed:stuck"
                        st.remaining.remove(g)
                    st.expl_t = max(t_new, st.expl_t)
                    return
                st.expl_t = r
                st.look_steps += self.look_cost
                if o is None and self.cfg.eval.fallback and g not in st.fell_back:
                    st.fell_back.add(g)  # everything explored: etp_leg goes back to what fits the goal best
                    st.leg = None
                    return
                if o is None:
                    st.status[g] = "failed:not_observed"
                    st.remaining.remove(g)
                    st.leg = None
                    return
            else:
                o = payload
            st.leg = ("approach", g, o, self.approach_points(st, o, pose))
        elif kind == "approach":
            obj = sc.objects[payload]
            st.leg = None
            if box_distance(obj, pose[:2]) <= self.cfg.eval.found_radius:
                j = self.true_goal_at(st, obj, pose)
                if j is not None:
                    st.found[j] = True
                st.declarations.append({"goal": g, "truth": j, "object": obj.id, "correct": j is not None,
                                        "step": st.steps + st.look_steps, "xy": [round(float(x), 3) for x in pose[:2]],
                                        **({"fallback": True} if g in st.fell_back else {})})
                st.status[g] = "found" if j is not None else "wrong"
                st.remaining.remove(g)
                for k in st.remaining:  # an object answers one goal ("both boilers" are two boilers), unless the
                    if st.subgoals is not None and k < len(st.subgoals) and REVISIT.search(st.subgoals[k].text):
                        continue  # goal goes back to it ("then back to the sofa")
                    st.skip.add((k, payload))
                    if st.backup.get(k, (0, None))[1] == payload:
                        del st.backup[k]
            else:
                st.skip.add((g, payload))
                if self.spec.explores:
                    return
                self.reject(st, g, "blocked")

    def _record_near(self, st, pose, r_end) -> int:
        stream = self.streams[st.ep.scene]
        lo = st.expl_t
        d = np.linalg.norm(stream.pose[lo : r_end + 1, :2] - pose[None, :2], axis=1)
        return lo + int(np.argmin(d))


def prepare_episodes(bank: MemoryBank, scenes: Sequence[Scene], episodes: Sequence[Episode], embedder, cfg: Config,
                     spec: MethodSpec, streams: dict | None = None, executor: Executor | None = None,
                     verifier: Verifier | None = None, trace: Collection[str] = ()):
    """Everything before the first leg, for either engine: (loop, states, candidates, the Oracle's candidates,
    task time per episode). Parses, grounds and retrieves for every episode, computes the verdict and search
    tables and each episode's first plan."""
    names = list(bank.names)
    unknown = sorted({ep.scene for ep in episodes} - set(names))
    if unknown:
        raise UserError(f"episodes refer to scenes without memory: {', '.join(unknown)}")
    used = [s for s in scenes if s.name in {ep.scene for ep in episodes}]
    ex = executor or make_executor(used, cfg)
    loop = Loop(spec, bank, scenes, cfg, ex, streams)
    # 1. instruction -> plan, for all episodes (host wall clock: parsing, embedding, retrieval, order)
    t0 = time.perf_counter()
    verifier = verifier or Verifier.build(embedder, cfg)
    cands = retrieve_candidates(spec, bank, scenes, episodes, embedder, cfg, verifier)
    oracle = cands if spec.retrieval == "truth" else retrieve_candidates(method_spec("oracle"), bank, scenes, episodes,
                                                                          embedder, cfg)
    t1 = time.perf_counter()
    views = memory_views(verifier, bank, scenes) if spec.reads else {}
    if spec.reads:  # the reflection's check, one verdict per (episode, goal, object)
        loop.verdicts = verdict_table(verifier, views, episodes, cands.subgoals)
        if cfg.eval.fallback:
            loop.misfits = verdict_table(verifier, views, episodes, cands.subgoals, graded=True)
    if spec.search and cfg.eval.search_nodes:
        loop.search = search_table(verifier, views, bank, episodes, cands.subgoals, cfg.eval.search_nodes)
    cands.timing["verify_s"] = time.perf_counter() - t1
    states = []
    for e, ep in enumerate(episodes):
        b = names.index(ep.scene)
        sc = loop.scenes[ep.scene]
        # the goals run: the subgoals read from the instruction (the Oracle, and an unread instruction: the true ones)
        sgs = cands.subgoals[e]
        G = len(ep.goals) if not spec.reads or sgs is None else len(sgs)
        strict = ep.order == "strict" if not spec.reads or sgs is None else parsed_order(ep.instruction) == "strict"
        start = loop.nearest(b, sc.start.position[:2])
        ests = ((cands.est[e] if cands.est else []) + [[]] * G)[:G]
        st = EpisodeState(e, ep, b, ex.names.index(ep.scene), sgs, (cands.nodes[e] + [[]] * G)[:G], ests, [0] * G,
                          [0] * G, list(range(G)), start, ["pending"] * G, strict, [False] * len(ep.goals))
        if not spec.explores:
            loop.replan(st)
        st.planned = list(st.remaining)
        st.trace = trace_of(loop, st, cands) if ep.id in trace else None
        states.append(st)
    task_time = (time.perf_counter() - t0) / max(len(episodes), 1)
    return loop, states, cands, oracle, task_time


def evaluate_navigation(bank: MemoryBank, scenes: Sequence[Scene], episodes: Sequence[Episode], embedder, cfg: Config,
                        method: str | None = None, streams: dict | None = None, progress: bool = False,
                        executor: Executor | None = None, verifier: Verifier | None = None,
                        trace: Collection[str] = ()) -> tuple[list[dict], dict]:
    """Runs one method over every episode; returns per-episode rows and the summary. Methods evaluated on
    the same episodes can share one `verifier` (and its encoder cache). The rows of the episode ids in
    `trace` also hold "legs" with per-step poses and a "trace" (candidates, rejections: `trace_of`).
    `eval.engine` picks the loop: "host" (`_run_chunk`, one batched MJX call per leg) or "device"
    (`evaluation/loop/program.py`, the whole loop one jitted program; etpnav, traces and record_legs run on
    the host)."""
    from ragnav_jax.evaluation.metrics import episode_row, summarise

    method = method or cfg.eval.method
    spec = method_spec(method)
    loop, states, cands, oracle, task_time = prepare_episodes(bank, scenes, episodes, embedder, cfg, spec, streams,
                                                              executor, verifier, trace)
    # 2./3. execute and reflect, a batch of episodes at a time
    t0 = time.perf_counter()
    B = min(cfg.eval.batch_size, max(len(states), 1))
    bar = _progress(len(states), progress, method)
    if cfg.eval.engine == "device" and not spec.explores and not trace and not cfg.eval.record_legs:
        from ragnav_jax.evaluation.loop.program import run_device

        run_device(loop, states, cfg, progress=bar)
    else:
        for c0 in range(0, len(states), B):
            chunk = states[c0 : c0 + B]
            _run_chunk(loop, chunk, B, cfg)
            bar(len(chunk))
    bar(0, close=True)
    cands.timing["loop_s"] = time.perf_counter() - t0
    rows = [episode_row(st, loop, oracle.nodes[st.e], cands, cfg, method) for st in states]
    for r, st in zip(rows, states):
        if st.trace is not None:
            r["trace"] = st.trace
    summary = summarise(rows, cands.timing, task_time, method)
    return rows, summary


def trace_of(loop: Loop, st: EpisodeState, cands: Candidates) -> dict:
    """An episode's recorder: per goal its candidates (node, node xy, retrieval score, estimated target
    position) and the rejections the loop appends (goal, candidate index, why, index of the leg after
    which it was made: -1 before the first)."""
    scores = cands.scores[st.e] if cands.scores else []

    def one(g, j, n):
        s = scores[g][j] if g < len(scores) else None
        e = st.ests[g][j] if j < len(st.ests[g]) else None
        return {"node": int(n), "xy": _xy(loop.pos[st.b][n]), "score": None if s is None else round(s, 4),
                "est": None if e is None else _xy(e)}

    return {"candidates": [[one(g, j, n) for j, n in enumerate(c)] for g, c in enumerate(st.cands)], "rejections": []}


def _xy(v) -> list[float]:
    return [round(float(x), 3) for x in v[:2]]


def _progress(total: int, on: bool, label: str):
    if not on:
        return lambda n, close=False: None
    from tqdm import tqdm

    bar = tqdm(total=total, desc=f"eval {label}", unit="ep")

    def step(n, close=False):
        bar.update(n)
        if close:
            bar.close()

    return step


def _run_chunk(loop: Loop, chunk: list, B: int, cfg: Config) -> None:
    ex = loop.ex
    P = ex.path_points
    E = len(chunk)
    scene_idx = np.zeros(B, np.int32)
    start = np.zeros((B, 3), np.float32)
    for i, st in enumerate(chunk):
        sc = loop.scenes[st.ep.scene]
        scene_idx[i] = st.s
        start[i] = (sc.start.position[0], sc.start.position[1], sc.start.yaw)
    if E < B:
        scene_idx[E:], start[E:] = scene_idx[0], start[0]
    sidx = jnp.asarray(scene_idx)
    d = ex.init(sidx, jnp.asarray(start))
    poses = start.copy()
    traced = any(st.trace is not None for st in chunk)
    while True:
        legs = [None] * E
        for i, st in enumerate(chunk):
            if not st.done and st.steps + st.look_steps >= cfg.eval.max_steps:
                st.done, st.reason = True, "budget"
                for g in list(st.remaining):
                    st.status[g] = "failed:budget"
                st.remaining = []
            legs[i] = None if st.done else loop.next_leg(st, poses[i])
        if not any(legs):
            break
        pts = np.zeros((B, P, 2), np.float32)
        n = np.zeros(B, np.int32)
        allow = np.zeros(B, np.int32)
        ways = {}
        for i, leg in enumerate(legs):
            if leg is not None:
                if leg[0] == "approach":  # from where the robot stands, round whatever is in the way
                    way = loop.drive_points(chunk[i], loop.approach_route(chunk[i], poses[i], leg[3][-1]))
                else:
                    way = loop.drive_points(chunk[i], leg[3]) if leg[0] in ("nav", "search", "closer", "goto_seen") else leg[3]
                pts[i], n[i] = pad_points(way, P)
                ways[i] = way
                st = chunk[i]
                allow[i] = max(min(cfg.eval.leg_max_steps, cfg.eval.max_steps - st.steps - st.look_steps), 0)
        args = (sidx, d, jnp.asarray(pts), jnp.asarray(n), jnp.asarray(allow))
        res, trail = ex.run_traced(*args) if traced else (ex.run(*args), None)
        d = res.d
        vis, _ = ex.look(sidx, d)
        poses = np.asarray(d.qpos[:, :3])
        arrived, steps, length = np.asarray(res.arrived), np.asarray(res.steps), np.asarray(res.length)
        pen, vis = np.asarray(res.penetration), np.asarray(vis)
        trail = None if trail is None else np.asarray(trail)  # (B, leg_max_steps, 3) poses per control step
        for i, leg in enumerate(legs):
            if leg is None:
                continue
            st = chunk[i]
            st.steps += int(steps[i])
            st.length += float(length[i])
            st.penetration = max(st.penetration, float(pen[i]))
            if cfg.eval.record_legs or st.trace is not None:
                st.legs.append({"kind": leg[0], "goal": int(leg[1]), "steps": int(steps[i]), "arrived": bool(arrived[i]),
                                "waypoints": np.round(np.asarray(ways[i], np.float64)[: n[i]], 3).tolist(),
                                "end": _xy(poses[i])})
                if st.trace is not None:
                    objs = loop.scenes[st.ep.scene].objects
                    st.legs[-1].update(poses=np.round(trail[i, : steps[i]].astype(np.float64), 3).tolist(),
                                       visible=[objs[o].id for o in np.flatnonzero(vis[i]) if o < len(objs)])
            loop.after_leg(st, leg, poses[i], bool(arrived[i]), vis[i])
