"""Typed, frozen configs loaded from YAML with dotted command-line overrides.

    cfg = load_config("configs/paper.yaml", ["world.num_scenes=20"])

Every section is a frozen dataclass; unknown keys and wrongly typed values raise ConfigError naming
the dotted key. Later stages add their own sections here.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import types
import typing
from pathlib import Path
from typing import Any

import yaml

from ragnav_jax.errors import ConfigError
from ragnav_jax.filenames import name_problem

# episodes.split: the sentence templates, seen then unseen (see EpisodesConfig.split).
EPISODE_SPLITS = ("seen", "unseen_dev", "unseen_dev2", "unseen_dev3", "unseen_dev4", "unseen_dev5", "unseen_dev6",
                  "unseen_dev7", "unseen_dev8", "unseen_dev9", "unseen_dev10",
                  "unseen_dev11", "unseen_dev12", "unseen_train1", "unseen_train2", "unseen_train3",
                  "unseen_train4", "unseen_q", "unseen_r", "unseen_s", "unseen_t", "unseen_u",
                  "unseen_v", "unseen_x", "unseen_y", "unseen_z", "unseen_w", "unseen_aa", "unseen_ab",
                  "unseen_ac", "unseen_ad", "unseen_ae", "unseen_af", "unseen_ag", "unseen_ah", "unseen_ai",
                  "unseen_aj", "unseen_ak", "unseen_al", "unseen_am", "unseen_an", "unseen_ao", "unseen_ap",
                  "unseen_aq", "unseen_ar", "unseen_as", "unseen_at", "unseen_au", "unseen_av", "unseen")

ROOM_TYPES = (
    "kitchen",
    "living room",
    "bedroom",
    "study",
    "bathroom",
    "dining room",
    "office",
    "hallway",
    "gym",
    "greenhouse",
)


def _check(ok: bool, key: str, why: str) -> None:
    if not ok:
        raise ConfigError(f"config key '{key}': {why}")


@dataclasses.dataclass(frozen=True)
class Hyper:
    """One row of a hyperparameter table: what a section's field declares beyond its comment.

    `hyper(...)` puts the rule on the field; `hyperparameters(section)` fills in name, type and default.
    """

    gt: float | None = None  # exclusive lower bound
    ge: float | None = None  # inclusive lower bound
    le: float | None = None  # inclusive upper bound
    among: tuple[float, ...] = ()  # the only values allowed (a 0/1 switch); () = any within the bounds
    sweep: bool = False  # a sweep.axes entry (SweepAxes)
    tune: str = ""  # ragnav tune moves it, optimised as log(x) | logit(x) | raw x; "" = not tuned
    name: str = ""
    type: Any = float  # int | float
    default: Any = None

    @property
    def rule(self) -> str:
        """The range in words, as error messages give it: "must be in [1, 16]", "must be > 0", "must be 0 or 1"."""
        if self.among:
            return "must be " + " or ".join(f"{x:g}" for x in self.among)
        lo = self.gt if self.gt is not None else self.ge
        if lo is not None and self.le is not None:
            return f"must be in {'(' if self.gt is not None else '['}{lo:g}, {self.le:g}]"
        if lo is not None:
            return f"must be {'>' if self.gt is not None else '>='} {lo:g}"
        return f"must be <= {self.le:g}" if self.le is not None else "any value"

    def allows(self, x: float) -> bool:
        return ((not self.among or x in self.among) and (self.gt is None or x > self.gt)
                and (self.ge is None or x >= self.ge) and (self.le is None or x <= self.le))

    def check(self, key: str, values: typing.Iterable[float]) -> None:
        """ConfigError naming `key` unless every value is in range."""
        _check(all(self.allows(x) for x in values), key, self.rule)


def hyper(default: float, *, gt: float | None = None, ge: float | None = None, le: float | None = None,
          among: tuple[float, ...] = (), sweep: bool = False, tune: str = "") -> Any:
    """A hyperparameter field: its default and range, and whether `ragnav sweep` / `ragnav tune` vary it."""
    if tune not in ("", "log", "logit", "raw"):
        raise ValueError(f"tune must be '', log, logit or raw, got {tune!r}")
    return dataclasses.field(default=default, metadata={"hyper": Hyper(gt, ge, le, among, sweep, tune)})


@functools.cache
def hyperparameters(section: type) -> typing.Mapping[str, Hyper]:
    """The section's hyperparameter table in field order: name -> Hyper (range, sweep, tune, type, default)."""
    hints = typing.get_type_hints(section)
    return types.MappingProxyType({
        f.name: dataclasses.replace(f.metadata["hyper"], name=f.name, type=hints[f.name], default=f.default)
        for f in dataclasses.fields(section) if "hyper" in f.metadata})


def _check_hyperparameters(cfg: Any, section: str) -> None:
    for name, h in hyperparameters(type(cfg)).items():
        h.check(f"{section}.{name}", (getattr(cfg, name),))


@dataclasses.dataclass(frozen=True)
class WorldConfig:
    """Procedural house generator settings (ragnav generate)."""

    num_scenes: int = 4
    min_rooms: int = 4
    max_rooms: int = 9
    min_objects: int = 25  # per scene
    max_objects: int = 70
    room_side: tuple[float, float] = (3.0, 6.5)  # metres, range of a room's target side length
    door_width: float = 1.0  # metres
    extra_door_prob: float = 0.35  # chance of a door between adjacent rooms beyond the spanning tree
    min_distractor_categories: int = 3  # categories that appear at least twice per scene
    room_types: tuple[str, ...] = ROOM_TYPES  # the seen default becomes the unseen types under split=unseen
    name_prefix: str = "house"
    split: str = "seen"  # seen | unseen: catalogue, room types and attribute kinds (world/vocabulary.py)

    def __post_init__(self):
        _check(self.num_scenes >= 1, "world.num_scenes", "must be >= 1")
        _check(1 <= self.min_rooms <= self.max_rooms, "world.min_rooms", "need 1 <= min_rooms <= max_rooms")
        _check(self.max_rooms <= 16, "world.max_rooms", "must be <= 16")
        _check(
            1 <= self.min_objects <= self.max_objects, "world.min_objects", "need 1 <= min_objects <= max_objects"
        )
        _check(
            2.0 <= self.room_side[0] <= self.room_side[1], "world.room_side", "need 2.0 <= low <= high (metres)"
        )
        _check(0.6 <= self.door_width <= 2.0, "world.door_width", "must be in [0.6, 2.0] metres")
        _check(0.0 <= self.extra_door_prob <= 1.0, "world.extra_door_prob", "must be in [0, 1]")
        _check(len(self.room_types) >= 1, "world.room_types", "must name at least one room type")
        _check(self.split in ("seen", "unseen"), "world.split", "must be seen or unseen")
        bad_name = name_problem(f"{self.name_prefix}_000")  # scene names PREFIX_000, ... become file names
        _check(bad_name is None, "world.name_prefix", f"scene name {bad_name}")
        if self.split == "unseen" and tuple(self.room_types) == ROOM_TYPES:
            from ragnav_jax.world.vocabulary import ROOM_TYPES_UNSEEN

            object.__setattr__(self, "room_types", ROOM_TYPES_UNSEEN)


