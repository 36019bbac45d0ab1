# Two commands set up a fresh machine from nothing (Python 3.11, make, and Node.js/npm for
# the JavaScript the book ships, which make installs with apt-get where it can):
#   make book   build the HTML book into book/_build/html and check its links
#   make test   run every test (lint, unit and doc tests, notebooks, book build, browser)
# Both create .venv from environment.txt when it is missing or out of date.

SHELL := /bin/bash
.SHELLFLAGS := -eu -o pipefail -c
.DEFAULT_GOAL := help

PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
# notebooks find the kernel installed into .venv, not one of the user's
export JUPYTER_PREFER_ENV_PATH := 1
export PYDEVD_DISABLE_FILE_VALIDATION := 1
# Python caches the bytecode of what it compiles (gearlib, the tests, pytest's rewritten
# asserts) in __pycache__ (ignored by git and by book/inputs.py), as it does by default: an
# environment that turns this off makes every kernel, worker and command compile it all again
unexport PYTHONDONTWRITEBYTECODE

NOTEBOOKS := chapters exercises book/solutions book/lecturers.ipynb
LINTED := gearlib tests chapters exercises book benchmarks course
JB_FLAGS := --config book/_config.yml --toc book/_toc.yml --path-output book -W -n --keep-going
# JavaScript the book ships so that it reads offline: pinned in book/vendor/package-lock.json,
# installed by npm into book/vendor/node_modules (a cache, ignored by git) and staged in
# book/vendor/_static, which Sphinx copies into book/_build/html/_static.
VENDOR := book/vendor
VENDOR_STAMP := $(VENDOR)/_static/.staged
CHROMIUM ?= $(shell command -v chromium || command -v chromium-browser || true)

.PHONY: help venv vendor lint unit notebooks book build-book clean-book tex pdf pdf-from-build browser browser-pages browser-lab book-then-pages chromium test lab bench nbval-repeat strip clean \
	proxy course course-notebooks course-html course-test course-then-html hub binder-constraints

help:
	@echo "make book     build the HTML book into book/_build/html (creates .venv if needed)"
	@echo "make pdf      the HTML book, then the whole book as one PDF, book/_build/latex/book.pdf (xelatex)"
	@echo "make test     lint, unit and doc tests, book build (runs every notebook), PDF, browser tests"
	@echo "make notebooks  every notebook under nbval (quicker than a book build when writing one)"
	@echo "make lab      open JupyterLab at the book's start"
	@echo "make browser  every page of the built book in headless Chromium, offline, and every chapter in JupyterLab"
	@echo "make bench    speed benchmarks (benchmarks/)"
	@echo "make nbval-repeat  run every notebook three times; fail if an output changes"
	@echo "make strip    remove outputs from every notebook before committing"
	@echo "make course   the course kit in course/_build: students' notebooks, nbgrader, links, the course's HTML book"
	@echo "              (CLASS=class.csv HUB=https://hub... REPO=git-url BRANCH=main; see book/lecturers.ipynb)"
	@echo "make hub      JupyterHub for a class on this machine (course/jupyterhub_config.py; as root)"

$(STAMP): environment.txt pyproject.toml
	@test -d $(VENV) || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip 2>&1 | grep -v "is ignored" || true
	$(BIN)/python -m pip install --quiet -r environment.txt 2>&1 | grep -v "is ignored" || true
	$(BIN)/python .ci/sync_venv.py environment.txt
	$(BIN)/python -c "import gearlib, jupyter_book, nbval, sympy, matplotlib"
	$(BIN)/python -m ipykernel install --sys-prefix --name python3 --display-name "Python 3 (gearlib)" >/dev/null
	@# nbgrader is the course kit's grader, run from its command line: its server and lab extensions
	@# would load in every reader's JupyterLab (about 4 s at each start) and are not needed there
	for e in formgrader validate_assignment assignment_list course_list; do \
		$(BIN)/jupyter server extension disable --sys-prefix nbgrader.server_extensions.$$e >/dev/null 2>&1; done
	$(BIN)/jupyter labextension disable --level=sys_prefix @jupyter/nbgrader >/dev/null 2>&1
	@touch $(STAMP)

venv: $(STAMP)

# Every kernel of .venv reads this (figures as retina PNG); see book/ipython_kernel_config.py
KERNEL_CONFIG := $(VENV)/etc/ipython/ipython_kernel_config.py
$(KERNEL_CONFIG): book/ipython_kernel_config.py $(STAMP)
	mkdir -p $(dir $@) && cp $< $@

