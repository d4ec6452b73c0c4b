"""Goals read with and without the instruction tagger, per template set, on the unseen test houses.

    .venv/bin/python experiments/tagger_reading.py --tagger runs/tagger/all/tagger.npz \
        --splits seen,unseen_dev,...,unseen_dev8 --out DIR [--parses SPLIT=FILE ...]

For each template set (episodes.split) over configs/unseen.yaml's houses (seed 7): how many instructions
the parse gives the true number of goals, and the true goal heads in order, before and after
`language/tagger.py: reconcile`; how many parses the tagger changed, fixed (wrong count -> right) and
broke (right count -> wrong). `--parses SPLIT=FILE` reads that set's parses from a JSONL of task chains
(one per instruction, `null` where the parser refused) instead of the current parser: written by
`--dump` with an older checkout on PYTHONPATH, it measures how the tagger would have served a parser that
had never met the set (a new author). With `--clauses` goals are reconciled as `eval.tagger_clauses` does (each
takes what its own clause says, and the coordinate head's hints), and "hints right" counts the instructions
with a coordinate hint whose goals carry exactly the truth's hints and no reading read from a hint's number.
Writes tagger_reading.json and tagger_reading.md.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from ragnav_jax.config import load_config
from ragnav_jax.language.episodes import generate_episodes
from ragnav_jax.language.parser import parse_instruction
from ragnav_jax.language.types import ParseError, TaskChain
from ragnav_jax.world.generator import generate_scenes

ROOT = Path(__file__).resolve().parents[1]


def episodes_of(split: str):
    cfg = load_config(ROOT / "configs" / "unseen.yaml", [f"episodes.split={split}"])
    return generate_episodes(generate_scenes(cfg.world, cfg.seed), cfg.episodes, cfg.seed)


def episodes_from(path: str):
    """GeneratedEpisode pairs of an episodes file and the truth chains written beside it."""
    from ragnav_jax.language.episodes import GeneratedEpisode, load_episodes, load_truth

    p = Path(path)
    chains = p.with_name(p.stem + ".chains.jsonl")
    truth = load_truth(chains) if chains.exists() else {}
    return [GeneratedEpisode(e, truth.get(e.id)) for e in load_episodes(p)]


def parses(pairs, path: str | None):
    if path:
        rows = [json.loads(x) for x in Path(path).read_text().splitlines()]
        return [None if r is None else TaskChain.from_dict(r).subgoals for r in rows]
    out = []
    for p in pairs:
        try:
            out.append(parse_instruction(p.episode.instruction).subgoals)
        except ParseError:
            out.append(None)
    return out


def hints(subgoals) -> list[tuple[float, float]]:
    """The coordinate hints of a chain's goals, in order."""
    return [(g.location.x, g.location.y) for g in subgoals if g.location is not None]


def hints_right(subgoals, want: list[tuple[float, float]]) -> bool:
    """The goals carry exactly the hints `want` (to 1e-6) and no reading whose value is one of their numbers."""
    got = hints(subgoals)
    values = {v for w in want for v in w}
    return (len(got) == len(want) and all(abs(a - b) < 1e-6 for g, w in zip(got, want) for a, b in zip(g, w))
            and not any(c.value is not None and any(abs(c.value - v) < 1e-6 for v in values)
                        for g in subgoals for c in g.sensors))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--tagger", help="tagger.npz (default ragnav_jax/data/tagger.npz)")
    ap.add_argument("--splits", help="template sets, comma-separated")
    ap.add_argument("--conf", type=float, default=0.0, help="0 = the confidence fitted with the tagger")
    ap.add_argument("--clauses", action="store_true", help="reconcile as eval.tagger_clauses does")
    ap.add_argument("--parses", action="append", default=[], metavar="SPLIT=FILE")
    ap.add_argument("--episodes", action="append", default=[], metavar="NAME=FILE",
                    help="an episodes .jsonl (truth from its .chains.jsonl beside it) measured like a template set")
    ap.add_argument("--dump", help="write the current parser's chains of --splits (one set) to this JSONL and stop")
    ap.add_argument("--out")
    args = ap.parse_args()
    splits = args.splits.split(",") if args.splits else []
    if args.dump:
        pairs = episodes_of(splits[0])
        rows = []
        for p in pairs:
            try:
                rows.append(json.dumps(parse_instruction(p.episode.instruction).to_dict()))
            except ParseError:
                rows.append("null")
        Path(args.dump).write_text("\n".join(rows) + "\n")
        return
    from ragnav_jax.language.tagger import load_tagger, reconcile

    tagger = load_tagger(args.tagger or "")
    args.conf = args.conf or tagger.meta["reconcile"]["conf"]
    given = dict(x.split("=", 1) for x in args.parses)
    report = {"tagger": args.tagger or "ragnav_jax/data/tagger.npz", "conf": args.conf, "splits": {}}
    lines = ["| template set | parser | instructions | goal count right | + tagger | heads right | + tagger | changed | fixed "
             "| broke | with hints | hints right | + tagger |",
             "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    files = dict(x.split("=", 1) for x in args.episodes)
    for split in [*splits, *files]:
        pairs = episodes_of(split) if split not in files else episodes_from(files[split])
        sgs = parses(pairs, given.get(split))
        probs = tagger.word_probs([p.episode.instruction for p in pairs])
        n = c0 = c1 = h0 = h1 = changed = fixed = broke = hinted = k0 = k1 = 0
        examples = []
        for p, s, pr in zip(pairs, sgs, probs):
            truth = [g.target.head for g in p.truth.subgoals] if p.truth is not None else None
            n += 1
            if s is None:
                continue
            r, dropped, added = reconcile(p.episode.instruction, s, pr, args.conf, args.clauses)
            before, after = [g.target.head for g in s], [g.target.head for g in r]
            changed += bool(dropped or added)
            if (dropped or added) and len(examples) < 12:
                examples.append({"instruction": p.episode.instruction, "truth": truth, "parsed": before,
                                 "reconciled": after, "dropped": dropped, "added": added})
            if truth is None:  # no truth beside the file: only the changes count
                continue
            ok0, ok1 = len(before) == len(truth), len(after) == len(truth)
            c0 += ok0
            c1 += ok1
            h0 += before == truth
            h1 += after == truth
            fixed += ok1 and not ok0
            broke += ok0 and not ok1
            want = hints(p.truth.subgoals)
            if want:
                hinted += 1
                k0 += hints_right(s, want)
                k1 += hints_right(r, want)
        row = {"instructions": n, "count_parser": c0, "count_tagger": c1, "heads_parser": h0, "heads_tagger": h1,
               "changed": changed, "fixed": fixed, "broke": broke, "with_hints": hinted, "hints_parser": k0,
               "hints_tagger": k1, "clauses": args.clauses, "examples": examples,
               "parser": "from " + given[split] if split in given else "current"}
        report["splits"][split] = row
        known = pairs and pairs[0].truth is not None
        cells = [c0, c1, h0, h1] if known else ["-"] * 4
        more = [hinted, k0, k1] if known else ["-"] * 3
        lines.append(f"| {split} | {'given' if split in given else 'current'} | {n} | " + " | ".join(map(str, cells))
                     + f" | {changed} | {fixed if known else '-'} | {broke if known else '-'} | "
                     + " | ".join(map(str, more)) + " |")
        print(lines[-1], flush=True)
    if args.out:
        out = Path(args.out)
        out.mkdir(parents=True, exist_ok=True)
        (out / "tagger_reading.json").write_text(json.dumps(report, indent=1) + "\n")
        (out / "tagger_reading.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
