// What the routes computed on the tool-path service's pool share: the
// answer of computed bytes (with where they came from) and of a run that
// failed.
#pragma once

#include <string>
#include <string_view>

#include "dnc/api_http.hpp"
#include "dnc/web_toolpath_service.hpp"

namespace usina::dnc {

HttpResponse computed_response(const ToolpathReply& r, std::string_view content_type,
                               const std::string& bytes, ToolpathFrom from);
HttpResponse run_failed(const ToolpathReply& r, const std::string& why);

}  // namespace usina::dnc
