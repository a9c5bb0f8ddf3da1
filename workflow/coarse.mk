# The coarse-grain validation (issue 17, docs/coarse-grain.md, paper/coarse-grain.md): for each
# seed of COARSE_CONFIG the two-decade medium (softpack-coarse medium: its packings are most of
# the time), then its oedometric compression resolved and with soft-particles (softpack-coarse
# run: one results file per model and seed), then the comparison, its table and its figure
# (softpack-coarse report; figures/coarse_grain.gp). A rerun redoes only what is missing or whose
# stage's stamp changed (softpack-coarse stamp: a hash of exactly what the stage reads, the law
# file's content for the soft model; coarse/settings.hpp), never because a program was relinked;
# every file is written atomically.
#
#   make coarse-grain                          # every seed, both models, then the report
#   make coarse-grain COARSE_SEEDS="301"       # only those seeds
#   make coarse-grain-report                   # the report from the runs there are
COARSE_CONFIG ?= experiments/coarse-grain.yaml
COARSE_DIR ?= data/coarse-grain
COARSE_TOOL := $(BUILD)/bin/softpack-coarse
# The stages' stamps, once the tool exists (a fresh clone asks after building it: coarse-grain
# runs coarse-grain-runs in a make of its own); a stamp file is rewritten only when it changes.
# (Asked only for the coarse goals: a make of the profile's never reads the coarse settings.)
ifneq ($(wildcard $(COARSE_TOOL)),)
ifneq ($(filter coarse-grain%,$(MAKECMDGOALS)),)
COARSE_STAMPS := $(shell $(COARSE_TOOL) stamp --config $(COARSE_CONFIG) --release $(VERSION))
ifneq ($(.SHELLSTATUS),0)
$(error $(COARSE_CONFIG) is refused (the message above); fix it, or make build if softpack-coarse is out of date)
endif
endif
endif
coarse_stamp = $(COARSE_DIR)/stamps/$(1).hash
$(foreach stage,medium resolved soft,$(eval $(call stamp_rule,$(call coarse_stamp,$(stage)),$(patsubst \
  $(stage)=%,%,$(filter $(stage)=%,$(COARSE_STAMPS))))))

.PHONY: coarse-grain coarse-grain-runs coarse-grain-report
coarse-grain: | $(TOOLS)  ## the coarse-grain validation: resolved against soft-particles (COARSE_DIR/report/)
	+@$(MAKE) --no-print-directory coarse-grain-runs
	@$(MAKE) --no-print-directory coarse-grain-report

# The seeds (asked of the tool: make reads no YAML), once the tools are built.
COARSE_SEEDS ?= $(shell test -x $(COARSE_TOOL) && $(COARSE_TOOL) seeds --config $(COARSE_CONFIG))
coarse-grain-runs: $(foreach s,$(COARSE_SEEDS),$(COARSE_DIR)/runs/resolved-$(s).h5 $(COARSE_DIR)/runs/soft-$(s).h5)

$(COARSE_DIR)/media/medium-%.h5: $(call coarse_stamp,medium) | $(TOOLS)
	@mkdir -p $(@D)
	@$(RUN) $(COARSE_TOOL) medium --config $(COARSE_CONFIG) --seed $* --out $@ 2> $(@D)/medium-$*.log \
	  || { echo "coarse-grain: medium $* FAILED (log: $(@D)/medium-$*.log)"; tail -3 $(@D)/medium-$*.log; exit 1; }
	@tr '\r' '\n' < $(@D)/medium-$*.log | tail -1

define coarse_run
$(COARSE_DIR)/runs/$(1)-$(2).h5: $(COARSE_DIR)/media/medium-$(2).h5 $(call coarse_stamp,$(1)) | $(TOOLS)
	@mkdir -p $$(@D)
	@$(RUN) $(COARSE_TOOL) run --config $(COARSE_CONFIG) --model $(1) --medium $$< --out $$@ 2> $$(@D)/$(1)-$(2).log \
	  || { echo "coarse-grain: $(1) $(2) FAILED (log: $$(@D)/$(1)-$(2).log)"; tr '\r' '\n' < $$(@D)/$(1)-$(2).log | tail -3; exit 1; }
	@tr '\r' '\n' < $$(@D)/$(1)-$(2).log | tail -1
endef
$(foreach s,$(COARSE_SEEDS),$(foreach m,resolved soft,$(eval $(call coarse_run,$(m),$(s)))))

coarse-grain-report: | $(TOOLS)  ## the coarse-grain validation's table and figure from the runs there are
	@$(COARSE_TOOL) report --config $(COARSE_CONFIG) --runs $(COARSE_DIR)/runs --out $(COARSE_DIR)/report
	@for ext in pdf png; do \
	  gnuplot -e "data='$(COARSE_DIR)/report/curves.dat'; out='$(COARSE_DIR)/report/coarse-grain.tmp.$$ext'" figures/coarse_grain.gp \
	  && mv $(COARSE_DIR)/report/coarse-grain.tmp.$$ext $(COARSE_DIR)/report/coarse-grain.$$ext \
	  || { echo "coarse-grain: FAILED to draw the figure"; exit 1; }; done
	@echo "coarse-grain: $(COARSE_DIR)/report/coarse-grain.md, coarse-grain.pdf, summary.json"

# Why the two models part (docs/coarse-grain.md): one resolved soft-particle of the medium's
# generator pressed by 1, 2 and 6 walls at once, for the packing of site 0 of each seed.
COARSE_PROBE_DN := 0.1 0.15 0.2 0.25 0.3 0.35
.PHONY: coarse-grain-multi-contact
coarse-grain-multi-contact: $(foreach s,$(COARSE_SEEDS),$(COARSE_DIR)/multi-contact/seed-$(s)000.dat)  ## one soft-particle pressed by 1, 2, 6 walls at once (COARSE_DIR/multi-contact/)
$(COARSE_DIR)/multi-contact/seed-%.dat: $(COARSE_CONFIG) $(COARSE_TOOL) | $(TOOLS)
	@mkdir -p $(@D)
	@$(RUN) $(COARSE_TOOL) multi-contact --config $(COARSE_CONFIG) --packing-seed $* --walls 1 2 6 --delta-n $(COARSE_PROBE_DN) --out $@ \
	  2> $(@D)/seed-$*.log || { echo "coarse-grain: multi-contact $* FAILED (log: $(@D)/seed-$*.log)"; tail -2 $(@D)/seed-$*.log; exit 1; }
	@echo "coarse-grain: $@"
