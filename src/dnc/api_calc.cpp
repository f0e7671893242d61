// POST /api/calc/{open-loop|closed-loop|precision|cutting}: seed 004's
// calculators for the page, answered as `usina calc NAME --format json`
// prints them (sim/calc_json.hpp), so the page and the command line give
// the same figures and the same messages.
#include "dnc/api_json.hpp"
#include "dnc/api_router.hpp"
#include "sim/calc_json.hpp"

namespace usina::dnc {

HttpResponse api_calc(ApiCall& c) {
  auto body = json_body(c.req);
  if (!body) return error_response(c.req, http::status::bad_request, body.error());
  auto answer = sim::calc_from_json(c.params[0], *body);
  if (!answer) return error_response(c.req, http::status::bad_request, answer.error());
  return json_response(c.req, http::status::ok, *answer);
}

}  // namespace usina::dnc
