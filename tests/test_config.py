import dataclasses
from pathlib import Path

import pytest

from ragnav_jax.config import Config, WorldConfig, apply_overrides, dump_yaml, load_config, read_yaml
from ragnav_jax.errors import ConfigError

CONFIGS = Path(__file__).resolve().parents[1] / "configs"


@pytest.mark.parametrize("name", ["default.yaml", "paper.yaml"])
def test_shipped_configs_load(name):
    cfg = load_config(CONFIGS / name)
    assert isinstance(cfg, Config)
    assert cfg.world.num_scenes >= 1


def test_paper_preset_has_14_scenes():
    assert load_config(CONFIGS / "paper.yaml").world.num_scenes == 14


def test_dotted_overrides_apply_and_are_typed():
    cfg = load_config(CONFIGS / "paper.yaml", ["world.num_scenes=20", "seed=7", "world.room_side=[3, 5.5]"])
    assert cfg.world.num_scenes == 20 and cfg.seed == 7
    assert cfg.world.room_side == (3.0, 5.5) and isinstance(cfg.world.room_side[0], float)


def test_config_is_frozen():
    cfg = load_config()
    with pytest.raises(dataclasses.FrozenInstanceError):
        cfg.seed = 3  # type: ignore[misc]


@pytest.mark.parametrize(
    "override, fragment",
    [
        ("world.bogus=1", "unknown config key 'world.bogus'"),
        ("nonsense=1", "unknown config key 'nonsense'"),
        ("world.num_scenes=two", "'world.num_scenes': expected an integer"),
        ("world.num_scenes=1.5", "'world.num_scenes': expected an integer"),
        ("world.num_scenes=true", "'world.num_scenes': expected an integer"),
        ("world.door_width=wide", "'world.door_width': expected a number"),
        ("world.room_side=[3]", "'world.room_side': expected a list of 2"),
        ("world=3", "'world': expected a mapping"),
        ("world.num_scenes.x=3", "'world.num_scenes': expected an integer"),
        ("world.min_rooms.x=3", "'world.min_rooms': expected an integer"),
        ("world.min_rooms=12", "world.min_rooms"),
        ("world.num_scenes=0", "world.num_scenes"),
        ("novalue", "must look like key.sub=value"),
    ],
)
def test_bad_overrides_name_the_key(override, fragment):
    with pytest.raises(ConfigError) as e:
        load_config(None, [override])
    assert fragment in str(e.value)


def test_bad_yaml_file_names_file_and_line(tmp_path):
    p = tmp_path / "bad.yaml"
    p.write_text("world:\n  num_scenes: [1,\n")
    with pytest.raises(ConfigError) as e:
        read_yaml(p)
    assert str(p) in str(e.value) and "line" in str(e.value)


def test_unknown_key_in_file_names_file_and_key(tmp_path):
    p = tmp_path / "c.yaml"
    p.write_text("world:\n  num_rooms: 3\n")
    with pytest.raises(ConfigError) as e:
        load_config(p)
    assert str(p) in str(e.value) and "world.num_rooms" in str(e.value)


def test_missing_file(tmp_path):
    with pytest.raises(ConfigError, match="cannot read config"):
        load_config(tmp_path / "nope.yaml")


def test_dump_and_reload_round_trip(tmp_path):
    cfg = load_config(CONFIGS / "paper.yaml", ["world.num_scenes=3"])
    p = tmp_path / "resolved.yaml"
    p.write_text(dump_yaml(cfg))
    assert load_config(p) == cfg


def test_apply_overrides_does_not_mutate_input():
    data = {"world": {"num_scenes": 2}}
    out = apply_overrides(data, ["world.num_scenes=5"])
    assert data["world"]["num_scenes"] == 2 and out["world"]["num_scenes"] == 5


def test_world_config_checks_ranges():
    with pytest.raises(ConfigError, match="min_objects"):
        WorldConfig(min_objects=50, max_objects=10)


def test_retrieval_defaults_sweep_axes_and_tunables_name_retrieval_params_fields():
    """Retrieval defaults are written once (RetrievalConfig); every sweep axis but lam and every tunable is a
    RetrievalParams field, so a new hyperparameter cannot be half-added."""
    import dataclasses

    import numpy as np

    from ragnav_jax.config import TUNABLE, RetrievalConfig, SweepAxes
    from ragnav_jax.retrieval.params import DEFAULTS, FLAGS, INT_FIELDS, RetrievalParams, params_from_config

    fields = [f.name for f in dataclasses.fields(RetrievalParams)]
    assert list(DEFAULTS) == fields
    assert {f.name for f in dataclasses.fields(RetrievalConfig)} - {"method"} == set(fields) - set(FLAGS)
    assert {f.name for f in dataclasses.fields(SweepAxes)} - {"lam"} <= set(fields)
    assert set(TUNABLE) <= set(fields) - set(INT_FIELDS) - set(FLAGS)
    p = params_from_config(RetrievalConfig(sigma=3.5, top_k=4))
    assert float(p.sigma) == 3.5 and int(p.top_k) == 4 and p.eta == np.float32(RetrievalConfig().eta)
