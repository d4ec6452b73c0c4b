"""Hyperparameter sweeps: a grid of RetrievalParams (ablation variants included) scored in one compiled call.

    grid = make_grid(cfg.sweep, params_from_config(cfg.retrieval), cfg.planning.lam)   # P = V x K points
    metric = retrieval_metric(batch, meta, grid, mesh)      # chunk of params -> hits (V, C, G)
    sums, stats = evaluate_grid([metric], grid, chunk_size=100, store=ChunkStore(folder, fp))
    rows = sweep_rows(grid, [metric], sums)                  # one row per grid point and modality

The grid is the product of the configured axes (K combinations) for each ablation variant (V flags of
the one kernel). A chunk is every variant at C combinations, evaluated as a nested vmap (variants x
combinations x scenes x subgoals) in one jitted call; the vmaps map only the fields that vary, so
what does not depend on the swept axes is computed once per variant. Chunks have a fixed size (the
last is padded), so the function compiles once. Each finished chunk can be saved with orbax
(ChunkStore): a sweep that is killed and started again loads the finished chunks and computes only the
rest, and its table is bit-for-bit that of an uninterrupted run (the sums are integers).

More metrics plug in as GridMetrics: fn(params chunk, lam (C,)) -> per-modality sums (V, C, G) with
their denominators; the planning lambda axis (sweep.axes.lam) only reaches metrics with uses_lam=True.
Given the memory bank and scenes, run_sweep adds `plan_success` (evaluation/plan_metric.py: top-1
retrieval of every subgoal, then the exact visiting order under each point's lambda), so a sweep over
sigma x eta x lambda scores retrieval and order planning in the same compiled chunks.
"""

from __future__ import annotations

import dataclasses
import functools
import hashlib
import itertools
import json
import shutil
import time
from collections.abc import Callable, Sequence
from pathlib import Path

import jax
import numpy as np

from ragnav_jax.config import SweepAxes, SweepConfig
from ragnav_jax.errors import ConfigError, UserError
from ragnav_jax.evaluation import sharding
from ragnav_jax.io import save_figure, write_json
from ragnav_jax.retrieval.evaluate import BatchMeta, RetrievalBatch, correct_counts
from ragnav_jax.retrieval.params import ABLATIONS, RetrievalParams, ablation_params, stack_params

AXES = tuple(f.name for f in dataclasses.fields(SweepAxes))  # RetrievalParams fields, then lam
FIELDS = tuple(f.name for f in dataclasses.fields(RetrievalParams))


@dataclasses.dataclass(frozen=True)
class Grid:
    """P = V x K grid points: each of V ablation variants at each of K combinations of the varied axes.

    Point p is variant p // K at combination p % K. A chunk holds every variant and a run of combinations:
    the fields that differ between variants (the flags) carry a (V,) axis, the fields that differ
    between combinations a (C,) axis, and the rest are scalars, so the metric is a nested vmap whose
    inner level recomputes only what depends on the swept axes (a sigma x eta grid re-runs the spatial
    and boosting terms per point; instance similarities, forest pruning and top-K recall run once per
    variant).
    """

    axes: dict  # varied axis name -> tuple of values, in SweepAxes order
    variants: tuple[str, ...]
    points: tuple[dict, ...]  # (P,) {"variant": name, axis: value, ...}
    params: RetrievalParams  # (P,) leaves, every point in full
    lam: np.ndarray  # (P,) float32 planning lambda
    outer: tuple[str, ...]  # fields that differ between variants
    inner: tuple[str, ...]  # fields that differ between combinations (at least one field)

    @property
    def size(self) -> int:
        return len(self.points)

    @property
    def num_combos(self) -> int:
        return self.size // len(self.variants)

    def chunk(self, lo: int, hi: int, size: int) -> tuple[RetrievalParams, np.ndarray]:
        """Combinations [lo, hi) padded to `size` (last repeated), for every variant; lam (size,)."""
        K = self.num_combos

        def leaf(f):
            x = np.asarray(getattr(self.params, f))
            if f in self.outer:
                return x[::K]  # (V,)
            if f in self.inner:
                return sharding.pad_leading(x[lo:hi], size)  # (size,)
            return x[0]

        return RetrievalParams(**{f: leaf(f) for f in FIELDS}), sharding.pad_leading(self.lam[lo:hi], size)


