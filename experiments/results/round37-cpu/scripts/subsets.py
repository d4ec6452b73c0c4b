"""subsets.py: writes runs/r37/sub-<name>/episodes.jsonl, the development-set episodes whose rule-parser reading
round 37 changed (changed_episodes.json: found by pdump.py before and after each change), for sub.sh."""
import json
import os
from pathlib import Path

here = Path(__file__).parent
for name, ids in json.load(open(here / "changed_episodes.json")).items():
    split = name.removeprefix("c3_")
    keep = set(ids)
    os.makedirs(f"runs/r37/sub-{name}", exist_ok=True)
    with open(f"runs/r37/sub-{name}/episodes.jsonl", "w") as f:
        for line in open(f"runs/unseen2/episodes-{split}/episodes.jsonl"):
            if json.loads(line)["id"] in keep:
                f.write(line)
