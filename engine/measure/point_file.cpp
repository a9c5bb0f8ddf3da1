#include "measure/point_file.hpp"

#include <fmt/format.h>

#include "io/hdf5_file.hpp"

namespace softpack {
namespace {

std::vector<double> flatten(const std::vector<Vec3>& v) {
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const Vec3& x : v) out.insert(out.end(), {x.x(), x.y(), x.z()});
  return out;
}

std::vector<Vec3> unflatten(const std::vector<double>& v) {
  std::vector<Vec3> out;
  for (std::size_t k = 0; k + 2 < v.size(); k += 3) out.emplace_back(v[k], v[k + 1], v[k + 2]);
  return out;
}

void write_vec3s(h5::File& f, const std::string& name, const std::vector<Vec3>& v) { f.write(name, flatten(v), {v.size(), 3}); }

std::vector<Vec3> read_vec3s(const h5::File& f, const std::string& name) {
  std::vector<std::size_t> dims;
  const auto v = f.read_doubles(name, &dims);
  return unflatten(v);
}

void write_vec3(h5::File& f, const std::string& name, const Vec3& v) { f.write(name, std::vector<double>{v.x(), v.y(), v.z()}); }
Vec3 read_vec3(const h5::File& f, const std::string& name) {
  const auto v = f.read_doubles(name);
  return v.size() == 3 ? Vec3(v[0], v[1], v[2]) : Vec3::Zero();
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

std::vector<std::vector<SimulationState::WallSpring>> read_wall_springs(const h5::File& f, const std::string& group) {
  std::vector<std::vector<SimulationState::WallSpring>> out;
  for (std::size_t w = 0; f.exists(fmt::format("{}/{}/i", group, w)); ++w) {
    const auto ids = f.read_int64s(fmt::format("{}/{}/i", group, w));
    const auto xi = read_vec3s(f, fmt::format("{}/{}/xi", group, w));
    out.emplace_back();
    for (std::size_t k = 0; k < ids.size() && k < xi.size(); ++k) out.back().push_back({static_cast<int>(ids[k]), xi[k]});
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
  r.delta_n = f.read_scalar_double(g + "/delta_n");
  r.hn = f.read_scalar_double(g + "/hn");
  r.alpha_deg = f.read_scalar_double(g + "/alpha_deg");
  r.ht = f.read_scalar_double(g + "/ht");
  r.force = read_vec3(f, g + "/force");
  r.force_first = read_vec3(f, g + "/force_first");
  r.force_between = read_vec3(f, g + "/force_between");
  r.contacts = f.read_scalar_int64(g + "/contacts");
  r.relax_steps = f.read_scalar_int64(g + "/relax_steps");
  r.relax_time = f.read_scalar_double(g + "/relax_time");
  r.steps = f.read_scalar_int64(g + "/steps");
  r.seconds = f.read_scalar_double(g + "/seconds");
  const auto t = f.read_doubles(g + "/checks/time"), ke = f.read_doubles(g + "/checks/kinetic_energy"),
             ee = f.read_doubles(g + "/checks/elastic_energy"), mu = f.read_doubles(g + "/checks/max_unbalanced_force"),
             mc = f.read_doubles(g + "/checks/mean_contact_force"), nc = f.read_doubles(g + "/checks/contacts");
  for (std::size_t k = 0; k < t.size(); ++k) {
    RelaxationCheck c;
    c.time = t[k];
    c.residuals.kinetic_energy = ke[k];
    c.residuals.elastic_energy = ee[k];
    c.residuals.max_unbalanced_force = mu[k];
    c.residuals.mean_contact_force = mc[k];
    c.residuals.contacts = static_cast<std::size_t>(nc[k]);
    r.checks.push_back(c);
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
  PointFile p;
  p.result = read_result(f, "result");
  p.provenance.stage = f.read_string("provenance/stage");
  p.provenance.scene = f.read_string("provenance/scene");
  p.provenance.config = f.read_string("provenance/config");
  p.provenance.code_version = f.read_string("provenance/code_version");
  if (with_state) {
    SimulationState& s = p.state;
    s.time = f.read_scalar_double("state/time");
    s.steps = f.read_scalar_int64("state/steps");
    s.x = read_vec3s(f, "state/x");
    s.v = read_vec3s(f, "state/v");
    s.w = read_vec3s(f, "state/w");
    s.F = read_vec3s(f, "state/F");
    s.T = read_vec3s(f, "state/T");
    s.plane_points = read_vec3s(f, "state/plane_points");
    s.shell_centres = read_vec3s(f, "state/shell_centres");
    const auto pi = f.read_int64s("state/pair_springs/i"), pj = f.read_int64s("state/pair_springs/j");
    const auto pxi = read_vec3s(f, "state/pair_springs/xi");
    for (std::size_t k = 0; k < pi.size(); ++k) s.pair_springs.push_back({static_cast<int>(pi[k]), static_cast<int>(pj[k]), pxi[k]});
    s.plane_springs = read_wall_springs(f, "state/plane_springs");
    s.shell_springs = read_wall_springs(f, "state/shell_springs");
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
