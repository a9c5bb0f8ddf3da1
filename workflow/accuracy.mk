# The fidelity study (issue 13, docs/accuracy.md): `make accuracy` writes the profile of the
# reference and of every setting of experiments/accuracy-cost.yaml (softpack-accuracy profiles),
# runs each one's packings and sweeps with the profile DAG itself (a make of its own, PROFILE_FILE
# the generated profile, DATA the study's folder: each point is checkpointed and every stage is
# stamped, so a stopped study loses at most the points in progress and a changed setting reruns
# only what it touches), then compares them (softpack-accuracy report) and draws the figure.
# ACCURACY_SETTINGS=name... runs only those (the reference always: everything is compared to it).
# A setting whose run fails (the watchdog stops a time step too long to be stable) is reported
# as failed, with the first error of its logs (DATA/accuracy/<setting>/failed.txt); the study
# goes on. The reference must not fail.

# Another study (experiments/fast-profile.yaml) runs in a folder of its own: ACCURACY_DIR=data/fast-profile.
ACCURACY_STUDY ?= experiments/accuracy-cost.yaml
ACCURACY_DIR ?= $(DATA)/accuracy
ACCURACY_REPORT := $(ACCURACY_DIR)/report
ACCURACY_TOOL := $(BUILD)/bin/softpack-accuracy

.PHONY: accuracy accuracy-report calibrate calibrate-report radius radius-report
accuracy: | $(TOOLS)  ## the fidelity study: every knob's error against its CPU time (DATA/accuracy/report/)
	$(call study,$(ACCURACY_STUDY),$(ACCURACY_DIR),$(ACCURACY_SETTINGS))
	@$(MAKE) --no-print-directory accuracy-report

# study STUDY DIR SETTINGS: the recipe line that runs a study (run_study). Under make -n it says
# what it would run and runs nothing: a line that calls $(MAKE), or starts with +, runs even under
# -n, and the study's would write its profiles, logs and records.
study = $(if $(findstring n,$(MAKE_LETTERS)),@echo "study $(1): would write the profiles of its settings into $(2)/profiles \
  (softpack-accuracy profiles) and run make $(or $(STUDY_GOALS),tangential) for each setting in $(2)",+@$(call run_study,$(1),$(2),$(3)))

