#include "control/http_head.h"

#include <strings.h>

#include <cstring>

namespace control::http {

namespace {

bool is_token_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  return (u >= '0' && u <= '9') || (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') ||
         (u != 0 && std::strchr("!#$%&'*+-.^_`|~", c) != nullptr);
}

bool is_token(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!is_token_char(c)) return false;
  return true;
}

bool same_name(std::string_view a, std::string_view b) {
  return a.size() == b.size() && ::strncasecmp(a.data(), b.data(), a.size()) == 0;
}

HeadVerdict refuse(int status, std::string reason) {
  return HeadVerdict{HeadVerdict::Kind::Refused, status, std::move(reason)};
}

/// Non-empty pieces of `s` between `sep` (query parameters, cookies).
std::size_t count_items(std::string_view s, char sep) {
  std::size_t n = 0;
  for (std::size_t at = 0; at <= s.size();) {
    auto end = s.find(sep, at);
    if (end == std::string_view::npos) end = s.size();
    if (end > at) ++n;
    at = end + 1;
  }
  return n;
}

/// One line without its "\n" and an optional "\r"; npos: the line has not ended within `bytes`.
std::size_t line_end(std::string_view bytes, std::size_t from, std::string_view& line) {
  const auto eol = bytes.find('\n', from);
  if (eol == std::string_view::npos) return eol;
  line = bytes.substr(from, eol - from);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return eol;
}

/// Control characters other than a tab (a bare CR included) or DEL.
bool has_control(std::string_view s) {
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\t') || u == 0x7f) return true;
  }
  return false;
}

}  // namespace

HeadVerdict check_head(std::string_view bytes, const HeadLimits& limits) {
  const std::string head_limit = std::to_string(limits.max_head) + " bytes";
  const std::string fields_limit = std::to_string(limits.max_fields);
  std::size_t at = 0;
  while (at < bytes.size() && (bytes[at] == '\r' || bytes[at] == '\n')) ++at;  // empty lines before it: allowed

  std::string_view line;
  auto eol = line_end(bytes, at, line);
  if (eol == std::string_view::npos || eol >= limits.max_head) {
    if (eol == std::string_view::npos && bytes.size() < limits.max_head) return {};
    return refuse(414, "the request line is longer than " + head_limit);
  }
  const auto sp1 = line.find(' ');
  const auto sp2 = sp1 == std::string_view::npos ? sp1 : line.find(' ', sp1 + 1);
  if (sp2 == std::string_view::npos || line.find(' ', sp2 + 1) != std::string_view::npos || has_control(line))
    return refuse(400, "malformed request line (expected: METHOD /path HTTP/1.1)");
  const auto method = line.substr(0, sp1);
  const auto target = line.substr(sp1 + 1, sp2 - sp1 - 1);
  const auto version = line.substr(sp2 + 1);
  if (!is_token(method)) return refuse(400, "malformed method in the request line");
  if (target.empty() || target.front() != '/') return refuse(400, "the request target must be a path starting with /");
  const bool http11 = version == "HTTP/1.1";
  if (!http11 && version != "HTTP/1.0") {
    const bool looks_like_http = version.size() == 8 && version.substr(0, 5) == "HTTP/" && version[6] == '.';
    if (looks_like_http) return refuse(505, "HTTP version " + std::string(version.substr(5)) + " is not supported (1.0 and 1.1 are)");
    return refuse(400, "malformed HTTP version in the request line");
  }
  if (const auto q = target.find('?'); q != std::string_view::npos && count_items(target.substr(q + 1), '&') > limits.max_fields)
    return refuse(414, "more than " + fields_limit + " query parameters");

  std::size_t fields = 0, cookies = 0;
  bool host = false, length = false;
  for (;;) {
    at = eol + 1;
    eol = line_end(bytes, at, line);
    if (eol == std::string_view::npos || eol >= limits.max_head) {
      if (eol == std::string_view::npos && bytes.size() < limits.max_head) return {};
      return refuse(431, "the request line and headers are larger than " + head_limit);
    }
    if (line.empty()) break;  // the end of the head
    if (line.front() == ' ' || line.front() == '\t')
      return refuse(400, "a header line starts with white space (folded header lines are not accepted)");
    const auto colon = line.find(':');
    if (colon == std::string_view::npos || !is_token(line.substr(0, colon)))
      return refuse(400, "malformed header line (expected: Name: value)");
    const auto name = line.substr(0, colon);
    auto value = line.substr(colon + 1);
    while (!value.empty() && (value.front() == ' ' || value.front() == '\t')) value.remove_prefix(1);
    while (!value.empty() && (value.back() == ' ' || value.back() == '\t')) value.remove_suffix(1);
    if (has_control(value)) return refuse(400, "a control character in the header " + std::string(name));
    if (++fields > limits.max_fields) return refuse(431, "more than " + fields_limit + " header fields");
    if (same_name(name, "Host")) {
      if (host) return refuse(400, "more than one Host header");
      host = true;
    } else if (same_name(name, "Content-Length")) {
      if (length) return refuse(400, "more than one Content-Length header");
      length = true;
      if (value.empty() || value.size() > 18 || value.find_first_not_of("0123456789") != std::string_view::npos)
        return refuse(400, "Content-Length '" + std::string(value) + "' is not a byte count");
    } else if (same_name(name, "Transfer-Encoding")) {
      return refuse(411, "send the body with a Content-Length (Transfer-Encoding is not accepted: " +
                             std::string(value) + ")");
    } else if (same_name(name, "Cookie")) {
      if ((cookies += count_items(value, ';')) > limits.max_fields)
        return refuse(431, "more than " + fields_limit + " cookies");
    }
  }
  if (http11 && !host) return refuse(400, "an HTTP/1.1 request needs a Host header");
  return HeadVerdict{HeadVerdict::Kind::Complete, 0, {}};
}

}  // namespace control::http
