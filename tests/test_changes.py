"""Change lists (world/changes.py, `ragnav changes`): drawn lists keep every room and object reachable and
change about `fraction` of the objects, deterministically; the file round-trips and matches its schema;
a list that does not fit its scene, or is no list at all, is a one-line error naming the file and field."""

import dataclasses
import json

import jsonschema
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ragnav_jax.cli import main
from ragnav_jax.config import ChangesConfig
from ragnav_jax.errors import SceneError
from ragnav_jax.world.changes import (
    Change,
    ChangeList,
    apply_changes,
    changes_from_dict,
    changes_to_dict,
    generate_changes,
    load_changes,
)
from ragnav_jax.world.commands import scene_summary
from ragnav_jax.world.scene import load_schema


@pytest.fixture(scope="module")
def drawn(apartment):
    cfg = ChangesConfig(fraction=0.4, doors=1)
    return cfg, generate_changes(apartment, cfg, seed=1)  # 5 moves, 1 removal, 2 additions, 1 door


def test_a_drawn_list_changes_its_share_and_keeps_the_house_reachable(apartment, drawn):
    cfg, cl = drawn
    after = apply_changes(apartment, cl)
    counts = cl.counts()
    assert counts["move"] + counts["remove"] + counts["add"] == round(cfg.fraction * len(apartment.objects))
    assert counts["close_door"] == 1 and len(after.walls) == len(apartment.walls) + 1
    summary = scene_summary(after)  # the grid reachability of `ragnav generate`'s summary
    assert summary["all_rooms_reachable"] and summary["all_objects_reachable"]
    ids = {o.id for o in after.objects}
    for c in cl.changes:
        if c.kind == "remove":
            assert c.object not in ids
        elif c.kind == "add":
            assert c.object in ids and c.object not in {o.id for o in apartment.objects}
        elif c.kind == "move":
            o = after.object_by_id(c.object)
            assert o.position == c.to and after.room_by_id(o.room).contains(*c.to[:2])
            assert c.origin == apartment.object_by_id(c.object).position
    assert generate_changes(apartment, cfg, seed=1) == cl  # the same seed draws the same list
    assert generate_changes(apartment, cfg, seed=2) != cl


@settings(max_examples=4, deadline=None)
@given(seed=st.integers(0, 10_000))
def test_any_seed_keeps_every_room_and_object_reachable(apartment, seed):
    after = apply_changes(apartment, generate_changes(apartment, ChangesConfig(fraction=0.3, doors=2), seed))
    summary = scene_summary(after)
    assert summary["all_rooms_reachable"] and summary["all_objects_reachable"]


def test_the_file_round_trips_and_matches_its_schema(drawn, tmp_path):
    from referencing import Registry, Resource

    _, cl = drawn
    data = changes_to_dict(cl)
    scene_schema = load_schema("scene")
    registry = Registry().with_resource(scene_schema["$id"], Resource.from_contents(scene_schema))
    jsonschema.Draft202012Validator(load_schema("changes"), registry=registry).validate(data)
    assert changes_from_dict(json.loads(json.dumps(data))) == cl
    path = tmp_path / "x.changes.json"
    path.write_text(json.dumps(data))
    assert load_changes(path) == cl


def _bad(cl, i, **kw):
    ch = list(cl.changes)
    ch[i] = dataclasses.replace(ch[i], **kw)
    return dataclasses.replace(cl, changes=tuple(ch))


def test_a_list_that_does_not_fit_its_scene_names_the_change(apartment, drawn):
    _, cl = drawn
    k = next(i for i, c in enumerate(cl.changes) if c.kind == "move")
    cases = [(_bad(cl, k, object="ghost_1", origin=None), rf"\$\.changes\[{k}\]\.object: no object 'ghost_1'"),
             (_bad(cl, k, to=(500.0, 500.0, 0.3), room=""), rf"\$\.changes\[{k}\]\.to: .* outside every room"),
             (_bad(cl, k, origin=(0.0, 0.0, 0.0)), rf"\$\.changes\[{k}\]\.from: object"),
             (dataclasses.replace(cl, scene="elsewhere"), r"\$\.scene: the list is for scene 'elsewhere'"),
             (ChangeList(cl.scene, (Change("remove", cl.changes[k].object),) * 2), r"\$\.changes\[1\]\.object")]
    twice = next(c for c in cl.changes if c.kind == "add")
    cases.append((ChangeList(cl.scene, (twice, twice)), r"\$\.changes\[1\]\.object\.id: object id .* already"))
    for bad, msg in cases:
        with pytest.raises(SceneError, match=msg):
            apply_changes(apartment, bad, "f.json")
    with pytest.raises(SceneError, match=r"\$\.changes\[0\]\.kind"):
        changes_from_dict({"format": "ragnav-changes/1", "scene": "s", "changes": [{"kind": "teleport"}]})
    with pytest.raises(SceneError, match=r"\$\.changes\[0\]: Additional properties"):
        changes_from_dict({"format": "ragnav-changes/1", "scene": "s",
                           "changes": [{"kind": "remove", "object": "a", "to": [1, 2, 3]}]})


def test_cli_draws_applies_and_refuses_bad_or_existing_outputs(apartment, tmp_path, capsys):
    from ragnav_jax.world.scene import load_scene_set, save_scene

    run = tmp_path / "run"
    save_scene(apartment, run / "scenes" / f"{apartment.name}.json")
    (run / "config.yaml").write_text("seed: 0\n")
    assert main(["changes", "--scenes", str(run), "--quiet", "changes.fraction=0.2"]) == 0
    lst = run / "changes" / f"{apartment.name}.changes.json"
    assert load_changes(lst).scene == apartment.name
    assert (run / "changes" / "plots" / f"{apartment.name}.png").stat().st_size > 10_000  # the changes drawn
    assert main(["changes", "--scenes", str(run), "--quiet"]) == 2  # the lists exist: no --force
    assert main(["changes", "--scenes", str(run), "--apply", str(run / "changes"), "--quiet"]) == 0
    after, = load_scene_set(run / "scenes-changed")
    assert after == apply_changes(apartment, load_changes(lst))
    data = json.loads(lst.read_text())
    data["changes"][0]["kind"] = "teleport"
    lst.write_text(json.dumps(data))
    capsys.readouterr()
    assert main(["changes", "--scenes", str(run), "--apply", str(run / "changes"), "--out", str(tmp_path / "o"),
                 "--quiet"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and f"{apartment.name}.changes.json: $.changes[0].kind" in err
    assert not (tmp_path / "o").exists()  # nothing written
