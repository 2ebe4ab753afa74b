# Two commands do all set-up:  `make lab` opens the course, `make test` passes the tests.
# Both build .venv from environment.txt when it is missing or older than environment.txt.

PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.course-installed

.PHONY: lab test e2e student bench lint clean

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

# Every notebook in a real JupyterLab, run in headless Chromium (/usr/bin/chromium);
# screenshots in build/e2e/.
e2e: $(STAMP)
	$(BIN)/python e2e/run_e2e.py

student: $(STAMP)
	$(BIN)/python -m course_lib.student notebooks build/student --force

# Speed against the reference (scipy) and of the exercise checks: CPU time, best of N, printed.
bench: $(STAMP)
	$(BIN)/python benchmarks/bench_so3.py
	$(BIN)/python benchmarks/bench_exercises.py

# Style: ruff's checks and its formatter (configured in pyproject.toml) over the Python sources.
LINT_PATHS := course_lib tests benchmarks e2e tools
lint: $(STAMP)
	$(BIN)/ruff check $(wildcard $(LINT_PATHS))
	$(BIN)/ruff format --check $(wildcard $(LINT_PATHS))

clean:
	rm -rf $(VENV) build
