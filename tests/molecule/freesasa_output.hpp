// SPDX-License-Identifier: Apache-2.0
// The per-atom output of the `freesasa` program (FreeSASA, Debian package
// freesasa), a test oracle for radii and areas: `freesasa --format=pdb`
// writes each atom with the radius it used in the occupancy column and its
// SASA in the B-factor column (2 decimals each).
#pragma once
#include <string>
#include <vector>

struct FreesasaAtom {
  std::string chain, residue_name;
  int seq_num = 0;
  std::string name;
  double radius = 0;  // A
  double area = 0;    // A^2
};

// Runs `<freesasa> FLAGS --format=pdb 'FILE'`; fails the current test when
// it cannot be run or does not succeed.
std::vector<FreesasaAtom> run_freesasa(const std::string& freesasa, const std::string& file,
                                       const std::string& flags);
