import json
import subprocess
import sys

import pytest

from ragnav_jax.cli import main
from ragnav_jax.world.scene import example_scene_path, load_scene_set


def test_generate_writes_run_folder(tmp_path, capsys):
    run = tmp_path / "run"
    assert main(["generate", "--out", str(run), "--quiet", "world.num_scenes=2", "seed=4"]) == 0
    scenes = load_scene_set(run / "scenes")
    assert [s.name for s in scenes] == ["house_000", "house_001"]
    for name in ("config.yaml", "run_info.json", "generate/summary.json", "generate/scenes_summary.csv",
                 "generate/scenes_summary.md"):
        assert (run / name).exists(), name
    assert (run / "generate" / "plots" / "house_000.png").stat().st_size > 10_000
    info = json.loads((run / "run_info.json").read_text())
    assert info["packages"]["jax"] == "0.9.2" and info["git_commit"]
    assert "num_scenes: 2" in (run / "config.yaml").read_text() and "seed: 4" in (run / "config.yaml").read_text()
    assert "house_001" in capsys.readouterr().out
    # A second generate into the same folder refuses to overwrite the user's scenes.
    assert main(["generate", "--out", str(run), "--quiet", "world.num_scenes=1"]) == 2


def test_show_scene_and_validate(tmp_path):
    out = tmp_path / "plan.png"
    assert main(["show-scene", str(example_scene_path()), "--out", str(out)]) == 0
    assert out.read_bytes()[:4] == b"\x89PNG"
    assert main(["validate", str(example_scene_path())]) == 0
    assert main(["show-scene", str(example_scene_path()), "--out", str(tmp_path / "plan.txt")]) == 2


@pytest.mark.parametrize(
    "argv",
    [
        ["generate", "world.bogus=1"],
        ["generate", "world.num_scenes=abc"],
        ["generate", "--config", "/nonexistent.yaml"],
        ["validate", "/nonexistent/scene.json"],
        ["generate", "stray"],
    ],
)
def test_user_errors_exit_2_without_traceback(argv, tmp_path):
    proc = subprocess.run(
        [sys.executable, "-m", "ragnav_jax.cli", *argv, *(["--out", str(tmp_path / "r")] if argv[0] == "generate" else [])],
        capture_output=True, text=True,
    )
    assert proc.returncode == 2, proc.stderr
    assert "Traceback" not in proc.stderr and proc.stderr.startswith("ragnav: error:")


def test_console_script_help():
    proc = subprocess.run([sys.executable, "-m", "ragnav_jax.cli", "--help"], capture_output=True, text=True)
    assert proc.returncode == 0 and "generate" in proc.stdout and "show-scene" in proc.stdout
