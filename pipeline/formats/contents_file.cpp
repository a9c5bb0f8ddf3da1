#include "formats/contents_file.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <system_error>

#include "core/error.hpp"
#include "core/version.hpp"
#include "formats/h5_fields.hpp"
#include "io/file_lock.hpp"
#include "io/sha256.hpp"

namespace softpack {
namespace {

using namespace formats;

// The contents as flat lists, one entry per level packing in pre-order.
struct Flat {
  std::vector<std::int64_t> children, grains, sites, sampled, discarded, grown, sites_drawn, sites_discarded;
  std::vector<double> site_radius, radii, radii_inserted;
  std::vector<Vec3> centres, site_centres;

  void add(const SiteContent& c) {
    const LevelPacking& l = c.level;
    children.push_back(static_cast<std::int64_t>(c.sites.size()));
    grains.push_back(static_cast<std::int64_t>(l.grains.radii.size()));
    sites.push_back(static_cast<std::int64_t>(l.sites.size()));
    sampled.push_back(static_cast<std::int64_t>(l.grains.sampled));
    discarded.push_back(static_cast<std::int64_t>(l.grains.discarded));
    grown.push_back(static_cast<std::int64_t>(l.grains.grown));
    sites_drawn.push_back(static_cast<std::int64_t>(l.sites_drawn));
    sites_discarded.push_back(static_cast<std::int64_t>(l.sites_discarded));
    site_radius.push_back(l.site_radius);
    centres.insert(centres.end(), l.grains.centres.begin(), l.grains.centres.end());
    radii.insert(radii.end(), l.grains.radii.begin(), l.grains.radii.end());
    radii_inserted.insert(radii_inserted.end(), l.grains.radii_inserted.begin(), l.grains.radii_inserted.end());
    site_centres.insert(site_centres.end(), l.sites.begin(), l.sites.end());
    for (const SiteContent& s : c.sites) add(s);
  }

  template <class F>
  void fields(F&& f) {
    f("nodes/children", children), f("nodes/grains", grains), f("nodes/sites", sites), f("nodes/sampled", sampled);
    f("nodes/discarded", discarded), f("nodes/grown", grown), f("nodes/sites_drawn", sites_drawn);
    f("nodes/sites_discarded", sites_discarded), f("nodes/site_radius", site_radius);
    f("grains/centres", centres), f("grains/radii", radii), f("grains/radii_inserted", radii_inserted), f("sites/centres", site_centres);
  }
};

// Reads node `node` and its subtree from the lists; InputError when they do not add up.
struct Cursor {
  const Flat& f;
  std::size_t node = 0, grain = 0, site = 0;

