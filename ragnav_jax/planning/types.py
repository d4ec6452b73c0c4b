"""Array records of the planning stage: one order problem per episode, its solution, a path.

Shapes are for one episode; batched calls add leading axes (lambda L, episode E) to every field.
G is the padded goal count of the batch, K the number of candidate nodes per goal (1 unless the
caller asks for a joint candidate + order choice), N the padded node count of the map.
"""

from __future__ import annotations

from typing import NamedTuple

import jax

Array = jax.Array

# Episode status codes (OrderResult.status); STATUS_NAMES[code] is the name written to JSON.
OK = 0  # every goal reachable and planned
SOME_UNREACHABLE = 1  # some goals have no path from the start; the plan covers the others
NONE_REACHABLE = 2  # goals were given but none has a path from the start; the plan is empty
INFEASIBLE = 3  # goals are reachable from the start but no order chains them (directed map)
STATUS_NAMES = ("ok", "some_unreachable", "none_reachable", "infeasible")


class OrderProblem(NamedTuple):
    """One episode's multi-goal order problem (paper, Route Planning: Pi* objective).

    Costs are shortest-path costs from the memory (`+inf` where no path exists). Goal g's candidates
    are alternative nodes for the same target (top-k retrieval); K = 1 is the plain problem.
    """

    start_cost: Array  # (G, K) float32: cost from the start node to each candidate, inf if unreachable
    cost: Array  # (G, K, G, K) float32: cost from candidate (g, k) to candidate (h, l)
    unary: Array  # (G, K) float32: extra cost of choosing a candidate (0 for K = 1)
    nodes: Array  # (G, K) int32: map node of each candidate, -1 for padding
    cand_mask: Array  # (G, K) bool: candidate present
    rank: Array  # (G,) int32: position of the goal in the instruction; equal ranks are unordered
    mask: Array  # (G,) bool: goal present (padding is False)


class OrderResult(NamedTuple):
    """The chosen visiting order of one episode and what it costs."""

    order: Array  # (G,) int32: goal indices in visiting order, -1 after the last planned goal
    choice: Array  # (G,) int32: chosen candidate per goal (indexed by goal), -1 if not planned
    visit_nodes: Array  # (G,) int32: map node of each visited goal, in visiting order, -1 after
    travel: Array  # () float32: sum of shortest-path costs along the plan (start leg included)
    inversions: Array  # () int32: goal pairs visited against the instruction order (Kendall tau)
    objective: Array  # () float32: travel + lambda * inversions (+ unary costs of the choices)
    reachable: Array  # (G,) bool: goal present and some candidate reachable from the start
    status: Array  # () int32: OK / SOME_UNREACHABLE / NONE_REACHABLE / INFEASIBLE


class Path(NamedTuple):
    """A node path of fixed maximum length."""

    nodes: Array  # (P,) int32: source first, destination last, -1 after
    mask: Array  # (P,) bool
    found: Array  # () bool: a path exists and fits in P nodes
