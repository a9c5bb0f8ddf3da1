#include "coarse/kinematics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "analysis/seed_statistics.hpp"
#include "coarse/in_place.hpp"
#include "contact/soft_particle_law.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "io/atomic_file.hpp"

namespace softpack {
namespace {

// One body pressing a soft-particle (a site) at one strain: F the soft law's force or the resolved
// push, law the law's force (the soft's F; resolved: from the same geometry), alone the law with
// the soft-particle's other caps removed.
struct Press {
  double strain = 0.0;
  int kind = 0;
  double dn = 0.0, ratio = 0.0, F = 0.0, law = 0.0, alone = 0.0;
};

struct Group {
  std::size_t presses = 0, below = 0;
  double F = 0.0, law = 0.0;
  std::vector<double> dn, confinement;
  void add(const Press& p) {
    ++presses, F += p.F, law += p.law, dn.push_back(p.dn);
    if (p.alone > 0.0) confinement.push_back(p.law / p.alone);
    else ++below;
  }
};

// The law alone at Δn: the engine's many-body model with the soft-particle's E its own cap.
double alone(const SoftParticleLaws& laws, double Rs, int kind, double dn, double ratio) {
  const SoftNormal::Params params{&laws, GrainContactRule::wall, false};
  ContactGeometry<double> g{};
  g.h = dn * Rs, g.body1 = cap_volume(dn), g.body2 = kind == 2 ? cap_volume(dn) : 0.0;
  return SoftManyBodyNormal::evaluate(params, SoftManyBodyNormal::constants(params, site_partners(Rs, kind, ratio)), g).Fn;
}

// A median, or "–" where there is none.
std::string median_cell(const std::vector<double>& v, const char* f) { return v.empty() ? "–" : fmt::format(fmt::runtime(f), rank_quantile(v, 0.5)); }

}  // namespace

void write_kinematics_report(const ManyBodyProbe& plan, const std::string& plan_path, const SoftParticleLaws& laws, const std::string& laws_source,
                             const std::string& census_rows, const std::string& in_place_dir, const std::string& out_dir, int version) {
  if (!laws.many_body || !laws.soft_solid || !laws.soft_soft)
    throw InputError(fmt::format("{}: no many_body or a scene missing; the comparison needs both scenes and many_body", laws_source));
  const std::vector<std::uint64_t>& seeds = plan.media_seeds_of(version);
  std::map<std::uint64_t, std::pair<std::size_t, double>> media;  // seed -> its sites, Rs
  const auto same_laws = [&](const std::string& named, const std::string& where) {
    if (named != laws_source)
      throw InputError(fmt::format("{}: made with the laws {}, not {} (rerun it, or give the laws it was made with)", where, named, laws_source));
  };
  std::vector<Press> soft, resolved;
  {
    std::ifstream in(census_rows);
    if (!in) throw InputError(fmt::format("{}: cannot read it (make many-body-v3-verdict writes it with softpack-coarse soft-contacts)", census_rows));
    int line_no = 0;
    for (std::string line; std::getline(in, line);) {
      ++line_no;
      std::uint64_t seed = 0;
      std::size_t n = 0;
      double Rs = 0.0;
      std::string word;
      if (const std::size_t at = line.find(" with the laws "); line_no == 1) same_laws(at == std::string::npos ? "" : line.substr(at + 15), census_rows);
      if (std::istringstream head(line); line.rfind("# seed ", 0) == 0 && head >> word >> word >> seed >> word >> n >> word >> word >> Rs) media[seed] = {n, Rs};
      if (line.empty() || line[0] == '#') continue;
      std::istringstream r(line);
      Press p;
      std::size_t site = 0, count = 0;
      if (!(r >> seed >> p.strain >> site >> p.kind >> p.dn >> p.ratio >> count >> p.F) || !media.count(seed) || p.kind < 0 || p.kind > 2)
        throw InputError(fmt::format("{}:{}: expected 'seed strain soft_particle kind dn r_over_Rs count Fn' after its seed's '# seed S: N soft-particles, Rs R m'",
                                     census_rows, line_no));
      if (std::find(seeds.begin(), seeds.end(), seed) == seeds.end())
        throw InputError(fmt::format("{}:{}: seed {} is not one of {}'s validation.{}", census_rows, line_no, seed, plan_path, media_seeds_key(version)));
      p.law = p.F;
      if (tabled_strain(p.strain)) p.alone = alone(laws, media[seed].second, p.kind, p.dn, p.ratio), soft.push_back(p);
    }
  }
  double sites = 0.0;  // of all the seeds: the same at every strain, in both models
  for (const std::uint64_t seed : seeds) {
    if (!media.count(seed)) throw InputError(fmt::format("{}: no seed {} (rerun its census)", census_rows, seed));
    sites += static_cast<double>(media[seed].first);
    const std::string path = fmt::format("{}/seed-{}.dat", in_place_dir, seed);
    std::string named;
    for (const InPlaceContact& c : read_in_place_rows(path, &named))
      if (tabled_strain(c.strain))
        resolved.push_back({c.strain, c.kind, c.dn, c.ratio, c.measured, c.law, alone(laws, media[seed].second, c.kind, c.dn, c.ratio)});
    same_laws(named, path);
  }
  // Each tabled strain and kind (3: all), soft and resolved.
  std::map<double, std::map<int, std::pair<Group, Group>>> groups;
  for (const Press& p : soft) {
    const double e = std::round(p.strain * 100.0) / 100.0;
    groups[e][p.kind].first.add(p), groups[e][3].first.add(p);
  }
  for (const Press& p : resolved) {
    const double e = std::round(p.strain * 100.0) / 100.0;
    groups[e][p.kind].second.add(p), groups[e][3].second.add(p);
  }
  const char* kinds[] = {"wall", "grain", "soft-particle", "all"};
  std::string md = fmt::format(
      "# The soft medium's geometry against the resolved one's (generated by softpack-coarse kinematics, {})\n\n"
      "The media of the law's version {} (seeds {} of `{}`; paper/many-body.md, \"Next: the soft medium's geometry against the resolved "
      "one's\"), laws of `{}`. Soft: every closed contact of a soft-particle in the soft runs (`{}`); resolved: every body whose "
      "sphere intrudes a site's (`{}/seed-S.dat`). Per soft-particle: over the sites of all seeds. Push: soft, its law's force; "
      "resolved, measured (and the law's from the same geometry). Confinement: Fn over the law alone at the same Δn (the "
      "soft-particle's other caps removed), median over the contacts where the law alone is not 0 (resolved: the law's Fn); "
      "below the onset: the share of contacts where it is 0. \"–\": no contact to take it from.\n\n"
      "| strain | body | bodies per soft-particle soft / resolved | Δn median soft / resolved | Δn 90 % soft / resolved | push per "
      "soft-particle [N] soft / resolved / law on resolved | confinement soft / resolved | below the onset soft / resolved |\n"
      "|---|---|---|---|---|---|---|---|\n",
      code_version(), version, fmt::join(seeds, ", "), plan_path, laws_source, census_rows, in_place_dir);
  if (!(sites > 0.0)) throw InputError(fmt::format("{}: no soft-particle in its seeds", census_rows));
  for (const auto& [strain, by_kind] : groups)
    for (const auto& [kind, g] : by_kind) {
      const auto& [a, b] = g;
      const auto share = [](const Group& x) { return x.presses ? fmt::format("{:.2f}", static_cast<double>(x.below) / static_cast<double>(x.presses)) : std::string("–"); };
      const auto dn = [](const Group& x, double q) { return x.dn.empty() ? std::string("–") : fmt::format("{:.3f}", rank_quantile(x.dn, q)); };
      md += fmt::format("| {:.2f} | {} | {:.2f} / {:.2f} | {} / {} | {} / {} | {:.3g} / {:.3g} / {:.3g} | {} / {} | {} / {} |\n", strain, kinds[kind],
                        static_cast<double>(a.presses) / sites, static_cast<double>(b.presses) / sites, dn(a, 0.5), dn(b, 0.5), dn(a, 0.9), dn(b, 0.9),
                        a.F / sites, b.F / sites, b.law / sites, median_cell(a.confinement, "{:.2f}"), median_cell(b.confinement, "{:.2f}"), share(a), share(b));
    }
  write_file_atomically(out_dir + "/kinematics.md", md);
}

}  // namespace softpack
