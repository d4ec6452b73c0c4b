"""CLI subcommands of the world stage: generate, validate, show-scene, changes."""

from __future__ import annotations

import argparse
from collections import Counter
from pathlib import Path

from ragnav_jax.cli import PositionalsAndOverrides
from ragnav_jax.errors import UserError, printable
from ragnav_jax.io import write_json
from ragnav_jax.runs import default_run_dir, init_run, refuse_overwrite, run_file, scene_source
from ragnav_jax.tables import write_table


def scene_summary(scene) -> dict:
    from ragnav_jax.world.geometry import reachability

    counts = Counter(o.category for o in scene.objects)
    reach = reachability(scene)
    return {
        "scene": scene.name,
        "rooms": len(scene.rooms),
        "room_types": ", ".join(r.type for r in scene.rooms),
        "walls": len(scene.walls),
        "objects": len(scene.objects),
        "categories": len(counts),
        "distractor_categories": sum(1 for v in counts.values() if v >= 2),
        "floor_area_m2": round(sum(r.area for r in scene.rooms), 1),
        "reachable_area_m2": round(reach.reachable_area, 1),
        "all_rooms_reachable": all(reach.rooms_reachable.values()),
        "all_objects_reachable": all(reach.objects_reachable.values()),
    }


def cmd_generate(args, cfg) -> int:
    from ragnav_jax.world.generator import generate_scenes
    from ragnav_jax.world.plot import save_floor_plan
    from ragnav_jax.world.scene import save_scene

    run = Path(args.out) if args.out else default_run_dir(cfg, "generate")
    scenes_dir = run / "scenes"
    if scenes_dir.exists() and any(scenes_dir.iterdir()) and not args.force:
        raise UserError(f"{scenes_dir}: already holds scenes; pass --force to overwrite or choose another --out")
    init_run(run, cfg, "generate")
    scenes = generate_scenes(cfg.world, cfg.seed, progress=not args.quiet)
    for s in scenes:
        save_scene(s, run_file(run, "scenes", f"{s.name}.json"))
    stage = run / "generate"
    rows = [scene_summary(s) for s in scenes]
    write_table(rows, stage / "scenes_summary")
    totals = {
        "num_scenes": len(scenes),
        "mean_rooms": sum(r["rooms"] for r in rows) / len(rows),
        "mean_objects": sum(r["objects"] for r in rows) / len(rows),
        "all_reachable": all(r["all_rooms_reachable"] and r["all_objects_reachable"] for r in rows),
        "scenes": rows,
    }
    write_json(stage / "summary.json", totals)
    if args.plots:
        for s in scenes:
            save_floor_plan(s, run_file(run, "generate", "plots", f"{s.name}.png"))
    print((stage / "scenes_summary.md").read_text())
    print(f"{len(scenes)} scenes written to {scenes_dir}" + (f"; floor plans in {stage / 'plots'}" if args.plots else ""))
    return 0


def cmd_validate(args, cfg) -> int:
    """Checks scene files; reachability problems for a robot of `sim.robot_radius` are warnings on
    stderr (one line each), errors only with --strict."""
    import sys

    from ragnav_jax.errors import SceneError
    from ragnav_jax.world.blockers import lidar_blind, reach_warnings
    from ragnav_jax.world.limits import scene_size_problems
    from ragnav_jax.world.scene import load_scene, scene_files

    bad: list[SceneError] = []
    warned = {"size": 0, "reachability": 0}
    for src in args.paths:
        for f in scene_files(src):
            try:
                s = load_scene(f)
                print(f"ok   {f} ({s.name}: {len(s.rooms)} rooms, {len(s.walls)} walls, {len(s.objects)} objects)")
            except SceneError as e:
                print(f"FAIL {printable(e)}")
                bad.append(e)
                continue
            for problem in scene_size_problems(s, cfg.sim):
                print(f"warning: {f}: {problem}: explore refuses it", file=sys.stderr)
                warned["size"] += 1
            blind = lidar_blind(s, cfg.sim.lidar_height, cfg.sim.robot_height - cfg.sim.robot_radius)
            for line in reach_warnings(s, cfg.sim.robot_radius) + blind:
                print(f"warning: {f}: {line}", file=sys.stderr)
                warned["reachability"] += 1
    if bad:
        more = f" (and {len(bad) - 1} more invalid scene file(s), listed above)" if len(bad) > 1 else ""
        raise UserError(f"{bad[0]}{more}")
    if any(warned.values()) and args.strict:
        raise UserError(", ".join(f"{n} {kind} warning(s)" for kind, n in warned.items() if n) + " (--strict)")
    return 0


