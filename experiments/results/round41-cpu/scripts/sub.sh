#!/bin/bash
# usage: sub.sh WT TAG: ragnav alone on runs/r41b/sub.jsonl (the episodes whose reading changed, ids prefixed by their set), code from WT
W=$1; T=$2
(cd $W && PYTHONPATH=$W /work/main/.venv/bin/python -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes /work/main/runs/unseen2 --episodes /work/main/runs/r41b/sub.jsonl --method ragnav --out /work/main/runs/r41b/$T --allow-unparsed --quiet) > /work/main/runs/r41b/$T.log 2>&1
echo "$T $(grep "| ragnav " /work/main/runs/r41b/$T.log | tail -1)"
