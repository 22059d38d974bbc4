// SPDX-License-Identifier: Apache-2.0
// Cavities of a molecule found on the weighted alpha complex of its atoms
// (balls of radius r_i + probe, alpha_sq = 0: the solvent-accessible model).
//
// Pockets and voids are regions of EMPTY tetrahedra (not in the complex at
// alpha_sq = 0), grouped by the discrete flow of Edelsbrunner, Facello &
// Liang (1998) (alpha/discrete_flow.hpp): an empty tetrahedron flows into
// its neighbour across a facet that separates it from its orthocenter,
// when that facet is empty too. Tetrahedra that flow to the outside (the
// infinite cells) are outside; the others drain to finite sinks, and sink
// regions joined through empty facets form one region (a CASTp pocket or
// void). A region with empty facets towards the outside is a pocket; one
// without is a VOID (an enclosed cavity: the voids are counted by b2).
//
// A CASTp pocket can be a long groove or a wide cleft holding several
// binding sites, so it is split into POCKETS (alpha/persistent_basins.hpp,
// the basins of its largest empty spheres) at two kinds of passage:
// - where it narrows: a basin whose widest orthosphere's radius exceeds
//   that of the passage into its neighbour by more than
//   CavityOptions::split_persistence stays apart;
// - where it outgrows a ligand site: two parts that each hold at least
//   CavityOptions::split_min_volume of free space (a fragment's site) and
//   together more than CavityOptions::split_volume (a drug-sized ligand's
//   site) stay apart, however wide the passage between them, unless the
//   smaller one's widest cell flows into the other.
// Each pocket opens to the outside or to a neighbouring pocket of the same
// region through its mouths. With infinite split_persistence and
// split_volume the pockets are exactly CASTp's.
//
// TUNNELS are 1-cycles of the complex alive at alpha_sq = 0 that die later.
//
// SITES, the candidate ligand-binding sites, rank the pockets and the voids
// large enough to hold a ligand together (Cavities::sites).
//
// Too small to hold the probe: sa_volume is the space the probe's centre
// can reach in the cavity (points farther than r_i + probe from every atom
// centre). Cavities whose sa_volume is below CavityOptions::min_volume are
// dropped (default 1 A^3: in less the probe's centre cannot move half an
// Angstrom every way). The small dents are kept as candidate sites for the
// ligandability model to rank: on pockets-train, a ligand often lies over
// one (1 instead of 4 A^3 puts a site centre within 4 A of 7 more of its
// 225 ligands, 173 to 180), and the model gives most of them a low
// probability; search_pockets leaves such sites out (kMinSiteProbability).
// With min_volume = 0 the voids are exactly the b2 classes at alpha_sq = 0.
//
// All values here are in Angstrom (lengths), Angstrom^2 and Angstrom^3, or
// squared Angstrom for alpha_sq values (as everywhere in alphapocket).
#pragma once
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "alpha/alpha_complex.hpp"
#include "alpha/eroded_union.hpp"
#include "alpha/geometry.hpp"
#include "alpha/union_of_balls.hpp"

