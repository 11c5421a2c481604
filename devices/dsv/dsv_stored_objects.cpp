#include "devices/dsv/dsv_stored_objects.h"

#include <string>
#include <utility>


namespace dsv {

using canopen::CheckStage;
using canopen::OdEntry;
using canopen::Origin;
using canopen::SdoAbort;

namespace {
constexpr std::uint16_t kRam = 0x5520;   // EMCY: the non-volatile memory fails
constexpr std::uint8_t kRegGeneric = 0x01;
}  // namespace

DsvStoredObjects::DsvStoredObjects(canopen::ObjectDictionary& od, canopen::StoreRestore& store, DsvParameters& parameters,
                                   wandfluh::DeviceErrors& errors, std::function<void()> put_back_alias)
    : store_(store), parameters_(parameters), errors_(errors), put_back_alias_(std::move(put_back_alias)) {
  store_.allow_device_stored(DsvParameters::kCurveStoreIndex, DsvParameters::kCurveStoreFirstSub,
                             DsvParameters::kCurveStoreLastSub);
  for (std::uint8_t sub : {std::uint8_t{1}, std::uint8_t{3}}) {
    od.add_observer(0x1010, sub, [this](OdEntry&, Origin o) {
      if (o != Origin::Sdo) return;
      auto& memory = store_.memory();
      parameters_.save_curves(memory);
      std::string error;
      (void)memory.save(error);
      curve_restore_pending_ = false;
    });
    od.add_observer(0x1011, sub, [this](OdEntry&, Origin o) {
      if (o == Origin::Sdo) curve_restore_pending_ = true;
    });
  }
  for (std::uint16_t index : {std::uint16_t{0x1010}, std::uint16_t{0x1011}}) {
    for (std::uint8_t sub = 1; sub <= 3; ++sub) {
      od.add_check(
          index, sub,
          [this, index](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
            put_back_alias_();  // 230Eh:01 is saved with its own value
            const auto v = static_cast<std::uint32_t>(canopen::decode_unsigned(data));
            const bool signature = v == (index == 0x1010 ? canopen::StoreRestore::kSaveSignature
                                                         : canopen::StoreRestore::kLoadSignature);
            if (origin == Origin::Sdo && signature && store_.failing()) errors_.latch(kRam, kRegGeneric);
            return SdoAbort::None;
          },
          CheckStage::State);
    }
  }
}

void DsvStoredObjects::reset() {
  if (curve_restore_pending_) {
    parameters_.reset_curves();
    curve_restore_pending_ = false;
  } else {
    parameters_.load_curves(store_.memory());
  }
}

}  // namespace dsv
