# The soft-particle medium in LAMMPS against softpack's engine (issue 34, deliverable 3b;
# docs/lammps.md; the rule in experiments/lammps.yaml, written before the runs): make lammps-check.
# For each run SETTING/npR/seed-S of the plan (softpack-coarse lammps-check --runs), the medium
# seed-S.h5 of the study (its first setting's media: the settings share them) is exported (softpack-coarse export --lammps) into
# DATA/lammps/SETTING/npR/seed-S/, run there by softpack-lammps on R MPI ranks (curve.dat,
# log.lammps) and read back into DATA/lammps/SETTING/npR/seed-S.h5 (softpack-coarse lammps-curve);
# then the check against the study's engine runs, DATA/lammps/report/check.md.
LAMMPS_PLAN := experiments/lammps.yaml
LAMMPS_TOOL := $(BUILD)/bin/softpack-lammps
MPIRUN ?= mpirun --allow-run-as-root --oversubscribe -np
ifneq ($(filter lammps-check,$(MAKECMDGOALS)),)
LAMMPS_RUNS := $(shell test -x $(COARSE_TOOL) && $(COARSE_TOOL) lammps-check --plan $(LAMMPS_PLAN) --dir $(DATA)/lammps --runs)
LAMMPS_STUDY_MEDIA := $(shell test -x $(COARSE_TOOL) && $(COARSE_TOOL) lammps-check --plan $(LAMMPS_PLAN) --dir $(DATA)/lammps --study)
LAMMPS_STUDY := $(word 1,$(LAMMPS_STUDY_MEDIA))
LAMMPS_MEDIA := $(word 2,$(LAMMPS_STUDY_MEDIA))
LAMMPS_SETTINGS := $(sort $(foreach r,$(LAMMPS_RUNS),$(word 1,$(subst /, ,$(r)))))
# A setting's runs rerun when its soft model's stamp changes (softpack-coarse stamp: its settings, the
# law file's content, the release), not because a program was relinked.
$(foreach st,$(LAMMPS_SETTINGS),$(eval LAMMPS_STAMP_$(st) := $(patsubst soft=%,%,$(filter soft=%,$(shell \
  $(COARSE_TOOL) stamp --config $(LAMMPS_STUDY)/profiles/$(st).yaml --release $(VERSION))))))
$(foreach st,$(LAMMPS_SETTINGS),$(eval $(call stamp_rule,$(DATA)/lammps/$(st)/stamps/soft.hash,$(LAMMPS_STAMP_$(st)))))
endif

.PHONY: lammps-check
lammps-check: $(LAMMPS_RUNS:%=$(DATA)/lammps/%.h5) | $(TOOLS)  ## the coarse-grain compression in LAMMPS (1, 2 ranks) against the engine (DATA/lammps/report/check.md)
	@test -x $(LAMMPS_TOOL) || { echo "lammps-check: $(LAMMPS_TOOL) is not built (make setup installs liblammps-dev; then make build)"; exit 1; }
	@$(COARSE_TOOL) lammps-check --plan $(LAMMPS_PLAN) --dir $(DATA)/lammps

# run SETTING/npR/seed-S: $(1) setting, $(2) ranks, $(3) seed
define lammps_run
$(DATA)/lammps/$(1)/np$(2)/seed-$(3).h5: $(LAMMPS_MEDIA)/seed-$(3).h5 $(DATA)/lammps/$(1)/stamps/soft.hash | $(TOOLS)
	@test -x $(LAMMPS_TOOL) || { echo "lammps-check: $(LAMMPS_TOOL) is not built (make setup installs liblammps-dev; then make build)"; exit 1; }
	@rm -rf $$(basename $$@) && mkdir -p $$(basename $$@)
	@$(COARSE_TOOL) export --lammps --config $(LAMMPS_STUDY)/profiles/$(1).yaml --medium $$< --out $$(basename $$@) 2> $$(basename $$@).log
	@cd $$(basename $$@) && $(MPIRUN) $(2) $(abspath $(LAMMPS_TOOL)) -in in.compression -log log.lammps -screen none \
	  || { echo "lammps-check: $(1) np$(2) seed $(3) FAILED (log: $$(basename $$@)/log.lammps)"; tail -3 log.lammps; exit 1; }
	@$(COARSE_TOOL) lammps-curve --config $(LAMMPS_STUDY)/profiles/$(1).yaml --medium $$< --dir $$(basename $$@) --out $$@ 2>> $$(basename $$@).log
	@echo "lammps-check: $$$$(tail -1 $$(basename $$@).log)"
endef
$(foreach r,$(LAMMPS_RUNS),$(eval $(call lammps_run,$(word 1,$(subst /, ,$(r))),$(patsubst np%,%,$(word 2,$(subst /, ,$(r)))),$(patsubst seed-%,%,$(word 3,$(subst /, ,$(r)))))))
