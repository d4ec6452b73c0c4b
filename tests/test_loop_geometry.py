"""loop/geometry.py against the host code it replaces: memory/paths.py's reconstruct_path (and networkx),
execute.py's densify + pad_points, clearance.py's approach_ring and host_loop.py's Loop.attach / way_exists /
approach_points / drive_points, on small random inputs and on the apartment; every kernel under jit, the apartment's under vmap."""

import dataclasses
import functools
from types import SimpleNamespace

import jax
import jax.numpy as jnp
import networkx as nx
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from test_memory_streams import synthetic_stream

from ragnav_jax.config import load_config
from ragnav_jax.evaluation.clearance import GRID_M, TIGHT_GAP_M, approach_ring
from ragnav_jax.evaluation.execute import densify, make_executor, pad_points
from ragnav_jax.evaluation.host_loop import EpisodeState, Loop
from ragnav_jax.evaluation.loop import geometry as geo
from ragnav_jax.evaluation.methods import method_spec
from ragnav_jax.language.episodes import Episode
from ragnav_jax.memory.build import build_bank
from ragnav_jax.memory.encoder import HashingEmbedder
from ragnav_jax.memory.paths import reconstruct_path, shortest_paths

SEEDS = st.integers(0, 2**31 - 1)
RADIUS = 0.15  # the robot's radius in the random scenes


@pytest.fixture(scope="module")
def setup(apartment):
    cfg = load_config(None, ["memory.embedder=hashing", "eval.batch_size=8"])
    bank, _ = build_bank([apartment], [synthetic_stream(apartment)], cfg,
                         embedder=HashingEmbedder(dim=cfg.memory.hashing_dim))
    ex = make_executor([apartment], cfg)
    loop = Loop(method_spec("ragnav"), bank, [apartment], cfg, ex, None)
    ep = Episode("t", apartment.name, "Go to the fridge.", ("fridge_1",), "text", "strict")
    st_ = EpisodeState(0, ep, 0, 0, None, [[]], [[]], [0], [0], [], 0, ["pending"], True, [False])
    return cfg, bank, ex, loop, st_


def _jnp(tree):
    return jax.tree.map(jnp.asarray, tree)


def _fake_loop(pos=None, mask=None, obs=None, grid=None):
    """What Loop.attach / Loop.way_exists read of `self`, for random scenes."""
    cfg = SimpleNamespace(sim=SimpleNamespace(robot_radius=RADIUS))
    return SimpleNamespace(pos=None if pos is None else pos[None], mask=None if mask is None else mask[None],
                           obstacles={0: obs}, cfg=cfg, _grid=lambda b: grid, _grids={})


def _random_obstacles(rng, walls=3, boxes=2, size=4.0) -> dict:
    a = rng.uniform(0, size, (walls, 2)).astype(np.float32)
    return {"wall_a": a, "wall_b": (a + rng.normal(0, 1.0, (walls, 2))).astype(np.float32),
            "wall_half": rng.uniform(0.02, 0.1, walls).astype(np.float32), "wall_mask": rng.random(walls) < 0.8,
            "box_center": rng.uniform(0, size, (boxes, 2)).astype(np.float32),
            "box_half": rng.uniform(0.1, 0.5, (boxes, 2)).astype(np.float32), "box_mask": rng.random(boxes) < 0.8}


# ----------------------------------------------------------------------------------------------------
# Paths


N_GRAPH = 7
_all_paths = jax.jit(jax.vmap(geo.path_nodes, in_axes=(None, 0, 0, None)), static_argnums=3)


@settings(max_examples=25, deadline=None)
@given(st.lists(st.booleans(), min_size=N_GRAPH * N_GRAPH, max_size=N_GRAPH * N_GRAPH),
       st.lists(st.floats(0.125, 2.0, width=32), min_size=N_GRAPH * N_GRAPH, max_size=N_GRAPH * N_GRAPH),
       st.lists(st.booleans(), min_size=N_GRAPH, max_size=N_GRAPH))
