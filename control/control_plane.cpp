#include "control/control_plane.h"

#include <arpa/inet.h>
#include <httplib.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "control/dictionary_catalog.h"
#include "control/event_hub.h"
#include "control/json_views.h"
#include "control/server_thread_priority.h"
#include "devices/canopen/nmt_state.h"
#include "devices/canopen/sdo_abort.h"
#include "engine/fault_injector.h"
#include "engine/master_monitor.h"
#include "engine/scenario.h"
#include "engine/value_codec.h"
#include "engine/yaml_fields.h"
#include "engine/world.h"
#include "sim/scheduler.h"
#ifdef VPLANT_HAVE_DASHBOARD
#include "dashboard/assets.h"
#endif

namespace control {

using nlohmann::json;

namespace {

constexpr std::size_t kMaxBody = 64 * 1024;
constexpr auto kCommandTimeout = std::chrono::milliseconds(2000);
// GET /api/findings answers at most this many findings (built between ticks: keep it short).
constexpr std::size_t kFindingsPage = 100;
constexpr auto kSdoWait = std::chrono::milliseconds(5000);

/// httplib's worker pool, its threads at lowered priority (control/server_thread_priority.h).
class LowPriorityPool final : public httplib::TaskQueue {
 public:
  explicit LowPriorityPool(std::size_t threads) : pool_(threads) {}
  void enqueue(std::function<void()> fn) override {
    pool_.enqueue([fn = std::move(fn)] {
      lower_this_thread_priority();
      fn();
    });
  }
  void shutdown() override { pool_.shutdown(); }

 private:
  httplib::ThreadPool pool_;
};

/// A client error: answered as {"error": reason} with its status, nothing changed.
struct HttpError {
  int status;
  std::string reason;
};

void reply(httplib::Response& res, int status, const json& body) {
  res.status = status;
  res.set_content(body.dump(), "application/json");
}

json parse_body(const httplib::Request& req) {
  json j = json::parse(req.body, nullptr, false);
  if (j.is_discarded()) throw HttpError{400, "malformed JSON body"};
  if (!j.is_object()) throw HttpError{400, "the body must be a JSON object"};
  return j;
}

/// An integer field given as a number or as text ("0x6040", "24640").
std::optional<std::int64_t> integer_field(const json& j, const char* key, std::int64_t lo, std::int64_t hi,
                                          std::optional<std::int64_t> fallback = std::nullopt) {
  if (!j.contains(key)) {
    if (fallback) return fallback;
    throw HttpError{400, std::string("missing field '") + key + "'"};
  }
  const auto& v = j[key];
  std::int64_t n = 0;
  if (v.is_number_integer()) {
    n = v.get<std::int64_t>();
  } else if (v.is_string()) {
    const auto s = v.get<std::string>();
    char* end = nullptr;
    errno = 0;
    n = std::strtoll(s.c_str(), &end, 0);
    if (s.empty() || *end != '\0' || errno != 0) throw HttpError{400, std::string("field '") + key + "' is not an integer"};
  } else {
    throw HttpError{400, std::string("field '") + key + "' is not an integer"};
  }
  if (n < lo || n > hi)
    throw HttpError{400, std::string("field '") + key + "' out of range " + std::to_string(lo) + ".." + std::to_string(hi)};
  return n;
}

std::string string_field(const json& j, const char* key, std::optional<std::string> fallback = std::nullopt) {
  if (!j.contains(key)) {
    if (fallback) return *fallback;
    throw HttpError{400, std::string("missing field '") + key + "'"};
  }
  if (!j[key].is_string()) throw HttpError{400, std::string("field '") + key + "' is not a string"};
  return j[key].get<std::string>();
}

double number_field(const json& j, const char* key) {
  if (!j.contains(key)) throw HttpError{400, std::string("missing field '") + key + "'"};
  if (!j[key].is_number()) throw HttpError{400, std::string("field '") + key + "' is not a number"};
  const double v = j[key].get<double>();
  if (!std::isfinite(v)) throw HttpError{400, std::string("field '") + key + "' is not finite"};
  return v;
}

bool bool_field(const json& j, const char* key, bool fallback) {
  if (!j.contains(key)) return fallback;
  if (!j[key].is_boolean()) throw HttpError{400, std::string("field '") + key + "' is not true/false"};
  return j[key].get<bool>();
}

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= s.size()) {
    const auto comma = s.find(',', start);
    const auto part = s.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (!part.empty()) out.push_back(part);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

const char* access_name(canopen::Access a) {
  switch (a) {
    case canopen::Access::ReadOnly: return "ro";
    case canopen::Access::WriteOnly: return "wo";
    case canopen::Access::ReadWrite: return "rw";
    case canopen::Access::Const: return "const";
  }
  return "rw";
}

/// A dictionary value as JSON: numbers for numeric types, text for visible strings, hex else.
json value_json(canopen::DataType type, const std::vector<std::uint8_t>& bytes) {
  using canopen::DataType;
  if (type == DataType::VisibleString) {
    std::string s(bytes.begin(), bytes.end());
    while (!s.empty() && s.back() == '\0') s.pop_back();
    return s;
  }
  if (canopen::is_variable_length(type) || bytes.size() != canopen::type_size(type)) return hex_string(bytes.data(), bytes.size());
  if (canopen::is_real(type)) return scenario::decode_number(type, bytes);
  if (canopen::is_signed_integer(type)) return canopen::decode_signed(bytes);
  return canopen::decode_unsigned(bytes);
}

std::string abort_hex(std::uint32_t code) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08X", code);
  return buf;
}

std::optional<canopen::NmtCommand> nmt_command(const std::string& s) {
  if (s == "start") return canopen::NmtCommand::Start;
  if (s == "stop") return canopen::NmtCommand::Stop;
  if (s == "preop") return canopen::NmtCommand::EnterPreOperational;
  if (s == "reset_node") return canopen::NmtCommand::ResetNode;
  if (s == "reset_comm") return canopen::NmtCommand::ResetCommunication;
  return std::nullopt;
}

}  // namespace

