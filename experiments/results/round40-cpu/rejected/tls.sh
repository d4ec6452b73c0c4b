#!/bin/bash
# usage: tls.sh TAG: ragnav alone on runs/r41/sub-tls/episodes.jsonl (the text+location+sensor episodes of AM, AN, AO,
# AP, AQ, AS and the seen templates, ids prefixed by their set), code from $WT
W=${WT:-/work/main}
cd /work/main
T=$1
(cd $W && PYTHONPATH=$W /work/main/.venv/bin/python -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes /work/main/runs/unseen2 --episodes /work/main/runs/r41/sub-tls/episodes.jsonl --method ragnav --out /work/main/runs/r41/tls-$T --allow-unparsed --quiet $OV) > runs/r41/tls-$T.log 2>&1
echo "tls-$T $(grep "| ragnav " runs/r41/tls-$T.log | tail -1)"
