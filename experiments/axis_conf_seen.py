"""How the coordinate head's threshold (`tagger.AXIS_CONF`) does on the seen split: hints read right per threshold.

    .venv/bin/python experiments/axis_conf_seen.py --out experiments/results/round24-cpu/axis_conf_seen.json

Seen-split houses of the tagger's confidence seed (4243, never a training or evaluation house), text+location
episodes written by every template set the tagger learns from, reconciled as `eval.tagger_clauses` does with the
shipped tagger; for each threshold of adapters.CONF_GRID, the instructions whose goals carry exactly the truth's
hints and no reading read from their numbers (`tagger_reading.hints_right`).
"""

from __future__ import annotations

import argparse
import dataclasses
import json
from pathlib import Path

from tagger_reading import hints, hints_right

from ragnav_jax.config import Config
from ragnav_jax.evaluation.fitting import _seen_scenes
from ragnav_jax.language import tagger as T
from ragnav_jax.language.adapters import CONF_GRID
from ragnav_jax.language.episodes import generate_episodes
from ragnav_jax.language.parser import parse_instruction
from ragnav_jax.language.types import ParseError


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--scenes", type=int, default=4)
    ap.add_argument("--seed", type=int, default=4243)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    cfg = Config()
    houses = _seen_scenes(cfg, args.scenes, args.seed)
    items = []
    for split in T.TRAIN_SPLITS:
        ecfg = dataclasses.replace(cfg.episodes, split=split, text=0, text_location=3, text_location_sensor=0)
        for g in generate_episodes(houses, ecfg, args.seed):
            if hints(g.truth.subgoals):
                try:
                    items.append((g.episode.instruction, parse_instruction(g.episode.instruction).subgoals,
                                  hints(g.truth.subgoals)))
                except ParseError:
                    pass
    tagger = T.load_tagger("")
    probs = tagger.word_probs([t for t, _, _ in items])
    conf = tagger.meta["reconcile"]["conf"]
    right = {}
    for c in sorted({T.AXIS_CONF, *CONF_GRID}):
        T.axis_hint.__defaults__ = (c,)  # the threshold reconcile reads hints at
        right[str(c)] = sum(hints_right(T.reconcile(t, s, p, conf, True)[0], w) for (t, s, w), p in zip(items, probs))
        print(c, right[str(c)], flush=True)
    out = {"instructions_with_hints": len(items), "hints_right": right, "axis_conf": T.AXIS_CONF,
           "seen_houses": args.scenes, "seed": args.seed, "template_sets": list(T.TRAIN_SPLITS)}
    Path(args.out).write_text(json.dumps(out, indent=1) + "\n")


if __name__ == "__main__":
    main()
