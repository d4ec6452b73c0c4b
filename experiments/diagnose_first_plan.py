"""The device program's first plan on each JAX backend of this machine against the host engine's.

    python experiments/diagnose_first_plan.py --config configs/paper.yaml --scenes RUN --episodes FILE \
        --method oracle --out OUT.json [KEY=VALUE ...]

Prepares the episodes as `ragnav eval` does, then solves every episode's first order with the device
program's `initial_state` (jit, vmapped re-plan) once per backend (the default one and the CPU) and lists
the episodes whose order differs from the host engine's first plan (`host_loop.Loop.replan`).
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import jax
import numpy as np


def main(argv=None) -> int:
    from ragnav_jax.config import load_config
    from ragnav_jax.evaluation.eval_commands import prepare_inputs
    from ragnav_jax.evaluation.execute import make_executor
    from ragnav_jax.evaluation.loop import program, step
    from ragnav_jax.evaluation.methods import method_spec
    from ragnav_jax.evaluation.navigate import prepare_episodes
    from ragnav_jax.language.episodes import load_episodes
    from ragnav_jax.memory.encoder import bank_embedder

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--config", required=True)
    ap.add_argument("--scenes", required=True)
    ap.add_argument("--episodes", required=True)
    ap.add_argument("--method", default="oracle")
    ap.add_argument("--stride", type=int, default=1)
    ap.add_argument("--out", type=Path, required=True)
    ap.add_argument("overrides", nargs="*")
    a = ap.parse_args(argv)
    cfg = load_config(a.config, a.overrides)
    scenes, bank, streams = prepare_inputs(a.scenes, None, a.out.parent / "diag-run", cfg, True)
    episodes = load_episodes(a.episodes, scenes)[:: a.stride]
    embedder = bank_embedder(bank, cfg)
    used = [s for s in scenes if s.name in {e.scene for e in episodes}]
    ex = make_executor(used, cfg)
    loop, states, *_ = prepare_episodes(bank, scenes, episodes, embedder, cfg, method_spec(a.method), streams, ex)
    fl = program.flags_of(cfg, loop.look_cost)
    world = program.world_of(loop)
    inp = program.inputs_of(loop, states, *program.batch_sizes(states, cfg))
    N, O = world.pos.shape[1], world.known.shape[1]
    lam = np.full(len(states), cfg.planning.lam, np.float32)
    report = {"backend": jax.default_backend(), "episodes": len(states), "lam": float(cfg.planning.lam),
              "solver": cfg.planning.solver, "backends": {}}
    host = [list(st.planned) for st in states]

    def pieces(i, lm, w):  # the first re-plan's intermediates, each piece also jitted alone
        st0 = program.initial_state(i, lm, w, fl, N, O)  # its order is the first plan
        q = jax.vmap(lambda s, i, lm: step.order_inputs(s, i, w, lm, fl))(st0, i, lm)
        k = jax.vmap(lambda q: step.solve_order(q, fl))(q)
        return st0, q, k

    got = {}
    for name in dict.fromkeys([jax.default_backend(), "cpu"]):
        dev = jax.devices(name)[0]
        args = jax.device_put((inp, lam, world), dev)
        with jax.default_device(dev):
            st, q, k = jax.device_get(jax.jit(pieces)(*args))
            k_alone = jax.device_get(jax.jit(jax.vmap(lambda q: step.solve_order(q, fl)))(jax.device_put(q, dev)))
        got[name] = (q, k)
        plans = [st.order[e][: st.n_left[e]].tolist() for e in range(len(states))]
        diff = [{"episode": s.ep.id, "strict": bool(s.strict), "host": h, "device": p, "slots": k[e].tolist(),
                 "slots_solved_alone": k_alone[e].tolist(), "ranks": q["ranks"][e].tolist(),
                 "goal_of": q["goal_of"][e].tolist(), "lam": float(q["lam"][e])}
                for e, (s, h, p) in enumerate(zip(states, host, plans)) if h != p]
        report["backends"][name] = {"differ": len(diff), "examples": diff[:20]}
        print(name, "first plans differing from the host's:", len(diff), "of", len(states), flush=True)
    if len(got) == 2:  # which intermediate first differs between the backends
        (qa, ka), (qb, kb) = got.values()
        report["inputs_differ"] = {f: int(np.sum(np.any(np.asarray(qa[f] != qb[f]).reshape(len(states), -1), 1)))
                                   for f in qa if f != "sub"}
        report["inputs_differ"]["sub"] = int(np.sum(~np.all(np.isclose(qa["sub"], qb["sub"]).reshape(len(states), -1), 1)))
        report["slots_differ"] = int(np.sum(np.any(ka != kb, 1)))
        print("differ between backends:", report["inputs_differ"], "slots", report["slots_differ"], flush=True)
    a.out.parent.mkdir(parents=True, exist_ok=True)
    a.out.write_text(json.dumps(report, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
