// SPDX-License-Identifier: Apache-2.0
// The colour of a pocket or void, the same in every output (mesh face
// colours, the viewer scripts), given in the order of the binding sites
// (Cavities::sites), so that the best site is red whether it is a pocket
// or a void. The first 12 are chosen to stay apart from each other, from
// the grey of the molecule, the cyan of the tunnels and the yellow of the
// ligands; after them come hues around the colour wheel (the golden angle
// apart) in six shades: no colour repeats among the first 250.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "molecule/cavities.hpp"
#include "molecule/mesh_export.hpp"

namespace molecule {

inline constexpr std::array<Rgb, 12> kPocketPalette{{
    {228, 26, 28},    // red
    {55, 126, 184},   // blue
    {77, 175, 74},    // green
    {152, 78, 163},   // purple
    {255, 127, 0},    // orange
    {247, 129, 191},  // pink
    {166, 86, 40},    // brown
    {31, 58, 147},    // navy
    {140, 20, 70},    // wine
    {166, 216, 84},   // lime
    {202, 178, 214},  // lavender
    {0, 100, 60},     // dark green
}};

// The molecule's own surface, the tunnels' bottlenecks, the ligands' carbons.
inline constexpr Rgb kMoleculeColor{200, 200, 200};
inline constexpr Rgb kTunnelColor{0, 255, 255};
inline constexpr Rgb kLigandColor{255, 255, 0};

// hue in sextants of the colour wheel [0, 6), saturation and value in [0, 1].
inline Rgb hsv_color(double hue, double saturation, double value) {
  const double chroma = value * saturation, x = chroma * (1 - std::fabs(std::fmod(hue, 2) - 1)), m = value - chroma;
  double r = 0, g = 0, b = 0;
  switch (int(hue)) {
    case 0: r = chroma, g = x; break;
    case 1: r = x, g = chroma; break;
    case 2: g = chroma, b = x; break;
    case 3: g = x, b = chroma; break;
    case 4: r = x, b = chroma; break;
    default: r = chroma, b = x; break;
  }
  const auto byte = [m](double v) { return std::uint8_t(std::lround((v + m) * 255)); };
  return {byte(r), byte(g), byte(b)};
}

// The colour of tunnel or pore k (from 0) in the viewer scripts: the cyan
// family of the tunnels' bottlenecks, apart from the sites' first 12
// colours; hues from 172 to 201 degrees (11 apart, modulo 30) in four
// shades and two saturations, so the first 30 differ.
inline Rgb tunnel_color(std::size_t k) {
  static constexpr double kValue[] = {0.95, 0.7, 0.85, 0.6}, kSaturation[] = {1.0, 0.55};
  return hsv_color((172 + double(k * 11 % 30)) / 60, kSaturation[(k / 4) % 2], kValue[k % 4]);
}

// rank counts from 1.
inline Rgb rank_color(std::size_t rank) {
  if (rank >= 1 && rank <= kPocketPalette.size()) return kPocketPalette[rank - 1];
  const std::size_t k = rank - kPocketPalette.size();
  const double hue = std::fmod(double(k) * 0.3819660112501051, 1.0) * 6;  // golden angle, in sextants
  const double value = 0.95 - 0.25 * double((k / 7) % 3), saturation = 0.75 - 0.2 * double((k / 3) % 2);
  return hsv_color(hue, saturation, value);
}

// The colour rank of each pocket and void (indices as in Cavities): its
// site rank, then, for the pockets and then the voids that are not sites,
// the ranks that follow, in their lists' order.
struct CavityRanks {
  std::vector<std::size_t> pockets, voids;
};
inline CavityRanks cavity_ranks(const Cavities& cavities) {
  CavityRanks out{std::vector<std::size_t>(cavities.pockets.size()), std::vector<std::size_t>(cavities.voids.size())};
  std::size_t rank = 0;
  for (const Site& s : cavities.sites) (s.is_void ? out.voids : out.pockets).at(s.index) = ++rank;
  for (std::vector<std::size_t>* list : {&out.pockets, &out.voids})
    for (std::size_t& r : *list)
      if (r == 0) r = ++rank;
  return out;
}

// rank_color of each pocket's and void's colour rank.
struct CavityColors {
  std::vector<Rgb> pockets, voids;
};
inline CavityColors cavity_colors(const Cavities& cavities) {
  const CavityRanks ranks = cavity_ranks(cavities);
  CavityColors out;
  for (std::size_t r : ranks.pockets) out.pockets.push_back(rank_color(r));
  for (std::size_t r : ranks.voids) out.voids.push_back(rank_color(r));
  return out;
}

// A lighter tint of c (its mix with white, 60% white): mouths of a pocket.
inline Rgb mouth_tint(Rgb c) {
  auto tint = [](int v) { return std::uint8_t(v + (255 - v) * 3 / 5); };
  return {tint(c.r), tint(c.g), tint(c.b)};
}

}  // namespace molecule
