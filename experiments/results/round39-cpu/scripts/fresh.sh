#!/bin/bash
# Round 39's fresh measures: sets AS (clean) and AR (its helper's report quoted some of its idioms) on the fixed houses
# (runs/unseen2): every method with the design frozen at c3b39a7 (worktree /tmp/r40), table_generalisation.py,
# failure_causes.py; then round 38's design (/tmp/r39, 376130c) on the same houses, RAGNav only, and before_after.py
set -e
PY=/work/main/.venv/bin/python
R=/work/main/runs
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { wt=$1; set_=$2; out=$3; shift 3; (cd $wt && PYTHONPATH=$wt $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/unseen2 --episodes $R/unseen2/episodes-unseen_$set_/episodes.jsonl --out $R/r39/$out --allow-unparsed --quiet "$@" > $R/r39/$out.log 2>&1); echo "$out $(grep '| ragnav ' $R/r39/$out.log | tail -1)"; }
for S in as ar; do
  U=$(echo $S | tr a-z A-Z)
  ev /tmp/r40 $S $U-fresh --method $M
  grep '^| [a-z_]* ' $R/r39/$U-fresh.log | tail -8
  cd /work/main
  $PY experiments/table_generalisation.py --split $U-fresh=$R/r39/$U-fresh --out $R/r39/table-$U
  $PY experiments/failure_causes.py $R/r39/$U-fresh --method ragnav | head -12
  ev /tmp/r39 $S $U-r38 --method ragnav
  $PY experiments/before_after.py "$U r38 -> r39=runs/r39/$U-r38,runs/r39/$U-fresh"
done
