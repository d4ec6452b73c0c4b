#!/bin/bash
# Round 34's fresh set AL on the fixed houses (runs/unseen2): every method with the design frozen at da299c1 (worktree
# /tmp/r34), table_generalisation.py, failure_causes.py; then round 33's design (/tmp/r33, 76a6c63) on the same
# houses, and before_after.py
set -e
cd /tmp/r34
export PYTHONPATH=/tmp/r34
PY=/work/main/.venv/bin/python
R=/work/main/runs
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { sc=$1; out=$2; shift 2; $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/$sc --episodes $R/$sc/episodes-unseen_al/episodes.jsonl --out $R/r34/$out --allow-unparsed --quiet "$@" > $R/r34/$out.log 2>&1; echo "$out $(grep '| ragnav ' $R/r34/$out.log | tail -1)"; }
ev unseen2 AL-fresh --method $M
grep '^| [a-z_]* ' $R/r34/AL-fresh.log | tail -8
$PY experiments/table_generalisation.py --split AL-fresh=$R/r34/AL-fresh --out $R/r34/table-AL
$PY experiments/failure_causes.py $R/r34/AL-fresh --method ragnav
cd /tmp/r33 && export PYTHONPATH=/tmp/r33
ev unseen2 AL-r33 --method ragnav
cd /work/main && $PY experiments/before_after.py "AL r33 -> r34=runs/r34/AL-r33,runs/r34/AL-fresh"
