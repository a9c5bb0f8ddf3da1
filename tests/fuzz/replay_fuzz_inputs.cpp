// The fuzz regressions (ctest, label fuzz-regression): feeds every file of the given folders
// (fuzz/regressions/<target>/: inputs that once crashed a reader; fuzz/corpus/<target>/: the
// seeds) to the entry point of a fuzz target (fuzz/fuzz_entry.hpp), as libFuzzer does in the
// fuzz build, and fails when one ends otherwise than by returning or by throwing InputError.
// Under the sanitizer build (make test-sanitize) crashes and memory errors show too.
//
//   replay_fuzz_inputs TARGET DIR...
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <typeinfo>
#include <vector>

#include "core/error.hpp"
#include "fuzz_entry.hpp"

namespace {

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  const auto& targets = softpack::fuzz::targets();
  if (argc < 3 || std::find(targets.begin(), targets.end(), argv[1]) == targets.end()) {
    std::fprintf(stderr, "usage: replay_fuzz_inputs TARGET DIR...   (TARGET: config, packing, sweep or average)\n");
    return 2;
  }
  const std::string target = argv[1];
  std::vector<fs::path> files;
  for (int k = 2; k < argc; ++k) {
    std::error_code ec;
    if (!fs::is_directory(argv[k], ec)) continue;  // a target without regressions yet
    for (const auto& e : fs::directory_iterator(argv[k]))
      if (e.is_regular_file() && e.path().filename().string()[0] != '.') files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    std::fprintf(stderr, "replay %s: no input files found\n", target.c_str());
    return 1;
  }
  std::size_t accepted = 0, rejected = 0, failed = 0;
  for (const fs::path& f : files) {
    try {
      softpack::fuzz::run_file(target, f.string());
      ++accepted;
      std::printf("read      %s\n", f.string().c_str());
    } catch (const softpack::InputError& e) {
      ++rejected;
      std::printf("refused   %s\n          %s\n", f.string().c_str(), first_line(e.what()).c_str());
    } catch (const std::exception& e) {
      ++failed;
      std::printf("FAILED    %s\n          %s escaped (not InputError): %s\n", f.string().c_str(),
                  softpack::fuzz::type_name(typeid(e)).c_str(), e.what());
    }
  }
  // "read": the entry point returned (the config target answers each parser's InputError itself).
  std::printf("replay %s: %zu inputs, %zu read, %zu refused with InputError, %zu failed\n", target.c_str(), files.size(),
              accepted, rejected, failed);
  return failed == 0 ? 0 : 1;
}
