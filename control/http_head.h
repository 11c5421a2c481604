// The check a request's head (request line and header block) passes before libmicrohttpd parses
// it. libmicrohttpd answers what it cannot parse with a built-in HTML page and offers no hook to
// change it, so everything it would refuse is refused here first, with a JSON reason: a head
// that passes this check is one it parses (docs/api.md, "Limits"; docs/architecture.md).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace control::http {

struct HeadLimits {
  std::size_t max_head = 16 * 1024;  ///< request line + header block, bytes
  std::size_t max_fields = 64;       ///< header fields; also query parameters and cookies
};

struct HeadVerdict {
  enum class Kind { Incomplete, Complete, Refused } kind = Kind::Incomplete;
  int status = 0;      ///< Refused: the HTTP status
  std::string reason;  ///< Refused: why, for the JSON error
};

/// Judges the bytes a connection has sent so far (the head and whatever follows it).
/// Incomplete: the head has not ended yet and is within the limit.
HeadVerdict check_head(std::string_view bytes, const HeadLimits& limits);

}  // namespace control::http
