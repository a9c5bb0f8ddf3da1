#include "measure/point_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "io/file_kind.hpp"
#include "io/hdf5_file.hpp"

namespace softpack {
namespace {

std::vector<double> flatten(const std::vector<Vec3>& v) {
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const Vec3& x : v) out.insert(out.end(), {x.x(), x.y(), x.z()});
  return out;
}

void write_vec3s(h5::File& f, const std::string& name, const std::vector<Vec3>& v) { f.write(name, flatten(v), {v.size(), 3}); }

// Every number read back must be finite: a checkpoint's state is restored into a simulation.
void check_finite(const h5::File& f, const std::string& name, const std::vector<double>& v) {
  for (std::size_t k = 0; k < v.size(); ++k)
    if (!std::isfinite(v[k]))
      throw InputError(fmt::format("{}: /{}: value {} is {}; allowed: finite numbers", f.path(), name, k, v[k]));
}

double read_finite(const h5::File& f, const std::string& name) {
  const double v = f.read_scalar_double(name);
  check_finite(f, name, {v});
  return v;
}

long read_count(const h5::File& f, const std::string& name) {
  const std::int64_t v = f.read_scalar_int64(name);
  if (v < 0) throw InputError(fmt::format("{}: /{}: {} is not allowed; allowed: >= 0", f.path(), name, v));
  return static_cast<long>(v);
}

std::vector<Vec3> read_vec3s(const h5::File& f, const std::string& name) {
  std::vector<std::size_t> dims;
  const auto v = f.read_doubles(name, &dims);
  if (dims.size() != 2 || dims[1] != 3)
    throw InputError(fmt::format("{}: /{}: expected shape (N, 3), found ({})", f.path(), name, fmt::join(dims, ", ")));
  check_finite(f, name, v);
  std::vector<Vec3> out;
  out.reserve(dims[0]);
  for (std::size_t k = 0; k < dims[0]; ++k) out.emplace_back(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
  return out;
}

// Sphere ids of springs: 0 <= id < the number of spheres of the state.
std::vector<int> read_ids(const h5::File& f, const std::string& name, std::size_t spheres) {
  const auto v = f.read_int64s(name);
  std::vector<int> out;
  out.reserve(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (v[k] < 0 || static_cast<std::uint64_t>(v[k]) >= spheres)
      throw InputError(fmt::format("{}: /{}: value {} = {} is not a sphere of the state (0 to {})", f.path(), name, k, v[k],
                                   spheres == 0 ? std::string("none") : std::to_string(spheres - 1)));
    out.push_back(static_cast<int>(v[k]));
  }
  return out;
}

void same_length(const h5::File& f, const std::string& name, std::size_t n, const std::string& ref, std::size_t n_ref) {
  if (n != n_ref)
    throw InputError(fmt::format("{}: /{} has {} entries but /{} has {}; allowed: the same number", f.path(), name, n, ref, n_ref));
}

void write_vec3(h5::File& f, const std::string& name, const Vec3& v) { f.write(name, std::vector<double>{v.x(), v.y(), v.z()}); }
Vec3 read_vec3(const h5::File& f, const std::string& name) {
  const auto v = f.read_doubles(name);
  if (v.size() != 3) throw InputError(fmt::format("{}: /{}: expected 3 values, found {}", f.path(), name, v.size()));
  check_finite(f, name, v);
  return Vec3(v[0], v[1], v[2]);
}

void write_wall_springs(h5::File& f, const std::string& group, const std::vector<std::vector<SimulationState::WallSpring>>& walls) {
  for (std::size_t w = 0; w < walls.size(); ++w) {
    std::vector<std::int64_t> ids;
    std::vector<Vec3> xi;
    for (const auto& s : walls[w]) ids.push_back(s.i), xi.push_back(s.xi);
    f.write(fmt::format("{}/{}/i", group, w), ids);
    write_vec3s(f, fmt::format("{}/{}/xi", group, w), xi);
  }
}

std::vector<std::vector<SimulationState::WallSpring>> read_wall_springs(const h5::File& f, const std::string& group,
                                                                      std::size_t spheres) {
  std::vector<std::vector<SimulationState::WallSpring>> out;
  for (std::size_t w = 0; f.exists(fmt::format("{}/{}/i", group, w)); ++w) {
    const std::string i_name = fmt::format("{}/{}/i", group, w), xi_name = fmt::format("{}/{}/xi", group, w);
    const auto ids = read_ids(f, i_name, spheres);
    const auto xi = read_vec3s(f, xi_name);
    same_length(f, xi_name, xi.size(), i_name, ids.size());
    out.emplace_back();
    for (std::size_t k = 0; k < ids.size(); ++k) out.back().push_back({ids[k], xi[k]});
  }
  return out;
}

void write_result(h5::File& f, const std::string& g, const PointResult& r) {
  f.write_scalar(g + "/delta_n", r.delta_n);
  f.write_scalar(g + "/hn", r.hn);
  f.write_scalar(g + "/alpha_deg", r.alpha_deg);
  f.write_scalar(g + "/ht", r.ht);
  write_vec3(f, g + "/force", r.force);
  write_vec3(f, g + "/force_first", r.force_first);
  write_vec3(f, g + "/force_between", r.force_between);
  f.write_scalar(g + "/contacts", static_cast<std::int64_t>(r.contacts));
  f.write_scalar(g + "/relax_steps", static_cast<std::int64_t>(r.relax_steps));
  f.write_scalar(g + "/relax_time", r.relax_time);
  f.write_scalar(g + "/steps", static_cast<std::int64_t>(r.steps));
  f.write_scalar(g + "/seconds", r.seconds);
  std::vector<double> t, fr, er, ke, ee, mu, mc, nc;
  for (const auto& c : r.checks) {
    t.push_back(c.time), fr.push_back(c.residuals.force_ratio()), er.push_back(c.residuals.energy_ratio());
    ke.push_back(c.residuals.kinetic_energy), ee.push_back(c.residuals.elastic_energy);
    mu.push_back(c.residuals.max_unbalanced_force), mc.push_back(c.residuals.mean_contact_force);
    nc.push_back(static_cast<double>(c.residuals.contacts));
  }
  f.write(g + "/checks/time", t);
  f.write(g + "/checks/force_ratio", fr);
  f.write(g + "/checks/energy_ratio", er);
  f.write(g + "/checks/kinetic_energy", ke);
  f.write(g + "/checks/elastic_energy", ee);
  f.write(g + "/checks/max_unbalanced_force", mu);
  f.write(g + "/checks/mean_contact_force", mc);
  f.write(g + "/checks/contacts", nc);
}

PointResult read_result(const h5::File& f, const std::string& g) {
  PointResult r;
  r.delta_n = read_finite(f, g + "/delta_n");
  r.hn = read_finite(f, g + "/hn");
  r.alpha_deg = read_finite(f, g + "/alpha_deg");
  r.ht = read_finite(f, g + "/ht");
  r.force = read_vec3(f, g + "/force");
  r.force_first = read_vec3(f, g + "/force_first");
  r.force_between = read_vec3(f, g + "/force_between");
  r.contacts = read_count(f, g + "/contacts");
  r.relax_steps = read_count(f, g + "/relax_steps");
  r.relax_time = read_finite(f, g + "/relax_time");
  r.steps = read_count(f, g + "/steps");
  r.seconds = f.read_scalar_double(g + "/seconds");
  const std::string c = g + "/checks/";
  const auto t = f.read_doubles(c + "time"), ke = f.read_doubles(c + "kinetic_energy"), ee = f.read_doubles(c + "elastic_energy"),
             mu = f.read_doubles(c + "max_unbalanced_force"), mc = f.read_doubles(c + "mean_contact_force"),
             nc = f.read_doubles(c + "contacts");
  same_length(f, c + "kinetic_energy", ke.size(), c + "time", t.size());
  same_length(f, c + "elastic_energy", ee.size(), c + "time", t.size());
  same_length(f, c + "max_unbalanced_force", mu.size(), c + "time", t.size());
  same_length(f, c + "mean_contact_force", mc.size(), c + "time", t.size());
  same_length(f, c + "contacts", nc.size(), c + "time", t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!(nc[k] >= 0.0 && nc[k] <= 9007199254740992.0 && nc[k] == std::floor(nc[k])))
      throw InputError(fmt::format("{}: /{}contacts: value {} = {} is not allowed; allowed: a count of contacts", f.path(), c, k,
                                   nc[k]));
    RelaxationCheck check;
    check.time = t[k];
    check.residuals.kinetic_energy = ke[k];
    check.residuals.elastic_energy = ee[k];
    check.residuals.max_unbalanced_force = mu[k];
    check.residuals.mean_contact_force = mc[k];
    check.residuals.contacts = static_cast<std::size_t>(nc[k]);
    r.checks.push_back(check);
  }
  return r;
}

void write_provenance(h5::File& f, const PointProvenance& p) {
  f.write_string("provenance/stage", p.stage);
  f.write_string("provenance/scene", p.scene);
  f.write_string("provenance/config", p.config);
  f.write_string("provenance/code_version", p.code_version);
}

}  // namespace

