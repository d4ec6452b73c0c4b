"""Benchmark suite (`ragnav bench`): peer comparisons and scaling curves; see suite.run_suite."""
