"""`ragnav bench`: the quick profile's peer comparisons all land in bench.json and bench.md, and the GPU
profile runs end to end at tiny scale on the CPU (chunked retrieval, capped faiss, its sweep)."""

import json

import numpy as np
import pytest

from ragnav_jax.bench.profiles import FULL, GPU, PROFILES, QUICK, SECTIONS, scaled
from ragnav_jax.cli import main

PEER_SECTIONS = ("retrieval", "paths", "planning", "simulation")


def test_profiles_scale_down_and_keep_their_shape():
    assert set(PROFILES) == {"quick", "full", "gpu"}
    assert max(GPU.retrieval_sizes) >= 1_000_000 and max(GPU.retrieval_queries) >= 1_000_000
    assert max(GPU.sim_batches) >= 16384 and 1024 in GPU.e2e_scenes and GPU.sweep_points >= 1000
    assert FULL.retrieval_sizes == (80, 1000, 10000, 100000) and FULL.path_nodes == (80, 200)
    assert FULL.plan_episodes == 10_000 and FULL.sim_batches[0] == 1 and FULL.sim_batches[-1] == 1024
    tiny = scaled(GPU, 0.001)
    assert tiny.name == "gpu@0.001" and tiny.retrieval_sizes == (16, 100, 1000) and tiny.retrieval_chunk == 5
    assert all(n >= 16 for n in tiny.retrieval_sizes) and len(set(tiny.retrieval_sizes)) == len(tiny.retrieval_sizes)
    assert tiny.e2e_scenes == (1, 2) and tiny.e2e_embedder == "hashing" and tiny.e2e_explore_steps == 200
    assert scaled(QUICK, 1.0) is QUICK
    with pytest.raises(ValueError):
        scaled(QUICK, 0)


def test_bench_rejects_bad_arguments(tmp_path, capsys):
    assert main(["bench", "--out", str(tmp_path), "--quick", "--gpu"]) == 2
    assert main(["bench", "--out", str(tmp_path), "--only", "nonsense"]) == 2
    assert "unknown section" in capsys.readouterr().err


@pytest.mark.slow
def test_quick_bench_reports_every_comparison(tmp_path):
    out = tmp_path / "bench"
    assert main(["bench", "--out", str(out), "--quick", "--scale", "0.05", "--quiet", "--set", "sim_batches=4",  # one MJX compile
                 "--only", *PEER_SECTIONS]) == 0
    doc = json.loads((out / "bench.json").read_text())
    assert {"cpu_model", "cpu_count", "memory_gb", "jax_devices"} <= set(doc["machine"])
    assert doc["packages"]["jax"] != "not installed"
    assert all(doc["sections"][s]["status"] == "ok" for s in PEER_SECTIONS)
    comps = doc["comparisons"]
    peers = {(c["section"], c["peer"]["name"].split()[0]) for c in comps}
    assert {("retrieval", "faiss-cpu"), ("retrieval", "paper"), ("paths", "networkx"), ("planning", "Python"),
            ("simulation", "MuJoCo")} <= peers
    names = " ".join(c["name"] for c in comps)
    assert "brute force n=8" in names and "held karp n=12" in names
    for c in comps:
        o = c["ours"]
        assert o["min_s"] <= o["median_s"] <= o["max_s"] and c["ratio"] > 0
        assert c["ratio_range"][0] <= c["ratio"] <= c["ratio_range"][1]
    assert all(c.get("agrees", True) for c in comps)
    assert all(r["compile_s"] > 0 for r in doc["sections"]["planning"]["rows"])
    md = (out / "bench.md").read_text()
    assert "## Comparisons" in md and "faiss" in md and "networkx" in md and (out / "retrieval.png").is_file()


