# Two commands set up a fresh machine from nothing (Python 3.11 and make):
#   make book   build the HTML book into book/_build/html
#   make test   run every test (lint, unit and doc tests, notebooks, book build)
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
export MPLBACKEND := Agg

NOTEBOOKS := chapters exercises book/solutions
LINTED := gearlib tests chapters exercises book benchmarks
JB_FLAGS := --config book/_config.yml --toc book/_toc.yml --path-output book -W -n --keep-going

.PHONY: help venv lint unit notebooks book build-book test lab bench strip clean

help:
	@echo "make book   build the HTML book into book/_build/html (creates .venv if needed)"
	@echo "make test   lint, unit and doc tests, notebooks (nbval), book build"
	@echo "make lab    open JupyterLab at the book's start"
	@echo "make bench  speed benchmarks (benchmarks/)"
	@echo "make strip  remove outputs from every notebook before committing"

$(STAMP): environment.txt pyproject.toml
	@test -d $(VENV) || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip 2>&1 | grep -v "is ignored" || true
	$(BIN)/python -m pip install --quiet -r environment.txt 2>&1 | grep -v "is ignored" || true
	$(BIN)/python -c "import gearlib, jupyter_book, nbval, sympy, matplotlib"
	$(BIN)/python -m ipykernel install --sys-prefix --name python3 --display-name "Python 3 (gearlib)" >/dev/null
	@touch $(STAMP)

venv: $(STAMP)

lint: $(STAMP)
	$(BIN)/ruff check $(wildcard $(LINTED))

unit: $(STAMP)
	$(BIN)/python -m pytest -q -p no:cacheprovider tests gearlib --doctest-modules -n 2

notebooks: $(STAMP)
	$(BIN)/python -m pytest -q -p no:cacheprovider --nbval-lax --nbval-sanitize-with tests/nbval_sanitize.cfg \
		--nbval-cell-timeout=300 -n 2 --dist loadfile $(wildcard $(NOTEBOOKS))

build-book: $(STAMP)
	rm -rf book/_build
	$(BIN)/jupyter-book build . $(JB_FLAGS)
	@test -f book/_build/html/index.html
	@echo "The book is in book/_build/html/index.html"

book: build-book

test: lint unit notebooks build-book

lab: $(STAMP)
	$(BIN)/jupyter lab chapters/00_introduction.ipynb

bench: $(STAMP)
	$(BIN)/python benchmarks/run.py

strip: $(STAMP)
	$(BIN)/python tests/notebook_tools.py strip $(wildcard $(NOTEBOOKS))

clean:
	rm -rf book/_build .pytest_cache .hypothesis
