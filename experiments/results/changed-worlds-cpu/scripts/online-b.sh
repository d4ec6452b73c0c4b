#!/bin/bash
# changed seen houses: ragnav:online with the tour (copy of the working tree), then etpnav exploring the changed worlds
cd /tmp/w22/code
export PYTHONPATH=/tmp/w22/code
PY=/work/main/.venv/bin/python
$PY -m ragnav_jax.cli eval --config configs/seen.yaml --scenes /work/main/runs/seen --changes /tmp/w22/ch0.3 --episodes /tmp/w22/ch0.3-ep/episodes.jsonl --method ragnav:online --out /work/main/runs/r43/online-b --quiet > /work/main/runs/r43/online-b.log 2>&1
$PY -m ragnav_jax.cli eval --config configs/seen.yaml --scenes /work/main/runs/seen --changes /tmp/w22/ch0.3 --episodes /tmp/w22/ch0.3-ep/episodes.jsonl --method etpnav --out /work/main/runs/r43/etp-b --quiet > /work/main/runs/r43/etp-b.log 2>&1
