"""`ragnav eval`: closed-loop navigation of one or more methods over a scene set and an episodes file.

    ragnav eval --scenes DIR --episodes FILE --method ragnav --out RUN [--memory BANK]

--scenes is a run folder (with scenes/, and explore/ + memory/bank when already built) or a folder of
scene files; scenes without memory are explored and their memory built in RUN first. --method takes a
name, a comma-separated list, or `all`. Writes RUN/eval/<method>/{episodes.jsonl, summary.json}, the
tables (`write_eval_tables`: table, table_by_modality, table_full; .md and .csv), the bar chart
RUN/eval/methods.png and, with eval.record_legs=true, the first method's route of one episode
RUN/eval/route.png; prints the main table and the paths. With --changes FOLDER (`ragnav changes`), the memory
is the explored scenes' and the tasks run in the world after the change lists (evaluation/worlds.py); rows say
which goals' objects changed, and the tables split static from changed episodes (table_by_change).
"""

from __future__ import annotations

import argparse
import shutil
from pathlib import Path

from ragnav_jax.errors import UserError
from ragnav_jax.io import save_figure, write_json, write_jsonl, write_text

# table_full: every figure of a summary and of its modality blocks
TABLE_KEYS = ("episodes", "success_rate", "retrieval_accuracy", "spl", "progress", "ppl", "travel_distance_m", "oracle_m",
              "planned_rule1_m", "retrieval_ms", "retrieval_ms_single", "task_time_s", "sim_time_s", "total_time_s",
              "wrong_declarations", "fallback_declarations", "fallback_correct")
# The main table's markdown: header and number format of each CSV column (success carries its interval).
HEADERS = {"success": "success [95% CI]", "spl": "SPL", "top1": "top-1 retrieval", "travel_m": "travel (m)",
           "time_s": "time / episode (s)", "static": "success, static", "changed": "success, changed"}
FORMATS = {"success": "{:.3f}", "spl": "{:.3f}", "top1": "{:.3f}", "travel_m": "{:.1f}", "time_s": "{:.1f}",
           "static": "{:.3f}", "changed": "{:.3f}"}


def prepare_inputs(scenes_arg: str, memory_arg: str | None, out: Path, cfg, quiet: bool):
    """(scenes, bank, streams by scene name, source run folder): explores and builds memory when missing."""
    from ragnav_jax.cli import main as cli_main
    from ragnav_jax.config import dump_yaml
    from ragnav_jax.memory.checkpoint import bank_exists, load_bank
    from ragnav_jax.memory.commands import bank_dir
    from ragnav_jax.sim.stream import ExplorationStream
    from ragnav_jax.world.scene import load_scene_set

    src = Path(scenes_arg)
    if not src.exists():
        raise UserError(f"{src}: no such scene folder or file")
    run = src if (src / "scenes").is_dir() else None
    scenes = load_scene_set(run / "scenes" if run else src)
    if memory_arg:
        bank = load_bank(memory_arg, scenes)
    elif run is not None and bank_exists(bank_dir(run)):
        bank = load_bank(bank_dir(run), scenes)
    else:
        out.mkdir(parents=True, exist_ok=True)
        cfg_file = out / "config.eval-input.yaml"
        write_text(cfg_file, dump_yaml(cfg))
        q = ["--quiet"] if quiet else []
        if not (out / "explore" / "summary.json").exists():
            rc = cli_main(["explore", "--scenes", str(run / "scenes" if run else src), "--out", str(out), "--config",
                           str(cfg_file), "--no-plots", *q])
            if rc:
                raise UserError(f"exploring {src} failed (exit {rc})")
        if not bank_exists(bank_dir(out)):
            rc = cli_main(["build-memory", "--run", str(out), "--config", str(cfg_file), *q])
            if rc:
                raise UserError(f"building memory for {src} failed (exit {rc})")
        run = out
        bank = load_bank(bank_dir(out), scenes)
    streams = {}
    for base in [p for p in (run, out) if p is not None]:
        for s in scenes:
            f = base / "explore" / "streams" / f"{s.name}.npz"
            if s.name not in streams and f.is_file():
                streams[s.name] = ExplorationStream.load(f)
    return scenes, bank, streams


