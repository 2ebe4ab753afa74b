# Two commands do all set-up:  `make lab` opens the course, `make test` passes the tests.
# Both build .venv from environment.txt (and environment-student.txt, which it includes) when it is
# missing or older than either.

PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.course-installed

.PHONY: lab test e2e student bench lint clean test-fast notebooks exercises site site-test

$(STAMP): environment.txt environment-student.txt pyproject.toml
	@$(PYTHON) -c 'import sys; sys.exit(sys.version_info < (3, 11))' || { echo "make: $(PYTHON) is $$($(PYTHON) -V 2>&1); this environment (nbgrader 0.9.6) needs Python 3.11-3.13: install one, then e.g. make PYTHON=python3.11 (README, What they need)" >&2; exit 1; }
	rm -rf $(VENV)
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -r environment.txt
	$(BIN)/python -m pip install --quiet --no-deps -e .
	touch $(STAMP)

# `make lab LAB_ARGS="--no-browser --port=8890"` passes arguments on; as root (containers)
# --allow-root is added. The "Jupyter news" pop-up is switched off inside .venv only.
LAB_ARGS  ?=
ROOT_FLAG := $(if $(filter 0,$(shell id -u)),--allow-root)
lab: $(STAMP)
	$(BIN)/jupyter labextension disable --level=sys_prefix "@jupyterlab/apputils-extension:announcements" >/dev/null 2>&1
	@echo "Opening the course on notebooks/: the URL to open (with its token) is printed below."
	$(BIN)/jupyter lab --ServerApp.root_dir=notebooks --LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate $(ROOT_FLAG) $(LAB_ARGS)

# Two pytest workers by default (`make test JOBS=1`: one); a notebook's cells run in order in
# one worker (--dist loadfile); pyproject's testpaths list the notebooks first, so the longest
# files start early. docs/testing.md: the time of each part.
JOBS ?= 2
test: $(STAMP)
	$(BIN)/python -m pytest -n $(JOBS) --dist loadfile

# Unit, property and doctests without executing any notebook (nbval cells are notebook_exec too).
test-fast: $(STAMP)
	$(BIN)/python -m pytest -m "not notebook_exec" -q

# Give each figure's plotting.show the caption under it as alt text (instructor/build/alt_text.py), put the
# setup cell first, execute and clean every chapter and problem set (idempotent: a
# re-run changes nothing), then refresh the README's launch links from pyproject.toml.
notebooks: $(STAMP)
	$(BIN)/python -m instructor.build.alt_text --apply notebooks/[0-9]*.ipynb
	$(BIN)/python -m instructor.build.notebooks --apply notebooks/[0-9]*.ipynb problem_sets/ps*.ipynb
	$(BIN)/python -m instructor.build.course_links --readme

# After editing an exercise (its bank entry, its solution in instructor/answers): the variant
# tables (instructor/build/variant_tables.py), the checker's fingerprints, the problem sets (hidden tests and hand-made cells kept) and the chapters'
# pointers, then the problem sets executed. One command; a re-run changes nothing.
exercises: $(STAMP)
	$(BIN)/python -m instructor.build.variant_tables
	$(BIN)/python -m instructor.build.exercise_fingerprints
	$(BIN)/python -m instructor.build.sync_exercises
	$(BIN)/python -m instructor.build.notebooks --apply problem_sets/ps*.ipynb

# One student's numbers and answers for a problem set: `make variant STUDENT=id PS=ps04`
# (instructor/build/show_variant.py; the id as the grader gets it). Variants on/off for the course:
# `.venv/bin/python -m instructor.build.variant_tables --on` / `--off`, then `make exercises`.
.PHONY: variant
variant: $(STAMP)
	@test -n "$(STUDENT)" -a -n "$(PS)" || { echo "usage: make variant STUDENT=id PS=psNN"; exit 2; }
	$(BIN)/python -m instructor.build.show_variant "$(STUDENT)" "$(PS)" $(if $(ROSTER),--roster "$(ROSTER)")

# The course website in build/site/ from the student copies; SOLUTIONS=1: the instructor's, in
# build/site-instructor/ with a banner on every page (never over the student site). Its tools
# (site/requirements.txt, MathJax from npm) are installed on first use only.
SITE_STAMP := $(VENV)/.site-installed
SOLUTIONS  ?=
$(SITE_STAMP): $(STAMP) site/requirements.txt
	$(BIN)/python -m pip install --quiet -r site/requirements.txt
	touch $(SITE_STAMP)

site: $(SITE_STAMP)
	$(BIN)/python -m instructor.build.website $(if $(SOLUTIONS),--solutions)

# Builds the student site, then opens its pages in headless Chromium (/usr/bin/chromium): every
# figure on its page, no page wider than 1200 px, no request leaving the site, no solution.
site-test: $(SITE_STAMP)
	$(BIN)/python -m instructor.build.website
	$(BIN)/python -m pytest site/test_site.py -q

