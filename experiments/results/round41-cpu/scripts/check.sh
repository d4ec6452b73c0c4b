#!/bin/bash
# usage: check.sh TAG: seen templates (fixed houses runs/unseen2), paper preset (stride 6) with ragnav alone ($OV
# overrides; code from $WT)
W=${WT:-/work/main}
cd /work/main
T=$1
(cd $W && PYTHONPATH=$W /work/main/.venv/bin/python -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes /work/main/runs/unseen2 --episodes /work/main/runs/unseen2/episodes-seen/episodes.jsonl --method ragnav --out /work/main/runs/r40/seen-$T --quiet $OV) > runs/r40/seen-$T.log 2>&1
echo "seen-$T $(grep '| ragnav ' runs/r40/seen-$T.log | tail -1)"
(cd $W && PYTHONPATH=$W /work/main/.venv/bin/python -m ragnav_jax.cli eval --config configs/paper.yaml --scenes /work/main/runs/pb-cpu --episodes /work/main/experiments/results/paper-episodes.jsonl --stride 6 --method ragnav --out /work/main/runs/r40/paper-$T --quiet $OV) > runs/r40/paper-$T.log 2>&1
echo "paper-$T $(grep '| ragnav ' runs/r40/paper-$T.log | tail -1)"
