// Who may do what in a classroom (`vplant classroom`, docs/classroom.md): one random token per
// seat and one for the trainer. A seat's token opens only its seat (/seats/K/...); the trainer's
// opens everything, but a browser that carries it as a cookie only looks at a seat (GET): the
// trainer's view of a trainee's plant is read-only, and the trainer acts through the overview's
// own endpoints (/api/seats/...). Decided once a request's headers are in, before its body is read.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace control::http {
struct Request;
struct Response;
}  // namespace control::http

namespace control {

/// 128 random bits (getrandom) as 32 lowercase hex digits; throws std::runtime_error when the
/// kernel has none to give.
std::string random_token();
/// Equal without an early exit: the time taken says nothing of where two tokens differ.
bool tokens_equal(std::string_view a, std::string_view b);

/// The name of the cookie a `?token=` link turns into.
inline constexpr std::string_view kTokenCookie = "vplant_token";

class ClassroomAccess {
 public:
  /// Tokens: [0] the trainer's, [k] seat k's (1-based).
  explicit ClassroomAccess(std::vector<std::string> tokens);
  /// Fresh random tokens for `seats` seats.
  static ClassroomAccess random(std::size_t seats);

  std::size_t seats() const { return tokens_.size() - 1; }
  const std::string& trainer_token() const { return tokens_[0]; }
  const std::string& seat_token(std::size_t seat) const { return tokens_.at(seat); }

  /// The seat a path belongs to: "/seats/K" or "/seats/K/..." with 1 <= K <= seats(); 0 = the
  /// trainer's area (the overview, /api/...); nullopt = a /seats/ path naming no seat.
  std::optional<std::size_t> seat_of(std::string_view path) const;

  /// The admission check: a response with status 0 admits `request`; else it is the answer
  /// (401 no or a wrong token, 403 a read-only view asked to change something, 404 no such seat,
  /// 303 a `?token=` link turned into a cookie).
  http::Response check(const http::Request& request) const;

 private:
  /// Who presents `token`: 0 the trainer, K seat K, nullopt nobody. Every token is compared.
  std::optional<std::size_t> identify(std::string_view token) const;
  std::vector<std::string> tokens_;
};

}  // namespace control
