#include "coarse/in_place.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "analysis/seed_statistics.hpp"
#include "coarse/medium_file.hpp"
#include "contact/soft_particle_law.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "forces/contact_walk.hpp"
#include "formats/law_file.hpp"
#include "io/atomic_file.hpp"

namespace softpack {
namespace {

// Bodies intruding a site: a wall w is -1 - w, a grain g is g, another site l is grains + l.
struct Intrusion {
  int body;
  Vec3 u;     // from the site's centre towards the body
  double dn;
  double measured = 0.0;
};

}  // namespace

ContactPartners site_partners(double Rs, int kind, double ratio) {
  ContactPartners b;
  b.kind = kind == 0 ? ContactPartners::Kind::plane : ContactPartners::Kind::pair;
  b.R1 = Rs, b.soft1 = true, b.soft2 = kind == 2;
  b.R2 = kind == 1 ? ratio * Rs : kind == 2 ? Rs : 0.0;
  return b;
}

bool tabled_strain(double strain) {
  const double hundredths = std::round(strain * 100.0);
  return std::abs(strain * 100.0 - hundredths) < 1e-6 && static_cast<long>(hundredths) % 5 == 0;
}

std::vector<InPlaceContact> read_in_place_rows(const std::string& path, std::string* laws) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot read it (make many-body-in-place writes it)", path));
  std::vector<InPlaceContact> rows;
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (line_no == 1 && laws) *laws = line.find(", laws ") != std::string::npos ? line.substr(line.find(", laws ") + 7) : "";
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    InPlaceContact c;
    if (!(s >> c.strain >> c.site >> c.kind >> c.dn >> c.ratio >> c.count >> c.measured >> c.law >> c.pairwise) || c.kind < 0 || c.kind > 2)
      throw InputError(fmt::format("{}:{}: expected 'strain site kind(0-2) dn r_over_Rs count F_measured F_law F_pairwise'", path, line_no));
    rows.push_back(c);
  }
  return rows;
}

std::vector<InPlaceContact> in_place_contacts(const Simulation& sim, const Medium& m, const SoftParticleLaws& laws, double strain) {
  const Particles& p = sim.particles();
  const World& w = sim.world();
  const std::size_t grains = m.grain_x.size(), sites = m.sites.size();
  if (w.shells.size() != sites) throw InputError("in_place_contacts: the scene is not the medium's resolved scene (one shell per site)");
  const double Rs = m.Rs;
  std::vector<std::vector<Intrusion>> by_site(sites);
  for (std::size_t k = 0; k < sites; ++k) {
    const Vec3& c = w.shells[k].centre;
    for (std::size_t g = 0; g < grains; ++g) {
      const Vec3 d = p.x[g] - c;
      const double dn = (Rs + p.r[g] - d.norm()) / Rs;
      if (dn > 0.0) by_site[k].push_back({static_cast<int>(g), d.normalized(), dn});
    }
    for (std::size_t l = 0; l < sites; ++l) {
      const Vec3 d = w.shells[l].centre - c;
      const double dn = (2.0 * Rs - d.norm()) / Rs;
      if (l != k && dn > 0.0) by_site[k].push_back({static_cast<int>(grains + l), d.normalized(), dn});
    }
    for (std::size_t q = 0; q < w.planes.size(); ++q) {
      const double dn = (Rs - w.planes[q].distance(c)) / Rs;
      if (dn > 0.0) by_site[k].push_back({-1 - static_cast<int>(q), -w.planes[q].normal, dn});
    }
  }
  // The measured pushes: each contact of a site's fines with another body's sphere or a wall.
  const std::vector<int> body = sphere_bodies(m, CoarseModel::resolved);
  const auto add = [&](int b, int partner, const Vec3& F) {
    if (b < static_cast<int>(grains) || b == partner) return;
    for (Intrusion& in : by_site[static_cast<std::size_t>(b) - grains])
      if (in.body == partner) return void(in.measured -= F.dot(in.u));
    // a fine touching a body whose sphere does not reach the site's: its push is not the law's
  };
  for_each_closed_contact(w, sim.contact_lists(), sim.force_field(), [&](const ClosedContact& cc) {
    if (cc.kind == ClosedContact::Kind::shell) return;  // the fines and their own shell
    const auto i = static_cast<std::size_t>(cc.i);
    if (cc.kind == ClosedContact::Kind::plane) return add(body[i], -1 - cc.wall, cc.Fn() * w.planes[static_cast<std::size_t>(cc.wall)].normal);
    const auto j = static_cast<std::size_t>(cc.j);
    const Vec3 n = (p.x[i] - p.x[j]).normalized();  // the force on i is along it
    add(body[i], body[j], cc.Fn() * n);
    add(body[j], body[i], -cc.Fn() * n);
  });
  // The law's prediction from the same geometry: the engine's soft-particle model, its body
  // states made as the per-body pass makes them (contact/soft_particle_law.hpp).
  const SoftNormal::Params params{&laws, GrainContactRule::wall, false};
  std::vector<double> E(sites, 0.0);
  for (std::size_t k = 0; k < sites; ++k) {
    std::vector<Vec3> u;
    std::vector<double> d;
    for (const Intrusion& in : by_site[k]) u.push_back(in.u), d.push_back(in.dn), E[k] += cap_volume(in.dn);
    if (SoftManyBodyNormal::body_caps(params) && u.size() >= 2) E[k] = SoftManyBodyNormal::body_state(u, d);
  }
  std::vector<InPlaceContact> out;
  for (std::size_t k = 0; k < sites; ++k)
    for (const Intrusion& in : by_site[k]) {
      InPlaceContact c{strain, k, in.body < 0 ? 0 : in.body < static_cast<int>(grains) ? 1 : 2, in.dn, 0.0, by_site[k].size(), in.measured, 0.0, 0.0};
      if (c.kind == 1) c.ratio = p.r[static_cast<std::size_t>(in.body)] / Rs;
      const SoftManyBodyNormal::Constants<double> constants = SoftManyBodyNormal::constants(params, site_partners(Rs, c.kind, c.ratio));
      ContactGeometry<double> g{};
      g.h = in.dn * Rs, g.body1 = E[k], g.body2 = c.kind == 2 ? E[static_cast<std::size_t>(in.body) - grains] : 0.0;
      c.law = SoftManyBodyNormal::evaluate(params, constants, g).Fn;
      c.pairwise = SoftNormal::evaluate(params, constants, g).Fn;  // Eq. 7 at Δn, a grain as a wall
      out.push_back(c);
    }
  return out;
}

