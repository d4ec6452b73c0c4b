import copy
import json

import pytest
from conftest import SHARED
from hypothesis import given, settings
from hypothesis import strategies as st

from ragnav_jax.cli import main
from ragnav_jax.errors import SceneError
from ragnav_jax.world.scene import (
    example_scene_path,
    load_scene,
    load_scene_set,
    parse_scene_text,
    scene_from_dict,
    scene_to_dict,
    scene_to_json,
)


@pytest.fixture
def data(apartment):
    return scene_to_dict(apartment)


def test_shared_example_loads():
    s = load_scene(SHARED / "examples" / "scenes" / "apartment.json") if SHARED.exists() else load_scene(example_scene_path())
    assert s.name == "apartment"
    assert len(s.rooms) == 4 and len(s.objects) == 19
    assert s.object_by_id("plant_2").readings == {"ndvi": 0.22}
    assert s.object_by_id("sofa_1").attrs == {"color": "grey", "material": "fabric"}


def test_embedded_example_matches_shared():
    if not SHARED.exists():
        pytest.skip("shared/ not beside the checkout")
    assert load_scene(example_scene_path()) == load_scene(SHARED / "examples" / "scenes" / "apartment.json")


def test_round_trip_is_exact(apartment):
    text = scene_to_json(apartment)
    again = parse_scene_text(text)
    assert again == apartment
    assert scene_to_json(again) == text


def test_defaults_and_derived_room(data):
    d = copy.deepcopy(data)
    del d["objects"][0]["size"]
    del d["objects"][0]["room"]
    del d["walls"][0]["thickness"]
    s = scene_from_dict(d)
    assert s.objects[0].size == (0.5, 0.5, 0.5)
    assert s.objects[0].room == "living"  # derived from the position
    assert s.walls[0].thickness == 0.1


def _mutations():
    def nan(d):
        d["objects"][2]["position"][0] = float("nan")

    def inf(d):
        d["walls"][1]["b"][1] = float("inf")

    def missing_field(d):
        del d["objects"][4]["category"]

    def wrong_type(d):
        d["rooms"][1]["min"] = "zero"

    def wrong_type_num(d):
        d["objects"][0]["position"][1] = "1.0"

    def short_xy(d):
        d["start"]["position"] = [1.0]

    def bad_format(d):
        d["format"] = "ragnav-scene/2"

    def extra_key(d):
        d["objects"][0]["colour"] = "red"

    def overlap(d):
        d["rooms"][1]["min"] = [5.0, 0.0]

    def outside(d):
        d["objects"][3]["position"] = [20.0, 3.0, 0.5]

    def dup_object(d):
        d["objects"][5]["id"] = "sofa_1"

    def dup_room(d):
        d["rooms"][2]["id"] = "living"

    def start_in_wall(d):
        d["start"]["position"] = [5.0, 5.5]

    def start_outside(d):
        d["start"]["position"] = [-3.0, 2.0]

    def unknown_room(d):
        d["objects"][0]["room"] = "attic"

    def neg_size(d):
        d["objects"][0]["size"] = [1.0, -1.0, 1.0]

    def zero_wall(d):
        d["walls"][0]["b"] = list(d["walls"][0]["a"])

    def inverted_room(d):
        d["rooms"][0]["max"] = [-1.0, 5.0]

    def sensor_string(d):
        d["objects"][4]["sensors"] = {"temperature_c": "hot"}

    return [
        (nan, "$.objects[2].position[0]", "finite"),
        (inf, "$.walls[1].b[1]", "finite"),
        (missing_field, "$.objects[4]", "'category' is a required property"),
        (wrong_type, "$.rooms[1].min", "not of type 'array'"),
        (wrong_type_num, "$.objects[0].position[1]", "not of type 'number'"),
        (short_xy, "$.start.position", "too short"),
        (bad_format, "$.format", "ragnav-scene/1"),
        (extra_key, "$.objects[0]", "colour"),
        (overlap, "$.rooms[1]", "overlaps room 'living'"),
        (outside, "$.objects[3].position", "outside every room"),
        (dup_object, "$.objects[5].id", "duplicate object id 'sofa_1'"),
        (dup_room, "$.rooms[2].id", "duplicate room id 'living'"),
        (start_in_wall, "$.start.position", "inside wall"),
        (start_outside, "$.start.position", "outside every room"),
        (unknown_room, "$.objects[0].room", "unknown room id 'attic'"),
        (neg_size, "$.objects[0].size", "positive"),
        (zero_wall, "$.walls[0]", "zero length"),
        (inverted_room, "$.rooms[0]", "min < max"),
        (sensor_string, "$.objects[4].sensors.temperature_c", "not of type 'number'"),
    ]


@pytest.mark.parametrize("mutate, path, fragment", _mutations(), ids=lambda x: getattr(x, "__name__", None))
def test_bad_scene_names_file_and_path(data, tmp_path, mutate, path, fragment):
    d = copy.deepcopy(data)
    mutate(d)
    f = tmp_path / "bad.json"
    f.write_text(json.dumps(d))  # json writes NaN/Infinity literals, which Python's parser accepts
    with pytest.raises(SceneError) as e:
        load_scene(f)
    msg = str(e.value)
    assert msg.startswith(f"{f}: {path}:"), msg
    assert fragment in msg, msg


