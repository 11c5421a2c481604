// A scenario running on its own thread with the control plane on an ephemeral loopback port, in
// virtual time (started paused, as fast as possible when resumed), and an HTTP client for it.
#pragma once

#include <gtest/gtest.h>
#include <httplib.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "control/control_plane.h"
#include "engine/running/environment.h"
#include "engine/runner.h"
#include "engine/loading/scenario_loader.h"

namespace vtest {

class LivePlant {
 public:
  /// `scenario`: loaded by the caller; its script and duration are dropped (the test drives).
  /// `exercises_dir`: the control plane's exercise files (docs/exercises.md), "" = none.
  LivePlant(scenario::Scenario scenario, const scenario::Environment& env, std::size_t max_streams = 4,
            std::string exercises_dir = "")
      : scenario_(std::move(scenario)), env_(env) {
    scenario_.script.clear();
    scenario_.clock.duration.reset();
    control::UiOptions u;
    u.address = "127.0.0.1";
    u.port = 0;
    u.clock.start_paused = true;
    u.clock.speed = 0;
    u.max_streams = max_streams;
    u.out = nullptr;
    u.exercises_dir = std::move(exercises_dir);
    plane_ = std::make_unique<control::ControlPlane>(u);
    const auto err = plane_->bind();
    EXPECT_EQ(err, "");
    out_ = std::tmpfile();
    thread_ = std::thread([this] {
      scenario::RunOptions o;
      o.quiet = true;
      o.out = out_;
      o.extension = plane_.get();
      scenario::Runner runner(scenario_, env_, o);
      runner_ = &runner;
      rc_ = runner.run();
      runner_ = nullptr;
    });
    for (int i = 0; i < 500 && !plane_->bridge().attached(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    client_ = std::make_unique<httplib::Client>("127.0.0.1", plane_->port());
    client_->set_read_timeout(10, 0);
  }
  ~LivePlant() {
    stop();
    plane_.reset();
    std::fclose(out_);
  }
  /// Stops the run as SIGINT does (Runner::request_stop) and waits for it; returns how long the
  /// run took to end, outputs written.
  std::chrono::milliseconds stop() {
    if (!thread_.joinable()) return {};
    for (int i = 0; i < 500 && !runner_; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const auto t0 = std::chrono::steady_clock::now();
    if (auto* r = runner_.load()) r->request_stop();
    thread_.join();
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - t0);
  }
  int exit_code() const { return rc_; }

  httplib::Client& http() { return *client_; }
  int port() const { return plane_->port(); }
  control::ControlPlane& plane() { return *plane_; }

  /// Body as JSON (fails the test when it is not JSON).
  static nlohmann::json json_of(const httplib::Result& r) {
    EXPECT_TRUE(r) << "no response";
    if (!r) return {};
    auto j = nlohmann::json::parse(r->body, nullptr, false);
    EXPECT_FALSE(j.is_discarded()) << r->body;
    return j;
  }
  httplib::Result post(const std::string& path, const nlohmann::json& body) {
    return client_->Post(path.c_str(), body.dump(), "application/json");
  }
  /// Runs `ms` of simulated time and waits until the clock stands again.
  void run_ms(int ms) {
    const auto before = json_of(client_->Get("/api/clock"))["t_us"].get<std::int64_t>();
    ASSERT_EQ(post("/api/clock", {{"action", "run"}, {"ms", ms}})->status, 200);
    for (int i = 0; i < 3000; ++i) {
      const auto c = json_of(client_->Get("/api/clock"));
      if (c["paused"].get<bool>() && c["t_us"].get<std::int64_t>() >= before + ms * 1000) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    FAIL() << "the clock did not run " << ms << " ms";
  }

 private:
  scenario::Scenario scenario_;
  scenario::Environment env_;  ///< a copy: callers pass default_environment()'s temporary
  std::unique_ptr<control::ControlPlane> plane_;
  std::thread thread_;
  std::atomic<scenario::Runner*> runner_{nullptr};
  std::atomic<int> rc_{-1};
  std::FILE* out_ = nullptr;
  std::unique_ptr<httplib::Client> client_;
};

/// The text of a plant's live stream (GET /api/events + query) as it arrives, read on a thread of
/// its own until stop() or destruction.
class StreamCapture {
 public:
  StreamCapture(int port, const std::string& query) : client_("127.0.0.1", port) {
    client_.set_read_timeout(5, 0);
    reader_ = std::thread([this, query] {
      client_.Get(("/api/events" + query).c_str(), [this](const char* data, std::size_t n) {
        std::lock_guard lk(mu_);
        text_.append(data, n);
        return !stop_.load();
      });
    });
  }
  ~StreamCapture() { stop(); }
  StreamCapture(const StreamCapture&) = delete;
  StreamCapture& operator=(const StreamCapture&) = delete;

  std::string text() {
    std::lock_guard lk(mu_);
    return text_;
  }
  /// Waits up to 3 s (wall time: the hub sends on its own clock) until the text holds `what`.
  bool wait_for(const std::string& what) {
    for (int i = 0; i < 150 && text().find(what) == std::string::npos; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return text().find(what) != std::string::npos;
  }
  void stop() {
    stop_ = true;
    if (reader_.joinable()) reader_.join();
  }

 private:
  httplib::Client client_;
  std::mutex mu_;
  std::string text_;
  std::atomic<bool> stop_{false};
  std::thread reader_;
};

/// The data of every `name` event in a stream's text, in order (an event not whole yet is left out).
inline std::vector<nlohmann::json> events_of(const std::string& stream, const std::string& name) {
  std::vector<nlohmann::json> out;
  const std::string head = "event: " + name + "\ndata: ";
  for (auto at = stream.find(head); at != std::string::npos; at = stream.find(head, at + 1)) {
    const auto from = at + head.size();
    const auto end = stream.find('\n', from);
    if (end == std::string::npos) break;
    out.push_back(nlohmann::json::parse(stream.substr(from, end - from)));
  }
  return out;
}

}  // namespace vtest
