import dataclasses
import re
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
        ("retrieval.sigma_loc=0", "'retrieval.sigma_loc': must be > 0"),
        ("retrieval.boost_hops=2", "'retrieval.boost_hops': must be in [0, 1]"),
        ("retrieval.forest_lock=0.5", "'retrieval.forest_lock': must be 0 or 1"),
        ("sweep.axes.top_k=[8,17]", "'sweep.axes.top_k': must be in [1, 16]"),
        ("sweep.axes.sigma_loc=[1,-1]", "'sweep.axes.sigma_loc': must be > 0"),
        ("sweep.axes.lam=[-1]", "'sweep.axes.lam': must be >= 0"),
        ("sweep.axes.sigma_rel=[1]", "unknown config key 'sweep.axes.sigma_rel'"),
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


def _outside(h) -> list:
    """Values just outside a hyperparameter's declared range (none when it has no range)."""
    if h.among:
        return [(h.among[0] + h.among[1]) / 2]
    out = [h.gt] if h.gt is not None else [h.ge - 1] if h.ge is not None else []
    return out + ([h.le + 1] if h.le is not None else [])


def test_hyperparameter_table_drives_range_checks_sweep_axes_tuning_and_params():
    """RetrievalConfig's table (config.hyper fields) is the one list: the sweepable and tunable sets come from it, every
    sweepable field is a SweepAxes field of its type, a value outside a field's range is refused naming that field in
    both sections, and RetrievalParams has exactly the table's fields (integers where the table says int) and the flags."""
    from ragnav_jax.config import TUNABLE, PlanningConfig, RetrievalConfig, SweepAxes, hyperparameters
    from ragnav_jax.evaluation.tune import POSITIVE, UNIT
    from ragnav_jax.retrieval.params import FLAGS, INT_FIELDS, RetrievalParams

    table = hyperparameters(RetrievalConfig)
    assert set(table) == {f.name for f in dataclasses.fields(RetrievalConfig)} - {"method"}
    assert [f.name for f in dataclasses.fields(RetrievalParams)] == [*table, *FLAGS]
    assert {n for n, h in table.items() if h.sweep} == {
        "sigma", "eta", "top_k", "hops", "boost_hops", "beam", "anchor_threshold", "boost_threshold", "w_slot",
        "match_threshold", "sigma_loc", "w_loc", "w_sensor", "w_time", "w_recency"}
    assert set(TUNABLE) == {"sigma", "eta", "sigma_loc", "w_slot", "w_loc", "w_sensor", "anchor_threshold",
                            "boost_threshold"}
    assert (set(POSITIVE), set(UNIT)) == ({"sigma", "sigma_loc", "w_loc", "w_sensor", "eta"}, {"w_slot"})
    assert set(INT_FIELDS) == {"top_k", "hops", "boost_hops", "beam"}
    axes = {f.name: f.type for f in dataclasses.fields(SweepAxes)}
    sweepable = {n: h for n, h in [*table.items(), *hyperparameters(PlanningConfig).items()] if h.sweep}
    assert axes == {n: tuple[h.type, ...] for n, h in sweepable.items()} and list(axes)[-1] == "lam"
    assert load_config(None, ["sweep.axes.top_k=[1,16]", "sweep.axes.sigma=[0.5,4]"]).sweep.axes.top_k == (1, 16)

    checked = 0
    for section, hypers in (("retrieval", table), ("sweep.axes", sweepable)):
        for name, h in hypers.items():
            for bad in _outside(h):
                value = f"[{h.default}, {bad}]" if section == "sweep.axes" else bad
                with pytest.raises(ConfigError, match=rf"'{section}\.{name}': {re.escape(h.rule)}"):
                    load_config(None, [f"{section}.{name}={value}"])
                checked += 1
    assert checked >= 10  # sigma, sigma_loc, top_k, hops, boost_hops, beam (both sections), sigma_rel, forest_lock, lam
    with pytest.raises(ConfigError, match=r"'sweep.axes.eta': values must be distinct"):
        SweepAxes(eta=(0.5, 0.5))
