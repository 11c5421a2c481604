// Behaviour knobs of the CiA 301 stack. Defaults follow CiA 301; each product sets what its manual
// says where the manuals differ (abort codes, tolerance of short frames, TPDO triggers, ...).
// Anything more particular than a knob is done with object-dictionary hooks or Application events.
#pragma once

#include <bitset>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "devices/canopen/sdo_abort.h"
#include "sim/time.h"

namespace canopen {

struct SdoPolicy {
  /// Request frames with DLC < 8: ignored (CiA 301) or read with missing bytes as 0.
  bool pad_short_requests = false;
  /// Expedited/segmented download whose size differs from a fixed-size object.
  enum class SizeMode : std::uint8_t {
    Strict,            ///< 0x06070012 / 0x06070013
    Lenient,           ///< extend (sign/zero) or truncate
    ExcessMustBeZero,  ///< longer accepted if the extra bytes are 0 / a sign extension; shorter extended
  } size_mode = SizeMode::Strict;
  SdoAbort unknown_command = SdoAbort::InvalidCommand;
  /// With SizeMode::Strict: the abort for a length that does not match a fixed-size object
  /// (None = CiA 301's 0x06070012 too long / 0x06070013 too short; some devices send 0x06070010).
  SdoAbort length_mismatch = SdoAbort::None;
  sim::Duration timeout = sim::milliseconds(1000);  ///< segmented transfer idle limit; 0 = none
  bool segmented_download = true;
  /// A segmented transfer whose total differs from the object size (numeric types).
  SdoAbort segmented_size_mismatch = SdoAbort::TypeMismatch;
  /// Segmented downloads of numeric objects must have exactly the object's size, even when
  /// expedited ones are lenient (SizeMode::Lenient / ExcessMustBeZero).
  bool segmented_exact_size = false;
  /// A download to a data type definition (DEFTYPE/DEFSTRUCT object, e.g. the dummy types
  /// 0x0002-0x0007 an EDS declares in [DummyUsage]): CiA 301 §7.4.7 entries that describe a type
  /// and hold no parameter, so the access itself is unsupported (reading gives the length).
  SdoAbort type_definition_write = SdoAbort::UnsupportedAccess;
};

struct NmtPolicy {
  bool require_dlc_2 = true;  ///< false: accept DLC >= 2
  bool stop_supported = true;
  sim::Duration boot_delay{0};   ///< power-on → boot-up frame
  sim::Duration reset_delay{0};  ///< NMT reset → boot-up frame
};

struct ErrorControlPolicy {
  /// Answer node-guarding RTRs while the heartbeat producer runs (CiA 301 says they are
  /// exclusive; many devices answer anyway). false: RTRs are ignored and life guarding is
  /// disarmed while 0x1017 != 0 (no life-guarding event for RTRs the node would not answer).
  bool guard_while_heartbeat = true;
  /// EMCY for a life-guarding or heartbeat-consumer timeout; 0 = none.
  std::uint16_t life_guard_emcy = 0x8130;
  std::uint16_t heartbeat_consumer_emcy = 0x8130;
  /// EMCY when the CAN controller is back from bus-off (CiA 301: 0x8140, an event); 0 = none.
  std::uint16_t bus_off_recovered_emcy = 0x8140;
  /// EMCY while the CAN controller is error passive (CiA 301: 0x8120); 0 = none. Raised when
  /// the bus's fault confinement reports error passive, cleared when it is error active again.
  std::uint16_t error_passive_emcy = 0x8120;
  std::uint8_t communication_error_register = 0x11;
  /// CiA 301 §7.5.2.21 (0x1016): configuring a second non-zero consumer heartbeat time for a
  /// node-ID that another sub-index already watches is refused with this code (None = allowed).
  SdoAbort duplicate_consumer = SdoAbort::ParameterIncompatible;
};

struct EmcyPolicy {
  enum class History : std::uint8_t {
    Events,         ///< 0x1003 logs every EMCY event, newest first (CiA 301)
    PresentErrors,  ///< 0x1003 lists only errors still present, newest first
  } history = History::Events;
  std::uint8_t history_depth = 8;  ///< 0 = no 0x1003 handling by the stack
  /// Send the "error reset / no error" EMCY (code 0x0000) when the last active error clears.
  bool send_no_error = true;
  /// Send EMCYs in Pre-operational (CiA 301). false: only in Operational, for manuals whose
  /// Pre-operational state offers "only NMT, node guarding and SDO"; errors are still recorded.
  bool send_in_preoperational = true;
  /// Record events that occur in Stopped (their EMCY is never sent).
  bool record_when_not_sent = true;
  bool clear_history_on_reset_communication = true;
  SdoAbort history_write_nonzero = SdoAbort::InvalidValue;
  /// Reading 0x1003:k with k above the current count.
  SdoAbort history_read_beyond = SdoAbort::NoData;
};

struct PdoPolicy {
  /// Asynchronous TPDO (types 254, 255) triggers.
  struct AsyncTriggers {
    bool on_change = true;     ///< mapped data changed (checked every tick)
    bool after_rpdo = false;   ///< right after the RPDO with the same number was processed
    bool on_timer = true;      ///< event timer (sub 5)
  };
  AsyncTriggers type254{};
  AsyncTriggers type255{};
  /// Send each event-driven TPDO once when entering Operational.
  bool send_async_on_operational = false;
  /// Without the initial transmission: change detection starts from the data present when
  /// Operational is entered (default: the first check counts as a change and sends once).
  bool change_baseline_on_operational = false;
  /// Type 255 with event timer 0 means "PDO off" (some vendors' tables): nothing is sent.
  bool type255_off_without_timer = false;
  /// TPDOs answer remote requests on their COB-ID (CiA 301; COB-ID bit 30 = 0). false: every
  /// remote request for a TPDO identifier is ignored (devices that send only on their timer).
  bool tpdo_remote_requests = true;
  /// A write to a TPDO's event timer (sub 5) restarts it: the next timer-driven frame follows one
  /// new period after the write. false: the running period ends as scheduled.
  bool event_timer_restart_on_write = false;
  /// Remote request whose DLC differs from the TPDO length.
  enum class RtrDlcMismatch : std::uint8_t { Answer, EmptyFrame, Ignore } rtr_dlc_mismatch = RtrDlcMismatch::Answer;
  /// TPDOs go out with DLC 8, the bytes after the mapped ones 0 (manuals that draw every PDO as
  /// 8 bytes with "not used" fields); a remote request must then ask for 8 bytes.
  bool pad_tpdo_to_8 = false;
  /// RPDO shorter than its mapping: EMCY 0x8210 (CiA 301) or silently ignored. Longer: 0x8220.
  bool rpdo_length_emcy = true;
  bool rpdo_too_long_is_error = true;
  /// Transmission types accepted on writes to sub 2.
  std::bitset<256> rpdo_types = default_rpdo_types();
  std::bitset<256> tpdo_types = default_tpdo_types();
  SdoAbort bad_transmission_type = SdoAbort::InvalidValue;
  /// CiA 301 rules for changing parameters: COB-ID only while invalid (else 0x06090030), mapping
  /// only while the PDO is invalid (else 0x08000022), entries only while sub 0 is 0 (0x08000022).
  bool cobid_change_requires_invalid = true;
  bool mapping_requires_invalid = true;
  bool mapping_entry_requires_sub0_zero = true;
  /// All PDO parameter writes refused outside Pre-operational (0x08000022).
  bool parameters_preop_only = false;
  bool dummy_mapping = true;
  /// Mapping length may differ from the object size (value widened / truncated).
  bool width_conversion = false;
  /// Mapping entry whose length differs from the object (without width conversion).
  SdoAbort mapping_length_mismatch = SdoAbort::NotMappable;
  /// SYNC frames with DLC != 0 are ignored (some devices insist on DLC 0).
  bool sync_requires_dlc0 = false;
  /// 0x1005 written with bit 30 (SYNC producer): the emulated nodes only consume SYNC.
  SdoAbort sync_producer_refused = SdoAbort::InvalidValue;

