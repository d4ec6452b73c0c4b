#!/bin/bash
# Fresh set AE, run once with round 27's design (no change of the readers after AD; see NOTE.md)
set -e
cd /work/main
E=runs/unseen/episodes-unseen_ae/episodes.jsonl
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { out=$1; shift; .venv/bin/ragnav eval --config configs/unseen.yaml --scenes runs/unseen --episodes $E --out runs/r27/$out --allow-unparsed --quiet "$@" > runs/r27/$out.log 2>&1; echo "$out $(grep '| ragnav ' runs/r27/$out.log | tail -1)"; }
ev AE-fresh --method $M
grep '^| [a-z_]* ' runs/r27/AE-fresh.log | tail -8
ev AE-r26 --method ragnav eval.clause_anchors=false eval.likely_anchors=false
.venv/bin/python experiments/before_after.py "AE r26 -> r27=runs/r27/AE-r26,runs/r27/AE-fresh"
.venv/bin/python experiments/table_generalisation.py --split AE-fresh=runs/r27/AE-fresh --out runs/r27/table-AE
.venv/bin/python experiments/failure_causes.py runs/r27/AE-fresh --method ragnav
