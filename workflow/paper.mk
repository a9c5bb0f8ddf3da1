# The reproduction report: paper/paper.tex with the generated tables and figures, citing the
# archived dataset; built with latexmk into DATA/PROFILE/paper/ (under DATA and its lock, as
# everything a run writes), DATA/PROFILE/paper/paper.pdf.

PAPER_BUILD := $(DATA)/$(PROFILE)/paper
PAPER_PDF := $(PAPER_BUILD)/paper.pdf
# Every number of a result reaches the text as a macro (issue 29): paper/variables.py writes them
# from the result files into DATA/PROFILE/paper/generated/variables.tex. The report also states
# what the preregistered rules chose on the held-out seeds: the select profile's verdict (its
# tables, reused from its archive when the stamps match, as the profile's own). The studies'
# reports are the committed ones (data/studies/*/report, data/radius/report, data/coarse-grain/report/reference,
# data/nested/level-*/report, data/three-decades/level-*/report, data/nested-medium/report,
# data/many-body-v6/report)
PAPER_VARIABLES := $(PAPER_BUILD)/generated/variables.tex
SELECT_VERDICT := $(DATA)/select/tables/verdict.json
STUDY_REPORTS := data/studies/density-rule/report/density-rule.json data/radius/report/radius.json \
  data/coarse-grain/report/reference/summary.json data/coarse-grain/report/reference/curves.dat \
  data/studies/packing-density/report/packing-density.png data/nested/level-1/report/nested.json \
  data/nested/level-0/report/nested.json data/three-decades/level-3/report/nested.json \
  data/three-decades/level-2/report/nested.json data/three-decades/level-1/report/nested.json \
  data/three-decades/level-0/report/nested.json data/nested-medium/report/coarse.json \
  data/nested-medium/report/reference/summary.json data/nested-medium/report/reference/curves.dat \
  data/nested-medium/report/pairwise/summary.json data/nested-medium/report/pairwise/curves.dat \
  data/many-body-v6/report/coarse.json data/many-body-v6/report/many-body/summary.json \
  data/many-body-v6/report/many-body/curves.dat

# (In the select profile itself the file is its own table's, made by the tables rule.)
ifneq ($(PROFILE),select)
.PHONY: select-tables
select-tables: | $(TOOLS)
	@$(MAKE) --no-print-directory PROFILE=select PROFILE_FILE=experiments/select.yaml tables > /dev/null
$(SELECT_VERDICT): select-tables ;
endif

# The studies' committed reports are read, never made here: as prerequisites (even order-only
# ones) make would rerun a study whenever its programs are newer than its report, as they are in
# every fresh clone (make density-rule, make radius-report, ... rebuild them on request). So the
# macros are recomputed on every build (milliseconds) and the file rewritten only when a number
# changed; the PDF follows the file's time.
.PHONY: paper-variables
paper-variables: $(TABLES) $(SELECT_VERDICT)
	@for r in $(STUDY_REPORTS); do [ -f $$r ] || { echo "paper: $$r is missing (a committed study report; git checkout it, or rerun its study)" >&2; exit 2; }; done
	@mkdir -p $(dir $(PAPER_VARIABLES)) && python3 paper/variables.py --out $(PAPER_VARIABLES) --profile $(DATA)/$(PROFILE) --select $(DATA)/select \
	  --density data/studies/density-rule/report/density-rule.json --radius data/radius/report/radius.json \
	  --coarse data/coarse-grain/report/reference/summary.json --nested data/nested --chain data/three-decades \
	  --nested-medium data/nested-medium/report --one-level data/many-body-v6/report/coarse.json
$(PAPER_VARIABLES): paper-variables ;

.PHONY: paper
paper: $(PAPER_PDF)  ## the reproduction report, DATA/PROFILE/paper/paper.pdf (LaTeX: tables, figures, cited data)

$(PAPER_PDF): paper/paper.tex paper/references.bib $(PAPER_VARIABLES) $(TABLES) $(FIGURES_3_6) $(FIGURES_OUT)/fig1_apollonian.pdf $(FIGURES_OUT)/fig2_softparticle.pdf \
    $(ARCHIVE_MANIFEST)
	@mkdir -p $(PAPER_BUILD)
	@echo "paper: $(PROFILE) -> $@ (log $(PAPER_BUILD)/latex/paper.log)"
	@cd paper && BIBINPUTS=.:$(abspath $(ARCHIVE)): latexmk -pdf -interaction=nonstopmode -halt-on-error -silent \
	  -outdir=$(abspath $(PAPER_BUILD)/latex) \
	  -usepretex='\def\softpackprofile{$(PROFILE)}\def\datadir{$(abspath $(DATA)/$(PROFILE))}\def\figdir{$(abspath $(FIGURES_OUT))}\def\studyfigdir{$(abspath data/studies/packing-density/report)}\def\softpackversion{$(VERSION)}\def\gendir{$(abspath $(PAPER_BUILD)/generated)}' \
	  paper.tex > /dev/null \
	  || { echo "paper: FAILED for $(PROFILE); see $(PAPER_BUILD)/latex/paper.log"; grep -A3 '^!' $(PAPER_BUILD)/latex/paper.log | head -20; exit 1; }
	@cp $(PAPER_BUILD)/latex/paper.pdf $@.tmp && mv $@.tmp $@
