// usina gen engrave: text in a single-stroke Hershey font (seed 004,
// table 7.5, "inscrição").
#include <memory>

#include "cam/engrave.hpp"
#include "cam/hershey.hpp"
#include "cli/gen_cam_options.hpp"
#include "cli/post_output.hpp"

namespace usina::cli {
namespace {

struct EngraveCli {
  cam::EngraveOptions gen;
  std::vector<double> at{0.0, 0.0};
  std::string font = "rowmans";
  PostOutput output;
};

}  // namespace

void add_gen_engrave(CLI::App& gen) {
  auto o = std::make_shared<EngraveCli>();
  CLI::App* cmd = gen.add_subcommand("engrave", "engrave text in a single-stroke font");
  cmd->add_option("--text", o->gen.text, "printable ASCII")->required();
  cmd->add_option("--height", o->gen.height, "height of a capital letter, mm")->required();
  cmd->add_option("--font", o->font,
                  "a Hershey font of /usr/share/hershey-fonts (rowmans, futural, scripts, "
                  "...) or a .jhf file")
      ->capture_default_str();
  cmd->add_option("--at", o->at, "start of the baseline, X,Y (mm)")
      ->delimiter(',')
      ->expected(2)
      ->capture_default_str();
  cmd->add_option("--depth", o->gen.depth, "depth below Z0, mm")->capture_default_str();
  add_cutting_options(*cmd, o->gen.cut);
  add_post_options(*cmd, o->output);
  cmd->callback([o] {
    o->gen.at = {o->at.at(0), o->at.at(1)};
    run_generator("engrave", o->output, [&](canon::Sink& sink, core::DiagnosticSink& diags) {
      const auto font = cam::read_hershey(cam::hershey_file(o->font), diags);
      return font && cam::generate_engrave(*font, o->gen, sink, diags);
    });
  });
}

}  // namespace usina::cli
