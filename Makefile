# softpack — top-level entry points. `make help` lists them.
#
# The build lives in build/ (release, -O3 -march=x86-64-v2) and build-sanitize/ (debug with
# AddressSanitizer + UndefinedBehaviorSanitizer). CI=true turns warnings into errors.

SHELL := /bin/bash
.DEFAULT_GOAL := help
.DELETE_ON_ERROR:

PROFILE ?= paper
# Your own profile, kept anywhere: PROFILE=path/to/own.yaml (absolute, or relative to this folder;
# from elsewhere, make -C softpack PROFILE=$PWD/own.yaml) is that file, named after it (its
# results in DATA/own/); the paths in it (imported packings) are relative to its folder.
ifneq ($(filter %.yaml %.yml,$(PROFILE)),)
override PROFILE_FILE := $(abspath $(PROFILE))
override PROFILE := $(basename $(notdir $(PROFILE)))
endif
DATA ?= data
RUN ?=
BUILD ?= build
BUILD_SANITIZE ?= build-sanitize
JOBS ?= $(shell nproc)
CMAKE_FLAGS := -DCMAKE_BUILD_TYPE=Release $(if $(filter true,$(CI)),-DSOFTPACK_WERROR=ON)

# Debian 12 packages the project needs (build, tests, benchmarks, plots, LAMMPS comparison).
APT_PACKAGES := cmake g++ make git pkg-config gnuplot-nox \
  libeigen3-dev libyaml-cpp-dev libhdf5-dev hdf5-tools nlohmann-json3-dev \
  libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev libfmt-dev libssl-dev \
  lammps liblammps-dev python3-numpy python3-h5py clang libclang-rt-14-dev
# Installed without their recommends (about a tenth of the download): the report (make paper,
# TeX Live); a one-node Slurm cluster for the tests (tests/cluster/); the readers users open our
# files with, in the tests (ParaView's pvpython and VTK, ASE, matplotlib; tests/readers/). Debian 12's
# python3-vtk9 conflicts with python3-paraview: ParaView's own VTK modules stand for it.
APT_LEAN_PACKAGES := latexmk texlive-latex-recommended texlive-latex-extra texlive-fonts-recommended poppler-utils \
  slurm-wlm munge python3-paraview python3-ase python3-matplotlib
SUDO := $(if $(filter 0,$(shell id -u)),,sudo)

