#include "coarse/medium_file.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "formats/h5_fields.hpp"
#include "io/hdf5_file.hpp"

namespace softpack {

using formats::get;
using formats::put;

void write_medium_file(const std::string& path, const MediumFile& mf) {
  const Medium& m = mf.medium;
  h5::AtomicH5 out(path);
  h5::File& f = out.file();
  put(f, "grains/x", m.grain_x), put(f, "grains/r", m.grain_r), put(f, "sites/x", m.sites);
  std::vector<std::int64_t> offsets{0}, seeds;
  std::vector<Vec3> centres;
  std::vector<double> radii;
  for (std::size_t k = 0; k < m.packings.size(); ++k) {
    centres.insert(centres.end(), m.packings[k].centres.begin(), m.packings[k].centres.end());
    radii.insert(radii.end(), m.packings[k].radii.begin(), m.packings[k].radii.end());
    offsets.push_back(static_cast<std::int64_t>(radii.size()));
    seeds.push_back(static_cast<std::int64_t>(m.packing_seeds[k]));
  }
  put(f, "packings/offsets", offsets), put(f, "packings/centres", centres), put(f, "packings/radii", radii), put(f, "packings/seeds", seeds);
  put(f, "box/L", m.L), put(f, "box/H", m.H), put(f, "box/Rs", m.Rs);
  put(f, "volumes/grains", m.grains_volume), put(f, "volumes/packings", m.packings_volume), put(f, "volumes/target", m.target_volume);
  put(f, "provenance/seed", static_cast<std::int64_t>(mf.seed)), put(f, "provenance/settings", mf.settings);
  put(f, "provenance/code_version", mf.code_version);
  put(f, "provenance/seconds", mf.time.wall), put(f, "provenance/cpu_seconds", mf.time.cpu);
  out.commit();
}

MediumFile read_medium_file(const std::string& path) {
  const h5::File f = h5::File::open(path);
  MediumFile mf;
  Medium& m = mf.medium;
  get(f, "grains/x", m.grain_x), get(f, "grains/r", m.grain_r), get(f, "sites/x", m.sites);
  formats::same_length(f, "grains/r", m.grain_r.size(), "grains/x", m.grain_x.size());
  std::vector<std::int64_t> offsets, seeds;
  std::vector<Vec3> centres;
  std::vector<double> radii;
  get(f, "packings/offsets", offsets), get(f, "packings/centres", centres), get(f, "packings/radii", radii), get(f, "packings/seeds", seeds);
  formats::same_length(f, "packings/radii", radii.size(), "packings/centres", centres.size());
  formats::same_length(f, "packings/offsets", offsets.size(), "sites/x + 1", m.sites.size() + 1);
  formats::same_length(f, "packings/seeds", seeds.size(), "sites/x", m.sites.size());
  for (std::size_t k = 0; k < m.sites.size(); ++k) {
    const auto a = offsets[k], b = offsets[k + 1];
    if (a < 0 || b < a || b > static_cast<std::int64_t>(radii.size()))
      throw InputError(fmt::format("{}: packings/offsets: rows {} to {} of site {} are not in the {} grains", path, a, b, k, radii.size()));
    Packing p;
    p.centres.assign(centres.begin() + a, centres.begin() + b);
    p.radii.assign(radii.begin() + a, radii.begin() + b);
    m.packings.push_back(std::move(p));
    m.packing_seeds.push_back(static_cast<std::uint64_t>(seeds[k]));
  }
  get(f, "box/L", m.L), get(f, "box/H", m.H), get(f, "box/Rs", m.Rs);
  get(f, "volumes/grains", m.grains_volume), get(f, "volumes/packings", m.packings_volume), get(f, "volumes/target", m.target_volume);
  std::int64_t seed = 0;
  get(f, "provenance/seed", seed), get(f, "provenance/settings", mf.settings), get(f, "provenance/code_version", mf.code_version);
  get(f, "provenance/seconds", mf.time.wall), get(f, "provenance/cpu_seconds", mf.time.cpu);
  mf.seed = static_cast<std::uint64_t>(seed);
  if (!(m.L > 0.0 && m.H > 0.0 && m.Rs > 0.0)) throw InputError(path + ": box/L, H and Rs must be > 0");
  return mf;
}

}  // namespace softpack
