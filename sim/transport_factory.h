// Opens a bus's transport from its text form (the `--can BUS=...` value, a scenario's
// `transport:`), so the command line and the scenario engine accept the same spellings:
//
//   IFACE, socketcan:IFACE                 a SocketCAN interface (vcan0, can0)
//   socketcand:ADDR:PORT[/CHANNEL]         serve the bus over socketcand on TCP; clients open
//                                          CHANNEL (default: the bus name). Port 0: any free port.
//   socketcand-client:HOST:PORT/CHANNEL    join CHANNEL of a remote socketcand daemon
#pragma once

#include <memory>
#include <string>

#include "sim/transport.h"

namespace sim {

std::unique_ptr<Transport> open_transport(const std::string& bus_name, const std::string& spec, std::string& error);

/// True if `spec` names a transport other than SocketCAN (it needs no kernel support).
bool is_socketcand_spec(const std::string& spec);
/// True if `spec` serves the bus itself (socketcand server): no outside wire times its frames, so
/// the bus's own timing model does (its clients' frames arbitrate with the plant's).
bool is_socketcand_server_spec(const std::string& spec);

}  // namespace sim
