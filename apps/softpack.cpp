// softpack: the executable of every command (apps/commands.hpp). Called as softpack-<name> (the
// links build/bin/softpack-*), it runs that command; called as `softpack <name> ARGS...`, the
// same; `softpack --help` lists the commands. An unknown name is bad input: one line, exit 2.
#include <fmt/format.h>

#include <cstdio>
#include <string>
#include <string_view>

#include "apps/commands.hpp"
#include "apps/exit_codes.hpp"

namespace {

using softpack::apps::Command;
using softpack::apps::kCommands;

const Command* find(std::string_view name) {
  for (const Command& c : kCommands)
    if (c.name == name) return &c;
  return nullptr;
}

void list(std::FILE* out) {
  fmt::print(out, "softpack: the engine's commands; run one as softpack-<command> (or softpack <command>), with --help for its options\n\n");
  for (const Command& c : kCommands) fmt::print(out, "  softpack-{:<15} {}\n", c.name, c.what);
}

}  // namespace

int main(int argc, char** argv) {
  std::string_view called = argc > 0 ? argv[0] : "softpack";
  if (const auto slash = called.rfind('/'); slash != std::string_view::npos) called.remove_prefix(slash + 1);
  constexpr std::string_view prefix = "softpack-";
  if (called.starts_with(prefix)) {
    if (const Command* c = find(called.substr(prefix.size()))) return softpack::checked_exit(called, c->main(argc, argv));
    fmt::print(stderr, "softpack: error: '{}' is not a command of softpack; see softpack --help\n", called);
    return softpack::kExitInput;
  }
  if (argc < 2) {
    list(stderr);
    return softpack::kExitInput;
  }
  const std::string_view name = argv[1];
  if (name == "--help" || name == "-h") {
    list(stdout);
    return softpack::checked_exit("softpack", 0);
  }
  if (const Command* c = find(name.starts_with(prefix) ? name.substr(prefix.size()) : name)) {
    std::string called_as = fmt::format("{}{}", prefix, c->name);  // its usage names it softpack-<name>
    argv[1] = called_as.data();
    return softpack::checked_exit(called_as, c->main(argc - 1, argv + 1));
  }
  fmt::print(stderr, "softpack: error: '{}' is not a command of softpack; see softpack --help\n", name);
  return softpack::kExitInput;
}
