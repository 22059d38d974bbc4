// SPDX-License-Identifier: Apache-2.0
#include "molecule/ligandability_model.hpp"

#include <algorithm>
#include <charconv>
#include <initializer_list>
#include <string>
#include <type_traits>
#include <utility>

#include "alpha/error.hpp"
#include "molecule/site_features.hpp"

namespace molecule {

// Generated at build time from molecule/data/ligandability.json.
extern const char* const kLigandabilityModelJson;

namespace {

[[noreturn]] void fail_model(const std::string& what, alpha::ErrorKind kind) {
  alpha::fail("ligandability model: " + what, kind);
}

// Reads the JSON a model file is: objects, arrays, strings without escapes
// and numbers. Not nlohmann's parser: its document of a bagged model's
// 1000 trees cost 7 % of a run's instructions.
class Reader {
public:
  explicit Reader(std::string_view text) : text_(text) {}

  // Whether the next character after white space is c (then consumed).
  bool accept(char c) {
    skip_space();
    if (at_ == text_.size() || text_[at_] != c) return false;
    ++at_;
    return true;
  }
  void expect(char c) {
    if (!accept(c))
      fail_model(std::string("expected '") + c + "' at byte " + std::to_string(at_), alpha::ErrorKind::BadInput);
  }
  void finish() {
    skip_space();
    if (at_ != text_.size())
      fail_model("text after the model at byte " + std::to_string(at_), alpha::ErrorKind::BadInput);
  }

  std::string_view string() {
    expect('"');
    const std::size_t start = at_;
    at_ = text_.find_first_of("\"\\", at_);
    if (at_ == std::string_view::npos || text_[at_] != '"')
      fail_model("a string is not closed or has an escape", alpha::ErrorKind::BadInput);
    return text_.substr(start, at_++ - start);
  }
  template <class T>
  T value() {
    if constexpr (std::is_same_v<T, std::string>) {
      return std::string(string());
    } else {
      skip_space();
      T x{};
      const auto [end, error] = std::from_chars(text_.data() + at_, text_.data() + text_.size(), x);
      if (error != std::errc())
        fail_model("expected a number at byte " + std::to_string(at_), alpha::ErrorKind::BadInput);
      at_ = end - text_.data();
      return x;
    }
  }
  // An array into `out` (cleared first: a buffer reused).
  template <class T>
  void array(std::vector<T>& out) {
    out.clear();
    expect('[');
    if (accept(']')) return;
    do out.push_back(value<T>());
    while (accept(','));
    expect(']');
  }
  // Calls read(key) with the reader at each key's value; fails unless all
  // of `required` were there.
  template <class Read>
  void object(std::initializer_list<std::string_view> required, Read&& read) {
    unsigned seen = 0;
    expect('{');
    if (!accept('}')) {
      do {
        const std::string_view key = string();
        expect(':');
        const auto known = std::find(required.begin(), required.end(), key);
        if (known != required.end()) seen |= 1u << (known - required.begin());
        read(key);
      } while (accept(','));
      expect('}');
    }
    for (std::size_t k = 0; k < required.size(); ++k)
      if (!(seen >> k & 1)) fail_model("no \"" + std::string(required.begin()[k]) + "\"", alpha::ErrorKind::BadInput);
  }

private:
  void skip_space() {
    while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\n' || text_[at_] == '\r' || text_[at_] == '\t'))
      ++at_;
  }

