#!/bin/bash
# A second fresh measure of round 37's design: set AP on the fixed houses (runs/unseen2): every method with the design frozen at round 37's
# commit (worktree /tmp/r37, cde9a44), table_generalisation.py, failure_causes.py; then round 36's design (/tmp/s37,
# 861cacf: dc7592b's code with AO wired in) on the same houses, and before_after.py
set -e
cd /tmp/r37
export PYTHONPATH=/tmp/r37
PY=/work/main/.venv/bin/python
R=/work/main/runs
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { sc=$1; out=$2; shift 2; $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/$sc --episodes $R/$sc/episodes-unseen_ap/episodes.jsonl --out $R/r37/$out --allow-unparsed --quiet "$@" > $R/r37/$out.log 2>&1; echo "$out $(grep '| ragnav ' $R/r37/$out.log | tail -1)"; }
ev unseen2 AP-fresh --method $M
grep '^| [a-z_]* ' $R/r37/AP-fresh.log | tail -8
$PY experiments/table_generalisation.py --split AP-fresh=$R/r37/AP-fresh --out $R/r37/table-AP
$PY experiments/failure_causes.py $R/r37/AP-fresh --method ragnav
cd /tmp/s37 && export PYTHONPATH=/tmp/s37
ev unseen2 AP-r36 --method ragnav
cd /work/main && $PY experiments/before_after.py "AP r36 -> r37=runs/r37/AP-r36,runs/r37/AP-fresh"
