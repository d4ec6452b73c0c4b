"""CLI subcommands of the memory stage: build-memory, show-memory."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ragnav_jax.errors import UserError, printable
from ragnav_jax.io import write_json, write_jsonl


def bank_dir(run: Path) -> Path:
    return Path(run) / "memory" / "bank"


def load_run_inputs(run: Path):
    """Scenes of RUN/scenes and their streams RUN/explore/streams/<scene>.npz (same order)."""
    from ragnav_jax.sim.stream import ExplorationStream
    from ragnav_jax.world.scene import load_scene_set

    if not (run / "scenes").is_dir():
        raise UserError(f"{run}: no scenes/ folder; run `ragnav generate --out {run}` first")
    scenes = load_scene_set(run / "scenes")
    streams_dir = run / "explore" / "streams"
    missing = [s.name for s in scenes if not (streams_dir / f"{s.name}.npz").is_file()]
    if missing:
        raise UserError(f"{streams_dir}: no exploration stream for {', '.join(missing)}; "
                        f"run `ragnav explore --scenes {run / 'scenes'} --out {run}` first")
    streams = [ExplorationStream.load(streams_dir / f"{s.name}.npz") for s in scenes]
    for s, st in zip(scenes, streams):
        if st.scene != s.name:
            raise UserError(f"{streams_dir / (s.name + '.npz')}: stream of scene '{st.scene}', expected '{s.name}'")
    return scenes, streams


def cmd_build_memory(args, cfg) -> int:
    from ragnav_jax.memory.build import build_bank, memory_summary
    from ragnav_jax.memory.checkpoint import bank_exists, save_bank
    from ragnav_jax.runs import init_run
    from ragnav_jax.tables import write_table

    run = Path(args.run)
    out = bank_dir(run)
    if bank_exists(out) and not args.force:  # a folder left by an interrupted build is no bank
        raise UserError(f"{out}: a memory bank exists; pass --force to rebuild it")
    scenes, streams = load_run_inputs(run)
    init_run(run, cfg, "build-memory")
    bank, stats = build_bank(scenes, streams, cfg, progress=not args.quiet)
    save_bank(bank, out)
    stage = run / "memory"
    summary = memory_summary(bank)
    summary["embedder"] = cfg.memory.embedder
    summary["stage_seconds"] = {k: round(v, 4) for k, v in stats.stage_seconds.items()}
    summary["texts_embedded"] = stats.texts_embedded
    summary["captions_rejected"] = list(stats.captions_rejected)
    if stats.captions_rejected:
        n = len(stats.captions_rejected)
        print(f"ragnav: warning: memory.captioner=llm: {n} of {sum(m.num_nodes for m in bank.metas)} replies did not read as a "
              f"caption and were replaced by template captions ({printable(stats.captions_rejected[0])}"
              f"{'; all listed in summary.json' if n > 1 else ''})", file=sys.stderr)
    write_json(stage / "summary.json", summary)
    rows = [{k: (", ".join(map(str, v)) if isinstance(v, list) else v) for k, v in r.items()} for r in summary["scenes"]]
    write_table(rows, stage / "memory_summary")
    pos = bank.memory.position
    write_jsonl(stage / "nodes.jsonl", ({
        "scene": meta.scene, "node": i, "position": [round(float(v), 3) for v in pos[b, i]],
        "caption": meta.captions[i], "observed": list(meta.observed_ids[i]),
    } for b, meta in enumerate(bank.metas) for i in range(meta.num_nodes)))
    print((stage / "memory_summary.md").read_text())
    print(f"memory of {len(scenes)} scenes (mean {summary['mean_nodes']:.1f} nodes) written to {out}")
    return 0


def cmd_show_memory(args, cfg) -> int:
    from ragnav_jax.memory.checkpoint import load_bank
    from ragnav_jax.memory.plot import save_memory_plot
    from ragnav_jax.runs import refuse_overwrite
    from ragnav_jax.world.scene import load_scene_set

    run = Path(args.run)
    out = Path(args.out)
    if out.suffix.lower() not in (".png", ".pdf", ".svg"):
        raise UserError(f"--out {out}: use a .png, .pdf or .svg file name")
    refuse_overwrite([out], args.force)
    if not (run / "scenes").is_dir():
        raise UserError(f"{run}: no scenes/ folder (run generate, explore and build-memory first)")
    scenes = {s.name: s for s in load_scene_set(run / "scenes")}
    bank = load_bank(bank_dir(run), scenes.values())
    mem, meta = bank.scene(args.scene)
    if args.scene not in scenes:
        raise UserError(f"{run / 'scenes'}: no scene named '{args.scene}'")
    levels = mem.num_levels
    if not -levels <= args.level < levels:
        raise UserError(f"--level {args.level}: this memory has levels 0 to {levels - 1} (negative: from the top)")
    save_memory_plot(scenes[args.scene], mem, meta, out, level=args.level)
    print(f"memory of {args.scene} ({meta.num_nodes} nodes) drawn to {out}")
    return 0


def register(sub: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    p = sub.add_parser("build-memory", parents=[common], help="build the dual-basis memory bank of a run")
    p.add_argument("--run", required=True, help="run folder with scenes/ and explore/streams/")
    p.add_argument("--force", action="store_true", help="rebuild an existing memory bank")
    p.set_defaults(func=cmd_build_memory)

    p = sub.add_parser("show-memory", parents=[common], help="draw a scene's memory: map, forest clusters, dendrogram")
    p.add_argument("run", help="run folder holding memory/bank")
    p.add_argument("--scene", required=True, help="scene name")
    p.add_argument("--out", required=True, help="picture file (.png, .pdf, .svg)")
    p.add_argument("--level", type=int, default=-1, help="forest level that colours the nodes (default: the top)")
    p.add_argument("--force", action="store_true", help="overwrite an existing --out file")
    p.set_defaults(func=cmd_show_memory)
