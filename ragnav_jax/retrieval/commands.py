"""CLI subcommand of the retrieval stage: retrieve (accuracy and timing of a method over episodes)."""

from __future__ import annotations

import argparse
from pathlib import Path

from ragnav_jax.errors import UserError
from ragnav_jax.io import write_json, write_jsonl


def cmd_retrieve(args, cfg) -> int:
    from ragnav_jax.language.episodes import load_episodes
    from ragnav_jax.memory.checkpoint import load_bank
    from ragnav_jax.memory.commands import bank_dir
    from ragnav_jax.memory.encoder import make_embedder
    from ragnav_jax.retrieval.evaluate import evaluate_retrieval
    from ragnav_jax.retrieval.params import params_from_config
    from ragnav_jax.runs import init_run
    from ragnav_jax.tables import write_table
    from ragnav_jax.world.scene import load_scene_set

    run = Path(args.run)
    if not (run / "scenes").is_dir():
        raise UserError(f"{run}: no scenes/ folder (run generate, explore and build-memory first)")
    scenes = load_scene_set(run / "scenes")
    bank = load_bank(bank_dir(run))
    episodes = load_episodes(args.episodes, scenes)
    method = args.method or cfg.retrieval.method
    embedder = make_embedder(bank.metas[0].embedder if bank.metas else cfg.memory.embedder,
                             dim=cfg.memory.hashing_dim, batch_size=cfg.memory.embed_batch,
                             buckets=cfg.memory.token_buckets)
    out = Path(args.out)
    init_run(out, cfg, "retrieve")
    rows, summary = evaluate_retrieval(bank, scenes, episodes, embedder, method, params_from_config(cfg.retrieval))
    summary.update({"run": str(run), "episodes_file": str(args.episodes)})
    write_jsonl(out / "results.jsonl", rows)
    write_json(out / "summary.json", summary)
    table = [{"method": method, "modality": "all", "accuracy": round(summary["retrieval_accuracy"], 4),
              "queries": summary["queries"]}]
    for m, v in summary["by_modality"].items():
        table.append({"method": method, "modality": m, "accuracy": round(v["retrieval_accuracy"], 4), "queries": v["queries"]})
    write_table(table, out / "summary")
    print((out / "summary.md").read_text())
    print(f"retrieval_ms_single={summary.get('retrieval_ms_single')} retrieval_ms_batched={summary.get('retrieval_ms_batched')}"
          f" -> {out / 'summary.json'}")
    return 0


def register(sub: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    from ragnav_jax.retrieval.evaluate import METHODS

    p = sub.add_parser("retrieve", parents=[common], help="retrieval accuracy of a method over an episodes file")
    p.add_argument("--run", required=True, help="run folder with scenes/ and memory/bank")
    p.add_argument("--episodes", required=True, help="episodes .jsonl file")
    p.add_argument("--method", choices=METHODS, help="method (default: retrieval.method from the config)")
    p.add_argument("--out", required=True, help="output folder")
    p.set_defaults(func=cmd_retrieve)
