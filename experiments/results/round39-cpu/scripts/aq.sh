#!/bin/bash
# Round 38's fresh measure: set AQ on the fixed houses (runs/unseen2): every method with the design frozen at HEAD
# 376130c (worktree /tmp/r39), table_generalisation.py, failure_causes.py; then round 37's design (/tmp/r37, cde9a44)
# on the same houses, RAGNav only, and before_after.py
set -e
cd /tmp/r39
export PYTHONPATH=/tmp/r39
PY=/work/main/.venv/bin/python
R=/work/main/runs
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { sc=$1; out=$2; shift 2; $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/$sc --episodes $R/$sc/episodes-unseen_aq/episodes.jsonl --out $R/r39/$out --allow-unparsed --quiet "$@" > $R/r39/$out.log 2>&1; echo "$out $(grep '| ragnav ' $R/r39/$out.log | tail -1)"; }
ev unseen2 AQ-fresh --method $M
grep '^| [a-z_]* ' $R/r39/AQ-fresh.log | tail -8
$PY experiments/table_generalisation.py --split AQ-fresh=$R/r39/AQ-fresh --out $R/r39/table-AQ
$PY experiments/failure_causes.py $R/r39/AQ-fresh --method ragnav
cd /tmp/r37 && export PYTHONPATH=/tmp/r37
ev unseen2 AQ-r37 --method ragnav
cd /work/main && $PY experiments/before_after.py "AQ r37 -> r38=runs/r39/AQ-r37,runs/r39/AQ-fresh"
