# The coarse-grain validation's stages (issue 17, docs/coarse-grain.md, paper/coarse-grain.md), run
# for each setting of a study of the coarse-grain settings (experiments/studies/coarse-grain.yaml,
# `make coarse-grain`: workflow/studies.mk gives COARSE_CONFIG, the setting's generated file, and
# COARSE_DIR, its folder): for each seed the two-decade medium (softpack-coarse medium: its packings
# are most of the time), then its oedometric compression resolved and with soft-particles
# (softpack-coarse run), one folder per stage,
#
#   COARSE_DIR/media/seed-S.h5   COARSE_DIR/resolved/seed-S.h5   COARSE_DIR/soft/seed-S.h5
#
# so that a setting shares a stage with an earlier one by its stamp (share_stages). A rerun redoes
# only what is missing or whose stage's stamp changed (softpack-coarse stamp: a hash of exactly what
# the stage reads, the law file's content for the soft model; coarse/settings.hpp), never because
# a program was relinked; every file is written atomically. The report is the study's (report kind
# `coarse`, make coarse-grain-report).
COARSE_CONFIG ?= experiments/coarse-grain.yaml
COARSE_DIR ?= $(DATA)/coarse-grain/reference
COARSE_TOOL := $(BUILD)/bin/softpack-coarse
# The stages' stamps, once the tool exists (the study's make of a setting runs after the build); a
# stamp file is rewritten only when it changes. (Asked only for the runs: a make of the profile's
# never reads the coarse settings.)
ifneq ($(wildcard $(COARSE_TOOL)),)
ifneq ($(filter coarse-grain-runs,$(MAKECMDGOALS)),)
COARSE_STAMPS := $(shell $(COARSE_TOOL) stamp --config $(COARSE_CONFIG) --release $(VERSION))
ifneq ($(.SHELLSTATUS),0)
$(error $(COARSE_CONFIG) is refused (the message above); fix it, or make build if softpack-coarse is out of date)
endif
endif
endif
coarse_stamp = $(COARSE_DIR)/stamps/$(1).hash
# A make that did not ask for the stamps (another goal whose prerequisites are runs, as the
# three-decade medium's estimates, whose measured runs the line before made) has no rule for the
# stamp files: an empty stamp would differ from every file's and remake every run.
ifneq ($(COARSE_STAMPS),)
$(foreach stage,medium resolved soft,$(eval $(call stamp_rule,$(call coarse_stamp,$(stage)),$(patsubst \
  $(stage)=%,%,$(filter $(stage)=%,$(COARSE_STAMPS))))))
endif

# The seeds (asked of the tool: make reads no YAML), once the tools are built.
COARSE_SEEDS ?= $(shell test -x $(COARSE_TOOL) && $(COARSE_TOOL) seeds --config $(COARSE_CONFIG))
# The models run (the three-decade medium runs soft only: its resolved model is estimated).
COARSE_MODELS ?= resolved soft
.PHONY: coarse-grain-runs
coarse-grain-runs: $(foreach s,$(COARSE_SEEDS),$(foreach m,$(COARSE_MODELS),$(COARSE_DIR)/$(m)/seed-$(s).h5))

$(COARSE_DIR)/media/seed-%.h5: $(call coarse_stamp,medium) | $(TOOLS)
	@mkdir -p $(@D)
	@$(RUN) $(COARSE_TOOL) medium --config $(COARSE_CONFIG) --seed $* --out $@ 2> $(@D)/seed-$*.log \
	  || { echo "coarse-grain: medium $* FAILED (log: $(@D)/seed-$*.log)"; tail -3 $(@D)/seed-$*.log; exit 1; }
	@echo "coarse-grain: $$(tr '\r' '\n' < $(@D)/seed-$*.log | tail -1)"

define coarse_run
$(COARSE_DIR)/$(1)/seed-$(2).h5: $(COARSE_DIR)/media/seed-$(2).h5 $(call coarse_stamp,$(1)) | $(TOOLS)
	@mkdir -p $$(@D)
	@$(RUN) $(COARSE_TOOL) run --config $(COARSE_CONFIG) --model $(1) --medium $$< --out $$@ 2> $$(@D)/seed-$(2).log \
	  || { echo "coarse-grain: $(1) $(2) FAILED (log: $$(@D)/seed-$(2).log)"; tr '\r' '\n' < $$(@D)/seed-$(2).log | tail -3; exit 1; }
	@echo "coarse-grain: $$$$(tr '\r' '\n' < $$(@D)/seed-$(2).log | tail -1)"
