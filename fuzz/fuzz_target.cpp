// One libFuzzer target per reader: compiled once per target with SOFTPACK_FUZZ_TARGET set to
// its name (fuzz/CMakeLists.txt). An InputError is the expected answer to bad input; any other
// exception is reported with its type and aborts, so libFuzzer keeps the input as a crash.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

#include "core/error.hpp"
#include "fuzz_entry.hpp"
#include "io/hdf5_file.hpp"

#ifndef SOFTPACK_FUZZ_TARGET
#error "define SOFTPACK_FUZZ_TARGET (config, packing, sweep or average)"
#endif

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // A file on which the HDF5 library hangs is refused after 5 s (libFuzzer's -timeout is 30 s).
  softpack::h5::set_preflight_seconds(5);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string target = SOFTPACK_FUZZ_TARGET;
  static const std::string scratch = softpack::fuzz::scratch_path(target);
  try {
    softpack::fuzz::run_bytes(target, {reinterpret_cast<const char*>(data), size}, scratch);
  } catch (const softpack::InputError&) {
    // the expected answer to bad input
  } catch (const std::exception& e) {
    std::fprintf(stderr, "==softpack-fuzz== %s: an exception other than InputError escaped: %s: %s\n", target.c_str(),
                 softpack::fuzz::type_name(typeid(e)).c_str(), e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "==softpack-fuzz== %s: a non-standard exception escaped\n", target.c_str());
    std::abort();
  }
  return 0;
}
