#!/bin/bash
# Round 29's fresh set AG, run once with the design frozen (see experiments/results/round29-cpu/NOTE.md)
set -e
cd /work/main
E=runs/unseen/episodes-unseen_ag/episodes.jsonl
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { out=$1; shift; .venv/bin/ragnav eval --config configs/unseen.yaml --scenes runs/unseen --episodes $E --out runs/r29/$out --allow-unparsed --quiet "$@" > runs/r29/$out.log 2>&1; echo "$out $(grep '| ragnav ' runs/r29/$out.log | tail -1)"; }
ev AG-fresh --method $M
grep '^| [a-z_]* ' runs/r29/AG-fresh.log | tail -8
.venv/bin/python experiments/table_generalisation.py --split AG-fresh=runs/r29/AG-fresh --out runs/r29/table-AG
.venv/bin/python experiments/failure_causes.py runs/r29/AG-fresh --method ragnav
