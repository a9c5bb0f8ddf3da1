# Measurement stage: the normal and tangential sweeps of every scene and seed of the profile.
# The tangential stage shears the normal stage's checkpoints; when the normal results were taken
# from the archive (which keeps no checkpoints), softpack-tangential computes those states itself.
# Soft-soft pairs the packing of seed k with that of the next seed of the profile (cyclic), so
# that the two soft-particles are independent and no extra packing is made.

SWEEP_DIR := $(DATA)/$(PROFILE)
CHECKPOINTS := $(SWEEP_DIR)/checkpoints

# next_seed SEED: the seed after SEED in the list, the first after the last.
seed_index = $(words $(shell for s in $(SEEDS); do echo $$s; [ $$s = $(1) ] && break; done))
next_seed = $(or $(word 2,$(wordlist $(call seed_index,$(1)),999,$(SEEDS))),$(firstword $(SEEDS)))

.PHONY: normal tangential sliding sweeps

# sweep_args SCENE SEED: the arguments both stages share.
sweep_args = --config $(PROFILE_FILE) --scene $(1) --seed $(2) --packing $(PACKING_DIR)/seed-$(2).h5 \
  $(if $(filter soft-soft,$(1)),--second-packing $(PACKING_DIR)/seed-$(call next_seed,$(2)).h5)

define sweep_rules
$(SWEEP_DIR)/normal/$(1)-seed-$(2).h5: $(NORMAL_STAMP) $(PACKING_DIR)/seed-$(2).h5 \
    $(if $(filter soft-soft,$(1)),$(PACKING_DIR)/seed-$(call next_seed,$(2)).h5) | $(TOOLS)
	@mkdir -p $$(@D) && $$(call clear_stale,$$@,$(CHECKPOINTS)/normal/$(1)/seed-$(2))
	@$$(call from_archive,$$@,$(NORMAL_STAMP)) || { \
	  echo "normal: $(PROFILE) $(1) seed $(2) -> $$@ (log $$(@:.h5=.log))"; \
	  $(RUN) $(BUILD)/bin/softpack-normal $(call sweep_args,$(1),$(2)) $$(call planned,$(NORMAL_STAMP)) \
	    --checkpoints $(CHECKPOINTS)/normal/$(1)/seed-$(2) --out $$@ 2> $$(@:.h5=.log) \
	  || { echo "normal: FAILED for $(PROFILE) $(1) seed $(2); see $$(@:.h5=.log)"; tail -5 $$(@:.h5=.log); exit 1; }; }
$(SWEEP_DIR)/tangential/$(1)-seed-$(2).h5: $(TANGENTIAL_STAMP) $(SWEEP_DIR)/normal/$(1)-seed-$(2).h5 | $(TOOLS)
	@mkdir -p $$(@D) && $$(call clear_stale,$$@,$(CHECKPOINTS)/normal/$(1)/seed-$(2) $(CHECKPOINTS)/tangential/$(1)/seed-$(2))
	@$$(call from_archive,$$@,$(TANGENTIAL_STAMP)) || { \
	  echo "tangential: $(PROFILE) $(1) seed $(2) -> $$@ (log $$(@:.h5=.log))"; \
	  $(RUN) $(BUILD)/bin/softpack-tangential $(call sweep_args,$(1),$(2)) $$(call planned,$(TANGENTIAL_STAMP)) \
	    --checkpoints $(CHECKPOINTS)/tangential/$(1)/seed-$(2) --normal-checkpoints $(CHECKPOINTS)/normal/$(1)/seed-$(2) \
	    --out $$@ 2> $$(@:.h5=.log) \
	  || { echo "tangential: FAILED for $(PROFILE) $(1) seed $(2); see $$(@:.h5=.log)"; tail -5 $$(@:.h5=.log); exit 1; }; }
endef
$(foreach scene,$(SCENES),$(foreach seed,$(SEEDS),$(eval $(call sweep_rules,$(scene),$(seed)))))

# The sliding measurement (issue 16, a profile with a `sliding` section): from the normal states,
# as the tangential stage.
define sliding_rules
$(SWEEP_DIR)/sliding/$(1)-seed-$(2).h5: $(SLIDING_STAMP) $(SWEEP_DIR)/normal/$(1)-seed-$(2).h5 | $(TOOLS)
	@mkdir -p $$(@D) && $$(call clear_stale,$$@,$(CHECKPOINTS)/normal/$(1)/seed-$(2) $(CHECKPOINTS)/sliding/$(1)/seed-$(2))
	@echo "sliding: $(PROFILE) $(1) seed $(2) -> $$@ (log $$(@:.h5=.log))"; \
	  $(RUN) $(BUILD)/bin/softpack-sliding $(call sweep_args,$(1),$(2)) $$(call planned,$(SLIDING_STAMP)) \
	    --checkpoints $(CHECKPOINTS)/sliding/$(1)/seed-$(2) --normal-checkpoints $(CHECKPOINTS)/normal/$(1)/seed-$(2) \
	    --out $$@ 2> $$(@:.h5=.log) \
	  || { echo "sliding: FAILED for $(PROFILE) $(1) seed $(2); see $$(@:.h5=.log)"; tail -5 $$(@:.h5=.log); exit 1; }
endef
$(if $(HAS_SLIDING),$(foreach scene,$(SCENES),$(foreach seed,$(SEEDS),$(eval $(call sliding_rules,$(scene),$(seed))))))

NORMAL_RESULTS = $(foreach seed,$(SEEDS),$(SWEEP_DIR)/normal/$(1)-seed-$(seed).h5)
TANGENTIAL_RESULTS = $(foreach seed,$(SEEDS),$(SWEEP_DIR)/tangential/$(1)-seed-$(seed).h5)
normal: $(foreach scene,$(SCENES),$(call NORMAL_RESULTS,$(scene)))  ## normal sweeps of every scene and seed (make -j2: two at once)
tangential: $(foreach scene,$(SCENES),$(call TANGENTIAL_RESULTS,$(scene)))  ## tangential sweeps (after the normal ones)
SLIDING_RESULTS = $(foreach seed,$(SEEDS),$(SWEEP_DIR)/sliding/$(1)-seed-$(seed).h5)
sliding: $(foreach scene,$(SCENES),$(call SLIDING_RESULTS,$(scene)))  ## the sliding measurement (a profile with a sliding section)
sweeps: normal tangential  ## both sweeps
