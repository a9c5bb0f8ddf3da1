# The studies of settings (issue 30, docs/studies.md): every file of experiments/studies/ is a
# study and a make goal of its name, with no make edit: `make NAME` writes the profile of the
# reference and of every setting (softpack-study profiles), runs each one's stages (the study's
# `stages`, by default the tangential sweeps and what they need) with the profile DAG itself (a
# make of its own: PROFILE_FILE the generated profile, DATA the study's folder `out`, so every
# point is checkpointed and every stage stamped; a study of the coarse-grain settings runs
# coarse-grain-runs likewise, workflow/coarse.mk; a stopped study loses at most the points in
# progress and a changed setting reruns only what it touches; a stage whose stamp and seeds are an
# earlier setting's is shared with it, share_stages), then `make NAME-report` writes
# the report of the study's kind (softpack-study report) and draws its figures.
#
#   make radius SETTINGS="similar-2"   # only those settings (and the reference: all is compared to it)
#   make radius-report                 # the report from what has run
#   make study STUDY=path/to/file.yaml # a study file elsewhere (study-report likewise)
#
# A setting whose run fails (the watchdog stops a time step too long to be stable) is reported
# as failed, with the first error of its logs (<folder>/<setting>/failed.txt); the study goes
# on. The reference must not fail.
STUDY_TOOL := $(BUILD)/bin/softpack-study
# (STUDY_FILES and STUDY_NAMES: Makefile, which needs them before the tools exist.)

.PHONY: study study-report $(STUDY_NAMES) $(STUDY_NAMES:%=%-report) fast-check
study: | $(TOOLS)  ## a study of settings: make study STUDY=FILE (each file of experiments/studies/ is a goal of its name)
	$(call study_run,$(STUDY))
	@$(MAKE) --no-print-directory study-report STUDY=$(STUDY)
study-report: | $(TOOLS)  ## the report and figures of a study from what has run: make study-report STUDY=FILE (or NAME-report)
	@$(call study_report,$(STUDY))
$(STUDY_NAMES): | $(TOOLS)
	$(call study_run,experiments/studies/$@.yaml)
	@$(MAKE) --no-print-directory study-report STUDY=experiments/studies/$@.yaml
$(STUDY_NAMES:%=%-report): | $(TOOLS)
	@$(call study_report,experiments/studies/$(@:-report=).yaml)

# study_run FILE: the recipe line that runs a study. Under make -n it says what it would run and
# runs nothing: a line that calls $(MAKE), or starts with +, runs even under -n, and the study's
# would write its profiles, logs and records.
study_run = $(if $(findstring n,$(MAKE_LETTERS)),@echo "study $(1): would write the profiles of its settings into its folder \
  (softpack-study plan) and run their stages there",+@$(call run_study,$(1)))

