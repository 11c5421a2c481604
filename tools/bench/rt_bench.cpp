// Real-time benchmark over real SocketCAN (run it on vcan0, e.g. through tools/vcan/vcan-run):
//  * SDO expedited upload round-trip latency, measured by a master in a separate process from
//    a node running in real-time mode (median, p99, max);
//  * real-time tick lateness of that node's scheduler while it serves the master (median, p99,
//    max) and its overrun count.
//  * --heartbeat: a node's heartbeat period on the wall clock and the tick lateness, on the host
//    with CPU-bound competitors, with or without real-time scheduling (--rt).
// Usage: rt_bench [--iface vcan0] [--requests 2000] [--tick-us 1000]
//        rt_bench --host-only SECONDS [--tick-us 1000]
//        rt_bench --heartbeat SECONDS [--competitors 2] [--rt] [--period-ms 10] [--tick-us 1000]
// --host-only needs no CAN: the node runs in real time on the virtual bus of this process while
// an in-process master sends one SDO request per tick; it measures the scheduler's tick lateness
// on the host kernel (useful where vcan exists only inside the emulated qemu guest).
#include <linux/can.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <sys/socket.h>
#include <time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "devices/canopen/node.h"
#include "devices/canopen/standard_objects.h"
#include "sim/bus.h"
#include "sim/realtime_setup.h"
#include "sim/scheduler.h"
#include "sim/socketcan_transport.h"

namespace {

constexpr std::uint8_t kNodeId = 5;

struct Stats {
  double median, p99, max;
};

Stats summarize(std::vector<double> v) {
  if (v.empty()) return {0, 0, 0};
  std::sort(v.begin(), v.end());
  auto at = [&](double q) { return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))]; };
  return {at(0.5), at(0.99), v.back()};
}

sim::Scheduler* g_scheduler = nullptr;
extern "C" void on_term(int) {
  if (g_scheduler) g_scheduler->request_stop();
}

// The node process: a CiA 301 node in real time; prints its tick lateness statistics on exit.
int run_node(const std::string& iface, long tick_us, int report_fd) {
  canopen::ObjectDictionary od;
  canopen::CommunicationProfile profile;
  profile.device_type = 0x191;
  profile.vendor_id = 0x1234;
  canopen::add_communication_objects(od, profile);
  canopen::Node node("bench", std::move(od), {}, kNodeId);
  sim::Bus bus(iface);
  std::string error;
  auto transport = sim::SocketCanTransport::open(iface, error);
  if (!transport) {
    std::fprintf(stderr, "rt_bench: %s\n", error.c_str());
    return 2;
  }
  bus.set_transport(std::move(transport));
  sim::Scheduler scheduler(sim::microseconds(tick_us), sim::ClockMode::RealTime);
  scheduler.add_bus(&bus);
  node.attach(bus);
  scheduler.add(&node);
  std::vector<double> lateness;
  lateness.reserve(1 << 22);
  scheduler.set_lateness_observer([&](sim::Duration d) {
    if (lateness.size() < lateness.capacity()) lateness.push_back(static_cast<double>(d.count()));
  });
  g_scheduler = &scheduler;
  std::signal(SIGTERM, on_term);
  node.power_on(scheduler.now());
  scheduler.run_until_stopped();
  const Stats s = summarize(lateness);
  const std::string text = std::to_string(lateness.size()) + " " + std::to_string(s.median) + " " +
                           std::to_string(s.p99) + " " + std::to_string(s.max) + " " +
                           std::to_string(scheduler.stats().overruns) + "\n";
  if (write(report_fd, text.data(), text.size()) < 0) return 1;
  return 0;
}

double now_us() {
  return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

int open_raw(const std::string& iface) {
  const int fd = socket(PF_CAN, SOCK_RAW, CAN_RAW);
  if (fd < 0) return -1;
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = static_cast<int>(if_nametoindex(iface.c_str()));
  can_filter filter{0x580u + kNodeId, CAN_SFF_MASK | CAN_RTR_FLAG | CAN_EFF_FLAG};
  setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FILTER, &filter, sizeof filter);
  if (addr.can_ifindex == 0 || bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) < 0) {
    close(fd);
    return -1;
  }
  return fd;
}

