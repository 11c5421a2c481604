// The value an object-dictionary entry holds. A scalar (every integer width up to 64 bit,
// REAL32/REAL64, BOOLEAN) lives inline in one 8-byte aligned cell; only a longer value (a domain,
// a visible string over 8 characters) takes a heap byte vector. The cell holds the value in its
// CiA encoding (little-endian, which is the native layout of the hosts we build for), so the SDO
// and PDO paths see the same bytes as always through data()/size(), and canopen::EntryRef<T>
// (entry_ref.h) reads and writes the typed value with one load or store.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <span>
#include <vector>

namespace canopen {

using Bytes = std::vector<std::uint8_t>;

class StoredValue {
 public:
  static constexpr std::size_t kInline = 8;  // the widest scalar (INTEGER64, REAL64)

  StoredValue() = default;
  StoredValue(const Bytes& bytes) { assign(bytes.begin(), bytes.end()); }  // NOLINT: as a Bytes was
  StoredValue(std::span<const std::uint8_t> bytes) { assign(bytes.begin(), bytes.end()); }  // NOLINT
  StoredValue& operator=(std::span<const std::uint8_t> bytes) {
    assign(bytes.begin(), bytes.end());
    return *this;
  }
  StoredValue& operator=(const Bytes& bytes) { return *this = std::span<const std::uint8_t>(bytes); }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  bool is_inline() const { return size_ <= kInline; }
  std::uint8_t* data() { return is_inline() ? cell_.data() : heap_.data(); }
  const std::uint8_t* data() const { return is_inline() ? cell_.data() : heap_.data(); }
  std::uint8_t* begin() { return data(); }
  std::uint8_t* end() { return data() + size_; }
  const std::uint8_t* begin() const { return data(); }
  const std::uint8_t* end() const { return data() + size_; }
  std::uint8_t& operator[](std::size_t i) { return data()[i]; }
  std::uint8_t operator[](std::size_t i) const { return data()[i]; }
  std::uint8_t back() const { return data()[size_ - 1]; }

  /// The inline cell (meaningful while is_inline()): bytes past size() are zero.
  std::uint8_t* cell() { return cell_.data(); }
  const std::uint8_t* cell() const { return cell_.data(); }

  /// `n` bytes of `fill`. A scalar never allocates.
  void assign(std::size_t n, std::uint8_t fill) {
    resize_storage(n);
    std::fill_n(data(), n, fill);
  }
  template <typename It>
  void assign(It first, It last) {
    const auto n = static_cast<std::size_t>(std::distance(first, last));
    if (n > kInline) {
      heap_.assign(first, last);
      size_ = n;
      return;
    }
    std::array<std::uint8_t, kInline> copy{};  // the source may be this value's own bytes
    std::copy(first, last, copy.begin());
    resize_storage(n);
    cell_ = copy;
  }

  /// A copy as a byte vector (allocates: not for the per-tick paths).
  Bytes bytes() const { return Bytes(begin(), end()); }
  explicit operator Bytes() const { return bytes(); }

  friend bool operator==(const StoredValue& a, const StoredValue& b) {
    return a.size_ == b.size_ && std::equal(a.begin(), a.end(), b.begin());
  }
  friend bool operator==(const StoredValue& a, const Bytes& b) {
    return a.size_ == b.size() && std::equal(a.begin(), a.end(), b.begin());
  }

 private:
  // Switches to `n` bytes of storage; the inline cell is zeroed, so its tail stays zero.
  void resize_storage(std::size_t n) {
    if (n <= kInline) {
      cell_.fill(0);
      heap_.clear();  // keeps its capacity: a string that shrinks and grows again
    } else {
      heap_.resize(n);
    }
    size_ = n;
  }

  alignas(8) std::array<std::uint8_t, kInline> cell_{};
  std::uint32_t size_ = 0;
  Bytes heap_;  // used only for values longer than the cell
};

}  // namespace canopen
