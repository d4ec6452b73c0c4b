#!/bin/bash
# changed seen houses (changes.fraction=0.3), every method with the memory as explored (frozen), at ca19e29
cd /tmp/s3
export PYTHONPATH=/tmp/s3
/work/main/.venv/bin/python -m ragnav_jax.cli eval --config configs/seen.yaml --scenes /work/main/runs/seen --changes /tmp/w22/ch0.3 --episodes /tmp/w22/ch0.3-ep/episodes.jsonl --method ragnav,oracle,etpnav,remembr,naive_rag,graphrag,lightrag --out /work/main/runs/r43/frozen --quiet