endef
$(foreach s,$(COARSE_SEEDS),$(foreach m,resolved soft,$(eval $(call coarse_run,$(m),$(s)))))

# Why the two models part (docs/coarse-grain.md): one resolved soft-particle of the medium's
# generator pressed by 1, 2 and 6 walls at once, for the packing of site 0 of each seed.
COARSE_PROBE_DN := 0.1 0.15 0.2 0.25 0.3 0.35
.PHONY: coarse-grain-multi-contact
coarse-grain-multi-contact: $(foreach s,$(COARSE_SEEDS),$(COARSE_DIR)/multi-contact/seed-$(s)000.dat)  ## one soft-particle pressed by 1, 2, 6 walls at once (COARSE_DIR/multi-contact/)
$(COARSE_DIR)/multi-contact/seed-%.dat: $(COARSE_CONFIG) $(COARSE_TOOL) | $(TOOLS)
	@mkdir -p $(@D)
	@$(RUN) $(COARSE_TOOL) multi-contact --config $(COARSE_CONFIG) --packing-seed $* --arrangements one opposite cube --delta-n $(COARSE_PROBE_DN) --out $@ \
	  2> $(@D)/seed-$*.log || { echo "coarse-grain: multi-contact $* FAILED (log: $(@D)/seed-$*.log)"; tail -2 $(@D)/seed-$*.log; exit 1; }
	@echo "coarse-grain: $@"

# The many-body probe (issue 33, paper/many-body.md): one resolved soft-particle pressed by 1 to 6
# walls in each arrangement of the plan (experiments/many-body.yaml, read and checked by the tool),
# for each of its radii and packing seeds: PROBE_DIR/RADIUS/seed-S.dat (a block per arrangement);
# its second part, the same pressed by each kind of body of its `bodies` (RADIUS/bodies-KIND-S.dat)
# and sheared under confinement (RADIUS/shear-S.dat).
PROBE_PLAN ?= experiments/many-body.yaml
PROBE_DIR ?= $(DATA)/many-body/probe
# (Asked of the tool once, and only for the goals that need them: other goals never read the plan.)
ifneq ($(filter many-body-probe many-body-report $(PROBE_DIR)/%,$(MAKECMDGOALS)),)
PROBE_RUNS ?= $(shell test -x $(COARSE_TOOL) && $(COARSE_TOOL) seeds --probe $(PROBE_PLAN))
PROBE_RUNS := $(PROBE_RUNS)
PROBE_STAMPS := $(shell test -x $(COARSE_TOOL) && $(COARSE_TOOL) seeds --probe $(PROBE_PLAN) --runs-stamp $(VERSION))
endif
.PHONY: many-body-probe
many-body-probe: $(foreach r,$(PROBE_RUNS),$(PROBE_DIR)/$(r).dat)  ## the many-body probe's runs (PROBE_DIR/RADIUS/GROUP-S.dat)
# The runs come in groups (seed: the walls' arrangements; bodies-KIND; shear), each redone when
# what decides it changes (softpack-coarse seeds --probe --runs-stamp: the plan's settings, seeds,
# radii and the group's own keys, and the release; not the selection rule, the validation or
# another group), never because the tool was relinked or a file is older than another. Each file
# holds its group's stamp on its first line ("# stamp HASH", written by the tool); a file whose
# stamp is not its group's now (or that has none) is made again. No stamp file and no time
# stamp decide it, so a fresh clone, whose files' times are those of the checkout, reruns nothing.
probe_group = $(patsubst %-$(lastword $(subst -, ,$(1))),%,$(1))
probe_options = $(if $(filter seed,$(1)),--part walls,$(if $(filter shear,$(1)),--part shear,--part bodies --kind $(patsubst bodies-%,%,$(1))))
# $(1): a group's file; $(2): the group's stamp -> the file, when it holds another stamp (or none)
probe_stale = $(if $(wildcard $(1)),$(call probe_differs,$(strip $(wordlist 2,3,$(file < $(1)))),stamp $(2),$(1)))
# $(1), $(2): two texts; $(3) when they differ
probe_differs = $(if $(and $(findstring $(1),$(2)),$(findstring $(2),$(1))),,$(3))
define probe_group_rule
$(eval probe_targets := $(foreach r,$(PROBE_RUNS),$(if $(filter $(1),$(call probe_group,$(notdir $(r)))),$(PROBE_DIR)/$(r).dat)))
$(if $(probe_targets),$(eval $(call probe_group_recipe,$(1))))
$(foreach t,$(probe_targets),$(if $(call probe_stale,$(t),$(2)),$(eval $(t): FORCE)))
endef
define probe_group_recipe
$(probe_targets): $(PROBE_DIR)/%.dat: | $(TOOLS)
	@mkdir -p $$(@D)
	@$$(RUN) $$(COARSE_TOOL) multi-contact --probe $$(PROBE_PLAN) --radius $$(patsubst %/,%,$$(dir $$*)) \
	  $(call probe_options,$(1)) --packing-seed $$(lastword $$(subst -, ,$$(notdir $$*))) --out $$@ 2> $$(basename $$@).log \
	  || { echo "many-body probe: $$* FAILED (log: $$(basename $$@).log)"; tail -2 $$(basename $$@).log; exit 1; }
	@echo "many-body probe: $$@ ($$$$(head -2 $$@ | grep -o '[0-9.]* CPU-s'))"
