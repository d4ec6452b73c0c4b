"""The exploration stream D = {(t, pose, lidar scan, visible objects)} of one scene.

This is the contract between the simulator (which writes it, `ragnav explore`) and the memory builder
(which reads it, `ragnav build-memory`). Streams live in `RUN/explore/streams/<scene>.npz`.
Object columns follow the order of `scene.objects`.
"""

from __future__ import annotations

import dataclasses
import zipfile
import zlib
from pathlib import Path

import numpy as np

from ragnav_jax.errors import UserError

# What np.load raises on a missing, truncated (a killed write) or damaged .npz file, or one lacking a key.
NPZ_ERRORS = (OSError, KeyError, ValueError, EOFError, zipfile.BadZipFile, zlib.error)

STREAM_VERSION = 1


@dataclasses.dataclass(frozen=True)
class ExplorationStream:
    scene: str  # scene name
    t: np.ndarray  # (T,) int32 control-step index of each record
    pose: np.ndarray  # (T, 4) float32 odometry: x, y, z, yaw
    lidar: np.ndarray  # (T, L) float32 ranges in metres (the max range where a ray hits nothing)
    lidar_angles: np.ndarray  # (L,) float32 ray angles relative to the heading, radians
    visible: np.ndarray  # (T, O) bool: object o seen by the forward camera at record t
    distance: np.ndarray  # (T, O) float32 metres to the object's centre (meaningful where visible)
    bearing: np.ndarray  # (T, O) float32 radians relative to the heading (meaningful where visible)
    object_ids: tuple[str, ...]  # (O,) ids in scene.objects order

    def __post_init__(self):
        T, O = self.visible.shape
        assert self.pose.shape == (T, 4) and self.t.shape == (T,), "stream arrays disagree in length"
        assert self.distance.shape == (T, O) and self.bearing.shape == (T, O) and len(self.object_ids) == O
        assert self.lidar.shape[0] == T and self.lidar.shape[1] == self.lidar_angles.shape[0]

    def view_times(self) -> tuple[np.ndarray, np.ndarray]:
        """(first, last) (O,) int64: the first and the last record in which each object was seen, -1 where never."""
        vis = np.asarray(self.visible, bool)
        seen = vis.any(0)
        first = np.where(seen, vis.argmax(0), -1)
        last = np.where(seen, vis.shape[0] - 1 - vis[::-1].argmax(0), -1)
        return first, last

    def save(self, path: str | Path) -> Path:
        from ragnav_jax.io import atomic_open

        path = Path(path)
        with atomic_open(path, "wb") as f:
            np.savez_compressed(
                f, version=np.int32(STREAM_VERSION), scene=np.str_(self.scene), t=self.t, pose=self.pose,
                lidar=self.lidar, lidar_angles=self.lidar_angles, visible=self.visible, distance=self.distance,
                bearing=self.bearing, object_ids=np.array(self.object_ids, dtype=np.str_),
            )
        return path

    @staticmethod
    def load(path: str | Path) -> ExplorationStream:
        path = Path(path)
        try:
            with np.load(path, allow_pickle=False) as z:
                if int(z["version"]) != STREAM_VERSION:
                    raise UserError(f"{path}: stream format version {int(z['version'])}, expected {STREAM_VERSION}")
                return ExplorationStream(
                    scene=str(z["scene"]), t=z["t"], pose=z["pose"], lidar=z["lidar"],
                    lidar_angles=z["lidar_angles"], visible=z["visible"], distance=z["distance"],
                    bearing=z["bearing"], object_ids=tuple(str(x) for x in z["object_ids"]),
                )
        except (*NPZ_ERRORS, AssertionError) as e:
            raise UserError(f"{path}: not a readable exploration stream ({e.__class__.__name__}: {e})") from None
