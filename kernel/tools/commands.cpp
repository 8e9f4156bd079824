// commands.cpp -- the registry of subcommands.
#include "tools/commands.h"

#include <algorithm>
#include <exception>
#include <iostream>

namespace grassfire::cli {

namespace {
std::vector<Command>& registry() {
  static std::vector<Command> list;
  return list;
}
}  // namespace

bool register_command(Command c) {
  registry().push_back(std::move(c));
  return true;
}

std::vector<Command> commands() {
  std::vector<Command> list = registry();
  std::sort(list.begin(), list.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
  return list;
}

int run_guarded(const Command& c, int argc, char** argv) {
  try {
    return c.run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "grassfire " << c.name << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace grassfire::cli
