"""Reliability, one test per class of fault: --out on a file, atomic outputs (full disk, read-only folder),
a config that is not text, scenes too large to simulate, the packages' public API, overrides on every
subcommand, control characters echoed back, failed commands leaving no empty run folder, and LLM
captioner replies that are not captions. The bad-input table is tests/test_bad_input.py."""

from __future__ import annotations

import errno
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from ragnav_jax import io as rio
from ragnav_jax.cli import main
from ragnav_jax.errors import ConfigError, UserError, printable
from ragnav_jax.world.scene import example_scene_path

README = Path(__file__).resolve().parents[1] / "README.md"
SCENE = str(example_scene_path())


def one_error_line(err: str) -> str:
    lines = [x for x in err.splitlines() if x.strip()]
    assert len(lines) == 1 and lines[0].startswith("ragnav: error:"), err
    assert "Traceback" not in err
    return lines[0]


def leftovers(folder: Path) -> list[str]:
    """Temporary files of atomic writes still in `folder` (there must be none)."""
    return sorted(p.name for p in folder.rglob(f"*{rio.TMP_SUFFIX}*"))


# ----------------------------------------------------------------------------------------------------
# --out pointing at a file


@pytest.mark.parametrize("argv", [["generate", "--out", "taken"], ["explore", "--scenes", SCENE, "--out", "taken"],
                                  ["fit-verifier", "--out", "taken", "memory.embedder=hashing"]])
def test_out_on_an_existing_file_is_one_line(argv, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "taken").write_text("my notes\n")
    assert main(argv) == 2
    assert "taken" in one_error_line(capsys.readouterr().err)
    assert (tmp_path / "taken").read_text() == "my notes\n"


# ----------------------------------------------------------------------------------------------------
# Atomic writes


def _fail(monkeypatch, name: str, code: int) -> None:
    def fail(*args, **kwargs):
        raise OSError(code, os.strerror(code))

    monkeypatch.setattr(os, name, fail)


@pytest.mark.parametrize("where", ["fsync", "replace"])  # the disk fills while writing, or at the rename
def test_a_failed_write_keeps_the_old_file_and_leaves_no_partial_one(where, tmp_path, monkeypatch):
    path = tmp_path / "summary.json"
    rio.write_json(path, {"old": 1})
    _fail(monkeypatch, where, errno.ENOSPC)
    with pytest.raises(OSError) as e:
        rio.write_json(path, {"new": 2})
    monkeypatch.undo()
    assert e.value.filename == str(path) and e.value.errno == errno.ENOSPC  # named, for the CLI's one line
    assert json.loads(path.read_text()) == {"old": 1}
    assert leftovers(tmp_path) == []


def test_an_error_inside_the_write_leaves_nothing(tmp_path):
    with pytest.raises(RuntimeError), rio.atomic_open(tmp_path / "x.npz", "wb") as f:
        f.write(b"half")
        raise RuntimeError("interrupted")
    assert list(tmp_path.iterdir()) == []


def test_written_files_get_the_usual_permissions(tmp_path):
    rio.write_text(tmp_path / "a.txt", "x")
    mask = os.umask(0)
    os.umask(mask)
    assert (tmp_path / "a.txt").stat().st_mode & 0o777 == 0o666 & ~mask


@pytest.mark.parametrize("where", ["fsync", "replace"])
def test_full_disk_during_generate_leaves_the_old_scene_whole(where, tmp_path, monkeypatch, capsys):
    run = tmp_path / "run"
    old = run / "scenes" / "house_000.json"
    rio.write_text(old, '{"an": "earlier scene"}')
    real = getattr(os, where)

    def full(*args):  # the disk fills while the scene file is written (fsync) or renamed into place
        if where == "fsync" or str(args[1]).endswith("house_000.json"):
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        return real(*args)

    monkeypatch.setattr(os, where, full)
    assert main(["generate", "--out", str(run), "--force", "--quiet", "world.num_scenes=1", "world.max_rooms=4",
                 "world.max_objects=25"]) == 2
    line = one_error_line(capsys.readouterr().err)
    assert "No space left on device" in line and ("house_000.json" in line or where == "fsync")
    assert old.read_text() == '{"an": "earlier scene"}'
    assert leftovers(tmp_path) == []


def test_read_only_output_folder_is_one_line(tmp_path, monkeypatch, capsys):
    locked = tmp_path / "locked"
    locked.mkdir()
    if os.geteuid() == 0:  # root writes through chmod: simulate the refusal where files are created
        real = os.open

        def deny(path, *args, **kwargs):
            if str(path).startswith(str(locked)):
                raise OSError(errno.EACCES, os.strerror(errno.EACCES), str(path))
            return real(path, *args, **kwargs)

        monkeypatch.setattr(os, "open", deny)
    else:
        locked.chmod(0o555)
    try:
        assert main(["generate", "--out", str(locked / "run"), "world.num_scenes=1"]) == 2
    finally:
        locked.chmod(0o755)
    assert "Permission denied" in one_error_line(capsys.readouterr().err)