void write_in_place_seed(const ManyBodyProbe& plan, const std::string& config, const std::string& media_dir, std::uint64_t seed,
                         const std::string& out_dir, const std::function<void(double, double, const CurveRow&)>& progress) {
  const CoarseGrainSettings s = read_coarse_grain_settings(config);
  const SoftParticleLaws laws = read_soft_particle_laws("coarse_grain.soft_particle", s.laws, s.many_body);
  if (!laws.many_body || !laws.soft_solid || !laws.soft_soft)
    throw InputError(fmt::format("{}: the law file {}{} has no many_body or lacks a scene; the law in place needs both scenes and many_body",
                                 config, s.laws, s.many_body.empty() ? "" : fmt::format(" (many-body law: {})", s.many_body)));
  const std::string path = fmt::format("{}/seed-{}.h5", media_dir, seed);
  const MediumFile mf = read_medium_file(path);
  if (mf.settings != s.medium_text) throw InputError(fmt::format("{}: made with other settings than {}", path, config));
  const Medium& m = mf.medium;
  std::string dat = fmt::format(
      "# the law in place (softpack-coarse in-place, {}): resolved medium {} with the settings {}{}, laws {}\n"
      "# strain site kind(0 wall, 1 grain, 2 site) dn r_over_Rs count F_measured[N] F_law[N] F_pairwise[N]\n",
      code_version(), path, config, s.many_body.empty() ? "" : fmt::format(" (many-body law of {})", s.many_body), s.laws);
  const Stopwatch clock;
  run_compression(medium_scene(s, m, CoarseModel::resolved, laws), m, CoarseModel::resolved, s, progress, [&](const Simulation& sim, const CurveRow& row) {
    if (row.phase != 1 || row.strain < plan.strain_lo - 1e-9 || row.strain > plan.strain_hi + 1e-9) return;
    for (const InPlaceContact& c : in_place_contacts(sim, m, laws, row.strain))
      dat += fmt::format("{:.4f} {} {} {:.6f} {:.4f} {} {:.6e} {:.6e} {:.6e}\n", c.strain, c.site, c.kind, c.dn, c.ratio, c.count, c.measured, c.law, c.pairwise);
  });
  dat += fmt::format("# {:.1f} CPU-s\n", clock.elapsed().cpu);
  std::filesystem::create_directories(out_dir);
  write_file_atomically(fmt::format("{}/seed-{}.dat", out_dir, seed), dat);
}

