#include "control/classroom_server.h"

#include <nlohmann/json.hpp>

#include "control/http_server.h"
#include "control/request_body.h"

namespace control {

using nlohmann::json;

namespace {

constexpr std::size_t kMaxBody = 64 * 1024;
constexpr unsigned kMaxConnectionsPerAddress = 64;

void reply(http::Response& res, int status, const json& body) {
  res.status = status;
  res.type = "application/json";
  res.body = body.dump(-1, ' ', false, json::error_handler_t::replace);
}

}  // namespace

struct ClassroomServer::Impl {
  ClassroomAccess access;
  std::vector<ClassroomSeat*> seats;
  std::string address;
  std::unique_ptr<http::Server> http;
  http::Router router;  // the trainer's endpoints

  Impl(ClassroomAccess a, std::vector<ClassroomSeat*> s) : access(std::move(a)), seats(std::move(s)) {}

  /// The path a seat sees: "/seats/K/api/nodes" → "/api/nodes".
  static std::string seat_path(const std::string& path) {
    const auto slash = path.find('/', std::string("/seats/").size());
    return slash == std::string::npos ? "/" : path.substr(slash);
  }

  http::Response admit(const http::Request& req) const {
    // The Host/Origin checks first (every seat listens where the classroom does), as a seat
    // would make them on the path it sees.
    http::Request seen;
    seen.method = req.method;
    seen.path = access.seat_of(req.path).value_or(0) > 0 ? seat_path(req.path) : req.path;
    seen.headers = req.headers;
    if (auto res = seats.front()->plane().admit(seen); res.status != 0) return res;
    return access.check(req);
  }

  void dispatch(http::Request& req, http::Response& res) {
    const auto seat = access.seat_of(req.path).value_or(0);
    if (seat > 0) {
      if (req.path.find('/', 7) == std::string::npos) {  // "/seats/K": the page's relative links need "/seats/K/"
        res.status = 308;
        res.headers.emplace_back("Location", req.path + "/");
        res.body = http::error_body("the seat's page is at " + req.path + "/");
        return;
      }
      req.path = seat_path(req.path);
      seats[seat - 1]->plane().handle(req, res);
      return;
    }
    if (router.dispatch(req, res)) return;
    if (req.path.rfind("/api/", 0) == 0 || req.method != "GET") {
      reply(res, 404, {{"error", "no such endpoint: " + req.path}});
      return;
    }
    serve_overview(req, res);
  }

  /// The overview's files: the page's built files hold them under /classroom/ (any control plane
  /// serves them; seat 1's does).
  void serve_overview(http::Request& req, http::Response& res) {
    if (req.path == "/") req.path = "/classroom/index.html";
    if (req.path.rfind("/classroom/", 0) != 0) return reply(res, 404, {{"error", "no such file: " + req.path}});
    seats.front()->plane().handle(req, res);
  }

  /// A request to seat k's control plane from the overview's endpoints.
  http::Response ask(std::size_t k, const std::string& method, const std::string& path, const std::string& body = {}) {
    http::Request r;
    r.method = method;
    r.path = path;
    r.body = body;
    http::Response res;
    seats[k - 1]->plane().handle(r, res);
    return res;
  }
  static json body_json(const http::Response& res) {
    auto j = json::parse(res.body, nullptr, false);
    return j.is_discarded() ? json() : j;
  }

  json seat_json(std::size_t k) {
    auto& seat = *seats[k - 1];
    json s = {{"seat", k}, {"running", seat.plane().bridge().attached() && !seat.plane().bridge().finished()}};
    const auto nodes = ask(k, "GET", "/api/nodes");
    s["nodes"] = nodes.status == 200 ? body_json(nodes) : json::array();
    const auto clock = ask(k, "GET", "/api/clock");
    s["clock"] = clock.status == 200 ? body_json(clock) : json();
    // The exercise endpoints (docs/exercises.md): null while the seat has none selected.
    const auto exercise = ask(k, "GET", "/api/exercise");
    auto progress = exercise.status == 200 ? body_json(exercise) : json();
    s["exercise"] = progress.is_object() && progress.contains("name") && progress["name"].is_string() ? progress : json();
    const auto& late = seat.lateness();
    s["lateness_us"] = late.count() == 0 ? json()
                                         : json{{"ticks", late.count()},
                                                {"p50", late.quantile_us(0.5)},
                                                {"p99", late.quantile_us(0.99)},
                                                {"max", late.max_us()}};
    return s;
  }