@dataclasses.dataclass(frozen=True)
class LLMConfig:
    """Optional OpenAI-compatible chat endpoint, shared by the instruction parser and the captioner.

    An empty base_url means off: everything then runs offline and deterministically. The API key is
    read from the environment variable named by api_key_env at call time and is never stored.
    """

    base_url: str = ""  # e.g. http://127.0.0.1:8000/v1 ; "" = no LLM
    model: str = ""
    api_key_env: str = "OPENAI_API_KEY"  # name of the environment variable holding the key (may be unset)
    timeout_s: float = 30.0
    temperature: float = 0.0
    use_for_parsing: bool = True  # instruction -> TaskChain (falls back to the rule parser on any failure)
    use_for_captions: bool = True  # memory captioner

    def __post_init__(self):
        _check(self.timeout_s > 0, "llm.timeout_s", "must be > 0")
        _check(0.0 <= self.temperature <= 2.0, "llm.temperature", "must be in [0, 2]")
        _check(
            self.base_url == "" or self.base_url.startswith(("http://", "https://")),
            "llm.base_url",
            "must be empty (off) or start with http:// or https://",
        )


@dataclasses.dataclass(frozen=True)
class EpisodesConfig:
    """Episode generator settings (ragnav episodes): counts per scene and modality, goals, order mix."""

    text: int = 10  # episodes per scene whose goals are told apart by words only
    text_location: int = 5  # ... where a coordinate hint is the disambiguator
    text_location_sensor: int = 5  # ... where a sensor reading or superlative is
    min_goals: int = 1
    max_goals: int = 5
    strict_fraction: float = 0.5  # share of episodes with a strict visiting order (the rest: free)
    near_distance: float = 1.0  # metres between object boxes for near / next to / beside / by
    location_radius: float = 1.0  # metres: a coordinate hint refers to objects within this of the point
    location_margin: float = 2.0  # metres: no other candidate within this of a generated hint
    relation_prob: float = 0.3  # chance of describing a goal by a neighbour even when not needed
    room_prob: float = 0.3  # chance of naming the room even when not needed
    synonym_prob: float = 0.3  # chance of a synonym for the category name (couch, TV, bedside table, ...)
    split: str = "seen"  # sentence templates: seen (the generator's own) | unseen_dev .. unseen_dev10
    # (language/phrasings.py, phrasings_dev2.py .. phrasings_dev10.py: parser rounds 2-13 were developed
    # against them, each measured first as the held-out set) | unseen_dev11 (phrasings_dev11.py, set N: the
    # held-out set of round 13, measured fresh, then developed against in round 14) | unseen_dev12
    # (phrasings_dev12.py, set O: written before any parser change after round 14, by an author who never read
    # the parser; measured fresh with rounds 14 and 15, then developed against in round 16) | unseen
    # (phrasings_heldout.py, set P: written before round 16 was measured, by an author who never read the parser)
    # | unseen_q (phrasings_q.py, set Q: a further held-out set by an author who never read the parser)
    # | unseen_r (phrasings_r.py, set R: another held-out set by an author who never read the parser);
    # the names (synonyms, hypernyms) come with the houses' catalogue (episodes.names())
    # time-indexed episodes (ragnav episodes --time-indexed, language/time_episodes.py):
    time_per_scene: int = 12  # queries drawn per explored scene
    time_gap: int = 25  # stream records between the target's view and its neighbours' in the asked order
    time_phrasing: str = "seen"  # seen (the generator's own templates) | heldout, heldout2, heldout3, heldout4
    # (time_text_heldout*.py: sets by authors who never read the reader)

    def __post_init__(self):
        _check(self.time_per_scene >= 1, "episodes.time_per_scene", "must be >= 1")
        _check(self.time_gap >= 0, "episodes.time_gap", "must be >= 0")
        _check(self.time_phrasing in ("seen", "heldout", "heldout2", "heldout3", "heldout4"), "episodes.time_phrasing",
               "must be seen or heldout, heldout2, heldout3, heldout4")
        for k in ("text", "text_location", "text_location_sensor"):
            _check(getattr(self, k) >= 0, f"episodes.{k}", "must be >= 0")
        _check(1 <= self.min_goals <= self.max_goals <= 8, "episodes.min_goals", "need 1 <= min_goals <= max_goals <= 8")
        for k in ("strict_fraction", "relation_prob", "room_prob", "synonym_prob"):
            _check(0.0 <= getattr(self, k) <= 1.0, f"episodes.{k}", "must be in [0, 1]")
        _check(self.near_distance > 0, "episodes.near_distance", "must be > 0")
        _check(self.location_radius > 0, "episodes.location_radius", "must be > 0")
        _check(self.location_margin >= self.location_radius, "episodes.location_margin", "must be >= location_radius")
        _check(self.split in EPISODE_SPLITS, "episodes.split", f"must be one of {', '.join(EPISODE_SPLITS)}")


