"""Reliability of runs (issue 20): no silently wrong results, no writes outside the run folder, no lost results.

One table-driven test per class of fault. Each bad case exits 2 with one line naming the file, field or flag,
prints no traceback, and changes no file (the whole tmp folder is compared before and after); the cases that
must go through (--allow-unparsed, --force, a bank from before fingerprints) are checked to do so.
"""

from __future__ import annotations

import hashlib
import json
import shutil

import orbax.checkpoint as ocp
import pytest
import sweep_fixtures

from ragnav_jax.cli import main
from ragnav_jax.errors import UserError
from ragnav_jax.memory.checkpoint import bank_exists, load_bank, save_bank
from ragnav_jax.memory.commands import bank_dir
from ragnav_jax.runs import run_file
from ragnav_jax.world.scene import example_scene_path, load_scene, load_scene_set, scene_to_dict

tiny_run = sweep_fixtures.tiny_run  # the session fixture: apartment, its hashing-embedder bank, episodes
HASHING = "memory.embedder=hashing"


def snapshot(root) -> dict[str, str]:
    """Relative path -> SHA-256 of every file under `root`."""
    return {str(p.relative_to(root)): hashlib.sha256(p.read_bytes()).hexdigest() for p in root.rglob("*") if p.is_file()}


def ragnav(argv: list[str], capsys) -> tuple[int, str, str]:
    """(exit code, stdout, stderr) of `ragnav ARGV` in process; never a traceback."""
    try:
        rc = main(argv)
    except SystemExit as e:  # argparse's own usage errors
        rc = e.code
    out, err = capsys.readouterr()
    assert "Traceback" not in out + err
    return rc, out, err


def assert_refused(argv: list[str], capsys, tmp_path, *names: str) -> str:
    """`ragnav ARGV` exits 2 with one error line naming each of `names`, and changes no file under tmp_path."""
    before = snapshot(tmp_path)
    rc, _, err = ragnav(argv, capsys)
    errors = [line for line in err.splitlines() if line.startswith("ragnav: error:")]
    assert rc == 2 and len(errors) == 1, err
    for name in names:
        assert name in errors[0], (name, errors[0])
    assert snapshot(tmp_path) == before
    return errors[0]


@pytest.fixture
def run(tiny_run, tmp_path):
    """A copy of the tiny run folder (scenes/apartment.json, memory/bank, episodes/episodes.jsonl)."""
    dest = tmp_path / "run"
    shutil.copytree(tiny_run[0], dest)
    return dest


def episodes_of(run) -> str:
    return str(run / "episodes" / "episodes.jsonl")


# ----------------------------------------------------------------------------------------------------
# Silently wrong results


def _objects_reversed(scene: dict) -> None:
    scene["objects"].reverse()


def _category_changed(scene: dict) -> None:
    scene["objects"][0]["category"] = "piano"


@pytest.mark.parametrize("edit", [_objects_reversed, _category_changed])
@pytest.mark.parametrize("command", ["retrieve", "eval", "plan", "show-memory", "sweep", "tune"])
def test_a_bank_of_another_scene_is_refused_by_every_consumer(run, tmp_path, capsys, command, edit):
    """The bank was built from the apartment; the run's scene file now holds another apartment."""
    data = scene_to_dict(load_scene(run / "scenes" / "apartment.json"))
    edit(data)
    (run / "scenes" / "apartment.json").write_text(json.dumps(data))
    out = str(tmp_path / "out")
    argv = {
        "retrieve": ["retrieve", "--run", str(run), "--episodes", episodes_of(run), "--out", out],
        "eval": ["eval", "--scenes", str(run), "--episodes", episodes_of(run), "--method", "ragnav", "--out", out],
        "plan": ["plan", "--run", str(run), "--scene", "apartment", "go to the sofa"],
        "show-memory": ["show-memory", str(run), "--scene", "apartment", "--out", str(tmp_path / "m.png")],
        "sweep": ["sweep", "--run", str(run), "--episodes", episodes_of(run), "--out", out],
        "tune": ["tune", "--run", str(run), "--episodes", episodes_of(run), "--out", out],
    }[command]
    overrides = [] if command in ("plan", "show-memory") else [HASHING]  # they read no episodes: the bank's embedder
    assert_refused([*argv, "--quiet", *overrides], capsys, tmp_path, "'apartment'", str(bank_dir(run).resolve()),
                   "fingerprint")


