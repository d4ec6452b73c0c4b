"""Paper Table 2 (complete navigation systems): RAGNav vs ReMEmbR-style, ETPNav-style and the Oracle.

    python experiments/table_navigation.py --run runs/paper --out runs/table_navigation [--stride 8] [--reuse]

Runs the closed loop (`ragnav eval`) for each method on the same episodes and prints total time
(task_time_s + simulated time), travel distance (simulated trajectory) and success rate beside the
paper's numbers (the paper has no oracle row). Writes OUT/table_navigation.{md,json} and a plot.
The baselines are reimplementations in the style of the papers (README, Evaluation), not the originals.
"""

from __future__ import annotations

import json
from pathlib import Path

from _nav_table import bar_plot, fmt, parser, run_methods, write_table

# method -> (total time s, travel distance m, success rate), paper Table 2
PAPER = {"remembr": (45.67, 24.85, 0.52), "etpnav": (38.41, 20.30, 0.42), "ragnav": (30.02, 16.13, 0.65),
         "oracle": (None, None, None)}
NAMES = {"remembr": "ReMEmbR-style", "etpnav": "ETPNav-style", "ragnav": "RAGNav", "oracle": "Oracle"}


def main(argv=None) -> int:
    args = parser(__doc__, "runs/table_navigation").parse_args(argv)
    methods = list(PAPER)
    res = run_methods(args, methods)
    header = ["Method", "Total time (s)", "paper", "Travel distance (m)", "paper", "Success rate", "paper", "SPL",
              "episodes"]
    rows = []
    for m in methods:
        s, p = res[m], PAPER[m]
        rows.append([NAMES[m], fmt(s["total_time_s"]), fmt(p[0]), fmt(s["travel_distance_m"]), fmt(p[1]),
                     fmt(s["success_rate"], 3), fmt(p[2]), fmt(s["spl"], 3), str(s["episodes"])])
    out = Path(args.out)
    text = write_table(rows, header, out / "table_navigation.md")
    (out / "table_navigation.json").write_text(json.dumps({"stride": args.stride, "run": args.run, "measured": res,
                                                           "paper": PAPER}, indent=1) + "\n")
    labels = [NAMES[m] for m in methods]
    bar_plot(labels, {
        "success rate": ([res[m]["success_rate"] for m in methods], [PAPER[m][2] for m in methods]),
        "travel distance (m)": ([res[m]["travel_distance_m"] for m in methods], [PAPER[m][1] for m in methods]),
        "total time (s)": ([res[m]["total_time_s"] for m in methods], [PAPER[m][0] for m in methods]),
    }, out / "table_navigation.png", f"Table 2: navigation systems ({args.run}, stride {args.stride})")
    print(text)
    print(f"-> {out / 'table_navigation.md'}, {out / 'table_navigation.png'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