@pytest.mark.slow
def test_gpu_profile_runs_at_tiny_scale_on_cpu(tmp_path):
    # GPU settings at 1/2000: chunked 500-query batches, capped faiss, the sweep; simulation and peers are
    # covered by the quick test above (their GPU sizes only change batch sizes), the execute stage's loop
    # (evaluate_navigation) by test_eval.py, so it is skipped here (about 50 s of compiling the paper loop)
    out = tmp_path / "gpu"
    assert main(["bench", "--out", str(out), "--gpu", "--scale", "0.0005", "--quiet", "--set", "e2e_execute_episodes=0",
                 "--only", "retrieval", "end_to_end", "sweep"]) == 0
    doc = json.loads((out / "bench.json").read_text())
    assert doc["profile"] == "gpu@0.0005+set"
    r = doc["sections"]["retrieval"]["rows"]
    assert [x["nodes"] for x in r] == [16, 50, 500]  # 80, 1k and 10k all floor to 16 nodes, deduplicated
    assert all(x["query_chunk"] < x["batch_queries"] and x["sim_top1_agreement"] >= 0.99 for x in r)
    e2e = doc["sections"]["end_to_end"]
    assert e2e["status"] == "ok" and [x["scenes"] for x in e2e["by_scenes"]] == [1]  # 1 .. 1024 scenes -> 1
    st = e2e["by_scenes"][0]["stages"]
    for s in ("generate", "explore", "build_memory", "episodes", "retrieve", "plan"):
        assert st[s]["wall_s"] >= st[s]["compile_s"] >= 0 and st[s]["peak_rss_mb"] > 0
    assert st["execute"]["status"] == "skipped" and "e2e_execute_episodes=0" in st["execute"]["reason"]
    assert len(e2e["by_nodes"]) == 2
    sw = doc["sections"]["sweep"]
    assert sw["status"] == "ok" and sw["grid_points"] >= 1 and sw["points_per_s"] > 0
    assert set(doc["sections"]) == {"retrieval", "end_to_end", "sweep"} and set(SECTIONS) > set(doc["sections"])
    assert (out / "end_to_end_scenes.png").is_file() and (out / "end_to_end_nodes.png").is_file()


def _fake_run(folder, section, ratio):
    from ragnav_jax.bench.sections import comparison
    from ragnav_jax.bench.timing import stats

    comp = comparison(section, f"{section} case", stats([1.0, 1.2, 0.9]), stats([ratio] * 3), "peer x", "item")
    doc = {"profile": "full", "time": "t", "git_commit": "abc", "note": "n", "notes": "", "total_wall_s": 2.0,
           "machine": {"cpu_model": "cpu", "cpu_count": 2, "cpus_usable": 2, "memory_gb": 1, "jax_devices": ["cpu"],
                       "load_average_1_5_15": [0, 0, 0], "device_kind": "cpu", "jax_backend": "cpu"},
           "packages": {"jax": "0"}, "comparisons": [comp],
           "sections": {section: {"status": "ok", "comparisons": [comp], "section_wall_s": 2.0, "section_cpu_s": 3.0}}}
    folder.mkdir()
    (folder / "bench.json").write_text(json.dumps(doc))


def test_merge_combines_sections_and_rewrites_the_report(tmp_path):
    _fake_run(tmp_path / "a", "paths", 10.0)
    _fake_run(tmp_path / "b", "planning", 5.0)
    assert main(["bench", "--out", str(tmp_path / "m"), "--merge", str(tmp_path / "a"), str(tmp_path / "b")]) == 0
    doc = json.loads((tmp_path / "m" / "bench.json").read_text())
    assert set(doc["sections"]) == {"paths", "planning"} and len(doc["comparisons"]) == 2 and doc["total_wall_s"] == 4.0
    assert doc["comparisons"][0]["ratio"] == pytest.approx(10.0) and len(doc["parts"]) == 2
    md = (tmp_path / "m" / "bench.md").read_text()
    assert "paths case" in md and "planning case" in md and "| paths | ok | 2.0 | 3.0 | 1.50 |" in md
    assert main(["bench", "--out", str(tmp_path / "m2"), "--merge", str(tmp_path / "nothing")]) == 2


def test_profile_overrides_parse_and_reject():
    from ragnav_jax.bench.commands import override_profile
    from ragnav_jax.bench.profiles import GPU
    from ragnav_jax.errors import UserError

    p = override_profile(GPU, ["e2e_embedder=hashing", "e2e_scenes=1,14", "path_chunk=none", "sweep_points=1000"])
    assert (p.e2e_embedder, p.e2e_scenes, p.path_chunk, p.sweep_points) == ("hashing", (1, 14), None, 1000)
    assert p.retrieval_sizes == GPU.retrieval_sizes and p.name == "gpu+set"
    with pytest.raises(UserError, match="FIELD one of"):
        override_profile(GPU, ["no_such_field=1"])
    with pytest.raises(UserError, match="--set sweep_points.*expected an integer"):
        override_profile(GPU, ["sweep_points=many"])
    with pytest.raises(UserError, match=r"--set sim_batches\[1\].*expected an integer"):
        override_profile(GPU, ["sim_batches=1,x"])


