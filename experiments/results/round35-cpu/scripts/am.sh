#!/bin/bash
# Round 35's fresh set AM on the fixed houses (runs/unseen2): every method with the design frozen at round 35's
# commit (worktree /tmp/r35), table_generalisation.py, failure_causes.py; then round 34's design (/tmp/r34,
# da299c1) on the same houses, and before_after.py
set -e
cd /tmp/r35
export PYTHONPATH=/tmp/r35
PY=/work/main/.venv/bin/python
R=/work/main/runs
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { sc=$1; out=$2; shift 2; $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/$sc --episodes $R/$sc/episodes-unseen_am/episodes.jsonl --out $R/r35/$out --allow-unparsed --quiet "$@" > $R/r35/$out.log 2>&1; echo "$out $(grep '| ragnav ' $R/r35/$out.log | tail -1)"; }
ev unseen2 AM-fresh --method $M
grep '^| [a-z_]* ' $R/r35/AM-fresh.log | tail -8
$PY experiments/table_generalisation.py --split AM-fresh=$R/r35/AM-fresh --out $R/r35/table-AM
$PY experiments/failure_causes.py $R/r35/AM-fresh --method ragnav
cd /tmp/r34 && export PYTHONPATH=/tmp/r34
ev unseen2 AM-r34 --method ragnav
cd /work/main && $PY experiments/before_after.py "AM r34 -> r35=runs/r35/AM-r34,runs/r35/AM-fresh"