namespace {

struct Sums {
  std::size_t n = 0, loaded = 0;
  double measured = 0.0, law = 0.0, pairwise = 0.0, below_onset = 0.0;  // below_onset: measured where Eq. 7 is 0
  double law_log = 0.0, law_log2 = 0.0, pair_log = 0.0, pair_log2 = 0.0;  // over the loaded ones
  std::vector<double> dn;
  void add(const InPlaceContact& c, double floor) {
    dn.push_back(c.dn);
    ++n, measured += c.measured, law += c.law, pairwise += c.pairwise, below_onset += c.pairwise > 0.0 ? 0.0 : c.measured;
    if (!(c.measured > floor)) return;
    ++loaded;
    const double a = std::log(std::max(c.law, floor) / c.measured), b = std::log(std::max(c.pairwise, floor) / c.measured);
    law_log += a, law_log2 += a * a, pair_log += b, pair_log2 += b * b;
  }
  std::string row() const {
    const double k = static_cast<double>(loaded);
    const auto e = [&](double s1, double s2) { return loaded ? fmt::format("{:.2f} ({:+.2f})", std::exp(std::sqrt(s2 / k)), s1 / k) : std::string("–"); };
    const auto ratio = [&](double x) { return measured > 0.0 ? x / measured : 0.0; };
    const auto q = [&](double f) { return rank_quantile(dn, f); };
    return fmt::format("{} | {} | {:.3f} / {:.3f} | {:.3g} | {:.2f} | {:.3f} | {:.3f} | {} | {} |", n, loaded, q(0.5), q(0.9), measured, ratio(below_onset),
                       ratio(law), ratio(pairwise), e(law_log, law_log2), e(pair_log, pair_log2));
  }
};

}  // namespace

void write_in_place_report(const ManyBodyProbe& plan, const std::string& plan_path, const std::string& out_dir, int version) {
  const std::vector<std::uint64_t>& seeds = plan.media_seeds_of(version);
  std::vector<InPlaceContact> all;
  std::string laws;
  for (const std::uint64_t seed : seeds) {
    const std::vector<InPlaceContact> rows = read_in_place_rows(fmt::format("{}/seed-{}.dat", out_dir, seed), &laws);
    all.insert(all.end(), rows.begin(), rows.end());
  }
  // The floor of the probe's errors: force_floor of the single contact's law at the plan's largest Δn.
  const SoftParticleLaws l = soft_particle_laws(read_law_file(laws.empty() ? plan.settings.laws : laws), laws);
  const double floor = plan.force_floor * l.soft_solid->normal(plan.delta_n.back());
  const char* kinds[] = {"wall", "grain", "site"};
  std::string md = fmt::format(
      "# The law in place (generated by softpack-coarse in-place-report, {})\n\n"
      "Resolved media seeds {} (`{}`, paper/many-body.md, \"Next: measuring the law in place\"), laws `{}`. Each body whose sphere "
      "intrudes a site's (Δn > 0): its push on the site's fines (measured) against the law file's many-body law and its pairwise laws "
      "from the same geometry. Sums over the seeds; law / measured and pairwise / measured are ratios of the sums; an error is as in "
      "probe.md, exp(rms ln(pred/meas)) (mean of the logarithm), over the contacts whose push exceeds the floor {:.3g} N (force_floor of "
      "the soft-solid law at Δn = {}). Every contact: `seed-S.dat`.\n\n"
      "The column \"below the onset\" is the share of the measured push made by contacts where Eq. 7 is 0 (Δn below the law's onset: "
      "the pairwise law gives nothing there, the many-body law only with the site's other caps).\n\n"
      "## At every fifth of the strain range's hundredths\n\n"
      "| strain | body | contacts | above the floor | Δn median / 90 % | Σ measured [N] | below the onset | law / measured | pairwise / measured | error of the law | "
      "error of pairwise |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
      code_version(), fmt::join(seeds, ", "), plan_path, laws, floor, plan.delta_n.back());
  std::map<double, std::map<int, Sums>> by_strain;
  std::map<int, Sums> by_kind, by_count;  // by_count: the site's intruding bodies, 1-3, 4-6, 7-9, 10 or more
  for (const InPlaceContact& c : all) {
    if (const double at = std::round(c.strain * 100.0) / 100.0; tabled_strain(c.strain))
      by_strain[at][c.kind].add(c, floor), by_strain[at][3].add(c, floor);
    by_kind[c.kind].add(c, floor), by_kind[3].add(c, floor);
    by_count[std::min<int>(3, static_cast<int>((c.count - 1) / 3))].add(c, floor);
  }
  for (const auto& [strain, kinds_at] : by_strain)
    for (const auto& [kind, sums] : kinds_at) md += fmt::format("| {:.2f} | {} | {}\n", strain, kind == 3 ? "all" : kinds[kind], sums.row());
  const std::string head = "| contacts | above the floor | Δn median / 90 % | Σ measured [N] | below the onset | law / measured | pairwise / measured | "
                           "error of the law | error of pairwise |\n|---|---|---|---|---|---|---|---|---|---|\n";
  md += fmt::format("\n## Every recorded loading strain from {} to {}, by body\n\n| body ", plan.strain_lo, plan.strain_hi) + head;
  for (const auto& [kind, sums] : by_kind) md += fmt::format("| {} | {}\n", kind == 3 ? "all" : kinds[kind], sums.row());
  md += "\n## The same, by the site's number of intruding bodies\n\n| bodies " + head;
  const char* bins[] = {"1-3", "4-6", "7-9", "10 or more"};
  for (const auto& [bin, sums] : by_count) md += fmt::format("| {} | {}\n", bins[bin], sums.row());
  write_file_atomically(out_dir + "/in-place.md", md);
}

}  // namespace softpack
