"""CLI subcommand `ragnav bench`: the benchmark suite (ragnav_jax/bench), thin argument parsing only."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path


def cmd_bench(args, cfg) -> int:
    import os

    from ragnav_jax.bench.profiles import PROFILES, SECTIONS, scaled
    from ragnav_jax.bench.suite import run_suite
    from ragnav_jax.errors import UserError

    os.environ.setdefault("HF_HUB_OFFLINE", "1")
    if args.quick and args.gpu:
        raise UserError("--quick and --gpu are different profiles; pick one (scale the GPU one with --scale)")
    bad = [s for s in args.only or [] if s not in SECTIONS]
    if bad:
        raise UserError(f"--only: unknown section(s) {', '.join(bad)} (known: {', '.join(SECTIONS)})")
    if args.merge:
        from ragnav_jax.bench.suite import merge_runs

        missing = [d for d in args.merge if not (Path(d) / "bench.json").is_file()]
        if missing:
            raise UserError(f"--merge: no bench.json in {', '.join(missing)}")
        merge_runs(args.out, args.merge, log=print)
        return 0
    profile = PROFILES["gpu" if args.gpu else "quick" if args.quick else "full"]
    profile = scaled(profile, args.scale)
    if args.set:
        profile = override_profile(profile, args.set)
    log = (lambda m: None) if args.quiet else (lambda m: print(m, flush=True))
    doc = run_suite(args.out, profile, args.only or (), log=log, notes=args.notes, argv=sys.argv)
    failed = [k for k, v in doc["sections"].items() if v["status"] == "failed"]
    if failed:
        raise UserError(f"section(s) failed: {', '.join(failed)} (tracebacks in {args.out}/bench.json)")
    return 0


def register(sub: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    from ragnav_jax.argtypes import positive_float
    from ragnav_jax.bench.profiles import SECTIONS

    p = sub.add_parser("bench", parents=[common], help="benchmark suite with peer comparisons -> RUN/bench.json, bench.md")
    p.add_argument("--out", required=True, help="run folder for bench.json, bench.md and plots")
    p.add_argument("--quick", action="store_true", help="smaller sizes (about 2 minutes on a 2-core CPU)")
    p.add_argument("--gpu", action="store_true", help="GPU-sized profile (1M nodes/queries, 16384 envs, 1024 scenes)")
    p.add_argument("--scale", type=positive_float, default=1.0, help="multiply every size of the profile (e.g. --gpu --scale 0.001)")
    p.add_argument("--only", nargs="+", metavar="SECTION", help=f"run only these sections ({', '.join(SECTIONS)})")
    p.add_argument("--notes", default="", help="free text stored in the report (e.g. machine load)")
    p.add_argument("--set", action="append", default=[], metavar="FIELD=VALUE",
                   help="override a profile field, e.g. --set e2e_embedder=hashing --set sim_batches=1,64 (bench/profiles.py)")
    p.add_argument("--merge", nargs="+", metavar="RUN", help="combine earlier runs' bench.json into --out (later wins)")
    p.set_defaults(func=cmd_bench, overrides_allowed=False)


def override_profile(profile, items: list[str]):
    """The profile with FIELD=VALUE overrides applied, values read as YAML and checked against the field's
    annotation by the config's own coercion (tuples may be written bare: sim_batches=1,64; none: None)."""
    import dataclasses
    import typing

    import yaml

    from ragnav_jax.config import _coerce
    from ragnav_jax.errors import UserError

    hints = typing.get_type_hints(type(profile))
    changes = {}
    for item in items:
        key, sep, raw = item.partition("=")
        if not sep or key not in hints or key == "name":
            known = ", ".join(f.name for f in dataclasses.fields(profile) if f.name != "name")
            raise UserError(f"--set {item!r}: expected FIELD=VALUE with FIELD one of {known}")
        text = "null" if raw.strip().lower() == "none" else raw
        if typing.get_origin(hints[key]) is tuple and not text.lstrip().startswith("["):
            text = f"[{text}]"
        try:
            value = yaml.safe_load(text)
        except yaml.YAMLError:
            raise UserError(f"--set {key}={raw!r}: cannot read the value") from None
        changes[key] = _coerce(value, hints[key], f"--set {key}")
    return profile.replace(name=profile.name + "+set", **changes)
