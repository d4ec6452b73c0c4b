"""Bad input and faults against the CLI, as one table: scenes, episodes, configs, command-line arguments,
memory banks, interrupted runs and file-system faults.

Every row: exit code 2, exactly one line on stderr that starts with 'ragnav: error:' and names the file,
field or line at fault, no traceback anywhere, and no file created, changed or removed outside the run
folder the command may write (a snapshot of the test's folder before and after). Each row runs in its own
folder (the current directory), so paths in commands and messages are relative.
"""

from __future__ import annotations

import copy
import errno
import hashlib
import json
import math
import os
import shutil
from collections.abc import Callable
from pathlib import Path
from typing import NamedTuple

import pytest

from ragnav_jax.cli import main
from ragnav_jax.world.scene import example_scene_path

APARTMENT = json.loads(example_scene_path().read_text())
EPISODE_LINES = (example_scene_path().parent / "episodes.jsonl").read_text().splitlines(keepends=True)
RUN = object()  # a file value: a copy of the prepared run (scenes/, explore/streams/, memory/bank)
FOLDER = object()  # a file value: an empty folder


def scene(edit: Callable[[dict], object] | None = None) -> bytes:
    """The apartment scene as JSON bytes after `edit` changed a copy of it in place."""
    d = copy.deepcopy(APARTMENT)
    if edit is not None:
        edit(d)
    return json.dumps(d).encode()


def episodes(edit: Callable[[list[dict]], object] | None = None) -> bytes:
    """The example episodes (JSONL bytes) after `edit` changed a copy of them in place."""
    rows = [json.loads(x) for x in EPISODE_LINES]
    if edit is not None:
        edit(rows)
    return "".join(json.dumps(r) + "\n" for r in rows).encode()


def _meta_edit(edit: Callable[[dict], object]) -> Callable[[Path], None]:
    """Damage to a bank's meta.json, its own checksum (where it has one) recomputed, so only the edited
    entry is wrong."""

    def damage(root: Path) -> None:
        path = root / "run" / "memory" / "bank" / "meta.json"
        meta = json.loads(path.read_text())
        edit(meta)
        if "meta_sha256" in meta:
            from ragnav_jax.memory.checkpoint import _meta_digest

            meta["meta_sha256"] = _meta_digest(meta)
        path.write_text(json.dumps(meta))

    return damage


