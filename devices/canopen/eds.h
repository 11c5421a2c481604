// EDS (CiA 306 electronic data sheet): load any EDS into an object dictionary, and write an
// object dictionary out as an EDS. Errors name the file and line.
//
// Errors make the file unusable (the dictionary would be ambiguous, contradictory or not what the
// file says); warnings are CiA 306 conformance defects that do not change the dictionary
// (metadata keys, unknown keys or sections, counts that disagree with the objects). The full
// list is in docs/runtime.md, section "EDS files".
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "devices/canopen/object_dictionary.h"
#include "sim/diagnostic.h"

namespace canopen {

/// [FileInfo], [DeviceInfo], [DummyUsage] and [Comments] content.
struct EdsFileInfo {
  // [FileInfo]
  std::string file_name;       ///< e.g. "WAGMD2C1.eds"
  std::uint8_t file_version = 1;
  std::uint8_t file_revision = 0;
  std::string eds_version = "4.0";
  std::string description;
  /// Written as given, never taken from the clock: the same dictionary must give the same text.
  std::string creation_time = "12:00AM";     ///< hh:mm(AM|PM)
  std::string creation_date = "01-01-2026";  ///< mm-dd-yyyy
  std::string created_by = "vplant";
  std::string modification_time;  ///< the three Modification keys are written only when set
  std::string modification_date;
  std::string modified_by;

  // [DeviceInfo]
  std::string vendor_name;
  /// VendorNumber, ProductNumber, RevisionNumber: the writer takes them from 0x1018 sub 1..3
  /// when the dictionary has them (what the node reports), from here otherwise.
  std::uint32_t vendor_number = 0;
  std::string product_name;
  std::uint32_t product_number = 0;
  std::uint32_t revision_number = 0;
  std::string order_code;
  std::vector<unsigned> baud_rates_kbit = {10, 20, 50, 125, 250, 500, 800, 1000};
  bool simple_boot_up_master = false;
  bool simple_boot_up_slave = true;
  bool lss_supported = false;
  std::uint8_t granularity = 8;
  bool dynamic_channels = false;
  bool group_messaging = false;
  /// CompactPDO bits read from a file (the writer always describes PDOs explicitly: 0).
  std::uint8_t compact_pdo = 0;
  std::uint16_t nr_of_rx_pdo = 0;  ///< filled from the dictionary when writing
  std::uint16_t nr_of_tx_pdo = 0;

  /// [DummyUsage]: bit i set = Dummy000i supported (i = 1..7). The default is what the stack
  /// maps (PdoPolicy::dummy_mapping, byte-granular: 0x0002-0x0007); a product that disables
  /// dummy mapping clears it. DEFTYPE objects 0x0001-0x0007 in the dictionary are added.
  std::uint8_t dummy_usage = 0xFC;

  /// [Comments] lines.
  std::vector<std::string> comments;
};

/// An EDS error or warning: the project's one diagnostic (sim/diagnostic.h). The mark has the
/// file and the 1-based line (0: the whole file, e.g. cannot open) and no column (the INI format
/// is line-based), so to_string() reads "file:line: reason" ("file:line: warning: reason").
using EdsError = sim::Diagnostic;

/// How the reader treats the CiA 306 deviations that EDS/DCF writing tools produce and masters
/// tolerate (a RECORD with CompactSubObj, counts one too high, no 0x1000, a RECORD without sub 0,
/// no DefaultValue below a LowLimit; list in docs/runtime.md, "EDS files"). Tolerant loads the file
/// with a warning per deviation saying how it is read; Strict rejects it.
enum class EdsStrictness { Tolerant, Strict };

/// Parses EDS text. On error returns nullopt and fills `error` (the error with the lowest line).
/// Warnings (the dictionary is still built) go to `warnings` when given.
std::optional<ObjectDictionary> parse_eds(std::string_view text, const std::string& file_name, EdsError& error,
                                          EdsFileInfo* info = nullptr, std::vector<EdsError>* warnings = nullptr,
                                          EdsStrictness strictness = EdsStrictness::Tolerant);
/// Reads the file with sim::read_input_file (a regular file of bounded size; a FIFO or device is
/// an error, never a hang) and parses it.
std::optional<ObjectDictionary> load_eds(const std::string& path, EdsError& error, EdsFileInfo* info = nullptr,
                                         std::vector<EdsError>* warnings = nullptr,
                                         EdsStrictness strictness = EdsStrictness::Tolerant);

/// Every error and warning of an EDS, in line order (`vplant eds --check FILE`). Empty = a clean,
/// CiA 306-conformant file. Strict by default: a checker reports deviations as errors.
std::vector<EdsError> check_eds(std::string_view text, const std::string& file_name,
                                EdsStrictness strictness = EdsStrictness::Strict);
std::vector<EdsError> check_eds_file(const std::string& path, EdsStrictness strictness = EdsStrictness::Strict);

/// Writes `od` as a complete CiA 306 EDS: [FileInfo], [DeviceInfo], [DummyUsage], [Comments],
/// the three object lists and every object and sub-index section. Node-relative defaults are
/// written as $NODEID+0x…. Byte-stable: the same dictionary and info give the same text, and
/// parse_eds() of the text reproduces the dictionary without warnings.
std::string write_eds(const ObjectDictionary& od, const EdsFileInfo& info);

/// [DeviceComissioning] of a DCF: where and as what the node is configured in its network.
struct DcfCommissioning {
  std::uint8_t node_id = 0;
  std::string node_name;
  unsigned baudrate_kbit = 0;  ///< 0 = not stated
  std::uint32_t net_number = 0;
  std::string network_name;
};

/// Writes `od` as a CiA 306 DCF: write_eds()'s text plus [DeviceComissioning] and, on every
/// entry but write-only ones and DOMAINs, ParameterValue= with its current value (node-relative
/// entries resolved for the node-ID). parse_eds() of the text gives a dictionary whose defaults
/// are those values.
std::string write_dcf(const ObjectDictionary& od, const EdsFileInfo& info, const DcfCommissioning& commissioning);

}  // namespace canopen
