"""ragnav_jax.sim: the MJX world (robot model, sensors, controller, exploration).

MuJoCo MJX prints two lines at import when its optional Warp backend is absent ("Failed to import
warp: ..."); they are dropped here, once, before any module of this package or brax imports MJX. Any
other output of the import is passed on.
"""

import contextlib as _contextlib
import io as _io
import sys as _sys

if "mujoco.mjx" not in _sys.modules:
    _out = _io.StringIO()
    with _contextlib.redirect_stdout(_out):
        import mujoco.mjx  # noqa: F401
    for _line in _out.getvalue().splitlines():
        if not _line.startswith(("Failed to import warp:", "Failed to import mujoco_warp:")):
            print(_line)

from mujoco import mjx  # noqa: E402, F401  (for modules outside this package: `from ragnav_jax.sim import mjx`)
