#!/bin/bash
# The seen split (seen houses, seen catalogue, seen templates: configs/seen.yaml), RAGNav alone, at HEAD (worktree /tmp/s3)
set -e
PY=/work/main/.venv/bin/python
cd /tmp/s3
export PYTHONPATH=/tmp/s3
R=/work/main/runs/seen
$PY -m ragnav_jax.cli generate --config configs/seen.yaml --out $R --quiet --no-plots
$PY -m ragnav_jax.cli explore --config configs/seen.yaml --out $R --quiet --no-plots
$PY -m ragnav_jax.cli build-memory --config configs/seen.yaml --run $R --quiet
$PY -m ragnav_jax.cli episodes --config configs/seen.yaml --scenes $R --quiet
$PY -m ragnav_jax.cli eval --config configs/seen.yaml --scenes $R --episodes $R/episodes/episodes.jsonl --method ragnav --out /work/main/runs/r42/eval-seen --quiet
