# Every target installs what it needs: `make test` on a fresh clone just works.
PY ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
export OPENBLAS_NUM_THREADS := 1
export OMP_NUM_THREADS := 1
export MKL_NUM_THREADS := 1

.PHONY: install demo test test-all bench lint clean

install: $(STAMP)

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PY) -m venv $(VENV)
	$(BIN)/pip install -q -e '.[dev]'
	touch $(STAMP)

DEMO_DOMAIN := domains/arm-pick-place/domain.pddl
DEMO_PROBLEM := problems/arm-pick-place/p02.pddl

demo: install
	$(BIN)/tampcli check domains/blocksworld/domain.pddl problems/blocksworld/p01.pddl
	$(BIN)/tampcli plan domains/blocksworld/domain.pddl problems/blocksworld/p01.pddl -k 3
	$(BIN)/tampcli check $(DEMO_DOMAIN) $(DEMO_PROBLEM)
	mkdir -p out
	$(BIN)/tampcli solve $(DEMO_DOMAIN) $(DEMO_PROBLEM) --out out/demo.solution.json --video out/demo.mp4
	$(BIN)/tampcli validate $(DEMO_DOMAIN) $(DEMO_PROBLEM) out/demo.solution.json
	@echo "video: $(CURDIR)/out/demo.mp4"

test: install
	$(BIN)/python -m pytest -q

test-all: install
	$(BIN)/python -m pytest -q -m ''

bench: install
	@for script in bench/*.py; do echo "== $$script"; $(BIN)/python $$script || exit 1; done

lint: install
	$(BIN)/ruff check tampcli tests bench

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache
