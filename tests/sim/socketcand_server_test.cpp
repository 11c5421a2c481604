// The socketcand server and client transports over loopback TCP, in-process: frames fan out
// between the bus and several clients, a misbehaving client is closed with a reason while the
// bus and the other clients carry on, and the client transport joins the server.
#include "sim/socketcand_server.h"

#include <gtest/gtest.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "sim/bus.h"
#include "sim/can_bit_timing.h"
#include "sim/socketcand_client.h"
#include "sim/socketcand_protocol.h"
#include "sim/transport_factory.h"

namespace sc = sim::socketcand;

namespace {

using Clock = std::chrono::steady_clock;

bool wait_for(const std::function<bool()>& done, int timeout_ms = 5000) {
  const auto until = Clock::now() + std::chrono::milliseconds(timeout_ms);
  while (Clock::now() < until) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return done();
}

// A raw TCP client that speaks the protocol by hand, as python-can or a misbehaving tool would.
class TcpClient {
 public:
  explicit TcpClient(std::uint16_t port, int rcvbuf = 0) {
    fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (rcvbuf > 0) ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &rcvbuf, sizeof rcvbuf);
    timeval tv{3, 0};
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
  }
  ~TcpClient() { ::close(fd_); }
  bool connected() const { return connected_; }

  /// One recv() of up to 256 bytes, as python-can 4.1 reads the handshake answers.
  std::string recv_once() {
    char buf[256];
    const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
    return n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : "";
  }
  void send(std::string_view text) { ASSERT_EQ(::send(fd_, text.data(), text.size(), MSG_NOSIGNAL), (ssize_t)text.size()); }
  /// send() for a client that may already have been closed by the server (fuzzing).
  void send_anyway(std::string_view text) { (void)::send(fd_, text.data(), text.size(), MSG_NOSIGNAL | MSG_DONTWAIT); }
  /// The next message, or "" on EOF / timeout (3 s).
  std::string next() {
    for (;;) {
      std::string_view m;
      std::string error;
      const auto r = in_.next(m, error);
      if (r == sc::Splitter::Result::Message) return std::string(m);
      if (r == sc::Splitter::Result::Error) return "splitter: " + error;
      char buf[256];  // fits beside the part message a drained Splitter may hold
      const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
      if (n <= 0) {
        eof_ = n == 0;
        return "";
      }
      std::string_view rest(buf, static_cast<std::size_t>(n));
      while (!rest.empty()) {
        rest.remove_prefix(in_.feed(rest));
        if (!rest.empty()) return "splitter full";
      }
    }
  }
  void handshake(const std::string& channel = "main") {
    EXPECT_EQ(next(), "< hi >");
    handshake_after_hi(channel);
  }
  void handshake_after_hi(const std::string& channel = "main") {
    send("< open " + channel + " >");
    EXPECT_EQ(next(), "< ok >");
    send("< rawmode >");
    EXPECT_EQ(next(), "< ok >");
  }
  sim::CanFrame next_frame() {
    const auto text = next();
    sc::Message m;
    std::string error;
    EXPECT_TRUE(sc::parse(text, m, error)) << text << ": " << error;
    EXPECT_EQ(m.kind, sc::Kind::Frame) << text;
    return m.frame;
  }
  /// Reads until the server closes the connection; returns the last message seen.
  std::string last_message_before_close() {
    std::string last;
    for (int i = 0; i < 1000; ++i) {
      auto m = next();
      if (m.empty()) return eof_ ? last : "timeout";
      last = m;
    }
    return "never closed";
  }

 private:
  int fd_ = -1;
  bool connected_ = false;
  bool eof_ = false;
  sc::Splitter in_;
};

struct Recorder : sim::FrameReceiver {
  std::vector<sim::CanFrame> frames;
  void on_frame(const sim::CanFrame& f, sim::Time) override { frames.push_back(f); }
};

std::unique_ptr<sim::SocketcandServer> serve(const std::string& channel = "main") {
  std::string error;
  auto s = sim::SocketcandServer::open(channel, sim::TcpEndpoint{"127.0.0.1", 0}, error);
  EXPECT_TRUE(s) << error;
  return s;
}

bool receive_within(sim::Transport& t, sim::CanFrame& f, int timeout_ms = 3000) {
  const auto until = Clock::now() + std::chrono::milliseconds(timeout_ms);
  while (Clock::now() < until) {
    if (t.receive(f)) return true;
    pollfd p{t.wait_fd(), POLLIN, 0};
    ::poll(&p, 1, 10);
  }
  return t.receive(f);
}