  SiteContent next() {
    if (node >= f.children.size()) throw InputError("fewer nodes than the tree needs");
    const std::size_t k = node++;
    if (f.grains[k] < 0 || f.sites[k] < 0 || f.children[k] < 0) throw InputError("a negative count");
    SiteContent c;
    const auto n = static_cast<std::size_t>(f.grains[k]), m = static_cast<std::size_t>(f.sites[k]);
    if (grain + n > f.radii.size() || grain + n > f.centres.size() || grain + n > f.radii_inserted.size() ||
        site + m > f.site_centres.size())
      throw InputError("fewer grains or sites than the nodes say");
    Packing& g = c.level.grains;
    g.centres.assign(f.centres.begin() + static_cast<std::ptrdiff_t>(grain), f.centres.begin() + static_cast<std::ptrdiff_t>(grain + n));
    g.radii.assign(f.radii.begin() + static_cast<std::ptrdiff_t>(grain), f.radii.begin() + static_cast<std::ptrdiff_t>(grain + n));
    g.radii_inserted.assign(f.radii_inserted.begin() + static_cast<std::ptrdiff_t>(grain),
                            f.radii_inserted.begin() + static_cast<std::ptrdiff_t>(grain + n));
    g.sampled = static_cast<std::size_t>(f.sampled[k]), g.discarded = static_cast<std::size_t>(f.discarded[k]);
    g.grown = static_cast<std::size_t>(f.grown[k]);
    c.level.site_radius = f.site_radius[k];
    c.level.sites.assign(f.site_centres.begin() + static_cast<std::ptrdiff_t>(site),
                         f.site_centres.begin() + static_cast<std::ptrdiff_t>(site + m));
    c.level.sites_drawn = static_cast<std::size_t>(f.sites_drawn[k]);
    c.level.sites_discarded = static_cast<std::size_t>(f.sites_discarded[k]);
    grain += n, site += m;
    for (std::int64_t s = 0; s < f.children[k]; ++s) c.sites.push_back(next());
    return c;
  }
};

}  // namespace

void write_contents_file(const std::string& path, const std::string& packing_sha256, int levels_below,
                         const std::vector<SiteContent>& contents) {
  Flat flat;
  for (const SiteContent& c : contents) flat.add(c);
  h5::AtomicH5 out(path);
  h5::File& f = out.file();
  put(f, "key/packing_sha256", packing_sha256);
  put(f, "key/levels_below", static_cast<std::int64_t>(levels_below));
  put(f, "key/sites", static_cast<std::int64_t>(contents.size()));
  flat.fields(writer(f));
  put(f, "provenance/code_version", code_version());
  out.commit();
}

std::optional<std::vector<SiteContent>> read_contents_file(const std::string& path, const std::string& packing_sha256,
                                                           int levels_below, std::size_t sites) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  try {
    const h5::File f = h5::File::open(path);
    std::string key;
    get(f, "key/packing_sha256", key);
    if (key != packing_sha256 || get_count(f, "key/levels_below") != levels_below ||
        get_count(f, "key/sites") != static_cast<std::int64_t>(sites))
      return std::nullopt;
    Flat flat;
    flat.fields(reader(f));
    Cursor at{flat};
    std::vector<SiteContent> out;
    for (std::size_t k = 0; k < sites; ++k) out.push_back(at.next());
    if (at.node != flat.children.size() || at.grain != flat.radii.size() || at.site != flat.site_centres.size()) return std::nullopt;
    return out;
  } catch (const InputError&) {
    return std::nullopt;  // made again below
  }
}

std::vector<SiteContent> packing_contents(const PackingFile& p) {
  if (p.sites.levels <= 1) return {};
  const int below = p.sites.levels - 1;
  const std::size_t sites = p.sites.centres.size();
  if (p.path.empty()) return generate_contents(p.parameters, below, p.provenance.seed, sites);
  const std::string cache = p.path + ".contents.h5", key = sha256_of_file(p.path);
  if (auto kept = read_contents_file(cache, key, below, sites)) return std::move(*kept);
  // One maker per packing: the scenes of a packing run side by side (make -j) and each needs them;
  // the others wait for the first and read what it kept.
  const FileLock lock(cache + ".lock", [&] {
    fmt::print(stderr, "contents: another process is making those of {}; waiting for it\n", p.path);
  });
  if (auto kept = read_contents_file(cache, key, below, sites)) return std::move(*kept);
  // Making them takes minutes at the chain's level 0 (docs/nested.md): a line per site, with the
  // time left, on the standard error (a stage's log), as the sweep's notes.
  fmt::print(stderr, "contents: making those of {} ({} sites, {} levels below; kept in {})\n", p.path, sites, below, cache);
  const auto start = std::chrono::steady_clock::now();
  const PackingProgress progress = [&](const std::string&, std::size_t done, std::size_t total) {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fmt::print(stderr, "contents: site {}/{} made, {:.0f} s, ETA {:.0f} s\n", done, total, s,
               s / static_cast<double>(done) * static_cast<double>(total - done));
  };
  std::vector<SiteContent> made = generate_contents(p.parameters, below, p.provenance.seed, sites, progress);
  try {
    write_contents_file(cache, key, below, made);
  } catch (const InputError&) {
    // A folder that cannot be written (an archive, a read-only copy): made, not kept.
  }
  return made;
}

}  // namespace softpack
