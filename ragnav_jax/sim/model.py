"""Scenes as MuJoCo models: one padded template, per-scene geometry batched into it.

The template holds a floor plane, W wall slots and O object slots (boxes in the world body) and a
planar robot (slide x, slide y, hinge yaw, velocity actuators, one sphere). A scene fills the first
slots; unused slots are parked far below and away from the house, tiny, so that they never collide nor
meet a ray. Per-scene geometry (`SceneGeometry`: geom positions, sizes, orientations and bounding
radii) is swapped into the one compiled MJX model with `tree_replace` under `vmap` with an `in_axes`
pytree that is None everywhere but 0 on those fields (`batch_model`), so scenes of one padded shape
share one compilation and new layouts never recompile.

The same slot geometry also writes a plain MJCF for one scene (`scene_xml`), which the tests load into
MuJoCo's C engine to check MJX against it.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Sequence

import jax
import mujoco
import numpy as np
from flax import struct
from mujoco import mjx

from ragnav_jax.config import SimConfig
from ragnav_jax.world.scene import Scene

PARK = 1000.0  # metres: unused slots sit at (PARK + 3 i, PARK, -PARK)
PARK_SIZE = 0.01  # half size of a parked box
ROBOT_MASS = 5.0  # kg
MIN_SLOTS = 8  # at least this many wall and object slots, so contact shapes never depend on a small scene


@dataclasses.dataclass(frozen=True)
class Layout:
    """Static facts of a template: slot counts and MuJoCo ids."""

    walls: int  # W wall slots
    objects: int  # O object slots
    ngeom: int  # G = 1 + W + O + 1
    robot_body: int
    robot_geom: int

    @property
    def wall_geom0(self) -> int:
        return 1

    @property
    def obj_geom0(self) -> int:
        return 1 + self.walls


@struct.dataclass
class SceneGeometry:
    """Per-scene values of the geom fields that differ between scenes (leading batch axis B when batched)."""

    geom_pos: jax.Array  # (G, 3) float32
    geom_size: jax.Array  # (G, 3) float32, box half sizes
    geom_quat: jax.Array  # (G, 4) float32
    geom_rbound: jax.Array  # (G,) float32, bounding-sphere radius (MJX's contact broad phase)


GEOMETRY_FIELDS = ("geom_pos", "geom_size", "geom_quat", "geom_rbound")


@dataclasses.dataclass(frozen=True)
class SimModel:
    """A compiled template: the MuJoCo model, its MJX copy and the slot layout."""

    mj: mujoco.MjModel
    mx: mjx.Model
    layout: Layout
    sim: SimConfig


def slot_counts(scenes: Sequence[Scene]) -> tuple[int, int]:
    """(W, O): wall and object slots that fit every scene (at least MIN_SLOTS each)."""
    walls = max([len(s.walls) for s in scenes] + [MIN_SLOTS])
    objects = max([len(s.objects) for s in scenes] + [MIN_SLOTS])
    return walls, objects


def _parked(i: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    return np.array([PARK + 3.0 * i, PARK, -PARK]), np.full(3, PARK_SIZE), np.array([1.0, 0.0, 0.0, 0.0])


def wall_box(a, b, thickness: float, height: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(pos, half sizes, quat) of the box of a wall segment; it reaches thickness/2 past each end, so
    corners close like the scene's capsule walls (`world.geometry`)."""
    (ax, ay), (bx, by) = a, b
    length = math.hypot(bx - ax, by - ay)
    angle = math.atan2(by - ay, bx - ax)
    pos = np.array([(ax + bx) / 2, (ay + by) / 2, height / 2])
    size = np.array([length / 2 + thickness / 2, thickness / 2, height / 2])
    quat = np.array([math.cos(angle / 2), 0.0, 0.0, math.sin(angle / 2)])
    if abs(quat[3]) < 1e-12:
        quat = np.array([1.0, 0.0, 0.0, 0.0])
    return pos, size, quat