# Everything students get, in build/release/: student/ (the student edition, a git repository of
# its own), dist/ (the wheel), site/ (the website); the leak gate scans all three and fails the
# release on any worked-solution line, nbgrader marker or solutions folder (instructor/release/).
.PHONY: release
release: $(SITE_STAMP)
	$(BIN)/python -m instructor.release.make_release

# Every notebook in a real JupyterLab, run in headless Chromium (/usr/bin/chromium): outputs,
# math, figures, every slider and a mouse drag of each explorer's 3D view; screenshots in build/e2e/.
# `make e2e E2E_ARGS=--axe` (CI) also runs axe-core on each notebook's content on the same page.
E2E_ARGS ?=
e2e: $(STAMP)
	$(BIN)/python e2e/run_e2e.py $(E2E_ARGS)

# Student copies (solutions replaced by stubs, outputs cleared) of the chapters and, when there,
# the problem sets, in build/student/; `make release` builds the whole student edition.
student: $(STAMP)
	$(BIN)/python -m instructor.build.student notebooks build/student --force
	$(if $(wildcard problem_sets/*.ipynb),$(BIN)/python -m instructor.build.student problem_sets build/student/problem_sets --force)

# Speed against the reference (scipy) and of the exercise checks: CPU time, best of N, printed.
bench: $(STAMP)
	$(BIN)/python -m benchmarks.bench_so3
	$(BIN)/python -m benchmarks.bench_orientation
	$(BIN)/python -m benchmarks.bench_exercises
	$(BIN)/python -m benchmarks.bench_report

# Style: ruff's checks and its formatter (configured in pyproject.toml) over the Python sources
# and the code cells of the notebooks (ruff reads .ipynb itself; .ipynb_checkpoints is skipped).
LINT_PATHS := conftest.py course_lib instructor site tests benchmarks e2e notebooks problem_sets
lint: $(STAMP)
	$(BIN)/ruff check $(wildcard $(LINT_PATHS))
	$(BIN)/ruff format --check $(wildcard $(LINT_PATHS))

# A class on a real JupyterHub (loopback only): STUDENTS users run every chapter notebook at once;
# prints the table of docs/classroom.md. JupyterHub (benchmarks/hub-requirements.txt) goes into
# .venv, its proxy from npm into build/node, both on first use.
.PHONY: hub-load
STUDENTS    ?= 20
CHP_VERSION := 5.3.0
CHP         := build/node/node_modules/.bin/configurable-http-proxy
CHP_STAMP   := build/node/.installed-$(CHP_VERSION)
HUB_STAMP   := $(VENV)/.hub-installed

$(HUB_STAMP): $(STAMP) benchmarks/hub-requirements.txt
	$(BIN)/python -m pip install --quiet -r benchmarks/hub-requirements.txt -c environment.txt
	touch $(HUB_STAMP)

$(CHP_STAMP):
	npm install --silent --no-audit --no-fund --prefix build/node \
		configurable-http-proxy@$(CHP_VERSION)
	touch $(CHP_STAMP)

hub-load: $(HUB_STAMP) $(CHP_STAMP)
	$(BIN)/python benchmarks/hub_load.py --students $(STUDENTS) --proxy $(CHP) \
		--json build/hub-load/students-$(STUDENTS).json --log build/hub-load/hub-$(STUDENTS).log

clean:
	rm -rf $(VENV) build

# An nbgrader course directory for the problem sets (docs/grading.md): nbgrader_config.py with
# the confined kernel and the grader's preprocessors, and source/psNN/ for every problem set.
.PHONY: course bench-grade
COURSE ?=
course: $(STAMP)
	@test -n "$(COURSE)" || { echo "usage: make course COURSE=DIR [ROSTER=roster.csv]"; exit 2; }
	$(BIN)/python -m instructor.grading.course $(COURSE) $(if $(ROSTER),--roster "$(ROSTER)")

# A class of 20 simulated students through `make course` and real nbgrader (a benchmark, not a
# test): CPU per submission, the confined kernels' included, where it goes, and the projection
# for 200 students x 5 problem sets on 2 cores (goal 20 min).
bench-grade: $(STAMP)
	$(BIN)/python -m benchmarks.bench_grade --students 20 --jobs 2

# Gradescope and Canvas (docs/grading.md): an autograder zip per problem set in build/gradescope/
# (UNCONFINED=1: run submissions even where bubblewrap cannot confine them), the Canvas gradebook
# CSV from an nbgrader course directory, the time of run_autograder, and their tests.
.PHONY: gradescope grades-canvas bench-gradescope test-gradescope
ASSIGNMENT ?=
ROSTER     ?=
UNCONFINED ?=
gradescope: $(STAMP)
	$(BIN)/python -m instructor.grading.gradescope $(if $(UNCONFINED),--unconfined) $(if $(ROSTER),--roster "$(ROSTER)")

# GRADESCOPE=EXPORT (issue 34): the scores of Gradescope's export(s) instead of COURSE; MISSING=zero
# writes 0 for missing work (default: blank, which Canvas leaves unchanged).
MISSING    ?=
GRADESCOPE ?=
grades-canvas: $(STAMP)
	@test -n "$(COURSE)$(GRADESCOPE)" || { echo "usage: make grades-canvas COURSE=DIR|GRADESCOPE=EXPORT [ASSIGNMENT=psNN] [ROSTER=canvas-export.csv] [MISSING=zero]"; exit 2; }
	$(BIN)/python -m instructor.grading.canvas $(COURSE) $(foreach g,$(GRADESCOPE),--gradescope $(g)) $(foreach a,$(ASSIGNMENT),--assignment $(a)) $(if $(ROSTER),--roster $(ROSTER)) $(if $(MISSING),--missing $(MISSING))

# What the class got wrong (issue 34, docs/grading.md): one HTML report and CSV per problem set,
# the instructor's copy and a de-identified one, from an nbgrader course or a Gradescope export.
.PHONY: report
OUT ?=
report: $(STAMP)
	@test -n "$(COURSE)$(GRADESCOPE)" || { echo "usage: make report COURSE=DIR|GRADESCOPE=EXPORT [ASSIGNMENT=psNN] [ROSTER=canvas-export.csv] [OUT=folder]"; exit 2; }
	$(BIN)/python -m instructor.grading.report $(if $(COURSE),--course $(COURSE)) $(if $(GRADESCOPE),--gradescope $(GRADESCOPE)) $(foreach a,$(ASSIGNMENT),--assignment $(a)) $(if $(ROSTER),--roster $(ROSTER)) $(if $(OUT),--out $(OUT))

bench-gradescope: $(STAMP)
	$(BIN)/python -m benchmarks.bench_gradescope

test-gradescope: $(STAMP)
	$(BIN)/python -m pytest -m gradescope tests/test_grading_gradescope.py -q

# Gradescope's image build (setup.sh) and one run_autograder in a real Ubuntu userland
# (debootstrap), under Docker's constraint: UBUNTU=jammy (22.04) or noble (24.04). Needs root
# and archive.ubuntu.com; 10-20 minutes; not in CI (docs/grading.md).
.PHONY: gradescope-image
UBUNTU ?= jammy
gradescope-image: $(STAMP)
	bash tests/gradescope_image.sh $(UBUNTU) $(or $(PS),ps01)

# What is too slow for `make test` (docs/testing.md), on two workers: the rest of the attacks on
# grading through real nbgrader and the Gradescope autograder in a temporary /autograder. Test by
# test (--dist loadgroup), not file by file: one file's run_autograder tests were half the run;
# the privilege-drop tests stay together in one worker (their xdist_group).
.PHONY: test-slow
test-slow: $(STAMP)
	$(BIN)/python -m pytest -n $(JOBS) --dist loadgroup -q \
		-m "slow_grading or gradescope or slow_variants" \
		tests/test_grading_nbgrader.py tests/test_grading_gradescope.py tests/test_variant_tables.py \
		tests/test_grading_variants_nbgrader.py tests/test_grading_identity.py \
		tests/test_report_roundtrip.py tests/test_grading_intake_nbgrader.py \
		tests/test_grading_privdrop.py

# Accessibility (WCAG 2.1 AA, docs/accessibility.md): builds both editions of the site, then runs
# three engines (axe-core, IBM Equal Access, HTML_CodeSniffer: pinned in e2e/engines/, from npm
# into build/a11y-deps/) in headless Chromium on every page (at 1200 and 320 CSS px) and on every
# chapter and problem set opened in JupyterLab; the keyboard (sliders, the 3D view), the maths in
# JupyterLab, and every figure's colours (instructor/build/figure_audit.py). Fails on any problem in the
# course's content.
.PHONY: a11y
a11y: $(SITE_STAMP)
	@test -x /usr/bin/chromium || { echo "make a11y needs Chromium: sudo apt-get install chromium"; exit 2; }
	@command -v npm >/dev/null || { echo "make a11y needs npm (axe-core, IBM's accessibility-checker-engine, HTML_CodeSniffer, MathJax): sudo apt-get install npm"; exit 2; }
	$(BIN)/python -m instructor.build.website
	$(BIN)/python -m instructor.build.website --solutions
	$(BIN)/python -m pytest -q -p no:cacheprovider site/test_a11y_site.py
	$(BIN)/python e2e/a11y_keyboard.py
	$(BIN)/python e2e/a11y_math_lab.py
	$(BIN)/python e2e/a11y.py
	$(BIN)/python -m instructor.build.figure_audit
