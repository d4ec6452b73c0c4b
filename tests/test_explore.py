"""Frontier exploration: coverage of the apartment and a generated house, no penetration, results that do
not depend on the batch, one trace per shape, and the CLI."""

import json

import numpy as np
import pytest

from ragnav_jax.cli import main
from ragnav_jax.config import WorldConfig, load_config
from ragnav_jax.sim.coverage import coverage, scan_cover
from ragnav_jax.sim.explore import explore_scenes, explorer_for
from ragnav_jax.sim.sensors import lidar_angles
from ragnav_jax.sim.stream import ExplorationStream
from ragnav_jax.world.generator import generate_scenes
from ragnav_jax.world.scene import save_scene

CFG = load_config(None, ["explore.max_steps=2500"])


@pytest.fixture(scope="module")
def scenes(apartment):
    house = generate_scenes(WorldConfig(num_scenes=1, min_rooms=3, max_rooms=3, min_objects=10, max_objects=14), seed=2)
    return [apartment, house[0]]


@pytest.fixture(scope="module")
def together(scenes):
    explorer = explorer_for(scenes, CFG)
    return explorer, explore_scenes(scenes, CFG, explorer=explorer)


def _coverage(scene, r):
    return coverage(scene, r.true_pose, r.stream.lidar, lidar_angles(CFG.sim), CFG.sim.robot_radius)


def test_coverage_and_no_penetration(scenes, together):
    _, results = together
    for scene, r in zip(scenes, results):
        cov = _coverage(scene, r)
        assert r.finished, scene.name  # stopped because no frontier was left
        assert cov.fraction >= 0.95, (scene.name, cov.fraction)
        assert r.max_penetration < 0.02, (scene.name, r.max_penetration)
        s = r.stream
        assert s.visible.shape == (len(s.t), len(scene.objects)) and s.lidar.shape[1] == CFG.sim.lidar_rays
        assert s.visible.any(0).mean() >= 0.9  # the camera saw (almost) every object
        np.testing.assert_array_equal(s.t, np.arange(len(s.t)))  # a record every control step
        assert np.all(np.linalg.norm(np.diff(r.true_pose[:, :2], axis=0), axis=1) < 0.2)  # no jumps


def test_batch_composition_does_not_change_a_scene(scenes, together):
    """A scene explored alone (its own, smaller padding) gives what it gives in a batch of different sizes. One
    scene, the one with fewer objects (each scene alone is a compilation of its own, about 40 s here)."""
    _, results = together
    e = min(range(len(scenes)), key=lambda i: len(scenes[i].objects))
    for scene, batched in [(scenes[e], results[e])]:
        (alone,) = explore_scenes([scene], CFG)
        a, b = alone.stream, batched.stream
        assert len(a.t) == len(b.t) and alone.steps == batched.steps
        # Equal up to float32 round-off (XLA may vectorise a batch of one differently from a batch of two).
        np.testing.assert_allclose(a.pose, b.pose, atol=1e-3)
        np.testing.assert_allclose(a.lidar, b.lidar, atol=2e-3)
        assert np.mean(a.visible != b.visible) < 1e-3
        assert abs(alone.path_length - batched.path_length) < 1e-2
        assert alone.finished == batched.finished and alone.plans == batched.plans


def test_new_layouts_do_not_retrace(scenes, together):
    explorer, results = together
    traces = explorer.run._cache_size()  # one per batch shape run so far (the cache may share explorers)
    swapped = explore_scenes(scenes[::-1], CFG, explorer=explorer)  # other layouts in the same slots
    assert explorer.run._cache_size() == traces
    np.testing.assert_allclose(swapped[1].stream.pose, results[0].stream.pose, atol=1e-4)


def test_scan_cover_fills_the_scan_polygon():
    angles = lidar_angles(CFG.sim)
    ranges = np.full((1, angles.size), 2.0, np.float32)
    xs = np.array([0.0, 1.9, 0.0, 2.1, -1.0])
    ys = np.array([0.0, 0.0, -1.9, 0.0, 1.0])
    got = scan_cover(xs, ys, np.zeros((1, 3), np.float32), ranges, angles)
    np.testing.assert_array_equal(got, [True, True, True, False, True])


def test_cli_explore_and_show_trajectory(tmp_path, scenes):
    """The scene the batch test above explores alone, with the same settings, so the CLI reuses that compiled
    explorer of this process."""
    scene = min(scenes, key=lambda s: len(s.objects))
    name = scene.name
    run = tmp_path / "run"
    scenes_dir = tmp_path / "scenes"
    save_scene(scene, scenes_dir / f"{name}.json")
    argv = ["explore", "--scenes", str(scenes_dir), "--out", str(run), "--quiet", "explore.max_steps=2500"]
    assert main(argv) == 0
    summary = json.loads((run / "explore" / "summary.json").read_text())
    assert summary["num_scenes"] == 1 and summary["coverage"] >= 0.95 and summary["all_finished"]
    stream = ExplorationStream.load(run / "explore" / "streams" / f"{name}.npz")
    assert stream.scene == name and len(stream.t) == summary["scenes"][0]["records"]
    assert stream.object_ids == tuple(o.id for o in scene.objects)
    assert (run / "scenes" / f"{name}.json").exists() and (run / "explore" / "plots" / f"{name}.png").exists()
    png = tmp_path / "traj.png"
    assert main(["show-trajectory", str(run), "--scene", name, "--out", str(png)]) == 0
    assert png.read_bytes()[:4] == b"\x89PNG"
    assert main(["show-trajectory", str(run), "--scene", "nope", "--out", str(png)]) == 2
    assert main(argv) == 2  # an exploration is already there (no --force)
    # A differing scene file of the same name in RUN/scenes is a user error, not an overwrite.
    other = tmp_path / "other"
    (other).mkdir()
    (other / f"{name}.json").write_text((scenes_dir / f"{name}.json").read_text().replace(f'"{name}"', f'"{name}2"'))
    assert main(["explore", "--scenes", str(other), "--out", str(run), "--force", "--quiet"]) == 2
