# Configuration stamps: each stage depends on a file holding a hash of exactly the profile
# sections it reads (and of the release version), not on the profile's timestamp. The stamps
# are brought up to date while make reads the makefiles, so `make -n` and `make -q` see them:
# a file is rewritten (new mtime) only when its hash changes, and make reruns exactly the
# stages downstream of a changed stamp. Editing a comment or a key no stage reads reruns nothing.

VERSION := $(shell awk '/^project/ { print $$3; exit }' CMakeLists.txt)
STAMPS := $(DATA)/$(PROFILE)/stamps

# config_slice SECTIONS [FILE]: those top-level sections of FILE (the profile by default),
# comments and blank lines dropped.
config_slice = awk -v want="$(1)" 'BEGIN { n = split(want, w, " "); for (i = 1; i <= n; i++) keep[w[i]] = 1 } \
  /^[A-Za-z_][A-Za-z0-9_-]*:/ { key = $$0; sub(/:.*/, "", key); on = (key in keep) } \
  on { sub(/[ \t]+\#.*$$/, ""); if ($$0 ~ /^[ \t]*(\#|$$)/) next; print }' $(or $(2),experiments/$(PROFILE).yaml)

# stamp NAME SECTIONS [FILE [DIR]]: the path of DIR/NAME.hash (DIR: $(STAMPS)), brought up to date.
stamp = $(shell d=$(or $(4),$(STAMPS)) && mkdir -p $$d && \
  h=$$( { echo "softpack $(VERSION)"; $(call config_slice,$(2),$(3)); } | sha256sum | cut -c1-16) && \
  { [ "$$h" = "$$(cat $$d/$(1).hash 2> /dev/null)" ] || echo "$$h" > $$d/$(1).hash; } && echo $$d/$(1).hash)

ifneq ($(wildcard experiments/$(PROFILE).yaml),)
PACK_STAMP := $(call stamp,packing,packing)
NORMAL_STAMP := $(call stamp,normal,packing material simulation relaxation normal)
TANGENTIAL_STAMP := $(call stamp,tangential,packing material simulation relaxation normal tangential)
AVERAGE_STAMP := $(call stamp,average,seeds packing material simulation relaxation normal tangential)
else
$(error experiments/$(PROFILE).yaml: no such profile (PROFILE=$(PROFILE)); profiles: $(notdir $(basename $(wildcard experiments/*.yaml))))
endif

# Results recorded in the archive are reused when their stage's stamp matches (FROM_SCRATCH=1
# ignores the archive). from_archive FILES STAMP: copies the archived FILES (all of them), or fails.
ARCHIVE_ROOT := data/archive
ARCHIVE := $(ARCHIVE_ROOT)/$(VERSION)/$(PROFILE)
archived = $(patsubst $(DATA)/$(PROFILE)/%,$(ARCHIVE)/%,$(1))
from_archive = [ -z "$(FROM_SCRATCH)" ] && cmp -s $(call archived,$(2)) $(2) && \
  $(foreach f,$(1),[ -f $(call archived,$(f)) ] &&) \
  $(foreach f,$(1),cp $(call archived,$(f)) $(f).tmp.archive && mv $(f).tmp.archive $(f) &&) \
  echo "reused $(1) from $(ARCHIVE) (same configuration)"

# clear_stale FILES [DIRS]: removes what a killed run may have left: temporaries of FILES
# (FILE.tmp.<pid>) and of anything in DIRS. Only this recipe writes these names, so concurrent
# jobs (make -j, RUN=srun) never remove each other's files.
clear_stale = rm -f $(addsuffix .tmp.*,$(1)) $(addsuffix /*.tmp.*,$(2))
