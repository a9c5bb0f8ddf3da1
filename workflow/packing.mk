# Packing stage: packings of the profile's seeds (with pictures), Figures 1 and 2. Included by the
# top-level Makefile. (The packing studies are studies of settings, experiments/studies/:
# make packing-density, make density-rule.)

PACKING_DIR := $(DATA)/$(PROFILE)/packings
PACKINGS := $(foreach s,$(SEEDS),$(PACKING_DIR)/seed-$(s).h5)
# Everything a run writes lives under its DATA (and its lock): the figures too.
FIGURES_OUT := $(DATA)/$(PROFILE)/figures
# Generated packings (softpack-pack), or imported ones when the profile's packing section has
# `import` (softpack-import; docs/import.md): same options, same packing file.
IMPORTED := $(filter imported,$(call config,packings))
PACK := $(BUILD)/bin/softpack-$(if $(IMPORTED),import,pack)
# An import's summary (spheres, shell and the outermost grain's gap, overlap, density) goes to
# its log and is shown: it says what was assumed. softpack-pack's progress is not.
PACK_QUIET := $(if $(IMPORTED),,--quiet)

.PHONY: packings figure1 figure2
# The executables are brought up to date before any stage runs (an order-only prerequisite);
# not under make -n or make -q, which must only say what would run.
TOOLS := $(if $(findstring n,$(MAKE_LETTERS))$(findstring q,$(MAKE_LETTERS)),,build-tools)

packings: $(PACKINGS)  ## packings of the profile's seeds, generated or imported (DATA/PROFILE/packings/, with .vtp and .xyz)

$(PACKING_DIR)/seed-%.h5: $(PACK_STAMP) | $(TOOLS)
	@mkdir -p $(@D) && $(call clear_stale,$@ $(@:.h5=.vtp) $(@:.h5=.xyz))
	@$(call from_archive,$@ $(@:.h5=.vtp) $(@:.h5=.xyz),$(PACK_STAMP)) || { \
	  echo "pack: $(PROFILE) seed $* -> $@ (log $(@:.h5=.log))"; \
	  $(RUN) $(PACK) --config $(PROFILE_FILE) $(call planned,$(PACK_STAMP)) --seed $* --out $@ --vtp $(@:.h5=.vtp) \
	    --xyz $(@:.h5=.xyz) $(PACK_QUIET) 2> $(@:.h5=.log) \
	  || { echo "pack: FAILED for $(PROFILE) seed $*; see $(@:.h5=.log)"; cat $(@:.h5=.log); exit 1; }; \
	  $(if $(IMPORTED),sed 's/^/pack: /' $(@:.h5=.log);) }

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
