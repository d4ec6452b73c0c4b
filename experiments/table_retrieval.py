"""Paper Table 1: retrieval accuracy and time by method and input modality, beside the paper's numbers.

    .venv/bin/python experiments/table_retrieval.py --run runs/paper --episodes runs/paper/episodes.jsonl \
        --out runs/paper/table1 [--methods ragnav naive_rag ...]

The run folder must hold scenes/ and memory/bank (ragnav generate / explore / build-memory); the
episodes come from `ragnav episodes`. Writes OUT/table1.{csv,md,json} and OUT/table1.png.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

PAPER = {  # method -> modality -> (retrieval ms, accuracy), from the paper's Table 1
    "naive_rag": {"text": (152, 0.08), "text+location": (155, 0.03), "text+location+sensor": (160, 0.04)},
    "graphrag": {"text": (420, 0.09), "text+location": (425, 0.04), "text+location+sensor": (430, 0.04)},
    "lightrag": {"text": (205, 0.17), "text+location": (210, 0.09), "text+location+sensor": (215, 0.10)},
    "ragnav": {"text": (185, 0.46), "text+location": (190, 0.21), "text+location+sensor": (195, 0.34)},
}
MODALITIES = ("text", "text+location", "text+location+sensor")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--run", required=True)
    ap.add_argument("--episodes", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--methods", nargs="*", default=["naive_rag", "graphrag", "lightrag", "ragnav"])
    ap.add_argument("--config", default=None, help="config for retrieval parameters (default: built-in)")
    args = ap.parse_args(argv)

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ragnav_jax.config import load_config
    from ragnav_jax.language.episodes import load_episodes
    from ragnav_jax.memory.checkpoint import load_bank
    from ragnav_jax.memory.commands import bank_dir
    from ragnav_jax.memory.encoder import bank_embedder
    from ragnav_jax.retrieval.evaluate import evaluate_retrieval
    from ragnav_jax.retrieval.params import params_from_config
    from ragnav_jax.tables import write_table
    from ragnav_jax.world.scene import load_scene_set

    cfg = load_config(args.config)
    run = Path(args.run)
    scenes = load_scene_set(run / "scenes")
    bank = load_bank(bank_dir(run), scenes)
    episodes = load_episodes(args.episodes, scenes)
    emb = bank_embedder(bank, cfg)
    rows, summaries = [], {}
    for m in args.methods:
        _, s = evaluate_retrieval(bank, scenes, episodes, emb, m, params_from_config(cfg.retrieval))
        summaries[m] = s
        for mod in MODALITIES:
            acc = s["by_modality"].get(mod, {}).get("retrieval_accuracy")
            paper = PAPER.get(m, {}).get(mod)
            rows.append({
                "method": m, "input": mod, "accuracy": None if acc is None else round(acc, 3),
                "retrieval_ms_single": round(s["retrieval_ms_single"], 3),
                "retrieval_ms_batched": round(s["retrieval_ms_batched"], 3),
                "paper_accuracy": paper[1] if paper else None, "paper_ms": paper[0] if paper else None,
            })
        print(f"{m:>20}: accuracy {s['retrieval_accuracy']:.3f}", flush=True)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    write_table(rows, out / "table1")
    (out / "table1.json").write_text(json.dumps({"rows": rows, "summaries": summaries}, indent=1) + "\n")
    fig, ax = plt.subplots(figsize=(8, 4))
    w = 0.8 / len(args.methods)
    for k, m in enumerate(args.methods):
        ys = [next(r["accuracy"] for r in rows if r["method"] == m and r["input"] == mod) or 0 for mod in MODALITIES]
        ax.bar([i + k * w for i in range(len(MODALITIES))], ys, w, label=m)
    ax.set_xticks([i + w * (len(args.methods) - 1) / 2 for i in range(len(MODALITIES))], MODALITIES)
    ax.set_ylabel("top-1 instance-level accuracy")
    ax.set_ylim(0, 1)
    ax.legend(fontsize=8)
    ax.set_title("Retrieval accuracy by method and input (paper Table 1)")
    fig.tight_layout()
    fig.savefig(out / "table1.png", dpi=150)
    print((out / "table1.md").read_text())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
