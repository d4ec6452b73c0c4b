"""Closed-loop navigation as sweep metrics: every grid point's retrieval, candidates and closed loop, in one call.

    metrics = closed_loop_metrics(cfg, bank, scenes, episodes, embedder, grid, meta.modalities)
    run_sweep(cfg, batch, meta, out, extra_metrics=metrics)   # `ragnav sweep --closed-loop`

For a chunk of grid points (sigma, eta, ... and the planning lambda) the jitted function scores every subgoal
with the retrieval kernel (`scored_batch`), ranks each subgoal's candidates on the device
(`candidates.rank_all`: RAGNav's widened order, distinct instances, the pre-check as a table, the closest
view), and runs the closed loop (`program.closed_loop`) on points x episodes as one queue on eval.batch_size lanes,
each episode with its point's lambda; then judges every episode on the device (`judge`: the rules of `metrics.episode_row`).
What does not depend on the grid (parses, verdict and search tables, the pre-check, the Oracle's route) is
computed once on the host. Sums per modality: successes, SPL, progress and metres driven; the sweep table
divides them by the episodes of each modality.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence

import jax
import jax.numpy as jnp
import numpy as np
from flax import struct

from ragnav_jax.config import Config
from ragnav_jax.evaluation.loop import program
from ragnav_jax.evaluation.loop.candidates import rank_all
from ragnav_jax.evaluation.loop.state import Flags, Inputs, State, World
from ragnav_jax.evaluation.sweep import Grid, GridMetric, _digest, _in_axes
from ragnav_jax.retrieval.evaluate import RetrievalBatch, scored_batch

NAMES = ("nav_success", "nav_spl", "nav_progress", "nav_travel_m")


@struct.dataclass
class LoopEpisodes:
    """What a closed-loop sweep reads, E episodes (device arrays)."""

    batch: RetrievalBatch  # the retrieval kernel's inputs (bucketed slots)
    world: World
    base: Inputs  # (E, ...) every input but the candidates
    slot: jax.Array  # (E, G) int32 candidate slot of each goal run (-1: none)
    slot_b: jax.Array  # (M,) int32 scene of each slot
    slot_q: jax.Array  # (M,) int32 subgoal slot in its scene
    ruled: jax.Array  # (M, I) bool the pre-check rules the instance out for the slot
    scene_idx: jax.Array  # (E,) int32 executor scene
    start: jax.Array  # (E, 3) start pose
    strict: jax.Array  # (E,) bool the episode's true order
    num_true: jax.Array  # (E,) int32 true goals
    oracle_m: jax.Array  # (E,) float32 the Oracle's shortest route (SPL's reference)
    group: jax.Array  # (E, Mods) bool one-hot modality


def judge(st: State, num_true, strict, oracle_m, max_steps: int):
    """(success, spl, progress, travel) of one episode's final State, by `metrics.episode_row`'s rules."""
    T, D = st.found.shape[0], st.decl_truth.shape[0]
    tm = jnp.arange(T) < num_true
    found = st.found & tm
    valid = jnp.arange(D) < st.n_decl
    truth = st.decl_truth
    correct = valid & (truth >= 0)
    wrong = jnp.any(valid & (truth < 0))
    later = jnp.arange(D)[:, None] < jnp.arange(D)[None, :]
    in_order = ~jnp.any(correct[:, None] & correct[None, :] & later & (truth[:, None] > truth[None, :]))
    budget_ok = st.steps + st.look_steps <= max_steps
    success = jnp.all(found | ~tm) & (in_order | ~strict) & budget_ok & ~wrong
    G = jnp.maximum(num_true, 1).astype(jnp.float32)
    prefix = jnp.sum(jnp.cumprod((found | ~tm) & tm)).astype(jnp.float32)
    rank = jnp.cumsum(correct) - 1
    placed = jnp.sum(correct & (rank == truth)).astype(jnp.float32)
    progress = jnp.where(strict, jnp.where(in_order, prefix, placed), found.sum()) / G
    L, Ls = st.length, oracle_m
    ratio = jnp.where((Ls <= 0) & (L <= 0), 1.0, Ls / jnp.maximum(jnp.maximum(L, Ls), 1e-9))
    return success, success * ratio, progress, L


def _candidates(le: LoopEpisodes, params, *, k: int, depth: int, widen: bool, closest_view: bool):
    """(E, G, k) candidate key poses, (E, G, k, 2) instance estimates and (E, G, k) their masks at one point."""
    s, ex = scored_batch(le.batch.index, le.batch.queries, params)
    r = rank_all(s, ex["relaxed"], ex["category"], ex["instance"], le.batch.index.node_mask, le.batch.index.slot_inst,
                 le.batch.index.inst_pos[..., :2], le.batch.index.node_pos[..., :2], le.ruled, le.slot_b, le.slot_q,
                 k, depth, widen, closest_view)
    has = le.slot >= 0
    idx = jnp.maximum(le.slot, 0)
    return (jnp.where(has[..., None], r.nodes[idx], -1), r.est[idx],
            has[..., None] & r.has_est[idx])


def _points(le: LoopEpisodes, params, lam, *, outer, inner, fl: Flags, refill: float, lanes: int, ranking: dict, init,
            advance, look):
    """Sums (V, C, Mods) of every NAMES metric for a chunk of grid points (params as Grid.chunk gives them); the
    points x episodes runs are queued on `lanes` lanes (eval.batch_size)."""
    f = jax.vmap(functools.partial(_candidates, **ranking), in_axes=(None, _in_axes(inner)))
    if outer:
        f = jax.vmap(f, in_axes=(None, _in_axes(outer)))
        cands, est, has = f(le, params)  # (V, C, E, G, k)
    else:
        cands, est, has = (x[None] for x in f(le, params))
    V, C, E = cands.shape[:3]
    flat = lambda x: x.reshape((V * C * E, *x.shape[3:]))  # noqa: E731
    tile = lambda x: jnp.broadcast_to(x, (V, C, *x.shape)).reshape((V * C * x.shape[0], *x.shape[1:]))  # noqa: E731
    inp = jax.tree.map(tile, le.base).replace(cands=flat(cands), est=flat(est), has_est=flat(has))
    lams = jnp.broadcast_to(lam[None, :, None], (V, C, E)).reshape(-1)
    st = program.closed_loop(le.world, inp, tile(le.scene_idx), tile(le.start), lams, jnp.float32(refill), fl=fl,
                             init=init, advance=advance, look=look, lanes=lanes)
    out = jax.vmap(lambda s, n, o, m: judge(s, n, o, m, fl.max_steps))(st, tile(le.num_true), tile(le.strict),
                                                                        tile(le.oracle_m))
    group = le.group.astype(jnp.float32)
    return {name: jnp.einsum("vce,em->vcm", x.astype(jnp.float32).reshape(V, C, E), group)
            for name, x in zip(NAMES, out)}


def loop_episodes(cfg: Config, bank, scenes: Sequence, episodes: Sequence, embedder, modalities: Sequence[str],
                  executor=None, verifier=None):
    """(LoopEpisodes, totals (Mods,) episodes per modality, host Loop, the ranking's static settings) for RAGNav
    on these episodes."""
    from ragnav_jax.evaluation.methods import method_spec
    from ragnav_jax.evaluation.metrics import _oracle_length
    from ragnav_jax.evaluation.navigate import prepare_episodes
    from ragnav_jax.evaluation.ranking import CANDIDATE_DEPTH, grounder, ruled_out
    from ragnav_jax.evaluation.verify import Verifier, name_classes, recorded, vocabulary
    from ragnav_jax.retrieval.evaluate import prepare_batch

    spec = method_spec("ragnav")
    verifier = verifier or Verifier.build(embedder, cfg)
    loop, states, _, oracle, _ = prepare_episodes(bank, scenes, episodes, embedder, cfg, spec, executor=executor,
                                                  verifier=verifier)
    ground = grounder(spec, bank, scenes, episodes, cfg, verifier)
    batch, bmeta = prepare_batch(bank, scenes, episodes, embedder, ground=ground, every_subgoal=True, bucket_slots=True)
    by_name = {s.name: s for s in scenes}
    G = max(max(len(st.status) for st in states), 1)
    k = cfg.eval.candidates
    S, T = max(1, cfg.eval.search_nodes), max(len(st.ep.goals) for st in states)
    base = program.inputs_of(loop, states, G, k, S, T)
    index_of = {ep.id: e for e, ep in enumerate(episodes)}
    I = int(batch.index.inst_pos.shape[1])
    slot = np.full((len(states), G), -1, np.int32)
    sb, sq, ruled = [], [], []
    rec = [recorded(m, by_name[m.scene]) if m.scene in by_name else ({}, {}) for m in bank.metas]
    inst_pos = np.asarray(batch.index.inst_pos)[..., :2]
    for (ep, kk, _goal, sg), sl in zip(bmeta.items, bmeta.slots):
        e = index_of[ep.id]
        if sl is None or kk >= G or states[e].subgoals is None:
            continue
        b, q = sl
        slot[e, kk] = len(sb)
        sb.append(b)
        sq.append(q)
        row = np.zeros(I, bool)
        if cfg.eval.precheck:
            phrases = bmeta.imetas[b].instance_phrases
            names, classes, vocab = rec[b][1], name_classes(rec[b][0])[0], vocabulary(rec[b][0])
            for i, texts in enumerate(phrases[:I]):
                row[i] = ruled_out(verifier, sg, [names.get(t, t) for t in texts], texts, vocab, classes, inst_pos[b, i],
                                   cfg.episodes.location_radius)
        ruled.append(row)
    mods = list(modalities)
    group = np.zeros((len(states), len(mods)), bool)
    totals = np.zeros(len(mods), np.int64)
    for e, st in enumerate(states):
        group[e, mods.index(st.ep.modality)] = True
        totals[mods.index(st.ep.modality)] += 1
    oracle_m = np.asarray([_oracle_length(loop, st, oracle.nodes[st.e]) for st in states], np.float32)
    le = LoopEpisodes(
        batch=batch, world=program.world_of(loop), base=base, slot=jnp.asarray(slot),
        slot_b=jnp.asarray(np.asarray(sb or [0], np.int32)), slot_q=jnp.asarray(np.asarray(sq or [0], np.int32)),
        ruled=jnp.asarray(np.stack(ruled) if ruled else np.zeros((1, I), bool)),
        scene_idx=jnp.asarray([st.s for st in states], jnp.int32),
        start=jnp.asarray([[*by_name[st.ep.scene].start.position[:2], by_name[st.ep.scene].start.yaw] for st in states],
                          jnp.float32),
        strict=jnp.asarray([st.ep.order == "strict" for st in states]),
        num_true=jnp.asarray([len(st.ep.goals) for st in states], jnp.int32), oracle_m=jnp.asarray(oracle_m),
        group=jnp.asarray(group))
    return le, totals, loop, dict(k=k, depth=CANDIDATE_DEPTH, widen=cfg.eval.widen, closest_view=cfg.eval.closest_view)


def closed_loop_metrics(cfg: Config, bank, scenes: Sequence, episodes: Sequence, embedder, grid: Grid,
                        modalities: Sequence[str], executor=None, verifier=None) -> list[GridMetric]:
    """NAMES as GridMetrics of `run_sweep` (uses_lam): one compiled call per chunk computes all four; each
    metric reads its part of the chunk's result."""
    if "no_topology" in grid.variants:
        from ragnav_jax.errors import UserError

        raise UserError("sweep --closed-loop: the no_topology variant also drives without the map (other loop flags); "
                        "drop it from sweep.variants")
    le, totals, loop, ranking = loop_episodes(cfg, bank, scenes, episodes, embedder, modalities, executor, verifier)
    fl = program.flags_of(cfg, loop.look_cost)
    ex = loop.ex
    fn = jax.jit(functools.partial(_points, outer=tuple(grid.outer), inner=tuple(grid.inner), fl=fl,
                                   refill=cfg.eval.refill, lanes=cfg.eval.batch_size, ranking=ranking, init=ex.init, advance=ex.advance, look=ex.look_fn))
    last: dict = {}

    def part(name):
        def f(params, lam):
            if "args" not in last or last["args"][0] is not params or last["args"][1] is not lam:  # a new chunk
                last.update(args=(params, lam), out=fn(le, params, jnp.asarray(lam)))
            return last["out"][name]

        return f

    fp = _digest((le.base, le.slot, le.ruled, le.oracle_m)) + f"|{fl}|{ranking}"
    return [GridMetric(name, part(name), totals, tuple(modalities), fp, uses_lam=True) for name in NAMES]

