// Who may do what in a classroom (control/classroom_access.h): seat tokens, the trainer's token,
// the read-only trainer view, `?token=` links turned into cookies, tokens from getrandom.
#include "control/classroom_access.h"

#include <gtest/gtest.h>

#include <set>

#include "control/http_server.h"

namespace {

using control::ClassroomAccess;

const std::string kTrainer(32, 't'), kSeat1(32, 'a'), kSeat2(32, 'b');

ClassroomAccess two_seats() { return ClassroomAccess({kTrainer, kSeat1, kSeat2}); }

control::http::Request request(std::string method, std::string path) {
  control::http::Request r;
  r.method = std::move(method);
  r.path = std::move(path);
  return r;
}
control::http::Request with_bearer(control::http::Request r, const std::string& token) {
  r.headers.emplace_back("Authorization", "Bearer " + token);
  return r;
}
control::http::Request with_cookie(control::http::Request r, const std::string& cookie) {
  r.headers.emplace_back("Cookie", cookie);
  return r;
}
std::string header(const control::http::Response& res, const std::string& name) {
  for (const auto& [k, v] : res.headers)
    if (k == name) return v;
  return {};
}

TEST(ClassroomAccess, RandomTokensAre128BitHexAndDiffer) {
  std::set<std::string> seen;
  for (int i = 0; i < 64; ++i) {
    const auto t = control::random_token();
    ASSERT_EQ(t.size(), 32u);
    EXPECT_EQ(t.find_first_not_of("0123456789abcdef"), std::string::npos);
    seen.insert(t);
  }
  EXPECT_EQ(seen.size(), 64u);
  const auto room = ClassroomAccess::random(3);
  EXPECT_EQ(room.seats(), 3u);
  EXPECT_NE(room.seat_token(1), room.seat_token(2));
  EXPECT_NE(room.trainer_token(), room.seat_token(3));
}

TEST(ClassroomAccess, TokensCompareWhole) {
  EXPECT_TRUE(control::tokens_equal(kSeat1, kSeat1));
  EXPECT_FALSE(control::tokens_equal(kSeat1, kSeat2));
  EXPECT_FALSE(control::tokens_equal(kSeat1.substr(0, 31), kSeat1));
  EXPECT_FALSE(control::tokens_equal(kSeat1 + "a", kSeat1));
  EXPECT_FALSE(control::tokens_equal("", kSeat1));
}

TEST(ClassroomAccess, PathsNameTheirSeat) {
  const auto room = two_seats();
  EXPECT_EQ(room.seat_of("/"), 0u);
  EXPECT_EQ(room.seat_of("/api/seats"), 0u);
  EXPECT_EQ(room.seat_of("/seats/1/api/nodes"), 1u);
  EXPECT_EQ(room.seat_of("/seats/2"), 2u);
  EXPECT_EQ(room.seat_of("/seats/3/"), std::nullopt);
  EXPECT_EQ(room.seat_of("/seats/0/"), std::nullopt);
  EXPECT_EQ(room.seat_of("/seats/01/"), std::nullopt);
  EXPECT_EQ(room.seat_of("/seats/x/"), std::nullopt);
  EXPECT_EQ(room.seat_of("/seats"), std::nullopt);
  EXPECT_EQ(room.seat_of("/seatsX"), 0u);
}

TEST(ClassroomAccess, WithoutATokenEverythingIs401) {
  const auto room = two_seats();
  for (const auto* path : {"/", "/api/seats", "/seats/1/", "/seats/1/api/nodes", "/seats/9/", "/classroom/classroom.js"}) {
    const auto res = room.check(request("GET", path));
    EXPECT_EQ(res.status, 401) << path;
    EXPECT_NE(res.body.find("\"error\""), std::string::npos) << path;
    EXPECT_EQ(header(res, "WWW-Authenticate"), "Bearer");
  }
  EXPECT_EQ(room.check(with_bearer(request("GET", "/seats/1/"), std::string(32, 'x'))).status, 401);
  EXPECT_EQ(room.check(with_bearer(request("GET", "/seats/1/"), "")).status, 401);
}

TEST(ClassroomAccess, ASeatTokenOpensOnlyItsSeat) {
  const auto room = two_seats();
  EXPECT_EQ(room.check(with_bearer(request("POST", "/seats/1/api/nmt"), kSeat1)).status, 0);
  EXPECT_EQ(room.check(with_cookie(request("POST", "/seats/1/api/nmt"), "vplant_token=" + kSeat1)).status, 0);
  EXPECT_EQ(room.check(with_bearer(request("GET", "/seats/2/api/nodes"), kSeat1)).status, 401);
  EXPECT_EQ(room.check(with_cookie(request("GET", "/seats/2/"), "vplant_token=" + kSeat1)).status, 401);
  EXPECT_EQ(room.check(with_bearer(request("GET", "/"), kSeat1)).status, 401);
  EXPECT_EQ(room.check(with_bearer(request("GET", "/api/seats"), kSeat2)).status, 401);
  // Another cookie beside it changes nothing.
  EXPECT_EQ(room.check(with_cookie(request("GET", "/seats/2/"), "other=1; vplant_token=" + kSeat2)).status, 0);
}

TEST(ClassroomAccess, TheTrainerOpensEverythingButOnlyLooksAtSeatsFromTheBrowser) {
  const auto room = two_seats();
  EXPECT_EQ(room.check(with_bearer(request("GET", "/api/seats"), kTrainer)).status, 0);
  EXPECT_EQ(room.check(with_cookie(request("POST", "/api/seats/1/restart"), "vplant_token=" + kTrainer)).status, 0);
  EXPECT_EQ(room.check(with_bearer(request("POST", "/seats/2/api/nmt"), kTrainer)).status, 0);
  // The cookie: a read-only view of a seat.
  EXPECT_EQ(room.check(with_cookie(request("GET", "/seats/2/api/nodes"), "vplant_token=" + kTrainer)).status, 0);
  const auto post = room.check(with_cookie(request("POST", "/seats/2/api/nmt"), "vplant_token=" + kTrainer));
  EXPECT_EQ(post.status, 403);
  EXPECT_NE(post.body.find("read-only"), std::string::npos);
  // With the seat's own cookie too (the trainer opened the seat's link), the seat acts.
  EXPECT_EQ(room.check(with_cookie(request("POST", "/seats/2/api/nmt"), "vplant_token=" + kSeat2 + "; vplant_token=" + kTrainer)).status, 0);
  // A seat that does not exist: 404 for the trainer only.
  EXPECT_EQ(room.check(with_bearer(request("GET", "/seats/3/"), kTrainer)).status, 404);
  EXPECT_EQ(room.check(with_bearer(request("GET", "/seats/3/"), kSeat1)).status, 401);
}

TEST(ClassroomAccess, ASeatWithoutItsSlashRedirectsToItsPage) {
  const auto room = two_seats();
  const auto res = room.check(request("GET", "/seats/2"));
  EXPECT_EQ(res.status, 308);
  EXPECT_EQ(header(res, "Location"), "/seats/2/");
  EXPECT_EQ(room.check(request("POST", "/seats/2")).status, 401);
  EXPECT_EQ(room.check(request("GET", "/seats/3")).status, 401);
}

TEST(ClassroomAccess, ATokenLinkBecomesAStrictHttpOnlyCookie) {
  const auto room = two_seats();
  auto link = request("GET", "/seats/1");
  link.query = {{"token", kSeat1}, {"view", "a b"}};
  const auto res = room.check(link);
  EXPECT_EQ(res.status, 303);
  EXPECT_EQ(header(res, "Location"), "/seats/1/?view=a%20b");
  EXPECT_EQ(header(res, "Set-Cookie"), "vplant_token=" + kSeat1 + "; Path=/seats/1/; HttpOnly; SameSite=Strict");
  auto trainer = request("GET", "/");
  trainer.query = {{"token", kTrainer}};
  const auto t = room.check(trainer);
  EXPECT_EQ(t.status, 303);
  EXPECT_EQ(header(t, "Location"), "/");
  EXPECT_EQ(header(t, "Set-Cookie"), "vplant_token=" + kTrainer + "; Path=/; HttpOnly; SameSite=Strict");
  // A link with another seat's token, a wrong one, or on a POST: 401, no cookie.
  auto wrong = request("GET", "/seats/2/");
  wrong.query = {{"token", kSeat1}};
  EXPECT_EQ(room.check(wrong).status, 401);
  wrong.query = {{"token", "nope"}};
  EXPECT_EQ(room.check(wrong).status, 401);
  auto post = request("POST", "/seats/1/api/nmt");
  post.query = {{"token", kSeat1}};
  const auto p = room.check(post);
  EXPECT_EQ(p.status, 401);
  EXPECT_EQ(header(p, "Set-Cookie"), "");
}

}  // namespace
