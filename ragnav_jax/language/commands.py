"""CLI subcommands of the language stage: parse, episodes, check-parse."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from ragnav_jax.errors import UserError, printable
from ragnav_jax.io import write_json
from ragnav_jax.runs import scene_source


def cmd_parse(args, cfg) -> int:
    from ragnav_jax.language.llm import parse_with_fallback
    from ragnav_jax.language.types import ParseError, TaskChain

    text, tag = " ".join(args.instruction), args.tagger
    try:
        chain, note = parse_with_fallback(text, cfg.llm if args.llm else None)
    except ParseError as e:
        if not tag:
            raise
        # as eval.tagger does: the tagger reads alone what the parser cannot, in the order written
        chain, tag = _tagged(TaskChain(text, (), "strict", parser="tagger"), cfg), False
        if not chain.subgoals:
            raise
        note = f"the parser cannot read it ({e}); the tagger read it alone"
    if note:
        print(f"ragnav: note: {printable(note)}", file=sys.stderr)
    if tag:
        chain = _tagged(chain, cfg)
    if not args.json:  # the description quotes the instruction: control characters are shown, not sent
        print(printable(chain.describe(), keep_newlines=True))
        print()
    print(json.dumps(chain.to_dict(), indent=None if args.json else 1))
    return 0


def _tagged(chain, cfg):
    """The chain reconciled with the instruction tagger and its sensor comparisons read again by the sensor reader
    (as `eval.tagger` and `eval.sensor_reader` do), what changed on stderr."""
    import dataclasses

    from ragnav_jax.language.tagger import BT, TAGS, load_tagger, reconcile, spans, words
    from ragnav_jax.language.types import derive_dependencies

    tagger = load_tagger(cfg.eval.tagger_file)
    conf = cfg.eval.tagger_conf or tagger.meta["reconcile"]["conf"]
    probs = tagger.word_probs([chain.instruction])[0]
    ws = words(chain.instruction)
    phrases = [" ".join(ws[i:j]) for i, j in spans(probs[:, : len(TAGS)].argmax(-1), BT)]
    subgoals, dropped, added = reconcile(chain.instruction, chain.subgoals, probs, conf, cfg.eval.tagger_clauses)
    print(f"ragnav: note: tagger (confidence {conf}): goal phrases {phrases}; dropped {list(dropped)}; "
          f"added {list(added)}", file=sys.stderr)
    if cfg.eval.sensor_reader:
        from ragnav_jax.language.sensor_reader import load_reader, revise

        reader = load_reader(cfg.eval.sensor_reader_file)
        rconf = cfg.eval.sensor_reader_conf or reader.meta["revise"]["conf"]
        pr, pw = reader.probs([sg.text for sg in subgoals])
        revised = tuple(revise(sg, a, b, rconf) for sg, a, b in zip(subgoals, pr, pw))
        print(f"ragnav: note: sensor reader (confidence {rconf}): revised "
              f"{[x.text for x, y in zip(subgoals, revised) if x != y]}", file=sys.stderr)
        subgoals = revised
    return dataclasses.replace(chain, subgoals=subgoals, dependencies=derive_dependencies(subgoals, chain.order))


def _time_episodes(run: Path, scenes, cfg) -> list:
    """Time-indexed episodes of an explored run (language/time_episodes.py)."""
    from ragnav_jax.language.episodes import SceneFacts
    from ragnav_jax.language.time_episodes import generate_time_episodes
    from ragnav_jax.sim.stream import ExplorationStream

    streams = {}
    for s in scenes:
        path = run / "explore" / "streams" / f"{s.name}.npz"
        if not path.is_file():
            raise UserError(f"{path}: no exploration stream for scene '{s.name}' (run ragnav explore first)")
        streams[s.name] = ExplorationStream.load(path)
    e = cfg.episodes
    return generate_time_episodes(scenes, streams, lambda s: SceneFacts.build(s, e), e.time_per_scene, e.time_gap,
                                  e.time_phrasing, cfg.seed)


def cmd_episodes(args, cfg) -> int:
    from ragnav_jax.language.agreement import parse_agreement
    from ragnav_jax.language.episodes import (
        episode_summary,
        generate_episodes,
        save_episodes,
        save_truth,
        validate_episode_dict,
    )
    from ragnav_jax.runs import init_run, refuse_overwrite
    from ragnav_jax.tables import write_table
    from ragnav_jax.world.scene import load_scene_set

    src, run = scene_source(args.scenes)
    scenes = load_scene_set(src)
    if args.out:
        out = Path(args.out)
    elif run is not None:
        out = run / "episodes" / "episodes.jsonl"
    else:
        raise UserError("--out FILE is needed when --scenes is not a run folder (RUN or RUN/scenes)")
    if out.suffix != ".jsonl":
        raise UserError(f"--out {out}: use a .jsonl file name")
    if args.time_indexed and run is None:
        raise UserError(f"--time-indexed: {args.scenes} is not a run folder (it reads RUN/explore/streams)")
    if args.time_indexed and not args.out:
        out = run / "episodes" / "time.jsonl"
    truth_path, summary_path = out.with_name(out.stem + ".chains.jsonl"), out.with_name(out.stem + "_summary")
    report_path = out.with_name(out.stem + ".agreement.json")
    refuse_overwrite([out, truth_path, summary_path.with_suffix(".md"), summary_path.with_suffix(".csv"), report_path],
                     args.force)
    if run is not None:
        init_run(run, cfg, "episodes-time" if args.time_indexed else "episodes")
    if args.time_indexed:
        pairs = _time_episodes(run, scenes, cfg)
    else:
        pairs = generate_episodes(scenes, cfg.episodes, cfg.seed, progress=not args.quiet)
    if not pairs:
        raise UserError(f"{src}: no episodes could be generated (scenes without describable objects?)")
    for k, p in enumerate(pairs, start=1):  # the schema promise, checked before writing
        validate_episode_dict(p.episode.to_dict(), "<generated>", k)
    save_episodes([p.episode for p in pairs], out)
    save_truth(pairs, truth_path)
    rows = episode_summary(pairs)
    write_table(rows, summary_path)
    report = parse_agreement(pairs)
    write_json(report_path, report)
    by_mod = {}
    for p in pairs:
        by_mod[p.episode.modality] = by_mod.get(p.episode.modality, 0) + 1
    print(f"{len(pairs)} episodes over {len(scenes)} scene(s) written to {out}")
    print("  per modality: " + ", ".join(f"{m}: {n}" for m, n in by_mod.items()))
    print(f"  ground-truth chains: {truth_path}")
    print(f"  parse agreement with the rule parser: {report['agree']}/{report['instructions']} "
          f"({100 * report['rate']:.2f}%), details in {report_path}")
    return 0


def cmd_check_parse(args, cfg) -> int:
    """Agreement of the parser with ground-truth chains written by `ragnav episodes`."""
    from ragnav_jax.language.agreement import chain_differences
    from ragnav_jax.language.episodes import EpisodeError, load_episodes, load_truth
    from ragnav_jax.language.llm import parse_with_fallback
    from ragnav_jax.language.types import ParseError

    episodes = load_episodes(args.episodes)
    truth_path = Path(args.truth) if args.truth else Path(args.episodes).with_name(Path(args.episodes).stem + ".chains.jsonl")
    truth = load_truth(truth_path)
    missing = [e.id for e in episodes if e.id not in truth]
    if missing:
        raise EpisodeError(f"{truth_path}: no ground-truth chain for episode '{missing[0]}' ({len(missing)} missing)")
    ok, bad = 0, []
    for e in episodes:
        try:
            chain, _ = parse_with_fallback(e.instruction, cfg.llm if args.llm else None)
            diffs = chain_differences(chain, truth[e.id])
        except ParseError as err:
            diffs = [f"ParseError: {err}"]
        if diffs:
            bad.append((e, diffs))
        else:
            ok += 1
    for e, diffs in bad[: args.show]:
        print(f"{e.id}: {e.instruction}")
        for d in diffs:
            print(f"    {d}")
    print(f"parse agreement: {ok}/{len(episodes)} ({100 * ok / len(episodes):.2f}%)")
    return 0 if ok / len(episodes) >= args.min_rate else 1


def _fit_command(args, cfg, m, command: str, filename: str, fit, reader, conf_key: str, cfg_key: str) -> int:
    """`ragnav fit-tagger` / `fit-sensor-reader`: fit a learned reader of module m on seen-split houses, then its
    confidence on other seen-split houses (m.fit_conf), and write OUT/<filename>.npz and .json."""
    from ragnav_jax.language.adapters import save_adapters
    from ragnav_jax.runs import init_run, refuse_overwrite

    out = Path(args.out)
    splits = tuple(s.strip() for s in args.splits.split(",")) if args.splits else None
    if splits is not None:
        m.check_splits(splits)  # before the run folder is made
    refuse_overwrite([out / f"{filename}.npz"], args.force)
    init_run(out, cfg, command)
    settings = m.FitSettings(scenes=args.scenes, seed=args.seed, lora=args.lora, epochs=args.epochs)
    trained, meta = fit(cfg, settings, *([splits] if splits else []), progress=not args.quiet)
    meta[conf_key] = m.fit_conf(reader(trained, meta), cfg, args.scenes, args.seed + 1,
                                tuple(meta["fitted_on"]["template_sets"]))
    path = save_adapters(trained, meta, out / f"{filename}.npz")
    write_json(out / f"{filename}.json", meta)
    on = meta["fitted_on"]
    more = f" (+{on['augmented']} augmented)" if "augmented" in on else ""
    print(f"{command.removeprefix('fit-')} fitted on {on['examples']} examples{more} of "
          f"{len(on['template_sets'])} template sets over {args.scenes} seen-split houses, final loss "
          f"{meta['final_loss']:.4f}, confidence {meta[conf_key]['conf']} -> {path}; use with {cfg_key}={path}")
    return 0


def cmd_fit_tagger(args, cfg) -> int:
    from ragnav_jax.language import tagger as m

    return _fit_command(args, cfg, m, "fit-tagger", "tagger", m.fit_tagger, m.InstructionTagger, "reconcile",
                        "eval.tagger_file")


def cmd_fit_sensor_reader(args, cfg) -> int:
    from ragnav_jax.language import sensor_reader as m

    return _fit_command(args, cfg, m, "fit-sensor-reader", "sensor_reader", m.fit_reader, m.SensorReader, "revise",
                        "eval.sensor_reader_file")


def register(sub: argparse._SubParsersAction, common: argparse.ArgumentParser) -> None:
    from ragnav_jax.argtypes import nonneg_int, positive_int, unit_float
    from ragnav_jax.cli import PositionalsAndOverrides

    # The instruction is free text (it may hold "x=3.5"), so overrides come with --set instead of positionally.
    p = sub.add_parser("parse", help="parse an instruction into a task chain (text and JSON)")
    p.add_argument("instruction", nargs="+", help='the instruction, e.g. "first go to the sofa, then the fridge"')
    p.add_argument("--config", help="YAML config (for the llm section)")
    p.add_argument("--set", dest="overrides", action="append", default=[], metavar="KEY=VALUE",
                   help="dotted config override, repeatable (e.g. --set llm.base_url=http://127.0.0.1:8000/v1)")
    p.add_argument("--quiet", action="store_true", help=argparse.SUPPRESS)
    p.add_argument("--json", action="store_true", help="print only the JSON (one line)")
    p.add_argument("--llm", action="store_true", help="use the LLM endpoint of the config (llm.base_url), with fallback")
    p.add_argument("--tagger", action="store_true",
                   help="reconcile the parse with the instruction tagger and read its sensor comparisons again with "
                        "the sensor reader, as `ragnav eval` does by default (eval.tagger, eval.sensor_reader; "
                        "without the house's memory, which eval also grounds in)")
    p.set_defaults(func=cmd_parse)

    p = sub.add_parser("episodes", parents=[common], help="generate multi-goal episodes for a scene set")
    p.add_argument("--scenes", required=True, help="scene folder or file, or a run folder from `ragnav generate`")
    p.add_argument("--out", help="episodes .jsonl file (default: RUN/episodes/episodes.jsonl for a run folder)")
    p.add_argument("--force", action="store_true", help="overwrite an existing episodes file")
    p.add_argument("--time-indexed", action="store_true",
                   help="time-indexed queries ('the mug you saw first') from an explored run's streams "
                        "(default --out RUN/episodes/time.jsonl; episodes.time_per_scene, time_gap, time_phrasing)")
    p.set_defaults(func=cmd_episodes)

    p = sub.add_parser("check-parse", parents=[common], help="parse agreement with ground-truth chains")
    p.add_argument("episodes", metavar="EPISODES", action=PositionalsAndOverrides,
                   help="episodes .jsonl written by `ragnav episodes`")
    p.add_argument("--truth", help="ground-truth chains (default: EPISODES stem + .chains.jsonl)")
    p.add_argument("--llm", action="store_true", help="parse with the configured LLM endpoint (with fallback)")
    p.add_argument("--show", type=nonneg_int, default=20, help="disagreements to print")
    p.add_argument("--min-rate", type=unit_float, default=0.99, help="exit 1 below this agreement")
    p.set_defaults(func=cmd_check_parse)

    for name, what, file, seed, default, func in (
            ("fit-tagger", "the instruction tagger (goal phrases, coordinate hints)", "tagger", 4242,
             "every set but the held-out one", cmd_fit_tagger),
            ("fit-sensor-reader", "the learned reader of sensor comparisons", "sensor_reader", 5151,
             "every set but the held-out one", cmd_fit_sensor_reader)):
        p = sub.add_parser(name, parents=[common], help=f"fit {what} on seen-split houses (writes OUT/{file}.npz)")
        p.add_argument("--out", required=True, help="output folder")
        p.add_argument("--scenes", type=positive_int, default=8, help="seen-split training houses (default 8)")
        p.add_argument("--seed", type=nonneg_int, default=seed, help=f"seed of houses, episodes and training (default {seed})")
        p.add_argument("--lora", type=positive_int, default=8, help="adapter rank (default 8)")
        p.add_argument("--epochs", type=positive_int, default=3, help="passes over the examples (default 3)")
        p.add_argument("--splits", help=f"template sets to learn from, comma-separated (default: {default})")
        p.add_argument("--force", action="store_true", help=f"overwrite an earlier OUT/{file}.npz")
        p.set_defaults(func=func)