# npm, from Debian where it is missing and can be installed (root and apt-get)
define NPM
	@if ! command -v npm >/dev/null && [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
		echo "installing Debian's npm to install $(1)"; \
		apt-get -o DPkg::Lock::Timeout=900 update -qq && DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=900 install -y -qq npm >/dev/null; \
	fi
	@command -v npm >/dev/null || { echo "this needs Node.js and npm to install $(1) from npm (install npm, e.g. apt-get install npm)"; exit 1; }
endef

$(VENDOR_STAMP): $(VENDOR)/package.json $(VENDOR)/package-lock.json
	$(call NPM,the book's JavaScript (MathJax and require.js and the widgets manager))
	cd $(VENDOR) && npm ci --ignore-scripts --no-audit --no-fund --loglevel=error
	rm -rf $(VENDOR)/_static
	mkdir -p $(VENDOR)/_static/mathjax $(VENDOR)/_static/mathjax/output $(VENDOR)/_static/requirejs $(VENDOR)/_static/html-manager
	cd $(VENDOR)/node_modules/mathjax && cp -R LICENSE package.json es5/tex-mml-chtml.js es5/input es5/a11y es5/ui es5/sre es5/adaptors ../../_static/mathjax/
	cp -R $(VENDOR)/node_modules/mathjax/es5/output/chtml $(VENDOR)/_static/mathjax/output/
	cp $(VENDOR)/node_modules/requirejs/require.js $(VENDOR)/node_modules/requirejs/package.json $(VENDOR)/_static/requirejs/
	cd $(VENDOR)/node_modules/@jupyter-widgets/html-manager && cp package.json dist/embed-amd.js dist/*.woff dist/*.woff2 \
		dist/*.ttf dist/*.eot dist/*.svg ../../../_static/html-manager/
	@touch $@

vendor: $(VENDOR_STAMP)

lint: $(STAMP)
	$(BIN)/ruff check $(wildcard $(LINTED))

# Agg for the tests' own drawings, on this line only: a notebook kernel that inherits
# MPLBACKEND draws nowhere, and the book would build with every figure missing
# (tests/test_book.py checks that each cell that draws shows a figure).
# The browser tests' modules list the built pages when collected: left out here, so that
# `make test` can run this beside a book build that is rewriting book/_build.
unit: $(STAMP)
	MPLBACKEND=Agg $(BIN)/python -m pytest -q -p no:cacheprovider tests gearlib --doctest-modules -n 2 --dist worksteal \
		-m "not book and not browser and not pdf and not course and not course_html" \
		--ignore=tests/test_browser.py --ignore=tests/test_lab.py

notebooks: $(STAMP) $(KERNEL_CONFIG)
	$(BIN)/python -m pytest -q -p no:cacheprovider --nbval-lax --nbval-sanitize-with tests/nbval_sanitize.cfg \
		--nbval-cell-timeout=300 -n 2 --dist loadfile $(wildcard $(NOTEBOOKS))

# Warnings are errors (-W, -n: every reference must resolve); then the built files are
# checked: every local link and anchor resolves, nothing loads from another host.
# book/build.py is `jupyter-book build` with Sphinx reading (so executing) pages in
# parallel, one worker per CPU (JB_JOBS=1 for a serial build).
# A clean build removes everything in book/_build but the screenshots, which the JupyterLab
# test may be writing meanwhile (make test).
# The build is skipped when book/_build/.inputs says it was made from these very sources
# (book/inputs.py: a digest of chapters/, exercises/, book/, gearlib/, course/, the pins and
# this file); its tests run either way. make clean-book forces a build.
build-book: $(STAMP) $(KERNEL_CONFIG) $(VENDOR_STAMP)
	@digest=$$($(BIN)/python book/inputs.py); \
	if [ -f book/_build/html/index.html ] && [ "$$digest" = "$$(cat book/_build/.inputs 2>/dev/null)" ]; then \
		echo "book/_build was built from these sources (book/inputs.py): not built again (make clean-book forces it)"; \
	else \
		mkdir -p book/_build && find book/_build -mindepth 1 -maxdepth 1 ! -name screenshots -exec rm -rf {} + && \
		echo "$(BIN)/python book/build.py . $(JB_FLAGS)" && $(BIN)/python book/build.py . $(JB_FLAGS) && \
		test -f book/_build/html/index.html && echo "$$digest" > book/_build/.inputs; \
	fi
	$(BIN)/python -m pytest -q -p no:cacheprovider -m book tests/test_book.py tests/test_book_reading.py tests/test_exercise_leaks.py
	@echo "The book is in book/_build/html/index.html"

book: build-book

clean-book:
	mkdir -p book/_build && find book/_build -mindepth 1 -maxdepth 1 ! -name screenshots -exec rm -rf {} +
	rm -rf course/_build/html

# The PDF: Sphinx's LaTeX builder on a copy of the environment the HTML build left in
# book/_build/.doctrees (it reads and executes nothing again: "0 changed"; a copy, because
# Jupyter Book's LaTeX extension changes numfig_secnum_depth for the LaTeX build, and an
# environment saved with it would make the next build read and execute every page), then
# xelatex through latexmk (three runs and xindy for the index), then a check of the PDF
# (tests/test_pdf.py). Debian's TeX Live, fonts and poppler-utils are installed with
# apt-get where that is possible (root); about 86 MB to download, 600 MB installed.
TEX_PACKAGES := texlive-xetex texlive-latex-recommended texlive-latex-extra texlive-fonts-recommended \
	latexmk xindy fonts-freefont-otf fonts-dejavu-core poppler-utils
LATEX_DIR := book/_build/latex

tex:
	@if ! { command -v xelatex && command -v latexmk && command -v xindy && command -v pdftotext \
			&& fc-list | grep -q FreeSerif && fc-list | grep -q "DejaVu Sans Mono"; } >/dev/null; then \
		if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
			echo "installing Debian's TeX Live (xelatex), fonts and poppler-utils for the PDF"; \
			apt-get -o DPkg::Lock::Timeout=900 update -qq && DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=900 install -y -qq --no-install-recommends \
				$(TEX_PACKAGES) >/dev/null; \
		else \
			echo "make pdf needs xelatex, latexmk, xindy, fonts and pdftotext: apt-get install --no-install-recommends $(TEX_PACKAGES)"; \
			exit 1; \
		fi; \
	fi

# after build-book (or make book), without building the HTML again
pdf-from-build: $(STAMP) tex
	@test -f book/_build/.doctrees/environment.pickle || { echo "no built book: run make book first"; exit 1; }
	@if [ -f $(LATEX_DIR)/book.pdf ] && [ -f book/_build/.inputs ] && cmp -s book/_build/.inputs $(LATEX_DIR)/.inputs; then \
		echo "$(LATEX_DIR)/book.pdf was made from this build of the book: not made again"; \
	else \
		rm -rf book/_build/.doctrees-latex $(LATEX_DIR) && cp -R book/_build/.doctrees book/_build/.doctrees-latex && \
		JB_DOCTREES=book/_build/.doctrees-latex $(BIN)/python book/build.py . $(JB_FLAGS) --builder latex && \
		$(MAKE) --no-print-directory -C $(LATEX_DIR) all-pdf LATEXMKOPTS="-xelatex -silent" \
			LATEXOPTS="-interaction=nonstopmode -halt-on-error -file-line-error" && \
		{ cp book/_build/.inputs $(LATEX_DIR)/.inputs 2>/dev/null || true; }; \
	fi
	$(BIN)/python -m pytest -q -p no:cacheprovider -m pdf tests/test_pdf.py
	@echo "The PDF is in $(LATEX_DIR)/book.pdf"

pdf: build-book
	$(MAKE) --no-print-directory pdf-from-build

# Debian's chromium for the browser test: installed when missing where that is possible
# (root and apt-get); elsewhere the browser test skips and says why.
chromium:
	@if [ -z "$(CHROMIUM)" ]; then \
		if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
			echo "installing Debian's chromium for the browser test"; \
			(apt-get -o DPkg::Lock::Timeout=900 update -qq && DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=900 install -y -qq chromium >/dev/null) \
				|| echo "could not install chromium: the browser test will be skipped"; \
		else \
			echo "chromium is missing and cannot be installed here (needs root and apt-get): the browser test will be skipped"; \
		fi; \
	fi

# Headless Chromium: every page of the built book from disk with the network off
# (browser-pages, after build-book), and each chapter run in JupyterLab (make lab's server,
# on 127.0.0.1) with its widgets moved (browser-lab, needs no build). Screenshots go to
# book/_build/screenshots.
browser: browser-pages browser-lab

browser-pages: $(STAMP) chromium
	@test -f book/_build/html/index.html || { echo "no built book: run make book first"; exit 1; }
	$(BIN)/python -m pytest -q -p no:cacheprovider -m browser -n 2 --durations=3 tests/test_browser.py

browser-lab: $(STAMP) $(KERNEL_CONFIG) chromium
	$(BIN)/python -m pytest -q -p no:cacheprovider -m browser -n 2 --durations=3 tests/test_lab.py

# after the build: its pages in Chromium, and the PDF from the same environment (side by side)
book-then-pages: build-book
	$(MAKE) --no-print-directory -j2 -O browser-pages pdf-from-build

# The book build executes every notebook in a fresh kernel and fails on any error (as nbval
# did here before; tests/test_repo.py checks that every notebook is in the book), so make
# test does not run them twice; `make notebooks` runs them under nbval alone.
# Four chains side by side on two cores, so that none leaves a core idle (kernel
# start-ups, Sphinx's serial steps, a browser waiting for a kernel): the unit tests, the
# chapters in JupyterLab, the book build followed by its pages in Chromium and the PDF, and
# the course kit's tests followed, once the book is built (one build serves both chains),
# by the course's HTML book. -O prints each one's output whole when it ends.
test: lint
	$(MAKE) --no-print-directory -j4 -O unit browser-lab book-then-pages course-then-html

course-then-html: course-test build-book
	$(MAKE) --no-print-directory course-html

# JupyterLab (root must say so) at the book's start, with ipywidgets' extension for live widgets
lab: $(STAMP) $(KERNEL_CONFIG)
	$(BIN)/jupyter lab $(if $(filter 0,$(shell id -u)),--allow-root) chapters/00_introduction.ipynb

bench: $(STAMP) $(KERNEL_CONFIG)
	$(BIN)/python benchmarks/run.py

# Determinism: every notebook three times in fresh kernels; outputs nbval compares must not change.
nbval-repeat: $(STAMP) $(KERNEL_CONFIG)
	$(BIN)/python tests/notebook_tools.py repeat 3 $(wildcard $(NOTEBOOKS))

strip: $(STAMP)
	$(BIN)/python tests/notebook_tools.py strip $(wildcard $(NOTEBOOKS))

clean:
	rm -rf book/_build .pytest_cache .hypothesis $(VENDOR)/_static $(VENDOR)/node_modules course/_build $(PROXY)/node_modules

# The course kit (book/lecturers.ipynb). make course builds course/_build from the exercise
# notebooks and their worked solutions: each student's notebooks (from the class list
# CLASS), nbgrader's course directory (source with solutions and autograder tests, release,
# gradebook), nbgitpuller links for the hub HUB pulling REPO at BRANCH (default: origin and
# the current branch), and the course's HTML book (no solution pages) from the notebooks the
# last book build executed (make book first when the chapters changed).
CLASS ?= course/class.csv
HUB ?= http://127.0.0.1:8000
REPO ?=
BRANCH ?=
PROXY := course/proxy
PROXY_STAMP := $(PROXY)/node_modules/.installed

course-notebooks: $(STAMP)
	$(BIN)/python -m course.build notebooks --classlist $(CLASS) --hub $(HUB) $(if $(REPO),--repo $(REPO)) \
		$(if $(BRANCH),--branch $(BRANCH))

course-html: $(STAMP) $(VENDOR_STAMP)
	@test -d book/_build/jupyter_execute || $(MAKE) --no-print-directory build-book
	@if [ -f course/_build/html/index.html ] && [ -f book/_build/.inputs ] && cmp -s book/_build/.inputs course/_build/html/.inputs; then \
		echo "course/_build/html was made from this build of the book: not made again"; \
	else \
		$(BIN)/python -m course.build html && { cp book/_build/.inputs course/_build/html/.inputs 2>/dev/null || true; }; \
	fi
	$(BIN)/python -m pytest -q -p no:cacheprovider -m course_html tests/test_course_html.py

course: course-notebooks course-html

# configurable-http-proxy, JupyterHub's proxy, from npm (pinned in course/proxy/package-lock.json)
$(PROXY_STAMP): $(PROXY)/package.json $(PROXY)/package-lock.json
	$(call NPM,configurable-http-proxy)
	cd $(PROXY) && npm ci --ignore-scripts --no-audit --no-fund --loglevel=error
	@touch $@

proxy: $(PROXY_STAMP)

# JupyterHub for a class on this machine (PAM accounts, a server per student; settings in
# course/jupyterhub_config.py: COURSE_CLASS, COURSE_ADMINS, COURSE_REPO, ...)
hub: $(STAMP) $(PROXY_STAMP)
	$(BIN)/jupyterhub -f course/jupyterhub_config.py

# The kit's tests: the grader on a course built for a test class (tests/test_course.py), and
# a class of two on JupyterHub whose servers run in a fresh environment installed from
# binder/ (tests/test_course_hub.py), side by side
course-test: $(STAMP) $(PROXY_STAMP)
	$(BIN)/python -m pytest -q -p no:cacheprovider -m course -n 2 --dist loadfile --durations=6 \
		tests/test_course.py tests/test_course_hub.py

# binder/constraints.txt: the pins of environment.txt for repo2docker (a test compares them)
binder-constraints:
	{ sed -n 1,3p binder/constraints.txt; grep -E "^[A-Za-z0-9_.-]+==" environment.txt; } > binder/constraints.txt.new
	mv binder/constraints.txt.new binder/constraints.txt
