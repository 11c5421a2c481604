// The socketcand message parser and formatter: the exact text socketcand and python-can 4.1
// exchange, round trips, and every class of bad input with its reason.
#include "sim/socketcand_protocol.h"

#include <gtest/gtest.h>

#include <string>

namespace sc = sim::socketcand;

namespace {

sc::Message parse_ok(std::string_view text) {
  sc::Message m;
  std::string error;
  EXPECT_TRUE(sc::parse(text, m, error)) << text << ": " << error;
  return m;
}

std::string parse_error(std::string_view text) {
  sc::Message m;
  std::string error;
  EXPECT_FALSE(sc::parse(text, m, error)) << text;
  return error;
}

std::string frame_text(const sim::CanFrame& f, std::int64_t sec, std::int64_t usec) {
  char buf[sc::kFormatMax];
  const auto n = sc::format_frame(f, sec, usec, buf);
  return std::string(buf, n);
}

std::string send_text(const sim::CanFrame& f) {
  char buf[sc::kFormatMax];
  const auto n = sc::format_send(f, buf);
  return std::string(buf, n);
}

sim::CanFrame extended(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
  auto f = sim::CanFrame::data_frame(id, bytes);
  f.extended = true;
  return f;
}

}  // namespace

TEST(SocketcandProtocol, FormatsFramesAsSocketcandRawModeDoes) {
  EXPECT_EQ(frame_text(sim::CanFrame::data_frame(0x123, {0x11, 0x22}), 12, 345), "< frame 123 12.000345 1122 >");
  EXPECT_EQ(frame_text(sim::CanFrame::data_frame(0x80, {}), 1, 0), "< frame 080 1.000000  >");
  EXPECT_EQ(frame_text(extended(0x1AAAAAAA, {0x01, 0xF1}), 0, 999999), "< frame 1AAAAAAA 0.999999 01F1 >");
  EXPECT_EQ(frame_text(extended(0x5, {}), 3, 4), "< frame 00000005 3.000004  >");
  EXPECT_EQ(frame_text(sim::CanFrame::remote_frame(0x705, 1), 2, 5), "< rtr 705 2.000005 1 >");
  EXPECT_EQ(frame_text(sim::CanFrame::data_frame(0x7FF, {1, 2, 3, 4, 5, 6, 7, 8}), 1795619759, 5426),
            "< frame 7FF 1795619759.005426 0102030405060708 >");
}

TEST(SocketcandProtocol, FormatsSendCommands) {
  EXPECT_EQ(send_text(sim::CanFrame::data_frame(0x123, {})), "< send 123 0 >");
  EXPECT_EQ(send_text(extended(0x1AAAAAAA, {0x01, 0xF1})), "< send 1AAAAAAA 2 01 F1 >");
  EXPECT_EQ(send_text(sim::CanFrame::remote_frame(0x123, 4)), "< sendrtr 123 4 >");
}

TEST(SocketcandProtocol, ParsesWhatPythonCanSends) {
  // python-can 4.1: `< send {id:X} {dlc:X} {bytes as {:x}} >`: lower case, no zero padding.
  auto m = parse_ok("< send 601 8 2f 60 60 0 1 0 0 0 >");
  EXPECT_EQ(m.kind, sc::Kind::Send);
  EXPECT_EQ(m.frame, sim::CanFrame::data_frame(0x601, {0x2F, 0x60, 0x60, 0x00, 0x01, 0, 0, 0}));
  // No data: two spaces before the bracket.
  m = parse_ok("< send 0 2 1 0 >");
  EXPECT_EQ(m.frame, sim::CanFrame::data_frame(0x000, {0x01, 0x00}));
  m = parse_ok("< send 80 0  >");
  EXPECT_EQ(m.frame, sim::CanFrame::data_frame(0x080, {}));
  // An ID above 0x7FF is extended even without eight digits; eight digits are always extended.
  m = parse_ok("< send 123456 1 ff >");
  EXPECT_EQ(m.frame, extended(0x123456, {0xFF}));
  m = parse_ok("< send 00000123 0 >");
  EXPECT_EQ(m.frame, extended(0x123, {}));
}

