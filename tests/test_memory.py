"""Dual-basis memory: key poses, captions, edges against the scene geometry, the built bank, orbax round trip
and corruption detection, CLI, optional LLM endpoint. Streams come from `test_memory_streams` (no simulator)."""

from __future__ import annotations

import dataclasses
import json
import math
import threading
from http.server import BaseHTTPRequestHandler, HTTPServer

import jax
import numpy as np
import pytest
from test_memory_streams import synthetic_stream

from ragnav_jax.config import LLMConfig, WorldConfig, load_config
from ragnav_jax.errors import UserError
from ragnav_jax.memory.build import build_bank, caption_noise, memory_summary
from ragnav_jax.memory.captioner import CONFUSIONS, SYNONYMS, canonical, template_caption
from ragnav_jax.memory.checkpoint import load_bank, save_bank
from ragnav_jax.memory.keyposes import KeyframeRule, observe, select_key_poses
from ragnav_jax.memory.summarise import Summariser
from ragnav_jax.memory.topomap import obstacles_numpy
from ragnav_jax.memory.types import DualBasisMemory, MemoryBank
from ragnav_jax.world import geometry
from ragnav_jax.world.generator import generate_scene

CFG = load_config(None, ["memory.embedder=hashing", "memory.hashing_dim=64"])


@pytest.fixture(scope="module")
def scenes(apartment):
    house = generate_scene(WorldConfig(min_rooms=5, max_rooms=5, min_objects=25, max_objects=30), 3, 0)
    return [apartment, house]


@pytest.fixture(scope="module")
def streams(scenes):
    return [synthetic_stream(s) for s in scenes]


@pytest.fixture(scope="module")
def built(scenes, streams):
    return build_bank(scenes, streams, CFG)


# ----------------------------------------------------------------------------------------------------
# Key poses


@pytest.mark.parametrize("rule", ["spacing", "novelty", "both"])
def test_key_poses_rules(scenes, streams, rule):
    scene, stream = scenes[1], streams[1]
    r = KeyframeRule(rule=rule, spacing=1.5)
    keys = select_key_poses(stream, obstacles_numpy(scene), r)
    assert keys[0] == 0 and np.all(np.diff(keys) > 0) and keys[-1] < stream.pose.shape[0]
    xy = stream.pose[keys, :2]
    # every key pose links to an earlier one (the map stays connected along the trajectory)
    for k in range(1, len(keys)):
        d = np.hypot(*(xy[:k] - xy[k]).T)
        assert any(d[j] < r.link_distance and not _segment_blocked(scene, xy[j], xy[k], r.link_clearance)
                   for j in range(k)), k
    if rule == "spacing":
        # every record has a key pose within the spacing or a forced link nearby
        d = np.hypot(stream.pose[:, None, 0] - xy[None, :, 0], stream.pose[:, None, 1] - xy[None, :, 1]).min(1)
        assert d.max() < r.link_distance


def test_spacing_controls_node_count(scenes, streams):
    obs = obstacles_numpy(scenes[1])
    counts = [len(select_key_poses(streams[1], obs, KeyframeRule("spacing", spacing=s))) for s in (0.75, 1.5, 3.0)]
    assert counts[0] > counts[1] > counts[2] >= 1


def test_observations_sorted_and_windowed(streams):
    s = streams[0]
    one = observe(s, np.array([5]), 0)[0]
    assert list(one.distances) == sorted(one.distances)
    assert set(one.objects) == set(np.flatnonzero(s.visible[5]))
    wide = observe(s, np.array([5]), 3)[0]
    assert set(one.objects) <= set(wide.objects)


# ----------------------------------------------------------------------------------------------------
# Captions


def test_captions_deterministic_noisy_and_free_of_room_types(scenes, streams):
    scene, stream = scenes[1], streams[1]
    obs = observe(stream, select_key_poses(stream, obstacles_numpy(scene), KeyframeRule()), 0)
    noise = caption_noise(CFG.memory)
    caps = [template_caption(scene, o, i, 0, noise) for i, o in enumerate(obs)]
    again = [template_caption(scene, o, i, 0, noise) for i, o in enumerate(obs)]
    assert caps == again
    other = [template_caption(scene, o, i, 1, noise) for i, o in enumerate(obs)]
    assert caps != other  # the seed matters
    rooms = {r.type for r in scene.rooms} | {r.id for r in scene.rooms}
    for c in caps:
        assert not any(t in c.text.lower() for t in rooms if t not in ("office", "gym"))
    # every label is a (possibly synonymous) name of a category the node saw or a known confusion
    for c, o in zip(caps, obs):
        seen = {scene.objects[i].category for i in o.objects}
        seen |= {CONFUSIONS[x] for x in seen if x in CONFUSIONS}
        assert all(canonical(lbl) in seen for lbl in c.labels), (c, seen)
        assert len(c.labels) <= noise.max_objects


