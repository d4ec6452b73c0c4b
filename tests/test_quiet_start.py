"""A plain command starts quietly: MJX's notice about its optional Warp backend is not printed."""

import subprocess
import sys


def test_importing_the_simulator_prints_nothing():
    code = "import ragnav_jax.sim.env, ragnav_jax.evaluation.execute"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert "warp" not in (r.stdout + r.stderr).lower(), r.stdout + r.stderr
    assert r.stdout == "" and r.stderr == "", r.stdout + r.stderr