std::string parse_ui_address(std::string_view text, UiOptions& options) {
  std::string address = "127.0.0.1";
  std::string_view port_text = text;
  if (const auto colon = text.rfind(':'); colon != std::string_view::npos) {
    address = std::string(text.substr(0, colon));
    port_text = text.substr(colon + 1);
    if (address == "localhost") address = "127.0.0.1";
    in_addr a{};
    if (::inet_pton(AF_INET, address.c_str(), &a) != 1) return "'" + address + "' is not an IPv4 address";
  }
  int port = 0;
  for (const char c : port_text) {
    if (c < '0' || c > '9' || port > 65535) return "'" + std::string(port_text) + "' is not a port (0..65535)";
    port = port * 10 + (c - '0');
  }
  if (port_text.empty() || port > 65535) return "'" + std::string(port_text) + "' is not a port (0..65535)";
  options.address = address;
  options.port = port;
  return {};
}

bool is_loopback(const std::string& address) {
  in_addr a{};
  if (::inet_pton(AF_INET, address.c_str(), &a) != 1) return address == "localhost";
  return (ntohl(a.s_addr) >> 24) == 127;
}

struct ControlPlane::Server {
  ControlPlane& cp;
  httplib::Server http;
  std::thread listener;
  DictionaryCatalog catalog;
  std::unique_ptr<EventHub> hub;
  json scenario_json;
  std::map<std::string, std::size_t> node_index, bus_index, signal_index;
  std::vector<std::string> node_names, bus_names;
  std::vector<int> node_bus;
  std::vector<std::string> node_products;
  std::vector<std::vector<std::string>> node_inputs;
  const scenario::MasterMonitor* monitor = nullptr;

  explicit Server(ControlPlane& c) : cp(c) {}

  // ---- security -------------------------------------------------------------------------------
  bool host_allowed(const std::string& host) const {
    const auto colon = host.rfind(':');
    const std::string name = colon == std::string::npos ? host : host.substr(0, colon);
    const std::string port = colon == std::string::npos ? "80" : host.substr(colon + 1);
    if (port != std::to_string(cp.port_)) return false;
    if (name == cp.options_.address) return true;
    if (name == "localhost" || name == "127.0.0.1") return is_loopback(cp.options_.address);
    // Bound to every interface: an address literal cannot be a rebound DNS name.
    in_addr a{};
    return cp.options_.address == "0.0.0.0" && ::inet_pton(AF_INET, name.c_str(), &a) == 1;
  }

  httplib::Server::HandlerResponse check_request(const httplib::Request& req, httplib::Response& res) const {
    const auto host = req.get_header_value("Host");
    if (!host_allowed(host)) {
      reply(res, 403, {{"error", "Host '" + host + "' is not the address this server serves"}});
      return httplib::Server::HandlerResponse::Handled;
    }
    if (req.has_header("Origin")) {
      const auto origin = req.get_header_value("Origin");
      if (origin != "http://" + host) {
        reply(res, 403, {{"error", "Origin '" + origin + "' is not this server"}});
        return httplib::Server::HandlerResponse::Handled;
      }
    }
    return httplib::Server::HandlerResponse::Unhandled;
  }

  // ---- lookups --------------------------------------------------------------------------------
  std::size_t node(const std::string& name) const {
    const auto it = node_index.find(name);
    if (it == node_index.end()) throw HttpError{404, "no node '" + name + "'"};
    return it->second;
  }
  void need_run() const {
    if (!cp.bridge_.attached()) throw HttpError{503, "the run is starting"};
    if (cp.bridge_.finished()) throw HttpError{503, "the run has ended"};
  }
  template <typename R>
  R call(std::function<R(const scenario::RunContext&)> f) {
    need_run();
    auto r = cp.bridge_.call<R>(std::move(f), kCommandTimeout);
    if (!r) throw HttpError{503, "the simulation did not answer (the run has ended?)"};
    return std::move(*r);
  }
  json node_json_now(std::size_t i) {
    std::vector<NodeStatus> nodes;
    cp.bridge_.nodes(nodes);
    return node_json(node_names[i], bus_names[static_cast<std::size_t>(node_bus[i])], nodes[i]);
  }

