"""Does one config and seed give one result? The whole pipeline twice, compared stage by stage.

    python experiments/gpu_determinism.py --out DIR [--config configs/default.yaml] [--methods ragnav,oracle]
                                          [KEY=VALUE ...]

Runs `generate`, `explore`, `build-memory`, `episodes` and `eval` twice, each stage in a fresh process, into
DIR/a and DIR/b, then compares them: the scene files (bytes), the exploration streams and the memory bank
(every array), the episodes file (bytes) and each method's episode rows (how many episodes differ in
success, found goals, steps or travel). Writes DIR/determinism.json with the JAX backend and XLA_FLAGS, so
a run with `XLA_FLAGS=--xla_gpu_deterministic_ops=true` can be set beside one without. Meant for a GPU (the
CPU backend is deterministic); run from the repository root.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

STAGES = ("generate", "explore", "build-memory", "episodes", "eval")


def _cli(args: list[str]) -> None:
    code = f"import sys; from ragnav_jax.cli import main; sys.exit(main({args!r}))"
    subprocess.run([sys.executable, "-c", code], check=True)


def run_pipeline(out: Path, config: str, methods: str, overrides: list[str]) -> None:
    c = ["--config", config]
    _cli(["generate", *c, "--out", str(out), "--force", "--quiet", *overrides])
    _cli(["explore", *c, "--out", str(out), "--force", "--quiet", "--no-plots", *overrides])
    _cli(["build-memory", *c, "--run", str(out), "--force", "--quiet", *overrides])
    _cli(["episodes", *c, "--scenes", str(out), "--out", str(out / "episodes.jsonl"), "--force", "--quiet", *overrides])
    _cli(["eval", *c, "--scenes", str(out), "--episodes", str(out / "episodes.jsonl"), "--method", methods,
          "--out", str(out), "--force", "--quiet", *overrides])


def _arrays_differ(a: dict, b: dict) -> list[str]:
    return sorted(k for k in set(a) | set(b) if k not in a or k not in b
                  or np.asarray(a[k]).shape != np.asarray(b[k]).shape or not np.array_equal(a[k], b[k]))


def compare(a: Path, b: Path, methods: list[str]) -> dict:
    from ragnav_jax.memory.checkpoint import load_bank

    out: dict = {}
    sa, sb = sorted((a / "scenes").glob("*.json")), sorted((b / "scenes").glob("*.json"))
    out["scenes_differ"] = [p.name for p, q in zip(sa, sb) if p.read_bytes() != q.read_bytes()] + (
        ["(count)"] if len(sa) != len(sb) else [])
    streams = {}
    for p in sorted((a / "explore" / "streams").glob("*.npz")):
        with np.load(p) as x, np.load(b / "explore" / "streams" / p.name) as y:
            d = _arrays_differ(dict(x), dict(y))
        if d:
            streams[p.stem] = d
    out["streams_differ"] = streams
    ba, bb = load_bank(a / "memory" / "bank"), load_bank(b / "memory" / "bank")
    fields = [f.name for f in dataclasses.fields(ba.memory)]
    out["memory_differ"] = _arrays_differ({k: np.asarray(getattr(ba.memory, k)) for k in fields},
                                          {k: np.asarray(getattr(bb.memory, k)) for k in fields})
    out["episodes_differ"] = (a / "episodes.jsonl").read_bytes() != (b / "episodes.jsonl").read_bytes()
    rows = {}
    for m in methods:
        ra = {json.loads(x)["episode"]: json.loads(x) for x in (a / "eval" / m / "episodes.jsonl").read_text().splitlines()}
        rb = {json.loads(x)["episode"]: json.loads(x) for x in (b / "eval" / m / "episodes.jsonl").read_text().splitlines()}
        keys = ("success", "goal_status", "steps", "travel_distance_m")
        rows[m] = {"episodes": len(ra), **{k: sum(ra[e][k] != rb.get(e, {}).get(k) for e in ra) for k in keys}}
    out["rows_differ"] = rows
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--config", default="configs/default.yaml")
    ap.add_argument("--methods", default="ragnav,oracle")
    ap.add_argument("overrides", nargs="*")
    args = ap.parse_args()
    out = Path(args.out)
    for k in ("a", "b"):
        run_pipeline(out / k, args.config, args.methods, args.overrides)
    import jax

    report = {"backend": jax.default_backend(), "devices": [str(d) for d in jax.devices()],
              "jax": jax.__version__, "xla_flags": os.environ.get("XLA_FLAGS", ""), "config": args.config,
              "overrides": args.overrides, **compare(out / "a", out / "b", args.methods.split(","))}
    (out / "determinism.json").write_text(json.dumps(report, indent=1) + "\n")
    print(json.dumps(report, indent=1))


if __name__ == "__main__":
    main()
