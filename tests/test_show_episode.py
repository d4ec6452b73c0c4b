"""show-episode: an episode of an eval run, replayed with the recorder on, reproduces the row the eval
wrote (success, declarations, steps, distance); its video is a playable GIF / MP4 (read back: frame
count and image size); bad input exits 2 with one line."""

import numpy as np
import pytest
import sweep_fixtures
from PIL import Image

from ragnav_jax.cli import main
from ragnav_jax.evaluation.execute import make_executor
from ragnav_jax.evaluation.replay import load_eval_run, outcome_differences, replay_episode
from ragnav_jax.evaluation.video import frame_plan, save_episode_video

tiny_run = sweep_fixtures.tiny_run  # the session fixture


@pytest.fixture(scope="module")
def eval_run(tiny_run, tmp_path_factory):
    """An eval run folder of three episodes (every fifth: --stride and --limit as users pass them)."""
    run, episodes, *_ = tiny_run
    out = tmp_path_factory.mktemp("show") / "ev"
    argv = ["eval", "--scenes", str(run), "--episodes", str(episodes), "--method", "ragnav", "--out", str(out),
            "--stride", "5", "--limit", "3", "--quiet", "memory.embedder=hashing"]
    assert main(argv) == 0
    return out


@pytest.fixture(scope="module")
def replayed(eval_run):
    """(EvalRun, executor, {episode id: replayed row}): every episode replayed on one executor."""
    ev = load_eval_run(eval_run, "ragnav")
    ex = make_executor([s for s in ev.scenes if s.name in {e.scene for e in ev.episodes}], ev.cfg)
    return ev, ex, {i: replay_episode(ev, i, ex) for i in ev.rows}


def test_replay_reproduces_the_recorded_rows(replayed):
    ev, ex, rows = replayed
    assert len(ev.rows) == 3 and [e.id for e in ev.episodes] == list(ev.rows)
    assert ex.traces["run_traced"] == 1  # the recording runner compiles once across replays
    for i, rec in ev.rows.items():
        row = rows[i]
        assert outcome_differences(rec, row) == []
        assert (row["success"], row["declarations"], row["steps"]) == (rec["success"], rec["declarations"], rec["steps"])
        assert "legs" not in rec and "trace" not in rec  # the eval itself recorded nothing
        legs = row["legs"]
        assert all(len(leg["poses"]) == leg["steps"] for leg in legs)
        for leg in legs:  # the per-step poses end where the leg's simulation ended
            if leg["poses"]:
                assert np.allclose(leg["poses"][-1][:2], leg["end"], atol=2e-3)
        scene = next(s for s in ev.scenes if s.name == row["scene"])
        path = np.concatenate([[scene.start.position[:2]], *[np.asarray(leg["poses"])[:, :2] for leg in legs if leg["poses"]]])
        assert np.linalg.norm(np.diff(path, axis=0), axis=1).sum() == pytest.approx(row["travel_distance_m"], rel=0.02)
        trace = row["trace"]
        assert len(trace["rejections"]) == row["rejected_candidates"]
        assert len(trace["candidates"]) == len(row["subgoal_status"])  # one list per goal read
        assert all(isinstance(c["score"], float) for cs in trace["candidates"] for c in cs)
        assert all(-1 <= r["leg"] < len(legs) for r in trace["rejections"])


@pytest.mark.parametrize("steps", [[0], [1], [5, 0, 40], [300, 2, 1, 77]])
@pytest.mark.parametrize("max_frames", [2, 12, 200])
def test_frame_plan_stays_within_budget_and_ends_every_leg(steps, max_frames):
    legs = [{"poses": [[0.0, 0.0, 0.0]] * n} for n in steps]
    plan = frame_plan(legs, max_frames)
    assert len(plan) <= max(max_frames, len(legs))
    assert [k for k, i in plan] == sorted(k for k, i in plan)
    assert {k for k, i in plan if i == -1} == set(range(len(legs)))  # every leg's end is shown
    assert all(-1 > i >= -4 or 0 <= i < steps[k] - 1 or i == -1 for k, i in plan)


def test_gif_and_mp4_read_back(replayed, tmp_path):
    ev, _, rows = replayed
    row = max(rows.values(), key=lambda r: len(r["legs"]))
    ep = next(e for e in ev.episodes if e.id == row["episode"])
    scene = next(s for s in ev.scenes if s.name == ep.scene)
    gif = tmp_path / "ep.gif"
    n = save_episode_video(scene, row, gif, fps=5, max_frames=16, dpi=40, instruction=ep.instruction)
    assert 2 <= n <= max(16, len(row["legs"]))
    with Image.open(gif) as im:
        w, h = im.size
        assert w % 2 == 0 and h % 2 == 0 and 150 <= w <= 600 and 150 <= h <= 300  # even (yuv420p), ~5.4 in x 40 dpi
        durations = []
        for f in range(im.n_frames):  # Pillow merges identical frames, adding up their durations
            im.seek(f)
            durations.append(im.info["duration"])
    assert sum(durations) == pytest.approx(n * 200, abs=10 * len(durations))
    imageio_ffmpeg = pytest.importorskip("imageio_ffmpeg")
    mp4 = tmp_path / "ep.mp4"
    assert save_episode_video(scene, row, mp4, fps=5, max_frames=16, dpi=40) == n
    frames, _secs = imageio_ffmpeg.count_frames_and_secs(str(mp4))
    meta = next(imageio_ffmpeg.read_frames(str(mp4)))
    assert frames == n and tuple(meta["size"]) == (w, h)


def test_show_episode_cli_writes_a_gif(eval_run, tmp_path, capsys):
    eid = next(iter(load_eval_run(eval_run, "ragnav").rows))
    out = tmp_path / "ep.gif"
    assert main(["show-episode", str(eval_run), "--episode", eid, "--out", str(out), "--max-frames", "12"]) == 0
    assert "replay matches the run" in capsys.readouterr().out
    with Image.open(out) as im:
        assert im.format == "GIF" and im.n_frames >= 2
    assert main(["show-episode", str(eval_run), "--episode", eid, "--out", str(out)]) == 2  # exists, no --force


@pytest.mark.parametrize("case", ["no_run", "method", "episode", "suffix", "exists"])
def test_show_episode_bad_input_exits_2_with_one_line(case, eval_run, tmp_path, capsys):
    out = tmp_path / "ep.gif"
    if case == "exists":
        out.write_bytes(b"GIF89a")
    args = {"no_run": [str(tmp_path / "nowhere"), "--episode", "x", "--out", str(out)],
            "method": [str(eval_run), "--method", "nope", "--episode", "x", "--out", str(out)],
            "episode": [str(eval_run), "--episode", "nope", "--out", str(out)],
            "suffix": [str(eval_run), "--episode", "x", "--out", str(tmp_path / "ep.avi")],
            "exists": [str(eval_run), "--episode", "x", "--out", str(out)]}[case]
    capsys.readouterr()
    assert main(["show-episode", *args]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("ragnav: error:") and "\n" not in err, err
