// CL records as binary CLDATA, ISO 3592's numeric records as IBM's CLTAPE
// lays them out (research/apt.md §6.1; the layout is in docs/apt.md): each
// record a header of four little-endian 32-bit integers (record number,
// word count, class, subclass), then its words of 8 bytes each. A word is a
// real (an IEEE double), a vocabulary code (the code in the low 32 bits, 0
// in the high ones) or text (6 characters, then 2 blanks).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "apt/cl.hpp"
#include "core/diagnostic.hpp"

namespace usina::apt {

// What a record may hold: more words than this is a broken file (IBM's
// longest records hold 242).
inline constexpr std::size_t kMostCldataWords = 4096;

// The bytes of `records`, numbered from `first` (a file written in parts
// numbers each part on from the last). A real smaller than 1e-150 in
// magnitude is written as 0 (its bytes could read as text); text longer
// than 6 characters is cut.
std::string write_cldata(const std::vector<ClRecord>& records, std::uint32_t first = 1);

// Reads the records of `bytes` (file `file` of a SourceManager) in order,
// handing each to `take` until it returns false. A record that breaks the
// layout (cut short, a word count beyond kMostCldataWords, a number out of
// order, a real that is not finite or beyond kLargestClNumber) is an error (E_CL_BAD_RECORD)
// located at line = its record number; reading stops there. Returns the number of records read.
std::size_t read_cldata(std::string_view bytes, std::uint32_t file, core::DiagnosticSink& diags,
                        const std::function<bool(ClRecord&&)>& take);

// Every record of `bytes` (tests, the round trip).
std::vector<ClRecord> read_cldata(std::string_view bytes, std::uint32_t file,
                                  core::DiagnosticSink& diags);

}  // namespace usina::apt