TEST(SocketcandProtocol, ReadsPythonCan41RemoteFrames) {
  // python-can 4.1 writes a remote frame as `< send ID DLC >` with no bytes (its data is empty).
  auto m = parse_ok("< send 705 1  >");
  EXPECT_EQ(m.kind, sc::Kind::Send);
  EXPECT_EQ(m.frame, sim::CanFrame::remote_frame(0x705, 1));
  m = parse_ok("< send 1AAAAAAA 8  >");
  auto ext = sim::CanFrame::remote_frame(0x1AAAAAAA, 8);
  ext.extended = true;
  EXPECT_EQ(m.frame, ext);
  // DLC 0 on node guarding's COB-IDs (python-canopen's guard request) is a remote frame ...
  EXPECT_EQ(parse_ok("< send 705 0  >").frame, sim::CanFrame::remote_frame(0x705, 0));
  EXPECT_EQ(parse_ok("< send 701 0 >").frame, sim::CanFrame::remote_frame(0x701, 0));
  EXPECT_EQ(parse_ok("< send 77F 0 >").frame, sim::CanFrame::remote_frame(0x77F, 0));
  // ... and elsewhere the protocol's data frame without data (SYNC, LSS, 700h, extended 705h).
  EXPECT_EQ(parse_ok("< send 80 0  >").frame, sim::CanFrame::data_frame(0x080, {}));
  EXPECT_EQ(parse_ok("< send 700 0 >").frame, sim::CanFrame::data_frame(0x700, {}));
  EXPECT_EQ(parse_ok("< send 780 0 >").frame, sim::CanFrame::data_frame(0x780, {}));
  EXPECT_FALSE(parse_ok("< send 00000705 0 >").frame.rtr);
  // The protocol's own spelling still works; a data frame of DLC N still needs N bytes.
  EXPECT_EQ(parse_ok("< sendrtr 705 0 >").frame, sim::CanFrame::remote_frame(0x705, 0));
  EXPECT_FALSE(parse_ok("< send 705 1 05 >").frame.rtr);
}

TEST(SocketcandProtocol, ParsesHandshakeAndControlMessages) {
  EXPECT_EQ(parse_ok("< hi >").kind, sc::Kind::Hi);
  EXPECT_EQ(parse_ok("< ok >").kind, sc::Kind::Ok);
  EXPECT_EQ(parse_ok("< rawmode >").kind, sc::Kind::Rawmode);
  EXPECT_EQ(parse_ok("< bcmmode >").kind, sc::Kind::Bcmmode);
  EXPECT_EQ(parse_ok("<echo>").kind, sc::Kind::Echo);
  auto m = parse_ok("< open main >");
  EXPECT_EQ(m.kind, sc::Kind::Open);
  EXPECT_EQ(m.text, "main");
  m = parse_ok("< error unknown command >");
  EXPECT_EQ(m.kind, sc::Kind::Error);
  EXPECT_EQ(m.text, "unknown command");
}

TEST(SocketcandProtocol, ParsesFramesWithPackedOrSpacedData) {
  auto m = parse_ok("< frame 123 23.424242 11223344 >");
  EXPECT_EQ(m.kind, sc::Kind::Frame);
  EXPECT_EQ(m.sec, 23);
  EXPECT_EQ(m.usec, 424242);
  EXPECT_EQ(m.frame, sim::CanFrame::data_frame(0x123, {0x11, 0x22, 0x33, 0x44}));
  // The protocol document's example writes the bytes apart.
  EXPECT_EQ(parse_ok("< frame 123 23.424242 11 22 33 44 >").frame, m.frame);
  m = parse_ok("< rtr 123 23.5 4 >");
  EXPECT_EQ(m.frame, sim::CanFrame::remote_frame(0x123, 4));
  EXPECT_EQ(m.usec, 500000);
}

TEST(SocketcandProtocol, RoundTripsEveryFrameShape) {
  const sim::CanFrame frames[] = {
      sim::CanFrame::data_frame(0x000, {}),
      sim::CanFrame::data_frame(0x7FF, {0xDE, 0xAD, 0xBE, 0xEF, 0x00, 0x01, 0x02, 0x03}),
      sim::CanFrame::data_frame(0x181, {0x0F}),
      extended(0x1FFFFFFF, {1, 2, 3}),
      extended(0x0, {}),
      sim::CanFrame::remote_frame(0x701, 1),
  };
  for (const auto& f : frames) {
    const auto sent = parse_ok(send_text(f));
    EXPECT_EQ(sent.kind, sc::Kind::Send);
    EXPECT_EQ(sent.frame, f) << send_text(f);
    const auto received = parse_ok(frame_text(f, 1700000000, 42));
    EXPECT_EQ(received.kind, sc::Kind::Frame);
    EXPECT_EQ(received.frame, f) << frame_text(f, 1700000000, 42);
    EXPECT_EQ(received.sec, 1700000000);
    EXPECT_EQ(received.usec, 42);
  }
}

