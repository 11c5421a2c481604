// `HOST:PORT` endpoints for the TCP transports: parsing, resolution and the loopback check.
#pragma once

#include <sys/socket.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace sim {

struct TcpEndpoint {
  std::string host;  ///< name or numeric address, without IPv6 brackets
  std::uint16_t port = 0;
};

/// Parses `HOST:PORT` or `[IPV6]:PORT` (port 0..65535; 0 lets a server pick a free one).
std::optional<TcpEndpoint> parse_tcp_endpoint(std::string_view text, std::string& error);

struct ResolvedAddress {
  sockaddr_storage addr{};
  socklen_t len = 0;
  int family = 0;
};

/// Resolves an endpoint (may consult DNS: call it off the scheduler thread or before the run).
std::optional<ResolvedAddress> resolve_tcp(const TcpEndpoint& ep, std::string& error);

bool is_loopback(const ResolvedAddress& a);
/// `127.0.0.1:29536`, `[::1]:29536`.
std::string to_string(const sockaddr* addr, socklen_t len);

}  // namespace sim
