#include "sim/socketcand_protocol.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace sim::socketcand {

namespace {

constexpr std::size_t kMaxTokens = 12;  // `send ID DLC` + 8 bytes, plus one to detect extras
constexpr std::size_t kMaxNameLength = 64;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string quoted(std::string_view token) {
  std::string s = "'";
  for (char c : token.substr(0, 24)) {
    if (c >= 0x20 && c < 0x7F)
      s += c;
    else
      s += fmt::format("\\x{:02X}", static_cast<unsigned char>(c));
  }
  if (token.size() > 24) s += "...";
  return s + "'";
}

// Splits the body between the brackets at whitespace; false if there are more than kMaxTokens.
bool tokenize(std::string_view body, std::array<std::string_view, kMaxTokens>& tokens, std::size_t& count) {
  count = 0;
  std::size_t i = 0;
  while (i < body.size()) {
    while (i < body.size() && is_space(body[i])) ++i;
    if (i == body.size()) break;
    const std::size_t start = i;
    while (i < body.size() && !is_space(body[i])) ++i;
    if (count == kMaxTokens) return false;
    tokens[count++] = body.substr(start, i - start);
  }
  return true;
}

// A CAN identifier in hex. socketcand treats an 8-digit ID as extended; an ID above 0x7FF cannot
// be standard either (python-can writes extended IDs without leading zeros).
bool parse_id(std::string_view t, CanFrame& f, std::string& error) {
  if (t.empty() || t.size() > 8) {
    error = "bad CAN ID " + quoted(t) + " (1 to 8 hex digits)";
    return false;
  }
  std::uint32_t v = 0;
  for (char c : t) {
    const int h = hex_value(c);
    if (h < 0) {
      error = "bad CAN ID " + quoted(t) + " (not hex)";
      return false;
    }
    v = (v << 4) | static_cast<std::uint32_t>(h);
  }
  if (v > CanFrame::kMaxExtId) {
    error = "CAN ID " + quoted(t) + " exceeds 29 bits";
    return false;
  }
  f.id = v;
  f.extended = t.size() == 8 || v > CanFrame::kMaxStdId;
  return true;
}

bool parse_dlc(std::string_view t, CanFrame& f, std::string& error) {
  if (t.size() != 1 || t[0] < '0' || t[0] > '9') {
    error = "bad DLC " + quoted(t);
    return false;
  }
  if (t[0] > '8') {
    error = "DLC " + std::string(t) + " exceeds 8";
    return false;
  }
  f.dlc = static_cast<std::uint8_t>(t[0] - '0');
  return true;
}

// python-can 4.1 (Debian 12) writes every frame as `< send ID DLC B.. >` and a remote frame's
// data is empty, so its remote frames arrive as `< send ID N >` without bytes. With N >= 1 that
// can only be a remote frame (a data frame of DLC N carries N bytes). With N = 0 it is, by the
// protocol, a data frame without data (a SYNC), except on 701h-77Fh: there CANopen's NMT error
// control has no empty data frame, and python-canopen's node guarding sends exactly this.
bool reads_as_remote(const CanFrame& f) {
  if (f.dlc > 0) return true;
  return !f.extended && f.id >= kGuardingFirst && f.id <= kGuardingLast;
}

bool parse_byte(std::string_view t, std::uint8_t& b, std::string& error) {
  if (t.empty() || t.size() > 2 || hex_value(t[0]) < 0 || (t.size() == 2 && hex_value(t[1]) < 0)) {
    error = "bad hex byte " + quoted(t);
    return false;
  }
  b = static_cast<std::uint8_t>(t.size() == 1 ? hex_value(t[0]) : hex_value(t[0]) * 16 + hex_value(t[1]));
  return true;
}

bool parse_timestamp(std::string_view t, Message& m, std::string& error) {
  const auto dot = t.find('.');
  const auto sec = t.substr(0, dot);
  const auto usec = dot == std::string_view::npos ? std::string_view{} : t.substr(dot + 1);
  bool ok = !sec.empty() && sec.size() <= 12 && usec.size() <= 6 && (dot == std::string_view::npos || !usec.empty());
  std::int64_t s = 0;
  std::int64_t u = 0;
  for (char c : sec) {
    ok = ok && c >= '0' && c <= '9';
    s = s * 10 + (c - '0');
  }
  for (std::size_t i = 0; i < 6; ++i) {
    const char c = i < usec.size() ? usec[i] : '0';
    ok = ok && c >= '0' && c <= '9';
    u = u * 10 + (c - '0');
  }
  if (!ok) {
    error = "bad timestamp " + quoted(t) + " (expected SECONDS.MICROSECONDS)";
    return false;
  }
  m.sec = s;
  m.usec = u;
  return true;
}

bool expect_fields(std::string_view command, std::size_t count, std::size_t expected, std::string& error) {
  if (count == expected) return true;
  error = fmt::format("'{}' takes {} field(s), got {}", command, expected - 1, count - 1);
  return false;
}

}  // namespace

