// What a save (1010h) and a restore (1011h) do on a DSV, in one place. Three owners act on each
// write of 1010h/1011h sub 1..3 by SDO, in this order:
//   1. the node's CiA 301 store (devices/canopen/store_restore.cpp): the signature, the groups
//      (sub 1 all, 2 communication, 3 application), the non-volatile memory file, abort 0x06060000
//      while the memory fails; restored defaults take effect at the next reset;
//   2. this unit, the DSV's own objects:
//      - before the write is accepted: 230Eh:01 gets its own (mode 4) value back if it shows
//        250Eh:01, so a save stores its own value; a save or restore signature while the
//        memory fails latches EMCY 5520h besides the store's abort;
//      - save (1010h sub 1 "all" or 3 "application"): the characteristic points (not dictionary
//        entries: pseudo sub-indices 2344h:10..25 of the store, DsvParameters::save_curves) are
//        written to the memory too; a pending restore of them is cancelled;
//      - restore (1011h sub 1 or 3): the points go back to their defaults at the next reset
//        instead of loading from the memory; a power cycle forgets the pending restore;
//   3. the Wandfluh application group (devices/profiles/wandfluh/valve_application.cpp): a
//      restore of the application group also takes effect at a communication reset; 2000h/2001h
//      keep their values under option A-18 (restore_keeps_address).
#pragma once

#include <functional>

#include "devices/canopen/object_dictionary.h"
#include "devices/canopen/store_restore.h"
#include "devices/dsv/dsv_parameters.h"
#include "devices/profiles/wandfluh/device_errors.h"

namespace dsv {

class DsvStoredObjects {
 public:
  /// `put_back_alias`: gives 230Eh:01 its own value back (DsvDevice's A-21 alias).
  DsvStoredObjects(canopen::ObjectDictionary& od, canopen::StoreRestore& store, DsvParameters& parameters,
                   wandfluh::DeviceErrors& errors, std::function<void()> put_back_alias);
  DsvStoredObjects(const DsvStoredObjects&) = delete;
  DsvStoredObjects& operator=(const DsvStoredObjects&) = delete;

  /// Power-on: a pending restore is discarded.
  void power_on() { curve_restore_pending_ = false; }
  /// Application reset: the characteristic points from the memory, or their defaults after a restore.
  void reset();

 private:
  canopen::StoreRestore& store_;
  DsvParameters& parameters_;
  wandfluh::DeviceErrors& errors_;
  std::function<void()> put_back_alias_;
  bool curve_restore_pending_ = false;
};

}  // namespace dsv