# run_study FILE: the file of the reference and of every setting (a profile, or the coarse-grain
# settings: report/study_base.hpp), then each one's stages in the study's folder by the make goals
# its base has (the profile DAG with PROFILE_FILE and DATA; the coarse-grain runs with
# COARSE_CONFIG and COARSE_DIR: softpack-study plan says which). SETTINGS: only those, and the
# reference. A setting whose run fails is recorded as failed. Nothing is taken from the release's
# archive of a profile (a setting is no profile of the project), except from the study's own
# `archive`, where the stamps match (workflow/archive_check.sh checks it first).
define run_study
[ -n "$(1)" ] || { echo "study: say which study: make study STUDY=FILE, or make NAME for experiments/studies/NAME.yaml" >&2; exit 2; }; \
plan=$$($(STUDY_TOOL) plan --study $(1) --data $(DATA)) || exit 2; eval "$$plan"; \
mkdir -p $$study_dir/profiles; \
settings=$$($(STUDY_TOOL) profiles --study $(1) --out-dir $$study_dir/profiles) || exit 2; \
chosen="$(SETTINGS)"; n=0; total=$$(echo $$settings | wc -w); done=; \
for s in $$settings; do n=$$((n + 1)); \
  if [ -n "$$chosen" ] && [ $$s != reference ] && ! echo " $$chosen " | grep -qF -- " $$s "; then continue; fi; \
  echo "study $(1): setting $$n/$$total: $$s ($$study_dir/$$s)"; mkdir -p $$study_dir/$$s; \
  $(call share_stages,$(1),$$study_dir,$$s,$$done); done="$$done $$s"; \
  if $(MAKE) --no-print-directory $${study_args//@SETTING@/$$s} > $$study_dir/$$s/make.log 2>&1; then rm -f $$study_dir/$$s/failed.txt; \
  else [ $$s != reference ] || { tail -20 $$study_dir/$$s/make.log; exit 1; }; \
    grep -h -m1 -e 'numerical error' -e 'error:' $$study_dir/$$s/*/*.log $$study_dir/$$s/make.log 2>/dev/null | head -1 \
      > $$study_dir/$$s/failed.txt; \
    echo "study $(1): setting $$s FAILED, reported as such: $$(cat $$study_dir/$$s/failed.txt)"; fi; \
  grep -E '^(pack|normal|tangential|sliding|average|fit|coarse-grain):' $$study_dir/$$s/make.log || true; \
done
endef

# share_stages FILE DIR SETTING EARLIER: a stage's results are shared, not recomputed, when an
# earlier setting of the study has the same stamp of that stage (stamps include every section
# upstream: workflow/stamps.mk, softpack-coarse stamp) and every seed of the setting, and the
# setting has none of its own yet (softpack-study share decides): its folder is hard links to the
# earlier one's, with its stamp file (same names, same times), so make finds it up to date; the
# normal stage's checkpoints come along (the tangential stage starts from them). A rerun of either
# writes new files (atomic renames), never through the links; the logs, which a recipe's
# redirection truncates in place, are copies of their own.
define share_stages
$(STUDY_TOOL) share --study $(1) --data $(2) --setting $(3) --earlier "$(4)" --release $(VERSION) | while read stage dir d; do \
  mkdir -p $(2)/$(3)/stamps && cp -al $(2)/$$d/$$dir $(2)/$(3)/$$dir && ln -f $(2)/$$d/stamps/$$stage.hash $(2)/$(3)/stamps/$$stage.hash \
  && if [ $$stage = normal ] && [ -d $(2)/$$d/checkpoints/normal ] && [ ! -e $(2)/$(3)/checkpoints/normal ]; then \
    mkdir -p $(2)/$(3)/checkpoints && cp -al $(2)/$$d/checkpoints/normal $(2)/$(3)/checkpoints/normal; fi \
  && find $(2)/$(3)/$$dir -name '*.log' -exec sh -c 'cp "$$1" "$$1.own" && mv "$$1.own" "$$1"' sh {} \; \
  && echo "study: $(3) shares $$d's $$dir (the same $$stage stamp, its seeds among $$d's)"; done; \
[ $${PIPESTATUS[0]} = 0 ] || exit 2
endef

# study_report FILE: the report of the study's kind from the settings run so far (settings not
# run are listed as such), then each of its figures (gnuplot: the script reads `data` and `out`).
define study_report
[ -n "$(1)" ] || { echo "study-report: say which study: make study-report STUDY=FILE, or make NAME-report" >&2; exit 2; }; \
plan=$$($(STUDY_TOOL) plan --study $(1) --data $(DATA)) || exit 2; eval "$$plan"; \
mkdir -p $$study_dir/report; \
$(STUDY_TOOL) report --study $(1) --data $$study_dir --out-dir $$study_dir/report > /dev/null || exit 2; \
for fig in $$study_figures; do script=$${fig%%:*}; rest=$${fig#*:}; data=$${rest%%:*}; name=$${rest#*:}; \
  if [ ! -f $$study_dir/report/$$data ]; then \
    echo "study $(1): the figure $$name is not drawn: no $$study_dir/report/$$data (its setting has not run)"; continue; fi; \
  for ext in pdf png; do \
    gnuplot -e "data='$$study_dir/report/$$data'; out='$$study_dir/report/$$name.tmp.$$ext'" $$script \
    && mv $$study_dir/report/$$name.tmp.$$ext $$study_dir/report/$$name.$$ext \
    || { echo "study $(1): FAILED to draw the figure $$name ($$script)"; exit 1; }; done; done; \
echo "study $(1): $$study_dir/report/table.md$$(for fig in $$study_figures; do printf ', %s.pdf' $${fig##*:}; done)"
endef

# The fast profile's confirmation (docs/accuracy.md, "The fast profile"): the tables of the paper
# profile and of the fast one (each reusing or computing its results as `make tables` does;
# FROM_SCRATCH=1 recomputes both, one after the other, for their costs side by side), then every
# quantity of the fidelity study compared on the paper's seeds, and the CPU time of each.
FAST_CHECK_DIR ?= $(DATA)/fast-check
fast-check: | $(TOOLS)  ## the fast profile against the paper profile on the paper's seeds (DATA/fast-check/)
	@$(MAKE) --no-print-directory PROFILE=paper tables
	@$(MAKE) --no-print-directory PROFILE=fast tables
	@$(STUDY_TOOL) check --data $(DATA) --reference experiments/paper.yaml --candidate experiments/fast.yaml \
	  --out-dir $(FAST_CHECK_DIR)