@dataclasses.dataclass(frozen=True)
class MemoryConfig:
    """Dual-basis memory (ragnav build-memory): key poses, captions, encoder, map edges, semantic forest."""

    # key poses (memory/keyposes.py)
    keyframe_rule: str = "both"  # spacing | novelty | both
    # tuned so that the paper preset's maps average about 80 nodes (README, Memory)
    keyframe_spacing: float = 0.8  # metres: a record with no key pose in sight this close becomes one
    keyframe_min_spacing: float = 0.3  # metres: the novelty rule never adds a key pose closer than this
    novelty_threshold: float = 0.25  # share of never-seen objects in view that makes a record novel
    observation_window: int = 10  # records either side merged into a node's observation (a look around)
    max_objects_per_node: int = 16  # padded width of the node -> observed objects arrays
    # captions (memory/captioner.py); room types are never handed to the captioner
    captioner: str = "template"  # template | llm (uses the llm section)
    caption_detect_near: float = 0.97
    caption_detect_falloff: float = 4.0  # metres
    caption_confusion: float = 0.03
    caption_synonym: float = 0.35
    caption_attribute_keep: float = 0.6
    caption_sensor_text: float = 0.7
    caption_max_objects: int = 8
    # text encoder (memory/encoder.py)
    embedder: str = "minilm"  # minilm | hashing
    hashing_dim: int = 384
    embed_batch: int = 32
    token_buckets: tuple[int, ...] = (16, 32, 64, 128, 256)
    # topological map (memory/topomap.py)
    delta_spatial: float = 2.0  # metres: edge when D_ij < delta_spatial ...
    edge_clearance: float = 0.05  # ... and the straight segment clears walls and objects by this much
    node_pad_multiple: int = 16  # padded node counts are multiples of this (fewer recompiles)
    # semantic forest (memory/forest.py)
    omega: float = 0.5  # S_ij = omega * Phi_spatial + (1 - omega) * Psi_semantic
    alpha: float = 0.5  # F_i = alpha * Norm(f_spa) + (1 - alpha) * Norm(f_sem)
    spatial_scale: float = 3.0  # metres: Phi_spatial = exp(-d_ij / spatial_scale)
    spatial_distance: str = "geodesic"  # geodesic (shortest path over G_t) | euclidean
    forest_metric: str = "hybrid"  # hybrid: 1 - S_ij | fused: Euclidean distance of fused features F_i
    linkage: str = "average"  # average | single | complete | weighted | ward
    level_sizes: tuple[float, ...] = (5.0, 16.0)  # mean leaves per cluster of each level above the leaves
    summariser: str = "template"  # template | llm

    def __post_init__(self):
        _check(self.keyframe_rule in ("spacing", "novelty", "both"), "memory.keyframe_rule",
               "must be spacing, novelty or both")
        _check(self.keyframe_spacing > 0, "memory.keyframe_spacing", "must be > 0")
        _check(0 <= self.keyframe_min_spacing, "memory.keyframe_min_spacing", "must be >= 0")
        _check(0.0 < self.novelty_threshold <= 1.0, "memory.novelty_threshold", "must be in (0, 1]")
        _check(self.observation_window >= 0, "memory.observation_window", "must be >= 0")
        _check(self.max_objects_per_node >= 1, "memory.max_objects_per_node", "must be >= 1")
        _check(self.captioner in ("template", "llm"), "memory.captioner", "must be template or llm")
        for k in ("caption_detect_near", "caption_confusion", "caption_synonym", "caption_attribute_keep",
                  "caption_sensor_text"):
            _check(0.0 <= getattr(self, k) <= 1.0, f"memory.{k}", "must be in [0, 1]")
        _check(self.caption_detect_falloff > 0, "memory.caption_detect_falloff", "must be > 0")
        _check(self.caption_max_objects >= 1, "memory.caption_max_objects", "must be >= 1")
        _check(self.embedder in ("minilm", "hashing"), "memory.embedder", "must be minilm or hashing")
        _check(self.hashing_dim >= 8, "memory.hashing_dim", "must be >= 8")
        _check(self.embed_batch >= 8, "memory.embed_batch", "must be >= 8")
        _check(len(self.token_buckets) >= 1 and all(b >= 4 for b in self.token_buckets), "memory.token_buckets",
               "must list token lengths >= 4")
        _check(self.delta_spatial > 0, "memory.delta_spatial", "must be > 0")
        _check(self.edge_clearance >= 0, "memory.edge_clearance", "must be >= 0")
        _check(self.node_pad_multiple >= 1, "memory.node_pad_multiple", "must be >= 1")
        _check(0.0 <= self.omega <= 1.0, "memory.omega", "must be in [0, 1]")
        _check(0.0 <= self.alpha <= 1.0, "memory.alpha", "must be in [0, 1]")
        _check(self.spatial_scale > 0, "memory.spatial_scale", "must be > 0")
        _check(self.spatial_distance in ("geodesic", "euclidean"), "memory.spatial_distance",
               "must be geodesic or euclidean")
        _check(self.forest_metric in ("hybrid", "fused"), "memory.forest_metric", "must be hybrid or fused")
        _check(self.linkage in ("average", "single", "complete", "weighted", "ward"), "memory.linkage",
               "must be average, single, complete, weighted or ward")
        _check(len(self.level_sizes) >= 2 and all(s >= 1.0 for s in self.level_sizes)
               and list(self.level_sizes) == sorted(self.level_sizes), "memory.level_sizes",
               "needs at least two increasing sizes >= 1 (leaf - subtree - forest: three levels or more)")
        _check(self.summariser in ("template", "llm"), "memory.summariser", "must be template or llm")