TEST(SocketcandProtocol, RejectsBadInputWithAReason) {
  EXPECT_EQ(parse_error("< send 123 1 G1 >"), "bad hex byte 'G1'");
  EXPECT_EQ(parse_error("< send 123 1 123 >"), "bad hex byte '123'");
  EXPECT_EQ(parse_error("< send 123 2 11 >"), "DLC 2 but 1 data byte(s)");
  EXPECT_EQ(parse_error("< send 123 1 11 22 >"), "DLC 1 but 2 data byte(s)");
  EXPECT_EQ(parse_error("< send 123 9 1 2 3 4 5 6 7 8 9 >"), "DLC 9 exceeds 8");
  EXPECT_EQ(parse_error("< send 123 x >"), "bad DLC 'x'");
  EXPECT_EQ(parse_error("< send XYZ 0 >"), "bad CAN ID 'XYZ' (not hex)");
  EXPECT_EQ(parse_error("< send 123456789 0 >"), "bad CAN ID '123456789' (1 to 8 hex digits)");
  EXPECT_EQ(parse_error("< send 3FFFFFFF 0 >"), "CAN ID '3FFFFFFF' exceeds 29 bits");
  EXPECT_EQ(parse_error("< send 123 >"), "'send' takes 2 field(s), got 1");
  EXPECT_EQ(parse_error("< sendrtr 123 >"), "'sendrtr' takes 2 field(s), got 1");
  EXPECT_EQ(parse_error("< frame 123 1.5 ABC >"), "bad frame data 'ABC' (at most 8 bytes as pairs of hex digits)");
  EXPECT_EQ(parse_error("< frame 123 1.5 010203040506070809 >"),
            "bad frame data '010203040506070809' (at most 8 bytes as pairs of hex digits)");
  EXPECT_EQ(parse_error("< frame 123 1.x 00 >"), "bad timestamp '1.x' (expected SECONDS.MICROSECONDS)");
  EXPECT_EQ(parse_error("< frame 123 1.1234567 00 >"), "bad timestamp '1.1234567' (expected SECONDS.MICROSECONDS)");
  EXPECT_EQ(parse_error("< subscribe 0 0 123 >"), "unknown command 'subscribe'");
  EXPECT_EQ(parse_error("< >"), "empty message");
  EXPECT_EQ(parse_error("< hi there >"), "'hi' takes 0 field(s), got 1");
  EXPECT_EQ(parse_error("< open >"), "'open' takes 1 field(s), got 0");
  EXPECT_EQ(parse_error("< open a b >"), "'open' takes 1 field(s), got 2");
  EXPECT_EQ(parse_error("< send 1 1 1 1 1 1 1 1 1 1 1 1 1 >"), "too many fields in '< send 1 1 1 1 1 1 1 1 1...'");
  EXPECT_EQ(parse_error(std::string("< send 1 1 \x01 >")), "non-printable byte 0x01 in a message");
  EXPECT_EQ(parse_error("send 1 0"), "not a message in angle brackets: 'send 1 0'");
  EXPECT_EQ(parse_error("< open " + std::string(70, 'x') + " >"), "bus name longer than 64 characters");
}

TEST(SocketcandSplitter, CutsAStreamIntoMessagesWhateverTheChunks) {
  const std::string stream = "< hi >< ok >\n< frame 123 1.000000 11 >  \t< echo >";
  for (std::size_t chunk = 1; chunk <= stream.size(); ++chunk) {
    sc::Splitter s;
    std::vector<std::string> got;
    std::string error;
    for (std::size_t i = 0; i < stream.size(); i += chunk) {
      std::string_view part = std::string_view(stream).substr(i, chunk);
      while (!part.empty()) {
        part.remove_prefix(s.feed(part));
        std::string_view m;
        sc::Splitter::Result r;
        while ((r = s.next(m, error)) == sc::Splitter::Result::Message) got.emplace_back(m);
        ASSERT_EQ(r, sc::Splitter::Result::NeedMore) << error;
      }
    }
    EXPECT_EQ(got, (std::vector<std::string>{"< hi >", "< ok >", "< frame 123 1.000000 11 >", "< echo >"})) << chunk;
    EXPECT_EQ(s.buffered(), 0u);
  }
}

TEST(SocketcandSplitter, GarbageOutsideAMessageIsAnError) {
  sc::Splitter s;
  std::string error;
  std::string_view m;
  s.feed("< ok > GET / HTTP/1.1\r\n");
  EXPECT_EQ(s.next(m, error), sc::Splitter::Result::Message);
  EXPECT_EQ(s.next(m, error), sc::Splitter::Result::Error);
  EXPECT_EQ(error, "bytes outside a '< ... >' message: 'GET / HTTP/1.1\\x0D\\x0A'");
}

TEST(SocketcandSplitter, AnOverlongMessageIsAnErrorAndTheBufferStaysBounded) {
  sc::Splitter s;
  std::string error;
  std::string_view m;
  const std::string endless = "< send " + std::string(10000, '1');
  std::size_t taken = 0;
  sc::Splitter::Result r = sc::Splitter::Result::NeedMore;
  while (taken < endless.size() && r == sc::Splitter::Result::NeedMore) {
    taken += s.feed(std::string_view(endless).substr(taken));
    r = s.next(m, error);
  }
  EXPECT_EQ(r, sc::Splitter::Result::Error);
  EXPECT_EQ(error, "message longer than 128 bytes");
  EXPECT_LT(taken, 1024u);
  // A message of exactly the limit is still fine.
  sc::Splitter ok;
  const std::string longest = "< open " + std::string(sc::kMaxMessage - 9, 'x') + " >";
  ASSERT_EQ(longest.size(), sc::kMaxMessage);
  EXPECT_EQ(ok.feed(longest), longest.size());
  EXPECT_EQ(ok.next(m, error), sc::Splitter::Result::Message);
  EXPECT_EQ(m, longest);
}
