"""Floor-plan pictures: rooms, walls, objects with labels, start pose; a change list drawn over the house."""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.patches as patches  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

from ragnav_jax.io import save_figure  # noqa: E402
from ragnav_jax.world.scene import Scene  # noqa: E402

ROOM_COLORS = plt.get_cmap("Pastel1").colors + plt.get_cmap("Pastel2").colors


def draw_floor_plan(scene: Scene, ax=None, labels: bool = True, fontsize: float = 5.5):
    """Draws the scene on a matplotlib axis (created when None) and returns the axis."""
    if ax is None:
        xmin, ymin, xmax, ymax = scene.bounds
        scale = 0.9
        _, ax = plt.subplots(figsize=(max(4, (xmax - xmin) * scale), max(4, (ymax - ymin) * scale)))
    types = sorted({r.type for r in scene.rooms})
    for r in scene.rooms:
        color = ROOM_COLORS[types.index(r.type) % len(ROOM_COLORS)]
        ax.add_patch(patches.Rectangle(r.min, r.max[0] - r.min[0], r.max[1] - r.min[1], color=color, alpha=0.6, lw=0))
        ax.text(r.min[0] + 0.1, r.max[1] - 0.1, f"{r.type}\n({r.id})", fontsize=fontsize + 1.5, va="top", ha="left",
                color="0.25", style="italic")
    for w in scene.walls:
        ax.plot([w.a[0], w.b[0]], [w.a[1], w.b[1]], color="black", lw=max(1.0, w.thickness * 25), solid_capstyle="butt")
    for o in scene.objects:
        resting = o.position[2] - o.size[2] / 2 > 0.05
        face = "none" if o.size[2] <= 0.05 else ("#f4a261" if resting else "#457b9d")
        ax.add_patch(
            patches.Rectangle(
                (o.position[0] - o.size[0] / 2, o.position[1] - o.size[1] / 2), o.size[0], o.size[1],
                facecolor=face, edgecolor="#1d3557", lw=0.6, alpha=0.85, hatch="///" if face == "none" else None,
            )
        )
        if labels:
            ax.text(o.position[0], o.position[1], o.category, fontsize=fontsize, ha="center", va="center", color="#111",
                    bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.6))
    sx, sy = scene.start.position
    ax.plot(sx, sy, marker="o", color="#e63946", ms=7)
    ax.annotate("", xy=(sx + 0.6 * math.cos(scene.start.yaw), sy + 0.6 * math.sin(scene.start.yaw)), xytext=(sx, sy),
                arrowprops=dict(arrowstyle="->", color="#e63946", lw=1.5))
    ax.text(sx, sy - 0.3, "start", color="#e63946", fontsize=fontsize + 1, ha="center", va="top")
    ax.set_aspect("equal")
    xmin, ymin, xmax, ymax = scene.bounds
    ax.set_xlim(xmin - 0.3, xmax + 0.3)
    ax.set_ylim(ymin - 0.3, ymax + 0.3)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(f"{scene.name}: {len(scene.rooms)} rooms, {len(scene.objects)} objects")
    return ax


def save_floor_plan(scene: Scene, out: str | Path, dpi: int = 150) -> Path:
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    ax = draw_floor_plan(scene)
    ax.figure.tight_layout()
    save_figure(ax.figure, out, dpi=dpi)
    plt.close(ax.figure)
    return out


def save_changes_plan(before: Scene, after: Scene, changes, out: str | Path, dpi: int = 150) -> Path:
    """The house after a change list (world/changes.py), the changes marked: a move as an arrow from where the
    object stood, a removal as a cross where it stood, an addition ringed, a closed door as a red wall."""
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    ax = draw_floor_plan(after, labels=True)
    for c in changes.changes:
        if c.kind == "move":
            o = before.object_by_id(c.object)
            ax.annotate("", xy=c.to[:2], xytext=o.position[:2],
                        arrowprops=dict(arrowstyle="->", color="#2a9d8f", lw=1.6, alpha=0.9))
        elif c.kind == "remove":
            o = before.object_by_id(c.object)
            ax.plot(*o.position[:2], marker="x", color="#e63946", ms=9, mew=2)
            ax.text(o.position[0], o.position[1] - 0.25, o.category, fontsize=5, color="#e63946", ha="center", va="top")
        elif c.kind == "add":
            ax.plot(*c.added.position[:2], marker="o", mfc="none", mec="#2a9d8f", ms=14, mew=1.8)
        else:
            ax.plot([c.wall.a[0], c.wall.b[0]], [c.wall.a[1], c.wall.b[1]], color="#e63946", lw=4, solid_capstyle="butt")
    n = changes.counts()
    ax.set_title(f"{after.name} after its changes: {n['move']} moved (arrows), {n['remove']} removed (crosses), "
                 f"{n['add']} added (rings), {n['close_door']} door(s) closed (red)", fontsize=8)
    ax.figure.tight_layout()
    save_figure(ax.figure, out, dpi=dpi)
    plt.close(ax.figure)
    return out