@dataclasses.dataclass(frozen=True)
class SimConfig:
    """MJX simulation (ragnav explore): the planar robot, its sensors and the physics/control rates."""

    timestep: float = 0.025  # seconds per physics step
    substeps: int = 4  # physics steps per control step (control at 1 / (timestep * substeps) Hz)
    robot_radius: float = 0.15  # metres, collision sphere
    robot_height: float = 0.2  # metres, sphere centre above the floor (flat things below it never touch)
    max_speed: float = 0.8  # m/s
    max_yaw_rate: float = 2.5  # rad/s
    lidar_rays: int = 144  # evenly spread over lidar_fov_deg
    lidar_fov_deg: float = 360.0
    lidar_range: float = 6.0  # metres; a ray hitting nothing reports this
    lidar_height: float = 0.25  # metres above the floor
    camera_fov_deg: float = 90.0  # horizontal field of view of the forward camera
    camera_range: float = 4.0  # metres, planar distance to an object's centre
    camera_height: float = 0.8  # metres
    odom_noise: tuple[float, float] = (0.0, 0.0)  # std of recorded pose noise: (x/y metres, yaw radians)
    max_contact_pairs: int = 16  # robot-vs-box pairs collided per physics step (nearest by bounding sphere)
    # Largest scene explore accepts: every wall and object is an MJX geom each lidar ray and contact test
    # sees, and every object a column of the (records, objects) stream arrays (world/limits.py)
    max_walls: int = 4096
    max_objects: int = 4096

    def __post_init__(self):
        _check(0 < self.timestep <= 0.05, "sim.timestep", "must be in (0, 0.05] seconds")
        _check(1 <= self.substeps <= 50, "sim.substeps", "must be in [1, 50]")
        _check(0.05 <= self.robot_radius <= 0.5, "sim.robot_radius", "must be in [0.05, 0.5] metres")
        _check(self.robot_height >= self.robot_radius, "sim.robot_height", "must be >= sim.robot_radius")
        _check(self.max_speed > 0 and self.max_yaw_rate > 0, "sim.max_speed", "speeds must be > 0")
        _check(1 <= self.lidar_rays <= 2048, "sim.lidar_rays", "must be in [1, 2048]")
        _check(0 < self.lidar_fov_deg <= 360, "sim.lidar_fov_deg", "must be in (0, 360]")
        _check(self.lidar_range > 0 and self.camera_range > 0, "sim.lidar_range", "ranges must be > 0")
        _check(0 < self.camera_fov_deg < 360, "sim.camera_fov_deg", "must be in (0, 360)")
        _check(min(self.odom_noise) >= 0, "sim.odom_noise", "standard deviations must be >= 0")
        _check(self.max_contact_pairs >= 1, "sim.max_contact_pairs", "must be >= 1")
        _check(self.max_walls >= 1 and self.max_objects >= 1, "sim.max_walls", "max_walls and max_objects must be >= 1")


@dataclasses.dataclass(frozen=True)
class ExploreConfig:
    """Frontier exploration (ragnav explore): grids, frontier rules, controller and step budget."""

    grid_resolution: float = 1.0  # metres, the paper's exploration grid (frontier regions are clustered on it)
    map_resolution: float = 0.2  # metres, the occupancy raster beneath it (free / occupied / unknown, paths)
    min_frontier_cells: int = 3  # frontier regions with fewer map cells are dropped as noise
    target_rule: str = "path"  # "euclidean" (the paper: nearest frontier point) or "path" (shortest path)
    clearance: float = 0.15  # metres kept between the robot's sphere and mapped obstacles when planning
    lookahead: float = 0.4  # metres, pure-pursuit lookahead of the waypoint controller
    arrive_tol: float = 0.25  # metres from a frontier target that count as arrived
    goal_timeout: int = 100  # control steps allowed beyond 3x the nominal drive time before a target is given up
    stall_steps: int = 30  # control steps without progress (< 2 mm each) before a target is given up
    look_sweep_deg: float = 60.0  # camera heading sweeps this far either side of the motion (0: look ahead)
    look_period: float = 4.0  # seconds per sweep cycle
    camera_frontiers: bool = True  # also visit free space the camera has not looked at (the paper: lidar only)
    max_steps: int = 5000  # control steps per scene (the step budget)
    scan_every: int = 1  # control steps between lidar/camera records (and map updates)
    batch_size: int = 8  # scenes explored together in one vmapped call

    def __post_init__(self):
        _check(
            0 < self.map_resolution <= 0.5,
            "explore.map_resolution",
            "must be in (0, 0.5] metres to resolve 10 cm walls and 1 m doors (the paper's 1.0 m grid is explore.grid_resolution)",
        )
        ratio = self.grid_resolution / self.map_resolution if self.map_resolution > 0 else 0
        _check(
            ratio >= 1 and abs(ratio - round(ratio)) < 1e-6,
            "explore.grid_resolution",
            "must be a whole multiple of explore.map_resolution",
        )
        _check(self.min_frontier_cells >= 1, "explore.min_frontier_cells", "must be >= 1")
        _check(self.target_rule in ("euclidean", "path"), "explore.target_rule", "must be 'euclidean' or 'path'")
        _check(self.clearance >= 0, "explore.clearance", "must be >= 0")
        _check(self.lookahead > 0 and self.arrive_tol > 0, "explore.lookahead", "distances must be > 0")
        _check(self.goal_timeout >= 1, "explore.goal_timeout", "must be >= 1")
        _check(self.stall_steps >= 1, "explore.stall_steps", "must be >= 1")
        _check(0 <= self.look_sweep_deg <= 180, "explore.look_sweep_deg", "must be in [0, 180]")
        _check(self.look_period > 0, "explore.look_period", "must be > 0")
        _check(self.max_steps >= 1, "explore.max_steps", "must be >= 1")
        _check(self.scan_every >= 1, "explore.scan_every", "must be >= 1")
        _check(self.batch_size >= 1, "explore.batch_size", "must be >= 1")


@dataclasses.dataclass(frozen=True)
class PlanningConfig:
    """Order planning (paper's Pi* objective), paths and guide (ragnav_jax/planning)."""

    lam: float = hyper(1.0e4, ge=0, sweep=True)  # metres charged per goal pair visited against the instruction
    # order; 0 = free. Read by `ragnav plan` and the closed loop for strict instructions; the default keeps their
    # order (a strict episode visited out of order fails), smaller values trade the order for travel (sweep.axes.lam:
    # navigation metrics only)
    solver: str = "auto"  # auto (Held-Karp up to 16 goals, else local search) | brute_force | held_karp | local_search
    local_search_iters: int = 100  # improving moves per start at most
    top_k: int = 1  # candidates per goal; > 1 chooses candidate and order jointly (Held-Karp)
    candidate_weight: float = 0.0  # metres per unit of retrieval-score deficit of a lower-ranked candidate
    max_path_nodes: int = 128  # static length of jitted node paths
    turn_threshold_deg: float = 30.0  # heading changes below this are not announced in the guide

    def __post_init__(self):
        _check_hyperparameters(self, "planning")
        solvers = ("auto", "brute_force", "held_karp", "local_search")
        _check(self.solver in solvers, "planning.solver", f"must be one of {', '.join(solvers)}")
        _check(self.local_search_iters >= 1, "planning.local_search_iters", "must be >= 1")
        _check(1 <= self.top_k <= 8, "planning.top_k", "must be in [1, 8]")
        _check(self.candidate_weight >= 0.0, "planning.candidate_weight", "must be >= 0")
        _check(self.max_path_nodes >= 2, "planning.max_path_nodes", "must be >= 2")
        _check(0.0 < self.turn_threshold_deg < 150.0, "planning.turn_threshold_deg", "must be in (0, 150)")


