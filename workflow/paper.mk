# The reproduction report: paper/paper.tex with the generated tables and figures, citing the
# archived dataset; built with latexmk into DATA/PROFILE/paper/ (under DATA and its lock, as
# everything a run writes), DATA/PROFILE/paper/paper.pdf.

PAPER_BUILD := $(DATA)/$(PROFILE)/paper
PAPER_PDF := $(PAPER_BUILD)/paper.pdf

.PHONY: paper
paper: $(PAPER_PDF)  ## the reproduction report, DATA/PROFILE/paper/paper.pdf (LaTeX: tables, figures, cited data)

$(PAPER_PDF): paper/paper.tex paper/references.bib $(TABLES) $(FIGURES_3_6) $(FIGURES_OUT)/fig1_apollonian.pdf $(FIGURES_OUT)/fig2_softparticle.pdf \
    $(STUDY_FIGURES)/packing-density.png $(ARCHIVE_MANIFEST)
	@mkdir -p $(PAPER_BUILD)
	@echo "paper: $(PROFILE) -> $@ (log $(PAPER_BUILD)/latex/paper.log)"
	@cd paper && BIBINPUTS=.:$(abspath $(ARCHIVE)): latexmk -pdf -interaction=nonstopmode -halt-on-error -silent \
	  -outdir=$(abspath $(PAPER_BUILD)/latex) \
	  -usepretex='\def\softpackprofile{$(PROFILE)}\def\datadir{$(abspath $(DATA)/$(PROFILE))}\def\figdir{$(abspath $(FIGURES_OUT))}\def\studyfigdir{$(abspath $(STUDY_FIGURES))}\def\softpackversion{$(VERSION)}' \
	  paper.tex > /dev/null \
	  || { echo "paper: FAILED for $(PROFILE); see $(PAPER_BUILD)/latex/paper.log"; grep -A3 '^!' $(PAPER_BUILD)/latex/paper.log | head -20; exit 1; }
	@cp $(PAPER_BUILD)/latex/paper.pdf $@.tmp && mv $@.tmp $@
