#!/bin/bash
# After AG-fresh (ag.sh): round 28's design on AG, from a worktree at b860fd7, then before_after.py
set -e
cd /tmp/wt28
export PYTHONPATH=/tmp/wt28
E=runs/unseen/episodes-unseen_ag/episodes.jsonl
/work/main/.venv/bin/python -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes runs/unseen --episodes $E --out runs/r29/AG-r28 --allow-unparsed --quiet --method ragnav > runs/r29/AG-r28.log 2>&1
echo "AG-r28 $(grep '| ragnav ' runs/r29/AG-r28.log | tail -1)"
/work/main/.venv/bin/python experiments/before_after.py "AG r28 -> r29=runs/r29/AG-r28,runs/r29/AG-fresh"
