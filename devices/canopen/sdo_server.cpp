#include "devices/canopen/sdo_server.h"

#include <algorithm>


namespace canopen {

namespace {
constexpr std::uint16_t kSdoServerParameter = 0x1200;
constexpr std::size_t kBufferReserve = 1024;

std::uint16_t index_of(const std::uint8_t* req) { return static_cast<std::uint16_t>(req[1] | req[2] << 8); }

/// Widens or truncates a numeric value in the transfer buffer (its capacity is reserved: no
/// allocation per request).
void resize_in_place(DataType type, Bytes& data, std::size_t size) {
  std::array<std::uint8_t, 8> tmp{};
  if (size > tmp.size()) {
    data = resize_value(type, data, size);
    return;
  }
  resize_value_into(type, data, std::span<std::uint8_t>(tmp.data(), size));
  data.assign(tmp.begin(), tmp.begin() + static_cast<std::ptrdiff_t>(size));
}
}  // namespace

SdoServer::SdoServer(ObjectDictionary& od, const SdoPolicy& policy, const NodeStatus& status, FrameSender& sender)
    : od_(od), policy_(policy), status_(status), sender_(sender) {
  buffer_.reserve(kBufferReserve);
}

std::uint32_t SdoServer::rx_cob_id() const {
  if (const auto* e = od_.entry(kSdoServerParameter, 1)) return e->as<std::uint32_t>();
  return 0x600u + status_.node_id;
}

std::uint32_t SdoServer::tx_cob_id() const {
  if (const auto* e = od_.entry(kSdoServerParameter, 2)) return e->as<std::uint32_t>();
  return 0x580u + status_.node_id;
}

void SdoServer::reset() {
  state_ = State::Idle;
  entry_ = nullptr;
  buffer_.clear();
  deferred_.reset();
}

void SdoServer::respond(const std::array<std::uint8_t, 8>& bytes) {
  const std::uint32_t cob = tx_cob_id();
  if (cob & 0x80000000u) return;
  sim::CanFrame f;
  f.extended = (cob & 0x20000000u) != 0;
  f.id = cob & (f.extended ? 0x1FFFFFFFu : 0x7FFu);
  f.dlc = 8;
  f.data = bytes;
  if (status_.silent()) {
    deferred_ = f;  // e.g. "store parameters" answers only when the save is finished
    return;
  }
  sender_.send(f);
}

void SdoServer::abort(std::uint16_t index, std::uint8_t sub, SdoAbort code) {
  const std::uint32_t c = static_cast<std::uint32_t>(code);
  respond({0x80, static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8), sub,
           static_cast<std::uint8_t>(c), static_cast<std::uint8_t>(c >> 8), static_cast<std::uint8_t>(c >> 16),
           static_cast<std::uint8_t>(c >> 24)});
  state_ = State::Idle;
  entry_ = nullptr;
}

void SdoServer::on_request(const sim::CanFrame& frame, sim::Time now) {
  if (frame.rtr) return;
  std::array<std::uint8_t, 8> req{};
  if (frame.dlc < 8) {
    if (!policy_.pad_short_requests || frame.dlc == 0) return;
  }
  std::copy_n(frame.data.begin(), frame.dlc, req.begin());
  last_activity_ = now;
  const std::uint8_t ccs = req[0] >> 5;
  switch (ccs) {
    case 1: initiate_download(req.data()); break;
    case 0: download_segment(req.data()); break;
    case 2: initiate_upload(req.data()); break;
    case 3: upload_segment(req.data()); break;
    case 4:  // abort from the client: drop the transfer silently
      state_ = State::Idle;
      entry_ = nullptr;
      break;
    default:  // block transfer (5, 6) is not supported; 7 is invalid
      state_ = State::Idle;
      abort(index_of(req.data()), req[3], policy_.unknown_command);
      break;
  }
}

