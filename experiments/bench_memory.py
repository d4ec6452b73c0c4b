"""Benchmark: memory-build time per scene by stage, and encoder throughput (embeddings per second).

    python experiments/bench_memory.py --run RUN [--out DIR] [KEY=VALUE ...]

RUN holds scenes/ and explore/streams/ (`ragnav generate` + `ragnav explore`). With --synthetic instead of
streams, the test suite's synthetic tour (tests/test_memory_streams.py) stands in for the explorer.

Every timed call runs after a warm-up call of the same shapes, so compile time is not counted; timing is
host-side wall clock around calls that block on their results. Writes DIR/bench_memory.json (default
RUN/bench/).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import sys
import time
from pathlib import Path

os.environ.setdefault("HF_HUB_OFFLINE", "1")


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--run", required=True)
    p.add_argument("--out", default=None)
    p.add_argument("--config", default=None)
    p.add_argument("--synthetic", action="store_true", help="tour streams from the test helper instead of RUN/explore")
    p.add_argument("--embed-texts", type=int, default=512, help="distinct captions for the throughput test")
    p.add_argument("overrides", nargs="*")
    args = p.parse_args(argv)

    import jax
    import numpy as np

    from ragnav_jax.config import load_config, to_dict
    from ragnav_jax.memory.build import STAGES, build_bank, memory_summary
    from ragnav_jax.memory.encoder import HashingEmbedder, TextCache, make_embedder
    from ragnav_jax.runs import package_versions

    cfg = load_config(args.config, args.overrides)
    run = Path(args.run)
    if args.synthetic:
        from ragnav_jax.world.scene import load_scene_set

        sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
        from test_memory_streams import synthetic_stream

        scenes = load_scene_set(run / "scenes")
        streams = [synthetic_stream(s) for s in scenes]
    else:
        from ragnav_jax.memory.commands import load_run_inputs

        scenes, streams = load_run_inputs(run)
    m = cfg.memory
    embedder = make_embedder(m.embedder, dim=m.hashing_dim, batch_size=m.embed_batch, buckets=m.token_buckets)

    # Whole set in one batched build (the CLI's path): warm-up, then timed with a cold text cache.
    build_bank(scenes, streams, cfg, embedder=embedder)
    embedder.cache = TextCache()
    t0 = time.perf_counter()
    bank, stats = build_bank(scenes, streams, cfg, embedder=embedder)
    batched_total = time.perf_counter() - t0
    summary = memory_summary(bank)

    # Per scene (B = 1): warm-up then timed, cold cache each time.
    per_scene = []
    for scene, stream in zip(scenes, streams):
        build_bank([scene], [stream], cfg, embedder=embedder)
        embedder.cache = TextCache()
        t0 = time.perf_counter()
        b1, s1 = build_bank([scene], [stream], cfg, embedder=embedder)
        total = time.perf_counter() - t0
        row = {"scene": scene.name, "nodes": b1.metas[0].num_nodes, "records": int(stream.pose.shape[0]),
               "total_s": round(total, 4)}
        row.update({f"{k}_s": round(v, 4) for k, v in s1.stage_seconds.items()})
        per_scene.append(row)
        print(json.dumps(row))

    # Encoder throughput on distinct captions (cold cache, compiled shapes).
    texts = [c for meta in bank.metas for c in meta.captions]
    texts = [f"{t} (view {i})" for i, t in enumerate((texts * (args.embed_texts // max(len(texts), 1) + 1))[: args.embed_texts])]
    throughput = {}
    for name, emb in (("minilm" if m.embedder == "minilm" else m.embedder, embedder), ("hashing", HashingEmbedder(m.hashing_dim))):
        emb.embed(texts[:64])  # compile the buckets in use
        emb.cache = TextCache()
        t0 = time.perf_counter()
        out = emb.embed(texts)
        dt = time.perf_counter() - t0
        throughput[name] = {"texts": len(texts), "seconds": round(dt, 4), "embeddings_per_s": round(len(texts) / dt, 1),
                            "dim": int(out.shape[1])}
        print(name, throughput[name])

    mean = {f"{k}_s": round(float(np.mean([r[f"{k}_s"] for r in per_scene])), 4) for k in STAGES}
    result = {
        "what": "memory build time per scene by stage (B=1 builds) and for the whole set in one batched build",
        "run": str(run), "streams": "synthetic tour" if args.synthetic else "ragnav explore",
        "device": str(jax.devices()[0]), "cpu_count": os.cpu_count(), "platform": platform.platform(),
        "packages": package_versions(), "memory_config": to_dict(m),
        "num_scenes": len(scenes), "mean_nodes": summary["mean_nodes"],
        "per_scene": per_scene, "per_scene_mean": mean,
        "per_scene_mean_total_s": round(float(np.mean([r["total_s"] for r in per_scene])), 4),
        "batched": {"total_s": round(batched_total, 4), **{f"{k}_s": round(v, 4) for k, v in stats.stage_seconds.items()}},
        "throughput": throughput,
    }
    out = Path(args.out) if args.out else run / "bench"
    out.mkdir(parents=True, exist_ok=True)
    (out / "bench_memory.json").write_text(json.dumps(result, indent=1) + "\n")
    print(f"per-scene mean by stage: {mean}")
    print(f"written {out / 'bench_memory.json'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
