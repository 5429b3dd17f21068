// tissue-sim: the headless command. Subcommands are listed in commands.def.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "command.h"
#include "output.h"

namespace tissue::sim_app {
#define TISSUE_COMMAND(fn) void fn(CLI::App& app, const GlobalOptions& global, int& exitCode);
#include "commands.def"
#undef TISSUE_COMMAND
}  // namespace tissue::sim_app

int main(int argc, char** argv) {
  using namespace tissue::sim_app;
  CLI::App app{"tissue-sim: headless simulation, mesh processing and rendering of deforming tissue"};
  app.require_subcommand(1);
  app.fallthrough();  // subcommands inherit it: --json works after the subcommand too
  GlobalOptions global;
  app.add_flag("--json", global.json, "print exactly one JSON object on stdout");
  int exitCode = 0;
#define TISSUE_COMMAND(fn) fn(app, global, exitCode);
#include "commands.def"
#undef TISSUE_COMMAND
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line on stderr, never CLI11's multi-line usage dump.
    std::cerr << "tissue-sim: " << e.what() << "; run 'tissue-sim --help' for usage" << std::endl;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "tissue-sim: unexpected error: " << e.what() << std::endl;
    return 1;
  }
  return exitCode;
}