# run_study STUDY DIR SETTINGS: the profile of the reference and of every setting of STUDY
# (softpack-accuracy profiles), then each one's packings and sweeps by the profile DAG in DIR
# (SETTINGS: only those, and the reference; the goals STUDY_GOALS, by default the tangential
# sweeps and what they need). A setting whose run fails is recorded as failed.
define run_study
mkdir -p $(2)/profiles; \
settings=$$($(ACCURACY_TOOL) profiles --study $(1) --out-dir $(2)/profiles) || exit 2; \
chosen="$(3)"; n=0; total=$$(echo $$settings | wc -w); \
for s in $$settings; do n=$$((n + 1)); \
  if [ -n "$$chosen" ] && [ $$s != reference ] && ! echo " $$chosen " | grep -q " $$s "; then continue; fi; \
  echo "study $(1): setting $$n/$$total: $$s ($(2)/$$s)"; mkdir -p $(2)/$$s; \
  if $(MAKE) --no-print-directory PROFILE=$$s PROFILE_FILE=$(2)/profiles/$$s.yaml DATA=$(2) \
    FROM_SCRATCH=1 $(or $(STUDY_GOALS),tangential) > $(2)/$$s/make.log 2>&1; then rm -f $(2)/$$s/failed.txt; \
  else [ $$s != reference ] || { tail -20 $(2)/$$s/make.log; exit 1; }; \
    grep -h -m1 -e 'numerical error' -e 'error:' $(2)/$$s/*/*.log $(2)/$$s/make.log 2>/dev/null | head -1 \
      > $(2)/$$s/failed.txt; \
    echo "study $(1): setting $$s FAILED, reported as such: $$(cat $(2)/$$s/failed.txt)"; fi; \
  grep -E '^(pack|normal|tangential|sliding):' $(2)/$$s/make.log || true; \
done
endef

# The calibration study (issue 14, paper/calibration.md): every open parameter of the paper
# profile varied around the base on held-out seeds, each setting run as above; the report gives
# every setting's laws and packings with their seed-to-seed errors and their change against the
# base. CALIBRATE_SETTINGS=name... runs only those (and the base).
CALIBRATE_STUDY ?= experiments/calibrate.yaml
CALIBRATE_DIR ?= $(DATA)/calibrate
calibrate: | $(TOOLS)  ## the calibration study: each open parameter's effect on the laws (CALIBRATE_DIR/report/)
	$(call study,$(CALIBRATE_STUDY),$(CALIBRATE_DIR),$(CALIBRATE_SETTINGS))
	@$(MAKE) --no-print-directory calibrate-report

calibrate-report: | $(TOOLS)  ## the calibration table and figure from the settings run so far
	@mkdir -p $(CALIBRATE_DIR)/report
	@$(ACCURACY_TOOL) calibrate --study $(CALIBRATE_STUDY) --data $(CALIBRATE_DIR) --out-dir $(CALIBRATE_DIR)/report \
	  --title "Calibration ($(CALIBRATE_STUDY), release $(VERSION))" > /dev/null
	@for fig in onset sensitivity; do for ext in pdf png; do \
	  gnuplot -e "data='$(CALIBRATE_DIR)/report/$$fig.dat'; out='$(CALIBRATE_DIR)/report/$$fig.tmp.$$ext'" \
	  figures/calibration_$$fig.gp && mv $(CALIBRATE_DIR)/report/$$fig.tmp.$$ext $(CALIBRATE_DIR)/report/$$fig.$$ext \
	  || { echo "calibrate: FAILED to draw the figure $$fig"; exit 1; }; done; done
	@echo "calibrate: $(CALIBRATE_DIR)/report/table.md, $(CALIBRATE_DIR)/report/onset.pdf, $(CALIBRATE_DIR)/report/sensitivity.pdf"

# The comparison and the figure from what has been run so far (settings not run are listed as such).
accuracy-report: | $(TOOLS)  ## compare the settings run so far with the reference, draw the figure
	@mkdir -p $(ACCURACY_REPORT)
	@$(ACCURACY_TOOL) report --study $(ACCURACY_STUDY) --data $(ACCURACY_DIR) --out-dir $(ACCURACY_REPORT) \
	  --title "Accuracy against cost ($(ACCURACY_STUDY), release $(VERSION))"
	@for ext in pdf png; do gnuplot -e "data='$(ACCURACY_REPORT)/pareto.dat'; out='$(ACCURACY_REPORT)/accuracy-cost.tmp.$$ext'" \
	  figures/accuracy_cost.gp && mv $(ACCURACY_REPORT)/accuracy-cost.tmp.$$ext $(ACCURACY_REPORT)/accuracy-cost.$$ext \
	  || { echo "accuracy: FAILED to draw the figure"; exit 1; }; done
	@echo "accuracy: $(ACCURACY_REPORT)/table.md, $(ACCURACY_REPORT)/accuracy-cost.pdf"

# The fast profile's confirmation (docs/accuracy.md, "The fast profile"): the tables of the paper
# profile and of the fast one (each reusing or computing its results as `make tables` does;
# FROM_SCRATCH=1 recomputes both, one after the other, for their costs side by side), then every
# quantity of the fidelity study compared on the paper's seeds, and the CPU time of each.
FAST_CHECK_DIR ?= $(DATA)/fast-check
.PHONY: fast-check
fast-check: | $(TOOLS)  ## the fast profile against the paper profile on the paper's seeds (DATA/fast-check/)
	@$(MAKE) --no-print-directory PROFILE=paper tables
	@$(MAKE) --no-print-directory PROFILE=fast tables
	@$(ACCURACY_TOOL) check --data $(DATA) --reference experiments/paper.yaml --candidate experiments/fast.yaml \
	  --out-dir $(FAST_CHECK_DIR)

# The radius study (issue 16, paper/radius.md): the laws at shell radii Rs0/2 to 4 Rs0, the grains
# scaled with the shell (self-similar) or not (fixed), and soft-soft contacts of two radii, each
# setting run as above. RADIUS_SETTINGS=name... runs only those (and the reference).
RADIUS_STUDY ?= experiments/radius-study.yaml
RADIUS_DIR ?= $(DATA)/radius
radius: STUDY_GOALS := tangential sliding
radius: | $(TOOLS)  ## the radius study: the laws against the soft-particle's radius, its friction (RADIUS_DIR/report/)
	$(call study,$(RADIUS_STUDY),$(RADIUS_DIR),$(RADIUS_SETTINGS))
	@$(MAKE) --no-print-directory radius-report

# The report, the figures and the law file (RADIUS_DIR/report/laws.json) from what has run.
radius-report: | $(TOOLS)  ## the radius study's table, figures and law file from the settings run so far
	@mkdir -p $(RADIUS_DIR)/report
	@$(ACCURACY_TOOL) radius --study $(RADIUS_STUDY) --data $(RADIUS_DIR) --out-dir $(RADIUS_DIR)/report \
	  --title "Radius and friction ($(RADIUS_STUDY), release $(VERSION))" > /dev/null
	@for fig in scaling friction; do for ext in pdf png; do \
	  gnuplot -e "data='$(RADIUS_DIR)/report/$$fig.dat'; out='$(RADIUS_DIR)/report/$$fig.tmp.$$ext'" \
	  figures/radius_$$fig.gp && mv $(RADIUS_DIR)/report/$$fig.tmp.$$ext $(RADIUS_DIR)/report/$$fig.$$ext \
	  || { echo "radius: FAILED to draw the figure $$fig"; exit 1; }; done; done
	@echo "radius: $(RADIUS_DIR)/report/table.md, scaling.pdf, friction.pdf, laws.json"