SdoAbort SdoServer::fit_size(const OdEntry& e, Bytes& data, bool size_indicated) const {
  const std::size_t fixed = type_size(e.type);
  if (fixed == 0) {
    if (e.max_length != 0 && data.size() > e.max_length) return SdoAbort::LengthTooHigh;
    return SdoAbort::None;
  }
  if (data.size() == fixed) return SdoAbort::None;
  if (!size_indicated) {
    resize_in_place(e.type, data, fixed);
    return SdoAbort::None;
  }
  using Mode = SdoPolicy::SizeMode;
  const Mode mode = policy_.size_mode;
  const SdoAbort mismatch = policy_.length_mismatch;
  if (data.size() < fixed) {
    if (mode == Mode::Strict) return mismatch != SdoAbort::None ? mismatch : SdoAbort::LengthTooLow;
    resize_in_place(e.type, data, fixed);
    return SdoAbort::None;
  }
  // Longer than the object.
  if (mode == Mode::Strict) return mismatch != SdoAbort::None ? mismatch : SdoAbort::LengthTooHigh;
  if (mode == Mode::ExcessMustBeZero) {
    const bool negative = is_signed_integer(e.type) && (data[fixed - 1] & 0x80);
    const std::uint8_t fill = negative ? 0xFF : 0x00;
    if (!std::all_of(data.begin() + static_cast<std::ptrdiff_t>(fixed), data.end(),
                     [fill](std::uint8_t b) { return b == fill; })) {
      return SdoAbort::LengthTooHigh;
    }
  }
  data.resize(fixed);
  return SdoAbort::None;
}

void SdoServer::initiate_download(const std::uint8_t* req) {
  state_ = State::Idle;  // a new initiate abandons an unfinished transfer
  const std::uint16_t index = index_of(req);
  const std::uint8_t sub = req[3];
  OdEntry* e = nullptr;
  if (!od_.visible(index)) return abort(index, sub, SdoAbort::NoObject);
  if (auto a = od_.locate(index, sub, e); a != SdoAbort::None) return abort(index, sub, a);
  if (const auto code = od_.object(index)->code; code == ObjectCode::DefType || code == ObjectCode::DefStruct) {
    return abort(index, sub, policy_.type_definition_write);
  }
  if (!e->writable()) return abort(index, sub, od_.access_aborts().write_read_only);

  const bool expedited = req[0] & 0x02;
  const bool size_indicated = req[0] & 0x01;
  if (expedited) {
    const std::size_t n = size_indicated ? 4u - ((req[0] >> 2) & 0x03) : 4u;
    buffer_.assign(req + 4, req + 4 + n);
    if (!size_indicated && type_size(e->type) != 0 && type_size(e->type) < 4) buffer_.resize(type_size(e->type));
    if (auto a = fit_size(*e, buffer_, size_indicated); a != SdoAbort::None) return abort(index, sub, a);
    if (auto a = od_.write(*e, buffer_, Origin::Sdo); a != SdoAbort::None) return abort(index, sub, a);
    return respond({0x60, req[1], req[2], sub, 0, 0, 0, 0});
  }

  if (!policy_.segmented_download) return abort(index, sub, policy_.unknown_command);
  size_indicated_ = size_indicated;
  expected_size_ = size_indicated ? static_cast<std::size_t>(decode_unsigned({req + 4, 4})) : 0;
  const std::size_t fixed = type_size(e->type);
  if (size_indicated && fixed != 0 && expected_size_ != fixed &&
      policy_.size_mode == SdoPolicy::SizeMode::Strict) {
    const SdoAbort mismatch = policy_.length_mismatch;
    if (mismatch != SdoAbort::None) return abort(index, sub, mismatch);
    return abort(index, sub, expected_size_ > fixed ? SdoAbort::LengthTooHigh : SdoAbort::LengthTooLow);
  }
  if (size_indicated && fixed != 0 && expected_size_ != fixed && policy_.segmented_exact_size) {
    return abort(index, sub, policy_.segmented_size_mismatch);
  }
  if (size_indicated && fixed == 0 && e->max_length != 0 && expected_size_ > e->max_length) {
    return abort(index, sub, SdoAbort::LengthTooHigh);
  }
  state_ = State::Download;
  index_ = index;
  sub_ = sub;
  entry_ = e;
  toggle_ = false;
  buffer_.clear();
  respond({0x60, req[1], req[2], sub, 0, 0, 0, 0});
}

