#include "control/classroom_access.h"

#include <strings.h>
#include <sys/random.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "control/http_server.h"

namespace control {

namespace {

void deny(http::Response& res, int status, const std::string& reason) {
  res.status = status;
  res.type = "application/json";
  res.body = http::error_body(reason);
  if (status == 401) res.headers.emplace_back("WWW-Authenticate", "Bearer");
}

/// Every `vplant_token` value in the request's Cookie headers (a browser may send several: the
/// trainer's for "/" and a seat's for "/seats/K/").
std::vector<std::string> token_cookies(const http::Request& req) {
  std::vector<std::string> out;
  for (const auto& [name, value] : req.headers) {
    if (strcasecmp(name.c_str(), "Cookie") != 0) continue;
    std::string_view rest = value;
    while (!rest.empty()) {
      const auto semi = rest.find(';');
      std::string_view pair = rest.substr(0, semi);
      rest = semi == std::string_view::npos ? std::string_view() : rest.substr(semi + 1);
      while (!pair.empty() && pair.front() == ' ') pair.remove_prefix(1);
      const auto eq = pair.find('=');
      if (eq != std::string_view::npos && pair.substr(0, eq) == kTokenCookie) out.emplace_back(pair.substr(eq + 1));
    }
  }
  return out;
}

std::optional<std::string> bearer(const http::Request& req) {
  const auto* h = req.header("Authorization");
  if (!h || h->size() < 7 || strncasecmp(h->c_str(), "Bearer ", 7) != 0) return std::nullopt;
  return h->substr(7);
}

/// The link without its token: the path, the other query parameters kept (re-encoded).
std::string without_token(const http::Request& req, std::optional<std::size_t> seat) {
  std::string location = req.path;
  if (seat && *seat > 0 && location.back() != '/') location += '/';  // "/seats/K" → the page at "/seats/K/"
  std::string query;
  for (const auto& [k, v] : req.query) {
    if (k == "token") continue;
    query += query.empty() ? '?' : '&';
    for (const std::string* part : {&k, &v}) {
      for (const unsigned char c : *part) {
        if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
          query += static_cast<char>(c);
        } else {
          static constexpr char kHex[] = "0123456789ABCDEF";
          query += '%';
          query += kHex[c >> 4];
          query += kHex[c & 15];
        }
      }
      if (part == &k) query += '=';
    }
  }
  return location + query;
}

}  // namespace

std::string random_token() {
  unsigned char bytes[16];
  std::size_t got = 0;
  while (got < sizeof bytes) {
    const auto n = ::getrandom(bytes + got, sizeof bytes - got, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(std::string("getrandom: ") + std::strerror(errno));
    got += static_cast<std::size_t>(n);
  }
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (const unsigned char b : bytes) {
    out += kHex[b >> 4];
    out += kHex[b & 15];
  }
  return out;
}

bool tokens_equal(std::string_view a, std::string_view b) {
  // Every byte of `b` (the secret) is visited whatever `a` holds; only the length is not hidden,
  // and every token has the same length.
  unsigned diff = a.size() == b.size() ? 0U : 1U;
  for (std::size_t i = 0; i < b.size(); ++i)
    diff |= static_cast<unsigned char>(i < a.size() ? a[i] : 0) ^ static_cast<unsigned char>(b[i]);
  return diff == 0;
}

ClassroomAccess::ClassroomAccess(std::vector<std::string> tokens) : tokens_(std::move(tokens)) {
  if (tokens_.size() < 2) throw std::invalid_argument("a classroom has a trainer and at least one seat");
}

ClassroomAccess ClassroomAccess::random(std::size_t seats) {
  std::vector<std::string> tokens;
  for (std::size_t k = 0; k <= seats; ++k) tokens.push_back(random_token());
  return ClassroomAccess(std::move(tokens));
}

std::optional<std::size_t> ClassroomAccess::seat_of(std::string_view path) const {
  constexpr std::string_view kSeats = "/seats/";
  if (path.substr(0, kSeats.size()) != kSeats && path != "/seats") return 0;
  path.remove_prefix(std::min(path.size(), kSeats.size()));
  const auto slash = path.find('/');
  const auto digits = path.substr(0, slash);
  if (digits.empty() || digits.size() > 3 || digits.front() == '0') return std::nullopt;
  std::size_t k = 0;
  for (const char c : digits) {
    if (c < '0' || c > '9') return std::nullopt;
    k = k * 10 + static_cast<std::size_t>(c - '0');
  }
  if (k > seats()) return std::nullopt;
  return k;
}

std::optional<std::size_t> ClassroomAccess::identify(std::string_view token) const {
  std::optional<std::size_t> who;
  for (std::size_t k = 0; k < tokens_.size(); ++k)
    if (tokens_equal(token, tokens_[k])) who = k;
  return who;
}

http::Response ClassroomAccess::check(const http::Request& req) const {
  http::Response res;
  res.status = 0;
  const auto seat = seat_of(req.path);
  const bool reads = req.method == "GET" || req.method == "HEAD";
  const std::string area = !seat ? "this page" : *seat == 0 ? "the trainer's overview" : "seat " + std::to_string(*seat);
  // "/seats/K" (a link typed without its slash): the seat cookie's path is "/seats/K/", so it is not
  // sent here; the redirect reveals nothing.
  if (seat && *seat > 0 && reads && !req.has_param("token") && req.path.find('/', 7) == std::string::npos) {
    res.status = 308;
    res.headers.emplace_back("Location", req.path + "/");
    return res;
  }
  // A `?token=` link: opens the page once, then the cookie carries the token (HttpOnly: the page's
  // scripts never see it; SameSite=Strict: another site cannot make the browser use it).
  if (req.has_param("token")) {
    const auto who = identify(req.param("token"));
    if (!who || !reads || (*who != 0 && (!seat || *seat != *who))) {
      deny(res, 401, "the token in this link does not open " + area);
      return res;
    }
    res.status = 303;
    res.type = "application/json";
    res.body = R"({"ok": true})";
    const std::string cookie_path = *who == 0 ? "/" : "/seats/" + std::to_string(*who) + "/";
    res.headers.emplace_back("Set-Cookie", std::string(kTokenCookie) + "=" + tokens_[*who] + "; Path=" + cookie_path +
                                               "; HttpOnly; SameSite=Strict");
    res.headers.emplace_back("Location", without_token(req, seat));
    res.headers.emplace_back("Cache-Control", "no-store");
    res.headers.emplace_back("Referrer-Policy", "no-referrer");
    return res;
  }
  // What the request carries: a script's bearer token acts fully; a browser's cookies act fully
  // on their own seat, while the trainer's cookie only looks at a seat.
  bool any = false, full = false, view = false;
  const auto grant = [&](const std::string& token, bool acts) {
    any = true;
    const auto who = identify(token);
    if (who && !seat) full = *who == 0;  // the trainer asks for a seat that does not exist: 404
    if (!who || !seat) return;
    if (*who == *seat) full = true;
    if (*who == 0 && *seat != 0) (acts ? full : view) = true;
  };
  if (const auto b = bearer(req)) grant(*b, true);
  for (const auto& c : token_cookies(req)) grant(c, false);
  if (full || (view && reads)) {
    if (!seat) deny(res, 404, "no such seat: " + req.path);
    return res;
  }
  if (view) {
    deny(res, 403, "the trainer's view of " + area + " is read-only (act from the overview, or as the seat)");
  } else if (!any) {
    deny(res, 401, "no token: open the link `vplant classroom` printed, or send Authorization: Bearer TOKEN");
  } else {
    deny(res, 401, "this token does not open " + area);
  }
  return res;
}

}  // namespace control