def test_path_nodes_is_reconstruct_path_and_a_networkx_shortest_path(edges, weights, dead):
    adj = np.asarray(edges).reshape(N_GRAPH, N_GRAPH) & ~np.eye(N_GRAPH, dtype=bool)
    w = np.where(adj, np.asarray(weights, np.float32).reshape(N_GRAPH, N_GRAPH), np.inf).astype(np.float32)
    mask = ~np.asarray(dead)
    cost, pred = map(np.asarray, shortest_paths(jnp.asarray(w), jnp.asarray(mask)))
    i, j = (a.ravel().astype(np.int32) for a in np.meshgrid(np.arange(N_GRAPH), np.arange(N_GRAPH), indexing="ij"))
    nodes, n = map(np.asarray, _all_paths(jnp.asarray(pred), jnp.asarray(i), jnp.asarray(j), N_GRAPH))
    g = nx.DiGraph()
    g.add_nodes_from(np.flatnonzero(mask))
    g.add_weighted_edges_from((a, b, float(w[a, b])) for a, b in zip(*np.nonzero(adj & mask[:, None] & mask[None])))
    for k, (a, b) in enumerate(zip(i, j)):
        host = reconstruct_path(pred, int(a), int(b))
        assert n[k] == len(host) and nodes[k, : n[k]].tolist() == host
        assert (nodes[k, n[k] :] == (host[-1] if host else a)).all()
        if mask[a] and mask[b] and a != b:
            assert (n[k] > 0) == nx.has_path(g, a, b)
            if n[k]:
                assert all(g.has_edge(x, y) for x, y in zip(host[:-1], host[1:]))
                length = sum(w[x, y] for x, y in zip(host[:-1], host[1:]))
                assert np.isclose(length, nx.shortest_path_length(g, a, b, weight="weight"), rtol=1e-5)


# ----------------------------------------------------------------------------------------------------
# Attaching to the map


_attach = jax.jit(jax.vmap(geo.attach, in_axes=(None, None, None, 0, None)))


@settings(max_examples=25, deadline=None)
@given(SEEDS, st.integers(0, 12))
def test_attach_matches_loop_attach(seed, live):
    """Random key poses (some dead: never chosen unless none lives), walls and boxes, 16 query points."""
    rng = np.random.default_rng(seed)
    pos = rng.uniform(0, 4, (12, 2)).astype(np.float32)
    mask = np.arange(12) < live
    rng.shuffle(mask)
    obs = _random_obstacles(rng)
    xy = rng.uniform(-0.5, 4.5, (16, 2)).astype(np.float32)
    dev = np.asarray(_attach(jnp.asarray(pos), jnp.asarray(mask), _jnp(obs), jnp.asarray(xy), RADIUS))
    host = _fake_loop(pos, mask, obs)
    assert dev.tolist() == [Loop.attach(host, 0, p) for p in xy]


def test_attach_matches_on_the_apartment(setup):
    cfg, bank, ex, loop, _ = setup
    rng = np.random.default_rng(0)
    lo, hi = loop.pos[0][loop.mask[0]].min(0) - 0.5, loop.pos[0][loop.mask[0]].max(0) + 0.5
    xy = rng.uniform(lo, hi, (100, 2)).astype(np.float32)
    dev = _attach(jnp.asarray(loop.pos[0]), jnp.asarray(loop.mask[0]), _jnp(loop.obstacles[0]), jnp.asarray(xy),
                  cfg.sim.robot_radius)
    assert np.asarray(dev).tolist() == [loop.attach(0, p) for p in xy]


# ----------------------------------------------------------------------------------------------------
# Densified waypoints


_densify = jax.jit(geo.densify, static_argnums=2)  # spacing traced: one compile per P


def _check_densify(points, n, P, spacing=0.25):
    ref, m_ref = pad_points(densify(points[:n], P, spacing), P)
    out, m = _densify(jnp.asarray(points), n, P, spacing)
    assert int(m) == m_ref, (n, P)
    np.testing.assert_allclose(np.asarray(out), ref, atol=1e-5, rtol=0)


