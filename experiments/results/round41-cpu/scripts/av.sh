#!/bin/bash
# The fresh measure of round 41's design: set AV on the fixed houses (runs/unseen2): every method with the design frozen at 7cb45b1
# (worktree /tmp/r42), table_generalisation.py, failure_causes.py; then round 40's design (/tmp/s0, c956241: the readers of
# 6c0d028) on the same houses, RAGNav only, and before_after.py
set -e
PY=/work/main/.venv/bin/python
R=/work/main/runs
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { wt=$1; out=$2; shift 2; (cd $wt && PYTHONPATH=$wt $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/unseen2 --episodes $R/unseen2/episodes-unseen_av/episodes.jsonl --out $R/r42/$out --allow-unparsed --quiet "$@" > $R/r42/$out.log 2>&1); echo "$out $(grep '| ragnav ' $R/r42/$out.log | tail -1)"; }
ev /tmp/s0 AV-r40 --method ragnav &
ev /tmp/r42 AV-fresh --method $M
wait
grep '^| [a-z_]* ' $R/r42/AV-fresh.log | tail -8
cd /work/main
$PY experiments/table_generalisation.py --split AV-fresh=$R/r42/AV-fresh --out $R/r42/table-AV
$PY experiments/failure_causes.py $R/r42/AV-fresh --method ragnav | head -12
$PY experiments/before_after.py "AV r40 -> r41=runs/r42/AV-r40,runs/r42/AV-fresh"
