// SPDX-License-Identifier: Apache-2.0
#include "molecule/track_result.hpp"

namespace molecule {

const char* kind_name(CavityKind kind) {
  return kind == CavityKind::pocket ? "pocket" : kind == CavityKind::void_ ? "void" : "tunnel";
}

}  // namespace molecule
