# Packing stage: packings of the profile's seeds (with pictures), Figures 1 and 2, and the
# packing density study. Included by the top-level Makefile.

PACKING_DIR := $(DATA)/$(PROFILE)/packings
PACKINGS := $(foreach s,$(SEEDS),$(PACKING_DIR)/seed-$(s).h5)
# Everything a run writes lives under its DATA (and its lock): the figures too.
FIGURES_OUT := $(DATA)/$(PROFILE)/figures
STUDY_FIGURES := $(DATA)/studies/figures
# Generated packings (softpack-pack), or imported ones when the profile's packing section has
# `import` (softpack-import; docs/import.md): same options, same packing file.
PACK := $(BUILD)/bin/softpack-$(if $(filter imported,$(call config,packings)),import,pack)

.PHONY: packings study-packing density-rule figure1 figure2
# The executables are brought up to date before any stage runs (an order-only prerequisite);
# not under make -n or make -q, which must only say what would run.
TOOLS := $(if $(findstring n,$(MAKE_LETTERS))$(findstring q,$(MAKE_LETTERS)),,build-tools)

packings: $(PACKINGS)  ## packings of the profile's seeds, generated or imported (DATA/PROFILE/packings/, with .vtp and .xyz)

$(PACKING_DIR)/seed-%.h5: $(PACK_STAMP) | $(TOOLS)
	@mkdir -p $(@D) && $(call clear_stale,$@ $(@:.h5=.vtp) $(@:.h5=.xyz))
	@$(call from_archive,$@ $(@:.h5=.vtp) $(@:.h5=.xyz),$(PACK_STAMP)) || { \
	  echo "pack: $(PROFILE) seed $* -> $@ (log $(@:.h5=.log))"; \
	  $(RUN) $(PACK) --config $(PROFILE_FILE) $(call planned,$(PACK_STAMP)) --seed $* --out $@ --vtp $(@:.h5=.vtp) \
	    --xyz $(@:.h5=.xyz) --quiet 2> $(@:.h5=.log) \
	  || { echo "pack: FAILED for $(PROFILE) seed $*; see $(@:.h5=.log)"; cat $(@:.h5=.log); exit 1; }; }

figure1: $(FIGURES_OUT)/fig1_apollonian.png $(FIGURES_OUT)/fig1_apollonian.pdf  ## Figure 1: a 2D Apollonian packing
figure2: $(FIGURES_OUT)/fig2_softparticle.png $(FIGURES_OUT)/fig2_softparticle.pdf  ## Figure 2: a soft-particle (cross-section)

$(FIGURES_OUT)/fig1_apollonian.dat: | $(TOOLS)
	@mkdir -p $(@D)
	@$(RUN) $(BUILD)/bin/softpack-apollonian --min-radius 1e-3 --out $@
$(FIGURES_OUT)/fig1_apollonian.%: $(FIGURES_OUT)/fig1_apollonian.dat figures/fig1_apollonian.gp
	@gnuplot -e "data='$<'; out='$@.tmp.$*'" figures/fig1_apollonian.gp && mv $@.tmp.$* $@

$(FIGURES_OUT)/fig2_section.dat: $(PACKING_DIR)/seed-$(firstword $(SEEDS)).h5 | $(TOOLS)
	@mkdir -p $(@D)
	@$(RUN) $(BUILD)/bin/softpack-section --packing $< --out $@ 2> /dev/null
$(FIGURES_OUT)/fig2_softparticle.%: $(FIGURES_OUT)/fig2_section.dat figures/fig2_softparticle.gp
	@gnuplot -e "data='$<'; $$($(CONFIG_TOOL) $(PROFILE_FILE) gnuplot); out='$@.tmp.$*'" \
	  figures/fig2_softparticle.gp && mv $@.tmp.$* $@

STUDY_DIR := $(DATA)/studies/packing-density
study-packing: $(STUDY_DIR)/packing-density.md $(STUDY_FIGURES)/packing-density.png  ## the packing density study (beta, I, r_max/Rs)
	@cat $(STUDY_DIR)/packing-density.md
# The study varies its base profile's packing section (experiments/fast.yaml: the packing of
# releases <= 0.4.0): it depends on that section only.
STUDY_STAMP := $(call stamp,packing-density,packing,experiments/fast.yaml,$(DATA)/studies/stamps)
$(STUDY_DIR)/packing-density.md $(STUDY_DIR)/packing-density.dat &: experiments/packing-density.yaml $(STUDY_STAMP) | $(TOOLS)
	$(RUN) $(BUILD)/bin/softpack-packing-study --config experiments/packing-density.yaml --out $(STUDY_DIR)
$(STUDY_FIGURES)/packing-density.png: $(STUDY_DIR)/packing-density.dat figures/packing_density.gp
	@mkdir -p $(@D)
	@gnuplot -e "data='$<'; out='$@.tmp.png'" figures/packing_density.gp && mv $@.tmp.png $@

# The preregistered density rule (issue 29: experiments/criteria.yaml, paper/preregistration.md):
# the criteria's (beta, trials) grid on its select seeds; the chosen setting is the paper
# profile's. It reads the criteria and the base's packing section (the grid replaces beta and trials).
DENSITY_RULE_DIR := $(DATA)/studies/density-rule
density-rule: $(DENSITY_RULE_DIR)/density-rule.md  ## the preregistered packing-density rule on the held-out seeds (DATA/studies/density-rule/)
	@cat $<
$(DENSITY_RULE_DIR)/density-rule.md $(DENSITY_RULE_DIR)/density-rule.json &: experiments/density-rule.yaml experiments/criteria.yaml | $(TOOLS)
	@mkdir -p $(@D) && echo "density-rule: -> $(@D) (log $(@D)/density-rule.log)"
	@$(RUN) $(BUILD)/bin/softpack-packing-study --config experiments/density-rule.yaml --out $(@D) 2> $(@D)/density-rule.log \
	  || { echo "density-rule: FAILED; see $(@D)/density-rule.log"; tail -5 $(@D)/density-rule.log; exit 1; }
