#pragma once
/// \file
/// How tissue-sim's subcommands plug in: each file in commands/ defines one register
/// function that adds a CLI11 subcommand and its callback. A callback returns the exit code;
/// it prints readable text, or exactly one JSON object with --json, and errors as one line
/// on stderr (see output.h).

#include <CLI/CLI.hpp>

namespace tissue::sim_app {

/// Options every subcommand shares.
struct GlobalOptions {
  bool json = false;  ///< print one JSON object on stdout instead of text
};

/// Adds one subcommand to `app`. `exitCode` receives the subcommand's exit status.
using RegisterFn = void (*)(CLI::App& app, const GlobalOptions& global, int& exitCode);

}  // namespace tissue::sim_app
