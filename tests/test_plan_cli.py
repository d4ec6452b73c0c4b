"""`ragnav plan`: instruction -> retrieval -> order -> guide on the apartment."""

import json

import networkx as nx
import numpy as np
import pytest
from test_memory_streams import synthetic_stream

from ragnav_jax.cli import main
from ragnav_jax.config import load_config
from ragnav_jax.memory.build import build_bank
from ragnav_jax.memory.checkpoint import save_bank
from ragnav_jax.memory.encoder import HashingEmbedder
from ragnav_jax.planning.plan import plan_instruction
from ragnav_jax.world.scene import save_scene


@pytest.fixture(scope="module")
def bank(apartment):
    cfg = load_config(None, ["memory.embedder=hashing"])
    b, _ = build_bank([apartment], [synthetic_stream(apartment)], cfg, embedder=HashingEmbedder(dim=cfg.memory.hashing_dim))
    return cfg, b


def test_strict_order_is_kept_and_paths_follow_the_map(bank, apartment):
    cfg, b = bank
    guide = plan_instruction(b, apartment, "First go to the wardrobe, then the fridge.", HashingEmbedder(dim=cfg.memory.hashing_dim), cfg)
    assert guide["chain"]["order"] == "strict" and guide["status"] == "ok"
    assert [t["name"] for t in guide["targets"]] == ["wardrobe", "fridge"]
    mem, meta = b.scene("apartment")
    adj = np.asarray(mem.adjacency)
    g = nx.from_numpy_array(adj[: meta.num_nodes, : meta.num_nodes].astype(int))
    for t in guide["targets"]:
        nodes = t["leg"]["nodes"]
        assert all(g.has_edge(a, c) for a, c in zip(nodes, nodes[1:]))  # every step is a map edge


def test_plan_cli(bank, apartment, tmp_path, capsys):
    cfg, b = bank
    run = tmp_path / "run"
    save_scene(apartment, run / "scenes" / "apartment.json")
    save_bank(b, run / "memory" / "bank")
    png, js = tmp_path / "route.png", tmp_path / "guide.json"
    assert main(["plan", "--run", str(run), "--scene", "apartment", "Visit the fridge and the bed in any order",
                 "--out", str(png), "--json", str(js)]) == 0
    assert png.read_bytes()[:4] == b"\x89PNG"
    guide = json.loads(js.read_text())
    assert len(guide["targets"]) == 2 and "why" in guide["targets"][0]
    assert "Plan" in capsys.readouterr().out
    assert main(["plan", "--run", str(run), "--scene", "nowhere", "go to the bed"]) == 2
    assert main(["plan", "--run", str(run), "--scene", "apartment", "   "]) == 2
