#include "measure/contact_scenes.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "formats/contents_file.hpp"
#include "formats/law_file.hpp"
#include "measure/content_scene.hpp"
#include "packing/nested.hpp"

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

// How the profile's resolved content enters the measurement scenes.
ContentPlacement placement(const SimulationSettings& s) {
  return ContentPlacement{kGrain, kWall, s.material.density, s.shell_contact_radius, s.content->shell_mass_fraction};
}

// The packing's grains and shell about `centre`, every length times `scale` (1: as generated),
// and the sites of a packing of nested soft-particles in the form of the profile's `content`.
void add_soft_particle(SceneDef& scene, const PackingFile& p, int body, const Vec3& centre, const std::string& shell,
                       const SimulationSettings& s, int& next_body, double scale = 1.0) {
  for (std::size_t i = 0; i < p.radii.size(); ++i) {
    ParticleDef d;
    d.x = centre + scale * p.centres[i];
    d.r = scale * p.radii[i];
    d.body = body;
    d.material = kGrain;
    scene.particles.push_back(d);
  }
  scene.shells.push_back(ShellDef{shell, body, centre, scale * p.Rs, kWall, s.shell_contact_radius, std::nullopt});
  if (p.sites.levels == 1) return;
  // parse_measurement refuses a profile of levels without `content`; a packing file of levels
  // measured with a profile without them is refused here, rather than measured without its sites.
  if (!s.content)
    throw InputError(fmt::format("the packing of seed {} ({}) holds {} soft-particles of the level below (packing.levels = {}), "
                                 "but the profile has no `content` section saying how to hold them; allowed: a profile with "
                                 "packing.levels {} and `content` (docs/nested.md)",
                                 p.provenance.seed, p.provenance.config_file, p.sites.centres.size(), p.sites.levels, p.sites.levels));
  const std::vector<SiteContent> contents = packing_contents(p);  // made once per packing, then read
  if (s.content->form == ContentForm::resolved) {
    add_contents(scene, contents, p.sites.centres, p.sites.radius, body, centre, scale, placement(s), next_body);
    return;
  }
  for (std::size_t k = 0; k < contents.size(); ++k) {
    const double grains = s.material.density * contents[k].solid_volume();
    ParticleDef d = {};
    d.x = centre + scale * p.sites.centres[k];
    d.r = scale * p.sites.radius;
    d.body = body;
    d.material = kGrain;
    d.soft = true;
    // Its content's mass resolved: the grains and their free shells (scaled as every length^3).
    d.mass = scale * scale * scale * (grains + content_shells_mass(contents[k], s.material.density, s.content->shell_mass_fraction));
    scene.particles.push_back(d);
  }
  if (!scene.effects.soft_particles) {
    // The level below's law file is made by its study (docs/nested.md); the sites' many-body law
    // may come from another file (dimensionless).
    const SoftParticleLaws laws = read_soft_particle_laws("content", s.content->laws, s.content->many_body);
    scene.effects.soft_particles = SoftParticlesDef{laws, s.content->grain_contact, SoftParticlesDef::BeyondRange::report};
  }
}

}  // namespace

ContactSetup soft_solid_setup(const PackingFile& first, const SimulationSettings& s) {
  ContactSetup c;
  c.kind = ContactScene::soft_solid;
  c.scene = base_scene(s);
  c.Rs = first.Rs;
  int next_body = 1;
  add_soft_particle(c.scene, first, 0, Vec3::Zero(), "shell-1", s, next_body);
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
  int next_body = 2;  // the bodies inside the two soft-particles, when their content is resolved
  add_soft_particle(c.scene, first, 0, Vec3::Zero(), "shell-1", s, next_body);
  const double Rs2 = second_radius_ratio * second.Rs;  // touching: centres Rs + Rs2 apart
  add_soft_particle(c.scene, second, 1, Vec3(first.Rs + Rs2, 0, 0), "shell-2", s, next_body, second_radius_ratio);
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
