#include "control/control_plane.h"

#include <arpa/inet.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "control/dictionary_catalog.h"
#include "control/event_hub.h"
#include "control/http_server.h"
#include "control/json_views.h"
#include "control/pdo_view.h"
#include "control/request_body.h"
#include "control/machine_views.h"
#include "control/server_thread_priority.h"
#include "devices/canopen/nmt_command.h"
#include "devices/canopen/sdo_abort.h"
#include "engine/loading/fault_codec.h"
#include "engine/running/fault_injector.h"
#include "engine/running/master_monitor.h"
#include "engine/running/rpdo_frame.h"
#include "engine/loading/scenario.h"
#include "engine/loading/value_codec.h"
#include "engine/loading/yaml_fields.h"
#include "engine/running/world.h"
#include "sim/scheduler.h"
#ifdef VPLANT_HAVE_DASHBOARD
#include "dashboard/assets.h"
#endif

namespace control {

using nlohmann::json;

namespace {

constexpr std::size_t kMaxBody = 64 * 1024;
constexpr unsigned kMaxConnectionsPerAddress = 64;
constexpr std::size_t kMaxLiveFaults = 256;
constexpr auto kCommandTimeout = std::chrono::milliseconds(2000);
// GET /api/findings answers at most this many findings (built between ticks: keep it short).
constexpr std::size_t kFindingsPage = 100;
constexpr auto kSdoWait = std::chrono::milliseconds(5000);
// POST /api/sync: a minute between SYNCs is far beyond any cycle a lesson shows.
constexpr std::int64_t kMaxSyncPeriodMs = 60000;
// POST /api/restart: the rebuild (dictionaries, EDS files, plant) takes well under a second.
constexpr auto kRestartWait = std::chrono::seconds(10);

/// A client error: answered as {"error": reason} with its status, nothing changed.
struct HttpError {
  int status;
  std::string reason;
};

/// A JSON answer; text that is not valid UTF-8 (a node name, a header echoed) is replaced, so the
/// reply is always valid JSON.
void reply(http::Response& res, int status, const json& body) {
  res.status = status;
  res.type = "application/json";
  res.body = body.dump(-1, ' ', false, json::error_handler_t::replace);
}

/// An integer in a path or query parameter ("12", "0x0C"): the scenario's integer syntax.
std::int64_t query_integer(const std::string& text, const char* what, std::int64_t lo, std::int64_t hi) {
  const auto n = scenario::parse_integer(text);
  if (!n) throw HttpError{400, std::string(what) + " '" + text + "' is not an integer"};
  if (*n < lo || *n > hi)
    throw HttpError{400, std::string(what) + " out of range " + std::to_string(lo) + ".." + std::to_string(hi)};
  return *n;
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
std::string abort_hex(std::uint32_t code) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08X", code);
  return buf;
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

/// An event-hub client as the server's streaming body.
class EventStream final : public http::Stream {
 public:
  EventStream(EventHub& hub, std::shared_ptr<EventHub::Client> client) : hub_(hub), client_(std::move(client)) {}
  bool poll(std::string& out) override { return client_->next(out, std::chrono::milliseconds(0)); }
  void close() override { hub_.close(client_); }

 private:
  EventHub& hub_;
  std::shared_ptr<EventHub::Client> client_;
};

struct ControlPlane::Server {
  ControlPlane& cp;
  http::Router router;
  std::unique_ptr<http::Server> http;
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

  /// Runs once the headers are in, before the body is read (http::Admission).
  http::Response check_request(const http::Request& req) const {
    http::Response res;
    res.status = 0;
    const auto host = req.header_value("Host");
    if (!host_allowed(host)) {
      reply(res, 403, {{"error", "Host '" + host + "' is not the address this server serves"}});
    } else if (req.has_header("Origin") && req.header_value("Origin") != "http://" + host) {
      reply(res, 403, {{"error", "Origin '" + req.header_value("Origin") + "' is not this server"}});
    } else if (const auto site = req.header_value("Sec-Fetch-Site");
               req.path.rfind("/api/", 0) == 0 && (site == "cross-site" || site == "same-site")) {
      // A browser says where a request comes from even when it sends no Origin (<img>, <form>).
      reply(res, 403, {{"error", "a request from another site (Sec-Fetch-Site: " + site + ") may not use the API"}});
    }
    return res;
  }

  /// Every request that passed check_request (a worker thread).
  void dispatch(http::Request& req, http::Response& res) {
    if (router.dispatch(req, res)) return;
    if (req.path.rfind("/api/", 0) == 0 || req.method != "GET") {
      reply(res, 404, {{"error", "no such endpoint: " + req.path}});
      return;
    }
    serve_static(req, res);
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
    SimBridge::Posted posted{};
    auto r = cp.bridge_.call<R>(std::move(f), kCommandTimeout, &posted);
    if (posted == SimBridge::Posted::Full)
      throw HttpError{429, "too many commands wait for the simulation (at most " + std::to_string(kMaxQueuedCommands) +
                               "): retry later"};
    if (!r) throw HttpError{503, "the simulation did not answer (the run has ended?)"};
    return std::move(*r);
  }
  json node_json_now(std::size_t i) {
    std::vector<NodeStatus> nodes;
    cp.bridge_.nodes(nodes);
    return node_json(node_names[i], bus_names[static_cast<std::size_t>(node_bus[i])], nodes[i],
                     [this, i](std::uint16_t code) { return catalog.emcy_text(i, code); });
  }

  // ---- routes ---------------------------------------------------------------------------------
  using Handler = std::function<void(const http::Request&, http::Response&)>;
  Handler guarded(Handler h) {
    return [h = std::move(h)](const http::Request& req, http::Response& res) {
      try {
        h(req, res);
      } catch (const HttpError& e) {
        reply(res, e.status, {{"error", e.reason}});
      } catch (const BodyError& e) {
        reply(res, 400, {{"error", e.reason}});
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
      catalog.add_node(*n.device);
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
        auto input = signal_json(p.name, p.unit, p.display);
        input["node"] = n.spec->name;
        inputs.push_back(std::move(input));
        in.push_back(p.name);
      }
      node_inputs.push_back(std::move(in));
      bus_off.push_back(n.spec->name);
    }
    json signals = json::array();
    for (std::size_t s = 0; s < cp.bridge_.signals().size(); ++s) {
      const auto& sig = cp.bridge_.signals()[s];
      signal_index[sig.name] = s;
      signals.push_back(signal_json(sig.name, sig.unit, sig.display));
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
          {"power", {"power_off", "power_on", "power_cycle", "reset"}},
          {"plant", plant}}},
        {"inputs", inputs}};
  }

