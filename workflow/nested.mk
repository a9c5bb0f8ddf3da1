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
