"""Strict numerics and shared fixtures for the test suite."""

from __future__ import annotations

import os

os.environ.setdefault("JAX_PLATFORMS", "cpu")
os.environ.setdefault("HF_HUB_OFFLINE", "1")
# Tests run tiny shapes, so XLA's CPU compile time dominates them: skip LLVM's optimisation passes (the
# programs stay the same HLO; measured 10-20% off the closed-loop tests). Processes the tests start inherit it.
if "xla_backend_optimization_level" not in os.environ.get("XLA_FLAGS", ""):
    os.environ["XLA_FLAGS"] = (os.environ.get("XLA_FLAGS", "") + " --xla_backend_optimization_level=0").strip()

import shutil  # noqa: E402
import tempfile  # noqa: E402
from pathlib import Path  # noqa: E402

import jax  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

jax.config.update("jax_numpy_rank_promotion", "raise")

from hypothesis import settings  # noqa: E402

# The same examples on every run, so a CI result is reproducible; HYPOTHESIS_PROFILE=explore draws new ones.
settings.register_profile("repeatable", derandomize=True)
settings.register_profile("explore", derandomize=False)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repeatable"))

_CACHE_ENV = "RAGNAV_TEST_COMPILATION_CACHE"
_MIN_COMPILE_S = 0.5  # programs compiled faster than this are not worth a file


def pytest_configure(config):
    """One persistent XLA compilation cache for the whole run, shared by the xdist workers (which inherit the
    controller's environment): a program that several test files compile with the same shapes is compiled
    once. It lives in a temporary folder that the controller removes at the end."""
    if not hasattr(config, "workerinput") and _CACHE_ENV not in os.environ:
        os.environ[_CACHE_ENV] = config._ragnav_cache = tempfile.mkdtemp(prefix="ragnav-jax-cache-")
        # the same for processes the tests start (notebook kernels, the CLI), which read JAX's variables
        os.environ["JAX_COMPILATION_CACHE_DIR"] = os.environ[_CACHE_ENV]
        os.environ["JAX_PERSISTENT_CACHE_MIN_COMPILE_TIME_SECS"] = str(_MIN_COMPILE_S)
    jax.config.update("jax_compilation_cache_dir", os.environ[_CACHE_ENV])
    jax.config.update("jax_persistent_cache_min_compile_time_secs", _MIN_COMPILE_S)


# Files whose module fixtures compile the simulator or the device program: run first, so that the two
# workers (`--dist loadfile` hands out files in collection order) end on short files instead of one of these.
HEAVY_FIRST = ("test_loop_program.py", "test_bench.py", "test_eval.py", "test_show_episode.py", "test_notebooks.py",
               "test_explore.py", "test_tagger.py", "test_sim.py", "test_search.py")


def pytest_collection_modifyitems(config, items):
    rank = {name: i for i, name in enumerate(HEAVY_FIRST)}
    items.sort(key=lambda item: rank.get(item.path.name, len(rank)))  # stable: each file keeps its own order


def pytest_unconfigure(config):
    folder = getattr(config, "_ragnav_cache", None)
    if folder:
        shutil.rmtree(folder, ignore_errors=True)
        for k in (_CACHE_ENV, "JAX_COMPILATION_CACHE_DIR", "JAX_PERSISTENT_CACHE_MIN_COMPILE_TIME_SECS"):
            os.environ.pop(k, None)

from ragnav_jax.world.scene import example_scene_path, load_scene  # noqa: E402

SHARED = Path(__file__).resolve().parents[1].parent / "shared"


@pytest.fixture
def key():
    return jax.random.PRNGKey(0)


@pytest.fixture(scope="session")
def apartment():
    return load_scene(example_scene_path())


def tree_allclose(a, b, rtol=1e-6, atol=1e-6) -> bool:
    la, ta = jax.tree.flatten(a)
    lb, tb = jax.tree.flatten(b)
    if ta != tb:
        return False
    return all(np.allclose(np.asarray(x), np.asarray(y), rtol=rtol, atol=atol) for x, y in zip(la, lb))
