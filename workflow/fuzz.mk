# Fuzzing: libFuzzer targets for the configuration loader (YAML -> profile and scene) and for
# each HDF5 reader (packing, sweep point/results, average), built with clang, AddressSanitizer
# and UndefinedBehaviorSanitizer in their own build ($(FUZZ_BUILD), fuzz/CMakeLists.txt).
# `make fuzz` runs every target FUZZ_SECONDS and fails when one finds a crash, a sanitizer
# report, an exception other than InputError, a hang or a leak; the input is left in
# fuzz/crashes/<target>/. After the fix, move it to fuzz/regressions/<target>/: the ctest
# tests fuzz_regression.* (label fuzz-regression) replay it in the normal build.
# Needs the Debian packages clang and libclang-rt-14-dev (libFuzzer and the sanitizer runtimes).

FUZZ_SECONDS ?= 60
FUZZ_BUILD ?= build-fuzz
FUZZ_TARGETS ?= config packing sweep average
FUZZ_CC ?= clang
FUZZ_CXX ?= clang++

.PHONY: fuzz fuzz-build fuzz-corpus

$(FUZZ_BUILD)/CMakeCache.txt:
	cmake -S fuzz -B $(FUZZ_BUILD) -DCMAKE_C_COMPILER=$(FUZZ_CC) -DCMAKE_CXX_COMPILER=$(FUZZ_CXX)

fuzz-build: $(FUZZ_BUILD)/CMakeCache.txt  ## build the libFuzzer targets with clang (FUZZ_BUILD, default build-fuzz)
	@MAKEFLAGS= cmake --build $(FUZZ_BUILD) -j $(JOBS) > $(FUZZ_BUILD)/build.log 2>&1 \
	  || { echo "fuzz-build: FAILED; the end of $(FUZZ_BUILD)/build.log:"; tail -40 $(FUZZ_BUILD)/build.log; exit 1; }
	@echo "fuzz-build: $(FUZZ_BUILD) is up to date (log $(FUZZ_BUILD)/build.log)"

fuzz: fuzz-build  ## fuzz each reader FUZZ_SECONDS (60) s; fails on a crash, leaving it in fuzz/crashes/
	@status=0; for target in $(FUZZ_TARGETS); do \
	  fuzz/run_fuzz.sh $$target $(FUZZ_SECONDS) $(FUZZ_BUILD) || status=1; \
	done; exit $$status

fuzz-corpus: build  ## regenerate the seed corpora fuzz/corpus/ (small valid files; needs python3-h5py)
	fuzz/make_corpus.sh $(BUILD)