def make_grid(sweep: SweepConfig, base: RetrievalParams, lam: float = 0.0) -> Grid:
    """The sweep's grid around `base` (the values of axes that are not varied) and planning lambda `lam`."""
    bad = [v for v in sweep.variants if v not in ABLATIONS]
    if bad:
        raise ConfigError(f"config key 'sweep.variants': unknown variant(s) {', '.join(bad)} "
                          f"(known: {', '.join(ABLATIONS)})")
    axes = {a: tuple(getattr(sweep.axes, a)) for a in AXES if getattr(sweep.axes, a)}
    points, plist, lams = [], [], []
    for variant in sweep.variants:
        vbase = ablation_params(base, variant)
        for combo in itertools.product(*axes.values()):
            point = dict(zip(axes, combo))
            fields = {k: v for k, v in point.items() if k != "lam"}
            p = vbase.replace(**{k: np.asarray(v, np.asarray(getattr(vbase, k)).dtype) for k, v in fields.items()})
            points.append({"variant": variant, **point})
            plist.append(p)
            lams.append(point.get("lam", lam))
    params = jax.tree.map(np.asarray, stack_params(plist))
    V, K = len(sweep.variants), len(points) // len(sweep.variants)
    view = {f: np.asarray(getattr(params, f)).reshape(V, K) for f in FIELDS}
    outer = tuple(f for f in FIELDS if V > 1 and np.unique(view[f][:, 0]).size > 1)
    inner = tuple(f for f in FIELDS if f not in outer and np.unique(view[f][0]).size > 1) or (FIELDS[0],)
    return Grid(axes, tuple(sweep.variants), tuple(points), params, np.asarray(lams, np.float32), outer, inner)


@dataclasses.dataclass(frozen=True)
class GridMetric:
    """A metric of a chunk of grid points computed in one batched call.

    fn(params, lam (C,), real) -> sums (V, C, G) over the modalities, params as Grid.chunk gives them (outer
    fields (V,), inner fields (C,)), the first `real` of the C combinations grid points and the rest padding
    (the last repeated); the table reports sums / totals.
    """

    name: str  # column of the table, e.g. "retrieval_accuracy"
    fn: Callable
    totals: np.ndarray  # (G,) denominators per modality (goals for retrieval, episodes for navigation)
    modalities: tuple[str, ...]
    fingerprint: str  # digest of the data the metric reads (checkpoints of another data set are refused)
    uses_lam: bool = False
    stats: dict = dataclasses.field(default_factory=dict)  # what computing it counted (reported in the summary)


def _digest(tree) -> str:
    h = hashlib.sha256()
    for x in jax.tree.leaves(tree):
        x = np.asarray(x)
        h.update(f"{x.dtype.str}{x.shape}".encode())
        h.update(np.ascontiguousarray(x).tobytes())
    return h.hexdigest()


def _in_axes(fields: tuple[str, ...]) -> RetrievalParams:
    return RetrievalParams(**{f: (0 if f in fields else None) for f in FIELDS})


@functools.cache
def _grid_correct(outer: tuple[str, ...], inner: tuple[str, ...]):
    f = jax.vmap(correct_counts, in_axes=(None, _in_axes(inner)))  # (C, G)
    if outer:
        f = jax.vmap(f, in_axes=(None, _in_axes(outer)))  # (V, C, G)
    else:
        f = (lambda g: lambda b, p: g(b, p)[None])(f)  # (1, C, G)
    return jax.jit(f)


def grid_correct(batch: RetrievalBatch, params: RetrievalParams, outer: tuple[str, ...],
                 inner: tuple[str, ...]) -> jax.Array:
    """Top-1 hits per modality (V, C, G) for a chunk of grid points in one compiled call.

    params: the `outer` fields (V,), the `inner` fields (C,), the rest scalars (Grid.chunk). A nested
    vmap: everything that does not depend on the inner fields is computed once per variant. One compile
    per (outer, inner) pair and chunk shape.
    """
    return _grid_correct(tuple(outer), tuple(inner))(batch, params)