  std::string_view text_;
  std::size_t at_ = 0;
};

}  // namespace

namespace {

// Reads a tree into `trees` (its nodes after those of the trees before).
void read_tree(Reader& in, LigandabilityModel::Trees& trees) {
  const int features = int(site_feature_names().size());
  std::vector<int> feature, left, right;
  std::vector<double> threshold, value;
  in.object({"feature", "left", "right", "threshold", "value"}, [&](std::string_view key) {
    if (key == "feature") in.array(feature);
    else if (key == "left") in.array(left);
    else if (key == "right") in.array(right);
    else if (key == "threshold") in.array(threshold);
    else if (key == "value") in.array(value);
    else
      fail_model("a tree has \"" + std::string(key) + "\"", alpha::ErrorKind::BadInput);
  });
  const std::size_t n = feature.size();
  if (n == 0 || left.size() != n || right.size() != n || threshold.size() != n || value.size() != n)
    fail_model("a tree's arrays differ in length", alpha::ErrorKind::BadInput);
  trees.roots.push_back(trees.nodes.size());
  for (std::size_t k = 0; k < n; ++k) {
    // Children come after their parent: every walk ends.
    if (left[k] >= 0 && (feature[k] < 0 || feature[k] >= features || left[k] <= int(k) || right[k] <= int(k) ||
                         left[k] >= int(n) || right[k] >= int(n)))
      fail_model("a tree node is out of range", alpha::ErrorKind::BadInput);
    trees.nodes.push_back({feature[k], left[k], right[k], threshold[k], value[k]});
  }
}

// Reads the value of a "trees" key: an array of trees.
void read_trees(Reader& in, LigandabilityModel::Trees& trees) {
  in.expect('[');
  if (!in.accept(']')) {
    do read_tree(in, trees);
    while (in.accept(','));
    in.expect(']');
  }
}

}  // namespace

LigandabilityModel::LigandabilityModel(std::string_view text) {
  Reader in(text);
  in.object({"features", "init", "scale", "trees", "calibration"}, [&](std::string_view key) {
    if (key == "features") {
      std::vector<std::string> names;
      in.array(names);
      if (names != site_feature_names())
        fail_model("its features are not this version's site features", alpha::ErrorKind::BadInput);
    } else if (key == "init") {
      classifier_.init = in.value<double>();
    } else if (key == "scale") {
      classifier_.scale = in.value<double>();
    } else if (key == "trees") {
      read_trees(in, classifier_);
    } else if (key == "ranking") {
      Trees ranking;
      in.object({"init", "scale", "trees"}, [&](std::string_view k) {
        if (k == "init") ranking.init = in.value<double>();
        else if (k == "scale") ranking.scale = in.value<double>();
        else if (k == "trees") read_trees(in, ranking);
        else
          fail_model("the ranking has \"" + std::string(k) + "\"", alpha::ErrorKind::BadInput);
      });
      ranking_ = std::move(ranking);
    } else if (key == "calibration") {
      in.object({"x", "y"}, [&](std::string_view k) {
        if (k == "x") in.array(knots_x_);
        else if (k == "y") in.array(knots_y_);
        else
          fail_model("the calibration has \"" + std::string(k) + "\"", alpha::ErrorKind::BadInput);
      });
    } else {
      in.string();  // format, kind, trained_on: notes
    }
  });
  in.finish();
  if (knots_x_.empty() || knots_x_.size() != knots_y_.size() || !std::is_sorted(knots_x_.begin(), knots_x_.end()))
    fail_model("the calibration's knots are not sorted pairs", alpha::ErrorKind::BadInput);
}

double LigandabilityModel::Trees::margin(const std::vector<double>& features) const {
  if (features.size() != site_feature_names().size()) fail_model("wrong number of features", alpha::ErrorKind::Misuse);
  double sum = 0;
  for (const std::size_t root : roots) {
    const Node* tree = &nodes[root];
    int k = 0;
    while (tree[k].left >= 0)
      k = double(float(features[tree[k].feature])) <= tree[k].threshold ? tree[k].left : tree[k].right;
    sum += tree[k].value;
  }
  return init + scale * sum;
}

double LigandabilityModel::margin(const std::vector<double>& features) const { return classifier_.margin(features); }

double LigandabilityModel::rank_score(const std::vector<double>& features) const {
  return (ranking_ ? *ranking_ : classifier_).margin(features);
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
  // Immutable once built. The compiled-in model is no caller's input: one
  // that does not parse is a broken build (Internal), not bad input.
  static const LigandabilityModel kModel = [] {
    try {
      return LigandabilityModel(kLigandabilityModelJson);
    } catch (const alpha::Error& e) {
      throw alpha::Error(e.what(), alpha::ErrorKind::Internal);
    }
  }();
  return kModel;
}

}  // namespace molecule