@dataclasses.dataclass(frozen=True)
class ChangesConfig:
    """How `ragnav changes` draws what changes in a house after exploration (world/changes.py)."""

    fraction: float = 0.25  # object changes per object of the house (moves, removals, additions)
    move: float = 0.5  # the kinds' proportions among object changes
    remove: float = 0.25
    add: float = 0.25
    other_room: float = 0.5  # chance that a moved object goes to another room
    doors: int = 1  # doors closed (each only where every room and object stays reachable)

    @property
    def weights(self) -> tuple[tuple[str, float], ...]:
        return (("move", self.move), ("remove", self.remove), ("add", self.add))

    def __post_init__(self):
        _check(0.0 <= self.fraction <= 1.0, "changes.fraction", "must be in [0, 1]")
        for k, w in self.weights:
            _check(w >= 0.0, f"changes.{k}", "must be >= 0")
        _check(self.move + self.remove + self.add > 0, "changes.move", "one of move, remove, add must be > 0")
        _check(0.0 <= self.other_room <= 1.0, "changes.other_room", "must be in [0, 1]")
        _check(self.doors >= 0, "changes.doors", "must be >= 0")


@dataclasses.dataclass(frozen=True)
class RunConfig:
    """Where run folders go."""

    root: str = "runs"


@dataclasses.dataclass(frozen=True)
class RetrievalConfig:
    """Retrieval hyperparameters (see ragnav_jax/retrieval/params.py) and the method to run.

    The hyperparameter table: each `hyper` field is written once here with its default and valid range, whether
    it is a sweep axis (SweepAxes) and whether `ragnav tune` moves it, optimised as log(x), logit(x) or raw x
    (evaluation/tune.py). RetrievalParams has these fields and the ablation flags; its integer fields are the
    int ones here.
    """

    method: str = "ragnav"  # ragnav | ragnav:no_forest | ragnav:no_topology | ragnav:no_spatial | ragnav:no_boost | naive_rag | graphrag | lightrag
    sigma: float = hyper(2.0, gt=0, sweep=True, tune="log")  # metres, S_spatial Gaussian width
    eta: float = hyper(0.3, sweep=True, tune="log")  # neighbour boosting coefficient
    top_k: int = hyper(8, ge=1, le=16, sweep=True)  # anchor-guided recall size K (params.MAX_K)
    hops: int = hyper(2, ge=0, le=3, sweep=True)  # anchor validation neighbourhood, hops (params.MAX_HOPS)
    boost_hops: int = hyper(1, ge=0, le=1, sweep=True)  # neighbour boosting neighbourhood, hops
    beam: int = hyper(32, ge=1, le=32, sweep=True)  # forest beam width per level (params.MAX_BEAM) when a room
    # phrase locks a region
    anchor_threshold: float = hyper(0.45, sweep=True, tune="raw")  # similarity for a node to match the anchor
    boost_threshold: float = hyper(0.45, sweep=True, tune="raw")  # score a neighbour needs to count as relevant
    w_slot: float = hyper(0.7, sweep=True, tune="logit")  # instance phrase vs node fingerprint
    match_threshold: float = hyper(0.45, sweep=True)  # head-noun similarity for an instance to count as the
    # category (superlatives)
    sigma_loc: float = hyper(1.5, gt=0, sweep=True, tune="log")  # metres, location hint Gaussian width
    sigma_rel: float = hyper(3.0, gt=0)  # metres, instance-level "A near B" Gaussian width (ours; retrieval/score.py)
    w_loc: float = hyper(1.0, sweep=True, tune="log")  # exponent of the location term (0 ignores hints)
    w_sensor: float = hyper(1.0, sweep=True, tune="log")  # exponent of the sensor term (0 ignores sensor constraints)
    w_time: float = hyper(1.0, ge=0, sweep=True)  # exponent of the time term ("the mug you saw first"; 0 ignores it)
    w_recency: float = hyper(0.0, ge=0, sweep=True)  # recency: an instance last seen at relative age a in [0, 1]
    # of the memory's span scores exp(-w_recency * a) (0: off, the paper)
    w_room: float = hyper(1.0)  # soft room term from the forest's summary labels (0: off)
    tau_room: float = hyper(0.05)  # softness of the room term (similarity units)
    forest_lock: float = hyper(0.0, among=(0.0, 1.0))  # 1: a room phrase also prunes the leaves outside the beam's
    # region (the paper's hard hierarchical pruning); 0: the forest's labels rank regions through the soft room
    # term only (ours; see README)

    def __post_init__(self):
        _check_hyperparameters(self, "retrieval")


# sweep.axes: the sweepable hyperparameters (sweep=True) of the retrieval section, then the planning lambda.
_SWEEPABLE = {name: h for section in (RetrievalConfig, PlanningConfig)
              for name, h in hyperparameters(section).items() if h.sweep}


def _check_axes(axes) -> None:
    for name, h in _SWEEPABLE.items():
        values = getattr(axes, name)
        _check(len(set(values)) == len(values), f"sweep.axes.{name}", "values must be distinct")
        h.check(f"sweep.axes.{name}", values)


SweepAxes = dataclasses.make_dataclass(
    "SweepAxes",
    [(name, tuple[h.type, ...], dataclasses.field(default=())) for name, h in _SWEEPABLE.items()],
    namespace={"__module__": __name__, "__post_init__": _check_axes,
               "__doc__": "Values of each swept hyperparameter (empty: not varied, the retrieval/planning section's "
                          "value). One field per sweepable hyperparameter (RetrievalConfig, then planning.lam)."},
    frozen=True,
)


