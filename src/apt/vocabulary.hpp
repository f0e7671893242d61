// The IBM APT vocabulary codes (research/apt.md §6.3, from the IBM manual's
// table): post-processor major words are the subclass of their 2000-class
// record, minor words are written as their code (#60 for CLW).
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace usina::apt {

namespace vocabulary_detail {

struct Entry {
  std::string_view word;
  int code;
};

inline constexpr Entry kPostWords[] = {
    {"END", 1},       {"STOP", 2},      {"OPSTOP", 3},    {"ISTOP", 4},     {"RAPID", 5},
    {"SWITCH", 6},    {"RETRCT", 7},    {"DRESS", 8},     {"PICKUP", 9},    {"UNLOAD", 10},
    {"PENUP", 11},    {"PENDWN", 12},   {"ZERO", 13},     {"GOHOME", 14},   {"RESET", 15},
    {"GOCLER", 16},   {"DRAWLI", 17},   {"PROBY", 18},    {"PROBX", 19},    {"ULOCKX", 20},
    {"LOCKX", 21},    {"FACEML", 22},   {"PLUNGE", 1001}, {"HEAD", 1002},   {"MODE", 1003},
    {"CLEARP", 1004}, {"TMARK", 1005},  {"REWIND", 1006}, {"CUTCOM", 1007}, {"REVERS", 1008},
    {"FEDRAT", 1009}, {"DELAY", 1010},  {"AIR", 1011},    {"DELETE", 1012}, {"LEADER", 1013},
    {"PPLOT", 1014},  {"MACHIN", 1015}, {"MCHTOL", 1016}, {"PIVOTZ", 1017}, {"MCHFIN", 1018},
    {"SEQNO", 1019},  {"INTCOD", 1020}, {"DISPLY", 1021}, {"AUXFUN", 1022}, {"CHECK", 1023},
    {"POSTN", 1024},  {"TOOLNO", 1025}, {"ROTABL", 1026}, {"ORIGIN", 1027}, {"SAFETY", 1028},
    {"ARCSLP", 1029}, {"COOLNT", 1030}, {"SPINDL", 1031}, {"IFRO", 1032},   {"TURRET", 1033},
    {"ROTHED", 1035}, {"THREAD", 1036}, {"TRANS", 1037},  {"TRACUT", 1038}, {"INDEX", 1039},
    {"COPY", 1040},   {"PLOT", 1041},   {"OVPLOT", 1042}, {"LETTER", 1043}, {"PPRINT", 1044},
    {"PARTNO", 1045}, {"INSERT", 1046}, {"CAMERA", 1047}, {"PREFUN", 1048}, {"COUPLE", 1049},
    {"PITCH", 1050},  {"MDWRIT", 1051}, {"MDEND", 1052},  {"ASLOPE", 1053}, {"CYCLE", 1054},
    {"LOADTL", 1055}, {"SELCTL", 1056}, {"CLRSRF", 1057}, {"DWELL", 1058},  {"DRAFT", 1059},
    {"CLAMP", 1060},  {"PLABEL", 1061}, {"MAXDPM", 1062}, {"SLOWDN", 1063}, {"MAXVEL", 1064},
    {"LPRINT", 1065}, {"MOVETO", 1066}, {"CORNFD", 1067}, {"PBS", 1068},    {"REGBRK", 1069},
    {"VTLAXS", 1070}, {"WCORN", 1071},  {"MAGTAP", 1072}, {"LINTOL", 1073}, {"BREAK", 1083},
    {"DEFSUB", 1140}, {"ENDSUB", 1141}, {"CALSUB", 1142}, {"SELECT", 1143}, {"MATLNO", 1144},
};

inline constexpr Entry kMinorWords[] = {
    {"ATANGL", 1},  {"CENTER", 2},  {"CROSS", 3},   {"INTOF", 5},   {"INVERS", 6},  {"LARGE", 7},
    {"LEFT", 8},    {"LENGTH", 9},  {"MINUS", 10},  {"NEGX", 11},   {"NEGY", 12},   {"NEGZ", 13},
    {"NOX", 14},    {"NOY", 15},    {"NOZ", 16},    {"PARLEL", 17}, {"PERPTO", 18}, {"PLUS", 19},
    {"POSX", 20},   {"POSY", 21},   {"POSZ", 22},   {"RADIUS", 23}, {"RIGHT", 24},  {"SCALE", 25},
    {"SMALL", 26},  {"TANTO", 27},  {"IN", 48},     {"OUT", 49},    {"ALL", 51},    {"LAST", 52},
    {"NOMORE", 53}, {"SAME", 54},   {"MODIFY", 55}, {"MIRROR", 56}, {"START", 57},  {"ENDARC", 58},
    {"CCLW", 59},   {"CLW", 60},    {"MEDIUM", 61}, {"HIGH", 62},   {"LOW", 63},    {"CONST", 64},
    {"DECR", 65},   {"INCR", 66},   {"TO", 69},     {"PAST", 70},   {"ON", 71},     {"OFF", 72},
    {"IPM", 73},    {"IPR", 74},    {"CIRCUL", 75}, {"LINEAR", 76}, {"PARAB", 77},  {"RPM", 78},
    {"MAXRPM", 79}, {"TURN", 80},   {"FACE", 81},   {"BORE", 82},   {"BOTH", 83},   {"XAXIS", 84},
    {"YAXIS", 85},  {"ZAXIS", 86},  {"AUTO", 88},   {"FLOOD", 89},  {"MIST", 90},   {"STEP", 92},
    {"MAIN", 93},   {"SIDE", 94},   {"LINCIR", 95}, {"MAXIPM", 96}, {"REV", 97},    {"TYPE", 98},
    {"RANGE", 145}, {"PSTAN", 146}, {"FULL", 147},  {"DEEP", 153},  {"DRILL", 163}, {"TAP", 168},
    {"MMPM", 171},  {"MMPR", 172},  {"AT", 175},    {"ANGLE", 236},
};

template <std::size_t N>
consteval int code_in(const Entry (&table)[N], std::string_view word) {
  for (const Entry& e : table)
    if (e.word == word) return e.code;
  throw "not a word of the vocabulary";  // a compile error: the word is misspelt
}

}  // namespace vocabulary_detail

// The codes of words known when compiling (post_code("FEDRAT") is 1009),
// from the one table: the CL writers and readers name codes by their words.
consteval int post_code(std::string_view word) {
  return vocabulary_detail::code_in(vocabulary_detail::kPostWords, word);
}

consteval int minor_code(std::string_view word) {
  return vocabulary_detail::code_in(vocabulary_detail::kMinorWords, word);
}

// The 2000-class subclass of a post-processor word (FEDRAT 1009, END 1).
std::optional<int> post_word_code(std::string_view word);

// The code of a minor word (CLW 60, ON 71).
std::optional<int> minor_word_code(std::string_view word);

// The post-processor word of a 2000-class subclass, "" when it has none.
std::string_view post_word_name(int code);

// The minor word of a code, "" when it has none.
std::string_view minor_word_name(int code);

}  // namespace usina::apt
