"""GPU determinism: importing ragnav_jax asks XLA for deterministic GPU ops, unless XLA_FLAGS already says."""

import os
import subprocess
import sys


def _flags_after_import(env_flags: str | None) -> str:
    env = {k: v for k, v in os.environ.items() if k != "XLA_FLAGS"}
    if env_flags is not None:
        env["XLA_FLAGS"] = env_flags
    code = "import os, ragnav_jax, jax.numpy as jnp; jnp.ones(2).sum().block_until_ready(); print(os.environ['XLA_FLAGS'])"
    return subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True).stdout.strip()


def test_import_asks_for_deterministic_gpu_ops():
    assert _flags_after_import(None) == "--xla_gpu_deterministic_ops=true"
    assert _flags_after_import("--xla_cpu_multi_thread_eigen=false") == "--xla_cpu_multi_thread_eigen=false --xla_gpu_deterministic_ops=true"


def test_an_explicit_setting_is_left_alone():
    assert _flags_after_import("--xla_gpu_deterministic_ops=false") == "--xla_gpu_deterministic_ops=false"
