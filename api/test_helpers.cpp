// The test helpers of <vplant/test_helpers.h>: an SDO client (CiA 301 expedited and segmented
// transfers, one at a time), NMT frames and PDO layout by a node's current mapping.
#include <vplant/test_helpers.h>

#include <vplant/error.h>
#include <vplant/simulation.h>

#include <algorithm>
#include <array>

#include "api/error_convert.h"
#include "api/frame_convert.h"
#include "devices/canopen/sdo_abort.h"

namespace vplant::test {

namespace {

using detail::fail;

using detail::hex;

std::uint32_t le32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

std::uint32_t read_u32(const Simulation& sim, const std::string& node, std::uint16_t index, std::uint8_t sub) {
  const auto bytes = sim.object(node, index, sub);
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < bytes.size() && i < 4; ++i) v |= static_cast<std::uint32_t>(bytes[i]) << (8 * i);
  return v;
}

/// One mapped entry of a PDO: its length in bits (the index and sub-index only name it in errors).
struct Mapped {
  std::uint32_t entry;
  unsigned bits() const { return entry & 0xFF; }
};

/// A PDO as the node's communication (COB-ID) and mapping parameters say now.
struct PdoLayout {
  Frame frame;  // id, extended; dlc from the mapping's length
  std::vector<Mapped> entries;
  unsigned bits = 0;
};

PdoLayout layout(const Simulation& sim, const std::string& node, int number, bool receive) {
  const char* kind = receive ? "RPDO" : "TPDO";
  if (number < 1 || number > 512) fail(std::string(kind) + " " + std::to_string(number) + " is out of range: 1..512");
  const auto comm = static_cast<std::uint16_t>((receive ? 0x1400 : 0x1800) + number - 1);
  const auto map = static_cast<std::uint16_t>((receive ? 0x1600 : 0x1A00) + number - 1);
  const std::string name = std::string(kind) + " " + std::to_string(number) + " of node '" + node + "'";
  const std::uint32_t cob = read_u32(sim, node, comm, 1);
  if (cob & 0x80000000u) fail(name + " is not valid (" + hex(comm, 4) + "h:01 = " + hex(cob, 8) + "h, bit 31 set)");
  PdoLayout l;
  l.frame.extended = (cob & 0x20000000u) != 0;
  l.frame.id = cob & (l.frame.extended ? 0x1FFFFFFFu : 0x7FFu);
  const auto count = sim.object(node, map, 0);
  const unsigned n = count.empty() ? 0 : count[0];
  for (unsigned i = 1; i <= n; ++i) {
    const Mapped m{read_u32(sim, node, map, static_cast<std::uint8_t>(i))};
    l.entries.push_back(m);
    l.bits += m.bits();
  }
  if (l.bits > 64) fail(name + " maps " + std::to_string(l.bits) + " bits: a PDO carries at most 64");
  l.frame.dlc = static_cast<std::uint8_t>((l.bits + 7) / 8);
  return l;
}

}  // namespace

Nmt nmt_command(std::string_view word) {
  if (word == "start") return Nmt::start;
  if (word == "stop") return Nmt::stop;
  if (word == "pre_operational") return Nmt::pre_operational;
  if (word == "reset_node") return Nmt::reset_node;
  if (word == "reset_communication") return Nmt::reset_communication;
  fail("unknown NMT command '" + std::string(word) +
       "': expected start, stop, pre_operational, reset_node or reset_communication");
}

Frame nmt_frame(Nmt command, std::uint8_t node) {
  if (node > 127) fail("nmt_frame: node-ID " + std::to_string(node) + " is out of range: 0 (all) or 1..127");
  return Frame::make(0x000, {static_cast<std::uint8_t>(command), node});
}

