#include "structure_file.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include <gemmi/gz.hpp>
#include <gemmi/mmread.hpp>

#include "point_file.hpp"

namespace alphapocket {
namespace {

bool ends_with_ci(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         std::equal(suffix.rbegin(), suffix.rend(), s.rbegin(),
                    [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
}

// gemmi messages may span lines; the CLI reports errors on one line.
std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

}  // namespace

bool is_structure_file(const std::string& path) {
  std::string p = path;
  if (ends_with_ci(p, ".gz")) p.resize(p.size() - 3);
  for (const char* ext : {".pdb", ".ent", ".cif", ".mmcif"})
    if (ends_with_ci(p, ext)) return true;
  return false;
}

std::vector<alpha::Vec3> read_structure_atoms(const std::string& path) {
  check_input_file(path);
  gemmi::Structure st;
  try {
    st = gemmi::read_structure(gemmi::MaybeGzipped(path));
  } catch (const std::exception& e) {
    const std::string msg = one_line(e.what());
    // gemmi names the file in some messages (often with a line number).
    throw std::runtime_error(msg.find(path) == std::string::npos ? path + ": " + msg : msg);
  }
  if (st.models.empty()) throw std::runtime_error(path + ": no models (no atom records found)");
  std::vector<alpha::Vec3> atoms;
  for (const gemmi::Chain& chain : st.models.front().chains)
    for (const gemmi::Residue& res : chain.residues)
      for (const gemmi::Atom& atom : res.atoms) atoms.push_back({atom.pos.x, atom.pos.y, atom.pos.z});
  if (atoms.empty()) throw std::runtime_error(path + ": the first model has no atoms");
  return atoms;
}

}  // namespace alphapocket