def test_an_eval_memory_bank_of_other_scenes_is_refused(run, tmp_path, capsys):
    scenes = tmp_path / "scenes"
    data = scene_to_dict(load_scene(example_scene_path()))
    _objects_reversed(data)
    scenes.mkdir()
    (scenes / "apartment.json").write_text(json.dumps(data))
    assert_refused(["eval", "--scenes", str(scenes), "--memory", str(bank_dir(run)), "--episodes", episodes_of(run),
                    "--method", "ragnav", "--out", str(tmp_path / "out"), "--quiet", HASHING],
                   capsys, tmp_path, "'apartment'", str(bank_dir(run).resolve()))


def test_a_bank_written_before_fingerprints_loads_with_one_warning(run, capsys):
    meta_path = bank_dir(run) / "meta.json"
    meta = json.loads(meta_path.read_text())
    del meta["meta_sha256"]
    for m in meta["scenes"]:
        del m["fingerprint"]
    meta_path.write_text(json.dumps(meta))
    bank = load_bank(bank_dir(run), load_scene_set(run / "scenes"))
    assert bank.names == ("apartment",)
    warnings = capsys.readouterr().err.strip().splitlines()
    assert len(warnings) == 1 and warnings[0].startswith("ragnav: warning:") and str(bank_dir(run).resolve()) in warnings[0]


@pytest.mark.parametrize("field", ["captions", "object_ids", "num_nodes"])
def test_an_edited_bank_meta_is_refused(run, tmp_path, capsys, field):
    meta_path = bank_dir(run) / "meta.json"
    meta = json.loads(meta_path.read_text())
    scene = meta["scenes"][0]
    if field == "num_nodes":
        scene["num_nodes"] -= 1
    else:
        scene[field][0], scene[field][1] = scene[field][1], scene[field][0]
    meta_path.write_text(json.dumps(meta, indent=1))
    assert_refused(["retrieve", "--run", str(run), "--episodes", episodes_of(run), "--out", str(tmp_path / "out"),
                    "--quiet", HASHING], capsys, tmp_path, str(meta_path.resolve()))


def _with_unreadable_instructions(run, tmp_path):
    """The run's episodes (the first 6) and two whose instruction the parser rejects: empty, and too long."""
    lines = (run / "episodes" / "episodes.jsonl").read_text().splitlines()[:6]
    first = json.loads(lines[0])
    for eid, text in (("bad-empty", ""), ("bad-long", "go to the sofa " * 700)):
        lines.append(json.dumps({**first, "id": eid, "instruction": text}))
    path = tmp_path / "eps.jsonl"
    path.write_text("\n".join(lines) + "\n")
    return str(path)


@pytest.mark.parametrize("command", ["retrieve", "eval", "sweep", "tune"])
def test_unreadable_instructions_are_refused_without_the_flag(run, tmp_path, capsys, command):
    eps = _with_unreadable_instructions(run, tmp_path)
    argv = {"retrieve": ["retrieve", "--run", str(run)], "eval": ["eval", "--scenes", str(run), "--method", "ragnav"],
            "sweep": ["sweep", "--run", str(run)], "tune": ["tune", "--run", str(run)]}[command]
    line = assert_refused([*argv, "--episodes", eps, "--out", str(tmp_path / "out"), "--quiet", HASHING],
                          capsys, tmp_path, "--allow-unparsed", "bad-empty", "bad-long", eps)
    assert "2 of 8 episodes" in line


def test_unreadable_instructions_are_named_and_counted_with_the_flag(run, tmp_path, capsys):
    """--allow-unparsed scores them as misses, names them on stderr and counts them in summary.json; --force
    lets the run replace an earlier one in the same --out."""
    eps = _with_unreadable_instructions(run, tmp_path)
    out = tmp_path / "out"
    out.mkdir()
    (out / "summary.json").write_text("{}\n")
    rc, _, err = ragnav(["retrieve", "--run", str(run), "--episodes", eps, "--out", str(out), "--method", "naive_rag",
                         "--quiet", HASHING, "--allow-unparsed", "--force"], capsys)
    assert rc == 0, err
    warnings = [line for line in err.splitlines() if line.startswith("ragnav: warning:")]
    assert len(warnings) == 1 and "bad-empty, bad-long" in warnings[0]
    summary = json.loads((out / "summary.json").read_text())
    assert summary["unparsed"] == {"count": 2, "episodes": ["bad-empty", "bad-long"]}
    assert summary["parse_failures"] >= 2


