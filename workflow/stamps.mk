# Configuration: Make takes the profile's seeds, scenes and the stages' stamps from
# softpack-config (apps/softpack_config.cpp), which reads the profile with the stages' own
# readers and section lists (pipeline/profile/profile.cpp): Make never parses YAML.
#
# Stamps: each stage depends on a file holding a hash of exactly the profile sections it reads
# (and of the release), not on the profile's timestamp. The hash is computed while make reads the
# makefiles; the stamp file is rewritten by a rule, and only when the hash differs from what it
# holds, so make reruns exactly the stages downstream of a changed section, and `make -n` and
# `make -q` say so without writing anything. Editing a comment or a key no stage reads reruns
# nothing.

VERSION := $(shell awk '/^project/ { print $$3; exit }' CMakeLists.txt)
STAMPS := $(DATA)/$(PROFILE)/stamps
# A profile is experiments/PROFILE.yaml unless PROFILE_FILE names another file (the accuracy
# study's generated profiles, workflow/studies.mk).
PROFILE_FILE ?= experiments/$(PROFILE).yaml

# config ARGS [PROFILE]: what softpack-config says of the profile (ARGS: seeds, scenes, stamp STAGE);
# a profile it refuses stops make with its message.
config = $(shell $(CONFIG_TOOL) $(or $(2),$(PROFILE_FILE)) $(1))$(if $(filter-out 0,$(.SHELLSTATUS)),$(error \
  $(or $(2),$(PROFILE_FILE)) is refused (the message above); fix it, or make build if softpack-config is out of date))

# stamp NAME STAGE [PROFILE [DIR]]: the path of DIR/NAME.hash (DIR: $(STAMPS)), with a rule that
# writes the stage's current stamp into it when it holds another (or does not exist), first
# removing what a run killed between the write and the rename left (only this rule writes them).
stamp = $(eval $(call stamp_rule,$(or $(4),$(STAMPS))/$(1).hash,$(call config,stamp $(2) --release $(VERSION),$(3))))$(or \
  $(4),$(STAMPS))/$(1).hash
define stamp_rule
$(1): $(if $(filter-out $(2),$(file < $(1))),FORCE)
	@mkdir -p $$(@D) && rm -f $$@.tmp.* && echo $(2) > $$@.tmp.$$$$$$$$ && mv $$@.tmp.$$$$$$$$ $$@
endef
.PHONY: FORCE
FORCE:

# planned STAMP_FILE: the option that gives a stage the stamp make planned it with, read from the
# stamp file when the stage's recipe runs (after the stamp rule wrote it); the stage refuses to run
# when the profile's stamp differs by then (the profile was edited during the run: a revert before
# the run ends would otherwise leave results of the edited profile that look up to date).
planned = --stamp '$(file < $(1))'

ifeq ($(wildcard $(PROFILE_FILE)),)
$(error $(PROFILE_FILE): no such profile (PROFILE=$(PROFILE)); the profiles here: $(notdir $(basename $(shell \
  grep -l '^profile:' experiments/*.yaml))); or your own, PROFILE=path/to/own.yaml)
endif
# A profile's results carry the name make gives it (its file's, or PROFILE=); a `profile:` key
# naming another would be refused only at the fit, after the sweeps: refused here instead.
PROFILE_NAME := $(call config,name)
ifneq ($(if $(PROFILE_NAME),$(PROFILE_NAME),$(PROFILE)),$(PROFILE))
$(error $(PROFILE_FILE) names itself '$(PROFILE_NAME)' (its profile: key), but make names it '$(PROFILE)' \
  (after its file) and puts its results in $(DATA)/$(PROFILE)/: make the key profile: $(PROFILE), or rename the file $(PROFILE_NAME).yaml)
endif
SEEDS := $(call config,seeds)
SCENES := $(call config,scenes)
# A normal-only profile (no `tangential` section) has the packing and normal stages, and its
# averages, fits, Table 1 and Figure 3 are of the normal law only (workflow/analysis.mk).
STAGES := $(call config,stages)
NORMAL_ONLY := $(if $(filter tangential,$(STAGES)),,1)
NOT_NORMAL_ONLY_GOALS := tangential sweeps paper archive all timing
ifneq ($(NORMAL_ONLY),)
ifneq ($(filter $(NOT_NORMAL_ONLY_GOALS),$(MAKECMDGOALS)),)
$(error $(PROFILE_FILE) is a normal-only profile (no tangential section): $(filter $(NOT_NORMAL_ONLY_GOALS),$(MAKECMDGOALS)) \
  need the tangential stage; its targets are packings, normal, averages, fits, tables and figures)
endif
endif
PACK_STAMP := $(call stamp,packing,packing)
NORMAL_STAMP := $(call stamp,normal,normal)
TANGENTIAL_STAMP := $(call stamp,tangential,tangential)
# The sliding measurement (issue 16): only in a profile with a `sliding` section.
HAS_SLIDING := $(filter sliding,$(STAGES))
ifneq ($(filter sliding,$(MAKECMDGOALS)),)
ifeq ($(HAS_SLIDING),)
$(error $(PROFILE_FILE) has no sliding section: make sliding measures the friction of a profile that has one (experiments/studies/radius.yaml))
endif
endif
SLIDING_STAMP := $(if $(HAS_SLIDING),$(call stamp,sliding,sliding))
AVERAGE_STAMP := $(call stamp,average,average)

# Results recorded in the archive are reused when their stage's stamp matches (FROM_SCRATCH=1
# ignores the archive), after workflow/archive_check.sh has checked them, the stamp and the
# manifest against MANIFEST.sha256 and dataset.bib. from_archive FILES STAMP: copies the archived
# FILES (all of them), or fails when the archive does not hold them; a damaged archive ends the
# recipe (exit 2) with the checker's message, never a silent recomputation.
ARCHIVE := $(ARCHIVE_ROOT)/$(VERSION)/$(PROFILE)
from_archive = $(if $(FROM_SCRATCH),false,{ workflow/archive_check.sh reuse $(ARCHIVE) $(2) $(1); \
  rc=$$?; [ $$rc != 2 ] || exit 2; [ $$rc = 0 ]; })

# clear_stale FILES [DIRS]: removes what a killed run may have left: temporaries of FILES
# (FILE.tmp.<pid>) and of anything in DIRS. Only this recipe writes these names, so concurrent
# jobs (make -j, RUN=srun) never remove each other's files.
clear_stale = rm -f $(addsuffix .tmp.*,$(1)) $(addsuffix /*.tmp.*,$(2))
