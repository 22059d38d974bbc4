// SPDX-License-Identifier: Apache-2.0
// The ligandability model: how likely a ligand binds in a cavity, from its
// features (molecule/site_features.hpp). An ensemble of decision trees
// (gradient-boosted or a random forest, fitted by training/ on
// pockets-train and pockets-train-pb) gives a margin, init + scale * sum of
// the trees' leaf values; an isotonic map fitted on out-of-fold margins
// turns it into a calibrated probability. A second ensemble, when the model
// has one (its "ranking"), fitted to rank each structure's ligand sites
// above its other candidates, gives the score that orders the sites;
// without one the margin orders them. The model is a JSON file
// (training/ writes it; format in training/README.md); the default one,
// molecule/data/ligandability.json, is compiled into the binary.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace molecule {

class LigandabilityModel {
public:
  // Parses the JSON text; throws alpha::Error when it is not a model or its
  // features are not site_feature_names().
  explicit LigandabilityModel(std::string_view json);

  // The margin of a feature vector (site_feature_names() order). As
  // scikit-learn's trees, a feature is compared with a node's threshold as
  // a float (x_float <= threshold: left).
  double margin(const std::vector<double>& features) const;
  // The calibrated probability of a margin: the isotonic map, linear
  // between its knots, constant beyond them (scikit-learn's
  // IsotonicRegression with out_of_bounds="clip").
  double probability(double margin) const;
  // The score that orders the sites (larger first): the ranking ensemble's
  // margin, or margin() when the model has none.
  double rank_score(const std::vector<double>& features) const;

  // An ensemble of trees and its margin.
  struct Trees {
    struct Node {
      int feature, left, right;  // left -1: a leaf; children indexed within the tree
      double threshold, value;
    };
    std::vector<Node> nodes;        // all trees' nodes, tree by tree
    std::vector<std::size_t> roots;  // where each tree starts in nodes
    double init = 0, scale = 1;
    double margin(const std::vector<double>& features) const;
  };

private:
  Trees classifier_;
  std::optional<Trees> ranking_;
  std::vector<double> knots_x_, knots_y_;
};

// The model compiled into alphapocket (molecule/data/ligandability.json).
const LigandabilityModel& default_ligandability_model();

}  // namespace molecule
