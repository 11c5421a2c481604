#include "devices/wdga/position_filter.h"

namespace wdga {

cia406::Int128 PositionFilter::update(cia406::Int128 s, unsigned constant) {
  if (constant <= 1) {
    y_ = s * kOne;  // c = 1 (and 0, taken as 1): y + floor((S·one − y) / 1) = S·one
  } else {
    y_ += cia406::floor_div(s * kOne - y_, constant);
  }
  return (y_ + kOne / 2) >> kFractionBits;  // floor division by one = 2^16: an arithmetic shift
}

}  // namespace wdga
