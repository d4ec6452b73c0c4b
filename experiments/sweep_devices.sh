#!/usr/bin/env bash
# The closed-loop sweep of the paper preset (all 840 episodes, 2,000 grid points) on some or all GPUs of one host.
#   experiments/sweep_devices.sh RUN OUT DEVICES     DEVICES: a CUDA_VISIBLE_DEVICES value ("0": one GPU) or "all"
# Builds RUN (paper preset, hashing embedder: inside one device call) if it has no episodes yet, then runs
#   ragnav sweep --closed-loop: 4 retrieval variants x 10 sigma x 10 eta x 5 planning lambdas, eval.batch_size
#   lanes on each device (sweep.shard splits every chunk over the visible devices). Compare two OUTs' sweep.csv.
set -euo pipefail
R=$1; OUT=$2; DEV=$3; S=memory.embedder=hashing
rag() { python3 -m ragnav_jax.cli "$@"; }
if [ ! -f "$R/episodes.jsonl" ]; then
  rag generate --config configs/paper.yaml --out "$R" --no-plots --quiet $S
  rag explore --config configs/paper.yaml --out "$R" --no-plots --quiet $S
  rag build-memory --config configs/paper.yaml --run "$R" --quiet $S
  rag episodes --config configs/paper.yaml --scenes "$R" --out "$R/episodes.jsonl" --quiet $S
fi
if [ "$DEV" != all ]; then export CUDA_VISIBLE_DEVICES=$DEV; fi
rag sweep --config configs/sweep.yaml --run "$R" --episodes "$R/episodes.jsonl" --closed-loop --quiet --out "$OUT" $S \
  "sweep.variants=[ragnav,no_forest,no_spatial,no_boost]" "sweep.axes.lam=[0.0,1.0,5.0,10.0,10000.0]" \
  sweep.chunk_size=400 sweep.checkpoint=false "eval.batch_size=${LANES:-2048}"
