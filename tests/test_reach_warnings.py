"""Reachability warnings of `ragnav validate` (world/blockers.py): doorways, blockers, CLI."""

import json

import numpy as np
import pytest

from ragnav_jax.cli import main
from ragnav_jax.config import WorldConfig
from ragnav_jax.world.blockers import doorways, find_blocked, reach_warnings
from ragnav_jax.world.generator import build_walls, generate_scenes, place_doors, split_rooms
from ragnav_jax.world.scene import Room, Scene, Start, scene_from_dict


def _obj(id_, category, x, y, w, d, h=0.8):
    return {"id": id_, "category": category, "position": [x, y, h / 2], "size": [w, d, h]}


def two_rooms(objects, divider=((4, 0), (4, 1.5), (4, 2.5), (4, 4))) -> dict:
    """Living room [0, 4] x [0, 4] and kitchen [4, 8] x [0, 4]; the divider x = 4 has a doorway at
    y in [1.5, 2.5] (centre (4.0, 2.0)); the robot starts in the living room."""
    outer = [((0, 0), (8, 0)), ((8, 0), (8, 4)), ((8, 4), (0, 4)), ((0, 4), (0, 0))]
    inner = [(divider[k], divider[k + 1]) for k in range(0, len(divider), 2)]
    return {
        "format": "ragnav-scene/1",
        "name": "two_rooms",
        "rooms": [
            {"id": "living_1", "type": "living room", "min": [0, 0], "max": [4, 4]},
            {"id": "kitchen_1", "type": "kitchen", "min": [4, 0], "max": [8, 4]},
        ],
        "walls": [{"a": list(a), "b": list(b), "thickness": 0.1} for a, b in outer + inner],
        "objects": [
            _obj("plant_1", "potted plant", 0.5, 3.5, 0.4, 0.4),
            _obj("fridge_1", "fridge", 7.5, 3.5, 0.7, 0.7, 1.8),
        ]
        + objects,
        "start": {"position": [1.0, 2.0], "yaw": 0.0},
    }


BLOCKING_SOFA = _obj("sofa_2", "sofa", 4.6, 2.0, 0.8, 1.8)  # right behind the doorway, on the kitchen side
CLEAR_SOFA = _obj("sofa_2", "sofa", 6.5, 2.0, 0.8, 1.8)  # in the middle of the kitchen: the robot goes round


def test_doorways_of_the_two_room_scene():
    (d,) = doorways(scene_from_dict(two_rooms([])))
    assert set(d.rooms) == {"living_1", "kitchen_1"}
    assert d.center == pytest.approx((4.0, 2.0)) and d.width == pytest.approx(1.0) and d.clear == pytest.approx(0.9)
    # No divider at all: an open plan is one doorway as long as the shared side.
    (d,) = doorways(scene_from_dict(two_rooms([], divider=())))
    assert d.width == pytest.approx(4.0) and d.clear == pytest.approx(4.0)


@pytest.mark.parametrize("seed", [0, 1])
def test_doorways_match_the_generators_doors(seed):
    """Independent reference: the doors the generator cut into its walls."""
    rng = np.random.default_rng(seed)
    rects = split_rooms(rng, 6, (3.0, 6.5))
    doors = place_doors(rng, rects, 1.0, 0.35)
    rooms = tuple(Room(f"r{k}", "study", r[:2], r[2:]) for k, r in enumerate(rects))
    scene = Scene("s", rooms, tuple(build_walls(rects, doors, 1.0)), (), Start(rooms[0].center))
    got = sorted((round(d.center[0], 4), round(d.center[1], 4), tuple(sorted(d.rooms))) for d in doorways(scene))
    want = sorted(
        (round(d.center[0], 4), round(d.center[1], 4), tuple(sorted((f"r{d.rooms[0]}", f"r{d.rooms[1]}"))))
        for d in doors
    )
    assert got == want
    assert all(d.width == pytest.approx(1.0) for d in doorways(scene))


def test_object_in_doorway_names_room_doorway_and_object():
    scene = scene_from_dict(two_rooms([BLOCKING_SOFA]))
    assert reach_warnings(scene, 0.15) == [
        "room 'kitchen_1' (kitchen) is not reachable from the start: doorway to 'living_1' at (4.0, 2.0) "
        "is blocked by object 'sofa_2' (sofa); 1 object in it unreachable too"
    ]


def test_clear_doorway_gives_no_warning():
    assert reach_warnings(scene_from_dict(two_rooms([CLEAR_SOFA])), 0.15) == []
    assert reach_warnings(scene_from_dict(two_rooms([])), 0.15) == []


def test_narrow_doorway_and_walled_off_room():
    scene = scene_from_dict(two_rooms([]))
    (line,) = reach_warnings(scene, 0.45)  # 0.9 m clear < 0.9 m robot diameter plus raster slack
    assert line.startswith(
        "room 'kitchen_1' (kitchen) is not reachable from the start: doorway to 'living_1' at (4.0, 2.0)"
    )
    assert "too narrow for a robot of radius 0.45 m (0.9 m clear" in line
    walled = scene_from_dict(two_rooms([], divider=((4, 0), (4, 4))))
    assert doorways(walled) == []
    (line,) = reach_warnings(walled, 0.15)
    assert "room 'kitchen_1' (kitchen)" in line and "walled off" in line and "1 object in it" in line