endef
$(foreach e,$(PROBE_STAMPS),$(eval $(call probe_group_rule,$(firstword $(subst =, ,$(e))),$(lastword $(subst =, ,$(e))))))

# Its analysis (coarse/probe_fit.hpp): the candidate laws fitted and judged by the plan's rule.
PROBE_REPORT ?= $(DATA)/many-body/report
.PHONY: many-body-report
many-body-report: $(foreach r,$(PROBE_RUNS),$(PROBE_DIR)/$(r).dat) | $(TOOLS)  ## the many-body probe's report (PROBE_REPORT/probe.md)
	@$(RUN) $(COARSE_TOOL) probe-report --probe $(PROBE_PLAN) --dir $(PROBE_DIR) --out $(PROBE_REPORT)
	@# each soft-soft part's figure, one per radius (NAME-RADIUS.png), from the variables it wrote
	@set -e; for v in $(PROBE_REPORT)/*-vars.gp; do [ -f "$$v" ] || continue; part=$${v%-vars.gp}; \
	  gnuplot -e "load '$$v'; out='$$part-%s.png'" figures/confined_soft.gp; echo "many-body probe: $$part-*.png"; done

# Where the media use the law (issue 33, item 5): the many-body setting's soft runs again, every
# soft-particle contact against the probe's range (coarse/soft_census.hpp; a few seconds).
.PHONY: many-body-census
many-body-census: | $(TOOLS)  ## the validation media's soft-particle contacts against the probe's range (DATA/many-body-validation/report/contacts.md)
	@$(RUN) $(COARSE_TOOL) soft-contacts --probe $(PROBE_PLAN) --config $(DATA)/many-body-validation/profiles/many-body.yaml \
	  --media $(DATA)/many-body-validation/many-body/media --out $(DATA)/many-body-validation/report

# The law's acceptance on media (issue 33, item 4): after make many-body-validation, the
# preregistered criterion judged on each of its settings (coarse/validation.hpp).
.PHONY: many-body-verdict
many-body-verdict: | $(TOOLS)  ## the many-body law's acceptance on the validation media (DATA/many-body-validation/report/validation.md)
	@$(RUN) $(COARSE_TOOL) validation --probe $(PROBE_PLAN) --dir $(DATA)/many-body-validation --out $(DATA)/many-body-validation/report
# A version's media seeds (softpack-coarse seeds --probe --media-of N), asked of the tool once and
# only for the goals that run on them; empty when the tool is not built yet or refuses the plan
# (those goals then stop, saying so).
V3_MEDIA_GOALS := many-body-in-place many-body-speed
V5_MEDIA_GOALS := many-body-v5-speed
V6_MEDIA_GOALS := many-body-v6-speed
media_seeds_of = $(if $(filter $(V$(1)_MEDIA_GOALS),$(MAKECMDGOALS)),$(shell test -x $(COARSE_TOOL) && $(COARSE_TOOL) seeds --probe $(PROBE_PLAN) --media-of $(1)))
V3_MEDIA_SEEDS := $(call media_seeds_of,3)
V5_MEDIA_SEEDS := $(call media_seeds_of,5)
V6_MEDIA_SEEDS := $(call media_seeds_of,6)
# $(1): the goal; $(2): the version
media_seeds_known = $(if $(V$(2)_MEDIA_SEEDS),,$(error $(1): $(COARSE_TOOL) gave no media seeds when make started (not built, or it refused the plan: see $(COARSE_TOOL) seeds --probe $(PROBE_PLAN) --media-of $(2)); run make build, then make $(1) again))
# The law in place (paper/many-body.md, "Next: measuring the law in place"): the third version's
# media compressed resolved again, each site's pushes against the law's (coarse/in_place.hpp).
IN_PLACE_DIR ?= $(DATA)/many-body-v3/in-place
.PHONY: many-body-in-place
many-body-in-place: $(foreach s,$(V3_MEDIA_SEEDS),$(IN_PLACE_DIR)/seed-$(s).dat) | $(TOOLS)  ## the law in place on the third version's media (DATA/many-body-v3/in-place/in-place.md)
	$(call media_seeds_known,many-body-in-place,3)
	@$(RUN) $(COARSE_TOOL) in-place-report --probe $(PROBE_PLAN) --dir $(IN_PLACE_DIR) --law-version 3
$(IN_PLACE_DIR)/seed-%.dat: $(DATA)/many-body-v3/reference/media/seed-%.h5 $(DATA)/many-body/report/laws.json | $(TOOLS)
	@mkdir -p $(@D)
	@$(RUN) $(COARSE_TOOL) in-place --probe $(PROBE_PLAN) --config $(DATA)/many-body-v3/profiles/many-body.yaml \
	  --media $(DATA)/many-body-v3/reference/media --seed $* --out $(@D) 2> $(@D)/seed-$*.log \
	  || { echo "in-place: seed $* FAILED (log: $(@D)/seed-$*.log)"; tr '\r' '\n' < $(@D)/seed-$*.log | tail -3; exit 1; }
	@echo "$$(tr '\r' '\n' < $(@D)/seed-$*.log | tail -1)"
# The soft medium's geometry against the resolved one's (paper/many-body.md, "Next: the soft
# medium's geometry against the resolved one's"): after make many-body-in-place and make
# many-body-v3-verdict (whose census writes every soft-particle contact, report/contact-rows.dat),
# the comparison of their rows (a second or so).
.PHONY: many-body-kinematics
many-body-kinematics: | $(TOOLS)  ## the soft medium's contacts against the resolved one's intrusions (DATA/many-body-v3/report/kinematics.md)
	@$(RUN) $(COARSE_TOOL) kinematics --probe $(PROBE_PLAN) --dir $(DATA)/many-body-v3 --law-version 3

# The speed-up side by side (issue 33's target; paper/many-body.md, "Next: the speed-up side by
# side"): each medium of a version resolved, soft pairwise and soft many-body (the version's study's
# profiles) in one process on one thread (coarse/speed.hpp), one seed after the other even under -j
# (each seed's file waits for the previous one's); run nothing else beside it. About 15 CPU-minutes
# a version. A seed is timed again when its medium, the law file or the settings change, not when
# the code does: to time new code, remove DATA/many-body-vN/speed/seed-*.dat first.
#   make many-body-speed      the third version's media (DATA/many-body-v3/speed/speed.md)
#   make many-body-v5-speed   the fifth's, with the stress term's pass (DATA/many-body-v5/speed/speed.md)
#   make many-body-v6-speed   the sixth's (DATA/many-body-v6/speed/speed.md)
.PHONY: many-body-speed many-body-v5-speed many-body-v6-speed
many-body-speed: $(foreach s,$(V3_MEDIA_SEEDS),$(DATA)/many-body-v3/speed/seed-$(s).dat) | $(TOOLS)  ## the speed-up over resolved side by side (DATA/many-body-v3/speed/speed.md)
	$(call media_seeds_known,many-body-speed,3)
	@$(RUN) $(COARSE_TOOL) speed --probe $(PROBE_PLAN) --dir $(DATA)/many-body-v3 --law-version 3 --report
many-body-v5-speed: $(foreach s,$(V5_MEDIA_SEEDS),$(DATA)/many-body-v5/speed/seed-$(s).dat) | $(TOOLS)  ## the same on the fifth version's media (DATA/many-body-v5/speed/speed.md)
	$(call media_seeds_known,many-body-v5-speed,5)
	@$(RUN) $(COARSE_TOOL) speed --probe $(PROBE_PLAN) --dir $(DATA)/many-body-v5 --law-version 5 --report
many-body-v6-speed: $(foreach s,$(V6_MEDIA_SEEDS),$(DATA)/many-body-v6/speed/seed-$(s).dat) | $(TOOLS)  ## the same on the sixth version's media (DATA/many-body-v6/speed/speed.md)
	$(call media_seeds_known,many-body-v6-speed,6)
	@$(RUN) $(COARSE_TOOL) speed --probe $(PROBE_PLAN) --dir $(DATA)/many-body-v6 --law-version 6 --report
# $(1): the version; $(2): its many-body law file; $(3): the seed; $(4): the seed timed before it
define speed_seed
$(DATA)/many-body-v$(1)/speed/seed-$(3).dat: $(DATA)/many-body-v$(1)/reference/media/seed-$(3).h5 $(2) \
  $(DATA)/many-body-v$(1)/profiles/reference.yaml $(DATA)/many-body-v$(1)/profiles/many-body.yaml | $(TOOLS) $(4)
	@mkdir -p $$(@D)
	@SOFTPACK_THREADS=1 $(RUN) $(COARSE_TOOL) speed --probe $(PROBE_PLAN) --dir $(DATA)/many-body-v$(1) --law-version $(1) --seed $(3) 2> $$(@D)/seed-$(3).log \
	  || { echo "speed: seed $(3) FAILED (log: $$(@D)/seed-$(3).log)"; tr '\r' '\n' < $$(@D)/seed-$(3).log | tail -3; exit 1; }
	@echo "$$$$(tr '\r' '\n' < $$(@D)/seed-$(3).log | tail -1)"
endef
prev :=
$(foreach s,$(V3_MEDIA_SEEDS),$(eval $(call speed_seed,3,$(DATA)/many-body/report/laws.json,$(s),$(if $(prev),$(DATA)/many-body-v3/speed/seed-$(prev).dat)))$(eval prev := $(s)))
prev :=
$(foreach s,$(V5_MEDIA_SEEDS),$(eval $(call speed_seed,5,$(DATA)/many-body/report/laws-v5.json,$(s),$(if $(prev),$(DATA)/many-body-v5/speed/seed-$(prev).dat)))$(eval prev := $(s)))
prev :=
$(foreach s,$(V6_MEDIA_SEEDS),$(eval $(call speed_seed,6,$(DATA)/many-body/report/laws-v6.json,$(s),$(if $(prev),$(DATA)/many-body-v6/speed/seed-$(prev).dat)))$(eval prev := $(s)))
# A version of the law judged on its own media (paper/many-body.md), after make many-body-vN: the
# criterion on each soft setting of its study (and the resolved one), then the census of its
# many-body setting. $(1): the version; $(2): its soft settings; $(3), if given: the setting the
# others are also read against (a bound against the version it changes: validation --against).
define version_verdict
	@$(RUN) $(COARSE_TOOL) validation --probe $(PROBE_PLAN) --dir $(DATA)/many-body-v$(1) --out $(DATA)/many-body-v$(1)/report --law-version $(1) \
	  --settings reference $(2)$(if $(3), --against $(3))
	@$(RUN) $(COARSE_TOOL) soft-contacts --probe $(PROBE_PLAN) --config $(DATA)/many-body-v$(1)/profiles/many-body.yaml \
	  --media $(DATA)/many-body-v$(1)/many-body/media --out $(DATA)/many-body-v$(1)/report --law-version $(1)
endef
.PHONY: many-body-v3-verdict many-body-v4-verdict many-body-v5-verdict many-body-v6-verdict
many-body-v3-verdict: | $(TOOLS)  ## the law's third version's acceptance on its media, and its census (DATA/many-body-v3/report/validation.md, contacts.md)
	$(call version_verdict,3,many-body)
many-body-v4-verdict: | $(TOOLS)  ## the fourth version's and the third's acceptance on the fourth's media, and its census (DATA/many-body-v4/report/)
	$(call version_verdict,4,many-body-v3 many-body)
many-body-v5-verdict: | $(TOOLS)  ## the fifth version's (the stress term) and the fourth's acceptance on the fifth's media, and its census (DATA/many-body-v5/report/)
	$(call version_verdict,5,many-body-v4 many-body)
many-body-v6-verdict: | $(TOOLS)  ## the sixth version's (the seventh part's β) and the fifth's acceptance on the sixth's media, the spin-locked bound against the sixth, and its census (DATA/many-body-v6/report/)
	$(call version_verdict,6,many-body-v5 many-body spin-locked,many-body)
