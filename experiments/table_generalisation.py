"""Seen and unseen splits side by side (the generalisation table).

    python experiments/table_generalisation.py --split seen=runs/eval-seen --split unseen=runs/eval-unseen \
        [--split paper=runs/eval-paper] --out runs/table_generalisation

Each --split names a `ragnav eval` output folder (OUT/eval/<method>/{summary.json, episodes.jsonl}) with
the same methods, or a folder of kept rows (<method>/episodes.jsonl.gz, as experiments/results keeps them);
several folders joined by commas are pooled into one split (`--split fresh=runs/AS,runs/AT`: their episodes
together, paired within each folder). For every split and method: success with a 95% Wilson interval, top-1 retrieval,
success on text+location+sensor episodes, wrong declarations, and the episode-paired comparison with
RAGNav (episodes only RAGNav succeeds on / only the method does, exact sign test p). Writes
OUT/table_generalisation.{md,csv,json}.
"""

from __future__ import annotations

import argparse
import csv
import gzip
import json
import sys
from pathlib import Path

from ragnav_jax.evaluation.metrics import paired_comparison, wilson_interval

BASE = "ragnav"


def _method_dirs(folder: Path) -> Path:
    """Where a folder keeps its methods: OUT/eval of an eval run, or the folder itself (kept rows)."""
    return folder / "eval" if (folder / "eval").is_dir() else folder


def _rows(folder: Path, method: str) -> list[dict]:
    d = _method_dirs(folder) / method.replace(":", "_")
    if (d / "episodes.jsonl").is_file():
        text = (d / "episodes.jsonl").read_text()
    else:
        text = gzip.decompress((d / "episodes.jsonl.gz").read_bytes()).decode()
    return [json.loads(x) for x in text.splitlines() if x.strip()]


def _methods(folder: Path) -> set[str]:
    if not folder.is_dir():
        return set()
    return {p.name.replace("_", ":", 1) if p.name.startswith("ragnav_") else p.name
            for p in _method_dirs(folder).iterdir()
            if (p / "episodes.jsonl").is_file() or (p / "episodes.jsonl.gz").is_file()}


def split_table(folders: Path | list[Path]) -> dict[str, dict]:
    """method -> figures for one eval folder, or for several pooled (episode ids prefixed by the folder's
    place, so that rows pair within a folder); methods: those every folder holds."""
    folders = [folders] if isinstance(folders, Path) else list(folders)
    methods = sorted(set.intersection(*(_methods(f) for f in folders)))
    if not methods:
        print(f"{','.join(map(str, folders))}: no method's episode rows (<method>/episodes.jsonl)", file=sys.stderr)
        raise SystemExit(2)
    if len(folders) == 1:
        rows = {m: _rows(folders[0], m) for m in methods}
    else:
        rows = {m: [{**r, "episode": f"{i}/{r['episode']}"} for i, f in enumerate(folders) for r in _rows(f, m)]
                for m in methods}
    out = {}
    for m, rs in rows.items():
        k, n = sum(r["success"] for r in rs), len(rs)
        tls = [r for r in rs if r["modality"] == "text+location+sensor"]
        top = [x for r in rs for x in r["retrieval_top1"] if x is not None]
        lo, hi = wilson_interval(k, n)  # kept to 4 places as the eval tables do: rounding twice moved 0.9145 to 0.92
        out[m] = {"episodes": n, "success": k / max(n, 1), "success_ci95": [round(lo, 4), round(hi, 4)],
                  "top1": sum(top) / len(top) if top else None,  # None: no retrieval (ETPNav-style)
                  "tls_success": sum(r["success"] for r in tls) / max(len(tls), 1), "tls_episodes": len(tls),
                  "wrong_declarations": sum(not d["correct"] for r in rs for d in r["declarations"])}
        if m != BASE and BASE in rows:
            out[m]["vs_ragnav"] = paired_comparison(rows[BASE], rs)
    return out


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--split", action="append", required=True, metavar="NAME=EVAL_FOLDER")
    p.add_argument("--out", default="runs/table_generalisation")
    args = p.parse_args(argv)
    splits = dict(s.split("=", 1) for s in args.split)
    res = {name: split_table([Path(f) for f in folders.split(",")]) for name, folders in splits.items()}
    methods = [m for m in next(iter(res.values())) if all(m in r for r in res.values())]
    methods = sorted(methods, key=lambda m: (m != BASE, m == "oracle", m))
    header = ["method"]
    for name in res:
        header += [f"{name}: success [95% CI]", f"{name}: top-1", f"{name}: TLS success", f"{name}: wrong decl.",
                   f"{name}: only RAGNav / only method (p)"]
    table = []
    for m in methods:
        row = [m]
        for r in res.values():
            f = r[m]
            c = f.get("vs_ragnav")
            row += [f"{f['success']:.3f} [{f['success_ci95'][0]:.2f}, {f['success_ci95'][1]:.2f}]",
                    "-" if f["top1"] is None else f"{f['top1']:.3f}",
                    f"{f['tls_success']:.3f}", str(f["wrong_declarations"]),
                    "-" if c is None else f"{c['success_wins']} / {c['success_losses']} ({c['success_p']:.2g})"]
        table.append(row)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)] + ["| " + " | ".join(r) + " |" for r in table]
    md = "\n".join(lines) + "\n" + "\n".join(f"- {n}: {splits[n]}, {next(iter(r.values()))['episodes']} episodes"
                                             for n, r in res.items()) + "\n"
    (out / "table_generalisation.md").write_text(md)
    with open(out / "table_generalisation.csv", "w", newline="") as fh:
        csv.writer(fh).writerows([header, *table])
    (out / "table_generalisation.json").write_text(json.dumps({"splits": splits, "results": res}, indent=1) + "\n")
    print(md)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
