"""`ragnav eval`: closed-loop navigation of one or more methods over a scene set and an episodes file.

    ragnav eval --scenes DIR --episodes FILE --method ragnav --out RUN [--memory BANK]

--scenes is a run folder (with scenes/, and explore/ + memory/bank when already built) or a folder of
scene files; scenes without memory are explored and their memory built in RUN first. --method takes a
name, a comma-separated list, or `all`. Writes RUN/eval/<method>/{episodes.jsonl, summary.json} and
RUN/eval/table.{md,csv} (one row per method), and prints the table.
"""

from __future__ import annotations

import argparse
import json
import shutil
from pathlib import Path

from ragnav_jax.errors import UserError

TABLE_KEYS = ("success_rate", "retrieval_accuracy", "spl", "progress", "ppl", "travel_distance_m", "oracle_m",
              "planned_rule1_m", "retrieval_ms", "retrieval_ms_single", "task_time_s", "sim_time_s", "total_time_s",
              "wrong_declarations")


def prepare_inputs(scenes_arg: str, memory_arg: str | None, out: Path, cfg, quiet: bool):
    """(scenes, bank, streams by scene name, source run folder): explores and builds memory when missing."""
    from ragnav_jax.cli import main as cli_main
    from ragnav_jax.config import dump_yaml
    from ragnav_jax.memory.checkpoint import load_bank
    from ragnav_jax.memory.commands import bank_dir
    from ragnav_jax.sim.stream import ExplorationStream
    from ragnav_jax.world.scene import load_scene_set

    src = Path(scenes_arg)
    if not src.exists():
        raise UserError(f"{src}: no such scene folder or file")
    run = src if (src / "scenes").is_dir() else None
    scenes = load_scene_set(run / "scenes" if run else src)
    if memory_arg:
        bank = load_bank(memory_arg)
    elif run is not None and bank_dir(run).exists():
        bank = load_bank(bank_dir(run))
    else:
        out.mkdir(parents=True, exist_ok=True)
        cfg_file = out / "config.eval-input.yaml"
        cfg_file.write_text(dump_yaml(cfg))
        q = ["--quiet"] if quiet else []
        if not (out / "explore" / "summary.json").exists():
            rc = cli_main(["explore", "--scenes", str(run / "scenes" if run else src), "--out", str(out), "--config",
                           str(cfg_file), "--no-plots", *q])
            if rc:
                raise UserError(f"exploring {src} failed (exit {rc})")
        if not bank_dir(out).exists():
            rc = cli_main(["build-memory", "--run", str(out), "--config", str(cfg_file), *q])
            if rc:
                raise UserError(f"building memory for {src} failed (exit {rc})")
        run = out
        bank = load_bank(bank_dir(out))
    streams = {}
    for base in [p for p in (run, out) if p is not None]:
        for s in scenes:
            f = base / "explore" / "streams" / f"{s.name}.npz"
            if s.name not in streams and f.is_file():
                streams[s.name] = ExplorationStream.load(f)
    return scenes, bank, streams


def cmd_eval(args, cfg) -> int:
    from ragnav_jax.evaluation.episode import NAV_METHODS, evaluate_navigation
    from ragnav_jax.evaluation.execute import make_executor
    from ragnav_jax.language.episodes import load_episodes
    from ragnav_jax.memory.encoder import make_embedder
    from ragnav_jax.runs import init_run
    from ragnav_jax.tables import write_table

    out = Path(args.out)
    methods = list(NAV_METHODS) if args.method == "all" else [m.strip() for m in (args.method or cfg.eval.method).split(",")]
    bad = [m for m in methods if m not in NAV_METHODS]
    if bad:
        raise UserError(f"unknown method(s) {', '.join(bad)} (known: {', '.join(NAV_METHODS)}, all)")
    load_episodes(args.episodes)  # format errors (file:line, exit 2) before any exploring
    scenes, bank, streams = prepare_inputs(args.scenes, args.memory, out, cfg, args.quiet)
    episodes = load_episodes(args.episodes, scenes)
    if args.stride > 1:  # an even subsample across scenes and modalities
        episodes = episodes[:: args.stride]
    if args.limit:
        episodes = episodes[: args.limit]
    if not episodes:
        raise UserError(f"{args.episodes}: no episodes")
    init_run(out, cfg, "eval")
    embedder = make_embedder(bank.metas[0].embedder if bank.metas else cfg.memory.embedder,
                             dim=cfg.memory.hashing_dim, batch_size=cfg.memory.embed_batch,
                             buckets=cfg.memory.token_buckets)
    used = [s for s in scenes if s.name in {e.scene for e in episodes}]
    executor = make_executor(used, cfg)
    table = []
    for m in methods:
        rows, summary = evaluate_navigation(bank, scenes, episodes, embedder, cfg, m, streams=streams,
                                            progress=not args.quiet, executor=executor)
        summary.update({"scenes": str(Path(args.scenes).resolve()), "episodes_file": str(Path(args.episodes).resolve()),
                        "memory": args.memory and str(Path(args.memory).resolve())})  # what show-episode replays
        d = out / "eval" / m.replace(":", "_")
        d.mkdir(parents=True, exist_ok=True)
        with open(d / "episodes.jsonl", "w") as f:
            for r in rows:
                f.write(json.dumps(r) + "\n")
        (d / "summary.json").write_text(json.dumps(summary, indent=1) + "\n")
        table.append({"method": m, **{k: summary.get(k) for k in TABLE_KEYS}})
        for mod, blk in summary["by_modality"].items():
            table.append({"method": f"{m} [{mod}]", **{k: blk.get(k) for k in TABLE_KEYS if k in blk}})
    write_table(table, out / "eval" / "table")
    save_bar_plot([r for r in table if "[" not in r["method"]], out / "eval" / "methods.png")
    if len(methods) == 1:  # a single method's summary also sits at the top of the eval folder
        shutil.copy(out / "eval" / methods[0].replace(":", "_") / "summary.json", out / "eval" / "summary.json")
    print((out / "eval" / "table.md").read_text())
    print(f"-> {out / 'eval'}")
    return 0


def register(sub: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    p = sub.add_parser("eval", parents=[common], help="closed-loop multi-goal navigation in MJX: success, SPL, distance, times")
    p.add_argument("--scenes", required=True, help="run folder (scenes/, explore/, memory/bank) or folder of scene files")
    p.add_argument("--episodes", required=True, help="episodes .jsonl file")
    p.add_argument("--method", help="method, comma-separated methods, or 'all' (default: eval.method)")
    p.add_argument("--memory", help="memory bank folder to reuse (default: SCENES/memory/bank, else built in --out)")
    p.add_argument("--out", required=True, help="output run folder")
    p.add_argument("--limit", type=int, default=0, help="first N episodes only (0: all)")
    p.add_argument("--stride", type=int, default=1, help="every N-th episode only (an even subsample)")
    p.set_defaults(func=cmd_eval)


def save_bar_plot(rows: list[dict], path: Path) -> Path:
    """Success rate, SPL and retrieval accuracy per method, side by side."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    keys = ("success_rate", "spl", "retrieval_accuracy")
    x = np.arange(len(rows))
    fig, ax = plt.subplots(figsize=(max(6, 1.1 * len(rows)), 3.5))
    for j, k in enumerate(keys):
        ax.bar(x + (j - 1) * 0.27, [r.get(k) or 0.0 for r in rows], 0.27, label=k)
    ax.set_xticks(x, [r["method"] for r in rows], rotation=30, ha="right")
    ax.set_ylim(0, 1)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path
