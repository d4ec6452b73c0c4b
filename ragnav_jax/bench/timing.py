"""Host-side measurement helpers of the benchmark suite: repeat statistics, compile-time accounting
through jax.monitoring, peak resident memory per stage, the machine description.

All timing here is wall clock around calls that block on their results; nothing runs inside jit.
"""

from __future__ import annotations

import contextlib
import os
import platform
import resource
import statistics
import threading
import time
from collections.abc import Sequence

import jax
from jax import monitoring

COMPILE_EVENTS = (
    "/jax/core/compile/jaxpr_trace_duration",
    "/jax/core/compile/jaxpr_to_mlir_module_duration",
    "/jax/core/compile/backend_compile_duration",
)


def stats(times: Sequence[float]) -> dict:
    """{median_s, min_s, max_s, repeats} of a list of seconds."""
    ts = [float(t) for t in times]
    return {"median_s": statistics.median(ts), "min_s": min(ts), "max_s": max(ts), "repeats": len(ts)}


def point(median_s: float) -> dict:
    """A figure measured once (or given as a median only): min and max equal the median."""
    return {"median_s": float(median_s), "min_s": float(median_s), "max_s": float(median_s), "repeats": 1}


class _CompileClock:
    """Sums JAX's tracing, lowering and backend-compile durations (jax.monitoring events) while active."""

    def __init__(self):
        self.total = 0.0
        self.active = 0
        monitoring.register_event_duration_secs_listener(self._on)

    def _on(self, event: str, duration: float, **_) -> None:
        if self.active and event in COMPILE_EVENTS:
            self.total += duration


_CLOCK: _CompileClock | None = None


@contextlib.contextmanager
def stage_clock(record: dict, key: str = "wall_s"):
    """Times the block into record[key], JAX compile seconds inside it into record['compile_s'], process CPU
    seconds into record['cpu_s'] and the peak resident memory during it into record['peak_rss_mb'] (10 ms)."""
    global _CLOCK
    if _CLOCK is None:
        _CLOCK = _CompileClock()
    c0 = _CLOCK.total
    _CLOCK.active += 1
    sampler = _PeakRss()
    t0, c0_cpu = time.perf_counter(), time.process_time()
    try:
        yield record
    finally:
        wall = time.perf_counter() - t0
        record["cpu_s"] = time.process_time() - c0_cpu  # all threads; cpu_s / wall_s shows contention
        _CLOCK.active -= 1
        record[key] = wall
        record["compile_s"] = min(_CLOCK.total - c0, wall)
        record["run_s"] = max(wall - record["compile_s"], 0.0)
        record["peak_rss_mb"] = sampler.stop()


class _PeakRss:
    def __init__(self, every: float = 0.01):
        import psutil

        self._proc = psutil.Process()
        self.peak = self._proc.memory_info().rss
        self._stop = threading.Event()
        self._every = every
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()

    def _run(self):
        while not self._stop.wait(self._every):
            self.peak = max(self.peak, self._proc.memory_info().rss)

    def stop(self) -> float:
        self._stop.set()
        self._thread.join()
        self.peak = max(self.peak, self._proc.memory_info().rss)
        return round(self.peak / 2**20, 1)


def max_rss_mb() -> float:
    """Peak resident memory of this process so far (getrusage; kilobytes on Linux)."""
    return round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024, 1)


def machine() -> dict:
    """CPU model, cores, memory, JAX devices and the load at the time of the run."""
    import psutil

    model = platform.processor() or "unknown"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    try:
        affinity = len(os.sched_getaffinity(0))
    except AttributeError:
        affinity = os.cpu_count()
    devices = jax.devices()
    return {
        "cpu_model": model, "cpu_count": os.cpu_count(), "cpus_usable": affinity,
        "memory_gb": round(psutil.virtual_memory().total / 2**30, 1),
        "load_average_1_5_15": [round(x, 2) for x in os.getloadavg()],
        "jax_backend": jax.default_backend(), "jax_devices": [str(d) for d in devices],
        "device_kind": devices[0].device_kind if devices else None,
        "platform": platform.platform(), "python": platform.python_version(),
    }