namespace molecule {

// One mouth: a connected set (through shared edges) of the empty triangles
// a pocket shares with the outside, or with a neighbouring pocket split
// from the same region.
struct Mouth {
  std::vector<alpha::Index> triangles;  // alpha::Simplices triangle ids, sorted
  // Solvent-accessible area of the opening: the triangles' area not covered
  // by the inflated balls' discs in their planes (fractional
  // inclusion-exclusion per triangle, as for the cells), A^2.
  double area = 0;
  bool to_outside = true;  // false: opens into a neighbouring pocket
};

struct Cavity {
  std::vector<alpha::Index> cells;  // empty tetrahedra (triangulation cell ids), sorted
  std::vector<Mouth> mouths;        // empty for a void; outside mouths first
  // Empty space of the cells not covered by the probe-inflated balls (the
  // space the probe's centre can reach), A^3: the cells less the union's
  // part in each (alpha::UnionOfBalls::cell_cover, exact per cell).
  double sa_volume = 0;
  double sa_area = 0;  // area of the probe-inflated spheres lining the cavity, A^2 (same split)
  // The same bounded by the molecular (solvent-excluded) surface instead of
  // the SA surface (alpha::ErodedUnion): ms_volume adds to sa_volume the
  // probe layer under the cavity's wall (the points within one probe
  // radius of the cavity's SA space, nearest to it), ms_area is the
  // molecular surface lining the cavity. The layer and that surface are
  // split by regions of space (each point to the cell whose cone, wedge or
  // side holds its nearest SA point: alpha::ErodedUnion::cell_share), the
  // sa_volume part as above.
  double ms_volume = 0;  // A^3
  double ms_area = 0;    // A^2
  // Largest distance of a cell centroid from the outside mouths of the
  // cavity's region (0 for voids), A.
  double depth = 0;
  alpha::Vec3 center{};  // the cells' centroids weighted by their free volume
  std::vector<alpha::Index> lining_atoms;  // input point (atom) indices of the cells' vertices, sorted
  // The cells where the discrete flow ends (their orthocentre inside them),
  // sorted: where the largest probes sit.
  std::vector<alpha::Index> sinks;
  // Squared radius of the largest probe the cavity can hold: the largest
  // orthosphere size among its cells (alpha_sq of the cell that fills last).
  double max_alpha_sq = 0;
  // The largest probe centred at the orthocentre of the cell that fills
  // last (the centre of the cavity's widest empty sphere): its distance to
  // the nearest atom's van der Waals sphere, A; > probe.
  double max_probe_radius = 0;
  // The cavity on the spectrum: it is cut off from the outside (no path of
  // empty cells through absent triangles leads from any of its cells to
  // the unbounded space) for close_alpha_sq <= alpha_sq, and filled for
  // alpha_sq >= fill_alpha_sq. A void has close_alpha_sq <= 0 (how far the
  // balls can shrink before it opens to the solvent); a pocket closes at
  // some alpha_sq > 0 if its mouths seal before its cells fill, and has
  // close_alpha_sq == fill_alpha_sq if it never does.
  // fill_alpha_sq == max_alpha_sq (the last cell's size).
  double close_alpha_sq = 0;
  double fill_alpha_sq = 0;
  double mouth_area = 0;  // sum of the mouths' areas, A^2 (0 for a void)
  // Share of the cavity's wall that is molecule rather than opening:
  // sa_area / (sa_area + mouth_area); 1 for a void.
  double buriedness = 1;
  // Atoms (input points) within CavityOptions::burial_radius of the centre:
  // how deep in the molecule the cavity lies (P2Rank's "protrusion").
  std::size_t burial_atoms = 0;
  double score = 0;  // geometric ranking score, larger is better (see cavity_score)
  // The ligandability model's margin and its calibrated probability that a
  // ligand binds here (molecule/ligandability_model.hpp), set by
  // search_pockets (find_cavities leaves them NaN); rank_score, the model's
  // score that orders the sites (its ranking ensemble's margin).
  double ligandability = std::numeric_limits<double>::quiet_NaN();
  double probability = std::numeric_limits<double>::quiet_NaN();
  double rank_score = std::numeric_limits<double>::quiet_NaN();
};

struct Tunnel {
  double birth_alpha_sq = 0;  // when the 1-cycle forms (<= 0: present at alpha_sq = 0)
  double death_alpha_sq = 0;  // when its killing triangle enters (> 0)
  alpha::Index bottleneck_triangle = alpha::kNone;  // the killing triangle (Simplices id)
  // Radius of the largest probe passing through the bottleneck: at the
  // death the triangle's balls, grown to radius sqrt((r_i + probe)^2 +
  // death), just close it, while a probe of radius rho reaches within
  // r_i + rho of atom i; so rho = min over the triangle's atoms of
  // sqrt((r_i + probe)^2 + death) - r_i. Exact for equal radii (then the
  // grown balls are the probe's excluded balls: rho = sqrt(death) for
  // unweighted points); for unequal radii an estimate (grown balls and
  // excluded balls differ slightly); >= probe, A.
  double bottleneck_radius = 0;
  // The centre of that probe: the killing triangle's orthocentre, where the
  // grown balls meet at the death (its power to each lining atom's ball is
  // death_alpha_sq).
  alpha::Vec3 bottleneck_center{};
  std::vector<alpha::Index> lining_atoms;  // vertices of the bottleneck triangle, sorted
};

// A candidate ligand-binding site: a pocket, or a void large enough to
// hold a drug-sized ligand whole (see Cavities::sites).
struct Site {
  bool is_void = false;
  std::size_t index = 0;  // into Cavities::pockets, or Cavities::voids if is_void
  // Where the site's ligand is expected: the cavity's centre, or, ranked
  // by the model, the centre of the cluster the site heads
  // (ranking/site_clusters.hpp).
  alpha::Vec3 center{};
};

// "pocket 3", "void 1": the cavity a site is, by its rank in its list.
std::string site_cavity_name(const Site& site);

struct Cavities {
  // The whole molecule's solvent-accessible model: area and volume of the
  // union of the probe-inflated balls (the union the cavities' shares are
  // split from), A^2 and A^3.
  double sa_area = 0;
  double sa_volume = 0;
  std::vector<Cavity> pockets;  // ranked: best first
  std::vector<Cavity> voids;    // ranked: best first
  std::vector<Tunnel> tunnels;  // by decreasing death_alpha_sq (widest bottleneck first)
  // Where a ligand may bind, best first: every pocket, and every void that
  // holds a ligand (holds_ligand: a drug-sized ligand's free space or a
  // small ligand's MS volume), in one ranking by score (ties: pockets
  // first, then each list's order). A ligand in a pocket may
  // reach out through its mouths, so a pocket of any size can be a site;
  // an enclosed cavity must hold the whole ligand, and smaller voids are
  // packing defects and water sites. Holo structures often close a lid over
  // their ligand, so a site can be a void once the ligand is removed.
  // (search_pockets leaves out the pockets of a low probability and may
  // rank the sites by the model instead.)
  std::vector<Site> sites;

