// What a drawing writer returns: nothing, or why the file could not be
// written; and the one way a writer's output reaches a file.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include <tl/expected.hpp>

#include "core/output_file.hpp"

namespace usina::draw {

using WriteResult = tl::expected<void, std::string>;

// Runs `write(FILE*)` into `path` through core::OutputFile: the target is
// replaced only when the whole drawing was written (docs/cli.md).
template <class Write>
WriteResult write_to_file(const std::string& path, const std::vector<std::string>& inputs,
                          Write write) {
  auto out = core::OutputFile::open(path, inputs);
  if (!out) return tl::unexpected(out.error());
  const WriteResult written = write(out->stream());
  // A writer that stopped on a failed write (cairo's "error while writing")
  // gets the reason the file gives; the target stays as it was either way.
  if (!written) return tl::unexpected(out->write_error().value_or(written.error()));
  return out->commit();
}

}  // namespace usina::draw
