// Signal expressions: what a scenario samples, plots and asserts on.
//   cyl.position                      a plant port (component.signal) or a device port (node.port)
//   dsv.nmt_state                     a node's NMT state (0, 4, 5, 127) as a number
//   frame(0x185)[0:4] as i32          bytes [0,4) of the last frame with COB-ID 0x185, little-endian
//   frame(main:0x185)[4] as u8        ... on bus `main` (default: the first bus)
//   cyl.position * 1000 + 5           any of the above scaled (`* k`, `/ k`) and offset (`+ c`, `- c`)
//   frame(0x1FF)[0:4] as i32 - shaft.angle * 57.3
//                                     a sum of such terms (`+`, `-`; `*` and `/` bind tighter; a
//                                     product of two signals is not an expression)
// Types of frame fields: u8 u16 u24 u32 u64 i8 i16 i24 i32 i64 f32 f64 (default: unsigned of the
// field's width). A frame field is NaN until its first frame.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "engine/loading/source_mark.h"

namespace scenario {

struct FrameField {
  std::string bus;  ///< "" = the scenario's first bus
  std::uint32_t id = 0;
  bool extended = false;
  int first = 0;  ///< first byte
  int count = 1;  ///< number of bytes (1..8)
  enum class Type { Unsigned, Signed, Float32, Float64 } type = Type::Unsigned;
};

/// The first term (kind, owner/port or frame, times `scale`) plus `more` terms (each its own
/// signal times its `scale`, the sign included) plus `offset`.
struct SignalExpr {
  enum class Kind { Port, Frame } kind = Kind::Port;
  std::string owner;  ///< Port: node or plant component name
  std::string port;   ///< Port: the rest after the first '.'
  FrameField frame;
  double scale = 1.0;
  double offset = 0.0;
  std::vector<SignalExpr> more;  ///< further signal terms of a sum (their offset is 0)
  std::string text;  ///< as written (used as the column / legend name)
  SourceMark mark;

  std::string qualified_port() const { return owner + "." + port; }
};

/// Parses an expression; throws LoadError at `mark` with the reason.
SignalExpr parse_signal(std::string_view text, const SourceMark& mark);

/// Decodes a frame field from a payload (NaN when the frame is too short).
double decode_field(const FrameField& field, const std::uint8_t* data, int dlc);

}  // namespace scenario
