#pragma once
/// @file spelling.hpp
/// Telling a misspelt keyword or parameter from a real one gapfem lacks. An unknown keyword that
/// is an Abaqus (or CalculiX) keyword is "not supported by gapfem"; one that is not, but lies a
/// few typing mistakes from a keyword gapfem knows, is a misspelling ("did you mean *SOLID
/// SECTION?"); anything else is text that starts with a single star (a title or a comment written
/// with one *). Parameters likewise, against the keyword's own parameters.
#include <string>
#include <string_view>
#include <vector>

namespace gapfem::inp {

/// True for a keyword of Abaqus/Standard or CalculiX (canonical form: upper case, no blanks, no
/// star), whether or not gapfem reads it.
bool foreign_keyword(std::string_view key);
/// The Abaqus and CalculiX keywords (display names, without the star).
const std::vector<std::string>& foreign_keyword_names();
/// True for a parameter name some Abaqus or CalculiX keyword takes (canonical form).
bool foreign_parameter(std::string_view key);

/// Edit distance between two canonical names: insertions, deletions, substitutions and swaps of
/// two neighbouring characters count one each ("SECTON" → "SECTION": 1).
int spelling_distance(std::string_view a, std::string_view b);

/// The candidates (display names, a leading * ignored) that `key` (canonical) is a plausible
/// misspelling of: those at the smallest edit distance, when that distance is small for the length
/// of `key` (one mistake in a name of up to 4 characters, two up to 8, three beyond) and below half
/// the candidate's length; common synonyms (NODESET for NSET) count as misspellings too. Empty when
/// none is close.
std::vector<std::string> misspelling_of(std::string_view key,
                                        const std::vector<std::string>& candidates);

/// "A or B" / "A, B or C" for a suggestion.
std::string one_of(const std::vector<std::string>& names);

} // namespace gapfem::inp
