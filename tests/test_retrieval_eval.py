"""Retrieval evaluation end to end on the apartment: memory -> episodes -> accuracy per modality."""

import json

import numpy as np
import pytest
from test_memory_streams import synthetic_stream

from ragnav_jax.cli import main
from ragnav_jax.config import load_config
from ragnav_jax.language.episodes import load_episodes
from ragnav_jax.memory.build import build_bank
from ragnav_jax.memory.encoder import HashingEmbedder
from ragnav_jax.retrieval.evaluate import METHODS, evaluate_retrieval
from ragnav_jax.world.scene import example_scene_path, save_scene

EPISODES = example_scene_path().parent / "episodes.jsonl"


@pytest.fixture(scope="module")
def setup(apartment):
    cfg = load_config(None, ["memory.embedder=hashing"])
    stream = synthetic_stream(apartment)
    emb = HashingEmbedder(dim=cfg.memory.hashing_dim)
    bank, _ = build_bank([apartment], [stream], cfg, embedder=emb)
    return cfg, bank, stream, emb


@pytest.mark.parametrize("method", METHODS)
def test_every_method_runs_and_rows_follow_the_instance_rule(setup, apartment, method):
    cfg, bank, _, emb = setup
    episodes = load_episodes(EPISODES, [apartment])
    rows, summary = evaluate_retrieval(bank, [apartment], episodes, emb, method)
    assert len(rows) == sum(len(e.goals) for e in episodes) == summary["queries"]
    assert 0.0 <= summary["retrieval_accuracy"] <= 1.0
    assert set(summary["by_modality"]) == {"text", "text+location", "text+location+sensor"}
    obs = np.asarray(bank.memory.obs_object[0])
    ids = [o.id for o in apartment.objects]
    for r in rows:
        if r["correct"]:  # correct means the chosen node observes the goal instance itself
            assert ids.index(r["goal"]) in set(obs[r["node"]][obs[r["node"]] >= 0].tolist())
    assert summary["retrieval_ms_single"] >= 0
    if method.startswith("ragnav"):  # the instance rule is the stricter: its hits are node hits
        assert all(r["correct"] or not r["instance_correct"] for r in rows)
        assert summary["instance_accuracy"] <= summary["retrieval_accuracy"]
        assert summary["instance_accuracy"] > 0.5 * summary["retrieval_accuracy"]


def test_ragnav_text_queries_are_retrieved(setup, apartment):
    cfg, bank, _, emb = setup
    episodes = [e for e in load_episodes(EPISODES, [apartment]) if e.modality == "text"]
    _, summary = evaluate_retrieval(bank, [apartment], episodes, emb, "ragnav")
    assert summary["by_modality"]["text"]["retrieval_accuracy"] >= 0.8


def test_retrieve_cli(setup, apartment, tmp_path):
    from ragnav_jax.memory.checkpoint import save_bank

    cfg, bank, stream, _ = setup
    run = tmp_path / "run"
    save_scene(apartment, run / "scenes" / "apartment.json")
    save_bank(bank, run / "memory" / "bank")
    out = tmp_path / "out"
    assert main(["retrieve", "--run", str(run), "--episodes", str(EPISODES), "--method", "ragnav", "--out", str(out),
                 "--quiet", "memory.embedder=hashing"]) == 0
    s = json.loads((out / "summary.json").read_text())
    assert "retrieval_accuracy" in s and "by_modality" in s and (out / "results.jsonl").exists()
    assert (out / "config.yaml").exists() and (out / "summary.md").exists()
    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"id": "x", "scene": "apartment", "instruction": "go", "goals": []}\n')
    assert main(["retrieve", "--run", str(run), "--episodes", str(bad), "--out", str(tmp_path / "o2"), "--quiet"]) == 2
    with pytest.raises(SystemExit) as e:
        main(["retrieve", "--run", str(run), "--episodes", str(EPISODES), "--method", "nope", "--out", str(out)])
    assert e.value.code == 2
