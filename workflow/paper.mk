# The reproduction report: paper/paper.tex with the generated tables and figures, citing the
# archived dataset; built with latexmk into $(BUILD)/paper and copied to paper/paper.pdf
# (paper/paper-PROFILE.pdf for another profile).

PAPER_PDF := paper/$(if $(filter paper,$(PROFILE)),paper,paper-$(PROFILE)).pdf
PAPER_BUILD := $(BUILD)/paper/$(PROFILE)

.PHONY: paper
paper: $(PAPER_PDF)  ## the reproduction report, paper/paper.pdf (LaTeX: tables, figures, cited data)

$(PAPER_PDF): paper/paper.tex paper/references.bib $(TABLES) $(FIGURES_3_6) $(FIGURES_OUT)/fig1_apollonian.pdf $(FIGURES_OUT)/fig2_softparticle.pdf \
    figures/generated/studies/packing-density.png $(ARCHIVE_MANIFEST)
	@mkdir -p $(PAPER_BUILD)
	@echo "paper: $(PROFILE) -> $@ (log $(PAPER_BUILD)/paper.log)"
	@cd paper && BIBINPUTS=.:$(abspath $(ARCHIVE)): latexmk -pdf -interaction=nonstopmode -halt-on-error -silent \
	  -outdir=$(abspath $(PAPER_BUILD)) \
	  -usepretex='\def\softpackprofile{$(PROFILE)}\def\datadir{$(abspath $(DATA)/$(PROFILE))}\def\figdir{$(abspath $(FIGURES_OUT))}\def\softpackversion{$(VERSION)}' \
	  paper.tex > /dev/null \
	  || { echo "paper: FAILED for $(PROFILE); see $(PAPER_BUILD)/paper.log"; grep -A3 '^!' $(PAPER_BUILD)/paper.log | head -20; exit 1; }
	@cp $(PAPER_BUILD)/paper.pdf $@.tmp && mv $@.tmp $@
