"""Tasks in worlds that changed after exploration (evaluation/worlds.py, `ragnav eval --changes`): the world keeps
the memory's object indices, what left it is neither seen, touched nor passed by the check, the Oracle goes
where a goal stands now, rows and tables split static from changed episodes, and bad inputs exit 2."""

import dataclasses
import json
import shutil

import numpy as np
import pytest
import sweep_fixtures

from ragnav_jax.cli import main
from ragnav_jax.config import ChangesConfig
from ragnav_jax.evaluation.execute import make_executor
from ragnav_jax.evaluation.navigate import evaluate_navigation
from ragnav_jax.evaluation.worlds import explore_worlds, goal_changes, load_worlds
from ragnav_jax.language.episodes import Episode, EpisodeError, load_episodes, save_episodes
from ragnav_jax.world.changes import Change, ChangeList, apply_changes, generate_changes, world_after
from ragnav_jax.world.scene import load_scene_set

tiny_run = sweep_fixtures.tiny_run


def test_the_world_keeps_the_memorys_indices(apartment):
    cl = generate_changes(apartment, ChangesConfig(fraction=0.4, doors=1), seed=1)
    w = world_after(apartment, cl)
    after = apply_changes(apartment, cl)
    n = len(apartment.objects)
    assert [o.id for o in w.objects[:n]] == [o.id for o in apartment.objects]  # obs_object stays valid
    removed = {c.object for c in cl.changes if c.kind == "remove"}
    added = [c.added.id for c in cl.changes if c.kind == "add"]
    assert removed and added and w.absent == removed
    assert [o.id for o in w.objects[n:]] == added
    present = {o.id: o for o in w.objects if o.id not in w.absent}
    assert present == {o.id: o for o in after.objects} and w.walls == after.walls
    moved = [c.object for c in cl.changes if c.kind == "move"]
    still = next(o.id for o in apartment.objects if o.id not in {c.object for c in cl.changes})
    assert goal_changes([*moved, *added, still], w, apartment) == ["move"] * len(moved) + ["add"] * len(added) + [""]


def _moved_to(scene, oid, xyz, room):
    return ChangeList(scene.name, (Change("move", oid, to=xyz, origin=scene.object_by_id(oid).position, room=room),
                                   Change("remove", "radiator_1")))


@pytest.fixture(scope="module")
def moved(tiny_run, apartment):
    """The tiny run's memory; a world where the fridge went from the kitchen to the bedroom and the radiator left."""
    _, _, cfg, bank, emb = tiny_run
    w = world_after(apartment, _moved_to(apartment, "fridge_1", (1.0, 6.0, 0.9), "bedroom"))
    return cfg, bank, emb, w, make_executor([w], cfg)


@pytest.fixture(scope="module")
def loops(moved, apartment):
    """RAGNav with the memory as explored and with an online memory, in the changed apartment (traced rows):
    "fr" asks for the fridge with no room or hint, "bf" for the bed and then the fridge. The tour counts a key pose
    seen within 2 m of a look-around here (the default 3 m, chosen on the seen split's houses, leaves the
    bedroom's far corner, 4.2 m from the nearest stop, unseen in this small map)."""
    cfg, bank, emb, w, ex = moved
    cfg = dataclasses.replace(cfg, eval=dataclasses.replace(cfg.eval, tour_radius=2.0))
    eps = [Episode("fr", apartment.name, "Go to the fridge.", ("fridge_1",)),
           Episode("bf", apartment.name, "Go to the bed, then to the fridge.", ("bed_1", "fridge_1"))]
    return {m: {r["episode"]: r for r in evaluate_navigation(bank, [w], eps, emb, cfg, m, executor=ex,
                                                             memory_scenes=[apartment], trace=["fr", "bf"])[0]}
            for m in ("ragnav", "ragnav:online")}


