#!/bin/bash
# Round 28's fresh set AF, run once with the design frozen (see experiments/results/round28-cpu/NOTE.md)
set -e
cd /work/main
E=runs/unseen/episodes-unseen_af/episodes.jsonl
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { out=$1; shift; .venv/bin/ragnav eval --config configs/unseen.yaml --scenes runs/unseen --episodes $E --out runs/r28/$out --allow-unparsed --quiet "$@" > runs/r28/$out.log 2>&1; echo "$out $(grep '| ragnav ' runs/r28/$out.log | tail -1)"; }
ev AF-fresh --method $M
grep '^| [a-z_]* ' runs/r28/AF-fresh.log | tail -8
ev AF-r27 --method ragnav eval.tagger_regroup=false
ev AF-r26 --method ragnav eval.tagger_regroup=false eval.clause_anchors=false eval.likely_anchors=false
.venv/bin/python experiments/before_after.py "AF r27 -> r28=runs/r28/AF-r27,runs/r28/AF-fresh" "AF r26 -> r28=runs/r28/AF-r26,runs/r28/AF-fresh"
.venv/bin/python experiments/table_generalisation.py --split AF-fresh=runs/r28/AF-fresh --out runs/r28/table-AF
.venv/bin/python experiments/failure_causes.py runs/r28/AF-fresh --method ragnav
