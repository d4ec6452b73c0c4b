"""Stand-in for `ragnav explore` until the MJX explorer (issue 3) lands: writes RUN/explore/streams/<scene>.npz.

The streams come from the test suite's synthetic tour (tests/test_memory_streams.py: a path through every
room on the free-space grid, a look-around at each room centre, visibility by field of view and wall
line of sight), so `ragnav build-memory --run RUN` and everything after it run unchanged.

    python experiments/synthetic_explore.py RUN        # RUN/scenes from `ragnav generate --out RUN`
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from test_memory_streams import synthetic_stream  # noqa: E402

from ragnav_jax.world.scene import load_scene_set  # noqa: E402


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run", help="run folder with scenes/")
    args = ap.parse_args(argv)
    run = Path(args.run)
    out = run / "explore" / "streams"
    out.mkdir(parents=True, exist_ok=True)
    for scene in load_scene_set(run / "scenes"):
        synthetic_stream(scene).save(out / f"{scene.name}.npz")
        print(f"{scene.name}: stream written", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
