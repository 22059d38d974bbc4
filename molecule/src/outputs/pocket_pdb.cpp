// SPDX-License-Identifier: Apache-2.0
#include "outputs/pocket_pdb.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string_view>

#include "alpha/sizes.hpp"
#include "util/safe_text.hpp"

namespace molecule {
namespace {

void remark(std::string& out, std::string_view text) {
  out += "REMARK   1 ";
  out += text.substr(0, 69);  // the record is 80 columns wide
  out += '\n';
}

// HETATM records, leaving out (and counting) those the fixed columns cannot
// hold: serials above 99999, residue numbers above 9999, coordinates
// outside -999.999 .. 9999.999.
class HetatmWriter {
public:
  explicit HetatmWriter(const char* residue = "STP") : residue_(residue) {}
  void hetatm(const char* name, char chain, std::size_t rank, const alpha::Vec3& p, double b) {
    bool fits = serial_ < 99999 && rank <= 9999;
    for (double x : {p.x, p.y, p.z}) fits = fits && std::abs(x) < 9999.9995 && x > -999.9995;  // NaN does not
    if (!fits) {
      ++left_out_;
      return;
    }
    // (Checked above; GCC cannot follow the check through to the format.)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-truncation"
    char line[96];
    std::snprintf(line, sizeof line, "HETATM%5zu %-4s %3s %c%4zu    %8.3f%8.3f%8.3f%6.2f%6.2f           C  \n",
                  ++serial_, name, residue_, chain, rank, p.x, p.y, p.z, 1.0, std::clamp(b, 0.0, 999.99));
#pragma GCC diagnostic pop
    records_ += line;
  }
  const std::string& records() const { return records_; }
  std::size_t left_out() const { return left_out_; }

private:
  const char* residue_;
  std::string records_;
  std::size_t serial_ = 0, left_out_ = 0;
};

// The file: REMARK lines (the title, what the file holds, how many atoms
// were left out), the records, END.
PocketPdb pdb_file(const HetatmWriter& pdb, const std::string& title, std::initializer_list<std::string_view> about) {
  PocketPdb out;
  out.left_out = pdb.left_out();
  remark(out.text, printable_ascii(title));
  for (const std::string_view line : about) remark(out.text, line);
  if (out.left_out > 0)
    remark(out.text, std::to_string(out.left_out) + " pseudo-atoms left out: beyond the PDB columns' range");
  out.text += pdb.records();
  out.text += "END\n";
  return out;
}

}  // namespace

std::vector<SinkSphere> sink_spheres(const alpha::AlphaComplex& ac, const Cavity& cavity) {
  const alpha::Triangulation& t = ac.triangulation();
  const alpha::SizeKernel sizes = ac.size_kernel();
  std::vector<SinkSphere> out;
  for (const alpha::Index c : cavity.sinks) {
    const alpha::Simplex tetra(t.cell(c).v);
    out.push_back({sizes.center(tetra), std::sqrt(std::fmax(sizes.size(tetra).value, 0.0))});
  }
  return out;
}

PocketPdb pocket_pdb(const alpha::AlphaComplex& ac, const Cavities& cavities, const std::string& title) {
  HetatmWriter pdb;
  const auto write = [&](const std::vector<Cavity>& list, char chain) {
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Cavity& cavity = list[i];
      pdb.hetatm(" CEN", chain, i + 1, cavity.center, 0);
      for (const SinkSphere& sink : sink_spheres(ac, cavity)) pdb.hetatm(" SNK", chain, i + 1, sink.center, sink.radius);
    }
  };
  write(cavities.pockets, 'P');
  write(cavities.voids, 'V');
  for (std::size_t i = 0; i < cavities.tunnels.size(); ++i)
    pdb.hetatm(" BTN", 'T', i + 1, cavities.tunnels[i].bottleneck_center, cavities.tunnels[i].bottleneck_radius);

  return pdb_file(pdb, title,
                  {"cavities as pseudo-atoms: residue STP, residue number = rank,",
                   "chain P = pockets, chain V = voids; atom CEN = cavity centre,",
                   "atom SNK = orthocentre of a sink tetrahedron (B = its radius, A);",
                   "chain T = tunnels, atom BTN = bottleneck centre (B = its radius, A)"});
}

PocketPdb tunnel_pdb(const std::vector<TunnelPath>& cycles, const std::vector<TunnelPath>& paths,
                     const std::string& title) {
  HetatmWriter pdb("TUN");
  for (std::size_t i = 0; i < cycles.size(); ++i)
    for (const ProfilePoint& q : cycles[i].profile) pdb.hetatm(" TUN", 'C', i + 1, q.x, q.radius);
  for (std::size_t i = 0; i < paths.size(); ++i)
    for (const ProfilePoint& q : paths[i].profile)
      pdb.hetatm(" TUN", paths[i].pore ? 'P' : 'T', cycles.size() + i + 1, q.x, q.radius);
  return pdb_file(pdb, title,
                  {"centrelines of the ways through cycles (chain C), tunnels (chain T)",
                   "and pores (chain P): residue TUN, residue number = the rank in",
                   "report.json, one atom per profile point, B = the radius there, A"});
}

}  // namespace molecule
