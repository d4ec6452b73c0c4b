"""Pytrees of the device closed loop: per-scene world arrays, per-episode inputs, per-episode state, flags.

Leading axes: B scenes of the memory bank, E episodes. Padded sizes: N key poses, O scene objects (the
executor's template), G goals run per episode, C candidates per goal, S search key poses per goal, T true
goals per episode. -1 pads every index array.
"""

from __future__ import annotations

from typing import NamedTuple

import jax
from flax import struct

# Leg kinds (what the robot is doing between two reflections).
NONE, NAV, SEARCH, CLOSER, APPROACH = 0, 1, 2, 3, 4
LEG_NAMES = ("none", "nav", "search", "closer", "approach")

# Goal status codes; the host rows spell them as evaluation/host_loop.py does.
PENDING, FOUND, WRONG = 0, 1, 2
FAILURES = ("parse", "searched", "no_candidate", "not_confirmed", "stuck", "blocked", "unreachable", "budget")
FAILED = {why: 3 + k for k, why in enumerate(FAILURES)}
STATUS_NAMES = ("pending", "found", "wrong", *(f"failed:{w}" for w in FAILURES))

# Episode end reasons.
REASON_NAMES = ("", "completed", "budget")


class Flags(NamedTuple):
    """Static settings of one compiled program (the method's flags are data: `Inputs`)."""

    retries: int
    max_steps: int
    leg_max_steps: int
    look_cost: int  # control steps of one look-around (a turn in place)
    found_radius: float
    approach_gap: float
    robot_radius: float
    need: float  # clearance the local planner keeps (robot radius + margin)
    tight: float  # clearance of the passages the local planner tries last
    solver: str  # planning.solver
    search_iters: int  # planning.local_search_iters
    path_points: int  # P: waypoints per leg
    refill: float = 1.0  # eval.refill: share of the lanes one reflection serves
    serial: bool = False  # a reflection serves one lane: its branches and grid searches run for it alone
    # (lax.cond / switch as conditionals, a leg's segments one after another), not as selects over a batch


@struct.dataclass
class World:
    """Per-scene arrays, gathered per episode by its bank index."""

    pos: jax.Array  # (B, N, 2) key pose positions
    node_mask: jax.Array  # (B, N) bool live key poses
    path_cost: jax.Array  # (B, N, N) map shortest-path costs (the order planner's and the search's)
    euclid: jax.Array  # (B, N, N) straight-line distances (their costs for methods without the map)
    drive_pred: jax.Array  # (B, N, N) int32 predecessors of the paths the robot drives
    obstacles: dict  # segment_clearance's arrays, each with a leading B axis
    grid_origin: jax.Array  # (B, 2) occupancy grid of the local planner
    grid_clear: jax.Array  # (B, H, W) clearance of each cell (0: outside)
    grid_labels: jax.Array  # (B, H, W) int32 connected regions the robot fits through (0: none)
    grid_shape: jax.Array  # (B, 2) int32 each scene's own (H, W) within the padded grids
    plan_idx: jax.Array  # (B, N, N) int32 local plan of each map edge (-1: none)
    plans: jax.Array  # (B, M, K, 2) local plans' waypoints
    plan_count: jax.Array  # (B, M) int32 waypoints of each plan
    known: jax.Array  # (B, O) bool objects some key pose recorded
    obj_center: jax.Array  # (B, O, 2) footprint centres, in the scene's object order
    obj_half: jax.Array  # (B, O, 2) footprint half sizes