COORD = st.one_of(st.sampled_from([0.0, 0.5, 1.0, -1.5]), st.floats(-3, 3, width=32))


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(COORD, COORD), min_size=12, max_size=12), st.integers(0, 12),
       st.sampled_from([1, 3, 8, 40]), st.sampled_from([0.25, 0.1]))
def test_densify_matches_host_densify_and_pad_points(points, n, P, spacing):
    """Short polylines (repeated points, exact halves, P below, at and above n: thinning and the dense list that
    would not fit) at two spacings."""
    _check_densify(np.asarray(points, np.float32), n, P, spacing)


def test_densify_long_polylines_match_host():
    """The spacing long polylines set (NumPy's pairwise float32 sum decides the ceil()ed counts), thinning with
    P - 1 odd and even (exact halves NumPy's linspace rounds off the half), P = 1."""
    rng = np.random.default_rng(1)
    L = 300
    for P in (128, 15, 1):
        for n in sorted({0, 1, 2, P - 1, P, P + 1, 26, 30, 76, 101, L} | set(rng.integers(0, L + 1, 6).tolist())):
            steps = rng.normal(0, 1, (L, 2)) * rng.choice([0.01, 0.3, 2.0], (L, 1))
            _check_densify(np.cumsum(steps, 0).astype(np.float32), n, P)
    m = np.asarray([0, 1, 7, 8, 9, 128, 129, 200, 300])  # the sum itself, bit for bit, through both recursion levels
    x = (rng.random((len(m), 300)) * rng.choice([1e-3, 1.0, 1e3], (len(m), 300))).astype(np.float32)
    x = np.where(np.arange(300) < m[:, None], x, 0.0).astype(np.float32)
    assert np.asarray(jax.jit(jax.vmap(geo._np_sum))(x, m)).tolist() == [r[:k].sum() for r, k in zip(x, m)]


# ----------------------------------------------------------------------------------------------------
# The local planner's grid: way_exists


_ways = jax.jit(jax.vmap(geo.way_exists, in_axes=(None, None, None, 0, 0, None, None, None, None)),
                static_argnums=(6, 7))


def _random_grid(rng, H=24, W=30):
    """A clearance field of disc obstacles (metres), float32, with its origin."""
    lo = rng.uniform(-1, 1, 2).astype(np.float32)
    xy = lo + np.stack(np.meshgrid(np.arange(H), np.arange(W), indexing="ij"), -1) * GRID_M
    c, r = rng.uniform(lo, lo + [H * GRID_M, W * GRID_M], (6, 2)), rng.uniform(0.02, 0.2, 6)
    clear = (np.linalg.norm(xy[:, :, None] - c, axis=-1) - r).min(-1)
    return lo, clear.astype(np.float32)


@settings(max_examples=25, deadline=None)
@given(SEEDS)
def test_way_exists_matches_loop_way_exists_on_random_grids(seed):
    """Ends anywhere on the grid or beyond it (clipped to the edge), on cell centres and between; the grid alone
    and padded into a larger batch (`stack_grids`, clipped to its own shape)."""
    rng = np.random.default_rng(seed)
    lo, clear = _random_grid(rng)
    host = _fake_loop(grid=(lo, clear))
    origin, cl, labels = geo.scene_grid(host, 0)
    ext = np.asarray(clear.shape) * GRID_M
    pts = rng.uniform(lo - 0.3, lo + ext + 0.3, (64, 2)).astype(np.float32)
    cells = (lo + rng.integers(0, clear.shape, (64, 2)) * GRID_M).astype(np.float32)
    a = np.concatenate([pts[:32], cells[:32]])
    c = np.concatenate([pts[32:], cells[32:]])
    c[::4] = a[::4] + rng.normal(0, 0.2, (16, 2)).astype(np.float32)  # nearby pairs: mostly joined
    ref = [Loop.way_exists(host, 0, p, q) for p, q in zip(a, c)]
    tight = RADIUS + TIGHT_GAP_M
    dev = _ways(origin, cl, labels, a, c, tight, GRID_M, geo.ESCAPE_M, None)
    assert np.asarray(dev).tolist() == ref
    big = geo.stack_grids([(origin, cl, labels), _random_grid(rng, 31, 33) + (np.zeros((31, 33), np.int32),)])
    dev = _ways(big["origin"][0], big["clear"][0], big["labels"][0], a, c, tight, GRID_M, geo.ESCAPE_M,
                big["shape"][0])
    assert np.asarray(dev).tolist() == ref


