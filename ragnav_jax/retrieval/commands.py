"""CLI subcommand of the retrieval stage: retrieve (accuracy and timing of a method over episodes)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ragnav_jax.errors import UserError
from ragnav_jax.io import write_json, write_jsonl


def check_unparsed(episodes, allow: bool, source, tagger: bool = False) -> dict:
    """summary.json's "unparsed" entry: the episodes whose instruction the parser cannot read, named on stderr
    (one line) and refused with a UserError naming --allow-unparsed unless `allow` (they score as misses) or
    `tagger` (the instruction tagger reads them alone, `eval.tagger`; it is still refused, unless `allow`,
    where some are no instruction at all: blank or too long, `parser.input_problem`)."""
    from ragnav_jax.language.parser import input_problem
    from ragnav_jax.retrieval.evaluate import unparsed

    ids = unparsed(episodes)
    if ids:
        shown = ", ".join(ids[:5]) + (f", ... ({len(ids) - 5} more)" if len(ids) > 5 else "")
        what = f"{source}: {len(ids)} of {len(episodes)} episodes have instructions the parser cannot read ({shown})"
        by_id = {ep.id: ep for ep in episodes}
        if tagger and not any(input_problem(by_id[i].instruction) for i in ids):
            print(f"ragnav: note: {what}; the instruction tagger reads them alone (eval.tagger)", file=sys.stderr)
        elif not allow:
            raise UserError(f"{what}; pass --allow-unparsed to score them as misses")
        else:
            print(f"ragnav: warning: {what}; scored as misses (--allow-unparsed)", file=sys.stderr)
    return {"count": len(ids), "episodes": ids}


def add_batch_flags(p: argparse.ArgumentParser, force: bool = True) -> None:
    """--allow-unparsed and (with `force`) --force of the batch commands that score an episodes file
    (retrieve, eval, tune; sweep resumes instead of overwriting)."""
    p.add_argument("--allow-unparsed", action="store_true",
                   help="score episodes whose instruction the parser cannot read as misses (default: refuse; "
                        "they are named on stderr and counted in summary.json either way)")
    if force:
        p.add_argument("--force", action="store_true", help="overwrite the results of an earlier run in --out")


def cmd_retrieve(args, cfg) -> int:
    from ragnav_jax.language.episodes import load_episodes
    from ragnav_jax.memory.checkpoint import load_bank
    from ragnav_jax.memory.commands import bank_dir
    from ragnav_jax.memory.encoder import bank_embedder
    from ragnav_jax.retrieval.evaluate import evaluate_retrieval
    from ragnav_jax.retrieval.params import params_from_config
    from ragnav_jax.runs import init_run, refuse_overwrite
    from ragnav_jax.tables import write_table
    from ragnav_jax.world.scene import load_scene_set

    run, out = Path(args.run), Path(args.out)
    refuse_overwrite([out / "summary.json", out / "results.jsonl", out / "summary.md", out / "summary.csv"], args.force)
    if not (run / "scenes").is_dir():
        raise UserError(f"{run}: no scenes/ folder (run generate, explore and build-memory first)")
    scenes = load_scene_set(run / "scenes")
    bank = load_bank(bank_dir(run), scenes)
    episodes = load_episodes(args.episodes, scenes)
    unparsed = check_unparsed(episodes, args.allow_unparsed, args.episodes)
    method = args.method or cfg.retrieval.method
    embedder = bank_embedder(bank, cfg)
    init_run(out, cfg, "retrieve")
    rows, summary = evaluate_retrieval(bank, scenes, episodes, embedder, method, params_from_config(cfg.retrieval))
    summary.update({"run": str(run), "episodes_file": str(args.episodes), "unparsed": unparsed})
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
    add_batch_flags(p)
    p.set_defaults(func=cmd_retrieve)
