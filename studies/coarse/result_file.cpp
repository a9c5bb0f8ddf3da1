#include "coarse/result_file.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/types.hpp"
#include "core/version.hpp"
#include "formats/h5_fields.hpp"
#include "io/hdf5_file.hpp"

namespace softpack {

using formats::get;
using formats::put;

CoarseResult coarse_result(const CompressionRun& run, const Medium& m, CoarseModel model, std::uint64_t seed,
                           const CoarseGrainSettings& s) {
  CoarseResult r;
  r.model = name(model), r.settings = s.section_text, r.laws = s.laws, r.code_version = code_version();
  r.seed = seed;
  r.L = m.L, r.H = m.H, r.Rs = m.Rs;
  r.grains = static_cast<std::int64_t>(m.grain_x.size()), r.sites = static_cast<std::int64_t>(m.sites.size());
  r.spheres = static_cast<std::int64_t>(run.spheres), r.bodies = static_cast<std::int64_t>(run.bodies);
  r.grains_volume = m.grains_volume, r.packings_volume = m.packings_volume, r.target_volume = m.target_volume;
  for (std::uint64_t k : m.packing_seeds) r.packing_seeds.push_back(static_cast<std::int64_t>(k));
  r.steps = run.steps, r.dt = run.dt, r.seconds = run.time.wall, r.cpu_seconds = run.time.cpu;
  r.threads = parallel::threads_for(run.spheres);  // what the run used (core/parallel.hpp)
  r.beyond_range = run.soft.beyond_range, r.max_dn = run.soft.max_dn;
  r.rows = run.rows;
  return r;
}

namespace {

// The curve's columns, one member of CurveRow each.
template <class F>
void columns(F&& f) {
  f("strain", &CurveRow::strain);
  f("sigma_top", &CurveRow::sigma_top);
  f("sigma_bottom", &CurveRow::sigma_bottom);
  f("sigma_lateral", &CurveRow::sigma_lateral);
  f("fraction", &CurveRow::fraction);
  f("Z", &CurveRow::Z);
  f("kinetic", &CurveRow::kinetic);
  f("elastic", &CurveRow::elastic);
  f("shear", &CurveRow::shear);
  f("tau", &CurveRow::tau);
}

template <class F>
void counts(F&& f) {
  f("phase", &CurveRow::phase);
  f("grain_grain", &CurveRow::grain_grain);
  f("grain_soft", &CurveRow::grain_soft);
  f("soft_soft", &CurveRow::soft_soft);
}

}  // namespace

void write_coarse_result(const std::string& path, const CoarseResult& r) {
  h5::AtomicH5 out(path);
  h5::File& f = out.file();
  // A run that did not record a column (LAMMPS's: Z, the bodies in contact and the elastic energy,
  // coarse/lammps_export.hpp) leaves it out; the reader gives NaN (or 0 counts) for it.
  const auto unrecorded = [&](auto member) {
    return !r.rows.empty() && std::all_of(r.rows.begin(), r.rows.end(), [&](const CurveRow& row) { return std::isnan(row.*member); });
  };
  columns([&](const char* name, auto member) {
    if ((member == &CurveRow::Z || member == &CurveRow::elastic) && unrecorded(member)) return;
    std::vector<double> v;
    for (const CurveRow& row : r.rows) v.push_back(row.*member);
    put(f, std::string("curve/") + name, v);
  });
  counts([&](const char* name, auto member) {
    if (std::string_view(name) != "phase" && unrecorded(&CurveRow::Z)) return;
    std::vector<std::int64_t> v;
    for (const CurveRow& row : r.rows) v.push_back(static_cast<std::int64_t>(row.*member));
    put(f, std::string("curve/") + name, v);
  });
  // The soft contacts beyond the laws' range row by row: only where the rows count them (soft model).
  if (!r.rows.empty() && r.rows.front().beyond_range >= 0) {
    std::vector<std::int64_t> beyond;
    std::vector<double> max_dn;
    for (const CurveRow& row : r.rows) beyond.push_back(row.beyond_range), max_dn.push_back(row.max_dn);
    put(f, "curve/beyond_range", beyond), put(f, "curve/max_dn", max_dn);
  }
  put(f, "medium/L", r.L), put(f, "medium/H", r.H), put(f, "medium/Rs", r.Rs);
  put(f, "medium/grains", r.grains), put(f, "medium/sites", r.sites), put(f, "medium/spheres", r.spheres), put(f, "medium/bodies", r.bodies);
  put(f, "medium/grains_volume", r.grains_volume), put(f, "medium/packings_volume", r.packings_volume);
  put(f, "medium/target_volume", r.target_volume), put(f, "medium/packing_seeds", r.packing_seeds);
  if (r.beyond_range >= 0) put(f, "soft/beyond_range", r.beyond_range), put(f, "soft/max_dn", r.max_dn);  // < 0: not counted (LAMMPS)
  put(f, "provenance/model", r.model), put(f, "provenance/seed", static_cast<std::int64_t>(r.seed));
  put(f, "provenance/settings", r.settings), put(f, "provenance/laws", r.laws), put(f, "provenance/code_version", r.code_version);
  put(f, "provenance/steps", r.steps), put(f, "provenance/dt", r.dt);
  put(f, "provenance/seconds", r.seconds), put(f, "provenance/cpu_seconds", r.cpu_seconds);
  put(f, "provenance/threads", r.threads);
  put(f, "provenance/engine", r.engine);
  out.commit();
}

CoarseResult read_coarse_result(const std::string& path) {
  const h5::File f = h5::File::open(path);
  CoarseResult r;
  r.path = path;
  if (f.exists("provenance/engine")) get(f, "provenance/engine", r.engine);
  if (r.engine != "softpack" && r.engine != "lammps")
    throw InputError(path + ": provenance/engine: '" + r.engine + "' is not allowed; allowed: softpack, lammps");
  const bool lammps = r.engine == "lammps";  // only its runs may lack what they do not record
  std::vector<double> strain;
  get(f, "curve/strain", strain);
  r.rows.resize(strain.size());
  columns([&](const char* name, auto member) {
    // A run from before the platen shear was added (the committed reduced-radius runs) has neither the
    // wall's displacement nor its shear stress: no shear (0), tau not recorded (NaN).
    const std::string key = std::string("curve/") + name;
    // A LAMMPS run (coarse/lammps_export.hpp) records neither Z nor the elastic energy: NaN.
    if ((key == "curve/shear" || key == "curve/tau" || (lammps && (key == "curve/Z" || key == "curve/elastic"))) && !f.exists(key)) {
      for (CurveRow& row : r.rows) row.*member = key == "curve/shear" ? 0.0 : kNaN;
      return;
    }
    std::vector<double> v;
    get(f, key, v);
    formats::same_length(f, std::string("curve/") + name, v.size(), "curve/strain", strain.size());
    formats::check_finite(f, std::string("curve/") + name, v);
    for (std::size_t k = 0; k < v.size(); ++k) r.rows[k].*member = v[k];
  });
  counts([&](const char* name, auto member) {
    if (lammps && std::string_view(name) != "phase" && !f.exists(std::string("curve/") + name)) return;  // not recorded (Z NaN): 0
    std::vector<std::int64_t> v;
    get(f, std::string("curve/") + name, v);
    formats::same_length(f, std::string("curve/") + name, v.size(), "curve/strain", strain.size());
    for (std::size_t k = 0; k < v.size(); ++k) r.rows[k].*member = static_cast<std::remove_reference_t<decltype(r.rows[k].*member)>>(v[k]);
  });
  // Counted row by row by the soft model's runs since the count was added; otherwise -1 and NaN.
  if (f.exists("curve/beyond_range")) {
    std::vector<std::int64_t> beyond;
    std::vector<double> max_dn;
    get(f, "curve/beyond_range", beyond), get(f, "curve/max_dn", max_dn);
    formats::same_length(f, "curve/beyond_range", beyond.size(), "curve/strain", strain.size());
    formats::same_length(f, "curve/max_dn", max_dn.size(), "curve/strain", strain.size());
    for (std::size_t k = 0; k < beyond.size(); ++k) r.rows[k].beyond_range = static_cast<long>(beyond[k]), r.rows[k].max_dn = max_dn[k];
  }
  get(f, "medium/L", r.L), get(f, "medium/H", r.H), get(f, "medium/Rs", r.Rs);
  get(f, "medium/grains", r.grains), get(f, "medium/sites", r.sites), get(f, "medium/spheres", r.spheres), get(f, "medium/bodies", r.bodies);
  get(f, "medium/grains_volume", r.grains_volume), get(f, "medium/packings_volume", r.packings_volume);
  get(f, "medium/target_volume", r.target_volume), get(f, "medium/packing_seeds", r.packing_seeds);
  if (!lammps || f.exists("soft/beyond_range")) get(f, "soft/beyond_range", r.beyond_range), get(f, "soft/max_dn", r.max_dn);
  else r.beyond_range = -1, r.max_dn = kNaN;  // not counted by LAMMPS's run
  std::int64_t seed = 0;
  get(f, "provenance/model", r.model), get(f, "provenance/seed", seed);
  r.seed = static_cast<std::uint64_t>(seed);
  get(f, "provenance/settings", r.settings), get(f, "provenance/laws", r.laws), get(f, "provenance/code_version", r.code_version);
  get(f, "provenance/steps", r.steps), get(f, "provenance/dt", r.dt);
  get(f, "provenance/seconds", r.seconds), get(f, "provenance/cpu_seconds", r.cpu_seconds);
  if (f.exists("provenance/threads")) get(f, "provenance/threads", r.threads);
  if (r.model != "resolved" && r.model != "soft")
    throw InputError(path + ": provenance/model: '" + r.model + "' is not allowed; allowed: resolved, soft");
  return r;
}

}  // namespace softpack