  // ---- routes ---------------------------------------------------------------------------------
  using Handler = std::function<void(const httplib::Request&, httplib::Response&)>;
  Handler guarded(Handler h) {
    return [h = std::move(h)](const httplib::Request& req, httplib::Response& res) {
      try {
        h(req, res);
      } catch (const HttpError& e) {
        reply(res, e.status, {{"error", e.reason}});
      } catch (const std::exception& e) {
        reply(res, 500, {{"error", std::string("internal error: ") + e.what()}});
      }
    };
  }

  void build_static(const scenario::RunContext& ctx) {
    monitor = ctx.master_monitor;
    auto& world = ctx.world;
    const auto& sc = ctx.scenario;
    json buses = json::array();
    for (std::size_t b = 0; b < world.buses().size(); ++b) {
      const auto& bus = *world.buses()[b];
      bus_index[bus.name()] = b;
      bus_names.push_back(bus.name());
      const auto* spec = b < sc.buses.size() ? &sc.buses[b] : nullptr;
      buses.push_back({{"name", bus.name()},
                       {"wire", bus.transport() ? std::string(bus.transport()->name()) : std::string("virtual")},
                       {"bitrate", spec ? spec->bitrate : 0}});
    }
    json nodes = json::array(), device_faults = json::array(), inputs = json::array(), bus_off = json::array();
    for (std::size_t i = 0; i < world.nodes().size(); ++i) {
      auto& n = world.nodes()[i];
      catalog.add_node(n.device->node().od());
      node_index[n.spec->name] = i;
      node_names.push_back(n.spec->name);
      node_bus.push_back(n.bus);
      node_products.push_back(n.spec->device);
      nodes.push_back({{"name", n.spec->name},
                       {"product", n.spec->device},
                       {"variant", n.spec->variant},
                       {"node_id", n.device->node().node_id()},
                       {"bus", bus_names[static_cast<std::size_t>(n.bus)]},
                       {"profile", std::string(devices::to_string(n.device->profile_status().profile))}});
      for (const auto& f : n.device->faults())
        device_faults.push_back({{"node", n.spec->name}, {"name", f.name}, {"description", f.description}});
      std::vector<std::string> in;
      for (const auto& p : n.ports) {
        if (p.direction != sim::PortDirection::Input) continue;
        inputs.push_back({{"node", n.spec->name}, {"name", p.name}, {"unit", p.unit}});
        in.push_back(p.name);
      }
      node_inputs.push_back(std::move(in));
      bus_off.push_back(n.spec->name);
    }
    json signals = json::array();
    for (std::size_t s = 0; s < cp.bridge_.signals().size(); ++s) {
      const auto& sig = cp.bridge_.signals()[s];
      signal_index[sig.name] = s;
      signals.push_back(sig.name);
    }
    json plant = json::array();
    if (auto* p = world.plant())
      for (const auto& name : p->parameter_names()) plant.push_back(name);
    scenario_json = {
        {"name", sc.name},
        {"description", sc.description},
        {"clock",
         {{"mode", ctx.scheduler.mode() == sim::ClockMode::RealTime ? "realtime" : "virtual"},
          {"tick_us", ctx.scheduler.tick().count()}}},
        {"buses", buses},
        {"nodes", nodes},
        {"signals", signals},
        {"faults",
         {{"device", device_faults},
          {"wire", {"drop", "delay", "corrupt"}},
          {"bus_off", bus_off},
          {"power", {"off", "on", "cycle", "reset"}},
          {"plant", plant}}},
        {"inputs", inputs}};
  }

