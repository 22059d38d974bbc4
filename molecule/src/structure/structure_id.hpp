// SPDX-License-Identifier: Apache-2.0
// The id a structure is known by: its file's name without .pdb/.ent/.cif/
// .mmcif and .gz. `pockets` names its default output directory after it,
// `batch` its rows and its inputs' duplicates.
#pragma once
#include <string>

namespace molecule {

// "x/1abc.cif.gz" -> "1abc"; never empty ("structure" for a bare ".pdb").
std::string structure_id(const std::string& path);

}  // namespace molecule
