#!/bin/bash
# After AH-fresh (ah.sh): round 29's design on AH, from a worktree at 3080195 (/tmp/base), then before_after.py
set -e
cd /work/main
E=/work/main/runs/unseen/episodes-unseen_ah/episodes.jsonl
(cd /tmp/base && PYTHONPATH=/tmp/base /work/main/.venv/bin/python -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes /work/main/runs/unseen --episodes $E --out /work/main/runs/r30/AH-r29 --allow-unparsed --quiet --method ragnav) > runs/r30/AH-r29.log 2>&1
echo "AH-r29 $(grep '| ragnav ' runs/r30/AH-r29.log | tail -1)"
.venv/bin/python experiments/before_after.py "AH r29 -> r30=runs/r30/AH-r29,runs/r30/AH-fresh"
