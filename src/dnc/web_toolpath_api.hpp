// What the routes computed on the tool-path service's pool share: the
// program and revision a route names, the answer of computed bytes (with
// where they came from) and of a run that failed, and the glue that answers
// from the cache or runs the work on the pool.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include <tl/expected.hpp>

#include "dnc/api_http.hpp"
#include "dnc/api_router.hpp"
#include "dnc/store_revisions.hpp"
#include "dnc/web_toolpath_service.hpp"

namespace usina::dnc {

HttpResponse computed_response(const ToolpathReply& r, std::string_view content_type,
                               const std::string& bytes, ToolpathFrom from);
HttpResponse run_failed(const ToolpathReply& r, const std::string& why);

// The program and the revision of the route's two parameters, or the answer
// saying which is missing.
struct NamedRevision {
  Program program;
  Revision revision;
};

tl::expected<NamedRevision, HttpResponse> named_revision(ApiCall& c);

// The answer's bytes, from the revision's text.
using RevisionWork = std::function<std::string(const std::string& text)>;

// How computed bytes become the answer: computed_response's, or the
// route's own (the stock route answers a refusal its run wrote as a 422).
using Respond =
    std::function<HttpResponse(const ToolpathReply& r, const std::string& bytes, ToolpathFrom)>;

// Computed here, on the loop (an Api made without the service).
HttpResponse answer_now(ApiCall& c, std::string_view content_type, const RevisionWork& work);
HttpResponse answer_now(ApiCall& c, const Respond& respond, const RevisionWork& work);

// From the cache under `key`, or the revision's bytes read (and verified
// against its hash) here, since the store is the loop's, and `work` run on
// the service's pool; `answer` is called on the loop either way.
void answer_later(ApiCall& c, HttpAnswer answer, const std::string& key,
                  std::string_view content_type, RevisionWork work);
void answer_later(ApiCall& c, HttpAnswer answer, const std::string& key, Respond respond,
                  RevisionWork work);

}  // namespace usina::dnc
