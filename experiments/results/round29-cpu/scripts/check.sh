#!/bin/bash
# usage: check.sh TAG: seen templates, paper preset (stride 6), W, Z, Y with ragnav alone ($OV overrides)
cd /work/main
T=$1
.venv/bin/ragnav eval --config configs/unseen.yaml --scenes runs/unseen --episodes runs/unseen/episodes-seen/episodes.jsonl --method ragnav --out runs/r27/seen-$T --quiet $OV > runs/r27/seen-$T.log 2>&1
echo "seen-$T $(grep '| ragnav ' runs/r27/seen-$T.log | tail -1)"
.venv/bin/ragnav eval --config configs/paper.yaml --scenes runs/pb-cpu --episodes experiments/results/paper-episodes.jsonl --stride 6 --method ragnav --out runs/r27/paper-$T --quiet $OV > runs/r27/paper-$T.log 2>&1
echo "paper-$T $(grep '| ragnav ' runs/r27/paper-$T.log | tail -1)"
runs/r27/dev.sh $T unseen_w unseen_z unseen_y
