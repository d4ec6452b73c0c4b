"""CLI subcommands of the evaluation stage: sweep (hyperparameter grids), tune (gradient tuning),
fit-verifier (the reflection's thresholds, fitted on the seen split) and show-episode (a video of one
episode of an eval run, replayed with the recorder on)."""

from __future__ import annotations

import argparse
from pathlib import Path

from ragnav_jax.errors import UserError
from ragnav_jax.io import write_json, write_text


def load_retrieval_inputs(run: str | Path, episodes_file: str | Path, cfg):
    """(bank, scenes, episodes, embedder) of a run folder with scenes/ and memory/bank."""
    from ragnav_jax.language.episodes import load_episodes
    from ragnav_jax.memory.checkpoint import load_bank
    from ragnav_jax.memory.commands import bank_dir
    from ragnav_jax.memory.encoder import bank_embedder
    from ragnav_jax.world.scene import load_scene_set

    run = Path(run)
    if not (run / "scenes").is_dir():
        raise UserError(f"{run}: no scenes/ folder (run generate, explore and build-memory first)")
    scenes = load_scene_set(run / "scenes")
    bank = load_bank(bank_dir(run), scenes)
    episodes = load_episodes(episodes_file, scenes)
    return bank, scenes, episodes, bank_embedder(bank, cfg)


def cmd_sweep(args, cfg) -> int:
    from ragnav_jax.evaluation.sweep import run_sweep
    from ragnav_jax.retrieval.commands import check_unparsed
    from ragnav_jax.retrieval.evaluate import prepare_batch
    from ragnav_jax.runs import init_run

    bank, scenes, episodes, embedder = load_retrieval_inputs(args.run, args.episodes, cfg)
    if args.stride > 1:
        episodes = episodes[:: args.stride]
    unparsed = check_unparsed(episodes, args.allow_unparsed, args.episodes)
    out = Path(args.out)
    init_run(out, cfg, "sweep")
    batch, meta = prepare_batch(bank, scenes, episodes, embedder)
    extra = []
    if args.closed_loop:  # success, SPL, progress and travel of RAGNav's closed loop at every grid point
        from ragnav_jax.evaluation.loop.sweep_metric import closed_loop_metrics
        from ragnav_jax.evaluation.sweep import make_grid
        from ragnav_jax.retrieval.params import params_from_config

        grid = make_grid(cfg.sweep, params_from_config(cfg.retrieval), cfg.planning.lam)
        extra = closed_loop_metrics(cfg, bank, scenes, episodes, embedder, grid, meta.modalities)
    rows, summary = run_sweep(cfg, batch, meta, out, fresh=args.fresh, progress=not args.quiet,
                              log=lambda m: print(m, flush=True), bank=bank, scenes=scenes, extra_metrics=extra)
    summary.update({"run": str(args.run), "episodes_file": str(args.episodes), "unparsed": unparsed,
                    "stride": args.stride, "closed_loop": bool(args.closed_loop)})
    write_json(out / "summary.json", summary)
    for key in ("best", "best_plan", "best_nav"):
        for v, b in summary.get(key, {}).items():
            print(f"{key} {v}: " + ", ".join(f"{k}={b[k]}" for k in b))
    print(f"{summary['grid_points']} grid points x {len(summary['modalities']) + 1} modalities -> {out / 'sweep.csv'}"
          f" ({summary['chunks_computed']} chunks computed, {summary['chunks_resumed']} resumed, "
          f"{summary['wall_s']} s); heatmaps in {out / 'heatmaps'}")
    return 0


def cmd_tune(args, cfg) -> int:
    from ragnav_jax.config import dump_yaml
    from ragnav_jax.evaluation.tune import run_tune
    from ragnav_jax.retrieval.commands import check_unparsed
    from ragnav_jax.runs import init_run, refuse_overwrite

    out = Path(args.out)
    refuse_overwrite([out / "summary.json", out / "tuned.yaml", out / "tune.md"], args.force)
    bank, scenes, episodes, embedder = load_retrieval_inputs(args.run, args.episodes, cfg)
    unparsed = check_unparsed(episodes, args.allow_unparsed, args.episodes)
    init_run(out, cfg, "tune")
    summary, tuned_cfg = run_tune(cfg, bank, scenes, episodes, embedder, out, progress=not args.quiet)
    write_text(out / "tuned.yaml", "# ragnav tune: the input config with the tuned retrieval section "
                                   "(use with --config)\n" + dump_yaml(tuned_cfg))
    summary.update({"run": str(args.run), "episodes_file": str(args.episodes), "tuned_config": str(out / "tuned.yaml"),
                    "unparsed": unparsed})
    write_json(out / "summary.json", summary)
    print((out / "tune.md").read_text())
    h = summary["held_out"]
    print(f"held-out accuracy: tuned {h['tuned']:.4f} vs best grid point {h['grid_best']:.4f} "
          f"(config {h['config']:.4f}); tuned values in {out / 'tuned.yaml'} and {out / 'tuned'} (orbax)")
    if "held_out_success" in summary:
        n = summary["held_out_success"]
        print(f"held-out closed-loop success (RAGNav, {summary['held_out_episodes']} episodes): tuned {n['tuned']:.4f} "
              f"vs best grid point {n['grid_best']:.4f} (config {n['config']:.4f})")
    return 0


