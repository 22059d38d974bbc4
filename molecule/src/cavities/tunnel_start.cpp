// SPDX-License-Identifier: Apache-2.0
#include "molecule/tunnel_start.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include "alpha/error.hpp"

namespace molecule {
namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, sep);) out.push_back(part);
  return out;
}

bool number(const std::string& s, double& x) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
  return ec == std::errc() && end == s.data() + s.size() && std::isfinite(x);
}

TunnelStart site_start(const Cavities& cavities, std::size_t rank) {
  if (rank < 1 || rank > cavities.sites.size())
    throw alpha::Error(
        "--tunnels-from " + std::to_string(rank) + ": there are " + std::to_string(cavities.sites.size()) + " sites",
        alpha::ErrorKind::BadInput);
  return {"site " + std::to_string(rank), cavities.cavity(cavities.sites[rank - 1]).cells, {}};
}

}  // namespace

std::vector<TunnelStart> tunnel_starts(const std::string& spec, const Structure& structure, const Cavities& cavities) {
  std::vector<TunnelStart> out;
  if (spec == "none") return out;
  if (spec == "auto") {
    for (std::size_t k = 1; k <= std::min(kAutoTunnelSites, cavities.sites.size()); ++k)
      out.push_back(site_start(cavities, k));
    return out;
  }
  double x[3];
  const std::vector<std::string> parts = split(spec, ',');
  if (spec.find_first_not_of("0123456789") == std::string::npos && !spec.empty()) {
    out.push_back(site_start(cavities, std::stoul(spec)));
  } else if (parts.size() == 3 && number(parts[0], x[0]) && number(parts[1], x[1]) && number(parts[2], x[2])) {
    out.push_back({spec, {}, {x[0], x[1], x[2]}});
  } else if (spec.find(':') != std::string::npos) {
    alpha::Vec3 sum{};
    std::size_t n = 0;
    for (const std::string& r : parts) {
      std::size_t found = 0;
      for (const Atom& a : structure.atoms)
        if (a.chain + ':' + std::to_string(a.seq_num) + icode_text(a.icode) == r) sum = sum + a.position, ++found;
      if (found == 0)
        throw alpha::Error("--tunnels-from " + spec + ": no atom of residue " + r, alpha::ErrorKind::BadInput);
      n += found;
    }
    out.push_back({spec, {}, (1.0 / double(n)) * sum});
  } else {
    throw alpha::Error("--tunnels-from " + spec + ": expected auto, none, a site rank, residues (A:45,A:67) or x,y,z",
                       alpha::ErrorKind::BadInput);
  }
  return out;
}

}  // namespace molecule