# Make splits words at spaces and reads ':' and '%' in targets as rule syntax: a path holding
# one is refused, in one line, before anything runs.
ifneq ($(words $(DATA)),1)
$(error DATA='$(DATA)' holds a space (or is empty): make cannot use such a path; choose a data folder without spaces)
endif
ifneq ($(findstring :,$(DATA))$(findstring %,$(DATA)),)
$(error DATA='$(DATA)' holds ':' or '%': make cannot use such a path in its rules; choose another data folder)
endif
# ... and a path holding a character make or the shell reads as syntax (; * ? # $ quotes, a
# backtick, a backslash, brackets, braces, parentheses, < > | & !, a control character) would run
# another command or take another folder's lock: refused likewise. Allowed: letters, digits and
# . _ - + = , @ / ~ (docs/architecture.md, "Everything a run writes lives under its DATA").
DATA_SYNTAX := $(shell printf '%s' '$(subst ','"'"',$(value DATA))' | LC_ALL=C tr -d 'A-Za-z0-9._+=,@/~-')
ifneq ($(DATA_SYNTAX),)
$(error DATA holds '$(DATA_SYNTAX)': characters make or the shell would read as syntax; choose a data folder of letters, digits and . _ - + = , @ / ~)
endif
ifneq ($(words $(BUILD) $(CURDIR)),2)
$(error the build folder '$(BUILD)' or the source folder '$(CURDIR)' holds a space: make cannot use such a path)
endif

# The studies of settings: each file of experiments/studies/ is a goal of its name and NAME-report
# (workflow/studies.mk), known without the tools (a fresh clone builds them, then runs the goal).
STUDY_FILES := $(sort $(wildcard experiments/studies/*.yaml))
STUDY_NAMES := $(basename $(notdir $(STUDY_FILES)))
# The goals that need the tools and a profile (the pipeline's and the studies').
PIPELINE_GOALS := all tables figures paper archive packings normal tangential sliding sweeps averages fits figure1 figure2 \
  study study-report $(STUDY_NAMES) $(STUDY_NAMES:%=%-report) fast-check timing \
  coarse-grain-runs coarse-grain-multi-contact many-body-probe many-body-report many-body-verdict many-body-census lammps-check nested nested-report
# The goals that write nothing under DATA; every other goal (a file named on the command line too)
# writes there and takes its lock.
NO_DATA_GOALS := help setup build build-tools test test-sanitize test-all bench verify fuzz-build fuzz fuzz-corpus
MAKE_LETTERS := $(firstword -$(MAKEFLAGS))

# One run per data folder: a goal that writes DATA runs make again under DATA's lock
# (workflow/with_lock.sh; a second run waits for the first, or refuses with LOCK_WAIT=0).
# make -n and make -q write nothing and take no lock.
LOCKED_GOALS := $(if $(SOFTPACK_LOCK)$(findstring n,$(MAKE_LETTERS))$(findstring q,$(MAKE_LETTERS)),,$(filter-out \
  $(NO_DATA_GOALS),$(MAKECMDGOALS)))
ifneq ($(LOCKED_GOALS),)
.PHONY: $(MAKECMDGOALS)
$(firstword $(MAKECMDGOALS)):
	@workflow/with_lock.sh $(DATA) $(MAKE) --no-print-directory SOFTPACK_LOCK=held $(MAKECMDGOALS)
$(wordlist 2,$(words $(MAKECMDGOALS)),$(MAKECMDGOALS)): $(firstword $(MAKECMDGOALS))
	@:
else

.PHONY: help setup all build build-tools test test-sanitize bench clean

help:  ## list the targets
	@echo "softpack — reproducible soft-particle contact laws (see README.md)"
	@echo
	@grep -hE '^[a-z0-9-]+:.*## ' Makefile workflow/*.mk | sed -E 's/^([a-z0-9-]+):.*## (.*)/  make \1\t\2/' | expand -t 24
	@echo; echo "the studies of experiments/studies/ (make NAME, make NAME-report; SETTINGS=\"a b\" runs only those):"
	@for s in $(STUDY_NAMES); do echo "  make $$s"; done

setup:  ## install the Debian packages (apt-get; quick when they are there)
	@missing=$$(for p in $(APT_PACKAGES) $(APT_LEAN_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q 'ok installed' || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "setup: installing" $$missing; \
	  $(SUDO) apt-get update -q && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -q $(APT_PACKAGES) \
	  && DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -q --no-install-recommends $(APT_LEAN_PACKAGES); \
	else echo "setup: all $(words $(APT_PACKAGES) $(APT_LEAN_PACKAGES)) Debian packages are present"; fi

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) $(CMAKE_FLAGS)

build: build-tools  ## compile the engine, its commands and the tests (log: BUILD/build.log; make bench builds the benchmarks)

# The one rule that compiles (make -j would otherwise run two builds in the same folder). Every
# stage has it as an order-only prerequisite ($(TOOLS), workflow/packing.mk).
build-tools: $(BUILD)/CMakeCache.txt
	@MAKEFLAGS= cmake --build $(BUILD) -j $(JOBS) > $(BUILD)/build.log 2>&1 \
	  || { echo "build: FAILED; the end of $(BUILD)/build.log:"; tail -40 $(BUILD)/build.log; exit 1; }
	@echo "build: $(BUILD) is up to date (log $(BUILD)/build.log)"

ifneq ($(wildcard $(BUILD)/bin/softpack-config),)
all: build tables figures paper scenes  ## the main job: Tables 1-2, Figures 1-6, DATA/PROFILE/paper/paper.pdf, the example scenes
endif

.PHONY: scenes
scenes: | build-tools  ## run the example scenes of experiments/scenes/ (DATA/scenes/*.json)
	@for scene in experiments/scenes/*.yaml; do \
	  out=$(DATA)/scenes/$$(basename $$scene .yaml).json; \
	  echo "softpack-run $$scene -> $$out"; \
	  $(RUN) $(BUILD)/bin/softpack-run --scene $$scene --out $$out --quiet || exit 1; \
	done

# ctest runs $(JOBS) tests at once: each on one engine thread unless SOFTPACK_THREADS says
# otherwise (the tests of threads ask for theirs; core/parallel.hpp).
test: build  ## build and run the test suite (ctest)
	cd $(BUILD) && SOFTPACK_THREADS=$${SOFTPACK_THREADS:-1} ctest --output-on-failure -j $(JOBS)

# The sanitizer build checks our C++ for memory errors and undefined behaviour: -O1 (what
# AddressSanitizer is made for), -g1 (line tables for the reports' stacks; full debug info tripled
# the compile time of the force loops), the portable force loops only (SOFTPACK_AVX512=OFF:
# AddressSanitizer does not see what AVX-512 gathers touch). It runs the tests that exercise our
# C++, not those of the orchestration around it (labels workflow, cluster, readers: Make, Slurm,
# Python, whose C++ the others already run) nor the long ones (slow); tests/README.md.
SANITIZE_SKIPS := workflow|cluster|readers|slow
test-sanitize:  ## the tests of our C++ under AddressSanitizer + UndefinedBehaviorSanitizer
	cmake -S . -B $(BUILD_SANITIZE) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
	  -DSOFTPACK_SANITIZE=ON -DSOFTPACK_BENCH=OFF -DSOFTPACK_AVX512=OFF \
	  $(if $(filter true,$(CI)),-DSOFTPACK_WERROR=ON)
	cmake --build $(BUILD_SANITIZE) -j $(JOBS)
	cd $(BUILD_SANITIZE) && SOFTPACK_THREADS=$${SOFTPACK_THREADS:-1} ctest --output-on-failure -j $(JOBS) $(if $(SANITIZE_SKIPS),-LE "$(SANITIZE_SKIPS)")

.PHONY: test-all
test-all: test  ## on demand: make test, then every label under the sanitizers too (tests/README.md)
	@$(MAKE) --no-print-directory test-sanitize SANITIZE_SKIPS=

bench: build  ## benchmarks: engine throughput, contact detection, LAMMPS side by side
	@MAKEFLAGS= cmake --build $(BUILD) -j $(JOBS) --target softpack_bench >> $(BUILD)/build.log 2>&1 \
	  || { echo "build: the benchmarks FAILED; the end of $(BUILD)/build.log:"; tail -40 $(BUILD)/build.log; exit 1; }
	bench/run_benchmarks.sh $(BUILD)

clean:  ## remove the builds and the profile's generated data and figures (keeps data/archive and the studies' committed records)
	rm -rf $(BUILD) $(BUILD_SANITIZE) $(FUZZ_BUILD) $(DATA)/scenes $(DATA)/$(PROFILE)
	@if git ls-files --error-unmatch $(DATA)/studies > /dev/null 2>&1; then git clean -fdxq -- $(DATA)/studies; \
	  else rm -rf $(DATA)/studies; fi

# make verify needs no build: every archive under data/archive (or ARCHIVES=dir...) against its
# MANIFEST.sha256, and each manifest against the SHA-256 its dataset.bib cites.
ARCHIVE_ROOT := data/archive
ARCHIVES ?= $(patsubst %/MANIFEST.sha256,%,$(wildcard $(ARCHIVE_ROOT)/*/*/MANIFEST.sha256))
.PHONY: verify
verify:  ## check every archived file against MANIFEST.sha256 (ARCHIVES=dir... for some)
	@workflow/archive_check.sh verify $(ARCHIVES)

# The pipeline's rules come from the profile, which softpack-config reads for Make
# (workflow/stamps.mk). Before it is built (a fresh clone), the pipeline's goals build the tools,
# then run make again, which then reads the profile.
CONFIG_TOOL := $(BUILD)/bin/softpack-config
# Goals that need no profile: they must work with tools of an older checkout, which may refuse
# the current profile (make build is what updates them).
NO_PROFILE_GOALS := build build-tools setup help clean test test-sanitize test-all bench verify
PROFILE_GOALS := $(if $(MAKECMDGOALS),$(filter-out $(NO_PROFILE_GOALS),$(MAKECMDGOALS)),help)
ifeq ($(PROFILE_GOALS),)
# build, setup, test... only: the pipeline's rules are not read.
else ifneq ($(wildcard $(CONFIG_TOOL)),)
include workflow/stamps.mk
include workflow/packing.mk
include workflow/sweeps.mk
include workflow/analysis.mk
include workflow/archive.mk
include workflow/paper.mk
include workflow/studies.mk
include workflow/coarse.mk
include workflow/lammps.mk
include workflow/nested.mk
else ifneq ($(SOFTPACK_TOOLS_BUILT),)
$(error $(CONFIG_TOOL) is missing: $(if $(findstring n,$(firstword -$(MAKEFLAGS))),make -n needs the tools: run make build first,\
  the build did not make it (see $(BUILD)/build.log)))
else
.PHONY: $(PIPELINE_GOALS)
$(PIPELINE_GOALS): | build-tools
	@$(MAKE) --no-print-directory SOFTPACK_TOOLS_BUILT=1 $@
endif
include workflow/fuzz.mk

endif  # LOCKED_GOALS
