"""One episode of a `ragnav eval` run, evaluated again with the recorder on (show-episode's videos).

    ev = load_eval_run("runs/eval-seen", "ragnav")   # what the eval read, from the run folder's records
    row = replay_episode(ev, "seen_000-t-001")       # its row, with "legs" (per-step poses) and "trace"
    outcome_differences(ev.rows["seen_000-t-001"], row)  # [] when the replay reproduces the recorded row

The run folder records what the eval read: its config (config.eval.yaml, else config.yaml) and, in
eval/<method>/summary.json, the scene set, the episodes file and a --memory bank (else the bank of the
scene run or of RUN itself, as `ragnav eval` chose). The evaluated episodes are the file's episodes
that the rows name, in the rows' order (--limit and --stride kept). The replay drives the one episode
on an executor built for every scene of those episodes, as the eval's was; the loop is deterministic
(perception noise is seeded by episode id), so the same machine reproduces the row.
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

from ragnav_jax.config import Config
from ragnav_jax.errors import UserError

# Row fields a replay must reproduce (timings and the recorder's own fields aside).
OUTCOME_KEYS = ("success", "progress", "goal_status", "declarations", "rejected_candidates", "steps",
                "travel_distance_m", "reason")


@dataclasses.dataclass(frozen=True)
class EvalRun:
    """What one method's evaluation in a run folder read, and the rows it wrote."""

    run: Path
    method: str
    cfg: Config
    scenes: tuple  # the scene set (Scene, ...)
    bank: object  # MemoryBank
    streams: dict  # scene name -> ExplorationStream (ETPNav-style replays)
    episodes: tuple  # the evaluated episodes, in the eval's order
    rows: dict  # episode id -> recorded row (RUN/eval/<method>/episodes.jsonl)


def eval_methods(run: Path) -> list[str]:
    """Methods with rows in RUN/eval (as the rows name them)."""
    out = []
    for f in sorted(run.glob("eval/*/episodes.jsonl")):
        with open(f) as fh:
            first = fh.readline()
        out.append(json.loads(first)["method"] if first.strip() else f.parent.name)
    return out


def load_eval_run(run: str | Path, method: str) -> EvalRun:
    """The config, scenes, bank, streams, episodes and rows of `method`'s evaluation in `run`."""
    from ragnav_jax.config import load_config
    from ragnav_jax.evaluation.eval_commands import prepare_inputs
    from ragnav_jax.language.episodes import load_episodes
    from ragnav_jax.memory.commands import bank_dir

    run = Path(run)
    if not run.is_dir():
        raise UserError(f"{run}: no such run folder")
    d = run / "eval" / method.replace(":", "_")
    if not (d / "episodes.jsonl").is_file():
        known = eval_methods(run)
        if not known:
            raise UserError(f"{run}: no evaluation in this folder (run `ragnav eval --out {run}` first)")
        raise UserError(f"{run}: no evaluation of method '{method}' (evaluated: {', '.join(known)})")
    rows = {r["episode"]: r for r in (json.loads(x) for x in (d / "episodes.jsonl").read_text().splitlines() if x.strip())}
    if not rows or not (d / "summary.json").is_file():
        raise UserError(f"{d}: an unfinished evaluation (no rows or no summary.json)")
    summary = json.loads((d / "summary.json").read_text())
    cfg_file = next((f for f in (run / "config.eval.yaml", run / "config.yaml") if f.is_file()), None)
    if cfg_file is None:
        raise UserError(f"{run}: no config.yaml recorded")
    cfg = load_config(cfg_file)
    for key in ("scenes", "episodes_file", "memory"):
        if summary.get(key) and not Path(summary[key]).exists():
            raise UserError(f"{d / 'summary.json'}: the evaluated {key} {summary[key]} is not there (relative paths "
                            "are read from the current folder)")
    scenes_arg, memory = summary["scenes"], summary.get("memory")
    if not memory and not (bank_dir(Path(scenes_arg)).exists() and (Path(scenes_arg) / "scenes").is_dir()):
        memory = str(bank_dir(run))  # the eval explored the scenes and built their memory in RUN
        if not Path(memory).exists():
            raise UserError(f"{run}: no memory bank (memory/bank) for the evaluated scenes {scenes_arg}")
    scenes, bank, streams = prepare_inputs(scenes_arg, memory, run, cfg, quiet=True)
    by_id = {e.id: e for e in load_episodes(summary["episodes_file"], scenes)}
    missing = [i for i in rows if i not in by_id]
    if missing:
        raise UserError(f"{summary['episodes_file']}: episode {missing[0]} of {d / 'episodes.jsonl'} is not in it")
    return EvalRun(run, method, cfg, tuple(scenes), bank, streams, tuple(by_id[i] for i in rows), rows)


def replay_episode(ev: EvalRun, episode_id: str, executor=None) -> dict:
    """The episode's row evaluated again with the recorder on: "legs" with every control step's pose and
    what the camera saw, and "trace" (candidates with scores, rejections). `executor`: one built for the
    scenes of ev.episodes (make_executor), to reuse across replays."""
    from ragnav_jax.evaluation.execute import make_executor
    from ragnav_jax.evaluation.navigate import evaluate_navigation
    from ragnav_jax.memory.encoder import make_embedder

    if episode_id not in ev.rows:
        ids = list(ev.rows)
        raise UserError(f"no episode '{episode_id}' in {ev.run / 'eval' / ev.method.replace(':', '_')}/episodes.jsonl "
                        f"({len(ids)} episodes: {', '.join(ids[:3])}{', ...' if len(ids) > 3 else ''})")
    ep = next(e for e in ev.episodes if e.id == episode_id)
    cfg, bank = ev.cfg, ev.bank
    embedder = make_embedder(bank.metas[0].embedder if bank.metas else cfg.memory.embedder,
                             dim=cfg.memory.hashing_dim, batch_size=cfg.memory.embed_batch,
                             buckets=cfg.memory.token_buckets)
    used = {e.scene for e in ev.episodes}
    ex = executor or make_executor([s for s in ev.scenes if s.name in used], cfg)
    rows, _ = evaluate_navigation(bank, ev.scenes, [ep], embedder, cfg, ev.method, streams=ev.streams, executor=ex,
                                  trace={episode_id})
    return rows[0]


def outcome_differences(recorded: dict, replayed: dict) -> list[str]:
    """The OUTCOME_KEYS on which a replayed row differs from the recorded one."""
    return [k for k in OUTCOME_KEYS if recorded.get(k) != replayed.get(k)]
