#!/bin/bash
# Round 36's fresh set AN on the fixed houses (runs/unseen2): every method with the design frozen at round 36's
# commit (worktree /tmp/r36), table_generalisation.py, failure_causes.py; then round 35's design (/tmp/r35,
# db7ebb0) on the same houses, and before_after.py
set -e
cd /tmp/r36
export PYTHONPATH=/tmp/r36
PY=/work/main/.venv/bin/python
R=/work/main/runs
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { sc=$1; out=$2; shift 2; $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/$sc --episodes $R/$sc/episodes-unseen_an/episodes.jsonl --out $R/r36/$out --allow-unparsed --quiet "$@" > $R/r36/$out.log 2>&1; echo "$out $(grep '| ragnav ' $R/r36/$out.log | tail -1)"; }
ev unseen2 AN-fresh --method $M
grep '^| [a-z_]* ' $R/r36/AN-fresh.log | tail -8
$PY experiments/table_generalisation.py --split AN-fresh=$R/r36/AN-fresh --out $R/r36/table-AN
$PY experiments/failure_causes.py $R/r36/AN-fresh --method ragnav
cd /tmp/r35 && export PYTHONPATH=/tmp/r35
ev unseen2 AN-r35 --method ragnav
cd /work/main && $PY experiments/before_after.py "AN r35 -> r36=runs/r36/AN-r35,runs/r36/AN-fresh"
