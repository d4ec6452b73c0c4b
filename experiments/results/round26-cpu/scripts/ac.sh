#!/bin/bash
# Round 26's fresh set AC, run once with the design frozen (see experiments/results/round26-cpu/NOTE.md)
set -e
cd /work/main
E=runs/unseen/episodes-unseen_ac/episodes.jsonl
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { out=$1; shift; .venv/bin/ragnav eval --config configs/unseen.yaml --scenes runs/unseen --episodes $E --out runs/r26/$out --allow-unparsed --quiet "$@" > runs/r26/$out.log 2>&1; echo "$out $(grep '| ragnav ' runs/r26/$out.log | tail -1)"; }
ev AC-fresh --method $M
grep '^| [a-z_]* ' runs/r26/AC-fresh.log | tail -8
ev AC-r25 --method ragnav eval.tagger_anchors=false
ev AC-r24 --method ragnav eval.tagger_anchors=false eval.ground_described=false
.venv/bin/python experiments/before_after.py "AC r25 -> r26=runs/r26/AC-r25,runs/r26/AC-fresh" "AC r24 -> r26=runs/r26/AC-r24,runs/r26/AC-fresh"
