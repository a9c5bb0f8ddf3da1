# Analysis stage: per scene, the mean over the seeds (softpack-average), the fits of Eqs. 7 and 8
# (softpack-fit); then Tables 1-2 (softpack-table) and Figures 3-6 (gnuplot). Included by the
# top-level Makefile after sweeps.mk.

AVERAGE_DIR := $(DATA)/$(PROFILE)/averages
FIT_DIR := $(DATA)/$(PROFILE)/fits
TABLE_DIR := $(DATA)/$(PROFILE)/tables
PUBLISHED := experiments/published.yaml
# The preregistered rules (issue 29; paper/preregistration.md): the fits judge every candidate by
# them, the tables apply the selection, Table 2's unit rule and the tolerances (verdict.*).
CRITERIA := experiments/criteria.yaml

# average_outputs SCENE: the files softpack-average writes for SCENE.
# (A normal-only profile, NORMAL_ONLY in workflow/stamps.mk: no tangential results to average.)
average_outputs = $(AVERAGE_DIR)/$(1).h5 $(AVERAGE_DIR)/normal-$(1).dat $(if $(NORMAL_ONLY),,$(AVERAGE_DIR)/tangential-$(1).dat \
  $(AVERAGE_DIR)/kt-$(1).dat)
fit_outputs = $(FIT_DIR)/$(1).json $(FIT_DIR)/$(1).gp

define analysis_rules
$(call average_outputs,$(1)) &: $(AVERAGE_STAMP) $(call NORMAL_RESULTS,$(1)) $(if $(NORMAL_ONLY),,$(call TANGENTIAL_RESULTS,$(1))) | $(TOOLS)
	@mkdir -p $(AVERAGE_DIR) && $(call clear_stale,$(call average_outputs,$(1)))
	@$$(call from_archive,$(call average_outputs,$(1)),$(AVERAGE_STAMP)) || { \
	  echo "average: $(PROFILE) $(1) over seeds $(SEEDS) -> $(AVERAGE_DIR)/$(1).h5 (log $(AVERAGE_DIR)/$(1).log)"; \
	  $(RUN) $(BUILD)/bin/softpack-average --scene $(1) --profile $(PROFILE) --config $(PROFILE_FILE) --normal $(call NORMAL_RESULTS,$(1)) \
	    $(if $(NORMAL_ONLY),,--tangential $(call TANGENTIAL_RESULTS,$(1))) --out-dir $(AVERAGE_DIR) 2> $(AVERAGE_DIR)/$(1).log \
	  || { echo "average: FAILED for $(PROFILE) $(1); see $(AVERAGE_DIR)/$(1).log"; tail -5 $(AVERAGE_DIR)/$(1).log; exit 1; }; }
$(call fit_outputs,$(1)) &: $(AVERAGE_STAMP) $(AVERAGE_DIR)/$(1).h5 $(CRITERIA) | $(TOOLS)
	@mkdir -p $(FIT_DIR) && $(call clear_stale,$(call fit_outputs,$(1)))
	@$$(call from_archive,$(call fit_outputs,$(1)),$(AVERAGE_STAMP)) || { \
	  echo "fit: $(PROFILE) $(1) Eqs. 7-8 -> $(FIT_DIR)/$(1).json (log $(FIT_DIR)/$(1).log)"; \
	  $(RUN) $(BUILD)/bin/softpack-fit --average $(AVERAGE_DIR)/$(1).h5 --config $(PROFILE_FILE) --criteria $(CRITERIA) --out $(FIT_DIR)/$(1).json \
	    --gnuplot $(FIT_DIR)/$(1).gp 2> $(FIT_DIR)/$(1).log \
	  || { echo "fit: FAILED for $(PROFILE) $(1); see $(FIT_DIR)/$(1).log"; tail -5 $(FIT_DIR)/$(1).log; exit 1; }; }
endef
$(foreach scene,$(SCENES),$(eval $(call analysis_rules,$(scene))))

AVERAGES := $(foreach scene,$(SCENES),$(call average_outputs,$(scene)))
FITS := $(foreach scene,$(SCENES),$(call fit_outputs,$(scene)))
TABLES := $(TABLE_DIR)/table1.md $(TABLE_DIR)/table2.md $(TABLE_DIR)/table1.tex $(TABLE_DIR)/table2.tex \
  $(TABLE_DIR)/published.gp $(if $(NORMAL_ONLY),,$(TABLE_DIR)/kt_unit.md $(TABLE_DIR)/verdict.json $(TABLE_DIR)/verdict.md \
  $(TABLE_DIR)/verdict.tex)

.PHONY: averages fits tables figures
averages: $(AVERAGES)  ## mean and standard error over the seeds (DATA/PROFILE/averages/)
fits: $(FITS)  ## Eq. 7 and Eq. 8 fitted to the averages (DATA/PROFILE/fits/*.json)

tables: $(TABLES)  ## Tables 1 and 2: ours beside the paper's (DATA/PROFILE/tables/; printed)
	@cat $(TABLE_DIR)/table1.md; echo; cat $(TABLE_DIR)/table2.md

