"""Gradient tuning of the continuous retrieval hyperparameters with optax, through a differentiable surrogate.

    train, test = split_episodes(episodes, 0.5, seed=0)
    result = tune(train_batch, base_params, cfg.tune)          # optax Adam on the surrogate loss
    save_tuned(result.params, result.temperature, folder)     # orbax; load_tuned(folder) -> RetrievalParams

Surrogate: for each subgoal, a softmax over the node scores of retrieval/evaluate.py's node_scores (the
same kernel evaluation and sweeps run, so the two cannot drift) at temperature T, and the cross-entropy
to the ground-truth node set (every node that observes the goal instance):
    loss = mean over subgoals of  logsumexp_n(s_n / T) - logsumexp_{n observes the goal}(s_n / T).
Gradients flow through the continuous terms (sigma, eta, sigma_loc, w_slot, w_loc, w_sensor) as they
are; the anchor and boost thresholds get straight-through gradients of sigmoid gates (kernels.gate,
softness tune.gate_tau), so the scores in the loss are exactly the hard kernel's. Hard choices that
remain (top-K recall, best instance, forest beam) pass gradients to the selected entries only; the
integer fields (top_k, hops, beam) and match_threshold are left to the grid.
Parameters move in an unconstrained space: log for widths and exponents, logit for w_slot, raw for
thresholds; T is learned too (log). The returned point is the iterate with the best training accuracy
(the starting point included), checked every tune.eval_every steps; the loss curve is returned whole.
"""

from __future__ import annotations

import dataclasses
import zlib
from collections import defaultdict
from collections.abc import Sequence
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np
import optax

from ragnav_jax.config import RetrievalConfig, hyperparameters
from ragnav_jax.io import save_figure
from ragnav_jax.language.episodes import Episode
from ragnav_jax.retrieval.evaluate import RetrievalBatch, correct_counts, node_scores
from ragnav_jax.retrieval.kernels import NEG
from ragnav_jax.retrieval.params import RetrievalParams

# How each tunable field moves (config.RetrievalConfig's table, `tune=`); the rest of TUNABLE move raw.
POSITIVE = tuple(name for name, h in hyperparameters(RetrievalConfig).items() if h.tune == "log")  # as log(x)
UNIT = tuple(name for name, h in hyperparameters(RetrievalConfig).items() if h.tune == "logit")  # as logit(x)
EPS = 1e-4  # keeps log/logit finite for parameters that start at their bounds (eta = 0, w_slot = 1)


def split_episodes(episodes: Sequence[Episode], train_fraction: float, seed: int) -> tuple[list, list]:
    """Training and held-out episodes: within each (scene, modality), a seeded hash order, first share trains."""
    groups = defaultdict(list)
    for ep in episodes:
        groups[(ep.scene, ep.modality)].append(ep)
    train, test = [], []
    for eps in groups.values():
        eps = sorted(eps, key=lambda e: zlib.crc32(f"{seed}:{e.id}".encode()))
        n = int(round(train_fraction * len(eps)))
        if len(eps) >= 2:
            n = min(max(n, 1), len(eps) - 1)
        train += eps[:n]
        test += eps[n:]
    order = {e.id: k for k, e in enumerate(episodes)}
    return sorted(train, key=lambda e: order[e.id]), sorted(test, key=lambda e: order[e.id])


def to_free(p: RetrievalParams, names: Sequence[str]) -> dict[str, jax.Array]:
    """The tuned fields of p in the unconstrained space."""
    out = {}
    for n in names:
        x = jnp.asarray(getattr(p, n), jnp.float32)
        if n in POSITIVE:
            out[n] = jnp.log(jnp.maximum(x, EPS))
        elif n in UNIT:
            x = jnp.clip(x, EPS, 1 - EPS)
            out[n] = jnp.log(x) - jnp.log1p(-x)
        else:
            out[n] = x
    return out


def from_free(free: dict[str, jax.Array], base: RetrievalParams) -> RetrievalParams:
    """base with the tuned fields mapped back from the unconstrained space."""
    vals = {}
    for n, z in free.items():
        vals[n] = jnp.exp(z) if n in POSITIVE else jax.nn.sigmoid(z) if n in UNIT else z
    return base.replace(**vals)


