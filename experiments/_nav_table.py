"""Shared by table_navigation.py and table_ablation.py: run `ragnav eval` for some methods on a run
folder, then print the measured table beside the paper's numbers and save a grouped bar plot."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from ragnav_jax.cli import main as cli_main


def parser(doc: str, default_out: str) -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--run", default="runs/paper", help="run folder with scenes/, explore/ and memory/bank")
    p.add_argument("--episodes", help="episodes .jsonl (default RUN/episodes.jsonl)")
    p.add_argument("--config", default="configs/paper.yaml")
    p.add_argument("--out", default=default_out, help="output run folder (eval results, table, plot)")
    p.add_argument("--stride", type=int, default=1, help="every N-th episode only (an even subsample)")
    p.add_argument("--reuse", action="store_true", help="reuse OUT/eval/<method>/summary.json where present")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                   help="config override passed to `ragnav eval` (repeatable), e.g. eval.retries=0")
    return p


def run_methods(args, methods: list[str]) -> dict[str, dict]:
    """summary.json of every method (running `ragnav eval` for those missing or not reused)."""
    out = Path(args.out)
    episodes = args.episodes or str(Path(args.run) / "episodes.jsonl")
    todo = [m for m in methods if not (args.reuse and (out / "eval" / m.replace(":", "_") / "summary.json").is_file())]
    if todo:  # one call: the executor is compiled once for every method; OUT is this script's (--force)
        rc = cli_main(["eval", "--config", args.config, "--scenes", args.run, "--episodes", episodes,
                       "--method", ",".join(todo), "--stride", str(args.stride), "--out", str(out), "--quiet",
                       "--force", *args.set])
        if rc:
            raise SystemExit(f"ragnav eval --method {','.join(todo)} failed (exit {rc})")
    return {m: json.loads((out / "eval" / m.replace(":", "_") / "summary.json").read_text()) for m in methods}


def episode_rows(args, method: str) -> list[dict]:
    path = Path(args.out) / "eval" / method.replace(":", "_") / "episodes.jsonl"
    return [json.loads(line) for line in path.read_text().splitlines() if line.strip()]


def fmt(x, nd=2) -> str:
    return "-" if x is None else f"{x:.{nd}f}"


def write_table(rows: list[list[str]], header: list[str], path: Path) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    text = "\n".join(lines) + "\n"
    path.write_text(text)
    return text


def bar_plot(labels: list[str], series: dict[str, tuple[list, list]], path: Path, title: str) -> None:
    """One panel per metric: measured vs paper bars per method. series: metric -> (measured, paper)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    fig, axes = plt.subplots(1, len(series), figsize=(4.2 * len(series), 3.6))
    x = np.arange(len(labels))
    for ax, (metric, (ours, paper)) in zip(np.atleast_1d(axes), series.items()):
        ax.bar(x - 0.2, [v if v is not None else 0 for v in ours], 0.4, label="measured")
        ax.bar(x + 0.2, [v if v is not None else 0 for v in paper], 0.4, label="paper")
        ax.set_xticks(x, labels, rotation=30, ha="right", fontsize=8)
        ax.set_title(metric, fontsize=9)
    np.atleast_1d(axes)[0].legend(fontsize=8)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
