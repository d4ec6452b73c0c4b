"""Paper Table 3 (ablations): RAGNav without the semantic forest, the topological map, spatial or
neighbour enhancement, against the full method.

    python experiments/table_ablation.py --run runs/paper --out runs/table_ablation [--stride 8] [--reuse]

Each variant is a flag of one implementation (`ragnav:no_forest|no_topology|no_spatial|no_boost`;
no_topology also plans and drives straight lines). Prints retrieval accuracy (top-1, instance-level),
travel distance (simulated trajectory) and closed-loop success beside the paper's numbers, and each
variant paired with the full method episode by episode: episodes only RAGNav succeeds on / only the
variant does, with an exact sign test's p (likewise per goal for top-1). Writes
OUT/table_ablation.{md,json} and a plot. `--set eval.retries=0` runs the paper's protocol (navigate to
the top-1 retrieval, no reflection retries).
"""

from __future__ import annotations

import json
from pathlib import Path

from _nav_table import bar_plot, episode_rows, fmt, parser, run_methods, write_table

from ragnav_jax.evaluation.metrics import paired_comparison

# variant -> (retrieval accuracy, travel distance m, success rate), paper Table 3
PAPER = {"ragnav:no_forest": (0.15, 21.72, 0.28), "ragnav:no_topology": (0.24, 24.37, 0.21),
         "ragnav:no_spatial": (0.35, 17.91, 0.28), "ragnav:no_boost": (0.39, 17.25, 0.31),
         "ragnav": (0.46, 16.13, 0.65)}
NAMES = {"ragnav:no_forest": "w/o Semantic Forest", "ragnav:no_topology": "w/o Topological Map",
         "ragnav:no_spatial": "w/o Spatial Enhancement", "ragnav:no_boost": "w/o Neighbor Enhancement",
         "ragnav": "RAGNav"}


def main(argv=None) -> int:
    args = parser(__doc__, "runs/table_ablation").parse_args(argv)
    methods = list(PAPER)
    res = run_methods(args, methods)
    header = ["Variant", "Retrieval acc.", "paper", "Travel distance (m)", "paper", "Success rate", "paper", "episodes",
              "success: only RAGNav / only variant (p)", "top-1: only RAGNav / only variant (p)"]
    rows, paired = [], {}
    full = episode_rows(args, "ragnav")
    for m in methods:
        s, p = res[m], PAPER[m]
        c = paired[m] = paired_comparison(full, episode_rows(args, m)) if m != "ragnav" else None
        pair_s = "-" if c is None else f"{c['success_wins']} / {c['success_losses']} ({c['success_p']:.2g})"
        pair_r = "-" if c is None else f"{c['top1_wins']} / {c['top1_losses']} ({c['top1_p']:.2g})"
        rows.append([NAMES[m], fmt(s["retrieval_accuracy"], 3), fmt(p[0]), fmt(s["travel_distance_m"]), fmt(p[1]),
                     fmt(s["success_rate"], 3), fmt(p[2]), str(s["episodes"]), pair_s, pair_r])
    out = Path(args.out)
    text = write_table(rows, header, out / "table_ablation.md")
    (out / "table_ablation.json").write_text(json.dumps({"stride": args.stride, "run": args.run, "overrides": args.set,
                                                         "measured": res, "paired": paired, "paper": PAPER}, indent=1) + "\n")
    bar_plot([NAMES[m] for m in methods], {
        "retrieval accuracy": ([res[m]["retrieval_accuracy"] for m in methods], [PAPER[m][0] for m in methods]),
        "travel distance (m)": ([res[m]["travel_distance_m"] for m in methods], [PAPER[m][1] for m in methods]),
        "success rate": ([res[m]["success_rate"] for m in methods], [PAPER[m][2] for m in methods]),
    }, out / "table_ablation.png", f"Table 3: ablations ({args.run}, stride {args.stride})")
    print(text)
    print(f"-> {out / 'table_ablation.md'}, {out / 'table_ablation.png'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
