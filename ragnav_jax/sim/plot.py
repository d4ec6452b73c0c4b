"""Exploration pictures: floor plan, explored map, frontiers left, given-up cells and the trajectory."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402

from ragnav_jax.io import save_figure  # noqa: E402
from ragnav_jax.world.plot import draw_floor_plan  # noqa: E402
from ragnav_jax.world.scene import Scene  # noqa: E402


def draw_exploration(scene: Scene, explored: dict, ax=None, title: str | None = None):
    """Draws one scene's exploration on an axis (created when None) and returns the axis.

    explored: the arrays of `RUN/explore/maps/<scene>.npz` (origin, resolution, grid_factor, seen, hit,
    frontier, blocked, true_pose).
    """
    ax = draw_floor_plan(scene, ax=ax, labels=False)
    x0, y0 = (float(v) for v in explored["origin"])
    res = float(explored["resolution"])
    k = int(explored["grid_factor"])
    seen, hit = np.asarray(explored["seen"]), np.asarray(explored["hit"])
    h, w = seen.shape
    ext = (x0, x0 + w * res, y0, y0 + h * res)
    state = np.where(hit, 2, np.where(seen, 1, 0))
    ax.imshow(np.ma.masked_equal(state, 0), origin="lower", extent=ext, cmap=ListedColormap(["#90be6d", "#222222"]),
              vmin=1, vmax=2, alpha=0.35, interpolation="nearest", zorder=1)
    # The paper's exploration grid (explored cells outlined) and the cells whose targets were given up.
    blocked = np.asarray(explored["blocked"])
    for i, j in zip(*np.nonzero(blocked)):
        ax.add_patch(plt.Rectangle((x0 + j * k * res, y0 + i * k * res), k * res, k * res, fill=False, ec="#e76f51",
                                   lw=1.0, ls="--", zorder=3))
    fr = np.asarray(explored["frontier"])
    if fr.any():
        ii, jj = np.nonzero(fr)
        ax.scatter(x0 + (jj + 0.5) * res, y0 + (ii + 0.5) * res, s=6, c="#f72585", marker="s", zorder=4,
                   label=f"frontier cells left ({fr.sum()})")
    pose = np.asarray(explored["true_pose"])
    if len(pose):
        ax.plot(pose[:, 0], pose[:, 1], color="#3a0ca3", lw=1.2, zorder=5, label="trajectory")
        ax.plot(pose[-1, 0], pose[-1, 1], marker="s", color="#3a0ca3", ms=6, zorder=6)
    ax.legend(loc="lower right", fontsize=7)
    if title:
        ax.set_title(title)
    return ax


def save_exploration(scene: Scene, explored: dict, out: str | Path, title: str | None = None, dpi: int = 150) -> Path:
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    ax = draw_exploration(scene, explored, title=title)
    ax.figure.tight_layout()
    save_figure(ax.figure, out, dpi=dpi)
    plt.close(ax.figure)
    return out