def test_retrieval_blocks_are_capped_by_cells_and_a_failing_size_keeps_the_others(monkeypatch):
    # retrieval_max_cells bounds queries x nodes per block and the faiss batch (1M nodes on an 80 GB GPU);
    # a size that fails (device memory) is recorded with its error and the next sizes still run
    from ragnav_jax.bench import sections
    from ragnav_jax.bench.profiles import QUICK

    p = QUICK.replace(retrieval_sizes=(16, 64, 32), retrieval_queries=(8, 8, 8), retrieval_chunk=None,
                      faiss_queries=None, retrieval_max_cells=128, repeats=2)
    mod = sections.experiment("bench_retrieval")
    real = mod.bench_size

    def flaky(n, *a, **kw):
        if n == 64:
            raise MemoryError("RESOURCE_EXHAUSTED: pretend")
        return real(n, *a, **kw)

    monkeypatch.setattr(mod, "bench_size", flaky)
    res = sections.bench_retrieval(p, lambda s: None)
    by_n = {r["nodes"]: r for r in res["rows"]}
    assert by_n[16]["query_chunk"] == 8 and by_n[32]["query_chunk"] == 4  # 128 cells // 32 nodes
    assert "RESOURCE_EXHAUSTED" in by_n[64]["error"] and "single" not in by_n[64]
    if by_n[32]["sim_faiss"] is not None:
        assert by_n[32]["sim_faiss_queries"] == 4
    from ragnav_jax.bench.report import readme_table
    doc = {"machine": {"device_kind": None, "jax_backend": "cpu"}, "profile": "t", "comparisons": res["comparisons"],
           "sections": {"retrieval": {"status": "ok", **res}}}
    assert sum("retrieval," in line for line in readme_table(doc)) == 2


def test_merge_section_combines_rows_per_size():
    from ragnav_jax.bench.suite import _merge_section

    a = {"status": "partial", "rows": [{"nodes": 80, "v": 1}, {"nodes": 1000, "v": 1}],
         "comparisons": [{"name": "n80"}, {"name": "n1000"}], "section_wall_s": 2.0}
    b = {"status": "ok", "rows": [{"nodes": 1000, "v": 2}, {"nodes": 10**6, "v": 2}], "comparisons": [{"name": "n1M"}],
         "section_wall_s": 3.0}
    m = _merge_section(a, b, "nodes")
    assert [(r["nodes"], r["v"]) for r in m["rows"]] == [(80, 1), (1000, 2), (10**6, 2)]
    assert [c["name"] for c in m["comparisons"]] == ["n80", "n1000", "n1M"]
    assert m["status"] == "ok" and m["merged_statuses"] == ["partial", "ok"] and m["section_wall_s"] == 5.0
    failed = {"status": "failed", "reason": "OOM"}
    assert _merge_section(b, failed, "nodes") is b and _merge_section(failed, b, "nodes") is b
    assert _merge_section({"status": "ok", "x": 1}, {"status": "ok", "x": 2}, None)["x"] == 2


