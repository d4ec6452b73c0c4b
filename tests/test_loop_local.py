"""loop/geometry.py's local planner (`local_route`) against the host's (`Loop._local(..., anywhere=True)`) on the
apartment: approach legs whose straight segment is blocked (from key poses and stops to stops by object boxes),
clear segments, under jit + vmap and one by one."""

import functools

import jax
import jax.numpy as jnp
import numpy as np
import pytest
from test_memory_streams import synthetic_stream

from ragnav_jax.config import load_config
from ragnav_jax.evaluation.clearance import ESCAPE_M, GRID_M, TIGHT_GAP_M, approach_ring, segment_clearance_np
from ragnav_jax.evaluation.execute import make_executor
from ragnav_jax.evaluation.host_loop import Loop
from ragnav_jax.evaluation.loop import geometry as geo
from ragnav_jax.evaluation.methods import method_spec
from ragnav_jax.memory.build import build_bank
from ragnav_jax.memory.encoder import HashingEmbedder

BLOCKED, CLEAR = 150, 16  # pairs
WINDOW, MAX_POINTS = 128, 16
_routes = jax.jit(jax.vmap(functools.partial(geo.local_route, anywhere=True), in_axes=(0, 0) + (None,) * 6))


@pytest.fixture(scope="module")
def case(apartment):
    """The apartment's Loop, its grid, BLOCKED + CLEAR + 2 (a == c) pairs and the host's routes of the blocked."""
    cfg = load_config(None, ["memory.embedder=hashing", "eval.batch_size=8"])
    bank, _ = build_bank([apartment], [synthetic_stream(apartment)], cfg,
                         embedder=HashingEmbedder(dim=cfg.memory.hashing_dim))
    loop = Loop(method_spec("ragnav"), bank, [apartment], cfg, make_executor([apartment], cfg), None)
    origin, clear = loop._grid(0)
    obs = loop.obstacles[0]
    rng = np.random.default_rng(0)
    live = loop.pos[0][loop.mask[0]]
    gap = cfg.eval.approach_gap + cfg.sim.robot_radius
    stops = np.concatenate([approach_ring(np.asarray(o.position[:2], np.float32), np.asarray(o.size[:2]) / 2, g)
                            for o in apartment.objects for g in (gap, 0.25)]).astype(np.float32)
    a = np.where(rng.random((4000, 1)) < 0.75, live[rng.integers(0, len(live), 4000)],
                 stops[rng.integers(0, len(stops), 4000)]).astype(np.float32)
    c = stops[rng.integers(0, len(stops), 4000)]
    sc = segment_clearance_np(a, c, obs)
    far = np.linalg.norm(a - c, axis=1)
    blocked = np.flatnonzero((sc < loop._need()) & (far < 3.0))[:BLOCKED]
    free = np.flatnonzero((sc >= loop._need()) & (far > 0.3))[:CLEAR]
    inside = a[blocked[:2]]  # blocked, but a and c one point (|c - a| < 1e-3): straight too
    a = np.concatenate([a[blocked], a[free], inside])
    c = np.concatenate([c[blocked], c[free], inside + np.float32(1e-4)])
    assert len(blocked) == BLOCKED and len(free) == CLEAR
    host = [loop._local(0, p, q, anywhere=True) for p, q in zip(a[:BLOCKED], c[:BLOCKED])]
    args = (jax.tree.map(jnp.asarray, obs), origin, clear, np.asarray(clear.shape, np.int32), loop._need(),
            cfg.sim.robot_radius + TIGHT_GAP_M)
    pts, n = map(np.asarray, _routes(a, c, *args))
    return loop, a, c, host, args, pts, n


def _length(route: np.ndarray) -> float:
    return float(np.linalg.norm(np.diff(route, axis=0), axis=1).sum())


def _blocked_segments(route, a, c, obs, tight) -> np.ndarray:
    """(n - 1,) bool: the route's segments that clear less than the host's string pulling keeps (tight * 0.999),
    except where one of their points is within ESCAPE_M of an end's cell (where the host lets the robot out of
    a tight spot)."""
    p, q = route[:-1], route[1:]
    low = segment_clearance_np(p, q, obs) < tight * 0.999 - 1e-4
    reach = ESCAPE_M + GRID_M  # the escape disc is about an end's cell, up to a half diagonal from the end
    near = [np.minimum(np.linalg.norm(x - a, axis=1), np.linalg.norm(x - c, axis=1)) <= reach for x in (p, q)]
    return low & ~(near[0] | near[1])