  void routes() {
    router.add("GET", "/api/scenario", guarded([this](const http::Request&, http::Response& res) {
      need_run();
      reply(res, 200, scenario_json);
    }));
    router.add("GET", "/api/nodes", guarded([this](const http::Request&, http::Response& res) {
      need_run();
      std::vector<NodeStatus> nodes;
      cp.bridge_.nodes(nodes);
      json a = json::array();
      for (std::size_t i = 0; i < nodes.size(); ++i)
        a.push_back(node_json(node_names[i], bus_names[static_cast<std::size_t>(node_bus[i])], nodes[i],
                              [this, i](std::uint16_t code) { return catalog.emcy_text(i, code); }));
      reply(res, 200, a);
    }));
    router.add("GET", R"(/api/nodes/([^/]+))", guarded([this](const http::Request& req, http::Response& res) {
      const auto i = node(req.matches[1]);
      need_run();
      reply(res, 200, node_json_now(i));
    }));
    router.add("GET", R"(/api/nodes/([^/]+)/transitions)", guarded([this](const http::Request& req, http::Response& res) {
      const auto i = node(req.matches[1]);
      std::uint64_t after = 0;
      if (req.has_param("after")) {
        const auto text = req.param("after");
        char* end = nullptr;
        errno = 0;
        after = std::strtoull(text.c_str(), &end, 10);
        if (text.empty() || *end != '\0' || errno != 0 || text[0] == '-') throw HttpError{400, "'after' is not a sequence number"};
      }
      const auto entries = call<std::vector<devices::Transition>>([i, after](const scenario::RunContext& c) {
        return transitions_after(c.world.nodes()[i].device->transition_log(), after);
      });
      json a = json::array();
      for (const auto& t : entries) a.push_back(transition_json(t));
      reply(res, 200, a);
    }));
    router.add("GET", R"(/api/nodes/([^/]+)/machines)", guarded([this](const http::Request& req, http::Response& res) {
      const auto i = node(req.matches[1]);
      auto m = call<std::pair<bool, std::vector<devices::MachineView>>>([i](const scenario::RunContext& c) {
        auto& dev = *c.world.nodes()[i].device;
        return std::make_pair(dev.node().powered(), dev.machines());
      });
      reply(res, 200, machines_json(node_names[i], m.first, m.second));
    }));
    router.add("GET", R"(/api/nodes/([^/]+)/od)", guarded([this](const http::Request& req, http::Response& res) { od(req, res); }));
    router.add("POST", R"(/api/nodes/([^/]+)/sdo)", guarded([this](const http::Request& req, http::Response& res) { sdo_write(req, res); }));
    router.add("POST", R"(/api/nodes/([^/]+)/sdo/read)", guarded([this](const http::Request& req, http::Response& res) { sdo_read(req, res); }));
    router.add("POST", R"(/api/nodes/([^/]+)/inputs)", guarded([this](const http::Request& req, http::Response& res) { set_input(req, res); }));
    router.add("POST", "/api/nmt", guarded([this](const http::Request& req, http::Response& res) { nmt(req, res); }));
    router.add("POST", "/api/frames", guarded([this](const http::Request& req, http::Response& res) { send_frame(req, res); }));
    router.add("POST", "/api/faults", guarded([this](const http::Request& req, http::Response& res) { inject(req, res); }));
    router.add("GET", "/api/faults", guarded([this](const http::Request& req, http::Response& res) { list_faults(req, res); }));
    router.add("DELETE", R"(/api/faults/([^/]+))", guarded([this](const http::Request& req, http::Response& res) { clear_fault(req, res); }));
    router.add("GET", "/api/signals", guarded([this](const http::Request& req, http::Response& res) { signals(req, res); }));
    // The verdict on the master: findings from ?since=N on, a page at a time, taken between ticks.
    router.add("GET", "/api/findings", guarded([this](const http::Request& req, http::Response& res) {
      if (!monitor) throw HttpError{404, "this run has no master monitor"};
      std::size_t since = 0;
      if (req.has_param("since")) {
        const auto v = scenario::parse_integer(req.param("since"));
        if (!v || *v < 0) throw HttpError{400, "since must be a finding count (a non-negative integer)"};
        since = static_cast<std::size_t>(*v);
      }
      res.status = 200;
      res.type = "application/json";
      // The run's monitor as the command finds it (a restart replaces it).
      res.body = call<std::string>([since](const scenario::RunContext& c) {
        const auto* m = c.master_monitor;
        return scenario::findings_json(m->findings(), m->rules(), m->bus_names(), since, kFindingsPage);
      });
    }));
    router.add("GET", "/api/clock", guarded([this](const http::Request&, http::Response& res) {
      need_run();
      reply(res, 200, clock_json());
    }));
    router.add("POST", "/api/clock", guarded([this](const http::Request& req, http::Response& res) { clock_control(req, res); }));
    router.add("GET", "/api/events", [this](const http::Request& req, http::Response& res) { events(req, res); });
    cp.exercises_.add_routes(router);
    // The controls a lesson needs (docs/api.md, "Lesson controls").
    router.add("GET", "/api/sync", guarded([this](const http::Request& req, http::Response& res) { sync_state(req, res); }));
    router.add("POST", "/api/sync", guarded([this](const http::Request& req, http::Response& res) { sync_control(req, res); }));
    router.add("GET", R"(/api/nodes/([^/]+)/pdos)", guarded([this](const http::Request& req, http::Response& res) { pdos(req, res); }));
    router.add("POST", R"(/api/nodes/([^/]+)/rpdo)", guarded([this](const http::Request& req, http::Response& res) { rpdo(req, res); }));
    router.add("POST", "/api/events/node", guarded([this](const http::Request& req, http::Response& res) { select_node(req, res); }));
    router.add("POST", "/api/restart", guarded([this](const http::Request&, http::Response& res) { restart(res); }));

  }

