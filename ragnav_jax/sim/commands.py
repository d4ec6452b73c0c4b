"""CLI subcommands of the simulation stage: explore, show-trajectory."""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from ragnav_jax.errors import UserError
from ragnav_jax.io import atomic_open, write_bytes, write_json
from ragnav_jax.runs import default_run_dir, init_run, refuse_overwrite, run_file
from ragnav_jax.tables import write_table

MAP_KEYS = ("origin", "resolution", "grid_factor", "seen", "hit", "viewed", "frontier", "blocked", "true_pose")


def copy_scenes(files: list[Path], dest: Path) -> None:
    """Copies scene files into RUN/scenes; an existing file of the same name must be identical."""
    dest.mkdir(parents=True, exist_ok=True)
    for f in files:
        target = dest / f.name
        if target.resolve() == f.resolve():
            continue
        data = f.read_bytes()
        if target.exists():
            if target.read_bytes() != data:
                raise UserError(f"{target}: already exists and differs from {f}; choose another --out")
            continue
        write_bytes(target, data)


def scene_row(scene, result, cov, robot_radius: float = 0.0) -> dict:
    """One scene's summary row. Rooms count as entered when the true trajectory's centre passed at least
    `robot_radius` inside them; `rooms_not_entered` and `rooms_objects_unseen` list room ids."""
    from ragnav_jax.sim.coverage import room_objects_unseen, rooms_entered

    vis = result.stream.visible
    entered = rooms_entered(scene, result.true_pose, margin=robot_radius)  # (R,)
    unseen = room_objects_unseen(scene, vis)  # (R,)
    return {
        "scene": scene.name,
        "coverage": round(cov.fraction, 4),
        "reachable_area_m2": round(cov.reachable_area, 2),
        "covered_area_m2": round(cov.covered_area, 2),
        "rooms": len(scene.rooms),
        "rooms_entered": int(entered.sum()),
        "rooms_entered_share": round(float(entered.mean()) if entered.size else 1.0, 4),
        "rooms_not_entered": [r.id for r, e in zip(scene.rooms, entered) if not e],
        "path_length_m": round(result.path_length, 2),
        "steps": result.steps,
        "sim_time_s": round(result.steps * result.control_dt, 1),
        "records": int(result.stream.t.shape[0]),
        "finished": result.finished,
        "objects": len(scene.objects),
        "objects_seen": round(float(vis.any(0).mean()) if vis.shape[1] else 1.0, 4),
        "rooms_objects_unseen": [r.id for r, u in zip(scene.rooms, unseen) if u],
        "targets": result.plans,
        "targets_given_up": result.given_up,
        "max_penetration_m": round(result.max_penetration, 4),
    }


def cmd_explore(args, cfg) -> int:
    from ragnav_jax.sim.coverage import coverage
    from ragnav_jax.sim.explore import explore_scenes, explorer_for
    from ragnav_jax.sim.plot import save_exploration
    from ragnav_jax.sim.sensors import lidar_angles
    from ragnav_jax.world.limits import check_explore_fits
    from ragnav_jax.world.scene import load_scene_set, scene_files

    run = Path(args.out) if args.out else default_run_dir(cfg, "explore")
    source = Path(args.scenes) if args.scenes else run / "scenes"
    if not args.scenes and not source.exists():
        raise UserError(f"no --scenes given and {source} does not exist")
    files = scene_files(source)
    scenes = load_scene_set(source)
    check_explore_fits(scenes, cfg)  # sizes and memory, before anything is written or compiled
    stage = run / "explore"
    if (stage / "summary.json").exists() and not args.force:
        raise UserError(f"{stage}: already holds an exploration; pass --force to overwrite or choose another --out")
    copy_scenes(files, run / "scenes")
    init_run(run, cfg, "explore")
    t0 = time.perf_counter()
    explorer = explorer_for(scenes, cfg)
    results = explore_scenes(scenes, cfg, progress=not args.quiet, explorer=explorer)
    seconds = time.perf_counter() - t0  # host wall clock, compilation included
    angles = lidar_angles(cfg.sim)
    rows = []
    for scene, r in zip(scenes, results):
        r.stream.save(run_file(run, "explore", "streams", f"{scene.name}.npz"))
        cov = coverage(scene, r.true_pose, r.stream.lidar, angles, cfg.sim.robot_radius)
        maps = {k: getattr(r, k) for k in MAP_KEYS}
        map_file = run_file(run, "explore", "maps", f"{scene.name}.npz")
        with atomic_open(map_file, "wb") as f:
            np.savez_compressed(f, covered=cov.covered, reachable=cov.reachable, **maps)
        row = scene_row(scene, r, cov, cfg.sim.robot_radius)
        rows.append(row)
        if args.plots:
            save_exploration(scene, {**maps}, run_file(run, "explore", "plots", f"{scene.name}.png"),
                             title=f"{scene.name}: coverage {row['coverage']:.3f}, path {row['path_length_m']:.0f} m")
    write_table([{k: " ".join(v) if isinstance(v, list) else v for k, v in r.items()} for r in rows], stage / "summary_table")
    reach = sum(r["reachable_area_m2"] for r in rows)
    summary = {
        "num_scenes": len(rows),
        "coverage": round(float(np.mean([r["coverage"] for r in rows])), 4),
        "coverage_min": min(r["coverage"] for r in rows),
        "coverage_area_weighted": round(sum(r["covered_area_m2"] for r in rows) / reach, 4) if reach else 1.0,
        "path_length_m": round(sum(r["path_length_m"] for r in rows), 2),
        "mean_path_length_m": round(float(np.mean([r["path_length_m"] for r in rows])), 2),
        "steps": int(sum(r["steps"] for r in rows)),
        "rooms_entered_share": round(float(np.mean([r["rooms_entered_share"] for r in rows])), 4),
        "rooms_entered_share_min": min(r["rooms_entered_share"] for r in rows),
        "rooms_not_entered_count": sum(len(r["rooms_not_entered"]) for r in rows),
        "objects_seen": round(float(np.mean([r["objects_seen"] for r in rows])), 4),
        "rooms_objects_unseen_count": sum(len(r["rooms_objects_unseen"]) for r in rows),
        "max_penetration_m": max(r["max_penetration_m"] for r in rows),
        "all_finished": all(r["finished"] for r in rows),
        "control_hz": round(1.0 / (cfg.sim.timestep * cfg.sim.substeps), 3),
        "physics_hz": round(1.0 / cfg.sim.timestep, 3),
        "wall_seconds": round(seconds, 1),
        "scenes": rows,
    }
    write_json(stage / "summary.json", summary)
    print((stage / "summary_table.md").read_text())
    print(
        f"explored {len(rows)} scenes in {seconds:.0f} s: coverage mean {summary['coverage']:.3f} "
        f"(min {summary['coverage_min']:.3f}), rooms entered mean {summary['rooms_entered_share']:.3f} "
        f"({summary['rooms_not_entered_count']} never entered), streams in {stage / 'streams'}"
    )
    return 0