// Real-time scheduler on the host, virtual bus, an SDO request every tick from a master endpoint.
int run_host_only(double seconds, long tick_us) {
  canopen::ObjectDictionary od;
  canopen::CommunicationProfile profile;
  profile.device_type = 0x191;
  canopen::add_communication_objects(od, profile);
  canopen::Node node("bench", std::move(od), {}, kNodeId);
  sim::Bus bus("virtual");
  struct Master : sim::FrameReceiver, sim::Steppable {
    sim::Bus* bus = nullptr;
    int ep = -1;
    std::uint64_t answers = 0;
    void on_frame(const sim::CanFrame& f, sim::Time) override { answers += f.id == 0x580u + kNodeId; }
    void step(sim::Time now, sim::Duration) override {
      bus->send(ep, sim::CanFrame::data_frame(0x600u + kNodeId, {0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0}), now);
    }
  } master;
  master.bus = &bus;
  master.ep = bus.attach(&master);
  node.attach(bus);
  sim::Scheduler scheduler(sim::microseconds(tick_us), sim::ClockMode::RealTime);
  scheduler.add_bus(&bus);
  scheduler.add(&node);
  scheduler.add(&master);
  std::vector<double> lateness;
  lateness.reserve(static_cast<std::size_t>(seconds * 1e6 / static_cast<double>(tick_us)) + 16);
  scheduler.set_lateness_observer([&](sim::Duration d) {
    if (lateness.size() < lateness.capacity()) lateness.push_back(static_cast<double>(d.count()));
  });
  node.power_on(scheduler.now());
  scheduler.run_for(sim::from_seconds(seconds));
  const Stats s = summarize(lateness);
  std::printf("Real-time tick lateness on the host (tick %ld us, %zu ticks, virtual bus, %llu SDO answers):\n", tick_us,
              lateness.size(), static_cast<unsigned long long>(master.answers));
  std::printf("  median %.0f us   p99 %.0f us   max %.0f us   overruns %llu\n", s.median, s.p99, s.max,
              static_cast<unsigned long long>(scheduler.stats().overruns));
  return 0;
}

std::int64_t monotonic_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<std::int64_t>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

std::string load_average() {
  double l[3] = {0, 0, 0};
  if (getloadavg(l, 3) != 3) return "unknown";
  char text[64];
  std::snprintf(text, sizeof text, "%.2f %.2f %.2f", l[0], l[1], l[2]);
  return text;
}

