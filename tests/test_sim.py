"""MJX world vs MuJoCo's C engine: slot geometry, rays, a controlled trajectory; brax wrappers."""

import jax
import jax.numpy as jnp
import mujoco
import numpy as np
import pytest
from mujoco import mjx

from ragnav_jax.config import SimConfig, WorldConfig
from ragnav_jax.sim import grid as G
from ragnav_jax.sim.controller import Path, follow
from ragnav_jax.sim.model import (
    GEOMETRY_FIELDS,
    PARK,
    batch_model,
    build_template,
    initial_data,
    mjx_step,
    scene_geometry,
    scene_mj_model,
    slot_counts,
)
from ragnav_jax.sim.sensors import camera_visibility, lidar_angles, lidar_scan, look_around
from ragnav_jax.world.generator import generate_scenes

SIM = SimConfig(lidar_rays=48)


@pytest.fixture(scope="module")
def scenes(apartment):
    small = generate_scenes(WorldConfig(num_scenes=1, min_rooms=2, max_rooms=3, min_objects=8, max_objects=12), seed=1)
    return [apartment, *small]


@pytest.fixture(scope="module")
def template(scenes):
    return build_template(*slot_counts(scenes), SIM)


def test_slot_geometry_matches_compiled_models(scenes, template):
    geo = scene_geometry(scenes, template)
    W, n_obj = template.layout.walls, template.layout.objects
    for b, s in enumerate(scenes):
        mj = scene_mj_model(s, W, n_obj, SIM)  # the same slots written as MJCF and compiled by MuJoCo
        for k in GEOMETRY_FIELDS:
            np.testing.assert_allclose(np.asarray(getattr(geo, k)[b]), getattr(mj, k), atol=2e-6, err_msg=k)
        # Unused slots are parked far below the house.
        pos = np.asarray(geo.geom_pos[b])
        used = 1 + np.r_[np.arange(len(s.walls)), W + np.arange(len(s.objects))]
        parked = np.setdiff1d(np.arange(1, 1 + W + n_obj), used)
        assert np.all(pos[parked, 2] <= -PARK + 1e-3)
    assert len(scenes[1].walls) < W  # the small scene does use parked slots


def _poses(scene, n, seed):
    from ragnav_jax.sim.env import reachable_points

    rng = np.random.default_rng(seed)
    pts = reachable_points(scene, SIM.robot_radius, k=n, seed=seed)
    return np.concatenate([pts, rng.uniform(-np.pi, np.pi, (n, 1)).astype(np.float32)], 1)


def test_lidar_matches_c_engine_in_a_batched_model(scenes, template):
    """Rays of each scene of one batched model agree with the C engine on that scene's own model."""
    geo = scene_geometry(scenes, template)
    m, axes = batch_model(template.mx, geo)
    angles = jnp.asarray(lidar_angles(SIM))
    rb = template.layout.robot_body
    poses = np.stack([_poses(s, 6, seed=b) for b, s in enumerate(scenes)])  # (B, 6, 3)

    def scans(m, poses):
        def one(p):
            d = initial_data(m, p)
            return lidar_scan(m, d, angles, SIM.lidar_height, SIM.lidar_range, rb)

        return jax.vmap(one)(poses)

    got = np.asarray(jax.jit(jax.vmap(scans, in_axes=(axes, 0)))(m, jnp.asarray(poses)))
    assert got.shape == (len(scenes), 6, SIM.lidar_rays)
    W, n_obj = template.layout.walls, template.layout.objects
    worst = 0.0
    for b, s in enumerate(scenes):
        mj = scene_mj_model(s, W, n_obj, SIM)
        d = mujoco.MjData(mj)
        gid = np.zeros(1, np.int32)
        for i, (x, y, yaw) in enumerate(poses[b]):
            d.qpos[:] = (x, y, yaw)
            mujoco.mj_forward(mj, d)
            for j, a in enumerate(lidar_angles(SIM)):
                vec = np.array([np.cos(yaw + a), np.sin(yaw + a), 0.0])
                r = mujoco.mj_ray(mj, d, np.array([x, y, SIM.lidar_height]), vec, None, 1, rb, gid)
                want = SIM.lidar_range if (r < 0 or r > SIM.lidar_range) else r
                worst = max(worst, abs(want - got[b, i, j]))
    assert worst < 5e-3, worst
    assert np.all(got > SIM.robot_radius)  # the robot's own sphere is never hit


def test_controlled_trajectory_matches_c_engine(scenes, template):
    """The same velocity commands (including a push into a wall) give the same motion in MJX and C."""
    scene = scenes[0]
    mj = scene_mj_model(scene, template.layout.walls, template.layout.objects, SIM)
    mx = mjx.put_model(mj)
    steps = 120
    t = np.arange(steps)
    ctrl = np.stack([0.6 * np.ones(steps), np.where(t < 60, 0.0, -0.8), np.where(t < 40, 1.0, 0.0)], 1).astype(np.float32)
    start = np.array([*scene.start.position, scene.start.yaw])

    @jax.jit
    def roll(ctrl):
        d = initial_data(mx, jnp.asarray(start, jnp.float32))

        def body(d, u):
            d = mjx_step(mx, d.replace(ctrl=u))
            return d, (d.qpos, jnp.min(d._impl.contact.dist))

        return jax.lax.scan(body, d, ctrl)[1]

    qpos, dist = (np.asarray(x) for x in roll(jnp.asarray(ctrl)))
    d = mujoco.MjData(mj)
    d.qpos[:] = start
    want = []
    for u in ctrl:
        d.ctrl[:] = u
        mujoco.mj_step(mj, d)
        want.append(d.qpos.copy())
    want = np.array(want)
    assert np.min(dist) < 0.0  # the push reached the wall: the comparison includes a contact
    np.testing.assert_allclose(qpos, want, atol=2e-3)
    assert -np.min(dist) < 0.02  # penetration stays below 2 cm even when pushing at full force


