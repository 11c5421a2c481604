// Builders for the CiA 301 communication area (0x1000-0x1FFF), so a product declares what its
// manual lists in a few lines and every product gets identical, standard-conformant entries.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "devices/canopen/object_dictionary.h"

namespace canopen {

struct CommunicationProfile {
  std::uint32_t device_type = 0;
  std::uint32_t vendor_id = 0;
  std::uint32_t product_code = 0;
  std::uint32_t revision = 0;
  std::uint32_t serial = 0;
  std::uint8_t identity_entries = 4;  ///< 0x1018 sub 0 (1..4)

  std::string device_name;       ///< 0x1008 ("" = absent)
  std::string hardware_version;  ///< 0x1009
  std::string software_version;  ///< 0x100A

  std::uint8_t error_history_depth = 8;  ///< 0x1003 (0 = absent)
  bool sync = true;                      ///< 0x1005
  bool sync_counter = false;             ///< 0x1019 (synchronous counter overflow value, 0)
  bool guarding = true;                  ///< 0x100C, 0x100D
  std::uint8_t store_groups = 4;         ///< 0x1010/0x1011 sub-indices (0 = absent)
  bool emcy_cob_id = true;               ///< 0x1014
  bool emcy_inhibit = true;              ///< 0x1015
  std::uint8_t heartbeat_consumers = 1;  ///< 0x1016 entries (0 = absent)
  bool heartbeat_producer = true;        ///< 0x1017
  bool sdo_server_parameter = true;      ///< 0x1200
  bool error_behaviour = false;          ///< 0x1029:01
};

/// Adds the communication-area objects described by `profile`.
void add_communication_objects(ObjectDictionary& od, const CommunicationProfile& profile);

/// A PDO's default parameters. COB-IDs are node-relative (`$NODEID+base`) unless `absolute`.
struct PdoDefaults {
  std::uint32_t cob_base = 0;       ///< e.g. 0x180 for TPDO1; 0x80000000 = invalid
  bool absolute = false;
  std::uint8_t transmission_type = 255;
  std::uint16_t inhibit_time = 0;   ///< 100 µs units (TPDO only)
  std::uint16_t event_timer = 0;    ///< ms
  std::vector<std::uint32_t> mapping;  ///< entries index<<16 | sub<<8 | bits
  std::uint8_t mapping_capacity = 8;   ///< number of mapping sub-indices
  bool with_inhibit_and_timer = true;  ///< TPDO subs 3 and 5 (RPDO: sub 5 only if event timer)
  bool with_sync_start = false;        ///< TPDO sub 6 (SYNC start value, 0)
};

/// RPDO n (1-based): 0x1400+n-1 and 0x1600+n-1.
void add_rpdo(ObjectDictionary& od, int number, const PdoDefaults& d);
/// TPDO n (1-based): 0x1800+n-1 and 0x1A00+n-1.
void add_tpdo(ObjectDictionary& od, int number, const PdoDefaults& d);
/// Predefined connection set defaults for PDO 1..4 (0x180/0x200, 0x280/0x300, ...).
std::uint32_t default_tpdo_cob_base(int number);
std::uint32_t default_rpdo_cob_base(int number);

}  // namespace canopen