def test_way_exists_matches_on_the_apartment(setup):
    cfg, bank, ex, loop, _ = setup
    origin, clear, labels = geo.scene_grid(loop, 0)
    rng = np.random.default_rng(2)
    ext = np.asarray(clear.shape) * GRID_M
    a, c = rng.uniform(origin, origin + ext, (2, 300, 2)).astype(np.float32)
    ref = [loop.way_exists(0, p, q) for p, q in zip(a, c)]
    assert 0 < sum(ref) < len(ref)
    dev = _ways(origin, clear, labels, a, c, cfg.sim.robot_radius + TIGHT_GAP_M, GRID_M, geo.ESCAPE_M, None)
    assert np.asarray(dev).tolist() == ref


# ----------------------------------------------------------------------------------------------------
# Approaches


@settings(max_examples=25, deadline=None)
@given(st.tuples(st.floats(-5, 5), st.floats(-5, 5)), st.tuples(st.floats(0.01, 2), st.floats(0.01, 2)),
       st.floats(0.0, 1.5))
def test_approach_ring_jnp_matches_approach_ring(c, half, gap):
    c, half = np.asarray(c, np.float32), np.asarray(half, np.float32)
    dev = jax.jit(geo.approach_ring_jnp)(jnp.asarray(c), jnp.asarray(half), gap)
    np.testing.assert_allclose(np.asarray(dev), approach_ring(c, half, gap), atol=1e-5, rtol=0)


def test_approach_stop_matches_loop_approach_points(setup, apartment):
    """Every object of the apartment from robot poses all over the house and close by (within the gap: the robot
    stays): the robot-side spot, ring stops round whatever blocks it or cuts it off (way_exists), free stops none
    reachable; and with a clearance no stop has (nothing free)."""
    cfg, bank, ex, loop, st_ = setup
    origin, clear, labels = geo.scene_grid(loop, 0)
    rng = np.random.default_rng(3)
    ext = np.asarray(clear.shape) * GRID_M
    O = len(apartment.objects)
    per = 8
    obj = np.repeat(np.arange(O), per)
    centre = np.asarray([o.position[:2] for o in apartment.objects], np.float32)
    half = np.asarray([o.size[:2] for o in apartment.objects], np.float32) / 2
    pose = np.concatenate([rng.uniform(origin, origin + ext, (O * per, 2)), rng.uniform(-np.pi, np.pi, (O * per, 1))], 1)
    close = rng.random(O * per) < 0.25
    pose[close, :2] = centre[obj[close]] + rng.uniform(-1, 1, (close.sum(), 2)) * (half[obj[close]] + 0.7)
    pose = pose.astype(np.float32)
    ref = np.stack([loop.approach_points(st_, int(o), p)[0] for o, p in zip(obj, pose)])
    gap = cfg.eval.approach_gap + cfg.sim.robot_radius
    stop = jax.jit(jax.vmap(geo.approach_stop, in_axes=(0, 0, 0) + (None,) * 7))
    dev = stop(centre[obj], half[obj], pose, gap, loop._need(), _jnp(loop.obstacles[0]), origin, clear, labels,
               cfg.sim.robot_radius + TIGHT_GAP_M)
    np.testing.assert_allclose(np.asarray(dev), ref, atol=1e-5, rtol=0)
    # no stop is free (a clearance no spot has): the robot-side spot
    boxed = SimpleNamespace(scenes=loop.scenes, cfg=cfg, obstacles=loop.obstacles, _need=lambda: 10.0,
                            way_exists=loop.way_exists)
    ref_boxed = np.stack([Loop.approach_points(boxed, st_, int(o), p)[0] for o, p in zip(obj[:40], pose[:40])])
    dev = stop(centre[obj[:40]], half[obj[:40]], pose[:40], gap, 10.0, _jnp(loop.obstacles[0]), origin, clear,
               labels, cfg.sim.robot_radius + TIGHT_GAP_M)
    np.testing.assert_allclose(np.asarray(dev), ref_boxed, atol=1e-5, rtol=0)
    stays = np.all(ref == pose[:, :2], axis=1)
    near = np.clip(pose[:, :2], centre[obj] - half[obj], centre[obj] + half[obj])
    v = pose[:, :2] - near
    spot = near + v / np.maximum(np.linalg.norm(v, axis=1, keepdims=True), 1e-9) * gap
    ring = ~stays & (np.linalg.norm(ref - spot, axis=1) > 1e-4)
    assert stays.sum() >= 10 and ring.sum() >= 10 and (~stays & ~ring).sum() >= 10  # every branch was compared


