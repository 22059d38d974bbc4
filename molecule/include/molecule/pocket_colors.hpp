// The colour of a pocket or void, the same in every output (mesh face
// colours, the PyMOL script): a cycle of 12 colours that stay apart from
// each other and from the grey of the molecule, given in the order of the
// binding sites (Cavities::sites), so that the best site is red whether it
// is a pocket or a void.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "molecule/cavities.hpp"
#include "molecule/mesh_export.hpp"

namespace molecule {

inline constexpr std::array<Rgb, 12> kPocketPalette{{
    {228, 26, 28},   // red
    {55, 126, 184},  // blue
    {77, 175, 74},   // green
    {152, 78, 163},  // purple
    {255, 127, 0},   // orange
    {23, 190, 207},  // cyan
    {166, 86, 40},   // brown
    {247, 129, 191}, // pink
    {188, 189, 34},  // olive
    {31, 58, 147},   // navy
    {0, 128, 128},   // teal
    {140, 20, 70},   // wine
}};

// The molecule's own surface.
inline constexpr Rgb kMoleculeColor{200, 200, 200};

// rank counts from 1.
inline Rgb rank_color(std::size_t rank) { return kPocketPalette[(rank - 1) % kPocketPalette.size()]; }

// The colour of each pocket and void (indices as in Cavities): rank_color
// of its site rank, then, for the voids that are not sites, of the ranks
// that follow, in their list's order.
struct CavityColors {
  std::vector<Rgb> pockets, voids;
};
inline CavityColors cavity_colors(const Cavities& cavities) {
  CavityColors out{std::vector<Rgb>(cavities.pockets.size()), std::vector<Rgb>(cavities.voids.size())};
  std::vector<bool> void_is_site(cavities.voids.size(), false);
  std::size_t rank = 0;
  for (const Site& s : cavities.sites) {
    (s.is_void ? out.voids : out.pockets).at(s.index) = rank_color(++rank);
    if (s.is_void) void_is_site[s.index] = true;
  }
  for (std::size_t i = 0; i < cavities.voids.size(); ++i)
    if (!void_is_site[i]) out.voids[i] = rank_color(++rank);
  return out;
}

// A lighter tint of c (its mix with white, 60% white): mouths of a pocket.
inline Rgb mouth_tint(Rgb c) {
  auto tint = [](int v) { return std::uint8_t(v + (255 - v) * 3 / 5); };
  return {tint(c.r), tint(c.g), tint(c.b)};
}

}  // namespace molecule
