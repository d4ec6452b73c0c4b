#!/bin/bash
# usage: sub.sh TAG SPLIT...: ragnav alone on runs/r38/sub-SPLIT/episodes.jsonl (the episodes whose parse changed), code from $WT
W=${WT:-/work/main}
cd /work/main
T=$1; shift
for S in "$@"; do
  (cd $W && PYTHONPATH=$W /work/main/.venv/bin/python -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes /work/main/runs/unseen2 --episodes /work/main/runs/r38/sub-$S/episodes.jsonl --method ragnav --out /work/main/runs/r38/$S-$T --allow-unparsed --quiet $OV) > runs/r38/$S-$T.log 2>&1
  echo "$S-$T $(grep "| ragnav " runs/r38/$S-$T.log | tail -1)"
done
