#!/bin/bash
# After AE-fresh (ae.sh): round 26's design on AE, from a worktree at df6d3c5 (round 27 frozen), then the tables
set -e
cd /tmp/wt27
E=runs/unseen/episodes-unseen_ae/episodes.jsonl
PYTHONPATH=/tmp/wt27 /work/main/.venv/bin/python -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes runs/unseen --episodes $E --out runs/r27/AE-r26 --allow-unparsed --quiet --method ragnav eval.clause_anchors=false eval.likely_anchors=false > runs/r27/AE-r26.log 2>&1
echo "AE-r26 $(grep '| ragnav ' runs/r27/AE-r26.log | tail -1)"
cd /tmp/wt27; export PYTHONPATH=/tmp/wt27
/work/main/.venv/bin/python experiments/before_after.py "AE r26 -> r27=runs/r27/AE-r26,runs/r27/AE-fresh"
/work/main/.venv/bin/python experiments/table_generalisation.py --split AE-fresh=runs/r27/AE-fresh --out runs/r27/table-AE
/work/main/.venv/bin/python experiments/failure_causes.py runs/r27/AE-fresh --method ragnav
