#!/bin/bash
# A second fresh measure of round 40's design: set AU on the fixed houses (runs/unseen2): every method with the design frozen at 6c0d028
# (worktree /tmp/r41), table_generalisation.py, failure_causes.py; then round 39's design (/tmp/r40, c3b39a7) on the
# same houses, RAGNav only, and before_after.py
set -e
PY=/work/main/.venv/bin/python
R=/work/main/runs
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { wt=$1; out=$2; shift 2; (cd $wt && PYTHONPATH=$wt $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/unseen2 --episodes $R/unseen2/episodes-unseen_au/episodes.jsonl --out $R/r40/$out --allow-unparsed --quiet "$@" > $R/r40/$out.log 2>&1); echo "$out $(grep '| ragnav ' $R/r40/$out.log | tail -1)"; }
ev /tmp/r41 AU-fresh --method $M
grep '^| [a-z_]* ' $R/r40/AU-fresh.log | tail -8
cd /work/main
$PY experiments/table_generalisation.py --split AU-fresh=$R/r40/AU-fresh --out $R/r40/table-AU
$PY experiments/failure_causes.py $R/r40/AU-fresh --method ragnav | head -12
ev /tmp/r40 AU-r39 --method ragnav
$PY experiments/before_after.py "AU r39 -> r40=runs/r40/AU-r39,runs/r40/AU-fresh"