def test_closed_loop_section_times_the_loop_alone_and_replays_it(monkeypatch, apartment):
    # The engines are stood in for (a real device compile takes minutes on a 2-core CPU; `ragnav bench --only
    # closed_loop` measures them): the fake evaluate_navigation goes through the same module functions the real
    # one calls, so the section's capture, replays, tiling, agreement and compile accounting are what is tested.
    import types

    from ragnav_jax.bench import sections
    from ragnav_jax.bench.report import comparison_table
    from ragnav_jax.evaluation import host_loop
    from ragnav_jax.evaluation.loop import program
    from ragnav_jax.language.episodes import load_episodes
    from ragnav_jax.memory.encoder import HashingEmbedder
    from ragnav_jax.world.scene import example_scene_path

    assert "closed_loop" in SECTIONS and "closed_loop" in sections.SECTION_FUNCS
    assert GPU.loop_episodes >= 16384 and scaled(GPU, 0.001).loop_episodes >= 2
    compiled, seen = set(), []

    def loop_stub(engine):
        def run(ex, states, *rest, **kw):
            if (engine, len(states)) not in compiled:  # one trace per engine and batch size, as jit caches them
                compiled.add((engine, len(states)))
                ex.traces["run"] += 1
            seen.append(all(st.status == ["pending"] * len(st.status) for st in states))
            for st in states:  # every goal found, except episode 0 on the host engine
                ok = engine == "device" or st.e != 0
                st.status = ["found" if ok else "failed:stuck"] * len(st.status)
                st.found = [ok] * len(st.found)
                st.steps, st.look_steps = 40, 8
        return run

    def fake_evaluate(bank, scenes, eps, embedder, cfg, method, streams=None, executor=None, verifier=None):
        states = [types.SimpleNamespace(e=i, status=["pending"] * len(ep.goals), found=[False] * len(ep.goals),
                                        steps=0, look_steps=0) for i, ep in enumerate(eps)]
        if cfg.eval.engine == "device":
            program.run_device(executor, states, cfg)
        else:
            for c0 in range(0, len(states), 2):  # host batches of 2
                host_loop._run_chunk(executor, states[c0 : c0 + 2], 2, cfg)
        return [{"success": all(st.found), "goal_status": list(st.status), "steps": st.steps + st.look_steps}
                for st in states], {}

    monkeypatch.setattr(host_loop, "_run_chunk", loop_stub("host"))
    monkeypatch.setattr(program, "run_device", loop_stub("device"))
    monkeypatch.setattr(sections, "execute_stage", lambda: fake_evaluate)
    monkeypatch.setattr(sections.experiment("bench_sim"), "bench_mjx",
                        lambda env, b, steps, reps: {"batch": b, "env_steps_per_s": 960.0, "compile_s": 0.1})
    p = QUICK.replace(name="loop-test", loop_scenes=1, loop_episodes=6, loop_distinct=3, loop_repeats=2,
                      loop_host_repeats=1, loop_refills=(0.5,))
    eps = load_episodes(example_scene_path().parent / "episodes.jsonl", [apartment])
    art = {"scenes": [apartment], "explored": [types.SimpleNamespace(stream=None)], "bank": None,
           "embedder": HashingEmbedder(dim=64), "episodes": eps}
    monkeypatch.setitem(sections._ARTIFACTS, (p.name, 1), art)
    res = sections.bench_closed_loop(p, lambda s: None)
    assert not hasattr(host_loop._run_chunk, "__wrapped__") and not hasattr(program.run_device, "__wrapped__")
    assert all(seen)  # every replay started from copies of the states as they were before the loop
    assert res["distinct_episodes"] == 3 and res["episodes"] == 6 and res["env_steps_per_s"] == 960.0
    assert set(res["methods"]) == {"oracle", "ragnav"} and len(res["comparisons"]) == 2
    for m in res["methods"].values():
        h, d = m["host"], m["device"]
        assert (h["episodes"], h["tiled"], len(h["runs"])) == (3, False, 2)  # the evaluate call's loop + 1 replay
        assert (d["episodes"], d["tiled"], len(d["runs"])) == (6, True, 3)  # tiled: 1 + 2 replays of 6
        assert m["agreement"] == pytest.approx(2 / 3) and 0 <= m["agreement"] <= 1
        assert h["replay_agreement"] == d["replay_agreement"] == 1.0
        for e in (h, d):
            assert e["episodes_per_s"] > 0 and np.isfinite(e["episodes_per_s"]) and e["compile_s"] >= 0
            assert e["compilations_after_first"] == 0 and e["evaluate_call"]["preamble_s"] >= 0
            assert e["episodes_per_s_range"][0] <= e["episodes_per_s"] <= e["episodes_per_s_range"][1]
        assert m["steps_per_episode"] == 48 and m["episodes_per_s_bound"] == pytest.approx(20.0)
    first = res["methods"]["oracle"]
    assert first["host"]["compilations"] == 2 and first["device"]["compilations"] == 2  # sizes 2, 1; 3, 6
    assert res["methods"]["ragnav"]["device"]["compilations"] == 0  # the stub's cache, like jit's, is warm
    c = res["comparisons"][0]
    assert c["section"] == "closed_loop" and c["ratio"] > 0 and c["peer_episodes"] == 3 and c["episodes"] == 6
    for m in res["methods"].values():  # the device runs again at eval.refill=0.5, a compilation timed apart
        r = m["device"]["refills"]["0.5"]
        assert r["episodes_per_s"] > 0 and r["compile_s"] >= 0 and len(r["warm"]) > 0
    md = sections.closed_loop_markdown(res)
    assert md[0].startswith("## Closed loop") and sum(line.startswith("| oracle") for line in md) == 2
    assert any("eval.refill" in line for line in md)
    assert len(comparison_table(res["comparisons"])) == 4


def test_loop_episodes_spaces_or_repeats():
    from ragnav_jax.bench.sections import loop_episodes

    xs = list(range(10))
    assert loop_episodes(xs, 5) == [0, 2, 4, 6, 8] and loop_episodes(xs, 10) == xs
    assert loop_episodes(xs, 23) == xs + xs + [0, 1, 2]
