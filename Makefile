# Two commands do all set-up:  `make lab` opens the course, `make test` passes the tests.
# Both build .venv from environment.txt when it is missing or older than environment.txt.

PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.course-installed

.PHONY: lab test e2e student bench clean

$(STAMP): environment.txt pyproject.toml
	rm -rf $(VENV)
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -r environment.txt
	$(BIN)/python -m pip install --quiet --no-deps -e .
	touch $(STAMP)

lab: $(STAMP)
	$(BIN)/jupyter lab --ServerApp.root_dir=notebooks

test: $(STAMP)
	$(BIN)/python -m pytest

# Every notebook in a real JupyterLab, run in headless Chromium (/usr/bin/chromium): outputs,
# math, figures, every slider and a mouse drag of each explorer's 3D view; screenshots in build/e2e/.
e2e: $(STAMP)
	$(BIN)/python e2e/run_e2e.py

student: $(STAMP)
	$(BIN)/python -m course_lib.student notebooks build/student --force

bench: $(STAMP)
	$(BIN)/python benchmarks/bench_so3.py

clean:
	rm -rf $(VENV) build