def test_follow_stays_on_path_and_stops():
    pts = jnp.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [1.0, 1.0]])
    path = Path.of(pts, 3)
    cmd, path = follow(path, jnp.array([0.0, 0.0, 0.0]), 0.4, 0.8, 2.0)
    assert int(path.index) == 1 and cmd[0] > 0 and abs(float(cmd[1])) < 1e-6
    # Heading toward the goal at the last waypoint: slows down, never moves back along the list.
    cmd, path = follow(path, jnp.array([1.0, 0.95, np.pi / 2]), 0.4, 0.8, 2.0)
    assert int(path.index) == 2 and 0 < float(cmd[1]) < 0.1
    cmd, _ = follow(Path.empty(4), jnp.zeros(3), 0.4, 0.8, 2.0)
    np.testing.assert_array_equal(cmd, 0.0)


@pytest.mark.parametrize("H,W", [(1, 1), (5, 7)])
def test_distance_field_and_path(H, W):
    spec = G.GridSpec(0.5, (H, W), 1, 0.0)
    cost = jnp.ones((H, W))
    if W > 3:
        cost = cost.at[: H - 1, 3].set(G.BIG)  # a wall with a gap at the bottom row
    d = jax.jit(lambda c: G.distance_field(spec, c, jnp.array([0, 0])))(cost)
    assert float(d[0, 0]) == 0.0
    goal = jnp.array([0, W - 1])
    cells, n, ok = G.extract_path(d, goal, 4 * (H + W))
    cells = np.asarray(cells)[: int(n)]
    assert bool(ok) and tuple(cells[0]) == (0, 0) and tuple(cells[-1]) == (0, W - 1)
    assert all(float(cost[i, j]) < G.BIG for i, j in cells)
    assert np.all(np.abs(np.diff(cells, axis=0)).max(1) == 1) if len(cells) > 1 else True


def test_brax_wrappers(apartment):
    """NavEnv runs through brax's training wrappers (vmap, episode, auto-reset) under jit."""
    from brax.envs.wrappers import training

    from ragnav_jax.sim.env import NavEnv

    env = NavEnv([apartment], SIM, with_camera=False)
    wrapped = training.wrap(env, episode_length=3, action_repeat=1)
    state = jax.jit(wrapped.reset)(jax.random.split(jax.random.PRNGKey(0), 2))
    assert state.obs.shape == (2, env.observation_size)
    step = jax.jit(wrapped.step)
    for _ in range(4):
        state = step(state, jnp.full((2, 3), 0.5))
    assert state.obs.shape == (2, env.observation_size) and np.all(np.isfinite(state.obs))
    np.testing.assert_array_equal(state.info["steps"], [1, 1])  # auto-reset after 3 steps
    assert set(state.metrics) == {"distance", "visible_objects", "penetration", "success"}
    assert step._cache_size() == 1


def test_look_around_is_the_camera_turned_in_place(scenes, template):
    """look_around (lines of sight cast once) sees what camera_visibility sees at some heading of the turn."""
    geo = scene_geometry(scenes, template)
    m, axes = batch_model(template.mx, geo)
    O = template.layout.objects
    geom = jnp.arange(template.layout.obj_geom0, template.layout.obj_geom0 + O, dtype=jnp.int32)
    rb = template.layout.robot_body
    headings = jnp.linspace(0, 2 * np.pi, 8, endpoint=False)
    poses = np.stack([_poses(s, 5, seed=7 + b) for b, s in enumerate(scenes)])  # (B, 5, 3)
    objs = np.zeros((len(scenes), O, 2, 3), np.float32)
    objs[..., 1, :] = 0.01
    for b, s in enumerate(scenes):
        for j, o in enumerate(s.objects):
            objs[b, j] = o.position, o.size
    mask = jnp.asarray(objs[..., 1, 0] > 0.011)

    def both(m, poses, objs, mask):
        def one(p):
            d = initial_data(m, p)
            turned = jax.vmap(lambda h: camera_visibility(m, d.replace(qpos=d.qpos.at[2].set(h)), objs[:, 0], objs[:, 1],
                                                          mask, geom, SIM, rb).visible)(headings)
            return look_around(m, d, objs[:, 0], objs[:, 1], mask, geom, SIM, rb, headings)[0], turned.any(0)

        return jax.vmap(one)(poses)

    got, want = jax.jit(jax.vmap(both, in_axes=(axes, 0, 0, 0)))(m, jnp.asarray(poses), jnp.asarray(objs), mask)
    np.testing.assert_array_equal(np.asarray(got), np.asarray(want))
    assert np.asarray(want).any() and not np.asarray(want).all()  # some objects seen, not all