def cmd_eval(args, cfg) -> int:
    from ragnav_jax.evaluation.execute import make_executor
    from ragnav_jax.evaluation.methods import NAV_METHODS
    from ragnav_jax.evaluation.navigate import evaluate_navigation
    from ragnav_jax.evaluation.verify import Verifier
    from ragnav_jax.language.episodes import load_episodes
    from ragnav_jax.memory.encoder import bank_embedder
    from ragnav_jax.retrieval.commands import check_unparsed
    from ragnav_jax.runs import init_run, refuse_overwrite

    out = Path(args.out)
    methods = list(NAV_METHODS) if args.method == "all" else [m.strip() for m in (args.method or cfg.eval.method).split(",")]
    bad = [m for m in methods if m not in NAV_METHODS]
    if bad:
        raise UserError(f"unknown method(s) {', '.join(bad)} (known: {', '.join(NAV_METHODS)}, all)")
    refuse_overwrite([out / "eval" / "table.md", out / "eval" / "summary.json",
                      *(out / "eval" / m.replace(":", "_") / f for m in methods for f in ("episodes.jsonl", "summary.json"))],
                     args.force)

    def select(eps):  # an even subsample across scenes and modalities (--stride), then the first --limit
        return eps[:: args.stride][: args.limit or None]

    # format errors (file:line, exit 2) and unreadable instructions before any exploring
    unparsed = check_unparsed(select(load_episodes(args.episodes)), args.allow_unparsed, args.episodes, cfg.eval.tagger)
    scenes, bank, streams = prepare_inputs(args.scenes, args.memory, out, cfg, args.quiet)
    explored = scenes
    if args.changes:  # the memory is the explored scenes', the tasks run in the world after the change lists
        from ragnav_jax.evaluation.worlds import explore_worlds, load_worlds

        if cfg.eval.engine == "device":
            raise UserError("--changes runs on the host engine (eval.engine=host); the device engine has not been "
                            "checked on changed houses")
        worlds = load_worlds(scenes, args.changes, sorted({e.scene for e in select(load_episodes(args.episodes))}))
        scenes = [worlds.get(s.name, s) for s in scenes]
    episodes = select(load_episodes(args.episodes, scenes))
    if not episodes:
        raise UserError(f"{args.episodes}: no episodes")
    init_run(out, cfg, "eval")
    embedder = bank_embedder(bank, cfg)
    used = [s for s in scenes if s.name in {e.scene for e in episodes}]
    executor = make_executor(used, cfg)
    if args.changes and "etpnav" in methods:  # it explores for itself: the world as it is now
        streams = {**streams, **explore_worlds([s for s in used if s.name in worlds], cfg, progress=not args.quiet)}
    verifier = Verifier.build(embedder, cfg)  # shared: its encoder cache, memory views and checks serve every method
    summaries, first = {}, None
    for m in methods:
        rows, summary = evaluate_navigation(bank, scenes, episodes, embedder, cfg, m, streams=streams,
                                            progress=not args.quiet, executor=executor, verifier=verifier,
                                            memory_scenes=explored if args.changes else None)
        summary.update({"scenes": str(Path(args.scenes).resolve()), "episodes_file": str(Path(args.episodes).resolve()),
                        "memory": args.memory and str(Path(args.memory).resolve()),  # what show-episode replays
                        "changes": args.changes and str(Path(args.changes).resolve()), "unparsed": unparsed})
        d = out / "eval" / m.replace(":", "_")
        write_jsonl(d / "episodes.jsonl", rows)
        write_json(d / "summary.json", summary)
        summaries[m] = summary
        first = first or rows
    tables = write_eval_tables(summaries, out / "eval")
    pictures = [save_bar_plot([{"method": m, **figures(s)} for m, s in summaries.items()], out / "eval" / "methods.png")]
    if cfg.eval.record_legs:  # one episode with the most goals (the first such), not chosen by its outcome
        from ragnav_jax.evaluation.plot import save_episode_plot

        row = max(first, key=lambda r: r["goals"])
        pictures.append(save_episode_plot(next(s for s in scenes if s.name == row["scene"]), row, out / "eval" / "route.png",
                                          next(e.instruction for e in episodes if e.id == row["episode"])))
    if len(methods) == 1:  # a single method's summary also sits at the top of the eval folder
        shutil.copy(out / "eval" / methods[0].replace(":", "_") / "summary.json", out / "eval" / "summary.json")
    print(tables[0].read_text())
    print("tables (.md and .csv): " + ", ".join(str(t) for t in tables))
    print("pictures: " + ", ".join(str(p) for p in pictures))
    return 0


def figures(blk: dict) -> dict:
    """The main table's figures of one summary block (a method's, or one modality's of it: no time there)."""
    lo, hi = blk.get("success_ci95") or (None, None)
    out = {"episodes": blk.get("episodes"), "success": blk.get("success_rate"), "ci_low": lo, "ci_high": hi,
           "spl": blk.get("spl"), "top1": blk.get("retrieval_accuracy"), "travel_m": blk.get("travel_distance_m")}
    if "by_change" in blk:  # a changed world (--changes): success on episodes with and without a changed goal
        out |= {k: blk["by_change"][k]["success_rate"] for k in ("static", "changed")}
    return out | ({"time_s": blk["total_time_s"]} if "total_time_s" in blk else {})