def surrogate_loss(free: dict, log_temp: jax.Array, batch: RetrievalBatch, base: RetrievalParams,
                   gate_tau: jax.Array) -> jax.Array:
    """Mean cross-entropy of the node softmax to the ground-truth node set, over learnable subgoals.

    A subgoal is learnable when some node observing its goal has a score (not masked or pruned).
    """
    s = node_scores(batch.index, batch.queries, from_free(free, base), gate_tau)  # (B, Q, N)
    valid = s > NEG / 2
    logits = jnp.where(valid, s / jnp.exp(log_temp), -1e30)
    pos = batch.truth & valid
    lse_all = jax.nn.logsumexp(logits, axis=-1)
    lse_pos = jax.nn.logsumexp(jnp.where(pos, logits, -1e30), axis=-1)
    learn = batch.qmask & jnp.any(pos, axis=-1)
    return jnp.sum(jnp.where(learn, lse_all - lse_pos, 0.0)) / jnp.maximum(jnp.sum(learn), 1)


@dataclasses.dataclass(frozen=True)
class TuneResult:
    params: RetrievalParams  # the iterate with the best training accuracy
    temperature: float
    losses: np.ndarray  # (S + 1,) loss before each step and after the last (S: steps rounded up to eval_every)
    train_hits: list  # [(step, hits (G,))] at every check, step 0 = the starting point
    best_step: int


