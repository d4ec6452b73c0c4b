"""Closed-loop navigation as sweep metrics: every grid point's retrieval, candidates and closed loop, in one call.

    metrics = closed_loop_metrics(cfg, bank, scenes, episodes, embedder, grid, meta.modalities)
    run_sweep(cfg, batch, meta, out, extra_metrics=metrics)   # `ragnav sweep --closed-loop`

For a chunk of grid points (sigma, eta, ... and the planning lambda) one jitted function scores every subgoal
with the retrieval kernel (`scored_batch`) and ranks each subgoal's candidates on the device
(`candidates.rank_all`: RAGNav's widened order, distinct instances, the pre-check as a table, the closest
view). `LoopRuns` then runs the closed loop (`program.closed_loop`) once for each distinct (episode,
candidates, lambda) the sweep meets, queued on eval.batch_size lanes (on each device of the sweep's mesh),
and judges each run on the device (`judge`: the rules of `metrics.episode_row`); grid points that rank an
episode's candidates alike read the same run. What does not depend on the grid (parses, verdict and search
tables, the pre-check, the Oracle's route) is computed once on the host. Sums per modality: successes, SPL,
progress and metres driven; the sweep table divides them by the episodes of each modality.
"""

from __future__ import annotations

import functools
import time
from collections.abc import Sequence
from concurrent.futures import ThreadPoolExecutor

import jax
import jax.numpy as jnp
import numpy as np
from flax import struct

from ragnav_jax.config import Config
from ragnav_jax.evaluation.loop import program
from ragnav_jax.evaluation.loop.candidates import rank_all
from ragnav_jax.evaluation.loop.state import Inputs, State, World
from ragnav_jax.evaluation.sweep import Grid, GridMetric, _digest, _in_axes, sweep_mesh
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


def _chunk_candidates(le: LoopEpisodes, params, *, outer, inner, ranking: dict):
    """(V, C, E, G, K) candidates, instance estimates (zero where there is none) and their masks for a chunk of
    grid points (params as Grid.chunk gives them), K the width of the episodes' inputs (-1 / False padded)."""
    f = jax.vmap(functools.partial(_candidates, **ranking), in_axes=(None, _in_axes(inner)))
    if outer:
        cands, est, has = jax.vmap(f, in_axes=(None, _in_axes(outer)))(le, params)
    else:
        cands, est, has = (x[None] for x in f(le, params))
    wide = [(0, 0)] * 4 + [(0, le.base.cands.shape[-1] - cands.shape[-1])]
    return (jnp.pad(cands, wide, constant_values=-1), jnp.pad(jnp.where(has[..., None], est, 0.0), [*wide, (0, 0)]),
            jnp.pad(has, wide))


@functools.partial(jax.jit, static_argnames="max_steps")
def _judge_runs(st: State, num_true, strict, oracle_m, *, max_steps: int):
    """(Q, 4) float32 success, SPL, progress and metres driven of Q final States."""
    out = jax.vmap(lambda s, n, o, m: judge(s, n, o, m, max_steps))(st, num_true, strict, oracle_m)
    return jnp.stack([x.astype(jnp.float32) for x in out], axis=-1)


def _judged_runs(le: LoopEpisodes, run_e, cands, est, has, lam, count, *, loop_fn, max_steps: int):
    """(Q, 4) `_judge_runs` of Q queued closed-loop runs: episode run_e (Q,) with candidates (Q, G, K), estimates
    (Q, G, K, 2), masks (Q, G, K) and order penalty lam (Q,); the first count[0] are run, the rest is padding.
    loop_fn: `program.closed_loop` with its static settings (`program.compiled`)."""
    inp = jax.tree.map(lambda x: x[run_e], le.base).replace(cands=cands, est=est, has_est=has)
    st = loop_fn(le.world, inp, le.scene_idx[run_e], le.start[run_e], lam, count[0])
    return _judge_runs(st, le.num_true[run_e], le.strict[run_e], le.oracle_m[run_e], max_steps=max_steps)


def _deal(x: np.ndarray, slot: np.ndarray, size: int) -> np.ndarray:
    """x's rows placed at `slot` of `size` zero rows."""
    y = np.zeros((size, *x.shape[1:]), x.dtype)
    y[slot] = x
    return y