@dataclasses.dataclass(frozen=True)
class SweepConfig:
    """Hyperparameter grid (ragnav sweep): the product of the axes, times the ablation variants."""

    axes: SweepAxes = dataclasses.field(default_factory=SweepAxes)
    variants: tuple[str, ...] = ("ragnav",)  # names from retrieval/params.py ABLATIONS, same batched call
    chunk_size: int = 256  # grid points per device per compiled call (a chunk, and checkpoint, has n times more)
    checkpoint: bool = True  # save each finished chunk (orbax) so a killed sweep resumes where it stopped
    shard: bool = True  # split each chunk's grid points over all devices (jax.sharding)
    heatmap: tuple[str, str] = ("sigma", "eta")  # axes of the heatmaps (x, y); other axes: best value
    pause_s: float = 0.0  # wait after each chunk (demos and the kill-and-resume test); 0 in real runs

    def __post_init__(self):
        # variant names are checked against retrieval/params.py ABLATIONS when the sweep starts (no jax here)
        _check(len(self.variants) >= 1 and len(set(self.variants)) == len(self.variants), "sweep.variants",
               "must list one or more distinct ablation variants")
        _check(self.chunk_size >= 1, "sweep.chunk_size", "must be >= 1")
        names = [f.name for f in dataclasses.fields(SweepAxes)]
        _check(all(h in names for h in self.heatmap) and self.heatmap[0] != self.heatmap[1], "sweep.heatmap",
               f"two different axes among {', '.join(names)}")
        _check(self.pause_s >= 0, "sweep.pause_s", "must be >= 0")


TUNABLE = tuple(name for name, h in hyperparameters(RetrievalConfig).items() if h.tune)  # RetrievalConfig order


@dataclasses.dataclass(frozen=True)
class TuneConfig:
    """Gradient tuning of the continuous retrieval hyperparameters (ragnav tune), optax on a surrogate."""

    params: tuple[str, ...] = TUNABLE  # which RetrievalParams fields move
    steps: int = 200  # optimiser steps (full batch of the training split)
    learning_rate: float = 0.03  # Adam, on log / logit / raw parameters (see evaluation/tune.py)
    eval_every: int = 20  # steps per compiled segment; training accuracy is checked between segments
    temperature: float = 0.05  # initial softmax temperature of the surrogate (learned with the rest)
    gate_tau: float = 0.05  # softness of the threshold gates' straight-through gradients
    train_fraction: float = 0.5  # share of each (scene, modality)'s episodes in the training split
    split_seed: int = 0
    init: str = "grid"  # grid: start from the best sweep point on the training split | config: from retrieval
    closed_loop: bool = False  # also run RAGNav's closed loop (the device engine) on the held-out episodes with the
    # config's, the best grid point's and the tuned values: held-out navigation success next to retrieval accuracy

    def __post_init__(self):
        _check(len(self.params) >= 1 and all(x in TUNABLE for x in self.params), "tune.params",
               f"must name one or more of {', '.join(TUNABLE)}")
        _check(self.steps >= 1 and self.eval_every >= 1, "tune.steps", "steps and eval_every must be >= 1")
        _check(self.learning_rate > 0 and self.temperature > 0 and self.gate_tau > 0, "tune.learning_rate",
               "learning_rate, temperature and gate_tau must be > 0")
        _check(0.0 < self.train_fraction < 1.0, "tune.train_fraction", "must be in (0, 1)")
        _check(self.init in ("grid", "config"), "tune.init", "must be grid or config")


