#include "devices/profiles/cia406/work_area.h"


namespace cia406 {

using canopen::Access;
using canopen::DataType;
using canopen::ObjectCode;

std::uint8_t work_area_state(std::int64_t x, std::int64_t low, std::int64_t high) {
  if (x > high) return kWorkAreaAbove;
  if (x < low) return kWorkAreaBelow;
  return kWorkAreaInside;
}

void WorkArea::add_objects(canopen::ObjectDictionary& od, std::int32_t default_low, std::int32_t default_high) {
  od.add_object(kState, "Area state register", ObjectCode::Array);
  od.add_entry(kState, 0, "Highest sub-index supported", DataType::Unsigned8, Access::Const, 1);
  od.add_entry(kState, 1, "Work area state channel 1", DataType::Unsigned8, Access::ReadOnly, 0, true).persistent = false;
  od.add_object(kLowLimit, "Work area low limit", ObjectCode::Array);
  od.add_entry(kLowLimit, 0, "Highest sub-index supported", DataType::Unsigned8, Access::Const, 1);
  od.add_entry(kLowLimit, 1, "Work area low limit channel 1", DataType::Integer32, Access::ReadWrite, default_low);
  od.add_object(kHighLimit, "Work area high limit", ObjectCode::Array);
  od.add_entry(kHighLimit, 0, "Highest sub-index supported", DataType::Unsigned8, Access::Const, 1);
  od.add_entry(kHighLimit, 1, "Work area high limit channel 1", DataType::Integer32, Access::ReadWrite, default_high);
}

void WorkArea::bind(canopen::ObjectDictionary& od) {
  state_ = canopen::EntryRef<std::uint8_t>(od, kState, 1);
  low_ = canopen::EntryRef<std::int32_t>(od, kLowLimit, 1);
  high_ = canopen::EntryRef<std::int32_t>(od, kHighLimit, 1);
}

std::uint8_t WorkArea::update(std::int64_t x) {
  const std::uint8_t s = work_area_state(x, low_.get(), high_.get());
  state_.set(s);
  return s;
}

}  // namespace cia406