  static std::bitset<256> default_rpdo_types() {
    std::bitset<256> b;
    for (int t = 0; t <= 240; ++t) b.set(t);
    b.set(254);
    b.set(255);
    return b;
  }
  static std::bitset<256> default_tpdo_types() {
    std::bitset<256> b;
    for (int t = 0; t <= 240; ++t) b.set(t);
    for (int t = 252; t <= 255; ++t) b.set(t);
    return b;
  }
};

struct StorePolicy {
  SdoAbort wrong_signature = SdoAbort::DataTransfer;
  enum class Restore : std::uint8_t {
    EraseStored,       ///< CiA 301 / CANopenNode: stored values are erased; defaults at next reset
    PendingUntilReset, ///< non-volatile memory untouched; defaults at next reset; power cycle discards
  } restore = Restore::EraseStored;
  /// Time during which the node is silent while saving (frames in and out dropped).
  sim::Duration busy_time{0};
  /// The same for a successful restore (0x1011).
  sim::Duration restore_busy_time{0};
  /// Abort code when the non-volatile memory fails (some manuals print another value).
  SdoAbort hardware_error = SdoAbort::HardwareError;
  /// File holding this node's stored parameters ("" = RAM only: lost at power-off).
  std::string path;
  /// Storing a node-ID-relative entry (COB-IDs) that still has its default keeps it relative,
  /// so it follows a later node-ID change. true: store the absolute value ("frozen").
  bool freeze_node_relative = false;
  /// Sub-index of 0x1010/0x1011 → index ranges it covers. Empty = CiA 301 default
  /// (1 all, 2 communication, 3 application 6000h-9FFFh, 4 manufacturer 2000h-5FFFh).
  struct Group {
    std::uint8_t sub;
    std::vector<std::pair<std::uint16_t, std::uint16_t>> ranges;
  };
  std::vector<Group> groups;
  /// Values the non-volatile memory holds at every power-on, on top of the file (a scenario's
  /// parameter overrides): loaded like stored values, so resets apply them and 0x1011 erases them.
  struct Preset {
    std::uint16_t index;
    std::uint8_t sub;
    std::vector<std::uint8_t> bytes;
  };
  std::vector<Preset> preset;
};

struct NodePolicy {
  SdoPolicy sdo;
  NmtPolicy nmt;
  ErrorControlPolicy error_control;
  EmcyPolicy emcy;
  PdoPolicy pdo;
  StorePolicy store;
};

}  // namespace canopen
