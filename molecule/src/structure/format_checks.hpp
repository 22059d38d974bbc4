// SPDX-License-Identifier: Apache-2.0
// The structure reader's checks of a file's text, made before gemmi parses
// it because gemmi reads some broken files without a word or rejects them
// without saying where: the format, PDB records and mmCIF _atom_site values
// gemmi would misread, a file cut short, the old PDB columns 73-80. Each
// problem throws an alpha::Error (BadInput) naming the file and the line,
// which the reader (structure.cpp) throws on as its StructureError.
#pragma once
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gemmi::cif {
struct Block;
}  // namespace gemmi::cif

namespace molecule::format_checks {

// Whether text is white space only.
bool is_blank(std::string_view text);

enum class Format { Pdb, Mmcif };

// PDB or mmCIF, from the text (a data_ block first: mmCIF; ATOM or HETATM
// records: PDB); throws for anything else.
Format detect_format(std::string_view text, const std::string& name);

// What the text of an atom record says that gemmi's structure no longer
// does: the element symbols gemmi does not know (it reads them as X), each
// with the first line holding it.
using UnknownElements = std::map<std::string, std::size_t>;

// gemmi reads a coordinate that is not a number ("abc", blank) as 0 without
// a word, and rejects a bad charge without a line number, so the records it
// reads are checked here first: those starting with ATOM or HETA in any
// case, up to an END record. `old_columns`: columns 73-80 are not read.
// A file cut short (an interrupted download or copy) ends without a line
// end inside a record: its last ATOM or HETATM record, with no line end, is
// then shorter than every other one, as a file's writer gives them one
// length (80 columns, or fewer when it drops trailing blanks). A cut at a
// line end cannot be told from a whole file: END is optional.
void check_pdb_records(std::string_view text, const std::string& name, bool old_columns, UnknownElements& unknown);

// Whether the ATOM or HETATM records of some residue are not together: a
// residue met again after another residue's records in the same model. A
// residue as gemmi tells them apart: name, chain, number, insertion code
// (columns 18-27) and segment (73-76, unless `old_columns`).
bool has_scattered_residues(std::string_view text, bool old_columns);

// Columns 73-80 of the PDB format before 1996 (e.g. HOLE's gramicidin,
// gemmi's pdb1gdr.ent): the id code and a line number ("1GRM 125"), where
// the current format has the segment id, element and charge. Such a record
// has a right-justified number of two digits or more in columns 77-80,
// which no element and charge can be. The first one found, with its line
// number, tells the file is in that format.
struct OldColumns {
  std::size_t line_number = 0;
  std::string text;  // columns 73-80
};
std::optional<OldColumns> old_format_columns(std::string_view text);

// mmCIF data without its data_ block (gemmi would take the rows for PDB
// records): the line of the first CIF tag or loop_, before any data_.
std::optional<std::size_t> cif_without_data_block(std::string_view text);

// gemmi converts the _atom_site values it reads (a single character, an
// integer, a number) without saying where a bad one is, and reads a
// coordinate that is not a number as NaN, so its table is checked here
// first, each bad value named with its line and its text. The table is
// found as gemmi finds it (the loop holding _atom_site.id if it has every
// required column, else pair items), so no other loop hides a bad value.
// Unknown element symbols are noted.
void check_atom_site(gemmi::cif::Block& block, std::string_view text, const std::string& name,
                     UnknownElements& unknown);

// The required columns a block's _atom_site lacks; none if it has no _atom_site.
std::vector<std::string> missing_atom_site_columns(gemmi::cif::Block& block);

}  // namespace molecule::format_checks
