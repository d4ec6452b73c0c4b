"""Planning: visiting order of the retrieved targets, paths between them, and the navigation guide.

Built on plain arrays from the memory (shortest-path costs, predecessors, node positions, edge
weights); see the README's "Planning" section.
"""

from ragnav_jax.planning.costs import candidate_unary, order_problem, precedence, reachable_candidates
from ragnav_jax.planning.guide import build_guide, draw_route, guide_text, leg_cues, save_route_picture
from ragnav_jax.planning.order import (
    MAX_BRUTE_FORCE_GOALS,
    MAX_HELD_KARP_GOALS,
    SOLVERS,
    brute_force,
    count_inversions,
    greedy_order,
    held_karp,
    local_search,
    penalty,
    pick_solver,
    solve,
)
from ragnav_jax.planning.paths import edge_lengths, path_length, path_list, path_nodes, route_list, route_paths
from ragnav_jax.planning.types import (
    INFEASIBLE,
    NONE_REACHABLE,
    OK,
    SOME_UNREACHABLE,
    STATUS_NAMES,
    OrderProblem,
    OrderResult,
    Path,
)

__all__ = [
    "INFEASIBLE",
    "MAX_BRUTE_FORCE_GOALS",
    "MAX_HELD_KARP_GOALS",
    "NONE_REACHABLE",
    "OK",
    "SOLVERS",
    "SOME_UNREACHABLE",
    "STATUS_NAMES",
    "OrderProblem",
    "OrderResult",
    "Path",
    "brute_force",
    "build_guide",
    "candidate_unary",
    "count_inversions",
    "draw_route",
    "edge_lengths",
    "greedy_order",
    "guide_text",
    "held_karp",
    "leg_cues",
    "local_search",
    "order_problem",
    "path_length",
    "path_list",
    "path_nodes",
    "penalty",
    "pick_solver",
    "precedence",
    "reachable_candidates",
    "route_list",
    "route_paths",
    "save_route_picture",
    "solve",
]
