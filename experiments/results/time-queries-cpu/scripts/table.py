"""table.py ROOT [ROOT_FRESH1 ROOT_FRESH2 ROOT_FRESH3]: markdown table of the time-indexed measure (measure.sh)."""
import json
import sys
from pathlib import Path

root = Path(sys.argv[1])
fresh = {f"heldout{k if k > 1 else ''}": Path(p) for k, p in enumerate(sys.argv[2:], start=1)}
HOUSES = {"seen-t": "seen split", "unseen2-t": "fixed unseen", "unseen3": "fresh unseen"}
print("| houses | phrasing | RAGNav top-1 (instance) | fresh run | time term off | NaiveRAG-style | parse agreement |")
print("|---|---|---|---|---|---|---|")
for run, name in HOUSES.items():
    for ph in ("seen", "heldout", "heldout2", "heldout3"):
        d = root / "time" / f"{run}-{ph}"
        s = json.loads((d / "retrieve" / "summary.json").read_text())
        fr = "-"
        if ph in fresh and (f := fresh[ph] / "time" / f"{run}-{ph}" / "retrieve" / "summary.json").exists():
            x = json.loads(f.read_text())
            fr = f"{x['retrieval_accuracy']:.3f} ({x.get('instance_accuracy', float('nan')):.3f})"
        off = json.loads((d / "retrieve-notime" / "summary.json").read_text())
        nv = json.loads((d / "retrieve-naive_rag" / "summary.json").read_text())
        ag = json.loads((d / "check-parse.json").read_text()) if (d / "check-parse.json").exists() else None
        agree = f"{ag['agree']}/{ag['instructions']}" if ag else "-"
        print(f"| {name} | {ph} | {s['retrieval_accuracy']:.3f} ({s['instance_accuracy']:.3f}) | {fr} | "
              f"{off['retrieval_accuracy']:.3f} ({off['instance_accuracy']:.3f}) | {nv['retrieval_accuracy']:.3f} | {agree} |")