def test_what_left_the_world_is_not_seen_nor_in_the_way(moved, apartment):
    cfg, _, _, w, ex = moved
    ids = [o.id for o in w.objects]
    k, fridge = ids.index("radiator_1"), ids.index("fridge_1")
    assert not bool(ex.tables.obj_mask[0, k])
    lanes = np.zeros(4, np.int32)  # the loop's lane count for a few episodes: its programs, compiled once
    rad = apartment.object_by_id("radiator_1").position
    start = np.array([[rad[0], rad[1] + 0.9, -np.pi / 2], [2.5, 6.5, np.pi]] * 2, np.float32)
    d = ex.init(lanes, start)
    visible = np.asarray(ex.look(lanes, d)[0])
    assert not visible[:, k].any()
    assert visible[1, fridge]  # the fridge is seen where it stands now, from the bedroom
    # the robot drives through where the radiator stood
    pts = np.zeros((4, ex.path_points, 2), np.float32)
    pts[:, :2] = [[rad[0], rad[1] + 0.9], [rad[0], rad[1] - 0.6]]
    d = ex.init(lanes, np.repeat(start[:1], 4, 0))
    res = ex.run(lanes, d, pts, np.full(4, 2, np.int32), np.full(4, 200, np.int32))
    assert bool(res.arrived[0])


def test_the_oracle_finds_a_moved_goal_and_rows_say_what_changed(moved, loops, apartment):
    cfg, bank, emb, w, ex = moved
    eps = [Episode("fr", apartment.name, "Go to the fridge.", ("fridge_1",)),
           Episode("bd", apartment.name, "Go to the bed.", ("bed_1",))]
    rows, s = evaluate_navigation(bank, [w], eps, emb, cfg, "oracle", executor=ex, memory_scenes=[apartment])
    assert [r["changed_goals"] for r in rows] == [["move"], [""]] and [r["changed"] for r in rows] == [True, False]
    assert all(r["success"] for r in rows)
    fridge = w.object_by_id("fridge_1").position
    assert np.hypot(*(np.array(rows[0]["declarations"][0]["xy"]) - fridge[:2])) < 1.5  # found in the bedroom
    assert s["by_change"]["changed"]["episodes"] == 1 and s["by_change"]["static"]["success_rate"] == 1.0
    # RAGNav's memory still puts the fridge in the kitchen: its top-1 is the kitchen's key pose, it fails there
    frozen = loops["ragnav"]["fr"]
    assert frozen["retrieval_top1"] == [True] and not frozen["success"]


def test_an_episode_cannot_target_what_left(moved, tmp_path, apartment):
    w = moved[3]
    f = tmp_path / "e.jsonl"
    save_episodes([Episode("r", apartment.name, "Go to the radiator.", ("radiator_1",))], f)
    with pytest.raises(EpisodeError, match=r"e.jsonl: line 1: goal object 'radiator_1' .*removes it"):
        load_episodes(f, [w])


def test_the_etpnav_style_baseline_explores_the_world_as_it_is(moved, apartment):
    cfg, w = moved[0], moved[3]
    cfg = dataclasses.replace(cfg, explore=dataclasses.replace(cfg.explore, max_steps=600, batch_size=1))
    stream = explore_worlds([w], cfg)[w.name]
    ids = [o.id for o in w.objects]
    assert stream.object_ids == tuple(ids) and stream.visible.shape == (len(stream.t), len(ids))
    assert not stream.visible[:, ids.index("radiator_1")].any()  # it left
    seen = stream.visible[:, ids.index("fridge_1")]
    fridge = np.array(w.object_by_id("fridge_1").position[:2])  # where it stands now, in the bedroom
    assert seen.any() and np.linalg.norm(stream.pose[seen, :2] - fridge, axis=1).max() <= cfg.sim.camera_range + 0.5


