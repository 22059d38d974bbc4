// SPDX-License-Identifier: Apache-2.0
// alphapocket persistence FILE [--weighted]
//
// The persistence diagram of the alpha filtration, one line per pair:
//
//   dim birth_sq death_sq
//
// dim is 0, 1 or 2; birth_sq and death_sq are the squared radii (alpha_sq)
// at which the class is born and dies, printed to round-trip as doubles;
// death_sq is "inf" for a class that never dies. Pairs that are born and die
// at the same critical value are left out. Lines are sorted by dim, birth,
// death (GUDHI's plain "dim birth death" diagram format).
#include <algorithm>
#include <array>
#include <cstdio>
#include <iterator>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <fmt/compile.h>
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "alpha/alpha_complex.hpp"
#include "alpha/error.hpp"
#include "commands.hpp"
#include "common.hpp"

namespace alphapocket {
namespace {

// Appends the shortest text that reads back as the same double ("0" for -0).
// (A compiled format: the value's own formatting, no format string parsing.)
void append_value(std::string& out, double v) { fmt::format_to(std::back_inserter(out), FMT_COMPILE("{}"), printable(v)); }

// Appends the lines of a run of pairs to out; returns how many.
std::size_t append_lines(const alpha::AlphaComplex& ac, std::span<const alpha::PersistencePair> pairs,
                         std::string& out) {
  // Each column's last value kept as text: lattices have few distinct
  // values, and sorted pairs repeat them on consecutive lines. The values
  // of a block of pairs are fetched together (spectrum_values): at a
  // million points each one is a few cache misses.
  struct Column {
    alpha::Index rank = alpha::kNever;
    std::string text;
  };
  std::array<Column, 2> columns;  // birth, death
  const auto rank_of = [](const alpha::PersistencePair& p, int column) { return column == 0 ? p.birth : p.death; };
  // Whether a column's text changes at `rank` (last: the rank it shows);
  // the same rule chooses the ranks to fetch and reads their values back.
  const auto changes = [](alpha::Index rank, alpha::Index& last) {
    if (rank == alpha::kNever || rank == last) return false;
    last = rank;
    return true;
  };
  constexpr std::size_t kBlock = 4096;
  std::vector<alpha::Index> ranks;
  std::vector<double> values;
  std::size_t lines = 0;
  for (std::size_t first = 0; first < pairs.size(); first += kBlock) {
    const auto block = pairs.subspan(first, std::min(kBlock, pairs.size() - first));
    ranks.clear();
    std::array<alpha::Index, 2> shown{columns[0].rank, columns[1].rank};
    for (const alpha::PersistencePair& p : block) {
      if (p.birth == p.death) continue;  // zero length (the complex keeps none; be sure)
      for (int c = 0; c < 2; ++c)
        if (changes(rank_of(p, c), shown[c])) ranks.push_back(rank_of(p, c));
    }
    values.resize(ranks.size());
    ac.spectrum_values(ranks, values);
    std::size_t next = 0;
    for (const alpha::PersistencePair& p : block) {
      if (p.birth == p.death) continue;
      out += char('0' + p.dim);
      for (int c = 0; c < 2; ++c) {
        Column& column = columns[c];
        if (changes(rank_of(p, c), column.rank)) {
          column.text.clear();
          append_value(column.text, values[next++]);
        }
        out += ' ';
        out += rank_of(p, c) == alpha::kNever ? std::string_view("inf") : std::string_view(column.text);
      }
      out += '\n';
      ++lines;
    }
  }
  return lines;
}

int run_persistence(const InputOptions& opt) {
  const AlphaInput in = load_alpha_complex(opt);
  const alpha::AlphaComplex& ac = in.shape.complex();
  Stopwatch pairs_time;
  const std::vector<alpha::PersistencePair>& pairs = ac.persistence();
  spdlog::info("persistence pairs: {:.3f} s", pairs_time.seconds());
  // Runs of pairs are turned into text on the threads side by side (the
  // values' exact rounding is most of the time), then written in order: a
  // few megabytes at a time, where the whole diagram in one string would
  // add ~40 bytes a pair to the peak memory (240 MB for 1e6 points).
  constexpr std::size_t kRun = std::size_t(1) << 15;
  const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, opt.threads);
  std::vector<std::string> texts(threads);
  std::vector<std::size_t> counts(threads);
  std::size_t lines = 0;
  for (std::size_t first = 0; first < pairs.size(); first += threads * kRun) {
    const auto format = [&](unsigned k) {
      const std::size_t begin = std::min(first + k * kRun, pairs.size());
      texts[k].clear();
      counts[k] = append_lines(ac, std::span(pairs).subspan(begin, std::min(kRun, pairs.size() - begin)), texts[k]);
    };
    {
      std::vector<std::jthread> side;
      for (unsigned k = 1; k < threads; ++k) side.emplace_back(format, k);
      format(0);
    }
    for (unsigned k = 0; k < threads; ++k) {
      if (std::fwrite(texts[k].data(), 1, texts[k].size(), stdout) != texts[k].size())
        throw alpha::Error("cannot write to standard output", alpha::ErrorKind::BadInput);
      lines += counts[k];
    }
  }
  flush_stdout();
  spdlog::info("{} persistence pairs", lines);
  return 0;
}

}  // namespace

Subcommand add_persistence_command(CLI::App& app) {
  auto opt = std::make_shared<InputOptions>();
  CLI::App* sub = app.add_subcommand(
      "persistence",
      "Persistence diagram of the alpha filtration: one line 'dim birth_sq death_sq' per pair");
  sub->footer(
      "dim is 0, 1 or 2; birth_sq and death_sq are squared radii (alpha_sq, negative possible with --weighted), "
      "printed so that they read back as the same double; death_sq is 'inf' for a class that never dies. "
      "Pairs born and dying at the same value are left out. Sorted by dim, birth, death.");
  add_input_options(*sub, *opt);
  add_threads_option(*sub, opt->threads);
  return {sub, [opt] { return run_persistence(*opt); }};
}

}  // namespace alphapocket
