"""The hot leg runner compiles once: every leg of every episode, over several chunks and a second
method's evaluation, reuses the same trace of Executor.run / look / init (fixed batch size, padded
waypoints, array arguments)."""

from test_memory_streams import synthetic_stream

from ragnav_jax.config import load_config
from ragnav_jax.evaluation.execute import make_executor
from ragnav_jax.evaluation.navigate import evaluate_navigation
from ragnav_jax.language.episodes import load_episodes
from ragnav_jax.memory.build import build_bank
from ragnav_jax.memory.encoder import HashingEmbedder
from ragnav_jax.world.scene import example_scene_path


def test_leg_runner_traces_once_across_legs(apartment):
    cfg = load_config(None, ["memory.embedder=hashing", "eval.batch_size=4"])
    emb = HashingEmbedder(dim=cfg.memory.hashing_dim)
    bank, _ = build_bank([apartment], [synthetic_stream(apartment)], cfg, embedder=emb)
    episodes = load_episodes(example_scene_path().parent / "episodes.jsonl", [apartment])[:6]  # two chunks of 4
    ex = make_executor([apartment], cfg)
    rows, _ = evaluate_navigation(bank, [apartment], episodes, emb, cfg, "ragnav", executor=ex)
    legs = sum(len(r["declarations"]) + r["rejected_candidates"] for r in rows)
    assert legs >= 2  # several legs really ran through the compiled runner
    assert ex.traces == {"run": 1, "look": 1, "init": 1}
    # Another method over the same episodes (same batch size B = min(batch_size, episodes)) reuses it too.
    evaluate_navigation(bank, [apartment], episodes, emb, cfg, "oracle", executor=ex)
    assert ex.traces == {"run": 1, "look": 1, "init": 1}
