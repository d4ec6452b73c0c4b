#!/bin/bash
# Round 31's fresh set AI, run once with the design frozen (a worktree there: /tmp/r31), then round 30's design on
# AI (a worktree at adc1051: /tmp/base) and before_after.py
set -e
cd /tmp/r31
export PYTHONPATH=/tmp/r31
PY=/work/main/.venv/bin/python
R=/work/main/runs
E=$R/unseen/episodes-unseen_ai/episodes.jsonl
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { out=$1; shift; $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/unseen --episodes $E --out $R/r31/$out --allow-unparsed --quiet "$@" > $R/r31/$out.log 2>&1; echo "$out $(grep '| ragnav ' $R/r31/$out.log | tail -1)"; }
ev AI-fresh --method $M
grep '^| [a-z_]* ' $R/r31/AI-fresh.log | tail -8
$PY experiments/table_generalisation.py --split AI-fresh=$R/r31/AI-fresh --out $R/r31/table-AI
$PY experiments/failure_causes.py $R/r31/AI-fresh --method ragnav
(cd /tmp/base && PYTHONPATH=/tmp/base $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/unseen --episodes $E --out $R/r31/AI-r30 --allow-unparsed --quiet --method ragnav) > $R/r31/AI-r30.log 2>&1
echo "AI-r30 $(grep '| ragnav ' $R/r31/AI-r30.log | tail -1)"
cd /work/main && $PY experiments/before_after.py "AI r30 -> r31=runs/r31/AI-r30,runs/r31/AI-fresh"
