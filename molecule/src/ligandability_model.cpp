// SPDX-License-Identifier: Apache-2.0
#include "molecule/ligandability_model.hpp"

#include <algorithm>
#include <exception>

#include <nlohmann/json.hpp>

#include "alpha/error.hpp"
#include "molecule/site_features.hpp"

namespace molecule {

// Generated at build time from molecule/data/ligandability.json.
extern const char* const kLigandabilityModelJson;

LigandabilityModel::LigandabilityModel(std::string_view text) {
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    if (j.at("features").get<std::vector<std::string>>() != site_feature_names())
      alpha::fail("ligandability model: its features are not this version's site features");
    init_ = j.at("init").get<double>();
    scale_ = j.at("scale").get<double>();
    const int features = int(site_feature_names().size());
    for (const auto& t : j.at("trees")) {
      Tree tree{t.at("feature"), t.at("left"), t.at("right"), t.at("threshold"), t.at("value")};
      const std::size_t n = tree.feature.size();
      if (n == 0 || tree.left.size() != n || tree.right.size() != n || tree.threshold.size() != n ||
          tree.value.size() != n)
        alpha::fail("ligandability model: a tree's arrays differ in length");
      for (std::size_t k = 0; k < n; ++k) {
        const bool leaf = tree.left[k] < 0;
        // Children come after their parent: every walk ends.
        if (!leaf && (tree.feature[k] < 0 || tree.feature[k] >= features || tree.left[k] <= int(k) ||
                      tree.right[k] <= int(k) || tree.left[k] >= int(n) || tree.right[k] >= int(n)))
          alpha::fail("ligandability model: a tree node is out of range");
      }
      trees_.push_back(std::move(tree));
    }
    knots_x_ = j.at("calibration").at("x").get<std::vector<double>>();
    knots_y_ = j.at("calibration").at("y").get<std::vector<double>>();
    if (knots_x_.empty() || knots_x_.size() != knots_y_.size() || !std::is_sorted(knots_x_.begin(), knots_x_.end()))
      alpha::fail("ligandability model: the calibration's knots are not sorted pairs");
  } catch (const nlohmann::json::exception& e) {
    alpha::fail(std::string("ligandability model: ") + e.what());
  }
}

double LigandabilityModel::margin(const std::vector<double>& features) const {
  if (features.size() != site_feature_names().size()) alpha::fail("ligandability model: wrong number of features");
  double sum = 0;
  for (const Tree& t : trees_) {
    int k = 0;
    while (t.left[k] >= 0) k = double(float(features[t.feature[k]])) <= t.threshold[k] ? t.left[k] : t.right[k];
    sum += t.value[k];
  }
  return init_ + scale_ * sum;
}

double LigandabilityModel::probability(double m) const {
  if (m <= knots_x_.front()) return knots_y_.front();
  if (m >= knots_x_.back()) return knots_y_.back();
  const std::size_t j = std::upper_bound(knots_x_.begin(), knots_x_.end(), m) - knots_x_.begin() - 1;
  const double dx = knots_x_[j + 1] - knots_x_[j];
  if (dx <= 0) return knots_y_[j + 1];
  return knots_y_[j] + (knots_y_[j + 1] - knots_y_[j]) / dx * (m - knots_x_[j]);
}

const LigandabilityModel& default_ligandability_model() {
  static const LigandabilityModel kModel(kLigandabilityModelJson);  // immutable once built
  return kModel;
}

}  // namespace molecule