def slot_geometry(scene: Scene | None, layout: Layout) -> dict[str, np.ndarray]:
    """NumPy (G, ...) geom fields of one scene in the template's slots (None: everything parked)."""
    G = layout.ngeom
    pos = np.zeros((G, 3))
    size = np.zeros((G, 3))
    quat = np.tile([1.0, 0.0, 0.0, 0.0], (G, 1))
    walls = scene.walls if scene is not None else ()
    objects = scene.objects if scene is not None else ()
    if len(walls) > layout.walls or len(objects) > layout.objects:
        raise ValueError(f"scene '{scene.name}' does not fit the template's {layout.walls} wall / {layout.objects} object slots")
    for i in range(layout.walls):
        g = layout.wall_geom0 + i
        pos[g], size[g], quat[g] = wall_box(walls[i].a, walls[i].b, walls[i].thickness, walls[i].height) if i < len(walls) else _parked(g)
    for i in range(layout.objects):
        g = layout.obj_geom0 + i
        if i < len(objects) and objects[i].id not in scene.absent:
            pos[g], size[g] = np.array(objects[i].position), np.array(objects[i].size) / 2
        else:
            pos[g], size[g], quat[g] = _parked(g)
    # The floor (slot 0) and the robot's sphere (last slot) stay zero here; scene_geometry copies them
    # from the template.
    rbound = np.linalg.norm(size, axis=1)
    return dict(geom_pos=pos, geom_size=size, geom_quat=quat, geom_rbound=rbound)


def _fmt(v) -> str:
    return " ".join(f"{float(x):.9g}" for x in np.ravel(v))


def scene_xml(scene: Scene | None, walls: int, objects: int, sim: SimConfig) -> str:
    """MJCF of the template with `scene` in its slots (None: all slots parked)."""
    layout = Layout(walls, objects, 1 + walls + objects + 1, robot_body=1, robot_geom=1 + walls + objects)
    geo = slot_geometry(scene, layout)
    boxes = []
    for g in range(1, 1 + walls + objects):
        kind = "wall" if g < layout.obj_geom0 else "obj"
        idx = g - (layout.wall_geom0 if kind == "wall" else layout.obj_geom0)
        boxes.append(
            f'    <geom name="{kind}{idx}" type="box" pos="{_fmt(geo["geom_pos"][g])}" size="{_fmt(geo["geom_size"][g])}" '
            f'quat="{_fmt(geo["geom_quat"][g])}" class="{kind}"/>'
        )
    r, h = sim.robot_radius, sim.robot_height
    kv = ROBOT_MASS / 0.1  # translational velocity servo with a 0.1 s time constant
    inertia = 0.4 * ROBOT_MASS * r * r
    kv_yaw = inertia / 0.05
    fmax = kv * sim.max_speed * 1.5
    tmax = kv_yaw * sim.max_yaw_rate * 1.5
    return f"""<mujoco model="ragnav_scene">
  <compiler angle="radian" autolimits="true"/>
  <option timestep="{sim.timestep}" gravity="0 0 0" integrator="implicitfast" solver="Newton" iterations="8"
          ls_iterations="8" cone="pyramidal"/>
  <custom><numeric name="max_geom_pairs" data="{sim.max_contact_pairs}"/></custom>
  <asset><material name="ragnav" rgba="0.8 0.8 0.8 1"/></asset>
  <default>
    <geom condim="1" contype="1" conaffinity="1" solref="0.05 1" solimp="0.95 0.99 0.001" friction="0 0 0"/>
    <default class="wall"><geom rgba="0.3 0.3 0.3 1"/></default>
    <default class="obj"><geom rgba="0.3 0.5 0.7 1"/></default>
  </default>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 0.1" contype="0" conaffinity="0" material="ragnav"/>
{chr(10).join(boxes)}
    <body name="robot" pos="0 0 {h}">
      <joint name="x" type="slide" axis="1 0 0"/>
      <joint name="y" type="slide" axis="0 1 0"/>
      <joint name="yaw" type="hinge" axis="0 0 1"/>
      <geom name="robot" type="sphere" size="{r}" mass="{ROBOT_MASS}" rgba="0.9 0.2 0.2 1"/>
    </body>
  </worldbody>
  <actuator>
    <velocity name="vx" joint="x" kv="{kv}" forcerange="{-fmax} {fmax}"/>
    <velocity name="vy" joint="y" kv="{kv}" forcerange="{-fmax} {fmax}"/>
    <velocity name="wz" joint="yaw" kv="{kv_yaw}" forcerange="{-tmax} {tmax}"/>
  </actuator>
</mujoco>
"""