  static void serve_static(const http::Request& req, http::Response& res) {
#ifdef VPLANT_HAVE_DASHBOARD
    if (const auto* asset = dashboard::find_asset(req.path)) {
      res.status = 200;
      res.type = std::string(asset->content_type);
      res.body = std::string(asset->body);  // whole: Range is not supported (no amplification)
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

  void od(const http::Request& req, http::Response& res) {
    const auto i = node(req.matches[1]);
    const auto& entries = catalog.entries(i);
    struct Read {
      std::vector<std::vector<std::uint8_t>> values;
      std::vector<canopen::ValueScaling> scalings;  ///< the product's, as configured now
    };
    auto read = call<Read>([i, &entries](const scenario::RunContext& c) {
      Read r;
      r.values.reserve(entries.size());
      r.scalings.reserve(entries.size());
      auto& device = *c.world.nodes()[i].device;
      const auto& od = device.node().od();
      for (const auto& e : entries) {
        const auto* entry = od.entry(e.index, e.sub);
        r.values.push_back(entry ? entry->value.bytes() : std::vector<std::uint8_t>{});
        r.scalings.push_back(device.value_scaling(e.index, e.sub));
      }
      return r;
    });
    json a = json::array();
    for (std::size_t k = 0; k < entries.size(); ++k) {
      const auto& e = entries[k];
      json j = {{"index", e.index},
                {"sub", e.sub},
                {"name", e.name},
                {"type", std::string(canopen::type_name(e.type))},
                {"access", access_name(e.access)},
                {"pdo_mappable", e.pdo_mappable},
                {"value", value_json(e.type, read.values[k])}};
      if (const auto display = display_text(e.type, read.values[k], read.scalings[k]); !display.empty()) {
        j["unit"] = std::string(read.scalings[k].unit);
        j["display"] = display;
      }
      a.push_back(std::move(j));
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
                    const CatalogEntry* entry, http::Response& res) {
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

  void sdo_write(const http::Request& req, http::Response& res) {
    const auto i = node(req.matches[1]);
    RequestBody body(req.body, "the SDO write");
    const auto index = static_cast<std::uint16_t>(body.integer("index", 0, 0xFFFF));
    const auto sub = static_cast<std::uint8_t>(body.integer_or("sub", 0, 0xFF).value_or(0));
    const auto* entry = catalog.find(i, index, sub);
    std::vector<std::uint8_t> data;
    if (body.has("data") && body.has("value")) throw HttpError{400, "give 'value' or 'data', not both"};
    if (body.has("data")) {
      data = body.bytes("data", 1, 4096);
    } else if (body.has("value")) {
      if (!entry)
        throw HttpError{400, "node '" + node_names[i] + "' has no object " + abort_hex(index).substr(6) +
                                 ":" + std::to_string(sub) + " (give \"data\" to send the request anyway)"};
      if (auto err = scenario::encode_literal(entry->type, body.literal("value"), data); !err.empty()) throw HttpError{400, err};
    } else {
      throw HttpError{400, "give 'value' or 'data'"};
    }
    body.finish();
    sdo_transfer(i, false, index, sub, std::move(data), entry, res);
  }

  void sdo_read(const http::Request& req, http::Response& res) {
    const auto i = node(req.matches[1]);
    RequestBody body(req.body, "the SDO read");
    const auto index = static_cast<std::uint16_t>(body.integer("index", 0, 0xFFFF));
    const auto sub = static_cast<std::uint8_t>(body.integer_or("sub", 0, 0xFF).value_or(0));
    body.finish();
    sdo_transfer(i, true, index, sub, {}, catalog.find(i, index, sub), res);
  }

  void set_input(const http::Request& req, http::Response& res) {
    const auto i = node(req.matches[1]);
    RequestBody body(req.body, "the input");
    const auto name = body.text("name");
    const double value = body.number("value");
    body.finish();
    const auto err = call<std::string>([i, name, value](const scenario::RunContext& c) {
      return c.world.nodes()[i].device->set_input(name, value);
    });
    if (!err.empty()) throw HttpError{400, err};
    reply(res, 200, {{"ok", true}});
  }

  void nmt(const http::Request& req, http::Response& res) {
    RequestBody body(req.body, "the NMT command");
    const auto command = canopen::parse_nmt_command(body.text("command"));
    if (!command) throw HttpError{400, "field 'command' must be " + std::string(canopen::kNmtCommandWords)};
    std::optional<std::size_t> target;
    if (const auto name = body.node_or_all("node", false)) target = node(*name);
    body.finish();
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

  void send_frame(const http::Request& req, http::Response& res) {
    RequestBody body(req.body, "the frame");
    const auto bus_name = body.text_or("bus").value_or(bus_names.front());
    const bool ext = body.flag_or("extended", false);
    const bool rtr = body.flag_or("rtr", false);
    const auto id = static_cast<std::uint32_t>(body.integer("id", 0, ext ? sim::CanFrame::kMaxExtId : sim::CanFrame::kMaxStdId));
    std::vector<std::uint8_t> data;
    if (body.has("data")) data = body.bytes("data", 0, 8);
    const auto dlc = static_cast<std::uint8_t>(body.integer_or("dlc", 0, 8).value_or(0));
    body.finish();
    const auto b = bus_index.find(bus_name);
    if (b == bus_index.end()) throw HttpError{404, "no bus '" + bus_name + "'"};
    sim::CanFrame f = rtr ? sim::CanFrame::remote_frame(id, dlc) : sim::CanFrame::data_frame(id, data);
    f.extended = ext;
    const auto bus = b->second;
    const bool queued = call<bool>([this, bus, f](const scenario::RunContext&) { return cp.bridge_.send_frame(bus, f); });
    if (!queued)
      throw HttpError{503, "the bus refused the frame: the control plane's transmit queue on '" + bus_name +
                               "' is full (the bus carries frames at its bit rate): retry later"};
    reply(res, 200, {{"ok", true}, {"queued", true}});
  }

  /// The body is a fault as a scenario writes it, as JSON (engine/loading/fault_codec.h, docs/api.md).
  static scenario::FaultSpec fault_spec(const http::Request& req) {
    RequestBody::parse(req.body);  // a JSON object (valid UTF-8), as every body of the API
    try {
      return scenario::parse_fault(req.body, "<body>");
    } catch (const scenario::LoadError& e) {
      throw HttpError{400, e.what()};
    }
  }

  void inject(const http::Request& req, http::Response& res) {
    const auto spec = fault_spec(req);
    struct Result {
      std::string error;
      int id = 0;
      bool active = false;
      bool full = false;
    };
    const auto r = call<Result>([this, spec](const scenario::RunContext& c) {
      const auto now = c.scheduler.now();
      const auto now_us = now.time_since_epoch().count();
      // Active faults are a client-growable table (each wire fault is a rule every frame on its
      // bus is checked against): bounded exactly, because the check and the insert run in one
      // command on the scheduler's thread, never apart across the HTTP threads.
      auto& faults = cp.bridge_.live_faults(now_us);
      if (faults.size() >= kMaxLiveFaults) return Result{{}, 0, false, true};
      SimBridge::LiveFault live;
      try {
        auto injected = c.faults.inject(spec, now);
        live.clear = std::move(injected.clear);
        live.over = std::move(injected.over);
      } catch (const scenario::LoadError& e) {
        return Result{e.what(), 0, false, false};
      }
      Result out;
      out.id = cp.bridge_.next_fault_id();
      out.active = static_cast<bool>(live.clear);
      if (out.active) {
        live.id = out.id;
        live.summary = spec.name;
        live.since_us = now_us;
        if (spec.duration) live.until_us = now_us + spec.duration->count();
        faults.push_back(std::move(live));
      }
      return out;
    });
    if (r.full) throw HttpError{429, "too many active faults (at most " + std::to_string(kMaxLiveFaults) + "): clear some first"};
    if (!r.error.empty()) throw HttpError{400, r.error};
    reply(res, 200, {{"ok", true}, {"id", r.id}, {"active", r.active}});
  }

  void list_faults(const http::Request&, http::Response& res) {
    const auto a = call<json>([this](const scenario::RunContext& c) {
      auto& faults = cp.bridge_.live_faults(c.scheduler.now().time_since_epoch().count());
      json out = json::array();
      for (const auto& f : faults) {
        json j = {{"id", f.id}, {"summary", f.summary}, {"since_t_us", f.since_us}};
        if (f.until_us >= 0) j["until_t_us"] = f.until_us;
        out.push_back(std::move(j));
      }
      return out;
    });
    reply(res, 200, a);
  }

  void clear_fault(const http::Request& req, http::Response& res) {
    const int id = static_cast<int>(query_integer(std::string(req.matches[1]), "fault id", 1, INT32_MAX));
    const bool found = call<bool>([this, id](const scenario::RunContext& c) {
      auto& faults = cp.bridge_.live_faults(c.scheduler.now().time_since_epoch().count());
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

  void signals(const http::Request& req, http::Response& res) {
    auto list = signal_list(req.param("names"));
    if (!req.has_param("names"))
      for (std::size_t s = 0; s < cp.bridge_.signals().size(); ++s) list.push_back(s);
    const auto& sigs = cp.bridge_.signals();
    const auto values = call<std::pair<std::int64_t, std::vector<double>>>([&sigs, list](const scenario::RunContext& c) {
      std::vector<double> v;
      for (const auto s : list) v.push_back(*sigs[s].value);
      return std::make_pair(static_cast<std::int64_t>(c.scheduler.now().time_since_epoch().count()), v);
    });
    json vals = json::object();
    json meta = json::array();
    for (std::size_t k = 0; k < list.size(); ++k) {
      const auto& sig = sigs[list[k]];
      vals[sig.name] = values.second[k];
      meta.push_back(signal_json(sig.name, sig.unit, sig.display));
    }
    reply(res, 200, {{"t_us", values.first}, {"values", vals}, {"signals", meta}});
  }

  void clock_control(const http::Request& req, http::Response& res) {
    RequestBody body(req.body, "the clock action");
    const auto action = body.text("action");
    const auto speed = body.number_or("speed");
    if (speed && *speed != 0 && (*speed < kMinSpeed || *speed > kMaxSpeed))
      throw HttpError{400, "field 'speed' must be 0 (as fast as possible) or 0.001..1000 (× wall clock)"};
    const auto ms = action == "run" ? body.integer("ms", 1, 3600000) : 0;
    body.finish();
    need_run();
    if (cp.bridge_.clock().realtime) throw HttpError{409, "the clock is real time: it cannot be paused or stepped"};
    bool ok = false;
    if (action == "pause") {
      ok = cp.bridge_.pause();
    } else if (action == "resume") {
      ok = cp.bridge_.resume(speed);
    } else if (action == "step") {
      ok = cp.bridge_.run_ticks(1);
    } else if (action == "run") {
      const auto tick = cp.bridge_.clock().tick_us;
      ok = cp.bridge_.run_ticks(static_cast<std::uint64_t>((ms * 1000 + tick - 1) / tick));
    } else {
      throw HttpError{400, "field 'action' must be pause, resume, step or run"};
    }
    if (!ok) throw HttpError{503, "the run has ended"};
    reply(res, 200, {{"ok", true}});
  }

  // ---- lesson controls ------------------------------------------------------------------------
  std::size_t bus_of_request(const std::string& name) const {
    if (name.empty()) return 0;
    const auto b = bus_index.find(name);
    if (b == bus_index.end()) throw HttpError{404, "no bus '" + name + "'"};
    return b->second;
  }

  json sync_json(std::size_t bus) {
    return call<json>([this, bus](const scenario::RunContext&) {
      const auto& p = cp.bridge_.sync(bus);
      return json{{"bus", bus_names[bus]},
                  {"period_ms", p.period.count() / 1000},
                  {"counter_overflow", p.overflow}};
    });
  }

  void sync_state(const http::Request& req, http::Response& res) {
    reply(res, 200, sync_json(bus_of_request(req.param("bus"))));
  }

  void sync_control(const http::Request& req, http::Response& res) {
    RequestBody body(req.body, "the SYNC producer");
    const auto bus_name = body.text_or("bus").value_or("");
    const auto period_ms = body.integer("period_ms", 0, kMaxSyncPeriodMs);
    const auto overflow = static_cast<std::uint8_t>(body.integer_or("counter_overflow", 0, 240).value_or(0));
    body.finish();
    const auto bus = bus_of_request(bus_name);
    if (overflow == 1) throw HttpError{400, "field 'counter_overflow' must be 0 (no counter) or 2..240 (CiA 301 1019h)"};
    need_run();
    const auto tick_us = cp.bridge_.clock().tick_us;
    if (period_ms > 0 && period_ms * 1000 < tick_us)
      throw HttpError{400, "field 'period_ms' is shorter than the tick (" + std::to_string(tick_us) + " us)"};
    call<bool>([this, bus, period_ms, overflow](const scenario::RunContext&) {
      cp.bridge_.set_sync(bus, sim::milliseconds(period_ms), overflow);
      return true;
    });
    reply(res, 200, sync_json(bus));
  }

  void pdos(const http::Request& req, http::Response& res) {
    const auto i = node(req.matches[1]);
    const auto configs = call<std::vector<PdoConfig>>(
        [i](const scenario::RunContext& c) { return read_pdo_configs(c.world.nodes()[i].device->node().od()); });
    reply(res, 200, pdos_json(configs, catalog, i));
  }

  void rpdo(const http::Request& req, http::Response& res) {
    const auto i = node(req.matches[1]);
    RequestBody body(req.body, "the RPDO");
    const int pdo = static_cast<int>(body.integer("pdo", 1, 512));
    const auto mapped = body.get("values");
    if (!mapped.IsMap())
      throw HttpError{400, body.at(mapped) + ": 'values' must be an object of mapped objects and their values, e.g. {\"6040:00\": 15}"};
    body.finish();
    std::vector<scenario::ParameterOverride> values;
    for (const auto& kv : mapped) {
      const auto key = kv.first.Scalar();
      const auto address = parse_object_key(key);
      if (!address) throw HttpError{400, body.at(kv.first) + ": '" + key + "' is not an object address (INDEX:SUB in hex, e.g. 6040:00)"};
      scenario::ParameterOverride o;
      o.index = address->first;
      o.sub = address->second;
      o.value = read_body([&] { return scenario::read_literal(kv.second, body.file(), key); });
      values.push_back(std::move(o));
    }
    // By value: a command that waits past the timeout still runs later.
    const auto r = call<std::pair<std::string, std::optional<sim::CanFrame>>>(
        [this, i, pdo, name = node_names[i], values = std::move(values)](const scenario::RunContext& c) -> std::pair<std::string, std::optional<sim::CanFrame>> {
          auto& n = c.world.nodes()[i];
          const auto built = scenario::build_rpdo(n.device->node().od(), name, pdo, values);
          if (!built.frame)
            return {"RPDO " + std::to_string(pdo) + " of " + name + ": " + built.actual + " (expected " + built.expected + ")",
                    std::nullopt};
          if (!cp.bridge_.send_frame(static_cast<std::size_t>(n.bus), *built.frame))
            return {"the bus refused the frame: the control plane's transmit queue is full: retry later", built.frame};
          return {{}, built.frame};
        });
    if (!r.first.empty()) throw HttpError{r.second ? 503 : 400, r.first};
    const auto& f = *r.second;
    reply(res, 200, {{"ok", true}, {"id", f.id}, {"data", hex_string(f.data.data(), f.dlc)}});
  }

  /// The node whose dictionary a stream carries ("od" deltas): {"stream": ID, "node": NAME|null}.
  void select_node(const http::Request& req, http::Response& res) {
    RequestBody body(req.body, "the stream's node");
    const auto id = static_cast<std::uint64_t>(body.integer("stream", 1, INT64_MAX));
    int selected = -1;
    if (const auto name = body.node_or_all("node", true)) selected = static_cast<int>(node(*name));
    body.finish();
    need_run();
    if (!hub->select_node(id, selected))
      throw HttpError{404, "no stream " + std::to_string(id) + " that may choose a node (a shared read-only stream may not)"};
    reply(res, 200, {{"ok", true}});
  }

  void restart(http::Response& res) {
    need_run();
    auto done = cp.bridge_.request_restart();
    if (done.wait_for(kRestartWait) != std::future_status::ready) throw HttpError{504, "the scenario did not restart in time"};
    if (!done.get()) throw HttpError{503, "the run has ended"};
    reply(res, 200, {{"ok", true}, {"clock", clock_json()}});
  }

  void events(const http::Request& req, http::Response& res) {
    try {
      need_run();
      const auto list = signal_list(req.param("signals"));
      double rate = 10;
      if (req.has_param("rate")) {
        rate = static_cast<double>(query_integer(req.param("rate"), "rate", 1, 50));
      }
      const int selected = req.has_param("node") ? static_cast<int>(node(req.param("node"))) : -1;
      auto client = hub->open(list, rate, selected);
      if (!client)
        throw HttpError{503, "too many event streams (at most " + std::to_string(cp.options_.max_streams) + ", and " +
                                 std::to_string(EventHub::kMaxSharedClients) + " shared read-only ones)"};
      res.status = 200;
      res.type = "text/event-stream";
      res.headers.emplace_back("Cache-Control", "no-cache");
      res.stream = std::make_shared<EventStream>(*hub, client);
    } catch (const HttpError& e) {
      reply(res, e.status, {{"error", e.reason}});
    }
  }
};

ControlPlane::ControlPlane(UiOptions options)
    : options_(std::move(options)), bridge_(options_.clock), exercises_(bridge_, options_.exercises_dir, options_.exercise) {
  server_ = std::make_unique<Server>(*this);
}

ControlPlane::~ControlPlane() {
  if (server_->hub) server_->hub->stop();
  if (server_->http) server_->http->stop();
}

std::string ControlPlane::bind() {
  if (!is_loopback(options_.address) && !options_.allow_remote)
    return "--ui " + options_.address + ": a non-loopback address needs --ui-allow-remote";
  http::Limits limits;
  limits.max_body = kMaxBody;
  // On loopback every client has the same address: a per-address cap would lock out the dashboard
  // together with an abuser.
  limits.max_connections_per_ip = is_loopback(options_.address) ? 0 : kMaxConnectionsPerAddress;
  auto& s = *server_;
  s.http = std::make_unique<http::Server>(
      limits, [&s](http::Request& req, http::Response& res) { s.dispatch(req, res); },
      [&s](const http::Request& req) { return s.check_request(req); });
  if (auto err = s.http->listen(options_.address, options_.port); !err.empty()) return err;
  port_ = s.http->port();
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
  exercises_.attach(context);  // first: a bad --exercise ends the run before anything serves
  bridge_.attach(context);
  auto& s = *server_;
  if (s.hub) return;  // a restart (POST /api/restart): the same scenario, server and streams
  s.build_static(context);
  s.hub = std::make_unique<EventHub>(bridge_, s.catalog, StreamTopology{s.bus_names, s.node_names, s.node_bus},
                                     options_.max_streams, &exercises_);
  s.hub->start();
  s.routes();
  routed_ = true;
  if (!s.http) return;  // hosted: the host serves
  s.http->start();
  if (options_.out) {
    std::fprintf(options_.out, "vplant: control plane at %s%s\n", url().c_str(),
                 context.scheduler.mode() == sim::ClockMode::Virtual && options_.clock.start_paused
                     ? " (virtual time, paused: resume from the dashboard or POST /api/clock)"
                     : "");
    std::fflush(options_.out);
  }
}

void ControlPlane::detach() { bridge_.detach(); }

void ControlPlane::host_at(const std::string& address, int port) {
  options_.address = address;
  port_ = port;
}

http::Response ControlPlane::admit(const http::Request& request) const { return server_->check_request(request); }

void ControlPlane::handle(http::Request& request, http::Response& response) { server_->dispatch(request, response); }

}  // namespace control
