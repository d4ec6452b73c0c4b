"""Benchmark profiles: the sizes each section of `ragnav bench` runs at (quick, full CPU, GPU).

A profile is a frozen record; `scaled(profile, s)` shrinks every size by `s` (with floors) so the GPU
profile can run at tiny scale on a CPU in a test and still exercise its code paths (chunked queries,
large batches, the big sweep).
"""

from __future__ import annotations

import dataclasses
import math

SECTIONS = ("retrieval", "paths", "planning", "simulation", "end_to_end", "sweep", "closed_loop", "memory_update")


@dataclasses.dataclass(frozen=True)
class Profile:
    name: str
    repeats: int = 5  # timed repeats of every figure (median, min, max)
    # retrieval: memory sizes and queries per size; chunk = queries per vmapped block
    retrieval_sizes: tuple[int, ...] = (80, 1000, 10000, 100000)
    retrieval_queries: tuple[int, ...] = (256, 256, 256, 64)
    retrieval_chunk: int | None = None
    retrieval_max_cells: int | None = None  # cap on queries x nodes per block and per faiss batch (memory, time)
    faiss_queries: int | None = None  # cap on the queries faiss searches (compared per query)
    # shortest paths: graphs per batch and node counts; networkx on a sample, extrapolated
    path_graphs: int = 1000
    path_nodes: tuple[int, ...] = (80, 200)
    path_nx_sample: int = 50
    path_repeats: int | None = None  # timed repeats of the batched call (None: `repeats`)
    path_chunk: int | None = None  # graphs in flight at once (lax.map over blocks; None: all in one vmap)
    path_max_cells: int | None = None  # cap on graphs x n^2 per size (device memory; None: path_graphs always)
    # order planning: episodes, Python sample sizes
    plan_episodes: int = 10_000
    plan_python_bf: int = 20
    plan_python_hk: int = 5
    # simulation: MJX batch sizes, env steps per call, C-loop steps
    sim_batches: tuple[int, ...] = (1, 4, 16, 64, 256, 1024)
    sim_steps: int = 8
    sim_c_steps: int = 200
    # end to end on the paper preset: scene counts, keyframe spacings (nodes per scene), episodes per scene
    e2e_scenes: tuple[int, ...] = (1, 4, 14, 64)
    e2e_spacings: tuple[float, ...] = (0.8, 0.5, 0.3)
    e2e_spacing_scenes: int = 2
    e2e_plan_episodes: int = 8  # instructions planned (plan_instruction) per scene count
    e2e_embedder: str = "hashing"  # MiniLM inference would dominate the CPU figures; hashing keeps stages visible
    e2e_explore_steps: int | None = None  # explore.max_steps override (None: the preset's budget)
    e2e_explore_batch: int | None = 1  # explore.batch_size: 1 on CPU (one compile for every scene count)
    e2e_execute_episodes: int = 8  # episodes run through the closed loop (execute stage; 0 skips it)
    # sweep: grid points of sigma x eta (x lambda where navigation metrics exist)
    sweep_points: int = 100
    sweep_scenes: int = 2
    # closed loop, eval.engine=host vs device, on the paper preset's first loop_scenes scenes: both engines run
    # evaluate_navigation on the distinct episodes (evenly spaced over the scenes' episodes), then the loop alone
    # again on copies of its states; the device runs tile them to loop_episodes (bench_closed_loop)
    loop_scenes: int = 1
    loop_episodes: int = 16  # episodes of each timed device run
    loop_distinct: int | None = None  # distinct episodes (None: loop_episodes, at most the scenes' episodes)
    loop_repeats: int = 3  # timed device runs after the first (which compiles)
    loop_host_repeats: int = 1  # timed host runs after the first
    loop_batch: int | None = None  # eval.batch_size (None: the config's)
    loop_methods: tuple[str, ...] = ("oracle", "ragnav")
    loop_refills: tuple[float, ...] = ()  # eval.refill shares the device runs are also timed at (replays; a share
    # compiles once, timed apart; the config's is timed anyway)
    loop_lanes: tuple[int, ...] = ()  # eval.batch_size lanes the device runs are also timed at (replays: the same
    # episodes queued on fewer lanes; loop_batch is timed anyway)

    # online memory updates (memory/update.py) of one paper-preset scene's memory: episodes (copies) per batched
    # update, against rebuilding the scene's memory
    update_episodes: int = 64

    def replace(self, **kw) -> Profile:
        return dataclasses.replace(self, **kw)


QUICK = Profile(
    name="quick", repeats=3,
    retrieval_sizes=(80, 1000, 10000), retrieval_queries=(64, 64, 32),
    path_graphs=200, path_nx_sample=5,
    plan_episodes=1000, plan_python_bf=2, plan_python_hk=1,
    sim_batches=(1, 64), sim_steps=4, sim_c_steps=50,  # two compiles: keeps --quick under 2 minutes
    e2e_scenes=(1,), e2e_spacings=(0.8, 0.5), e2e_spacing_scenes=1, e2e_plan_episodes=2,
    e2e_explore_steps=400, e2e_execute_episodes=1,
    sweep_points=36, sweep_scenes=1,
    loop_scenes=1, loop_episodes=8, loop_repeats=2, loop_host_repeats=1,  # ~5 min on 2 cores, mostly compiling
)

# CPU: explore runs a shortened budget (1500 steps) so 1 + 4 + 14 + 64 scenes fit the suite's 10 minutes on
# 2 cores (9.5 minutes measured on an idle machine, 158 s of it for 64 scenes).
FULL = Profile(
    name="full", path_nx_sample=20, path_repeats=3, retrieval_queries=(256, 256, 64, 16), sim_batches=(1, 32, 1024),
    e2e_scenes=(1, 4, 14, 64), e2e_spacing_scenes=1, e2e_explore_steps=1500, e2e_execute_episodes=4,
    sweep_points=100, sweep_scenes=4,
    loop_scenes=4, loop_episodes=64, loop_repeats=3, loop_host_repeats=1,
)

