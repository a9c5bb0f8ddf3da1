# Nested soft-particles (issue 35, docs/nested.md): the self-consistency test's levels are studies
# (experiments/studies/nested-level-{2,1,0}.yaml, report kind nested), run in order so that each
# level's law files (DATA/nested/level-K/report/SETTING/laws.json) exist before the level above
# reads them: level-(k+1) laws -> level-k packings -> level-k laws. Each level is stamped and
# resumable as every study is; a changed law file reruns the stages that read it (its SHA-256 is in
# their stamps).
.PHONY: nested nested-report
nested: | $(TOOLS)  ## the nested soft-particles' self-consistency test: the three levels' studies in order (experiments/nested.yaml)
	@$(MAKE) --no-print-directory nested-level-2
	@$(MAKE) --no-print-directory nested-level-1
	@$(MAKE) --no-print-directory nested-level-0
nested-report: | $(TOOLS)  ## the three levels' reports from what has run
	@$(MAKE) --no-print-directory nested-level-2-report nested-level-1-report nested-level-0-report

# The three-decade medium (docs/nested.md, experiments/three-decades.yaml): the chain of four levels
# at Π = √10 (experiments/studies/three-decades-level-{3,2,1,0}.yaml, each nested on the level below's
# laws), then the medium of experiments/three-decades.yaml compressed with level 0's soft-particles
# (the coarse-grain stages of workflow/coarse.mk, soft model only) and, per seed, the resolved
# model's cost estimated (softpack-coarse estimate: DATA/three-decades/medium/estimate/seed-S.json).
THREE_DECADES_CONFIG := experiments/three-decades.yaml
THREE_DECADES_DIR := $(DATA)/three-decades/medium
# The resolved runs whose CPU time per sphere-step the estimate takes: the coarse-grain study's
# reference (experiments/coarse-grain.yaml), run by the recipe above before the estimates.
THREE_DECADES_MEASURED := $(wildcard $(DATA)/coarse-grain/reference/resolved/seed-*.h5)
.PHONY: three-decades three-decades-medium
three-decades: | $(TOOLS)  ## the three-decade medium: its four levels' laws in order, then its soft run and the resolved estimate
	@$(MAKE) --no-print-directory three-decades-level-3
	@$(MAKE) --no-print-directory three-decades-level-2
	@$(MAKE) --no-print-directory three-decades-level-1
	@$(MAKE) --no-print-directory three-decades-level-0
	@$(MAKE) --no-print-directory three-decades-medium
three-decades-medium: | $(TOOLS)  ## the three-decade medium's soft runs and resolved estimates (level 0's laws must exist)
	@$(MAKE) --no-print-directory coarse-grain-runs COARSE_CONFIG=$(THREE_DECADES_CONFIG) COARSE_DIR=$(THREE_DECADES_DIR) COARSE_MODELS=soft
	@$(MAKE) --no-print-directory coarse-grain-runs COARSE_MODELS=resolved  # the measured runs (the coarse-grain study's reference)
	@$(MAKE) --no-print-directory $(foreach s,$(THREE_DECADES_SEEDS),$(THREE_DECADES_DIR)/estimate/seed-$(s).json)
# (Asked of the tool only when the recipe above runs: other goals never read the settings.)
THREE_DECADES_SEEDS = $(shell test -x $(COARSE_TOOL) && $(COARSE_TOOL) seeds --config $(THREE_DECADES_CONFIG))
# An estimate is redone when its medium, its soft run or a measured run changes, or the settings
# (their `plan` is read by the estimate only: no stage's stamp holds it).
$(THREE_DECADES_DIR)/estimate/seed-%.json: $(THREE_DECADES_DIR)/media/seed-%.h5 $(THREE_DECADES_DIR)/soft/seed-%.h5 $(THREE_DECADES_MEASURED) \
    $(THREE_DECADES_CONFIG) | $(TOOLS)
	@mkdir -p $(@D)
	@$(RUN) $(COARSE_TOOL) estimate --config $(THREE_DECADES_CONFIG) --medium $< --soft $(word 2,$^) \
	  $(foreach f,$(THREE_DECADES_MEASURED),--measured $(f)) --out $@
