// SPDX-License-Identifier: Apache-2.0
// Macromolecular structure files (PDB, mmCIF, either optionally gzipped),
// read through gemmi, reduced to the atoms a cavity search works on.
//
// The format is found from the content, not the name: gzip by its magic
// bytes, mmCIF by its leading "data_" block, PDB by ATOM/HETATM records.
// One model is read (the first by default). From it, in this order:
//
//   1. chains not selected are dropped (all chains by default);
//   2. alternate locations: one conformer per residue is kept, the altloc
//      with the highest mean occupancy (ties: the smallest letter).
//      Atoms without an altloc are always kept; an atom name that has no
//      atom in the chosen altloc keeps its own highest-occupancy
//      alternative. Residues sharing a sequence number (microheterogeneity,
//      e.g. ALA and SER both at 42) are one unit: a residue whose atoms all
//      belong to altlocs not chosen is dropped;
//   3. waters are dropped unless keep_waters;
//   4. hetero groups (ligands, ions, sugars, buffer molecules: residues that
//      are neither polymer nor water) are dropped unless kept (keep_hetero:
//      all; keep_hetero_codes: those named; keep_cofactors: kCofactors). A
//      modified residue inside a polymer (MSE in a protein chain) is polymer
//      and kept. Polymer or not comes from the mmCIF entities, or for PDB
//      files from TER records and gemmi's polymer heuristics; HETATM records
//      count as hetero even inside a polymer when their chain has no ATOM
//      records (peptide ligands) or gemmi's tables do not know the residue
//      as an amino acid or nucleotide (a covalently bound inhibitor);
//   5. hydrogens (H and D) are dropped unless keep_hydrogens;
//   6. predicted models: residues whose pLDDT (mean B-factor of the
//      residue's atoms) is below min_plddt.
//
// Each dropped atom is counted once, under the first reason that applies.
// Every kept atom gets a radius from molecule/radii.hpp (ProtOr).
//
// The hetero groups of the model (after steps 1 and 2) are also returned on
// their own, whatever keep_hetero says, each with its heavy atoms: the
// ligands a pocket may hold.
//
// Errors throw alpha::Error (StructureError) with one line naming the file:
// missing, a directory, empty, corrupt or truncated gzip data, not PDB or
// mmCIF, a broken or truncated mmCIF/PDB file (including a PDB coordinate
// that is not a number, an mmCIF _atom_site without a column gemmi needs),
// no such model or chain, no atoms left after the selection, fewer than 4
// atoms. The library itself never logs: what was kept and dropped, and
// warnings (e.g. an unknown element), come back in StructureReport.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "alpha/error.hpp"
#include "alpha/geometry.hpp"

