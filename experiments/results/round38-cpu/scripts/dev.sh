#!/bin/bash
# usage: dev.sh TAG SPLIT... (ragnav alone on each dev split over the fixed houses runs/unseen2; extra overrides in
# $OV; code from $WT or /work/main)
W=${WT:-/work/main}
cd /work/main
T=$1; shift
for S in "$@"; do
  E=runs/unseen2/episodes-$S/episodes.jsonl
  (cd $W && PYTHONPATH=$W /work/main/.venv/bin/python -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes /work/main/runs/unseen2 --episodes /work/main/$E --method ragnav --out /work/main/runs/r38/$S-$T --allow-unparsed --quiet $OV) > runs/r38/$S-$T.log 2>&1
  echo "$S-$T $(grep "| ragnav " runs/r38/$S-$T.log | tail -1)"
done
