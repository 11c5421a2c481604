// The socketcand ASCII protocol (linux-can/socketcand doc/protocol.md), the part a raw-mode CAN
// link needs: `< hi >`, `< open BUS >`, `< ok >`, `< rawmode >`, `< echo >`, `< send ID DLC B.. >`,
// `< sendrtr ID DLC >`, `< frame ID SEC.USEC HEX >`, `< error TEXT >`. Pure parsing and formatting:
// no sockets, no allocation per frame (the server and the client transport share it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "sim/can_frame.h"

namespace sim::socketcand {

/// Longest message accepted, brackets included. The longest legal one is an extended `< send >`
/// with 8 bytes written with extra spaces, or `< open NAME >` with a long name; real clients stay
/// far below.
inline constexpr std::size_t kMaxMessage = 128;
/// Room for any message this module formats.
inline constexpr std::size_t kFormatMax = 64;

/// `< send ID 0 >` (no bytes) on these identifiers is read as a remote frame: CANopen node
/// guarding's request (0x700 + node-ID 1..127), as python-can 4.1 writes it (see parse()).
inline constexpr std::uint32_t kGuardingFirst = 0x701;
inline constexpr std::uint32_t kGuardingLast = 0x77F;

enum class Kind {
  Hi,        ///< `< hi >` (server greeting)
  Ok,        ///< `< ok >`
  Open,      ///< `< open NAME >`: `text` is the channel
  Rawmode,   ///< `< rawmode >`
  Bcmmode,   ///< `< bcmmode >`
  Echo,      ///< `< echo >`
  Send,      ///< `< send ID DLC B.. >` or `< sendrtr ID DLC >`: `frame`
  Frame,     ///< `< frame ID SEC.USEC HEX >` or `< rtr ID SEC.USEC DLC >`: `frame`, `sec`, `usec`
  Error,     ///< `< error TEXT >`: `text`
};

struct Message {
  Kind kind = Kind::Hi;
  CanFrame frame;
  std::int64_t sec = 0;
  std::int64_t usec = 0;
  std::string_view text;  ///< points into the parsed input
};

/// Parses one complete message `< ... >` (brackets included). On failure returns false and sets
/// `error` to a reason naming the field ("bad hex byte 'G1'", "DLC 9 exceeds 8", ...).
/// `< send ID N >` without data bytes is a remote frame of DLC N when N >= 1 (python-can 4.1 sends
/// remote frames so), and when N = 0 on kGuardingFirst..kGuardingLast; elsewhere with N = 0 it
/// is a data frame without data, as the protocol defines it.
bool parse(std::string_view message, Message& out, std::string& error);

/// `< frame 123 12.000345 1122 >` as socketcand's raw mode sends it (IDs padded to 3 or 8 hex
/// digits; an 8-digit ID is extended), `< rtr 123 12.000345 4 >` for a remote frame.
std::size_t format_frame(const CanFrame& f, std::int64_t sec, std::int64_t usec, char* out);
/// `< send 123 2 11 22 >` (`< sendrtr 123 4 >` for a remote frame), as a client sends it.
std::size_t format_send(const CanFrame& f, char* out);

/// Cuts a byte stream into `< ... >` messages. Whitespace between messages is skipped; anything
/// else outside brackets, or a message longer than kMaxMessage, is a protocol error (the stream
/// cannot be resynchronised safely, so the caller closes the connection).
class Splitter {
 public:
  enum class Result { Message, NeedMore, Error };
  /// Appends as many received bytes as fit and returns how many it took; drain next() and feed
  /// the rest (a buffer without a complete message is always shorter than kMaxMessage, so there
  /// is room again after draining).
  std::size_t feed(std::string_view bytes);
  /// The next complete message (valid until the next feed), or NeedMore / Error (with `error`).
  Result next(std::string_view& message, std::string& error);
  std::size_t buffered() const { return end_ - begin_; }

 private:
  void compact();
  static constexpr std::size_t kCapacity = 4 * kMaxMessage;
  char buf_[kCapacity];
  std::size_t begin_ = 0;
  std::size_t end_ = 0;
};

}  // namespace sim::socketcand
