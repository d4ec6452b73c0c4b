#!/bin/bash
# usage: dev.sh TAG SPLIT... (ragnav alone on each dev split; extra overrides in $OV)
cd /work/main
T=$1; shift
for S in "$@"; do
  E=runs/unseen/episodes-$S/episodes.jsonl
  [ "$S" = seen ] && E=runs/unseen/episodes-seen/episodes.jsonl
  .venv/bin/ragnav eval --config configs/unseen.yaml --scenes runs/unseen --episodes $E --method ragnav --out runs/r27/$S-$T --allow-unparsed --quiet $OV > runs/r27/$S-$T.log 2>&1
  echo "$S-$T $(grep "| ragnav " runs/r27/$S-$T.log | tail -1)"
done
