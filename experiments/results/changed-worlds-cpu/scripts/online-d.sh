#!/bin/bash
# changed seen houses: ragnav:online with the tour at (copy of the working tree)
cd /tmp/w22/code
export PYTHONPATH=/tmp/w22/code
PY=/work/main/.venv/bin/python
$PY -m ragnav_jax.cli eval --config configs/seen.yaml --scenes /work/main/runs/seen --changes /tmp/w22/ch0.3 --episodes /tmp/w22/ch0.3-ep/episodes.jsonl --method ragnav:online --out /work/main/runs/r43/online-d --quiet > /work/main/runs/r43/online-d.log 2>&1
