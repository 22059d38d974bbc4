// SPDX-License-Identifier: Apache-2.0
// alphapocket spectrum FILE [--weighted] [--alpha-sq V ...] [--json]
//
// The alpha spectrum of a point or structure file: its size, the optimal
// alpha (the smallest critical value at which the shape is one connected
// component holding every vertex), and at each requested alpha the
// classification counts, Betti numbers, volume and area of the shape.
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>

#include "alpha/alpha_complex.hpp"
#include "commands.hpp"
#include "common.hpp"

namespace alphapocket {
namespace {

struct SpectrumOptions {
  InputOptions input;
  std::vector<double> alpha_sq;
  bool json = false;
};

constexpr const char* kDimensionNames[4] = {"vertices", "edges", "triangles", "tetrahedra"};

// The shape at one alpha; level = number of critical values <= alpha_sq.
struct Sample {
  double alpha_sq;
  alpha::Index level;
};

nlohmann::ordered_json sample_json(const alpha::AlphaComplex& ac, const Sample& s) {
  nlohmann::ordered_json j;
  j["alpha_sq"] = s.alpha_sq;
  const alpha::ClassCounts counts = ac.counts(s.level);
  for (int d = 0; d < 4; ++d) {
    nlohmann::ordered_json c;
    for (int k = 0; k < 4; ++k) c[alpha::to_string(alpha::Classification(k))] = counts[d][k];
    j[kDimensionNames[d]] = c;
  }
  const auto betti = ac.betti(s.level);
  j["betti"] = betti;
  j["components"] = betti[0];
  j["volume"] = ac.volume(s.level);
  j["area"] = ac.area(s.level);
  return j;
}

void print_summary(const alpha::AlphaComplex& ac, const Sample& s) {
  const auto betti = ac.betti(s.level);
  std::printf("%s", fmt::format("alpha_sq {}: betti {} {} {}, components {}, volume {:.6g}, area {:.6g}\n",
                                printable(s.alpha_sq), betti[0], betti[1], betti[2], betti[0],
                                ac.volume(s.level), ac.area(s.level))
                        .c_str());
  const alpha::ClassCounts counts = ac.counts(s.level);
  for (int d = 0; d < 4; ++d) {
    std::string line = fmt::format("  {:<11}", kDimensionNames[d]);
    for (int k = 0; k < 4; ++k)
      line += fmt::format("{}{} {}", k ? ", " : "", alpha::to_string(alpha::Classification(k)), counts[d][k]);
    std::printf("%s\n", line.c_str());
  }
}

int run_spectrum(const SpectrumOptions& opt) {
  const AlphaInput in = load_alpha_complex(opt.input);
  const alpha::AlphaComplex& ac = in.shape.complex();
  const alpha::Triangulation& t = in.shape.triangulation();

  // optimal_level() >= 1: the critical value that completes the shape is
  // critical value number optimal - 1. Users feed the printed value back
  // through --alpha-sq, so it must reach that level: the nearest double may
  // lie a hair below the exact value, and then the next double does not.
  const alpha::Index optimal = ac.optimal_level();
  double optimal_alpha_sq = ac.spectrum_value(optimal - 1);
  if (ac.level(optimal_alpha_sq) < optimal)
    optimal_alpha_sq = std::nextafter(optimal_alpha_sq, std::numeric_limits<double>::infinity());
  optimal_alpha_sq = printable(optimal_alpha_sq);
  std::vector<Sample> samples;
  for (double a : opt.alpha_sq) samples.push_back({printable(a), ac.level(a)});
  if (samples.empty()) samples.push_back({optimal_alpha_sq, optimal});

  if (opt.json) {
    nlohmann::ordered_json j;
    j["points"] = in.points;
    j["vertices"] = t.num_vertices();
    j["spectrum_size"] = ac.spectrum_size();
    j["optimal_alpha_sq"] = optimal_alpha_sq;
    j["at"] = nlohmann::ordered_json::array();
    for (const Sample& s : samples) j["at"].push_back(sample_json(ac, s));
    std::printf("%s\n", j.dump().c_str());
  } else {
    std::printf("%s", fmt::format("{}: {} points, {} vertices, {} critical values of alpha_sq from {} to {}\n",
                                  opt.input.file, in.points, t.num_vertices(), ac.spectrum_size(),
                                  printable(ac.spectrum_value(0)),
                                  printable(ac.spectrum_value(alpha::Index(ac.spectrum_size() - 1))))
                          .c_str());
    std::printf("%s", fmt::format("optimal alpha_sq: {} (one component holding every vertex)\n", optimal_alpha_sq)
                          .c_str());
    for (const Sample& s : samples) print_summary(ac, s);
  }
  flush_stdout();
  return 0;
}

}  // namespace

Subcommand add_spectrum_command(CLI::App& app) {
  auto opt = std::make_shared<SpectrumOptions>();
  CLI::App* sub = app.add_subcommand(
      "spectrum",
      "Alpha spectrum: its size, the optimal alpha, and the shape at given alphas (classification counts, "
      "Betti numbers, volume, area)");
  sub->footer(kAlphaSqHelp);
  add_input_options(*sub, opt->input);
  sub->add_option("--alpha-sq", opt->alpha_sq,
                  "Squared radius at which to report the shape; repeatable, may be negative "
                  "(default: the optimal alpha_sq, the smallest at which the shape is one component "
                  "holding every vertex)")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->check(finite_number());
  sub->add_flag("--json", opt->json, "Print one JSON object on stdout instead of a summary");
  return {sub, [opt] { return run_spectrum(*opt); }};
}

}  // namespace alphapocket
