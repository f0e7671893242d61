// The restart program (resume.hpp).
#include "dnc/resume.hpp"

#include "post/resume_preamble.hpp"

namespace usina::dnc {

tl::expected<std::string, std::string> resume_program(std::string_view text,
                                                      std::string_view dialect,
                                                      const gcode::ResumeStart& start) {
  auto point = gcode::find_resume_point(text, dialect, start);
  if (!point) return tl::unexpected(point.error());
  auto preamble = post::resume_preamble(dialect, point->state);
  if (!preamble) return tl::unexpected(preamble.error());
  std::string out = point->head;
  out += point->definitions;
  out += *preamble;
  out.append(text.substr(point->offset));
  return out;
}

}  // namespace usina::dnc
