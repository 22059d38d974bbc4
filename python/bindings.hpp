// SPDX-License-Identifier: Apache-2.0
// What the binding files of alphapocket/_core share: numpy arrays of
// doubles, the options of `alphapocket pockets` by the CLI's names
// (module.cpp), and each topic's bindings added to the module.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "molecule/analysis.hpp"

namespace alphapocket_python {

using Points = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

// Throws alpha::Error (misuse) naming the option for a value out of range.
molecule::AnalysisOptions analysis_options(const pybind11::dict& options);

// track_frames and TrackResult (track.cpp).
void add_track(pybind11::module_& m);

}  // namespace alphapocket_python