# ----------------------------------------------------------------------------------------------------
# A config file that is not text


def test_binary_config_is_a_config_error(tmp_path, capsys):
    from ragnav_jax.config import load_config

    cfg = tmp_path / "cfg.yaml"
    cfg.write_bytes(b"\x89PNG\r\n\x1a\n\x00\xff")
    with pytest.raises(ConfigError, match="cfg.yaml: not a YAML config"):
        load_config(cfg)
    assert main(["validate", "--config", str(cfg), SCENE]) == 2
    assert "cfg.yaml" in one_error_line(capsys.readouterr().err)


# ----------------------------------------------------------------------------------------------------
# Scenes too large to simulate


def _large_scene(path: Path, objects: int) -> Path:
    d = json.loads(example_scene_path().read_text())
    d["name"] = "large"
    d["objects"] = [{"id": f"cup_{i}", "category": "cup", "position": [0.3 + (i % 90) * 0.06, 0.3 + (i // 90) * 0.09, 0.05],
                     "size": [0.02, 0.02, 0.02], "room": "living"} for i in range(objects)]
    path.write_text(json.dumps(d))
    return path


def test_scene_beyond_the_object_limit_warns_in_validate_and_stops_explore(tmp_path, monkeypatch, capsys):
    from ragnav_jax.config import SimConfig

    monkeypatch.chdir(tmp_path)
    n = SimConfig().max_objects + 1
    big = _large_scene(tmp_path / "large.json", n)
    assert main(["validate", str(big)]) == 0
    err = capsys.readouterr().err
    assert f"{n} objects, more than sim.max_objects={n - 1}" in err
    assert main(["validate", str(big), "--strict"]) == 2
    capsys.readouterr()
    assert main(["explore", "--scenes", str(big), "--out", "run"]) == 2  # before anything is written or compiled
    assert "sim.max_objects" in one_error_line(capsys.readouterr().err)
    assert not (tmp_path / "run").exists()


def test_explore_memory_estimate_against_the_device(apartment, monkeypatch, capsys, tmp_path):
    from ragnav_jax.config import load_config
    from ragnav_jax.world import limits

    # the estimate follows XLA's memory analysis of the compiled explorer: G^2 collision work dominates
    per_pair = limits.explore_bytes(16, 2048, 0, 0, 144, 1) / (2 + 16 + 2048) ** 2
    assert 140 <= per_pair <= 200
    assert limits.explore_bytes(11, 150_000, 3025, 5000, 144, 1) > 3e12  # the 150,000-object scene: 3 TB
    assert limits.explore_bytes(11, 19, 3025, 5000, 144, 2) == 2 * limits.explore_bytes(11, 19, 3025, 5000, 144, 1)
    cfg = load_config(None)
    limits.check_explore_fits([apartment], cfg)  # the example fits this machine
    monkeypatch.setattr(limits, "available_memory", lambda: (1_000_000, "free on the test device"))
    with pytest.raises(UserError, match="more than the 1.0 MB free on the test device"):
        limits.check_explore_fits([apartment], cfg)
    monkeypatch.chdir(tmp_path)
    assert main(["explore", "--scenes", SCENE, "--out", "run"]) == 2
    assert "explore.max_steps" in one_error_line(capsys.readouterr().err)
    assert not (tmp_path / "run").exists()


# ----------------------------------------------------------------------------------------------------
# The packages' public API


def test_readme_python_snippets_import():
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(), re.S)
    imports = [line for b in blocks for line in b.splitlines() if re.match(r"from ragnav_jax\S* import ", line)]
    assert imports
    for line in imports:
        exec(line, {})


@pytest.mark.parametrize("package", ["language", "memory", "retrieval", "planning", "world", "evaluation"])
def test_subpackages_reexport_their_public_api(package):
    import importlib

    mod = importlib.import_module(f"ragnav_jax.{package}")
    assert mod.__all__
    for name in mod.__all__:
        assert getattr(mod, name) is not None
    with pytest.raises(AttributeError):
        mod.no_such_name  # noqa: B018


def test_reexports_are_the_modules_objects_and_import_lazily():
    from ragnav_jax.language import parse_instruction
    from ragnav_jax.language.parser import parse_instruction as original
    from ragnav_jax.memory import load_bank
    from ragnav_jax.memory.checkpoint import load_bank as original_bank

    assert parse_instruction is original and load_bank is original_bank
    assert parse_instruction("go to the sofa").subgoals[0].target.head == "sofa"
    code = "import sys, ragnav_jax.memory, ragnav_jax.world; print('jax' in sys.modules)"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.stdout.strip() == "False", r.stdout + r.stderr  # naming the API imports nothing heavy


# ----------------------------------------------------------------------------------------------------
# Every subcommand takes overrides


def test_validate_and_check_parse_take_overrides(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    for argv in (["validate", SCENE, "sim.max_objects=10"], ["validate", "sim.max_objects=10", SCENE]):
        assert main(argv) == 0
        assert "more than sim.max_objects=10" in capsys.readouterr().err  # the override took effect
    assert main(["episodes", "--scenes", SCENE, "--out", "eps.jsonl", "--quiet", "episodes.text=2",
                 "episodes.text_location=0", "episodes.text_location_sensor=0"]) == 0
    capsys.readouterr()
    assert main(["check-parse", "eps.jsonl", "llm.timeout_s=5", "--min-rate", "0"]) == 0
    assert main(["check-parse", "llm.timeout_s=0", "eps.jsonl"]) == 2
    assert "llm.timeout_s" in one_error_line(capsys.readouterr().err)


# ----------------------------------------------------------------------------------------------------
# Control characters are shown, never sent to the terminal


def test_parse_does_not_echo_escape_sequences(capsys):
    assert main(["parse", "go to the \x1b[31mred sofa\x1b[0m, then the \x07fridge"]) == 0
    out = capsys.readouterr().out
    assert "\x1b" not in out and "\x07" not in out
    assert "\\x1b[31m" in out


def test_error_messages_stay_one_printable_line(tmp_path, capsys):
    eps = tmp_path / "eps\x1b[2J\nfake.jsonl"
    assert main(["check-parse", str(eps)]) == 2
    line = one_error_line(capsys.readouterr().err)
    assert "\x1b" not in line and "\\x1b[2J\\nfake" in line
    assert printable("a\tb\x1b") == "a\\tb\\x1b" and printable("x\ny", keep_newlines=True) == "x\ny"


# ----------------------------------------------------------------------------------------------------
# A command failing on a bad setting leaves no empty run folder


def test_failed_command_removes_the_run_folder_it_created(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main(["fit-verifier", "--out", "fresh", "world.split=unseen", "memory.embedder=hashing"]) == 2
    assert "world.split" in one_error_line(capsys.readouterr().err)
    assert not (tmp_path / "fresh").exists()
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "notes.txt").write_text("keep")
    assert main(["fit-verifier", "--out", "mine", "world.split=unseen", "memory.embedder=hashing"]) == 2
    assert (tmp_path / "mine" / "notes.txt").read_text() == "keep"  # a folder it did not create stays


def test_a_run_folder_with_results_is_kept(tmp_path):
    from ragnav_jax.config import load_config
    from ragnav_jax.runs import discard_failed_runs, init_run

    with pytest.raises(UserError), discard_failed_runs():
        init_run(tmp_path / "a", load_config(None), "test")
        init_run(tmp_path / "b", load_config(None), "test")
        rio.write_json(tmp_path / "b" / "chunks" / "0.json", {"resume": "from here"})
        raise UserError("bad setting")
    assert not (tmp_path / "a").exists() and (tmp_path / "b" / "chunks" / "0.json").exists()


# ----------------------------------------------------------------------------------------------------
# LLM captioner replies that are not captions


def test_caption_problem():
    from ragnav_jax.memory.captioner import caption_problem

    assert caption_problem("A grey fabric sofa with a remote beside it.") is None
    assert caption_problem("A red couch.") is None
    for bad in ("Sure! Here is a description of the view: a sofa.", "Certainly. The view shows a sofa.",
                "I'm sorry, I cannot see images.", "", "- sofa\n- lamp", "What room is this?", "x" * 600,
                '{"caption": "a sofa"}'):
        assert caption_problem(bad), bad


def test_llm_captioner_replaces_chat_replies_and_refuses_an_endpoint_that_never_captions(apartment, monkeypatch):
    from test_memory_streams import synthetic_stream

    from ragnav_jax.config import load_config
    from ragnav_jax.memory import llm
    from ragnav_jax.memory.build import build_bank

    cfg = load_config(None, ["memory.embedder=hashing", "memory.hashing_dim=64", "memory.captioner=llm",
                             "llm.base_url=http://127.0.0.1:9/v1", "llm.model=fake"])
    stream = synthetic_stream(apartment)
    calls = []

    def chat(llm_cfg, messages, max_tokens=200):
        calls.append(1)
        return "Sure! Here is a description of the view:\n\nA sofa." if len(calls) % 2 else "A grey sofa by a lamp."

    monkeypatch.setattr(llm, "chat", chat)
    bank, stats = build_bank([apartment], [stream], cfg)
    captions = bank.metas[0].captions
    assert not any("Sure" in c for c in captions) and "A grey sofa by a lamp." in captions
    assert len(stats.captions_rejected) == (len(calls) + 1) // 2 and "a chat reply" in stats.captions_rejected[0]
    monkeypatch.setattr(llm, "chat", lambda *a, **k: "Sure! Here is what I see: a sofa and a lamp.")
    with pytest.raises(UserError, match="memory.captioner=llm: none of the .* replies"):
        build_bank([apartment], [stream], cfg)