void write_point_file(const std::string& path, const PointResult& r, const SimulationState& s, const PointProvenance& prov) {
  h5::AtomicH5 out(path);
  h5::File& f = out.file();
  write_result(f, "result", r);
  f.write_scalar("state/time", s.time);
  f.write_scalar("state/steps", static_cast<std::int64_t>(s.steps));
  write_vec3s(f, "state/x", s.x);
  write_vec3s(f, "state/v", s.v);
  write_vec3s(f, "state/w", s.w);
  write_vec3s(f, "state/F", s.F);
  write_vec3s(f, "state/T", s.T);
  write_vec3s(f, "state/plane_points", s.plane_points);
  write_vec3s(f, "state/shell_centres", s.shell_centres);
  std::vector<std::int64_t> pi, pj;
  std::vector<Vec3> pxi;
  for (const auto& sp : s.pair_springs) pi.push_back(sp.i), pj.push_back(sp.j), pxi.push_back(sp.xi);
  f.write("state/pair_springs/i", pi);
  f.write("state/pair_springs/j", pj);
  write_vec3s(f, "state/pair_springs/xi", pxi);
  write_wall_springs(f, "state/plane_springs", s.plane_springs);
  write_wall_springs(f, "state/shell_springs", s.shell_springs);
  write_provenance(f, prov);
  out.commit();
}

