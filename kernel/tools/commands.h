// commands.h -- the subcommands of the grassfire program and their registry.
//
// Each subcommand lives in its own kernel/tools/<name>.cpp and registers itself with
// GF_REGISTER_COMMAND; the program lists them sorted by name. Files under kernel/tools
// are compiled into the executable itself, so the static registrars always run.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace grassfire::cli {

struct Command {
  std::string name;
  std::string summary;
  std::function<int(int argc, char** argv)> run;  // argv[0] is the command name
};

// All registered subcommands, sorted by name.
std::vector<Command> commands();
bool register_command(Command c);

// Runs a command; turns exceptions into "grassfire <cmd>: <message>" and exit code 1.
int run_guarded(const Command& c, int argc, char** argv);

}  // namespace grassfire::cli

#define GF_CONCAT_INNER(a, b) a##b
#define GF_CONCAT(a, b) GF_CONCAT_INNER(a, b)
#define GF_REGISTER_COMMAND(name, summary, fn) \
  static const bool GF_CONCAT(gf_registered_command_, __LINE__) = ::grassfire::cli::register_command({name, summary, fn})
