#!/bin/bash
# Round 33's fresh set AK on the fixed houses (runs/unseen2): every method with the design frozen at $R33 (worktree
# /tmp/r33), table_generalisation.py, failure_causes.py; then round 32's design (/tmp/r32, d13d9bb, the thresholds
# fitted before) on the same houses, and on the houses as they were (runs/unseen), and before_after.py
set -e
cd /tmp/r33
export PYTHONPATH=/tmp/r33
PY=/work/main/.venv/bin/python
R=/work/main/runs
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { sc=$1; out=$2; shift 2; $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/$sc --episodes $R/$sc/episodes-unseen_ak/episodes.jsonl --out $R/r33/$out --allow-unparsed --quiet "$@" > $R/r33/$out.log 2>&1; echo "$out $(grep '| ragnav ' $R/r33/$out.log | tail -1)"; }
ev unseen2 AK-fresh --method $M
grep '^| [a-z_]* ' $R/r33/AK-fresh.log | tail -8
$PY experiments/table_generalisation.py --split AK-fresh=$R/r33/AK-fresh --out $R/r33/table-AK
$PY experiments/failure_causes.py $R/r33/AK-fresh --method ragnav
cd /tmp/r32 && export PYTHONPATH=/tmp/r32
ev unseen2 AK-r32 --method ragnav
ev unseen AK-r32-oldhouses --method ragnav
cd /work/main && $PY experiments/before_after.py "AK r32 -> r33=runs/r33/AK-r32,runs/r33/AK-fresh"
