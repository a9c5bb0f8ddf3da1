#include "fuzz_entry.hpp"

#include <cxxabi.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "analysis/average.hpp"
#include "analysis/power_fit.hpp"
#include "profile/profile.hpp"
#include "packing/packing_profile.hpp"
#include "core/error.hpp"
#include "formats/average_file.hpp"
#include "formats/fit_file.hpp"
#include "formats/packing_file.hpp"
#include "formats/sweep_file.hpp"
#include "measure/settings.hpp"
#include "scene/scene_yaml.hpp"

namespace softpack::fuzz {
namespace {

// Runs one reader; its InputError is the expected answer to bad input, so the next reader
// still sees the input (one bad section must not hide a crash in the next one).
void attempt(const std::function<void()>& reader) {
  try {
    reader();
  } catch (const InputError&) {
  }
}

// Text the executables write as provenance (HDF5 strings, JSON): what a reader accepted must
// be writable, i.e. UTF-8 without NUL. Violations are bugs of the reader (not InputError).
void check_writable_text(const std::string& text, const char* what) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == 0) throw std::logic_error(std::string(what) + ": accepted text holds a NUL character");
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || i + n > text.size()) throw std::logic_error(std::string(what) + ": accepted text is not UTF-8");
    for (std::size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(text[i + k]) >> 6) != 0x2)
        throw std::logic_error(std::string(what) + ": accepted text is not UTF-8");
    i += n;
  }
  // nlohmann::json refuses what is not UTF-8 (overlong forms, surrogates): let it judge too.
  (void)nlohmann::json(text).dump();
}

}  // namespace

const std::vector<std::string>& targets() {
  static const std::vector<std::string> names{"config", "packing", "sweep", "average"};
  return names;
}

void config_text(const std::string& text, const std::string& name) {
  const ConfigNode root = ConfigNode::load_string(text, name);
  // A profile, as the stages read it (softpack-pack, softpack-normal, softpack-tangential):
  // each section is recorded as provenance text.
  attempt([&] {
    parse_packing(root);
    check_writable_text(section_text(root, "packing"), "packing section");
  });
  attempt([&] { parse_seeds(root); });
  attempt([&] {
    parse_measurement(root);
    for (const char* s : {"material", "simulation", "relaxation", "normal", "tangential"})
      check_writable_text(section_text(root, s), s);
  });
  // A scene, as softpack-run reads it (the names end up in its JSON report).
  attempt([&] {
    const SceneFile f = parse_scene(root);
    for (const auto& m : f.scene.materials) check_writable_text(m.name, "material name");
    for (const auto& p : f.scene.planes) check_writable_text(p.name, "plane name");
    for (const auto& s : f.scene.shells) check_writable_text(s.name, "shell name");
  });
}

void packing_file(const std::string& path) {
  // As softpack-section and the sweeps use it.
  const PackingFile p = read_packing_file(path);
  check_writable_text(p.provenance.config, "packing provenance");
  (void)nlohmann::json({{"program", p.provenance.program}, {"version", p.provenance.code_version},
                        {"config_file", p.provenance.config_file}}).dump();
}

void sweep_file(const std::string& path) {
  // A checkpoint, as the resume reads it (with the state the tangential stage restores).
  attempt([&] { (void)read_point_file(path, true); });
  // A results file, as softpack-average reads and averages it.
  const SweepResults d = read_sweep_results_file(path);
  (void)average_normal({d, d});
  (void)average_tangential({d, d});
}

void average_file(const std::string& path) {
  // As softpack-fit reads it, fits it and writes the fit file.
  const AverageFile a = read_average_file(path);
  FitFile out;
  out.scene = a.scene;
  out.input = {path, a.profile, a.code_version, a.seeds};
  out.normal = fit::fit_normal_law(a.delta_n, a.Fn, a.Fn_stderr);
  if (a.has_kt) {
    try {
      out.tangential = fit::fit_tangential_law(a.kt_delta_n, a.kt, a.kt_stderr, out.normal.delta);
    } catch (const InputError& e) {
      out.tangential_reason = e.what();
    }
  }
  (void)fit_file_text(out);
}

std::string scratch_path(const std::string& target) {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir != nullptr && *dir != '\0' ? dir : "/tmp") + "/softpack-fuzz-" + target + "-" +
         std::to_string(::getpid()) + ".h5";
}

void run_bytes(const std::string& target, std::string_view data, const std::string& scratch) {
  if (target == "config") return config_text(std::string(data), "fuzz.yaml");
  {
    std::ofstream out(scratch, std::ios::binary | std::ios::trunc);
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
    if (!out) throw std::runtime_error("cannot write the scratch file " + scratch);
  }
  run_file(target, scratch);
}

void run_file(const std::string& target, const std::string& path) {
  if (target == "config") {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return config_text(text.str(), path);
  }
  if (target == "packing") return packing_file(path);
  if (target == "sweep") return sweep_file(path);
  if (target == "average") return average_file(path);
  throw std::invalid_argument("unknown fuzz target '" + target + "'");
}

std::string type_name(const std::type_info& t) {
  int status = 0;
  char* name = abi::__cxa_demangle(t.name(), nullptr, nullptr, &status);
  std::string out = status == 0 && name != nullptr ? name : t.name();
  std::free(name);
  return out;
}

}  // namespace softpack::fuzz
