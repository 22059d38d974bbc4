// alphapocket: one executable, one subcommand per file (cmd_*.cpp).
// Machine output goes to stdout; logs (spdlog) and errors go to stderr.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "commands.hpp"

#ifndef ALPHAPOCKET_VERSION
#define ALPHAPOCKET_VERSION "unknown"
#endif

namespace {

int run(int argc, char** argv) {
  CLI::App app{"alphapocket: cavities in molecules from exact 3D alpha shapes"};
  app.set_version_flag("--version", "alphapocket " ALPHAPOCKET_VERSION);
  app.require_subcommand(1);
  int verbose = 0;
  bool quiet = false;
  auto* v = app.add_flag("-v,--verbose", verbose, "More log output on stderr (-vv for trace)");
  app.add_flag("-q,--quiet", quiet, "Log only warnings and errors")->excludes(v);

  std::vector<alphapocket::Subcommand> commands;
  commands.push_back(alphapocket::add_delaunay_command(app));
  commands.push_back(alphapocket::add_spectrum_command(app));
  commands.push_back(alphapocket::add_persistence_command(app));
  commands.push_back(alphapocket::add_shape_command(app));
  commands.push_back(alphapocket::add_pockets_command(app));
  commands.push_back(alphapocket::add_surface_command(app));
  commands.push_back(alphapocket::add_batch_command(app));
  commands.push_back(alphapocket::add_merge_command(app));

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version print to stdout and exit 0; a usage error is one
    // ERROR line like every other error, and exits 2, as usual for tools.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::string message = e.what();
    std::replace(message.begin(), message.end(), '\n', ' ');
    std::fprintf(stderr, "ERROR: %s (see --help)\n", message.c_str());
    return 2;
  }

  auto logger = spdlog::stderr_color_mt("alphapocket");
  logger->set_pattern("%^[%l]%$ %v");
  spdlog::set_default_logger(logger);
  spdlog::set_level(quiet ? spdlog::level::warn
                    : verbose >= 2 ? spdlog::level::trace
                    : verbose == 1 ? spdlog::level::debug
                                   : spdlog::level::info);

  for (const auto& command : commands)
    if (command.app->parsed()) return command.run();
  return 2;  // unreachable: CLI11 requires one subcommand
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ERROR: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "ERROR: unknown error\n");
  }
  return 1;
}