def load_explored(run: Path, name: str) -> tuple[object, dict]:
    """(scene, map arrays) of one explored scene of a run folder."""
    from ragnav_jax.sim.stream import NPZ_ERRORS
    from ragnav_jax.world.scene import load_scene_set

    path = run / "explore" / "maps" / f"{name}.npz"
    if not (run / "scenes").is_dir():
        raise UserError(f"{run}: no scenes/ folder (run `ragnav explore --out {run}` first)")
    scenes = {s.name: s for s in load_scene_set(run / "scenes")}
    if name not in scenes:
        raise UserError(f"{run}: no scene '{name}' (known: {', '.join(sorted(scenes))})")
    if not path.exists():
        raise UserError(f"{path}: not found (run `ragnav explore --out {run}` first)")
    try:
        with np.load(path, allow_pickle=False) as z:
            maps = {k: z[k] for k in (*MAP_KEYS, "covered", "reachable")}
    except NPZ_ERRORS as e:
        raise UserError(f"{path}: not a readable exploration map ({e.__class__.__name__})") from None
    return scenes[name], maps


def cmd_show_trajectory(args, cfg) -> int:
    from ragnav_jax.sim.plot import save_exploration

    run = Path(args.run)
    out = Path(args.out)
    if out.suffix.lower() not in (".png", ".pdf", ".svg"):
        raise UserError(f"--out {out}: use a .png, .pdf or .svg file name")
    refuse_overwrite([out], args.force)
    scene, maps = load_explored(run, args.scene)
    cov = maps["covered"][maps["reachable"]].mean() if maps["reachable"].any() else 1.0
    save_exploration(scene, maps, out, title=f"{scene.name}: coverage {cov:.3f}")
    print(f"trajectory of {scene.name} written to {out}")
    return 0


def register(sub: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    p = sub.add_parser("explore", parents=[common], help="explore scenes with the MJX robot (frontier exploration)")
    p.add_argument("--scenes", help="scene folder or file (default: RUN/scenes)")
    p.add_argument("--out", help="run folder (default: RUN_ROOT/explore-TIMESTAMP)")
    p.add_argument("--force", action="store_true", help="overwrite an earlier exploration in the run folder")
    p.add_argument("--no-plots", dest="plots", action="store_false", help="skip trajectory pictures")
    p.set_defaults(func=cmd_explore)

    p = sub.add_parser("show-trajectory", parents=[common], help="draw an explored scene: map, trajectory, frontiers")
    p.add_argument("run", metavar="RUN")
    p.add_argument("--scene", required=True, help="scene name")
    p.add_argument("--out", required=True, help="picture file (.png, .pdf, .svg)")
    p.add_argument("--force", action="store_true", help="overwrite an existing --out file")
    p.set_defaults(func=cmd_show_trajectory, overrides_allowed=False)
