#include "devices/profiles/cia406/cam_unit.h"

#include <string>


namespace cia406 {

using canopen::Access;
using canopen::DataType;
using canopen::ObjectCode;
using canopen::ObjectDictionary;
using canopen::OdEntry;
using canopen::Origin;
using canopen::SdoAbort;

bool Cam::update(std::int64_t x) {
  const auto h = static_cast<std::int64_t>(hysteresis > 0x7FFFFFFFull ? 0x7FFFFFFFull : hysteresis);
  if (inside) {
    inside = x >= low - h && x <= high + h;
  } else {
    inside = x >= low && x <= high;
  }
  return inside;
}

void CamUnit::add_objects(ObjectDictionary& od) {
  od.add_object(kState, "CAM state register", ObjectCode::Array);
  od.add_entry(kState, 0, "Highest sub-index supported", DataType::Unsigned8, Access::ReadOnly, 1);
  od.add_entry(kState, 1, "CAM state channel 1", DataType::Unsigned8, Access::ReadOnly, 0, true).persistent = false;
  od.add_object(kEnable, "CAM enable register", ObjectCode::Array);
  od.add_entry(kEnable, 0, "Highest sub-index supported", DataType::Unsigned8, Access::ReadOnly, 1);
  od.add_entry(kEnable, 1, "CAM enable channel 1", DataType::Unsigned8, Access::ReadWrite, 0);
  od.add_object(kPolarity, "CAM polarity register", ObjectCode::Array);
  od.add_entry(kPolarity, 0, "Highest sub-index supported", DataType::Unsigned8, Access::ReadOnly, 1);
  od.add_entry(kPolarity, 1, "CAM polarity channel 1", DataType::Unsigned8, Access::ReadWrite, 0);
  for (int k = 0; k < kCams; ++k) {
    const std::string cam = "CAM" + std::to_string(k + 1);
    const auto low = static_cast<std::uint16_t>(kLowLimit + k);
    const auto high = static_cast<std::uint16_t>(kHighLimit + k);
    const auto hyst = static_cast<std::uint16_t>(kHysteresis + k);
    od.add_object(low, cam + " low limit", ObjectCode::Array);
    od.add_entry(low, 0, "Highest sub-index supported", DataType::Unsigned8, Access::Const, 1);
    od.add_entry(low, 1, cam + " low limit channel 1", DataType::Integer32, Access::ReadWrite, 0);
    od.add_object(high, cam + " high limit", ObjectCode::Array);
    od.add_entry(high, 0, "Highest sub-index supported", DataType::Unsigned8, Access::Const, 1);
    od.add_entry(high, 1, cam + " high limit channel 1", DataType::Integer32, Access::ReadWrite, 0);
    od.add_object(hyst, cam + " hysteresis", ObjectCode::Array);
    od.add_entry(hyst, 0, "Highest sub-index supported", DataType::Unsigned8, Access::Const, 1);
    od.add_entry(hyst, 1, cam + " hysteresis channel 1", DataType::Unsigned32, Access::ReadWrite, 0);
  }
}

void CamUnit::bind(ObjectDictionary& od, SdoAbort abort) {
  state_ = canopen::EntryRef<std::uint8_t>(od, kState, 1);
  enable_ = canopen::EntryRef<std::uint8_t>(od, kEnable, 1);
  polarity_ = canopen::EntryRef<std::uint8_t>(od, kPolarity, 1);
  for (int k = 0; k < kCams; ++k) {
    const auto low = static_cast<std::uint16_t>(kLowLimit + k);
    low_[k] = canopen::EntryRef<std::int32_t>(od, low, 1);
    high_[k] = canopen::EntryRef<std::int32_t>(od, static_cast<std::uint16_t>(kHighLimit + k), 1);
    hysteresis_[k] = canopen::EntryRef<std::uint32_t>(od, static_cast<std::uint16_t>(kHysteresis + k), 1);
    const OdEntry* high = &high_[k].entry();
    od.add_check(low, 1, [high, abort](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
      if (origin != Origin::Sdo) return SdoAbort::None;
      const auto next = canopen::value_as<std::int32_t>(e.type, data);
      if (next == e.as<std::int32_t>()) return SdoAbort::None;  // unchanged: always accepted
      return next >= high->as<std::int32_t>() ? abort : SdoAbort::None;
    });
  }
}

void CamUnit::reset() {
  inside_.fill(false);
}

std::uint8_t CamUnit::update(std::int64_t x) {
  // Cam::update() on the limits of this cycle, inline; only the switching memory is kept (the
  // limits are read anew in every cycle, so a value written by SDO or PDO, or reset, acts at once).
  unsigned inside = 0;  // bit k: cam k's switching memory after this position
  for (int k = 0; k < kCams; ++k) {
    bool& memory = inside_[static_cast<std::size_t>(k)];
    const std::int64_t low = low_[k].get(), high = high_[k].get();
    if (memory) {  // only a cam inside uses its hysteresis
      const std::uint32_t hysteresis = hysteresis_[k].get();
      const auto h = static_cast<std::int64_t>(hysteresis > 0x7FFFFFFFu ? 0x7FFFFFFFu : hysteresis);
      memory = x >= low - h && x <= high + h;
    } else {
      memory = x >= low && x <= high;
    }
    inside |= static_cast<unsigned>(memory) << k;
  }
  // Bit k = enabled and (inside xor inverted).
  const auto state = static_cast<std::uint8_t>((inside ^ polarity_.get()) & enable_.get());
  state_.set(state);
  return state;
}

}  // namespace cia406
