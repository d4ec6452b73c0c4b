"""Where the device closed loop's time goes: each phase of one reflection and a stretch of driving, timed apart
at one batch size, next to the whole program.

    python experiments/profile_device_loop.py --out DIR [--scenes 4] [--distinct 128] [--batch 16384] \
        [--method oracle] [--steps 100] [--lanes 4096,8192] [--refill 1.0,0.125] [--no-phases]

The paper preset's first --scenes scenes are generated, explored and given a memory (hashing embedder), the
method's evaluate_navigation runs on --distinct episodes with eval.engine=device, and the states it hands to
`loop.program.run_device` are tiled to --batch. Then, each jitted alone on that batch (median of 3 after a
first, compiling call): the initial plan, `step.next_leg`, `step.leg_waypoints`, the look-around, `step.after_leg`
(all vmapped, from the start pose), --steps control steps of driving (`Executor.advance`), and the whole
`closed_loop` at each --refill share (all --batch episodes at once, then queued on each of --lanes; first call
and one more). Writes DIR/profile.json; absolute times only mean something on a GPU.
"""

from __future__ import annotations

import argparse
import copy
import dataclasses
import json
import statistics
import sys
import time
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from ragnav_jax.bench.profiles import PROFILES  # noqa: E402
from ragnav_jax.bench.sections import loop_episodes, paper_config, run_pipeline  # noqa: E402
from ragnav_jax.evaluation.execute import Driving, make_executor  # noqa: E402
from ragnav_jax.evaluation.loop import program, step  # noqa: E402
from ragnav_jax.evaluation.navigate import evaluate_navigation  # noqa: E402
from ragnav_jax.evaluation.verify import Verifier  # noqa: E402


