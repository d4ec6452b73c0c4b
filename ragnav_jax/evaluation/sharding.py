"""Splitting a batch's leading axis over every device with jax.sharding (one host, or several via jax.distributed).

    mesh = batch_mesh()                          # all devices, one axis "batch" (AxisType.Auto)
    grid = shard_leading(pad_leading(grid, mesh.size), mesh)   # grid points split over devices
    data = replicate(batch, mesh)                # every device holds the whole retrieval batch
    out = to_host(jitted(grid, data))            # computation follows the inputs' shardings

Arrays are built with jax.make_array_from_callback from host data that every process holds, so the same
code runs on several hosts after jax.distributed.initialize(); to_host gathers across processes.
AxisType.Auto (not the Explicit default of recent jax.make_mesh) lets XLA propagate shardings through
kernels that scatter (MJX's collision code fails under Explicit).
"""

from __future__ import annotations

import os
from typing import Any

import jax
import numpy as np
from jax.sharding import AxisType, Mesh, NamedSharding, PartitionSpec

AXIS = "batch"


def batch_mesh(devices: list | None = None) -> Mesh:
    """A one-axis mesh named "batch" over `devices` (default: every device of every process)."""
    devices = list(devices) if devices is not None else jax.devices()
    return jax.make_mesh((len(devices),), (AXIS,), axis_types=(AxisType.Auto,), devices=devices)


def pad_leading(tree: Any, multiple: int) -> Any:
    """Pads every leaf's leading axis to a multiple of `multiple` by repeating its last entry (host arrays)."""

    def pad(x):
        x = np.asarray(x)
        extra = -x.shape[0] % multiple
        return np.concatenate([x, np.repeat(x[-1:], extra, axis=0)]) if extra else x

    return jax.tree.map(pad, tree)


def _put(x, sharding: NamedSharding) -> jax.Array:
    x = np.asarray(x)
    return jax.make_array_from_callback(x.shape, sharding, lambda idx: x[idx])


def shard_leading(tree: Any, mesh: Mesh) -> Any:
    """Every leaf split along its leading axis (a multiple of mesh.size) over the mesh's devices."""
    spec = NamedSharding(mesh, PartitionSpec(AXIS))
    return jax.tree.map(lambda x: _put(x, spec), tree)


def replicate(tree: Any, mesh: Mesh) -> Any:
    """Every leaf copied whole onto each device of the mesh."""
    spec = NamedSharding(mesh, PartitionSpec())
    return jax.tree.map(lambda x: _put(x, spec), tree)


def to_host(x: jax.Array) -> np.ndarray:
    """A (possibly sharded, possibly multi-process) array as one NumPy array on this host."""
    if jax.process_count() > 1:
        from jax.experimental import multihost_utils

        return np.asarray(multihost_utils.process_allgather(x, tiled=True))
    return np.asarray(x)


def init_distributed(env: dict | None = None) -> bool:
    """jax.distributed.initialize() when RAGNAV_DISTRIBUTED=1 (called by the CLI before any JAX work).

    RAGNAV_COORDINATOR (host:port of process 0), RAGNAV_NUM_PROCESSES and RAGNAV_PROCESS_ID are passed
    when set; left unset, JAX detects them on clusters it knows (SLURM, Open MPI, ...). Returns whether
    it initialised. Bad values are user errors naming the variable."""
    from ragnav_jax.errors import UserError

    env = dict(os.environ if env is None else env)
    if env.get("RAGNAV_DISTRIBUTED", "0") in ("", "0", "false", "no"):
        return False
    kw = {}
    if env.get("RAGNAV_COORDINATOR"):
        kw["coordinator_address"] = env["RAGNAV_COORDINATOR"]
    for var, key in (("RAGNAV_NUM_PROCESSES", "num_processes"), ("RAGNAV_PROCESS_ID", "process_id")):
        if env.get(var):
            try:
                kw[key] = int(env[var])
            except ValueError:
                raise UserError(f"{var}={env[var]!r}: expected an integer") from None
    jax.distributed.initialize(**kw)
    return True

