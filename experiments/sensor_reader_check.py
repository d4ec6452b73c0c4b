"""Sensor comparisons read by the rule parser and by a fitted sensor reader, per template set, goal by goal.

    .venv/bin/python experiments/sensor_reader_check.py --reader runs/sensor-reader/dev12/sensor_reader.npz \
        --splits unseen,unseen_q,...,unseen_x,seen,unseen_dev5 --out DIR [--houses 3 --seed 777]

Goal texts come from `sensor_reader.goal_examples` over `--houses` seen-split houses of `--seed` (not the
reader's training or confidence houses): every goal of each set's episodes, and each goal without a comparison
written again with a random one by the set's own templates. Each text is parsed alone ("Go to <text>") and
counted right where its first comparison has the truth's reading and way (none, above, below, about, most,
least); the reader is counted by its argmax, and `revise` at the reader's fitted confidence and at 0.9. A set
the reader learnt from measures nothing new: fit one without them (`ragnav fit-sensor-reader --splits ...`).
Writes sensor_reader_check.json and .md.
"""

from __future__ import annotations

import argparse
import json
from collections import Counter
from pathlib import Path

from ragnav_jax.config import load_config
from ragnav_jax.language.parser import parse_instruction
from ragnav_jax.language.sensor_reader import NONE, SensorReader, goal_examples, label, load_reader_file, revise
from ragnav_jax.language.types import ParseError, Subgoal, Target

ROOT = Path(__file__).resolve().parents[1]


def parsed(text: str) -> Subgoal:
    try:
        sgs = parse_instruction("Go to " + text).subgoals
    except ParseError:
        sgs = ()
    sg = sgs[0] if sgs else Subgoal(0, Target(text, text))
    return Subgoal(sg.index, sg.target, sg.room, sg.location, sg.sensors, text)


def right(got: tuple[int, int], reading: int, way: int) -> bool:
    return got[1] == way and (way == NONE or got[0] == reading)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--reader", required=True)
    ap.add_argument("--splits", required=True)
    ap.add_argument("--houses", type=int, default=3)
    ap.add_argument("--seed", type=int, default=777)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    cfg = load_config(ROOT / "configs" / "seen.yaml", [])
    trained, meta = load_reader_file(args.reader)
    reader, conf = SensorReader(trained, meta), meta["revise"]["conf"]
    learnt = set(meta["fitted_on"]["template_sets"])
    rows = []
    for split in args.splits.split(","):
        ex = goal_examples(cfg, args.houses, args.seed, (split,))
        pr, pw = reader.probs([t for t, _, _ in ex])
        c = Counter()
        for (text, r, w), a, b in zip(ex, pr, pw):
            sg = parsed(text)
            ok = {"parser": right(label(sg), r, w), "reader": right((int(a.argmax()), int(b.argmax())), r, w),
                  "revise": right(label(revise(sg, a, b, conf)), r, w), "revise_0.9": right(label(revise(sg, a, b, 0.9)), r, w)}
            for k, v in ok.items():
                c[k] += v
                c[k + "_cmp"] += v and w != NONE
            c["goals"] += 1
            c["with_comparison"] += w != NONE
        rows.append({"set": split, "learnt_from": split in learnt, **c})
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "sensor_reader_check.json").write_text(json.dumps({"reader": args.reader, "conf": conf, "houses": args.houses,
                                                              "seed": args.seed, "rows": rows}, indent=1))
    lines = [f"Reader {args.reader} (confidence {conf}); {args.houses} seen-split houses, seed {args.seed}.", "",
             "| set | learnt from | goals | with a comparison | parser | reader | revise | revise 0.9 | comparisons: parser | reader |",
             "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        n, m = r["goals"], max(r["with_comparison"], 1)
        lines.append(f"| {r['set']} | {'yes' if r['learnt_from'] else 'no'} | {n} | {r['with_comparison']} | "
                     f"{r['parser'] / n:.3f} | {r['reader'] / n:.3f} | {r['revise'] / n:.3f} | {r['revise_0.9'] / n:.3f} | "
                     f"{r['parser_cmp'] / m:.3f} | {r['reader_cmp'] / m:.3f} |")
    (out / "sensor_reader_check.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