std::vector<std::uint8_t> le(std::uint64_t value, std::size_t bytes) {
  if (bytes < 1 || bytes > 8) fail("le: " + std::to_string(bytes) + " bytes are out of range: 1..8");
  if (bytes < 8 && (value >> (8 * bytes)) != 0)
    fail("le: " + std::to_string(value) + " does not fit in " + std::to_string(bytes) + " byte(s)");
  std::vector<std::uint8_t> out(bytes);
  for (std::size_t i = 0; i < bytes; ++i) out[i] = static_cast<std::uint8_t>(value >> (8 * i));
  return out;
}

std::string_view describe_abort(std::uint32_t code) {
  const auto text = canopen::describe(static_cast<canopen::SdoAbort>(code));
  return text == "unknown abort code" ? std::string_view() : text;
}

std::uint64_t SdoResult::value() const {
  if (!ok()) fail("SdoResult::value: the transfer was aborted: " + abort_text());
  if (data.empty() || data.size() > 8)
    fail("SdoResult::value: " + std::to_string(data.size()) + " byte(s) received; an integer has 1..8");
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < data.size(); ++i) v |= static_cast<std::uint64_t>(data[i]) << (8 * i);
  return v;
}

std::string SdoResult::abort_text() const {
  if (ok()) return "ok";
  const auto text = describe_abort(abort_code);
  return "0x" + hex(abort_code, 8) + " (" + (text.empty() ? std::string("not a CiA 301 abort code") : std::string(text)) +
         (aborted_by_server ? ", from the server)" : ", by the client)");
}

// ---- SDO client ---------------------------------------------------------------------------------

struct SdoClient::State {
  enum class Phase { Idle, UploadInitiate, UploadSegment, DownloadInitiate, DownloadSegment, Done };
  static constexpr std::size_t kMaxUpload = 1 << 20;  // a bound on what a server can make us keep

  Simulation* sim = nullptr;
  Endpoint* endpoint = nullptr;
  std::uint8_t node = 0;
  Duration timeout{};

  Phase phase = Phase::Idle;
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  bool toggle = false;
  std::uint64_t answers = 0;  // server frames accepted in this transfer
  bool size_indicated = false;
  std::uint32_t size = 0;
  std::vector<std::uint8_t> out;  // download data
  std::size_t sent = 0;
  SdoResult result;

  void send(std::uint8_t command, std::array<std::uint8_t, 7> rest = {}) {
    Frame f;
    f.id = 0x600u + node;
    f.dlc = 8;
    f.data[0] = command;
    for (std::size_t i = 0; i < rest.size(); ++i) f.data[i + 1] = rest[i];
    endpoint->send(f);
  }
  std::array<std::uint8_t, 7> multiplexer(std::uint32_t payload = 0) const {
    return {static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8), sub,
            static_cast<std::uint8_t>(payload), static_cast<std::uint8_t>(payload >> 8),
            static_cast<std::uint8_t>(payload >> 16), static_cast<std::uint8_t>(payload >> 24)};
  }
  void done() { phase = Phase::Done; }
  /// The client gives up: tells the server (as CiA 301 requires) and records the code.
  void abort(canopen::SdoAbort code) {
    send(0x80, multiplexer(canopen::code(code)));
    result.abort_code = canopen::code(code);
    result.aborted_by_server = false;
    done();
  }
  void send_segment() {
    const std::size_t k = std::min<std::size_t>(7, out.size() - sent);
    const bool last = sent + k == out.size();
    std::array<std::uint8_t, 7> bytes{};
    for (std::size_t i = 0; i < k; ++i) bytes[i] = out[sent + i];
    sent += k;
    send(static_cast<std::uint8_t>((toggle ? 0x10 : 0) | (7 - k) << 1 | (last ? 1 : 0)), bytes);
  }

  void on_frame(const Frame& f);
  SdoResult run();
};