@dataclasses.dataclass(frozen=True)
class EvalConfig:
    """Closed-loop navigation evaluation (`ragnav eval`, ragnav_jax/evaluation/navigate.py)."""

    method: str = "ragnav"  # see evaluation/methods.py NAV_METHODS
    candidates: int = 4  # retrieved candidates per subgoal (top-k) the reflection may fall back to
    retries: int = 3  # rejected candidates per goal before it is given up
    max_steps: int = 3000  # control steps per episode (the step budget; 0.1 s each by default)
    leg_max_steps: int = 1200  # control steps one leg may take before it is cut
    observe_every: int = 20  # ragnav:online: control steps between the forward camera's frames it keeps while driving
    tour_radius: float = 3.0  # ragnav:online: search over, a key pose farther than this from every look-around is unseen
    found_radius: float = 1.0  # metres from the goal's box within which FOUND counts (MultiON)
    approach_gap: float = 0.45  # metres from the target's box the robot stops at before declaring
    arrive_tol: float = 0.3  # metres from a leg's last waypoint that count as arrived
    stall_steps: int = 40  # control steps without progress (< 2 mm each) that end a leg as stuck
    look_headings: int = 8  # camera headings of the look-around on arrival (a turn in place)
    path_points: int = 128  # static waypoint buffer per leg
    strict_lam: float = 1.0e4  # order penalty of the shortest route SPL measures a strict episode against (metres
    # per order inversion; the loop itself keeps a strict instruction's order)
    batch_size: int = 512  # episodes executed together in one vmapped call (device engine: lanes; an episode that
    # ends hands its lane to the next one queued, so lanes do not wait for the batch's longest episode)
    engine: str = "host"  # "device": the whole closed loop as one jitted program (evaluation/loop/; not etpnav,
    # traces or record_legs, which run on the host loop); "host": the host state machine of evaluation/host_loop.py
    refill: float = 0.125  # device engine: share of the lanes (eval.batch_size) one reflection serves. The loop
    # drives until that many lanes need a reflection (legs ended, episodes to load) and reflects on just those,
    # gathered into a batch of that size, while the others drive on (1.0: every lane, after every leg of the batch
    # has ended). Rows do not depend on it; speed and compilation do (README: The device loop)
    reflections: str = "auto"  # device engine: "serial" reflects on its lanes one after another (lax.map: each
    # lane runs only its own branches and grid searches), "batched" on all at once (vmap: every branch computed
    # for every lane, as a GPU wants), "auto" serial on a CPU. Rows do not depend on it
    look_closer: bool = True  # not confirmed at the key pose: drive towards the retrieved instance and look again
    record_legs: bool = False  # keep every leg's driven waypoints and simulated end pose in the episode rows (plots)
    precheck: bool = True  # RAGNav's candidates: drop those the memory's own captions contradict (category, attribute)
    # or whose estimated position lies beyond a coordinate hint's radius, before driving (see README)
    widen: bool = True  # RAGNav's candidates: after those the hard constraints kept (forest lock, anchor validation),
    # the best of the nodes they dropped, so a rejected region or anchor does not end the goal (see docs)
    closest_view: bool = True  # RAGNav's legs end at the key pose that recorded the retrieved instance from
    # closest, not at the best-scoring one (see README)
    fallback: bool = True  # candidates and search run out: approach and declare the object seen for the goal that
    # fails fewest parts of its check (`Verifier.misfits`; the name must fit), rather than give the goal up (README)
    search_nodes: int = 4  # candidates run out: key poses searched where the instruction puts the goal, its room
    # or coordinate hint (0 = none; evaluation/search.py)
    ground: bool = True  # parsed goals are grounded in the memory's names before retrieval: misread heads repaired,
    # goals naming nothing it knows dropped (evaluation/grounding.py)
    ground_described: bool = True  # grounding also gives each goal the words its span says of it after its name
    # that the house's captions describe things by ("the work light described as teal"), and the room named there
    # where it has none ("whose berth is the laundry room"; grounding.after_name)
    tagger: bool = True  # the parse is reconciled with the instruction tagger before grounding: remarks it is sure
    # name no goal dropped, goal phrases it is sure of and the parse missed added (language/tagger.py)
    tagger_file: str = ""  # tagger.npz (`ragnav fit-tagger`; "" = ragnav_jax/data/tagger.npz)
    tagger_conf: float = 0.0  # probability above which the tagger's reading overrides the parse (0 = the value
    # fitted with the tagger on seen-split houses, `ragnav fit-tagger`)
    tagger_clauses: bool = True  # a goal the tagger adds is what the rule parser reads in its own clause (its
    # attributes, room, relations, sensors), not the bare tagged phrase (language/tagger.py: reconcile)
    tagger_anchors: bool = True  # an anchor the parse read as a goal and the tagger drops is the anchor (near) of the
    # goal before, where the parse gave that one none ("the workbench immediately adjoining the work lamp")
    clause_anchors: bool = True  # a goal the tagger finds in place and the parse gave no relation takes the anchor the
    # tagger finds in its clause, and an anchor's relation (here and above) is the one the words before it say,
    # read by the encoder against the lexicon's relation phrases, not always near (grounding.RelationWords)
    likely_anchors: bool = True  # a parsed goal whose every occurrence the tagger finds likelier an anchor's than not
    # (tagger.ADD_CONF) is an anchor read as a goal, not only where it is sure (eval.tagger_conf): on every
    # development set no true goal's words are, while two thirds of the anchors read as goals are
    tagger_regroup: bool = True  # what the parse put in the wrong place goes where the tagger reads it: a goal phrase it
    # finds likelier a goal's than not inside an anchor the parse misread (closed-class words in its head: "the bonsai,
    # and at the last repair unto the easel") is a goal, and that anchor goes; a remark's reading or coordinate hint is
    # the goal before's ("the appliance (room: garage) with the highest temperature of the lot"; tagger.reconcile)
    sensor_reader: bool = True  # after the tagger and grounding, each goal's sensor comparison read again by the
    # learned reader where it is sure: its direction turned, a missed superlative or bound added (language/sensor_reader.py)
    sensor_reader_file: str = ""  # sensor_reader.npz (`ragnav fit-sensor-reader`; "" = ragnav_jax/data/sensor_reader.npz)
    sensor_reader_conf: float = 0.0  # probability above which the reader's way overrides the parse (0 = the value
    # fitted with the reader on seen-split houses)
    verifier_file: str = ""  # fitted.json with the verifier's thresholds ("" = ragnav_jax/data/fitted.json)
    verify_attribute_keep: float = 0.9  # close-range perception for the check: chance an attribute is said
    verify_confusion: float = 0.01  # ... and chance the object is named as a similar category
    verify_looks: int = 3  # close-range looks at an object on arrival (the look-around); an attribute said in one counts

    def __post_init__(self):
        _check(self.candidates >= 1 and self.retries >= 0, "eval.candidates", "candidates >= 1 and retries >= 0")
        _check(self.search_nodes >= 0, "eval.search_nodes", "must be >= 0")
        _check(self.engine in ("host", "device"), "eval.engine", "must be 'host' or 'device'")
        _check(0.0 < self.refill <= 1.0, "eval.refill", "must be in (0, 1]")
        _check(self.reflections in ("auto", "serial", "batched"), "eval.reflections",
               "must be 'auto', 'serial' or 'batched'")
        _check(self.tagger_conf == 0.0 or 0.5 <= self.tagger_conf < 1.0, "eval.tagger_conf", "must be 0 or in [0.5, 1)")
        _check(self.sensor_reader_conf == 0.0 or 0.5 <= self.sensor_reader_conf < 1.0, "eval.sensor_reader_conf",
               "must be 0 or in [0.5, 1)")
        _check(self.max_steps >= 1 and self.leg_max_steps >= 1, "eval.max_steps", "step budgets must be >= 1")
        _check(self.observe_every >= 1, "eval.observe_every", "must be >= 1")
        _check(self.tour_radius > 0, "eval.tour_radius", "must be > 0")
        _check(self.found_radius > 0 and self.approach_gap >= 0, "eval.found_radius", "must be > 0")
        _check(self.look_headings >= 1 and self.path_points >= 2 and self.batch_size >= 1, "eval.look_headings",
               "look_headings >= 1, path_points >= 2, batch_size >= 1")


@dataclasses.dataclass(frozen=True)
class Config:
    """The whole resolved configuration of a run."""

    seed: int = 0
    world: WorldConfig = dataclasses.field(default_factory=WorldConfig)
    changes: ChangesConfig = dataclasses.field(default_factory=ChangesConfig)
    run: RunConfig = dataclasses.field(default_factory=RunConfig)
    sim: SimConfig = dataclasses.field(default_factory=SimConfig)
    explore: ExploreConfig = dataclasses.field(default_factory=ExploreConfig)
    memory: MemoryConfig = dataclasses.field(default_factory=MemoryConfig)
    llm: LLMConfig = dataclasses.field(default_factory=LLMConfig)
    episodes: EpisodesConfig = dataclasses.field(default_factory=EpisodesConfig)
    planning: PlanningConfig = dataclasses.field(default_factory=PlanningConfig)
    retrieval: RetrievalConfig = dataclasses.field(default_factory=RetrievalConfig)
    sweep: SweepConfig = dataclasses.field(default_factory=SweepConfig)
    tune: TuneConfig = dataclasses.field(default_factory=TuneConfig)
    eval: EvalConfig = dataclasses.field(default_factory=EvalConfig)