def test_eval_changes_cli_writes_the_static_and_changed_split(tiny_run, tmp_path, capsys):
    run = tmp_path / "run"
    shutil.copytree(tiny_run[0], run)
    common = ["--quiet", *sweep_fixtures.SMALL]
    assert main(["changes", "--scenes", str(run), "--no-plots", *common, "changes.fraction=0.4"]) == 0
    assert main(["changes", "--scenes", str(run), "--apply", str(run / "changes"), *common]) == 0
    eps = run / "episodes-changed" / "episodes.jsonl"
    assert main(["episodes", "--scenes", str(run / "scenes-changed"), "--out", str(eps), *common]) == 0
    out = tmp_path / "ev"
    argv = ["eval", "--scenes", str(run), "--changes", str(run / "changes"), "--episodes", str(eps), "--method",
            "oracle", "--limit", "6", "--out", str(out), *common]
    assert main(argv) == 0
    s = json.loads((out / "eval" / "summary.json").read_text())
    rows = [json.loads(x) for x in (out / "eval" / "oracle" / "episodes.jsonl").read_text().splitlines()]
    assert {"static", "changed"} == set(s["by_change"]) and all("changed_goals" in r for r in rows)
    assert s["by_change"]["changed"]["episodes"] == sum(r["changed"] for r in rows)
    assert "success, changed" in (out / "eval" / "table.md").read_text()
    assert (out / "eval" / "table_by_change.md").is_file()
    # a scene without its list, a folder that is not there: one line naming it, exit 2
    (run / "changes" / "apartment.changes.json").rename(run / "changes" / "moved.json")
    capsys.readouterr()
    assert main([*argv[:-len(common) - 2], "--out", str(tmp_path / "ev2"), *common]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "apartment.changes.json: no change list for scene 'apartment'" in err
    assert main(["eval", "--scenes", str(run), "--changes", str(tmp_path / "nope"), "--episodes", str(eps),
                 "--out", str(tmp_path / "ev3"), *common]) == 2
    assert "nope: no such folder of change lists" in capsys.readouterr().err
    assert load_worlds(load_scene_set(run / "scenes"), run / "changes") == {}  # no list: the scene is static
    assert main(["eval", "--scenes", str(run), "--changes", str(run / "changes"), "--episodes", str(eps),
                 "--out", str(tmp_path / "ev4"), *common, "eval.engine=device"]) == 2
    assert "--changes runs on the host engine" in capsys.readouterr().err


def test_the_online_memory_goes_where_it_saw_a_moved_goal(loops):
    """Driving to the bed, the forward camera sees the fridge that left the kitchen for the bedroom: RAGNav with
    an online memory goes back to it instead of to the kitchen its memory still names."""
    online, frozen = loops["ragnav:online"]["bf"], loops["ragnav"]["bf"]
    assert online["success"] and online["changed_goals"] == ["", "move"]
    kinds = [(leg["kind"], leg["goal"]) for leg in online["legs"]]
    assert ("goto_seen", 1) in kinds and ("nav", 1) not in kinds  # never to the kitchen for the fridge
    assert ("nav", 1) in [(leg["kind"], leg["goal"]) for leg in frozen["legs"]]
    assert online["travel_distance_m"] < frozen["travel_distance_m"]


def test_the_online_memory_tours_what_it_has_not_seen_when_the_memory_was_wrong(loops):
    """"Go to the fridge": no room, no hint, the kitchen's fridge gone. The frozen memory has nowhere else to
    look; the online one retires the kitchen's fridge and tours the house it has not looked around in."""
    assert not loops["ragnav"]["fr"]["success"] and loops["ragnav:online"]["fr"]["success"]
    kinds = [leg["kind"] for leg in loops["ragnav:online"]["fr"]["legs"]]
    assert kinds[0] == "nav" and "search" in kinds  # the kitchen first, then the tour


def test_frames_take_every_nth_step_of_each_leg():
    from ragnav_jax.evaluation.host_loop import _frames

    trail = np.arange(2 * 10 * 3, dtype=np.float32).reshape(2, 10, 3)
    frames, counts = _frames(trail, np.array([7, 10]), [True, True], 3)
    assert counts.tolist() == [2, 3] and frames.shape == (2, 4, 3)
    assert (frames[0, :2] == trail[0, [2, 5]]).all() and (frames[0, 2:] == trail[0, 5]).all()
    assert (frames[1, :3] == trail[1, [2, 5, 8]]).all()
    assert _frames(trail, np.array([7, 10]), [False, False], 3)[1].tolist() == [0, 0]