namespace molecule {

class StructureError : public alpha::Error {
public:
  using alpha::Error::Error;
};

struct StructureOptions {
  int model = 0;                    // model number as in the file (MODEL n); 0: the first model
  std::vector<std::string> chains;  // chain names (author chain ids) to keep; empty: all chains
  bool keep_hydrogens = false;
  bool keep_waters = false;
  bool keep_hetero = false;                    // every hetero group
  std::vector<std::string> keep_hetero_codes;  // hetero groups of these residue names ("ZN", "HEM")
  bool keep_cofactors = false;                 // hetero groups named in kCofactors
  // Predicted models (StructureReport::predicted): residues whose pLDDT
  // (the B-factor column) is below this are dropped, after every other
  // reason. 0: none. Ignored, with a warning, for other structures.
  double min_plddt = 0;
  // Fewer atoms after the selection is an error: a triangulation needs 4
  // (a union of balls, 1).
  std::size_t min_atoms = 4;
  // A file (after gzip decompression) larger than this, MiB, is an error:
  // five times the largest PDB entry, and memory stays bounded whatever a
  // gzip file claims.
  std::size_t max_input_mib = 512;
};

// Metal ions and cofactors that are part of a protein's working structure
// rather than the ligands one looks for a site of (--keep-cofactors keeps
// them as protein): the common metal ions, hemes, flavins, nicotinamides,
// iron-sulfur clusters, pterins, and the like (PDB chemical component
// codes). Substrates and nucleotides such as ATP, GTP or SAM are not in it:
// they are the ligands of many sites.
inline constexpr const char* kCofactors[] = {
    // metal ions
    "ZN", "MG", "CA", "FE", "FE2", "MN", "CU", "CU1", "CO", "NI", "NA", "K", "CD", "MO",
    // hemes and chlorophylls
    "HEM", "HEC", "HEA", "HEB", "CLA", "BCL",
    // flavins, nicotinamides, quinones
    "FAD", "FMN", "NAD", "NAP", "NDP", "NAI", "PQQ",
    // iron-sulfur clusters, molybdopterin, other vitamin-derived cofactors
    "SF4", "FES", "F3S", "MGD", "PLP", "TPP", "COA", "B12", "BTN"};

// Whether the options keep a hetero group of this residue name.
bool keeps_hetero(const StructureOptions& options, const std::string& residue_name);

struct Atom {
  int serial = 0;            // atom serial number as in the file
  std::string name;          // atom name ("CA")
  std::string element;       // element symbol ("C", "Se"); "X" if not recognised
  char altloc = '\0';        // alternate location; '\0' for none
  float occupancy = 1;       // as stored by gemmi (single precision)
  float b_factor = 0;        // isotropic B, A^2
  std::string residue_name;  // "ALA"
  int seq_num = 0;           // residue sequence number (author numbering)
  char icode = '\0';         // insertion code; '\0' for none
  std::string chain;         // author chain id
  bool hetero = false;       // a HETATM record
  // Position among the model's atoms in the file, from 0: the atom's place
  // in a trajectory's coordinates (molecule/track.hpp).
  std::size_t file_index = 0;
  alpha::Vec3 position;      // A
  double radius = 0;         // A, from molecule/radii.hpp
};

// The insertion code as text: "" for none.
inline std::string icode_text(char icode) { return icode ? std::string(1, icode) : std::string(); }

// A ligand, ion or other non-polymer, non-water residue, with its heavy atoms.
struct HeteroGroup {
  std::string residue_name;
  std::string chain;
  int seq_num = 0;
  char icode = '\0';
  std::vector<Atom> atoms;  // never empty
  bool kept = false;        // its atoms are among Structure::atoms (a kept hetero group)
};

struct StructureReport {
  std::string format;  // "PDB" or "mmCIF"
  bool gzipped = false;
  // A predicted model (AlphaFold DB and the like), whose B-factor column
  // holds pLDDT: an mmCIF file with _ma_qa_metric_local, or a file named
  // AF-*.
  bool predicted = false;
  std::size_t models = 0;          // models in the file
  int model = 0;                   // number of the model read
  std::size_t model_index = 0;     // its position among the file's models, from 0
  std::size_t atoms_in_model = 0;  // every atom of that model
  std::size_t kept = 0;            // = atoms.size()
  // Dropped atoms, by reason (each atom once, in this order).
  std::size_t dropped_chain = 0;
  std::size_t dropped_altloc = 0;
  std::size_t dropped_water = 0;
  std::size_t dropped_hetero = 0;
  std::size_t dropped_hydrogen = 0;
  std::size_t dropped_plddt = 0;  // residues below StructureOptions::min_plddt
  std::size_t hetero_groups = 0;  // = hetero_groups.size()
  // Problems that did not stop the reading, one line each (e.g. one per
  // unrecognised element among the kept atoms, which got
  // molecule::kDefaultRadius).
  std::vector<std::string> warnings;
};

struct Structure {
  // The selected atoms, at least 4, in the canonical order: the polymer's,
  // then those of kept hetero groups, then waters; each part by chain,
  // residue number, insertion code, residue name, atom name, altloc, then
  // position, serial and the other fields. Not the file's: permuting the
  // records of a file changes nothing computed from them.
  std::vector<Atom> atoms;
  std::vector<HeteroGroup> hetero_groups;  // the same order (of their atoms, and of their first atoms)
  StructureReport report;
};

// Reads and selects; throws StructureError naming the file on any error.
Structure read_structure(const std::string& path, const StructureOptions& options = {});

// The same from the bytes of a file (possibly gzipped); `name` is used in
// error messages.
Structure parse_structure(std::string_view data, const std::string& name, const StructureOptions& options = {});

// Every model of the file's bytes (a multi-model PDB or mmCIF: an NMR
// ensemble), each selected as parse_structure selects one (options.model
// ignored), the file parsed once.
std::vector<Structure> parse_models(std::string_view data, const std::string& name, const StructureOptions& options = {});

// One line on what was read, kept and dropped, e.g. "PDB, model 1: kept
// 2966 of 3294 atoms; dropped: 295 water, 33 hetero; 3 hetero groups".
std::string summary(const StructureReport& report);

// Whether a file name looks like a structure file: .pdb .ent .cif .mmcif,
// each optionally followed by .gz (case-insensitive). Lets a caller choose
// between a structure file and another kind of input.
bool is_structure_file(std::string_view path);

}  // namespace molecule