@struct.dataclass
class Inputs:
    """Per-episode inputs computed on the host before the loop (E leading)."""

    b: jax.Array  # (E,) int32 scene index in the bank (World)
    start_node: jax.Array  # (E,) int32
    num_goals: jax.Array  # (E,) int32 goals run (the subgoals read; the true ones for the Oracle)
    parse_failed: jax.Array  # (E,) bool the instruction gave no subgoal
    strict: jax.Array  # (E,) bool visit the goals in the order written
    cands: jax.Array  # (E, G, C) int32 candidate key poses, best first
    est: jax.Array  # (E, G, C, 2) estimated target position of each candidate's instance
    has_est: jax.Array  # (E, G, C) bool
    verdict: jax.Array  # (E, G, O) bool the verifier passes the object for the goal (the Oracle: the true goal)
    misfit: jax.Array  # (E, G, O) float32 parts of the check failed (inf: name does not fit)
    search: jax.Array  # (E, G, S) int32 key poses to search
    revisit: jax.Array  # (E, G) bool the goal may go back to an object declared for another
    truth: jax.Array  # (E, T) int32 object index of each true goal (-1: absent from the scene)
    # the method, per episode (`methods.MethodSpec` and eval settings): one compiled program runs every method
    straight: jax.Array  # (E,) bool straight-line legs, Euclidean order costs (no topological map)
    optimal_order: jax.Array  # (E,) bool solve the visiting order (False: instruction order)
    searches: jax.Array  # (E,) bool search key poses when the candidates run out
    reads: jax.Array  # (E,) bool checks what it sees against the verdict table (False: the Oracle)
    fallback: jax.Array  # (E,) bool eval.fallback
    look_closer: jax.Array  # (E,) bool eval.look_closer


@struct.dataclass
class State:
    """Per-episode loop state (E leading); `step.py` updates it with array operations only."""

    order: jax.Array  # (E, G) int32 goals still to visit, in planned order (first n_left valid)
    n_left: jax.Array  # (E,) int32
    planned: jax.Array  # (E, G) int32 the first plan's order (first n_planned valid)
    n_planned: jax.Array  # (E,) int32
    cptr: jax.Array  # (E, G) int32 current candidate of each goal
    rejected: jax.Array  # (E, G) int32 candidates rejected so far
    status: jax.Array  # (E, G) int32 PENDING / FOUND / WRONG / FAILED[...]
    found: jax.Array  # (E, T) bool a correct declaration was made at the true goal
    skip: jax.Array  # (E, G, O) bool objects ruled out for a goal (rejected on approach, declared for another)
    looked: jax.Array  # (E, G, N) bool key poses looked around at for the goal
    backup: jax.Array  # (E, G) int32 fallback object (-1: none)
    backup_misfit: jax.Array  # (E, G) float32
    fell_back: jax.Array  # (E, G) bool
    node: jax.Array  # (E,) int32 key pose the robot is at or nearest to
    steps: jax.Array  # (E,) int32 control steps driven
    look_steps: jax.Array  # (E,) int32 control steps of look-arounds
    length: jax.Array  # (E,) float32 metres driven
    penetration: jax.Array  # (E,) float32 deepest contact
    leg_kind: jax.Array  # (E,) int32 pending leg issued by the reflection (APPROACH / CLOSER) or NONE
    leg_goal: jax.Array  # (E,) int32
    leg_target: jax.Array  # (E,) int32 key pose (NAV / SEARCH / CLOSER) or object (APPROACH)
    leg_xy: jax.Array  # (E, 2) the instance estimate a CLOSER leg heads for (an APPROACH's stop is placed when
    # it is driven, from the same pose the reflection saw it from)
    done: jax.Array  # (E,) bool
    reason: jax.Array  # (E,) int32 index into REASON_NAMES
    decl_goal: jax.Array  # (E, G) int32 declarations, in order (first n_decl valid)
    decl_truth: jax.Array  # (E, G) int32 true goal it counts for (-1: wrong)
    decl_obj: jax.Array  # (E, G) int32 object declared
    decl_step: jax.Array  # (E, G) int32
    decl_xy: jax.Array  # (E, G, 2)
    decl_fallback: jax.Array  # (E, G) bool
    n_decl: jax.Array  # (E,) int32
    legs: jax.Array  # (E,) int32 legs driven
