#!/bin/bash
# The two changed-house benchmarks of issue 22 (run from the repository root; RUN folders as in this session).
# Development: the seen split's houses (configs/seen.yaml, runs/seen: generated, explored and built by
# ../../round41-cpu/scripts/seen-split.sh). Held out: the fixed unseen houses (configs/unseen.yaml, runs/unseen2).
set -e
ragnav changes --config configs/seen.yaml --scenes runs/seen --out /tmp/w22/ch0.3 --no-plots --quiet changes.fraction=0.3
ragnav changes --config configs/seen.yaml --scenes runs/seen --apply /tmp/w22/ch0.3 --out /tmp/w22/ch0.3-scenes --quiet
ragnav episodes --config configs/seen.yaml --scenes /tmp/w22/ch0.3-scenes --out /tmp/w22/ch0.3-ep/episodes.jsonl --quiet
ragnav changes --config configs/unseen.yaml --scenes runs/unseen2 --out /tmp/w22/uch --no-plots --quiet changes.fraction=0.3
ragnav changes --config configs/unseen.yaml --scenes runs/unseen2 --apply /tmp/w22/uch --out /tmp/w22/uch-scenes --quiet
ragnav episodes --config configs/unseen.yaml --scenes /tmp/w22/uch-scenes --out /tmp/w22/uch-ep/episodes.jsonl --quiet