  /// The seat's answer, as the overview passes it on.
  static json answer_json(std::size_t k, const http::Response& res) {
    return {{"seat", k}, {"status", res.status}, {"answer", body_json(res)}};
  }

  void routes() {
    router.add("GET", "/api/seats", [this](http::Request&, http::Response& res) {
      json a = json::array();
      for (std::size_t k = 1; k <= seats.size(); ++k) a.push_back(seat_json(k));
      reply(res, 200, {{"seats", a}});
    });
    router.add("POST", R"(/api/seats/([0-9]{1,3})/restart)", [this](http::Request& req, http::Response& res) {
      const auto k = static_cast<std::size_t>(std::stoul(req.matches[1]));
      if (k < 1 || k > seats.size()) return reply(res, 404, {{"error", "no seat " + req.matches[1]}});
      const auto r = ask(k, "POST", "/api/restart", "{}");
      reply(res, r.status, answer_json(k, r));
    });
    // Every seat the same exercise: {"name": ...} as each seat's POST /api/exercise takes it.
    router.add("POST", "/api/seats/exercise", [this](http::Request& req, http::Response& res) {
      try {  // the shape here; each seat checks the name against its exercises
        RequestBody body(req.body, "the exercise choice");
        body.text("name");
        body.finish();
      } catch (const BodyError& e) {
        return reply(res, 400, {{"error", e.reason}});
      }
      json a = json::array();
      int worst = 200;
      for (std::size_t k = 1; k <= seats.size(); ++k) {
        const auto r = ask(k, "POST", "/api/exercise", req.body);
        worst = std::max(worst, r.status);
        a.push_back(answer_json(k, r));
      }
      reply(res, worst, {{"seats", a}});
    });
  }
};

ClassroomServer::ClassroomServer(ClassroomAccess access, std::vector<ClassroomSeat*> seats)
    : impl_(std::make_unique<Impl>(std::move(access), std::move(seats))) {
  impl_->routes();
}

ClassroomServer::~ClassroomServer() { stop(); }

std::string ClassroomServer::listen(const std::string& address, int port, bool allow_remote) {
  if (!is_loopback(address) && !allow_remote)
    return "--ui " + address + ": a non-loopback address needs --ui-allow-remote";
  http::Limits limits;
  limits.max_body = kMaxBody;
  limits.max_connections_per_ip = is_loopback(address) ? 0 : kMaxConnectionsPerAddress;
  auto& s = *impl_;
  s.http = std::make_unique<http::Server>(
      limits, [&s](http::Request& req, http::Response& res) { s.dispatch(req, res); },
      [&s](const http::Request& req) { return s.admit(req); });
  if (auto err = s.http->listen(address, port); !err.empty()) return err;
  s.address = address;
  for (auto* seat : s.seats) seat->plane().host_at(address, s.http->port());
  return {};
}

int ClassroomServer::port() const { return impl_->http ? impl_->http->port() : 0; }

void ClassroomServer::start() { impl_->http->start(); }

void ClassroomServer::stop() {
  if (impl_->http) impl_->http->stop();
}

std::vector<std::string> ClassroomServer::links() const {
  const std::string host = impl_->address == "0.0.0.0" ? "127.0.0.1" : impl_->address;
  const std::string base = "http://" + host + ":" + std::to_string(port());
  std::vector<std::string> out{base + "/?token=" + impl_->access.trainer_token()};
  for (std::size_t k = 1; k <= impl_->seats.size(); ++k)
    out.push_back(base + "/seats/" + std::to_string(k) + "/?token=" + impl_->access.seat_token(k));
  return out;
}

}  // namespace control
