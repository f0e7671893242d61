#include "post/post.hpp"

#include "post/control.hpp"
#include "post/writer.hpp"

namespace usina::post {

const std::vector<std::string>& post_names() {
  static const std::vector<std::string> names{"rs274ngc", "fanuc", "grbl", "romi"};
  return names;
}

std::unique_ptr<canon::Sink> make_post(std::string_view control, std::ostream& out,
                                       const PostOptions& options, core::DiagnosticSink& diags) {
  Control c;
  if (control == "rs274ngc") {
    c = rs274ngc_control();
  } else if (control == "fanuc") {
    c = fanuc_control();
  } else if (control == "grbl") {
    c = grbl_control();
  } else if (control == "romi") {
    c = romi_control();
  } else {
    return nullptr;
  }
  return std::make_unique<Writer>(out, std::move(c), options, diags);
}

}  // namespace usina::post
