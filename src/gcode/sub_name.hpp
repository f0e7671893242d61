// A subroutine called by name (o<name> call) and not defined in the program
// is read from the file <name>.ngc in a folder of the subroutine path. The
// name is only ever that file name: never a path, never given to a shell
// (LinuxCNC passes it to wordexp, which runs $(...)).
#pragma once

#include <string>
#include <string_view>

#include <tl/expected.hpp>

namespace usina::gcode {

// Why `name` cannot be the name of a subroutine file, as the error: a path
// separator ('/', or '\' as on Windows), a leading '.' ('..', hidden
// files), a control byte (NUL ends a C file name early), or more bytes than
// a file name may have.
tl::expected<void, std::string> subroutine_name_problem(std::string_view name);

}  // namespace usina::gcode