NUMERIC = [  # (argv without the run-specific paths, the option the error must name)
    (["eval", "--scenes", "S", "--episodes", "E", "--out", "O", "--stride", "0"], "--stride"),
    (["eval", "--scenes", "S", "--episodes", "E", "--out", "O", "--stride", "-2"], "--stride"),
    (["eval", "--scenes", "S", "--episodes", "E", "--out", "O", "--limit", "-1"], "--limit"),
    (["eval", "--scenes", "S", "--episodes", "E", "--out", "O", "--limit", "x"], "--limit"),
    (["fit-verifier", "--out", "O", "--scenes", "0"], "--scenes"),
    (["fit-verifier", "--out", "O", "--seed", "-1"], "--seed"),
    (["check-parse", "E", "--show", "-1"], "--show"),
    (["check-parse", "E", "--min-rate", "1.5"], "--min-rate"),
    (["bench", "--out", "O", "--scale", "0"], "--scale"),
    (["bench", "--out", "O", "--scale", "nan"], "--scale"),
    (["show-episode", "S", "--episode", "x", "--out", "O.gif", "--fps", "0"], "--fps"),
    (["show-episode", "S", "--episode", "x", "--out", "O.gif", "--max-frames", "1"], "--max-frames"),
    (["show-memory", "S", "--scene", "apartment", "--out", "O.png", "--level", "99"], "--level"),
]


@pytest.mark.parametrize(("argv", "option"), NUMERIC, ids=[f"{a[0]}{o}={a[-1]}" for a, o in NUMERIC])
def test_numeric_options_are_range_checked(run, tmp_path, capsys, argv, option):
    paths = {"S": str(run), "E": episodes_of(run), "O": str(tmp_path / "o"), "O.gif": str(tmp_path / "o.gif"),
             "O.png": str(tmp_path / "o.png")}
    assert_refused([paths.get(a, a) for a in argv], capsys, tmp_path, option)


# ----------------------------------------------------------------------------------------------------
# Writes outside the run folder, and lost results


def _scene_named(tmp_path, name: str) -> str:
    data = scene_to_dict(load_scene(example_scene_path()))
    data["name"] = name
    path = tmp_path / "in" / "bad.json"
    path.parent.mkdir(exist_ok=True)
    path.write_text(json.dumps(data))
    return str(path)


def _episode_with_id(tmp_path, run, eid: str) -> str:
    first = json.loads((run / "episodes" / "episodes.jsonl").read_text().splitlines()[0])
    path = tmp_path / "in" / "eps.jsonl"
    path.parent.mkdir(exist_ok=True)
    path.write_text(json.dumps({**first, "id": eid}) + "\n")
    return str(path)


UNSAFE = {"parent": "../../x", "separator": "a/b", "dotdot": "..", "backslash": "a\\b", "escape": "red\x1b[31m"}
NAMES = [pytest.param(source, name, id=f"{source}-{case}") for source in ("world.name_prefix", "scene name", "episode id")
         for case, name in UNSAFE.items() if (source, case) != ("world.name_prefix", "dotdot")]  # '.._000' is a name


@pytest.mark.parametrize(("source", "name"), NAMES)
def test_names_that_become_file_names_are_checked_where_they_are_read(run, tmp_path, capsys, source, name):
    out = tmp_path / "a" / "b" / "c" / "out"  # deep enough that ../../ would still land under tmp_path
    if source == "world.name_prefix":
        argv, names = ["generate", "--out", str(out), "--no-plots", f"world.name_prefix={name}"], ["world.name_prefix"]
    elif source == "scene name":
        f = _scene_named(tmp_path, name)
        argv, names = ["explore", "--scenes", f, "--out", str(out), "--no-plots"], [f, "$.name"]
    else:
        f = _episode_with_id(tmp_path, run, name)
        argv, names = ["retrieve", "--run", str(run), "--episodes", f, "--out", str(out), HASHING], [f, "$.id"]
    line = assert_refused([*argv, "--quiet"], capsys, tmp_path, *names)
    assert "\x1b" not in line  # the name is quoted, never echoed raw