PointFile read_point_file(const std::string& path, bool with_state) {
  const h5::File f = h5::File::open(path);
  if (!f.exists("result") || !f.exists("provenance/stage")) {
    const std::string kind = h5::kind_of(f);
    throw InputError(fmt::format("{}: not a softpack sweep point file ({})", path,
                                 kind.empty() ? "no /result or /provenance/stage" : "it is " + kind));
  }
  PointFile p;
  p.provenance.stage = f.read_string("provenance/stage");
  if (p.provenance.stage != "normal" && p.provenance.stage != "tangential")
    throw InputError(fmt::format("{}: /provenance/stage: '{}' is not allowed; allowed: normal, tangential", path, p.provenance.stage));
  p.provenance.scene = f.read_string("provenance/scene");
  p.provenance.config = f.read_string("provenance/config");
  p.provenance.code_version = f.read_string("provenance/code_version");
  p.result = read_result(f, "result");
  if (with_state) {
    SimulationState& s = p.state;
    s.time = read_finite(f, "state/time");
    s.steps = read_count(f, "state/steps");
    s.x = read_vec3s(f, "state/x");
    s.v = read_vec3s(f, "state/v");
    s.w = read_vec3s(f, "state/w");
    s.F = read_vec3s(f, "state/F");
    s.T = read_vec3s(f, "state/T");
    s.plane_points = read_vec3s(f, "state/plane_points");
    s.shell_centres = read_vec3s(f, "state/shell_centres");
    const std::size_t n = s.x.size();
    same_length(f, "state/v", s.v.size(), "state/x", n);
    same_length(f, "state/F", s.F.size(), "state/x", n);
    const auto pi = read_ids(f, "state/pair_springs/i", n), pj = read_ids(f, "state/pair_springs/j", n);
    const auto pxi = read_vec3s(f, "state/pair_springs/xi");
    same_length(f, "state/pair_springs/j", pj.size(), "state/pair_springs/i", pi.size());
    same_length(f, "state/pair_springs/xi", pxi.size(), "state/pair_springs/i", pi.size());
    for (std::size_t k = 0; k < pi.size(); ++k) s.pair_springs.push_back({pi[k], pj[k], pxi[k]});
    s.plane_springs = read_wall_springs(f, "state/plane_springs", n);
    s.shell_springs = read_wall_springs(f, "state/shell_springs", n);
  }
  return p;
}

