// The engine's commands, one per step of the workflow: each is the `main` of one file
// apps/softpack_<name>.cpp, in its own namespace. They are linked into one executable,
// `softpack` (apps/softpack.cpp), compiled as one unit: the command-line library (CLI11, header
// only) is then compiled once for all of them instead of once per command. Each command is
// reached by its name: build/bin/softpack-pack is a link to `softpack`, which looks at the
// name it was called by (as git and busybox do); `softpack pack ...` is the same.
#pragma once
#include <array>
#include <string_view>

namespace softpack::apps {

namespace study_app { int main(int argc, char** argv); }
namespace apollonian_app { int main(int argc, char** argv); }
namespace average_app { int main(int argc, char** argv); }
namespace coarse_app { int main(int argc, char** argv); }
namespace config_app { int main(int argc, char** argv); }
namespace fit_app { int main(int argc, char** argv); }
namespace import_app { int main(int argc, char** argv); }
namespace normal_app { int main(int argc, char** argv); }
namespace pack_app { int main(int argc, char** argv); }
namespace run_app { int main(int argc, char** argv); }
namespace section_app { int main(int argc, char** argv); }
namespace sliding_app { int main(int argc, char** argv); }
namespace table_app { int main(int argc, char** argv); }
namespace tangential_app { int main(int argc, char** argv); }
namespace timing_app { int main(int argc, char** argv); }

struct Command {
  std::string_view name;  ///< the command is softpack-<name>
  int (*main)(int argc, char** argv);
  std::string_view what;
};

/// Every command, in the order `softpack --help` lists them (the workflow's order). The names
/// are those of engine/CMakeLists.txt's SOFTPACK_COMMANDS, which makes a link for each.
inline constexpr std::array kCommands{
    Command{"config", config_app::main, "the seeds, scenes, sections and stamps of a profile, as the stages read it"},
    Command{"section", section_app::main, "circles cut from a packing by a plane (Figure 2)"},
    Command{"pack", pack_app::main, "the packing of one seed (paper §3)"},
    Command{"import", import_app::main, "a packing made elsewhere (LAMMPS data, extended XYZ, text)"},
    Command{"normal", normal_app::main, "the normal sweep of one scene and seed (paper §4)"},
    Command{"tangential", tangential_app::main, "the tangential sweep of one scene and seed"},
    Command{"sliding", sliding_app::main, "the sliding sweep of one scene and seed"},
    Command{"average", average_app::main, "the sweep results of one scene averaged over the seeds"},
    Command{"fit", fit_app::main, "Eq. 7 and Eq. 8 fitted to the averages of one scene"},
    Command{"table", table_app::main, "Tables 1 and 2 beside the paper's"},
    Command{"apollonian", apollonian_app::main, "the Apollonian gasket of Figure 1"},
    Command{"timing", timing_app::main, "the wall-clock and CPU time of a profile's outputs"},
    Command{"study", study_app::main, "a study of settings of a base profile: profiles, plan, report (accuracy, calibration, radius); the fast check"},
    Command{"coarse", coarse_app::main, "the coarse-grain validation"},
    Command{"run", run_app::main, "a scene file, reported as JSON"},
};

}  // namespace softpack::apps
