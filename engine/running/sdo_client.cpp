#include "engine/running/sdo_client.h"

#include <algorithm>
#include <cstdio>

namespace scenario {

namespace {
constexpr std::uint32_t kAbortToggle = 0x05030000;
constexpr std::uint32_t kAbortTimeout = 0x05040000;
constexpr std::uint32_t kAbortCommand = 0x05040001;
constexpr std::uint32_t kAbortGeneral = 0x08000000;
}  // namespace

void SdoClient::send(std::initializer_list<std::uint8_t> head, const std::uint8_t* tail, std::size_t tail_len) {
  sim::CanFrame f;
  f.id = 0x600u + node_id_;
  f.dlc = 8;
  std::size_t i = 0;
  for (auto b : head) f.data[i++] = b;
  for (std::size_t k = 0; k < tail_len && i < 8; ++k) f.data[i++] = tail[k];
  send_(f);
}

void SdoClient::begin(std::uint8_t node_id, std::uint16_t index, std::uint8_t sub, bool upload, sim::Time now,
                      sim::Duration timeout) {
  node_id_ = node_id;
  index_ = index;
  sub_ = sub;
  upload_ = upload;
  toggle_ = false;
  abort_code_ = 0;
  error_.clear();
  timeout_ = timeout;
  deadline_ = now + timeout;
  state_ = State::Busy;
}

void SdoClient::start_upload(std::uint8_t node_id, std::uint16_t index, std::uint8_t sub, sim::Time now,
                             sim::Duration timeout) {
  begin(node_id, index, sub, true, now, timeout);
  segmented_ = false;
  expected_size_ = 0;
  data_.clear();
  send({0x40, static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8), sub, 0, 0, 0, 0});
}

void SdoClient::start_download(std::uint8_t node_id, std::uint16_t index, std::uint8_t sub,
                               const std::vector<std::uint8_t>& data, sim::Time now, sim::Duration timeout) {
  begin(node_id, index, sub, false, now, timeout);
  offset_ = 0;
  data_ = data;
  const auto lo = static_cast<std::uint8_t>(index), hi = static_cast<std::uint8_t>(index >> 8);
  if (!data.empty() && data.size() <= 4) {
    segmented_ = false;
    const auto n = static_cast<std::uint8_t>(4 - data.size());
    send({static_cast<std::uint8_t>(0x23 | n << 2), lo, hi, sub}, data.data(), data.size());
  } else {
    segmented_ = true;
    const auto size = static_cast<std::uint32_t>(data.size());
    send({0x21, lo, hi, sub, static_cast<std::uint8_t>(size), static_cast<std::uint8_t>(size >> 8),
          static_cast<std::uint8_t>(size >> 16), static_cast<std::uint8_t>(size >> 24)});
  }
}

void SdoClient::fail(std::uint32_t code, const std::string& why) {
  state_ = State::Failed;
  abort_code_ = code;
  error_ = why;
  const std::uint8_t c[4] = {static_cast<std::uint8_t>(code), static_cast<std::uint8_t>(code >> 8),
                             static_cast<std::uint8_t>(code >> 16), static_cast<std::uint8_t>(code >> 24)};
  send({0x80, static_cast<std::uint8_t>(index_), static_cast<std::uint8_t>(index_ >> 8), sub_}, c, 4);
}

void SdoClient::poll(sim::Time now) {
  if (state_ == State::Busy && now >= deadline_) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "no SDO response from node %u within %.3f s", node_id_, sim::seconds(timeout_));
    fail(kAbortTimeout, buf);
  }
}

void SdoClient::next_download_segment() {
  const std::size_t n = std::min<std::size_t>(7, data_.size() - offset_);
  const bool last = offset_ + n == data_.size();
  const auto cmd = static_cast<std::uint8_t>((toggle_ ? 0x10 : 0) | (7 - n) << 1 | (last ? 1 : 0));
  send({cmd}, data_.data() + offset_, n);
  offset_ += n;
}

void SdoClient::on_frame(const sim::CanFrame& f, sim::Time now) {
  if (state_ != State::Busy || f.rtr || f.extended || f.id != 0x580u + node_id_) return;
  if (f.dlc < 8) return;  // CiA 301: SDO frames are 8 bytes; a short one is not ours to parse
  deadline_ = now + timeout_;
  const std::uint8_t cmd = f.data[0];
  const std::uint8_t scs = cmd >> 5;
  const auto matches_mux = [&] {
    return f.data[1] == static_cast<std::uint8_t>(index_) && f.data[2] == static_cast<std::uint8_t>(index_ >> 8) &&
           f.data[3] == sub_;
  };
  if (scs == 4) {  // abort transfer
    state_ = State::Aborted;
    abort_code_ = static_cast<std::uint32_t>(f.data[4]) | static_cast<std::uint32_t>(f.data[5]) << 8 |
                  static_cast<std::uint32_t>(f.data[6]) << 16 | static_cast<std::uint32_t>(f.data[7]) << 24;
    return;
  }
  if (upload_) {
    if (!segmented_) {
      if (scs != 2) return fail(kAbortCommand, "unexpected SDO response " + std::to_string(cmd) + " to an upload");
      if (!matches_mux()) return fail(kAbortGeneral, "SDO upload response for another object");
      const bool expedited = cmd & 0x02, size_given = cmd & 0x01;
      if (expedited) {
        const std::size_t n = size_given ? 4 - ((cmd >> 2) & 3) : 4;
        data_.assign(f.data.begin() + 4, f.data.begin() + 4 + static_cast<long>(n));
        state_ = State::Done;
        return;
      }
      segmented_ = true;
      expected_size_ = size_given ? (f.data[4] | f.data[5] << 8 | f.data[6] << 16 | static_cast<std::size_t>(f.data[7]) << 24) : 0;
      toggle_ = false;
      send({0x60, 0, 0, 0, 0, 0, 0, 0});
      return;
    }
    if (scs != 0) return fail(kAbortCommand, "unexpected SDO response during a segmented upload");
    if (((cmd >> 4) & 1) != (toggle_ ? 1 : 0)) return fail(kAbortToggle, "SDO upload segment with a wrong toggle bit");
    const std::size_t n = 7 - ((cmd >> 1) & 7);
    data_.insert(data_.end(), f.data.begin() + 1, f.data.begin() + 1 + static_cast<long>(n));
    if (cmd & 1) {
      if (expected_size_ && data_.size() != expected_size_)
        return fail(kAbortGeneral, "segmented upload delivered " + std::to_string(data_.size()) + " bytes, announced " +
                                       std::to_string(expected_size_));
      state_ = State::Done;
      return;
    }
    toggle_ = !toggle_;
    send({static_cast<std::uint8_t>(0x60 | (toggle_ ? 0x10 : 0)), 0, 0, 0, 0, 0, 0, 0});
    return;
  }
  // download
  if (offset_ == 0 && (!segmented_ || scs == 3)) {
    if (scs != 3) return fail(kAbortCommand, "unexpected SDO response " + std::to_string(cmd) + " to a download");
    if (!matches_mux()) return fail(kAbortGeneral, "SDO download response for another object");
    if (!segmented_) {
      state_ = State::Done;
      return;
    }
    next_download_segment();
    return;
  }
  if (scs != 1) return fail(kAbortCommand, "unexpected SDO response during a segmented download");
  if (((cmd >> 4) & 1) != (toggle_ ? 1 : 0)) return fail(kAbortToggle, "SDO download segment response with a wrong toggle bit");
  if (offset_ >= data_.size()) {
    state_ = State::Done;
    return;
  }
  toggle_ = !toggle_;
  next_download_segment();
}

}  // namespace scenario