// A node producing heartbeats every `period_ms` in real time on a virtual bus, beside
// `competitors` CPU-bound processes (one busy loop each, normal priority). Every heartbeat's wall
// time is taken where the bus delivers it, as a master on the wire would see it; the error is
// each period's distance from period_ms.
int run_heartbeat(double seconds, long tick_us, int competitors, bool rt, unsigned period_ms) {
  std::vector<pid_t> busy;
  for (int i = 0; i < competitors; ++i) {
    const pid_t pid = fork();
    if (pid == 0) {
      volatile unsigned long spin = 0;
      for (;;) spin = spin + 1;
    }
    if (pid > 0) busy.push_back(pid);
  }
  const std::string load_before = load_average();

  canopen::ObjectDictionary od;
  canopen::CommunicationProfile profile;
  profile.device_type = 0x191;
  canopen::add_communication_objects(od, profile);
  auto* hb = od.entry(0x1017, 0);
  hb->value = hb->default_value = {static_cast<std::uint8_t>(period_ms), static_cast<std::uint8_t>(period_ms >> 8)};
  canopen::Node node("bench", std::move(od), {}, kNodeId);
  sim::Bus bus("virtual");
  struct Observer : sim::FrameReceiver {
    std::vector<std::int64_t> at_ns;
    void on_frame(const sim::CanFrame& f, sim::Time) override {
      if (f.id == 0x700u + kNodeId && f.dlc == 1 && f.data[0] != 0 && at_ns.size() < at_ns.capacity())
        at_ns.push_back(monotonic_ns());  // a heartbeat, not the boot-up
    }
  } observer;
  observer.at_ns.reserve(static_cast<std::size_t>(seconds * 1000.0 / period_ms) + 16);
  bus.attach(&observer);
  node.attach(bus);
  sim::Scheduler scheduler(sim::microseconds(tick_us), sim::ClockMode::RealTime);
  scheduler.add_bus(&bus);
  scheduler.add(&node);
  std::vector<double> lateness;
  lateness.reserve(static_cast<std::size_t>(seconds * 1e6 / static_cast<double>(tick_us)) + 16);
  scheduler.set_lateness_observer([&](sim::Duration d) {
    if (lateness.size() < lateness.capacity()) lateness.push_back(static_cast<double>(d.count()));
  });
  std::string setup = "normal scheduling (no --rt)";
  if (rt) setup = sim::enter_realtime().message;
  node.power_on(scheduler.now());
  scheduler.run_for(sim::from_seconds(seconds));

  for (pid_t pid : busy) kill(pid, SIGKILL);
  for (pid_t pid : busy) waitpid(pid, nullptr, 0);

  std::vector<double> error;
  for (std::size_t i = 1; i < observer.at_ns.size(); ++i) {
    const double period_us = static_cast<double>(observer.at_ns[i] - observer.at_ns[i - 1]) / 1000.0;
    error.push_back(std::abs(period_us - period_ms * 1000.0));
  }
  const Stats e = summarize(error), l = summarize(lateness);
  const auto& st = scheduler.stats();
  std::printf("Heartbeat under load: %.0f s, %d CPU-bound competitor(s), tick %ld us, heartbeat %u ms\n", seconds,
              competitors, tick_us, period_ms);
  for (std::size_t from = 0, to; from < setup.size(); from = to + 1) {
    to = setup.find('\n', from);
    if (to == std::string::npos) to = setup.size();
    std::printf("  %s\n", setup.substr(from, to - from).c_str());
  }
  std::printf("  load average before: %s   after: %s (1, 5, 15 min)\n", load_before.c_str(), load_average().c_str());
  std::printf("  heartbeat period error (%zu periods): p50 %.0f us   p99 %.0f us   max %.0f us\n", error.size(), e.median,
              e.p99, e.max);
  std::printf("  tick lateness (%zu ticks): p50 %.0f us   p99 %.0f us   max %.0f us   overruns %llu   re-anchored %llu "
              "(simulated time %.1f ms behind)\n",
              lateness.size(), l.median, l.p99, l.max, static_cast<unsigned long long>(st.overruns),
              static_cast<unsigned long long>(st.reanchors), static_cast<double>(st.slipped.count()) / 1000.0);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string iface = "vcan0";
  int requests = 2000;
  long tick_us = 1000;
  double host_only = 0, heartbeat = 0;
  int competitors = 2;
  bool rt = false;
  unsigned period_ms = 10;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--rt") rt = true;
  }
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--rt") {
      --i;  // a flag without a value
      continue;
    }
    if (a == "--heartbeat") heartbeat = std::atof(argv[i + 1]);
    if (a == "--competitors") competitors = std::atoi(argv[i + 1]);
    if (a == "--period-ms") period_ms = static_cast<unsigned>(std::atoi(argv[i + 1]));
    if (a == "--host-only") host_only = std::atof(argv[i + 1]);
    if (a == "--iface") iface = argv[i + 1];
    else if (a == "--requests") requests = std::atoi(argv[i + 1]);
    else if (a == "--tick-us") tick_us = std::atol(argv[i + 1]);
  }
  if (heartbeat > 0) {
    if (period_ms < 1 || period_ms > 65535 || competitors < 0 || competitors > 64) {
      std::fprintf(stderr, "rt_bench: --period-ms 1..65535, --competitors 0..64\n");
      return 2;
    }
    return run_heartbeat(heartbeat, tick_us, competitors, rt, period_ms);
  }
  if (host_only > 0) return run_host_only(host_only, tick_us);
  if (!sim::socketcan_available() || if_nametoindex(iface.c_str()) == 0) {
    std::fprintf(stderr, "rt_bench: CAN interface '%s' does not exist (run through tools/vcan/vcan-run)\n", iface.c_str());
    return 2;
  }
  int pipe_fd[2];
  if (pipe(pipe_fd) != 0) return 1;
  const pid_t child = fork();
  if (child == 0) {
    close(pipe_fd[0]);
    _exit(run_node(iface, tick_us, pipe_fd[1]));
  }
  close(pipe_fd[1]);

  const int fd = open_raw(iface);
  if (fd < 0) {
    std::perror("rt_bench: socket");
    kill(child, SIGTERM);
    return 1;
  }
  usleep(300000);  // node boot
  std::vector<double> rtt;
  rtt.reserve(static_cast<std::size_t>(requests));
  int lost = 0;
  for (int i = 0; i < requests; ++i) {
    can_frame req{};
    req.can_id = 0x600u + kNodeId;
    req.can_dlc = 8;
    const std::uint8_t bytes[8] = {0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0};
    std::memcpy(req.data, bytes, 8);
    const double t0 = now_us();
    if (write(fd, &req, sizeof req) != sizeof req) {
      ++lost;
      continue;
    }
    pollfd p{fd, POLLIN, 0};
    bool got = false;
    while (!got && poll(&p, 1, 100) > 0) {
      can_frame resp{};
      if (read(fd, &resp, sizeof resp) == sizeof resp && resp.data[0] == 0x43) got = true;
    }
    if (got) rtt.push_back(now_us() - t0);
    else ++lost;
    usleep(200);
  }
  kill(child, SIGTERM);
  char buf[256] = {};
  const ssize_t n = read(pipe_fd[0], buf, sizeof buf - 1);
  int status = 0;
  waitpid(child, &status, 0);
  const Stats s = summarize(rtt);
  std::printf("SDO expedited upload round trip over %s (%zu requests, %d lost):\n", iface.c_str(), rtt.size(), lost);
  std::printf("  median %.1f us   p99 %.1f us   max %.1f us\n", s.median, s.p99, s.max);
  unsigned long ticks = 0, overruns = 0;
  double med = 0, p99 = 0, mx = 0;
  if (n > 0 && std::sscanf(buf, "%lu %lf %lf %lf %lu", &ticks, &med, &p99, &mx, &overruns) == 5) {
    std::printf("Real-time tick lateness (tick %ld us, %lu ticks, node serving the requests):\n", tick_us, ticks);
    std::printf("  median %.0f us   p99 %.0f us   max %.0f us   overruns %lu\n", med, p99, mx, overruns);
  } else {
    std::printf("Real-time tick lateness: node process reported nothing\n");
    return 1;
  }
  return lost > requests / 100 ? 1 : 0;
}
