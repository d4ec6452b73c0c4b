#!/bin/bash
# changed seen houses (changes.fraction=0.3), ragnav:online (a copy of the working tree in /tmp/w22/code)
cd /tmp/w22/code
export PYTHONPATH=/tmp/w22/code
/work/main/.venv/bin/python -m ragnav_jax.cli eval --config configs/seen.yaml --scenes /work/main/runs/seen --changes /tmp/w22/ch0.3 --episodes /tmp/w22/ch0.3-ep/episodes.jsonl --method ragnav:online --out /work/main/runs/r43/online-a --quiet
