"""The navigation methods, as flags of one closed loop: `NAV_METHODS` and each one's `MethodSpec` (`method_spec`).

RAGNav and its retrieval ablations; `ragnav:no_topology` also plans and drives straight lines (no map);
`ragnav:online` updates its memory while it works (worlds that change after exploration: `host_loop.Loop.observe`); the
retrieval baselines (naive_rag, graphrag, lightrag) on RAGNav's planner; navigation baselines reimplemented
*in the style of* the papers: `remembr` (flat caption memory with positions, text retrieval plus a position
term, instruction order, the same map paths and local planner as RAGNav), `etpnav` (no prior memory: replays
the robot's own frontier exploration from the start pose until the target is seen, then approaches it;
instruction order) and `oracle` (true goal positions, optimal order, topological paths). Every method but the
Oracle checks what it sees with the same open-vocabulary verifier (`verify.py`: a verdict table computed
before the loop).
"""

from __future__ import annotations

import dataclasses

from ragnav_jax.errors import UserError
from ragnav_jax.retrieval.baselines import BASELINES

NAV_METHODS = ("ragnav", "ragnav:no_forest", "ragnav:no_topology", "ragnav:no_spatial", "ragnav:no_boost",
               "naive_rag", "graphrag", "lightrag", "remembr", "etpnav", "oracle", "ragnav:online")


@dataclasses.dataclass(frozen=True)
class MethodSpec:
    name: str
    retrieval: str  # what ranks the memory's nodes: "kernel" (RAGNav's scores), "text" (a text-retrieval model),
    # "truth" (the true goals' nodes: the Oracle) or "none" (the ETPNav-style baseline explores instead)
    straight: bool  # straight-line legs and Euclidean order costs (no topological map)
    optimal_order: bool  # solve the order (False: instruction order)
    search: bool = True  # candidates run out: search the key poses where the instruction puts the goal (search.py)
    reads: bool = True  # reads the instruction and checks what it sees (False: the Oracle, which knows the goals)
    explores: bool = False  # finds goals by replaying its exploration, with no retrieval (the ETPNav-style baseline)
    variant: str = "ragnav"  # kernel: the ablation ("ragnav", "no_forest", ...); text: the model (a BASELINES name)
    positions: bool = False  # text: a position in the instruction adds a Gaussian term over node positions (ReMEmbR)
    online: bool = False  # updates its memory while it works (host_loop.Loop.observe): what it sees on the way and
    # where the memory was found wrong


def method_spec(name: str) -> MethodSpec:
    if name not in NAV_METHODS:
        raise UserError(f"unknown method '{name}' (known: {', '.join(NAV_METHODS)})")
    if name.startswith("ragnav"):
        variant = name.split(":", 1)[1] if ":" in name else "ragnav"
        online = variant == "online"
        return MethodSpec(name, "kernel", variant == "no_topology", True, variant="ragnav" if online else variant,
                          online=online)
    if name in BASELINES:
        return MethodSpec(name, "text", False, True, variant=name)
    # ReMEmbR hands its retrieved goal to a standard navigation stack: the same map paths and local planner as
    # RAGNav here (it once drove straight lines into walls, which measured a crippled navigator, not its memory).
    # The ETPNav-style baseline explores for itself, and the Oracle knows where every goal is: neither searches.
    return {"remembr": MethodSpec(name, "text", False, False, variant="naive_rag", positions=True),
            "etpnav": MethodSpec(name, "none", False, False, search=False, explores=True),
            "oracle": MethodSpec(name, "truth", False, True, search=False, reads=False)}[name]
