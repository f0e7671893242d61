// A job and everything it names, read: the job file, its tool library, its
// materials, its machine profile. The drawing is read per operation (by
// layer) when the job is made.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "job/job_file.hpp"
#include "job/materials.hpp"
#include "job/tools.hpp"
#include "sim/machine_profile.hpp"

namespace usina::job {

struct LoadedJob {
  Job job;
  std::vector<Tool> tools;
  std::vector<Material> materials;
  std::size_t material = 0;                    // the stock's, in `materials`
  std::optional<sim::MachineProfile> machine;  // none: no limits on speed and feed
};

// Nullopt after an error: `io_error` set when a file cannot be read (exit 2),
// else the diagnostics say what is wrong in which file (exit 1). Every file
// read is added to `sources` so that its diagnostics show their line.
std::optional<LoadedJob> load_job(const std::string& path, core::SourceManager& sources,
                                  core::DiagnosticSink& diags, std::string& io_error);

}  // namespace usina::job