bool parse(std::string_view message, Message& out, std::string& error) {
  if (message.size() < 2 || message.front() != '<' || message.back() != '>') {
    error = "not a message in angle brackets: " + quoted(message);
    return false;
  }
  if (message.size() > kMaxMessage) {
    error = fmt::format("message longer than {} bytes", kMaxMessage);
    return false;
  }
  for (char c : message) {
    if (!is_space(c) && (c < 0x20 || c > 0x7E)) {
      error = fmt::format("non-printable byte 0x{:02X} in a message", static_cast<unsigned char>(c));
      return false;
    }
  }
  const std::string_view body = message.substr(1, message.size() - 2);
  std::array<std::string_view, kMaxTokens> t{};
  std::size_t n = 0;
  if (!tokenize(body, t, n)) {
    error = "too many fields in " + quoted(message);
    return false;
  }
  if (n == 0) {
    error = "empty message";
    return false;
  }
  out = Message{};
  const std::string_view cmd = t[0];
  if (cmd == "hi" || cmd == "ok" || cmd == "rawmode" || cmd == "bcmmode" || cmd == "echo") {
    if (!expect_fields(cmd, n, 1, error)) return false;
    out.kind = cmd == "hi"        ? Kind::Hi
               : cmd == "ok"      ? Kind::Ok
               : cmd == "rawmode" ? Kind::Rawmode
               : cmd == "bcmmode" ? Kind::Bcmmode
                                  : Kind::Echo;
    return true;
  }
  if (cmd == "open") {
    if (!expect_fields(cmd, n, 2, error)) return false;
    if (t[1].size() > kMaxNameLength) {
      error = fmt::format("bus name longer than {} characters", kMaxNameLength);
      return false;
    }
    out.kind = Kind::Open;
    out.text = t[1];
    return true;
  }
  if (cmd == "send") {
    if (n < 3) return expect_fields(cmd, n, 3, error);
    out.kind = Kind::Send;
    if (!parse_id(t[1], out.frame, error) || !parse_dlc(t[2], out.frame, error)) return false;
    if (n == 3 && reads_as_remote(out.frame)) {
      out.frame.rtr = true;
      return true;
    }
    if (n - 3 != out.frame.dlc) {
      error = fmt::format("DLC {} but {} data byte(s)", out.frame.dlc, n - 3);
      return false;
    }
    for (std::size_t i = 0; i < out.frame.dlc; ++i)
      if (!parse_byte(t[3 + i], out.frame.data[i], error)) return false;
    return true;
  }
  if (cmd == "sendrtr") {
    if (!expect_fields(cmd, n, 3, error)) return false;
    out.kind = Kind::Send;
    out.frame.rtr = true;
    return parse_id(t[1], out.frame, error) && parse_dlc(t[2], out.frame, error);
  }
  if (cmd == "frame") {
    if (n < 3) return expect_fields(cmd, n, 3, error);
    out.kind = Kind::Frame;
    if (!parse_id(t[1], out.frame, error) || !parse_timestamp(t[2], out, error)) return false;
    // socketcand writes the data as one hex string; its protocol document shows spaced bytes:
    // accept both.
    std::size_t len = 0;
    for (std::size_t k = 3; k < n; ++k) {
      const auto hex = t[k];
      if (hex.size() % 2 != 0 || len + hex.size() / 2 > 8) {
        error = "bad frame data " + quoted(hex) + " (at most 8 bytes as pairs of hex digits)";
        return false;
      }
      for (std::size_t i = 0; i < hex.size(); i += 2)
        if (!parse_byte(hex.substr(i, 2), out.frame.data[len++], error)) return false;
    }
    out.frame.dlc = static_cast<std::uint8_t>(len);
    return true;
  }
  if (cmd == "rtr") {
    if (!expect_fields(cmd, n, 4, error)) return false;
    out.kind = Kind::Frame;
    out.frame.rtr = true;
    return parse_id(t[1], out.frame, error) && parse_timestamp(t[2], out, error) && parse_dlc(t[3], out.frame, error);
  }
  if (cmd == "error") {
    out.kind = Kind::Error;
    const auto start = body.find("error") + 5;
    auto text = body.substr(start);
    while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
    while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
    out.text = text;
    return true;
  }
  error = "unknown command " + quoted(cmd);
  return false;
}