  void routes() {
    http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) { return check_request(req, res); });
    http.set_payload_max_length(kMaxBody);

    http.Get("/api/scenario", guarded([this](const httplib::Request&, httplib::Response& res) {
      need_run();
      reply(res, 200, scenario_json);
    }));
    http.Get("/api/nodes", guarded([this](const httplib::Request&, httplib::Response& res) {
      need_run();
      std::vector<NodeStatus> nodes;
      cp.bridge_.nodes(nodes);
      json a = json::array();
      for (std::size_t i = 0; i < nodes.size(); ++i)
        a.push_back(node_json(node_names[i], bus_names[static_cast<std::size_t>(node_bus[i])], nodes[i]));
      reply(res, 200, a);
    }));
    http.Get(R"(/api/nodes/([^/]+))", guarded([this](const httplib::Request& req, httplib::Response& res) {
      const auto i = node(req.matches[1]);
      need_run();
      reply(res, 200, node_json_now(i));
    }));
    http.Get(R"(/api/nodes/([^/]+)/od)", guarded([this](const httplib::Request& req, httplib::Response& res) { od(req, res); }));
    http.Post(R"(/api/nodes/([^/]+)/sdo)", guarded([this](const httplib::Request& req, httplib::Response& res) { sdo_write(req, res); }));
    http.Get(R"(/api/nodes/([^/]+)/sdo)", guarded([this](const httplib::Request& req, httplib::Response& res) { sdo_read(req, res); }));
    http.Post(R"(/api/nodes/([^/]+)/inputs)", guarded([this](const httplib::Request& req, httplib::Response& res) { set_input(req, res); }));
    http.Post("/api/nmt", guarded([this](const httplib::Request& req, httplib::Response& res) { nmt(req, res); }));
    http.Post("/api/frames", guarded([this](const httplib::Request& req, httplib::Response& res) { send_frame(req, res); }));
    http.Post("/api/faults", guarded([this](const httplib::Request& req, httplib::Response& res) { inject(req, res); }));
    http.Get("/api/faults", guarded([this](const httplib::Request& req, httplib::Response& res) { list_faults(req, res); }));
    http.Delete(R"(/api/faults/([^/]+))", guarded([this](const httplib::Request& req, httplib::Response& res) { clear_fault(req, res); }));
    http.Get("/api/signals", guarded([this](const httplib::Request& req, httplib::Response& res) { signals(req, res); }));
    // The verdict on the master: findings from ?since=N on, a page at a time, taken between ticks.
    http.Get("/api/findings", guarded([this](const httplib::Request& req, httplib::Response& res) {
      if (!monitor) throw HttpError{404, "this run has no master monitor"};
      std::size_t since = 0;
      if (req.has_param("since")) {
        const auto v = scenario::parse_integer(req.get_param_value("since"));
        if (!v || *v < 0) throw HttpError{400, "since must be a finding count (a non-negative integer)"};
        since = static_cast<std::size_t>(*v);
      }
      const auto* m = monitor;
      auto body = call<std::string>([m, since](const scenario::RunContext&) {
        return scenario::findings_json(m->findings(), m->rules(), m->bus_names(), since, kFindingsPage);
      });
      res.status = 200;
      res.set_content(std::move(body), "application/json");
    }));
    http.Get("/api/clock", guarded([this](const httplib::Request&, httplib::Response& res) {
      need_run();
      reply(res, 200, clock_json());
    }));
    http.Post("/api/clock", guarded([this](const httplib::Request& req, httplib::Response& res) { clock_control(req, res); }));
    http.Get("/api/events", [this](const httplib::Request& req, httplib::Response& res) { events(req, res); });

    // Anything else under /api: 405 when the path exists with another method, else 404.
    const auto fallback = guarded([](const httplib::Request& req, httplib::Response&) {
      static const std::vector<std::pair<std::regex, const char*>> known = {
          {std::regex("/api/scenario"), "GET"},
          {std::regex("/api/nodes"), "GET"},
          {std::regex("/api/nodes/[^/]+"), "GET"},
          {std::regex("/api/nodes/[^/]+/od"), "GET"},
          {std::regex("/api/nodes/[^/]+/sdo"), "GET, POST"},
          {std::regex("/api/nodes/[^/]+/inputs"), "POST"},
          {std::regex("/api/nmt"), "POST"},
          {std::regex("/api/frames"), "POST"},
          {std::regex("/api/faults"), "GET, POST"},
          {std::regex("/api/faults/[^/]+"), "DELETE"},
          {std::regex("/api/signals"), "GET"},
          {std::regex("/api/clock"), "GET, POST"},
          {std::regex("/api/findings"), "GET"},
          {std::regex("/api/events"), "GET"}};
      for (const auto& [re, methods] : known)
        if (std::regex_match(req.path, re)) throw HttpError{405, req.method + " is not allowed on " + req.path + " (use " + methods + ")"};
      throw HttpError{404, "no such endpoint: " + req.path};
    });
    http.Get("/api/.*", fallback);
    http.Post("/api/.*", fallback);
    http.Put("/api/.*", fallback);
    http.Delete("/api/.*", fallback);
    http.Patch("/api/.*", fallback);
    http.Get("/.*", [](const httplib::Request& req, httplib::Response& res) { serve_static(req, res); });
  }

  static void serve_static(const httplib::Request& req, httplib::Response& res) {
#ifdef VPLANT_HAVE_DASHBOARD
    if (const auto* asset = dashboard::find_asset(req.path)) {
      res.status = 200;
      res.set_content(std::string(asset->body), std::string(asset->content_type));
      return;
    }
    reply(res, 404, {{"error", "no such file: " + req.path}});
#else
    (void)req;
    reply(res, 404, {{"error", "dashboard not built (this build has the API only: see docs/api.md)"}});
#endif
  }

  json clock_json() const {
    const auto c = cp.bridge_.clock();
    return {{"mode", c.realtime ? "realtime" : "virtual"}, {"t_us", c.t_us},          {"paused", c.paused},
            {"tick_us", c.tick_us},                         {"speed", c.speed},        {"run_ticks_left", c.run_ticks_left},
            {"end_reached", c.end_reached}};
  }

  void od(const httplib::Request& req, httplib::Response& res) {
    const auto i = node(req.matches[1]);
    const auto& entries = catalog.entries(i);
    auto values = call<std::vector<std::vector<std::uint8_t>>>([i, &entries](const scenario::RunContext& c) {
      std::vector<std::vector<std::uint8_t>> v;
      v.reserve(entries.size());
      const auto& od = c.world.nodes()[i].device->node().od();
      for (const auto& e : entries) {
        const auto* entry = od.entry(e.index, e.sub);
        v.push_back(entry ? entry->value : std::vector<std::uint8_t>{});
      }
      return v;
    });
    json a = json::array();
    for (std::size_t k = 0; k < entries.size(); ++k) {
      const auto& e = entries[k];
      a.push_back({{"index", e.index},
                   {"sub", e.sub},
                   {"name", e.name},
                   {"type", std::string(canopen::type_name(e.type))},
                   {"access", access_name(e.access)},
                   {"pdo_mappable", e.pdo_mappable},
                   {"value", value_json(e.type, values[k])}});
    }
    reply(res, 200, a);
  }

  json sdo_result(const SdoOutcome& o, const CatalogEntry* entry, bool upload) {
    switch (o.kind) {
      case SdoOutcome::Kind::Done: {
        json r = {{"ok", true}};
        if (upload) {
          r["data"] = hex_string(o.data.data(), o.data.size());
          if (entry) r["value"] = value_json(entry->type, o.data);
        }
        return r;
      }
      case SdoOutcome::Kind::Aborted:
        return {{"ok", false},
                {"abort_code", abort_hex(o.abort_code)},
                {"abort_text", std::string(canopen::describe(static_cast<canopen::SdoAbort>(o.abort_code)))}};
      case SdoOutcome::Kind::Busy: throw HttpError{409, o.error};
      case SdoOutcome::Kind::Failed:
        if (o.abort_code != 0)
          return {{"ok", false},
                  {"abort_code", abort_hex(o.abort_code)},
                  {"abort_text", std::string(canopen::describe(static_cast<canopen::SdoAbort>(o.abort_code)))},
                  {"error", o.error}};
        throw HttpError{504, o.error};
    }
    return {};
  }

  void sdo_transfer(std::size_t i, bool upload, std::uint16_t index, std::uint8_t sub, std::vector<std::uint8_t> data,
                    const CatalogEntry* entry, httplib::Response& res) {
    need_run();
    auto future = cp.bridge_.sdo(i, upload, index, sub, std::move(data));
    if (future.wait_for(kSdoWait) != std::future_status::ready) throw HttpError{504, "the SDO transfer did not end in time"};
    SdoOutcome outcome;
    try {
      outcome = future.get();
    } catch (const std::future_error&) {  // the run ended before the command ran
      throw HttpError{503, "the run has ended"};
    }
    reply(res, 200, sdo_result(outcome, entry, upload));
  }

  void sdo_write(const httplib::Request& req, httplib::Response& res) {
    const auto i = node(req.matches[1]);
    const auto body = parse_body(req);
    const auto index = static_cast<std::uint16_t>(*integer_field(body, "index", 0, 0xFFFF));
    const auto sub = static_cast<std::uint8_t>(*integer_field(body, "sub", 0, 0xFF, 0));
    const auto* entry = catalog.find(i, index, sub);
    std::vector<std::uint8_t> data;
    if (body.contains("data")) {
      if (!body["data"].is_string() || !parse_hex(body["data"].get<std::string>(), data, 4096) || data.empty())
        throw HttpError{400, "field 'data' must be 1..4096 bytes of hex, e.g. \"0F00\""};
    } else if (body.contains("value")) {
      if (!entry)
        throw HttpError{400, "node '" + node_names[i] + "' has no object " + abort_hex(index).substr(6) +
                                 ":" + std::to_string(sub) + " (give \"data\" to send the request anyway)"};
      scenario::Literal lit;
      const auto& v = body["value"];
      if (v.is_number_integer()) {
        lit.kind = scenario::Literal::Kind::Integer;
        lit.integer = v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX)
                          ? throw HttpError{400, "value out of range"}
                          : v.get<std::int64_t>();
      } else if (v.is_number()) {
        lit.kind = scenario::Literal::Kind::Real;
        lit.real = v.get<double>();
      } else if (v.is_string()) {
        lit.kind = scenario::Literal::Kind::Text;
        lit.text = v.get<std::string>();
      } else {
        throw HttpError{400, "field 'value' must be a number or a string"};
      }
      if (auto err = scenario::encode_literal(entry->type, lit, data); !err.empty()) throw HttpError{400, err};
    } else {
      throw HttpError{400, "give 'value' or 'data'"};
    }
    sdo_transfer(i, false, index, sub, std::move(data), entry, res);
  }

  void sdo_read(const httplib::Request& req, httplib::Response& res) {
    const auto i = node(req.matches[1]);
    json q = json::object();
    if (!req.has_param("index")) throw HttpError{400, "missing parameter 'index'"};
    q["index"] = req.get_param_value("index");
    if (req.has_param("sub")) q["sub"] = req.get_param_value("sub");
    const auto index = static_cast<std::uint16_t>(*integer_field(q, "index", 0, 0xFFFF));
    const auto sub = static_cast<std::uint8_t>(*integer_field(q, "sub", 0, 0xFF, 0));
    sdo_transfer(i, true, index, sub, {}, catalog.find(i, index, sub), res);
  }

  void set_input(const httplib::Request& req, httplib::Response& res) {
    const auto i = node(req.matches[1]);
    const auto body = parse_body(req);
    const auto name = string_field(body, "name");
    const double value = number_field(body, "value");
    const auto err = call<std::string>([i, name, value](const scenario::RunContext& c) {
      return c.world.nodes()[i].device->set_input(name, value);
    });
    if (!err.empty()) throw HttpError{400, err};
    reply(res, 200, {{"ok", true}});
  }

  void nmt(const httplib::Request& req, httplib::Response& res) {
    const auto body = parse_body(req);
    const auto command = nmt_command(string_field(body, "command"));
    if (!command) throw HttpError{400, "field 'command' must be start, stop, preop, reset_node or reset_comm"};
    if (!body.contains("node")) throw HttpError{400, "missing field 'node' (a node's name, or 0 for all)"};
    std::optional<std::size_t> target;
    if (body["node"].is_string()) target = node(body["node"].get<std::string>());
    else if (*integer_field(body, "node", 0, 0) != 0) throw HttpError{400, "field 'node' must be a node's name or 0"};
    const auto cmd = static_cast<std::uint8_t>(*command);
    call<bool>([this, cmd, target](const scenario::RunContext& c) {
      auto& world = c.world;
      for (std::size_t b = 0; b < world.buses().size(); ++b) {
        std::uint8_t id = 0;  // 0: every node on every bus
        if (target) {
          auto& n = world.nodes()[*target];
          if (static_cast<std::size_t>(n.bus) != b) continue;
          id = n.device->node().node_id();
        }
        cp.bridge_.send_frame(b, sim::CanFrame::data_frame(0x000, {cmd, id}));
      }
      return true;
    });
    reply(res, 200, {{"ok", true}});
  }

  void send_frame(const httplib::Request& req, httplib::Response& res) {
    const auto body = parse_body(req);
    const auto bus_name = string_field(body, "bus", bus_names.front());
    const auto b = bus_index.find(bus_name);
    if (b == bus_index.end()) throw HttpError{404, "no bus '" + bus_name + "'"};
    const bool ext = bool_field(body, "extended", false);
    const bool rtr = bool_field(body, "rtr", false);
    const auto id = static_cast<std::uint32_t>(*integer_field(body, "id", 0, ext ? sim::CanFrame::kMaxExtId : sim::CanFrame::kMaxStdId));
    std::vector<std::uint8_t> data;
    if (body.contains("data") && (!body["data"].is_string() || !parse_hex(body["data"].get<std::string>(), data, 8)))
      throw HttpError{400, "field 'data' must be 0..8 bytes of hex"};
    sim::CanFrame f = rtr ? sim::CanFrame::remote_frame(id, static_cast<std::uint8_t>(*integer_field(body, "dlc", 0, 8, 0)))
                          : sim::CanFrame::data_frame(id, data);
    f.extended = ext;
    const auto bus = b->second;
    call<bool>([this, bus, f](const scenario::RunContext&) {
      cp.bridge_.send_frame(bus, f);
      return true;
    });
    reply(res, 200, {{"ok", true}});
  }

  scenario::FaultSpec fault_spec(const json& body) {
    scenario::FaultSpec spec;
    spec.mark = scenario::SourceMark{"api", 0, 0};
    const auto kind = string_field(body, "kind");
    if (kind == "device") {
      scenario::DeviceFault d;
      d.node = node_names[node(string_field(body, "node"))];
      d.fault = string_field(body, "fault");
      d.active = bool_field(body, "active", true);
      spec.summary = "device " + d.node + " " + d.fault + (d.active ? "" : " (cleared)");
      spec.action = d;
    } else if (kind == "wire") {
      scenario::WireFault w;
      w.bus = string_field(body, "bus", bus_names.front());
      if (!bus_index.count(w.bus)) throw HttpError{404, "no bus '" + w.bus + "'"};
      w.match.id = static_cast<std::uint32_t>(*integer_field(body, "match", 0, sim::CanFrame::kMaxStdId));
      w.match.mask = static_cast<std::uint32_t>(*integer_field(body, "mask", 0, sim::CanFrame::kMaxStdId, 0x7FF));
      const auto action = string_field(body, "action");
      if (action == "drop") {
        w.kind = scenario::WireFault::Kind::Drop;
      } else if (action == "delay") {
        w.kind = scenario::WireFault::Kind::Delay;
        w.delay = sim::milliseconds(*integer_field(body, "delay_ms", 1, 60000));
      } else if (action == "corrupt") {
        w.kind = scenario::WireFault::Kind::Corrupt;
        w.byte = static_cast<int>(*integer_field(body, "byte", 0, 7, 0));
        w.xor_mask = static_cast<std::uint8_t>(*integer_field(body, "xor", 0, 255, 0xFF));
      } else {
        throw HttpError{400, "field 'action' must be drop, delay or corrupt"};
      }
      if (body.contains("probability")) {
        w.probability = number_field(body, "probability");
        if (w.probability < 0 || w.probability > 1) throw HttpError{400, "field 'probability' out of range 0..1"};
      }
      w.count = static_cast<std::uint64_t>(*integer_field(body, "count", 0, 1000000000, 0));
      char buf[96];
      std::snprintf(buf, sizeof buf, "wire %s %s 0x%03X/0x%03X", w.bus.c_str(), action.c_str(), w.match.id, w.match.mask);
      spec.summary = buf;
      spec.action = w;
    } else if (kind == "bus_off") {
      scenario::BusOff b;
      b.node = node_names[node(string_field(body, "node"))];
      spec.summary = "bus-off " + b.node;
      spec.action = b;
    } else if (kind == "power") {
      scenario::Power p;
      p.node = node_names[node(string_field(body, "node"))];
      const auto action = string_field(body, "action");
      if (action == "off") p.kind = scenario::Power::Kind::Off;
      else if (action == "on") p.kind = scenario::Power::Kind::On;
      else if (action == "reset") p.kind = scenario::Power::Kind::Reset;
      else if (action == "cycle") p.kind = scenario::Power::Kind::Cycle;
      else throw HttpError{400, "field 'action' must be off, on, cycle or reset"};
      p.off_time = sim::milliseconds(*integer_field(body, "off_ms", 0, 60000, 0));
      spec.summary = "power " + action + " " + p.node;
      spec.action = p;
    } else if (kind == "plant") {
      scenario::PlantParameter p;
      p.name = string_field(body, "name");
      p.value = number_field(body, "value");
      spec.summary = "plant " + p.name + " = " + scenario::format_value(p.value);
      spec.action = p;
    } else {
      throw HttpError{400, "field 'kind' must be device, wire, bus_off, power or plant"};
    }
    return spec;
  }

  void inject(const httplib::Request& req, httplib::Response& res) {
    const auto spec = fault_spec(parse_body(req));
    struct Result {
      std::string error;
      int id = 0;
      bool active = false;
    };
    const auto r = call<Result>([this, spec](const scenario::RunContext& c) {
      Result out;
      const auto now = c.scheduler.now();
      SimBridge::LiveFault live;
      if (const auto* p = std::get_if<scenario::PlantParameter>(&spec.action)) {
        // Checked and applied here, so a refused value changes nothing and fails no verdict.
        auto* plant = c.world.plant();
        if (!plant) return Result{"the scenario has no plant", 0, false};
        const auto old = plant->parameter(p->name);
        if (!old) return Result{"the plant has no parameter '" + p->name + "'", 0, false};
        if (auto err = plant->set_parameter(p->name, p->value); !err.empty()) return Result{err, 0, false};
        const std::string name = p->name;
        const double value = *old;
        live.clear = [plant, name, value](sim::Time) { plant->set_parameter(name, value); };
      } else {
        try {
          c.faults.check(spec);
        } catch (const std::exception& e) {
          std::string why = e.what();
          if (const auto at = why.find("fault: "); at != std::string::npos) why = why.substr(at + 7);
          return Result{why, 0, false};
        }
        live.clear = c.faults.apply_clearable(spec, now);
      }
      out.id = cp.bridge_.next_fault_id();
      out.active = static_cast<bool>(live.clear);
      if (out.active) {
        live.id = out.id;
        live.summary = spec.summary;
        live.since_us = now.time_since_epoch().count();
        cp.bridge_.live_faults().push_back(std::move(live));
      }
      return out;
    });
    if (!r.error.empty()) throw HttpError{400, r.error};
    reply(res, 200, {{"ok", true}, {"id", r.id}, {"active", r.active}});
  }

  void list_faults(const httplib::Request&, httplib::Response& res) {
    const auto a = call<json>([this](const scenario::RunContext&) {
      json out = json::array();
      for (const auto& f : cp.bridge_.live_faults())
        out.push_back({{"id", f.id}, {"summary", f.summary}, {"since_t_us", f.since_us}});
      return out;
    });
    reply(res, 200, a);
  }

  void clear_fault(const httplib::Request& req, httplib::Response& res) {
    json q = {{"id", std::string(req.matches[1])}};
    const int id = static_cast<int>(*integer_field(q, "id", 1, INT32_MAX));
    const bool found = call<bool>([this, id](const scenario::RunContext& c) {
      auto& faults = cp.bridge_.live_faults();
      for (auto it = faults.begin(); it != faults.end(); ++it) {
        if (it->id != id) continue;
        auto clear = std::move(it->clear);
        faults.erase(it);
        clear(c.scheduler.now());
        return true;
      }
      return false;
    });
    if (!found) throw HttpError{404, "no active fault " + std::to_string(id)};
    reply(res, 200, {{"ok", true}});
  }

  std::vector<std::size_t> signal_list(const std::string& names) const {
    std::vector<std::size_t> out;
    for (const auto& n : split_list(names)) {
      const auto it = signal_index.find(n);
      if (it == signal_index.end()) throw HttpError{400, "unknown signal '" + n + "' (see /api/scenario)"};
      out.push_back(it->second);
    }
    return out;
  }

  void signals(const httplib::Request& req, httplib::Response& res) {
    auto list = signal_list(req.get_param_value("names"));
    if (!req.has_param("names"))
      for (std::size_t s = 0; s < cp.bridge_.signals().size(); ++s) list.push_back(s);
    const auto& sigs = cp.bridge_.signals();
    const auto values = call<std::pair<std::int64_t, std::vector<double>>>([&sigs, list](const scenario::RunContext& c) {
      std::vector<double> v;
      for (const auto s : list) v.push_back(*sigs[s].value);
      return std::make_pair(static_cast<std::int64_t>(c.scheduler.now().time_since_epoch().count()), v);
    });
    json vals = json::object();
    for (std::size_t k = 0; k < list.size(); ++k) vals[sigs[list[k]].name] = values.second[k];
    reply(res, 200, {{"t_us", values.first}, {"values", vals}});
  }

  void clock_control(const httplib::Request& req, httplib::Response& res) {
    const auto body = parse_body(req);
    const auto action = string_field(body, "action");
    need_run();
    if (cp.bridge_.clock().realtime) throw HttpError{409, "the clock is real time: it cannot be paused or stepped"};
    std::optional<double> speed;
    if (body.contains("speed")) {
      speed = number_field(body, "speed");
      if (*speed < 0 || *speed > 1000) throw HttpError{400, "field 'speed' out of range 0..1000 (0 = as fast as possible)"};
    }
    bool ok = false;
    if (action == "pause") {
      ok = cp.bridge_.pause();
    } else if (action == "resume") {
      ok = cp.bridge_.resume(speed);
    } else if (action == "step") {
      ok = cp.bridge_.run_ticks(1);
    } else if (action == "run") {
      const auto ms = *integer_field(body, "ms", 1, 3600000);
      const auto tick = cp.bridge_.clock().tick_us;
      ok = cp.bridge_.run_ticks(static_cast<std::uint64_t>((ms * 1000 + tick - 1) / tick));
    } else {
      throw HttpError{400, "field 'action' must be pause, resume, step or run"};
    }
    if (!ok) throw HttpError{503, "the run has ended"};
    reply(res, 200, {{"ok", true}});
  }

  void events(const httplib::Request& req, httplib::Response& res) {
    try {
      need_run();
      const auto list = signal_list(req.get_param_value("signals"));
      double rate = 10;
      if (req.has_param("rate")) {
        json q = {{"rate", req.get_param_value("rate")}};
        rate = static_cast<double>(*integer_field(q, "rate", 1, 50));
      }
      auto client = hub->open(list, rate);
      if (!client) throw HttpError{503, "too many event streams (at most " + std::to_string(cp.options_.max_streams) + ")"};
      res.set_header("Cache-Control", "no-cache");
      res.set_chunked_content_provider(
          "text/event-stream",
          [client](std::size_t, httplib::DataSink& sink) {
            std::string chunk;
            const bool open = client->next(chunk, std::chrono::milliseconds(1000));
            if (chunk.empty()) chunk = ": keep-alive\n\n";
            if (!sink.is_writable() || !sink.write(chunk.data(), chunk.size())) return false;
            if (!open) sink.done();
            return true;
          },
          [this, client](bool) { hub->close(client); });
    } catch (const HttpError& e) {
      reply(res, e.status, {{"error", e.reason}});
    }
  }
};