// receive_within() as a bus does it: the frame is carried (wire_result) at once, so the server
// passes it to its other clients and the sender's transmit queue has room again.
bool carry_within(sim::Transport& t, sim::CanFrame& f, int timeout_ms = 3000) {
  const auto until = Clock::now() + std::chrono::milliseconds(timeout_ms);
  std::uint32_t tag = 0;
  for (;;) {
    if (t.receive_tagged(f, tag)) {
      if (tag != 0) t.wire_result(tag, f, sim::Transport::WireResult::Delivered);
      t.service(sim::Time{});
      return true;
    }
    if (Clock::now() >= until) return false;
    pollfd p{t.wait_fd(), POLLIN, 0};
    ::poll(&p, 1, 10);
  }
}

const sim::CanFrame kHeartbeat = sim::CanFrame::data_frame(0x705, {0x05});
const sim::CanFrame kSdo = sim::CanFrame::data_frame(0x601, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});

}  // namespace

TEST(SocketcandServer, FramesFanOutBetweenTheBusAndEveryClient) {
  sim::Bus bus("main");
  bus.set_transport(serve());
  auto& server = static_cast<sim::SocketcandServer&>(*bus.transport());
  Recorder plant;
  const int plant_ep = bus.attach(&plant);
  TcpClient a(server.port()), b(server.port());
  ASSERT_TRUE(a.connected() && b.connected());
  a.handshake();
  b.handshake();

  // The plant's frame reaches both clients.
  bus.send(plant_ep, kHeartbeat, sim::Time{});
  bus.deliver(sim::Time{});
  EXPECT_EQ(a.next_frame(), kHeartbeat);
  EXPECT_EQ(b.next_frame(), kHeartbeat);

  // A client's frame reaches the plant (through the bus) and the other client, not itself.
  a.send("< send 601 8 40 0 10 0 0 0 0 0 >");
  ASSERT_TRUE(wait_for([&] {
    bus.poll_transport(sim::Time{});
    bus.deliver(sim::Time{});
    return !plant.frames.empty();
  }));
  EXPECT_EQ(plant.frames.back(), kSdo);
  EXPECT_EQ(b.next_frame(), kSdo);
  // The bus does not echo a wire frame back to the wire, and the server does not echo it to its
  // sender: the next thing client a sees is the plant's next frame.
  bus.send(plant_ep, kHeartbeat, sim::Time{});
  bus.deliver(sim::Time{});
  EXPECT_EQ(a.next_frame(), kHeartbeat);
  EXPECT_EQ(b.next_frame(), kHeartbeat);
  EXPECT_EQ(server.stats().rx_frames, 1u);
  EXPECT_EQ(server.stats().tx_frames, 2u);
  EXPECT_TRUE(wait_for([&] { return server.client_count() == 2; }));
  EXPECT_EQ(server.clients_dropped(), 0u);
}

