"""The episode generator: schema-valid, deterministic, each description fits exactly its goal in the
scene's ground truth, all three modalities, parse agreement; episode files and the CLI."""

import dataclasses
import json
from pathlib import Path

import pytest

from ragnav_jax.cli import main
from ragnav_jax.config import load_config
from ragnav_jax.language.agreement import parse_agreement
from ragnav_jax.language.episodes import (
    EpisodeError,
    SceneFacts,
    generate_episodes,
    load_episodes,
    load_truth,
    resolve,
    save_episodes,
    validate_episode_dict,
)
from ragnav_jax.language.types import Subgoal
from ragnav_jax.world.generator import generate_scene
from ragnav_jax.world.scene import example_scene_path

CONFIGS = Path(__file__).resolve().parents[1] / "configs"


@pytest.fixture(scope="module")
def scenes(apartment):
    cfg = load_config(None, ["world.num_scenes=2", "seed=11"])
    return [apartment] + [generate_scene(cfg.world, cfg.seed, i) for i in range(2)]


@pytest.fixture(scope="module")
def pairs(scenes):
    cfg = load_config(None, ["episodes.text=25", "episodes.text_location=20", "episodes.text_location_sensor=20"])
    return generate_episodes(scenes, cfg.episodes, seed=3)


def test_episodes_are_schema_valid_and_varied(pairs, scenes):
    cfg = load_config().episodes
    assert len(pairs) >= 150
    by_scene = {s.name: s for s in scenes}
    for k, p in enumerate(pairs):
        e = p.episode
        assert validate_episode_dict(json.loads(json.dumps(e.to_dict())), "<test>", k) == e
        assert cfg.min_goals <= len(e.goals) <= cfg.max_goals and len(set(e.goals)) == len(e.goals)
        assert e.order == "strict" or len(e.goals) > 1
        assert p.truth.order == e.order and len(p.truth.subgoals) == len(e.goals)
        assert all(g in {o.id for o in by_scene[e.scene].objects} for g in e.goals)
    assert {p.episode.modality for p in pairs} == {"text", "text+location", "text+location+sensor"}
    assert {p.episode.order for p in pairs} == {"strict", "free"}
    assert {len(p.episode.goals) for p in pairs} == {1, 2, 3, 4, 5}
    assert len({p.episode.instruction for p in pairs}) == len(pairs)
    assert len({p.episode.id for p in pairs}) == len(pairs)


def test_each_description_identifies_exactly_its_goal(pairs, scenes):
    facts = {s.name: SceneFacts.build(s, load_config().episodes) for s in scenes}
    kinds = {"relation": 0, "room": 0, "nested": 0, "synonym": 0, "superlative": 0, "threshold": 0}
    for p in pairs:
        f = facts[p.episode.scene]
        for sg, goal in zip(p.truth.subgoals, p.episode.goals):
            assert resolve(f, sg) == (goal,), sg.text
            kinds["relation"] += bool(sg.target.relations)
            kinds["nested"] += any(r.anchor.relations for r in sg.target.relations)
            kinds["room"] += sg.room is not None
            kinds["synonym"] += sg.target.head != f.scene.object_by_id(goal).category
            kinds["superlative"] += any(c.is_superlative for c in sg.sensors)
            kinds["threshold"] += any(c.comparator in ("gt", "lt", "ge", "le") for c in sg.sensors)
    assert all(v > 0 for v in kinds.values()), kinds


def _disambiguator_needed(f, sg: Subgoal) -> bool:
    """Without its hint / sensor constraint, the description would fit more than one object."""
    return len(resolve(f, dataclasses.replace(sg, location=None, sensors=()))) >= 2


def test_modalities_carry_their_disambiguator(pairs, scenes):
    facts = {s.name: SceneFacts.build(s, load_config().episodes) for s in scenes}
    for p in pairs:
        f, subs, m = facts[p.episode.scene], p.truth.subgoals, p.episode.modality
        if m == "text":
            assert all(s.location is None and not s.sensors for s in subs)
        elif m == "text+location":
            assert not any(s.sensors for s in subs)
            assert any(s.location is not None and _disambiguator_needed(f, s) for s in subs)
        else:
            assert any(s.sensors and _disambiguator_needed(f, s) for s in subs)


def test_parser_agrees_with_generator_ground_truth(pairs):
    report = parse_agreement(pairs)
    assert report["rate"] >= 0.99, report["failures"][:5]
    assert report["parse_errors"] == 0


def test_generation_is_deterministic_for_a_seed(scenes):
    cfg = load_config(None, ["episodes.text=4", "episodes.text_location=3", "episodes.text_location_sensor=3"]).episodes
    a = generate_episodes(scenes, cfg, seed=7)
    b = generate_episodes(scenes, cfg, seed=7)
    c = generate_episodes(scenes, cfg, seed=8)
    assert [p.episode for p in a] == [p.episode for p in b] and [p.truth for p in a] == [p.truth for p in b]
    assert [p.episode.instruction for p in a] != [p.episode.instruction for p in c]
    # A scene's episodes depend on the scene and the seed only, not on the other scenes of the set.
    alone = generate_episodes(scenes[1:2], cfg, seed=7)
    assert [p.episode for p in alone] == [p.episode for p in a if p.episode.scene == scenes[1].name]


