"""table.py ROOT [FRESH]: markdown table of the time-indexed measure (measure.sh under ROOT; fresh.sh under FRESH).

Parse agreement is the reader's at the code this runs with (PYTHONPATH): head noun, room and time of the goal."""
import json
import sys
from pathlib import Path

from ragnav_jax.language.agreement import chain_differences
from ragnav_jax.language.episodes import load_truth
from ragnav_jax.language.parser import parse_instruction
from ragnav_jax.language.types import ParseError

root = Path(sys.argv[1])
fresh = Path(sys.argv[2]) if len(sys.argv) > 2 else None
HOUSES = {"seen-t": "seen split", "unseen2-t": "fixed unseen", "unseen3": "fresh unseen"}
PHRASINGS = [p for p in ("seen", "heldout", "heldout2", "heldout3", "heldout4")
             if (root / "time" / f"seen-t-{p}").exists()]


def acc(path: Path) -> str:
    if not path.exists():
        return "-"
    s = json.loads(path.read_text())
    inst = s.get("instance_accuracy")
    return f"{s['retrieval_accuracy']:.3f}" + (f" ({inst:.3f})" if inst is not None else "")


def agreement(d: Path) -> str:
    truth = load_truth(d / "episodes.chains.jsonl")
    ok = n = 0
    for line in (d / "episodes.jsonl").read_text().splitlines():
        ep = json.loads(line)
        n += 1
        try:
            ok += not chain_differences(parse_instruction(ep["instruction"]), truth[ep["id"]])
        except ParseError:
            pass
    return f"{ok}/{n}"


print("| houses | phrasing | RAGNav top-1 (instance) | fresh run | time term off | NaiveRAG-style "
      "| whole chain parsed |")
print("|---|---|---|---|---|---|---|")
for run, name in HOUSES.items():
    for ph in PHRASINGS:
        d = root / "time" / f"{run}-{ph}"
        fr = acc(fresh / f"{run}-{ph}" / "retrieve" / "summary.json") if fresh and ph != "seen" else "-"
        print(f"| {name} | {ph} | {acc(d / 'retrieve' / 'summary.json')} | {fr} | "
              f"{acc(d / 'retrieve-notime' / 'summary.json')} | {acc(d / 'retrieve-naive_rag' / 'summary.json')} | "
              f"{agreement(d)} |")
