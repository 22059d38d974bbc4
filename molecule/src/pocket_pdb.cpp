#include "molecule/pocket_pdb.hpp"

#include <cmath>
#include <cstdio>
#include <string_view>

#include "alpha/error.hpp"
#include "alpha/sizes.hpp"

namespace molecule {
namespace {

class PdbWriter {
public:
  explicit PdbWriter(std::string& out) : out_(out) {}

  void remark(std::string_view text) {
    out_ += "REMARK   1 ";
    out_ += text.substr(0, 69);  // the record is 80 columns wide
    out_ += '\n';
  }

  void hetatm(const char* name, char chain, std::size_t rank, const alpha::Vec3& p, double b) {
    if (++serial_ > 99999) alpha::fail("more than 99999 pseudo-atoms do not fit the PDB format");
    if (rank > 9999) alpha::fail("more than 9999 cavities do not fit the PDB format");
    for (double x : {p.x, p.y, p.z})
      if (!(std::abs(x) < 9999.9995) || x <= -999.9995)
        alpha::fail("coordinate " + std::to_string(x) + " does not fit the PDB format");
    char line[96];
    std::snprintf(line, sizeof line, "HETATM%5zu %-4s STP %c%4zu    %8.3f%8.3f%8.3f%6.2f%6.2f           C  \n",
                  serial_, name, chain, rank, p.x, p.y, p.z, 1.0, std::fmin(b, 999.99));
    out_ += line;
  }

private:
  std::string& out_;
  std::size_t serial_ = 0;
};

}  // namespace

std::string pocket_pdb(const alpha::AlphaComplex& ac, const Cavities& cavities, const std::string& title) {
  const alpha::Triangulation& t = ac.triangulation();
  const alpha::SizeKernel sizes(t.points().data(), t.weighted() ? t.weights().data() : nullptr);

  std::string out;
  PdbWriter pdb(out);
  pdb.remark(title);
  pdb.remark("cavities as pseudo-atoms: residue STP, residue number = rank,");
  pdb.remark("chain P = pockets, chain V = voids; atom CEN = cavity centre,");
  pdb.remark("atom SNK = orthocentre of a sink tetrahedron (B = its radius, A)");
  const auto write = [&](const std::vector<Cavity>& list, char chain) {
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Cavity& cavity = list[i];
      pdb.hetatm(" CEN", chain, i + 1, cavity.center, 0);
      for (const alpha::Index c : cavity.sinks) {
        const auto& v = t.cell(c).v;
        const alpha::Simplex tetra(v[0], v[1], v[2], v[3]);
        pdb.hetatm(" SNK", chain, i + 1, sizes.center(tetra), std::sqrt(std::fmax(sizes.size(tetra).value, 0.0)));
      }
    }
  };
  write(cavities.pockets, 'P');
  write(cavities.voids, 'V');
  out += "END\n";
  return out;
}

}  // namespace molecule