ControlPlane::ControlPlane(UiOptions options) : options_(std::move(options)), bridge_(options_.clock) {
  server_ = std::make_unique<Server>(*this);
}

ControlPlane::~ControlPlane() {
  if (server_->hub) server_->hub->stop();
  server_->http.stop();
  if (server_->listener.joinable()) server_->listener.join();
}

std::string ControlPlane::bind() {
  if (!is_loopback(options_.address) && !options_.allow_remote)
    return "--ui " + options_.address + ": a non-loopback address needs --ui-allow-remote";
  auto& http = server_->http;
  http.new_task_queue = [this] { return new LowPriorityPool(options_.max_streams + 4); };
  if (options_.port == 0) {
    port_ = http.bind_to_any_port(options_.address);
    if (port_ <= 0) return "cannot listen on " + options_.address;
  } else {
    if (!http.bind_to_port(options_.address, options_.port)) return "cannot listen on " + options_.address + ":" + std::to_string(options_.port) + " (in use?)";
    port_ = options_.port;
  }
  if (!is_loopback(options_.address) && options_.out)
    std::fprintf(options_.out,
                 "vplant: WARNING: the control plane listens on %s: anyone who reaches this address can drive the plant "
                 "(no authentication)\n",
                 options_.address.c_str());
  return {};
}

std::string ControlPlane::url() const {
  const std::string host = options_.address == "0.0.0.0" ? "127.0.0.1" : options_.address;
  return "http://" + host + ":" + std::to_string(port_) + "/";
}

void ControlPlane::attach(const scenario::RunContext& context) {
  bridge_.attach(context);
  auto& s = *server_;
  s.build_static(context);
  s.hub = std::make_unique<EventHub>(bridge_, s.catalog, StreamTopology{s.bus_names, s.node_names, s.node_bus},
                                     options_.max_streams);
  s.hub->start();
  s.routes();
  s.listener = std::thread([this] {
    lower_this_thread_priority();
    server_->http.listen_after_bind();
  });
  if (options_.out) {
    std::fprintf(options_.out, "vplant: control plane at %s%s\n", url().c_str(),
                 context.scheduler.mode() == sim::ClockMode::Virtual && options_.clock.start_paused
                     ? " (virtual time, paused: resume from the dashboard or POST /api/clock)"
                     : "");
    std::fflush(options_.out);
  }
}

void ControlPlane::detach() { bridge_.detach(); }

}  // namespace control
