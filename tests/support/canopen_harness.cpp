#include "tests/support/canopen_harness.h"

#include <iomanip>

namespace vtest {

Frame Frame::from(const sim::CanFrame& f) {
  if (f.rtr) return remote(f.id, f.dlc);
  Frame out;
  out.id = f.id;
  out.data.assign(f.data.begin(), f.data.begin() + f.dlc);
  return out;
}

sim::CanFrame Frame::to_can() const {
  if (rtr) return sim::CanFrame::remote_frame(id, rtr_dlc);
  return sim::CanFrame::data_frame(id, data);
}

std::ostream& operator<<(std::ostream& os, const Frame& f) { return os << sim::to_candump(f.to_can()); }

CanopenHarness::CanopenHarness(canopen::ObjectDictionary od, canopen::NodePolicy policy, std::uint8_t node_id,
                               canopen::Application* app) {
  owned_.emplace("node", std::move(od), std::move(policy), node_id);
  node_ = &*owned_;
  node_->set_application(app);
  wire();
}

CanopenHarness::CanopenHarness(canopen::Node& external_node) : node_(&external_node) { wire(); }

void CanopenHarness::wire() {
  master_ep_ = bus_.attach(&master_);
  node_->attach(bus_);
  scheduler_.add_bus(&bus_);
  scheduler_.add(node_);
}

void CanopenHarness::power_on() {
  node_->power_on(scheduler_.now());
  scheduler_.run_ticks(1);
}

void CanopenHarness::send(const Frame& f) {
  bus_.send(master_ep_, f.to_can(), scheduler_.now());
  scheduler_.deliver_all();
}

Frames CanopenHarness::take() {
  scheduler_.deliver_all();  // frames a test triggered directly (e.g. emergency().raise())
  Frames out;
  out.swap(master_.frames);
  master_.times.clear();
  return out;
}

std::vector<sim::Time> CanopenHarness::take_times() {
  scheduler_.deliver_all();
  std::vector<sim::Time> t;
  t.swap(master_.times);
  master_.frames.clear();
  return t;
}

CanopenHarness::FirstFrames CanopenHarness::run_until_frames(sim::Time since, sim::Duration limit) {
  FirstFrames out;
  while (out.frames.empty() && now() - since < limit) {
    out.at = now() - since;
    run_ms(1);
    out.frames = take();
  }
  return out;
}

std::optional<Frame> CanopenHarness::sdo(std::initializer_list<std::uint8_t> request) {
  take();
  std::vector<std::uint8_t> req(request);
  req.resize(8, 0);
  send(Frame(0x600u + id(), req));
  auto got = take();
  if (got.size() != 1 || got[0].id != 0x580u + id()) return std::nullopt;
  return got[0];
}

std::optional<std::vector<std::uint8_t>> CanopenHarness::read(std::uint16_t index, std::uint8_t sub, std::uint32_t* abort) {
  auto r = sdo({0x40, static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8), sub});
  if (!r || r->data.size() != 8) return std::nullopt;
  const auto& d = r->data;
  if (d[0] == 0x80) {
    if (abort) *abort = static_cast<std::uint32_t>(d[4] | d[5] << 8 | d[6] << 16 | d[7] << 24);
    return std::nullopt;
  }
  if ((d[0] & 0xE3) != 0x43) return std::nullopt;  // expedited with size only
  const std::size_t n = 4 - ((d[0] >> 2) & 3);
  return std::vector<std::uint8_t>(d.begin() + 4, d.begin() + 4 + static_cast<std::ptrdiff_t>(n));
}

std::optional<std::uint64_t> CanopenHarness::read_u(std::uint16_t index, std::uint8_t sub, std::uint32_t* abort) {
  auto v = upload(index, sub, abort);
  if (!v) return std::nullopt;
  std::uint64_t u = 0;
  for (std::size_t i = 0; i < v->size() && i < 8; ++i) u |= static_cast<std::uint64_t>((*v)[i]) << (8 * i);
  return u;
}

