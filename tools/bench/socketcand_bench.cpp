// What a socketcand-served bus costs: CPU time on the scheduler's thread per frame (it only
// queues and dequeues; the server thread does the sockets and the text), the process's CPU time
// per frame, and the wall-clock throughput to one client over loopback, both directions.
// Prints figures; it is not a test. Usage: socketcand_bench [frames]
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <thread>

#include "sim/log.h"
#include "sim/socketcand_server.h"

namespace {

double cpu_seconds(clockid_t clock) {
  timespec ts{};
  ::clock_gettime(clock, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

int connect_raw_client(std::uint16_t port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(port);
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) std::exit(1);
  const std::string hello = "< open main >< rawmode >";
  if (::send(fd, hello.data(), hello.size(), 0) != static_cast<ssize_t>(hello.size())) std::exit(1);
  return fd;
}

}  // namespace

int main(int argc, char** argv) {
  const long frames = argc > 1 ? std::atol(argv[1]) : 200000;
  sim::set_log_threshold(sim::LogLevel::Warn);
  std::string error;
  auto server = sim::SocketcandServer::open("main", sim::TcpEndpoint{"127.0.0.1", 0}, error);
  if (!server) {
    std::fprintf(stderr, "socketcand_bench: %s\n", error.c_str());
    return 1;
  }
  const int fd = connect_raw_client(server->port());
  std::atomic<long> received{0};
  std::atomic<bool> done{false};
  std::thread reader([&] {
    char buf[65536];
    while (!done) {
      pollfd p{fd, POLLIN, 0};
      if (::poll(&p, 1, 100) <= 0) continue;
      const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
      if (n <= 0) break;
      long k = 0;
      for (ssize_t i = 0; i < n; ++i) k += buf[i] == '>';
      received += k;
    }
  });
  // hi + two ok, then the settle time before frames flow.
  while (received < 3) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  std::this_thread::sleep_for(std::chrono::milliseconds(sim::SocketcandServer::kRawmodeSettleMs + 50));

  // Bus → client: ticks of 100 frames; the scheduler never waits on the server, the bench only
  // keeps the queue from overflowing so that every frame is measured end to end.
  const auto frame = sim::CanFrame::data_frame(0x285, {0x12, 0x34, 0x56, 0x78, 0, 0, 0, 0});
  double sched_cpu = 0;
  const double proc0 = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID);
  const auto wall0 = std::chrono::steady_clock::now();
  for (long sent = 0; sent < frames;) {
    const double t0 = cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
    for (int i = 0; i < 100; ++i) server->send(frame);
    server->service(sim::Time{});
    sched_cpu += cpu_seconds(CLOCK_THREAD_CPUTIME_ID) - t0;
    sent += 100;
    while (sent - (received - 3) > 500 && server->client_count() == 1)
      std::this_thread::sleep_for(std::chrono::microseconds(50));
  }
  while (received - 3 < frames && server->client_count() == 1) std::this_thread::sleep_for(std::chrono::microseconds(100));
  if (server->client_count() != 1) {
    std::fprintf(stderr, "socketcand_bench: the client was dropped\n");
    return 1;
  }
  const double wall_out = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const double proc_out = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID) - proc0;
  std::printf("bus -> client: %ld frames, %llu dropped\n", frames,
              static_cast<unsigned long long>(server->stats().tx_dropped));
  std::printf("  scheduler thread CPU: %.0f ns/frame (send + service)\n", sched_cpu / frames * 1e9);
  std::printf("  process CPU (incl. the client reader): %.2f us/frame; %.0f frames/s wall\n", proc_out / frames * 1e6,
              frames / wall_out);

  // Client → bus: the client writes `< send >` lines; the scheduler thread dequeues and reports
  // each frame carried. A client may have SocketcandServer::kClientTxQueue frames on the way; the
  // writer sends a window of that many and sends the next one when they have been carried.
  std::atomic<long> got{0};
  std::thread writer([&] {
    constexpr long kWindow = sim::SocketcandServer::kClientTxQueue;
    const std::string line = "< send 205 8 7 0 0 20 0 0 0 0 >";
    std::string batch;
    for (long i = 0; i < kWindow; ++i) batch += line;
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    for (long n = 0; n < frames; n += kWindow) {
      while (n - got.load() > 0 && std::chrono::steady_clock::now() < until) std::this_thread::yield();
      // The server frees the window when the results reach its thread, a moment after `got`.
      if (n > 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
      if (::send(fd, batch.data(), batch.size(), 0) != static_cast<ssize_t>(batch.size())) return;
    }
  });
  double recv_cpu = 0;
  const double proc1 = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID);
  const auto wall1 = std::chrono::steady_clock::now();
  sim::CanFrame f;
  while (got < frames) {
    pollfd p{server->wait_fd(), POLLIN, 0};
    ::poll(&p, 1, 100);
    const double t0 = cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
    // As the bus does: each frame's result returns the client's transmit-queue slot.
    std::uint32_t tag = 0;
    while (server->receive_tagged(f, tag)) {
      server->wire_result(tag, f, sim::Transport::WireResult::Delivered);
      ++got;
    }
    server->service(sim::Time{});
    recv_cpu += cpu_seconds(CLOCK_THREAD_CPUTIME_ID) - t0;
    if (std::chrono::steady_clock::now() - wall1 > std::chrono::seconds(60)) break;
  }
  const double wall_in = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall1).count();
  const double proc_in = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID) - proc1;
  writer.join();
  std::printf("client -> bus (windows of %d): %ld of %ld frames, %llu dropped (scheduler behind)\n",
              sim::SocketcandServer::kClientTxQueue, got.load(), frames,
              static_cast<unsigned long long>(server->rx_dropped()));
  std::printf("  scheduler thread CPU: %.0f ns/frame (receive, wake-ups included)\n", recv_cpu / (got ? got.load() : 1) * 1e9);
  std::printf("  process CPU (incl. the client writer): %.2f us/frame; %.0f frames/s wall\n",
              proc_in / (got ? got.load() : 1) * 1e6, static_cast<double>(got.load()) / wall_in);
  done = true;
  ::shutdown(fd, SHUT_RDWR);
  reader.join();
  ::close(fd);
  return 0;
}
