#!/usr/bin/env bash
# Time-indexed queries (issue 22), top-1 retrieval against the exploration stream.
# Houses: the seen split (runs/seen, rebuilt with the sighting log as runs/r44/seen-t), the fixed unseen houses
# (runs/unseen2 -> runs/r44/unseen2-t) and fresh unseen houses made for this measure (runs/r44/unseen3, seed 23).
# Phrasings: the generator's own (episodes.time_phrasing=seen) and the held-out set (heldout).
set -euo pipefail
R=${R:-runs/r44}
rag() { PYTHONPATH=${WT:-.} .venv/bin/python -m ragnav_jax.cli "$@"; }
for run in seen-t unseen2-t unseen3; do
  for ph in seen heldout heldout2; do
    out=$R/time/$run-$ph
    [ -f $out/episodes.jsonl ] || rag episodes --scenes $R/$run --time-indexed --out $out/episodes.jsonl --quiet \
      episodes.time_phrasing=$ph
    rag retrieve --run $R/$run --episodes $out/episodes.jsonl --out $out/retrieve --force --quiet --allow-unparsed > /dev/null
  done
done
