"""Benchmark: env-steps per second of the MJX world (physics + lidar + camera visibility) against a
single-threaded loop of MuJoCo's C engine on the same model, both measured in this run.

One env step = `sim.substeps` physics steps, a lidar scan of `sim.lidar_rays` rays and the camera's
visibility check of every object (MJX: four rays per object slot; C: four rays per object that is in the
field of view and range, what a C implementation would do). MJX: `NavEnv.step` vmapped over B envs and
scanned over K steps in one jitted call; timed as the median of several calls after two warm-up calls
(the first call may compile twice); compile time is measured apart. The C loop is timed right before
each MJX row and the ratio uses that measurement (the machine's load may change during a run). C: mujoco.mj_step,
mujoco.mj_multiRay for the lidar and mujoco.mj_ray for the camera, in a Python loop.

    .venv/bin/python experiments/bench_sim.py --out runs/bench_sim [--batches 1,64,256,1024] [KEY=VALUE ...]

Writes RUN/bench_sim.json (and prints it). Host timing stays outside the jitted code.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import statistics
import sys
import time
from pathlib import Path

import jax
import jax.numpy as jnp
import mujoco
import numpy as np

from ragnav_jax.config import load_config, to_dict
from ragnav_jax.runs import init_run
from ragnav_jax.sim.env import NavEnv
from ragnav_jax.sim.model import scene_mj_model
from ragnav_jax.sim.sensors import lidar_angles
from ragnav_jax.world.scene import example_scene_path, load_scene


def bench_mjx(env: NavEnv, batch: int, steps: int, repeats: int, seed: int = 0) -> dict:
    keys = jax.random.split(jax.random.PRNGKey(seed), batch)
    actions = jax.random.uniform(jax.random.PRNGKey(seed + 1), (steps, batch, 3), minval=-1.0, maxval=1.0)

    def rollout(state, actions):
        def body(s, a):
            s = jax.vmap(env.step)(s, a)
            return s, s.metrics["visible_objects"]

        return jax.lax.scan(body, state, actions)

    reset = jax.jit(jax.vmap(env.reset))
    state = jax.block_until_ready(reset(keys))
    t0 = time.perf_counter()
    compiled = jax.jit(rollout).lower(state, actions).compile()
    compile_s = time.perf_counter() - t0
    for _ in range(2):  # warm-up
        out = jax.block_until_ready(compiled(state, actions))
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = jax.block_until_ready(compiled(state, actions))
        times.append(time.perf_counter() - t0)
    med = statistics.median(times)
    return {
        "batch": batch, "steps_per_call": steps, "repeats": repeats, "compile_s": round(compile_s, 2),
        "median_call_s": round(med, 4), "min_call_s": round(min(times), 4), "max_call_s": round(max(times), 4),
        "env_steps_per_s": round(batch * steps / med, 1),
        "mean_visible_objects": round(float(jnp.mean(out[1])), 3),
    }


def bench_c(scene, cfg, walls: int, objects: int, steps: int, repeats: int, seed: int = 0) -> dict:
    sim = cfg.sim
    m = scene_mj_model(scene, walls, objects, sim)
    d = mujoco.MjData(m)
    rb = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, "robot")
    angles = lidar_angles(sim).astype(np.float64)
    L = angles.size
    rng = np.random.default_rng(seed)
    actions = rng.uniform(-1, 1, (steps, 3))
    obj = np.array([o.position for o in scene.objects]).reshape(-1, 3)
    size = np.array([o.size for o in scene.objects]).reshape(-1, 3)
    obj_geom = 1 + walls + np.arange(len(scene.objects))
    vec = np.zeros((L, 3))
    dist = np.zeros(L)
    gid = np.zeros(L, np.int32)
    one = np.zeros(1, np.int32)
    half_fov = math.radians(sim.camera_fov_deg) / 2

    def env_step(a):
        x, y, yaw = d.qpos
        c, s = math.cos(yaw), math.sin(yaw)
        v = sim.max_speed * a[:2]
        d.ctrl[:] = (c * v[0] - s * v[1], s * v[0] + c * v[1], sim.max_yaw_rate * a[2])
        for _ in range(sim.substeps):
            mujoco.mj_step(m, d)
        x, y, yaw = d.qpos
        vec[:, 0] = np.cos(yaw + angles)
        vec[:, 1] = np.sin(yaw + angles)
        pnt = np.array([x, y, sim.lidar_height])
        mujoco.mj_multiRay(m, d, pnt, vec.ravel(), None, 1, rb, gid, dist, None, L, sim.lidar_range)
        cam = np.array([x, y, sim.camera_height])
        seen = 0
        for i in range(len(obj)):
            rel = obj[i, :2] - cam[:2]
            r = math.hypot(*rel)
            bearing = math.atan2(math.sin(math.atan2(rel[1], rel[0]) - yaw), math.cos(math.atan2(rel[1], rel[0]) - yaw))
            if r > sim.camera_range or abs(bearing) > half_fov:
                continue
            top = obj[i] + np.array([0, 0, size[i, 2] / 2 - min(0.01, size[i, 2] / 4)])
            long_x = size[i, 0] >= size[i, 1]
            off = 0.35 * max(size[i, 0], size[i, 1]) * (np.array([1.0, 0, 0]) if long_x else np.array([0, 1.0, 0]))
            for t in (top, top - off, top + off, obj[i]):
                v3 = t - cam
                n = np.linalg.norm(v3)
                hit = mujoco.mj_ray(m, d, cam, v3 / n, None, 1, rb, one)
                if one[0] == obj_geom[i] or hit < 0 or hit >= n - 1e-3:
                    seen += 1
                    break
        return seen

    d.qpos[:] = (*scene.start.position, scene.start.yaw)
    mujoco.mj_forward(m, d)
    for a in actions[: min(20, steps)]:  # warm-up
        env_step(a)
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for a in actions:
            env_step(a)
        times.append(time.perf_counter() - t0)
    med = statistics.median(times)
    return {"steps_per_call": steps, "repeats": repeats, "median_call_s": round(med, 4),
            "min_call_s": round(min(times), 4), "max_call_s": round(max(times), 4),
            "env_steps_per_s": round(steps / med, 1)}


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--out", default="runs/bench_sim", help="run folder")
    p.add_argument("--scene", default=str(example_scene_path()), help="scene file (default: the apartment)")
    p.add_argument("--batches", default="1,64,256,1024")
    p.add_argument("--steps", type=int, default=16, help="env steps per timed MJX call")
    p.add_argument("--repeats", type=int, default=5)
    p.add_argument("--c-steps", type=int, default=300, help="env steps per timed C loop")
    p.add_argument("--config")
    p.add_argument("overrides", nargs="*")
    args = p.parse_args(argv)
    cfg = load_config(args.config, args.overrides)
    run = init_run(Path(args.out), cfg, "bench_sim", argv=sys.argv)
    scene = load_scene(args.scene)
    env = NavEnv([scene], cfg.sim)
    layout = env.model.layout
    rows, c_runs = [], []
    for b in (int(x) for x in args.batches.split(",")):
        # The C loop is timed right before each MJX row, so a ratio compares measurements taken under the
        # same machine load (other jobs may share the CPU).
        c = bench_c(scene, cfg, layout.walls, layout.objects, args.c_steps, args.repeats)
        c_runs.append(c)
        r = bench_mjx(env, b, args.steps, args.repeats)
        r["c_env_steps_per_s"] = c["env_steps_per_s"]
        r["ratio_vs_c"] = round(r["env_steps_per_s"] / c["env_steps_per_s"], 3)
        rows.append(r)
        print(f"MJX batch {b:5d}: {r['env_steps_per_s']:9.0f} env-steps/s vs C (1 thread) {c['env_steps_per_s']:7.0f}"
              f"  -> x{r['ratio_vs_c']:.2f} (compile {r['compile_s']:.1f} s)", flush=True)
    c = {**c_runs[-1], "env_steps_per_s_each_row": [x["env_steps_per_s"] for x in c_runs],
         "env_steps_per_s": round(statistics.median(x["env_steps_per_s"] for x in c_runs), 1)}
    out = {
        "what": "env-steps/s: physics substeps + lidar + camera visibility per env step",
        "scene": scene.name,
        "walls": len(scene.walls), "objects": len(scene.objects),
        "physics_steps_per_env_step": cfg.sim.substeps, "lidar_rays": cfg.sim.lidar_rays,
        "load_average_1min": round(os.getloadavg()[0], 2),
        "c_engine": c, "mjx": rows,
        "device": str(jax.devices()[0]), "cpu_count": os.cpu_count(), "platform": platform.platform(),
        "versions": {"jax": jax.__version__, "mujoco": mujoco.__version__},
        "sim": to_dict(cfg.sim),
    }
    (run / "bench_sim.json").write_text(json.dumps(out, indent=1) + "\n")
    print(f"written {run / 'bench_sim.json'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
