// main.cpp -- the grassfire command-line program: dispatches to subcommands.
#include <cstring>
#include <iostream>
#include <string>

#include "grassfire_version.h"
#include "tools/commands.h"

namespace {

void print_usage(std::ostream& os) {
  os << "usage: grassfire <command> [options]\n\n"
        "Exact medial geometry: medial axes, the extended distance function (EDF) and\n"
        "the extended medial axis (EMA) of Liu 2011.\n\ncommands:\n";
  for (const grassfire::cli::Command& c : grassfire::cli::commands())
    os << "  " << c.name << std::string(c.name.size() < 12 ? 12 - c.name.size() : 1, ' ') << c.summary << "\n";
  os << "\n'grassfire <command> --help' describes a command; 'grassfire --version' prints the version.\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
    print_usage(std::cout);
    return argc < 2 ? 2 : 0;
  }
  if (!std::strcmp(argv[1], "--version") || !std::strcmp(argv[1], "version")) {
    std::cout << "grassfire " << GRASSFIRE_VERSION << "\n";
    return 0;
  }
  for (const grassfire::cli::Command& c : grassfire::cli::commands())
    if (c.name == argv[1]) return grassfire::cli::run_guarded(c, argc - 1, argv + 1);
  std::cerr << "grassfire: unknown command '" << argv[1] << "'\n\n";
  print_usage(std::cerr);
  return 2;
}