void SdoClient::State::on_frame(const Frame& f) {
  if (phase == Phase::Idle || phase == Phase::Done) return;
  if (f.id != 0x580u + node || f.extended || f.rtr) return;
  ++answers;
  if (f.dlc != 8) return abort(canopen::SdoAbort::InvalidCommand);
  const std::uint8_t cmd = f.data[0];
  const int scs = cmd >> 5;
  if (scs == 4) {  // abort transfer
    result.abort_code = le32(&f.data[4]);
    result.aborted_by_server = true;
    return done();
  }
  const bool same_object = f.data[1] == static_cast<std::uint8_t>(index) &&
                           f.data[2] == static_cast<std::uint8_t>(index >> 8) && f.data[3] == sub;
  switch (phase) {
    case Phase::UploadInitiate:
      if (scs != 2 || !same_object) return abort(canopen::SdoAbort::InvalidCommand);
      if (cmd & 0x02) {  // expedited: n unused bytes when the size is indicated
        const int n = (cmd & 0x01) ? (cmd >> 2) & 3 : 0;
        result.data.assign(f.data.begin() + 4, f.data.begin() + 8 - n);
        return done();
      }
      size_indicated = (cmd & 0x01) != 0;
      size = le32(&f.data[4]);
      phase = Phase::UploadSegment;
      toggle = false;
      return send(0x60);
    case Phase::UploadSegment: {
      if (scs != 0) return abort(canopen::SdoAbort::InvalidCommand);
      if (((cmd >> 4) & 1) != (toggle ? 1 : 0)) return abort(canopen::SdoAbort::ToggleBit);
      const int n = (cmd >> 1) & 7;
      result.data.insert(result.data.end(), f.data.begin() + 1, f.data.begin() + 8 - n);
      if (result.data.size() > kMaxUpload) return abort(canopen::SdoAbort::OutOfMemory);
      if (cmd & 0x01) {  // last segment
        if (size_indicated && result.data.size() != size) return abort(canopen::SdoAbort::TypeMismatch);
        return done();
      }
      toggle = !toggle;
      return send(toggle ? 0x70 : 0x60);
    }
    case Phase::DownloadInitiate:
      if (scs != 3 || !same_object) return abort(canopen::SdoAbort::InvalidCommand);
      if (out.size() >= 1 && out.size() <= 4) return done();  // expedited
      phase = Phase::DownloadSegment;
      toggle = false;
      return send_segment();
    case Phase::DownloadSegment:
      if (scs != 1) return abort(canopen::SdoAbort::InvalidCommand);
      if (((cmd >> 4) & 1) != (toggle ? 1 : 0)) return abort(canopen::SdoAbort::ToggleBit);
      if (sent == out.size()) return done();
      toggle = !toggle;
      return send_segment();
    case Phase::Idle:
    case Phase::Done:
      break;
  }
}

SdoResult SdoClient::State::run() {
  // Each answer within `timeout` of the previous one; the run stops as soon as the transfer ends.
  while (phase != Phase::Done) {
    const auto before = answers;
    const bool moved =
        sim->run_until([&] { return phase == Phase::Done || answers != before; }, timeout);
    if (!moved) {
      abort(canopen::SdoAbort::Timeout);
      break;
    }
  }
  phase = Phase::Idle;
  return std::move(result);
}

SdoClient::SdoClient(Simulation& sim, std::uint8_t node_id, const std::string& bus, Duration timeout)
    : state_(std::make_shared<State>()) {
  if (node_id < 1 || node_id > 127) fail("SdoClient: node-ID " + std::to_string(node_id) + " is out of range: 1..127");
  if (timeout.count() <= 0) fail("SdoClient: the timeout must be positive");
  state_->sim = &sim;
  state_->node = node_id;
  state_->timeout = timeout;
  state_->endpoint = &sim.attach(bus, [state = state_](const Frame& f, Time) { state->on_frame(f); });
}

SdoClient::SdoClient(SdoClient&&) noexcept = default;
SdoClient& SdoClient::operator=(SdoClient&&) noexcept = default;
SdoClient::~SdoClient() = default;

