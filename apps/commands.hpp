// SPDX-License-Identifier: Apache-2.0
// The subcommands of alphapocket, one file each (cmd_*.cpp). Each adds
// itself to the top-level CLI11 app and returns the function that runs it
// once the command line is parsed; that function returns the exit code and
// reports errors by throwing (main prints them as "ERROR: <message>").
#pragma once
#include <functional>

#include <CLI/CLI.hpp>

namespace alphapocket {

struct Subcommand {
  CLI::App* app;
  std::function<int()> run;
};

Subcommand add_delaunay_command(CLI::App& app);
Subcommand add_spectrum_command(CLI::App& app);
Subcommand add_persistence_command(CLI::App& app);
Subcommand add_shape_command(CLI::App& app);
Subcommand add_pockets_command(CLI::App& app);
Subcommand add_surface_command(CLI::App& app);
Subcommand add_batch_command(CLI::App& app);
Subcommand add_merge_command(CLI::App& app);
Subcommand add_track_command(CLI::App& app);

}  // namespace alphapocket