def retrieval_metric(batch: RetrievalBatch, meta: BatchMeta, grid: Grid, mesh=None) -> GridMetric:
    """Retrieval accuracy (instance-level top-1, retrieval/evaluate.py's rule) as a GridMetric.

    With a mesh the batch is replicated on every device and each chunk's combinations are split over them.
    """
    fp = _digest(batch)
    if mesh is not None:
        batch = sharding.replicate(batch, mesh)
    return GridMetric("retrieval_accuracy", lambda params, lam, real: grid_correct(batch, params, grid.outer, grid.inner),
                      meta.totals, meta.modalities, fp)


class ChunkStore:
    """Finished chunks of one sweep as orbax checkpoints (step = chunk index) under `folder`.

    sweep.json beside them records the sweep's fingerprint (grid, chunking, data); a folder holding
    another sweep's chunks is refused unless fresh=True, which clears it.
    """

    def __init__(self, folder: str | Path, fingerprint: str, fresh: bool = False):
        import orbax.checkpoint as ocp

        self.folder = Path(folder).resolve()
        tag = self.folder / "sweep.json"
        if fresh and self.folder.exists():
            shutil.rmtree(self.folder)
        if tag.exists():
            try:
                old = json.loads(tag.read_text()).get("fingerprint")
            except (OSError, ValueError, AttributeError):  # unreadable, not text, not JSON, not an object
                old = None
            if old != fingerprint:
                raise UserError(f"{self.folder}: holds checkpoints of a different sweep (grid, chunk size, device count or data "
                                "changed); pass --fresh to discard them or choose another --out")
        self.folder.mkdir(parents=True, exist_ok=True)
        write_json(tag, {"fingerprint": fingerprint})
        self._ocp = ocp
        self.manager = ocp.CheckpointManager(
            self.folder / "chunks",
            options=ocp.CheckpointManagerOptions(max_to_keep=None, enable_async_checkpointing=False, create=True,
                                                 cleanup_tmp_directories=True),
        )

    def done(self) -> list[int]:
        return sorted(self.manager.all_steps())

    def load(self, i: int) -> dict[str, np.ndarray]:
        out = self.manager.restore(i, args=self._ocp.args.StandardRestore())
        return {k: np.asarray(v) for k, v in out.items()}

    def save(self, i: int, sums: dict[str, np.ndarray]) -> None:
        self.manager.save(i, args=self._ocp.args.StandardSave({k: np.asarray(v) for k, v in sums.items()}))
        self.manager.wait_until_finished()

    def close(self) -> None:
        self.manager.close()


def sweep_fingerprint(grid: Grid, metrics: Sequence[GridMetric], chunk: int) -> str:
    h = hashlib.sha256()
    h.update(_digest((grid.params, grid.lam)).encode())
    h.update(f"{chunk}|{[m.name for m in metrics]}|{[m.fingerprint for m in metrics]}".encode())
    return h.hexdigest()