def test_paper_preset_benchmark_covers_three_modalities():
    cfg = load_config(CONFIGS / "paper.yaml")
    e = cfg.episodes
    assert e.text > 0 and e.text_location > 0 and e.text_location_sensor > 0 and cfg.seed == 2024
    scene = generate_scene(cfg.world, cfg.seed, 0)
    pairs = generate_episodes([scene], e, cfg.seed)
    counts = {m: sum(p.episode.modality == m for p in pairs) for m in ("text", "text+location", "text+location+sensor")}
    assert counts == {"text": e.text, "text+location": e.text_location, "text+location+sensor": e.text_location_sensor}
    assert parse_agreement(pairs)["rate"] >= 0.99


def test_shipped_examples_load_against_the_apartment(apartment):
    eps = load_episodes(Path(str(example_scene_path())).with_name("episodes.jsonl"), [apartment])
    assert [e.id for e in eps][:2] == ["apt-1", "apt-2"] and eps[3].modality == "text+location"


@pytest.mark.parametrize(
    "lines, fragment",
    [
        (['{"id": "a", "scene": "apartment", "instruction": "x", "goals": [{"object_id": "sofa_1"}]}', "{oops"],
         "line 2: not valid JSON"),
        (['{"id": "a", "scene": "apartment", "instruction": "x", "goals": []}'], "line 1: $.goals"),
        (['{"id": "a", "scene": "apartment", "instruction": "x", "goals": [{"object_id": "s"}], "extra": 1}'],
         "line 1"),
        (['{"id": "a", "scene": "apartment", "instruction": "x", "goals": [{"object_id": "sofa_1"}]}',
          "", '{"id": "a", "scene": "apartment", "instruction": "y", "goals": [{"object_id": "sofa_1"}]}'],
         "line 3: duplicate episode id 'a' (also line 1)"),
        (['{"id": "a", "scene": "mansion", "instruction": "x", "goals": [{"object_id": "sofa_1"}]}'],
         "line 1: unknown scene 'mansion'"),
        (['{"id": "a", "scene": "apartment", "instruction": "x", "goals": [{"object_id": "unicorn_1"}]}'],
         "line 1: goal object 'unicorn_1'"),
        ([], "no episodes"),
    ],
)
def test_bad_episode_files_name_file_and_line(tmp_path, apartment, lines, fragment):
    f = tmp_path / "bad.jsonl"
    f.write_text("\n".join(lines) + "\n")
    with pytest.raises(EpisodeError) as e:
        load_episodes(f, [apartment])
    assert str(f) in str(e.value) and fragment in str(e.value)


def test_cli_episodes_on_a_run_folder_and_check_parse(tmp_path, capsys):
    run = tmp_path / "run"
    assert main(["generate", "--out", str(run), "--quiet", "--no-plots", "world.num_scenes=2", "seed=5"]) == 0
    argv = ["episodes", "--scenes", str(run), "--quiet", "episodes.text=6", "episodes.text_location=4",
            "episodes.text_location_sensor=4"]
    assert main(argv) == 0
    out = run / "episodes" / "episodes.jsonl"
    eps = load_episodes(out)
    assert len(eps) == 28 and (run / "config.episodes.yaml").exists()
    assert set(load_truth(out.with_name("episodes.chains.jsonl"))) == {e.id for e in eps}
    assert out.with_name("episodes_summary.md").exists() and out.with_name("episodes_summary.csv").exists()
    assert json.loads(out.with_name("episodes.agreement.json").read_text())["rate"] >= 0.99
    assert "parse agreement" in capsys.readouterr().out
    assert main(argv) == 2  # refuses to overwrite without --force
    assert main([*argv, "--force"]) == 0
    assert load_episodes(out) == eps  # same config and seed: the same file
    assert main(["check-parse", str(out)]) == 0
    assert "parse agreement: 28/28" in capsys.readouterr().out


def test_cli_episodes_user_errors(tmp_path, capsys):
    bad = tmp_path / "scenes"
    bad.mkdir()
    (bad / "broken.json").write_text('{"format": "ragnav-scene/1",\n "name": }')
    assert main(["episodes", "--scenes", str(bad), "--out", str(tmp_path / "e.jsonl")]) == 2
    err = capsys.readouterr().err
    assert "broken.json" in err and "line 2" in err
    assert main(["episodes", "--scenes", str(tmp_path / "nowhere"), "--out", str(tmp_path / "e.jsonl")]) == 2
    assert main(["episodes", "--scenes", str(example_scene_path())]) == 2  # no --out for a bare scene file
    assert main(["episodes", "--scenes", str(example_scene_path()), "--out", str(tmp_path / "e.txt")]) == 2
    ok = tmp_path / "apt.jsonl"
    assert main(["episodes", "--scenes", str(example_scene_path()), "--out", str(ok), "--quiet"]) == 0
    save_episodes(load_episodes(ok)[:1], tmp_path / "one.jsonl")
    assert main(["check-parse", str(tmp_path / "one.jsonl"), "--truth", str(tmp_path / "nope.jsonl")]) == 2
    broken = tmp_path / "broken.jsonl"
    broken.write_text(ok.read_text().splitlines()[0] + "\n{not json\n")
    assert main(["check-parse", str(broken)]) == 2
    err = capsys.readouterr().err
    assert "broken.jsonl: line 2: not valid JSON" in err
