"""`ragnav bench`: runs the sections of a profile, writes RUN/bench.json (machine, versions, every
figure and comparison) after each section so a killed run keeps what it measured, then RUN/bench.md
with plots.
"""

from __future__ import annotations

import datetime as _dt
import json
import time
import traceback
from collections.abc import Callable, Sequence
from pathlib import Path

from ragnav_jax.bench.profiles import SECTIONS, Profile
from ragnav_jax.bench.sections import SECTION_FUNCS, Unavailable
from ragnav_jax.bench.timing import machine, max_rss_mb
from ragnav_jax.io import write_text

NOTE = ("Timings are host wall clock around calls that block on their results, after warm-up, the median of "
        "several repeats with min and max; compile time is reported apart. Every ratio is peer time / our time on "
        "the same work in this run (> 1: ours is faster). Python and networkx baselines time a sample of the "
        "episodes or graphs and are extrapolated linearly (the comparison says from how many).")


def _jsonable(x):
    import numpy as np

    if isinstance(x, dict):
        return {str(k): _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, (np.floating, np.integer, np.bool_)):
        return x.item()
    if isinstance(x, np.ndarray):
        return x.tolist()
    if isinstance(x, float) and not np.isfinite(x):
        return None
    return x


def run_suite(out: str | Path, profile: Profile, only: Sequence[str] = (), log: Callable[[str], None] = print,
              notes: str = "", argv: Sequence[str] | None = None) -> dict:
    """Runs the profile's sections (all, or `only`), writing out/bench.json and out/bench.md; returns the doc."""
    from ragnav_jax.bench.report import write_report
    from ragnav_jax.runs import git_commit, package_versions

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    names = [s for s in SECTIONS if not only or s in only]
    doc = {
        "benchmark": "ragnav bench", "profile": profile.name, "profile_settings": _jsonable(vars(profile)),
        "time": _dt.datetime.now().isoformat(timespec="seconds"), "argv": list(argv or []), "git_commit": git_commit(),
        "machine": machine(), "packages": _pkg_versions(package_versions()), "note": NOTE, "notes": notes,
        "sections": {}, "comparisons": [],
    }
    from ragnav_jax.bench import sections

    def save():
        doc["comparisons"] = [c for s in doc["sections"].values() for c in s.get("comparisons", [])]
        doc["total_wall_s"] = time.perf_counter() - t_all
        doc["process_max_rss_mb"] = max_rss_mb()
        write_text(out / "bench.json", json.dumps(_jsonable(doc), indent=1) + "\n")

    t_all = time.perf_counter()
    for name in names:
        sections.partial_hook = lambda res, name=name: (doc["sections"].__setitem__(name, {**res, "status": "partial"}),
                                                        save())
        log(f"== {name}")
        t0, c0 = time.perf_counter(), time.process_time()
        try:
            res = SECTION_FUNCS[name](profile, log)
            res["status"] = "ok"
        except Unavailable as e:
            res = {"status": "not available", "reason": str(e)}
            log(f"{name}: not available ({e})")
        except Exception as e:  # one failing section must not lose the others' figures
            res = {"status": "failed", "reason": f"{type(e).__name__}: {e}", "traceback": traceback.format_exc()}
            log(f"{name}: FAILED {type(e).__name__}: {e}")
        res["section_wall_s"] = time.perf_counter() - t0
        res["section_cpu_s"] = time.process_time() - c0  # / wall: cores this process got (machine load)
        doc["sections"][name] = res
        save()
    sections.partial_hook = None
    write_report(doc, out)
    log(f"wrote {out / 'bench.json'} and {out / 'bench.md'} ({doc['total_wall_s']:.0f} s)")
    return doc


def _pkg_versions(base: dict) -> dict:
    from importlib import metadata

    for name in ("faiss-cpu", "psutil", "jax-cuda12-plugin", "jax-cuda13-plugin"):
        try:
            base[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            pass
    return base


ROW_KEYS = {"retrieval": "nodes", "paths": "nodes", "simulation": "batch"}  # one row per size in these sections


def _merge_section(old: dict | None, new: dict, key: str | None) -> dict:
    """A section seen in two runs: the later replaces it, except that sections with one row per size (key)
    combine their measured rows, the later winning per size (e.g. 1M nodes run apart from the smaller sizes),
    and a later failure keeps the earlier measurement."""
    if old is None:
        return new
    if new.get("status") == "failed":  # a later failure does not erase an earlier measurement
        return old if old.get("rows") or old.get("status") == "ok" else new
    if key is None or not old.get("rows"):
        return new
    rows = {r[key]: r for r in old["rows"]}
    rows.update({r[key]: r for r in new.get("rows", [])})
    comps = {c["name"]: c for c in old.get("comparisons", [])}
    comps.update({c["name"]: c for c in new.get("comparisons", [])})
    merged = {**new, "rows": sorted(rows.values(), key=lambda r: r[key]), "comparisons": list(comps.values())}
    merged["section_wall_s"] = old.get("section_wall_s", 0.0) + new.get("section_wall_s", 0.0)
    merged["section_cpu_s"] = old.get("section_cpu_s", 0.0) + new.get("section_cpu_s", 0.0)
    merged["merged_statuses"] = [*old.get("merged_statuses", [old.get("status")]), new.get("status")]
    if new.get("status") == "ok" and old.get("status") in ("ok", "partial"):
        merged["status"] = "ok"  # every row present is a complete measurement; the statuses are kept above
    return merged


def merge_runs(out: str | Path, parts: Sequence[str | Path], log: Callable[[str], None] = print) -> dict:
    """One report from several runs' bench.json (e.g. one `--only` section per command on a machine that
    limits command length): sections of later parts win; the machine and settings of the first part are
    kept and each part's are listed under `parts`."""
    from ragnav_jax.bench.report import write_report

    docs = [json.loads((Path(p) / "bench.json").read_text()) for p in parts]
    doc = dict(docs[0])
    doc["sections"] = {}
    for d in docs:
        for name, sec in d["sections"].items():
            doc["sections"][name] = _merge_section(doc["sections"].get(name), sec, ROW_KEYS.get(name))
    doc["comparisons"] = [c for s in doc["sections"].values() for c in s.get("comparisons", [])]
    doc["total_wall_s"] = sum(d.get("total_wall_s", 0.0) for d in docs)
    doc["process_max_rss_mb"] = max(d.get("process_max_rss_mb", 0.0) for d in docs)
    doc["parts"] = [{"run": str(p), "profile": d["profile"], "time": d["time"], "sections": list(d["sections"]),
                     "machine": d["machine"], "total_wall_s": d.get("total_wall_s")} for p, d in zip(parts, docs)]
    doc["profile"] = "+".join(dict.fromkeys(d["profile"] for d in docs))
    doc["notes"] = " ".join(dict.fromkeys(d.get("notes", "") for d in docs if d.get("notes")))
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    write_text(out / "bench.json", json.dumps(_jsonable(doc), indent=1) + "\n")
    write_report(doc, out)
    log(f"merged {len(docs)} runs into {out / 'bench.json'} and {out / 'bench.md'}")
    return doc