std::uint32_t CanopenHarness::write(std::uint16_t index, std::uint8_t sub, std::uint32_t value, std::uint8_t size) {
  const auto cmd = static_cast<std::uint8_t>(0x23 | ((4 - size) << 2));
  auto r = sdo({cmd, static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8), sub,
                static_cast<std::uint8_t>(value), static_cast<std::uint8_t>(size > 1 ? value >> 8 : 0),
                static_cast<std::uint8_t>(size > 2 ? value >> 16 : 0), static_cast<std::uint8_t>(size > 3 ? value >> 24 : 0)});
  if (!r) return 0xFFFFFFFFu;
  const auto& d = r->data;
  if (d[0] == 0x60) return 0;
  if (d[0] == 0x80) return static_cast<std::uint32_t>(d[4] | d[5] << 8 | d[6] << 16 | d[7] << 24);
  return 0xFFFFFFFEu;
}

std::optional<std::vector<std::uint8_t>> CanopenHarness::upload(std::uint16_t index, std::uint8_t sub, std::uint32_t* abort) {
  auto r = sdo({0x40, static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8), sub});
  if (!r) return std::nullopt;
  auto code = [&](const Frame& f) { return static_cast<std::uint32_t>(f.data[4] | f.data[5] << 8 | f.data[6] << 16 | f.data[7] << 24); };
  if (r->data[0] == 0x80) {
    if (abort) *abort = code(*r);
    return std::nullopt;
  }
  if ((r->data[0] & 0xE2) == 0x42) {  // expedited
    const std::size_t n = (r->data[0] & 1) ? 4 - ((r->data[0] >> 2) & 3) : 4;
    return std::vector<std::uint8_t>(r->data.begin() + 4, r->data.begin() + 4 + static_cast<std::ptrdiff_t>(n));
  }
  if (r->data[0] != 0x41) return std::nullopt;
  std::vector<std::uint8_t> out;
  bool toggle = false;
  for (int guard = 0; guard < 100000; ++guard) {
    auto s = sdo({static_cast<std::uint8_t>(0x60 | (toggle ? 0x10 : 0))});
    if (!s) return std::nullopt;
    if (s->data[0] == 0x80) {
      if (abort) *abort = code(*s);
      return std::nullopt;
    }
    const std::size_t n = 7 - ((s->data[0] >> 1) & 7);
    out.insert(out.end(), s->data.begin() + 1, s->data.begin() + 1 + static_cast<std::ptrdiff_t>(n));
    if (s->data[0] & 1) return out;
    toggle = !toggle;
  }
  return std::nullopt;
}

std::uint32_t CanopenHarness::download(std::uint16_t index, std::uint8_t sub, const std::vector<std::uint8_t>& data) {
  const auto size = static_cast<std::uint32_t>(data.size());
  auto r = sdo({0x21, static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8), sub,
                static_cast<std::uint8_t>(size), static_cast<std::uint8_t>(size >> 8), static_cast<std::uint8_t>(size >> 16),
                static_cast<std::uint8_t>(size >> 24)});
  auto code = [&](const Frame& f) { return static_cast<std::uint32_t>(f.data[4] | f.data[5] << 8 | f.data[6] << 16 | f.data[7] << 24); };
  if (!r) return 0xFFFFFFFFu;
  if (r->data[0] == 0x80) return code(*r);
  bool toggle = false;
  std::size_t pos = 0;
  do {
    const std::size_t n = std::min<std::size_t>(7, data.size() - pos);
    const bool last = pos + n >= data.size();
    std::vector<std::uint8_t> seg(8, 0);
    seg[0] = static_cast<std::uint8_t>((toggle ? 0x10 : 0) | ((7 - n) << 1) | (last ? 1 : 0));
    std::copy_n(data.begin() + static_cast<std::ptrdiff_t>(pos), n, seg.begin() + 1);
    take();
    send(Frame(0x600u + id(), seg));
    auto got = take();
    if (got.size() != 1) return 0xFFFFFFFFu;
    if (got[0].data[0] == 0x80) return code(got[0]);
    pos += n;
    toggle = !toggle;
    if (last) return 0;
  } while (true);
}

}  // namespace vtest
