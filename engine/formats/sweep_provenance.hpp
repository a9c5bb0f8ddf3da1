// The provenance that the sweep point files (formats/sweep_point_file.hpp) and the sweep
// results files (formats/sweep_results_file.hpp) share, with its dataset names.
#pragma once
#include <string>

namespace softpack {

struct PointProvenance {
  std::string stage;   ///< "normal" or "tangential"
  std::string scene;   ///< "soft-solid" or "soft-soft"
  std::string config;  ///< the configuration the point depends on (YAML)
  std::string code_version;
};

namespace sweep_names {

inline constexpr const char* kStage = "provenance/stage";
inline constexpr const char* kScene = "provenance/scene";

/// f(dataset, member) for each field of `p`, in the files' order.
template <class P, class F>
void each_provenance_field(P& p, F&& f) {
  f(kStage, p.stage);
  f(kScene, p.scene);
  f("provenance/config", p.config);
  f("provenance/code_version", p.code_version);
}

}  // namespace sweep_names
}  // namespace softpack
