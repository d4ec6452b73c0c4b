"""CLI subcommand of the planning stage: plan (instruction -> ordered route and guide on one scene)."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from ragnav_jax.errors import UserError, printable
from ragnav_jax.io import write_json


def cmd_plan(args, cfg) -> int:
    from ragnav_jax.memory.checkpoint import load_bank
    from ragnav_jax.memory.commands import bank_dir
    from ragnav_jax.memory.encoder import bank_embedder
    from ragnav_jax.planning.guide import guide_text, save_route_picture
    from ragnav_jax.planning.plan import plan_instruction
    from ragnav_jax.runs import refuse_overwrite
    from ragnav_jax.world.scene import load_scene_set

    run = Path(args.run)
    refuse_overwrite([args.json, args.out], args.force)
    if not (run / "scenes").is_dir():
        raise UserError(f"{run}: no scenes/ folder (run generate, explore and build-memory first)")
    scenes = {s.name: s for s in load_scene_set(run / "scenes")}
    if args.scene not in scenes:
        raise UserError(f"{run / 'scenes'}: no scene named '{args.scene}' (have: {', '.join(sorted(scenes))})")
    bank = load_bank(bank_dir(run), [scenes[args.scene]])
    bank.index(args.scene)
    emb = bank_embedder(bank, cfg)
    guide = plan_instruction(bank, scenes[args.scene], args.instruction, emb, cfg)
    print(printable(guide_text(guide), keep_newlines=True))  # the guide quotes the user's instruction
    if args.json:
        Path(args.json).parent.mkdir(parents=True, exist_ok=True)
        write_json(Path(args.json), guide)
        print(f"guide written to {args.json}")
    else:
        print(json.dumps({k: guide[k] for k in guide if k not in ("chain",)}, indent=1))
    if args.out:
        save_route_picture(scenes[args.scene], guide, args.out)
        print(f"route picture written to {args.out}")
    return 0


def register(sub: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    p = sub.add_parser("plan", parents=[common], help="plan an instruction on one scene and print the guide")
    p.add_argument("--run", required=True, help="run folder with scenes/ and memory/bank")
    p.add_argument("--scene", required=True, help="scene name")
    p.add_argument("instruction", help="the instruction, quoted")
    p.add_argument("--out", help="save a picture of the route on the floor plan (.png)")
    p.add_argument("--json", help="save the guide as JSON here")
    p.add_argument("--force", action="store_true", help="overwrite existing --out / --json files")
    p.set_defaults(func=cmd_plan)
