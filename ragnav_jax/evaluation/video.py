"""Episode videos: one replayed episode animated over the floor plan (show-episode), as GIF or MP4.

    n = save_episode_video(scene, row, "ep.gif", instruction=episode.instruction)

`row` is an episode row with the recorder's fields (evaluation/replay.py: "legs" with per-step poses
and what the look-around saw, "trace" with candidates, scores and rejections). Each frame shows the
simulated trajectory so far, the robot, the current leg's waypoints, the current goal's candidates
with their retrieval scores (rejected ones crossed out), the objects the camera saw at the end of a
leg, and the FOUND declarations; a side panel says the same in words. Encoded with matplotlib's
writers: Pillow for GIF, ffmpeg (the imageio-ffmpeg package's binary) for MP4.
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.patches as patches  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ragnav_jax.evaluation.plot import LEG_COLORS  # noqa: E402
from ragnav_jax.io import atomic_path  # noqa: E402
from ragnav_jax.world.plot import draw_floor_plan  # noqa: E402
from ragnav_jax.world.scene import Scene  # noqa: E402

SUFFIXES = (".gif", ".mp4")
HOLD = 3  # frames held after each leg: the look-around (a turn in place) and its outcome
LOOKING = ("nav", "closer", "search", "explore")  # legs after which the robot looks around (turns in place)


def ffmpeg_exe() -> str | None:
    """The ffmpeg binary shipped by the imageio-ffmpeg package, or None when it is not installed."""
    try:
        import imageio_ffmpeg
    except ImportError:
        return None
    return imageio_ffmpeg.get_ffmpeg_exe()


def frame_plan(legs: list[dict], max_frames: int, hold: int = HOLD) -> list[tuple[int, int]]:
    """(leg, pose index) per frame; pose index -1 is the leg's end and -2 .. -(hold + 1) the frames held there.

    Every leg's per-step poses are sampled with one stride so that the frames (`hold` per leg, fewer
    when those alone would pass max_frames) number at most max(max_frames, len(legs))."""
    hold = max(min(hold, (max_frames - len(legs)) // max(len(legs), 1)), 0)
    room = max(max_frames - len(legs) * (hold + 1), 0)
    total = sum(len(leg["poses"]) for leg in legs)
    stride = max(math.ceil(total / room), 1) if room else None
    out = []
    for k, leg in enumerate(legs):
        n = len(leg["poses"])
        if stride is not None:
            out += [(k, i) for i in range(stride - 1, n - 1, stride)]  # the leg's last pose is its end frame
        out += [(k, -j) for j in range(1, hold + 2)]
    return out


def _events(row: dict) -> tuple[dict, dict]:
    """(leg -> declarations made at its end, leg -> rejections made after it)."""
    legs = row["legs"]
    found: dict = {}
    for d in row["declarations"]:  # made where an approach leg's simulation ended
        k = next((i for i, leg in enumerate(legs) if leg["kind"] == "approach" and leg["end"] == d["xy"]
                  and d not in found.get(i, [])), len(legs) - 1)
        found.setdefault(k, []).append(d)
    rejected: dict = {}
    for r in row.get("trace", {}).get("rejections", []):
        rejected.setdefault(r["leg"], []).append(r)
    return found, rejected


def _figure(scene: Scene, dpi: int):
    """(figure, floor-plan axis, text panel axis): the plan sized to the scene's aspect, the panel on its
    right; width and height an even number of pixels (the H.264 encoder's yuv420p needs them)."""
    xmin, ymin, xmax, ymax = scene.bounds
    plan_h, panel_w = 4.8, 3.4
    plan_w = min(max(plan_h * (xmax - xmin + 0.6) / (ymax - ymin + 0.6), 3.0), 10.0)
    even = lambda inches: 2 * round(inches * dpi / 2) / dpi  # noqa: E731
    W, H = even(0.45 + plan_w + 0.2 + panel_w), even(0.3 + plan_h + 0.35)
    fig = plt.figure(figsize=(W, H), dpi=dpi)
    ax = fig.add_axes((0.45 / W, 0.3 / H, plan_w / W, plan_h / H))
    panel = fig.add_axes(((0.65 + plan_w) / W, 0.3 / H, panel_w / W, plan_h / H))
    panel.axis("off")
    return fig, ax, panel


def save_episode_video(scene: Scene, row: dict, out: str | Path, fps: int = 8, max_frames: int = 160, dpi: int = 80,
                       instruction: str | None = None) -> int:
    """Writes the animation of one recorded episode row to `out` (.gif or .mp4); returns the frame count."""
    from matplotlib.animation import FFMpegWriter, FuncAnimation, PillowWriter

    out = Path(out)
    if out.suffix.lower() not in SUFFIXES:
        raise ValueError(f"{out}: use a .gif or .mp4 file name")
    if not row.get("legs") or "poses" not in row["legs"][0]:
        raise ValueError(f"episode {row.get('episode')}: no per-step poses recorded (replay it with the recorder on)")
    frames = episode_frames(scene, row, max_frames)
    fig, ax, panel = _figure(scene, dpi)
    draw_floor_plan(scene, ax=ax, labels=False)
    ax.set(xlabel="", ylabel="")
    ax.tick_params(labelsize=6)
    ax.set_title(f"{row['episode']} ({row['method']}): {row['reason']}", fontsize=8)
    objs = {o.id: o for o in scene.objects}
    for g, oid in enumerate(row["goal_ids"]):
        if oid in objs:
            xy = objs[oid].position[:2]
            ax.plot(*xy, "*", ms=12, color="gold", mec="k", mew=0.6, zorder=6)
            ax.annotate(str(g + 1), xy, fontsize=7, xytext=(5, 4), textcoords="offset points", zorder=6)
    dynamic: list = []

    def draw(f: int) -> None:
        for a in dynamic:
            a.remove()
        dynamic.clear()
        dynamic.extend(_draw_frame(ax, panel, frames[f], row, objs, instruction))

    anim = FuncAnimation(fig, draw, frames=len(frames), interval=1000 / fps, blit=False, repeat=False)
    out.parent.mkdir(parents=True, exist_ok=True)
    if out.suffix.lower() == ".gif":
        writer = PillowWriter(fps=fps)
    else:
        exe = ffmpeg_exe()
        if exe is None:
            raise ValueError("MP4 needs the imageio-ffmpeg package (pip install imageio-ffmpeg); or write a .gif")
        matplotlib.rcParams["animation.ffmpeg_path"] = exe
        writer = FFMpegWriter(fps=fps, codec="libx264", extra_args=["-pix_fmt", "yuv420p"])
    try:
        with atomic_path(out) as tmp:
            anim.save(tmp, writer=writer, dpi=dpi)
    finally:
        plt.close(fig)
    return len(frames)


def episode_frames(scene: Scene, row: dict, max_frames: int) -> list[dict]:
    """What each frame shows (frame_plan's frames): the trajectory so far (n, 3), the robot's heading, the
    leg, the leg's goal's candidates with the rejected ones (index -> why) and the one being tried, what
    the camera saw (object ids, at a leg's end) and the declarations made so far."""
    legs, trace = row["legs"], row.get("trace", {"candidates": [], "rejections": []})
    plan = frame_plan(legs, max_frames)
    held_n = {k: -i for k, i in plan if i < 0}
    found, rejected = _events(row)
    start = np.asarray([*scene.start.position[:2], scene.start.yaw], float)
    poses = [np.asarray(leg["poses"], float).reshape(-1, 3) for leg in legs]
    out = []
    for k, i in plan:
        leg, held = legs[k], i < 0
        path = np.concatenate([start[None], *poses[:k], poses[k][: len(poses[k]) if held else i + 1]])
        turn = 2 * math.pi * (-i - 1) / held_n[k] if held and leg["kind"] in LOOKING else 0.0
        after = k + 1 if held else k  # events made after legs < after are shown
        g = leg["goal"]
        gone = {r["candidate"]: r["why"] for kk in range(-1, after) for r in rejected.get(kk, []) if r["goal"] == g}
        out.append({"leg": k, "held": held, "path": path, "yaw": path[-1, 2] + turn,
                    "candidates": trace["candidates"][g] if g < len(trace["candidates"]) else [], "rejected": gone,
                    "trying": len(gone) if leg["kind"] != "approach" else None,
                    "visible": leg.get("visible", []) if held else [],
                    "declarations": [d for kk in range(after) for d in found.get(kk, [])]})
    return out


def _draw_frame(ax, panel, fr: dict, row: dict, objs: dict, instruction: str | None) -> list:
    """Draws one frame's moving parts on the plan and the panel; returns the artists."""
    legs, k = row["legs"], fr["leg"]
    leg, g, pose = legs[k], legs[k]["goal"], fr["path"][-1]
    art = []
    w = np.asarray(leg["waypoints"], float).reshape(-1, 2)
    art += ax.plot(w[:, 0], w[:, 1], "--", color=LEG_COLORS.get(leg["kind"], "0.3"), lw=1.2, alpha=0.9, zorder=4)
    art += ax.plot(fr["path"][:, 0], fr["path"][:, 1], "-", color="#3a0ca3", lw=1.4, zorder=5)
    art.append(ax.add_patch(patches.Circle(pose[:2], 0.18, fc="#e63946", ec="k", lw=0.6, zorder=8)))
    art += ax.plot([pose[0], pose[0] + 0.35 * math.cos(fr["yaw"])], [pose[1], pose[1] + 0.35 * math.sin(fr["yaw"])],
                   "-", color="k", lw=1.5, zorder=9)
    lines = []
    for j, c in enumerate(fr["candidates"]):
        gone, now = j in fr["rejected"], j == fr["trying"]
        col = "tab:red" if gone else ("tab:orange" if now else "0.45")
        art += ax.plot(*c["xy"], "x" if gone else "D", ms=7 if now else 5, mew=2 if gone else 0.8, color=col,
                       mec=col if gone else "k", zorder=7)
        s = "-" if c["score"] is None else f"{c['score']:.2f}"
        art.append(ax.annotate(f"#{j + 1} {s}", c["xy"], fontsize=6, color=col, xytext=(4, -8),
                               textcoords="offset points", zorder=7))
        lines.append(f"  #{j + 1} node {c['node']}  score {s}"
                     + (f"  rejected: {fr['rejected'][j]}" if gone else ("  <- trying" if now else "")))
    for oid in fr["visible"]:
        o = objs.get(oid)
        if o is not None:
            art.append(ax.add_patch(patches.Rectangle(
                (o.position[0] - o.size[0] / 2 - 0.05, o.position[1] - o.size[1] / 2 - 0.05), o.size[0] + 0.1,
                o.size[1] + 0.1, fill=False, ec="tab:cyan", lw=1.5, zorder=6)))
    state = {}
    for d in fr["declarations"]:
        col = "tab:green" if d["correct"] else "tab:red"
        state[d["goal"]] = ("FOUND" if d["correct"] else "FOUND (wrong object)") + (" by the fallback" if d.get("fallback") else "")
        art += ax.plot(*d["xy"], "P" if d["correct"] else "X", ms=11, mec="k", mew=0.6, color=col, zorder=10)
        art.append(ax.annotate(f"FOUND {d['object']}", d["xy"], fontsize=7, weight="bold", xytext=(6, 6),
                               textcoords="offset points", color=col, zorder=10))
    end = f" ({'arrived' if leg['arrived'] else 'stopped short'})" if fr["held"] else ""
    text = [*(textwrap.wrap(instruction, 46) if instruction else []), "",
            *(f"goal {j + 1} {oid}: {state.get(j, '-')}" for j, oid in enumerate(row["goal_ids"])), "",
            f"leg {k + 1}/{len(legs)}: {leg['kind']} -> goal {g + 1}", f"control steps driven: {len(fr['path']) - 1}{end}", ""]
    if lines:
        text += [f"candidates of goal {g + 1} (retrieval score):", *lines, ""]
    if fr["held"] and "visible" in leg:
        text += textwrap.wrap("camera sees: " + (", ".join(fr["visible"]) or "-"), 46)
    art.append(panel.text(0.0, 1.0, "\n".join(text), va="top", ha="left", fontsize=7, family="monospace",
                          transform=panel.transAxes))
    return art