@pytest.mark.parametrize(
    "text, fragment",
    [("{not json", "not valid JSON"), ("", "not valid JSON"), ("[1, 2]", "is not of type 'object'"), ('{"format": 1', "line 1")],
)
def test_not_json(tmp_path, text, fragment):
    f = tmp_path / "x.json"
    f.write_text(text)
    with pytest.raises(SceneError) as e:
        load_scene(f)
    assert str(f) in str(e.value) and fragment in str(e.value)


def test_binary_and_missing_files(tmp_path):
    f = tmp_path / "bin.json"
    f.write_bytes(b"\xff\xfe\x00garbage")
    with pytest.raises(SceneError, match="UTF-8"):
        load_scene(f)
    with pytest.raises(SceneError, match="cannot read"):
        load_scene(tmp_path / "missing.json")


def test_scene_set_rejects_duplicate_names(apartment, tmp_path):
    for n in ("a.json", "b.json"):
        (tmp_path / n).write_text(scene_to_json(apartment))
    with pytest.raises(SceneError, match="duplicate scene name 'apartment'"):
        load_scene_set(tmp_path)
    (tmp_path / "empty").mkdir()
    with pytest.raises(SceneError, match="no \\*.json"):
        load_scene_set(tmp_path / "empty")
    with pytest.raises(SceneError, match="no such file"):
        load_scene_set(tmp_path / "nothing")


@pytest.mark.parametrize("command", ["validate", "show-scene"])
def test_cli_bad_scene_exit_2_no_traceback(data, tmp_path, capsys, command):
    d = copy.deepcopy(data)
    d["objects"][1]["id"] = "sofa_1"
    f = tmp_path / "bad.json"
    f.write_text(json.dumps(d))
    argv = [command, str(f)] + (["--out", str(tmp_path / "x.png")] if command == "show-scene" else [])
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert "Traceback" not in out + err
    assert "$.objects[1].id" in out + err and str(f) in out + err


# Property: random valid edits of coordinates keep the round trip exact.
@settings(max_examples=40, deadline=None)
@given(
    dx=st.floats(-0.4, 0.4, allow_nan=False),
    dy=st.floats(-0.4, 0.4, allow_nan=False),
    temp=st.floats(-50, 300, allow_nan=False),
    color=st.text(min_size=1, max_size=12),
)
def test_round_trip_property(dx, dy, temp, color):
    d = scene_to_dict(load_scene(example_scene_path()))
    o = d["objects"][0]
    o["position"] = [round(o["position"][0] + dx, 4), round(o["position"][1] + dy, 4), o["position"][2]]
    o["sensors"] = {"temperature_c": round(temp, 4)}
    o["attributes"] = {"color": color}
    s = scene_from_dict(d)
    assert scene_from_dict(json.loads(scene_to_json(s))) == s


def test_sensor_keys_are_read_under_their_canonical_names(data):
    """The schema's own example key "humidity" and a user's "temp_f" or "co2" meet the readings the parser
    names (humidity_pct, temperature_c in Celsius, co2_ppm); a reading nobody named stays as written."""
    d = copy.deepcopy(data)
    d["objects"][0]["sensors"] = {"humidity": 62, "temp_f": 98.6, "co2": 900, "vibration_mm_s": 3}
    got = scene_from_dict(d).objects[0].readings
    assert got == {"humidity_pct": 62.0, "temperature_c": pytest.approx(37.0), "co2_ppm": 900.0, "vibration_mm_s": 3.0}
    assert scene_from_dict(scene_to_dict(scene_from_dict(d))).objects[0].readings == got  # canonical keys stay
    d["objects"][0]["sensors"] = {"temperature": 20, "temperature_c": 21}
    with pytest.raises(SceneError, match=r"objects\[0\]\.sensors.*same reading \(temperature_c\)"):
        scene_from_dict(d, "house.json")


@settings(max_examples=60, deadline=None)
@given(words=st.lists(st.sampled_from(["temp", "temperature", "humidity", "relative", "co2", "noise", "light",
                                       "level", "battery", "soil", "moisture", "power", "weight", "x"]), min_size=1, max_size=3),
       unit=st.sampled_from(["", "c", "f", "k", "pct", "ppm", "db", "lux", "w", "kw", "kg", "g", "hpa"]),
       value=st.floats(-50, 5000, allow_nan=False))
def test_canonical_sensor_is_idempotent(words, unit, value):
    from ragnav_jax.language.readings import READINGS, canonical_sensor

    key = "_".join([*words, unit] if unit else words)
    k1, v1 = canonical_sensor(key, value)
    assert canonical_sensor(k1, v1) == (k1, v1)
    assert k1 in READINGS or k1 == key  # a key is canonical or left exactly as written
