#include "measure/contact_scenes.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace softpack {
namespace {

constexpr int kGrain = 0, kWall = 1;  // the scenes' materials

SceneDef base_scene(const SimulationSettings& s) {
  SceneDef scene;
  scene.materials = {s.material, s.wall_material};  // kGrain, kWall
  scene.effects = s.effects;
  scene.integration = s.integration;
  scene.neighbor = s.neighbor;
  return scene;
}

// The packing's grains and shell about `centre`, every length times `scale` (1: as generated).
void add_soft_particle(SceneDef& scene, const PackingFile& p, int body, const Vec3& centre, const std::string& shell,
                       ShellContactRadius radius, double scale = 1.0) {
  // A packing of nested soft-particles would be measured without its sites: refused, not run.
  if (p.sites.levels > 1)
    throw InputError(fmt::format("the packing of seed {} ({}) holds {} soft-particles of the level below (packing.levels = {}): "
                                 "the measurement scenes do not hold nested soft-particles yet (docs/nested.md, \"What is not "
                                 "done\"); allowed: packings of packing.levels 1",
                                 p.provenance.seed, p.provenance.config_file, p.sites.centres.size(), p.sites.levels));
  for (std::size_t i = 0; i < p.radii.size(); ++i) {
    ParticleDef d;
    d.x = centre + scale * p.centres[i];
    d.r = scale * p.radii[i];
    d.body = body;
    d.material = kGrain;
    scene.particles.push_back(d);
  }
  scene.shells.push_back(ShellDef{shell, body, centre, scale * p.Rs, kWall, radius, std::nullopt});
}

}  // namespace

ContactSetup soft_solid_setup(const PackingFile& first, const SimulationSettings& s) {
  ContactSetup c;
  c.kind = ContactScene::soft_solid;
  c.scene = base_scene(s);
  c.Rs = first.Rs;
  add_soft_particle(c.scene, first, 0, Vec3::Zero(), "shell-1", s.shell_contact_radius);
  c.scene.planes.push_back(PlaneDef{"wall", Vec3(first.Rs, 0, 0), Vec3(-1, 0, 0), kWall});
  c.second_wall = "wall";
  c.first_shell = "shell-1";
  return c;
}

ContactSetup soft_soft_setup(const PackingFile& first, const PackingFile& second, const SimulationSettings& s,
                             double second_radius_ratio) {
  if (first.Rs != second.Rs)
    throw InputError(fmt::format("soft-soft needs two packings of equal size (the second is scaled by normal.second_radius_ratio); "
                                 "the packings have Rs = {} and {} m",
                                 first.Rs, second.Rs));
  ContactSetup c;
  c.kind = ContactScene::soft_soft;
  c.scene = base_scene(s);
  c.Rs = first.Rs;
  add_soft_particle(c.scene, first, 0, Vec3::Zero(), "shell-1", s.shell_contact_radius);
  const double Rs2 = second_radius_ratio * second.Rs;  // touching: centres Rs + Rs2 apart
  add_soft_particle(c.scene, second, 1, Vec3(first.Rs + Rs2, 0, 0), "shell-2", s.shell_contact_radius, second_radius_ratio);
  c.second_wall = "shell-2";
  c.first_shell = "shell-1";
  c.second_body = 1;
  return c;
}

ContactSetup hertz_check_setup(double Rs, const SimulationSettings& s) {
  ContactSetup c;
  c.kind = ContactScene::soft_solid;
  c.scene = base_scene(s);
  c.Rs = Rs;
  ParticleDef sphere;
  sphere.r = Rs;
  sphere.body = 0;
  c.scene.particles.push_back(sphere);
  c.scene.planes.push_back(PlaneDef{"wall", Vec3(Rs, 0, 0), Vec3(-1, 0, 0), kWall});
  // The held sphere stands for the fixed shell.
  c.scene.drivers.emplace_back(std::in_place_type<HoldGroupDef>, HoldGroupDef{GroupDef{GroupDef::Kind::body, 0}});
  c.second_wall = "wall";
  return c;
}

}  // namespace softpack
