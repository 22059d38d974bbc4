// SPDX-License-Identifier: Apache-2.0
#include "outputs/result_entries.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "alpha/error.hpp"
#include "molecule/residues.hpp"
#include "outputs/report_numbers.hpp"

namespace molecule {
namespace {

using json = nlohmann::ordered_json;
using report_number::length;
using report_number::score;

// The way through cycle k of search->cavities.tunnels, or null when none
// was found.
const TunnelPath* cycle_path(const PocketRun& run, std::size_t k) {
  if (k >= run.cycle_paths.size() || run.cycle_paths[k].profile.empty()) return nullptr;
  return &run.cycle_paths[k];
}

// The index into run.paths of the first path that runs through a cycle's
// bottleneck (crosses its killing triangle, or passes its bottleneck
// centre), or npos.
std::size_t path_through(const PocketRun& run, const Tunnel& cycle) {
  for (std::size_t i = 0; i < run.paths.size(); ++i) {
    const TunnelPath& p = run.paths[i];
    if (std::find(p.triangles.begin(), p.triangles.end(), cycle.bottleneck_triangle) != p.triangles.end()) return i;
    // Ties: another triangle with the same narrowest point (a ring of
    // cocircular atoms, all triangles of its disc centred alike).
    for (const alpha::Vec3& x : p.centreline)
      if (norm(x - cycle.bottleneck_center) < 1e-9) return i;
  }
  return std::size_t(-1);
}

}  // namespace

std::vector<SiteEntry> site_entries(const PocketRun& run) {
  const Structure& st = run.structure;
  const Cavities& cavities = run.search.cavities;
  const std::span<const LigandSite> ligands = ligands_of(run);
  std::vector<SiteEntry> out;
  for (const Site& s : cavities.sites) {
    const Cavity& c = cavities.cavity(s);
    SiteEntry& e = out.emplace_back(SiteEntry{out.size() + 1, s.is_void ? "void" : "pocket", s.index + 1, &c, s.center,
                                              mean_plddt(st, c.lining_atoms), residues_of(st.atoms, c.lining_atoms), {}});
    for (const LigandSite& l : ligands)
      if (l.lies_in(e.rank)) e.ligands.push_back(ligand_id(st.hetero_groups[l.group]));
  }
  return out;
}

bool TunnelEntry::is_cycle() const { return std::string_view(kind) == "cycle"; }

std::vector<TunnelEntry> tunnel_entries(const PocketRun& run) {
  const std::vector<Atom>& atoms = run.structure.atoms;
  std::vector<TunnelEntry> out;
  const std::vector<Tunnel>& cycles = run.search.cavities.tunnels;
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    const Tunnel& t = cycles[k];
    const TunnelPath* way = cycle_path(run, k);
    const std::size_t through = path_through(run, t);
    out.push_back({out.size() + 1, "cycle", json(), t.bottleneck_radius, t.bottleneck_center,
                   way ? json(length(way->length)) : json(), json(), json(), t.birth_alpha_sq, t.death_alpha_sq,
                   through == std::size_t(-1) ? json() : json(cycles.size() + through + 1), &t.lining_atoms,
                   residues_of(atoms, t.lining_atoms), way});
  }
  for (std::size_t i = 0; i < run.paths.size(); ++i) {
    const TunnelPath& p = run.paths[i];
    out.push_back({out.size() + 1, p.pore ? "pore" : "tunnel", p.pore ? json() : json(run.tunnel_starts.at(p.start)),
                   p.bottleneck_radius, p.bottleneck, length(p.length),
                   std::isfinite(p.curvature) ? json(length(p.curvature)) : json(), score(p.cost), json(), json(),
                   json(), &p.lining_atoms, residues_of(atoms, p.lining_atoms), &p});
  }
  return out;
}

json report_probability(double p) { return std::isnan(p) ? json() : json(report_number::probability(p)); }

json mean_plddt(const Structure& structure) {
  std::vector<alpha::Index> all(structure.atoms.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = alpha::Index(i);
  return mean_plddt(structure, all);
}

json mean_plddt(const Structure& structure, const std::vector<alpha::Index>& atoms) {
  if (!structure.report.predicted) return nullptr;
  const std::vector<alpha::Index> residues = residues_of(structure.atoms, atoms);
  if (residues.empty()) return nullptr;
  double sum = 0;
  for (const alpha::Index i : residues) sum += structure.atoms[i].b_factor;
  return length(sum / double(residues.size()));
}

std::string ligand_id(const HeteroGroup& g) {
  return g.chain + ':' + g.residue_name + ':' + std::to_string(g.seq_num) + icode_text(g.icode);
}

std::span<const LigandSite> ligands_of(const PocketRun& run) {
  const std::span<const LigandSite> ligands = run.ligands;
  if (ligands.size() != run.structure.hetero_groups.size())
    alpha::fail("pocket_report: " + std::to_string(ligands.size()) + " ligand sites for " +
                    std::to_string(run.structure.hetero_groups.size()) + " hetero groups",
                alpha::ErrorKind::Misuse);
  return ligands;
}

}  // namespace molecule