# ----------------------------------------------------------------------------------------------------
# Driven routes


@functools.partial(jax.jit, static_argnums=(5,))
def _routes(pred, a, t, pos, plans, P):
    def one(a, t):
        nodes, n = geo.path_nodes(pred, a, t, pos.shape[0])
        return geo.drive_route(nodes, n, pos, *plans, P)

    return jax.vmap(one)(a, t)


def _check_routes(loop, st_, pairs, K, M=None):
    """drive_route of each pair's path against Loop.drive_points; M pads the plan table (one compile)."""
    P = loop.ex.path_points
    plans = geo.edge_plans(loop, 0, K)
    if M is not None:
        plans = (plans[0], *(np.pad(x, [(0, M - len(x))] + [(0, 0)] * (x.ndim - 1)) for x in plans[1:]))
    a, t = (np.asarray(x, np.int32) for x in zip(*pairs))
    pts, m = map(np.asarray, _routes(jnp.asarray(loop.drive_pred[0]), a, t, jnp.asarray(loop.pos[0]), plans, P))
    for k, (i, j) in enumerate(pairs):
        path = reconstruct_path(loop.drive_pred[0], i, j)
        ref, m_ref = pad_points(Loop.drive_points(loop, st_, loop.pos[0][path]), P)
        assert m[k] == m_ref, (i, j)
        np.testing.assert_allclose(pts[k], ref, atol=1e-5, rtol=0)
    return plans


@settings(max_examples=25, deadline=None)
@given(SEEDS)
def test_drive_route_matches_loop_drive_points_on_random_maps(seed):
    """Random maps whose edges have local plans of 2 to 5 points, every pair's path: densified joined ways,
    joined ways longer than P (the key poses densified instead, or thinned where they exceed P too)."""
    rng = np.random.default_rng(seed)
    N, P = 8, 5
    pos = rng.uniform(0, 4, (N, 2)).astype(np.float32)
    mask = rng.random(N) < 0.9
    adj = (rng.random((N, N)) < 0.35) & mask[:, None] & mask[None] & ~np.eye(N, dtype=bool)
    cost, pred = shortest_paths(jnp.asarray(np.where(adj, 1.0, np.inf), jnp.float32), jnp.asarray(mask))
    local = {}
    for i, j in zip(*np.nonzero(adj)):
        mid = pos[i] + rng.uniform(-0.5, 1.5, (rng.integers(0, 4), 2)).astype(np.float32) * (pos[j] - pos[i])
        local[pos[i].tobytes() + pos[j].tobytes()] = np.concatenate([pos[i][None], mid, pos[j][None]])
    loop = SimpleNamespace(pos=pos[None], mask=mask[None], obstacles={0: None}, drive_pred=np.asarray(pred)[None],
                           bank=SimpleNamespace(memory=SimpleNamespace(adjacency=adj[None])),
                           ex=SimpleNamespace(path_points=P),
                           local_plans=lambda b, A, C: [local[a.tobytes() + c.tobytes()] for a, c in zip(A, C)])
    _check_routes(loop, SimpleNamespace(b=0), [(i, j) for i in range(N) for j in range(N)], 5, N * N)


