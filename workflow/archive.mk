# Archive and cite: `make archive` copies the profile's results (packings, sweep results,
# averages, fits) with their configuration stamps into data/archive/VERSION/PROFILE/, with a
# MANIFEST of SHA-256 sums, the provenance and a BibTeX entry (workflow/archive.sh). A fresh
# checkout then reuses every archived result whose stamp matches (workflow/stamps.mk).

ARCHIVE_MANIFEST := $(ARCHIVE)/MANIFEST.sha256
ARCHIVED_INPUTS := $(PACKINGS) $(foreach scene,$(SCENES),$(call NORMAL_RESULTS,$(scene)) $(call TANGENTIAL_RESULTS,$(scene))) \
  $(AVERAGES) $(FITS)

.PHONY: archive
archive: $(ARCHIVE_MANIFEST)  ## archive the results with MANIFEST, provenance and BibTeX (data/archive/VERSION/PROFILE/)
	@echo "archive: $(ARCHIVE) is up to date; cite it with $(ARCHIVE)/dataset.bib"

$(ARCHIVE_MANIFEST): $(ARCHIVED_INPUTS) $(if $(NORMAL_ONLY),,$(TABLE_DIR)/verdict.json) $(PROFILE_FILE) workflow/archive.sh
	@workflow/archive.sh $(DATA) $(PROFILE) $(VERSION) $(ARCHIVE_ROOT) $(PROFILE_FILE)

