"""Run folders: every run writes its outputs next to its resolved config, git commit and versions."""

from __future__ import annotations

import datetime as _dt
import json
import platform
import subprocess
import sys
from importlib import metadata
from pathlib import Path

from ragnav_jax.config import Config, dump_yaml

TRACKED_PACKAGES = (
    "ragnav-jax", "jax", "jaxlib", "mujoco", "mujoco-mjx", "brax", "flax", "optax", "orbax-checkpoint",
    "numpy", "scipy", "networkx", "matplotlib", "pandas",
)


def package_versions(names: tuple[str, ...] = TRACKED_PACKAGES) -> dict[str, str]:
    """Installed version of each distribution in `names` ('not installed' where absent)."""
    out = {}
    for name in names:
        try:
            out[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            out[name] = "not installed"
    return out


def git_commit() -> str:
    """The commit of the source tree this package was imported from ('unknown' outside git)."""
    here = Path(__file__).resolve().parent
    try:
        sha = subprocess.run(["git", "rev-parse", "HEAD"], cwd=here, capture_output=True, text=True, timeout=5)
        dirty = subprocess.run(["git", "status", "--porcelain"], cwd=here, capture_output=True, text=True, timeout=5)
    except (OSError, subprocess.SubprocessError):
        return "unknown"
    if sha.returncode != 0:
        return "unknown"
    return sha.stdout.strip() + ("+dirty" if dirty.stdout.strip() else "")


def default_run_dir(cfg: Config, command: str) -> Path:
    stamp = _dt.datetime.now().strftime("%Y%m%d-%H%M%S")
    return Path(cfg.run.root) / f"{command}-{stamp}"


def init_run(run_dir: str | Path, cfg: Config, command: str, argv: list[str] | None = None) -> Path:
    """Creates the run folder and records the resolved config and provenance.

    A stage's config goes to `config.yaml` the first time and `config.<command>.yaml` for later stages
    that reuse the folder, so nothing earlier is overwritten.
    """
    run_dir = Path(run_dir)
    run_dir.mkdir(parents=True, exist_ok=True)
    cfg_path = run_dir / "config.yaml"
    if cfg_path.exists():
        cfg_path = run_dir / f"config.{command}.yaml"
    cfg_path.write_text(dump_yaml(cfg))
    info = {
        "command": command,
        "argv": list(sys.argv if argv is None else argv),
        "time": _dt.datetime.now().isoformat(timespec="seconds"),
        "git_commit": git_commit(),
        "python": platform.python_version(),
        "platform": platform.platform(),
        "packages": package_versions(),
    }
    info_path = run_dir / "run_info.json"
    history = []
    if info_path.exists():
        try:
            history = json.loads(info_path.read_text()).get("history", [])
        except (json.JSONDecodeError, AttributeError):
            history = []
    history.append(info)
    info_path.write_text(json.dumps({**info, "history": history}, indent=1) + "\n")
    return run_dir