@pytest.mark.parametrize("P", [None, 6])
def test_drive_route_matches_loop_drive_points(setup, apartment, P):
    """Pairs of the apartment's key poses, their driven paths (drive_pred), with the executor's buffer and with a
    small one (paths longer than P: thinned)."""
    cfg, bank, ex, loop, st_ = setup
    if P is not None:  # the same scene caches (grids, local plans), a smaller waypoint buffer
        loop = Loop(method_spec("ragnav"), bank, [apartment], cfg, dataclasses.replace(ex, path_points=P), None)
    live = np.flatnonzero(loop.mask[0])
    rng = np.random.default_rng(4)
    pairs = [(int(i), int(j)) for i, j in rng.choice(live, (160, 2))]
    plans = _check_routes(loop, st_, pairs, 4)
    assert (plans[2] > 2).any()  # some map edge is driven round something


def test_edge_plans_refuses_plans_longer_than_k(setup):
    loop = setup[3]
    with pytest.raises(ValueError, match="points"):
        geo.edge_plans(loop, 0, 2)


@settings(max_examples=40, deadline=None)
@given(SEEDS)
def test_join_plans_matches_numpy_concatenation(seed):
    """Each valid segment's plan without its first point (or the segment's end where it has none), in order,
    after the polyline's first point; zeros after the count."""
    rng = np.random.default_rng(seed)
    L, K = int(rng.choice([2, 6])), int(rng.choice([2, 5]))  # few shapes: few compilations
    pts = rng.normal(size=(L, 2)).astype(np.float32)
    plans = rng.normal(size=(L - 1, K, 2)).astype(np.float32)
    cnt = rng.integers(1, K + 1, L - 1).astype(np.int32)
    planned = rng.random(L - 1) < 0.6
    n = int(rng.integers(0, L + 1))
    want = [pts[0]]
    for s in range(max(n - 1, 0)):
        want += list(plans[s, 1 : cnt[s]]) if planned[s] else [pts[s + 1]]
    out, m = jax.jit(geo.join_plans)(pts, n, plans, cnt, planned)
    assert int(m) == (len(want) if n > 0 else 0)
    np.testing.assert_array_equal(np.asarray(out[: len(want)]), np.stack(want))
    assert not np.asarray(out[len(want):]).any()


@settings(max_examples=30, deadline=None)
@given(SEEDS)
def test_point_clearance_is_the_zero_length_segments_bit_for_bit(seed):
    """segment_clearance(p, None) (the occupancy grid's cells) equals segment_clearance(p, p) exactly, points on
    wall ends and at box centres included, and a point inside a blocking box has no clearance."""
    from ragnav_jax.memory.topomap import segment_clearance

    rng = np.random.default_rng(seed)
    W, B, P = int(rng.integers(0, 10)), int(rng.integers(0, 10)), int(rng.integers(20, 200))
    f = lambda *s: rng.uniform(-5, 5, s).astype(np.float32)  # noqa: E731
    obs = {"wall_a": f(W, 2), "wall_b": f(W, 2), "wall_half": rng.uniform(0, 0.1, W).astype(np.float32),
           "wall_mask": rng.random(W) < 0.8, "box_center": f(B, 2),
           "box_half": rng.uniform(0.05, 1, (B, 2)).astype(np.float32), "box_mask": rng.random(B) < 0.8}
    p = f(P, 2)
    p[:W] = obs["wall_a"]  # points on wall ends, then at box centres
    p[W : W + B] = obs["box_center"]
    got, want = segment_clearance(p, None, obs), segment_clearance(p, p, obs)
    assert got.dtype == want.dtype and np.array_equal(got, want)
    inside = np.zeros(P, bool)
    for c, h, m in zip(obs["box_center"], obs["box_half"], obs["box_mask"]):
        inside |= m & np.all(np.abs(p - c) <= h, axis=1)
    assert np.all(got[inside] <= 0.0)
