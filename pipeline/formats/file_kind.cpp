#include "formats/file_kind.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "formats/average_file.hpp"
#include "formats/fit_file.hpp"
#include "formats/h5_fields.hpp"
#include "formats/packing_file.hpp"
#include "formats/sweep_file.hpp"

namespace softpack {

std::string kind_of(const h5::File& f) {
  try {
    for (const auto describe : {describe_packing_file, describe_point_file, describe_sweep_results_file, describe_average_file})
      if (std::string kind = describe(f); !kind.empty()) return kind;
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

std::optional<RecordedStamp> recorded_stamp(const std::string& path) {
  try {
    RecordedStamp r;
    if (path.ends_with(".json")) {
      r = {"average", read_fit_file(path).stamp};
    } else {
      const h5::File f = h5::File::open(path);
      if (!f.exists(formats::kProvenanceStamp)) return std::nullopt;
      r.stamp = f.read_string(formats::kProvenanceStamp);
      r.stage = f.exists("provenance/stage") ? f.read_string("provenance/stage") : f.exists("provenance/program") ? "packing" : "average";
    }
    if (r.stamp.empty()) return std::nullopt;
    return r;
  } catch (const InputError&) {
    return std::nullopt;
  }
}

}  // namespace softpack