def test_captions_say_attributes_under_any_key(apartment):
    """A scene may name its attributes as it likes ("colour", "kind"): the captioner says their values too."""
    from ragnav_jax.memory.captioner import describe_object
    from ragnav_jax.world.scene import SceneObject

    noise = dataclasses.replace(caption_noise(CFG.memory), attribute_keep=1.0, synonym=0.0, confusion=0.0)
    o = SceneObject("kayak_1", "kayak", (1.0, 1.0, 0.2), (3.0, 0.6, 0.4), "shed",
                    (("colour", "yellow"), ("kind", "sea"), ("material", "plastic"), ("state", "empty")))
    name, text = describe_object(np.random.default_rng(0), o, 2.0, noise)
    assert name == "kayak" and all(w in text.split() for w in ("yellow", "sea", "plastic", "empty")), text
    # and the free-text description a scene may give (the schema's "description")
    o = dataclasses.replace(o, description="Dented, with a Faded racing stripe.")
    text = describe_object(np.random.default_rng(0), o, 2.0, noise)[1]
    assert text.endswith(", dented, with a faded racing stripe") and "yellow" in text, text


def test_caption_noise_statistics(apartment, streams):
    """Far objects are missed more often than near ones; synonyms appear; attributes are sometimes dropped."""
    from ragnav_jax.memory.keyposes import NodeObservation

    noise = caption_noise(CFG.memory)
    sofa = next(i for i, o in enumerate(apartment.objects) if o.category == "sofa")
    near_hits = far_hits = syn = 0
    lengths = set()
    for k in range(400):
        near = NodeObservation(k, (0, 0, 0), 0.0, (sofa,), (1.0,), (0.0,))
        far = NodeObservation(k, (0, 0, 0), 0.0, (sofa,), (7.0,), (0.0,))
        cn = template_caption(apartment, near, k, 0, noise)
        near_hits += bool(cn.labels)
        far_hits += bool(template_caption(apartment, far, k, 0, noise).labels)
        syn += "couch" in cn.text
        lengths.add(len(cn.text.split()))
    assert near_hits > 360 and far_hits < near_hits - 80
    assert 60 < syn < 260
    assert len(lengths) >= 3  # attributes dropped / templates varied
    assert canonical("bedside table") == "nightstand" and canonical("TV") == "television"
    assert "couch" in SYNONYMS["sofa"]


def test_summariser_prototypes():
    s = Summariser()
    from collections import Counter

    assert s.infer_type(Counter({"coffee machine": 2, "sink": 1}), 1)[0] == "breakfast nook"
    assert s.infer_type(Counter({"bed": 2, "nightstand": 2, "wardrobe": 1}), 2)[0] == "bedroom"
    assert s.infer_type(Counter(), 1)[0] == "passage"


# ----------------------------------------------------------------------------------------------------
# Edges against the scene geometry


def _segment_blocked(scene, p, q, clearance: float) -> bool:
    n = max(2, int(math.dist(p, q) / 0.01) + 1)
    t = np.linspace(0, 1, n)
    xs, ys = p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])
    for w in scene.walls:
        if (geometry.segment_distance(xs, ys, w.a, w.b) <= w.thickness / 2 + clearance - 0.005).any():
            return True
    for o in geometry.blocking_objects(scene):
        if (geometry.object_box_distance(o, xs, ys) <= clearance - 0.005).any():
            return True
    return False


def test_edges_never_cross_walls_or_objects(scenes, built):
    bank, _ = built
    total = 0
    for scene in scenes:
        mem, meta = bank.scene(scene.name)
        n = meta.num_nodes
        adj = np.asarray(mem.adjacency)[:n, :n]
        pos = np.asarray(mem.position)[:n]
        D = np.asarray(mem.distance)[:n, :n]
        assert (adj == adj.T).all() and not adj.diagonal().any()
        ii, jj = np.nonzero(np.triu(adj))
        total += len(ii)
        for i, j in zip(ii, jj):
            assert D[i, j] < CFG.memory.delta_spatial
            assert not _segment_blocked(scene, pos[i, :2], pos[j, :2], CFG.memory.edge_clearance), (scene.name, i, j)
        # exploration was one continuous trajectory: the map is one component
        assert meta.num_components == 1
        # pairs that are close but blocked by a wall exist and got no edge (the check is not vacuous)
        blocked = [(i, j) for i in range(n) for j in range(i + 1, n)
                   if D[i, j] < 1.5 and _segment_blocked(scene, pos[i, :2], pos[j, :2], 0.0)]
        assert all(not adj[i, j] for i, j in blocked)
    assert total > 20


