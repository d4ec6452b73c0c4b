#!/usr/bin/env bash
# Time-indexed queries (issue 22): top-1 retrieval against the exploration stream.
# Houses: the seen split (runs/seen rebuilt with the sighting log: $R/seen-t), the fixed unseen houses (runs/unseen2
# rebuilt: $R/unseen2-t) and fresh unseen houses made for this measure ($R/unseen3: generate, explore, build-memory
# with --config configs/unseen.yaml seed=23 world.name_prefix=fresh).
# Phrasings: the generator's own (episodes.time_phrasing=seen) and held-out sets 1-3 (heldout, heldout2, heldout3).
# Methods: RAGNav, RAGNav with the time term off (retrieval.w_time=0), and the NaiveRAG-style baseline.
set -euo pipefail
R=${R:-runs/r44}
rag() { PYTHONPATH=${WT:-.} .venv/bin/python -P -m ragnav_jax.cli "$@"; }  # -P: the package from WT, not the cwd
for run in seen-t unseen2-t unseen3; do
  for ph in seen heldout heldout2 heldout3 heldout4; do
    out=$R/time/$run-$ph
    [ -f $out/episodes.jsonl ] || rag episodes --scenes $R/$run --time-indexed --out $out/episodes.jsonl --quiet \
      episodes.time_phrasing=$ph
    rag retrieve --run $R/$run --episodes $out/episodes.jsonl --out $out/retrieve --force --quiet \
      --allow-unparsed > /dev/null
    [ -n "${ONLY_RAGNAV:-}" ] && continue
    rag retrieve --run $R/$run --episodes $out/episodes.jsonl --out $out/retrieve-notime --force --quiet \
      --allow-unparsed retrieval.w_time=0 > /dev/null
    rag retrieve --run $R/$run --episodes $out/episodes.jsonl --out $out/retrieve-naive_rag --method naive_rag \
      --force --quiet --allow-unparsed > /dev/null
  done
done
# Without the sighting log: the banks as built before it (runs/seen, runs/unseen2), the generator's phrasings.
for pair in "seen-t:runs/seen" "unseen2-t:runs/unseen2"; do
  run=${pair%%:*}; old=${pair##*:}
  rag retrieve --run $old --episodes $R/time/$run-seen/episodes.jsonl --out $R/time/$run-seen/retrieve-nolog --force \
    --quiet --allow-unparsed > /dev/null
done
