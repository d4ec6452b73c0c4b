"""Saving and restoring a MemoryBank with orbax-checkpoint.

Layout of a bank folder:
  arrays/      orbax StandardCheckpointer of the DualBasisMemory fields (leading scene axis)
  meta.json    format name and version, field shapes/dtypes, a SHA-256 per field, the per-scene MemoryMeta
               (with each scene's fingerprint), and `meta_sha256`: a SHA-256 of the rest of meta.json
A missing, truncated or corrupted file, an edited meta.json, another format version, arrays that disagree
with meta.json, or scenes other than those the memory was built from (`load_bank(path, scenes)`) raise
UserError naming the folder: never a silently wrong memory. The folder is written under a temporary name
and renamed into place, so a bank exists completely or not at all (`bank_exists`).
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import os
import shutil
import sys
from collections.abc import Iterable
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.errors import UserError
from ragnav_jax.memory.types import (
    FORMAT_VERSION,
    DualBasisMemory,
    MemoryBank,
    MemoryMeta,
    memory_to_numpy,
    scene_fingerprint,
)

FORMAT = "ragnav-memory-bank"


def _digest(a: np.ndarray) -> str:
    h = hashlib.sha256()
    h.update(f"{a.dtype.str}{a.shape}".encode())
    h.update(np.ascontiguousarray(a).tobytes())
    return h.hexdigest()


def _meta_digest(meta: dict) -> str:
    """SHA-256 of meta.json's content without its own `meta_sha256` entry (canonical JSON)."""
    body = {k: v for k, v in meta.items() if k != "meta_sha256"}
    return hashlib.sha256(json.dumps(body, sort_keys=True, separators=(",", ":")).encode()).hexdigest()


def bank_exists(path: str | Path) -> bool:
    """Whether folder `path` holds a bank (every command asks this, so they agree after an interrupted build)."""
    return (Path(path) / "meta.json").is_file()


def save_bank(bank: MemoryBank, path: str | Path) -> Path:
    """Writes the bank to folder `path` (replaced if it exists): into a hidden sibling first, renamed into
    place once complete, so an interrupted write leaves the earlier bank or none."""
    import orbax.checkpoint as ocp

    path = Path(path).resolve()
    path.parent.mkdir(parents=True, exist_ok=True)
    for stale in [*path.parent.glob(f".{path.name}.partial-*"), *path.parent.glob(f".{path.name}.old-*")]:
        shutil.rmtree(stale, ignore_errors=True)  # left by a killed build
    tmp = path.with_name(f".{path.name}.partial-{os.getpid()}")
    try:
        tmp.mkdir()
        arrays = memory_to_numpy(bank.memory)
        ck = ocp.StandardCheckpointer()
        ck.save(tmp / "arrays", arrays)
        ck.wait_until_finished()
        meta = {
            "format": FORMAT,
            "version": FORMAT_VERSION,
            "fields": {k: {"shape": list(v.shape), "dtype": v.dtype.str, "sha256": _digest(v)} for k, v in arrays.items()},
            "scenes": [m.to_json() for m in bank.metas],
        }
        meta["meta_sha256"] = _meta_digest(meta)
        (tmp / "meta.json").write_text(json.dumps(meta, indent=1) + "\n")
        old = path.with_name(f".{path.name}.old-{os.getpid()}")
        if path.exists():
            os.replace(path, old)
        os.replace(tmp, path)
        shutil.rmtree(old, ignore_errors=True)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return path


def check_bank_scenes(bank: MemoryBank, scenes: Iterable, path: str | Path) -> None:
    """Raises UserError naming the scene and the bank folder when a scene of `scenes` that the bank holds a
    memory for is not the scene that memory was built from (their fingerprints differ)."""
    for scene in scenes:
        if scene.name not in bank.names:
            continue  # a scene without memory: its consumers say so when they need it
        meta = bank.metas[bank.index(scene.name)]
        if meta.fingerprint and meta.fingerprint != scene_fingerprint(scene, meta.config):
            raise UserError(f"{path}: the memory of scene '{scene.name}' was built from another scene of that name "
                            "(fingerprint mismatch); use the bank built from these scenes or rebuild it "
                            "(`ragnav build-memory --force`)")