TEST(SocketcandServer, HandshakeAnswersArriveAloneWhileTheBusIsBusy) {
  // python-can 4.1 reads `< hi >` and both `< ok >` with one recv() each and compares the whole
  // string: no frame may share their segment, however busy the bus.
  auto server = serve();
  std::atomic<bool> stop{false};
  std::thread plant([&] {
    while (!stop) {
      server->send(kHeartbeat);
      server->service(sim::Time{});
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  });
  for (int i = 0; i < 3; ++i) {
    TcpClient c(server->port());
    EXPECT_EQ(c.recv_once(), "< hi >");
    c.send("< open main >");
    EXPECT_EQ(c.recv_once(), "< ok >");
    c.send("< rawmode >");
    EXPECT_EQ(c.recv_once(), "< ok >");
    EXPECT_EQ(c.next_frame(), kHeartbeat);
  }
  stop = true;
  plant.join();
}

TEST(SocketcandServer, AnswersEchoAndLeavesRawModeOnBcmmode) {
  auto server = serve();
  TcpClient a(server->port());
  a.handshake();
  a.send("< echo >");
  EXPECT_EQ(a.next(), "< echo >");
  a.send("< bcmmode >");
  EXPECT_EQ(a.next(), "< ok >");
  server->send(kHeartbeat);  // not for a client in BCM mode
  server->service(sim::Time{});
  a.send("< echo >");
  EXPECT_EQ(a.next(), "< echo >");
}

TEST(SocketcandServer, ExtendedAndRemoteFramesCrossBothWays) {
  auto server = serve();
  TcpClient a(server->port());
  a.handshake();
  a.send("< send 1AAAAAAA 2 1 F1 >< sendrtr 701 1 >");
  sim::CanFrame f;
  ASSERT_TRUE(receive_within(*server, f));
  auto ext = sim::CanFrame::data_frame(0x1AAAAAAA, {0x01, 0xF1});
  ext.extended = true;
  EXPECT_EQ(f, ext);
  ASSERT_TRUE(receive_within(*server, f));
  EXPECT_EQ(f, sim::CanFrame::remote_frame(0x701, 1));
  // python-can 4.1's remote frames: no data bytes (see socketcand::parse).
  a.send("< send 705 0  >< send 185 8  >");
  ASSERT_TRUE(receive_within(*server, f));
  EXPECT_EQ(f, sim::CanFrame::remote_frame(0x705, 0));
  ASSERT_TRUE(receive_within(*server, f));
  EXPECT_EQ(f, sim::CanFrame::remote_frame(0x185, 8));
  server->send(sim::CanFrame::remote_frame(0x705, 1));
  server->service(sim::Time{});
  EXPECT_EQ(a.next_frame(), sim::CanFrame::remote_frame(0x705, 1));  // `< rtr 705 SEC.USEC 1 >`
  server->send(ext);
  server->service(sim::Time{});
  EXPECT_EQ(a.next_frame(), ext);
}

struct BadInput {
  const char* name;
  bool before_open;     // sent instead of the handshake
  bool closes;          // the stream cannot be resynchronised (or the bus is wrong): closed
  std::string text;
  std::string reason;   // the `< error ... >` the client gets
};

class SocketcandBadClient : public ::testing::TestWithParam<BadInput> {};

TEST_P(SocketcandBadClient, GetsAReasonWhileTheBusAndOtherClientsContinue) {
  const auto& bad_input = GetParam();
  auto server = serve();
  TcpClient good(server->port()), bad(server->port());
  good.handshake();
  if (bad_input.before_open) {
    EXPECT_EQ(bad.next(), "< hi >");
  } else {
    bad.handshake();
  }
  bad.send(bad_input.text);
  sim::CanFrame f;
  if (bad_input.closes) {
    EXPECT_EQ(bad.last_message_before_close(), "< error " + bad_input.reason + " >");
    EXPECT_TRUE(wait_for([&] { return server->clients_dropped() == 1 && server->client_count() == 1; }));
  } else {
    // A well-delimited message it cannot use: answered, and the connection carries on.
    EXPECT_EQ(bad.next(), "< error " + bad_input.reason + " >");
    if (bad_input.before_open) bad.handshake_after_hi();
    EXPECT_FALSE(server->receive(f));
    bad.send("< send 601 8 40 0 10 0 0 0 0 0 >");
    ASSERT_TRUE(carry_within(*server, f));
    EXPECT_EQ(f, kSdo);
    EXPECT_EQ(good.next_frame(), kSdo);
    EXPECT_EQ(server->clients_dropped(), 0u);
    EXPECT_EQ(server->client_count(), 2);
  }

  // Nothing of it reached the bus; the good client still has the bus both ways.
  EXPECT_FALSE(server->receive(f));
  good.send("< send 601 8 40 0 10 0 0 0 0 0 >");
  ASSERT_TRUE(carry_within(*server, f));
  EXPECT_EQ(f, kSdo);
  server->send(kHeartbeat);
  server->service(sim::Time{});
  EXPECT_EQ(good.next_frame(), kHeartbeat);
}

INSTANTIATE_TEST_SUITE_P(
    EveryClassOfBadInput, SocketcandBadClient,
    ::testing::Values(
        BadInput{"garbage", false, true, "GET / HTTP/1.1\r\n", "bytes outside a '? ... ?' message: 'GET / HTTP/1.1\\x0D\\x0A'"},
        BadInput{"overlong", false, true, "< send " + std::string(300, '1'), "message longer than 128 bytes"},
        BadInput{"unknown_bus", true, true, "< open can0 >", "unknown bus 'can0' (this server has 'main')"},
        BadInput{"bad_hex", false, false, "< send 123 1 G1 >", "bad hex byte 'G1'"},
        BadInput{"wrong_dlc", false, false, "< send 123 3 1 2 >", "DLC 3 but 2 data byte(s)"},
        BadInput{"dlc_over_8", false, false, "< send 123 9 1 2 3 4 5 6 7 8 9 >", "DLC 9 exceeds 8"},
        BadInput{"unknown_command", false, false, "< subscribe 0 0 123 >", "unknown command 'subscribe'"},
        BadInput{"non_printable", false, false, "< send 123 0 \x01 >", "non-printable byte 0x01 in a message"},
        BadInput{"server_message", false, false, "< frame 123 1.0 00 >", "unexpected '? frame 123 1.0 00 ?' from a client"},
        BadInput{"send_before_open", true, false, "< send 123 0 >", "expected '? open main ?' first"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(SocketcandServer, AClientThatNeverReadsIsDroppedAndTheTransportNeverBlocks) {
  auto server = serve();
  TcpClient lazy(server->port(), 4096);
  lazy.handshake();
  std::this_thread::sleep_for(std::chrono::milliseconds(sim::SocketcandServer::kRawmodeSettleMs + 50));
  // Kernel buffers first, then the server's bounded output: the client goes, the bus stays.
  const auto until = Clock::now() + std::chrono::seconds(20);
  std::uint64_t sent = 0;
  while (server->clients_dropped() == 0 && Clock::now() < until) {
    for (int i = 0; i < 1000; ++i) server->send(kHeartbeat);
    server->service(sim::Time{});
    sent += 1000;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_EQ(server->clients_dropped(), 1u) << sent << " frames sent";
  EXPECT_TRUE(wait_for([&] { return server->client_count() == 0; }));
  // A new client is served as usual.
  TcpClient next(server->port());
  next.handshake();
  server->send(kSdo);
  server->service(sim::Time{});
  EXPECT_EQ(next.next_frame(), kSdo);
}

TEST(SocketcandServer, RefusesClientsBeyondTheLimit) {
  auto server = serve();
  std::vector<std::unique_ptr<TcpClient>> clients;
  for (int i = 0; i < sim::SocketcandServer::kMaxClients; ++i) {
    clients.push_back(std::make_unique<TcpClient>(server->port()));
    EXPECT_EQ(clients.back()->next(), "< hi >");
  }
  TcpClient one_too_many(server->port());
  EXPECT_EQ(one_too_many.last_message_before_close(), "< error too many clients >");
}

TEST(SocketcandServer, SilentConnectionsCannotHoldTheSlots) {
  // Every slot taken by a connection that never sends: each is closed when its handshake time is
  // up, and a real master then gets in.
  std::string error;
  sim::SocketcandServer::Limits limits;
  limits.handshake_ms = 300;
  auto server = sim::SocketcandServer::open("main", sim::TcpEndpoint{"127.0.0.1", 0}, error, limits);
  ASSERT_TRUE(server) << error;
  std::vector<std::unique_ptr<TcpClient>> silent;
  for (int i = 0; i < sim::SocketcandServer::kMaxClients; ++i) {
    silent.push_back(std::make_unique<TcpClient>(server->port()));
    EXPECT_EQ(silent.back()->next(), "< hi >");
  }
  EXPECT_TRUE(wait_for([&] { return server->client_count() == sim::SocketcandServer::kMaxClients; }));
  TcpClient refused(server->port());
  EXPECT_EQ(refused.last_message_before_close(), "< error too many clients >");
  for (auto& c : silent)
    EXPECT_EQ(c->last_message_before_close(), "< error no '? open main ?' within 300 ms of connecting >");
  EXPECT_TRUE(wait_for([&] { return server->client_count() == 0; }));
  TcpClient master(server->port());
  master.handshake();
  server->send(kHeartbeat);
  server->service(sim::Time{});
  EXPECT_EQ(master.next_frame(), kHeartbeat);
  // A raw-mode client that only listens is not idle: it outlives the handshake limit.
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  server->send(kSdo);
  server->service(sim::Time{});
  EXPECT_EQ(master.next_frame(), kSdo);
  EXPECT_EQ(server->client_count(), 1);
}

TEST(SocketcandServer, AClientIdleInBcmModeIsClosedAndOneThatTalksIsNot) {
  std::string error;
  sim::SocketcandServer::Limits limits;
  limits.bcm_idle_ms = 300;
  auto server = sim::SocketcandServer::open("main", sim::TcpEndpoint{"127.0.0.1", 0}, error, limits);
  ASSERT_TRUE(server) << error;
  TcpClient idle(server->port()), talking(server->port());
  for (auto* c : {&idle, &talking}) {
    EXPECT_EQ(c->next(), "< hi >");
    c->send("< open main >");
    EXPECT_EQ(c->next(), "< ok >");
  }
  for (int i = 0; i < 5; ++i) {  // 500 ms, an echo every 100 ms
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    talking.send("< echo >");
    EXPECT_EQ(talking.next(), "< echo >");
  }
  EXPECT_EQ(idle.last_message_before_close(), "< error idle in BCM mode for 300 ms >");
  EXPECT_EQ(server->client_count(), 1);
}

// A node that answers every SDO request to node 5 at once, and a log of what the bus delivered.
struct SdoAnswerer : sim::FrameReceiver {
  sim::Bus* bus = nullptr;
  int endpoint = -1;
  std::vector<std::pair<sim::CanFrame, sim::Time>> seen;
  void on_frame(const sim::CanFrame& f, sim::Time now) override {
    seen.emplace_back(f, now);
    if (f.id == 0x605 && !f.rtr)
      bus->send(endpoint, sim::CanFrame::data_frame(0x585, {0x43, 0x00, 0x10, 0x00, 0x96, 0x01, 0x0A, 0x00}), now);
  }
};

TEST(SocketcandServer, ClientFramesTakeTheBitTimedBusesTime) {
  // Virtual time: the bus stands still while the server hands the request over, then the request
  // and the answer each take their bit time at 500 kbit/s.
  sim::Bus bus("main");
  bus.set_timing(sim::BusTiming::Bit, 500000);
  bus.set_transport(serve());
  auto& server = static_cast<sim::SocketcandServer&>(*bus.transport());
  SdoAnswerer node;
  node.bus = &bus;
  node.endpoint = bus.attach(&node);
  TcpClient master(server.port());
  master.handshake();
  std::this_thread::sleep_for(std::chrono::milliseconds(sim::SocketcandServer::kRawmodeSettleMs + 50));

  const auto request = sim::CanFrame::data_frame(0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  master.send("< send 605 8 40 0 10 0 0 0 0 0 >");
  const sim::Time sent{std::chrono::microseconds(1000)};
  ASSERT_TRUE(wait_for([&] { return bus.poll_transport(sent) == 1; }));
  sim::Time t = sent;
  while (bus.stats().frames < 2 && t < sent + std::chrono::milliseconds(10)) {
    t += std::chrono::microseconds(1);
    bus.deliver(t);
  }
  ASSERT_EQ(node.seen.size(), 1u);  // the request (its own answer does not come back to it), then ...
  EXPECT_EQ(node.seen[0].first, request);
  const std::int64_t bit_us = 2;
  const auto request_bits = sim::frame_bits(request).until_eof();
  EXPECT_GE((node.seen[0].second - sent).count(), request_bits * bit_us);
  // ... the answer, seen by the master: at least both frames' bit time after the request was sent.
  const auto answer = master.next_frame();
  EXPECT_EQ(answer.id, 0x585u);
  const auto answer_bits = sim::frame_bits(answer).until_eof();
  ASSERT_EQ(bus.stats().frames, 2u);
  // The answer was delivered (to the wire) when the last deliver() ran past its end of frame.
  EXPECT_GE((t - sent).count(), (request_bits + answer_bits) * bit_us);
  EXPECT_GE(request_bits + answer_bits, 200u);  // 0.40 ms or more at 500 kbit/s
}

TEST(SocketcandServer, AFloodingClientIsBoundedByItsQueueAndTheBus) {
  // One client writes 2000 frames at once: it keeps at most kClientTxQueue on the way, the rest
  // are refused to it with a reason; the bus carries no more than its bit rate allows; another
  // client's frame still gets through.
  sim::Bus bus("main");
  bus.set_timing(sim::BusTiming::Bit, 500000);
  bus.set_transport(serve());
  auto& server = static_cast<sim::SocketcandServer&>(*bus.transport());
  Recorder plant;
  bus.attach(&plant);
  TcpClient flood(server.port()), polite(server.port());
  flood.handshake();
  polite.handshake();
  std::string lines;
  for (int i = 0; i < 2000; ++i) lines += "< send 100 8 1 2 3 4 5 6 7 8 >";
  flood.send(lines);
  int refused = 0;
  while (refused < 2000 - sim::SocketcandServer::kClientTxQueue) {
    const auto m = flood.next();
    if (m.rfind("< error frame 100 refused:", 0) == 0) ++refused;
    else ASSERT_EQ(m.rfind("< frame", 0), 0u) << m;
  }
  EXPECT_EQ(refused, 2000 - sim::SocketcandServer::kClientTxQueue);
  polite.send("< send 601 8 40 0 10 0 0 0 0 0 >");
  // 10 ms of virtual time in 10 µs ticks; the I/O thread gets a moment of wall time per tick.
  sim::Time t{};
  ASSERT_TRUE(wait_for([&] {
    bus.poll_transport(t);
    return bus.stats().from_wire + bus.pending_frames() >= 1u + sim::SocketcandServer::kClientTxQueue;
  }));
  while (t < sim::Time{std::chrono::milliseconds(10)}) {
    t += std::chrono::microseconds(10);
    bus.poll_transport(t);
    bus.deliver(t);
  }
  const auto frame_us = sim::frame_bits(kSdo).total() * 2;
  EXPECT_EQ(bus.stats().from_wire, 1u + sim::SocketcandServer::kClientTxQueue);
  EXPECT_LE(bus.stats().from_wire, 10000u / frame_us + 1);
  bool polite_delivered = false;
  for (const auto& f : plant.frames) polite_delivered |= f == kSdo;
  EXPECT_TRUE(polite_delivered);
  EXPECT_EQ(server.clients_dropped(), 0u);
  // Room again once the bus carried them: the flooding client may send again.
  flood.send("< send 100 0 >");
  ASSERT_TRUE(wait_for([&] { return bus.poll_transport(t) == 1; }));
}

TEST(SocketcandServer, AFullBusQueueRefusesTheFrameToItsSender) {
  // Two clients against a transmit queue of 4 for the wire: the fifth frame is refused by the bus
  // and the refusal reaches the client that sent it.
  sim::Bus bus("main");
  bus.set_timing(sim::BusTiming::Bit, 500000);
  bus.set_tx_queue_depth(4);
  bus.set_transport(serve());
  auto& server = static_cast<sim::SocketcandServer&>(*bus.transport());
  TcpClient a(server.port()), b(server.port());
  a.handshake();
  b.handshake();
  a.send("< send 100 0 >< send 101 0 >< send 102 0 >");
  ASSERT_TRUE(wait_for([&] { return bus.pending_frames() == 3 || bus.poll_transport(sim::Time{}) == 3; }));
  b.send("< send 200 0 >< send 201 0 >");
  std::size_t taken = 0;
  ASSERT_TRUE(wait_for([&] {
    taken += bus.poll_transport(sim::Time{});
    return taken == 2;
  }));
  bus.deliver(sim::Time{});  // service(): the results go to the server
  EXPECT_EQ(b.next(), "< error frame 201 refused: the bus's transmit queue is full >");
  EXPECT_EQ(bus.stats().tx_queue_overflow, 1u);
}

TEST(SocketcandClient, JoinsAServerAndExchangesFramesBothWays) {
  auto server = serve("can0");
  std::string error;
  auto client = sim::SocketcandClient::open(sim::TcpEndpoint{"127.0.0.1", server->port()}, "can0", error);
  ASSERT_TRUE(client) << error;
  EXPECT_EQ(client->name(), "can0");
  ASSERT_TRUE(wait_for([&] { return client->connected(); }));
  TcpClient observer(server->port());
  observer.handshake("can0");
  std::this_thread::sleep_for(std::chrono::milliseconds(sim::SocketcandServer::kRawmodeSettleMs + 50));

  // Our bus → the remote bus (the server's side) and its other clients.
  client->send(kSdo);
  client->service(sim::Time{});
  sim::CanFrame f;
  ASSERT_TRUE(carry_within(*server, f));
  EXPECT_EQ(f, kSdo);
  EXPECT_EQ(observer.next_frame(), kSdo);
  // The remote bus → our bus, from the server's side and from another client.
  server->send(kHeartbeat);
  server->service(sim::Time{});
  ASSERT_TRUE(receive_within(*client, f));
  EXPECT_EQ(f, kHeartbeat);
  auto ext = sim::CanFrame::data_frame(0x18FF0102, {1, 2, 3, 4, 5, 6, 7, 8});
  ext.extended = true;
  observer.send("< send 18FF0102 8 1 2 3 4 5 6 7 8 >");
  ASSERT_TRUE(carry_within(*server, f));  // the server's bus carries it, then its clients see it
  EXPECT_EQ(f, ext);
  ASSERT_TRUE(receive_within(*client, f));
  EXPECT_EQ(f, ext);
  EXPECT_EQ(client->stats().rx_frames, 2u);
}

TEST(SocketcandClient, ReconnectsWhenTheServerComesBack) {
  auto server = serve();
  const auto port = server->port();
  std::string error;
  auto client = sim::SocketcandClient::open(sim::TcpEndpoint{"127.0.0.1", port}, "main", error);
  ASSERT_TRUE(client) << error;
  ASSERT_TRUE(wait_for([&] { return client->connected(); }));
  server.reset();
  ASSERT_TRUE(wait_for([&] { return !client->connected(); }));
  // Frames sent while the link is down are counted, never queued without bound.
  client->send(kSdo);
  client->service(sim::Time{});
  EXPECT_TRUE(wait_for([&] { return client->wire_dropped() == 1; }));
  server = sim::SocketcandServer::open("main", sim::TcpEndpoint{"127.0.0.1", port}, error);
  ASSERT_TRUE(server) << error;
  ASSERT_TRUE(wait_for([&] { return client->connected(); }, 5000));
  client->service(sim::Time{});
  EXPECT_EQ(client->stats().link_down_events, 1u);
  std::this_thread::sleep_for(std::chrono::milliseconds(sim::SocketcandServer::kRawmodeSettleMs + 50));
  server->send(kHeartbeat);
  server->service(sim::Time{});
  sim::CanFrame f;
  ASSERT_TRUE(receive_within(*client, f));
  EXPECT_EQ(f, kHeartbeat);
}

TEST(SocketcandClient, FramesSentBeforeTheFirstConnectionWaitForIt) {
  // A node's boot-up is sent at power-on, before the connection is up: it is not lost.
  std::uint16_t port = serve()->port();  // a port that was free a moment ago
  std::string error;
  auto client = sim::SocketcandClient::open(sim::TcpEndpoint{"127.0.0.1", port}, "main", error);
  ASSERT_TRUE(client) << error;
  client->send(kHeartbeat);
  client->service(sim::Time{});
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  auto server = sim::SocketcandServer::open("main", sim::TcpEndpoint{"127.0.0.1", port}, error);
  ASSERT_TRUE(server) << error;
  sim::CanFrame f;
  ASSERT_TRUE(receive_within(*server, f, 5000));
  EXPECT_EQ(f, kHeartbeat);
  EXPECT_EQ(client->wire_dropped(), 0u);
}

TEST(SocketcandClient, AWrongChannelNeverConnects) {
  auto server = serve();
  std::string error;
  auto client = sim::SocketcandClient::open(sim::TcpEndpoint{"127.0.0.1", server->port()}, "can9", error);
  ASSERT_TRUE(client) << error;
  EXPECT_TRUE(wait_for([&] { return server->clients_dropped() >= 1; }));
  EXPECT_FALSE(client->connected());
}

TEST(TransportFactory, ParsesEverySpelling) {
  std::string error;
  auto t = sim::open_transport("main", "socketcand:127.0.0.1:0", error);
  ASSERT_TRUE(t) << error;
  EXPECT_EQ(t->name(), "main");
  t = sim::open_transport("main", "socketcand:127.0.0.1:0/can1", error);
  ASSERT_TRUE(t) << error;
  EXPECT_EQ(t->name(), "can1");
  t = sim::open_transport("main", "socketcand-client:127.0.0.1:1/can0", error);
  ASSERT_TRUE(t) << error;
  EXPECT_EQ(t->name(), "can0");
  EXPECT_FALSE(sim::open_transport("main", "socketcand-client:127.0.0.1:1", error));
  EXPECT_EQ(error, "'socketcand-client:127.0.0.1:1': expected socketcand-client:HOST:PORT/CHANNEL");
  EXPECT_FALSE(sim::open_transport("main", "socketcand:127.0.0.1", error));
  EXPECT_EQ(error, "'socketcand:127.0.0.1': '127.0.0.1' is not HOST:PORT");
  EXPECT_FALSE(sim::open_transport("main", "socketcand:127.0.0.1:70000", error));
  EXPECT_EQ(error, "'socketcand:127.0.0.1:70000': port '70000' is not a number from 0 to 65535");
  EXPECT_FALSE(sim::open_transport("main", "socketcand:127.0.0.1:0/", error));
  EXPECT_TRUE(sim::is_socketcand_spec("socketcand:x:1"));
  EXPECT_FALSE(sim::is_socketcand_spec("vcan0"));
}

namespace {

// A seeded generator of socketcand lines for the robustness test: well-formed messages, the same
// with one or more mutations (a byte changed, inserted or cut, a field repeated, a number
// stretched), and noise. Deterministic for a seed, so a failure is reproduced by its seed.
class LineFuzzer {
 public:
  explicit LineFuzzer(std::uint32_t seed) : rng_(seed) {}
  std::string next() {
    static const char* const kValid[] = {
        "< open main >", "< rawmode >", "< bcmmode >", "< echo >", "< send 601 8 40 0 10 0 0 0 0 0 >",
        "< send 705 0 >", "< send 705 1 >", "< sendrtr 705 1 >", "< send 80 0 >", "< send 1FFFFFFF 2 1 2 >",
        "< open can0 >", "< add 1 0 123 0 >", "< frame 123 1.0 00 >", "< hi >", "< subscribe 0 0 123 >"};
    std::string s = kValid[pick(std::size(kValid))];
    switch (pick(6)) {
      case 0: return s;  // as it is
      case 1: return mutate(s, 1);
      case 2: return mutate(s, 1 + pick(8));
      case 3: return s.substr(0, pick(s.size() + 1));  // cut short
      case 4: return "< send " + number() + " " + number() + " " + number() + " " + number() + " >";
      default: return noise();
    }
  }

 private:
  std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }
  char byte() { return static_cast<char>(pick(256)); }
  std::string number() {
    static const char* const kNumbers[] = {"0", "-1", "8", "9", "FFFFFFFF", "100000000", "7FF", "800", "G", "",
                                           "18446744073709551616", "0x10", "1e9"};
    return kNumbers[pick(std::size(kNumbers))];
  }
  std::string noise() {
    std::string s(pick(200), ' ');
    for (auto& c : s) c = byte();
    return s;
  }
  std::string mutate(std::string s, std::size_t times) {
    for (std::size_t i = 0; i < times && !s.empty(); ++i) {
      const std::size_t at = pick(s.size());
      switch (pick(4)) {
        case 0: s[at] = byte(); break;
        case 1: s.insert(at, 1, "<> 0F"[pick(5)]); break;
        case 2: s.erase(at, 1 + pick(4)); break;
        default: s.insert(at, s.substr(at, pick(40))); break;
      }
    }
    return s;
  }
  std::mt19937 rng_;
};

std::size_t resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
}

}  // namespace

// Robustness (issue 25): seeded batches of abusive socketcand lines from clients that never read.
// After each batch the server still serves a well-behaved client both ways, holds no more than its
// client slots, and the process's resident memory stays under 256 MiB (docs/remote.md, "Slots").
TEST(SocketcandServerRobustness, SeededAbusiveLinesLeaveTheServerServing) {
  std::string error;
  sim::SocketcandServer::Limits limits;
  limits.handshake_ms = 200;  // fuzz clients that never open are gone quickly
  auto server = sim::SocketcandServer::open("main", sim::TcpEndpoint{"127.0.0.1", 0}, error, limits);
  ASSERT_TRUE(server) << error;
  TcpClient good(server->port());
  good.handshake();
  const std::size_t rss_bound = 256u << 20;
  for (std::uint32_t seed = 1; seed <= 24; ++seed) {
    LineFuzzer fuzz(seed);
    {
      std::vector<std::unique_ptr<TcpClient>> abusers;
      for (int c = 0; c < 4; ++c) abusers.push_back(std::make_unique<TcpClient>(server->port()));
      for (int line = 0; line < 60; ++line) {
        auto& a = *abusers[static_cast<std::size_t>(line) % abusers.size()];
        a.send_anyway(fuzz.next() + (line % 3 ? "" : "\n"));
      }
      // Whatever the abusers got onto the bus is carried (as a bus would) and counted.
      sim::CanFrame f;
      for (int i = 0; i < 1000 && carry_within(*server, f, 20); ++i) {
      }
      EXPECT_LE(server->client_count(), sim::SocketcandServer::kMaxClients) << "seed " << seed;
    }  // the abusers disconnect
    // The well-behaved client still has the bus both ways.
    good.send("< send 601 8 40 0 10 0 0 0 0 0 >");
    sim::CanFrame f;
    bool got_sdo = false;
    for (int i = 0; i < 100 && !got_sdo && carry_within(*server, f, 1000); ++i) got_sdo = f == kSdo;
    EXPECT_TRUE(got_sdo) << "seed " << seed << ": the good client's frame did not reach the bus";
    server->send(sim::CanFrame::data_frame(0x7AB, {static_cast<std::uint8_t>(seed)}));  // an identifier no line uses
    server->service(sim::Time{});
    std::string seen;
    for (int i = 0; i < 100; ++i) {
      seen = good.next();
      if (seen.empty() || seen.find("< frame 7AB ") == 0) break;
    }
    EXPECT_EQ(seen.substr(0, 12), "< frame 7AB ") << "seed " << seed;
    EXPECT_LT(resident_bytes(), rss_bound) << "seed " << seed;
  }
  EXPECT_TRUE(wait_for([&] { return server->client_count() == 1; }));
}
