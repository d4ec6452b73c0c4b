"""What grounding parsed goals in the memory (evaluation/grounding.py) does to a parser's reading of a
template set, before any robot moves, on the unseen test houses and their real memories.

    .venv/bin/python experiments/grounding_effect.py --run runs/unseen --split unseen_dev7 [--parser-at 47a0bb2]

For each template split: the set's 192 instructions are parsed (by the current rule parser, or by the
parser of an earlier commit with --parser-at REV: a temporary `git worktree` of that commit parses them
and is removed again), grounded against the memory bank of --run, and compared with the generator's
ground truth goal by goal, as the closed loop pairs them (parsed subgoal k with goal k): `aligned` counts
the instructions whose first len(goals) parsed heads are the true heads, `goals` those whose first
len(goals) parsed subgoals agree with the truth in every part the loop reads (target with attributes and
relations, room, coordinates, readings: `agreement.subgoal_differences`), before and after grounding.
Also: parse errors, subgoals changed and dropped. Writes grounding_effect.json / .md under --out.
A parser's held-out set is only measured here in aggregate; no instruction is printed.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

from ragnav_jax.config import load_config
from ragnav_jax.evaluation.grounding import MemoryGrounder
from ragnav_jax.evaluation.verify import Verifier
from ragnav_jax.language.agreement import subgoal_differences
from ragnav_jax.language.episodes import generate_episodes
from ragnav_jax.language.types import ParseError, TaskChain
from ragnav_jax.memory.checkpoint import load_bank
from ragnav_jax.memory.encoder import make_embedder
from ragnav_jax.world.scene import load_scene_set

ROOT = Path(__file__).resolve().parents[1]
_DUMP = """
import json, sys
from ragnav_jax.language.parser import parse_instruction
from ragnav_jax.language.types import ParseError
for line in sys.stdin:
    try:
        print(json.dumps(parse_instruction(json.loads(line)).to_dict()))
    except ParseError:
        print("null")
"""


def parses(texts: list[str], rev: str | None) -> list[dict | None]:
    """Each text's chain as a dict (None: ParseError), by the current parser or the one at commit rev."""
    if rev is None:
        from ragnav_jax.language.parser import parse_instruction

        out = []
        for t in texts:
            try:
                out.append(parse_instruction(t).to_dict())
            except ParseError:
                out.append(None)
        return out
    with tempfile.TemporaryDirectory() as tmp:
        wt = Path(tmp) / "parser"
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", "-q", str(wt), rev], check=True)
        try:
            r = subprocess.run([sys.executable, "-c", _DUMP], input="".join(json.dumps(t) + "\n" for t in texts),
                               capture_output=True, text=True, check=True, cwd=wt, env={"PYTHONPATH": str(wt)})
        finally:
            subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(wt)], check=True)
    return [json.loads(x) for x in r.stdout.splitlines()]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--run", default="runs/unseen", help="explored run with a memory bank (configs/unseen.yaml)")
    ap.add_argument("--config", default=str(ROOT / "configs" / "unseen.yaml"))
    ap.add_argument("--split", action="append", required=True, help="episodes.split (repeat)")
    ap.add_argument("--parser-at", default=None, help="parse with the rule parser of this commit")
    ap.add_argument("--out", default="runs/grounding_effect")
    args = ap.parse_args()
    run, out = Path(args.run), Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    base = load_config(args.config, [])
    scenes = load_scene_set(run / "scenes")
    bank = load_bank(run / "memory" / "bank", scenes)
    ground = MemoryGrounder(Verifier.build(make_embedder(base.memory.embedder), base), bank, scenes)
    rows = []
    for split in args.split:
        cfg = load_config(args.config, [f"episodes.split={split}"])
        pairs = generate_episodes(scenes, cfg.episodes, cfg.seed)
        chains = parses([p.episode.instruction for p in pairs], args.parser_at)
        r = {"split": split, "parser": args.parser_at or "HEAD", "instructions": len(pairs), "parse_errors": 0,
             "aligned_before": 0, "aligned_after": 0, "goals_before": 0, "goals_after": 0, "changed": 0, "dropped": 0}
        for p, d in zip(pairs, chains):
            if d is None:
                r["parse_errors"] += 1
                continue
            sgs = TaskChain.from_dict(d, validate=False).subgoals
            truth = [s.target.head for s in p.truth.subgoals]
            grounded = ground(p.episode, sgs)
            for key, got in (("before", sgs), ("after", grounded)):
                whole = len(got) >= len(truth)
                r[f"aligned_{key}"] += whole and [s.target.head for s in got[: len(truth)]] == truth
                r[f"goals_{key}"] += whole and not any(subgoal_differences(a, b) for a, b in zip(got, p.truth.subgoals))
            r["changed"] += grounded != sgs
            r["dropped"] += len(sgs) - len(grounded)
        rows.append(r)
        print(json.dumps(r))
    (out / "grounding_effect.json").write_text(json.dumps(rows, indent=1) + "\n")
    lines = ["| split | parser | heads aligned: before | after | goals agree: before | after | parse errors | changed "
             "| dropped |", "|---|---|---:|---:|---:|---:|---:|---:|---:|"]
    lines += [f"| {r['split']} | {r['parser']} | {r['aligned_before']} / {r['instructions']} | {r['aligned_after']} | "
              f"{r['goals_before']} | {r['goals_after']} | {r['parse_errors']} | {r['changed']} | {r['dropped']} |"
              for r in rows]
    (out / "grounding_effect.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
