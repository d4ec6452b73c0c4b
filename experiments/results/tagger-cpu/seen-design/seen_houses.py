"""The tagger's design checks on seen-split houses (seed 4244: neither the tagger's training nor its confidence houses)."""
import json, sys, dataclasses
from ragnav_jax.config import load_config
from ragnav_jax.evaluation.fitting import _seen_scenes
from ragnav_jax.language.episodes import generate_episodes
from ragnav_jax.language.tagger import TRAIN_SPLITS
cfg = load_config('configs/seen.yaml', [])
houses = _seen_scenes(cfg, 12, 4244)
out = {}
for split in TRAIN_SPLITS:
    pairs = generate_episodes(houses, dataclasses.replace(cfg.episodes, split=split), 4244)
    out[split] = [{"instruction": p.episode.instruction, "truth": p.truth.to_dict()} for p in pairs]
json.dump(out, open('/tmp/tg/seen4244.json', 'w'))
json.dump([x["instruction"] for x in out["unseen_dev8"]], open('/tmp/tg/seen4244-dev8-inst.json', 'w'))
print({k: len(v) for k, v in out.items()})
