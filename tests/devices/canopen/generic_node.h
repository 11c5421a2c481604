// A small generic node used by the stack tests: the standard communication area, two PDOs and a
// few application objects of every access kind. `sync_counter` adds 0x1019 and TPDO2's SYNC start
// value (0x1801:06).
#pragma once

#include "devices/canopen/object_dictionary.h"
#include "devices/canopen/standard_objects.h"

namespace vtest {

inline canopen::ObjectDictionary make_generic_od(bool sync_counter = false) {
  using namespace canopen;
  using DT = DataType;
  ObjectDictionary od;
  CommunicationProfile p;
  p.device_type = 0x00000191;
  p.vendor_id = 0x12345678;
  p.product_code = 0x00000042;
  p.revision = 0x00010002;
  p.serial = 0x00C0FFEE;
  p.device_name = "vplant generic node";
  p.error_behaviour = true;
  p.sync_counter = sync_counter;
  add_communication_objects(od, p);
  od.add_var(0x2000, "U8 rw", DT::Unsigned8, Access::ReadWrite, 7);
  auto& limited = od.add_var(0x2001, "I16 rw limited", DT::Integer16, Access::ReadWrite, -5);
  limited.low_limit = ObjectDictionary::encode(DT::Integer16, -100);
  limited.high_limit = ObjectDictionary::encode(DT::Integer16, 100);
  od.add_var(0x2002, "Text", DT::VisibleString, Access::ReadWrite, ObjectDictionary::encode(DT::VisibleString, "hello segmented world"));
  od.add_var(0x2003, "U32 ro", DT::Unsigned32, Access::ReadOnly, 0xDEADBEEFu);
  od.add_var(0x2004, "U16 wo", DT::Unsigned16, Access::WriteOnly, 0);
  od.add_var(0x2005, "U32 const", DT::Unsigned32, Access::Const, 0x01020304u);
  od.add_var(0x2006, "U64 rw", DT::Unsigned64, Access::ReadWrite, 0x1122334455667788ull);
  od.add_var(0x6000, "Output U16", DT::Unsigned16, Access::ReadWrite, 0x1234, true);
  od.add_var(0x6001, "Command I32", DT::Integer32, Access::ReadWrite, 0, true);
  od.add_var(0x6002, "Status U8", DT::Unsigned8, Access::ReadOnly, 0x55, true);
  od.add_var(0x6003, "Not mappable", DT::Unsigned16, Access::ReadWrite, 0);
  PdoDefaults tpdo1{.cob_base = 0x180, .transmission_type = 255, .mapping = {0x60000010, 0x60020008}};
  add_tpdo(od, 1, tpdo1);
  PdoDefaults tpdo2{.cob_base = 0x280, .transmission_type = 1, .mapping = {0x60010020}};
  tpdo2.with_sync_start = sync_counter;
  add_tpdo(od, 2, tpdo2);
  PdoDefaults rpdo1{.cob_base = 0x200, .transmission_type = 255, .mapping = {0x60010020, 0x60000010}};
  add_rpdo(od, 1, rpdo1);
  PdoDefaults rpdo2{.cob_base = 0x300, .transmission_type = 0, .mapping = {0x60000010}};
  add_rpdo(od, 2, rpdo2);
  return od;
}

}  // namespace vtest
