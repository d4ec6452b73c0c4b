"""How many XLA programs one `ragnav eval` compiles, and where (a benchmark, not a test).

    .venv/bin/python experiments/bench_compiles.py --out DIR -- eval --config configs/default.yaml \
        --scenes runs/demo --episodes runs/demo/episodes.jsonl --method ragnav,oracle,etpnav,naive_rag --out X --force

Runs the given `ragnav` command in this process and counts JAX's backend compilations (jax.monitoring),
their seconds, and the source line in ragnav_jax that triggered each; writes DIR/compiles.json. Counts are
exact; seconds vary with the machine's load.
"""

from __future__ import annotations

import argparse
import collections
import json
import sys
import time
import traceback
from pathlib import Path

from jax import monitoring


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("command", nargs=argparse.REMAINDER, help="the ragnav command, after --")
    args = ap.parse_args()
    cmd = args.command[1:] if args.command[:1] == ["--"] else args.command
    sites, seconds = collections.Counter(), [0.0]

    def on(event: str, dur: float, **kw) -> None:
        if "backend_compile" in event:
            frames = [f for f in traceback.extract_stack() if "/ragnav_jax/" in f.filename]
            site = f"{frames[-1].filename.split('/ragnav_jax/')[1]}:{frames[-1].lineno}" if frames else "outside"
            sites[site] += 1
            seconds[0] += dur

    monitoring.register_event_duration_secs_listener(on)
    from ragnav_jax.cli import main as ragnav

    t0 = time.perf_counter()
    rc = ragnav(cmd)
    report = {"command": cmd, "rc": rc, "compilations": sum(sites.values()), "compile_s": round(seconds[0], 2),
              "wall_s": round(time.perf_counter() - t0, 2), "by_site": dict(sites.most_common())}
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "compiles.json").write_text(json.dumps(report, indent=1) + "\n")
    print(f"{report['compilations']} compilations, {report['compile_s']} s compiling, {report['wall_s']} s wall",
          file=sys.stderr)


if __name__ == "__main__":
    main()