def scene_mj_model(scene: Scene | None, walls: int, objects: int, sim: SimConfig) -> mujoco.MjModel:
    """A C-engine MuJoCo model of one scene in the template's slots (for reference checks and benchmarks)."""
    return mujoco.MjModel.from_xml_string(scene_xml(scene, walls, objects, sim))


def build_template(walls: int, objects: int, sim: SimConfig) -> SimModel:
    """Compiles the padded template (all slots parked) and its MJX copy."""
    mj = scene_mj_model(None, walls, objects, sim)
    robot_body = mujoco.mj_name2id(mj, mujoco.mjtObj.mjOBJ_BODY, "robot")
    robot_geom = mujoco.mj_name2id(mj, mujoco.mjtObj.mjOBJ_GEOM, "robot")
    layout = Layout(walls, objects, mj.ngeom, robot_body, robot_geom)
    assert robot_geom == 1 + walls + objects and mj.ngeom == robot_geom + 1
    return SimModel(mj=mj, mx=mjx.put_model(mj), layout=layout, sim=sim)


def scene_geometry(scenes: Sequence[Scene], model: SimModel) -> SceneGeometry:
    """Stacked (B, G, ...) geometry of scenes for `batch_model`."""
    per = []
    for s in scenes:
        geo = slot_geometry(s, model.layout)
        for g in (0, model.layout.robot_geom):  # floor and robot keep the template's values
            for k in GEOMETRY_FIELDS:
                geo[k][g] = getattr(model.mj, k)[g]
        per.append(geo)
    return SceneGeometry(**{k: jax.numpy.asarray(np.stack([p[k] for p in per]), dtype=np.float32) for k in GEOMETRY_FIELDS})


def batch_model(mx: mjx.Model, geometry: SceneGeometry) -> tuple[mjx.Model, mjx.Model]:
    """(model, in_axes): the template with batched geometry fields and the matching vmap in_axes."""
    model = mx.tree_replace({k: getattr(geometry, k) for k in GEOMETRY_FIELDS})
    in_axes = jax.tree.map(lambda _: None, mx)
    in_axes = in_axes.tree_replace({k: 0 for k in GEOMETRY_FIELDS})
    return model, in_axes


def _mjx_numerics(fn):
    """MJX's own code relies on NumPy-style rank promotion; allow it inside calls into MJX only, so our
    code stays under the strict setting the tests use."""

    @functools.wraps(fn)
    def wrapped(*args, **kwargs):
        with jax.numpy_rank_promotion("allow"):
            return fn(*args, **kwargs)

    return wrapped


mjx_step = _mjx_numerics(mjx.step)
mjx_forward = _mjx_numerics(mjx.forward)
mjx_ray = _mjx_numerics(mjx.ray)
mjx_make_data = _mjx_numerics(mjx.make_data)


def initial_data(m: mjx.Model, start: jax.Array) -> mjx.Data:
    """MJX data of model `m` at a start pose (3,) = (x, y, yaw), kinematics computed (jit/vmap friendly)."""
    d = mjx_make_data(m).replace(qpos=jax.numpy.asarray(start, dtype=jax.numpy.float32))
    return mjx_forward(m, d)