def load_bank(path: str | Path, scenes: Iterable | None = None) -> MemoryBank:
    """Restores a bank written by `save_bank`; raises UserError on any inconsistency, and with `scenes`
    (the scenes it will be used with) when one of them is not the scene its memory was built from.

    Banks written before fingerprints and the meta.json checksum load with a one-line warning on stderr."""
    import orbax.checkpoint as ocp

    path = Path(path).resolve()
    meta_path = path / "meta.json"
    try:
        meta = json.loads(meta_path.read_text())
    except FileNotFoundError:
        raise UserError(f"{path}: not a memory bank (no meta.json); run `ragnav build-memory` first") from None
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as e:
        raise UserError(f"{meta_path}: unreadable or truncated memory metadata ({e.__class__.__name__})") from None
    if not isinstance(meta, dict) or meta.get("format") != FORMAT:
        raise UserError(f"{meta_path}: not a {FORMAT} file")
    if meta.get("version") != FORMAT_VERSION:
        raise UserError(
            f"{path}: memory format version {meta.get('version')}, this code reads version {FORMAT_VERSION}; "
            "rebuild it with `ragnav build-memory`"
        )
    stored = meta.get("meta_sha256")
    if stored is not None and stored != _meta_digest(meta):
        raise UserError(f"{meta_path}: edited or corrupted (checksum mismatch); rebuild the bank with "
                        "`ragnav build-memory --force`")
    fields = meta.get("fields", {})
    expected = [f.name for f in dataclasses.fields(DualBasisMemory)]
    if sorted(fields) != sorted(expected):
        raise UserError(f"{path}: memory fields {sorted(fields)} do not match this code's {sorted(expected)}; rebuild it")
    try:
        abstract = {k: jax.ShapeDtypeStruct(tuple(v["shape"]), np.dtype(v["dtype"])) for k, v in fields.items()}
        metas = tuple(MemoryMeta.from_json(m) for m in meta["scenes"])
    except (KeyError, TypeError, ValueError) as e:
        raise UserError(f"{meta_path}: malformed memory metadata ({e.__class__.__name__}: {e})") from None
    try:
        restored = ocp.StandardCheckpointer().restore(path / "arrays", abstract)
    except Exception as e:  # orbax/tensorstore raise many types for missing or damaged files
        msg = str(e).splitlines()[0][:200] if str(e) else ""
        raise UserError(f"{path}: memory arrays are missing or corrupted ({e.__class__.__name__}: {msg})") from None
    for k, v in fields.items():
        a = np.asarray(restored[k])
        if list(a.shape) != v["shape"] or a.dtype.str != v["dtype"]:
            raise UserError(f"{path}: field '{k}' has shape {a.shape} {a.dtype}, meta.json says {v['shape']} {v['dtype']}")
        if _digest(a) != v["sha256"]:
            raise UserError(f"{path}: field '{k}' is corrupted (checksum mismatch)")
    B = fields["node_mask"]["shape"][0]
    if len(metas) != B:
        raise UserError(f"{path}: {len(metas)} scene metadata entries for {B} scenes of arrays")
    mem = DualBasisMemory(**{k: jnp.asarray(restored[k]) for k in expected})
    bank = MemoryBank(mem, metas)
    if stored is None or not all(m.fingerprint for m in metas):
        print(f"ragnav: warning: {path}: a bank written before scene fingerprints and meta.json checksums; its scenes "
              "and metadata cannot be checked (rebuild it with `ragnav build-memory --force` to add them)",
              file=sys.stderr)
    if scenes is not None:
        check_bank_scenes(bank, scenes, path)
    return bank