void write_sweep_file(const std::string& path, const std::vector<PointResult>& points, const PointProvenance& prov,
                      const std::string& packings, std::uint64_t seed, double seconds) {
  h5::AtomicH5 out(path);
  h5::File& f = out.file();
  const std::size_t n = points.size();
  std::vector<double> dn, hn, al, ht, Fn, Ft1, Ft2, sec, rt, fr, er;
  std::vector<Vec3> F, F1, Fb;
  std::vector<std::int64_t> contacts, steps, rsteps;
  std::vector<std::int64_t> check_point;
  std::vector<double> check_time, check_fr, check_er;
  for (std::size_t k = 0; k < n; ++k) {
    const PointResult& r = points[k];
    dn.push_back(r.delta_n), hn.push_back(r.hn), al.push_back(r.alpha_deg), ht.push_back(r.ht);
    Fn.push_back(r.force.x()), Ft1.push_back(r.force.y()), Ft2.push_back(r.force.z());
    F.push_back(r.force), F1.push_back(r.force_first), Fb.push_back(r.force_between);
    contacts.push_back(r.contacts), steps.push_back(r.steps), rsteps.push_back(r.relax_steps);
    sec.push_back(r.seconds), rt.push_back(r.relax_time);
    fr.push_back(r.checks.empty() ? 0.0 : r.checks.back().residuals.force_ratio());
    er.push_back(r.checks.empty() ? 0.0 : r.checks.back().residuals.energy_ratio());
    for (const auto& c : r.checks) {
      check_point.push_back(static_cast<std::int64_t>(k));
      check_time.push_back(c.time), check_fr.push_back(c.residuals.force_ratio()), check_er.push_back(c.residuals.energy_ratio());
    }
  }
  f.write("delta_n", dn);
  f.write("hn", hn);
  f.write("alpha_deg", al);
  f.write("ht", ht);
  f.write("Fn", Fn);
  f.write("Ft_parallel", Ft1);
  f.write("Ft_perpendicular", Ft2);
  write_vec3s(f, "force", F);
  write_vec3s(f, "force_first", F1);
  write_vec3s(f, "force_between", Fb);
  f.write("contacts", contacts);
  f.write("steps", steps);
  f.write("relaxation/steps", rsteps);
  f.write("relaxation/time", rt);
  f.write("relaxation/final_force_ratio", fr);
  f.write("relaxation/final_energy_ratio", er);
  f.write("relaxation/checks/point", check_point);
  f.write("relaxation/checks/time", check_time);
  f.write("relaxation/checks/force_ratio", check_fr);
  f.write("relaxation/checks/energy_ratio", check_er);
  f.write("seconds", sec);
  for (const char* name : {"Fn", "Ft_parallel", "Ft_perpendicular", "force", "force_first", "force_between"})
    f.set_attribute(name, "unit", std::string("N"));
  f.set_attribute("hn", "unit", std::string("m"));
  f.set_attribute("ht", "unit", std::string("m"));
  f.set_attribute("seconds", "description", std::string("wall-clock time of each point"));
  write_provenance(f, prov);
  f.write_string("provenance/packings", packings);
  f.write_scalar("provenance/seed", static_cast<std::int64_t>(seed));
  f.write_scalar("provenance/seconds", seconds);
  out.commit();
}

}  // namespace softpack