# kt_unit.md: the readings of Table 2's unit tested on kt/Fn (analysis/kt_unit.hpp), from the averages;
# verdict.*: the preregistered fit selection, Table 2's unit and the verdict (analysis/verdict.hpp).
$(TABLES) &: $(filter %.json,$(FITS)) $(filter %.h5,$(AVERAGES)) $(PUBLISHED) $(CRITERIA) | $(TOOLS)
	@mkdir -p $(TABLE_DIR) && $(call clear_stale,$(TABLES))
	@$(RUN) $(BUILD)/bin/softpack-table --fits $(filter %.json,$(FITS)) --config $(PROFILE_FILE) --published $(PUBLISHED) --out-dir $(TABLE_DIR) \
	  --gnuplot $(TABLE_DIR)/published.gp $(if $(NORMAL_ONLY),,--averages $(filter %.h5,$(AVERAGES)) --criteria $(CRITERIA) \
	  --Rs $$($(CONFIG_TOOL) $(PROFILE_FILE) gnuplot | sed 's/^Rs=\([^;]*\);.*/\1/')) > /dev/null 2> $(TABLE_DIR)/tables.log \
	  || { echo "tables: FAILED for $(PROFILE); see $(TABLE_DIR)/tables.log"; cat $(TABLE_DIR)/tables.log; exit 1; }

# Figures 3-6 as PDF (the report) and PNG (the screen). Every figure script reads the averages
# and the coefficients (ours, the paper's) as gnuplot variables.
# A profile of one scene (normal.scenes) draws that scene's: Figures 3 and 6 show what was measured.
FIGURE_NAMES := fig3_normal $(if $(NORMAL_ONLY),,$(if $(filter soft-solid,$(SCENES)),fig4_tangential_soft_solid) \
  $(if $(filter soft-soft,$(SCENES)),fig5_tangential_soft_soft) fig6_kt)
FIGURES_3_6 := $(foreach f,$(FIGURE_NAMES),$(FIGURES_OUT)/$(f).pdf $(FIGURES_OUT)/$(f).png)
figures: figure1 figure2 $(FIGURES_3_6)  ## Figures 1-6 (DATA/PROFILE/figures/, PDF and PNG)

# gnuplot_run SCRIPT OUT VARIABLES: draws via OUT.tmp.EXT, renamed into place.
gnuplot_run = mkdir -p $(FIGURES_OUT) && gnuplot -e "avg='$(AVERAGE_DIR)'; out='$(2).tmp$(suffix $(2))'; $(3)" \
  -e "$(foreach scene,$(SCENES),load '$(FIT_DIR)/$(scene).gp'; )load '$(TABLE_DIR)/published.gp'" $(1) \
  && mv $(2).tmp$(suffix $(2)) $(2) || { echo "figure: FAILED to draw $(2) with $(1)"; rm -f $(2).tmp$(suffix $(2)); exit 1; }
FIGURE_INPUTS := $(AVERAGES) $(FITS) $(TABLE_DIR)/published.gp

$(FIGURES_OUT)/fig3_normal.%: figures/fig3_normal.gp $(FIGURE_INPUTS)
	@$(call gnuplot_run,$<,$@,$$($(CONFIG_TOOL) $(PROFILE_FILE) gnuplot))
$(FIGURES_OUT)/fig4_tangential_soft_solid.%: figures/fig45_tangential.gp $(FIGURE_INPUTS)
	@$(call gnuplot_run,$<,$@,scene='soft-solid')
$(FIGURES_OUT)/fig5_tangential_soft_soft.%: figures/fig45_tangential.gp $(FIGURE_INPUTS)
	@$(call gnuplot_run,$<,$@,scene='soft-soft')
$(FIGURES_OUT)/fig6_kt.%: figures/fig6_kt.gp $(FIGURE_INPUTS)
	@$(call gnuplot_run,$<,$@,)

# Where the time went: what every output of the profile records (wall-clock and CPU time per stage,
# per sweep point and per phase of it), summed by softpack-timing (analysis/stage_timing.hpp).
# Files not made yet are listed as missing; nothing is run.
.PHONY: timing
timing: | $(TOOLS)  ## wall-clock and CPU time of the profile's last run, per stage and phase (also DATA/PROFILE/timing.json)
	@mkdir -p $(DATA)/$(PROFILE) && $(BUILD)/bin/softpack-timing --title "Time of the $(PROFILE) profile ($(DATA)/$(PROFILE))" \
	  --packings $(PACKINGS) --normal $(foreach scene,$(SCENES),$(call NORMAL_RESULTS,$(scene))) \
	  --tangential $(foreach scene,$(SCENES),$(call TANGENTIAL_RESULTS,$(scene))) \
	  --averages $(foreach scene,$(SCENES),$(AVERAGE_DIR)/$(scene).h5) --fits $(filter %.json,$(FITS)) \
	  --json $(DATA)/$(PROFILE)/timing.json

# One configuration per result, in make's up-to-date check too: a result whose recorded stamp is
# not its stage's stamp now (computed while the profile was edited, the edit reverted since) is
# out of date whatever its time (softpack-config PROFILE stale; results from before stamps record
# none and are judged by the stamp files alone). One call, when make starts, reads them all.
STAMPED_RESULTS := $(PACKINGS) $(foreach scene,$(SCENES),$(call NORMAL_RESULTS,$(scene)) $(call TANGENTIAL_RESULTS,$(scene)) \
  $(if $(HAS_SLIDING),$(call SLIDING_RESULTS,$(scene)))) $(filter %.h5 %.json,$(AVERAGES) $(FITS))
STALE_RESULTS := $(if $(wildcard $(STAMPED_RESULTS)),$(call config,stale $(wildcard $(STAMPED_RESULTS))))
$(foreach f,$(STALE_RESULTS),$(eval $(f): FORCE))
