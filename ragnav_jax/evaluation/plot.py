"""Pictures of evaluated episodes: the floor plan, every leg's driven waypoints, the simulated leg ends,
the declarations and the goals (rows recorded with `eval.record_legs=true`)."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ragnav_jax.io import save_figure  # noqa: E402
from ragnav_jax.world.plot import draw_floor_plan  # noqa: E402
from ragnav_jax.world.scene import Scene  # noqa: E402

LEG_COLORS = {"nav": "tab:blue", "closer": "tab:cyan", "search": "tab:orange", "approach": "tab:green", "explore": "tab:purple",
              "goto_seen": "tab:olive"}


def draw_episode(scene: Scene, row: dict, ax=None, title: str | None = None):
    """Draws one episode row (with "legs") over the scene's floor plan; returns the axis.

    Lines: the waypoints each leg drove (colour by kind); dots: where the simulation ended each leg
    (hollow: the leg stopped short, stuck or out of steps); stars: the goals (numbered in the
    instruction's order); crosses: declarations (green correct, red wrong; ringed: made by the reflection's
    fallback, `eval.fallback`).
    """
    if "legs" not in row:
        raise ValueError(f"episode {row.get('episode')}: no legs recorded (evaluate with eval.record_legs=true)")
    ax = draw_floor_plan(scene, ax=ax, labels=False)
    start = np.asarray(scene.start.position[:2])
    ax.plot(*start, "ks", ms=6, label="start")
    seen = set()
    for leg in row["legs"]:
        w = np.asarray(leg["waypoints"], float).reshape(-1, 2)
        c = LEG_COLORS.get(leg["kind"], "0.3")
        ax.plot(w[:, 0], w[:, 1], "-", color=c, lw=1.2, alpha=0.8, label=None if leg["kind"] in seen else leg["kind"])
        seen.add(leg["kind"])
        e = leg["end"]
        ax.plot(e[0], e[1], "o", ms=3.5, color=c, mfc=c if leg["arrived"] else "none")
    objs = {o.id: o for o in scene.objects}
    for g, oid in enumerate(row.get("goal_ids", [])):
        o = objs.get(oid)
        if o is not None:
            ax.plot(o.position[0], o.position[1], "*", ms=11, color="gold", mec="k", mew=0.6)
            ax.annotate(str(g + 1), (o.position[0], o.position[1]), fontsize=7, xytext=(4, 4), textcoords="offset points")
    for d in row["declarations"]:
        col = "tab:green" if d["correct"] else "tab:red"
        ax.plot(*d["xy"], "x", ms=8, mew=2, color=col)
        if d.get("fallback"):
            ax.plot(*d["xy"], "o", ms=13, mew=1.2, mfc="none", color=col)
    ax.set_title(title or f"{row['episode']} ({row['method']}): {row['reason']}", fontsize=8)
    ax.legend(fontsize=6, loc="lower right")
    return ax


def save_episode_plot(scene: Scene, row: dict, path: str | Path, instruction: str = "") -> Path:
    """Saves `draw_episode` of one row (with "legs") as a picture, the instruction under its title; returns
    the path."""
    import textwrap

    fig, ax = plt.subplots(figsize=(6, 6.4))
    title = f"{row['episode']} ({row['method']}): {row['reason']}"
    draw_episode(scene, row, ax=ax, title="\n".join([title, *textwrap.wrap(instruction, 80)]))
    fig.tight_layout()
    save_figure(fig, path, dpi=120)
    plt.close(fig)
    return Path(path)
