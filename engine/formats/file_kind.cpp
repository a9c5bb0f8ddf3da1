#include "formats/file_kind.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace softpack {

std::string kind_of(const h5::File& f) {
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

bool has_layout(const h5::File& f, std::span<const char* const> layout) {
  for (const char* name : layout)
    if (!f.exists(name)) return false;
  return true;
}

void expect_layout(const h5::File& f, const std::string& what, std::span<const char* const> layout) {
  if (has_layout(f, layout)) return;
  std::string kind = kind_of(f);
  if (kind.empty()) {
    kind = "no";
    for (std::size_t k = 0; k < layout.size(); ++k)
      kind += fmt::format("{}/{}", k == 0 ? " " : k + 1 == layout.size() ? " or " : ", ", layout[k]);
  } else {
    kind = "it is " + kind;
  }
  throw InputError(fmt::format("{}: not a softpack {} file ({})", f.path(), what, kind));
}

}  // namespace softpack
