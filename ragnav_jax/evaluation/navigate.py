"""The closed loop: perception (retrieval) - planning - execution (MJX) - reflection, over many episodes.

    rows, summary = evaluate_navigation(bank, scenes, episodes, embedder, cfg, method="ragnav", streams=streams)

Phases (host Python only between them; every simulation step runs inside a jitted batched call):
1. Plan (`prepare_episodes`): parse every instruction, retrieve the top-`eval.candidates` nodes of every
   subgoal in one batched kernel call (`ranking.retrieve_candidates`), solve each episode's visiting order.
2. Execute legs and 3. reflect on arrival: the host engine (`host_loop.py`) or the device engine
   (`loop/program.py`), by `eval.engine`.
The loop runs the subgoals it read, as many as it read and in the order type it read (strict: as written;
free: its own plan); it never sees the episode file's goals or order (only the Oracle does).
Judging (MultiON-style, on the simulated trajectory only): a FOUND counts for the true goal the robot
approached when it is one not found yet, else for the nearest such goal within `eval.found_radius` of the
robot's simulated position, whichever subgoal it was made for; passing near a goal without declaring does
not count; a FOUND at no true goal is a recorded wrong declaration and fails the episode. An episode
succeeds when every true goal was found (strict episodes: in the episode's order) within `eval.max_steps`.
The methods are flags of this one loop (`methods.py`).
"""

from __future__ import annotations

import time
from collections.abc import Collection, Sequence

from ragnav_jax.config import Config
from ragnav_jax.errors import UserError
from ragnav_jax.evaluation import host_loop
from ragnav_jax.evaluation.execute import Executor, make_executor
from ragnav_jax.evaluation.host_loop import EpisodeState, Loop, trace_of
from ragnav_jax.evaluation.methods import MethodSpec, method_spec
from ragnav_jax.evaluation.ranking import retrieve_candidates
from ragnav_jax.evaluation.search import search_table
from ragnav_jax.evaluation.verify import Verifier, memory_views, verdict_table
from ragnav_jax.language.episodes import Episode
from ragnav_jax.memory.types import MemoryBank
from ragnav_jax.retrieval.evaluate import parsed_order
from ragnav_jax.world.scene import Scene

LANE_STEP = 4  # the host loop's lane counts are multiples of this: runs of 1 to 4 episodes share one program


