#!/bin/bash
# Round 25's fresh set AB, run once with the design frozen at 4f7c083 (see NOTE.md)
set -e
cd /work/main
E=runs/unseen/episodes-unseen_ab/episodes.jsonl
[ -f $E ] || .venv/bin/ragnav episodes --config configs/unseen.yaml --scenes runs/unseen --out $E --quiet episodes.split=unseen_ab > runs/r25/AB-episodes.log 2>&1
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { out=$1; shift; .venv/bin/ragnav eval --config configs/unseen.yaml --scenes runs/unseen --episodes $E --out runs/r25/$out --allow-unparsed --quiet "$@" > runs/r25/$out.log 2>&1; echo "$out $(grep '| ragnav ' runs/r25/$out.log | tail -1)"; }
ev AB-fresh --method $M
grep '^| [a-z_]* ' runs/r25/AB-fresh.log | tail -8
ev AB-r24 --method ragnav eval.ground_described=false
ev AB-parser --method ragnav eval.tagger=false eval.tagger_clauses=false eval.sensor_reader=false
.venv/bin/python experiments/before_after.py "AB round 24 -> 25=runs/r25/AB-r24,runs/r25/AB-fresh"
