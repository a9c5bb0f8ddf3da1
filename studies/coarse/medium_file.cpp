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
  if (m.levels > 1) {  // nested: each site's own sites (their contents are made from the seeds)
    std::vector<std::int64_t> inner_offsets{0};
    std::vector<Vec3> inner;
    for (const std::vector<Vec3>& v : m.inner_sites) {
      inner.insert(inner.end(), v.begin(), v.end());
      inner_offsets.push_back(static_cast<std::int64_t>(inner.size()));
    }
    put(f, "packings/levels", static_cast<std::int64_t>(m.levels)), put(f, "packings/site_radius", m.inner_radius);
    put(f, "packings/site_offsets", inner_offsets), put(f, "packings/site_centres", inner);
    if (m.content_mean.sample > 0) {  // sampled: what a site's site holds, expected (ContentMean)
      const ContentMean& c = m.content_mean;
      put(f, "contents/sample", static_cast<std::int64_t>(c.sample));
      put(f, "contents/volume", std::vector<double>{c.volume, c.volume_error});
      put(f, "contents/shells_volume", std::vector<double>{c.shells_volume, c.shells_volume_error});
      put(f, "contents/grains", std::vector<double>{c.grains, c.grains_error});
      put(f, "contents/smallest_radius", c.smallest_radius);
    }
  }
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
  if (f.exists("packings/levels")) {  // nested soft-particles (absent: grains only)
    const std::int64_t levels = formats::get_count(f, "packings/levels");
    if (levels < 2 || levels > 1000) throw InputError(fmt::format("{}: packings/levels: {} is not allowed; allowed: 2 to 1000", path, levels));
    m.levels = static_cast<int>(levels);
    std::vector<std::int64_t> inner_offsets;
    std::vector<Vec3> inner;
    get(f, "packings/site_radius", m.inner_radius), get(f, "packings/site_offsets", inner_offsets), get(f, "packings/site_centres", inner);
    formats::same_length(f, "packings/site_offsets", inner_offsets.size(), "sites/x + 1", m.sites.size() + 1);
    for (std::size_t k = 0; k < m.sites.size(); ++k) {
      const auto a = inner_offsets[k], b = inner_offsets[k + 1];
      if (a < 0 || b < a || b > static_cast<std::int64_t>(inner.size()))
        throw InputError(fmt::format("{}: packings/site_offsets: rows {} to {} of site {} are not in the {} sites", path, a, b, k, inner.size()));
      m.inner_sites.emplace_back(inner.begin() + a, inner.begin() + b);
    }
    if (!(m.inner_radius > 0.0)) throw InputError(path + ": packings/site_radius must be > 0");
    if (f.exists("contents/sample")) {  // sampled contents (absent: made from the seeds)
      ContentMean& c = m.content_mean;
      const std::int64_t sample = formats::get_count(f, "contents/sample");
      if (sample < 2) throw InputError(fmt::format("{}: contents/sample: {} is not allowed; allowed: 2 or more", path, sample));
      c.sample = static_cast<std::size_t>(sample);
      const auto pair = [&](const char* name, double& value, double& error) {
        std::vector<double> v;
        get(f, name, v);
        if (v.size() != 2) throw InputError(fmt::format("{}: {}: {} numbers; allowed: 2, a value and its error", path, name, v.size()));
        if (!(v[0] > 0.0 && v[1] >= 0.0)) throw InputError(fmt::format("{}: {}: {} ± {}; allowed: > 0 ± >= 0", path, name, v[0], v[1]));
        value = v[0], error = v[1];
      };
      pair("contents/volume", c.volume, c.volume_error);
      pair("contents/shells_volume", c.shells_volume, c.shells_volume_error);
      pair("contents/grains", c.grains, c.grains_error);
      get(f, "contents/smallest_radius", c.smallest_radius);
      if (!(c.smallest_radius > 0.0)) throw InputError(path + ": contents/smallest_radius must be > 0");
    }
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