  const Cavity& cavity(const Site& site) const { return (site.is_void ? voids : pockets).at(site.index); }
};

// Free space (sa_volume, A^3) of the site of a drug-sized ligand of some
// 20-30 heavy atoms: on pockets-dev, pockets that one ligand fills hold
// 5-8 A^3 of it per heavy atom (1bzyA, 1e3vA, 1exaA, 5stdA). The score's
// volume cap, the size rule's default and the smallest void that is a site.
inline constexpr double kLigandSiteVolume = 150;

// Molecular-surface volume (A^3) of the smallest void that holds a ligand
// of about six heavy atoms: benzene in T4 lysozyme L99A (PDB 181L) fills a
// void of 209 A^3 MS volume that has only 17.9 A^3 of free (sa_volume)
// space, far below kLigandSiteVolume. On the training data such voids are
// rare (docs/ranking.md).
inline constexpr double kLigandVoidVolume = 150;

// Whether a void can hold a ligand: sa_volume of at least
// kLigandSiteVolume (a drug-sized ligand) or ms_volume of at least
// kLigandVoidVolume (a small one). Such a void is a site whatever its
// probability (search_pockets), ranked with the pockets.
bool holds_ligand(const Cavity& void_cavity);

// The cavities the ligandability model compares a site with (its context,
// molecule/site_features.hpp): every pocket, then every void of at least
// kLigandSiteVolume, each list in its order.
std::vector<Site> site_candidates(const Cavities& cavities);

struct CavityOptions {
  double probe = 1.4;       // A; the complex must be built with radii r_i + probe
  double min_volume = 1;    // A^3; pockets and voids with sa_volume below it are dropped
  // A (orthosphere radius): a region's basins stay separate pockets when
  // their widest sphere's radius exceeds the passage's by this much
  // (infinity, with an infinite split_volume: CASTp's whole pockets).
  // Calibrated on pockets-dev.
  double split_persistence = 0.25;
  // A^3 of free (sa_volume) space: a ligand site (kLigandSiteVolume) and
  // that of a fragment of 4-6 heavy atoms. Infinite split_volume: no size
  // rule. Chosen from a plateau on pockets-dev (split_min_volume 20-35
  // with split_volume 50-150 all raise DCC and DCA by 1-4 ligands of 51).
  double split_volume = kLigandSiteVolume;
  double split_min_volume = 30;
  double burial_radius = 14;  // A, for Cavity::burial_atoms
  // Threads measuring the cavities (0 counts as 1); the results are the
  // same, bit for bit, for any number.
  unsigned threads = 1;
  bool tunnels = true;  // Cavities::tunnels found (from the complex's persistence pairs)
  // Site::center placed by the ranking (search_pockets: clusters moved onto
  // the buried surface); off, each site's centre is its cavity's.
  bool site_centers = true;
};

// The two bodies find_cavities measures the cavities with: the
// solvent-accessible body (the union of the probe-inflated balls, the
// complex at alpha_sq = 0) and the solvent-excluded body (that union eroded
// by the probe), which the meshes are made of (molecule/pocket_meshes.hpp).
// On the heap: the union refers to the complex and the eroded union to the
// union, so moving this keeps them good; keep the complex alive and in place.
struct SolventBodies {
  std::unique_ptr<const alpha::UnionOfBalls> accessible;
  std::unique_ptr<const alpha::ErodedUnion> excluded;
};

// Cavities of the alpha complex `ac` of the atoms; radii[i] is the van der
// Waals radius of input point i (the complex's weights must be (radii[i] +
// probe)^2). Pockets and voids are ranked by cavity_score. Deterministic;
// throws alpha::Error on inconsistent input (radii count, weights, options).
// With `bodies`, the two bodies it measured with are kept there.
Cavities find_cavities(const alpha::AlphaComplex& ac, const std::vector<double>& radii,
                       const CavityOptions& options, SolventBodies* bodies = nullptr);

// The ranking score of a cavity (larger is better): how likely it is to
// bind a drug-like ligand, from its size and its burial,
//   score = min(sa_volume, kLigandSiteVolume) * (burial_atoms / 600)^12,
// the free space for a ligand weighted steeply by how deep in the protein
// it lies. Space beyond one drug-sized site does not make a better site
// (a pocket that large is one the size rule could not split; on
// pockets-dev the cap moves the hit to rank 1 for one ligand, and any cap
// of 100-150 A^3 does the same). 600 is about the number of heavy atoms that fill a 14 A sphere
// inside a protein (one per ~19 A^3), so the ratio is the share of the
// burial sphere the molecule fills, and 10% fewer atoms around a cavity
// cost it a factor 3.5. The exponent is calibrated on pockets-dev (DCC
// top-1 0.41-0.47 for exponents 8-12); burial outweighs size because
// binding sites are the buried parts of the surface.
double cavity_score(const Cavity& cavity);

// Sets each cavity's score and sorts by decreasing score (ties: the order
// given, which find_cavities makes deterministic).
void rank_cavities(std::vector<Cavity>& cavities);

}  // namespace molecule