def lanes_for(n: int) -> int:
    """Lanes the host loop drives n episodes on (before the eval.batch_size cap): n rounded up to a multiple of
    LANE_STEP, the extra lanes padding, so that small runs of different sizes share compiled programs (and
    the persistent compilation cache) at the price of at most LANE_STEP - 1 idle lanes."""
    return max(1, -(-n // LANE_STEP)) * LANE_STEP


def prepare_episodes(bank: MemoryBank, scenes: Sequence[Scene], episodes: Sequence[Episode], embedder, cfg: Config,
                     spec: MethodSpec, streams: dict | None = None, executor: Executor | None = None,
                     verifier: Verifier | None = None, trace: Collection[str] = (),
                     memory_scenes: Sequence[Scene] | None = None):
    """Everything before the first leg, for either engine: (loop, states, candidates, the Oracle's candidates,
    task time per episode). Parses, grounds and retrieves for every episode, computes the verdict and search
    tables and each episode's first plan. memory_scenes: the scenes as the memory was built from them, where
    `scenes` changed since (`world.changes.world_after`: same object indices); retrieval, grounding and what
    the memory knows of rooms read them, the world (driving, seeing, the check's perception, the Oracle)
    reads `scenes`."""
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
    memory_scenes = memory_scenes or scenes
    cands = retrieve_candidates(spec, bank, scenes if spec.retrieval == "truth" else memory_scenes, episodes, embedder,
                                cfg, verifier, memory_scenes=memory_scenes)
    oracle = cands if spec.retrieval == "truth" else retrieve_candidates(method_spec("oracle"), bank, scenes, episodes,
                                                                          embedder, cfg, memory_scenes=memory_scenes)
    t1 = time.perf_counter()
    views = memory_views(verifier, bank, scenes, memory_scenes) if spec.reads else {}
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
        # an order the parser could not read (the tagger read the goals) is the order they are written in
        strict = ep.order == "strict" if not spec.reads or sgs is None else parsed_order(ep.instruction) != "free"
        start = loop.nearest(b, sc.start.position[:2])
        ests = ((cands.est[e] if cands.est else []) + [[]] * G)[:G]
        st = EpisodeState(e, ep, b, ex.names.index(ep.scene), sgs, (cands.nodes[e] + [[]] * G)[:G], ests, [0] * G,
                          [0] * G, list(range(G)), start, ["pending"] * G, strict, [False] * len(ep.goals))
        states.append(st)
    if not spec.explores:
        loop.replan_all(states)
    for st in states:
        st.planned = list(st.remaining)
        st.trace = trace_of(loop, st, cands) if st.ep.id in trace else None
    task_time = (time.perf_counter() - t0) / max(len(episodes), 1)
    return loop, states, cands, oracle, task_time


def evaluate_navigation(bank: MemoryBank, scenes: Sequence[Scene], episodes: Sequence[Episode], embedder, cfg: Config,
                        method: str | None = None, streams: dict | None = None, progress: bool = False,
                        executor: Executor | None = None, verifier: Verifier | None = None,
                        trace: Collection[str] = (), memory_scenes: Sequence[Scene] | None = None
                        ) -> tuple[list[dict], dict]:
    """Runs one method over every episode; returns per-episode rows and the summary. Methods evaluated on
    the same episodes can share one `verifier` (and its encoder cache). The rows of the episode ids in
    `trace` also hold "legs" with per-step poses and a "trace" (candidates, rejections: `trace_of`).
    `eval.engine` picks the loop: "host" (`host_loop._run_chunk`, one batched MJX call per leg) or "device"
    (`evaluation/loop/program.py`, the whole loop one jitted program; etpnav, traces and record_legs run on
    the host). memory_scenes: as in `prepare_episodes` (a world that changed after exploration)."""
    from ragnav_jax.evaluation.metrics import episode_row, oracle_lengths, summarise

    method = method or cfg.eval.method
    spec = method_spec(method)
    loop, states, cands, oracle, task_time = prepare_episodes(bank, scenes, episodes, embedder, cfg, spec, streams,
                                                              executor, verifier, trace, memory_scenes)
    # 2./3. execute and reflect, a batch of episodes at a time
    t0 = time.perf_counter()
    B = min(cfg.eval.batch_size, lanes_for(len(states)))
    bar = _progress(len(states), progress, method)
    if cfg.eval.engine == "device" and not spec.explores and not spec.online and not trace and not cfg.eval.record_legs:
        from ragnav_jax.evaluation.loop.program import run_device

        run_device(loop, states, cfg, progress=bar)
    else:
        for c0 in range(0, len(states), B):
            chunk = states[c0 : c0 + B]
            host_loop._run_chunk(loop, chunk, B, cfg)  # via the module: bench LOOP_ENTRY_POINTS wraps it there
            bar(len(chunk))
    bar(0, close=True)
    cands.timing["loop_s"] = time.perf_counter() - t0
    lengths = oracle_lengths(loop, states, [oracle.nodes[st.e] for st in states])
    rows = [episode_row(st, loop, Ls, cands, cfg, method) for st, Ls in zip(states, lengths)]
    if memory_scenes is not None:  # a world that changed after exploration: which goals' objects changed
        from ragnav_jax.evaluation.worlds import goal_changes

        before = {s.name: s for s in memory_scenes}
        for r, st in zip(rows, states):
            r["changed_goals"] = goal_changes(st.ep.goals, loop.scenes[st.ep.scene], before[st.ep.scene])
            r["changed"] = any(r["changed_goals"])
    for r, st in zip(rows, states):
        if st.trace is not None:
            r["trace"] = st.trace
    summary = summarise(rows, cands.timing, task_time, method)
    return rows, summary


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
