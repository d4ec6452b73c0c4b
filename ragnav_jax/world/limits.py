"""How large a scene the simulator takes: limits checked before anything is compiled.

Two checks, each naming the limit it hit:
  - counts: walls and objects per scene against `sim.max_walls` / `sim.max_objects` (`scene_size_problems`;
    `ragnav validate` warns with them, `ragnav explore` refuses);
  - memory: an estimate of what one compiled exploration batch needs (`explore_bytes`) against the
    memory the device has free (`available_memory`: the accelerator's own figure where JAX reports one,
    else the host's available RAM).

The estimate counts what grows with the scene and the settings (measured with XLA's memory analysis of
the compiled explorer on CPU): per scene, the recorded stream, T records of 33 + 4 L + 9 O bytes (pose,
lidar, per-object visibility, distance, bearing); MJX's per-step collision and ray work, about
GEOM_PAIR_BYTES per pair of the G = 2 + W + O geoms; and the occupancy maps, MAP_CELL_BYTES per cell.
"""

from __future__ import annotations

import math
import os
from collections.abc import Sequence

from ragnav_jax.config import Config, SimConfig
from ragnav_jax.errors import UserError
from ragnav_jax.world.scene import Scene

GEOM_PAIR_BYTES = 160  # measured: ~140 bytes of XLA temporaries per geom pair per scene (O = 64 .. 2048)
MAP_CELL_BYTES = 64  # occupancy maps and grid planning per map cell, with margin


def scene_size_problems(scene: Scene, sim: SimConfig) -> list[str]:
    """One phrase per configured size limit `scene` exceeds (empty when it fits)."""
    out = []
    if len(scene.walls) > sim.max_walls:
        out.append(f"{len(scene.walls)} walls, more than sim.max_walls={sim.max_walls}")
    if len(scene.objects) > sim.max_objects:
        out.append(f"{len(scene.objects)} objects, more than sim.max_objects={sim.max_objects}")
    return out


def explore_bytes(walls: int, objects: int, map_cells: int, records: int, lidar_rays: int, batch: int) -> int:
    """Estimated bytes of one compiled exploration batch of `batch` scenes padded to these sizes."""
    from ragnav_jax.sim.model import MIN_SLOTS

    geoms = 2 + max(walls, MIN_SLOTS) + max(objects, MIN_SLOTS)
    stream = records * (33 + 4 * lidar_rays + 9 * max(objects, MIN_SLOTS))
    return batch * (stream + GEOM_PAIR_BYTES * geoms * geoms + MAP_CELL_BYTES * map_cells)


def available_memory() -> tuple[int | None, str]:
    """(free bytes, what they are) of the default JAX device: its allocator's limit less what is in use
    where the backend reports it (GPU, TPU), else the host's available memory (CPU); None when unknown."""
    import jax

    device = jax.devices()[0]
    stats = device.memory_stats() or {}
    if "bytes_limit" in stats:
        return int(stats["bytes_limit"]) - int(stats.get("bytes_in_use", 0)), f"free on {device.device_kind}"
    try:
        with open("/proc/meminfo") as f:
            kb = next(int(line.split()[1]) for line in f if line.startswith("MemAvailable:"))
        return kb * 1024, "host memory available"
    except (OSError, StopIteration, ValueError, IndexError):
        pass
    try:
        return os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE"), "host memory available"
    except (ValueError, OSError, AttributeError):
        return None, "unknown"


def _gb(n: float) -> str:
    return f"{n / 1e9:.1f} GB" if n >= 1e8 else f"{n / 1e6:.1f} MB"


def check_explore_fits(scenes: Sequence[Scene], cfg: Config) -> None:
    """Raises UserError (naming the scene and the limit) when a scene exceeds the configured sizes, or when
    one exploration batch would need more memory than the device has free."""
    from ragnav_jax.sim.grid import grid_spec

    for s in scenes:
        if problems := scene_size_problems(s, cfg.sim):
            raise UserError(f"scene '{s.name}': {'; '.join(problems)}: too large to simulate (raise the limit in the "
                            "config if the device can hold it)")
    if not scenes:
        return
    spec = grid_spec(scenes, cfg.explore.map_resolution, cfg.explore.grid_resolution,
                     cfg.sim.robot_radius + cfg.explore.clearance)
    walls, objects = max(len(s.walls) for s in scenes), max(len(s.objects) for s in scenes)
    records = -(-cfg.explore.max_steps // cfg.explore.scan_every)
    batch = min(cfg.explore.batch_size, len(scenes))
    need = explore_bytes(walls, objects, math.prod(spec.shape), records, cfg.sim.lidar_rays, batch)
    free, where = available_memory()
    if free is not None and need > free:
        one = explore_bytes(walls, objects, math.prod(spec.shape), records, cfg.sim.lidar_rays, 1)
        hint = "lower explore.batch_size" if one <= free else "raise explore.scan_every or lower explore.max_steps"
        raise UserError(f"explore needs about {_gb(need)} for {batch} scene(s) at once ({records} records x "
                        f"{objects} objects, {walls} walls, {spec.shape[0]}x{spec.shape[1]} map cells each), "
                        f"more than the {_gb(free)} {where}: {hint}")