std::uint8_t SdoClient::node_id() const { return state_->node; }

SdoResult SdoClient::upload(std::uint16_t index, std::uint8_t sub) {
  auto& s = *state_;
  s.result = {};
  s.answers = 0;
  s.index = index;
  s.sub = sub;
  s.phase = State::Phase::UploadInitiate;
  s.send(0x40, s.multiplexer());
  return s.run();
}

SdoResult SdoClient::download(std::uint16_t index, std::uint8_t sub, const std::vector<std::uint8_t>& data) {
  auto& s = *state_;
  s.result = {};
  s.answers = 0;
  s.index = index;
  s.sub = sub;
  s.out = data;
  s.sent = 0;
  s.phase = State::Phase::DownloadInitiate;
  if (!data.empty() && data.size() <= 4) {
    std::array<std::uint8_t, 4> value{};
    for (std::size_t i = 0; i < data.size(); ++i) value[i] = data[i];
    s.send(static_cast<std::uint8_t>(0x23 | (4 - data.size()) << 2), s.multiplexer(le32(value.data())));
  } else {
    s.send(0x21, s.multiplexer(static_cast<std::uint32_t>(data.size())));
  }
  return s.run();
}

// ---- PDO layout ---------------------------------------------------------------------------------

Frame pack_rpdo(const Simulation& sim, const std::string& node, int number, std::initializer_list<std::int64_t> values) {
  PdoLayout l = layout(sim, node, number, true);
  const std::string name = "RPDO " + std::to_string(number) + " of node '" + node + "'";
  if (values.size() != l.entries.size())
    fail(name + " maps " + std::to_string(l.entries.size()) + " entries; " + std::to_string(values.size()) +
         " value(s) given");
  std::uint64_t bits = 0;
  unsigned at = 0;
  std::size_t i = 0;
  for (const std::int64_t v : values) {
    const Mapped& m = l.entries[i++];
    const unsigned width = m.bits();
    const std::uint64_t mask = width >= 64 ? ~0ULL : (1ULL << width) - 1;
    const auto u = static_cast<std::uint64_t>(v);
    const bool fits_unsigned = v >= 0 && (u & ~mask) == 0;
    const bool fits_signed = v < 0 && width > 0 && (width >= 64 || v >= -(static_cast<std::int64_t>(1) << (width - 1)));
    if (width == 0 || !(fits_unsigned || fits_signed))
      fail(name + ": " + std::to_string(v) + " does not fit mapped entry " + std::to_string(i) + " (" +
           hex(m.entry >> 16, 4) + "h:" + hex((m.entry >> 8) & 0xFF, 2) + ", " + std::to_string(width) + " bits)");
    if (at < 64) bits |= (u & mask) << at;
    at += width;
  }
  for (unsigned b = 0; b < l.frame.dlc; ++b) l.frame.data[b] = static_cast<std::uint8_t>(bits >> (8 * b));
  return l.frame;
}

std::vector<std::uint64_t> unpack_tpdo(const Simulation& sim, const std::string& node, int number, const Frame& frame) {
  const PdoLayout l = layout(sim, node, number, false);
  if (frame.dlc < l.frame.dlc)
    fail("TPDO " + std::to_string(number) + " of node '" + node + "' maps " + std::to_string(l.bits) +
         " bits; the frame has " + std::to_string(frame.dlc) + " byte(s)");
  std::uint64_t bits = 0;
  for (unsigned b = 0; b < 8; ++b) bits |= static_cast<std::uint64_t>(frame.data[b]) << (8 * b);
  std::vector<std::uint64_t> values;
  unsigned at = 0;
  for (const auto& m : l.entries) {
    const unsigned width = m.bits();
    const std::uint64_t mask = width >= 64 ? ~0ULL : (1ULL << width) - 1;
    values.push_back(at < 64 ? (bits >> at) & mask : 0);
    at += width;
  }
  return values;
}

}  // namespace vplant::test