std::size_t format_frame(const CanFrame& f, std::int64_t sec, std::int64_t usec, char* out) {
  char* p = out;
  const auto id_digits = f.extended ? 8 : 3;
  if (f.rtr) {
    p = fmt::format_to(p, "< rtr {:0{}X} {}.{:06} {} >", f.id, id_digits, sec, usec, f.dlc);
  } else {
    p = fmt::format_to(p, "< frame {:0{}X} {}.{:06} ", f.id, id_digits, sec, usec);
    for (std::size_t i = 0; i < f.dlc && i < 8; ++i) p = fmt::format_to(p, "{:02X}", f.data[i]);
    p = fmt::format_to(p, " >");
  }
  *p = '\0';
  return static_cast<std::size_t>(p - out);
}

std::size_t format_send(const CanFrame& f, char* out) {
  char* p = out;
  const auto id_digits = f.extended ? 8 : 3;
  if (f.rtr) {
    p = fmt::format_to(p, "< sendrtr {:0{}X} {} >", f.id, id_digits, f.dlc);
  } else {
    p = fmt::format_to(p, "< send {:0{}X} {}", f.id, id_digits, f.dlc);
    for (std::size_t i = 0; i < f.dlc && i < 8; ++i) p = fmt::format_to(p, " {:02X}", f.data[i]);
    p = fmt::format_to(p, " >");
  }
  *p = '\0';
  return static_cast<std::size_t>(p - out);
}

std::size_t Splitter::feed(std::string_view bytes) {
  compact();
  const std::size_t n = std::min(bytes.size(), kCapacity - end_);
  std::memcpy(buf_ + end_, bytes.data(), n);
  end_ += n;
  return n;
}

Splitter::Result Splitter::next(std::string_view& message, std::string& error) {
  while (begin_ < end_ && is_space(buf_[begin_])) ++begin_;
  if (begin_ == end_) return Result::NeedMore;
  if (buf_[begin_] != '<') {
    error = "bytes outside a '< ... >' message: " + quoted(std::string_view(buf_ + begin_, end_ - begin_));
    return Result::Error;
  }
  const std::size_t limit = std::min(end_, begin_ + kMaxMessage);
  for (std::size_t i = begin_ + 1; i < limit; ++i) {
    if (buf_[i] == '>') {
      message = std::string_view(buf_ + begin_, i + 1 - begin_);
      begin_ = i + 1;
      return Result::Message;
    }
  }
  if (end_ - begin_ >= kMaxMessage) {
    error = fmt::format("message longer than {} bytes", kMaxMessage);
    return Result::Error;
  }
  return Result::NeedMore;
}

void Splitter::compact() {
  if (begin_ == 0) return;
  std::memmove(buf_, buf_ + begin_, end_ - begin_);
  end_ -= begin_;
  begin_ = 0;
}

}  // namespace sim::socketcand