def timed(f, *args, repeats: int = 3) -> dict:
    """{compile_s: first call - median, median_s} of a jitted f(*args)."""
    t = time.perf_counter()
    out = jax.block_until_ready(f(*args))
    first = time.perf_counter() - t
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        jax.block_until_ready(f(*args))
        times.append(time.perf_counter() - t)
    med = statistics.median(times)
    return {"median_s": med, "compile_s": max(first - med, 0.0), "out": out}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--scenes", type=int, default=4)
    ap.add_argument("--distinct", type=int, default=128)
    ap.add_argument("--batch", type=int, default=16384)
    ap.add_argument("--method", default="oracle")
    ap.add_argument("--steps", type=int, default=100)
    ap.add_argument("--lanes", default="", help="comma-separated lane counts: the whole closed_loop is also timed "
                    "with the --batch episodes queued on each (eval.batch_size)")
    ap.add_argument("--refill", default="1.0", help="comma-separated eval.refill shares (of the lanes one reflection "
                    "serves) the whole closed_loop is timed at, on each lane count")
    ap.add_argument("--no-phases", action="store_true", help="time only the whole closed_loop")
    a = ap.parse_args(argv)
    p = PROFILES["quick"].replace(e2e_explore_steps=None, e2e_explore_batch=None)
    base = paper_config(p, a.scenes)
    cfg = dataclasses.replace(base, eval=dataclasses.replace(base.eval, engine="device", batch_size=a.batch))
    _, art = run_pipeline(cfg, p, print, execute=False, plan=False)
    distinct = loop_episodes(art["episodes"], min(a.distinct, len(art["episodes"])))
    used = [s for s in art["scenes"] if s.name in {ep.scene for ep in distinct}]
    ex = make_executor(used, cfg)
    captured = {}

    def capture(loop, states, cfg, progress=None):
        captured.update(loop=loop, states=copy.deepcopy(states))

    run_device, program.run_device = program.run_device, capture
    try:
        evaluate_navigation(art["bank"], art["scenes"], distinct, art["embedder"], cfg, a.method,
                            streams={s.name: r.stream for s, r in zip(art["scenes"], art["explored"])}, executor=ex,
                            verifier=Verifier.build(art["embedder"], cfg))
    finally:
        program.run_device = run_device
    loop, states = captured["loop"], captured["states"]
    states = [states[i % len(states)] for i in range(a.batch)]
    G, C, S, T = program.batch_sizes(states, cfg)
    fl = program.flags_of(cfg, loop.look_cost)
    world = program.world_of(loop)
    t = time.perf_counter()
    inp = program.inputs_of(loop, states, G, C, S, T)
    host = {"inputs_of_s": time.perf_counter() - t}
    E = len(states)
    sidx = jnp.asarray([st.s for st in states], jnp.int32)
    start = jnp.asarray([[*loop.scenes[st.ep.scene].start.position[:2], loop.scenes[st.ep.scene].start.yaw]
                         for st in states], jnp.float32)
    lam = jnp.full(E, cfg.planning.lam, jnp.float32)
    N, O = world.pos.shape[1], world.known.shape[1]
    in_ep = (0, 0, None, 0, 0)
    res = {}
    phases = {}
    if not a.no_phases:
        res["init"] = timed(jax.jit(lambda i, s: ex.init(i, s)), sidx, start)
        d = res["init"]["out"]
        pose = d.qpos[:, :3]
        res["initial_plan"] = timed(jax.jit(lambda inp, lam: program.initial_state(inp, lam, world, fl, N, O)), inp,
                                    lam)
        st0 = res["initial_plan"]["out"]
        res["next_leg"] = timed(jax.jit(lambda s, p: jax.vmap(
            lambda s, i, w, p, lm: step.next_leg(s, i, w, p, lm, fl), in_axes=in_ep)(s, inp, world, p, lam)), st0, pose)
        st1 = res["next_leg"]["out"]
        res["leg_waypoints"] = timed(jax.jit(lambda s, p: jax.vmap(
            lambda s, i, w, p: step.leg_waypoints(s, i, w, p, fl), in_axes=in_ep[:4])(s, inp, world, p)), st1, pose)
        pts, n = res["leg_waypoints"]["out"]
        res["look"] = timed(jax.jit(lambda d: ex.look_fn(sidx, d)), d)
        visible = res["look"]["out"][0]
        res["after_leg"] = timed(jax.jit(lambda s, p, v: jax.vmap(
            lambda s, i, w, p, a, v, lm: step.after_leg(s, i, w, p, a, v, lm, fl), in_axes=(0, 0, None, 0, 0, 0, 0))(
            s, inp, world, p, jnp.ones(E, bool), v, lam)), st1, pose, visible)
        allow = jnp.full(E, a.steps, jnp.int32)
        res[f"drive_{a.steps}_steps"] = timed(jax.jit(lambda d: ex.advance(sidx, Driving.start(d, pts, n, allow), 0)),
                                              d)
        phases["drive_steps_taken_mean"] = float(np.asarray(res[f"drive_{a.steps}_steps"]["out"][0].steps).mean())
    final = None
    for lanes in [None] + [int(x) for x in a.lanes.split(",") if x]:
        for r in [float(x) for x in a.refill.split(",")]:
            prog = program.compiled(ex, fl._replace(refill=r), lanes)
            key = f"closed_loop_refill_{r:g}" + ("" if lanes is None else f"_lanes_{lanes}")
            res[key] = timed(prog, world, inp, sidx, start, lam, repeats=1)
            same = None if final is None else all(bool(np.array_equal(x, y)) for x, y in zip(
                jax.tree.leaves(final), jax.tree.leaves(res[key]["out"])))
            final = res[key]["out"] if final is None else final
            print(key, {k: round(v, 3) for k, v in res[key].items() if k != "out"}, "same State:", same, flush=True)
            if same is not None:
                phases[key + "_same_state"] = same
    out = {"device": str(jax.devices()[0].device_kind), "method": a.method, "batch": E, "distinct": len(distinct),
           "scenes": a.scenes, "host": host,
           "phases": {k: {"median_s": v["median_s"], "compile_s": v["compile_s"]} for k, v in res.items()},
           **phases,
           "legs_max": int(np.asarray(final.legs).max()), "legs_mean": float(np.asarray(final.legs).mean()),
           "steps_mean": float(np.asarray(final.steps).mean()),
           "look_steps_mean": float(np.asarray(final.look_steps).mean())}
    Path(a.out).mkdir(parents=True, exist_ok=True)
    (Path(a.out) / "profile.json").write_text(json.dumps(out, indent=1))
    print(json.dumps(out, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