GPU = Profile(
    name="gpu", repeats=5,
    retrieval_sizes=(80, 1000, 10000, 100000, 1_000_000),
    # 1M queries where a pass takes seconds; fewer at 100k and 1M nodes, where each query scores the
    # whole memory (throughput is per query either way; a 1M x 1M pass would take hours per repeat)
    retrieval_queries=(1_000_000, 1_000_000, 262_144, 32_768, 4096),
    retrieval_chunk=4096, faiss_queries=4096,
    # 4096 x 100k cells per block fit an 80 GB GPU (about 40 bytes a cell in the fused scoring); 1M nodes
    # then run in blocks of 409 queries (4096 at once asked for 168 GiB) and faiss times 409 queries
    retrieval_max_cells=4096 * 100_000,
    path_graphs=16384, path_nodes=(80, 200, 500), path_nx_sample=20, path_chunk=2048, path_repeats=3,
    path_max_cells=16384 * 200 * 200,  # n=500: 2621 graphs (16384 would need ~50 GB for inputs and outputs)
    plan_episodes=1_000_000, plan_python_bf=20, plan_python_hk=5,
    sim_batches=(1, 64, 1024, 4096, 8192, 16384), sim_steps=16, sim_c_steps=300,
    e2e_scenes=(1, 14, 64, 256, 1024), e2e_spacings=(0.8, 0.5, 0.3, 0.2), e2e_spacing_scenes=14,
    e2e_plan_episodes=32, e2e_embedder="minilm", e2e_explore_steps=None, e2e_explore_batch=256,
    e2e_execute_episodes=4096,
    sweep_points=1024, sweep_scenes=14,
    # 256 distinct episodes of the 14 x 60 (RAGNav's preamble costs about 0.3 s of host time per episode)
    # tiled to one device batch of 16384; the host engine runs the 256
    loop_scenes=14, loop_episodes=16384, loop_distinct=256, loop_repeats=3, loop_host_repeats=1, loop_batch=16384,
    loop_refills=(1.0,),  # every lane a reflection, next to the default eighth (README, The device loop)
)

PROFILES = {"quick": QUICK, "full": FULL, "gpu": GPU}


def _s(x: int, s: float, floor: int = 1) -> int:
    return max(floor, int(math.ceil(x * s)))


def scaled(p: Profile, s: float) -> Profile:
    """Every size times `s` (rounded up, at least 1 or the smallest meaningful value); s = 1 is `p`."""
    if s == 1.0:
        return p
    if s <= 0:
        raise ValueError("scale must be > 0")
    uniq = lambda xs: tuple(dict.fromkeys(xs))  # noqa: E731  scaled sizes may collide
    sizes = uniq(_s(n, s, 16) for n in p.retrieval_sizes)
    return p.replace(
        name=f"{p.name}@{s:g}", repeats=max(2, min(p.repeats, 3)) if s < 1 else p.repeats,
        retrieval_sizes=sizes, retrieval_queries=tuple(_s(q, s, 8) for q in p.retrieval_queries[: len(sizes)]),
        retrieval_chunk=None if p.retrieval_chunk is None else _s(p.retrieval_chunk, s, 4),
        faiss_queries=None if p.faiss_queries is None else _s(p.faiss_queries, s, 4),
        retrieval_max_cells=None if p.retrieval_max_cells is None else _s(p.retrieval_max_cells, s * s, 64),
        path_graphs=_s(p.path_graphs, s, 4), path_nodes=uniq(_s(n, s, 8) for n in p.path_nodes),
        path_nx_sample=_s(p.path_nx_sample, s, 2),
        path_chunk=None if p.path_chunk is None else _s(p.path_chunk, s, 2),
        plan_episodes=_s(p.plan_episodes, s, 8), plan_python_bf=_s(p.plan_python_bf, s, 1),
        plan_python_hk=_s(p.plan_python_hk, s, 1),
        sim_batches=uniq(_s(b, s, 1) for b in p.sim_batches), sim_steps=_s(p.sim_steps, s, 2),
        sim_c_steps=_s(p.sim_c_steps, s, 10),
        e2e_scenes=uniq(_s(n, s, 1) for n in p.e2e_scenes), e2e_spacings=p.e2e_spacings[:2] if s < 1 else p.e2e_spacings,
        e2e_spacing_scenes=_s(p.e2e_spacing_scenes, s, 1), e2e_plan_episodes=_s(p.e2e_plan_episodes, s, 1),
        e2e_embedder="hashing" if s < 1 else p.e2e_embedder,
        e2e_explore_steps=p.e2e_explore_steps if s >= 1 else max(200, int((p.e2e_explore_steps or 5000) * s)),
        e2e_explore_batch=None if p.e2e_explore_batch is None else _s(p.e2e_explore_batch, s, 1),
        e2e_execute_episodes=_s(p.e2e_execute_episodes, s, 1),
        sweep_points=_s(p.sweep_points, s, 8), sweep_scenes=_s(p.sweep_scenes, s, 1),
        loop_scenes=_s(p.loop_scenes, s, 1), loop_episodes=_s(p.loop_episodes, s, 2),
        loop_distinct=None if p.loop_distinct is None else _s(p.loop_distinct, s, 2),
        loop_batch=None if p.loop_batch is None else _s(p.loop_batch, s, 2),
    )
