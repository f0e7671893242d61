// The program library as the web page and a shop's scripts list it: one
// page of programs with their newest revision and the released one,
// filtered by machine class, dialect, state, a part of the name, a search
// of the newest revision's comments and program numbers, and a tool it
// calls (store_facts.hpp), counted in the store (SQL) so 10,000 programs
// are never all sent to be filtered.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dnc/store.hpp"
#include "dnc/store_revisions.hpp"
#include "dnc/store_states.hpp"

namespace usina::dnc {

struct LibraryQuery {
  std::string machine_class;           // empty: any
  std::string dialect;                 // empty: any
  std::optional<RevisionState> state;  // of the newest revision
  bool released_only = false;          // programs with a released revision
  std::string name_part;               // case-insensitive (ASCII) part of the name
  // Case-insensitive (ASCII) part of the name, of a comment or of a program
  // number of the newest revision.
  std::string text;
  std::optional<std::int64_t> tool;  // the newest revision calls it (a T word)
  std::int64_t limit = 10'000;
  std::int64_t offset = 0;
};

struct LibraryEntry {
  Program program;
  std::string newest_revision;  // SHA-256 hex, empty for a program without one
  std::string newest_state;     // its state's name
  std::int64_t newest_at_us = 0;
  std::string released_revision;  // empty when none is released
  std::int64_t revisions = 0;
};

struct LibraryPage {
  std::vector<LibraryEntry> programs;  // by name
  std::int64_t total = 0;              // programs the filters match, on every page
};

StoreResult<LibraryPage> library_page(Store& store, const LibraryQuery& q);

// Every machine class a program of the library has, in order: the choices
// of the page's filter.
StoreResult<std::vector<std::string>> library_machine_classes(Store& store);

}  // namespace usina::dnc