def tune(batch: RetrievalBatch, base: RetrievalParams, names: Sequence[str], steps: int, learning_rate: float,
         eval_every: int, temperature: float, gate_tau: float, progress: bool = False) -> TuneResult:
    """Adam on surrogate_loss from `base`; the loop over segments is host-side, each segment one jitted scan."""
    opt = optax.adam(learning_rate)
    state0 = (to_free(base, names), jnp.log(jnp.float32(temperature)))
    tau = jnp.float32(gate_tau)
    # The batch and base are arguments of the jitted functions, never closed over: as constants they
    # would be folded into the program (slow compiles on large batches).

    def loss_fn(st, b, p0):
        return surrogate_loss(st[0], st[1], b, p0, tau)

    grad_fn = jax.value_and_grad(loss_fn)

    @jax.jit
    def segment(st, os, b, p0):
        def step(carry, _):
            st, os = carry
            loss, g = grad_fn(st, b, p0)
            upd, os = opt.update(g, os)
            return (optax.apply_updates(st, upd), os), loss

        return jax.lax.scan(step, (st, os), None, length=eval_every)

    hits_fn = jax.jit(lambda st, b, p0: correct_counts(b, from_free(st[0], p0)))
    st, os = state0, opt.init(state0)
    losses, checks = [], [(0, np.asarray(hits_fn(st, batch, base)))]
    best = (int(checks[0][1].sum()), 0, st)
    done = 0
    it = range(-(-steps // eval_every))
    if progress:
        from tqdm.auto import tqdm

        it = tqdm(it, desc="tune", unit="segment")
    for _ in it:
        (st, os), ls = segment(st, os, batch, base)
        done += eval_every
        losses.extend(np.asarray(ls).tolist())
        h = np.asarray(hits_fn(st, batch, base))
        checks.append((done, h))
        if int(h.sum()) > best[0]:
            best = (int(h.sum()), done, st)
    losses.append(float(jax.jit(loss_fn)(st, batch, base)))
    _, best_step, best_st = best
    params = jax.tree.map(lambda x: jnp.asarray(x), from_free(best_st[0], base))
    return TuneResult(params, float(jnp.exp(best_st[1])), np.asarray(losses), checks, best_step)


def params_dict(p: RetrievalParams) -> dict:
    """Plain Python values of every field (ints for the integer fields)."""
    from ragnav_jax.retrieval.params import INT_FIELDS

    return {f.name: (int if f.name in INT_FIELDS else float)(np.asarray(getattr(p, f.name)))
            for f in dataclasses.fields(p)}


def save_tuned(p: RetrievalParams, temperature: float, folder: str | Path) -> Path:
    """Writes the tuned parameters (and the surrogate's temperature) as an orbax checkpoint folder."""
    import shutil

    import orbax.checkpoint as ocp

    folder = Path(folder).resolve()
    if folder.exists():
        shutil.rmtree(folder)
    tree = {k: np.asarray(v) for k, v in params_dict(p).items()} | {"temperature": np.float32(temperature)}
    ck = ocp.StandardCheckpointer()
    ck.save(folder, tree)
    ck.wait_until_finished()
    return folder


def load_tuned(folder: str | Path) -> tuple[RetrievalParams, float]:
    """(RetrievalParams, temperature) from save_tuned's folder."""
    import orbax.checkpoint as ocp

    tree = ocp.StandardCheckpointer().restore(Path(folder).resolve())
    temp = float(tree.pop("temperature"))
    known = {f.name for f in dataclasses.fields(RetrievalParams)}
    return RetrievalParams.create(**{k: np.asarray(v).item() for k, v in tree.items() if k in known}), temp


def tuned_config(cfg, p: RetrievalParams):
    """cfg with its retrieval section set to p's values (fields the section has)."""
    vals = params_dict(p)
    sect = cfg.retrieval
    return dataclasses.replace(cfg, retrieval=dataclasses.replace(
        sect, **{k: v for k, v in vals.items() if hasattr(sect, k)}))


def _accuracy(hits: np.ndarray, totals: np.ndarray, modalities: Sequence[str]) -> dict[str, float]:
    out = {m: float(hits[g]) / max(int(totals[g]), 1) for g, m in enumerate(modalities)}
    out["all"] = float(hits.sum()) / max(int(totals.sum()), 1)
    return out


def held_out_success(cfg, bank, scenes, episodes, embedder, candidates: dict, executor=None,
                     verifier=None) -> dict[str, float]:
    """RAGNav's closed-loop success on `episodes` with each candidate's retrieval values ({name: RetrievalParams}),
    on the device engine. One executor and verifier serve every candidate: retrieval values change the host's
    candidates, not the compiled loop."""
    from ragnav_jax.evaluation.execute import make_executor
    from ragnav_jax.evaluation.navigate import evaluate_navigation
    from ragnav_jax.evaluation.verify import Verifier

    cfg = dataclasses.replace(cfg, eval=dataclasses.replace(cfg.eval, engine="device"))
    used = {e.scene for e in episodes}
    executor = executor or make_executor([s for s in scenes if s.name in used], cfg)
    verifier = verifier or Verifier.build(embedder, cfg)
    out = {}
    for name, p in candidates.items():
        rows, _ = evaluate_navigation(bank, scenes, episodes, embedder, tuned_config(cfg, p), "ragnav",
                                      executor=executor, verifier=verifier)
        out[name] = float(np.mean([r["success"] for r in rows])) if rows else 0.0
    return out


def run_tune(cfg, bank, scenes, episodes, embedder, out: str | Path | None = None, progress: bool = False,
             executor=None, verifier=None):
    """Split, grid on the training split, tune from the best grid point, compare on the held-out split (retrieval
    accuracy; with tune.closed_loop also RAGNav's closed-loop success, `held_out_success`).

    With `out`: the orbax folder out/tuned, the tables out/tune.{csv,md} (and out/tune_closed_loop.{csv,md}) and
    the loss curve out/loss.png. Returns (summary dict, config with the tuned retrieval section).
    """
    import time

    from ragnav_jax.errors import UserError
    from ragnav_jax.evaluation.sweep import evaluate_grid, make_grid, retrieval_metric
    from ragnav_jax.retrieval.evaluate import prepare_batch
    from ragnav_jax.retrieval.index import build_bank_index
    from ragnav_jax.retrieval.params import params_from_config

    tc = cfg.tune
    train_eps, test_eps = split_episodes(episodes, tc.train_fraction, tc.split_seed)
    if not train_eps or not test_eps:
        raise UserError("tuning needs episodes in both splits (at least two per scene and modality)")
    index = build_bank_index(bank, scenes, embedder)
    mods = sorted({e.modality for e in episodes})
    train, tmeta = prepare_batch(bank, scenes, train_eps, embedder, index, mods)
    test, smeta = prepare_batch(bank, scenes, test_eps, embedder, index, mods)
    if train is None or test is None:
        raise UserError("no instruction of a split yields a subgoal: nothing to tune")
    base = params_from_config(cfg.retrieval)
    sweep = dataclasses.replace(cfg.sweep, variants=("ragnav",), axes=dataclasses.replace(cfg.sweep.axes, lam=()))
    grid = make_grid(sweep, base)
    g_train, _ = evaluate_grid([retrieval_metric(train, tmeta, grid)], grid, sweep.chunk_size)
    g_test, _ = evaluate_grid([retrieval_metric(test, smeta, grid)], grid, sweep.chunk_size)
    g_train, g_test = g_train["retrieval_accuracy"], g_test["retrieval_accuracy"]
    best = int(np.argmax(g_train.sum(1)))  # first on ties
    grid_best = jax.tree.map(lambda x: jnp.asarray(x[best]), grid.params)
    init = grid_best if tc.init == "grid" else base
    t0 = time.perf_counter()
    res = tune(train, init, tc.params, tc.steps, tc.learning_rate, tc.eval_every, tc.temperature, tc.gate_tau,
               progress)
    tune_s = time.perf_counter() - t0
    hits = jax.jit(correct_counts)
    acc = {
        "config": (np.asarray(hits(train, base)), np.asarray(hits(test, base))),
        "grid_best": (g_train[best], g_test[best]),
        "tuned": (np.asarray(hits(train, res.params)), np.asarray(hits(test, res.params))),
    }
    rows = []
    for method, (htr, hte) in acc.items():
        for split, h, meta in (("train", htr, tmeta), ("held_out", hte, smeta)):
            for m, a in _accuracy(h, meta.totals, mods).items():
                rows.append({"method": method, "split": split, "modality": m, "accuracy": round(a, 4),
                             "queries": int(meta.totals.sum() if m == "all" else meta.totals[mods.index(m)])})
    summary = {
        "train_episodes": len(train_eps), "held_out_episodes": len(test_eps),
        "train_queries": int(tmeta.totals.sum()), "held_out_queries": int(smeta.totals.sum()),
        "grid_points": grid.size, "grid_best_point": {**grid.points[best]},
        "grid_best_held_out_oracle": float(g_test.sum(1).max()) / max(int(smeta.totals.sum()), 1),
        "init": tc.init, "tuned_params": params_dict(res.params), "temperature": res.temperature,
        "loss_first": float(res.losses[0]), "loss_last": float(res.losses[-1]), "best_step": res.best_step,
        "steps": len(res.losses) - 1, "tune_s": round(tune_s, 2),
        "train": {k: _accuracy(v[0], tmeta.totals, mods)["all"] for k, v in acc.items()},
        "held_out": {k: _accuracy(v[1], smeta.totals, mods)["all"] for k, v in acc.items()},
    }
    if tc.closed_loop:
        nav = held_out_success(cfg, bank, scenes, test_eps, embedder,
                               {"config": base, "grid_best": grid_best, "tuned": res.params}, executor, verifier)
        summary["held_out_success"] = nav
    if out is not None:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        from ragnav_jax.tables import write_table

        out = Path(out)
        write_table(rows, out / "tune")
        if "held_out_success" in summary:
            write_table([{"method": k, "split": "held_out", "episodes": len(test_eps), "closed_loop_success": round(v, 4)}
                         for k, v in summary["held_out_success"].items()], out / "tune_closed_loop")
        save_tuned(res.params, res.temperature, out / "tuned")
        fig, ax = plt.subplots(figsize=(5, 3))
        ax.plot(res.losses)
        ax.axvline(res.best_step, ls="--", c="gray", label="returned iterate (best train accuracy)")
        ax.set_xlabel("step")
        ax.set_ylabel("surrogate loss (train)")
        ax.legend(fontsize=7)
        fig.tight_layout()
        save_figure(fig, out / "loss.png", dpi=110)
        plt.close(fig)
    return summary, tuned_config(cfg, res.params)