def _flip_arrays(root: Path) -> None:
    for f in (root / "run" / "memory" / "bank" / "arrays").rglob("*"):
        if f.is_file() and f.parent.name == "d":  # orbax's data files
            data = bytearray(f.read_bytes())
            data[len(data) // 2] ^= 0xFF
            f.write_bytes(bytes(data))


def _disk_full(monkeypatch) -> None:
    def replace(src, dst):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(os, "replace", replace)


class Row(NamedTuple):
    name: str
    files: dict  # relative path -> bytes | str | RUN | FOLDER, created before the command
    argv: list[str]
    expect: str  # the one stderr line must contain this (the file, field or line at fault)
    writes: str | None = None  # the one folder the command may change (None: nothing at all)
    setup: Callable[[Path], None] | None = None  # more damage to the created files
    fault: Callable | None = None  # fault(monkeypatch): an injected OS fault


S = "scene.json"
E = "eps.jsonl"
C = "cfg.yaml"
RETRIEVE = ["retrieve", "--run", "run", "--episodes", E, "--out", "out", "--quiet"]

ROWS = [
    # --- scenes ---------------------------------------------------------------------------------------
    Row("scene missing field", {S: scene(lambda d: d.pop("rooms"))}, ["validate", S], "rooms"),
    Row("scene wrong type", {S: scene(lambda d: d["objects"][0].update(position="here"))}, ["validate", S],
        "$.objects[0].position"),
    Row("scene NaN", {S: scene(lambda d: d["objects"][1].update(position=[math.nan, 1.0, 0.4]))}, ["validate", S],
        "$.objects[1].position"),
    Row("scene overlapping rooms", {S: scene(lambda d: d["rooms"][1].update(min=[1.0, 1.0]))}, ["validate", S],
        "overlap"),
    Row("scene unknown room ref", {S: scene(lambda d: d["objects"][2].update(room="attic"))}, ["validate", S], "attic"),
    Row("scene duplicate ids", {S: scene(lambda d: d["objects"][1].update(id=d["objects"][0]["id"]))}, ["validate", S],
        "sofa_1"),
    Row("scene empty file", {S: b""}, ["validate", S], f"{S}: line 1"),
    Row("scene not JSON", {S: b'{"format": "ragnav-scene/1", rooms: ['}, ["validate", S], f"{S}: line 1"),
    Row("scene is a folder", {S: FOLDER}, ["validate", S], S),
    Row("scene not text", {S: b"\x89PNG\r\n\x1a\n\xff\xfe"}, ["validate", S], "not UTF-8"),
    Row("scene missing file", {}, ["validate", "nope.json"], "nope.json"),
    Row("scene zero-length wall", {S: scene(lambda d: d["walls"][0].update(b=d["walls"][0]["a"]))}, ["validate", S],
        "$.walls[0]"),
    Row("scene start outside", {S: scene(lambda d: d["start"].update(position=[50.0, 50.0]))}, ["validate", S],
        "$.start"),
    Row("scene wrong format", {S: scene(lambda d: d.update(format="ragnav-scene/9"))}, ["validate", S], "$.format"),
    Row("scene top level list", {S: b"[]"}, ["validate", S], S),
    Row("scene name with a path", {S: scene(lambda d: d.update(name="../../x"))}, ["validate", S], "$.name"),
    Row("scene too many objects", {S: scene()}, ["explore", "--scenes", S, "--out", "out", "sim.max_objects=10"],
        "sim.max_objects", writes="out"),
    Row("scene exceeds memory", {S: scene()}, ["explore", "--scenes", S, "--out", "out", "explore.max_steps=10000000000"],
        "explore.max_steps", writes="out"),
    # --- episodes -------------------------------------------------------------------------------------
    Row("episodes bad JSON line", {E: b"".join([episodes().splitlines(keepends=True)[0], b"{oops\n"])},
        ["check-parse", E], f"{E}: line 2"),
    Row("episodes missing field", {E: episodes(lambda r: r[2].pop("instruction"))}, ["check-parse", E],
        f"{E}: line 3"),
    Row("episodes empty file", {E: b""}, ["check-parse", E], E),
    Row("episodes not text", {E: b"\xff\xfe\x00{"}, ["check-parse", E], E),
    Row("episodes missing truth", {E: episodes()}, ["check-parse", E], "eps.chains.jsonl"),
    Row("episodes unknown scene", {"run": RUN, E: episodes(lambda r: r[0].update(scene="castle"))}, RETRIEVE,
        "castle", writes="out"),
    Row("episodes unknown goal", {"run": RUN, E: episodes(lambda r: r[1]["goals"][0].update(object_id="unicorn_9"))},
        RETRIEVE, "unicorn_9", writes="out"),
    # --- configs --------------------------------------------------------------------------------------
    Row("config unknown key", {C: "world:\n  bogus: 1\n"}, ["generate", "--config", C, "--out", "out"], "world.bogus",
        writes="out"),
    Row("config wrong type", {C: "world:\n  num_scenes: many\n"}, ["generate", "--config", C, "--out", "out"],
        "world.num_scenes", writes="out"),
    Row("config out of range", {C: "sim:\n  timestep: 1.0\n"}, ["validate", "--config", C, "x.json"], "sim.timestep"),
    Row("config not text", {C: b"\x00\xff\xfe\x89binary"}, ["validate", "--config", C, "x.json"], C),
    Row("config missing file", {}, ["validate", "--config", "nope.yaml", "x.json"], "nope.yaml"),
    Row("config not a mapping", {C: "- 1\n- 2\n"}, ["validate", "--config", C, "x.json"], C),
    Row("config not YAML", {C: "world: [1\n"}, ["validate", "--config", C, "x.json"], f"{C}: line"),
    Row("config is a folder", {C: FOLDER}, ["validate", "--config", C, "x.json"], C),
    Row("override unknown key", {}, ["generate", "--out", "out", "world.bogus=1"], "world.bogus", writes="out"),
    Row("override wrong type", {}, ["generate", "--out", "out", "world.num_scenes=abc"], "world.num_scenes",
        writes="out"),
    Row("override out of range", {}, ["generate", "--out", "out", "world.max_rooms=99"], "world.max_rooms",
        writes="out"),
    Row("override on validate", {S: scene()}, ["validate", S, "sim.robot_radius=-1"], "sim.robot_radius"),
    Row("override on check-parse", {E: episodes()}, ["check-parse", E, "llm.timeout_s=0"], "llm.timeout_s"),
    Row("bad setting after the run folder", {}, ["fit-verifier", "--out", "out", "world.split=unseen",
                                                 "memory.embedder=hashing"], "world.split", writes="out"),
    # --- command-line arguments -----------------------------------------------------------------------
    Row("bad method", {}, ["retrieve", "--run", "r", "--episodes", E, "--out", "o", "--method", "bogus"], "--method"),
    Row("negative --limit", {}, ["eval", "--scenes", "r", "--episodes", E, "--out", "o", "--limit", "-1"], "--limit"),
    Row("zero --stride", {}, ["eval", "--scenes", "r", "--episodes", E, "--out", "o", "--stride", "0"], "--stride"),
    Row("missing required", {}, ["retrieve", "--episodes", E, "--out", "o"], "--run"),
    Row("stray argument", {}, ["generate", "--out", "out", "stray"], "stray", writes="out"),
    Row("unknown option", {}, ["generate", "--bogus"], "--bogus"),
    Row("two episodes files", {E: episodes()}, ["check-parse", E, E], E),
    Row("picture name", {}, ["show-scene", str(example_scene_path()), "--out", "plan.txt"], "plan.txt"),
    Row("--out is a file (generate)", {"out": b"mine"}, ["generate", "--out", "out"], "out: File exists"),
    Row("--out is a file (retrieve)", {"run": RUN, E: episodes(), "out": b"mine"}, RETRIEVE, "out: File exists"),
    Row("--out under a file", {"out": b"mine"}, ["generate", "--out", "out/run"], "out/run"),
    # --- memory banks ---------------------------------------------------------------------------------
    Row("missing bank", {"run": RUN, E: episodes()}, RETRIEVE, "no meta.json", writes="out",
        setup=lambda root: shutil.rmtree(root / "run" / "memory")),
    Row("corrupted array sum", {"run": RUN, E: episodes()}, RETRIEVE, "field 'adjacency' is corrupted", writes="out",
        setup=_meta_edit(lambda m: m["fields"]["adjacency"].update(sha256="0" * 64))),
    Row("edited bank metadata", {"run": RUN, E: episodes()}, RETRIEVE, "meta.json", writes="out",
        setup=lambda root: (root / "run/memory/bank/meta.json").write_text(
            (root / "run/memory/bank/meta.json").read_text().replace('"num_nodes": ', '"num_nodes": 1'))),
    Row("corrupted bank arrays", {"run": RUN, E: episodes()}, RETRIEVE, "run/memory/bank", writes="out",
        setup=_flip_arrays),
    Row("bank of another scene", {"run": RUN, E: episodes()}, RETRIEVE, "fingerprint", writes="out",
        setup=lambda root: (root / "run/scenes/apartment.json").write_bytes(
            scene(lambda d: d["objects"].reverse()))),
    # --- interrupted runs -----------------------------------------------------------------------------
    Row("stream cut short by a kill", {"run": RUN}, ["build-memory", "--run", "run", "--force", "--quiet"],
        "apartment.npz", writes="run/memory",
        setup=lambda root: (root / "run/explore/streams/apartment.npz").write_bytes(
            (root / "run/explore/streams/apartment.npz").read_bytes()[:200])),
    Row("bank killed before its metadata", {"run": RUN, E: episodes()}, RETRIEVE, "no meta.json", writes="out",
        setup=lambda root: (root / "run/memory/bank/meta.json").unlink()),
    Row("scene cut short by a kill", {"run": RUN}, ["explore", "--out", "run", "--force"], "apartment.json",
        writes="run/explore",
        setup=lambda root: (root / "run/scenes/apartment.json").write_bytes(scene()[:300])),
    Row("scene copy differs", {"run": RUN, S: scene(lambda d: d.update(name="apartment", objects=d["objects"][:5]))},
        ["explore", "--scenes", S, "--out", "run", "--force"], "differs", writes="run/explore",
        setup=lambda root: (root / "run/scenes/scene.json").write_bytes(scene())),
    # --- file-system faults ---------------------------------------------------------------------------
    Row("disk full", {}, ["generate", "--out", "out", "world.num_scenes=1"], "No space left on device", writes="out",
        fault=_disk_full),
]


@pytest.fixture(scope="module")
def prepared_run(tmp_path_factory, apartment):
    """A run folder of the apartment: scenes/, explore/streams/ (synthetic, no simulator), memory/bank."""
    from test_memory_streams import synthetic_stream

    from ragnav_jax.config import load_config
    from ragnav_jax.memory.build import build_bank
    from ragnav_jax.memory.checkpoint import save_bank
    from ragnav_jax.world.scene import save_scene

    run = tmp_path_factory.mktemp("prepared") / "run"
    stream = synthetic_stream(apartment)
    save_scene(apartment, run / "scenes" / "apartment.json")
    stream.save(run / "explore" / "streams" / "apartment.npz")
    bank, _ = build_bank([apartment], [stream], load_config(None, ["memory.embedder=hashing"]))
    save_bank(bank, run / "memory" / "bank")
    return run


def snapshot(root: Path) -> dict[str, str]:
    """Relative path -> content hash ('dir' for folders) of everything under `root`."""
    return {str(p.relative_to(root)): "dir" if p.is_dir() else hashlib.sha256(p.read_bytes()).hexdigest()
            for p in root.rglob("*")}


def run_cli(argv: list[str]) -> int:
    try:
        return main(argv)
    except SystemExit as e:  # argparse's usage errors
        return e.code


def test_the_table_is_large_enough():
    assert len(ROWS) >= 40 and len({r.name for r in ROWS}) == len(ROWS)


@pytest.mark.filterwarnings("ignore::pytest.PytestUnraisableExceptionWarning")  # orbax's event loop on a damaged bank
@pytest.mark.parametrize("row", ROWS, ids=[r.name for r in ROWS])
def test_bad_input(row: Row, tmp_path, monkeypatch, capsys, request):
    monkeypatch.chdir(tmp_path)
    for rel, content in row.files.items():
        path = tmp_path / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        if content is RUN:
            shutil.copytree(request.getfixturevalue("prepared_run"), path)
        elif content is FOLDER:
            path.mkdir()
        else:
            path.write_bytes(content.encode() if isinstance(content, str) else content)
    if row.setup is not None:
        row.setup(tmp_path)
    if row.fault is not None:
        row.fault(monkeypatch)
    before = snapshot(tmp_path)
    code = run_cli(row.argv)
    out, err = capsys.readouterr()
    assert code == 2, (out, err)
    assert "Traceback" not in out + err, err
    lines = [x for x in err.splitlines() if x.strip()]
    assert len(lines) == 1 and lines[0].startswith("ragnav: error:"), err
    assert row.expect in lines[0], lines[0]
    monkeypatch.undo()  # the fault off again before the snapshot reads files
    after = snapshot(tmp_path)
    allowed = (row.writes + os.sep) if row.writes else None
    changed = {k for k in before.keys() | after.keys() if before.get(k) != after.get(k)}
    outside = {k for k in changed if not (allowed and (k + os.sep).startswith(allowed))}
    assert not outside, outside
