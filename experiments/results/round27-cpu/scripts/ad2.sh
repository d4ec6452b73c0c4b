#!/bin/bash
# Round 27's fresh set AD, the earlier designs on the same episodes (after ad.sh's AD-fresh; see NOTE.md)
set -e
cd /work/main
E=runs/unseen/episodes-unseen_ad/episodes.jsonl
ev() { out=$1; shift; .venv/bin/ragnav eval --config configs/unseen.yaml --scenes runs/unseen --episodes $E --out runs/r27/$out --allow-unparsed --quiet "$@" > runs/r27/$out.log 2>&1; echo "$out $(grep '| ragnav ' runs/r27/$out.log | tail -1)"; }
ev AD-r26 --method ragnav eval.clause_anchors=false eval.likely_anchors=false
ev AD-r25 --method ragnav eval.clause_anchors=false eval.likely_anchors=false eval.tagger_anchors=false
.venv/bin/python experiments/before_after.py "AD r26 -> r27=runs/r27/AD-r26,runs/r27/AD-fresh" "AD r25 -> r27=runs/r27/AD-r25,runs/r27/AD-fresh"
