#!/bin/bash
# usage: sub.sh TAG: ragnav alone on runs/r40/sub-one/episodes.jsonl (the episodes whose reading changed, ids prefixed by
# their set), code from $WT
W=${WT:-/work/main}
cd /work/main
T=$1
(cd $W && PYTHONPATH=$W /work/main/.venv/bin/python -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes /work/main/runs/unseen2 --episodes /work/main/runs/r40/sub-one/episodes.jsonl --method ragnav --out /work/main/runs/r40/one-$T --allow-unparsed --quiet $OV) > runs/r40/one-$T.log 2>&1
echo "one-$T $(grep "| ragnav " runs/r40/one-$T.log | tail -1)"
