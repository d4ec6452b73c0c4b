"""A tiny run folder for the sweep, tuning, sharding and notebook tests: the apartment, its memory from the
synthetic stream with the hashing embedder, and generated episodes of all three modalities."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from test_memory_streams import synthetic_stream

from ragnav_jax.config import load_config
from ragnav_jax.language.episodes import generate_episodes, save_episodes
from ragnav_jax.memory.build import build_bank
from ragnav_jax.memory.checkpoint import save_bank
from ragnav_jax.memory.encoder import HashingEmbedder
from ragnav_jax.world.scene import save_scene

ROOT = Path(__file__).resolve().parents[1]
# Small config overrides shared by the tests: the hashing embedder, a 3 x 2 grid, three variants.
SMALL = ["memory.embedder=hashing", "sweep.axes.sigma=[0.5,2.0,6.0]", "sweep.axes.eta=[0.0,1.0]",
         "sweep.variants=[ragnav,no_boost,no_forest]", "sweep.chunk_size=12", "episodes.text=6",
         "episodes.text_location=4", "episodes.text_location_sensor=4", "tune.steps=12", "tune.eval_every=4"]


@pytest.fixture(scope="session")
def tiny_run(apartment, tmp_path_factory):
    """(run folder, episodes file, config, bank, embedder)."""
    cfg = load_config(None, SMALL)
    run = tmp_path_factory.mktemp("tiny_run")
    save_scene(apartment, run / "scenes" / "apartment.json")
    emb = HashingEmbedder(dim=cfg.memory.hashing_dim)
    bank, _ = build_bank([apartment], [synthetic_stream(apartment)], cfg, embedder=emb)
    save_bank(bank, run / "memory" / "bank")
    episodes = run / "episodes" / "episodes.jsonl"
    save_episodes([p.episode for p in generate_episodes([apartment], cfg.episodes, seed=0)], episodes)
    return run, episodes, cfg, bank, emb


def ragnav_subprocess(args: list[str], env: dict | None = None, cache: Path | None = None, **kw) -> subprocess.Popen:
    """`ragnav ARGS` in a fresh Python process (CPU, offline), stdout/stderr captured.

    cache: a persistent compilation cache folder shared by the test's processes (a restarted run then
    skips compiling again)."""
    e = {**os.environ, "JAX_PLATFORMS": "cpu", "HF_HUB_OFFLINE": "1", **(env or {})}
    if cache is not None:
        e.update(JAX_COMPILATION_CACHE_DIR=str(cache), JAX_PERSISTENT_CACHE_MIN_COMPILE_TIME_SECS="0",
                 JAX_PERSISTENT_CACHE_MIN_ENTRY_SIZE_BYTES="-1")
    return subprocess.Popen([sys.executable, "-m", "ragnav_jax.cli", *args], cwd=ROOT, env=e,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kw)
