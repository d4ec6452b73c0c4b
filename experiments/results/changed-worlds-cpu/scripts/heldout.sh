#!/bin/bash
# Held-out measure of issue 22: the fixed unseen houses (runs/unseen2) after their change lists (changes.fraction=0.3,
# configs/unseen.yaml's seed), unseen-split episodes generated on the changed houses; every method, code frozen
cd /tmp/s3
export PYTHONPATH=/tmp/s3
/work/main/.venv/bin/python -m ragnav_jax.cli eval --config configs/unseen.yaml --scenes /work/main/runs/unseen2 --changes /tmp/w22/uch --episodes /tmp/w22/uch-ep/episodes.jsonl --method ragnav:online,ragnav,oracle,etpnav,remembr,naive_rag,graphrag,lightrag --out /work/main/runs/r43/heldout --quiet