def cmd_fit_verifier(args, cfg) -> int:
    from ragnav_jax.evaluation.fitting import FIT_SCENES, fit_verifier, write_fitted
    from ragnav_jax.memory.encoder import make_embedder
    from ragnav_jax.runs import init_run, refuse_overwrite

    out = Path(args.out)
    refuse_overwrite([out / "fitted.json"], args.force)
    init_run(out, cfg, "fit-verifier")
    embedder = make_embedder(cfg.memory.embedder, dim=cfg.memory.hashing_dim, batch_size=cfg.memory.embed_batch,
                             buckets=cfg.memory.token_buckets)
    entry = fit_verifier(cfg, embedder, scenes=args.scenes or FIT_SCENES, seed=args.seed)
    path = write_fitted(entry, cfg.memory.embedder, out / "fitted.json")
    p, acc = entry["params"], entry["balanced_accuracy"]
    print(", ".join(f"{k}={v}" for k, v in p.items()) + " (balanced accuracy on the seen training houses: "
          + ", ".join(f"{k} {v}" for k, v in acc.items()) + f") -> {path}; use with eval.verifier_file={path}")
    return 0


def cmd_show_episode(args, cfg) -> int:
    import sys

    from ragnav_jax.evaluation.replay import load_eval_run, outcome_differences, replay_episode
    from ragnav_jax.evaluation.video import SUFFIXES, ffmpeg_exe, save_episode_video

    out = Path(args.out)
    if args.config:
        raise UserError("show-episode replays with the run's own config (RUN/config.yaml); drop --config")
    if out.suffix.lower() not in SUFFIXES:
        raise UserError(f"--out {out}: use a .gif or .mp4 file name")
    if out.exists() and not args.force:
        raise UserError(f"--out {out}: exists (use --force to overwrite)")
    if out.suffix.lower() == ".mp4" and ffmpeg_exe() is None:
        raise UserError("MP4 needs the imageio-ffmpeg package (pip install imageio-ffmpeg); or write a .gif")
    if args.fps < 1 or args.max_frames < 2:
        raise UserError("--fps must be >= 1 and --max-frames >= 2")
    ev = load_eval_run(args.run, args.method)
    row = replay_episode(ev, args.episode)
    if not row.get("legs"):
        raise UserError(f"episode {args.episode} drove no leg ({row['reason']}): nothing to animate")
    diff = outcome_differences(ev.rows[args.episode], row)
    if diff:  # another machine or JAX version can drive a step differently; the video shows the replay
        print(f"ragnav: warning: the replay of {args.episode} differs from {args.run}'s row in {', '.join(diff)}",
              file=sys.stderr)
    ep = next(e for e in ev.episodes if e.id == args.episode)
    scene = next(s for s in ev.scenes if s.name == ep.scene)
    n = save_episode_video(scene, row, out, fps=args.fps, max_frames=args.max_frames, instruction=ep.instruction)
    print(f"{args.episode} ({args.method}: {row['reason']}, {'replay matches the run' if not diff else 'replay differs'})"
          f": {n} frames -> {out}")
    return 0


def register(sub: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    from ragnav_jax.argtypes import int_at_least, nonneg_int, positive_int
    from ragnav_jax.retrieval.commands import add_batch_flags

    p = sub.add_parser("show-episode", parents=[common],
                       help="video of one episode of an eval run (replayed): trajectory, candidates, camera, FOUND")
    p.add_argument("run", metavar="RUN", help="the eval's --out folder")
    p.add_argument("--method", default="ragnav", help="evaluated method (default ragnav)")
    p.add_argument("--episode", required=True, help="episode id (RUN/eval/<method>/episodes.jsonl)")
    p.add_argument("--out", required=True, help="video file (.gif or .mp4)")
    p.add_argument("--force", action="store_true", help="overwrite --out")
    p.add_argument("--fps", type=positive_int, default=8, help="frames per second (default 8)")
    p.add_argument("--max-frames", type=int_at_least(2), default=160, help="frames at most (default 160)")
    p.set_defaults(func=cmd_show_episode, overrides_allowed=False)
    p = sub.add_parser("fit-verifier", parents=[common],
                       help="fit the reflection's verifier thresholds on seen-split houses (writes OUT/fitted.json)")
    p.add_argument("--out", required=True, help="output folder")
    p.add_argument("--scenes", type=positive_int, help="seen-split training houses (default: fitting.FIT_SCENES, 24)")
    p.add_argument("--seed", type=nonneg_int, default=12345, help="seed of the training houses (not the evaluation's)")
    p.add_argument("--force", action="store_true", help="overwrite an earlier OUT/fitted.json")
    p.set_defaults(func=cmd_fit_verifier)
    for name, func, text in (
        ("sweep", cmd_sweep, "retrieval accuracy over a hyperparameter grid (sweep section), one compiled call per chunk"),
        ("tune", cmd_tune, "optax tuning of the continuous retrieval hyperparameters vs the best grid point"),
    ):
        p = sub.add_parser(name, parents=[common], help=text)
        p.add_argument("--run", required=True, help="run folder with scenes/ and memory/bank")
        p.add_argument("--episodes", required=True, help="episodes .jsonl file")
        p.add_argument("--out", required=True, help="output folder")
        add_batch_flags(p, force=name == "tune")
        if name == "sweep":
            p.add_argument("--fresh", action="store_true", help="discard checkpoints of an earlier sweep in --out")
            p.add_argument("--closed-loop", action="store_true",
                           help="also RAGNav's closed-loop navigation (success, SPL, progress, travel) at every grid "
                                "point: retrieval, candidates and the MJX loop in one compiled call per chunk")
            p.add_argument("--stride", type=positive_int, default=1, help="every N-th episode only (default 1: all)")
        p.set_defaults(func=func)
