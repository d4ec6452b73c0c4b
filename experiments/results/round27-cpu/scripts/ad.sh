#!/bin/bash
# Round 27's fresh set AD, run once with the design frozen (see experiments/results/round27-cpu/NOTE.md)
set -e
cd /work/main
E=runs/unseen/episodes-unseen_ad/episodes.jsonl
M=ragnav,remembr,etpnav,naive_rag,graphrag,lightrag,oracle
ev() { out=$1; shift; .venv/bin/ragnav eval --config configs/unseen.yaml --scenes runs/unseen --episodes $E --out runs/r27/$out --allow-unparsed --quiet "$@" > runs/r27/$out.log 2>&1; echo "$out $(grep '| ragnav ' runs/r27/$out.log | tail -1)"; }
ev AD-fresh --method $M
grep '^| [a-z_]* ' runs/r27/AD-fresh.log | tail -8
