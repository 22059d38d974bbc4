// SPDX-License-Identifier: Apache-2.0
// The whole pocket search (molecule::analyse_content: read, alpha complex,
// cavities, ranking, tunnels; no meshes) on arbitrary bytes, mostly small
// mutated structures. Properties: an error is an AnalysisError with a
// one-line message naming the file, and a bad_input or limit_exceeded
// category (internal means a bug); a result's report has finite volumes.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.hpp"
#include "molecule/analysis.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string name = "fuzz.pdb";
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  molecule::AnalysisOptions options;
  options.max_atoms = 2000;  // keeps one input well under a second
  options.outputs.meshes = false;  // meshes cost 10-20 times the search: inputs would run past the timeout
  try {
    const molecule::Analysis a = molecule::analyse_content(name, bytes, options);
    const molecule::Cavities& c = a.search.cavities;
    fuzz::check(std::isfinite(c.sa_volume) && c.sa_volume > 0, "the SA volume is not finite and > 0");
    for (const auto* list : {&c.pockets, &c.voids})
      for (const molecule::Cavity& cavity : *list)
        fuzz::check(std::isfinite(cavity.sa_volume) && cavity.sa_volume >= 0 && std::isfinite(cavity.ms_volume) &&
                        cavity.ms_volume >= 0,
                    "a cavity volume is not finite and >= 0");
  } catch (const molecule::AnalysisError& e) {
    fuzz::check_message(e.what(), name);
    fuzz::check(e.kind() != molecule::FailureKind::Internal, "an internal error", e.what());
  }
  return 0;
}
