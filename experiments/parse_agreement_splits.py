"""Parse agreement per sentence-template split on the unseen test houses (configs/unseen.yaml, seed 7).

    .venv/bin/python experiments/parse_agreement_splits.py [--out experiments/results/generalisation-cpu]

For `seen` and every unseen template set (episodes.split: unseen_dev .. unseen_dev6, unseen): how many of
the 192 instructions the rule parser reads back exactly as the generator wrote them (`parse_agreement`),
by input type, with the first disagreements. Writes parse_agreement-<split>.json and parse_agreement.md.
Host-side only (no JAX).
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from ragnav_jax.config import EPISODE_SPLITS, load_config
from ragnav_jax.language.agreement import parse_agreement
from ragnav_jax.language.episodes import generate_episodes
from ragnav_jax.world.generator import generate_scenes

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", default=str(ROOT / "experiments" / "results" / "generalisation-cpu"))
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    base = load_config(ROOT / "configs" / "unseen.yaml", [])
    scenes = generate_scenes(base.world, base.seed)
    lines = ["# Parse agreement per template split (unseen test houses, configs/unseen.yaml)", "",
             "| split | agree | rate | text | text+location | text+location+sensor |", "|---|---:|---:|---:|---:|---:|"]
    for split in EPISODE_SPLITS:
        cfg = load_config(ROOT / "configs" / "unseen.yaml", [f"episodes.split={split}"])
        r = parse_agreement(generate_episodes(scenes, cfg.episodes, cfg.seed), keep=20)
        (out / f"parse_agreement-{split}.json").write_text(json.dumps(r, indent=1) + "\n")
        m = r["by_modality"]
        lines.append(f"| {split} | {r['agree']} / {r['instructions']} | {r['rate']:.3f} | {m['text']:.3f} | "
                     f"{m['text+location']:.3f} | {m['text+location+sensor']:.3f} |")
        print(lines[-1])
    (out / "parse_agreement.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
