#include "io/file_kind.hpp"

#include "core/error.hpp"

namespace softpack::h5 {

std::string kind_of(const File& f) {
  try {
    if (f.exists("centres") && f.exists("radii") && f.exists("provenance/program"))
      return f.read_string("provenance/program") == "softpack-pack" ? "a packing file (softpack-pack)"
                                                                    : "a packing file of another program";
    if (f.exists("result") && f.exists("state") && f.exists("provenance/stage"))
      return "a sweep point file (a checkpoint of softpack-" + f.read_string("provenance/stage") + ")";
    if (f.exists("Fn") && f.exists("provenance/stage")) {
      const std::string stage = f.read_string("provenance/stage");
      return "a " + stage + " sweep results file (softpack-" + stage + ")";
    }
    if (f.exists("normal/Fn_mean") && f.exists("provenance/scene")) return "an average file (softpack-average)";
  } catch (const InputError&) {
  }
  return "";
}

}  // namespace softpack::h5
