#include "coarse/soft_census.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "coarse/medium_file.hpp"
#include "analysis/seed_statistics.hpp"
#include "contact/soft_particle_law.hpp"
#include "core/error.hpp"
#include "core/version.hpp"
#include "forces/contact_walk.hpp"
#include "formats/law_file.hpp"
#include "io/atomic_file.hpp"

namespace softpack {

std::vector<SoftSide> soft_sides(const Simulation& sim, const Medium& m) {
  const Particles& p = sim.particles();
  const std::size_t grains = m.grain_x.size();
  std::vector<SoftSide> sides;
  for_each_closed_contact(sim.world(), sim.contact_lists(), sim.force_field(), [&](const ClosedContact& c) {
    if (c.kind == ClosedContact::Kind::shell) return;
    const double dn = c.h / c.overlap_scale(p), Fn = c.Fn();
    const auto add = [&](int s, int other) {
      if (s < static_cast<int>(grains)) return;
      if (static_cast<std::size_t>(s) - grains >= m.sites.size())
        throw InputError("soft_census: the scene holds more spheres than the medium's grains and sites (not its soft model's scene)");
      const int partner = other < 0 ? 0 : other < static_cast<int>(grains) ? 1 : 2;
      const double ratio = partner == 1 ? p.r[static_cast<std::size_t>(other)] / m.Rs : 0.0;
      sides.push_back({static_cast<std::size_t>(s) - grains, partner, dn, Fn, ratio});
    };
    add(c.i, c.j);
    if (c.j >= 0) add(c.j, c.i);
  });
  return sides;
}

SoftCensus soft_census(const Simulation& sim, const Medium& m, const CurveRow& row, double dn_max, double E_max) {
  return soft_census(soft_sides(sim, m), m, row, dn_max, E_max);
}

SoftCensus soft_census(const std::vector<SoftSide>& sides, const Medium& m, const CurveRow& row, double dn_max, double E_max) {
  SoftCensus out;
  out.strain = row.strain, out.phase = row.phase, out.soft_particles = m.sites.size(), out.contacts = sides.size();
  std::vector<double> E(m.sites.size(), 0.0), n(m.sites.size(), 0.0), dn, ratios;
  for (const SoftSide& s : sides) E[s.soft] += cap_volume(s.dn), n[s.soft] += 1.0;
  double ratio_force = 0.0, grain_force = 0.0;
  for (const SoftSide& s : sides) {
    (s.partner == 0 ? out.wall : s.partner == 1 ? out.grain : out.soft) += 1;
    (s.partner == 0 ? out.force_wall : s.partner == 1 ? out.force_grain : out.force_soft) += s.Fn;
    dn.push_back(s.dn);
    out.beyond_dn += s.dn > dn_max ? 1.0 : 0.0;
    out.beyond_n += n[s.soft] > 6.0 ? 1.0 : 0.0;
    out.beyond_E += E[s.soft] > E_max ? 1.0 : 0.0;
    if (s.partner == 1) ratios.push_back(s.ratio), ratio_force += s.ratio * s.Fn, grain_force += s.Fn;
  }
  if (!sides.empty()) {
    const double k = static_cast<double>(sides.size());
    out.beyond_dn /= k, out.beyond_n /= k, out.beyond_E /= k;
  }
  out.dn_median = rank_quantile(dn, 0.5), out.dn_p90 = rank_quantile(dn, 0.9), out.dn_max = rank_quantile(dn, 1.0);
  out.n_mean = m.sites.empty() ? 0.0 : static_cast<double>(sides.size()) / static_cast<double>(m.sites.size());
  out.grain_ratio_median = rank_quantile(ratios, 0.5);
  out.grain_ratio_force = grain_force > 0.0 ? ratio_force / grain_force : 0.0;
  return out;
}

void write_soft_census(const ManyBodyProbe& plan, const std::string& plan_path, const std::string& config, const std::string& media_dir,
                       const std::string& out_dir, int version) {
  const CoarseGrainSettings s = read_coarse_grain_settings(config);
  const SoftParticleLaws laws = read_soft_particle_laws("coarse_grain.soft_particle", s.laws, s.many_body);
  const double dn_max = plan.delta_n.back(), E_max = 6.0 * cap_volume(dn_max);
  std::string dat = fmt::format(
      "# soft-particle contacts in the media (softpack-coarse soft-contacts, {}): {} with the laws {}; probe range: dn <= {}, "
      "n <= 6, E <= {:.6g} ({})\n"
      "# seed strain phase soft_particles contacts wall grain soft F_wall F_grain F_soft dn_median dn_p90 dn_max beyond_dn beyond_n "
      "beyond_E n_mean grain_r_over_Rs_median grain_r_over_Rs_force\n",
      code_version(), config, s.laws, dn_max, E_max, plan_path);
  struct End {
    std::uint64_t seed;
    SoftCensus c, worst;  ///< the end of loading; each fraction's largest over the rows
  };
  std::vector<End> ends;
  std::string rows = fmt::format("# soft-particle contacts at the loading rows from strain {} to {} (softpack-coarse soft-contacts, {}): {} with the laws {}\n"
                                 "# seed strain soft_particle kind(0 wall, 1 grain, 2 soft) dn r_over_Rs count Fn[N]\n",
                                 plan.strain_lo, plan.strain_hi, code_version(), config, s.laws);
  for (const std::uint64_t seed : plan.media_seeds_of(version)) {
    const std::string path = fmt::format("{}/seed-{}.h5", media_dir, seed);
    const MediumFile mf = read_medium_file(path);
    if (mf.settings != s.medium_text) throw InputError(fmt::format("{}: made with other settings than {}", path, config));
    const Medium& m = mf.medium;
    End end{seed, {}, {}};
    rows += fmt::format("# seed {}: {} soft-particles, Rs {:.9g} m\n", seed, m.sites.size(), m.Rs);
    run_compression(medium_scene(s, m, CoarseModel::soft, laws), m, CoarseModel::soft, s, {}, [&](const Simulation& sim, const CurveRow& row) {
      const std::vector<SoftSide> sides = soft_sides(sim, m);
      const SoftCensus c = soft_census(sides, m, row, dn_max, E_max);
      dat += fmt::format("{} {:.4f} {} {} {} {} {} {} {:.6e} {:.6e} {:.6e} {:.5f} {:.5f} {:.5f} {:.5f} {:.5f} {:.5f} {:.4f} {:.4f} {:.4f}\n", seed,
                         c.strain, c.phase, c.soft_particles, c.contacts, c.wall, c.grain, c.soft, c.force_wall, c.force_grain, c.force_soft,
                         c.dn_median, c.dn_p90, c.dn_max, c.beyond_dn, c.beyond_n, c.beyond_E, c.n_mean, c.grain_ratio_median,
                         c.grain_ratio_force);
      if (row.phase == 1) end.c = c;
      if (row.phase == 1 && row.strain >= plan.strain_lo - 1e-9 && row.strain <= plan.strain_hi + 1e-9) {
        std::vector<std::size_t> count(m.sites.size(), 0);
        for (const SoftSide& x : sides) ++count[x.soft];
        for (const SoftSide& x : sides)
          rows += fmt::format("{} {:.4f} {} {} {:.6f} {:.4f} {} {:.6e}\n", seed, row.strain, x.soft, x.partner, x.dn, x.ratio, count[x.soft], x.Fn);
      }
      if (row.strain >= plan.strain_lo && row.phase != 2) {
        end.worst.beyond_dn = std::max(end.worst.beyond_dn, c.beyond_dn), end.worst.beyond_n = std::max(end.worst.beyond_n, c.beyond_n);
        end.worst.beyond_E = std::max(end.worst.beyond_E, c.beyond_E), end.worst.dn_max = std::max(end.worst.dn_max, c.dn_max);
      }
    });
    ends.push_back(end);
  }
  std::string md = fmt::format(
      "# Where the media use the soft-particle law (generated by softpack-coarse soft-contacts, {})\n\n"
      "The soft model of the validation media (`{}`, laws `{}`), every closed contact of a soft-particle (one between two "
      "soft-particles counted for each), against the many-body probe's range (`{}`): Δn ≤ {}, at most 6 contacts, E ≤ {:.4g} "
      "(the cube at Δn = {}). Every row: `contacts.dat`.\n\n"
      "## At the end of loading\n\n"
      "| seed | strain | soft-particles | contacts per soft-particle | wall / grain / soft contacts | Fn share wall / grain / soft | "
      "grain r/Rs median (Fn-weighted) | Δn median / 90 % / max | beyond Δn | beyond 6 contacts | beyond E |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n",
      code_version(), config, s.laws, plan_path, dn_max, E_max, dn_max);
  for (const End& e : ends) {
    const SoftCensus& c = e.c;
    const double F = c.force_wall + c.force_grain + c.force_soft;
    const auto share = [&](double f) { return F > 0.0 ? f / F : 0.0; };
    md += fmt::format("| {} | {:.3f} | {} | {:.2f} | {} / {} / {} | {:.2f} / {:.2f} / {:.2f} | {:.2f} ({:.2f}) | {:.3f} / {:.3f} / {:.3f} | {:.2f} | {:.2f} | {:.2f} |\n",
                      e.seed, c.strain, c.soft_particles, c.n_mean, c.wall, c.grain, c.soft, share(c.force_wall), share(c.force_grain),
                      share(c.force_soft), c.grain_ratio_median, c.grain_ratio_force, c.dn_median, c.dn_p90, c.dn_max, c.beyond_dn, c.beyond_n,
                      c.beyond_E);
  }
  md += fmt::format("\n## The largest over the loading and unloading rows from strain {}\n\n| seed | Δn max | beyond Δn | beyond 6 contacts | beyond E |\n|---|---|---|---|---|\n",
                    plan.strain_lo);
  for (const End& e : ends)
    md += fmt::format("| {} | {:.3f} | {:.2f} | {:.2f} | {:.2f} |\n", e.seed, e.worst.dn_max, e.worst.beyond_dn, e.worst.beyond_n, e.worst.beyond_E);
  std::filesystem::create_directories(out_dir);
  write_file_atomically(out_dir + "/contacts.dat", dat);
  write_file_atomically(out_dir + "/contacts.md", md);
  write_file_atomically(out_dir + "/contact-rows.dat", rows);
}

}  // namespace softpack
