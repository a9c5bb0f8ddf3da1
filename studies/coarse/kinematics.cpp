#include "coarse/kinematics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "analysis/seed_statistics.hpp"
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
  std::size_t presses = 0, sites = 0, below = 0;
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
  ContactPartners b;
  b.kind = kind == 0 ? ContactPartners::Kind::plane : ContactPartners::Kind::pair;
  b.R1 = Rs, b.soft1 = true, b.soft2 = kind == 2, b.R2 = kind == 1 ? ratio * Rs : kind == 2 ? Rs : 0.0;
  ContactGeometry<double> g{};
  g.h = dn * Rs, g.body1 = cap_volume(dn), g.body2 = kind == 2 ? cap_volume(dn) : 0.0;
  return SoftManyBodyNormal::evaluate(params, SoftManyBodyNormal::constants(params, b), g).Fn;
}

bool tabled(double strain) {  // a multiple of 0.05
  const double hundredths = std::round(strain * 100.0);
  return std::abs(strain * 100.0 - hundredths) < 1e-6 && static_cast<long>(hundredths) % 5 == 0;
}

}  // namespace

void write_kinematics_report(const ManyBodyProbe& plan, const std::string& plan_path, const SoftParticleLaws& laws, const std::string& laws_source,
                             const std::string& census_rows, const std::string& in_place_dir, const std::string& out_dir) {
  if (!laws.many_body || !laws.soft_solid || !laws.soft_soft)
    throw InputError(fmt::format("{}: no many_body or a scene missing; the comparison needs both scenes and many_body", laws_source));
  std::map<std::uint64_t, std::pair<std::size_t, double>> media;  // seed -> its sites, Rs
  std::vector<Press> soft, resolved;
  {
    std::ifstream in(census_rows);
    if (!in) throw InputError(fmt::format("{}: cannot read it (make many-body-kinematics writes it with softpack-coarse soft-contacts)", census_rows));
    int line_no = 0;
    for (std::string line; std::getline(in, line);) {
      ++line_no;
      std::uint64_t seed = 0;
      std::size_t n = 0;
      double Rs = 0.0;
      std::string word;
      if (std::istringstream head(line); line.rfind("# seed ", 0) == 0 && head >> word >> word >> seed >> word >> n >> word >> word >> Rs) media[seed] = {n, Rs};
      if (line.empty() || line[0] == '#') continue;
      std::istringstream r(line);
      Press p;
      std::size_t site = 0, count = 0;
      if (!(r >> seed >> p.strain >> site >> p.kind >> p.dn >> p.ratio >> count >> p.F) || !media.count(seed) || p.kind < 0 || p.kind > 2)
        throw InputError(fmt::format("{}:{}: expected 'seed strain soft_particle kind dn r_over_Rs count Fn' after its seed's '# seed S: N soft-particles, Rs R m'",
                                     census_rows, line_no));
      p.law = p.F;
      if (tabled(p.strain)) p.alone = alone(laws, media[seed].second, p.kind, p.dn, p.ratio), soft.push_back(p);
    }
  }
  std::map<double, std::size_t> sites_at;  // sites over the seeds at each tabled strain
  for (const std::uint64_t seed : plan.v3_media_seeds) {
    if (!media.count(seed)) throw InputError(fmt::format("{}: no seed {} (rerun make many-body-kinematics)", census_rows, seed));
    const std::string path = fmt::format("{}/seed-{}.dat", in_place_dir, seed);
    std::ifstream in(path);
    if (!in) throw InputError(fmt::format("{}: cannot read it (make many-body-in-place writes it)", path));
    int line_no = 0;
    std::map<double, bool> seen;
    for (std::string line; std::getline(in, line);) {
      ++line_no;
      if (line.empty() || line[0] == '#') continue;
      std::istringstream r(line);
      Press p;
      std::size_t site = 0, count = 0;
      double pairwise = 0.0;
      if (!(r >> p.strain >> site >> p.kind >> p.dn >> p.ratio >> count >> p.F >> p.law >> pairwise) || p.kind < 0 || p.kind > 2)
        throw InputError(fmt::format("{}:{}: expected 'strain site kind dn r_over_Rs count F_measured F_law F_pairwise'", path, line_no));
      if (!tabled(p.strain)) continue;
      p.alone = alone(laws, media[seed].second, p.kind, p.dn, p.ratio);
      resolved.push_back(p), seen[std::round(p.strain * 100.0) / 100.0] = true;
    }
    for (const auto& [strain, _] : seen) sites_at[strain] += media[seed].first;
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
      "The third version's media (seeds {} of `{}`; paper/many-body.md, \"Next: the soft medium's geometry against the resolved "
      "one's\"), laws of `{}`. Soft: every closed contact of a soft-particle in the soft runs (`{}`); resolved: every body whose "
      "sphere intrudes a site's (`{}/seed-S.dat`). Per soft-particle: over the sites of all seeds. Push: soft, its law's force; "
      "resolved, measured (and the law's from the same geometry). Confinement: Fn over the law alone at the same Δn (the "
      "soft-particle's other caps removed), median over the contacts where the law alone is not 0 (resolved: the law's Fn); "
      "below the onset: the share of contacts where it is 0.\n\n"
      "| strain | body | bodies per soft-particle soft / resolved | Δn median soft / resolved | Δn 90 % soft / resolved | push per "
      "soft-particle [N] soft / resolved / law on resolved | confinement soft / resolved | below the onset soft / resolved |\n"
      "|---|---|---|---|---|---|---|---|\n",
      code_version(), fmt::join(plan.v3_media_seeds, ", "), plan_path, laws_source, census_rows, in_place_dir);
  for (const auto& [strain, by_kind] : groups) {
    const double sites = static_cast<double>(sites_at[strain]);
    if (!(sites > 0.0)) continue;
    for (const auto& [kind, g] : by_kind) {
      const auto& [a, b] = g;
      const auto share = [](const Group& x) { return x.presses ? static_cast<double>(x.below) / static_cast<double>(x.presses) : 0.0; };
      md += fmt::format("| {:.2f} | {} | {:.2f} / {:.2f} | {:.3f} / {:.3f} | {:.3f} / {:.3f} | {:.3g} / {:.3g} / {:.3g} | {:.2f} / {:.2f} | {:.2f} / {:.2f} |\n", strain,
                        kinds[kind], static_cast<double>(a.presses) / sites, static_cast<double>(b.presses) / sites, rank_quantile(a.dn, 0.5),
                        rank_quantile(b.dn, 0.5), rank_quantile(a.dn, 0.9), rank_quantile(b.dn, 0.9), a.F / sites, b.F / sites, b.law / sites,
                        rank_quantile(a.confinement, 0.5), rank_quantile(b.confinement, 0.5), share(a), share(b));
    }
  }
  write_file_atomically(out_dir + "/kinematics.md", md);
}

}  // namespace softpack
