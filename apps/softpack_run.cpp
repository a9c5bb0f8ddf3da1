// softpack-run: runs one scene file (drivers for run.duration, then run.relaxation) and writes
// a JSON report: time step and its limit, steps, wall loads, relaxation residuals, provenance.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <nlohmann/json.hpp>

#include "apps/command_line.hpp"
#include "core/parallel.hpp"
#include "apps/exit_codes.hpp"
#include "core/error.hpp"
#include "core/text_input.hpp"
#include "core/version.hpp"
#include "formats/scene_laws.hpp"
#include "io/atomic_file.hpp"
#include "relax/relaxation.hpp"
#include "scene/scene_yaml.hpp"
#include "scene/validate.hpp"
#include "sim/simulation.hpp"

namespace softpack::apps::run_app {
namespace {
using Clock = std::chrono::steady_clock;
using json = nlohmann::json;

json vec(const Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }

json residuals(const Measurement& m) {
  return {{"kinetic_energy", m.kinetic_energy},
          {"elastic_energy", m.elastic_energy},
          {"max_unbalanced_force", m.max_unbalanced_force},
          {"mean_contact_force", m.mean_contact_force},
          {"force_ratio", m.force_ratio()},
          {"energy_ratio", m.energy_ratio()},
          {"contacts", m.contacts}};
}

/// Progress on stderr: redrawn in place on a terminal, one line per update otherwise.
class Progress {
 public:
  explicit Progress(bool quiet) : quiet_(quiet), tty_(::isatty(STDERR_FILENO) != 0) {}
  void update(const std::string& line) {
    if (quiet_) return;
    if (tty_) fmt::print(stderr, "\r\033[K{}", line);
    else fmt::print(stderr, "{}\n", line);
  }
  void done() {
    if (!quiet_ && tty_) fmt::print(stderr, "\n");
  }

 private:
  bool quiet_, tty_;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"softpack-run: run a scene file (drivers, then relaxation) and report the result as JSON"};
  std::string scene_path, out_path;
  bool quiet = false;
  app.add_option("--scene", scene_path, "scene file (YAML), see docs/scene-format.md")->required();
  app.add_option("--out", out_path, "write the JSON report here (atomically) instead of stdout");
  app.add_flag("--quiet", quiet, "no progress lines on stderr");
  add_threads_option(app);
  if (const auto code = parse_command_line(app, argc, argv, "softpack-run")) return *code;

  try {
    const auto wall_start = Clock::now();
    SceneFile file = load_scene_file(scene_path);
    load_scene_laws(file);  // its soft-particles' law file: the engine reads no JSON
    if (!file.run.duration && !file.run.relaxation)
      throw InputError(scene_path + ": run: nothing to do; give run.duration and/or run.relaxation");
    // The rules that need the time step (the steps of each duration), placed in the file.
    const auto located = [&](const auto& check) {
      try {
        check();
      } catch (const InputError& e) {
        throw file.root.locate(e);
      }
    };
    std::optional<Simulation> built;
    located([&] { built.emplace(file.scene); });
    Simulation& sim = *built;
    located([&] {
      if (file.run.duration) validate_steps(*file.run.duration, sim.dt(), "run.duration");
      if (file.run.relaxation) validate_steps(*file.run.relaxation, sim.dt(), "run.relaxation");
    });
    Progress progress(quiet);

    if (file.run.duration) {
      const long total = sim.steps_for(*file.run.duration);
      const long chunk = std::max(1L, total / 100);
      for (long done = 0; done < total;) {
        const long n = std::min(chunk, total - done);
        sim.run_steps(n);
        done += n;
        const double elapsed = std::chrono::duration<double>(Clock::now() - wall_start).count();
        progress.update(fmt::format("run: step {}/{}  t = {:.4g} s  ETA {:.0f} s", done, total, sim.time(),
                                    elapsed / static_cast<double>(done) * static_cast<double>(total - done)));
      }
      progress.done();
    }
    json relaxation = nullptr;
    if (file.run.relaxation) {
      const RelaxationReport rep = relax(sim, *file.run.relaxation, [&](const RelaxationCheck& c) {
        progress.update(fmt::format("relax: t = {:.4g} s  force ratio {:.3e}  energy ratio {:.3e}", c.time,
                                    c.residuals.force_ratio(), c.residuals.energy_ratio()));
      });
      progress.done();
      json checks = json::array();
      for (const auto& c : rep.checks)
        checks.push_back({{"time", c.time}, {"steps", c.steps}, {"residuals", residuals(c.residuals)}});
      relaxation = {{"steps", rep.steps}, {"simulated_time", rep.simulated_time}, {"checks", checks}};
      relaxation["converged"] = rep.converged ? json(*rep.converged) : json(nullptr);
    }

    json walls = json::object();
    for (std::size_t k = 0; k < file.scene.planes.size(); ++k)
      walls[file.scene.planes[k].name] = {{"force", vec(sim.plane_loads()[k].force)}, {"torque", vec(sim.plane_loads()[k].torque)}};
    for (std::size_t k = 0; k < file.scene.shells.size(); ++k)
      walls[file.scene.shells[k].name] = {{"force", vec(sim.shell_loads()[k].force)}, {"torque", vec(sim.shell_loads()[k].torque)}};

    const double seconds = std::chrono::duration<double>(Clock::now() - wall_start).count();
    const json report = {
        {"scene", scene_path},
        {"spheres", sim.particles().size()},
        {"dt", sim.dt()},
        {"stable_limit", sim.stable_limit().t_rayleigh},
        {"steps", sim.step_count()},
        {"time", sim.time()},
        {"neighbour_rebuilds", sim.neighbour_rebuilds()},
        {"walls", walls},
        {"relaxation", relaxation},
        {"final", residuals(sim.residuals())},
        {"provenance",
         {{"code_version", code_version()},
          {"config", read_text_input(scene_path, "a scene file (YAML)")},
          {"seconds", seconds},
          {"threads", parallel::threads_for(file.scene.particles.size())}}},
    };
    if (out_path.empty()) std::cout << report.dump(2) << "\n";
    else write_file_atomically(out_path, report.dump(2) + "\n");
    return 0;
  } catch (...) {
    return exit_on_error("softpack-run");
  }
}

}  // namespace softpack::apps::run_app