def chunk_shape(grid: Grid, chunk_size: int, mesh=None) -> int:
    """Combinations per compiled call: chunk_size / variants (at least 1) on each device, at most all, rounded
    up to a multiple of the devices. Each device gets a one-device chunk's work whatever their number: a
    closed-loop call with fewer runs per device lasts about as long (its longest episode sets the time)."""
    n = mesh.size if mesh is not None else 1
    c = min(max(chunk_size // len(grid.variants), 1) * n, grid.num_combos)
    return -(-c // n) * n


def evaluate_grid(
    metrics: Sequence[GridMetric], grid: Grid, chunk_size: int, mesh=None, store: ChunkStore | None = None,
    pause_s: float = 0.0, progress: bool = False, log: Callable[[str], None] | None = None,
) -> tuple[dict[str, np.ndarray], dict]:
    """Every metric at every grid point, chunk by chunk; returns ({name: sums (P, G)}, stats).

    Chunks already in `store` are loaded, not recomputed; each computed chunk is saved before the next.
    Timing is host-side, around the calls (the first computed chunk includes compilation).
    """
    C = chunk_shape(grid, chunk_size, mesh)
    K = grid.num_combos
    n_chunks = -(-K // C)
    done = set(store.done()) if store is not None else set()
    done &= set(range(n_chunks))
    if done and log:
        log(f"resuming: {len(done)} of {n_chunks} chunks already done in {store.folder}")
    parts: dict[int, dict[str, np.ndarray]] = {}
    times = []
    it = range(n_chunks)
    if progress:
        from tqdm.auto import tqdm

        it = tqdm(it, desc="sweep", unit="chunk")
    for i in it:
        if i in done:
            parts[i] = store.load(i)
            continue
        lo, hi = i * C, min((i + 1) * C, K)
        params, lam = grid.chunk(lo, hi, C)  # fixed chunk shape: one compile
        if mesh is not None:
            params = RetrievalParams(**{
                f: sharding.shard_leading(x, mesh) if f in grid.inner else sharding.replicate(x, mesh)
                for f, x in ((f, getattr(params, f)) for f in FIELDS)})
            lam = sharding.shard_leading(lam, mesh)
        t0 = time.perf_counter()
        out = {m.name: m.fn(params, lam, hi - lo) for m in metrics}
        out = {k: sharding.to_host(v)[:, : hi - lo] for k, v in out.items()}  # (V, c, G)
        times.append(time.perf_counter() - t0)
        parts[i] = out
        if store is not None:
            store.save(i, out)
        if pause_s:
            time.sleep(pause_s)
    sums = {}
    for m in metrics:
        full = np.concatenate([parts[i][m.name] for i in range(n_chunks)], axis=1)  # (V, K, G)
        sums[m.name] = full.reshape(grid.size, *full.shape[2:])
    stats = {
        "grid_points": grid.size, "combos_per_chunk": C, "points_per_chunk": C * len(grid.variants),
        "chunks": n_chunks, "chunks_resumed": len(done), "chunks_computed": len(times),
        "first_chunk_s": round(times[0], 4) if times else None,
        "later_chunks_s": round(float(np.median(times[1:])), 4) if len(times) > 1 else None,
        "devices": mesh.size if mesh is not None else 1,
    }
    return sums, stats


def sweep_rows(grid: Grid, metrics: Sequence[GridMetric], sums: dict[str, np.ndarray]) -> list[dict]:
    """The tidy table: one row per grid point and modality (plus "all"), each metric as sum / total."""
    mods = metrics[0].modalities
    rows = []
    for p, point in enumerate(grid.points):
        for g, mod in enumerate((*mods, "all")):
            row = {"point": p, **point, "modality": mod}
            for m in metrics:
                num = sums[m.name][p].sum() if mod == "all" else sums[m.name][p, g]
                den = m.totals.sum() if mod == "all" else m.totals[g]
                row[m.name] = round(float(num) / float(den), 6) if den else 0.0
                row[f"{m.name}_n"] = int(den)
            rows.append(row)
    return rows


def best_points(rows: list[dict], metric: str = "retrieval_accuracy") -> dict[str, dict]:
    """Per variant, the grid point with the best metric over all modalities (first on ties)."""
    best: dict[str, dict] = {}
    for r in rows:
        if r["modality"] == "all" and (r["variant"] not in best or r[metric] > best[r["variant"]][metric]):
            best[r["variant"]] = r
    return best


def plot_heatmaps(rows: list[dict], axes: tuple[str, str], folder: str | Path,
                  metric: str = "retrieval_accuracy") -> list[Path]:
    """One PNG per variant: `metric` over axes (x, y), a panel per modality; other axes at their best value."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import pandas as pd

    df = pd.DataFrame(rows)
    x, y = axes
    if x not in df or y not in df:
        return []
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    out = []
    mods = list(dict.fromkeys(df["modality"]))
    for variant, dv in df.groupby("variant", sort=False):
        fig, axs = plt.subplots(1, len(mods), figsize=(4.2 * len(mods), 3.6), squeeze=False, layout="constrained")
        for ax, mod in zip(axs[0], mods):
            piv = dv[dv["modality"] == mod].pivot_table(index=y, columns=x, values=metric, aggfunc="max")
            im = ax.imshow(piv.values, origin="lower", cmap="viridis", aspect="auto")
            fig.colorbar(im, ax=ax, shrink=0.85)
            ax.set_xticks(range(len(piv.columns)), [f"{v:g}" for v in piv.columns], rotation=90, fontsize=7)
            ax.set_yticks(range(len(piv.index)), [f"{v:g}" for v in piv.index], fontsize=7)
            ax.set_xlabel(x)
            ax.set_ylabel(y)
            ax.set_title(mod, fontsize=9)
            for (i, j), v in np.ndenumerate(piv.values):
                if piv.size <= 100:
                    ax.text(j, i, f"{100 * v:.1f}", ha="center", va="center", fontsize=5, color="w")
        fig.suptitle(f"{variant}: {metric} (%) over {x} x {y}" + (" (best over the other axes)" if len(
            [c for c in df.columns if c in AXES]) > 2 else ""), fontsize=10)
        tag = "" if metric == "retrieval_accuracy" else f"{metric}_"
        path = folder / f"{variant}_{tag}{x}_{y}.png"
        save_figure(fig, path, dpi=110)
        plt.close(fig)
        out.append(path)
    return out


def sweep_mesh(cfg):
    """The mesh a sweep splits its chunks over (sweep.shard and several devices), or None."""
    return sharding.batch_mesh() if cfg.sweep.shard and jax.device_count() > 1 else None


def run_sweep(cfg, batch: RetrievalBatch, meta: BatchMeta, out: str | Path | None = None, fresh: bool = False,
              progress: bool = False, log: Callable[[str], None] | None = None,
              extra_metrics: Sequence[GridMetric] = (), bank=None, scenes=None) -> tuple[list[dict], dict]:
    """The configured sweep over one retrieval batch; with `out`, checkpoints, table, heatmaps and summary.

    extra_metrics: more GridMetrics evaluated in the same chunks. bank, scenes: the batch's memory bank
    and scenes; with them a sweep whose axes include lam also reports `plan_success` (plan_metric.py).
    Returns (rows, summary).
    """
    from ragnav_jax.retrieval.params import params_from_config

    grid = make_grid(cfg.sweep, params_from_config(cfg.retrieval), cfg.planning.lam)
    if batch is None:
        raise UserError("no instruction of the episodes file yields a subgoal: nothing to sweep")
    extra = list(extra_metrics)
    if "lam" in grid.axes and not any(m.uses_lam for m in extra):
        if bank is None or scenes is None:
            raise UserError("sweep.axes.lam: the planning lambda changes plan success only, which needs the "
                            "memory bank and scenes (ragnav sweep passes them); retrieval accuracy does not "
                            "depend on it")
        from ragnav_jax.evaluation.plan_metric import plan_metric

        extra.append(plan_metric(batch, meta, bank, scenes, grid))
    mesh = sweep_mesh(cfg)
    metrics = [retrieval_metric(batch, meta, grid, mesh), *extra]
    store = None
    if out is not None and cfg.sweep.checkpoint:
        C = chunk_shape(grid, cfg.sweep.chunk_size, mesh)
        store = ChunkStore(Path(out) / "checkpoints", sweep_fingerprint(grid, metrics, C), fresh=fresh)
    t0 = time.perf_counter()
    try:
        sums, stats = evaluate_grid(metrics, grid, cfg.sweep.chunk_size, mesh, store, cfg.sweep.pause_s, progress,
                                    log)
    finally:
        if store is not None:
            store.close()
    stats["wall_s"] = round(time.perf_counter() - t0, 3)
    peaks = [(d.memory_stats() or {}).get("peak_bytes_in_use") for d in jax.local_devices()]
    if all(p is not None for p in peaks):  # accelerators report their memory; the CPU does not
        stats["device_peak_memory_mb"] = [round(p / 2**20, 1) for p in peaks]
    rows = sweep_rows(grid, metrics, sums)
    names = [m.name for m in metrics]
    summary = {
        "axes": {k: list(v) for k, v in grid.axes.items()}, "variants": list(grid.variants),
        "modalities": list(meta.modalities), "queries": int(meta.totals.sum()), "metrics": names,
        "best": {v: {k: r[k] for k in ("point", *grid.axes, *names)} for v, r in best_points(rows).items()},
        **stats,
        **{k: v for m in metrics for k, v in m.stats.items()},
    }
    if "nav_success" in names:
        summary["best_nav"] = {v: {k: r[k] for k in ("point", *grid.axes, *names)}
                               for v, r in best_points(rows, "nav_success").items()}
    if "plan_success" in names:
        summary["best_plan"] = {v: {k: r[k] for k in ("point", *grid.axes, *names)}
                                for v, r in best_points(rows, "plan_success").items()}
    if out is not None:
        from ragnav_jax.tables import write_table

        out = Path(out)
        write_table(rows, out / "sweep")
        summary["heatmaps"] = [str(p) for name in names
                               for p in plot_heatmaps(rows, cfg.sweep.heatmap, out / "heatmaps", name)]
        write_json(out / "summary.json", summary)
    return rows, summary
