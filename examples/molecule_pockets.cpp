// SPDX-License-Identifier: Apache-2.0
// The molecule API on a real protein: read a structure, find its cavities,
// and see where its bound ligand sits among the candidate binding sites.
//
//   molecule_pockets [STRUCTURE [OUTDIR]]
//        (defaults: examples/data/1a26A.pdb, and no files written)
//
// 1A26 chain A (poly(ADP-ribose) polymerase catalytic fragment) comes with
// the inhibitor carba-NAD (residue CNA) bound. The structure reader drops
// hetero groups from the atoms the cavities are computed on, but returns
// them on their own (Structure::hetero_groups), so the ligand's atoms can be
// compared with the pockets found on the empty protein. With OUTDIR, the
// files of `alphapocket pockets` are written there (write_outputs; the
// meshes only when options.outputs.meshes).
// It uses only the installed headers (tests/install/find_package.sh builds
// it against an installed package).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "molecule/analysis.hpp"
#include "molecule/residues.hpp"

namespace {

double distance(const alpha::Vec3& a, const alpha::Vec3& b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

int run(const std::string& file, const std::string& outdir) {
  // 1. The atoms (waters, hydrogens and hetero groups left out, ProtOr
  // radii) and 2. the cavities of the weighted alpha complex (radius +
  // 1.4 A probe) at alpha_sq = 0, ranked; no tunnels.
  molecule::AnalysisOptions options;
  options.tunnels_from = "none";
  const molecule::Analysis analysis = molecule::analyse(file, options);
  const molecule::Structure& structure = analysis.structure;
  const molecule::Cavities& cavities = analysis.search.cavities;
  std::printf("%s: %s\n", file.c_str(), molecule::summary(structure.report).c_str());
  std::printf("solvent-accessible area %.0f A^2, volume %.0f A^3; %zu pockets, %zu voids, %zu tunnels\n",
              cavities.sa_area, cavities.sa_volume, cavities.pockets.size(), cavities.voids.size(),
              cavities.tunnels.size());
  // The candidate binding sites: every pocket and each void large enough to
  // hold a drug-sized ligand, in one ranking by the ligandability model's
  // calibrated probability that a ligand binds there.
  for (std::size_t i = 0; i < std::min<std::size_t>(3, cavities.sites.size()); ++i) {
    const molecule::Cavity& c = cavities.cavity(cavities.sites[i]);
    const auto residues = molecule::residues_of(structure.atoms, c.lining_atoms);
    std::printf(
        "site %zu (%s): probability %.2f, score %.3g, volume %.0f A^3 (SA) / %.0f A^3 (molecular surface), %zu mouth(s), depth %.1f A, "
        "%zu lining residues, first %s\n",
        i + 1, molecule::site_cavity_name(cavities.sites[i]).c_str(), c.probability, c.score, c.sa_volume, c.ms_volume, c.mouths.size(),
        c.depth, residues.size(), molecule::residue_id(structure.atoms[residues[0]]).c_str());
  }

  // 3. Each ligand against the sites: the first site (by rank) whose centre
  //    is within 4 A of a ligand atom (the DCA criterion).
  for (const molecule::HeteroGroup& ligand : structure.hetero_groups) {
    std::string where = "in no site (no centre within 4 A)";
    for (std::size_t i = 0; i < cavities.sites.size(); ++i) {
      const alpha::Vec3 center = cavities.cavity(cavities.sites[i]).center;
      const auto near = [&](const molecule::Atom& a) { return distance(a.position, center) <= 4.0; };
      if (std::any_of(ligand.atoms.begin(), ligand.atoms.end(), near)) {
        where = "in site " + std::to_string(i + 1) + " (" + molecule::site_cavity_name(cavities.sites[i]) + ")";
        break;
      }
    }
    std::printf("ligand %s %s:%d (%zu heavy atoms): %s\n", ligand.residue_name.c_str(), ligand.chain.c_str(),
                ligand.seq_num, ligand.atoms.size(), where.c_str());
  }

  // 4. Optionally the files of `alphapocket pockets`.
  if (!outdir.empty())
    std::printf("wrote %zu files to %s\n", molecule::write_outputs(analysis, outdir).size(), outdir.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc > 1 ? argv[1] : "examples/data/1a26A.pdb", argc > 2 ? argv[2] : "");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ERROR: %s\n", e.what());
    return 1;
  }
}