# ----------------------------------------------------------------------------------------------------
# The bank


def test_bank_contents(scenes, built):
    bank, stats = built
    mem = bank.memory
    B, N = mem.node_mask.shape
    assert B == 2 and N % CFG.memory.node_pad_multiple == 0
    L = 1 + len(CFG.memory.level_sizes)
    assert mem.tree_level.shape == (B, L * N) and L >= 3
    assert mem.embedding.shape == (B, N, 64) and mem.obs_object.shape == (B, N, CFG.memory.max_objects_per_node)
    assert mem.path_pred.dtype == np.int32 and mem.path_cost.dtype == np.float32
    for b, meta in enumerate(bank.metas):
        n = meta.num_nodes
        assert n == int(mem.node_mask[b].sum()) == len(meta.captions) == len(meta.observed_ids)
        cost = np.asarray(mem.path_cost[b])
        assert np.isfinite(cost[:n, :n]).all() and np.isinf(cost[n:]).all()
        top = [s for s in range((L - 1) * N, L * N) if mem.tree_mask[b, s]]
        assert all(meta.tree_labels[s] for s in top) and all(mem.tree_parent[b, s] == -1 for s in top)
        # sensor vectors aggregate the seen objects' readings
        scene = scenes[b]
        for i in range(n):
            for si, name in enumerate(meta.sensor_names):
                vals = [v for oid in meta.observed_ids[i] for k, v in scene.object_by_id(oid).sensors if k == name]
                assert bool(mem.sensor_mask[b, i, si]) == bool(vals)
                if vals:
                    assert float(mem.sensors[b, i, si]) == pytest.approx(np.mean(vals), rel=1e-5)
    s = memory_summary(bank)
    assert s["num_scenes"] == 2 and s["mean_nodes"] == pytest.approx(np.mean([m.num_nodes for m in bank.metas]))
    assert set(stats.stage_seconds) == {"keyposes", "captioning", "embedding", "edges", "apsp", "forest", "summaries"}


def test_build_is_deterministic(scenes, streams, built):
    bank2, _ = build_bank(scenes[:1] + scenes[1:], streams, CFG)
    for a, b in zip(jax.tree.leaves(built[0].memory), jax.tree.leaves(bank2.memory)):
        np.testing.assert_array_equal(np.asarray(a), np.asarray(b))
    assert built[0].metas == bank2.metas


def test_orbax_round_trip_exact(built, tmp_path):
    bank, _ = built
    save_bank(bank, tmp_path / "bank")
    back = load_bank(tmp_path / "bank")
    assert isinstance(back, MemoryBank) and isinstance(back.memory, DualBasisMemory)
    for f in back.memory.__dataclass_fields__:
        a, b = np.asarray(getattr(bank.memory, f)), np.asarray(getattr(back.memory, f))
        assert a.dtype == b.dtype and a.shape == b.shape, f
        np.testing.assert_array_equal(a, b, err_msg=f)
    assert back.metas == bank.metas
    mem, meta = back.scene("apartment")
    assert mem.node_mask.ndim == 1 and meta.scene == "apartment"
    with pytest.raises(UserError, match="no memory for scene"):
        back.scene("castle")


def _data_files(root):
    return sorted(p for p in (root / "arrays").rglob("*") if p.is_file() and "/d/" in str(p))


@pytest.mark.filterwarnings("ignore::pytest.PytestUnraisableExceptionWarning")  # orbax's event loop on failure
@pytest.mark.parametrize("damage", ["flip", "truncate", "delete_arrays", "meta_version", "meta_shape", "meta_garbage",
                                    "meta_missing", "meta_checksum"])
