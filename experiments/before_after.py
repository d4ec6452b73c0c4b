"""Success of each method on episode sets run before and after a change, paired episode by episode.

    .venv/bin/python experiments/before_after.py "J (48)=runs/J-before,runs/J-after" "K (24)=runs/K-before,runs/K-after"

Each argument is NAME=BEFORE_RUN,AFTER_RUN (`ragnav eval --out` folders over the same episodes); each cell reads
"before -> after (episodes won / lost, exact two-sided sign test p)". Prints a markdown table.
"""
import json, sys
from math import comb
from pathlib import Path
M = [("ragnav", "**RAGNav**"), ("etpnav", "ETPNav-style"), ("graphrag", "GraphRAG-style"), ("lightrag", "LightRAG-style"),
     ("naive_rag", "NaiveRAG-style"), ("remembr", "ReMEmbR-style"), ("oracle", "Oracle (reads no instruction)")]
def rows(run, m):
    return {json.loads(l)["episode"]: json.loads(l)["success"] for l in open(Path(run) / "eval" / m / "episodes.jsonl")}
def p(w, l):
    n, k = w + l, min(w, l)
    return 1.0 if n == 0 else min(1.0, 2 * sum(comb(n, i) for i in range(k + 1)) / 2 ** n)
sets = [a.split("=") for a in sys.argv[1:]]  # name=before_run,after_run
out = ["| method | " + " | ".join(n for n, _ in sets) + " |", "|---|" + "---|" * len(sets)]
for m, label in M:
    cells = []
    for n, runs in sets:
        b, a = (rows(r, m) for r in runs.split(","))
        won = sum(a[e] and not b[e] for e in a); lost = sum(b[e] and not a[e] for e in a)
        sb, sa = sum(b.values()) / len(b), sum(a.values()) / len(a)
        cells.append(f"{sb:.3f} -> {sa:.3f} ({won} / {lost}, p {p(won, lost):.2g})")
    out.append(f"| {label} | " + " | ".join(cells) + " |")
print("\n".join(out))
