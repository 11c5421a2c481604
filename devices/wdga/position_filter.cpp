#include "devices/wdga/position_filter.h"

namespace wdga {

cia406::Int128 PositionFilter::update(cia406::Int128 s, unsigned constant) {
  y_ += cia406::floor_div(s * kOne - y_, constant == 0 ? 1 : constant);
  return cia406::floor_div(y_ + kOne / 2, kOne);
}

}  // namespace wdga