def test_corruption_is_a_clear_error(built, tmp_path, damage):
    bank, _ = built
    root = save_bank(bank, tmp_path / "bank")
    meta_path = root / "meta.json"
    meta = json.loads(meta_path.read_text())
    if damage == "flip":
        for f in _data_files(root):
            data = bytearray(f.read_bytes())
            data[len(data) // 2] ^= 0xFF
            f.write_bytes(bytes(data))
    elif damage == "truncate":
        for f in _data_files(root):
            f.write_bytes(f.read_bytes()[: len(f.read_bytes()) // 3])
    elif damage == "delete_arrays":
        import shutil

        shutil.rmtree(root / "arrays")
    elif damage == "meta_version":
        meta["version"] = 99
        meta_path.write_text(json.dumps(meta))
    elif damage == "meta_shape":
        meta["fields"]["position"]["shape"][1] += 1
        meta_path.write_text(json.dumps(meta))
    elif damage == "meta_checksum":
        meta["fields"]["adjacency"]["sha256"] = "0" * 64
        meta_path.write_text(json.dumps(meta))
    elif damage == "meta_garbage":
        meta_path.write_text(meta_path.read_text()[:100])
    elif damage == "meta_missing":
        meta_path.unlink()
    with pytest.raises(UserError) as e:
        load_bank(root)
    assert str(root) in str(e.value) or "meta.json" in str(e.value)


# ----------------------------------------------------------------------------------------------------
# CLI


@pytest.fixture
def run_folder(tmp_path, scenes, streams):
    from ragnav_jax.world.scene import save_scene

    run = tmp_path / "run"
    for s, st in zip(scenes, streams):
        save_scene(s, run / "scenes" / f"{s.name}.json")
        st.save(run / "explore" / "streams" / f"{s.name}.npz")
    return run


def _main(monkeypatch, argv):
    from ragnav_jax import cli

    monkeypatch.setattr(cli, "COMMAND_MODULES", ("ragnav_jax.world.commands", "ragnav_jax.memory.commands"))
    return cli.main(argv)


def test_cli_build_and_show_memory(monkeypatch, run_folder, capsys):
    argv = ["build-memory", "--run", str(run_folder), "--quiet", "memory.embedder=hashing", "memory.hashing_dim=64"]
    assert _main(monkeypatch, argv) == 0
    summary = json.loads((run_folder / "memory" / "summary.json").read_text())
    assert summary["num_scenes"] == 2 and summary["mean_nodes"] > 5
    assert {r["scene"] for r in summary["scenes"]} == {"apartment", "house_000"}
    assert (run_folder / "memory" / "memory_summary.md").exists()
    assert (run_folder / "config.yaml").exists() and (run_folder / "memory" / "nodes.jsonl").exists()
    assert _main(monkeypatch, argv) == 2  # exists: needs --force
    assert "--force" in capsys.readouterr().err
    out = run_folder / "mem.png"
    assert _main(monkeypatch, ["show-memory", str(run_folder), "--scene", "house_000", "--out", str(out)]) == 0
    assert out.stat().st_size > 10_000
    assert _main(monkeypatch, ["show-memory", str(run_folder), "--scene", "nope", "--out", str(out)]) == 2


def test_cli_missing_streams(monkeypatch, run_folder, capsys):
    (run_folder / "explore" / "streams" / "apartment.npz").unlink()
    assert _main(monkeypatch, ["build-memory", "--run", str(run_folder), "--quiet"]) == 2
    assert "ragnav explore" in capsys.readouterr().err


# ----------------------------------------------------------------------------------------------------
# Optional LLM endpoint (a local fake OpenAI-compatible server)


class _Fake(BaseHTTPRequestHandler):
    def do_POST(self):  # noqa: N802
        body = json.loads(self.rfile.read(int(self.headers["Content-Length"])))
        assert body["messages"][0]["role"] == "user"
        text = "kitchen corner\nA corner with appliances." if "area" in body["messages"][0]["content"] else "A red couch."
        out = json.dumps({"choices": [{"message": {"role": "assistant", "content": text}}]}).encode()
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(out)))
        self.end_headers()
        self.wfile.write(out)

    def log_message(self, *a):
        pass


def test_llm_captioner_and_summariser(apartment, streams):
    import dataclasses

    server = HTTPServer(("127.0.0.1", 0), _Fake)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        llm = LLMConfig(base_url=f"http://127.0.0.1:{server.server_port}/v1", model="fake", timeout_s=5.0)
        cfg = dataclasses.replace(CFG, llm=llm, memory=dataclasses.replace(CFG.memory, captioner="llm",
                                                                           summariser="llm"))
        bank, _ = build_bank([apartment], streams[:1], cfg)
        meta = bank.metas[0]
        assert set(meta.captions) == {"A red couch."}
        N = bank.memory.node_mask.shape[1]
        assert meta.tree_labels[N] == "kitchen corner"
    finally:
        server.shutdown()
    from ragnav_jax.memory.llm import LLMError, chat

    with pytest.raises(LLMError, match="off"):
        chat(LLMConfig(), [{"role": "user", "content": "hi"}])
    with pytest.raises(LLMError, match="failed"):
        chat(LLMConfig(base_url="http://127.0.0.1:9/v1", timeout_s=1.0), [{"role": "user", "content": "hi"}])
