#!/bin/bash
# Round 30's fresh set AH, run once with the design frozen at 5dfd87f (a worktree there: /tmp/r30)
set -e
cd /tmp/r30
export PYTHONPATH=/tmp/r30
PY=/work/main/.venv/bin/python
R=/work/main/runs
E=$R/unseen/episodes-unseen_ah/episodes.jsonl
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
$PY -m ragnav_jax.cli episodes --config configs/unseen.yaml --scenes $R/unseen --out $E --quiet episodes.split=unseen_ah
ev() { out=$1; shift; $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/unseen --episodes $E --out $R/r30/$out --allow-unparsed --quiet "$@" > $R/r30/$out.log 2>&1; echo "$out $(grep '| ragnav ' $R/r30/$out.log | tail -1)"; }
ev AH-fresh --method $M
grep '^| [a-z_]* ' $R/r30/AH-fresh.log | tail -8
$PY experiments/table_generalisation.py --split AH-fresh=$R/r30/AH-fresh --out $R/r30/table-AH
$PY experiments/failure_causes.py $R/r30/AH-fresh --method ragnav
