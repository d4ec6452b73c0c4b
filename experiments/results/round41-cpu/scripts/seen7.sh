#!/bin/bash
# The seen templates on the fixed houses (runs/unseen2/episodes-seen), every method, at aa4ffcd (worktree /tmp/s2)
PY=/work/main/.venv/bin/python
R=/work/main/runs
(cd /tmp/s2 && PYTHONPATH=/tmp/s2 $PY -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes $R/unseen2 --episodes $R/unseen2/episodes-seen/episodes.jsonl --out $R/r42/seen-all --method ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle --quiet > $R/r42/seen-all.log 2>&1)
cd /work/main && $PY experiments/table_generalisation.py --split seen-templates=$R/r42/seen-all --split AS+AT+AU+AV=experiments/results/round39-cpu/AS-fresh,experiments/results/round40-cpu/AT-fresh,experiments/results/round40-cpu/AU-fresh,experiments/results/round41-cpu/AV-fresh --out $R/r42/table-both