def readable(row: dict) -> dict:
    """A main-table CSV row as its markdown shows it: headers in words, figures rounded, the success rate
    and its interval in one cell ("0.917 [0.80, 0.97]"), empty cells where a figure does not exist."""
    out = {}
    for k, v in row.items():
        if k in ("ci_low", "ci_high"):
            continue
        cell = v if v is None or k not in FORMATS else FORMATS[k].format(v)
        if k == "success" and v is not None and row.get("ci_low") is not None:
            cell += f" [{row['ci_low']:.2f}, {row['ci_high']:.2f}]"
        out[HEADERS.get(k, k)] = cell
    return out


def write_eval_tables(summaries: dict[str, dict], folder: Path) -> list[Path]:
    """Writes the tables of `summaries` (method -> summary) in `folder`, as .csv and .md; returns the .md paths:
    table (one row per method: success with its Wilson 95% interval, SPL, top-1 retrieval, travel, time per
    episode = task time + simulated time; in a changed world also success on static and changed episodes),
    table_by_modality (the same per instruction modality, no time), table_full (every figure, one row per
    method and per method and modality) and, in a changed world, table_by_change (per method, the static and
    the changed episodes)."""
    from ragnav_jax.tables import write_table

    main = [{"method": m, **figures(s)} for m, s in summaries.items()]
    by_mod = [{"method": m, "modality": mod, **figures(b)} for m, s in summaries.items() for mod, b in s["by_modality"].items()]
    full = []
    for m, s in summaries.items():
        full.append({"method": m, **{k: s.get(k) for k in TABLE_KEYS}})
        full += [{"method": f"{m} [{mod}]", **{k: b.get(k) for k in TABLE_KEYS}} for mod, b in s["by_modality"].items()]
    out = [write_table(main, folder / "table", [readable(r) for r in main])[1],
           write_table(by_mod, folder / "table_by_modality", [readable(r) for r in by_mod])[1],
           write_table(full, folder / "table_full")[1]]
    by_change = [{"method": m, "episodes_of": k, **figures(b)} for m, s in summaries.items()
                 for k, b in s.get("by_change", {}).items()]
    if by_change:
        out.append(write_table(by_change, folder / "table_by_change", [readable(r) for r in by_change])[1])
    return out


def register(sub: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    from ragnav_jax.argtypes import nonneg_int, positive_int
    from ragnav_jax.retrieval.commands import add_batch_flags

    p = sub.add_parser("eval", parents=[common], help="closed-loop multi-goal navigation in MJX: success, SPL, distance, times")
    p.add_argument("--scenes", required=True, help="run folder (scenes/, explore/, memory/bank) or folder of scene files")
    p.add_argument("--episodes", required=True, help="episodes .jsonl file")
    p.add_argument("--method", help="method, comma-separated methods, or 'all' (default: eval.method)")
    p.add_argument("--memory", help="memory bank folder to reuse (default: SCENES/memory/bank, else built in --out)")
    p.add_argument("--changes", metavar="FOLDER",
                   help="change lists (`ragnav changes`, <scene>.changes.json): the memory is the explored scenes', "
                        "the tasks run in the scenes after the changes; tables split static and changed episodes")
    p.add_argument("--out", required=True, help="output run folder")
    p.add_argument("--limit", type=nonneg_int, default=0, help="first N episodes only (0: all)")
    p.add_argument("--stride", type=positive_int, default=1, help="every N-th episode only (an even subsample)")
    add_batch_flags(p)
    p.set_defaults(func=cmd_eval)


def save_bar_plot(rows: list[dict], path: Path) -> Path:
    """Success rate (error bars: its 95% interval), SPL and top-1 retrieval per method, side by side, from
    main-table rows (`figures`); a figure that does not exist (ETPNav's retrieval) has no bar."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    def col(k):
        return np.array([np.nan if r.get(k) is None else r[k] for r in rows], float)

    keys = {"success": "success (95% CI)", "spl": "SPL", "top1": "top-1 retrieval"}
    x = np.arange(len(rows))
    fig, ax = plt.subplots(figsize=(max(6, 1.1 * len(rows)), 3.5))
    for j, (k, label) in enumerate(keys.items()):
        ax.bar(x + (j - 1) * 0.27, col(k), 0.27, label=label)
    s = col("success")
    ax.errorbar(x - 0.27, s, yerr=np.abs([s - col("ci_low"), col("ci_high") - s]), fmt="none", ecolor="k", capsize=3, lw=1)
    ax.set_xticks(x, [r["method"] for r in rows], rotation=30, ha="right")
    ax.set_ylim(0, 1.05)
    ax.set_title(f"{rows[0].get('episodes') if rows else 0} episodes per method", fontsize=9)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    fig.tight_layout()
    save_figure(fig, path, dpi=120)
    plt.close(fig)
    return path
