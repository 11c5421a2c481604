#include "sim/transport_factory.h"

#include "sim/socketcan_transport.h"
#include "sim/socketcand_client.h"
#include "sim/socketcand_server.h"

namespace sim {

namespace {
constexpr std::string_view kServer = "socketcand:";
constexpr std::string_view kClient = "socketcand-client:";
constexpr std::string_view kSocketCan = "socketcan:";

bool starts_with(const std::string& s, std::string_view prefix) { return s.rfind(prefix, 0) == 0; }
}  // namespace

bool is_socketcand_spec(const std::string& spec) { return starts_with(spec, kServer) || starts_with(spec, kClient); }
bool is_socketcand_server_spec(const std::string& spec) { return starts_with(spec, kServer); }

std::unique_ptr<Transport> open_transport(const std::string& bus_name, const std::string& spec, std::string& error) {
  if (starts_with(spec, kServer) || starts_with(spec, kClient)) {
    const bool client = starts_with(spec, kClient);
    std::string rest = spec.substr(client ? kClient.size() : kServer.size());
    std::string channel = bus_name;
    if (const auto slash = rest.find('/'); slash != std::string::npos) {
      channel = rest.substr(slash + 1);
      rest.resize(slash);
      if (channel.empty()) {
        error = "'" + spec + "': empty channel after '/'";
        return nullptr;
      }
    } else if (client) {
      error = "'" + spec + "': expected socketcand-client:HOST:PORT/CHANNEL";
      return nullptr;
    }
    auto endpoint = parse_tcp_endpoint(rest, error);
    if (!endpoint) {
      error = "'" + spec + "': " + error;
      return nullptr;
    }
    if (client) return SocketcandClient::open(*endpoint, channel, error);
    return SocketcandServer::open(channel, *endpoint, error);
  }
  const std::string iface = starts_with(spec, kSocketCan) ? spec.substr(kSocketCan.size()) : spec;
  return SocketCanTransport::open(iface, error);
}

}  // namespace sim
