// store_revisions.hpp: the diff of two stored revisions.
#include "dnc/store_revisions.hpp"

namespace usina::dnc {

StoreResult<ProgramDiff> diff_revisions(Store& store, std::string_view program,
                                        std::string_view from, std::string_view to,
                                        bool normalised) {
  auto old_rev = find_revision(store, program, from);
  if (!old_rev) return tl::unexpected(old_rev.error());
  auto new_rev = find_revision(store, program, to);
  if (!new_rev) return tl::unexpected(new_rev.error());
  auto old_text = revision_bytes(store, program, from);
  if (!old_text) return tl::unexpected(old_text.error());
  auto new_text = revision_bytes(store, program, to);
  if (!new_text) return tl::unexpected(new_text.error());
  if (!normalised) return plain_diff(*old_text, *new_text);
  return normalised_diff(*old_text, *new_text, normalise_rules(new_rev->dialect));
}

}  // namespace usina::dnc
