#!/usr/bin/env bash
# The fresh (first) run of each held-out set, with the reader as it was frozen before that run, re-scored with
# RAGNav's instance-level rule (retrieve's instance_accuracy, added after set 1's run): worktrees at the commits
# that froze each design, with only retrieval/evaluate.py's scoring of rows patched in where it lacks it
# (eval_instance.patch, beside this script; set 4's commit has it).
set -euo pipefail
R=${R:-runs/r44}
for pair in "heldout:0e0bb4f" "heldout2:b92b4bd" "heldout3:b931297" "heldout4:bddf4d3"; do
  ph=${pair%%:*}; c=${pair##*:}; wt=/tmp/fresh-$c
  if [ ! -d $wt ]; then
    git worktree add -q $wt $c && ln -s $PWD/.venv $wt/.venv
    patch="$(cd "$(dirname "$0")" && pwd)/eval_instance.patch"
    grep -q instance_accuracy $wt/ragnav_jax/retrieval/evaluate.py || git -C $wt apply "$patch"
  fi
  for run in seen-t unseen2-t unseen3; do
    out=$R/fresh/$run-$ph
    mkdir -p $out
    PYTHONPATH=$wt .venv/bin/python -P -m ragnav_jax.cli retrieve --run $R/$run \
      --episodes $R/time/$run-$ph/episodes.jsonl \
      --out $out/retrieve --force --quiet --allow-unparsed > /dev/null
  done
done
