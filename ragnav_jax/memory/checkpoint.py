"""Saving and restoring a MemoryBank with orbax-checkpoint.

Layout of a bank folder:
  arrays/      orbax StandardCheckpointer of the DualBasisMemory fields (leading scene axis)
  meta.json    format name and version, field shapes/dtypes, a SHA-256 per field, the per-scene MemoryMeta
A missing, truncated or corrupted file, another format version, or arrays that disagree with meta.json
raise UserError naming the folder: never a silently wrong memory.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import shutil
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np

from ragnav_jax.errors import UserError
from ragnav_jax.memory.types import FORMAT_VERSION, DualBasisMemory, MemoryBank, MemoryMeta, memory_to_numpy

FORMAT = "ragnav-memory-bank"


def _digest(a: np.ndarray) -> str:
    h = hashlib.sha256()
    h.update(f"{a.dtype.str}{a.shape}".encode())
    h.update(np.ascontiguousarray(a).tobytes())
    return h.hexdigest()


def save_bank(bank: MemoryBank, path: str | Path) -> Path:
    """Writes the bank to folder `path` (replaced if it exists)."""
    import orbax.checkpoint as ocp

    path = Path(path).resolve()
    if path.exists():
        shutil.rmtree(path)
    path.mkdir(parents=True)
    arrays = memory_to_numpy(bank.memory)
    ck = ocp.StandardCheckpointer()
    ck.save(path / "arrays", arrays)
    ck.wait_until_finished()
    meta = {
        "format": FORMAT,
        "version": FORMAT_VERSION,
        "fields": {k: {"shape": list(v.shape), "dtype": v.dtype.str, "sha256": _digest(v)} for k, v in arrays.items()},
        "scenes": [m.to_json() for m in bank.metas],
    }
    (path / "meta.json").write_text(json.dumps(meta, indent=1) + "\n")
    return path


def load_bank(path: str | Path) -> MemoryBank:
    """Restores a bank written by `save_bank`; raises UserError on any inconsistency."""
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
    return MemoryBank(mem, metas)