def cmd_changes(args, cfg) -> int:
    """Draws a change list per scene (RUN/changes/<scene>.changes.json), or with --apply writes the scenes after
    the lists of a folder (default RUN/scenes-changed), every list checked against its scene."""
    from ragnav_jax.world.changes import apply_changes, changes_path, generate_changes, load_changes, save_changes
    from ragnav_jax.world.plot import save_changes_plan
    from ragnav_jax.world.scene import load_scene_set, save_scene

    src, run = scene_source(args.scenes)
    scenes = load_scene_set(src)
    if args.apply:
        lists = Path(args.apply)
        out = Path(args.out) if args.out else (run / "scenes-changed" if run is not None else None)
        if out is None:
            raise UserError("--out FOLDER is needed when --scenes is not a run folder (RUN or RUN/scenes)")
        files = {s.name: lists / changes_path("", s.name).name for s in scenes}
        missing = [n for n, f in files.items() if not f.is_file()]
        if missing:
            raise UserError(f"{files[missing[0]]}: no change list for scene '{missing[0]}'"
                            + (f" (and {len(missing) - 1} more)" if len(missing) > 1 else ""))
        targets = [out / f"{s.name}.json" for s in scenes]
        refuse_overwrite(targets, args.force)
        if run is not None:
            init_run(run, cfg, "changes-apply")
        after = [apply_changes(s, load_changes(files[s.name]), str(files[s.name])) for s in scenes]  # all, then write
        for s, t in zip(after, targets):
            save_scene(s, t)
        print(f"{len(scenes)} changed scene(s) written to {out}")
        return 0
    out = Path(args.out) if args.out else (run / "changes" if run is not None else None)
    if out is None:
        raise UserError("--out FOLDER is needed when --scenes is not a run folder (RUN or RUN/scenes)")
    targets = [out / f"{s.name}.changes.json" for s in scenes]
    refuse_overwrite([*targets, out / "changes_summary.md"], args.force)
    if run is not None:
        init_run(run, cfg, "changes")
    rows = []
    for s, t in zip(scenes, targets):
        cl = generate_changes(s, cfg.changes, cfg.seed, cfg.world.split)
        save_changes(cl, t)
        if args.plots:
            save_changes_plan(s, apply_changes(s, cl), cl, out / "plots" / f"{s.name}.png")
        rows.append({"scene": s.name, "objects": len(s.objects), **cl.counts()})
    write_table(rows, out / "changes_summary")
    print((out / "changes_summary.md").read_text())
    print(f"{len(scenes)} change list(s) written to {out}" + (f", pictures in {out / 'plots'}" if args.plots else "")
          + f"; `ragnav changes --scenes {args.scenes} --apply {out}` writes the scenes after them")
    return 0


def cmd_show_scene(args, cfg) -> int:
    from ragnav_jax.world.plot import save_floor_plan
    from ragnav_jax.world.scene import load_scene

    scene = load_scene(args.file)
    out = Path(args.out)
    if out.suffix.lower() not in (".png", ".pdf", ".svg"):
        raise UserError(f"--out {out}: use a .png, .pdf or .svg file name")
    refuse_overwrite([out], args.force)
    save_floor_plan(scene, out)
    print(f"floor plan of {scene.name} written to {out}")
    return 0


def register(sub: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    p = sub.add_parser("generate", parents=[common], help="generate procedural house scenes")
    p.add_argument("--out", help="run folder (default: RUN_ROOT/generate-TIMESTAMP)")
    p.add_argument("--force", action="store_true", help="overwrite scenes already in the run folder")
    p.add_argument("--no-plots", dest="plots", action="store_false", help="skip floor-plan pictures")
    p.set_defaults(func=cmd_generate)

    p = sub.add_parser(
        "validate", parents=[common], help="validate scene files or folders; warn about unreachable rooms and objects"
    )
    p.add_argument("paths", nargs="+", metavar="PATH", action=PositionalsAndOverrides)
    p.add_argument("--strict", action="store_true", help="exit 2 on reachability warnings")
    p.set_defaults(func=cmd_validate)

    p = sub.add_parser("changes", parents=[common],
                       help="draw what changes in each scene after exploration (moved, removed, added objects, "
                            "closed doors), or apply change lists")
    p.add_argument("--scenes", required=True, help="scene folder or file, or a run folder from `ragnav generate`")
    p.add_argument("--out", help="folder for the lists (default RUN/changes) or, with --apply, for the changed "
                                 "scenes (default RUN/scenes-changed)")
    p.add_argument("--apply", metavar="LISTS", help="folder of change lists to apply instead of drawing new ones")
    p.add_argument("--force", action="store_true", help="overwrite existing outputs")
    p.add_argument("--no-plots", dest="plots", action="store_false", help="skip the pictures of the changes")
    p.set_defaults(func=cmd_changes)

    p = sub.add_parser("show-scene", parents=[common], help="draw a scene's floor plan")
    p.add_argument("file")
    p.add_argument("--out", required=True, help="picture file (.png, .pdf, .svg)")
    p.add_argument("--force", action="store_true", help="overwrite an existing --out file")
    p.set_defaults(func=cmd_show_scene, overrides_allowed=False)
