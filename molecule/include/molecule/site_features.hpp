// SPDX-License-Identifier: Apache-2.0
// What the ligandability model (molecule/ligandability_model.hpp) knows of
// a cavity: a fixed list of numbers, its geometry as find_cavities measured
// it and the chemistry of the atoms lining it, the evidence P2Rank uses.
//
// Geometry: SA and MS volume and area, mouths (count, to the outside, total
// and largest area), buriedness, depth, the widest probe (max_probe_radius,
// max_alpha_sq), the basin's persistence (fill minus close alpha_sq),
// tetrahedra, sinks, lining atoms and residues; the burial count (atoms
// within R of the centre) at R = 6, 8, 10, 12, 14 (Cavity::burial_atoms),
// 16 and 20 A; the centre's clearance (distance to the nearest atom's van
// der Waals sphere) and its distance from the molecule's centroid over the
// molecule's radius of gyration; the geometric score's log and rank.
// Context within the structure (the model compares sites across
// structures, where only relative values carry over): the log score and
// the 14 A burial count minus the best among the structure's sites, the
// number of candidate sites (site_candidates) and of atoms.
// Chemistry of the lining atoms: fractions of C, N, O, S, of backbone,
// aromatic-ring, H-bond donor and acceptor, positively and negatively
// charged atoms (by residue and atom name, standard amino acids); of the
// lining residues: fractions hydrophobic (AVLIMFWC), aromatic (FWYH),
// polar (STNQ), positive (KRH), negative (DE), Gly, Pro, and their mean
// Kyte-Doolittle hydropathy; the lining atoms' mean B-factor as a z-score
// within their chain (0 where the chain's B-factors are all equal).
// The whole entry (PDB entries of several chains, cofactors, ions): the
// chains lining the cavity and the share of its lining atoms outside the
// main one (a site between chains), the other chains holding the same site
// (a candidate whose residues, by name and number, are at least half the
// same: a homo-oligomer's copies), the metal ions (one-atom hetero groups,
// whether kept or not) within 8 A of the centre, the cavity's share of the
// molecule's SA area and the structure's chains. Other hetero groups are
// no evidence here: in COACH420's files the ligand itself is one.
#pragma once
#include <string>
#include <vector>

#include "alpha/point_grid.hpp"
#include "molecule/cavities.hpp"
#include "molecule/structure.hpp"

namespace molecule {

// The features' names, in the order site_features gives them.
const std::vector<std::string>& site_feature_names();

// Measures the cavities of one structure (find_cavities of its atoms, so
// that lining atom indices are indices into structure.atoms).
class SiteFeatures {
public:
  SiteFeatures(const Structure& structure, const Cavities& cavities);
  // The features of a pocket or void of `cavities`.
  std::vector<double> operator()(const Cavity& cavity) const;

private:
  const Structure& structure_;
  const Cavities& cavities_;
  alpha::PointGrid atoms_;
  alpha::Vec3 centroid_{};
  double gyration_radius_ = 0;
  std::vector<double> b_zscore_;  // per atom
  std::vector<double> candidate_scores_;  // of site_candidates(cavities)
  double best_log_score_ = 0, best_burial_ = 0;
  // Per candidate: its main chain and its residues (name, number).
  std::vector<std::string> candidate_chains_;
  std::vector<std::vector<std::pair<std::string, int>>> candidate_residues_;
  std::size_t chains_ = 0;            // of the structure's atoms
  std::vector<alpha::Vec3> metals_;   // metal ions among the hetero groups

  std::vector<std::pair<std::string, int>> residue_keys(const Cavity& c) const;
};

// The features of every pocket, then every void, as CSV with a header:
// kind, cavity_rank, site_rank (0: not a site), centre, then the features
// and the cavity's ligandability (the model's margin), probability and
// rank_score, at
// full precision (for training/, which labels the rows by the centre and
// checks that scikit-learn predicts the same margins).
std::string site_features_csv(const Structure& structure, const Cavities& cavities);

}  // namespace molecule
