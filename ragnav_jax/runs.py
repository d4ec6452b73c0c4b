"""Run folders: every run writes its outputs next to its resolved config, git commit and versions."""

from __future__ import annotations

import contextlib
import contextvars
import datetime as _dt
import json
import platform
import subprocess
import sys
from collections.abc import Iterator
from importlib import metadata
from pathlib import Path

from ragnav_jax.config import Config, dump_yaml
from ragnav_jax.io import write_json, write_text

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
    created = not run_dir.exists()
    run_dir.mkdir(parents=True, exist_ok=True)
    if created and (new_runs := _NEW_RUNS.get()) is not None:
        new_runs.append(run_dir)
    cfg_path = run_dir / "config.yaml"
    if cfg_path.exists():
        cfg_path = run_dir / f"config.{command}.yaml"
    write_text(cfg_path, dump_yaml(cfg))
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
        except (ValueError, AttributeError):  # not JSON, not text, not an object: start the history afresh
            history = []
    history.append(info)
    write_json(info_path, {**info, "history": history})
    return run_dir


# Run folders created by init_run inside `discard_failed_runs` (None outside it).
_NEW_RUNS: contextvars.ContextVar[list[Path] | None] = contextvars.ContextVar("ragnav_new_runs", default=None)
PROVENANCE = ("config.yaml", "config.*.yaml", "run_info.json")  # what init_run writes: no results


@contextlib.contextmanager
def discard_failed_runs() -> Iterator[None]:
    """Within this block, a run folder that init_run creates is removed again when the block raises
    before any result is written (the folder holds only init_run's provenance files and empty folders),
    so a command failing on a bad setting leaves no empty run behind. A folder holding anything else
    (a checkpoint to resume from, a partial result) is kept."""
    new_runs: list[Path] = []
    token = _NEW_RUNS.set(new_runs)
    try:
        yield
    except BaseException:
        for run in new_runs:
            _remove_if_no_results(run)
        raise
    finally:
        _NEW_RUNS.reset(token)


def _remove_if_no_results(run: Path) -> None:
    entries = sorted(run.rglob("*"), key=lambda p: len(p.parts), reverse=True)  # deepest first
    files = [p for p in entries if not p.is_dir()]
    if any(p.parent != run or not any(p.match(g) for g in PROVENANCE) for p in files):
        return
    with contextlib.suppress(OSError):
        for p in entries:
            if p.is_dir():
                p.rmdir()
            else:
                p.unlink()
        run.rmdir()


def refuse_overwrite(paths, force: bool, flag: str = "--force") -> None:
    """Raises UserError naming the first of `paths` that exists, unless `force`: a command checks every output
    it is about to write before it starts, so earlier results are never replaced silently."""
    from ragnav_jax.errors import UserError

    existing = [Path(p) for p in paths if p is not None and Path(p).exists()]
    if existing and not force:
        more = f" (and {len(existing) - 1} more output(s))" if len(existing) > 1 else ""
        raise UserError(f"{existing[0]}: exists{more}; pass {flag} to overwrite, or choose another output")


def scene_source(path: str | Path) -> tuple[Path, Path | None]:
    """(scenes folder or file, run folder or None): accepts RUN, RUN/scenes or any scene folder/file."""
    p = Path(path)
    if p.is_dir() and (p / "scenes").is_dir():
        return p / "scenes", p
    if p.is_dir() and p.name == "scenes" and (p.parent / "config.yaml").exists():
        return p, p.parent
    return p, None


def run_file(run_dir: str | Path, *parts: str) -> Path:
    """RUN_DIR/parts[0]/parts[1]/..., each part one safe file name and the result inside RUN_DIR (UserError
    otherwise): the path of every output whose name comes from user data (scene names, ids)."""
    from ragnav_jax.errors import UserError
    from ragnav_jax.filenames import inside, name_problem

    for p in parts:
        if problem := name_problem(p):
            raise UserError(f"{Path(run_dir).joinpath(*parts)}: output name {problem}")
    return inside(run_dir, Path(run_dir).joinpath(*parts))
