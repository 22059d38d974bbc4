// SPDX-License-Identifier: Apache-2.0
// alphapocket: one executable, one subcommand per file (cmd_*.cpp).
// Machine output goes to stdout; logs (spdlog) and errors go to stderr.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "alpha/error.hpp"
#include "alphapocket/version.hpp"
#include "commands.hpp"

namespace {

constexpr const char* kExitCodes =
    "Exit codes: 0 success; 1 an error in the input or the output (one line 'ERROR: <file>: <problem>' on "
    "stderr); 2 a wrong command line; 5 a limit exceeded (a file above --max-input-mb, out of memory, too many "
    "points); 6 an internal error "
    "(a bug). Logs go to stderr (-q: warnings and errors only; -v, -vv: more, e.g. pockets "
    "logs every site); results to stdout and the output files.";

// A wrong command line: one ERROR line, exit code 2, as usual for tools.
int usage_error(std::string message) {
  std::replace(message.begin(), message.end(), '\n', ' ');
  std::fprintf(stderr, "ERROR: %s (see --help)\n", message.c_str());
  return 2;
}

// The index of the first argument that is not a global option (the
// subcommand), or 0 when there is none.
int first_word(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.empty() || a[0] != '-') return i;
  }
  return 0;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// "; did you mean 'pockets'?" for the closest name within 3 edits.
std::string suggestion(const std::string& word, const std::vector<std::string>& names) {
  std::string best;
  std::size_t best_distance = 4;
  for (const std::string& name : names)
    if (const std::size_t d = edit_distance(word, name); d < best_distance) best = name, best_distance = d;
  const std::string list = "; subcommands: " + [&] {
    std::string l;
    for (const std::string& n : names) l += (l.empty() ? "" : ", ") + n;
    return l;
  }();
  return best.empty() ? list : "; did you mean '" + best + "'?";
}

int run(int argc, char** argv) {
  CLI::App app{"alphapocket: cavities in molecules from exact 3D alpha shapes"};
  app.set_version_flag("--version", "alphapocket " ALPHAPOCKET_VERSION);
  app.require_subcommand(1);
  int verbose = 0;
  bool quiet = false;
  auto* v = app.add_flag("-v,--verbose", verbose, "More log output on stderr (-vv for trace)");
  app.add_flag("-q,--quiet", quiet, "Log only warnings and errors")->excludes(v);

  std::vector<alphapocket::Subcommand> commands;
  // In the order of --help: the product first, the layers below it last.
  commands.push_back(alphapocket::add_pockets_command(app));
  commands.push_back(alphapocket::add_batch_command(app));
  commands.push_back(alphapocket::add_track_command(app));
  commands.push_back(alphapocket::add_merge_command(app));
  commands.push_back(alphapocket::add_surface_command(app));
  commands.push_back(alphapocket::add_delaunay_command(app));
  commands.push_back(alphapocket::add_spectrum_command(app));
  commands.push_back(alphapocket::add_persistence_command(app));
  commands.push_back(alphapocket::add_shape_command(app));
  app.footer(kExitCodes);
  for (const auto& command : commands) {
    command.app->fallthrough();  // -q, -v after the subcommand
    command.app->footer(command.app->get_footer() + "\n\n" + kExitCodes);
  }

  // `help [SUBCOMMAND]`, and a misspelt subcommand named with the closest.
  std::vector<std::string> names;
  for (const auto& command : commands) names.push_back(command.app->get_name());
  if (const int first = first_word(argc, argv); first > 0) {
    const std::string word = argv[first];
    if (word == "help") {
      if (first + 1 >= argc) {
        std::fputs(app.help().c_str(), stdout);
        return 0;
      }
      for (const auto& command : commands)
        if (command.app->get_name() == argv[first + 1]) {
          std::fputs(command.app->help().c_str(), stdout);
          return 0;
        }
      return usage_error("unknown subcommand '" + std::string(argv[first + 1]) + "'" + suggestion(argv[first + 1], names));
    }
    if (std::find(names.begin(), names.end(), word) == names.end())
      return usage_error("unknown subcommand '" + word + "'" + suggestion(word, names));
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version print to stdout and exit 0; a usage error is one
    // ERROR line like every other error, and exits 2, as usual for tools.
    if (e.get_exit_code() == 0) return app.exit(e);
    return usage_error(e.what());
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

// The exit code of an error by its kind (docs/cli.md, "Usage").
int exit_code(alpha::ErrorKind kind) {
  switch (kind) {
    case alpha::ErrorKind::BadInput: return 1;
    case alpha::ErrorKind::LimitExceeded: return 5;
    case alpha::ErrorKind::Misuse: break;  // the CLI called the library wrongly: a bug
    case alpha::ErrorKind::Internal: break;
  }
  return 6;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const alpha::Error& e) {
    std::fprintf(stderr, "ERROR: %s\n", e.what());
    return exit_code(e.kind());
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "ERROR: out of memory\n");
    return 5;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ERROR: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "ERROR: unknown error\n");
  }
  return 1;
}