void SdoServer::download_segment(const std::uint8_t* req) {
  if (state_ != State::Download) return abort(0, 0, policy_.unknown_command);
  const bool toggle = req[0] & 0x10;
  if (toggle != toggle_) return abort(index_, sub_, SdoAbort::ToggleBit);
  const std::size_t n = 7u - ((req[0] >> 1) & 0x07);
  const bool last = req[0] & 0x01;
  constexpr std::size_t kMaxTransfer = 1u << 20;
  if (buffer_.size() + n > kMaxTransfer) return abort(index_, sub_, SdoAbort::OutOfMemory);
  buffer_.insert(buffer_.end(), req + 1, req + 1 + n);
  const std::uint8_t response = static_cast<std::uint8_t>(0x20 | (toggle_ ? 0x10 : 0x00));
  toggle_ = !toggle_;
  if (!last) return respond({response, 0, 0, 0, 0, 0, 0, 0});

  state_ = State::Idle;
  if (size_indicated_ && buffer_.size() != expected_size_) {
    return abort(index_, sub_, policy_.segmented_size_mismatch);
  }
  const std::size_t fixed = type_size(entry_->type);
  if (fixed != 0 && buffer_.size() != fixed &&
      (policy_.size_mode == SdoPolicy::SizeMode::Strict || policy_.segmented_exact_size)) {
    return abort(index_, sub_, policy_.segmented_size_mismatch);
  }
  if (auto a = fit_size(*entry_, buffer_, true); a != SdoAbort::None) return abort(index_, sub_, a);
  if (auto a = od_.write(*entry_, buffer_, Origin::Sdo); a != SdoAbort::None) return abort(index_, sub_, a);
  entry_ = nullptr;
  respond({response, 0, 0, 0, 0, 0, 0, 0});
}

void SdoServer::initiate_upload(const std::uint8_t* req) {
  state_ = State::Idle;
  const std::uint16_t index = index_of(req);
  const std::uint8_t sub = req[3];
  OdEntry* e = nullptr;
  if (!od_.visible(index)) return abort(index, sub, SdoAbort::NoObject);
  if (auto a = od_.locate(index, sub, e); a != SdoAbort::None) return abort(index, sub, a);
  if (auto a = od_.read(*e, Origin::Sdo); a != SdoAbort::None) return abort(index, sub, a);
  const std::size_t size = e->value.size();
  if (size >= 1 && size <= 4 && !e->force_segmented) {
    std::array<std::uint8_t, 8> r{static_cast<std::uint8_t>(0x43 | ((4 - size) << 2)), req[1], req[2], sub, 0, 0, 0, 0};
    std::copy(e->value.begin(), e->value.end(), r.begin() + 4);
    return respond(r);
  }
  buffer_.assign(e->value.begin(), e->value.end());  // snapshot: the value may change while the client reads segments
  state_ = State::Upload;
  index_ = index;
  sub_ = sub;
  offset_ = 0;
  toggle_ = false;
  respond({0x41, req[1], req[2], sub, static_cast<std::uint8_t>(size), static_cast<std::uint8_t>(size >> 8),
           static_cast<std::uint8_t>(size >> 16), static_cast<std::uint8_t>(size >> 24)});
}

void SdoServer::upload_segment(const std::uint8_t* req) {
  if (state_ != State::Upload) return abort(0, 0, policy_.unknown_command);
  const bool toggle = req[0] & 0x10;
  if (toggle != toggle_) return abort(index_, sub_, SdoAbort::ToggleBit);
  const std::size_t n = std::min<std::size_t>(7, buffer_.size() - offset_);
  const bool last = offset_ + n >= buffer_.size();
  std::array<std::uint8_t, 8> r{};
  r[0] = static_cast<std::uint8_t>((toggle_ ? 0x10 : 0x00) | ((7 - n) << 1) | (last ? 0x01 : 0x00));
  std::copy_n(buffer_.begin() + static_cast<std::ptrdiff_t>(offset_), n, r.begin() + 1);
  offset_ += n;
  toggle_ = !toggle_;
  if (last) state_ = State::Idle;
  respond(r);
}

void SdoServer::process(sim::Time now) {
  if (deferred_ && !status_.silent()) {
    sender_.send(*deferred_);
    deferred_.reset();
  }
  const auto timeout = policy_.timeout;
  if (state_ != State::Idle && timeout.count() > 0 && now - last_activity_ >= timeout) {
    abort(index_, sub_, SdoAbort::Timeout);
  }
}

}  // namespace canopen