# ----------------------------------------------------------------------------------------------------
# Building dataclasses from plain data, with type checks.


def _type_name(tp: Any) -> str:
    return getattr(tp, "__name__", None) or str(tp).replace("typing.", "")


def _coerce(value: Any, tp: Any, key: str) -> Any:
    """Checks `value` against the annotation `tp`; returns it converted (lists to tuples, int to float)."""
    origin = typing.get_origin(tp)
    if dataclasses.is_dataclass(tp):
        if not isinstance(value, dict):
            raise ConfigError(f"config key '{key}': expected a mapping (section), got {value!r}")
        return _build(tp, value, key)
    if origin in (typing.Union, types.UnionType):
        args = typing.get_args(tp)
        if value is None and type(None) in args:
            return None
        errors = []
        for arg in args:
            if arg is type(None):
                continue
            try:
                return _coerce(value, arg, key)
            except ConfigError as e:
                errors.append(str(e))
        raise ConfigError(f"config key '{key}': expected {_type_name(tp)}, got {value!r}")
    if origin is tuple:
        args = typing.get_args(tp)
        if not isinstance(value, (list, tuple)):
            raise ConfigError(f"config key '{key}': expected a list, got {value!r}")
        if len(args) == 2 and args[1] is Ellipsis:
            return tuple(_coerce(v, args[0], f"{key}[{i}]") for i, v in enumerate(value))
        if len(value) != len(args):
            raise ConfigError(f"config key '{key}': expected a list of {len(args)} items, got {value!r}")
        return tuple(_coerce(v, a, f"{key}[{i}]") for i, (v, a) in enumerate(zip(value, args)))
    if tp is bool:
        if not isinstance(value, bool):
            raise ConfigError(f"config key '{key}': expected true/false, got {value!r}")
        return value
    if tp is int:
        if isinstance(value, bool) or not isinstance(value, int):
            raise ConfigError(f"config key '{key}': expected an integer, got {value!r}")
        return value
    if tp is float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise ConfigError(f"config key '{key}': expected a number, got {value!r}")
        if not math.isfinite(value):
            raise ConfigError(f"config key '{key}': expected a finite number, got {value!r}")
        return float(value)
    if tp is str:
        if not isinstance(value, str):
            raise ConfigError(f"config key '{key}': expected a string, got {value!r}")
        return value
    raise TypeError(f"unsupported config annotation {tp!r} for {key}")  # a programming error


def _build(cls: type, data: dict, prefix: str = "") -> Any:
    hints = typing.get_type_hints(cls)
    names = [f.name for f in dataclasses.fields(cls)]
    kwargs = {}
    for k, v in data.items():
        key = f"{prefix}.{k}" if prefix else str(k)
        if k not in names:
            raise ConfigError(f"unknown config key '{key}' (known here: {', '.join(names)})")
        kwargs[k] = _coerce(v, hints[k], key)
    return cls(**kwargs)


def config_from_dict(data: dict) -> Config:
    """Builds a Config from nested plain data (as read from YAML)."""
    if data is None:
        data = {}
    if not isinstance(data, dict):
        raise ConfigError(f"config must be a mapping at the top level, got {type(data).__name__}")
    return _build(Config, data)


def to_dict(cfg: Any) -> dict:
    """Plain nested data (tuples as lists) for YAML/JSON output."""

    def plain(v):
        if dataclasses.is_dataclass(v):
            return {f.name: plain(getattr(v, f.name)) for f in dataclasses.fields(v)}
        if isinstance(v, (list, tuple)):
            return [plain(x) for x in v]
        return v

    return plain(cfg)


def apply_overrides(data: dict, overrides: typing.Iterable[str]) -> dict:
    """Applies `a.b.c=value` overrides (values parsed as YAML scalars/lists) to nested data."""
    data = dict(data or {})
    for item in overrides:
        if "=" not in item:
            raise ConfigError(f"override '{item}' must look like key.sub=value")
        key, raw = item.split("=", 1)
        key = key.strip()
        if not key:
            raise ConfigError(f"override '{item}' has an empty key")
        try:
            value = yaml.safe_load(raw) if raw.strip() else ""
        except yaml.YAMLError as e:
            raise ConfigError(f"override '{key}': cannot read value {raw!r} ({e.__class__.__name__})") from None
        node = data
        parts = key.split(".")
        for depth, part in enumerate(parts[:-1]):
            child = node.get(part, {})
            if not isinstance(child, dict):
                raise ConfigError(f"override '{key}': '{'.'.join(parts[: depth + 1])}' is not a section")
            child = dict(child)
            node[part] = child
            node = child
        node[parts[-1]] = value
    return data


def read_yaml(path: str | Path) -> dict:
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as e:
        raise ConfigError(f"{path}: cannot read config ({e.strerror})") from None
    except UnicodeDecodeError as e:
        raise ConfigError(f"{path}: not a YAML config (not UTF-8 text: undecodable byte at offset {e.start})") from None
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as e:
        mark = getattr(e, "problem_mark", None)
        where = f" line {mark.line + 1}" if mark is not None else ""
        raise ConfigError(f"{path}:{where} not valid YAML ({getattr(e, 'problem', e)})") from None
    if data is None:
        return {}
    if not isinstance(data, dict):
        raise ConfigError(f"{path}: config must be a mapping at the top level")
    return data


def load_config(path: str | Path | None = None, overrides: typing.Iterable[str] = ()) -> Config:
    """Loads a YAML config (defaults when `path` is None) and applies dotted overrides."""
    data = read_yaml(path) if path is not None else {}
    data = apply_overrides(data, overrides)
    try:
        return config_from_dict(data)
    except ConfigError as e:
        if path is not None:
            raise ConfigError(f"{path}: {e}") from None
        raise


def dump_yaml(cfg: Config) -> str:
    return yaml.safe_dump(to_dict(cfg), sort_keys=False)
