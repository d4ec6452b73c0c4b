#!/bin/bash
# Round 32's fresh set AJ: episodes, every method with the design frozen at d13d9bb (a worktree there: /tmp/r32),
# table_generalisation.py, failure_causes.py; then round 31's design (/tmp/r31, b0864f5) on AJ and before_after.py
set -e
cd /tmp/r32
export PYTHONPATH=/tmp/r32
PY=/work/main/.venv/bin/python
R=/work/main/runs
E=$R/unseen/episodes-unseen_aj/episodes.jsonl
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
$PY -m ragnav_jax.cli episodes --config configs/unseen.yaml --scenes $R/unseen --out $E --quiet episodes.split=unseen_aj
ev() { out=$1; shift; $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/unseen --episodes $E --out $R/r32/$out --allow-unparsed --quiet "$@" > $R/r32/$out.log 2>&1; echo "$out $(grep '| ragnav ' $R/r32/$out.log | tail -1)"; }
ev AJ-fresh --method $M
grep '^| [a-z_]* ' $R/r32/AJ-fresh.log | tail -8
$PY experiments/table_generalisation.py --split AJ-fresh=$R/r32/AJ-fresh --out $R/r32/table-AJ
$PY experiments/failure_causes.py $R/r32/AJ-fresh --method ragnav
(cd /tmp/r31 && PYTHONPATH=/tmp/r31 $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/unseen --episodes $E --out $R/r32/AJ-r31 --allow-unparsed --quiet --method ragnav) > $R/r32/AJ-r31.log 2>&1
echo "AJ-r31 $(grep '| ragnav ' $R/r32/AJ-r31.log | tail -1)"
cd /work/main && $PY experiments/before_after.py "AJ r31 -> r32=runs/r32/AJ-r31,runs/r32/AJ-fresh"