def _in_block(route, a, c, origin, shape) -> bool:
    """The route's cells lie in `local_route`'s block (WINDOW cells about the ends' cells' midpoint)."""
    cell = lambda p: np.clip(np.round((p - origin) / GRID_M), 0, shape - 1)  # noqa: E731
    top = np.clip((cell(a) + cell(c)) // 2 - WINDOW // 2, 0, shape - WINDOW)
    cells = np.round((route - origin) / GRID_M)
    return bool(np.all((cells >= top) & (cells < top + WINDOW)))


def test_local_route_ends_and_clearance(case):
    """(1) Every segment clears tight * 0.999 but for the escapes at the ends, as the host's; a first, c last."""
    loop, a, c, host, args, pts, n = case
    obs, tight = loop.obstacles[0], args[-1]
    assert (n >= 2).all() and (n <= MAX_POINTS).all()
    for k in range(BLOCKED):
        route = pts[k, : n[k]]
        assert np.array_equal(route[0], a[k]) and np.array_equal(route[-1], c[k])
        assert (pts[k, n[k] :] == c[k]).all()  # padded with c
        bad = _blocked_segments(route, a[k], c[k], obs, tight)
        if n[k] == MAX_POINTS and len(host[k]) > MAX_POINTS:
            bad[-1] = False  # cut short: the last kept point straight to c
        assert not bad.any(), (k, route, segment_clearance_np(route[:-1], route[1:], obs))
        assert not _blocked_segments(host[k], a[k], c[k], obs, tight).any(), k  # the rule is the host's


def test_local_route_finds_what_the_host_finds(case):
    """(2) A route round the obstacle (> 2 points) exactly where the host has one, wherever the host's route keeps
    to the block the device searches (the host's whole-house routes need not); (3) lengths within 15% (or 0.3 m)."""
    loop, a, c, host, args, pts, n = case
    origin, shape = args[1], args[3]
    found_h = np.asarray([len(h) > 2 for h in host])
    found_d = n[:BLOCKED] > 2
    inside = np.asarray([_in_block(h, p, q, origin, shape) for h, p, q in zip(host, a, c)])
    assert (found_h == found_d)[inside].all()
    assert not (found_d & ~found_h).any()  # the block is part of the house
    assert inside.mean() > 0.8 and (found_h == found_d).mean() > 0.85 and found_h.sum() > 100
    both = np.flatnonzero(found_h & found_d)
    lh = np.asarray([_length(host[k]) for k in both])
    ld = np.asarray([_length(pts[k, : n[k]]) for k in both])
    assert (np.abs(ld - lh) <= np.maximum(0.15 * lh, 0.3)).all()


def test_local_route_keeps_clear_segments_straight(case):
    """(4) A clear segment, and ends within 1e-3 of each other, give exactly [a, c]."""
    loop, a, c, host, args, pts, n = case
    assert (n[BLOCKED:] == 2).all()
    np.testing.assert_array_equal(pts[BLOCKED:, 0], a[BLOCKED:])
    np.testing.assert_array_equal(pts[BLOCKED:, 1:], np.broadcast_to(c[BLOCKED:, None], (len(a) - BLOCKED, MAX_POINTS - 1, 2)))
    assert [len(loop._local(0, p, q, anywhere=True)) for p, q in zip(a[BLOCKED:-2], c[BLOCKED:-2])] == [2] * CLEAR


def test_local_route_batched_is_one_by_one(case):
    """(5) jit + vmap over the batch (reversed: other batch-mates) as the kernel alone, one pair at a time."""
    loop, a, c, host, args, pts, n = case
    rp, rn = map(np.asarray, _routes(a[::-1], c[::-1], *args))
    np.testing.assert_array_equal(rp[::-1], pts)
    np.testing.assert_array_equal(rn[::-1], n)
    assert _routes._cache_size() == 1  # traced once
    one = jax.jit(functools.partial(geo.local_route, anywhere=True))
    for k in list(range(0, BLOCKED, 25)) + [BLOCKED, len(a) - 1]:
        p, m = one(a[k], c[k], *args)
        np.testing.assert_array_equal(np.asarray(p), pts[k])
        assert int(m) == n[k]
