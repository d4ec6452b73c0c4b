"""Parse agreement at scale: the rule parser against the episode generator's ground truth.

    .venv/bin/python experiments/parse_agreement.py [--per-scene 60 50 50] [--out experiments/results]

Scenes: the paper preset (14 scenes, seed 2024), the default preset under five seeds (20 scenes) and
the example apartment. Writes parse_agreement.json (rates, timings, first disagreements) and .md.
Host-side timing only (no JAX involved).
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from ragnav_jax.config import load_config
from ragnav_jax.language.agreement import parse_agreement
from ragnav_jax.language.episodes import generate_episodes
from ragnav_jax.world.generator import generate_scenes
from ragnav_jax.world.scene import example_scene_path, load_scene

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--per-scene", type=int, nargs=3, default=(60, 50, 50), metavar=("TEXT", "LOC", "SENSOR"))
    ap.add_argument("--default-seeds", type=int, default=5)
    ap.add_argument("--out", default=str(ROOT / "experiments" / "results"))
    args = ap.parse_args()
    t, tl, tls = args.per_scene
    counts = [f"episodes.text={t}", f"episodes.text_location={tl}", f"episodes.text_location_sensor={tls}"]

    sets = [("paper", load_config(ROOT / "configs" / "paper.yaml", counts))]
    sets += [(f"default-seed{s}", load_config(ROOT / "configs" / "default.yaml", [*counts, f"seed={s}"]))
             for s in range(args.default_seeds)]
    rows, pairs_all = [], []
    t_gen = t_scenes = 0.0
    for name, cfg in sets:
        t0 = time.perf_counter()
        scenes = generate_scenes(cfg.world, cfg.seed)
        t1 = time.perf_counter()
        pairs = generate_episodes(scenes, cfg.episodes, cfg.seed)
        t2 = time.perf_counter()
        t_scenes, t_gen = t_scenes + (t1 - t0), t_gen + (t2 - t1)
        r = parse_agreement(pairs, keep=0)
        rows.append({"set": name, "scenes": len(scenes), "instructions": r["instructions"], "rate": r["rate"]})
        pairs_all += pairs
        print(f"{name}: {len(scenes)} scenes, {r['instructions']} instructions, agreement {100 * r['rate']:.2f}%")
    cfg = load_config(None, counts)
    apt = generate_episodes([load_scene(example_scene_path())], cfg.episodes, cfg.seed)
    pairs_all += apt
    r = parse_agreement(apt, keep=0)
    rows.append({"set": "apartment", "scenes": 1, "instructions": r["instructions"], "rate": r["rate"]})

    t0 = time.perf_counter()
    report = parse_agreement(pairs_all, keep=100)
    t_parse = time.perf_counter() - t0
    result = {
        "instructions": report["instructions"],
        "agree": report["agree"],
        "rate": report["rate"],
        "parse_errors": report["parse_errors"],
        "by_modality": report["by_modality"],
        "by_set": rows,
        "ms_per_parse_and_compare": 1000 * t_parse / report["instructions"],
        "ms_per_generated_episode": 1000 * t_gen / report["instructions"],
        "failures": report["failures"],
    }
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "parse_agreement.json").write_text(json.dumps(result, indent=1) + "\n")
    lines = ["# Parse agreement with the episode generator's ground truth", "",
             f"{result['agree']} / {result['instructions']} instructions agree "
             f"({100 * result['rate']:.2f}%); parse errors: {result['parse_errors']}.", "",
             "| set | scenes | instructions | agreement |", "|---|---:|---:|---:|"]
    lines += [f"| {r['set']} | {r['scenes']} | {r['instructions']} | {100 * r['rate']:.2f}% |" for r in rows]
    lines += ["", "| modality | agreement |", "|---|---:|"]
    lines += [f"| {m} | {100 * v:.2f}% |" for m, v in result["by_modality"].items()]
    lines += ["", f"Parse + compare: {result['ms_per_parse_and_compare']:.2f} ms per instruction; generation: "
              f"{result['ms_per_generated_episode']:.2f} ms per episode (host CPU)."]
    if result["failures"]:
        lines += ["", "First disagreements:", ""]
        lines += [f"- `{f['instruction']}`: {'; '.join(f['differences'])[:300]}" for f in result["failures"][:20]]
    (out / "parse_agreement.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
