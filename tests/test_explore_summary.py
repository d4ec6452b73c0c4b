"""Rooms entered and rooms whose objects were never seen (sim/coverage.py), and the exploration summary
fields built from them; synthetic trajectories, no MJX run."""

import json

import numpy as np
import pytest

from ragnav_jax.config import load_config
from ragnav_jax.sim.coverage import densify, room_objects_unseen, rooms_entered
from ragnav_jax.world.scene import Room, Scene, SceneObject, Start, save_scene

# Three rooms side by side; the middle one is a 0.5 m wide strip a straight path can cross between records.
STRIP = Scene(
    "strip",
    (
        Room("a", "study", (0.0, 0.0), (2.0, 2.0)),
        Room("b", "hallway", (2.0, 0.0), (2.5, 2.0)),
        Room("c", "kitchen", (2.5, 0.0), (5.0, 2.0)),
    ),
    (),
    (
        SceneObject("desk_1", "desk", (1.0, 1.0, 0.4), room="a"),
        SceneObject("sink_1", "sink", (4.0, 1.0, 0.4), room="c"),
    ),
    Start((1.0, 1.0)),
)


@pytest.mark.parametrize("T", [0, 1, 2, 7])
def test_densify_keeps_vertices_and_spacing(T):
    xy = np.random.default_rng(T).uniform(0, 5, (T, 3))  # a yaw column is ignored
    got = densify(xy, 0.05)
    assert got.shape[1] == 2 and got.shape[0] >= T
    if T:
        assert all(np.isclose(got, p[:2]).all(1).any() for p in xy)
    if T >= 2:
        assert np.hypot(*np.diff(got, axis=0).T).max() <= 0.05 + 1e-9


def test_room_crossed_between_records_counts_as_entered():
    pose = np.array([[1.0, 1.0, 0.0], [4.0, 1.0, 0.0]])  # two records, one in a, one in c
    np.testing.assert_array_equal(rooms_entered(STRIP, pose), [True, True, True])
    np.testing.assert_array_equal(rooms_entered(STRIP, pose, margin=0.2), [True, True, True])
    np.testing.assert_array_equal(rooms_entered(STRIP, pose, margin=0.3), [True, False, True])  # b is 0.5 m wide
    np.testing.assert_array_equal(rooms_entered(STRIP, pose[:1]), [True, False, False])
    np.testing.assert_array_equal(rooms_entered(STRIP, np.zeros((0, 3))), [False, False, False])


def test_rooms_entered_against_dense_sampling(apartment):
    """Reference: every trajectory point sampled 200 times per segment, tested room by room."""
    rng = np.random.default_rng(0)
    for _ in range(20):
        pose = np.column_stack([rng.uniform(0, 10, 4), rng.uniform(0, 10, 4)])
        t = np.linspace(0, 1, 200)[:, None]
        dense = np.concatenate([p + t * (q - p) for p, q in zip(pose[:-1], pose[1:])])
        want = [
            (
                (dense[:, 0] >= r.min[0] + 0.15)
                & (dense[:, 0] <= r.max[0] - 0.15)
                & (dense[:, 1] >= r.min[1] + 0.15)
                & (dense[:, 1] <= r.max[1] - 0.15)
            ).any()
            for r in apartment.rooms
        ]
        np.testing.assert_array_equal(rooms_entered(apartment, pose, margin=0.15, step=0.01), want)


def test_room_objects_unseen():
    visible = np.array([[False, False], [True, False]])  # (T, O): the desk seen once
    np.testing.assert_array_equal(room_objects_unseen(STRIP, visible), [False, False, True])  # b holds nothing
    np.testing.assert_array_equal(room_objects_unseen(STRIP, visible[:0]), [True, False, True])
    np.testing.assert_array_equal(room_objects_unseen(STRIP, visible | True), [False, False, False])


def test_explore_summary_reports_rooms(tmp_path, apartment, monkeypatch):
    """`ragnav explore` with a fake explorer: the robot stays in the living room and the kitchen and sees
    only the sofa, so coverage says nothing about the bedroom and study but the new fields do."""
    import ragnav_jax.sim.explore as explore
    from ragnav_jax.cli import main
    from ragnav_jax.sim.explore import SceneResult
    from ragnav_jax.sim.sensors import lidar_angles
    from ragnav_jax.sim.stream import ExplorationStream

    cfg = load_config(None, [])
    angles = lidar_angles(cfg.sim)
    true = np.array([[3.0, 2.5, 0.0], [5.0, 2.5, 0.0], [8.0, 2.5, 0.0], [3.0, 2.5, 0.0]], np.float32)
    T, O, L = true.shape[0], len(apartment.objects), angles.shape[0]
    visible = np.zeros((T, O), bool)
    visible[1, [o.id for o in apartment.objects].index("sofa_1")] = True
    stream = ExplorationStream(
        scene="apartment",
        t=np.arange(T, dtype=np.int32),
        pose=np.column_stack([true[:, :2], np.zeros(T), true[:, 2]]),
        lidar=np.full((T, L), 3.0, np.float32),
        lidar_angles=angles,
        visible=visible,
        distance=np.zeros((T, O), np.float32),
        bearing=np.zeros((T, O), np.float32),
        object_ids=tuple(o.id for o in apartment.objects),
    )
    grid = np.zeros((4, 4), bool)
    result = SceneResult(
        stream=stream,
        true_pose=true,
        origin=np.zeros(2),
        resolution=0.2,
        grid_factor=2,
        seen=grid,
        hit=grid,
        viewed=grid,
        frontier=grid,
        blocked=grid[:2, :2],
        steps=40,
        finished=True,
        path_length=12.0,
        max_penetration=0.0,
        plans=3,
        given_up=0,
        control_dt=0.1,
    )
    monkeypatch.setattr(explore, "explorer_for", lambda scenes, cfg: None)
    monkeypatch.setattr(explore, "explore_scenes", lambda scenes, cfg, progress, explorer: [result])
    save_scene(apartment, tmp_path / "scenes" / "apartment.json")
    run = tmp_path / "run"
    assert main(["explore", "--scenes", str(tmp_path / "scenes"), "--out", str(run), "--quiet", "--no-plots"]) == 0
    summary = json.loads((run / "explore" / "summary.json").read_text())
    (row,) = summary["scenes"]
    assert row["rooms"] == 4 and row["rooms_entered"] == 2 and row["rooms_entered_share"] == 0.5
    assert row["rooms_not_entered"] == ["bedroom", "study"]
    assert row["rooms_objects_unseen"] == ["kitchen", "bedroom", "study"]
    assert row["objects_seen"] == round(1 / O, 4)
    assert summary["rooms_entered_share"] == summary["rooms_entered_share_min"] == 0.5
    assert summary["rooms_not_entered_count"] == 2 and summary["rooms_objects_unseen_count"] == 3
    table = (run / "explore" / "summary_table.csv").read_text()
    assert "bedroom study" in table and "kitchen bedroom study" in table
