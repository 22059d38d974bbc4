// The colour of a pocket or void by its rank, the same in every output
// (mesh face colours, the PyMOL script): a cycle of 12 colours that stay
// apart from each other and from the grey of the molecule.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

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

// A lighter tint of c (its mix with white, 60% white): mouths of a pocket.
inline Rgb mouth_tint(Rgb c) {
  auto tint = [](int v) { return std::uint8_t(v + (255 - v) * 3 / 5); };
  return {tint(c.r), tint(c.g), tint(c.b)};
}

}  // namespace molecule
