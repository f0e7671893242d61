// Unnamed temporary files: gone when closed, whatever happens to the run,
// so nothing is left behind for another user to read or a later run to
// take. Made in $TMPDIR when it is set, else /tmp, as a user who points
// TMPDIR at a bigger disk expects (std::tmpfile uses /tmp whatever TMPDIR
// says).
#pragma once

#include <string>

namespace usina::core {

// $TMPDIR when set and not empty, else /tmp.
std::string temporary_folder();

// A file descriptor (read and write, close-on-exec) of an unnamed file in
// `folder`: O_TMPFILE where the file system has it, else a named one removed
// at once. -1, errno set, when neither can be made.
int open_unnamed_file(const std::string& folder);

}  // namespace usina::core
