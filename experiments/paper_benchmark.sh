#!/usr/bin/env bash
# The whole paper benchmark, timed: a fresh paper-preset run (generate, explore, build-memory) and the closed loop
# of all 11 methods over all 840 episodes of experiments/results/paper-episodes.jsonl.
#   experiments/paper_benchmark.sh RUN [KEY=VALUE ...]      e.g. eval.batch_size=1024 memory.embedder=hashing
# Writes RUN/times.json (seconds of each phase and in all); the eval's run folder is RUN/eval (its tables in
# RUN/eval/eval/). The overrides go to every command; eval.engine=device is set here (the ETPNav-style baseline
# runs on the host loop on its own). PHASES=prep runs generate, explore and build-memory only; PHASES=eval then
# runs the eval on that run folder and adds its seconds to the ones RUN/times.json already holds.
set -euo pipefail
R=$1; shift
rag() { python3 -m ragnav_jax.cli "$@"; }
M=ragnav,ragnav:no_forest,ragnav:no_topology,ragnav:no_spatial,ragnav:no_boost,naive_rag,graphrag,lightrag,remembr,etpnav,oracle
now() { date +%s.%N; }
PHASES=${PHASES:-all}
t0=$(now); t1=$t0; t2=$t0; t3=$t0
if [ "$PHASES" != eval ]; then
  rag generate --config configs/paper.yaml --out "$R" --force --quiet --no-plots "$@"
  t1=$(now)
  rag explore --config configs/paper.yaml --out "$R" --force --quiet --no-plots "$@"
  t2=$(now)
  rag build-memory --config configs/paper.yaml --run "$R" --force --quiet "$@"
  t3=$(now)
fi
t4=$t3
if [ "$PHASES" != prep ]; then
  rag eval --config configs/paper.yaml --scenes "$R" --episodes experiments/results/paper-episodes.jsonl --method $M \
    --out "$R/eval" --force --quiet eval.engine=device "$@"
  t4=$(now)
fi
python3 - "$R/times.json" "$PHASES" "$t0" "$t1" "$t2" "$t3" "$t4" <<'EOF'
import json, sys
path, phases, t = sys.argv[1], sys.argv[2], [float(x) for x in sys.argv[3:]]
names = ["generate", "explore", "build_memory", "eval"]
d = {n: round(b - a, 1) for n, a, b in zip(names, t, t[1:])}
if phases == "eval":  # the preparation's seconds from the PHASES=prep run
    d = json.load(open(path)) | {"eval": d["eval"]}
elif phases == "prep":
    d.pop("eval")
d["total"] = round(sum(v for k, v in d.items() if k != "total"), 1)
json.dump(d, open(path, "w"), indent=1)
print(json.dumps(d))
EOF