def test_run_files_stay_in_their_run_folder(tmp_path):
    assert run_file(tmp_path, "scenes", "a.json") == tmp_path / "scenes" / "a.json"
    for parts in (("scenes", "../../x.json"), ("..", "x.json"), ("scenes", "a/b.json"), ("scenes", "")):
        with pytest.raises(UserError, match="output name"):
            run_file(tmp_path, *parts)


def _existing(path, text: str = "earlier results\n"):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return str(path)


OVERWRITES = ["retrieve", "eval-method", "eval-table", "episodes-chains", "episodes-summary", "plan-json",
              "plan-out", "show-scene", "tune", "fit-verifier"]


@pytest.mark.parametrize("case", OVERWRITES)
def test_earlier_results_are_not_overwritten_without_force(run, tmp_path, capsys, case):
    out = tmp_path / "out"
    eps = episodes_of(run)
    if case == "retrieve":
        kept = _existing(out / "summary.json")
        argv = ["retrieve", "--run", str(run), "--episodes", eps, "--out", str(out), HASHING]
    elif case.startswith("eval"):
        kept = _existing(out / "eval" / ("ragnav/summary.json" if case == "eval-method" else "table.md"))
        argv = ["eval", "--scenes", str(run), "--episodes", eps, "--method", "oracle" if case == "eval-table" else "ragnav",
                "--out", str(out), HASHING]
    elif case.startswith("episodes"):
        kept = _existing(out / ("e.chains.jsonl" if case == "episodes-chains" else "e_summary.md"))
        argv = ["episodes", "--scenes", str(example_scene_path()), "--out", str(out / "e.jsonl")]
    elif case.startswith("plan"):
        kept = _existing(tmp_path / ("mine.json" if case == "plan-json" else "mine.png"))
        argv = ["plan", "--run", str(run), "--scene", "apartment", "go to the sofa",
                "--json" if case == "plan-json" else "--out", kept]
    elif case == "show-scene":
        kept = _existing(tmp_path / "mine.png")
        argv = ["show-scene", str(example_scene_path()), "--out", kept]
    elif case == "tune":
        kept = _existing(out / "tuned.yaml")
        argv = ["tune", "--run", str(run), "--episodes", eps, "--out", str(out), HASHING]
    else:
        kept = _existing(out / "fitted.json")
        argv = ["fit-verifier", "--out", str(out), HASHING]
    assert_refused([*argv, "--quiet"], capsys, tmp_path, "--force", kept)


@pytest.mark.parametrize("earlier", [False, True], ids=["first-build", "rebuild"])
def test_an_interrupted_bank_write_leaves_the_earlier_bank_or_none(run, tiny_run, tmp_path, monkeypatch, capsys,
                                                                   earlier):
    """A kill during the checkpoint write (here: right after the arrays, before meta.json): the bank folder holds
    the complete earlier bank or nothing, and build-memory and retrieve agree on which."""
    bank = tiny_run[3]
    if not earlier:
        shutil.rmtree(bank_dir(run))
    scenes = load_scene_set(run / "scenes")
    save = ocp.StandardCheckpointer.save

    def save_then_killed(self, *args, **kw):
        save(self, *args, **kw)
        self.wait_until_finished()
        raise KeyboardInterrupt

    monkeypatch.setattr(ocp.StandardCheckpointer, "save", save_then_killed)
    with pytest.raises(KeyboardInterrupt):
        save_bank(bank, bank_dir(run))
    monkeypatch.undo()
    assert sorted(p.name for p in (run / "memory").iterdir()) == (["bank"] if earlier else [])  # no half bank
    assert bank_exists(bank_dir(run)) == earlier
    if earlier:
        assert load_bank(bank_dir(run), scenes).metas == bank.metas
        assert_refused(["build-memory", "--run", str(run), "--quiet"], capsys, tmp_path, "--force")
    else:  # build-memory goes on to build it (here it stops at the missing streams); retrieve finds no bank
        assert_refused(["build-memory", "--run", str(run), "--quiet"], capsys, tmp_path, "no exploration stream")
        assert_refused(["retrieve", "--run", str(run), "--episodes", episodes_of(run), "--out", str(tmp_path / "o"),
                        "--quiet"], capsys, tmp_path, "not a memory bank")
    save_bank(bank, bank_dir(run))  # and a later write completes
    assert load_bank(bank_dir(run), scenes).metas == bank.metas

