// SPDX-License-Identifier: Apache-2.0
// A point set's regular triangulation and its alpha complex, owned together:
// the complex refers to the triangulation, so neither may outlive or move
// away from the other. Both live on the heap; moving this object keeps them
// in place.
#pragma once
#include <memory>
#include <utility>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/geometry.hpp"
#include "alpha/triangulation.hpp"

namespace alpha {

class PointSetComplex {
public:
  // The triangulation of the (weighted) points, then its complex, both on
  // `threads` threads (Triangulation, AlphaComplex). Throws alpha::Error as
  // they do.
  explicit PointSetComplex(std::vector<Vec3> points, std::vector<double> weights = {}, unsigned threads = 1)
      : PointSetComplex(std::make_unique<Triangulation>(std::move(points), std::move(weights), threads), threads) {}
  // The complex of a triangulation already built (to time the two apart).
  explicit PointSetComplex(std::unique_ptr<Triangulation> triangulation, unsigned threads = 1)
      : triangulation_(std::move(triangulation)), complex_(std::make_unique<AlphaComplex>(*triangulation_, threads)) {}

  const Triangulation& triangulation() const { return *triangulation_; }
  const AlphaComplex& complex() const { return *complex_; }

private:
  std::unique_ptr<Triangulation> triangulation_;
  std::unique_ptr<AlphaComplex> complex_;  // refers to *triangulation_
};

}  // namespace alpha
