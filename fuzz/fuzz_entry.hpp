// The entry points shared by the libFuzzer targets (fuzz/fuzz_target.cpp, built by
// fuzz/CMakeLists.txt with clang) and by the regression replay of the normal build
// (tests/fuzz/replay_fuzz_inputs.cpp, ctest label fuzz-regression).
//
// Each entry point feeds one input to the engine's readers the way the executables do, and
// goes on with what the executables do with the data (averaging, fitting, writing it as
// provenance). Bad input must only ever end in softpack::InputError; any other exception, a
// crash, a sanitizer report or a hang is a bug of the reader.
//
// Targets:
//   config   YAML text: the profile sections (packing, seeds, measurement) and a scene
//   packing  a packing file (softpack-pack; read by the sweeps and softpack-section)
//   sweep    a sweep point file (checkpoint, with its state) and a sweep results file
//            (softpack-normal/-tangential; read by the resume and by softpack-average)
//   average  a seed-average file (softpack-average; read by softpack-fit)
#pragma once
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

namespace softpack::fuzz {

/// The names above, in that order.
const std::vector<std::string>& targets();

/// Feeds `data` to `target`. The HDF5 targets write it to `scratch` (a file path) first, as
/// the readers take a path. Returns, or throws InputError for bad input.
void run_bytes(const std::string& target, std::string_view data, const std::string& scratch);

/// Feeds the file `path` to `target` (the replay: corpus and regression files).
void run_file(const std::string& target, const std::string& path);

/// A scratch file for `target` in $TMPDIR (or /tmp), unique to this process.
std::string scratch_path(const std::string& target);

/// The demangled name of an exception type, for the report of one that escaped.
std::string type_name(const std::type_info& t);

// The entry points themselves.
void config_text(const std::string& text, const std::string& name);
void packing_file(const std::string& path);
void sweep_file(const std::string& path);
void average_file(const std::string& path);

}  // namespace softpack::fuzz