class LoopRuns:
    """RAGNav's closed loop at many grid points, each distinct run once.

    A run's outcome depends only on its episode, its candidates (with their instance estimates) and its order
    penalty: the loop reads nothing else of the grid point, and an episode's rows do not depend on its lane or
    its place in the queue (tests/test_loop_program.py). Grid points that rank an episode's candidates alike
    (most of a sigma x eta grid) share one run, so a sweep runs the distinct (episode, candidates, lambda)
    inputs it meets, each once over all its chunks, and reads the others from the runs it made.

    On several devices each call's runs are dealt out over them (run r to device r % n) and every device runs
    its own queue on eval.batch_size lanes: the one-device program, dispatched to each device from a thread of
    its own (XLA's GPU compiler crashed on the same loop as a shard_map over 4 GPUs, 2026-11-27), so a run's
    outcome does not depend on the number of devices either.
    """

    def __init__(self, fn, le, lanes: int, devices=None):
        """fn(le, run_e, cands, est, has, lam, count) -> (Q, 4) outcomes of one device's queue (`_judged_runs` with
        its settings); le: what fn reads besides the runs; lanes: eval.batch_size; devices: where the queues run
        (default: one queue, on the default device)."""
        self.fn, self.lanes = fn, lanes
        self.devices = list(devices) if devices else [None]
        self.n, self.q = len(self.devices), 0
        self.le = [le if d is None else jax.device_put(le, d) for d in self.devices]
        self.index: dict[bytes, int] = {}  # a run's inputs -> its row of `results`
        self.results = np.zeros((0, 4), np.float32)
        self.stats = {"episode_runs": 0, "loop_runs": 0, "loop_calls": 0, "loop_s": 0.0, "loop_call_s": [],
                      "loop_call_runs": [], "loop_devices": self.n}  # each call's seconds (the first of a queue
        # shape compiles, on each device) and runs

    def queue_size(self, runs: int) -> int:
        """Runs per device of one call: 1, 2, 4 or 8 batches of lanes, as few as hold `runs` but never fewer than
        an earlier call's (a sweep's later chunks, with few new runs, reuse its compilation)."""
        self.q = max(self.q, program.queue_size(-(-runs // self.n), self.lanes))
        return self.q

    def _queue(self, d: int, args: list) -> np.ndarray:
        """Device d's queue: its (Qd, ...) runs and count (1,), run to the end."""
        dev = self.devices[d]
        args = [jnp.asarray(a) if dev is None else jax.device_put(a, dev) for a in args]
        return np.asarray(self.fn(self.le[d], *args))

    def _run(self, *runs) -> np.ndarray:
        """(U, 4) outcomes of U new runs (host arrays run_e, cands, est, has, lam with U leading), in calls of at
        most QUEUE_BATCHES batches of lanes per device."""
        U, most, out = len(runs[0]), self.n * self.lanes * program.QUEUE_BATCHES, []
        for lo in range(0, U, most):
            m = min(U - lo, most)
            Qd = self.queue_size(m)
            slot = (np.arange(m) % self.n) * Qd + np.arange(m) // self.n  # run r: device r % n, in run order
            full = [_deal(x[lo : lo + m], slot, self.n * Qd) for x in runs]
            count = np.bincount(np.arange(m) % self.n, minlength=self.n).astype(np.int32)  # runs per device
            parts = [[x[d * Qd : (d + 1) * Qd] for x in full] + [count[d : d + 1]] for d in range(self.n)]
            t0 = time.perf_counter()
            with ThreadPoolExecutor(self.n) as pool:  # a thread a device: each compiles (the first time) and runs
                res = np.concatenate(list(pool.map(self._queue, range(self.n), parts)))  # its queue as the others do
            dt = time.perf_counter() - t0
            self.stats["loop_s"] = round(self.stats["loop_s"] + dt, 3)
            self.stats["loop_calls"] += 1
            self.stats["loop_call_s"].append(round(dt, 3))
            self.stats["loop_call_runs"].append(m)
            out.append(res[slot])
        return np.concatenate(out) if out else np.zeros((0, 4), np.float32)

    def __call__(self, cands, est, has, lam, real: int | None = None) -> np.ndarray:
        """(V, real, E, 4) outcomes of every episode at a chunk's points: cands, est, has (V, C, E, ...) as
        `_chunk_candidates` gives them, lam (C,), of which the first `real` are grid points (default all) and the
        rest padding, neither run nor counted. Runs only the inputs no earlier call met."""
        real = len(lam) if real is None else real
        cands, est, has = (np.asarray(x)[:, :real] for x in (cands, est, has))
        lam, est = np.asarray(lam)[:real], est.astype(np.float32)
        V, C, E = cands.shape[:3]
        R = V * C * E
        run_e = np.broadcast_to(np.arange(E, dtype=np.int32), (V, C, E)).reshape(R)
        lams = np.broadcast_to(np.asarray(lam, np.float32)[None, :, None], (V, C, E)).reshape(R)
        flat = [x.reshape(R, *x.shape[3:]) for x in (cands, est, has)]
        keys = np.concatenate([np.ascontiguousarray(x).reshape(R, -1).view(np.uint8).reshape(R, -1)
                               for x in (run_e, lams, *flat)], axis=1)
        uniq, first, inv = np.unique(keys, axis=0, return_index=True, return_inverse=True)
        rows, todo = np.empty(len(uniq), np.int64), []
        for u, k in enumerate(map(bytes, uniq)):
            if k not in self.index:
                self.index[k] = len(self.index)
                todo.append(u)
            rows[u] = self.index[k]
        if todo:
            f = first[todo]
            self.results = np.concatenate([self.results, self._run(run_e[f], *(x[f] for x in flat), lams[f])])
        self.stats["episode_runs"] += R
        self.stats["loop_runs"] += len(todo)
        return self.results[rows[inv.reshape(R)]].reshape(V, C, E, 4)


def loop_episodes(cfg: Config, bank, scenes: Sequence, episodes: Sequence, embedder, modalities: Sequence[str],
                  executor=None, verifier=None):
    """(LoopEpisodes, totals (Mods,) episodes per modality, host Loop, the ranking's static settings) for RAGNav
    on these episodes."""
    from ragnav_jax.evaluation.methods import method_spec
    from ragnav_jax.evaluation.metrics import oracle_lengths
    from ragnav_jax.evaluation.navigate import prepare_episodes
    from ragnav_jax.evaluation.ranking import CANDIDATE_DEPTH, grounder, ruled_out
    from ragnav_jax.evaluation.verify import Verifier, recorded, vocabulary
    from ragnav_jax.memory.names import name_classes
    from ragnav_jax.retrieval.evaluate import prepare_batch

    spec = method_spec("ragnav")
    verifier = verifier or Verifier.build(embedder, cfg)
    loop, states, _, oracle, _ = prepare_episodes(bank, scenes, episodes, embedder, cfg, spec, executor=executor,
                                                  verifier=verifier)
    ground = grounder(spec, bank, scenes, episodes, cfg, verifier)
    batch, bmeta = prepare_batch(bank, scenes, episodes, embedder, ground=ground, every_subgoal=True, bucket_slots=True)
    by_name = {s.name: s for s in scenes}
    G, C, S, T = program.batch_sizes(states, cfg)  # the device eval's shapes: its compiled loop serves the sweep
    base = program.inputs_of(loop, states, G, C, S, T)
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
    oracle_m = np.asarray(oracle_lengths(loop, states, [oracle.nodes[st.e] for st in states]), np.float32)
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
    return le, totals, loop, dict(k=cfg.eval.candidates, depth=CANDIDATE_DEPTH, widen=cfg.eval.widen,
                                  closest_view=cfg.eval.closest_view)


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
    ex, lanes, mesh = loop.ex, cfg.eval.batch_size, sweep_mesh(cfg)
    fn = functools.partial(_judged_runs, loop_fn=program.compiled(ex, fl, lanes),
                           max_steps=fl.max_steps)  # the device eval's compiled loop
    devices = list(mesh.devices.flat) if mesh is not None and jax.process_count() == 1 else None
    runs = LoopRuns(fn, le, lanes, devices)
    cands = jax.jit(functools.partial(_chunk_candidates, outer=tuple(grid.outer), inner=tuple(grid.inner),
                                      ranking=ranking))
    group = np.asarray(le.group, np.float64)
    last: dict = {}

    def part(name):
        def f(params, lam, real):
            if "args" not in last or last["args"][0] is not params or last["args"][1] is not lam:  # a new chunk
                out = runs(*cands(le, params), np.asarray(lam), real)  # (V, real, E, 4)
                last.update(args=(params, lam), out=dict(zip(NAMES, np.einsum("vcek,em->kvcm", out, group))))
            return last["out"][name]

        return f

    fp = _digest((le.base, le.slot, le.ruled, le.oracle_m)) + f"|{fl}|{ranking}"
    return [GridMetric(name, part(name), totals, tuple(modalities), fp, uses_lam=True, stats=runs.stats)
            for name in NAMES]

