"""one_file.py: runs/r38/sub-one/episodes.jsonl, every development-set episode whose reading the one-word-sentence
rule changes (changed_episodes.json), in one file for one compile; each id is prefixed by its set ("unseen_ap--..."),
so its perception draws (seeded by the id) differ from the full run's, the same on both sides of the comparison."""
import json
import os
from pathlib import Path

changed = json.load(open(Path(__file__).parent / "changed_episodes.json"))["one_word_sentences"]
os.makedirs("runs/r38/sub-one", exist_ok=True)
with open("runs/r38/sub-one/episodes.jsonl", "w") as f:
    for split, ids in sorted(changed.items()):
        keep = set(ids)
        for line in open(f"runs/unseen2/episodes-{split}/episodes.jsonl"):
            e = json.loads(line)
            if e["id"] in keep:
                e["id"] = f"{split}--{e['id']}"
                f.write(json.dumps(e) + "\n")
