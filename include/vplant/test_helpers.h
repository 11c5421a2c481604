// vplant public API: helpers for the caller's *tests*, not a master stack. Short ways for test code
// to set the scene or check what the master under test did: read or write an object by SDO
// (expedited and segmented, with the abort code), send an NMT command, and lay out a PDO as a
// node's current mapping says. One transfer at a time, no retries, no block transfer, no LSS: the
// master under test is the caller's own code; these stand beside it.
//
//   vplant::test::SdoClient sdo(sim, 5);                      // node-ID 5 on the first bus
//   auto r = sdo.upload(0x1017, 0);                          // runs the simulation until the answer
//   if (!r.ok()) ADD_FAILURE() << r.abort_text();
//   sdo.download(0x1017, 0, vplant::test::le(100, 2));      // 100 ms heartbeat, 2 bytes
//   bus.send(vplant::test::nmt_frame(vplant::test::Nmt::start, 5));
//   bus.send(vplant::test::pack_rpdo(sim, "dsv", 1, {0x000F, 5000}));
//
// SDO transfers run the Simulation in virtual time (Simulation::run_until) until the answer or the
// timeout: call them from test code between runs, never from a step function or frame handler
// (that would nest runs: Simulation throws Error). Everything else here is instant and sends
// nothing by itself. docs/embedding.md, "Test helpers".
#pragma once

#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <vplant/frame.h>

namespace vplant {

class Simulation;

namespace test {

/// CiA 301 NMT command specifiers, named with the words of the scenario vocabulary.
enum class Nmt : std::uint8_t {
  start = 0x01,
  stop = 0x02,
  pre_operational = 0x80,
  reset_node = 0x81,
  reset_communication = 0x82,
};

/// The NMT word (`start`, `stop`, `pre_operational`, `reset_node`, `reset_communication`) as a
/// command; throws Error naming the words for any other.
Nmt nmt_command(std::string_view word);
/// The NMT frame (COB-ID 000h, 2 bytes) addressed to `node` (0 = every node).
Frame nmt_frame(Nmt command, std::uint8_t node);

/// `value`'s low `bytes` bytes, little-endian (CANopen's byte order), for SdoClient::download.
std::vector<std::uint8_t> le(std::uint64_t value, std::size_t bytes);

/// The outcome of one SDO transfer.
struct SdoResult {
  /// 0: the transfer completed. Else the CiA 301 abort code: the server's (an abort frame), or
  /// the client's own when the server did not answer (05040000h, timeout) or answered out of
  /// protocol (05030000h toggle bit, 05040001h command specifier); the client then sent that
  /// abort to the server.
  std::uint32_t abort_code = 0;
  /// The abort came from the server (an abort frame) rather than from this client.
  bool aborted_by_server = false;
  /// Upload: the value as received (little-endian; a string's characters).
  std::vector<std::uint8_t> data;

  bool ok() const { return abort_code == 0; }
  /// The received value as an unsigned integer (little-endian, up to 8 bytes); throws Error
  /// after an abort or for more than 8 bytes.
  std::uint64_t value() const;
  /// The received bytes as text (VISIBLE_STRING).
  std::string text() const { return {data.begin(), data.end()}; }
  /// "0x06020000 (object does not exist in the object dictionary)", or "ok".
  std::string abort_text() const;
};

/// The meaning of a CiA 301 SDO abort code ("" for a code the standard does not define).
std::string_view describe_abort(std::uint32_t code);

/// An SDO client to one node's default SDO server (600h/580h + node-ID), on its own endpoint of
/// the bus. It sees the node's answers through that endpoint; the caller's endpoints see its
/// requests like any other frame.
class SdoClient {
 public:
  /// `bus` "" = the scenario's first bus; `timeout` = how long (simulated) to wait for each answer.
  /// Throws Error for an unknown bus or a node-ID outside 1..127.
  SdoClient(Simulation& sim, std::uint8_t node_id, const std::string& bus = "",
            Duration timeout = std::chrono::milliseconds(100));
  SdoClient(SdoClient&&) noexcept;
  SdoClient& operator=(SdoClient&&) noexcept;
  ~SdoClient();

  /// Reads index:sub; expedited or segmented as the server answers.
  SdoResult upload(std::uint16_t index, std::uint8_t sub);
  /// Writes index:sub: expedited for 1..4 bytes, segmented for 0 or more than 4.
  SdoResult download(std::uint16_t index, std::uint8_t sub, const std::vector<std::uint8_t>& data);

  std::uint8_t node_id() const;

 private:
  struct State;
  std::shared_ptr<State> state_;  // shared with the endpoint's frame handler, which the Simulation owns
};

/// The frame of RPDO `number` (1-based) of node `node` (its scenario name), laid out by the
/// node's current mapping (16xxh) and addressed by its current COB-ID (14xxh:01): one value per
/// mapped entry (dummy entries included), in mapping order, each the entry's low bits (a negative
/// value of a signed entry as its two's complement). Reads the node's object dictionary directly
/// (no frame, no time passes). Throws Error for an unknown node, a PDO the node lacks or marks
/// invalid (COB-ID bit 31), a count of values that differs from the mapping, or a value that does
/// not fit its entry.
Frame pack_rpdo(const Simulation& sim, const std::string& node, int number, std::initializer_list<std::int64_t> values);
/// The values of a frame of TPDO `number` (1-based) of `node`, split by its current mapping
/// (1Axxh): each entry's raw bits, zero-extended. Throws Error as pack_rpdo, or when the frame is
/// shorter than the mapping.
std::vector<std::uint64_t> unpack_tpdo(const Simulation& sim, const std::string& node, int number, const Frame& frame);

}  // namespace test
}  // namespace vplant
