// SPDX-License-Identifier: Apache-2.0
// volumes.svg: the solvent-accessible volume of some pocket tracks over
// time, one line per track in its viewer colour (broken where the pocket
// is absent), with axes and a legend. Plain SVG, readable in any browser.
#pragma once
#include <string>
#include <vector>

#include "molecule/track.hpp"

namespace molecule {

// `tracks`: indices into result.tracks, drawn in rank colours 1, 2, ...
std::string volume_plot_svg(const TrackResult& result, const std::vector<std::size_t>& tracks);

}  // namespace molecule