def test_objects_that_block_only_together():
    """A crate before the doorway and a shelf across the kitchen right behind it: neither alone opens it."""
    crate = _obj("crate_1", "crate", 3.6, 2.0, 0.3, 0.6)
    shelf = _obj("shelf_1", "bookshelf", 4.38, 2.0, 0.4, 3.6, 2.0)  # its inflated box covers x >= 4.03
    scene = scene_from_dict(two_rooms([crate, shelf]))
    (room,) = [b for b in find_blocked(scene, 0.15) if b.kind == "room"]
    assert room.id == "kitchen_1" and room.together and set(room.blockers) == {"crate_1", "shelf_1"}
    line = reach_warnings(scene, 0.15)[0]
    assert line.startswith(
        "room 'kitchen_1' (kitchen) is not reachable from the start: doorway to 'living_1' at (4.0, 2.0) is "
        "blocked by objects 'crate_1' (crate) and 'shelf_1' (bookshelf) together"
    )


def test_object_hemmed_in_inside_a_reachable_room():
    """A lamp in the living room's corner behind a shelf and a wardrobe: the lamp is warned about, not
    the room, and the shelf, though it reaches near the doorway, is not said to block it."""
    shelf = _obj("shelf_2", "bookshelf", 2.65, 2.5, 2.5, 0.4, 2.0)  # x in [1.4, 3.9]
    wardrobe = _obj("wardrobe_1", "wardrobe", 1.6, 3.1, 0.4, 1.6, 2.0)  # y in [2.3, 3.9]
    lamp = _obj("lamp_1", "floor lamp", 2.8, 3.5, 0.2, 0.2, 1.5)
    scene = scene_from_dict(two_rooms([shelf, wardrobe, lamp]))
    assert reach_warnings(scene, 0.15) == [
        "object 'lamp_1' (floor lamp) in room 'living_1' is not reachable from the start: the way is blocked by "
        "objects 'shelf_2' (bookshelf) at (2.65, 2.5), 'wardrobe_1' (wardrobe) at (1.6, 3.1) "
        "(removing any one of them opens it)"
    ]


def test_start_inside_an_inflated_object():
    scene = scene_from_dict(two_rooms([_obj("box_1", "box", 1.3, 2.0, 0.3, 0.3)]))
    (line,) = reach_warnings(scene, 0.15)
    assert line.startswith("start (1.0, 2.0) is not free for a robot of radius 0.15 m: it overlaps 'box_1' (box)")


def test_generated_scenes_give_no_warnings():
    cfg = WorldConfig(num_scenes=2, min_rooms=4, max_rooms=6, min_objects=20, max_objects=40)
    for scene in generate_scenes(cfg, seed=3):
        for radius in (0.15, 0.2):  # sim.robot_radius default, and the generator's own check
            assert reach_warnings(scene, radius) == [], scene.name


def test_cli_validate_warns_on_stderr_and_strict_fails(tmp_path, capsys):
    blocked, clear = tmp_path / "blocked.json", tmp_path / "clear" / "clear.json"
    clear.parent.mkdir()
    blocked.write_text(json.dumps(two_rooms([BLOCKING_SOFA])))
    clear.write_text(json.dumps(two_rooms([CLEAR_SOFA])))
    assert main(["validate", str(blocked), str(clear.parent)]) == 0
    out, err = capsys.readouterr()
    assert out.count("ok   ") == 2
    (line,) = err.splitlines()
    assert line == (
        f"warning: {blocked}: room 'kitchen_1' (kitchen) is not reachable from the start: doorway to 'living_1' "
        "at (4.0, 2.0) is blocked by object 'sofa_2' (sofa); 1 object in it unreachable too"
    )
    assert main(["validate", "--strict", str(blocked)]) == 2
    assert "1 reachability warning(s) (--strict)" in capsys.readouterr().err
    assert main(["validate", "--strict", str(clear)]) == 0
    # The robot radius comes from the config: a wide robot no longer fits the clear scene's doorway.
    assert main(["validate", str(clear), "sim.robot_radius=0.45", "sim.robot_height=0.5"]) == 0
    assert "too narrow for a robot of radius 0.45 m" in capsys.readouterr().err


def test_an_obstacle_under_the_lidar_is_named():
    """A dog bed 0.2 m tall stops the robot (its sphere reaches down to 0.05 m) but lies under the lidar's
    plane (0.25 m): exploration maps floor there. A rug (flat) and a table (cut by the plane) are fine."""
    from ragnav_jax.world.blockers import lidar_blind

    s = scene_from_dict(two_rooms([_obj("dog_bed_1", "dog bed", 2.0, 1.0, 0.9, 0.7, 0.2),
                                   _obj("rug_1", "rug", 2.0, 3.0, 1.0, 0.6, 0.02),
                                   _obj("table_1", "coffee table", 3.0, 3.0, 0.8, 0.5, 0.4)]))
    lines = lidar_blind(s, lidar_height=0.25, robot_bottom=0.05)
    assert len(lines) == 1 and "'dog_bed_1' (dog bed)" in lines[0] and "under the lidar (0.25 m)" in lines[0]
    assert lidar_blind(s, lidar_height=0.15, robot_bottom=0.05) == []
